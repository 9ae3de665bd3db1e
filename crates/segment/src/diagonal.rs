//! Step 9c: vertex positions, by tracing node diagonals in the map (paper
//! appendix "Quad Mesh Extraction"; DESIGN §5), in any dimension.
//!
//! Input: the map (its positions), the sanitized [`LocalMap`],
//! [`Topology`], the [`Nodes`]; one node corner (a diagonal direction
//! `(±1, …, ±1)`). Output: a [`Candidate`], a point in space and its map
//! distance to the target; a mesh vertex takes, among its corners'
//! candidates, the one of smallest distance. On a valid map every
//! candidate is exact, which is what QEx's primal extraction computes.
//!
//! The walk follows the straight map segment from the node to the
//! half-integer point `node + (±½, …, ±½)` simplex to simplex:
//! 1. start in the node's simplex, the best candidate the node itself at
//!    distance `|(½, …, ½)|` ([`DiagonalStep::half_diagonal`]);
//! 2. in each simplex ([`DiagonalStep::step`]): a foldover (`det < 0`
//!    after the first simplex) stops the walk; the target inside (all
//!    barycentric coordinates ≥ −10⁻¹²) returns its exact preimage,
//!    distance 0; otherwise the segment's exit facet (the entry excluded)
//!    and exit point are found, and the exit point becomes the best
//!    candidate when it is closer to the target;
//! 3. cross the exit facet (the boundary stops the walk): the segment's
//!    points and direction are carried through the transition; go to 2.
//!
//! The exit differs by dimension (each keeps its float operations):
//! D = 2 intersects the line through the node with the triangle's edges
//! and leaves by the furthest crossing ahead (degenerate triangles are
//! walked through); D = 3 writes the segment's barycentric coordinates
//! as affine in the progress `g` and leaves through the face whose
//! coordinate first drops to zero, from the exit point on (degenerate
//! tets stop the walk). The walk is cut after [`MAX_STEPS`] simplices.

use crate::local::LocalMap;
use crate::nodes::Nodes;
use crate::simplex::{Dim, Simplex};
use dualex_map::{SimplexMap, Topology};

/// Where a diagonal walk ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// Map distance from the returned point to the target grid point.
    pub dist: f64,
    /// Point in space.
    pub pos: [f64; 3],
}

/// Longest diagonal walk, in simplices.
pub const MAX_STEPS: usize = 100_000;

/// A diagonal walk in the current simplex's chart.
#[derive(Clone, Copy, Debug)]
pub struct Walk<const D: usize> {
    /// The current simplex.
    pub simplex: usize,
    /// Whether it is the first simplex (the node's).
    pub first: bool,
    /// The facet the walk entered by (none in the first simplex).
    pub entry: Option<usize>,
    /// Where the segment starts (D = 2: the node, carried; D = 3: the
    /// entry point).
    pub from: [f64; D],
    /// The target, `node + (±½, …)` carried.
    pub to: [f64; D],
    /// The walking direction `(±1, …)` carried (read by D = 2).
    pub dir: [f64; D],
}

/// What one simplex of the walk gives.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Step<const D: usize> {
    /// The target lies in the simplex: its preimage.
    Reached([f64; 3]),
    /// Leave through `face`; `from` is the next start, in this chart.
    Leave {
        /// The exit facet.
        face: usize,
        /// The segment's start for the next simplex, in this chart.
        from: [f64; D],
    },
    /// The walk stops (foldover, degenerate simplex, no exit).
    Stop,
}

/// The per-dimension half of the walk (module docs), one `impl` per
/// dimension on [`Dim`].
pub trait DiagonalStep<const N: usize, const D: usize> {
    /// The map distance from a node to the corners of its dual cell,
    /// `|(½, …, ½)|`, where the best candidate starts.
    fn half_diagonal() -> f64;

    /// One simplex of the walk: the target's preimage, or the facet to
    /// leave by, or the end; `best` is updated with the closest point
    /// seen.
    fn step(
        map: &SimplexMap<N, D>,
        local: &LocalMap<N, D>,
        walk: &Walk<D>,
        best: &mut Candidate,
    ) -> Step<D>;
}

/// Walks from node `n` along the diagonal with signs `sgn` (±1 each).
pub fn diagonal<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    local: &LocalMap<N, D>,
    topo: &Topology<N>,
    nodes: &Nodes<N, D>,
    n: usize,
    sgn: [f64; D],
) -> Candidate
where
    Dim<N, D>: DiagonalStep<N, D>,
{
    let s = nodes.simplex[n] as usize;
    let from = nodes.point[n].map(|x| x as f64);
    let mut walk = Walk {
        simplex: s,
        first: true,
        entry: None,
        from,
        to: std::array::from_fn(|k| from[k] + 0.5 * sgn[k]),
        dir: sgn,
    };
    let mut best = Candidate {
        dist: Dim::<N, D>::half_diagonal(),
        pos: bary_point(map, s, &nodes.bary[n]),
    };
    for step in 0..MAX_STEPS {
        walk.first = step == 0;
        let (face, from) = match Dim::<N, D>::step(map, local, &walk, &mut best) {
            Step::Reached(pos) => return Candidate { dist: 0.0, pos },
            Step::Stop => return best,
            Step::Leave { face, from } => (face, from),
        };
        let t = walk.simplex;
        let Some((t2, e2)) = topo.neighbour(t, face) else {
            return best;
        };
        walk.from = local.across(t, face, &from);
        walk.to = local.across(t, face, &walk.to);
        walk.dir = local.trans.rot[t][face].apply(&walk.dir);
        walk.entry = Some(e2);
        walk.simplex = t2;
    }
    best
}

