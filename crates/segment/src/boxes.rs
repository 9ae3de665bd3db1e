//! The integer boxes of one simplex's corners, computed once per simplex
//! and shared by the prefilters of the sanitization scan (both
//! dimensions): which corners lie on an iso, which edges span which
//! axes, and each edge's integer range.
//!
//! Input: the corners `c` of a simplex in local coordinates (not NaN:
//! validated input). Output: [`Boxes`], per corner `k` and axis `a` of
//! `x = c[k][a]`: `hi = floor(x + 2·EPS)` (one rounding) and whether the
//! range grown by `2·EPS` holds it (`x − 2·EPS ≤ hi`: "near").
//!
//! Invariant: every answer equals the one from the [`box_bounds`]
//! `[lo, hi] = [ceil(x − 2·EPS), hi]` of every coordinate. The grown range
//! is narrower than 1, so `lo` is `hi` when near and `hi + 1` otherwise;
//! two corners' ranges together hold an integer ([`box_spans`]) iff one of
//! them is near or their `hi` differ (`hi_k < hi_l`: `x_k − 2·EPS <
//! hi_k + 1 ≤ hi_l`, and `hi_l ≤ x_l + 2·EPS`).

#[cfg(doc)]
use crate::grid::{box_bounds, box_spans};
use crate::grid::{floor_above, near_int, EPS};
use dualex_util::round::{nearest_even, FAST};

/// Per corner and axis of a simplex: the greatest integer in reach of its
/// grown range, and whether the range holds it (module docs).
#[derive(Clone, Copy, Debug)]
pub struct Boxes<const N: usize, const D: usize> {
    /// `floor(x + 2·EPS)` per corner and axis ([`floor_above`]).
    pub hi: [[f64; D]; N],
    /// Per corner, bit `a` set when `x − 2·EPS ≤ hi` on axis `a`.
    pub near: [u8; N],
}

impl<const N: usize, const D: usize> Boxes<N, D> {
    /// The boxes of every coordinate of `c`.
    #[inline]
    pub fn of(c: &[[f64; D]; N]) -> Self {
        let small = c.iter().flatten().all(|x| x.abs() < 0.5 * FAST);
        Self::of_known(c, small)
    }

    /// [`Self::of`] given `small`: whether every coordinate of `c` is below
    /// `FAST / 2` in magnitude (as [`crate::grid::spanned_axes_small`]
    /// finds). Then [`floor_above`] is one exact rounding by
    /// [`nearest_even`] for every coordinate, without its test and branch.
    #[inline]
    pub fn of_known(c: &[[f64; D]; N], small: bool) -> Self {
        let (mut hi, mut near) = ([[0.0; D]; N], [0u8; N]);
        if small {
            for k in 0..N {
                for a in 0..D {
                    let z = c[k][a] + 2.0 * EPS;
                    let rz = nearest_even(z);
                    let h = if rz > z { rz - 1.0 } else { rz };
                    hi[k][a] = h;
                    near[k] |= u8::from(c[k][a] - 2.0 * EPS <= h) << a;
                }
            }
            return Boxes { hi, near };
        }
        for k in 0..N {
            for a in 0..D {
                let h = floor_above(c[k][a]);
                hi[k][a] = h;
                near[k] |= u8::from(c[k][a] - 2.0 * EPS <= h) << a;
            }
        }
        Boxes { hi, near }
    }

    /// Per axis `a`, bit `a` set when the box of the edge `k`–`l`, grown by
    /// `2·EPS`, holds an integer on that axis ([`box_spans`]).
    #[inline]
    pub fn spans(&self, k: usize, l: usize) -> u8 {
        let mut differ = 0u8;
        for a in 0..D {
            differ |= u8::from(self.hi[k][a] != self.hi[l][a]) << a;
        }
        differ | self.near[k] | self.near[l]
    }

    /// Per axis `a`, bit `a` set when some pair of corners spans an integer
    /// on it ([`Self::spans`] of some edge); as
    /// [`crate::grid::spanned_axes`].
    #[inline]
    pub fn spanned(&self) -> u8 {
        let mut bits = 0u8;
        for k in 1..N {
            bits |= self.spans(0, k);
        }
        bits
    }

