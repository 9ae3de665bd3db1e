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
/// from outside a hex of positive volume.
pub const HEX_FACES: [[usize; 4]; 6] = [
    [0, 3, 2, 1],
    [4, 5, 6, 7],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
];

/// The 12 edges of a hex (corner order above).
pub const HEX_EDGES: [[usize; 2]; 12] = [
    [0, 1],
    [1, 2],
    [2, 3],
    [3, 0],
    [4, 5],
    [5, 6],
    [6, 7],
    [7, 4],
    [0, 4],
    [1, 5],
    [2, 6],
    [3, 7],
];

/// A mesh whose cells all have `K` vertices (4: quads, 8: hexes).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct CellMesh<const K: usize> {
    /// Vertex positions.
    pub positions: Vec<[f64; 3]>,
    /// Cells, as vertex indices in the order of the module docs.
    pub cells: Vec<[u32; K]>,
}

/// An all-quad surface mesh.
pub type QuadMesh = CellMesh<4>;
/// An all-hex volume mesh.
pub type HexMesh = CellMesh<8>;
