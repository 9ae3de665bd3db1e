//! A numbering-free order of a 2D graph seen from one corner: what index
//! fairing breaks its ties by, so that the same graph numbered otherwise
//! (the nodes of a map's triangles against those of its extrusion's tets)
//! is faired alike.
//!
//! Input: a [`NodeGraph<2>`] obeying [`NodeGraph::check`] and a *start*, an
//! alive corner `(node, code)`. Output, lazily (a node is ranked on first
//! use, at the cost of the region explored so far):
//! - a **rank** per node of the start's component: the order in which a
//!   breadth-first search from the start node meets it, each node's sides
//!   visited in the order `+u, −u, +v, −v` *of the start's frame*;
//! - a **frame** per ranked node: the rotation from the start's frame to
//!   its chart, carried along the search (the start's frame is the turn of
//!   its chart that puts the start corner at code 0, `−u, −v`);
//! - a **corner rank** `rank·4 + code`, the code read in the frame.
//!
//! ```text
//!   ●────┐   start corner ● of X: code 2 in X's chart (−u, +v); the
//!   │ X  │   frame turns X's chart a quarter so that ● reads −u, −v;
//!   └────┘   X's sides are visited in that frame's order, then its
//!            neighbours' sides, … (ranks 0, 1, 2, … as met)
//! ```
//!
//! Invariants: ranks and corner ranks do not depend on node numbers nor on
//! the nodes' charts (a chart turned by ρ gets its frame turned by ρ), only
//! on the graph's sides, rotations and reverted flags seen from the start.
//! [`compare`] orders two starts by the *code* of their searches (per
//! node: each side's partner as rank, side in its frame and rotation
//! between frames, and the partner's reverted flag); two starts compare
//! equal only when an isomorphism of their component maps one onto the
//! other, so either is as good as the other.

use crate::fan::{corner_code, corner_sides};
use crate::graph::NodeGraph;
use crate::ids::Node;
use dualex_map::Rot2;
use std::cmp::Ordering;
use std::collections::HashMap;

/// One side in a search's code: its partner's rank, the partner's side in
/// the partner's frame, the rotation between the two frames (quarter
/// turns; 0 unless the search reached the partner with another frame) and
/// the partner's reverted flag; `None` when the side is unmatched.
type Token = Option<(u32, u8, u8, bool)>;

/// The lazy search from one start corner (module docs).
pub(crate) struct Canon<'a> {
    g: &'a NodeGraph<2>,
    /// Nodes by rank.
    order: Vec<(Node, Rot2)>,
    /// Rank of each node met.
    rank: HashMap<Node, u32>,
    /// Nodes of `order` whose sides were visited.
    expanded: usize,
}

/// The frame of a start corner: the rotation `f` (from the frame to the
/// chart) under which `code` reads as 0.
fn start_frame(code: usize) -> Rot2 {
    let all = Rot2::all();
    let read_as = |f: &Rot2| frame_code(f, code);
    all.iter()
        .copied()
        .find(|f| read_as(f) == 0)
        .unwrap_or(Rot2::IDENTITY)
}

/// Corner `code` of a node's chart read in the frame `f` (frame → chart).
fn frame_code(f: &Rot2, code: usize) -> usize {
    let (du, dv) = corner_sides(code % 4);
    let back = f.inverse();
    corner_code(back.apply_dir(du), back.apply_dir(dv))
}

impl<'a> Canon<'a> {
    /// The search from corner `code` of `start` (nothing ranked when
    /// `start` is dead or `code ≥ 4`).
    pub(crate) fn new(g: &'a NodeGraph<2>, (start, code): (Node, usize)) -> Self {
        let mut c = Canon {
            g,
            order: Vec::new(),
            rank: HashMap::new(),
            expanded: 0,
        };
        if g.is_alive(start) && code < 4 {
            c.order.push((start, start_frame(code)));
            c.rank.insert(start, 0);
        }
        c
    }

