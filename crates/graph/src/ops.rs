//! Local operations on the node graph: OP2 (reconnection), OP1 (deletion of
//! two nodes glued only to each other) and pleat removal (DESIGN §4).
//!
//! Each operation reads and checks everything first, returns
//! [`OpError`] ("not applicable") without writing anything when a
//! precondition fails, and keeps every invariant of [`crate::graph`],
//! the label rule included (OP2 requires the new pair a ↔ c to obey it;
//! then b ↔ e obeys it too whenever a ↔ b and c ↔ e did).

use crate::graph::NodeGraph;
use crate::ids::{Node, Side};
use dualex_map::Rot;
use std::fmt;

/// Why an operation is not applicable. Nothing was written.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OpError {
    /// The side does not exist.
    OutOfRange(Side),
    /// The side belongs to a dead node.
    Dead(Side),
    /// A side cannot be glued to itself.
    SameSide(Side),
    /// The side is already glued.
    Matched(Side),
    /// The side is not glued.
    Unmatched(Side),
    /// The two sides are already glued to each other.
    AlreadyGlued(Side),
    /// The pair (new or existing) breaks the label rule.
    LabelRule(Side),
    /// The glued pair at the side is not a pleat.
    NotPleat(Side),
    /// The nodes are not glued only to each other on all their sides.
    NotIsolated(Node, Node),
    /// A saddle lift at a corner of this node: the vertex is not interior,
    /// or the two fan crossings are invalid.
    BadLift(Node),
    /// No doublet at that corner (edge) of this node: the two sides are
    /// not glued to one other node of the same orientation closing a
    /// valence-2 vertex (edge chain), or the chain is inconsistent.
    NotDoublet(Node),
    /// A doublet whose outer side is glued into the doublet itself.
    DoubletPartner(Node),
    /// Merging the doublet at this node would repeat a vertex in a cell.
    RepeatedCorner(Node),
}

impl fmt::Display for OpError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            OpError::OutOfRange(s) => write!(f, "side {} does not exist", s.0),
            OpError::Dead(s) => write!(f, "side {} belongs to a dead node", s.0),
            OpError::SameSide(s) => write!(f, "side {} cannot be glued to itself", s.0),
            OpError::Matched(s) => write!(f, "side {} is already glued", s.0),
            OpError::Unmatched(s) => write!(f, "side {} is not glued", s.0),
            OpError::AlreadyGlued(s) => write!(f, "side {} is already glued there", s.0),
            OpError::LabelRule(s) => write!(f, "side {}: pair breaks the label rule", s.0),
            OpError::NotPleat(s) => write!(f, "side {} is not a pleat", s.0),
            OpError::NotIsolated(x, y) => {
                write!(
                    f,
                    "nodes {} and {} are not glued only to each other",
                    x.0, y.0
                )
            }
            OpError::BadLift(x) => write!(f, "node {}: no saddle lift at that corner", x.0),
            OpError::NotDoublet(x) => write!(f, "node {}: no doublet there", x.0),
            OpError::DoubletPartner(x) => {
                write!(f, "node {}: the doublet's outer side is glued into it", x.0)
            }
            OpError::RepeatedCorner(x) => {
                write!(f, "node {}: the merged cell would repeat a vertex", x.0)
            }
        }
    }
}

impl std::error::Error for OpError {}

/// What one OP2 did.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Op2Outcome {
    /// The former partners, now glued to each other (both were glued).
    pub new_pair: Option<(Side, Side)>,
    /// How many of the former partners were unmatched (0, 1 or 2).
    pub unmatched_partners: u8,
}

/// What one pleat removal did, case by case.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PleatRemoval {
    /// New pairs b ↔ e of alive nodes (one side each): maybe new pleats.
    pub new_pairs: Vec<Side>,
    /// OP2 performed.
    pub op2: usize,
    /// Sides besides the pleat's own on which X and Y already faced.
    pub bigon_sides: usize,
    /// OP2 with exactly one unmatched former partner.
    pub one_boundary: usize,
    /// OP2 with both former partners unmatched.
    pub both_boundary: usize,
    /// OP2 whose former partner was a side of X or Y.
    pub partner_in_pleat: usize,
    /// New pairs joining two sides of one node.
    pub self_loops: usize,
}

