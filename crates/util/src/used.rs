//! How many vertices a list of simplices uses, in parallel.
//!
//! Input: a vertex count `n` and simplices whose indices are `< n`.
//! Output: the number of distinct vertices that appear in some simplex.
//! Invariant: the same count whatever the number of threads (each vertex
//! is flagged by whichever thread reaches it first, and a flag is only
//! ever set).

use rayon::prelude::*;
use std::sync::atomic::{AtomicBool, Ordering::Relaxed};

/// Simplices per parallel task (below it, splitting costs more than it
/// saves).
const TASK: usize = 1 << 14;

/// The number of the `n` vertices used by `simplices` (every index must be
/// `< n`: an index out of range panics, a broken invariant).
pub fn used_vertices<const N: usize>(n: usize, simplices: &[[u32; N]]) -> usize {
    let used: Vec<AtomicBool> = (0..n).map(|_| AtomicBool::new(false)).collect();
    simplices.par_chunks(TASK).for_each(|part| {
        for s in part {
            for &v in s {
                used[v as usize].store(true, Relaxed);
            }
        }
    });
    used.par_iter()
        .with_min_len(TASK)
        .filter(|u| u.load(Relaxed))
        .count()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The serial count, as an oracle.
    fn serial<const N: usize>(n: usize, simplices: &[[u32; N]]) -> usize {
        let mut used = vec![false; n];
        for s in simplices {
            for &v in s {
                used[v as usize] = true;
            }
        }
        used.iter().filter(|&&u| u).count()
    }

    #[test]
    fn counts_as_the_serial_loop() {
        let mut rng = crate::rng::SplitMix::new(7);
        for (n, m) in [
            (0usize, 0usize),
            (1, 0),
            (1, 3),
            (5, 2),
            (100, 10),
            (70_000, 40_000),
            (200_000, 30_000),
        ] {
            let tris: Vec<[u32; 3]> = (0..m)
                .map(|_| [0; 3].map(|_| (rng.next_u64() % n.max(1) as u64) as u32))
                .collect();
            let tris: Vec<[u32; 3]> = if n == 0 { Vec::new() } else { tris };
            let tets: Vec<[u32; 4]> = tris.iter().map(|t| [t[0], t[1], t[2], t[0] / 2]).collect();
            assert_eq!(used_vertices(n, &tris), serial(n, &tris), "{n} {m}");
            assert_eq!(used_vertices(n, &tets), serial(n, &tets), "{n} {m}");
        }
    }
}
