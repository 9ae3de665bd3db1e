//! Directed rounding of facing boundary walls (issue 23: holes merged).
//!
//! Input: the integer unknowns of one rounding batch with their values
//! and nearest integers, the ones rounded before, and [`Apart`]: per
//! integer unknown its **wall** (a maximal run of aligned boundary edges
//! on one iso-line of one chart, whose integer unknowns are equal through
//! the rows), and pairs of walls facing each other across a strip of the
//! surface (found by [`crate::integrate::facing`]), `low` below `high` in
//! the continuous map. Output: the batch's targets changed so that every
//! pair with both walls known ends at least 1 apart in its continuous
//! order, `target(high) − target(low) ≥ 1`, every unknown of a wall
//! moved alike; the number of walls moved.
//!
//! Why: rounding each iso-value to its nearest integer puts two walls
//! less than a unit apart on the same iso-line, and the strip between
//! them gets width 0 in the map: the extraction loses it, two holes (or
//! a hole and the outer boundary) merge. Nearest rounding is monotone,
//! so walls at least 1 apart in the continuous map never collide; only
//! moves made here can bring such pairs below 1, and each move is
//! checked against every pair of the moved wall.
//!
//! Method: the pairs from the narrowest, in a few passes: a pair below 1
//! moves one of its walls that is in the batch (walls rounded in an
//! earlier batch stay), `high` to `target(low) + 1` or `low` to
//! `target(high) − 1`, the move that breaks fewer other pairs, then the
//! shorter one. The constraints `t(high) − t(low) ≥ 1` follow the
//! continuous order, so they have no cycle and a solution exists; pairs
//! left violated after the passes stay as nearest rounding made them.

/// "No wall" in [`Apart::wall`].
pub const NO_WALL: u32 = u32::MAX;

/// Passes over the pairs.
const PASSES: usize = 8;

/// Facing walls that must round apart (module docs).
#[derive(Clone, Copy, Debug, Default)]
pub struct Apart<'a> {
    /// Per integer unknown: its wall, or [`NO_WALL`].
    pub wall: &'a [u32],
    /// `(low, high)` walls, narrowest first.
    pub pairs: &'a [(u32, u32)],
}

/// A wall's state in one batch.
#[derive(Clone, Copy, Debug)]
struct State {
    /// Its continuous value.
    value: f64,
    /// Its integer target.
    target: f64,
    /// In the batch (else rounded before: it stays).
    movable: bool,
}

