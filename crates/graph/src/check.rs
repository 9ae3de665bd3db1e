//! Invariant checks of the node graph (see [`crate::graph`] for the list).
//!
//! [`NodeGraph::check`] verifies everything, [`NodeGraph::check_structure`]
//! everything but the label rule (traced input graphs may break it; it is
//! counted by [`NodeGraph::label_violations`]), and `check_sides` a few
//! sides only, cheap enough for `debug_assert!` after every operation.

use crate::graph::{NodeGraph, NONE};
use crate::ids::Side;
use rayon::prelude::*;
use std::fmt;

/// A broken invariant, naming the first offending side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GraphError {
    /// The per-node and per-side arrays have inconsistent lengths.
    Lengths,
    /// `opp[side]` is not a side of the graph.
    OppOutOfRange(Side),
    /// `opp[side]` is `side` itself.
    GluedToItself(Side),
    /// `opp[opp[side]] != side`.
    NotInvolution(Side),
    /// `rot[opp[side]] != rot[side].inverse()`.
    RotationNotInverse(Side),
    /// A side of a dead node is glued.
    LinkFromDead(Side),
    /// A side is glued to a side of a dead node.
    LinkToDead(Side),
    /// The glued pair breaks the label rule.
    LabelRule(Side),
}

impl fmt::Display for GraphError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            GraphError::Lengths => write!(f, "array lengths disagree"),
            GraphError::OppOutOfRange(s) => write!(f, "side {}: opposite out of range", s.0),
            GraphError::GluedToItself(s) => write!(f, "side {}: glued to itself", s.0),
            GraphError::NotInvolution(s) => write!(f, "side {}: opposite is not mutual", s.0),
            GraphError::RotationNotInverse(s) => {
                write!(f, "side {}: rotations of the pair are not inverse", s.0)
            }
            GraphError::LinkFromDead(s) => write!(f, "side {}: dead node is glued", s.0),
            GraphError::LinkToDead(s) => write!(f, "side {}: glued to a dead node", s.0),
            GraphError::LabelRule(s) => write!(f, "side {}: pair breaks the label rule", s.0),
        }
    }
}

impl std::error::Error for GraphError {}

impl<const D: usize> NodeGraph<D> {
    /// Checks every invariant, the label rule included.
    pub fn check(&self) -> Result<(), GraphError> {
        self.check_structure()?;
        match (0..self.n_sides() as u32)
            .map(Side)
            .find(|&s| self.opposite(s).is_some() && !self.label_ok(s))
        {
            Some(s) => Err(GraphError::LabelRule(s)),
            None => Ok(()),
        }
    }

    /// Checks every invariant except the label rule.
    pub fn check_structure(&self) -> Result<(), GraphError> {
        let n = self.reverted.len();
        if self.alive.len() != n || self.opp.len() != n * 2 * D || self.rot.len() != self.opp.len()
        {
            return Err(GraphError::Lengths);
        }
        (0..self.n_sides() as u32)
            .map(Side)
            .try_for_each(|s| self.check_side(s))
    }

    /// Checks the structural invariants at the given sides only.
    pub(crate) fn check_sides(&self, sides: &[Side]) -> Result<(), GraphError> {
        sides.iter().try_for_each(|&s| self.check_side(s))
    }

    fn check_side(&self, s: Side) -> Result<(), GraphError> {
        let o = self.opp[s.idx()];
        if o == NONE {
            return Ok(());
        }
        if !self.is_alive(self.node_of(s)) {
            return Err(GraphError::LinkFromDead(s));
        }
        let Some(&back) = self.opp.get(o as usize) else {
            return Err(GraphError::OppOutOfRange(s));
        };
        if o == s.0 {
            return Err(GraphError::GluedToItself(s));
        }
        if back != s.0 {
            return Err(GraphError::NotInvolution(s));
        }
        if !self.is_alive(self.node_of(Side(o))) {
            return Err(GraphError::LinkToDead(s));
        }
        if self.rot[o as usize] != self.rot[s.idx()].inverse() {
            return Err(GraphError::RotationNotInverse(s));
        }
        Ok(())
    }

    /// Number of glued pairs breaking the label rule.
    pub fn label_violations(&self) -> usize {
        (0..self.n_sides() as u32)
            .into_par_iter()
            .with_min_len(4096)
            .map(Side)
            .filter(|&s| self.opposite(s).is_some_and(|o| s < o) && !self.label_ok(s))
            .count()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ids::Node;
    use crate::testgrid::GridSpec;
    use dualex_map::{Rot2, Rot3};

    /// A valid 2D graph with one pleat, and the side of that pleat.
    fn sample() -> (NodeGraph<2>, Side) {
        let g = GridSpec::regular([3, 2]).fold(1).build();
        g.check().unwrap();
        let s = (0..g.n_sides() as u32)
            .map(Side)
            .find(|&s| g.is_pleat(s))
            .unwrap();
        (g, s)
    }

    #[test]
    fn checker_catches_every_broken_invariant() {
        let (g, s) = sample();
        let o = g.opposite(s).unwrap();
        let mut b = g.clone();
        b.opp[s.idx()] = 1_000_000;
        assert_eq!(b.check(), Err(GraphError::OppOutOfRange(s)));
        let mut b = g.clone();
        b.opp[s.idx()] = s.0;
        assert_eq!(b.check(), Err(GraphError::GluedToItself(s)));
        let mut b = g.clone();
        let free = (0..g.n_sides() as u32)
            .map(Side)
            .find(|&x| g.opposite(x).is_none())
            .unwrap();
        b.opp[o.idx()] = free.0;
        let first = Side(s.0.min(o.0));
        assert_eq!(b.check(), Err(GraphError::NotInvolution(first)));
        let mut b = g.clone();
        b.rot[s.idx()] = Rot2::quarter_turns(2);
        assert_eq!(b.check(), Err(GraphError::RotationNotInverse(first)));
        let mut b = g.clone();
        b.alive[g.node_of(o).idx()] = false;
        let err = b.check().unwrap_err();
        assert!(matches!(
            err,
            GraphError::LinkFromDead(_) | GraphError::LinkToDead(_)
        ));
        let mut b = g.clone();
        b.alive.push(true);
        assert_eq!(b.check(), Err(GraphError::Lengths));
        // label rule: a pleat with the other flag on one node is a plain pair
        // whose partner direction is wrong
        let mut b = g.clone();
        let x = g.node_of(s).idx();
        b.reverted[x] = !b.reverted[x];
        assert!(matches!(b.check(), Err(GraphError::LabelRule(_))));
        assert_eq!(b.check_structure(), Ok(()));
        assert!(b.label_violations() > 0);
    }

    #[test]
    fn link_to_dead_is_reported_from_the_living_side() {
        let mut g = NodeGraph::<3>::new(vec![false; 2]);
        let (a, b) = (g.side(Node(0), 4), g.side(Node(1), 5));
        g.link(a, b, Rot3::IDENTITY).unwrap();
        g.check().unwrap();
        g.alive[1] = false;
        assert_eq!(g.check(), Err(GraphError::LinkToDead(a)));
        assert!(GraphError::LinkToDead(a).to_string().contains("dead"));
    }
}
