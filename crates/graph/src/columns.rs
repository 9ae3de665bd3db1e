//! Index fairing on columns — the 2D fairing ([`crate::fair`]) applied to
//! every layer of a 3D graph made of columns (an extruded map's).
//!
//! A 3D graph is made of *columns* when every alive node's `+w` side is
//! unmatched (the top) or glued to the `−w` side of the node above it with
//! the same orientation and a rotation that fixes `w` (a node's chart may
//! be turned in `u, v` against the one below it: its frame, the rotations
//! composed up the stack, carries it back to the bottom node's chart), and
//! the stacks found from the bottom nodes (`−w` unmatched) all have the
//! same height L and hold every alive node. Then the `u, v` sides of the
//! nodes of layer k, read in their bottom nodes' charts, form a 2D graph
//! (rotations fixing `w` restricted to `u, v`), and when
//! the L layers are the same 2D graph, the 2D saddle lifts and the
//! collapse of folded corners are run on it once and written back in
//! every layer: a lift re-glues the same sides in every layer (a lift of a
//! whole column), a collapsed folded corner removes its whole column.
//!
//! ```text
//!   layer 1   x1 ─ y1        2D graph (layer 0):   x ─ y
//!             │+w   │+w                            │
//!   layer 0   x0 ─ y0        fair, collapse  →     x'─ y'   then each
//!                                                  layer re-glued alike
//! ```
//!
//! Input: an untangled 3D graph. Output: `None` when it is not made of
//! columns or its layers differ (nothing written); else the graph faired
//! and the stats. Invariants: the `w` links are not touched, every layer
//! gets the same `u, v` links; the result passes [`NodeGraph::check`]
//! (else the graph is left as it was).

use crate::fair::FairingStats;
use crate::graph::NodeGraph;
use crate::ids::Node;
use dualex_map::{Rot2, Rot3};

/// `+w` and `−w` (dir = 2·axis + negative).
const UP: usize = 4;
const DOWN: usize = 5;

/// What [`NodeGraph::fair_columns`] did.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct ColumnFairing {
    /// The 2D fairing of one layer (the same in every layer).
    pub fairing: FairingStats,
    /// Folded corners collapsed (columns removed).
    pub collapsed: usize,
    /// Layers (nodes per column).
    pub layers: usize,
    /// Columns.
    pub columns: usize,
}

/// The `u, v` links of one layer: per column and `u, v` side, the column,
/// side and 2D rotation it is glued to.
type Links = Vec<Option<(u32, usize, Rot2)>>;

fn to_2d(r: Rot3) -> Option<Rot2> {
    let [a, b, c] = r.images();
    (c == UP as u8).then(|| Rot2::from_images([a, b]))?
}

fn to_3d(r: Rot2) -> Option<Rot3> {
    let [a, b] = r.images();
    Rot3::from_images([a, b, UP as u8])
}

impl NodeGraph<3> {
    /// The stacks of alive nodes along `w`, lowest first, or `None` when
    /// the graph is not made of columns (module docs).
    pub fn columns(&self) -> Option<Vec<Vec<Node>>> {
        let stacks = self.framed_columns()?;
        Some(
            stacks
                .iter()
                .map(|s| s.iter().map(|&(x, _)| x).collect())
                .collect(),
        )
    }

    /// [`Self::columns`], each node with its frame: the rotation from the
    /// chart of its stack's bottom node to its own.
    fn framed_columns(&self) -> Option<Vec<Vec<(Node, Rot3)>>> {
        let mut seen = vec![false; self.n_nodes()];
        let mut stacks = Vec::new();
        for x in self.alive_nodes() {
            if self.opposite(self.side(x, DOWN)).is_some() {
                continue;
            }
            let (mut stack, mut cur, mut frame) = (Vec::new(), x, Rot3::IDENTITY);
            loop {
                if std::mem::replace(&mut seen[cur.idx()], true) {
                    return None;
                }
                stack.push((cur, frame));
                let s = self.side(cur, UP);
                let Some(t) = self.opposite(s) else { break };
                let next = self.node_of(t);
                let r = self.rotation(s)?;
                let same = self.is_reverted(next) == self.is_reverted(cur);
                if self.dir_of(t) != DOWN || to_2d(r).is_none() || !same {
                    return None;
                }
                frame = frame.then(&r);
                cur = next;
            }
            stacks.push(stack);
        }
        let layers = stacks.first()?.len();
        let all = self.alive_nodes().all(|x| seen[x.idx()]);
        (all && stacks.iter().all(|s| s.len() == layers)).then_some(stacks)
    }

