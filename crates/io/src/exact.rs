//! `w · 10^q` correctly rounded to an `f64`, for a decimal mantissa `w` of
//! at most 19 digits, when it can be decided cheaply.
//!
//! Input: `w > 0`, `q`. Output: the `f64` nearest to `w · 10^q` (ties to
//! even), or `None` when the result is subnormal, overflows, or lies so
//! close to a tie that the 128-bit product cannot decide: the caller then
//! asks `str::parse`. Invariant: a `Some` is the correctly rounded value,
//! hence the bits `str::parse` gives.
//!
//! Clinger's fast path first (`w ≤ 2^53`, `|q| ≤ 22`: one exact operand and
//! one correctly rounded `f64` multiplication or division), then the
//! Eisel–Lemire algorithm (Lemire, "Number parsing at a gigabyte per
//! second", 2021): `w`, normalized, times the 128-bit `5^q` of
//! [`crate::pow5`], keeping the high 128 bits of the product. For
//! `-307 ≤ q ≤ 288` the result is neither subnormal nor infinite for any
//! `w`, so that path skips both checks and adds the rounded mantissa to
//! the exponent field (a rounding carry then raises the exponent).

use crate::pow5::{MIN_Q, POW5};

/// `10^k` for `k ≤ 22`: exact as `f64`.
const POW10: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// Bits of the explicit mantissa of an `f64`.
const MANTISSA_BITS: u32 = 52;
/// The biased exponent of infinity.
const INFINITE_POWER: i32 = 0x7ff;
/// From this `q` on, `w · 10^q ≥ 10^-307` is normal for every `w ≥ 1`.
const MIN_NORMAL_Q: i32 = -307;
/// Up to this `q`, `w · 10^q < 10^19 · 10^288` is finite (and far from
/// overflow after rounding) for every `w < 2^64`.
const MAX_FINITE_Q: i32 = 288;

/// The `f64` nearest to `w · 10^q`, `w > 0` (see the module docs).
#[inline]
pub(crate) fn to_f64(w: u64, q: i32) -> Option<f64> {
    if w <= 1 << 53 && (-22..=22).contains(&q) {
        let x = w as f64;
        let p = POW10[q.unsigned_abs() as usize];
        return Some(if q < 0 { x / p } else { x * p });
    }
    eisel_lemire(w, q).map(f64::from_bits)
}

/// `⌊log2(10^q)⌋ + 63`, for `|q| ≤ 342` (217706 = `log2(10)·2^16`, rounded).
#[inline]
fn power(q: i32) -> i32 {
    ((q * 217_706) >> 16) + 63
}

/// The high 128 bits of `w · T(q)` as `(hi, lo)`; the low half of `T` is
/// used only when the high product leaves the result undecided.
#[inline]
fn product(w: u64, q: i32) -> Option<(u64, u64)> {
    let &(hi5, lo5) = POW5.get(usize::try_from(q - MIN_Q).ok()?)?;
    let first = u128::from(w) * u128::from(hi5);
    let (mut hi, mut lo) = ((first >> 64) as u64, first as u64);
    // the bits below the 54 kept (53 + a rounding bit) of the high word
    const BELOW: u64 = u64::MAX >> (MANTISSA_BITS + 3);
    if hi & BELOW == BELOW {
        let second = ((u128::from(w) * u128::from(lo5)) >> 64) as u64;
        let (sum, carry) = lo.overflowing_add(second);
        lo = sum;
        hi += u64::from(carry);
    }
    Some((hi, lo))
}

/// The leading 54 bits of `w · 10^q` (the 53 of the result and a rounding
/// bit) and the biased binary exponent of the leading one, before
/// rounding; `None` when the product cannot decide them.
struct Leading {
    mantissa: u64,
    exp2: i32,
}

/// [`Leading`] of `w · 10^q`, `w > 0`.
#[inline(always)]
fn leading(w: u64, q: i32) -> Option<Leading> {
    let lz = w.leading_zeros();
    let (hi, lo) = product(w << lz, q)?;
    if lo == u64::MAX {
        return None; // the truncated low bits may carry: undecided
    }
    let upper = (hi >> 63) as u32;
    let shift = upper + 64 - MANTISSA_BITS - 3;
    let mantissa = hi >> shift;
    if lo <= 1 && mantissa & 3 == 1 && mantissa << shift == hi {
        return None; // perhaps exactly halfway: ties to even not decided here
    }
    let exp2 = power(q) + upper as i32 - lz as i32 + 1023;
    Some(Leading { mantissa, exp2 })
}

/// The bits of the `f64` nearest to `w · 10^q` by Eisel–Lemire, or `None`
/// (see the module docs).
#[inline]
fn eisel_lemire(w: u64, q: i32) -> Option<u64> {
    if !(MIN_NORMAL_Q..=MAX_FINITE_Q).contains(&q) {
        return eisel_lemire_edges(w, q);
    }
    let Leading { mantissa, exp2 } = leading(w, q)?;
    // 1 ≤ exp2 < 0x7fe by the range of q; the mantissa, rounded, has its
    // leading bit at 2^52 (or at 2^53 when the rounding carried), and
    // adding it to the exponent field less one sets the field right
    let rounded = (mantissa + (mantissa & 1)) >> 1;
    Some((((exp2 - 1) as u64) << MANTISSA_BITS) + rounded)
}

/// [`eisel_lemire`] for `q` outside [`MIN_NORMAL_Q`]`..=`[`MAX_FINITE_Q`],
/// where the result may be subnormal or overflow.
#[cold]
fn eisel_lemire_edges(w: u64, q: i32) -> Option<u64> {
    let Leading {
        mut mantissa,
        mut exp2,
    } = leading(w, q)?;
    if exp2 <= 0 {
        return None; // subnormal
    }
    mantissa += mantissa & 1;
    mantissa >>= 1;
    if mantissa >= 2 << MANTISSA_BITS {
        mantissa = 1 << MANTISSA_BITS;
        exp2 += 1;
    }
    mantissa &= !(1 << MANTISSA_BITS);
    if exp2 >= INFINITE_POWER {
        return None; // overflow
    }
    Some(mantissa | (exp2 as u64) << MANTISSA_BITS)
}
