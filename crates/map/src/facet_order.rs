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
