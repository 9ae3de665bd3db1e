//! A checker's report handed over with a print of the mesh it judged, so
//! that a later check of the same mesh reads it instead of checking again
//! (the extraction checks its output as it counts it; the facade's last
//! check of the unchanged mesh would repeat it: 39 M instructions on the
//! torus537 quads, BENCHMARKS.md).
//!
//! Input: a report and the mesh it was made of (vertex count, cells).
//! Output: the report again for a mesh of the same vertex count, cell
//! count and cells' print ([`cells_print`]), or a fresh check otherwise.
//! Invariant: the checkers read nothing but the vertex count and the
//! cells, so a report handed back is the one a fresh check would make,
//! unless a changed mesh kept both counts and the 64-bit print (a changed
//! cell changes the print but with a chance of 2⁻⁶⁴).

use std::borrow::Cow;

/// A report of the mesh whose counts and print it keeps.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Checked<R> {
    report: R,
    n_vertices: usize,
    n_cells: usize,
    print: u64,
}

impl<R: Clone> Checked<R> {
    /// `report`, made by a checker of the mesh of `n_vertices` vertices
    /// and these `cells`.
    pub fn new<const K: usize>(report: R, n_vertices: usize, cells: &[[u32; K]]) -> Self {
        Checked {
            report,
            n_vertices,
            n_cells: cells.len(),
            print: cells_print(cells),
        }
    }

    /// The report.
    pub fn report(&self) -> &R {
        &self.report
    }

    /// The report when it was made of this mesh (`n_vertices`, `cells`).
    pub fn of<const K: usize>(&self, n_vertices: usize, cells: &[[u32; K]]) -> Option<&R> {
        let same = (self.n_vertices, self.n_cells) == (n_vertices, cells.len())
            && self.print == cells_print(cells);
        same.then_some(&self.report)
    }

    /// The report of `earlier` when it was made of this mesh (`n_vertices`,
    /// `cells`), else `check()`'s.
    pub fn or_check<'a, const K: usize>(
        earlier: Option<&'a Self>,
        n_vertices: usize,
        cells: &[[u32; K]],
        check: impl FnOnce() -> R,
    ) -> Cow<'a, R> {
        match earlier.and_then(|c| c.of(n_vertices, cells)) {
            Some(r) => Cow::Borrowed(r),
            None => Cow::Owned(check()),
        }
    }
}

/// A 64-bit print of the cells in order (a multiply–xor hash of every
/// corner, by blocks of [`PRINT_BLOCK`] cells in parallel, then of the
/// blocks' prints in order): equal cells, equal prints.
pub fn cells_print<const K: usize>(cells: &[[u32; K]]) -> u64 {
    use rayon::prelude::*;
    let blocks: Vec<u64> = cells
        .par_chunks(PRINT_BLOCK)
        .map(|b| {
            b.iter()
                .flatten()
                .fold(b.len() as u64, |h, &v| mix(h, u64::from(v)))
        })
        .collect();
    blocks.iter().fold(cells.len() as u64, |h, &b| mix(h, b))
}

/// Cells per block of [`cells_print`].
const PRINT_BLOCK: usize = 4096;

/// One step of the print: `h` rotated, `x` folded in, multiplied.
fn mix(h: u64, x: u64) -> u64 {
    const MIX: u64 = 0x9e37_79b9_7f4a_7c15;
    (h.rotate_left(5) ^ x).wrapping_mul(MIX)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn handed_back_only_for_the_same_mesh() {
        let cells = vec![[0u32, 1, 2, 3], [1, 4, 5, 2]];
        let calls = std::cell::Cell::new(0);
        let check = || {
            calls.set(calls.get() + 1);
            7
        };
        let c = Checked::new(5, 6, &cells);
        assert_eq!(*c.report(), 5);
        assert_eq!(*Checked::or_check(Some(&c), 6, &cells, check), 5);
        assert_eq!(calls.get(), 0);
        // another vertex count, another cell, cells swapped, no report
        let mut changed = cells.clone();
        changed[1][2] = 6;
        let swapped = vec![cells[1], cells[0]];
        for (n, cs) in [(7, &cells), (6, &changed), (6, &swapped)] {
            assert_eq!(*Checked::or_check(Some(&c), n, cs, check), 7);
        }
        assert_eq!(*Checked::or_check(None, 6, &cells, check), 7);
        assert_eq!(calls.get(), 4);
        // the report itself, for the same mesh only
        assert_eq!(c.of(6, &cells), Some(&5));
        for (n, cs) in [(7, &cells), (6, &changed), (6, &swapped)] {
            assert_eq!(c.of(n, cs), None);
        }
    }

    #[test]
    fn prints_of_many_blocks_see_every_cell_and_the_order() {
        let cells: Vec<[u32; 4]> = (0..3 * PRINT_BLOCK as u32 + 5)
            .map(|i| [i, i + 1, 2 * i, 7])
            .collect();
        let p = cells_print(&cells);
        assert_eq!(p, cells_print(&cells.clone()));
        for at in [
            0,
            PRINT_BLOCK - 1,
            PRINT_BLOCK,
            2 * PRINT_BLOCK + 3,
            cells.len() - 1,
        ] {
            let mut c = cells.clone();
            c[at][2] ^= 1;
            assert_ne!(cells_print(&c), p, "cell {at} changed");
            let mut c = cells.clone();
            c.swap(at, (at + PRINT_BLOCK) % cells.len());
            assert_ne!(cells_print(&c), p, "cells {at} swapped across blocks");
        }
        assert_ne!(cells_print(&cells[..cells.len() - 1]), p);
    }
}
