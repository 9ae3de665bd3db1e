//! Step 10, D = 2: the repairs on the placed mesh, in order.
//! - 10a. parallel edges and folded cells split by their identity in the
//!   graph ([`crate::ambiguous`], through `crate::slots`), so that vertex
//!   pairs name every edge of the repair;
//! - 10b. holes closed, faces quads cannot represent repaired by paths of
//!   quads or, as the fallback, the whole mesh subdivided once
//!   ([`crate::repair`]);
//! - 10c. pinch points split ([`crate::pinched`], within the repair); a
//!   pinch point split can leave a pocket of a fold beside the surface,
//!   and a node cut off the rest closed by its hole fill is a pillow:
//!   deleted as the bubbles of step 8d are
//!   ([`crate::bubbles::drop_mesh_bubbles`]).
//!
//! Input: the glued graph, the walks' ends (holes from boundary), the
//! input's topology and the placed quads of step 9. Output: the repaired
//! quads, their sources (a cell closing a hole: [`crate::NO_SOURCE`]) and
//! corners (kept where a cell is unchanged, [`crate::corner_uv`] through a
//! subdivision), the counts. Nothing changes when nothing is to repair.

use crate::{ambiguous, bubbles, corner_uv, repair, slots, QuadStats, NO_SOURCE};
use dualex_cells::QuadMesh;
use dualex_graph::{Glued, NodeGraph};
use dualex_map::Topology;
use dualex_segment::place::Placed;
use dualex_segment::trace::End;

/// Step 10 (module docs).
pub fn repair(
    graph: &NodeGraph<2>,
    glued: &Glued<2>,
    ends: &[End<2>],
    topo: &Topology<3>,
    out: &mut Placed<2, 4>,
    st: &mut QuadStats,
) {
    // nothing to do, as the output's check tells (no slot built)
    if checked_clean(st, &out.mesh) {
        // the slots' own test would say so too (asserted where the
        // crate's tests extract)
        #[cfg(test)]
        assert!(nothing_by_slots(graph, glued, ends, topo, &out.mesh));
        return nothing_repaired(st);
    }
    // 10a
    let slots = slots::cell_slots(graph, glued);
    let holes = slots::hole_slots(graph, glued, &slots, ends, topo.boundary_facets == 0);
    let marks = ambiguous::marks(&out.mesh.cells, &slots.partner);
    if nothing_to_repair(&marks, &holes, &out.mesh) {
        return nothing_repaired(st);
    }
    let amb = ambiguous::split_marked(&out.mesh, &slots.partner, &holes, marks);
    st.parallel_edges_split = amb.parallel_edges;
    st.folded_cells_cut = amb.folded_cells;
    // 10b
    let (fill, open) = dualex_cells::polygons::hole_polygons(&amb.hole_edges);
    st.holes_left_open = open;
    let Some(rep) = repair::repair_polygons(&amb.positions, &amb.polys, &fill, amb.changed())
    else {
        return;
    };
    st.repair_triangles = repair::odd_cells(&out.mesh);
    st.holes_filled = fill.len();
    st.repair_dropped = rep.dropped;
    st.subdivided = rep.subdivided;
    st.repair_paths = rep.local_paths;
    st.pinched_vertices_split = rep.pinched;
    // the collapsed sides of the triangles were unmatched sides whose two
    // corners are one vertex, and the filled holes' sides are glued to the
    // new faces: neither is boundary
    let collapsed = collapsed_unmatched_sides(graph, glued);
    st.unmatched_sides -= (collapsed + holes.len()).min(st.unmatched_sides);
    st.boundary_loops -= (collapsed + fill.len()).min(st.boundary_loops);
    // origins: a polygon of `amb` (then its cell; its corners only where it
    // is the cell unchanged) or a hole fill
    let cell_of = |o: u32| amb.origin.get(o as usize).copied().unwrap_or(NO_SOURCE);
    let intact_cell = |o: u32| match amb.intact.get(o as usize) {
        Some(true) => cell_of(o),
        _ => NO_SOURCE,
    };
    let carried: Vec<u32> = rep.origin.iter().map(|&o| intact_cell(o)).collect();
    out.corners = if rep.subdivided {
        corner_uv::subdivided(&out.mesh, &out.corners, &rep.mesh, &carried)
    } else {
        dualex_cells::corners::carry(&out.mesh, &out.corners, &rep.mesh, &carried)
    };
    out.sources = rep
        .origin
        .iter()
        .map(|&o| {
            let source = out.sources.get(cell_of(o) as usize);
            source.copied().unwrap_or(NO_SOURCE)
        })
        .collect();
    out.mesh = rep.mesh;
    // 10c
    drop_pockets(topo, out, st);
    st.finish_mesh(&out.mesh);
}

