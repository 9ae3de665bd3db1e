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
//! digits, is scanned here, eight bytes at a time (SWAR: one `u64` load is
//! checked to be eight digits and converted with three multiplications;
//! the first word that is not gives its leading digits in one step). When
//! the integer part has at most 7 digits and 25 bytes follow the sign (a
//! field not at the very end of the input), the point is skipped by
//! merging two loads one byte apart and at most three words are read
//! ([`pointed`]); otherwise the integer digits are read one by one
//! ([`loose`]). Then the value is converted exactly by [`crate::exact`].
//! Any other field, and any value `exact` leaves undecided, goes to
//! `str::parse`, which decides.
//! This replaced `fast-float2` (the same algorithm for the value): ~20 %
//! fewer instructions per field (BENCHMARKS.md, "Reading numbers").

/// `'0'` in every byte.
const ZEROS: u64 = 0x3030_3030_3030_3030;
/// The top bit of every byte.
const TOPS: u64 = 0x8080_8080_8080_8080;
/// `10^k` for `k ≤ 8`.
const POW10: [u64; 9] = [
    1,
    10,
    100,
    1_000,
    10_000,
    100_000,
    1_000_000,
    10_000_000,
    100_000_000,
];
/// At most this many mantissa digits make an exact `u64` mantissa.
const MAX_DIGITS: usize = 19;
/// At most this many exponent digits are read here (`|q|` stays small).
const MAX_EXP_DIGITS: usize = 4;

/// The field at the start of `b` as `str::parse::<f64>` reads it, and its
/// length (see the module docs).
#[cfg(test)]
pub(crate) fn parse_field(b: &[u8]) -> Option<(f64, usize)> {
    match scan(b).and_then(Decimal::value) {
        Some(x) => Some(x),
        None => by_std(b),
    }
}

/// [`parse_field`] when its value is finite: the fields read here always
/// are, those `str::parse` reads are checked.
#[inline]
pub(crate) fn finite_field(b: &[u8]) -> Option<(f64, usize)> {
    match scan(b).and_then(Decimal::value) {
        Some(x) => Some(x),
        None => by_std(b).filter(|(x, _)| x.is_finite()),
    }
}

/// [`finite_field`] with the length counting one space after the field
/// too, when one follows (the cursor's next field then starts there in
/// the common layout: one space between fields).
#[inline(always)]
pub(crate) fn finite_field_spaced(b: &[u8]) -> Option<(f64, usize)> {
    match scan(b).and_then(Decimal::spaced_value) {
        Some(x) => Some(x),
        None => by_std_spaced(b).filter(|(x, _)| x.is_finite()),
    }
}

/// A field in the common form: `±mantissa · 10^exponent`, `len` bytes,
/// then `gap` bytes (1 when a space follows, else 0).
struct Decimal {
    negative: bool,
    mantissa: u64,
    exponent: i32,
    len: usize,
    gap: usize,
}

impl Decimal {
    /// The value and the length, or `None` when [`crate::exact`] cannot
    /// decide.
    #[inline]
    fn value(self) -> Option<(f64, usize)> {
        let len = self.len;
        Some((self.signed()?, len))
    }

    /// [`Decimal::value`] with the length counting the gap.
    #[inline(always)]
    fn spaced_value(self) -> Option<(f64, usize)> {
        let len = self.len + self.gap;
        Some((self.signed()?, len))
    }

    /// The value, or `None` when [`crate::exact`] cannot decide.
    #[inline(always)]
    fn signed(self) -> Option<f64> {
        let x = match self.mantissa {
            0 => 0.0,
            w => crate::exact::to_f64(w, self.exponent)?,
        };
        Some(if self.negative { -x } else { x })
    }
}

/// The field at the start of `b` when it has the common form and ends at
/// whitespace or at the end of `b`.
#[inline(always)]
fn scan(b: &[u8]) -> Option<Decimal> {
    let negative = b.first() == Some(&b'-');
    let sign = usize::from(matches!(b.first(), Some(b'-' | b'+')));
    let m = match pointed(b, sign) {
        Some(m) => m,
        None => loose(b, sign)?,
    };
    if m.count == 0 || m.count > MAX_DIGITS {
        return None;
    }
    // at most 19 digits: the cast is exact
    let fraction = -(m.fraction as i32);
    // one space or a line end after the mantissa: the common ends of a
    // field, a comparison each; any other end out of line
    let (exponent, len, gap) = match m.next {
        Some(b' ') => (fraction, m.end, 1),
        Some(b'\n') => (fraction, m.end, 0),
        next => other_end(b, m.end, next, fraction)?,
    };
    Some(Decimal {
        negative,
        mantissa: m.value,
        exponent,
        len,
        gap,
    })
}