/// What removing a pleat would do, read without writing
/// ([`NodeGraph::pleat_preview`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct PleatPreview {
    /// OP2 (saddle lifts) the removal needs: the sides on which the two
    /// nodes do not face each other yet (0 = a pure OP1).
    pub op2: usize,
    /// New pairs that would join two sides of one node, among those whose
    /// former partners lie outside the pleat (the others are not
    /// predicted: earlier OP2 of the same removal change them).
    pub self_loops: usize,
}

impl<const D: usize> NodeGraph<D> {
    /// What [`NodeGraph::remove_pleat`] at `s` would do, without writing;
    /// `None` when it is not applicable (dead or unmatched side, not a
    /// pleat, label rule broken).
    pub fn pleat_preview(&self, s: Side) -> Option<PleatPreview> {
        self.usable(s).ok()?;
        let t = self.opposite(s)?;
        if !self.is_pleat(s) || !self.label_ok(s) {
            return None;
        }
        let (x, y, rho) = (self.node_of(s), self.node_of(t), self.rot[s.idx()]);
        let mut out = PleatPreview {
            op2: 0,
            self_loops: 0,
        };
        for d in 0..2 * D {
            let (a, c) = (self.side(x, d), self.side(y, rho.apply_dir(d)));
            let (b, e) = (self.opposite(a), self.opposite(c));
            if b == Some(c) {
                continue;
            }
            out.op2 += 1;
            if let (Some(b), Some(e)) = (b, e) {
                let (nb, ne) = (self.node_of(b), self.node_of(e));
                if nb == ne && nb != x && nb != y {
                    out.self_loops += 1;
                }
            }
        }
        Some(out)
    }

    /// OP2, reconnection (a saddle lift): glued pairs a ↔ b and c ↔ e
    /// become a ↔ c (rotation `rho_ac`, chart of node(a) to node(c)) and
    /// b ↔ e with rot(b→e) = rot(b→a) then ρ_ac then rot(c→e). If only one
    /// of b, e exists it becomes unmatched.
    ///
    /// ```text
    ///   before:   b ──── a  X        after:   b ──┐   a  X
    ///                                             │   │
    ///             e ──── c  Y                 e ──┘   c  Y
    /// ```
    /// Preconditions: a, c alive, distinct and not glued to each other;
    /// a ↔ c with `rho_ac` obeys the label rule.
    pub fn op2(&mut self, a: Side, c: Side, rho_ac: Rot<D>) -> Result<Op2Outcome, OpError> {
        self.usable(a)?;
        self.usable(c)?;
        if a == c {
            return Err(OpError::SameSide(a));
        }
        let (b, e) = (self.opposite(a), self.opposite(c));
        if b == Some(c) {
            return Err(OpError::AlreadyGlued(a));
        }
        let (x, y) = (self.node_of(a), self.node_of(c));
        if self.label_dir(x, y, self.dir_of(a), &rho_ac) != self.dir_of(c) {
            return Err(OpError::LabelRule(a));
        }
        let rot_ba = b.map(|b| self.rot[b.idx()]);
        let rot_ce = self.rot[c.idx()];
        // all read: write
        for s in [b, e].into_iter().flatten() {
            self.clear(s);
        }
        self.set_pair(a, c, rho_ac);
        let new_pair = match (b, e, rot_ba) {
            (Some(b), Some(e), Some(r)) => {
                self.set_pair(b, e, r.then(&rho_ac).then(&rot_ce));
                Some((b, e))
            }
            _ => None,
        };
        let touched: Vec<Side> = [Some(a), b, Some(c), e].into_iter().flatten().collect();
        debug_assert!(
            self.check_sides(&touched).is_ok(),
            "bug: OP2 broke the graph"
        );
        let unmatched_partners = u8::from(b.is_none()) + u8::from(e.is_none());
        Ok(Op2Outcome {
            new_pair,
            unmatched_partners,
        })
    }

