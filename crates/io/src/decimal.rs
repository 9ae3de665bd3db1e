//! Decimal text to `f64` for the fast paths, parsed where it lies.
//!
//! Input: bytes starting with a field (a field ends at ASCII whitespace or
//! at the end of the bytes). Output: the value `str::parse::<f64>` gives
//! for the field and the field's length, or `None` when `str::parse`
//! refuses it. Invariant: the same bits and the same decision as
//! `str::parse` for every field (`float_tests.rs`).
//!
//! The common field, `[sign] digits [. digits] [e [sign] digits]` with at
//! most 19 mantissa digits (leading zeros included) and at most 4 exponent
//! digits, is scanned here: the integer digits one by one (usually one or
//! two), the fraction eight bytes at a time (SWAR: one `u64` load is
//! checked to be eight digits and converted with three multiplications;
//! the first word that is not gives its leading digits in one step), then
//! the value is converted exactly by [`crate::exact`]. Any other field, and
//! any value `exact` leaves undecided, goes to `str::parse`, which decides.
//! This replaced `fast-float2` (the same algorithm for the value): ~20 %
//! fewer instructions per field (BENCHMARKS.md, "Reading numbers").

/// `'0'` in every byte.
const ZEROS: u64 = 0x3030_3030_3030_3030;
/// The top bit of every byte.
const TOPS: u64 = 0x8080_8080_8080_8080;
/// `10^k` for `k < 8`.
const POW10: [u64; 8] = [1, 10, 100, 1_000, 10_000, 100_000, 1_000_000, 10_000_000];
/// At most this many mantissa digits make an exact `u64` mantissa.
const MAX_DIGITS: usize = 19;
/// At most this many exponent digits are read here (`|q|` stays small).
const MAX_EXP_DIGITS: usize = 4;

/// The field at the start of `b` as `str::parse::<f64>` reads it, and its
/// length (see the module docs).
#[inline]
pub(crate) fn parse_field(b: &[u8]) -> Option<(f64, usize)> {
    match scan(b).and_then(Decimal::value) {
        Some(x) => Some(x),
        None => by_std(b),
    }
}

/// A field in the common form: `±mantissa · 10^exponent`, `len` bytes.
struct Decimal {
    negative: bool,
    mantissa: u64,
    exponent: i32,
    len: usize,
}

impl Decimal {
    /// The value and the length, or `None` when [`crate::exact`] cannot
    /// decide.
    #[inline]
    fn value(self) -> Option<(f64, usize)> {
        let x = match self.mantissa {
            0 => 0.0,
            w => crate::exact::to_f64(w, self.exponent)?,
        };
        Some((if self.negative { -x } else { x }, self.len))
    }
}

/// The field at the start of `b` when it has the common form and ends at
/// whitespace or at the end of `b`. Whole words of digits advance the
/// position by a predicted branch, not by a computed run length: the
/// next load need not wait for this one's digits (a first version that
/// measured every run was ~20 % slower in wall time).
#[inline]
fn scan(b: &[u8]) -> Option<Decimal> {
    let negative = b.first() == Some(&b'-');
    let mut i = usize::from(matches!(b.first(), Some(b'-' | b'+')));
    let mut mantissa = 0u64;
    let int = digits(b.get(i..)?, &mut mantissa);
    i += int;
    let mut fraction = 0;
    if b.get(i) == Some(&b'.') {
        i += 1;
        fraction = run(b.get(i..)?, &mut mantissa);
        i += fraction;
    }
    if int + fraction == 0 || int + fraction > MAX_DIGITS {
        return None;
    }
    let mut exponent = 0i32;
    if b.get(i).is_some_and(|&c| c | 0x20 == b'e') {
        let (e, n) = exponent_field(b.get(i + 1..)?)?;
        exponent = e;
        i += 1 + n;
    }
    if !b.get(i).is_none_or(u8::is_ascii_whitespace) {
        return None;
    }
    let exponent = exponent - i32::try_from(fraction).ok()?;
    Some(Decimal {
        negative,
        mantissa,
        exponent,
        len: i,
    })
}

