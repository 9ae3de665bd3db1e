//! Libm-free exact rounding: `f64::round`, `ceil` and `floor` bit for bit
//! (sign of zero included) without a library call on the common path
//! (they are library calls on the baseline x86-64 target, and the hot
//! loops of the map model and of the segmentation round every coordinate).
//!
//! Input: any `f64` (NaN and infinities included). Output: exactly what
//! `std` returns. Invariant: below [`FAST`] in magnitude the result comes
//! from one exact addition ([`nearest_even`]); above it, from `std`. The
//! bit-for-bit tests over the boundary values live with the grid tests of
//! `dualex-segment` (`grid::tests`), which also check its closeness test.

/// 2^51: below it in magnitude, [`nearest_even`] is exact.
pub const FAST: f64 = 2_251_799_813_685_248.0;
/// 1.5·2^52: `(x + MAGIC) − MAGIC` lands in `[2^52, 2^53)`, where the
/// spacing of doubles is 1, so the addition rounds `x` to an integer.
const MAGIC: f64 = 6_755_399_441_055_744.0;

/// The integer nearest to `x` (ties to even) for `|x| < 2^51`, as `+0.0`
/// when zero.
#[inline]
pub fn nearest_even(x: f64) -> f64 {
    (x + MAGIC) - MAGIC
}

/// `x.round()`, bit for bit (sign of zero included), without a library call
/// on the common path.
#[inline]
pub fn round(x: f64) -> f64 {
    if x.abs() < FAST {
        return round_small(x);
    }
    x.round()
}

/// `x.round()`, bit for bit, for `|x| <` [`FAST`] (the caller's check;
/// other values give a wrong result, never a panic), without a library
/// call: the nearest even integer `r`, moved one step away from zero at a
/// tie (`x − r = ±½`, exact) where `r` lies on zero's side of `x`
/// (`f64::round` rounds ties away from zero); the sign of `x` on a zero.
#[inline]
pub fn round_small(x: f64) -> f64 {
    let r = nearest_even(x);
    let t = x - r;
    let inward_tie = t.abs() == 0.5 && t * x > 0.0;
    let r = if inward_tie { r + 2.0 * t } else { r };
    r.copysign(x)
}

/// `x.ceil()`, bit for bit (see [`round`]).
#[inline]
pub fn ceil(x: f64) -> f64 {
    if x.abs() < FAST {
        let r = nearest_even(x);
        let c = if r < x { r + 1.0 } else { r };
        return c.copysign(x);
    }
    x.ceil()
}

/// `x.floor()`, bit for bit (see [`round`]).
#[inline]
pub fn floor(x: f64) -> f64 {
    if x.abs() < FAST {
        let r = nearest_even(x);
        let f = if r > x { r - 1.0 } else { r };
        return f.copysign(x);
    }
    x.floor()
}
