//! Output meshes: all-quad and all-hex meshes.
//!
//! Corner order of a cell:
//! ```text
//!   quad: counter-clockwise seen from the outside (front side)
//!        3 --- 2
//!        |     |
//!        0 --- 1
//!   hex (VTK_HEXAHEDRON / MEDIT order): bottom face 0-1-2-3, then the top
//!   face 4-5-6-7 with i+4 above i; 0-1-2-3 counter-clockwise seen from the
//!   top, so that the hex has positive volume.
//!        7 --- 6
//!       /|    /|
//!      4 --- 5 |
//!      | 3 --|-2
//!      |/    |/
//!      0 --- 1
//! ```

/// The 6 faces of a hex (corner order above), each counter-clockwise seen
/// from outside a hex of positive volume, and its 12 edges: the checker's
/// tables (one copy; the checker depends on no crate it checks).
pub use dualex_check::hex::{HEX_EDGES, HEX_FACES};

/// A mesh whose cells all have `K` vertices (4: quads, 8: hexes).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CellMesh<const K: usize> {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Cells, as vertex indices in the order of the module docs.
    pub cells: Vec<[u32; K]>,
}

impl<const K: usize> CellMesh<K> {
    /// The mesh without the vertices no cell uses: vertices renumbered in
    /// the order the cells first use them, cells kept as they are.
    pub fn without_unused_vertices(self) -> Self {
        let mut new_id = vec![u32::MAX; self.positions.len()];
        let mut positions = Vec::with_capacity(self.positions.len());
        let mut cells = self.cells;
        for v in cells.iter_mut().flatten() {
            let id = &mut new_id[*v as usize];
            if *id == u32::MAX {
                *id = positions.len() as u32;
                positions.push(self.positions[*v as usize]);
            }
            *v = *id;
        }
        CellMesh { positions, cells }
    }
}

/// An all-quad surface mesh.
pub type QuadMesh = CellMesh<4>;
/// An all-hex volume mesh.
pub type HexMesh = CellMesh<8>;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn unused_vertices_go_and_positions_follow_their_cells() {
        let p = |x: f64| [x, 0.0, 0.0];
        let mesh = QuadMesh {
            positions: (0..7).map(|i| p(i as f64)).collect(),
            cells: vec![[5, 1, 6, 3]],
        };
        let out = mesh.without_unused_vertices();
        assert_eq!(out.cells, vec![[0, 1, 2, 3]]);
        assert_eq!(out.positions, vec![p(5.0), p(1.0), p(6.0), p(3.0)]);
    }
}
