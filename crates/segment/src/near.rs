//! Closeness predicates of sanitization at D = 3: what counts as a vertex,
//! an edge or a face of a tet lying "on" the dual grid of the local
//! shifted map (D = 2: [`crate::grid`], whose 2D tests these build on).
//!
//! - a **vertex** is on an iso-surface when one coordinate is within
//!   [`EPS`] of an integer;
//! - an **edge** is on an iso-line when, for some pair of axes, its
//!   projection onto that pair's plane passes within [`EPS`] of an integer
//!   point (the iso-line `{x_b, x_c ∈ ℤ}` seen end-on);
//! - a **face** is on a grid point when an integer point is within [`EPS`]
//!   of the triangle's plane and projects inside the triangle.
//!
//! Coordinates are local (see [`crate::local`]), so `EPS` is absolute.
//! [`bad_vertices`] turns these into the vertices to move; a grid point at
//! (or next to) an endpoint is that endpoint's problem only, so a vertex
//! that cannot move (singular) does not keep its neighbours moving.
//! [`segment_near_iso_line_in_box`] and the boxes of [`crate::boxes`] are
//! the exact prefilters of the incremental scan ([`crate::sanitize`]):
//! same answers, fewer tests.
//!
//! Numbering (as in `dualex_map::mesh`): face `f` of a tet is opposite
//! corner `f`; its corners are `(f+1, f+2, f+3) mod 4` ([`face_corners`]).

use dualex_map::TetMap;

use crate::contact::segment_through_grid;
pub use crate::grid::{dist2d, grid_point_near_segment, near_int, EPS};
use crate::grid::{dist2d_below_eps, segment_clear_of_grid};
use dualex_util::round::{ceil, floor, round};

/// For the 3D segment `a`–`b` near an iso-line: whether the grid point is
/// at `a`, at `b` (within [`EPS`] in the projection), or at neither.
pub fn segment_near_iso_line(a: &[f64; 3], b: &[f64; 3]) -> Option<(bool, bool)> {
    for [i, j] in [[0, 1], [0, 2], [1, 2]] {
        let (pa, pb) = ([a[i], a[j]], [b[i], b[j]]);
        if let Some(g) = grid_point_near_segment(&pa, &pb) {
            return Some((dist2d(&g, &pa) < EPS, dist2d(&g, &pb) < EPS));
        }
    }
    None
}

/// [`segment_near_iso_line`] for a segment whose box, grown by `2·EPS`,
/// holds the integers `range[k][0]..=range[k][1]` on axis `k`: an axis pair
/// is skipped when the projection's box holds no integer point, or when
/// [`segment_clear_of_grid`] shows none is near (the answer is the same:
/// a grid point within `EPS` of the projection lies in its grown box);
/// when [`segment_through_grid`] shows one at neither end, that is the
/// answer.
pub fn segment_near_iso_line_in_box(
    a: &[f64; 3],
    b: &[f64; 3],
    range: &[[f64; 2]; 3],
) -> Option<(bool, bool)> {
    for [i, j] in [[0, 1], [0, 2], [1, 2]] {
        let (lo, hi) = ([range[i][0], range[j][0]], [range[i][1], range[j][1]]);
        if lo[0] > hi[0] || lo[1] > hi[1] {
            continue;
        }
        let (pa, pb) = ([a[i], a[j]], [b[i], b[j]]);
        if segment_clear_of_grid(&pa, &pb, lo, hi) {
            continue;
        }
        if segment_through_grid(&pa, &pb, lo, hi) {
            // a grid point, at neither end
            return Some((false, false));
        }
        if let Some(g) = grid_point_near_segment(&pa, &pb) {
            return Some((dist2d_below_eps(&g, &pa), dist2d_below_eps(&g, &pb)));
        }
    }
    None
}

pub use crate::simplex::face_corners;

/// The edges of a tet as corner pairs, in the order of the reference scan.
pub const EDGES: [[usize; 2]; 6] = [[0, 1], [0, 2], [0, 3], [1, 2], [1, 3], [2, 3]];
/// The edges (indices into [`EDGES`]) of face `f` (opposite corner `f`).
pub const FACE_EDGES: [[usize; 3]; 4] = [[3, 4, 5], [1, 2, 5], [0, 2, 4], [0, 1, 3]];

