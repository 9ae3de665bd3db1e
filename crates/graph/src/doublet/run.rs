//! The doublet pass: every doublet of the graph merged
//! ([`NodeGraph::merge_doublet`]), in passes until none is left, and what
//! the merged nodes took over ([`Takeover`]).
//!
//! Input: a graph (after fairing and the collapse of folded corners).
//! Output: the graph without the doublets whose preconditions hold,
//! [`DoubletStats`], and the takeovers recorded. Candidates are the
//! corners (2D) / edges (3D) of a node X whose two sides are glued to one
//! node Y > X (so the survivor is the smaller node); nodes are visited in
//! id order, a node again after each merge of its own. Invariants: every
//! pass but the last merges at least one doublet (so it terminates: each
//! merge deletes a node); the graph stays valid ([`NodeGraph::check`]).

use super::DoubletMerge;
use crate::graph::NodeGraph;
use crate::ids::{Node, Side};
use std::collections::{HashMap, HashSet};

/// What [`NodeGraph::dissolve_doublets`] did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct DoubletStats {
    /// Doublets merged: valence-2 vertices (2D), chains (3D).
    pub merged: usize,
    /// Node pairs merged (2D: one per doublet; 3D: valence-2 edges).
    pub pairs: usize,
    /// Passes after the first that merged doublets (made by earlier ones).
    pub rounds: usize,
    /// Candidates left at the end (a precondition failed), one per corner
    /// (2D) or edge (3D).
    pub refused: usize,
}

/// What merged nodes took over from the nodes they replaced, composed over
/// all merges: which corners' geometry each corner of a merged node now
/// is (vertex placement traces from those: the far corner of the deleted
/// node, or the corner itself and the deleted node's corner at the same
/// vertex), and which sides took over which (per-side data such as how a
/// side's walk ended moves along).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct Takeover<const D: usize> {
    /// Corner (`node·2^D + code`) → the corners whose geometry it is.
    corners: HashMap<u32, Vec<u32>>,
    /// Nodes that took over another one's corners.
    merged: HashSet<Node>,
    /// (side taken over, side that took it), in merge order.
    sides: Vec<(Side, Side)>,
}

impl<const D: usize> Takeover<D> {
    /// Records one merge, composing with the earlier ones.
    pub fn record(&mut self, m: &DoubletMerge) {
        let of = |t: &Self, c: u32| t.corners.get(&c).cloned().unwrap_or_else(|| vec![c]);
        for &(from, to) in &m.corners {
            let origins = of(self, from);
            self.corners.insert(to, origins);
        }
        for &(from, to) in &m.shared {
            let mut origins = of(self, to);
            origins.extend(of(self, from));
            self.corners.insert(to, origins);
        }
        self.merged.extend(m.pairs.iter().map(|&(x, _)| x));
        self.sides.extend_from_slice(&m.sides);
    }

    /// The corners (node, code) whose geometry corner `code` of `n` is,
    /// the preferred first: itself unless merges made it another node's
    /// corner, or gave it the corners of deleted nodes at its vertex.
    pub fn origins(&self, n: Node, code: usize) -> Vec<(Node, usize)> {
        let k = 1usize << D;
        let id = (n.idx() * k + code) as u32;
        match self.corners.get(&id) {
            Some(list) => list
                .iter()
                .map(|&o| (Node(o / k as u32), o as usize % k))
                .collect(),
            None => vec![(n, code)],
        }
    }

    /// The number of [`Self::origins`] of a corner.
    pub(crate) fn n_origins(&self, n: Node, code: usize) -> usize {
        if self.corners.is_empty() {
            return 1;
        }
        let id = (n.idx() * (1 << D) + code) as u32;
        self.corners.get(&id).map_or(1, Vec::len)
    }

    /// Calls `f` on each of [`Self::origins`], without allocating.
    pub(crate) fn for_each_origin(&self, n: Node, code: usize, mut f: impl FnMut(Node, usize)) {
        let k = 1usize << D;
        let id = (n.idx() * k + code) as u32;
        let found = if self.corners.is_empty() {
            None
        } else {
            self.corners.get(&id)
        };
        match found {
            Some(list) => {
                for &o in list {
                    f(Node(o / k as u32), o as usize % k);
                }
            }
            None => f(n, code),
        }
    }

    /// Whether `n` took over corners of another node (its cell is no longer
    /// its node's dual cell).
    pub fn is_merged(&self, n: Node) -> bool {
        self.merged.contains(&n)
    }

    /// Nothing was taken over.
    pub fn is_empty(&self) -> bool {
        self.sides.is_empty()
    }

    /// Moves per-side data (indexed by side id) along the takeovers: a side
    /// that took another one over gets its value.
    pub fn carry_sides<T: Copy>(&self, per_side: &mut [T]) {
        for &(from, to) in &self.sides {
            if let Some(&v) = per_side.get(from.idx()) {
                if let Some(slot) = per_side.get_mut(to.idx()) {
                    *slot = v;
                }
            }
        }
    }
}

impl<const D: usize> NodeGraph<D> {
    /// The candidate doublets at `x`: perpendicular sides (d0, d1), with
    /// d0's axis below d1's, glued to one node y > x.
    fn doublet_candidates(&self, x: Node) -> Vec<[usize; 2]> {
        let mut out = Vec::new();
        for d0 in 0..2 * D {
            for d1 in (d0 / 2 + 1) * 2..2 * D {
                let (s0, s1) = (self.side(x, d0), self.side(x, d1));
                let (Some(t0), Some(t1)) = (self.opposite(s0), self.opposite(s1)) else {
                    continue;
                };
                let y = self.node_of(t0);
                if self.node_of(t1) == y && y > x {
                    out.push([d0, d1]);
                }
            }
        }
        out
    }

    /// Merges every doublet whose preconditions hold (module docs),
    /// recording the takeovers in `takeover`.
    pub fn dissolve_doublets(&mut self, takeover: &mut Takeover<D>) -> DoubletStats {
        let mut st = DoubletStats::default();
        for pass in 0..=self.n_nodes() {
            let (mut merged, mut refused) = (0, 0);
            for x in (0..self.n_nodes() as u32).map(Node) {
                // again after each merge: x's cell changed
                while self.is_alive(x) {
                    let mut done = false;
                    for d in self.doublet_candidates(x) {
                        match self.merge_doublet(x, d[0], d[1]) {
                            Ok(m) => {
                                st.pairs += m.pairs.len();
                                takeover.record(&m);
                                merged += 1;
                                done = true;
                                break;
                            }
                            Err(_) => refused += 1,
                        }
                    }
                    if !done {
                        break;
                    }
                }
            }
            st.merged += merged;
            if merged == 0 {
                st.refused = refused;
                break;
            }
            st.rounds += usize::from(pass > 0);
        }
        st
    }
}
