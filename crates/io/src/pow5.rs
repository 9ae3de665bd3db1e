//! The 128-bit powers of five of the Eisel–Lemire conversion
//! ([`crate::exact`]), computed at compile time.
//!
//! Input: none. Output: [`POW5`], for every decimal exponent `q` in
//! [`MIN_Q`]`..=`[`MAX_Q`] at index `q - MIN_Q`, the pair `(hi, lo)` of a
//! 128-bit number `T = hi·2^64 + lo` with its top bit set:
//! - `q ≥ 0`: the leading 128 bits of `5^q`, truncated;
//! - `−27 ≤ q < 0`, with `z` the bit length of `5^−q`:
//!   `⌊2^(z+127) / 5^−q⌋ + 1`;
//! - `q < −27`: `⌊2^(2z+128) / 5^−q⌋ + 1`, truncated to its leading 128 bits.
//!
//! These are the definitions of Lemire's "Number parsing at a gigabyte per
//! second" (2021), on which the conversion's error bounds rest. The exact
//! integers are formed in a 28-limb (1792-bit) integer by repeated
//! multiplication and division by 5; `pow5_tests.rs` checks entries
//! against `u128` arithmetic where it suffices.

/// The smallest decimal exponent of the table (below it every 19-digit
/// mantissa rounds to zero).
pub(crate) const MIN_Q: i32 = -342;
/// The largest decimal exponent of the table (above it every mantissa
/// rounds to infinity).
pub(crate) const MAX_Q: i32 = 308;

/// Limbs of the big integers: `2^B` with `B = 1728 ≥ 2·795 + 128` fits,
/// 795 being the bit length of `5^342`.
const LIMBS: usize = 28;
/// The exponent of the dividend `2^B`.
const B: u32 = 1728;

/// A little-endian unsigned big integer.
type Big = [u64; LIMBS];

/// `x · 5`.
const fn mul5(mut x: Big) -> Big {
    let mut carry = 0u128;
    let mut i = 0;
    while i < LIMBS {
        let p = x[i] as u128 * 5 + carry;
        x[i] = p as u64;
        carry = p >> 64;
        i += 1;
    }
    x
}

/// `⌊x / 5⌋`.
const fn div5(mut x: Big) -> Big {
    let mut rem = 0u128;
    let mut i = LIMBS;
    while i > 0 {
        i -= 1;
        let cur = (rem << 64) | x[i] as u128;
        x[i] = (cur / 5) as u64;
        rem = cur % 5;
    }
    x
}

/// `x + 1`.
const fn add_one(mut x: Big) -> Big {
    let mut i = 0;
    while i < LIMBS {
        x[i] = x[i].wrapping_add(1);
        if x[i] != 0 {
            break;
        }
        i += 1;
    }
    x
}

/// The number of significant bits of `x`.
const fn bit_len(x: &Big) -> u32 {
    let mut i = LIMBS;
    while i > 0 {
        i -= 1;
        if x[i] != 0 {
            return i as u32 * 64 + 64 - x[i].leading_zeros();
        }
    }
    0
}

/// `⌊x / 2^s⌋`.
const fn shr(x: &Big, s: u32) -> Big {
    let mut out = [0u64; LIMBS];
    let (limbs, bits) = ((s / 64) as usize, s % 64);
    let mut i = 0;
    while i + limbs < LIMBS {
        let lo = x[i + limbs] >> bits;
        let hi = if bits > 0 && i + limbs + 1 < LIMBS {
            x[i + limbs + 1] << (64 - bits)
        } else {
            0
        };
        out[i] = lo | hi;
        i += 1;
    }
    out
}

/// The low 128 bits of `x`.
const fn low128(x: &Big) -> u128 {
    (x[1] as u128) << 64 | x[0] as u128
}

/// The leading 128 bits of `x` (`x` shifted up when it has fewer).
const fn top128(x: &Big) -> u128 {
    let n = bit_len(x);
    if n > 128 {
        low128(&shr(x, n - 128))
    } else {
        low128(x) << (128 - n)
    }
}

/// `T` for `q = −n`, `n ≥ 1`, given `r = ⌊2^B / 5^n⌋` and `z`, the bit
/// length of `5^n` (the module docs).
const fn negative_entry(r: &Big, z: u32, n: u32) -> u128 {
    if n <= 27 {
        low128(&add_one(shr(r, B - z - 127)))
    } else {
        top128(&add_one(shr(r, B - 2 * z - 128)))
    }
}

/// `(hi, lo)` of a 128-bit number.
const fn split(t: u128) -> (u64, u64) {
    ((t >> 64) as u64, t as u64)
}

/// The table (the module docs).
const fn table() -> [(u64, u64); (MAX_Q - MIN_Q + 1) as usize] {
    let mut out = [(0u64, 0u64); (MAX_Q - MIN_Q + 1) as usize];
    let zero = (-MIN_Q) as usize;
    let mut power = [0u64; LIMBS]; // 5^n
    power[0] = 1;
    let mut r = [0u64; LIMBS]; // ⌊2^B / 5^n⌋
    r[(B / 64) as usize] = 1 << (B % 64);
    let mut n = 0u32;
    while n as usize <= zero {
        if n as i32 <= MAX_Q {
            out[zero + n as usize] = split(top128(&power));
        }
        if n > 0 {
            out[zero - n as usize] = split(negative_entry(&r, bit_len(&power), n));
        }
        power = mul5(power);
        r = div5(r);
        n += 1;
    }
    out
}

/// `(hi, lo)` of `T(q)` at index `q - MIN_Q` (the module docs).
pub(crate) static POW5: [(u64, u64); (MAX_Q - MIN_Q + 1) as usize] = table();