fn sub(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [a[0] - b[0], a[1] - b[1], a[2] - b[2]]
}

fn cross(a: &[f64; 3], b: &[f64; 3]) -> [f64; 3] {
    [
        a[1] * b[2] - a[2] * b[1],
        a[2] * b[0] - a[0] * b[2],
        a[0] * b[1] - a[1] * b[0],
    ]
}

fn dot(a: &[f64; 3], b: &[f64; 3]) -> f64 {
    a[0] * b[0] + a[1] * b[1] + a[2] * b[2]
}

/// Whether an integer point lies within [`EPS`] of triangle `t`'s plane and
/// strictly inside it, farther than [`EPS`] from its edges (grid points
/// near an edge are the edge's problem). Zero-area triangles: `false`.
pub fn triangle_near_grid_point(t: &[[f64; 3]; 3]) -> bool {
    let n = cross(&sub(&t[1], &t[0]), &sub(&t[2], &t[0]));
    let len = dot(&n, &n).sqrt();
    if len == 0.0 || !len.is_finite() {
        return false;
    }
    // iterate the plane of the two axes other than the dominant normal one
    let z = (0..3).fold(0, |m, k| if n[k].abs() > n[m].abs() { k } else { m });
    let (x, y) = ((z + 1) % 3, (z + 2) % 3);
    let lo = |k: usize| ceil(t.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min)) as i64;
    let hi = |k: usize| floor(t.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max)) as i64;
    for gx in lo(x)..=hi(x) {
        for gy in lo(y)..=hi(y) {
            let mut g = [0.0; 3];
            g[x] = gx as f64;
            g[y] = gy as f64;
            g[z] = t[0][z] - (n[x] * (g[x] - t[0][x]) + n[y] * (g[y] - t[0][y])) / n[z];
            g[z] = round(g[z]);
            if dot(&sub(&g, &t[0]), &n).abs() / len >= EPS {
                continue;
            }
            let inside = (0..3).all(|i| {
                let (a, b) = (t[(i + 1) % 3], t[(i + 2) % 3]);
                let c = cross(&sub(&a, &g), &sub(&b, &g));
                let e = sub(&b, &a);
                // signed distance of g to edge a–b, in the plane
                dot(&c, &n) / (len * dot(&e, &e).sqrt()) > EPS
            });
            if inside {
                return true;
            }
        }
    }
    false
}

/// Whether [`triangle_near_grid_point`] certainly returns `false` for `t`,
/// whose box, grown by `2·EPS`, holds the integers `lo[k]..=hi[k]` on axis
/// `k` (from the boxes of its corners, [`crate::boxes::Boxes::range`]).
///
/// A grid point that test accepts lies within `EPS` of `t`'s plane (by
/// its computed normal `n`) and the line through it along `n` pierces `t`
/// more than `EPS` inside its edges, so it lies within `EPS + diam·sin θ`
/// of `t`, `θ` the angle between `n` and the exact normal: inside the
/// grown box when `diam·sin θ < EPS`. The rounding error of `n` (from
/// differences of the corners, one rounding each) is below `1.5e-15·E²`
/// (`E` the largest coordinate difference to `t[0]`, `diam ≤ 3.5·E`), so
/// `|n| > 1e-3·E³` keeps `diam·sin θ` below `6e-12`, and the rounding
/// errors of the test's own distances (its points within `6·E` of the
/// corners) stay below `1e-10`, far from `EPS`. When the box
/// holds one integer point `g` and `|(g − t₀)·n| > 3·EPS·|n|`, computed
/// as the test computes it, the test's `|(g − t₀)·n| / |n| ≥ EPS` skips
/// `g`. `false` when unsure (a coordinate of 1024 or more, more than one
/// point, a thin or tiny triangle).
#[inline]
pub fn triangle_clear_of_grid(t: &[[f64; 3]; 3], lo: [f64; 3], hi: [f64; 3]) -> bool {
    const SMALL: f64 = 1024.0;
    let big = max_abs(max_abs(max_abs(0.0, &t[0]), &t[1]), &t[2]);
    // one point per axis (a NaN corner gives a NaN `nn` below)
    let one_point = lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2];
    if !(big < SMALL && one_point) {
        return false;
    }
    let (e1, e2) = (sub(&t[1], &t[0]), sub(&t[2], &t[0]));
    let n = cross(&e1, &e2);
    let nn = dot(&n, &n);
    let e = max_abs(max_abs(0.0, &e1), &e2);
    let thin = 1e-3 * e * e * e;
    if !(nn > thin * thin && nn > 1e-200) {
        return false;
    }
    let s = dot(&sub(&lo, &t[0]), &n);
    s * s > 9.0 * EPS * EPS * nn
}

