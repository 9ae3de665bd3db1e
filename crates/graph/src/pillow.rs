//! Pillows left after untangling: two nodes glued only to each other.
//!
//! A pillow is a closed component of two cells (2D: two quads glued along
//! all four sides, a sphere with four valence-2 vertices). Pleat removal
//! deletes the pillows it makes itself (OP1 ends every pleat removal), but
//! on maps with many folds (`dualex remesh` with direct rounding, walks
//! lost at singular vertices) reconnections elsewhere can close a pair of
//! *non-pleat* nodes into one: a fold pocket that detaches as a component
//! of its own, which the input does not have.
//!
//! [`NodeGraph::remove_pillows`] deletes them by OP1 (its preconditions are
//! the definition: both nodes alive, distinct, every side of one glued to
//! the other). It keeps a pillow that is the whole graph (a pillowcase map
//! with four +½ singularities is one). Invariant: nothing but pillows
//! changes; every deletion removes one closed component.

use crate::graph::NodeGraph;
use crate::ids::Node;

impl<const D: usize> NodeGraph<D> {
    /// The node all of `x`'s sides are glued to, when `x` and it form a
    /// pillow.
    pub fn pillow_partner(&self, x: Node) -> Option<Node> {
        if !self.is_alive(x) {
            return None;
        }
        let y = self.node_of(self.opposite(self.side(x, 0))?);
        let closed = (0..2 * D).all(|d| {
            self.opposite(self.side(x, d))
                .is_some_and(|t| self.node_of(t) == y)
        });
        (closed && y != x).then_some(y)
    }

    /// Deletes every pillow unless it is the whole graph; returns how many.
    pub fn remove_pillows(&mut self) -> usize {
        let mut removed = 0;
        for i in 0..self.n_nodes() as u32 {
            let x = Node(i);
            let Some(y) = self.pillow_partner(x) else {
                continue;
            };
            if self.n_alive() <= 2 {
                break;
            }
            if self.op1(x, y).is_ok() {
                removed += 1;
            }
        }
        removed
    }
}

#[cfg(test)]
mod tests {
    use crate::graph::NodeGraph;
    use crate::ids::Node;
    use crate::testgrid::singular_disk;
    use dualex_map::Rot2;

    /// Two nodes glued side to side, each side d of x to side d ^ 1 of y.
    fn add_pillow(g: &mut NodeGraph<2>, x: Node, y: Node) {
        for d in 0..4 {
            g.link(g.side(x, d), g.side(y, d ^ 1), Rot2::IDENTITY)
                .expect("link");
        }
    }

    #[test]
    fn a_detached_pillow_is_removed_and_the_rest_kept() {
        let disk = singular_disk(4, 2);
        let n = disk.n_nodes();
        let mut g = NodeGraph::<2>::new(vec![false; n + 2]);
        for x in 0..n as u32 {
            for d in 0..4 {
                let s = disk.side(Node(x), d);
                if let (Some(t), Some(r)) = (disk.opposite(s), disk.rotation(s)) {
                    if s.0 < t.0 {
                        g.link(s, t, r).expect("copy");
                    }
                }
            }
        }
        let (x, y) = (Node(n as u32), Node(n as u32 + 1));
        add_pillow(&mut g, x, y);
        g.check_structure().expect("valid before");
        let before = g.glue();
        assert_eq!(before.components, 2);
        assert_eq!(g.pillow_partner(x), Some(y));
        assert_eq!(g.remove_pillows(), 1);
        g.check_structure().expect("valid after");
        let after = g.glue();
        assert_eq!(after.components, 1);
        assert_eq!(after.n_cells(), n);
        assert_eq!(after.vertex_of[..n * 4], before.vertex_of[..n * 4]);
    }

    #[test]
    fn a_pillow_alone_is_kept() {
        let mut g = NodeGraph::<2>::new(vec![false; 2]);
        add_pillow(&mut g, Node(0), Node(1));
        assert_eq!(g.remove_pillows(), 0);
        assert_eq!(g.n_alive(), 2);
    }
}
