//! Untangling: removes every pleat with a worklist (DESIGN §4).
//!
//! Input: a graph whose pairs obey the label rule (pairs breaking it are
//! left alone and counted). Output: the same graph with pleats removed
//! (pairs of nodes deleted, partners reconnected) and [`UntangleStats`].
//!
//! Order (issue 22): the paper applies OP1 "as soon as possible" and OP2
//! only to isolate a pleat. So the pleat popped next is one whose removal
//! needs the fewest OP2 (saddle lifts) now ([`NodeGraph::pleat_preview`]):
//! pure OP1 first, then pleats facing on all sides but one, and so on;
//! and, in a first pass, not one whose removal would glue a node to itself
//! (those are deferred until nothing else is left). A fold pulled through a
//! singular node, removed in side order, paired reverted nodes across the
//! node: the singularity split in two (2D: a valence 7 came back as a 3
//! and an 8) or hexes came out degenerate (3D).
//!
//! ```text
//!   buckets[c]   sides of pleats that needed c OP2 when pushed (c < 2·D)
//!   pop          the lowest non-empty bucket, from its end; the cost is
//!                read again: higher now → pushed into its bucket (it only
//!                ever moves up), else removed (or deferred, first pass)
//!   push         after a removal, each new pleat pair and every pleat side
//!                of the nodes it joins (their cost may have dropped)
//! ```
//!
//! Other orders ([`NodeGraph::untangle_best`]): the order above still
//! splits a singularity now and then (2D: 9 of 67 500 refined prism maps
//! folded at their poles, a valence 5 back as a 6 and a stray 3, with a
//! valence-1 vertex fairing finds no partner for). When the step after
//! untangling (fairing) leaves such degenerate vertices, the untangling is
//! tried again from the graph as it was, ties broken at random (seeded),
//! and the first order with the fewest is kept. A map without pleats pays
//! nothing; one whose fairing leaves none pays nothing but a copy.
//!
//! Termination: a removal deletes two nodes (at most N/2 happen) and
//! pushes at most 2·D·(1 + 4·D) sides; an entry moves up at most 2·D − 1
//! buckets and is deferred at most once. So the pops are bounded by
//! (2·D + 1)·(P + N·D·(1 + 4·D)) (P = initial pleat pairs).

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
    /// Pops put off to the second pass: the removal would have glued a
    /// node to itself.
    pub deferred: usize,
    /// Pleat pairs left at the end.
    pub pleats_left: usize,
    /// Alive reverted nodes left at the end.
    pub reverted_left: usize,
    /// Worklist pops.
    pub iterations: usize,
    /// Other (shuffled) orders tried by [`NodeGraph::untangle_best`].
    pub orders_tried: usize,
    /// The shuffled order kept (its seed), if not the first.
    pub order_kept: Option<u64>,
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
            "deferred": self.deferred,
            "pleats_left": self.pleats_left,
            "reverted_left": self.reverted_left,
            "iterations": self.iterations,
            "orders_tried": self.orders_tried,
            "order_kept": self.order_kept,
        })
    }
}

/// The worklist: one bucket of sides per OP2 count.
struct Work<const D: usize> {
    buckets: Vec<Vec<Side>>,
    rng: Option<SplitMix>,
}

impl<const D: usize> Work<D> {
    /// Pushes `s` into bucket `cost` (at a random place when shuffled).
    fn push(&mut self, s: Side, cost: usize) {
        let Some(b) = self.buckets.get_mut(cost) else {
            return;
        };
        b.push(s);
        if let Some(r) = self.rng.as_mut() {
            let (at, last) = (r.below(b.len()), b.len() - 1);
            b.swap(at, last);
        }
    }

