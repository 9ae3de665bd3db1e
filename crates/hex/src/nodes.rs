//! Step 3: nodes — the dimension-generic [`dualex_segment::nodes`] at
//! D = 3: the integer points strictly inside each tet.

pub use dualex_segment::nodes::{check_size, MAX_GRID_POINTS};

/// The nodes of the tets.
pub type Nodes = dualex_segment::nodes::Nodes<4, 3>;