/// The end of a field whose mantissa (`fraction` the exponent it gives)
/// ends at `end` before the byte `next` (not a space nor `\n`): whitespace, the end
/// of the bytes, or an exponent and then one of them. The exponent, the
/// field's length and the gap after it (1 for a space) as in [`Decimal`].
#[cold]
#[inline(never)]
fn other_end(b: &[u8], end: usize, next: Option<u8>, fraction: i32) -> Option<(i32, usize, usize)> {
    match next {
        None => Some((fraction, end, 0)),
        Some(c) if c.is_ascii_whitespace() => Some((fraction, end, 0)),
        Some(c) if c | 0x20 == b'e' => {
            let (e, n) = exponent_field(b.get(end + 1..)?)?;
            let len = end + 1 + n;
            match b.get(len) {
                Some(b' ') => Some((fraction + e, len, 1)),
                next if next.is_none_or(u8::is_ascii_whitespace) => Some((fraction + e, len, 0)),
                _ => None,
            }
        }
        Some(_) => None,
    }
}

/// The digits of a field's mantissa, `[digits] [. digits]`, read up to
/// the first byte that is not one of them.
struct Mantissa {
    /// The digits as one integer (wrapping past 19 digits).
    value: u64,
    /// How many digits, leading zeros included.
    count: usize,
    /// How many of them follow the point.
    fraction: usize,
    /// Where the mantissa ends (the sign and the point included).
    end: usize,
    /// The byte there (`None` at the end of the bytes).
    next: Option<u8>,
}

/// The mantissa after the `sign` bytes of `b` when its integer part has
/// at most 7 digits and a point follows them, and 25 bytes follow the
/// sign. The first eight digits are one word: the bytes before the point
/// from one load, those after it from a load one byte later, so the point
/// costs no step of its own. Then one word of digits, and the digits that
/// begin the next (with more than 16 digits in all).
#[inline(always)]
fn pointed(b: &[u8], sign: usize) -> Option<Mantissa> {
    let body: &[u8; 25] = b.get(sign..)?.first_chunk()?;
    let word = |at: usize| word_at(body, at);
    let w0 = word(0);
    let int = non_digits(w0).trailing_zeros() / 8;
    // (int = 8: the shift by 64 wraps to 0, and byte 0 is a digit)
    if w0.wrapping_shr(8 * int) as u8 != b'.' {
        return None;
    }
    // bytes below the point from w0, the rest from the next load
    let below = (1u64 << (8 * int)) - 1;
    let merged = (w0 & below) | (word(1) & !below);
    let mut value = 0;
    // the word that ends the digits, and how many digits precede it
    let (last, before) = if !all_digits(merged) {
        (merged, 0)
    } else {
        value = digit_values(merged.wrapping_sub(ZEROS));
        let next = word(9);
        if !all_digits(next) {
            (next, 8)
        } else {
            value = value
                .wrapping_mul(100_000_000)
                .wrapping_add(digit_values(next.wrapping_sub(ZEROS)));
            (word(17), 16)
        }
    };
    let k = part_word(last, &mut value);
    let count = before + k;
    Some(Mantissa {
        value,
        count,
        fraction: count - int as usize,
        end: sign + count + 1,
        // (k = 8 only with 24 digits, which the caller refuses)
        next: Some(last.wrapping_shr(8 * k as u32) as u8),
    })
}

/// The mantissa after the `sign` bytes of `b`, any form: the integer
/// digits one by one, then the point and the fraction by [`run`].
#[inline]
fn loose(b: &[u8], sign: usize) -> Option<Mantissa> {
    let body = b.get(sign..)?;
    let mut value = 0u64;
    let int = digits(body, &mut value);
    let mut fraction = 0;
    let mut end = sign + int;
    if body.get(int) == Some(&b'.') {
        fraction = run(body.get(int + 1..)?, &mut value);
        end += 1 + fraction;
    }
    Some(Mantissa {
        value,
        count: int + fraction,
        fraction,
        end,
        next: b.get(end).copied(),
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

/// The eight bytes of `b` from `at` as one little-endian word (the first
/// byte lowest); `at + 8 ≤ L` (the callers' fixed offsets).
#[inline(always)]
pub(crate) fn word_at<const L: usize>(b: &[u8; L], at: usize) -> u64 {
    let mut w = [0; 8];
    w.copy_from_slice(&b[at..at + 8]);
    u64::from_le_bytes(w)
}

/// Reads the digits that begin the word `w` into `m` (as [`run`]) and
/// returns how many (0 to 8).
#[inline(always)]
pub(crate) fn part_word(w: u64, m: &mut u64) -> usize {
    let k = non_digits(w).trailing_zeros() as usize / 8;
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
    non_digits(w) == 0
}

/// The top bit of every byte of `w` from its first non-digit on, at least
/// (the bytes before it: clear).
#[inline]
fn non_digits(w: u64) -> u64 {
    // a byte below '0' borrows into its top bit, one above '9' carries
    // into it (the lowest such byte does so whatever the others hold)
    (w.wrapping_sub(ZEROS) | w.wrapping_add(0x4646_4646_4646_4646)) & TOPS
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

/// [`by_std`] with the length counting one space after the field.
#[cold]
fn by_std_spaced(b: &[u8]) -> Option<(f64, usize)> {
    let (x, n) = by_std(b)?;
    Some((x, n + usize::from(b.get(n) == Some(&b' '))))
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
