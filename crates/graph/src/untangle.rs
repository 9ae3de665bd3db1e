//! Untangling: removes every pleat with a worklist (DESIGN §4).
//!
//! Input: a graph whose pairs obey the label rule (pairs breaking it are
//! left alone and counted). Output: the same graph with pleats removed
//! (pairs of nodes deleted, partners reconnected) and [`UntangleStats`].
//!
//! Termination: a pop either fails (nothing written, nothing pushed) or
//! removes a pleat, which deletes two nodes and pushes at most 2·D sides.
//! So at most N/2 removals happen and at most P + N·D sides are ever
//! pushed (P = initial pleat pairs), which bounds the iterations.

use crate::graph::NodeGraph;
use crate::ids::Side;
use crate::rng::SplitMix;
use serde_json::{json, Value};

/// What untangling did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct UntangleStats {
    /// Pleat pairs in the graph before untangling.
    pub pleats_found: usize,
    /// Pleats removed (each one OP1, deleting two nodes).
    pub pleats_removed: usize,
    /// OP2 (reconnections) performed.
    pub op2: usize,
    /// Sides on which the two nodes of a pleat already faced (bigons).
    pub bigon_sides: usize,
    /// OP2 with one unmatched former partner (boundary).
    pub one_boundary: usize,
    /// OP2 with both former partners unmatched (boundary).
    pub both_boundary: usize,
    /// OP2 whose former partner was a side of the pleat itself.
    pub partner_in_pleat: usize,
    /// New pairs joining two sides of one node.
    pub self_loops: usize,
    /// New pairs that were pleats.
    pub new_pleats: usize,
    /// Pleats that could not be removed (they break the label rule).
    pub not_applicable: usize,
    /// Pleat pairs left at the end.
    pub pleats_left: usize,
    /// Alive reverted nodes left at the end.
    pub reverted_left: usize,
    /// Worklist pops.
    pub iterations: usize,
}

impl UntangleStats {
    /// The stats as a JSON object.
    pub fn to_json(&self) -> Value {
        json!({
            "pleats_found": self.pleats_found,
            "pleats_removed": self.pleats_removed,
            "op1": self.pleats_removed,
            "op2": self.op2,
            "bigon_sides": self.bigon_sides,
            "one_boundary": self.one_boundary,
            "both_boundary": self.both_boundary,
            "partner_in_pleat": self.partner_in_pleat,
            "self_loops": self.self_loops,
            "new_pleats": self.new_pleats,
            "not_applicable": self.not_applicable,
            "pleats_left": self.pleats_left,
            "reverted_left": self.reverted_left,
            "iterations": self.iterations,
        })
    }
}

impl<const D: usize> NodeGraph<D> {
    /// One side of every pleat pair, in side order.
    pub fn pleat_sides(&self) -> Vec<Side> {
        (0..self.n_sides() as u32)
            .map(Side)
            .filter(|&s| self.is_pleat(s) && self.opposite(s).is_some_and(|o| s < o))
            .collect()
    }

    /// Removes all pleats, popping the worklist from its end.
    pub fn untangle(&mut self) -> UntangleStats {
        self.untangle_with(None)
    }

    /// Like [`NodeGraph::untangle`], but the initial worklist is shuffled
    /// and each new pair swaps places with a random entry (seeded).
    pub fn untangle_shuffled(&mut self, seed: u64) -> UntangleStats {
        self.untangle_with(Some(SplitMix::new(seed)))
    }

    fn untangle_with(&mut self, mut rng: Option<SplitMix>) -> UntangleStats {
        let mut work = self.pleat_sides();
        let mut st = UntangleStats {
            pleats_found: work.len(),
            ..Default::default()
        };
        if let Some(r) = rng.as_mut() {
            r.shuffle(&mut work);
        }
        let bound = work.len() + self.n_nodes() * D;
        while let Some(s) = work.pop() {
            st.iterations += 1;
            assert!(st.iterations <= bound, "bug: untangling exceeded its bound");
            if !self.is_alive(self.node_of(s)) || !self.is_pleat(s) {
                continue;
            }
            let Ok(done) = self.remove_pleat(s) else {
                st.not_applicable += 1;
                continue;
            };
            st.pleats_removed += 1;
            st.op2 += done.op2;
            st.bigon_sides += done.bigon_sides;
            st.one_boundary += done.one_boundary;
            st.both_boundary += done.both_boundary;
            st.partner_in_pleat += done.partner_in_pleat;
            st.self_loops += done.self_loops;
            for b in done.new_pairs {
                if self.is_pleat(b) {
                    st.new_pleats += 1;
                    work.push(b);
                    if let Some(r) = rng.as_mut() {
                        let at = r.below(work.len());
                        let last = work.len() - 1;
                        work.swap(at, last);
                    }
                }
            }
        }
        st.pleats_left = self.pleat_sides().len();
        st.reverted_left = self.n_reverted_alive();
        st
    }
}
