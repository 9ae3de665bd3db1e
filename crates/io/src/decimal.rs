//! Decimal text to `f64` for the fast paths, parsed where it lies.
//!
//! Input: bytes starting with a field (a field ends at ASCII whitespace or
//! at the end of the bytes). Output: the value `str::parse::<f64>` gives
//! for the field and the field's length, or `None` when `str::parse`
//! refuses it. Invariant: the same bits and the same decision as
//! `str::parse` for every field (`float_tests.rs`).
//!
//! The number is read by `fast_float2` (the Eisel–Lemire algorithm, as
//! `str::parse`; a correctly rounded result is unique, so the bits agree);
//! a field it does not read whole goes to `str::parse`, which decides. An
//! own exact parser (Clinger's fast path, then a 128-bit division) had the
//! same instruction count but was ~15 % slower in wall time on the
//! benchmark `.hexex` (the `div` instruction's latency): BENCHMARKS.md.

/// The field at the start of `b` as `str::parse::<f64>` reads it, and its
/// length (see the module docs).
#[inline]
pub(crate) fn parse_field(b: &[u8]) -> Option<(f64, usize)> {
    match fast_float2::parse_partial::<f64, _>(b) {
        Ok((x, n)) if b.get(n).is_none_or(u8::is_ascii_whitespace) => Some((x, n)),
        _ => by_std(b),
    }
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
