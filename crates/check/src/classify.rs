//! The first pass of both checks: each cell judged out of range,
//! degenerate or good, in parallel; the good ones kept for the later
//! passes.
//!
//! Input: the cells (`K` vertex ids each) and the per-dimension judgement
//! ([`Class`] of one cell: the quad check's and the hex check's own).
//! Output: [`Sorted`]: the out-of-range and degenerate cells' indices,
//! increasing, and the good cells in input order — the input itself,
//! borrowed, when every cell is good (an extraction's output always is),
//! else a copy. Invariant: the result does not depend on the thread count.

use rayon::prelude::*;
use std::borrow::Cow;

/// What a check finds one cell to be.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Class {
    /// A vertex at or beyond the vertex count.
    OutOfRange,
    /// A repeated vertex (hex: or fewer than 6 distinct faces).
    Degenerate,
    /// Neither.
    Good,
}

/// The cells sorted by [`Class`] ([`classify`]).
pub(crate) struct Sorted<'a, const K: usize> {
    /// The good cells, in input order.
    pub good: Cow<'a, [[u32; K]]>,
    /// Indices of the cells out of range, increasing.
    pub out_of_range: Vec<usize>,
    /// Indices of the degenerate cells, increasing.
    pub degenerate: Vec<usize>,
}

/// The cells judged by `class_of` in parallel, sorted in cell order (see
/// the module docs).
pub(crate) fn classify<const K: usize>(
    cells: &[[u32; K]],
    class_of: impl Fn(&[u32; K]) -> Class + Sync,
) -> Sorted<'_, K> {
    let class: Vec<Class> = cells
        .par_iter()
        .with_min_len(1 << 12)
        .map(&class_of)
        .collect();
    let mut s = Sorted {
        good: Cow::Borrowed(cells),
        out_of_range: Vec::new(),
        degenerate: Vec::new(),
    };
    if class.iter().all(|&c| c == Class::Good) {
        return s;
    }
    let mut good = Vec::with_capacity(cells.len());
    for (i, (cell, class)) in cells.iter().zip(&class).enumerate() {
        match class {
            Class::OutOfRange => s.out_of_range.push(i),
            Class::Degenerate => s.degenerate.push(i),
            Class::Good => good.push(*cell),
        }
    }
    s.good = Cow::Owned(good);
    s
}

/// Whether a vertex of `cell` is at or beyond `n`.
pub(crate) fn out_of_range<const K: usize>(n: usize, cell: &[u32; K]) -> bool {
    cell.iter().any(|&v| v as usize >= n)
}

/// Whether a vertex of `cell` appears twice.
pub(crate) fn repeated<const K: usize>(cell: &[u32; K]) -> bool {
    (0..K).any(|i| cell[..i].contains(&cell[i]))
}
