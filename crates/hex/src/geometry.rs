//! Step 6: vertex positions, by tracing node diagonals in the map
//! (paper appendix; DESIGN §5).
//!
//! Input: the sanitized [`LocalMap`], [`Topology`], the positions, the
//! [`Nodes`]. For one node corner (a diagonal direction `(±1, ±1, ±1)`),
//! walk the straight map segment from the node to the half-integer point
//! `node + (±½, ±½, ±½)` tet to tet across the transitions until that point
//! is reached (then its exact preimage is returned, distance 0) or a
//! foldover (`det < 0` after the first tet), the boundary or a degenerate
//! tet stops the walk (then the closest point seen is returned with its map
//! distance to the target). A mesh vertex takes, among its corners'
//! candidates, the one of smallest distance.
//!
//! In one tet the segment's barycentric coordinates are affine in the
//! progress `g`; it leaves through the face whose coordinate first drops to
//! zero (the entry face excluded).

use crate::local::LocalMap;
use crate::nodes::Nodes;
use crate::simplex::{bary_weights, det};
use dualex_map::{TetMap, Topology};

/// Where a diagonal walk ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// Map distance from the returned point to the target grid point.
    pub dist: f64,
    /// Point in space.
    pub pos: [f64; 3],
}

/// Longest diagonal walk, in tets.
const MAX_STEPS: usize = 100_000;

fn bary_point(map: &TetMap, s: usize, w: &[f64; 4]) -> [f64; 3] {
    let mut p = [0.0; 3];
    for (c, wc) in w.iter().enumerate() {
        let x = map.positions[map.simplices[s][c] as usize];
        for k in 0..3 {
            p[k] += wc * x[k];
        }
    }
    p
}

fn norm(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    ((a[0] - b[0]).powi(2) + (a[1] - b[1]).powi(2) + (a[2] - b[2]).powi(2)).sqrt()
}

/// Walks from node `n` along the diagonal with signs `sgn` (±1 each).
pub fn diagonal(
    map: &TetMap,
    local: &LocalMap,
    topo: &Topology<4>,
    nodes: &Nodes,
    n: usize,
    sgn: [f64; 3],
) -> Candidate {
    let mut t = nodes.tet[n] as usize;
    let mut p0 = nodes.ijk[n].map(|x| x as f64);
    let mut tgt: [f64; 3] = std::array::from_fn(|k| p0[k] + 0.5 * sgn[k]);
    let mut best = Candidate {
        dist: 0.75f64.sqrt(),
        pos: bary_point(map, t, &nodes.bary[n]),
    };
    let mut entry: Option<usize> = None;
    for step in 0..MAX_STEPS {
        let p = &local.coords[t];
        let d = det(p);
        if (step > 0 && d < 0.0) || d == 0.0 || !d.is_finite() {
            return best;
        }
        let w1 = bary_weights(p, &tgt).map(|x| x / d);
        if w1.iter().all(|&x| x >= -1e-12) {
            let s: f64 = w1.iter().map(|x| x.max(0.0)).sum();
            let w = w1.map(|x| x.max(0.0) / s);
            return Candidate {
                dist: 0.0,
                pos: bary_point(map, t, &w),
            };
        }
        let w0 = bary_weights(p, &p0).map(|x| x / d);
        // λ(g) = w0 + g (w1 − w0), g ∈ [0, 1] from p0 to the target
        let exit = (0..4)
            .filter(|&c| Some(c) != entry && w1[c] < w0[c])
            .map(|c| (c, w0[c] / (w0[c] - w1[c])))
            .min_by(|a, b| a.1.total_cmp(&b.1));
        let Some((e, g)) = exit else { return best };
        let g = g.clamp(0.0, 1.0);
        let w: [f64; 4] = std::array::from_fn(|c| (w0[c] + g * (w1[c] - w0[c])).max(0.0));
        let q: [f64; 3] = std::array::from_fn(|k| p0[k] + g * (tgt[k] - p0[k]));
        let dist = norm(&q, &tgt);
        if dist < best.dist {
            let s: f64 = w.iter().sum();
            if s > 0.0 {
                best = Candidate {
                    dist,
                    pos: bary_point(map, t, &w.map(|x| x / s)),
                };
            }
        }
        let Some((t2, e2)) = topo.neighbour(t, e) else {
            return best;
        };
        p0 = local.across(t, e, &q);
        tgt = local.across(t, e, &tgt);
        entry = Some(e2);
        t = t2;
    }
    best
}