/// The greatest of `m` and the magnitudes of `v` (not NaN).
#[inline]
fn max_abs(m: f64, v: &[f64; 3]) -> f64 {
    let (a, b, c) = (v[0].abs(), v[1].abs(), v[2].abs());
    let m = if a > m { a } else { m };
    let m = if b > m { b } else { m };
    if c > m {
        c
    } else {
        m
    }
}

/// Vertices on an iso-surface, endpoints of edges on an iso-line (not at
/// the grid point's own endpoint), and corners of faces on a grid point.
pub fn bad_vertices(map: &TetMap, coords: &[[[f64; 3]; 4]]) -> Vec<u32> {
    let mut bad = vec![false; map.positions.len()];
    for (s, tet) in map.simplices.iter().enumerate() {
        let c = &coords[s];
        for k in 0..4 {
            if c[k].iter().any(|&x| near_int(x)) {
                bad[tet[k] as usize] = true;
            }
            for l in k + 1..4 {
                if let Some((at_k, at_l)) = segment_near_iso_line(&c[k], &c[l]) {
                    bad[tet[k] as usize] |= at_k || !at_l;
                    bad[tet[l] as usize] |= at_l || !at_k;
                }
            }
        }
        for f in 0..4 {
            let fc = face_corners(f);
            if triangle_near_grid_point(&fc.map(|i| c[i])) {
                fc.iter().for_each(|&i| bad[tet[i] as usize] = true);
            }
        }
    }
    (0..bad.len() as u32).filter(|&v| bad[v as usize]).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn segment_through_iso_line_is_detected_for_each_axis_pair() {
        // moving along a diagonal through (1, 1, z) for every pair
        for k in 0..3 {
            let mut a = [0.3; 3];
            let mut b = [1.7; 3];
            a[k] = 0.2;
            b[k] = 0.4; // the third coordinate is free
            let (i, j) = ((k + 1) % 3, (k + 2) % 3);
            a[i] = 0.5;
            a[j] = 0.5;
            b[i] = 1.5;
            b[j] = 1.5;
            assert_eq!(
                segment_near_iso_line(&a, &b),
                Some((false, false)),
                "pair {k}"
            );
        }
        assert_eq!(
            segment_near_iso_line(&[0.5, 0.6, 0.3], &[1.5, 1.7, 0.4]),
            None
        );
        // the grid point at an endpoint
        assert_eq!(
            segment_near_iso_line(&[1.0, 2.0, 0.3], &[1.5, 1.7, 0.4]),
            Some((true, false))
        );
    }

    #[test]
    fn face_on_grid_point_is_detected_only_inside() {
        let t = [[0.2, 0.3, 1.0], [2.2, 0.4, 1.0], [0.5, 2.1, 1.0]];
        assert!(triangle_near_grid_point(&t)); // (1, 1, 1)
        let lifted = t.map(|p| [p[0], p[1], 1.1]);
        assert!(!triangle_near_grid_point(&lifted));
        // tilted plane through (1,1,1)
        let tilt = [[0.0, 0.0, 0.8], [2.5, 0.0, 1.3], [0.0, 2.5, 0.8]];
        assert!(triangle_near_grid_point(&tilt));
        // grid point on an edge: not the face's problem
        let edge = [[0.0, 1.0, 1.0], [2.0, 1.0, 1.0], [1.0, 1.8, 1.0]];
        assert!(!triangle_near_grid_point(&edge));
    }
}
