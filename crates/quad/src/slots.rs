//! Step 10a's view of the glued cells: each cell edge (a *slot*, `4 ·
//! cell + k`, the edge from corner k to corner k + 1) as the graph side
//! it is, its glued partner slot, and the unmatched slots that are holes.
//!
//! Input: the graph and its gluing (and the walks' ends, which tell holes
//! from boundary on an input with boundary). Output: [`CellSlots`] and
//! the hole slots, in the order of the cells, then of the sides'
//! directions. Invariant: `partner` is an involution on glued slots.

use dualex_graph::{NodeGraph, Side};
use dualex_segment::trace::End;
use rayon::prelude::*;

/// Each cell edge's side in the graph and its glued partner edge
/// (`crate::ambiguous::Slot`s: `4 · cell + k`, the edge from corner k to k + 1).
pub(crate) struct CellSlots {
    /// Per slot: the graph side it is.
    pub side: Vec<Side>,
    /// Per slot: the slot glued to it (`None`: unmatched, or glued to a
    /// dead node).
    pub partner: Vec<Option<crate::ambiguous::Slot>>,
}

/// The direction of the side of a node holding cell edge `k` (corners k
/// and k + 1 of the cell).
fn edge_dir(k: usize, reverted: bool) -> usize {
    let (a, b) = (
        dualex_graph::cell_code::<2>(k, reverted),
        dualex_graph::cell_code::<2>((k + 1) % 4, reverted),
    );
    // the axis on which the two corners agree, and their bit on it
    let same = if (a ^ b) & 1 == 0 { 0 } else { 1 };
    let bit = (a >> same) & 1;
    2 * same + (1 - bit)
}

/// The inverse of [`edge_dir`]: the cell edge of each side direction, for
/// a node not reverted (`[0]`) and reverted (`[1]`).
fn dir_edges() -> [[usize; 4]; 2] {
    [false, true].map(|rev| {
        let mut m = [0; 4];
        for k in 0..4 {
            m[edge_dir(k, rev)] = k;
        }
        m
    })
}

/// Each cell edge's side and partner (module docs).
pub(crate) fn cell_slots(graph: &NodeGraph<2>, glued: &dualex_graph::Glued<2>) -> CellSlots {
    let n = glued.nodes.len();
    let mut cell_of = vec![u32::MAX; graph.n_nodes()];
    for (c, node) in glued.nodes.iter().enumerate() {
        cell_of[node.idx()] = c as u32;
    }
    let dir_slot = dir_edges();
    let mut side = vec![Side(0); 4 * n];
    let mut partner = vec![None; 4 * n];
    // cell by cell in parallel (each writes its own four slots)
    side.par_chunks_mut(4)
        .zip(partner.par_chunks_mut(4))
        .zip(&glued.nodes)
        .for_each(|((side, partner), node)| {
            let rev = graph.is_reverted(*node);
            for k in 0..4 {
                let s = graph.side(*node, edge_dir(k, rev));
                side[k] = s;
                partner[k] = graph.opposite(s).and_then(|t| {
                    let y = graph.node_of(t);
                    let c = *cell_of.get(y.idx())?;
                    let k = dir_slot[usize::from(graph.is_reverted(y))][graph.dir_of(t)];
                    (c != u32::MAX).then_some(4 * c + k as u32)
                });
            }
        });
    CellSlots { side, partner }
}

/// Unmatched sides that are holes, not boundary, as cell edges: all of
/// them on a closed input; otherwise those whose walk got lost at a
/// singular vertex. Sides whose two corners are one vertex are left out.
pub(crate) fn hole_slots(
    graph: &NodeGraph<2>,
    glued: &dualex_graph::Glued<2>,
    slots: &CellSlots,
    ends: &[End<2>],
    closed: bool,
) -> Vec<crate::ambiguous::Slot> {
    // in the order of the cells, then of the sides' directions
    let dir_slot = dir_edges();
    let order = glued.nodes.iter().enumerate().flat_map(move |(c, node)| {
        let edges = dir_slot[usize::from(graph.is_reverted(*node))];
        edges.map(|k| 4 * c + k)
    });
    order
        .filter(|&i| {
            let s = slots.side[i];
            if graph.opposite(s).is_some() {
                return false;
            }
            // on an input with boundary, only the walks that got lost at a
            // singular vertex leave holes; the others are boundary (reached
            // directly, or handed over by a reconnection during untangling)
            let lost = matches!(ends.get(s.0 as usize), Some(End::Inconsistent | End::Loop));
            let (c, k) = (i / 4, i % 4);
            let cell = glued.cell(c).unwrap_or_default();
            (closed || lost) && cell.get(k) != cell.get((k + 1) % 4)
        })
        .map(|i| i as crate::ambiguous::Slot)
        .collect()
}
