//! Exact replacements for `f64::round` and `f64::floor` followed by a cast,
//! which compile to libm calls on baseline x86-64 (no SSE4.1 `roundsd`):
//! hot loops of the map stage use these instead.
//!
//! Input: any `f64`. Output: the same value as the std operation (up to the
//! sign of a zero result for [`round_half_away`]); see the tests.

/// `x.round()` (half away from zero) up to the sign of a zero result,
/// without the libm call that `f64::round` is on baseline x86-64: below
/// 2^52 the truncation `x as i64` is exact, and so are `x − t` and `t ± 1`;
/// from 2^52 on every float is an integer.
#[inline]
pub(crate) fn round_half_away(x: f64) -> f64 {
    if x.is_nan() || x.abs() >= 4_503_599_627_370_496.0 {
        return x; // |x| ≥ 2^52 (already integral), or NaN
    }
    let t = (x as i64) as f64;
    let d = x - t;
    if d >= 0.5 {
        t + 1.0
    } else if d <= -0.5 {
        t - 1.0
    } else {
        t
    }
}

/// `x.floor() as i64` without the libm call that `f64::floor` is on
/// baseline x86-64: the truncation `x as i64` (saturating, like the cast of
/// the floor) minus one for a negative non-integer.
#[inline]
pub(crate) fn floor_i64(x: f64) -> i64 {
    let t = x as i64;
    if (t as f64) > x && t != i64::MIN {
        t - 1
    } else {
        t
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::rng::SplitMix;

    #[test]
    fn round_half_away_is_round() {
        let mut xs = vec![
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.5,
            -2.5,
            0.49999999999999994,
            -0.49999999999999994,
            4503599627370495.5,
            -4503599627370495.5,
            4503599627370496.0,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
        ];
        let mut rng = SplitMix::new(7);
        for _ in 0..10000 {
            let e = rng.below(60) as i32 - 20;
            xs.push((rng.unit() - 0.5) * 2f64.powi(e));
            xs.push(xs[xs.len() - 1].floor() + 0.5);
        }
        for x in xs {
            let (r, want) = (round_half_away(x), x.round());
            assert!(r == want, "{x}: {r} vs {want}");
        }
        assert!(round_half_away(f64::NAN).is_nan());
    }

    #[test]
    fn floor_i64_is_the_cast_floor() {
        let mut xs = vec![
            0.0,
            -0.0,
            -0.5,
            0.5,
            -1.0,
            -1.5,
            2.0,
            -1e-300,
            4503599627370495.5,
            -4503599627370495.5,
            9.3e18,
            -9.3e18,
            i64::MIN as f64,
            1e300,
            -1e300,
            f64::INFINITY,
            f64::NEG_INFINITY,
            f64::NAN,
        ];
        let mut rng = SplitMix::new(3);
        for _ in 0..10000 {
            let e = rng.below(80) as i32 - 20;
            xs.push((rng.unit() - 0.5) * 2f64.powi(e));
        }
        for x in xs {
            assert_eq!(floor_i64(x), x.floor() as i64, "{x}");
        }
    }
}