    /// OP1: deletes two distinct nodes glued only to each other on all
    /// their 2·D sides (a closed "pillow"); both become dead, all their
    /// sides unmatched.
    pub fn op1(&mut self, x: Node, y: Node) -> Result<(), OpError> {
        self.usable(self.side(x, 0))?;
        self.usable(self.side(y, 0))?;
        if x == y {
            return Err(OpError::NotIsolated(x, y));
        }
        for d in 0..2 * D {
            let glued_to_y = self
                .opposite(self.side(x, d))
                .is_some_and(|o| self.node_of(o) == y);
            if !glued_to_y {
                return Err(OpError::NotIsolated(x, y));
            }
        }
        // x's 2D sides are glued to 2D distinct sides of y: all of them.
        for d in 0..2 * D {
            self.clear(self.side(x, d));
            self.clear(self.side(y, d));
        }
        self.alive[x.idx()] = false;
        self.alive[y.idx()] = false;
        Ok(())
    }

    /// Removes the pleat at side `s` (DESIGN §4): X = node(s), Y = the node
    /// glued to it, ρ = `rot[s]`. For every direction d of X, a = X.d and
    /// c = Y.ρ(d) (the side of Y with the same signed axis in the common
    /// chart) are glued by OP2 unless they already are; then X and Y face
    /// each other on all sides and OP1 deletes them.
    ///
    /// ```text
    ///   before:  b ── X ═╗          after:  b ────── e
    ///                    ║ pleat
    ///            e ── Y ═╝                  (X, Y deleted)
    /// ```
    /// Preconditions: `s` is glued, the pair is a pleat and obeys the label
    /// rule.
    pub fn remove_pleat(&mut self, s: Side) -> Result<PleatRemoval, OpError> {
        self.usable(s)?;
        let t = self.opposite(s).ok_or(OpError::Unmatched(s))?;
        if !self.is_pleat(s) {
            return Err(OpError::NotPleat(s));
        }
        if !self.label_ok(s) {
            return Err(OpError::LabelRule(s));
        }
        let (x, y, rho) = (self.node_of(s), self.node_of(t), self.rot[s.idx()]);
        let mut out = PleatRemoval::default();
        for d in 0..2 * D {
            let (a, c) = (self.side(x, d), self.side(y, rho.apply_dir(d)));
            if self.opposite(a) == Some(c) {
                out.bigon_sides += usize::from(a != s);
                continue;
            }
            let partners = [self.opposite(a), self.opposite(c)];
            if partners
                .iter()
                .flatten()
                .any(|p| [x, y].contains(&self.node_of(*p)))
            {
                out.partner_in_pleat += 1;
            }
            let done = match self.op2(a, c, rho) {
                Ok(done) => done,
                Err(e) => panic!("bug: OP2 inside a pleat removal failed: {e}"),
            };
            out.op2 += 1;
            match done.unmatched_partners {
                1 => out.one_boundary += 1,
                2 => out.both_boundary += 1,
                _ => {}
            }
            if let Some((b, _)) = done.new_pair {
                out.new_pairs.push(b);
            }
        }
        if let Err(e) = self.op1(x, y) {
            panic!("bug: X and Y not isolated after the OP2s of a pleat removal: {e}");
        }
        out.new_pairs.retain(|&b| self.opposite(b).is_some());
        out.new_pairs.sort_unstable();
        out.new_pairs.dedup();
        out.self_loops = out
            .new_pairs
            .iter()
            .filter(|&&b| self.opposite(b).map(|e| self.node_of(e)) == Some(self.node_of(b)))
            .count();
        Ok(out)
    }
}
