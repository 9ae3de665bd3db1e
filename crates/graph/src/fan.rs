//! Vertex fans of a 2D graph: the cyclic sequence of nodes around a mesh
//! vertex, read from the graph (not from a glued mesh).
//!
//! A corner of node X is given by its two sides `in` and `out` (one per
//! axis). Leaving X through `out` into Y = opp(X.out) with ρ, the same
//! corner of Y lies between `in' = dir(opp(X.out))` and `out' = ρ(in)`
//! (the gluing rule of [`crate::glue`]). Repeating closes the fan of an
//! interior vertex; a fan that reaches an unmatched side is on the boundary.
//!
//! ```text
//!        X2 │ X1           step k crosses the pair
//!       ────v────          X_k.out_k ↔ X_{k+1}.in_{k+1}
//!        X3 │ X0           (an edge of the mesh incident to v)
//! ```

use crate::graph::NodeGraph;
use crate::ids::{axis, positive, Node, Side};
use dualex_map::Rot2;

/// One node of a fan, with the two sides of its corner at the vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct FanStep {
    /// The node.
    pub node: Node,
    /// The side shared with the previous node of the fan.
    pub in_dir: usize,
    /// The side shared with the next node of the fan.
    pub out_dir: usize,
    /// Rotation from this node's chart to the next node's chart.
    pub rot: Rot2,
}

impl FanStep {
    /// The corner code of the node at the vertex.
    pub fn code(&self) -> usize {
        corner_code(self.in_dir, self.out_dir)
    }
}

/// The corner code between two perpendicular sides.
pub fn corner_code(d0: usize, d1: usize) -> usize {
    (usize::from(positive(d0)) << axis(d0)) | (usize::from(positive(d1)) << axis(d1))
}

/// The two sides (u side, v side) at corner `code` of a quad.
pub fn corner_sides(code: usize) -> (usize, usize) {
    (usize::from(code & 1 == 0), 2 + usize::from(code & 2 == 0))
}

impl NodeGraph<2> {
    /// The closed fan around corner `code` of `x`, starting at `x`; `None`
    /// if the vertex is on the boundary (or the graph is broken there).
    pub fn fan(&self, x: Node, code: usize) -> Option<Vec<FanStep>> {
        if !self.is_alive(x) || code >= 4 {
            return None;
        }
        let (du, dv) = corner_sides(code);
        let start = (x, du, dv);
        let (mut node, mut din, mut dout) = start;
        let mut out = Vec::new();
        for _ in 0..=self.n_sides() {
            let s: Side = self.side(node, dout);
            let t = self.opposite(s)?;
            let rot = self.rot[s.idx()];
            out.push(FanStep {
                node,
                in_dir: din,
                out_dir: dout,
                rot,
            });
            (node, din, dout) = (self.node_of(t), self.dir_of(t), rot.apply_dir(din));
            if axis(din) == axis(dout) {
                return None;
            }
            if (node, din, dout) == start {
                return Some(out);
            }
        }
        None
    }
}
