//! Step 8: the map coordinates of each hex's corners, in the input chart
//! of the tet that holds the hex's node — see [`dualex_cells::corners`] for
//! the definition (node ± ½, exact grid points of the input map: integers
//! with the grid offset `Half`, half-integers with `Zero`).
//!
//! Input: the glued cells with their nodes, then the cells step 7 remakes.
//! Output: per hex, its 8 corners' coordinates in its cell (VTK) order, or
//! `None` (a hex merged from a doublet chain: in the graph, or on the mesh
//! when its corners are not all corners of its first cell).

use crate::local::LocalMap;
use crate::nodes::Nodes;
use dualex_cells::corners::Corners;
use dualex_graph::{Glued, NodeGraph, Takeover};
use dualex_segment::local::node_corner;

/// The map coordinates of a hex's corners (module docs).
pub type HexCorners = Corners<3, 8>;

/// The corners of the glued cells, in [`Glued::cells`] order (none for a
/// node that took over another one's corners: a merged doublet chain).
pub fn of_glued(
    glued: &Glued<3>,
    graph: &NodeGraph<3>,
    local: &LocalMap,
    nodes: &Nodes,
    takeover: &Takeover<3>,
) -> Vec<HexCorners> {
    glued.cell_corners(graph, takeover, |n, code| {
        let (s, ijk) = (nodes.simplex[n.idx()] as usize, &nodes.point[n.idx()]);
        node_corner(local, s, ijk, code)
    })
}
