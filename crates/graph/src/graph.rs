//! The node graph: nodes, sides, the opposite relation and chart rotations.
//!
//! Input: one `reverted` flag per node (the node lies in a simplex whose map
//! has det < 0). Pairs of sides are then glued with [`NodeGraph::link`].
//!
//! Storage (parallel arrays, tombstones for deleted nodes):
//! ```text
//!   reverted[n]  node n's chart is mirrored w.r.t. the surface/volume
//!   alive[n]     node n has not been deleted (OP1)
//!   opp[s]       side glued to side s, NONE (u32::MAX) when unmatched
//!   rot[s]       rotation from the chart of node(s) to the chart of
//!                node(opp[s]); identity when s is unmatched
//! ```
//! Invariants (see [`NodeGraph::check`]): `opp` is an involution without
//! fixed points, `rot[opp[s]] == rot[s].inverse()`, dead nodes have no
//! glued side, and every pair obeys the **label rule**: for X.s ↔ Y.t with
//! ρ = rot[X.s], same flags ⇒ t = ρ(s ^ 1) (Y is one step from X along s),
//! different flags (a *pleat*) ⇒ t = ρ(s) (X and Y share their integer
//! coordinates in the common chart).

use crate::ids::{Node, Side};
use crate::ops::OpError;
use dualex_map::Rot;
use rayon::prelude::*;

/// Marker for an unmatched side in the flat opposite array.
pub(crate) const NONE: u32 = u32::MAX;

/// The dimension-generic node graph (D = 2: quads, D = 3: hexes).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct NodeGraph<const D: usize> {
    /// Per node: the chart is mirrored (det < 0).
    pub(crate) reverted: Vec<bool>,
    /// Per node: not deleted.
    pub(crate) alive: Vec<bool>,
    /// Per side: the glued side, or [`NONE`].
    pub(crate) opp: Vec<u32>,
    /// Per side: chart rotation from node(s) to node(opp[s]).
    pub(crate) rot: Vec<Rot<D>>,
}

impl<const D: usize> NodeGraph<D> {
    /// Sides per node.
    pub const SIDES: usize = 2 * D;
    /// Corners per node.
    pub const CORNERS: usize = 1 << D;

    /// A graph of `reverted.len()` alive nodes, all sides unmatched.
    pub fn new(reverted: Vec<bool>) -> Self {
        let n = reverted.len();
        NodeGraph {
            alive: vec![true; n],
            reverted,
            opp: vec![NONE; n * 2 * D],
            rot: vec![Rot::IDENTITY; n * 2 * D],
        }
    }

    /// Number of nodes, dead ones included.
    pub fn n_nodes(&self) -> usize {
        self.reverted.len()
    }

    /// Number of sides, dead nodes' included.
    pub fn n_sides(&self) -> usize {
        self.opp.len()
    }

    /// Number of alive nodes.
    pub fn n_alive(&self) -> usize {
        self.alive.iter().filter(|&&a| a).count()
    }

    /// Number of alive reverted nodes.
    pub fn n_reverted_alive(&self) -> usize {
        (0..self.n_nodes())
            .filter(|&n| self.alive[n] && self.reverted[n])
            .count()
    }

    /// Side `dir` of `node`.
    #[inline]
    pub fn side(&self, node: Node, dir: usize) -> Side {
        node.side::<D>(dir)
    }

    /// The node a side belongs to.
    #[inline]
    pub fn node_of(&self, s: Side) -> Node {
        s.node::<D>()
    }

    /// The direction of a side.
    #[inline]
    pub fn dir_of(&self, s: Side) -> usize {
        s.dir::<D>()
    }

    /// Whether the node exists and is alive.
    pub fn is_alive(&self, n: Node) -> bool {
        self.alive.get(n.idx()).copied().unwrap_or(false)
    }

    /// Whether the node exists and is reverted.
    pub fn is_reverted(&self, n: Node) -> bool {
        self.reverted.get(n.idx()).copied().unwrap_or(false)
    }

    /// The side glued to `s`, if any.
    pub fn opposite(&self, s: Side) -> Option<Side> {
        match self.opp.get(s.idx()) {
            Some(&o) if o != NONE => Some(Side(o)),
            _ => None,
        }
    }

    /// The rotation from the chart of node(s) to the chart of the node glued
    /// to `s`, if `s` is glued.
    pub fn rotation(&self, s: Side) -> Option<Rot<D>> {
        self.opposite(s).map(|_| self.rot[s.idx()])
    }

    /// Whether `s` is glued to a node of the other orientation.
    pub fn is_pleat(&self, s: Side) -> bool {
        self.opposite(s)
            .is_some_and(|o| self.is_reverted(self.node_of(s)) != self.is_reverted(self.node_of(o)))
    }

    /// The direction that the partner of side `s` of `x` must have under
    /// the label rule, for a partner node `y` reached with rotation `rho`.
    #[inline]
    pub fn label_dir(&self, x: Node, y: Node, dir: usize, rho: &Rot<D>) -> usize {
        let same = self.is_reverted(x) == self.is_reverted(y);
        rho.apply_dir(dir) ^ usize::from(same)
    }

