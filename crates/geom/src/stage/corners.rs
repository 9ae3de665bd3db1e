//! The corners of the mesh on the input's boundary (step 3 of the
//! stage): a boundary vertex of one cell goes onto a convex corner of the
//! input's curves when one is near; where it is not, the cell would be flat
//! or inverted with all its boundary vertices on a smooth or concave
//! boundary, and its neighbours are released instead.
//!
//! Input: positions, the stage's [`Input`], the reference, the cells
//! around each vertex, the constraints. Output: positions and constraints
//! changed in place; counts.

use super::topology::boundary_edges;
use super::{Input, Report, FLAT, MESH_CORNER_ANGLE};
use crate::constraint::{Constraints, Kind, Role};
use crate::quality::{self, norm, sub};
use crate::reference::Reference;
use rayon::prelude::*;

/// Step 3: every boundary vertex onto the input's boundary (to 1e-9 of
/// the bounding box; a vertex fixed at a corner of the curves exactly
/// there), the mesh's corners first onto the input's corners, then the
/// neighbours of cells that would be flat released; `start`: the
/// positions before. Records the distances and counts in `rep`.
#[allow(clippy::too_many_arguments, clippy::needless_range_loop)] // vertices index several arrays
pub(super) fn onto_boundary<const D: usize, const K: usize>(
    x: &mut [[f64; 3]],
    input: &Input<D, K>,
    r: &Reference,
    around: &(Vec<usize>, Vec<u32>),
    cons: &mut Constraints,
    start: &[[f64; 3]],
    tol: f64,
    rep: &mut Report,
) {
    let exact = 1e-9 * r.diagonal;
    mesh_corners_to_input_corners(x, input, r, around, cons, rep.mean_edge);
    bind_to_arcs(x, input, r, cons, tol.max(1e-9 * r.diagonal));
    // the boundary vertices' targets found in parallel (each query reads
    // only its own vertex's position and foot cache), applied in order;
    // arrays as long as the boundary only (the stage holds the peak)
    let boundary: Vec<usize> = (0..x.len()).filter(|&v| input.on_boundary[v]).collect();
    let onto: Vec<[f64; 3]> = {
        let cons = &*cons;
        let target = |v: usize| match cons.kind[v] {
            // a vertex fixed at a corner of the curves: exactly there
            Kind::Fixed => r.nearest_corner(x[v], tol, f64::INFINITY).unwrap_or(x[v]),
            _ => cons.project(r, v, x[v]),
        };
        boundary.par_iter().map(|&v| target(v)).collect()
    };
    for (&v, q) in boundary.iter().zip(onto) {
        let d = norm(sub(q, x[v]));
        rep.boundary_distance[0] = rep.boundary_distance[0].max(d);
        if d > exact {
            x[v] = q;
        }
    }
    rep.boundary_released = release_flat_corners(x, start, input, around, cons);
    // those on the boundary now that were not
    rep.boundary_off = (0..x.len())
        .filter(|&v| input.on_boundary[v] && x[v] != start[v])
        .count();
}

/// The corners of the mesh (boundary vertices of one cell) go onto a
/// corner of the input's curves within half an edge (on a surface: one
/// whose interior angle is at most [`MESH_CORNER_ANGLE`]) and become
/// fixed there.
#[allow(clippy::needless_range_loop)]
pub(super) fn mesh_corners_to_input_corners<const D: usize, const K: usize>(
    x: &mut [[f64; 3]],
    input: &Input<D, K>,
    r: &Reference,
    around: &(Vec<usize>, Vec<u32>),
    cons: &mut Constraints,
    mean_edge: f64,
) {
    let max_angle = match input.role {
        Role::Surface => MESH_CORNER_ANGLE.to_radians(),
        Role::Volume => f64::INFINITY,
    };
    for v in 0..x.len() {
        if !input.on_boundary[v]
            || around.0[v + 1] - around.0[v] != 1
            || cons.kind[v] == Kind::Fixed
        {
            continue;
        }
        let q = cons.project(r, v, x[v]);
        if let Some(c) = r.nearest_corner(q, 0.5 * mean_edge, max_angle) {
            x[v] = c;
            cons.kind[v] = Kind::Fixed;
        }
    }
}

