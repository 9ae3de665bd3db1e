//! The compile-time table of [`crate::pow5`] against its definition,
//! checked where `u128` arithmetic (and one 192-bit product) suffices:
//! `q` in `0..=55` exactly, `q` in `-27..=-1` by the bounds that define
//! `⌊2^(z+127) / 5^n⌋ + 1`, and the top bit of every entry.

use crate::pow5::{MAX_Q, MIN_Q, POW5};

/// `T(q)` as one number.
fn entry(q: i32) -> u128 {
    let (hi, lo) = POW5[(q - MIN_Q) as usize];
    u128::from(hi) << 64 | u128::from(lo)
}

/// `t · p` as `(high 64 bits, low 128 bits)`.
fn mul_192(t: u128, p: u64) -> (u64, u128) {
    let lo = (t & u128::from(u64::MAX)) * u128::from(p);
    let hi = (t >> 64) * u128::from(p) + (lo >> 64);
    ((hi >> 64) as u64, hi << 64 | (lo & u128::from(u64::MAX)))
}

#[test]
fn every_entry_has_its_top_bit_set() {
    for q in MIN_Q..=MAX_Q {
        assert!(entry(q) >> 127 == 1, "q = {q}");
    }
}

#[test]
fn small_positive_powers_are_exact() {
    for q in 0..=55u32 {
        let p = 5u128.pow(q);
        assert_eq!(entry(q as i32), p << p.leading_zeros(), "q = {q}");
    }
}

#[test]
fn small_negative_powers_are_the_rounded_up_reciprocals() {
    for n in 1..=27u32 {
        let p = 5u64.pow(n);
        let z = 64 - p.leading_zeros(); // 2^(z-1) < 5^n < 2^z
                                        // T = ⌊2^(z+127) / p⌋ + 1 ⇔ T·p > 2^(z+127) ≥ (T-1)·p
        let t = entry(-(n as i32));
        let (hi, lo) = mul_192(t, p);
        let (hi1, lo1) = mul_192(t - 1, p);
        // 2^(z+127) as (high 64, low 128): z + 127 ≥ 128
        let bound = (1u64 << (z - 1), 0u128);
        assert!((hi, lo) > bound, "n = {n}");
        assert!((hi1, lo1) <= bound, "n = {n}");
    }
}
