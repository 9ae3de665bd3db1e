//! # dualex-cells — the output meshes
//!
//! The last step's result, shared by everything after the extraction: the
//! all-quad and all-hex meshes ([`QuadMesh`], [`HexMesh`], one generic
//! [`CellMesh`]) with their corner order and hex tables, and the map
//! coordinates of each cell's corners ([`corners`]).
//!
//! Why a crate of its own: the writers (`dualex-io`), the geometric stage
//! (`dualex-geom`), the pictures (`dualex-render`) and the test generator
//! (`dualex-gen`) need the output mesh type but not the map model or the
//! segmentation; the map model (`dualex-map`) should not hold the output;
//! and the segmentation (`dualex-segment`) is too heavy for a writer. The
//! crate has no dependency. The checker (`dualex-check`) keeps its own
//! plain-slice interface and tables on purpose (a bug here cannot hide
//! there). The one function of the corners that reads the segmentation's
//! local charts, `node_corner`, lives with them in `dualex_segment::local`.
//!
//! Input: vertex positions and cells as vertex indices. Output: the same,
//! typed. Invariants: cells list their corners in the order drawn in
//! [`cells`]; indices are below the number of positions.
//!
//! - [`cells`]: [`CellMesh`], [`QuadMesh`], [`HexMesh`], the corner order,
//!   [`cells::HEX_FACES`] and [`cells::HEX_EDGES`];
//! - [`corners`]: per-cell corner coordinates ([`corners::Corners`]) and
//!   their carrying through steps that remake cells ([`corners::carry`]);
//! - [`polygons`]: cells as polygons (repeated corners dropped) and the
//!   holes of a glued mesh as polygons;
//! - [`repair_local`]: the local repair of the faces quads cannot
//!   represent (odd faces paired by paths of quads), run by quad's step 10
//!   and replayed by hex's columns on every layer: it lives here, with
//!   the mesh it edits, so that hex does not depend on quad.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod cells;
pub mod corners;
pub mod polygons;
pub mod repair_local;

pub use cells::{CellMesh, HexMesh, QuadMesh};
