//! Vertices at exactly the same position, for [`crate::weld`].
//!
//! Input: positions. Output: every group of two or more vertices whose
//! positions are equal (`-0.0 == 0.0`), each group's vertices in
//! increasing order, the groups in increasing order of their position's
//! bits ([`position_key`]) — the order a sort of all `(key, vertex)` pairs
//! gives. Invariant: the output does not depend on the hash or the
//! thread count.
//!
//! Why not that sort: it moves 32-byte records and compares three words
//! per step, while almost every vertex of a real map has its own
//! position. Here each vertex is tagged with a 32-bit hash of its key in
//! the high half of one `u64` (its id in the low half); one sort of those
//! words brings equal keys next to each other, and only runs of an equal
//! hash (the shared positions and a few collisions) are compared by key.

use rayon::prelude::*;

/// Bits of a position with `-0.0` read as `0.0`.
pub(crate) fn position_key(p: &[f64; 3]) -> [u64; 3] {
    p.map(|x| if x == 0.0 { 0 } else { x.to_bits() })
}

/// A 32-bit hash of a key (multiply–xorshift over its three words).
fn hash32(k: &[u64; 3]) -> u32 {
    const M: u64 = 0x9E37_79B9_7F4A_7C15;
    let mut h = k[0].wrapping_mul(M);
    h = (h ^ (h >> 29) ^ k[1]).wrapping_mul(M);
    h = (h ^ (h >> 29) ^ k[2]).wrapping_mul(M);
    (h >> 32) as u32
}

/// The groups of vertices sharing a position (see the module docs).
pub(crate) fn shared_positions(positions: &[[f64; 3]]) -> Vec<([u64; 3], Vec<u32>)> {
    shared_by(positions, hash32)
}

/// [`shared_positions`] with a given hash (tests pass a poor one).
fn shared_by(
    positions: &[[f64; 3]],
    hash: impl Fn(&[u64; 3]) -> u32 + Sync,
) -> Vec<([u64; 3], Vec<u32>)> {
    let mut tagged: Vec<u64> = positions
        .par_iter()
        .enumerate()
        .map(|(v, p)| u64::from(hash(&position_key(p))) << 32 | v as u64)
        .collect();
    tagged.par_sort_unstable();
    let mut groups = Vec::new();
    let mut keyed: Vec<([u64; 3], u32)> = Vec::new();
    for run in tagged.chunk_by(|a, b| a >> 32 == b >> 32) {
        if run.len() < 2 {
            continue;
        }
        keyed.clear();
        keyed.extend(run.iter().map(|&t| {
            let v = t as u32;
            (position_key(&positions[v as usize]), v)
        }));
        keyed.sort_unstable();
        for same in keyed.chunk_by(|a, b| a.0 == b.0) {
            if same.len() > 1 {
                groups.push((same[0].0, same.iter().map(|x| x.1).collect()));
            }
        }
    }
    groups.sort_unstable_by_key(|g: &([u64; 3], Vec<u32>)| g.0);
    groups
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The reference: a sort of all `(key, vertex)` pairs.
    fn by_sort(positions: &[[f64; 3]]) -> Vec<([u64; 3], Vec<u32>)> {
        let mut all: Vec<([u64; 3], u32)> = positions
            .iter()
            .enumerate()
            .map(|(v, p)| (position_key(p), v as u32))
            .collect();
        all.sort_unstable();
        all.chunk_by(|a, b| a.0 == b.0)
            .filter(|g| g.len() > 1)
            .map(|g| (g[0].0, g.iter().map(|x| x.1).collect()))
            .collect()
    }

    /// Positions on a small lattice (many shared, `±0.0` both), shuffled
    /// by a fixed LCG.
    fn lattice(n: usize, seed: u64) -> Vec<[f64; 3]> {
        let mut s = seed;
        let mut next = || {
            s = s.wrapping_mul(6_364_136_223_846_793_005).wrapping_add(1);
            (s >> 33) as i64
        };
        (0..n)
            .map(|_| {
                std::array::from_fn(|_| match next() % 7 {
                    0 => -0.0,
                    1 => 0.0,
                    r => (r - 3) as f64 * 0.25 + (next() % 3) as f64,
                })
            })
            .collect()
    }

    #[test]
    fn groups_are_those_of_the_full_sort() {
        for (n, seed) in [(0, 1), (1, 2), (2, 3), (50, 4), (3000, 5), (20_000, 6)] {
            let p = lattice(n, seed);
            let want = by_sort(&p);
            assert_eq!(shared_positions(&p), want, "n {n}");
            // every key in one run of a constant hash; a hash of one bit
            assert_eq!(shared_by(&p, |_| 7), want, "n {n}, constant hash");
            assert_eq!(
                shared_by(&p, |k| (k[0] & 1) as u32),
                want,
                "n {n}, 1-bit hash"
            );
        }
    }

    #[test]
    fn distinct_positions_share_nothing_and_signed_zeros_match() {
        let p: Vec<[f64; 3]> = (0..10_000).map(|i| [i as f64, 0.5, -1.0]).collect();
        assert!(shared_positions(&p).is_empty());
        let z = [[0.0, -0.0, 1.0], [-0.0, 0.0, 1.0], [0.0, 0.0, 1.0]];
        assert_eq!(
            shared_positions(&z),
            vec![([0, 0, 1f64.to_bits()], vec![0, 1, 2])]
        );
    }
}