    /// Visits the sides of the next node in rank order, ranking the new
    /// partners and pushing the node's code onto `out`; `false` when every
    /// node of the component was visited.
    fn expand(&mut self, out: &mut Vec<Token>) -> bool {
        let g = self.g;
        let Some(&(x, fx)) = self.order.get(self.expanded) else {
            return false;
        };
        if self.expanded == 0 {
            out.push(Some((0, 0, 0, g.is_reverted(x))));
        }
        self.expanded += 1;
        for k in 0..4 {
            let s = g.side(x, fx.apply_dir(k));
            let (Some(t), Some(r)) = (g.opposite(s), g.rotation(s)) else {
                out.push(None);
                continue;
            };
            let y = g.node_of(t);
            let carried = fx.then(&r);
            let rank = *self.rank.entry(y).or_insert_with(|| {
                self.order.push((y, carried));
                (self.order.len() - 1) as u32
            });
            let fy = self.order[rank as usize].1;
            let turn = carried.then(&fy.inverse()).turns() as u8;
            let dir = fy.inverse().apply_dir(g.dir_of(t)) as u8;
            out.push(Some((rank, dir, turn, g.is_reverted(y))));
        }
        true
    }

    /// Rank and frame of `x`, searching as far as needed; `None` when `x`
    /// is not in the start's component.
    fn ranked(&mut self, x: Node) -> Option<(u32, Rot2)> {
        let mut sink = Vec::new();
        loop {
            if let Some(&r) = self.rank.get(&x) {
                return Some((r, self.order[r as usize].1));
            }
            sink.clear();
            if !self.expand(&mut sink) {
                return None;
            }
        }
    }

    /// The corner rank of corner `code` of `x` (module docs); `None` when
    /// `x` is not in the start's component.
    pub(crate) fn corner_rank(&mut self, x: Node, code: usize) -> Option<u64> {
        let (r, f) = self.ranked(x)?;
        Some(4 * u64::from(r) + frame_code(&f, code) as u64)
    }
}

/// Orders two start corners by the codes of their searches, node by node
/// (module docs); `Equal` only for starts an isomorphism maps onto each
/// other. The cost is the region searched until the codes differ.
pub(crate) fn compare(g: &NodeGraph<2>, a: (Node, usize), b: (Node, usize)) -> Ordering {
    let (mut ca, mut cb) = (Canon::new(g, a), Canon::new(g, b));
    let (mut ta, mut tb) = (Vec::new(), Vec::new());
    loop {
        ta.clear();
        tb.clear();
        let more = (ca.expand(&mut ta), cb.expand(&mut tb));
        // a search that ends first (a smaller component) is less
        let o = more.0.cmp(&more.1).then_with(|| ta.cmp(&tb));
        if o != Ordering::Equal || more == (false, false) {
            return o;
        }
    }
}

/// The least of `starts` by [`compare`] (the first of equal ones).
pub(crate) fn least(g: &NodeGraph<2>, starts: &[(Node, usize)]) -> Option<(Node, usize)> {
    let mut best = *starts.first()?;
    for &s in &starts[1..] {
        if compare(g, s, best) == Ordering::Less {
            best = s;
        }
    }
    Some(best)
}

/// The code of the whole component of the least of all alive corners: two
/// connected graphs are isomorphic (up to node numbers and charts) exactly
/// when their codes are equal. For tests: the cost is quadratic at worst.
#[cfg(test)]
pub(crate) fn graph_code(g: &NodeGraph<2>) -> Vec<Token> {
    let corners: Vec<(Node, usize)> = g
        .alive_nodes()
        .flat_map(|x| (0..4).map(move |c| (x, c)))
        .collect();
    let mut out = Vec::new();
    if let Some(start) = least(g, &corners) {
        let mut c = Canon::new(g, start);
        while c.expand(&mut out) {}
    }
    out
}

#[cfg(test)]
mod tests;