/// The counts of a step 10 that changed nothing.
fn nothing_repaired(st: &mut QuadStats) {
    (
        st.parallel_edges_split,
        st.folded_cells_cut,
        st.holes_left_open,
    ) = (0, 0, 0);
}

/// Whether step 10 has nothing to do, read off the output's check
/// (`QuadStats::finish_output`, made of this very `mesh`) and the graph's
/// count, before any slot is built: no unmatched side (so no hole, and no
/// two unmatched sides between the same two vertices), no vertex pair
/// used by more than two cell edges (so no two glued pairs, or a pair and
/// a side, between the same two vertices: no parallel edge) and no cell
/// with a repeated corner (no folded cell; every cell a proper quad).
/// `false` says nothing: [`nothing_to_repair`] then decides.
fn checked_clean(st: &QuadStats, mesh: &QuadMesh) -> bool {
    let Some(checked) = &st.checked else {
        return false;
    };
    let report = checked.of(mesh.positions.len(), &mesh.cells);
    st.unmatched_sides == 0
        && report.is_some_and(|r| {
            r.non_manifold_edges.is_empty()
                && r.degenerate_faces.is_empty()
                && r.out_of_range_faces.is_empty()
        })
}

/// [`nothing_to_repair`] from the slots, as step 10a finds it.
#[cfg(test)]
fn nothing_by_slots(
    graph: &NodeGraph<2>,
    glued: &Glued<2>,
    ends: &[End<2>],
    topo: &Topology<3>,
    mesh: &QuadMesh,
) -> bool {
    let slots = slots::cell_slots(graph, glued);
    let holes = slots::hole_slots(graph, glued, &slots, ends, topo.boundary_facets == 0);
    let marks = ambiguous::marks(&mesh.cells, &slots.partner);
    nothing_to_repair(&marks, &holes, mesh)
}

/// Whether step 10 would leave the mesh as it is: nothing to split, no
/// hole, every cell a proper quad (the repair's own test, on the cells
/// before they are made polygons), so the split and the repair need not
/// be built.
fn nothing_to_repair(marks: &ambiguous::Marks, holes: &[ambiguous::Slot], mesh: &QuadMesh) -> bool {
    marks.is_empty() && holes.is_empty() && mesh.cells.iter().all(|c| repair::proper_quad(c))
}

/// Step 10c's deletion of the pieces beside the surface (module docs).
fn drop_pockets(topo: &Topology<3>, out: &mut Placed<2, 4>, st: &mut QuadStats) {
    if let Some((kept, deleted)) = bubbles::drop_mesh_bubbles(&out.mesh, topo, &out.sources) {
        st.bubbles_removed += deleted;
        let cells = kept.iter().map(|&c| out.mesh.cells[c as usize]).collect();
        let pruned = QuadMesh {
            positions: out.mesh.positions.clone(),
            cells,
        };
        out.remake(pruned, &kept);
        out.mesh = std::mem::take(&mut out.mesh).without_unused_vertices();
    }
}

/// Unmatched sides whose two corners are the same vertex (a loop of one
/// side: the collapsed edge of a triangle, see [`crate::repair`]).
fn collapsed_unmatched_sides(graph: &NodeGraph<2>, glued: &Glued<2>) -> usize {
    let mut n = 0;
    for (node, _) in glued.cells() {
        for d in 0..4 {
            if graph.opposite(graph.side(node, d)).is_some() {
                continue;
            }
            let (axis, bit) = (d >> 1, if d & 1 == 0 { 1 } else { 0 });
            let codes: Vec<usize> = (0..4).filter(|c| (c >> axis) & 1 == bit).collect();
            if glued.vertex(node, codes[0]) == glued.vertex(node, codes[1]) {
                n += 1;
            }
        }
    }
    n
}
