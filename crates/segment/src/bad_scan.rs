//! The bad vertices of a sanitization, kept up to date incrementally;
//! shared by the quad and hex sanitizers.
//!
//! Input: a map, its stars, the local coordinates, and a per-simplex test
//! `mask_of(corners) -> u8` (bit `k` set when the simplex makes its corner
//! `k` bad; a function of the simplex's own corners only). Output: per
//! vertex, whether some incident simplex's mask says it is bad.
//!
//! Invariant: after [`BadScan::update`] with the vertices that moved, the
//! flags equal those of a full scan — only the simplices in the stars of
//! the moved vertices are tested again, and only the vertices of simplices
//! whose mask changed are re-derived (a vertex's star holds all its
//! corners). The tests run in parallel (order-preserving collect; the
//! masks do not depend on the thread count); when the moved vertices'
//! stars cover about half the simplices or more, the update is one
//! parallel pass over all simplices and all vertices instead (same
//! result).

use dualex_map::{SimplexMap, Stars};
use rayon::prelude::*;

/// Bad-vertex flags with the per-simplex masks behind them.
pub struct BadScan {
    bad: Vec<bool>,
    mask: Vec<u8>,
    v_stamp: Vec<u32>,
    s_stamp: Vec<u32>,
    epoch: u32,
    /// Simplices per parallel task.
    min_task: usize,
}

impl BadScan {
    /// Tests every simplex; `min_task` simplices at least per parallel
    /// task (below it, splitting costs more than it saves).
    pub fn new<const N: usize, const D: usize>(
        map: &SimplexMap<N, D>,
        stars: &Stars<D>,
        coords: &[[[f64; D]; N]],
        mask_of: impl Fn(&[[f64; D]; N]) -> u8 + Sync,
        min_task: usize,
    ) -> Self {
        let nv = map.positions.len();
        let mask: Vec<u8> = coords
            .par_iter()
            .with_min_len(min_task)
            .map(&mask_of)
            .collect();
        let bad = all_bad(stars, &mask, nv, min_task);
        BadScan {
            bad,
            mask,
            v_stamp: vec![0; nv],
            s_stamp: vec![0; map.simplices.len()],
            epoch: 0,
            min_task,
        }
    }

    /// The bad vertices, in increasing order.
    pub fn list(&self) -> Vec<u32> {
        (0..self.bad.len() as u32)
            .filter(|&v| self.bad[v as usize])
            .collect()
    }

    /// Re-tests after the vertices `moved` (corners in their stars) moved.
    pub fn update<const N: usize, const D: usize>(
        &mut self,
        map: &SimplexMap<N, D>,
        stars: &Stars<D>,
        coords: &[[[f64; D]; N]],
        mask_of: impl Fn(&[[f64; D]; N]) -> u8 + Sync,
        moved: &[u32],
    ) {
        self.epoch += 1;
        let epoch = self.epoch;
        let corners: usize = moved.iter().map(|&v| stars.of(v as usize).len()).sum();
        if corners >= self.mask.len() / 2 {
            // about half the simplices or more: one parallel pass over all
            // simplices and all vertices (the same masks and flags)
            let mut is_moved = vec![false; self.bad.len()];
            for &v in moved {
                is_moved[v as usize] = true;
            }
            let old = std::mem::take(&mut self.mask);
            self.mask = retest_moved(
                &map.simplices,
                coords,
                old,
                &is_moved,
                mask_of,
                self.min_task,
            );
            self.bad = all_bad(stars, &self.mask, self.bad.len(), self.min_task);
            return;
        }
        // the simplices whose corners moved
        let mut redo = Vec::new();
        for &v in moved {
            for e in stars.of(v as usize) {
                let s = e.simplex as usize;
                if self.s_stamp[s] != epoch {
                    self.s_stamp[s] = epoch;
                    redo.push(e.simplex);
                }
            }
        }
        let masks: Vec<u8> = redo
            .par_iter()
            .with_min_len(self.min_task)
            .map(|&s| mask_of(&coords[s as usize]))
            .collect();
        // the vertices of the simplices whose mask changed
        let mut verts = Vec::new();
        for (&s, &m) in redo.iter().zip(&masks) {
            if self.mask[s as usize] == m {
                continue;
            }
            self.mask[s as usize] = m;
            for &w in &map.simplices[s as usize] {
                if self.v_stamp[w as usize] != epoch {
                    self.v_stamp[w as usize] = epoch;
                    verts.push(w);
                }
            }
        }
        for w in verts {
            self.bad[w as usize] = is_bad(stars, &self.mask, w as usize);
        }
    }
}

/// Whether vertex `v` is bad: some simplex of its star makes its corner
/// bad (a vertex's star holds all its corners).
#[inline]
fn is_bad<const D: usize>(stars: &Stars<D>, mask: &[u8], v: usize) -> bool {
    stars
        .of(v)
        .iter()
        .any(|e| mask[e.simplex as usize] >> e.corner & 1 != 0)
}

/// [`is_bad`] of the vertices `0..nv`, in parallel.
fn all_bad<const D: usize>(stars: &Stars<D>, mask: &[u8], nv: usize, min_task: usize) -> Vec<bool> {
    (0..nv)
        .into_par_iter()
        .with_min_len(min_task)
        .map(|v| is_bad(stars, mask, v))
        .collect()
}

/// The masks after a move: simplex `s`'s `old[s]`, tested again when one
/// of its vertices is `moved`; in parallel.
fn retest_moved<const N: usize, const D: usize>(
    simplices: &[[u32; N]],
    coords: &[[[f64; D]; N]],
    old: Vec<u8>,
    moved: &[bool],
    mask_of: impl Fn(&[[f64; D]; N]) -> u8 + Sync,
    min_task: usize,
) -> Vec<u8> {
    simplices
        .par_iter()
        .zip(coords)
        .zip(old)
        .with_min_len(min_task)
        .map(|((simplex, c), m)| {
            if simplex.iter().any(|&w| moved[w as usize]) {
                mask_of(c)
            } else {
                m
            }
        })
        .collect()
}
