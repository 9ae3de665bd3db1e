//! Step 9's placement, both dimensions: the glued cells as a mesh whose
//! vertices sit where the node diagonals reach ([`crate::diagonal`]), with
//! the input simplex holding each cell's node and its corners' map
//! coordinates (`--uv`, `dualex_cells::corners`); [`Placed::remake`]
//! carries both through the repairs of steps 10–11; [`Extracted`] is what
//! both extractions return.
//!
//! Input: the sanitized map ([`Sanitized`]), its nodes, the graph and its
//! gluing ([`Glued`]), the corners a doublet merge took over. Output: a
//! [`Placed`]. Invariants: the cells are [`Glued`]'s, in its order; a
//! vertex no alive corner uses is placed at the origin; a merged node's
//! cell has no corners.

use crate::diagonal::diagonal;
use crate::local::node_corner;
use crate::nodes::Nodes;
use crate::simplex::Dim;
use crate::steps::{Dimension, Sanitized};
use dualex_cells::corners::{carry, Corners};
use dualex_cells::CellMesh;
use dualex_graph::{Glued, NodeGraph, Takeover};
use rayon::prelude::*;

/// The output cells (`K = 2^D` corners each) with, per cell, the input
/// simplex holding its node and its corners' map coordinates.
#[derive(Clone, Debug)]
pub struct Placed<const D: usize, const K: usize> {
    /// The mesh.
    pub mesh: CellMesh<K>,
    /// Per cell, the input simplex holding its node (the driver's
    /// `NO_SOURCE` for a cell no node holds).
    pub sources: Vec<u32>,
    /// Per cell, its corners in that simplex's input chart.
    pub corners: Vec<Corners<D, K>>,
}

/// Step 9: the glued cells placed (corner code bits: bit `a` set = the +
/// side of axis `a`; a corner taken over by a doublet merge traced from
/// the node it belonged to), their sources and corners.
pub fn place<const N: usize, const D: usize, const K: usize>(
    s: &Sanitized<'_, N, D>,
    nodes: &Nodes<N, D>,
    graph: &NodeGraph<D>,
    glued: &Glued<D>,
    takeover: &Takeover<D>,
) -> Placed<D, K>
where
    Dim<N, D>: Dimension<N, D>,
{
    // each vertex's position written once (a vertex no alive corner uses
    // at the origin)
    let positions = glued.best_per_vertex(
        takeover,
        |node, code| {
            let sgn = std::array::from_fn(|a| if code >> a & 1 == 1 { 1.0 } else { -1.0 });
            diagonal(&s.map, &s.local, &s.topo, nodes, node.idx(), sgn)
        },
        |c| c.dist,
        |b| b.map_or([0.0; 3], |c| c.pos),
    );
    // the gluing's cells, copied in parallel
    let mesh = CellMesh {
        positions,
        cells: glued.cell_array().par_iter().copied().collect(),
    };
    // each source on its own, in parallel, collected in order
    let sources = glued
        .nodes
        .par_iter()
        .map(|node| s.parent[nodes.simplex[node.idx()] as usize])
        .collect();
    let corners = glued.cell_corners(graph, takeover, |n, code| {
        let (simplex, point) = (nodes.simplex[n.idx()] as usize, &nodes.point[n.idx()]);
        node_corner(&s.local, simplex, point, code)
    });
    Placed {
        mesh,
        sources,
        corners,
    }
}

impl<const D: usize, const K: usize> Placed<D, K> {
    /// The cells remade by a repair: cell `c` of `new` made from cell
    /// `origin[c]` (its source kept, its corners carried,
    /// [`dualex_cells::corners::carry`]).
    pub fn remake(&mut self, new: CellMesh<K>, origin: &[u32]) {
        self.corners = carry(&self.mesh, &self.corners, &new, origin);
        self.sources = origin.iter().map(|&o| self.sources[o as usize]).collect();
        self.mesh = new;
    }
}

/// What an extraction returns (`dualex_quad::extract_full`,
/// `dualex_hex::extract_full`): the mesh, its stats `S`, and per cell the
/// input simplex holding its node and its corners' map coordinates.
#[derive(Clone, Debug)]
pub struct Extracted<const D: usize, const K: usize, S> {
    /// The mesh (quads counter-clockwise, hexes in VTK order).
    pub mesh: CellMesh<K>,
    /// Its counts.
    pub stats: S,
    /// Per cell, the input simplex holding its node (as
    /// [`Placed::sources`]).
    pub sources: Vec<u32>,
    /// Per cell, its corners' map coordinates in that simplex's chart, in
    /// the cell's corner order (none for a cell merged from a doublet, a
    /// face closing a hole, a cell of a local repair path).
    pub corners: Vec<Corners<D, K>>,
}

impl<const D: usize, const K: usize> Placed<D, K> {
    /// The extraction's result: these cells with `stats`.
    pub fn extracted<S>(self, stats: S) -> Extracted<D, K, S> {
        Extracted {
            mesh: self.mesh,
            stats,
            sources: self.sources,
            corners: self.corners,
        }
    }
}

impl<const D: usize, const K: usize, S> Extracted<D, K, S> {
    /// The mesh, the stats and the sources (`extract_traced`).
    pub fn traced(self) -> (CellMesh<K>, S, Vec<u32>) {
        (self.mesh, self.stats, self.sources)
    }
}
