//! A counting sort into buckets, each bucket then sorted: equal items of a
//! bucket end up adjacent, in linear time but for the small per-bucket
//! sorts (a bucket per vertex: a vertex's few edges or faces), instead of
//! a sort or a hash map of all the items.
//!
//! Input: a bucket count and a producer that emits `(bucket, item)` pairs
//! (run twice: to count, then to place). Output: the start of each bucket
//! and the items, bucket by bucket (bucket `b` is
//! `items[start[b]..start[b + 1]]`), each bucket sorted. Invariant: the output depends only on the
//! emitted pairs (no hashing; the producer runs on the calling thread,
//! the buckets' sorts by groups in parallel, each bucket whole).

/// The items `each` emits, bucketed by `bucket % nb` (`nb` at least 1) and
/// sorted within each bucket; with the `nb + 1` bucket starts.
pub fn sorted<T: Copy + Default + Ord + Send>(
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
    sort_buckets(&start, &mut out, GROUP);
    (start, out)
}

/// Items per parallel task of [`sort_buckets`], about.
const GROUP: usize = 1 << 14;

/// Sorts each bucket `items[start[b]..start[b + 1]]`; groups of whole
/// buckets of about `group ≥ 1` items in parallel.
fn sort_buckets<T: Ord + Send>(start: &[usize], items: &mut [T], group: usize) {
    use rayon::prelude::*;
    let sort = |start: &[usize], items: &mut [T], base: usize| {
        for w in start.windows(2) {
            items[w[0] - base..w[1] - base].sort_unstable();
        }
    };
    if items.len() < 2 * group {
        sort(start, items, 0);
        return;
    }
    // cut after the first bucket ending `group` items or more past a cut
    let mut parts = Vec::new();
    let (mut rest, mut base, mut first) = (items, 0, 0);
    for b in 1..start.len() {
        if start[b] - base >= group || b + 1 == start.len() {
            let (part, tail) = std::mem::take(&mut rest).split_at_mut(start[b] - base);
            parts.push((&start[first..=b], part, base));
            (rest, base, first) = (tail, start[b], b);
        }
    }
    parts
        .into_par_iter()
        .for_each(|(start, part, base)| sort(start, part, base));
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

    /// Groups of any size sort every bucket as one group does, with
    /// empty buckets, buckets larger than a group, and at the ends.
    #[test]
    fn groups_sort_as_one() {
        let mut rng = crate::rng::SplitMix::new(5);
        for case in 0..40u64 {
            let nb = 1 + (case as usize * 7) % 50;
            let n = (case as usize * 37) % 900;
            let (mut start, mut items) = (vec![0usize; nb + 1], Vec::new());
            for b in 0..nb {
                // some buckets empty, some large
                let len = match b % 5 {
                    0 => 0,
                    1 => n / 3,
                    _ => (rng.next_u64() % 12) as usize,
                };
                items.extend((0..len).map(|_| rng.next_u64() % 20));
                start[b + 1] = items.len();
            }
            let mut want = items.clone();
            sort_buckets(&start, &mut want, usize::MAX / 4);
            for group in [1, 2, 5, 16, 100] {
                let mut got = items.clone();
                sort_buckets(&start, &mut got, group);
                assert_eq!(got, want, "case {case}, group {group}");
            }
            for w in start.windows(2) {
                assert!(want[w[0]..w[1]].is_sorted());
            }
        }
    }
}
