//! Test-only helpers: exact GP-ness, reverted fraction, orientation and
//! angle sums of a generated map, computed independently of dualex-map's
//! transition code.

use dualex_map::{Rot2, TriMap};
use std::collections::HashMap;

/// Interior edges as `(triangle s, corner of a in s, corner of b in s,
/// triangle t, corner of a in t, corner of b in t)`; panics (test failure)
/// on an edge with more than 2 triangles or two triangles traversing an
/// edge in the same direction.
pub(crate) fn interior_edges(map: &TriMap) -> Vec<[usize; 6]> {
    let mut directed: HashMap<(u32, u32), (usize, usize, usize)> = HashMap::new();
    for (s, t) in map.simplices.iter().enumerate() {
        for c in 0..3 {
            let (a, b) = (t[c], t[(c + 1) % 3]);
            let old = directed.insert((a, b), (s, c, (c + 1) % 3));
            assert!(old.is_none(), "edge {a}-{b} twice in the same direction");
        }
    }
    let mut out = Vec::new();
    for (&(a, b), &(s, ca, cb)) in &directed {
        if a < b {
            if let Some(&(t, cb2, ca2)) = directed.get(&(b, a)) {
                out.push([s, ca, cb, t, ca2, cb2]);
            }
        }
    }
    out
}

/// Largest GP residual over interior edges: for the best grid rotation `R`,
/// how far `q − R·p` is from one integer translation at both endpoints.
pub(crate) fn gp_residual(map: &TriMap) -> f64 {
    let mut worst: f64 = 0.0;
    for [s, ca, cb, t, ta, tb] in interior_edges(map) {
        let (pa, pb) = (map.coords[s][ca], map.coords[s][cb]);
        let (qa, qb) = (map.coords[t][ta], map.coords[t][tb]);
        let best = Rot2::all()
            .iter()
            .map(|r| {
                let (ra, rb) = (r.apply(&pa), r.apply(&pb));
                let t1 = [qa[0] - ra[0], qa[1] - ra[1]];
                let t2 = [qb[0] - rb[0], qb[1] - rb[1]];
                let mut e: f64 = 0.0;
                for k in 0..2 {
                    e = e
                        .max((t1[k] - t2[k]).abs())
                        .max((t1[k] - t1[k].round()).abs());
                }
                e
            })
            .fold(f64::INFINITY, f64::min);
        worst = worst.max(best);
    }
    worst
}

/// Fraction of triangles with a negative map determinant.
pub(crate) fn reverted_fraction(map: &TriMap) -> f64 {
    let n = (0..map.len()).filter(|&s| map.map_det(s) < 0.0).count();
    n as f64 / map.len() as f64
}

/// Fraction of triangles with a negative determinant of their positions
/// projected on the plane `z = 0` (planar meshes only).
pub(crate) fn position_det(map: &TriMap, s: usize) -> f64 {
    let p = map.simplices[s].map(|v| map.positions[v as usize]);
    (p[1][0] - p[0][0]) * (p[2][1] - p[0][1]) - (p[1][1] - p[0][1]) * (p[2][0] - p[0][0])
}

/// Sum of the map angles at the corners of vertex `v`.
pub(crate) fn angle_sum(map: &TriMap, v: u32) -> f64 {
    let mut sum = 0.0;
    for (t, c) in map.simplices.iter().zip(&map.coords) {
        if let Some(k) = t.iter().position(|&x| x == v) {
            let (p, a, b) = (c[k], c[(k + 1) % 3], c[(k + 2) % 3]);
            let (u, w) = ([a[0] - p[0], a[1] - p[1]], [b[0] - p[0], b[1] - p[1]]);
            sum += (u[0] * w[1] - u[1] * w[0]).atan2(u[0] * w[0] + u[1] * w[1]);
        }
    }
    sum
}
