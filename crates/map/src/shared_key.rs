//! Whether two of many keys are equal, in parallel and without a sort: an
//! insert-only hash set of the items' indices (open addressing, linear
//! probing, one compare-and-swap per insert).
//!
//! Input: `n` items and the key of each (a pure function of the index).
//! Output: `true` when two items have equal keys, `false` otherwise.
//! Invariant: the answer is the same whatever the number of threads and
//! their interleaving. Two equal keys share one probe sequence, and a slot
//! once taken is never emptied. Whichever of the two reaches the first
//! slot that was free for both, second, finds the other there. This holds
//! also when both race for that slot: the compare-and-swap that loses
//! reads the winner.
//!
//! What it is for: the weld's test for vertices at one position, which is
//! false for nearly every map (an uncut mesh, or one cut only in its
//! texture coordinates). A `true` sends the caller to its sort, which
//! finds the groups in position order.

use rayon::prelude::*;
use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

/// Items per parallel task, about.
const TASK: usize = 1 << 12;

/// Whether two of the items `0..n` have equal keys (see the module docs).
/// `n ≥ u32::MAX` answers `true` (not tested: the caller's sort decides).
pub fn any_equal<K, H>(n: usize, key: K, hash: H) -> bool
where
    K: Fn(usize) -> [u64; 3] + Sync,
    H: Fn(&[u64; 3]) -> u64 + Sync,
{
    let Ok(limit) = u32::try_from(n) else {
        return true;
    };
    if limit == u32::MAX {
        return true;
    }
    // slot value: item + 1; 0 is free (at most half the slots taken)
    let size = (2 * n).next_power_of_two().max(16);
    let mask = size - 1;
    let slots: Vec<AtomicU32> = (0..size)
        .into_par_iter()
        .with_min_len(TASK)
        .map(|_| AtomicU32::new(0))
        .collect();
    (0..n).into_par_iter().with_min_len(TASK).any(|i| {
        let k = key(i);
        // the low bits of a hash index the slots
        let mut at = hash(&k) as usize & mask;
        loop {
            let seen = match slots[at].compare_exchange(0, i as u32 + 1, Relaxed, Relaxed) {
                Ok(_) => return false,
                Err(seen) => seen,
            };
            if key(seen as usize - 1) == k {
                return true;
            }
            at = (at + 1) & mask;
        }
    })
}

/// A hash of three words: each mixed in by MurmurHash3's 64-bit
/// finalizer.
pub fn hash3(k: &[u64; 3]) -> u64 {
    let mix = |mut h: u64| {
        h ^= h >> 33;
        h = h.wrapping_mul(0xff51_afd7_ed55_8ccd);
        h ^= h >> 33;
        h = h.wrapping_mul(0xc4ce_b9fe_1a85_ec53);
        h ^ (h >> 33)
    };
    mix(mix(mix(k[0]) ^ k[1]) ^ k[2])
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_util::rng::SplitMix;

    /// The sort's answer, as an oracle.
    fn by_sort(keys: &[[u64; 3]]) -> bool {
        let mut k = keys.to_vec();
        k.sort_unstable();
        k.windows(2).any(|w| w[0] == w[1])
    }

    fn check(keys: &[[u64; 3]], hash: impl Fn(&[u64; 3]) -> u64 + Sync) {
        let want = by_sort(keys);
        for threads in [1, 2, 5] {
            let pool = rayon::ThreadPoolBuilder::new()
                .num_threads(threads)
                .build()
                .expect("pool");
            let got = pool.install(|| any_equal(keys.len(), |i| keys[i], &hash));
            assert_eq!(got, want, "{} keys, {threads} threads", keys.len());
        }
    }

    /// Random keys on a small grid (many keys equal in one or two words), some made
    /// equal to another at a random place; hashes good and bad (all
    /// colliding, low bits only), sizes around the task and table edges.
    #[test]
    fn answers_as_the_sort() {
        let mut rng = SplitMix::new(11);
        for n in [
            0usize, 1, 2, 3, 15, 16, 17, 1000, 4095, 4097, 20_000, 70_001,
        ] {
            // words from small ranges: keys equal in one or two words only
            let side = (n as f64).cbrt() as u64 + 2;
            let mut keys: Vec<[u64; 3]> = (0..n)
                .map(|_| [0; 3].map(|_| rng.next_u64() % side))
                .collect();
            keys.sort_unstable();
            keys.dedup();
            rng.shuffle(&mut keys);
            // distinct, then each in turn: one pair made equal
            check(&keys, hash3);
            if n > 1 && n <= 4097 {
                check(&keys, |k| k[0] & 7);
            }
            for _ in 0..4 {
                if keys.len() < 2 {
                    break;
                }
                let a = rng.next_u64() as usize % keys.len();
                let b = rng.next_u64() as usize % keys.len();
                let mut twin = keys.clone();
                twin[a] = twin[b];
                check(&twin, hash3);
                if n <= 1000 {
                    check(&twin, |_| 42);
                }
            }
        }
    }

    #[test]
    fn hash_spreads_grid_positions() {
        // positions of a grid as float bits: few collisions in the low bits
        let mut seen = std::collections::HashSet::new();
        for i in 0..64u32 {
            for j in 0..64u32 {
                let k = [f64::from(i).to_bits(), f64::from(j).to_bits(), 0];
                seen.insert(hash3(&k) & 0x3fff);
            }
        }
        assert!(seen.len() > 3500, "{} distinct of 4096", seen.len());
    }
}
