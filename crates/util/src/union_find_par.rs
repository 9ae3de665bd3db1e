//! A union–find that threads share: disjoint sets over `0..n` whose
//! unions may run in parallel, stored as one flat array of atomic `u32`
//! parents.
//!
//! Input: `n` (elements `0..n`, `n < 2^32`) and unions of pairs, from any
//! number of threads at once. Output: the representative of an element
//! ([`AtomicUnionFind::root`]), read once the unions are done.
//! Invariants: a parent is never larger than its child (a root links
//! under the smaller root, path halving only shortens), so the parents
//! hold no cycle and the representative of a set is its **smallest
//! element** — the same as [`crate::union_find::UnionFind::union`]'s —
//! whatever the order or the interleaving of the unions. A root is
//! linked by a compare-and-swap that fails when another thread linked it
//! first; the union then retries from the new roots.
//!
//! ```text
//!   thread 1: union(3, 1)    thread 2: union(2, 3)      1
//!                                                        \
//!             (either order, interleaved or not)          3   2 ──► 1
//! ```

use std::sync::atomic::{AtomicU32, Ordering};

/// Disjoint sets over `0..n`, shared by threads (module docs).
#[derive(Debug)]
pub struct AtomicUnionFind {
    parent: Vec<AtomicU32>,
}

impl AtomicUnionFind {
    /// `n` singleton sets.
    pub fn new(n: usize) -> Self {
        AtomicUnionFind {
            parent: (0..n as u32).map(AtomicU32::new).collect(),
        }
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// Whether there is no element.
    pub fn is_empty(&self) -> bool {
        self.parent.is_empty()
    }

    /// The root of `x`'s set as seen now, halving the path on the way (a
    /// halving lost to another thread's write is skipped: it only
    /// shortens).
    fn find(&self, mut x: u32) -> u32 {
        loop {
            let p = self.parent[x as usize].load(Ordering::Acquire);
            if p == x {
                return x;
            }
            let gp = self.parent[p as usize].load(Ordering::Acquire);
            if gp != p {
                let _ = self.parent[x as usize].compare_exchange_weak(
                    p,
                    gp,
                    Ordering::AcqRel,
                    Ordering::Relaxed,
                );
            }
            x = gp;
        }
    }

    /// Merges the sets of `a` and `b`, the smaller root becoming the root
    /// of both; whether this call merged them.
    pub fn union(&self, a: usize, b: usize) -> bool {
        let (mut a, mut b) = (a as u32, b as u32);
        loop {
            let (ra, rb) = (self.find(a), self.find(b));
            if ra == rb {
                return false;
            }
            let (lo, hi) = (ra.min(rb), ra.max(rb));
            let linked = self.parent[hi as usize].compare_exchange(
                hi,
                lo,
                Ordering::AcqRel,
                Ordering::Acquire,
            );
            if linked.is_ok() {
                return true;
            }
            // `hi` was linked meanwhile: again from the roots reached
            (a, b) = (ra, rb);
        }
    }

    /// The representative (smallest element) of `x`'s set; exact once no
    /// union runs.
    pub fn root(&self, x: usize) -> usize {
        let mut x = x as u32;
        loop {
            let p = self.parent[x as usize].load(Ordering::Acquire);
            if p == x {
                return x as usize;
            }
            x = p;
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::union_find::UnionFind;
    use rayon::prelude::*;

    /// Parallel unions give the roots of the serial union–find (the
    /// smallest element of each set), on random pairs over few and many
    /// elements.
    #[test]
    fn parallel_unions_give_the_serial_roots() {
        let mut rng = crate::rng::SplitMix::new(7);
        for n in [2usize, 10, 1000, 20_000] {
            let pairs: Vec<(usize, usize)> = (0..n).map(|_| (rng.below(n), rng.below(n))).collect();
            let mut serial = UnionFind::new(n);
            for &(a, b) in &pairs {
                serial.union(a, b);
            }
            let shared = AtomicUnionFind::new(n);
            let merged: usize = pairs
                .par_iter()
                .with_max_len(16)
                .map(|&(a, b)| usize::from(shared.union(a, b)))
                .sum();
            let want: Vec<usize> = (0..n).map(|x| serial.find(x)).collect();
            assert_eq!((0..n).map(|x| shared.root(x)).collect::<Vec<_>>(), want);
            assert_eq!(merged, n - serial.count_sets(0..n), "n = {n}");
        }
    }
}
