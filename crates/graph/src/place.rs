//! The choice of one candidate per output vertex, shared by quad and hex
//! vertex placement.
//!
//! Input: a [`Glued`] mesh, what doublet merges took over ([`Takeover`]:
//! a merged node's corner is traced from the corners it took over) and a
//! candidate function `(node, corner code) → C` with a distance (0 =
//! exact). Output: per vertex, the caller's value (e.g. a position,
//! written once) of the candidate with the smallest distance among the
//! corners of that vertex (their origins), taken in node order then
//! corner-code order, the first one on ties (so, the same as before the
//! merges); candidates after an exact one (distance 0) are not computed.
//! Vertices are processed in parallel (rayon); each vertex's corners are visited in the same order
//! as a sequential sweep over the cells would, so the result does not
//! depend on the thread count.

use crate::doublet::Takeover;
use crate::glue::{cell_code, Glued};
use crate::graph::NodeGraph;
use crate::ids::Node;
use rayon::prelude::*;

impl<const D: usize> Glued<D> {
    /// Per cell, in [`Glued::cells`] order, `corner(node, code)` at each of
    /// its `K = 2^D` corners in output order ([`cell_code`]: a reverted
    /// node's cell is mirrored); `None` for a node that took over another
    /// one's corners (a merged doublet: its corners are not where its node
    /// says). The map coordinates of the corners (`--uv`) in both
    /// pipelines.
    pub fn cell_corners<T: Send, const K: usize>(
        &self,
        graph: &NodeGraph<D>,
        takeover: &Takeover<D>,
        corner: impl Fn(Node, usize) -> T + Sync,
    ) -> Vec<Option<[T; K]>> {
        assert_eq!(K, 1 << D, "bug: a cell of dimension {D} has 2^{D} corners");
        // cell by cell in parallel, collected in cell order
        self.nodes
            .par_iter()
            .map(|&n| {
                if takeover.is_merged(n) {
                    return None;
                }
                let rev = graph.is_reverted(n);
                Some(std::array::from_fn(|k| corner(n, cell_code::<D>(k, rev))))
            })
            .collect()
    }

    /// `out` of the best candidate of every vertex (see the module docs;
    /// `None` for a vertex no alive corner uses), written once per vertex.
    pub fn best_per_vertex<C: Send, T: Send>(
        &self,
        takeover: &Takeover<D>,
        candidate: impl Fn(Node, usize) -> C + Sync,
        dist: impl Fn(&C) -> f64 + Sync,
        out: impl Fn(Option<C>) -> T + Sync,
    ) -> Vec<T> {
        let k = 1usize << D;
        let nv = self.n_vertices;
        // a corner's id `node·2^D + code` is a u32 (as the takeover's)
        assert!(
            u32::try_from(self.vertex_of.len()).is_ok(),
            "bug: more corners than u32 ids"
        );
        // the corners (origins) of each vertex, in (node, code) order, that
        // is in id order (CSR)
        let mut offsets = vec![0u32; nv + 1];
        for n in &self.nodes {
            for code in 0..k {
                let v = self.vertex(*n, code) as usize;
                let Some(count) = offsets.get_mut(v + 1) else {
                    panic!("bug: corner {code} of node {} has no vertex", n.idx());
                };
                *count += takeover.n_origins(*n, code) as u32;
            }
        }
        for v in 0..nv {
            offsets[v + 1] += offsets[v];
        }
        let mut fill: Vec<u32> = offsets[..nv].to_vec();
        // every slot is written below (a fill, not a zeroed block: no
        // memset of a block the allocator hands back)
        let mut corners = vec![u32::MAX; offsets[nv] as usize];
        for n in &self.nodes {
            for code in 0..k {
                let slot = &mut fill[self.vertex(*n, code) as usize];
                takeover.for_each_origin(*n, code, |m, c| {
                    corners[*slot as usize] = m.0 * k as u32 + c as u32;
                    *slot += 1;
                });
            }
        }
        if !takeover.is_empty() {
            for v in 0..nv {
                corners[offsets[v] as usize..offsets[v + 1] as usize].sort_unstable();
            }
        }
        (0..nv)
            .into_par_iter()
            .with_min_len(1024)
            .map(|v| {
                let mut best: Option<C> = None;
                for &id in &corners[offsets[v] as usize..offsets[v + 1] as usize] {
                    if best.as_ref().is_some_and(|b| dist(b) == 0.0) {
                        break;
                    }
                    let c = candidate(Node(id / k as u32), id as usize % k);
                    if best.as_ref().is_none_or(|b| dist(&c) < dist(b)) {
                        best = Some(c);
                    }
                }
                out(best)
            })
            .collect()
    }
}