    /// Pops from the lowest non-empty bucket: (side, bucket).
    fn pop(&mut self) -> Option<(Side, usize)> {
        let c = self.buckets.iter().position(|b| !b.is_empty())?;
        self.buckets[c].pop().map(|s| (s, c))
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

    /// Removes all pleats, fewest OP2 first (see the module docs).
    pub fn untangle(&mut self) -> UntangleStats {
        let first = self.pleat_sides();
        self.untangle_with(None, first)
    }

    /// Like [`NodeGraph::untangle`], but ties (pleats needing as many OP2)
    /// are broken at random (seeded): the initial worklist is shuffled and
    /// each push swaps places with a random entry of its bucket.
    pub fn untangle_shuffled(&mut self, seed: u64) -> UntangleStats {
        let first = self.pleat_sides();
        self.untangle_with(Some(SplitMix::new(seed)), first)
    }

    /// Untangles, then runs `next` (the following step, e.g. fairing),
    /// which returns its result and how many degenerate vertices it left.
    /// While some are left, the graph as it was before untangling is
    /// untangled again in shuffled orders (seeds 1..=`orders`), each
    /// followed by `next`; the first order with the fewest left is kept
    /// (its seed in [`UntangleStats::order_kept`]). Deterministic: the
    /// seeds are fixed.
    pub fn untangle_best<T>(
        &mut self,
        orders: u64,
        mut next: impl FnMut(&mut Self) -> (T, usize),
    ) -> (UntangleStats, T) {
        // no pleat: nothing to untangle, no order to choose (no copy)
        let first = self.pleat_sides();
        let before = (!first.is_empty()).then(|| self.clone());
        let mut st = self.untangle_with(None, first);
        let (mut out, mut left) = next(self);
        let Some(before) = before else {
            return (st, out);
        };
        let mut tried = 0;
        let mut kept = None;
        for seed in 1..=orders {
            if left == 0 {
                break;
            }
            tried += 1;
            let mut g = before.clone();
            let s = g.untangle_shuffled(seed);
            let (o, l) = next(&mut g);
            if l < left {
                (*self, st, out, left, kept) = (g, s, o, l, Some(seed));
            }
        }
        st.orders_tried = tried;
        st.order_kept = kept;
        (st, out)
    }

    /// Pushes `s` by its current OP2 count, if it is a removable pleat.
    fn push_pleat(&self, work: &mut Work<D>, s: Side) {
        if let Some(p) = self.pleat_preview(s) {
            work.push(s, p.op2);
        }
    }

    /// Untangles from the pleat sides `first` ([`Self::pleat_sides`]).
    fn untangle_with(&mut self, mut rng: Option<SplitMix>, mut first: Vec<Side>) -> UntangleStats {
        let mut st = UntangleStats {
            pleats_found: first.len(),
            ..Default::default()
        };
        if let Some(r) = rng.as_mut() {
            r.shuffle(&mut first);
        }
        let mut work = Work::<D> {
            buckets: vec![Vec::new(); 2 * D],
            rng,
        };
        for &s in first.iter().rev() {
            match self.pleat_preview(s) {
                Some(p) => work.push(s, p.op2),
                None => st.not_applicable += 1,
            }
        }
        let mut deferred = Vec::new();
        let mut first_pass = true;
        let bound = (2 * D + 1) * (first.len() + self.n_nodes() * D * (1 + 4 * D));
        loop {
            let Some((s, bucket)) = work.pop() else {
                if deferred.is_empty() || !first_pass {
                    break;
                }
                first_pass = false;
                for s in std::mem::take(&mut deferred).into_iter().rev() {
                    self.push_pleat(&mut work, s);
                }
                continue;
            };
            st.iterations += 1;
            assert!(st.iterations <= bound, "bug: untangling exceeded its bound");
            let Some(p) = self.pleat_preview(s) else {
                continue;
            };
            if p.op2 > bucket {
                work.push(s, p.op2);
                continue;
            }
            if first_pass && p.self_loops > 0 {
                st.deferred += 1;
                deferred.push(s);
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
            for &b in &done.new_pairs {
                st.new_pleats += usize::from(self.is_pleat(b));
                self.push_pleat(&mut work, b);
                let Some(e) = self.opposite(b) else {
                    continue;
                };
                for n in [self.node_of(b), self.node_of(e)] {
                    for d in 0..2 * D {
                        self.push_pleat(&mut work, self.side(n, d));
                    }
                }
            }
        }
        // no pleat to start from: nothing was popped, the graph is as it was
        if !first.is_empty() {
            st.pleats_left = self.pleat_sides().len();
        }
        st.reverted_left = self.n_reverted_alive();
        st
    }
}
