//! Vertex valence classes of a quad mesh, and their colours.
//!
//! Input: a [`QuadMesh`]. Output: one [`ValenceClass`] per vertex.
//!
//! The valence of an interior vertex is the number of quads around it (on a
//! manifold that is also its number of edges). A vertex on an edge used by
//! one quad only is on the boundary and is not classified (a boundary
//! vertex with 1, 2 or 3 quads can all be regular, depending on the domain);
//! a vertex on an edge shared by more than two quads is non-manifold and
//! classed [`ValenceClass::Other`]. A vertex used by no quad is
//! [`ValenceClass::Unused`].

use std::collections::HashMap;

use crate::error::RenderError;
use dualex_cells::QuadMesh;

/// What a vertex is coloured as.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ValenceClass {
    /// Interior, 3 quads (index +1/4).
    V3,
    /// Interior, 4 quads (regular).
    V4,
    /// Interior, 5 quads (index −1/4).
    V5,
    /// Interior with another valence, or non-manifold.
    Other,
    /// On the boundary: not classified.
    Boundary,
    /// In no quad.
    Unused,
}

impl ValenceClass {
    /// The class of an interior vertex with `n` quads around it.
    pub fn of_interior(n: usize) -> Self {
        match n {
            3 => ValenceClass::V3,
            4 => ValenceClass::V4,
            5 => ValenceClass::V5,
            _ => ValenceClass::Other,
        }
    }

    /// Colour as RGB, `None` for boundary and unused vertices (not marked).
    pub fn rgb(self) -> Option<[u8; 3]> {
        match self {
            ValenceClass::V3 => Some(V3_RGB),
            ValenceClass::V4 => Some(V4_RGB),
            ValenceClass::V5 => Some(V5_RGB),
            ValenceClass::Other => Some(OTHER_RGB),
            ValenceClass::Boundary | ValenceClass::Unused => None,
        }
    }

    /// Small code used by the HTML viewer: 3, 4, 5, 0 (other), −1 (none).
    pub fn code(self) -> i8 {
        match self {
            ValenceClass::V3 => 3,
            ValenceClass::V4 => 4,
            ValenceClass::V5 => 5,
            ValenceClass::Other => 0,
            ValenceClass::Boundary | ValenceClass::Unused => -1,
        }
    }
}

/// Valence 3: blue.
pub const V3_RGB: [u8; 3] = [0x1f, 0x66, 0xd1];
/// Valence 4: dark grey.
pub const V4_RGB: [u8; 3] = [0x4d, 0x4d, 0x4d];
/// Valence 5: red.
pub const V5_RGB: [u8; 3] = [0xd6, 0x27, 0x28];
/// Any other valence: green.
pub const OTHER_RGB: [u8; 3] = [0x2c, 0xa0, 0x2c];

/// Checks that every quad refers to existing vertices and every position
/// is finite; the error names the first offender.
pub fn check_quads(mesh: &QuadMesh) -> Result<(), RenderError> {
    check_cells(&mesh.positions, &mesh.cells, "quad")
}

/// Checks that every position is finite, then that every cell (`kind`:
/// `"quad"`, `"hex"`) refers to existing vertices; the error names the
/// first offender.
pub fn check_cells<const K: usize>(
    positions: &[[f64; 3]],
    cells: &[[u32; K]],
    kind: &'static str,
) -> Result<(), RenderError> {
    for (i, p) in positions.iter().enumerate() {
        if p.iter().any(|x| !x.is_finite()) {
            return Err(RenderError::VertexNotFinite { vertex: i });
        }
    }
    let nv = positions.len();
    for (c, cell) in cells.iter().enumerate() {
        if let Some(&v) = cell.iter().find(|&&v| v as usize >= nv) {
            return Err(RenderError::CellOutOfRange {
                kind,
                cell: c,
                vertex: v,
                vertices: nv,
            });
        }
    }
    Ok(())
}

/// The class of every vertex (see the module docs). Precondition:
/// [`check_quads`] passed (vertex ids in range); ids out of range are
/// ignored rather than panicking.
pub fn valence_classes(mesh: &QuadMesh) -> Vec<ValenceClass> {
    let nv = mesh.positions.len();
    let mut quads = vec![0usize; nv];
    let mut edges: HashMap<(u32, u32), u32> = HashMap::new();
    for cell in &mesh.cells {
        for k in 0..4 {
            let (a, b) = (cell[k], cell[(k + 1) % 4]);
            if let Some(n) = quads.get_mut(a as usize) {
                *n += 1;
            }
            *edges.entry((a.min(b), a.max(b))).or_insert(0) += 1;
        }
    }
    let mut class: Vec<ValenceClass> = quads
        .iter()
        .map(|&n| match n {
            0 => ValenceClass::Unused,
            n => ValenceClass::of_interior(n),
        })
        .collect();
    // Non-manifold first, so that boundary wins on a vertex that is both.
    for (&(a, b), &n) in &edges {
        if n > 2 {
            for v in [a, b] {
                if let Some(c) = class.get_mut(v as usize) {
                    *c = ValenceClass::Other;
                }
            }
        }
    }
    for (&(a, b), &n) in &edges {
        if n == 1 {
            for v in [a, b] {
                if let Some(c) = class.get_mut(v as usize) {
                    *c = ValenceClass::Boundary;
                }
            }
        }
    }
    class
}

