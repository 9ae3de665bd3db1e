//! A counting sort into buckets, each bucket then sorted: equal items of a
//! bucket end up adjacent, in linear time but for the small per-bucket
//! sorts (a bucket per vertex: a vertex's few edges or faces), instead of
//! a sort or a hash map of all the items.
//!
//! Input: a bucket count and a producer that emits `(bucket, item)` pairs
//! (run twice: to count, then to place). Output: the start of each bucket
//! and the items, bucket by bucket (bucket `b` is
//! `items[start[b]..start[b + 1]]`), each bucket sorted. Invariant: the output depends only on the
//! emitted pairs (no hashing, no threads).

/// The items `each` emits, bucketed by `bucket % nb` (`nb` at least 1) and
/// sorted within each bucket; with the `nb + 1` bucket starts.
pub fn sorted<T: Copy + Default + Ord>(
    nb: usize,
    each: impl Fn(&mut dyn FnMut(usize, T)),
) -> (Vec<usize>, Vec<T>) {
    let nb = nb.max(1);
    let mut start = vec![0usize; nb + 1];
    each(&mut |b, _| start[b % nb + 1] += 1);
    for i in 0..nb {
        start[i + 1] += start[i];
    }
    let mut out = vec![T::default(); start[nb]];
    let mut next = start[..nb].to_vec();
    each(&mut |b, x| {
        let b = b % nb;
        out[next[b]] = x;
        next[b] += 1;
    });
    for w in start.windows(2) {
        out[w[0]..w[1]].sort_unstable();
    }
    (start, out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn buckets_in_order_each_sorted() {
        let items = [(3usize, 7u32), (0, 5), (3, 1), (1, 9), (0, 2), (7, 4)];
        let (start, out) = sorted(4, |emit| {
            for &(b, x) in &items {
                emit(b, x);
            }
        });
        // bucket 3 holds 3's items and 7's (7 % 4)
        assert_eq!(start, vec![0, 2, 3, 3, 6]);
        assert_eq!(out, vec![2, 5, 9, 1, 4, 7]);
        let (start, out) = sorted::<u32>(0, |_| {});
        assert_eq!((start, out), (vec![0, 0], vec![]));
    }
}
