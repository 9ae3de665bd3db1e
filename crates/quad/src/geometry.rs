//! Step 7: vertex positions, by tracing node diagonals in the map
//! (paper appendix "Quad Mesh Extraction"; DESIGN §5).
//!
//! Input: the sanitized [`LocalMap`], [`Topology`], the positions, the
//! [`Nodes`]. For one node corner (a diagonal direction `(±1, ±1)`), walk the
//! straight map segment from the node to the half-integer point
//! `node + (±½, ±½)` across triangles and transitions until that point is
//! reached (then its exact preimage is returned, distance 0) or a foldover,
//! the boundary or a degenerate crossing stops the walk (then the closest
//! point seen along the way is returned with its map distance to the target).
//! A mesh vertex takes, among its corners' candidates, the one of smallest
//! distance. On a valid map every candidate is exact, which is what QEx's
//! primal extraction computes.

use crate::local::LocalMap;
use crate::nodes::Nodes;
use dualex_map::{Topology, TriMap};

/// Where a diagonal walk ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Candidate {
    /// Map distance from the returned point to the target grid point.
    pub dist: f64,
    /// Point on the surface.
    pub pos: [f64; 3],
}

/// Longest diagonal walk, in triangles.
const MAX_STEPS: usize = 100_000;

fn lerp3(a: &[f64; 3], b: &[f64; 3], t: f64) -> [f64; 3] {
    [
        a[0] + t * (b[0] - a[0]),
        a[1] + t * (b[1] - a[1]),
        a[2] + t * (b[2] - a[2]),
    ]
}

fn bary_point(map: &TriMap, s: usize, w: &[f64; 3]) -> [f64; 3] {
    let mut p = [0.0; 3];
    for (wc, &v) in w.iter().zip(&map.simplices[s]) {
        let x = map.positions[v as usize];
        for (pk, xk) in p.iter_mut().zip(x) {
            *pk += wc * xk;
        }
    }
    p
}

/// Barycentric coordinates of `q` in triangle `s` (None if degenerate).
fn bary(local: &LocalMap, s: usize, q: &[f64; 2]) -> Option<[f64; 3]> {
    let p = &local.coords[s];
    let det = local.det(s);
    if det == 0.0 || !det.is_finite() {
        return None;
    }
    Some(std::array::from_fn(|c| {
        let a = p[(c + 1) % 3];
        let b = p[(c + 2) % 3];
        ((a[0] - q[0]) * (b[1] - q[1]) - (a[1] - q[1]) * (b[0] - q[0])) / det
    }))
}

/// Walks from node `n` along diagonal `(su, sv)` (±1 each).
pub fn diagonal(
    map: &TriMap,
    local: &LocalMap,
    topo: &Topology<3>,
    nodes: &Nodes,
    n: usize,
    su: f64,
    sv: f64,
) -> Candidate {
    let mut t = nodes.tri[n] as usize;
    let mut p0 = nodes.ij[n].map(|x| x as f64);
    let mut d = [su, sv];
    let mut tgt = [p0[0] + 0.5 * su, p0[1] + 0.5 * sv];
    let mut best = Candidate {
        dist: (0.5f64).hypot(0.5),
        pos: bary_point(map, t, &nodes.bary[n]),
    };
    let mut entry: Option<usize> = None;
    for step in 0..MAX_STEPS {
        let det = local.det(t);
        if step > 0 && det < 0.0 {
            return best; // foldover
        }
        if let Some(w) = bary(local, t, &tgt) {
            if w.iter().all(|&x| x >= -1e-12) {
                let s: f64 = w.iter().map(|x| x.max(0.0)).sum();
                let w = w.map(|x| x.max(0.0) / s);
                return Candidate {
                    dist: 0.0,
                    pos: bary_point(map, t, &w),
                };
            }
        }
        let p = &local.coords[t];
        let f: [f64; 3] =
            std::array::from_fn(|c| d[0] * (p[c][1] - p0[1]) - d[1] * (p[c][0] - p0[0]));
        // candidate exits: (edge, progress along d, map point, 3D point)
        let mut exit: Option<(usize, f64, [f64; 2], [f64; 3])> = None;
        for e in 0..3 {
            if Some(e) == entry {
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
            if step == 0 && g <= 0.0 {
                continue;
            }
            let xa = map.positions[map.simplices[t][ca] as usize];
            let xb = map.positions[map.simplices[t][cb] as usize];
            if exit.is_none_or(|x| g > x.1) {
                exit = Some((e, g, q, lerp3(&xa, &xb, s)));
            }
        }
        let Some((e, _, q, x3)) = exit else {
            return best;
        };
        let dist = (q[0] - tgt[0]).hypot(q[1] - tgt[1]);
        if dist < best.dist {
            best = Candidate { dist, pos: x3 };
        }
        let Some((t2, e2)) = topo.neighbour(t, e) else {
            return best;
        };
        p0 = local.across(t, e, &p0);
        tgt = local.across(t, e, &tgt);
        d = local.trans.rot[t][e].apply(&d);
        entry = Some(e2);
        t = t2;
    }
    best
}
