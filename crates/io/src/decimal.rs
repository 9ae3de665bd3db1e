//! Decimal text to `f64` for the fast paths, parsed where it lies.
//!
//! Input: bytes starting with a field (a field ends at ASCII whitespace or
//! at the end of the bytes). Output: the value `str::parse::<f64>` gives
//! for the field and the field's length, or `None` when `str::parse`
//! refuses it. Invariant: the same bits and the same decision as
//! `str::parse` for every field (`float_tests.rs`): the common forms
//! (`[+-]digits[.digits][e[+-]digits]`, at most 19 digits) are converted
//! here by exact integer and float operations, everything else is handed
//! to `str::parse`.
//!
//! Exact conversions (each a single correctly rounded operation on exact
//! operands, so the result is the correctly rounded value, which is what
//! `str::parse` returns): `m · 10^e` or `m / 10^-e` with `m ≤ 2^53` and
//! `|e| ≤ 22` (Clinger's fast path); `m · 10^e` when it fits in a `u64`;
//! `m / 10^k` with `k ≤ 19` by a 128-bit integer division whose quotient
//! keeps 63–64 bits and whose remainder becomes a sticky bit.

/// `10^k` for `k ≤ 22`: exact as `f64`.
const POW10_F64: [f64; 23] = [
    1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15, 1e16,
    1e17, 1e18, 1e19, 1e20, 1e21, 1e22,
];

/// `10^k` for `k ≤ 19`: every power of ten below `2^64`.
const POW10_U64: [u64; 20] = {
    let mut t = [1u64; 20];
    let mut k = 1;
    while k < 20 {
        t[k] = t[k - 1] * 10;
        k += 1;
    }
    t
};

/// Whether the 8 bytes of `v` (little-endian) are all ASCII digits.
#[inline]
fn is_8digits(v: u64) -> bool {
    let a = v.wrapping_add(0x4646_4646_4646_4646);
    let b = v.wrapping_sub(0x3030_3030_3030_3030);
    (a | b) & 0x8080_8080_8080_8080 == 0
}

/// The value of 8 ASCII digits loaded little-endian (first digit lowest).
#[inline]
fn parse_8digits(mut v: u64) -> u64 {
    const MASK: u64 = 0x0000_00FF_0000_00FF;
    const MUL1: u64 = 0x000F_4240_0000_0064;
    const MUL2: u64 = 0x0000_2710_0000_0001;
    v = v.wrapping_sub(0x3030_3030_3030_3030);
    v = v.wrapping_mul(10).wrapping_add(v >> 8);
    let v1 = (v & MASK).wrapping_mul(MUL1);
    let v2 = ((v >> 16) & MASK).wrapping_mul(MUL2);
    u64::from((v1.wrapping_add(v2) >> 32) as u32)
}

/// Reads decimal digits at `b[*i..]` into `m` (wrapping: the caller
/// refuses more than 19 digits); returns how many.
#[inline]
fn digits(b: &[u8], i: &mut usize, m: &mut u64) -> usize {
    let start = *i;
    while let Some(v) = b.get(*i..*i + 8).and_then(|s| s.try_into().ok()) {
        let v = u64::from_le_bytes(v);
        if !is_8digits(v) {
            break;
        }
        *m = m.wrapping_mul(100_000_000).wrapping_add(parse_8digits(v));
        *i += 8;
    }
    while let Some(d) = b.get(*i).map(|c| c.wrapping_sub(b'0')).filter(|&d| d <= 9) {
        *m = m.wrapping_mul(10).wrapping_add(u64::from(d));
        *i += 1;
    }
    *i - start
}

/// The field at the start of `b` as `str::parse::<f64>` reads it, and its
/// length (see the module docs).
#[inline]
pub(crate) fn parse_field(b: &[u8]) -> Option<(f64, usize)> {
    let mut i = 0;
    let negative = b.first() == Some(&b'-');
    if matches!(b.first(), Some(b'-' | b'+')) {
        i = 1;
    }
    let mut m = 0u64;
    let mut n = digits(b, &mut i, &mut m);
    let mut e = 0i64;
    if b.get(i) == Some(&b'.') {
        i += 1;
        let frac = digits(b, &mut i, &mut m);
        n += frac;
        e = -(frac as i64);
    }
    if matches!(b.get(i), Some(b'e' | b'E')) {
        i += 1;
        let sign = match b.get(i) {
            Some(b'-') => -1,
            Some(b'+') => 1,
            _ => 0,
        };
        i += usize::from(sign != 0);
        let mut x = 0u64;
        let k = digits(b, &mut i, &mut x);
        if k == 0 || k > 4 {
            return by_std(b);
        }
        e += if sign < 0 { -(x as i64) } else { x as i64 };
    }
    let at_end = b.get(i).is_none_or(u8::is_ascii_whitespace);
    if n == 0 || n > 19 || !at_end {
        return by_std(b);
    }
    let x = match exact(m, e) {
        Some(x) => x,
        None => return by_std(b),
    };
    Some((if negative { -x } else { x }, i))
}

/// `m · 10^e` correctly rounded, for the cases of the module docs.
#[inline]
fn exact(m: u64, e: i64) -> Option<f64> {
    if m == 0 {
        return Some(0.0);
    }
    if m <= 1 << 53 && (-22..=22).contains(&e) {
        let p = POW10_F64[e.unsigned_abs() as usize];
        let x = m as f64;
        return Some(if e < 0 { x / p } else { x * p });
    }
    if e >= 0 {
        let p = *POW10_U64.get(usize::try_from(e).ok()?)?;
        return Some(m.checked_mul(p)? as f64);
    }
    // m / 10^k, k ≤ 19: the numerator shifted so that the quotient q has
    // 63 or 64 bits (≥ 10 below the rounding bit), the remainder folded
    // into its lowest bit as a sticky bit; q as f64 is correctly rounded,
    // and the power of two keeps it exact (s ≤ 127: a normal number)
    let d = *POW10_U64.get(usize::try_from(e.unsigned_abs()).ok()?)?;
    let mut s = 64 + m.leading_zeros() - d.leading_zeros();
    let mut num = u128::from(m) << s;
    if num >= u128::from(d) << 64 {
        s -= 1;
        num >>= 1;
    }
    let d = u128::from(d);
    let q = num / d;
    let sticky = num - q * d != 0;
    let q = q as u64 | u64::from(sticky);
    let scale = f64::from_bits(u64::from(1023 - s) << 52);
    Some(q as f64 * scale)
}

/// The field at the start of `b` by `str::parse::<f64>`.
#[cold]
fn by_std(b: &[u8]) -> Option<(f64, usize)> {
    let end = b
        .iter()
        .position(u8::is_ascii_whitespace)
        .unwrap_or(b.len());
    let field = std::str::from_utf8(b.get(..end)?).ok()?;
    Some((field.parse().ok()?, end))
}
