//! Components of the node graph, and deleting some (the "bubbles").
//!
//! On maps with many folds, untangling can close part of a fold into a
//! small surface of its own (a sphere of a few quads beside the real one),
//! and on maps with many walks lost at singular vertices a few nodes can
//! be cut off the rest (a strip of two quads with boundary): the output
//! then has more components than the input. The caller decides which
//! components are such bubbles (in 2D: the smaller ones in an input
//! component, see `dualex_quad::bubbles`); this module gives the labels and
//! the deletion.
//!
//! [`NodeGraph::delete_components`] precondition, checked before any
//! write: every node alive, every glued side glued to a node of the set
//! (the set is a union of components). Invariant: the rest of the graph is
//! untouched (no side outside the set changes).

use crate::graph::NodeGraph;
use crate::ids::Node;
use crate::ops::OpError;
use rayon::prelude::*;

/// Marker for dead nodes in [`NodeGraph::component_labels`].
pub const NO_COMPONENT: u32 = u32::MAX;

impl<const D: usize> NodeGraph<D> {
    /// Per node its component (ids `0..k` by first node), [`NO_COMPONENT`]
    /// for dead nodes; and k. The unions run in parallel
    /// (`NodeGraph::node_sets`), the roots are read in parallel, the
    /// numbering by first alive node is one serial pass over the nodes.
    pub fn component_labels(&self) -> (Vec<u32>, usize) {
        let uf = self.node_sets();
        let mut labels: Vec<u32> = (0..self.n_nodes() as u32)
            .into_par_iter()
            .with_min_len(1024)
            .map(|x| match self.is_alive(Node(x)) {
                true => uf.root(x as usize) as u32,
                false => NO_COMPONENT,
            })
            .collect();
        let mut id_of_root = vec![NO_COMPONENT; self.n_nodes()];
        let mut k = 0u32;
        for l in labels.iter_mut().filter(|l| **l != NO_COMPONENT) {
            let id = &mut id_of_root[*l as usize];
            if *id == NO_COMPONENT {
                (*id, k) = (k, k + 1);
            }
            *l = *id;
        }
        (labels, k as usize)
    }

    /// [`Self::component_labels`] by a serial union–find (its test oracle).
    #[cfg(test)]
    pub(crate) fn component_labels_serial(&self) -> (Vec<u32>, usize) {
        let mut uf = dualex_util::union_find::UnionFind::new(self.n_nodes());
        for s in (0..self.n_sides() as u32).map(crate::ids::Side) {
            if let Some(t) = self.opposite(s) {
                uf.union(self.node_of(s).idx(), self.node_of(t).idx());
            }
        }
        let mut id_of_root = vec![NO_COMPONENT; self.n_nodes()];
        let mut labels = vec![NO_COMPONENT; self.n_nodes()];
        let mut k = 0u32;
        for x in self.alive_nodes() {
            let r = uf.find(x.idx());
            if id_of_root[r] == NO_COMPONENT {
                id_of_root[r] = k;
                k += 1;
            }
            labels[x.idx()] = id_of_root[r];
        }
        (labels, k as usize)
    }

    /// Deletes `nodes`, a union of components (see the module docs).
    pub fn delete_components(&mut self, nodes: &[Node]) -> Result<(), OpError> {
        let mut inside = vec![false; self.n_nodes()];
        for &x in nodes {
            self.usable(self.side(x, 0))?;
            inside[x.idx()] = true;
        }
        for &x in nodes {
            for d in 0..2 * D {
                let s = self.side(x, d);
                if let Some(t) = self.opposite(s) {
                    if !inside[self.node_of(t).idx()] {
                        return Err(OpError::NotIsolated(x, self.node_of(t)));
                    }
                }
            }
        }
        for &x in nodes {
            for d in 0..2 * D {
                self.clear(self.side(x, d));
            }
            self.alive[x.idx()] = false;
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use crate::graph::NodeGraph;
    use crate::ids::Node;
    use crate::ops::OpError;
    use dualex_map::Rot2;

    /// A pillow (nodes 0, 1: closed) and a strip of two nodes (2, 3: open).
    fn two_components() -> NodeGraph<2> {
        let mut g = NodeGraph::<2>::new(vec![false; 4]);
        for d in 0..4 {
            g.link(g.side(Node(0), d), g.side(Node(1), d ^ 1), Rot2::IDENTITY)
                .expect("link");
        }
        g.link(g.side(Node(2), 0), g.side(Node(3), 1), Rot2::IDENTITY)
            .expect("link");
        g
    }

    #[test]
    fn labels_and_deletion_of_components() {
        let mut g = two_components();
        let (labels, k) = g.component_labels();
        assert_eq!((labels, k), (vec![0, 0, 1, 1], 2));
        // not a union of components: refused, nothing written
        let before = g.clone();
        assert!(matches!(
            g.delete_components(&[Node(0)]),
            Err(OpError::NotIsolated(..))
        ));
        assert!(matches!(
            g.delete_components(&[Node(1), Node(2), Node(3)]),
            Err(OpError::NotIsolated(..))
        ));
        assert_eq!(g, before);
        g.delete_components(&[Node(0), Node(1)]).expect("closed");
        g.check_structure().expect("valid");
        assert_eq!(g.n_alive(), 2);
        assert_eq!(g.opposite(g.side(Node(2), 0)), Some(g.side(Node(3), 1)));
        assert_eq!(g.component_labels().1, 1);
        // an open component too
        g.delete_components(&[Node(2), Node(3)]).expect("open");
        g.check_structure().expect("valid");
        assert_eq!(g.n_alive(), 0);
    }

    /// The parallel labels are the serial union–find's, in both dimensions,
    /// on grids cut into pieces by random unlinks, with whole pieces
    /// deleted (dead nodes among the alive) and the nodes renumbered.
    #[test]
    fn parallel_labels_are_the_serial_ones() {
        fn case<const D: usize>(dims: [usize; D], cuts: usize, seed: u64) -> usize {
            use crate::testgrid::{random_permutation, GridSpec};
            let mut rng = dualex_util::rng::SplitMix::new(seed);
            let mut g = GridSpec::regular(dims).build();
            for _ in 0..cuts {
                let s = crate::ids::Side(rng.below(g.n_sides()) as u32);
                if g.opposite(s).is_some() {
                    g.unlink(s).expect("unlink");
                }
            }
            let perm = random_permutation(g.n_nodes(), seed);
            let mut g = crate::testgrid::renumber(&g, &perm);
            // delete every third piece
            let (labels, k) = g.component_labels_serial();
            for c in (0..k as u32).filter(|c| c % 3 == 1) {
                let piece: Vec<Node> = g.alive_nodes().filter(|x| labels[x.idx()] == c).collect();
                g.delete_components(&piece).expect("a piece");
            }
            let want = g.component_labels_serial();
            assert_eq!(g.component_labels(), want, "D = {D}, seed {seed}");
            want.1
        }
        let mut pieces = 0;
        for seed in 0..40 {
            pieces += case([12, 9], 40 + 5 * seed as usize, seed);
            pieces += case([5, 4, 6], 60 + 8 * seed as usize, 100 + seed);
        }
        assert!(pieces > 400, "too few pieces to compare: {pieces}");
        assert_eq!(case([40, 40], 0, 7), 1);
        assert!(case([200, 50], 6000, 8) > 10);
    }
}
