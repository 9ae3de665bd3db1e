//! Parallel writes into a per-corner array from work split by vertex: the
//! snap ([`crate::local::LocalMap::snap`]) and the moves of sanitization
//! each compute, per vertex, values for the corners of its star, which lie
//! anywhere in the simplex-major array.
//!
//! Input: the per-corner array (`[[[f64; D]; N]]`, one row per simplex)
//! and [`Buckets`] filled per block of vertices, in parallel: each value
//! with its corner (simplex, corner index), sorted by the range of
//! simplices it falls in. Output: [`apply`] writes every bucket's values
//! with one task per range of simplices, each task reading only its own
//! bucket of every block.
//!
//! Invariant: a corner receives its values in the blocks' order, then in
//! each block's push order, whatever the number of threads and ranges: a
//! caller that fills the blocks in a fixed order gets the same result
//! bit for bit as one sequential pass in that order.

use rayon::prelude::*;

/// One block's values, by range of simplices.
pub struct Buckets<const D: usize> {
    /// Simplices per range.
    len: usize,
    /// Per range: (simplex, corner, value), in push order.
    parts: Vec<Vec<(u32, u8, [f64; D])>>,
}

impl<const D: usize> Buckets<D> {
    /// Empty buckets for `ranges` ranges of `len` simplices each
    /// ([`ranges`]).
    pub fn new((ranges, len): (usize, usize)) -> Self {
        Buckets {
            len,
            parts: (0..ranges).map(|_| Vec::new()).collect(),
        }
    }

    /// Empties every range, keeping the memory (for the next wave).
    pub fn clear(&mut self) {
        self.parts.iter_mut().for_each(Vec::clear);
    }

    /// Adds `value` for corner `corner` of simplex `simplex`.
    #[inline]
    pub fn push(&mut self, simplex: u32, corner: u8, value: [f64; D]) {
        let r = simplex as usize / self.len;
        // `ranges` covers every simplex: the last range is never passed
        let last = self.parts.len() - 1;
        self.parts[r.min(last)].push((simplex, corner, value));
    }
}

/// The ranges for `simplices` simplices: one per thread (one when a single
/// thread runs), as (count, simplices per range).
pub fn ranges(simplices: usize) -> (usize, usize) {
    let count = rayon::current_num_threads().max(1);
    (count, simplices.div_ceil(count).max(1))
}

/// Writes the values of `blocks` (made with [`ranges`] of `coords.len()`)
/// into `coords` by `write(corner, value)`, one parallel task per range,
/// in the blocks' order and each block's push order.
pub fn apply<const N: usize, const D: usize>(
    coords: &mut [[[f64; D]; N]],
    blocks: &[Buckets<D>],
    write: impl Fn(&mut [f64; D], &[f64; D]) + Sync,
) {
    let Some(len) = blocks.first().map(|b| b.len) else {
        return;
    };
    coords
        .par_chunks_mut(len)
        .enumerate()
        .for_each(|(r, part)| {
            let lo = r * len;
            for b in blocks {
                let Some(values) = b.parts.get(r) else {
                    continue;
                };
                for &(s, k, ref x) in values {
                    if let Some(row) = (s as usize).checked_sub(lo).and_then(|i| part.get_mut(i)) {
                        write(&mut row[k as usize], x);
                    }
                }
            }
        });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Values pushed in any order by blocks land where a sequential pass
    /// would put them, in the same order, whatever the thread count.
    #[test]
    fn apply_equals_sequential() {
        let ns = 1000;
        let mut want = vec![[[0.0f64; 2]; 3]; ns];
        let pushes: Vec<Vec<(u32, u8, [f64; 2])>> = (0..7)
            .map(|b| {
                (0..500)
                    .map(|i| {
                        let z = (b * 500 + i) as u32;
                        let s = z.wrapping_mul(2654435761) % ns as u32;
                        (s, (z % 3) as u8, [f64::from(z), 0.5 * f64::from(z)])
                    })
                    .collect()
            })
            .collect();
        for (s, k, x) in pushes.iter().flatten() {
            let c = &mut want[*s as usize][*k as usize];
            c[0] = c[0] * 0.5 + x[0];
            c[1] += x[1];
        }
        for threads in [1, 2, 3, 8] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .unwrap_or_else(|e| panic!("{e}"));
            let got = pool.install(|| {
                let mut got = vec![[[0.0f64; 2]; 3]; ns];
                let blocks: Vec<Buckets<2>> = pushes
                    .iter()
                    .map(|p| {
                        let mut b = Buckets::new(ranges(ns));
                        p.iter().for_each(|&(s, k, x)| b.push(s, k, x));
                        b
                    })
                    .collect();
                apply(&mut got, &blocks, |c, x| {
                    c[0] = c[0] * 0.5 + x[0];
                    c[1] += x[1];
                });
                got
            });
            assert_eq!(got, want, "{threads} threads");
        }
    }
}