/// The point of simplex `s` with barycentric coordinates `w`.
fn bary_point<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    s: usize,
    w: &[f64; N],
) -> [f64; 3] {
    let mut p = [0.0; 3];
    for (wc, &v) in w.iter().zip(&map.simplices[s]) {
        let x = map.positions[v as usize];
        for (pk, xk) in p.iter_mut().zip(x) {
            *pk += wc * xk;
        }
    }
    p
}

/// The target's preimage when its barycentric coordinates `w` are all
/// ≥ −10⁻¹² (clamped at 0 and renormalised).
fn reached<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    s: usize,
    w: &[f64; N],
) -> Option<[f64; 3]> {
    if !w.iter().all(|&x| x >= -1e-12) {
        return None;
    }
    let sum: f64 = w.iter().map(|x| x.max(0.0)).sum();
    Some(bary_point(map, s, &w.map(|x| x.max(0.0) / sum)))
}

impl DiagonalStep<3, 2> for Dim<3, 2> {
    fn half_diagonal() -> f64 {
        0.5f64.hypot(0.5)
    }

    /// D = 2: intersect the line through `walk.from` along `walk.dir` with
    /// the edges (the entry excluded; in the first triangle only crossings
    /// ahead), leave by the furthest crossing.
    fn step(
        map: &SimplexMap<3, 2>,
        local: &LocalMap<3, 2>,
        walk: &Walk<2>,
        best: &mut Candidate,
    ) -> Step<2> {
        let t = walk.simplex;
        let det = local.det(t);
        if !walk.first && det < 0.0 {
            return Step::Stop; // foldover
        }
        let p = &local.coords[t];
        if det != 0.0 && det.is_finite() {
            let w = Dim::<3, 2>::bary_weights(p, &walk.to).map(|x| x / det);
            if let Some(pos) = reached(map, t, &w) {
                return Step::Reached(pos);
            }
        }
        let (p0, d, tgt) = (walk.from, walk.dir, walk.to);
        let f: [f64; 3] =
            std::array::from_fn(|c| d[0] * (p[c][1] - p0[1]) - d[1] * (p[c][0] - p0[0]));
        // candidate exits: (edge, progress along d, map point, edge parameter)
        let mut exit: Option<(usize, f64, [f64; 2], f64)> = None;
        for e in 0..3 {
            if Some(e) == walk.entry {
                continue;
            }
            let (ca, cb) = ((e + 1) % 3, (e + 2) % 3);
            let (fa, fb) = (f[ca], f[cb]);
            if (fa > 0.0) == (fb > 0.0) {
                continue;
            }
            let s = fa / (fa - fb);
            let q = [
                p[ca][0] + s * (p[cb][0] - p[ca][0]),
                p[ca][1] + s * (p[cb][1] - p[ca][1]),
            ];
            let g = ((q[0] - p0[0]) * d[0] + (q[1] - p0[1]) * d[1]) / 2.0;
            if walk.first && g <= 0.0 {
                continue;
            }
            if exit.is_none_or(|x| g > x.1) {
                exit = Some((e, g, q, s));
            }
        }
        let Some((e, _, q, s)) = exit else {
            return Step::Stop;
        };
        let dist = (q[0] - tgt[0]).hypot(q[1] - tgt[1]);
        if dist < best.dist {
            let corner = |c: usize| map.positions[map.simplices[t][(e + c) % 3] as usize];
            let (xa, xb) = (corner(1), corner(2));
            let pos = std::array::from_fn(|k| xa[k] + s * (xb[k] - xa[k]));
            *best = Candidate { dist, pos };
        }
        Step::Leave { face: e, from: p0 }
    }
}

impl DiagonalStep<4, 3> for Dim<4, 3> {
    fn half_diagonal() -> f64 {
        0.75f64.sqrt()
    }

    /// D = 3: the segment's barycentric coordinates `λ(g) = w0 + g (w1 − w0)`
    /// from `walk.from` (g = 0) to the target (g = 1); leave through the face
    /// whose coordinate first drops to zero (the entry excluded).
    fn step(
        map: &SimplexMap<4, 3>,
        local: &LocalMap<4, 3>,
        walk: &Walk<3>,
        best: &mut Candidate,
    ) -> Step<3> {
        let t = walk.simplex;
        let p = &local.coords[t];
        let d = local.det(t);
        if (!walk.first && d < 0.0) || d == 0.0 || !d.is_finite() {
            return Step::Stop;
        }
        let (p0, tgt) = (walk.from, walk.to);
        let w1 = Dim::<4, 3>::bary_weights(p, &tgt).map(|x| x / d);
        if let Some(pos) = reached(map, t, &w1) {
            return Step::Reached(pos);
        }
        let w0 = Dim::<4, 3>::bary_weights(p, &p0).map(|x| x / d);
        let exit = (0..4)
            .filter(|&c| Some(c) != walk.entry && w1[c] < w0[c])
            .map(|c| (c, w0[c] / (w0[c] - w1[c])))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let Some((e, g)) = exit else {
            return Step::Stop;
        };
        let g = g.clamp(0.0, 1.0);
        let w: [f64; 4] = std::array::from_fn(|c| (w0[c] + g * (w1[c] - w0[c])).max(0.0));
        let q: [f64; 3] = std::array::from_fn(|k| p0[k] + g * (tgt[k] - p0[k]));
        let dist =
            ((q[0] - tgt[0]).powi(2) + (q[1] - tgt[1]).powi(2) + (q[2] - tgt[2]).powi(2)).sqrt();
        if dist < best.dist {
            let s: f64 = w.iter().sum();
            if s > 0.0 {
                *best = Candidate {
                    dist,
                    pos: bary_point(map, t, &w.map(|x| x / s)),
                };
            }
        }
        Step::Leave { face: e, from: q }
    }
}

#[cfg(test)]
#[path = "diagonal_tests.rs"]
mod tests;