impl Apart<'_> {
    /// Changes the targets of `batch` (`(unknown, value, target)`) so that
    /// facing walls end apart (module docs); `before` gives the walls
    /// rounded in earlier batches: `(unknown, its integer value)`. Returns
    /// the number of walls moved.
    pub fn separate(&self, batch: &mut [(usize, f64, f64)], before: &[(usize, f64)]) -> usize {
        if self.pairs.is_empty() {
            return 0;
        }
        let walls = self.walls();
        let mut state: Vec<Option<State>> = vec![None; walls];
        for &(i, value) in before {
            if let Some(w) = self.wall_of(i) {
                state[w] = Some(State {
                    value,
                    target: value.round(),
                    movable: false,
                });
            }
        }
        for &(i, value, target) in batch.iter() {
            if let Some(w) = self.wall_of(i) {
                if state[w].is_none() {
                    state[w] = Some(State {
                        value,
                        target,
                        movable: true,
                    });
                }
            }
        }
        let mut touching: Vec<Vec<usize>> = vec![Vec::new(); walls];
        for (p, &(lo, hi)) in self.pairs.iter().enumerate() {
            touching[lo as usize].push(p);
            touching[hi as usize].push(p);
        }
        let mut moved = vec![false; walls];
        for _ in 0..PASSES {
            let mut changed = false;
            for &(lo, hi) in self.pairs {
                let (lo, hi) = (lo as usize, hi as usize);
                let (Some(a), Some(b)) = (state[lo], state[hi]) else {
                    continue;
                };
                if b.target - a.target >= 1.0 {
                    continue;
                }
                let mut best: Option<(usize, f64, (usize, f64))> = None;
                for (w, s, t) in [(hi, b, a.target + 1.0), (lo, a, b.target - 1.0)] {
                    if !s.movable {
                        continue;
                    }
                    let broken = self.broken(&state, &touching[w], w, t);
                    let key = (broken, (t - s.value).abs());
                    if best.is_none_or(|(_, _, k)| key.0 < k.0 || (key.0 == k.0 && key.1 < k.1)) {
                        best = Some((w, t, key));
                    }
                }
                if let Some((w, t, _)) = best {
                    if let Some(s) = state[w].as_mut() {
                        s.target = t;
                    }
                    moved[w] = true;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        for entry in batch.iter_mut() {
            if let Some(s) = self.wall_of(entry.0).and_then(|w| state[w]) {
                if s.movable {
                    entry.2 = s.target;
                }
            }
        }
        moved.iter().filter(|&&m| m).count()
    }

    /// Number of walls: one more than the largest named.
    fn walls(&self) -> usize {
        let named = self.wall.iter().copied().filter(|&w| w != NO_WALL);
        let pairs = self.pairs.iter().flat_map(|&(a, b)| [a, b]);
        named
            .chain(pairs)
            .map(|w| w as usize + 1)
            .max()
            .unwrap_or(0)
    }

    /// The wall of integer unknown `i`, if any.
    fn wall_of(&self, i: usize) -> Option<usize> {
        self.wall
            .get(i)
            .filter(|&&w| w != NO_WALL)
            .map(|&w| w as usize)
    }

    /// Pairs among `pairs` (indices) that wall `w` at target `t` leaves
    /// below 1 apart.
    fn broken(&self, state: &[Option<State>], pairs: &[usize], w: usize, t: f64) -> usize {
        let at = |x: usize| {
            if x == w {
                Some(t)
            } else {
                state[x].map(|s| s.target)
            }
        };
        pairs
            .iter()
            .filter(|&&p| {
                let (lo, hi) = self.pairs[p];
                matches!((at(lo as usize), at(hi as usize)), (Some(a), Some(b)) if b - a < 1.0)
            })
            .count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Rounded targets of `values` (one wall each) with `pairs`.
    fn targets(values: &[f64], pairs: &[(u32, u32)]) -> (Vec<f64>, usize) {
        let wall: Vec<u32> = (0..values.len() as u32).collect();
        let apart = Apart { wall: &wall, pairs };
        let mut batch: Vec<(usize, f64, f64)> = values
            .iter()
            .enumerate()
            .map(|(i, &v)| (i, v, v.round()))
            .collect();
        let moved = apart.separate(&mut batch, &[]);
        (batch.iter().map(|b| b.2).collect(), moved)
    }

    /// Two walls 0.3 apart round to the same integer; the one closer to
    /// the next integer moves: 2.4 → 2 stays, 2.7 → 3 stays as well, so
    /// nothing moves; 2.1 and 2.4 both round to 2, and 2.4 goes to 3.
    #[test]
    fn two_walls_below_one_apart_round_apart() {
        assert_eq!(targets(&[2.4, 2.7], &[(0, 1)]), (vec![2.0, 3.0], 0));
        assert_eq!(targets(&[2.1, 2.4], &[(0, 1)]), (vec![2.0, 3.0], 1));
        // the order of the continuous map is kept, not the nearest pair
        assert_eq!(targets(&[2.4, 2.1], &[(1, 0)]), (vec![3.0, 2.0], 1));
    }

    /// Three walls in a row, each 0.3 from the next (a hole between two
    /// others): they end 1 apart each, the middle one unmoved.
    #[test]
    fn a_row_of_walls_spreads() {
        let (t, moved) = targets(&[4.7, 5.0, 5.3], &[(0, 1), (1, 2)]);
        assert_eq!(t, vec![4.0, 5.0, 6.0]);
        assert_eq!(moved, 2);
    }

    /// A wall rounded in an earlier batch stays; the other one moves.
    #[test]
    fn walls_rounded_before_stay() {
        let wall = [0, 1];
        let apart = Apart {
            wall: &wall,
            pairs: &[(0, 1)],
        };
        let mut batch = vec![(1, 3.2, 3.0)];
        assert_eq!(apart.separate(&mut batch, &[(0, 3.0)]), 1);
        assert_eq!(batch[0].2, 4.0);
        // no pair: nothing happens
        let none = Apart::default();
        let mut batch = vec![(0, 3.2, 3.0)];
        assert_eq!(none.separate(&mut batch, &[]), 0);
    }
}
