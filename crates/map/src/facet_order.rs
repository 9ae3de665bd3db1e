//! The order of a facet's corners in the order of its key (its sorted
//! vertex ids, `crate::topology_build`), and the parity of that order with
//! the apex last: what gluing reads a pair's corner map and orientation
//! off, without matching vertices.
//!
//! Input: a simplex of `N` corners (3 or 4, distinct vertices), a facet
//! `f` (the one opposite corner `f`) and the corner `c` of its least
//! vertex. Output: [`rest_without`]'s packed other vertices and order.
//! Invariant: [`ODD`] is set exactly when `(c, others in key order, f)` is
//! an odd permutation of `0..N` (tests: `topology_build_tests.rs`).

/// Bit of an order ([`rest_without`]): the permutation is odd.
pub(crate) const ODD: u8 = 1 << 6;

/// The other vertices of the key of facet `f` of `simplex` (all but its
/// least, at corner `c`), packed into one integer in the key's order; and
/// the facet's order: its corners in key order, 2 bits each (`c` first),
/// with [`ODD`] when they, followed by `f`, are an odd permutation of
/// `0..N` (N is 3 or 4: one or two other corners, from [`Others`]).
#[inline]
pub(crate) fn rest_without<const N: usize>(simplex: &[u32; N], f: usize, c: usize) -> (u64, u8) {
    let ([lo, hi], odd) = Others::<N>::TABLE[f][c];
    let first = (c as u8) | (lo << 2) | (ODD * odd);
    if N == 3 {
        return (u64::from(simplex[lo as usize]), first);
    }
    let (wl, wh) = (simplex[lo as usize], simplex[hi as usize]);
    // the key's order swaps the two: a transposition more
    let (rest, order) = if wl < wh {
        (u64::from(wl) << 32 | u64::from(wh), first | hi << 4)
    } else {
        (
            u64::from(wh) << 32 | u64::from(wl),
            (first ^ ODD ^ lo << 2) | hi << 2 | lo << 4,
        )
    };
    (rest, order)
}

/// Per pair of orders ([`rest_without`], their low 6 bits) of two
/// half-facets with the same key, the corner map between their simplices
/// (bit-packed as in `crate::topology_build`'s `mate`): byte `a` holds the
/// corner of the second for corner `a` of the first, key position by key
/// position, and the first's apex (the corner its order leaves out) to
/// the second's. A lookup in place of a loop over the key's positions per
/// glued pair.
pub(crate) struct CornerMaps<const N: usize>;

impl<const N: usize> CornerMaps<N> {
    /// `TABLE[o1][o2]`: the corner map from the order `o1` to `o2`
    /// (entries of orders that repeat a corner are never read).
    pub(crate) const TABLE: [[u32; 64]; 64] = {
        let mut table = [[0u32; 64]; 64];
        let mut o1 = 0;
        while o1 < 64 {
            let mut o2 = 0;
            while o2 < 64 {
                table[o1][o2] = Self::corner_map(o1, o2);
                o2 += 1;
            }
            o1 += 1;
        }
        table
    };

    /// [`Self::TABLE`]'s entry of the orders `o1`, `o2`.
    const fn corner_map(o1: usize, o2: usize) -> u32 {
        let (mut word, mut used1, mut used2) = (0u32, 0usize, 0usize);
        let mut i = 0;
        while i < N - 1 {
            let (a, b) = (o1 >> (2 * i) & 3, o2 >> (2 * i) & 3);
            word |= (b as u32) << (8 * a);
            used1 |= 1 << a;
            used2 |= 1 << b;
            i += 1;
        }
        let (apex1, apex2) = (Self::left_out(used1), Self::left_out(used2));
        word | (apex2 as u32) << (8 * apex1)
    }

    /// The least corner of `0..N` not in the set `used` (0 when none).
    const fn left_out(used: usize) -> usize {
        let mut c = 0;
        while c < N {
            if used >> c & 1 == 0 {
                return c;
            }
            c += 1;
        }
        0
    }
}

/// Per apex `f` and least corner `c` of a simplex of `N` corners (3 or
/// 4): its other corners in increasing order (the second 0 for N = 3),
/// and the parity of `(c, others…, f)` as a permutation of `0..N`.
struct Others<const N: usize>;

impl<const N: usize> Others<N> {
    const TABLE: [[([u8; 2], u8); 4]; 4] = {
        let mut table = [[([0u8; 2], 0u8); 4]; 4];
        let mut f = 0;
        while f < N {
            let mut c = 0;
            while c < N {
                let mut perm = [0u8; 4];
                perm[0] = c as u8;
                let mut k = 1;
                let mut j = 0;
                while j < N {
                    if j != f && j != c {
                        perm[k] = j as u8;
                        k += 1;
                    }
                    j += 1;
                }
                perm[N - 1] = f as u8;
                // inversions of perm[..N]
                let mut odd = 0u8;
                let mut i = 0;
                while i < N {
                    let mut l = i + 1;
                    while l < N {
                        odd ^= (perm[i] > perm[l]) as u8;
                        l += 1;
                    }
                    i += 1;
                }
                let second = if N == 4 { perm[2] } else { 0 };
                table[f][c] = ([perm[1], second], odd);
                c += 1;
            }
            f += 1;
        }
        table
    };
}

/// Parity (0 even, 1 odd) of a permutation of `0..N` (the tests' check
/// of [`Others`]).
#[cfg(test)]
pub(crate) fn permutation_parity<const N: usize>(p: &[u8; N]) -> u32 {
    let mut inv = 0;
    for i in 0..N {
        for j in i + 1..N {
            if p[i] > p[j] {
                inv += 1;
            }
        }
    }
    inv % 2
}
