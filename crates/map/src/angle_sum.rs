//! The index of a fold-free 2D one-ring in quarters, from its angle sum,
//! without a library `atan2` per corner on the common path.
//!
//! Input: the ring's triangles' map coordinates and the vertex's corner in
//! each (any finite values). Output: `round(4·(2π − Σ angles) / 2π)` with
//! `Σ` the sum, in ring order, of `atan2(cross, dot)` of each corner's
//! edge vectors: exactly what the sum of library `atan2`s gives
//! ([`quarters_exact`]).
//!
//! Invariant: the fast path sums [`atan2_approx`] (error below
//! [`ERR`] per corner, tested on a dense sweep) and keeps its rounding
//! only when the value lies farther than the summed error bound from a
//! rounding boundary (a half-integer); otherwise — and for a zero edge
//! vector, a corner on the branch cut or an overflow — the library sum
//! decides. A one-ring's value is an integer up to its float noise
//! (Gauss–Bonnet: the angles of a closed fan sum to `2π·(1 − index)`), far
//! from every half-integer, so the fallback is rare.

/// Bound on `|atan2_approx(y, x) − atan2(y, x)|` (the polynomial's error
/// is below 1e-5; ten times that, for the float noise of the reduction).
pub(crate) const ERR: f64 = 1e-4;

/// The edge vectors' `(cross, dot)` at corner `c` of triangle `p`.
#[inline]
fn corner_terms(p: &[[f64; 2]; 3], c: usize) -> (f64, f64) {
    let (o, a, b) = (p[c], p[(c + 1) % 3], p[(c + 2) % 3]);
    let e1 = [a[0] - o[0], a[1] - o[1]];
    let e2 = [b[0] - o[0], b[1] - o[1]];
    (e1[0] * e2[1] - e1[1] * e2[0], e1[0] * e2[0] + e1[1] * e2[1])
}

/// Signed angle of the map image of triangle `p` at corner `c`.
pub(crate) fn corner_angle(p: &[[f64; 2]; 3], c: usize) -> f64 {
    let (y, x) = corner_terms(p, c);
    y.atan2(x)
}

/// `atan2(y, x)` within [`ERR`] for `y ≠ 0` and finite `y`, `x` (not
/// both zero): an odd polynomial in `min/max` of the magnitudes, reflected
/// into the right octant; `None` where it is not used (`y == 0`, the
/// branch cut's side follows the sign of zero; or not finite).
#[inline]
pub(crate) fn atan2_approx(y: f64, x: f64) -> Option<f64> {
    let (ay, ax) = (y.abs(), x.abs());
    if y == 0.0 || !(y.is_finite() && x.is_finite()) {
        return None;
    }
    let (lo, hi) = (ay.min(ax), ay.max(ax));
    let t = lo / hi;
    let t2 = t * t;
    let mut a = t
        * (0.999_977_26
            + t2 * (-0.332_623_47
                + t2 * (0.193_543_46
                    + t2 * (-0.116_432_87 + t2 * (0.052_653_32 - t2 * 0.011_721_2)))));
    if ay > ax {
        a = std::f64::consts::FRAC_PI_2 - a;
    }
    if x < 0.0 {
        a = std::f64::consts::PI - a;
    }
    Some(a.copysign(y))
}

/// The quarters from the library's angle sum (module docs).
pub(crate) fn quarters_exact<'a>(ring: impl Iterator<Item = (&'a [[f64; 2]; 3], usize)>) -> i64 {
    let angles: f64 = ring.map(|(p, c)| corner_angle(p, c)).sum();
    let tau = std::f64::consts::TAU;
    (4.0 * (tau - angles) / tau).round() as i64
}