    /// Whether the glued pair at `s` obeys the label rule (false when `s`
    /// is unmatched).
    pub fn label_ok(&self, s: Side) -> bool {
        let Some(o) = self.opposite(s) else {
            return false;
        };
        let (x, y) = (self.node_of(s), self.node_of(o));
        self.label_dir(x, y, self.dir_of(s), &self.rot[s.idx()]) == self.dir_of(o)
    }

    /// Number of unmatched sides of alive nodes (boundary edges / faces).
    pub fn unmatched_sides(&self) -> usize {
        (0..self.n_sides())
            .into_par_iter()
            .with_min_len(4096)
            .filter(|&s| self.opp[s] == NONE && self.alive[s / (2 * D)])
            .count()
    }

    /// Alive nodes, in id order.
    pub fn alive_nodes(&self) -> impl Iterator<Item = Node> + '_ {
        (0..self.n_nodes() as u32)
            .map(Node)
            .filter(|n| self.alive[n.idx()])
    }

    /// Checks that `s` exists and belongs to an alive node.
    pub(crate) fn usable(&self, s: Side) -> Result<(), OpError> {
        if s.idx() >= self.n_sides() {
            return Err(OpError::OutOfRange(s));
        }
        if !self.alive[self.node_of(s).idx()] {
            return Err(OpError::Dead(s));
        }
        Ok(())
    }

    /// Glues the unmatched sides `a` and `b` of alive nodes; `rho` maps the
    /// chart of node(a) to the chart of node(b). Does not check the label
    /// rule (input graphs may break it: see [`NodeGraph::label_violations`]).
    pub fn link(&mut self, a: Side, b: Side, rho: Rot<D>) -> Result<(), OpError> {
        self.usable(a)?;
        self.usable(b)?;
        if a == b {
            return Err(OpError::SameSide(a));
        }
        for s in [a, b] {
            if self.opp[s.idx()] != NONE {
                return Err(OpError::Matched(s));
            }
        }
        self.set_pair(a, b, rho);
        Ok(())
    }

    /// Unglues `a` from its partner and returns the former partner.
    pub fn unlink(&mut self, a: Side) -> Result<Side, OpError> {
        self.usable(a)?;
        let b = self.opposite(a).ok_or(OpError::Unmatched(a))?;
        self.clear(a);
        self.clear(b);
        Ok(b)
    }

    /// Writes the pair a ↔ b without any check.
    pub(crate) fn set_pair(&mut self, a: Side, b: Side, rho: Rot<D>) {
        self.opp[a.idx()] = b.0;
        self.opp[b.idx()] = a.0;
        self.rot[a.idx()] = rho;
        self.rot[b.idx()] = rho.inverse();
    }

    /// Marks `a` unmatched without touching its former partner.
    pub(crate) fn clear(&mut self, a: Side) {
        self.opp[a.idx()] = NONE;
        self.rot[a.idx()] = Rot::IDENTITY;
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_map::Rot2;

    #[test]
    fn link_unlink_and_preconditions() {
        let mut g = NodeGraph::<2>::new(vec![false, true, false]);
        let (a, b) = (g.side(Node(0), 0), g.side(Node(1), 0));
        let rho = Rot2::quarter_turns(1);
        assert_eq!(g.link(a, b, rho), Ok(()));
        assert_eq!(g.opposite(a), Some(b));
        assert_eq!(g.rotation(b), Some(rho.inverse()));
        assert!(g.is_pleat(a) && g.is_pleat(b));
        assert_eq!(g.unmatched_sides(), 10);
        g.check_structure().unwrap();
        // preconditions: nothing is written when they fail
        let before = g.clone();
        let c = g.side(Node(2), 1);
        assert_eq!(g.link(a, c, rho), Err(OpError::Matched(a)));
        assert_eq!(g.link(c, c, rho), Err(OpError::SameSide(c)));
        assert_eq!(g.link(c, Side(99), rho), Err(OpError::OutOfRange(Side(99))));
        assert_eq!(g, before);
        assert_eq!(g.unlink(b), Ok(a));
        assert_eq!(g.unlink(b), Err(OpError::Unmatched(b)));
        assert_eq!((g.opposite(a), g.rotation(a)), (None, None));
        assert_eq!(g.unmatched_sides(), 12);
        g.check().unwrap();
    }

    #[test]
    fn label_rule_reading() {
        // same flags: Y one step along +u from X, identity: Y's side is -u
        let mut g = NodeGraph::<2>::new(vec![false, false, true]);
        g.link(g.side(Node(0), 0), g.side(Node(1), 1), Rot::IDENTITY)
            .unwrap();
        assert!(g.label_ok(g.side(Node(0), 0)));
        // pleat X.+v ↔ Z.ρ(+v) with a quarter turn: ρ(+v) = -u
        let rho = Rot2::quarter_turns(1);
        g.link(g.side(Node(0), 2), g.side(Node(2), 1), rho).unwrap();
        assert!(g.label_ok(g.side(Node(2), 1)));
        assert_eq!(g.label_violations(), 0);
        assert!(!g.label_ok(g.side(Node(1), 0)));
    }
}