/// A grid of `n × m` unit quads in the plane `z = 0`.
#[cfg(test)]
pub(crate) fn grid_quads(n: u32, m: u32) -> QuadMesh {
    let mut mesh = QuadMesh::default();
    for j in 0..=m {
        for i in 0..=n {
            mesh.positions.push([i as f64, j as f64, 0.0]);
        }
    }
    let id = |i: u32, j: u32| j * (n + 1) + i;
    for j in 0..m {
        for i in 0..n {
            mesh.cells
                .push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    mesh
}

/// The surface of the cube `[-1, 1]³` as 6 × 2 × 2 quads: 8 corners of
/// valence 3, every other vertex of valence 4, outward oriented.
#[cfg(test)]
pub(crate) fn cube_quads() -> QuadMesh {
    let mut mesh = QuadMesh::default();
    let mut ids: HashMap<[i32; 3], u32> = HashMap::new();
    let mut vid = |p: [i32; 3], mesh: &mut QuadMesh| {
        *ids.entry(p).or_insert_with(|| {
            mesh.positions.push(p.map(f64::from));
            (mesh.positions.len() - 1) as u32
        })
    };
    // face: outward axis `a`, sign `s`; (b, c) span it with b × c = s·e_a
    for a in 0..3 {
        for s in [-1, 1] {
            let (mut b, mut c) = ((a + 1) % 3, (a + 2) % 3);
            if s < 0 {
                std::mem::swap(&mut b, &mut c);
            }
            for i in 0..2 {
                for j in 0..2 {
                    let corner = |di: i32, dj: i32| {
                        let mut p = [0; 3];
                        p[a] = s;
                        p[b] = -1 + i + di;
                        p[c] = -1 + j + dj;
                        p
                    };
                    let q = [corner(0, 0), corner(1, 0), corner(1, 1), corner(0, 1)];
                    let cell = q.map(|p| vid(p, &mut mesh));
                    mesh.cells.push(cell);
                }
            }
        }
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;

    fn count(c: &[ValenceClass], k: ValenceClass) -> usize {
        c.iter().filter(|&&x| x == k).count()
    }

    #[test]
    fn grid_interior_is_regular_and_boundary_unclassified() {
        let c = valence_classes(&grid_quads(4, 3));
        assert_eq!(c.len(), 20);
        assert_eq!(count(&c, ValenceClass::V4), 3 * 2);
        assert_eq!(count(&c, ValenceClass::Boundary), 20 - 6);
    }

    #[test]
    fn cube_has_eight_valence_three_corners() {
        let mesh = cube_quads();
        assert_eq!(mesh.positions.len(), 26);
        assert_eq!(mesh.cells.len(), 24);
        let c = valence_classes(&mesh);
        assert_eq!(count(&c, ValenceClass::V3), 8);
        assert_eq!(count(&c, ValenceClass::V4), 18);
    }

    #[test]
    fn non_manifold_edge_is_other_and_unused_vertex_unused() {
        let mut mesh = grid_quads(1, 1);
        mesh.positions.push([0.0, 0.0, 1.0]);
        mesh.positions.push([1.0, 0.0, 1.0]);
        mesh.positions.push([5.0, 5.0, 5.0]);
        mesh.cells.push([0, 1, 5, 4]);
        mesh.cells.push([1, 0, 4, 5]);
        let c = valence_classes(&mesh);
        assert_eq!(c[0], ValenceClass::Boundary);
        assert_eq!(c[6], ValenceClass::Unused);
        // 4 lies in two quads only (valence 2): other
        assert_eq!(c[4], ValenceClass::Other);
    }

    #[test]
    fn check_quads_names_the_offender() {
        let mut mesh = grid_quads(1, 1);
        mesh.cells.push([0, 1, 9, 2]);
        let e = check_quads(&mesh).unwrap_err();
        assert!(
            matches!(
                e,
                RenderError::CellOutOfRange {
                    cell: 1,
                    vertex: 9,
                    ..
                }
            ),
            "{e}"
        );
        assert_eq!(
            e.to_string(),
            "quad 1 refers to vertex 9, but there are 4 vertices"
        );
        let mut mesh = grid_quads(1, 1);
        mesh.positions[2][1] = f64::NAN;
        assert_eq!(
            check_quads(&mesh).map_err(|e| e.to_string()),
            Err("vertex 2: position is not finite".into())
        );
    }

    #[test]
    fn colours_are_distinct() {
        let all = [V3_RGB, V4_RGB, V5_RGB, OTHER_RGB];
        for i in 0..4 {
            for j in 0..i {
                assert_ne!(all[i], all[j]);
            }
        }
    }
}
