//! The bad vertices of a sanitization, kept up to date incrementally;
//! shared by the quad and hex sanitizers.
//!
//! Input: a map, its stars, the local coordinates, and a per-simplex test
//! `mask_of(corners) -> u8` (bit `k` set when the simplex makes its corner
//! `k` bad; a function of the simplex's own corners only). Output: per
//! vertex, whether some incident simplex's mask says it is bad.
//!
//! The first scan ([`BadScan::new`]) sets the vertices' flags from the
//! simplices as it tests them, and gives each test the corners already
//! flagged (`mask_known(corners, known)`): it may skip the tests that
//! could only flag those again, and then stores a mask marked [`PARTIAL`]
//! (its bits a part of the simplex's). The flags are those of a full scan
//! whatever the order; a partial mask is tested again (with `mask_of`)
//! before it is read.
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
use std::sync::atomic::{AtomicU8, Ordering::Relaxed};

/// The bit of a stored mask that says its other bits may be only part of
/// the simplex's mask (above every corner's bit).
pub const PARTIAL: u8 = 0x80;

/// `mask`, marked [`PARTIAL`] when it lacks a bit of `known` (a test
/// skipped for `known`'s sake could have set it; with every bit of
/// `known` in `mask`, each skipped test's bits are in it: the mask is
/// whole).
#[inline(always)]
pub fn partial(mask: u8, known: u8) -> u8 {
    mask | if known & !mask != 0 { PARTIAL } else { 0 }
}

/// Bad-vertex flags with the per-simplex masks behind them.
pub struct BadScan {
    bad: Vec<bool>,
    /// Per simplex, its mask (possibly [`PARTIAL`]).
    mask: Vec<u8>,
    /// Whether some mask may be [`PARTIAL`] (before the first update).
    partial: bool,
    /// Per vertex and per simplex, the last update that met it (made with
    /// the scan: made at the first small update instead, they raised
    /// t1000's peak by ~24 MB through glibc's dynamic mmap threshold,
    /// BENCHMARKS.md; zeroed pages never touched cost no memory).
    v_stamp: Vec<u32>,
    s_stamp: Vec<u32>,
    epoch: u32,
    /// Simplices per parallel task.
    min_task: usize,
}

impl BadScan {
    /// Tests every simplex with `mask_known` (module docs); `min_task`
    /// simplices at least per parallel task (below it, splitting costs
    /// more than it saves).
    pub fn new<const N: usize, const D: usize>(
        map: &SimplexMap<N, D>,
        coords: &[[[f64; D]; N]],
        mask_known: impl Fn(&[[f64; D]; N], u8) -> u8 + Sync,
        min_task: usize,
    ) -> Self {
        let nv = map.positions.len();
        let flags = new_flags(nv);
        let mut mask = vec![0u8; coords.len()];
        // plain loops inside tasks of `min_task` simplices
        mask.par_chunks_mut(min_task)
            .zip(map.simplices.par_chunks(min_task))
            .zip(coords.par_chunks(min_task))
            .for_each(|((m, simplices), c)| {
                for ((m, simplex), c) in m.iter_mut().zip(simplices).zip(c) {
                    *m = flag_bad(simplex, c, &flags, &mask_known);
                }
            });
        let partial = mask.iter().any(|&m| m & PARTIAL != 0);
        let bad = into_bools(flags);
        BadScan {
            bad,
            mask,
            partial,
            v_stamp: vec![0; nv],
            s_stamp: vec![0; map.simplices.len()],
            epoch: 0,
            min_task,
        }
    }

    /// The bad vertices, in increasing order.
    pub fn list(&self) -> Vec<u32> {
        (0..self.bad.len() as u32)
            .into_par_iter()
            .with_min_len(LIST_TASK)
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
            // simplices, flagging the corners of every mask (the same masks
            // and flags)
            let mut is_moved = vec![false; self.bad.len()];
            for &v in moved {
                is_moved[v as usize] = true;
            }
            let old = std::mem::take(&mut self.mask);
            let flags = new_flags(self.bad.len());
            self.mask = retest_moved(
                &map.simplices,
                coords,
                old,
                &is_moved,
                &flags,
                mask_of,
                self.min_task,
            );
            self.partial = false;
            self.bad = into_bools(flags);
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
        if self.partial {
            // the partial masks not tested again above: their simplices'
            // flags are right, but `is_bad` reads their masks
            self.mask
                .par_iter_mut()
                .zip(coords)
                .with_min_len(self.min_task)
                .filter(|(m, _)| **m & PARTIAL != 0)
                .for_each(|(m, c)| *m = mask_of(c));
            self.partial = false;
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

/// Vertices per parallel task of [`BadScan::list`].
const LIST_TASK: usize = 1 << 15;

/// `n` vertex flags, all clear (1: bad).
fn new_flags(n: usize) -> Vec<AtomicU8> {
    (0..n).map(|_| AtomicU8::new(0)).collect()
}

/// The flags as `bool`s.
fn into_bools(flags: Vec<AtomicU8>) -> Vec<bool> {
    flags.into_iter().map(|f| f.into_inner() != 0).collect()
}

/// The mask of the simplex with vertices `simplex` and corners `c` by
/// `mask_known`, given its corners already `flags`ged; flags the corners
/// it makes bad.
#[inline]
fn flag_bad<const N: usize, const D: usize>(
    simplex: &[u32; N],
    c: &[[f64; D]; N],
    flags: &[AtomicU8],
    mask_known: impl Fn(&[[f64; D]; N], u8) -> u8,
) -> u8 {
    let mut known = 0u8;
    for (k, &w) in simplex.iter().enumerate() {
        known |= flags[w as usize].load(Relaxed) << k;
    }
    let m = mask_known(c, known);
    let new = m & !known & !PARTIAL;
    if new != 0 {
        for (k, &w) in simplex.iter().enumerate() {
            if new >> k & 1 != 0 {
                flags[w as usize].store(1, Relaxed);
            }
        }
    }
    m
}

/// The masks `mask` after a move: simplex `s`'s, tested again when one
/// of its vertices is `moved` or when it is [`PARTIAL`]; the corners of
/// every mask `flags`ged; in parallel.
fn retest_moved<const N: usize, const D: usize>(
    simplices: &[[u32; N]],
    coords: &[[[f64; D]; N]],
    mut mask: Vec<u8>,
    moved: &[bool],
    flags: &[AtomicU8],
    mask_of: impl Fn(&[[f64; D]; N]) -> u8 + Sync,
    min_task: usize,
) -> Vec<u8> {
    // plain loops inside tasks of `min_task` simplices
    mask.par_chunks_mut(min_task)
        .zip(simplices.par_chunks(min_task))
        .zip(coords.par_chunks(min_task))
        .for_each(|((m, simplices), c)| {
            for ((m, simplex), c) in m.iter_mut().zip(simplices).zip(c) {
                if *m & PARTIAL != 0 || simplex.iter().any(|&w| moved[w as usize]) {
                    *m = mask_of(c);
                }
                for (k, &w) in simplex.iter().enumerate() {
                    if *m >> k & 1 != 0 {
                        flags[w as usize].store(1, Relaxed);
                    }
                }
            }
        });
    mask
}