    /// The `u, v` links of layer `k` in the bottom nodes' charts (see
    /// [`Links`]), or `None` when a node of layer `k` is glued to another
    /// layer or by a rotation that moves `w`.
    fn layer_links(&self, stacks: &[Vec<(Node, Rot3)>], column: &[u32], k: usize) -> Option<Links> {
        let mut out = Vec::with_capacity(4 * stacks.len());
        for stack in stacks {
            let (x, fx) = stack[k];
            for d in 0..4 {
                let s = self.side(x, fx.apply_dir(d));
                let Some(t) = self.opposite(s) else {
                    out.push(None);
                    continue;
                };
                let y = self.node_of(t);
                let j = *column.get(y.idx())?;
                let &(yk, fy) = stacks.get(j as usize)?.get(k)?;
                let e = fy.inverse().apply_dir(self.dir_of(t));
                if e >= 4 || yk != y {
                    return None;
                }
                let r = fx.then(&self.rotation(s)?).then(&fy.inverse());
                out.push(Some((j, e, to_2d(r)?)));
            }
        }
        Some(out)
    }

    /// Index fairing on columns (module docs), with the 2D path bound.
    pub fn fair_columns(&mut self, max_path: usize) -> Option<ColumnFairing> {
        let stacks = self.framed_columns()?;
        let layers = stacks[0].len();
        let mut column = vec![u32::MAX; self.n_nodes()];
        for (i, s) in stacks.iter().enumerate() {
            for (x, _) in s {
                column[x.idx()] = i as u32;
            }
        }
        let links = self.layer_links(&stacks, &column, 0)?;
        for k in 1..layers {
            if self.layer_links(&stacks, &column, k)? != links {
                return None;
            }
        }
        // the 2D graph of one layer
        let reverted = stacks.iter().map(|s| self.is_reverted(s[0].0)).collect();
        let mut flat = NodeGraph::<2>::new(reverted);
        for (i, l) in links.iter().enumerate() {
            let Some((j, e, r)) = *l else { continue };
            let (a, b) = (
                flat.side(Node((i / 4) as u32), i % 4),
                flat.side(Node(j), e),
            );
            if flat.opposite(a).is_none() && flat.opposite(b).is_none() {
                flat.link(a, b, r).ok()?;
            }
        }
        let fairing = flat.fair(max_path);
        let collapsed = flat.collapse_folded_corners();
        let mut next = self.clone();
        next.write_layers(&flat, &stacks)?;
        next.check().ok()?;
        *self = next;
        Some(ColumnFairing {
            fairing,
            collapsed,
            layers,
            columns: stacks.len(),
        })
    }

    /// Replaces the `u, v` links of every layer by those of `flat` (in
    /// each node's own chart), and removes the columns of its dead nodes.
    fn write_layers(&mut self, flat: &NodeGraph<2>, stacks: &[Vec<(Node, Rot3)>]) -> Option<()> {
        for (i, stack) in stacks.iter().enumerate() {
            let dead = !flat.is_alive(Node(i as u32));
            let sides = if dead { 0..6 } else { 0..4 };
            for &(x, _) in stack {
                for d in sides.clone() {
                    let s = self.side(x, d);
                    if let Some(o) = self.opposite(s) {
                        self.clear(o);
                    }
                    self.clear(s);
                }
                if dead {
                    self.alive[x.idx()] = false;
                }
            }
        }
        for i in flat.alive_nodes() {
            for d in 0..4 {
                let a = flat.side(i, d);
                let Some(b) = flat.opposite(a) else { continue };
                if b.0 < a.0 {
                    continue; // each pair once
                }
                let (j, e) = (flat.node_of(b), flat.dir_of(b));
                let r = to_3d(flat.rotation(a)?)?;
                for (&(x, fx), &(y, fy)) in stacks[i.idx()].iter().zip(&stacks[j.idx()]) {
                    let rk = fx.inverse().then(&r).then(&fy);
                    let (sx, sy) = (self.side(x, fx.apply_dir(d)), self.side(y, fy.apply_dir(e)));
                    self.link(sx, sy, rk).ok()?;
                }
            }
        }
        Some(())
    }
}

#[cfg(test)]
mod tests;
