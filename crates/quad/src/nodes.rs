//! Step 3: nodes — the dimension-generic [`dualex_segment::nodes`] at
//! D = 2: the integer points strictly inside each triangle.

pub use dualex_segment::nodes::{check_size, MAX_GRID_POINTS};

/// The nodes of the triangles.
pub type Nodes = dualex_segment::nodes::Nodes<3, 2>;
