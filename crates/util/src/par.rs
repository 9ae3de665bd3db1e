//! Deterministic parallel building blocks (rayon).
//!
//! Every function here gives the same result whatever the number of
//! threads: work is split into fixed-size chunks of the input, and the
//! chunks' outputs are joined in input order.

use rayon::prelude::*;

/// Items produced per element of `0..n`, joined in element order, with
/// CSR offsets: the items of element `e` are `items[offsets[e]..offsets[e + 1]]`.
/// `produce(e, out)` pushes element `e`'s items onto `out`; elements are
/// processed in parallel in chunks of `chunk`.
pub fn csr<T: Send>(
    n: usize,
    chunk: usize,
    produce: impl Fn(usize, &mut Vec<T>) + Sync,
) -> (Vec<T>, Vec<u32>) {
    let chunk = chunk.max(1);
    let parts: Vec<(Vec<T>, Vec<u32>)> = (0..n.div_ceil(chunk))
        .into_par_iter()
        .map(|c| {
            let (lo, hi) = (c * chunk, ((c + 1) * chunk).min(n));
            let mut items = Vec::new();
            let mut ends = Vec::with_capacity(hi - lo);
            for e in lo..hi {
                produce(e, &mut items);
                ends.push(items.len() as u32);
            }
            (items, ends)
        })
        .collect();
    let total = parts.iter().map(|p| p.0.len()).sum();
    let mut items = Vec::with_capacity(total);
    let mut offsets = Vec::with_capacity(n + 1);
    offsets.push(0u32);
    for (part, ends) in parts {
        let base = items.len() as u32;
        offsets.extend(ends.iter().map(|&e| base + e));
        items.extend(part);
    }
    (items, offsets)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn csr_joins_in_order_whatever_the_chunk() {
        let make = |e: usize, out: &mut Vec<usize>| out.extend(std::iter::repeat_n(e, e % 3));
        let (items, offsets) = csr(10, 1000, make);
        for chunk in [1, 2, 3, 7] {
            assert_eq!(csr(10, chunk, make), (items.clone(), offsets.clone()));
        }
        assert_eq!(offsets.len(), 11);
        for e in 0..10 {
            let got = &items[offsets[e] as usize..offsets[e + 1] as usize];
            assert!(got.iter().all(|&x| x == e) && got.len() == e % 3);
        }
        assert_eq!(csr(0, 4, make), (vec![], vec![0]));
    }
}