/// A corner of the mesh on a smooth or concave part of the input's
/// boundary, its cell's neighbours on the boundary too, leaves that cell
/// flat or inverted there (value ≤ [`FLAT`]): those neighbours go back
/// where the map put them (`start`) and are released from the boundary
/// (free on the surface or in the volume). The count released.
pub(super) fn release_flat_corners<const D: usize, const K: usize>(
    x: &mut [[f64; 3]],
    start: &[[f64; 3]],
    input: &Input<D, K>,
    around: &(Vec<usize>, Vec<u32>),
    cons: &mut Constraints,
) -> usize {
    let free = match input.role {
        Role::Surface => Kind::Surface,
        Role::Volume => Kind::Free,
    };
    let mut released = 0;
    for v in 0..x.len() {
        if !input.on_boundary[v] || around.0[v + 1] - around.0[v] != 1 {
            continue;
        }
        let ci = around.1[around.0[v]] as usize;
        let cell = &input.cells[ci];
        if corner_value(x, input, ci, v) > FLAT {
            continue;
        }
        for e in input.edges {
            let (a, b) = (cell[e[0]] as usize, cell[e[1]] as usize);
            for (u, w) in [(a, b), (b, a)] {
                // (a vertex bound to its arc has its place: `bind_to_arcs`)
                if u == v
                    && input.on_boundary[w]
                    && cons.kind[w] != Kind::Fixed
                    && cons.kind[w] != free
                    && cons.arc[w] == u32::MAX
                {
                    x[w] = start[w];
                    cons.kind[w] = free;
                    released += 1;
                }
            }
        }
    }
    released
}

/// The scaled Jacobian of cell `ci` at its corner on vertex `v` (in the
/// cell's frame: against its normal for a quad).
fn corner_value<const D: usize, const K: usize>(
    x: &[[f64; 3]],
    input: &Input<D, K>,
    ci: usize,
    v: usize,
) -> f64 {
    let cell = &input.cells[ci];
    let Some(k) = cell.iter().position(|&u| u as usize == v) else {
        return 1.0;
    };
    let corner = input.corners[k];
    let frame = &input.frames[ci];
    let mut j = [[0.0; D]; D];
    let mut lengths = 1.0;
    for c in 0..D {
        let e = sub(x[cell[corner[c + 1]] as usize], x[v]);
        lengths *= norm(e);
        for (r, row) in frame.iter().enumerate() {
            j[r][c] = quality::dot(*row, e);
        }
    }
    if lengths > 0.0 {
        crate::energy::det_cofactor(&j).0 / lengths
    } else {
        0.0
    }
}

/// The boundary vertices of a quad mesh between two of its corners fixed
/// at input corners `A`, `B` (next along a boundary loop) stay on the
/// input's arc from `A` to `B` when one arc joins them
/// ([`Constraints::arc`]); the nearest curve point could be on the arc
/// past a corner, where a vertex the map put beyond that corner would
/// otherwise stay, its quad folded over the corner. Returns the vertices
/// so bound. A loop with a vertex of two boundary edges out (non-manifold)
/// binds nothing.
pub(super) fn bind_to_arcs<const D: usize, const K: usize>(
    x: &[[f64; 3]],
    input: &Input<D, K>,
    r: &Reference,
    cons: &mut Constraints,
    tol: f64,
) -> usize {
    if input.role != Role::Surface {
        return 0;
    }
    let mut next = vec![u32::MAX; x.len()];
    for [a, b] in boundary_edges(input.cells, input.edges) {
        if next[a as usize] != u32::MAX {
            return 0;
        }
        next[a as usize] = b;
    }
    let mut bound = 0;
    let mut seen = vec![false; x.len()];
    for start in 0..x.len() {
        if next[start] == u32::MAX || seen[start] {
            continue;
        }
        let mut lp = Vec::new();
        let mut v = start;
        while !seen[v] && next[v] != u32::MAX {
            seen[v] = true;
            lp.push(v);
            v = next[v] as usize;
        }
        // the loop's vertices at input corners, with those corners
        let at: Vec<(usize, u32)> = lp
            .iter()
            .enumerate()
            .filter(|(_, &v)| cons.kind[v] == Kind::Fixed)
            .filter_map(|(i, &v)| r.corner_at(x[v], tol).map(|c| (i, c)))
            .collect();
        if at.len() < 2 {
            continue;
        }
        for (k, &(i, a)) in at.iter().enumerate() {
            let (j, b) = at[(k + 1) % at.len()];
            let arcs_b = r.arcs_at(b);
            let common: Vec<u32> = r
                .arcs_at(a)
                .into_iter()
                .filter(|c| arcs_b.contains(c))
                .collect();
            let [arc] = common[..] else { continue };
            let mut m = (i + 1) % lp.len();
            while m != j {
                let v = lp[m];
                if matches!(cons.kind[v], Kind::Curve { boundary: true }) {
                    cons.arc[v] = arc;
                    bound += 1;
                }
                m = (m + 1) % lp.len();
            }
        }
    }
    bound
}