/// [`quarters_exact`] of the ring `ring` (triangle, corner), through the
/// fast path when its rounding is certain (module docs).
pub(crate) fn quarters<'a>(ring: impl Iterator<Item = (&'a [[f64; 2]; 3], usize)> + Clone) -> i64 {
    let tau = std::f64::consts::TAU;
    let (mut sum, mut n) = (0.0, 0usize);
    for (p, c) in ring.clone() {
        let (y, x) = corner_terms(p, c);
        let Some(a) = atan2_approx(y, x) else {
            return quarters_exact(ring);
        };
        sum += a;
        n += 1;
    }
    let v = 4.0 * (tau - sum) / tau;
    let r = v.round();
    // the value's error: 4/2π < 1 times the summed error, plus the noise
    // of the sum and the scaling
    let margin = n as f64 * ERR + 1e-9;
    if (v - r).abs() < 0.5 - margin {
        r as i64
    } else {
        quarters_exact(ring)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_maps::Lcg;

    /// The polynomial within a tenth of [`ERR`] over a dense sweep of
    /// directions, near the axes and diagonals included.
    #[test]
    fn approx_within_bound() {
        let mut worst = 0.0f64;
        let n = 200_000;
        for i in 0..n {
            let th = -std::f64::consts::PI + (i as f64 + 0.5) * std::f64::consts::TAU / n as f64;
            for r in [1e-200, 1e-3, 1.0, 7.5e5, 1e250] {
                let (y, x) = (r * th.sin(), r * th.cos());
                if let Some(a) = atan2_approx(y, x) {
                    worst = worst.max((a - y.atan2(x)).abs());
                }
            }
        }
        for (y, x) in [
            (1.0, 1.0),
            (1.0, -1.0),
            (-1.0, -1.0),
            (1e-300, -1.0),
            (-1e-300, -1.0),
        ] {
            let a = atan2_approx(y, x).expect("used");
            worst = worst.max((a - f64::atan2(y, x)).abs());
        }
        assert!(worst < ERR / 10.0, "{worst}");
        assert_eq!(atan2_approx(0.0, -1.0), None);
        assert_eq!(atan2_approx(-0.0, 1.0), None);
        assert_eq!(atan2_approx(1.0, f64::INFINITY), None);
        assert_eq!(atan2_approx(f64::NAN, 1.0), None);
        assert_eq!(atan2_approx(1.0, f64::NAN), None);
    }

    /// A fan of `k` triangles around the origin with the given angles
    /// (the last closing the turn), corner 0 at the centre.
    fn fan(angles: &[f64], radius: &[f64]) -> Vec<[[f64; 2]; 3]> {
        let mut at = 0.0f64;
        let mut out = Vec::new();
        for (i, &a) in angles.iter().enumerate() {
            let (r0, r1) = (radius[i], radius[(i + 1) % radius.len()]);
            let p = [r0 * at.cos(), r0 * at.sin()];
            at += a;
            let q = [r1 * at.cos(), r1 * at.sin()];
            out.push([[0.0, 0.0], p, q]);
        }
        out
    }

    /// The fast path's quarters equal the library sum's: random fans whose
    /// angles sum to every multiple of a quarter turn and to values near
    /// the half-quarters (the rounding boundaries), folded corners and
    /// collapsed ones included.
    #[test]
    fn same_quarters_as_the_library_sum() {
        let mut rng = Lcg(11);
        let mut fallbacks = 0;
        for case in 0..20_000 {
            let k = 3 + rng.below(9) as usize;
            // the target sum: a multiple of π/2, shifted near a boundary
            // (π/4 off) in some cases, by a tiny amount in others
            let q = rng.below(13) as f64 - 2.0;
            let mut total = std::f64::consts::FRAC_PI_2 * (4.0 - q);
            match case % 4 {
                1 => total += std::f64::consts::FRAC_PI_4,
                2 => {
                    total += std::f64::consts::FRAC_PI_4 + (rng.below(2001) as f64 - 1000.0) * 1e-7
                }
                3 => total += (rng.below(2001) as f64 - 1000.0) * 1e-3,
                _ => {}
            }
            let w: Vec<f64> = (0..k).map(|_| 1.0 + rng.below(100) as f64).collect();
            let sw: f64 = w.iter().sum();
            let angles: Vec<f64> = w.iter().map(|x| total * x / sw).collect();
            let radius: Vec<f64> = (0..k)
                .map(|_| 0.1 + rng.below(1000) as f64 * 1e-2)
                .collect();
            let mut tris = fan(&angles, &radius);
            if case % 7 == 0 {
                let j = rng.below(k as u64) as usize;
                tris[j][1] = tris[j][0];
            }
            let ring = tris.iter().map(|p| (p, 0usize));
            let want = quarters_exact(ring.clone());
            assert_eq!(quarters(ring.clone()), want, "case {case}");
            let sum: f64 = ring.clone().map(|(p, c)| corner_angle(p, c)).sum();
            let v = 4.0 * (std::f64::consts::TAU - sum) / std::f64::consts::TAU;
            fallbacks += usize::from((v - v.round()).abs() > 0.45);
        }
        assert!(fallbacks > 1000, "{fallbacks}");
    }
}
