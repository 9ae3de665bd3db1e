//! The input checks of the pipeline's step 1 in one walk over the
//! simplices (issue 25): [`TriMap::checked`] and [`TetMap::checked`]
//! answer what [`SimplexMap::validate`], [`SimplexMap::check_grid_size`]
//! and, in 3D, [`TetMap::check_not_reflected`] answer one after the other
//! (the same first error, in that order), and count what the first pass
//! reports: the reverted simplices (`det < 0`) and, in 3D, the degenerate
//! ones, as [`crate::singularity::quality`].
//!
//! Input: a map, not yet validated. Output: its [`InputCounts`], or the
//! first error. Invariants: blocks of [`BLOCK`] simplices are tallied in
//! parallel and combined in block order, so every result is the same for
//! every thread count; each simplex's values (determinants, grid points,
//! flat bounds) come from the functions the checks use. The checks sum
//! floats in simplex order; the blocks' sums differ from those by
//! rounding only ([`rounding`]), so they decide alone only when no
//! rounding can change the answer; otherwise (a map near a bound, or one
//! refused) the sequential check runs and decides: answers and errors
//! stay bit-identical.

use crate::error::InputError;
use crate::mesh::{det_of, grid_points, MAX_GRID_POINTS};
use crate::reflect::Reflect;
use crate::{SimplexMap, TetMap, TriMap};
use rayon::prelude::*;

/// Simplices per block of the walk.
const BLOCK: usize = 4096;

/// What the input checks count on the way.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct InputCounts {
    /// Simplices whose map image is reverted (`det < 0`).
    pub reverted: usize,
    /// Degenerate simplices ([`crate::singularity::is_degenerate`]),
    /// counted in 3D only.
    pub degenerate: Option<usize>,
}

/// A block's tally.
#[derive(Clone, Copy, Debug, Default)]
struct Block<X> {
    /// The block's first simplex that breaks the invariants (the rest of
    /// the block is not tallied).
    bad: Option<usize>,
    /// Grid points its simplices' images span ([`grid_points`]), summed.
    points: f64,
    /// Its simplices with `det < 0`.
    reverted: usize,
    /// The dimension's own tally.
    more: X,
}

/// A bound, with room, on the relative rounding error of a float sum of
/// `n` terms of one sign, in any order (about `n·ε/2`), and on how far
/// apart two such sums of the same terms are.
pub(crate) fn rounding(n: usize) -> f64 {
    4.0 * (n as f64 + 1.0) * f64::EPSILON
}

/// The blocks' tallies, in block order: per simplex the invariants
/// checked, and for a valid one its grid points, its reverted flag and
/// `more(tally, s, det)`.
fn walk<const N: usize, const D: usize, X: Default + Send>(
    map: &SimplexMap<N, D>,
    more: impl Fn(&mut X, usize, f64) + Sync,
) -> Vec<Block<X>> {
    let len = map.len();
    (0..len.div_ceil(BLOCK))
        .into_par_iter()
        .map(|b| {
            let mut t = Block::<X>::default();
            for s in b * BLOCK..len.min((b + 1) * BLOCK) {
                if !map.simplex_ok(s) {
                    t.bad = Some(s);
                    break;
                }
                let p = &map.coords[s];
                let det = det_of(p);
                t.points += grid_points(p);
                t.reverted += usize::from(det < 0.0);
                more(&mut t.more, s, det);
            }
            t
        })
        .collect()
}

impl<const N: usize, const D: usize> SimplexMap<N, D> {
    /// [`SimplexMap::validate`]'s and [`SimplexMap::check_grid_size`]'s
    /// answer from the walk's `blocks` (the positions checked before);
    /// the reverted simplices counted.
    fn first_checks<X>(&self, blocks: &[Block<X>]) -> Result<usize, InputError> {
        if let Some(s) = blocks.iter().find_map(|b| b.bad) {
            return Err(self.simplex_error(s));
        }
        let points: f64 = blocks.iter().map(|b| b.points).sum();
        let below = points <= MAX_GRID_POINTS * (1.0 - rounding(self.len()));
        if !below {
            // near the bound or above it: the sequential sum decides
            self.check_grid_size()?;
        }
        Ok(blocks.iter().map(|b| b.reverted).sum())
    }
}

impl TriMap {
    /// [`SimplexMap::validate`], then [`SimplexMap::check_grid_size`], in
    /// one walk (module docs); the reverted triangles counted.
    pub fn checked(&self) -> Result<InputCounts, InputError> {
        self.validate_vertices()?;
        let blocks = walk(self, |_: &mut (), _, _| {});
        let reverted = self.first_checks(&blocks)?;
        Ok(InputCounts {
            reverted,
            degenerate: None,
        })
    }
}

impl TetMap {
    /// [`SimplexMap::validate`], [`SimplexMap::check_grid_size`], then
    /// [`TetMap::check_not_reflected`], in one walk (module docs); the
    /// reverted and the degenerate tets counted.
    pub fn checked(&self) -> Result<InputCounts, InputError> {
        self.validate_vertices()?;
        let blocks = walk(self, |t: &mut Reflect, s, det| t.add(self, s, det));
        let reverted = self.first_checks(&blocks)?;
        let mut sums = Reflect::default();
        for b in &blocks {
            sums.merge(&b.more);
        }
        if !sums.surely_kept(self.len()) {
            self.check_not_reflected()?;
        }
        Ok(InputCounts {
            reverted,
            degenerate: Some(sums.degenerate),
        })
    }
}

#[cfg(test)]
#[path = "scan_tests.rs"]
mod tests;