/// The exponent after `e`: `[sign] digits` with 1 to 4 digits, and its
/// length.
#[inline]
fn exponent_field(b: &[u8]) -> Option<(i32, usize)> {
    let negative = b.first() == Some(&b'-');
    let sign = usize::from(matches!(b.first(), Some(b'-' | b'+')));
    let mut e = 0u64;
    let n = digits(b.get(sign..)?, &mut e);
    if n == 0 || n > MAX_EXP_DIGITS {
        return None;
    }
    let e = i32::try_from(e).ok()?;
    Some((if negative { -e } else { e }, sign + n))
}

/// Reads the run of decimal digits at the start of `b` into `m` (`m·10 +
/// digit` for each, wrapping: the caller refuses long runs) and returns
/// its length: whole words of eight digits, then the digits that begin
/// the next word.
#[inline(always)]
fn run(b: &[u8], m: &mut u64) -> usize {
    let mut rest = b;
    while let Some((w, tail)) = rest.split_first_chunk::<8>() {
        let w = u64::from_le_bytes(*w);
        if !all_digits(w) {
            return b.len() - rest.len() + part_word(w, m);
        }
        *m = m
            .wrapping_mul(100_000_000)
            .wrapping_add(digit_values(w.wrapping_sub(ZEROS)));
        rest = tail;
    }
    b.len() - rest.len() + digits(rest, m)
}

/// Reads the digits that begin the word `w` into `m` (as [`run`]) and
/// returns how many (at most 7: `w` is not all digits).
#[inline]
fn part_word(w: u64, m: &mut u64) -> usize {
    // a byte below '0' borrows into its top bit, one above '9' carries
    // into it; the bytes before the first non-digit do neither
    let non_digit = (w.wrapping_sub(ZEROS) | w.wrapping_add(0x4646_4646_4646_4646)) & TOPS;
    let k = non_digit.trailing_zeros() as usize / 8;
    // the k digits moved to the top bytes, zero digits below; two shifts
    // so that k = 0 shifts everything out
    let s = 32 - 4 * k as u32;
    let v = (w.wrapping_sub(ZEROS) << s) << s;
    *m = m
        .wrapping_mul(POW10.get(k).copied().unwrap_or(0))
        .wrapping_add(digit_values(v));
    k
}

/// Reads the decimal digits at the start of `b` one by one into `m` (as
/// [`run`]) and returns how many.
#[inline]
fn digits(b: &[u8], m: &mut u64) -> usize {
    let mut n = 0;
    for &c in b {
        let d = c.wrapping_sub(b'0');
        if d >= 10 {
            break;
        }
        *m = m.wrapping_mul(10).wrapping_add(u64::from(d));
        n += 1;
    }
    n
}

/// Whether the eight bytes of `w` are all digits.
#[inline]
fn all_digits(w: u64) -> bool {
    // a byte below '0' borrows into its top bit, one above '9' carries
    // into it (the lowest such byte does so whatever the others hold)
    (w.wrapping_sub(ZEROS) | w.wrapping_add(0x4646_4646_4646_4646)) & TOPS == 0
}

/// The value of the eight digit values (0–9) in the bytes of `v`, the
/// first byte (lowest) the most significant.
#[inline]
fn digit_values(v: u64) -> u64 {
    // pairs: byte 2j holds 10·d(2j) + d(2j+1)
    let v = v.wrapping_mul(10).wrapping_add(v >> 8);
    // then (a·100 + b)·10^4 + c·100 + d from the pairs a, b, c, d
    const LOW: u64 = 0x0000_00ff_0000_00ff;
    let ac = (v & LOW).wrapping_mul(100 + (1_000_000 << 32));
    let bd = ((v >> 16) & LOW).wrapping_mul(1 + (10_000 << 32));
    ac.wrapping_add(bd) >> 32
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
