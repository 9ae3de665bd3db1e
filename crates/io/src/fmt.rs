//! Fast text output of numbers, in parallel, in order.
//!
//! Floats are printed in their shortest round-trip form by `ryu` (exactly
//! what the readers, C's `strtod` and C++ streams read back bit for bit;
//! 3–4× faster than `{:?}` here, see BENCHMARKS.md), integers by `itoa`.
//! [`par_lines`] formats chunks of records on rayon's pool into separate
//! buffers and writes them in record order: the bytes do not depend on the
//! thread count.

use rayon::prelude::*;
use std::io::{self, Write};

/// Appends `x` in shortest round-trip form (`1.0`, `0.1`, `1e-7`).
#[inline]
pub(crate) fn float(out: &mut Vec<u8>, x: f64) {
    let mut b = ryu::Buffer::new();
    out.extend_from_slice(b.format(x).as_bytes());
}

/// Appends the decimal digits of `n`.
#[inline]
pub(crate) fn int(out: &mut Vec<u8>, n: u64) {
    let mut b = itoa::Buffer::new();
    out.extend_from_slice(b.format(n).as_bytes());
}

/// Appends one line: `prefix`, then each of `xs` after a space (no space
/// after an empty prefix), then `suffix` and a newline.
pub(crate) fn floats_line(out: &mut Vec<u8>, prefix: &[u8], xs: &[f64], suffix: &[u8]) {
    out.extend_from_slice(prefix);
    for (k, &x) in xs.iter().enumerate() {
        if k > 0 || !prefix.is_empty() {
            out.push(b' ');
        }
        float(out, x);
    }
    out.extend_from_slice(suffix);
    out.push(b'\n');
}

/// Records per parallel chunk, and chunks formatted before writing (bounds
/// the buffered bytes to ~`WAVE · CHUNK` records).
const CHUNK: usize = 8192;
const WAVE: usize = 32;

/// Writes `line(out, item)` for every item, formatted in parallel chunks
/// and written in order.
pub(crate) fn par_lines<T: Sync>(
    w: &mut impl Write,
    items: &[T],
    line: impl Fn(&mut Vec<u8>, &T) + Sync,
) -> io::Result<()> {
    for wave in items.chunks(CHUNK * WAVE) {
        let bufs: Vec<Vec<u8>> = wave
            .par_chunks(CHUNK)
            .map(|chunk| {
                let mut out = Vec::with_capacity(chunk.len() * 48);
                for item in chunk {
                    line(&mut out, item);
                }
                out
            })
            .collect();
        for b in &bufs {
            w.write_all(b)?;
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn floats_round_trip_and_lines_keep_their_order() {
        let xs = [
            0.0,
            -0.0,
            1.0,
            0.1,
            1e-7,
            1e300,
            -2.5e-300,
            123456.789,
            f64::MIN_POSITIVE,
        ];
        for x in xs {
            let mut out = Vec::new();
            float(&mut out, x);
            let text = String::from_utf8(out).unwrap_or_default();
            assert_eq!(
                text.parse::<f64>().map(f64::to_bits),
                Ok(x.to_bits()),
                "{text}"
            );
        }
        let items: Vec<u64> = (0..100_000).collect();
        let mut out = Vec::new();
        par_lines(&mut out, &items, |o, &n| {
            int(o, n);
            o.push(b'\n');
        })
        .unwrap_or_else(|e| panic!("{e}"));
        let want: String = items.iter().map(|n| format!("{n}\n")).collect();
        assert!(out == want.as_bytes());
    }
}
