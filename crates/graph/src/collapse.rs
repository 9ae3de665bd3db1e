//! Collapse of a folded corner (D = 2): the last resort against valence-1
//! vertices that index fairing could not merge.
//!
//! A valence-1 vertex is a node X whose two sides around one corner are
//! glued to each other (X.s ↔ X.p, p ⊥ s): the quad is folded onto itself
//! and has a repeated vertex. Collapsing deletes X and glues the partners
//! of its two other sides to each other, through X's charts:
//!
//! ```text
//!      Y ── a┌────┐            Y ──────── Z
//!            │ X  │s             (X deleted, the valence-1 vertex v
//!      Z ── c└─p──┘v             disappears; a, c's partners glued)
//! ```
//! The Euler characteristic is unchanged (V − 1, E − 2, F − 1) and the
//! index sum is conserved: v's +¾ moves to the two ends of the merged edge
//! (+½ and +¼). Preconditions are checked before any write.

use crate::graph::NodeGraph;
use crate::ids::{axis, Node};
use crate::ops::OpError;

impl NodeGraph<2> {
    /// The direction `s` of a side of `x` glued to a perpendicular side of
    /// `x` itself (a folded corner), if any.
    pub fn folded_corner(&self, x: Node) -> Option<usize> {
        if !self.is_alive(x) {
            return None;
        }
        (0..4).find(|&d| {
            self.opposite(self.side(x, d))
                .is_some_and(|t| self.node_of(t) == x && axis(self.dir_of(t)) != axis(d))
        })
    }

    /// Collapses the folded corner of `x` at side `s_dir` (see the module
    /// docs). Returns `NotIsolated` when the fold is not a folded corner.
    pub fn collapse_folded_corner(&mut self, x: Node, s_dir: usize) -> Result<(), OpError> {
        let s = self.side(x, s_dir);
        self.usable(s)?;
        let t = self.opposite(s).ok_or(OpError::Unmatched(s))?;
        let p_dir = self.dir_of(t);
        if self.node_of(t) != x || axis(p_dir) == axis(s_dir) {
            return Err(OpError::NotIsolated(x, x));
        }
        let q = self.rot[s.idx()];
        let (a, c) = (self.side(x, s_dir ^ 1), self.side(x, p_dir ^ 1));
        let (pa, pc) = (self.opposite(a), self.opposite(c));
        // rotation from a's partner to c's partner, through X's fold
        let rho = match (pa, pc) {
            (Some(pa), Some(_)) if pa != c => {
                Some(self.rot[pa.idx()].then(&q).then(&self.rot[c.idx()]))
            }
            _ => None,
        };
        for side in [s, t, a, c] {
            if let Some(o) = self.opposite(side) {
                self.clear(o);
            }
            self.clear(side);
        }
        self.alive[x.idx()] = false;
        if let (Some(pa), Some(pc), Some(rho)) = (pa, pc, rho) {
            self.link(pa, pc, rho)?;
        }
        Ok(())
    }

    /// Collapses folded corners until none is left; returns how many.
    /// Terminates: each collapse deletes one node.
    pub fn collapse_folded_corners(&mut self) -> usize {
        let mut done = 0;
        loop {
            let found = (0..self.n_nodes() as u32)
                .map(Node)
                .find_map(|x| self.folded_corner(x).map(|d| (x, d)));
            let Some((x, d)) = found else { return done };
            if self.collapse_folded_corner(x, d).is_err() {
                return done;
            }
            done += 1;
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::testgrid::singular_disk;
    use crate::Node;

    #[test]
    fn a_valence_one_vertex_is_collapsed() {
        let mut g = singular_disk(1, 3);
        g.check().expect("valid before");
        let before = g.glue();
        let x = Node(0);
        let d = g.folded_corner(x).expect("the sector's corner is folded");
        g.collapse_folded_corner(x, d).expect("collapse");
        g.check().expect("valid after");
        let after = g.glue();
        assert_eq!(after.n_cells(), before.n_cells() - 1);
        assert_eq!(after.n_vertices, before.n_vertices - 1);
        let euler = |gl: &crate::Glued<2>| {
            gl.n_vertices as i64 - gl.edges().len() as i64 + gl.n_cells() as i64
        };
        // a disk; (`edges()` merges the folded quad's two a–w edges, so the
        // Euler characteristic before cannot be read from it)
        assert_eq!(euler(&after), 1);
        assert_eq!(after.boundary_loops, 1);
        assert!((0..g.n_nodes() as u32).all(|n| g.folded_corner(Node(n)).is_none()));
        // no cell has a repeated vertex any more
        for i in 0..after.n_cells() {
            let c = after.cell(i).expect("cell");
            let mut v = c.to_vec();
            v.sort_unstable();
            v.dedup();
            assert_eq!(v.len(), 4, "cell {i}: {c:?}");
        }
    }

    #[test]
    fn regular_disks_have_no_folded_corner() {
        let mut g = singular_disk(4, 3);
        assert_eq!(g.collapse_folded_corners(), 0);
        g.check().expect("valid");
    }
}