/// Releases the interior vertices of the `flagged` cells bound to a
/// feature curve onto the surface; the count released.
pub(super) fn release_features(
    cons: &mut Constraints,
    cells: &[impl AsRef<[u32]>],
    flagged: &[bool],
    on_boundary: &[bool],
) -> usize {
    let mut released = 0;
    for (cell, _) in cells.iter().zip(flagged).filter(|(_, &f)| f) {
        for &u in cell.as_ref() {
            let u = u as usize;
            if !on_boundary[u] && cons.kind[u] == (Kind::Curve { boundary: false }) {
                cons.kind[u] = Kind::Surface;
                released += 1;
            }
        }
    }
    released
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::reference::Reference;

    /// Only the interior vertices of the flagged cells that are bound to a
    /// feature curve are released; boundary ones, fixed ones and those of
    /// other cells keep their constraint.
    #[test]
    fn release_features_frees_only_interior_curve_vertices_of_flagged_cells() {
        // a roof: two faces meeting at a 90° ridge along x (a feature at
        // the default 60°), 4 triangle pairs per face along it, open on
        // its other sides
        let mut p = Vec::new();
        for i in 0..5 {
            let x = i as f64 * 0.5;
            p.extend([[x, -1.0, 0.0], [x, 0.0, 1.0], [x, 1.0, 0.0]]);
        }
        let mut t = Vec::new();
        for i in 0..4u32 {
            let (a, b) = (3 * i, 3 * i + 3);
            t.extend([[a, b, b + 1], [a, b + 1, a + 1]]);
            t.extend([[a + 1, b + 1, b + 2], [a + 1, b + 2, a + 2]]);
        }
        let r = Reference::surface(&p, &t, 60.0);
        // mesh vertices: 0, 1 on the ridge's interior, 2 on the slope, 3
        // on the ridge but a boundary vertex of the mesh
        let x = [
            [0.5, 0.0, 1.0],
            [1.5, 0.0, 1.0],
            [1.0, -0.5, 0.5],
            [1.0, 0.0, 1.0],
        ];
        let on_boundary = [false, false, false, true];
        let mut cons = Constraints::classify(
            &r,
            &x,
            &on_boundary,
            vec![[0.0, 0.0, 1.0]; 4],
            Role::Surface,
            1e-6,
        );
        assert_eq!(cons.kind[0], Kind::Curve { boundary: false });
        assert_eq!(cons.kind[2], Kind::Surface);
        let cells = [[0u32, 2, 3, 3], [1, 1, 1, 1]];
        let released = release_features(&mut cons, &cells, &[true, false], &on_boundary);
        assert_eq!(released, 1);
        assert_eq!(
            cons.kind[0],
            Kind::Surface,
            "interior ridge vertex of the flagged cell"
        );
        assert_eq!(
            cons.kind[1],
            Kind::Curve { boundary: false },
            "not in a flagged cell"
        );
        assert_ne!(
            cons.kind[3],
            Kind::Surface,
            "a boundary vertex keeps its curve"
        );
    }
}
