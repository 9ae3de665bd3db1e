//! The fit of a facet whose corners are the same floats in both charts
//! (a facet off the seams; every facet of a map without seams), decided
//! from the set of its terms within `tol`.
//!
//! Input: the facet's corners `a` (one chart), its tolerance, the
//! [`Group`]. Output: the identity [`Fit`] with translation and residual
//! 0 when the identity is the only rotation within `tol` of the best, or
//! `None` for the whole fit ([`crate::transition_fit::fit_facet`]).
//!
//! Invariant: the answer is [`crate::transition_fit`]'s `identity_fit` on
//! `mismatch_table(a, a)`, bit for bit: that table's identity entries are
//! 0 (so its cut is `tol`) and its other entries are the `D²`
//! [`same_terms`]; a rotation other than the identity fits when every
//! term its axes go through is within `tol` ([`same_fits`]).

use crate::transition_fit::{Fit, Group};
use crate::Rot;

/// Per set `w` of terms (bit `k` for term `k` of [`same_terms`]), bit
/// `w`: whether a rotation of `all` other than the first (the identity)
/// goes through no term outside `w`.
pub(crate) fn same_fits<const D: usize>(all: &[Rot<D>]) -> [u64; 8] {
    let needs: Vec<usize> = all[1..]
        .iter()
        .map(|rot| {
            let mut need = 0usize;
            for (j, &d) in rot.images().iter().enumerate() {
                need |= same_term(j, d as usize, D).map_or(0, |k| 1 << k);
            }
            need
        })
        .collect();
    let mut fits = [0u64; 8];
    for w in 0..1usize << (D * D) {
        if needs.iter().any(|&need| need & !w == 0) {
            fits[w >> 6] |= 1 << (w & 63);
        }
    }
    fits
}

/// The fit of a facet whose corners are the same floats in both charts
/// (a facet off the seams) when the identity is the only rotation within
/// `tol` of the best: what `identity_fit` finds on the table of equal
/// charts, whose identity entries are 0 (so the cut is `tol`) and whose
/// other entries are the [`same_terms`], read off the set of terms within
/// `tol` ([`within_tol`]) ([`Group`]`::same_fits`). Then the identity with mismatch,
/// translation and residual 0 (what the whole fit finds: `b − a` is 0 bit
/// for bit). `None`: another rotation fits, left to the whole fit.
#[inline]
pub(crate) fn same_charts_fit<const D: usize>(
    a: &[[f64; D]],
    tol: f64,
    group: &Group<D>,
) -> Option<Fit<D>> {
    if tol.is_nan() || tol < 0.0 || !only_identity::<D>(within_tol(a, tol), group) {
        return None;
    }
    Some(Fit {
        rot: Rot::IDENTITY,
        #[cfg(test)]
        trans: [0.0; D],
        rounded: [0; D],
        residual: 0.0,
        tol,
        ambiguous: None,
    })
}

/// Whether the identity is the only rotation within `tol` of the best
/// on a facet with equal charts whose [`same_terms`] within `tol` are the
/// set `within` (bit `k` for term `k`): no other rotation has all its
/// terms in it (`tol` neither NaN nor negative).
#[inline]
pub(crate) fn only_identity<const D: usize>(within: usize, group: &Group<D>) -> bool {
    group.same_fits[within >> 6] >> (within & 63) & 1 == 0
}

/// The set of [`same_terms`] of the facet `a` within `tol` (bit `k` for
/// term `k`), without the terms: a term is the largest of its edges'
/// values skipping NaN (and 0 when there is none), so it is within `tol`
/// (`tol ≥ 0`) when no edge's value is above: the complement of the OR
/// over the edges of the values above `tol`.
#[inline]
pub(crate) fn within_tol<const D: usize>(a: &[[f64; D]], tol: f64) -> usize {
    // a facet has D corners: loops of a constant length, unrolled
    debug_assert_eq!(a.len(), D);
    let mut above = 0usize;
    for i in 1..D {
        let e: [f64; D] = std::array::from_fn(|k| a[i][k] - a[0][k]);
        let mut pair = D;
        for j in 0..D {
            above |= usize::from((-e[j] - e[j]).abs() > tol) << j;
            for l in j + 1..D {
                above |= usize::from((e[j] - e[l]).abs() > tol) << pair;
                above |= usize::from((-e[j] - e[l]).abs() > tol) << (pair + 1);
                pair += 2;
            }
        }
    }
    !above & ((1 << (D * D)) - 1)
}

/// The index in [`same_terms`] of the entry of axis `j` to direction `d`
/// in the table of equal charts, `None` for `d = 2j` (the identity's, 0):
/// `j` for `d = 2j + 1`, then per pair `lo < hi` of axes, in order, the
/// `+` and the `−` entry (`j → 2l` and `l → 2j` share one).
pub(crate) const fn same_term(j: usize, d: usize, dim: usize) -> Option<usize> {
    let (l, minus) = (d / 2, d % 2);
    if l == j {
        return if minus == 1 { Some(j) } else { None };
    }
    let (lo, hi) = if j < l { (j, l) } else { (l, j) };
    let pair = lo * (2 * dim - lo - 1) / 2 + (hi - lo - 1);
    Some(dim + 2 * pair + minus)
}

/// The `D²` distinct entries of `mismatch_table(a, a)` other than the
/// identity's, bit for bit, in [`same_term`] order: with `ea = eb = e`, the
/// entry of axis `j` to direction `2l` is `|e[j] − e[l]|` and to `2l + 1`
/// is `|−e[j] − e[l]|`, both symmetric in `j, l` (the same floats:
/// `x − y = −(y − x)` and `−x − y = −y − x` exactly), and 0 for `l = j`.
#[cfg(test)]
pub(crate) fn same_terms<const D: usize>(a: &[[f64; D]]) -> [f64; 9] {
    let mut terms = [0.0f64; 9];
    let mut raise = |at: usize, x: f64| {
        // `max` without its NaN branch (a term is never NaN)
        if x > terms[at] {
            terms[at] = x;
        }
    };
    // a facet has D corners: a loop of a constant length, unrolled
    debug_assert_eq!(a.len(), D);
    for i in 1..D {
        let e: [f64; D] = std::array::from_fn(|k| a[i][k] - a[0][k]);
        let mut pair = D;
        for j in 0..D {
            raise(j, (-e[j] - e[j]).abs());
            for l in j + 1..D {
                raise(pair, (e[j] - e[l]).abs());
                raise(pair + 1, (-e[j] - e[l]).abs());
                pair += 2;
            }
        }
    }
    terms
}

/// `mismatch_table(a, a)` from the [`same_terms`].
#[cfg(test)]
pub(crate) fn mismatch_table_same<const D: usize>(a: &[[f64; D]]) -> [f64; 18] {
    table_of_terms::<D>(&same_terms(a))
}

/// The table of equal charts whose terms are `terms`.
#[cfg(test)]
pub(crate) fn table_of_terms<const D: usize>(terms: &[f64; 9]) -> [f64; 18] {
    let mut table = [0.0f64; 18];
    for j in 0..D {
        for d in 0..2 * D {
            table[6 * j + d] = same_term(j, d, D).map_or(0.0, |k| terms[k]);
        }
    }
    table
}