    /// The corners of `c` (whose boxes these are) [`near_int`] on some
    /// axis, as a mask (bit `k`: corner `k`): only a near coordinate is
    /// rounded again.
    #[inline]
    pub fn near_any(&self, c: &[[f64; D]; N]) -> u8 {
        let mut mask = 0u8;
        for (k, (p, &near)) in c.iter().zip(&self.near).enumerate() {
            if near == 0 {
                continue;
            }
            let mut on = false;
            for (a, &x) in p.iter().enumerate() {
                on |= near >> a & 1 == 1 && near_int(x);
            }
            mask |= u8::from(on) << k;
        }
        mask
    }

    /// [`Self::spans`] of every edge of `edges`, in order.
    #[inline]
    pub fn edge_spans<const E: usize>(&self, edges: &[[usize; 2]; E]) -> [u8; E] {
        let mut span = [0u8; E];
        for (bits, &[k, l]) in span.iter_mut().zip(edges) {
            *bits = self.spans(k, l);
        }
        span
    }

    /// `ceil(x − 2·EPS)` of corner `k` on axis `a`: `hi` when near, else
    /// `hi + 1`.
    #[inline]
    fn lo(&self, k: usize, a: usize) -> f64 {
        // 1 when not near (no branch)
        let far = self.near[k] >> a & 1 ^ 1;
        self.hi[k][a] + f64::from(far)
    }

    /// The integer range of the edge `k`–`l`'s box (grown by `2·EPS`) per
    /// axis, `[lo, hi]` (empty when `lo > hi`).
    #[inline(always)]
    pub fn range(&self, k: usize, l: usize) -> [[f64; 2]; D] {
        // a plain loop (`array::from_fn` is not always inlined); not NaN
        // (validated input): plain comparisons, cheaper than f64::min
        let mut r = [[0.0; 2]; D];
        for (a, r) in r.iter_mut().enumerate() {
            let (lk, ll) = (self.lo(k, a), self.lo(l, a));
            let (hk, hl) = (self.hi[k][a], self.hi[l][a]);
            *r = [if ll < lk { ll } else { lk }, if hl > hk { hl } else { hk }];
        }
        r
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::tests::{near_values, pairs, picker};
    use crate::grid::{box_bounds, box_spans, spanned_axes};

    fn check<const N: usize, const D: usize>(c: &[[f64; D]; N]) {
        let b = Boxes::of(c);
        // the general path gives the fast path's boxes, bit for bit
        let slow = Boxes::of_known(c, false);
        assert_eq!(b.near, slow.near, "{c:?}");
        assert_eq!(
            b.hi.map(|p| p.map(f64::to_bits)),
            slow.hi.map(|p| p.map(f64::to_bits)),
            "{c:?}"
        );
        assert_eq!(b.spanned(), pairs(c), "{c:?}");
        assert_eq!(spanned_axes(c), pairs(c), "{c:?}");
        let mut any = 0u8;
        for a in 0..D {
            let want = (0..N).fold(0u8, |m, k| m | u8::from(near_int(c[k][a])) << k);
            assert!(want == 0 || b.spanned() >> a & 1 == 1, "{c:?}");
            any |= want;
        }
        assert_eq!(b.near_any(c), any, "{c:?}");
        for k in 0..N {
            for l in 0..N {
                let r = b.range(k, l);
                for a in 0..D {
                    let (p, q) = (box_bounds(c[k][a]), box_bounds(c[l][a]));
                    assert_eq!(b.spans(k, l) >> a & 1 == 1, box_spans(p, q), "{c:?}");
                    assert_eq!(r[a], [p[0].min(q[0]), p[1].max(q[1])], "{c:?}");
                }
            }
        }
    }

    /// Every answer of [`Boxes`] equals the per-value formulation, on
    /// triangles and tets of values near integers, ties and random ones.
    #[test]
    fn boxes_equal_per_value_tests() {
        let vals = near_values();
        let mut pick = picker(&vals, 5);
        for _ in 0..50000 {
            check::<3, 2>(&std::array::from_fn(|_| [pick(), pick()]));
            check::<4, 3>(&std::array::from_fn(|_| [pick(), pick(), pick()]));
        }
    }
}
