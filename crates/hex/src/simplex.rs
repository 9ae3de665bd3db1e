//! Exact-as-possible predicates on one tet image, shared by the steps:
//! barycentric coordinates of a point, and where an axis-parallel line
//! pierces the faces.
//!
//! Numbering (as in `dualex_map::mesh`): face `f` of a tet is opposite
//! corner `f`; its corners are `(f+1, f+2, f+3) mod 4`.
//!
//! An **axis line** is `{x : x[b] = vb, x[c] = vc}` for the two fixed axes
//! `b < c` (the moving axis `a` is the third). It pierces face `f` iff the
//! point `(vb, vc)` lies strictly inside the projection of the face's
//! triangle onto the `(b, c)` plane (three 2D orientations of one strict
//! sign); the moving coordinate there is the barycentric interpolation.

/// The two fixed axes when `a` moves, in increasing order.
#[inline]
pub fn fixed_axes(a: usize) -> [usize; 2] {
    match a {
        0 => [1, 2],
        1 => [0, 2],
        _ => [0, 1],
    }
}

/// Corners of face `f` (the face opposite corner `f`).
#[inline]
pub fn face_corners(f: usize) -> [usize; 3] {
    [(f + 1) % 4, (f + 2) % 4, (f + 3) % 4]
}

/// Signed 6× volume of a tet image.
#[inline]
pub fn det(p: &[[f64; 3]; 4]) -> f64 {
    dualex_map::mesh::det_of::<4, 3>(p)
}

/// Unnormalised barycentric coordinates of `q`: `w[c]` is the determinant
/// of the tet with corner `c` replaced by `q` (`Σ w = det`).
pub fn bary_weights(p: &[[f64; 3]; 4], q: &[f64; 3]) -> [f64; 4] {
    std::array::from_fn(|c| {
        let mut r = *p;
        r[c] = *q;
        det(&r)
    })
}

/// A face pierced by an axis line: the face and the moving coordinate there.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Pierce {
    /// The face (opposite corner).
    pub face: usize,
    /// The moving coordinate at the piercing point.
    pub at: f64,
}

/// The faces of `p` pierced by the axis line along `a` with fixed values
/// `val` (indexed by axis; the entry of `a` is ignored): at most 4, usually
/// 0 or 2. Returns them and their number.
pub fn pierced(p: &[[f64; 3]; 4], a: usize, val: &[i64; 3]) -> ([Pierce; 4], usize) {
    let [b, c] = fixed_axes(a);
    let (vb, vc) = (val[b] as f64, val[c] as f64);
    let mut out = [Pierce { face: 0, at: 0.0 }; 4];
    let mut n = 0;
    for f in 0..4 {
        let k = face_corners(f);
        let q = k.map(|i| [p[i][b] - vb, p[i][c] - vc]);
        let lam: [f64; 3] = std::array::from_fn(|i| {
            let (u, v) = (q[(i + 1) % 3], q[(i + 2) % 3]);
            u[0] * v[1] - u[1] * v[0]
        });
        let pos = lam.iter().all(|&l| l > 0.0);
        if pos || lam.iter().all(|&l| l < 0.0) {
            let sum = lam[0] + lam[1] + lam[2];
            let at = (0..3).map(|i| lam[i] * p[k[i]][a]).sum::<f64>() / sum;
            out[n] = Pierce { face: f, at };
            n += 1;
        }
    }
    (out, n)
}

#[cfg(test)]
mod tests {
    use super::*;

    const UNIT: [[f64; 3]; 4] = [
        [0.0, 0.0, 0.0],
        [1.0, 0.0, 0.0],
        [0.0, 1.0, 0.0],
        [0.0, 0.0, 1.0],
    ];

    #[test]
    fn weights_sum_to_det_and_vanish_on_faces() {
        let q = [0.1, 0.2, 0.3];
        let w = bary_weights(&UNIT, &q);
        assert!((w.iter().sum::<f64>() - det(&UNIT)).abs() < 1e-15);
        assert!((w[1] - 0.1).abs() < 1e-15 && (w[2] - 0.2).abs() < 1e-15);
        assert!((w[3] - 0.3).abs() < 1e-15 && (w[0] - 0.4).abs() < 1e-15);
    }

    #[test]
    fn axis_line_pierces_two_faces_in_every_direction() {
        // a tet shifted so no line below hits an edge
        let p = UNIT.map(|c| [c[0] * 4.0 - 0.3, c[1] * 4.0 - 0.2, c[2] * 4.0 - 0.1]);
        for a in 0..3 {
            let val = [0, 0, 0];
            let (hits, n) = pierced(&p, a, &val);
            assert_eq!(n, 2, "axis {a}");
            // the two points are on the line through the origin, inside the tet
            let (lo, hi) = (hits[0].at.min(hits[1].at), hits[0].at.max(hits[1].at));
            assert!(lo < 0.0 && hi > 0.0, "axis {a}: {hits:?}");
        }
        // a mirrored tet gives the same faces
        let mut m = p;
        m.swap(0, 1);
        let (_, n) = pierced(&m, 0, &[0, 0, 0]);
        assert_eq!(n, 2);
        // a line outside the tet pierces nothing
        assert_eq!(pierced(&p, 2, &[5, 5, 0]).1, 0);
    }
}
