//! # dualex-segment — the dual segmentation's shared steps
//!
//! Step 2 of the pipeline, the part both extractions share: from the map
//! model (`dualex-map`) to a map whose vertices are off the dual grid,
//! its nodes, their traced sides and the diagonal walks that place the
//! vertices, for `dualex-quad` and `dualex-hex`. Every module is generic
//! over the dimension (`N` corners per simplex, `D` map dimension); the
//! few predicates that differ sit in one `impl` block per dimension
//! ([`simplex`]). This is the crate where the quad and hex twins become
//! one code over `const D` (issue 24).
//! The sanitization ([`sanitize`]) is one code too.
//!
//! Input: a validated map, its topology, transitions and stars. Output:
//! local charts, the grid offset, snapped singular vertices, split faces,
//! collapsed clusters, the incremental bad-vertex scan, the
//! sanitization report, the nodes, the ends of their traced sides and
//! the vertices' candidate positions. Invariants: local coordinates stay small (exact
//! integer offsets), transitions between local charts are integral, and
//! every step is deterministic whatever the number of threads.
//!
//! - [`grid_offset`]: the dual grid's offset (½ or 0), chosen from the
//!   singular vertices once, and the local map built with it
//!   ([`grid_offset::local_map`], the step both drivers call);
//! - [`local`]: local shifted coordinates ([`local::LocalMap`]) and the
//!   input-chart coordinates of an output cell's corners
//!   ([`local::node_corner`]);
//! - [`grid`]: closeness to the integer grid (values on an iso, segments
//!   through a grid point);
//! - [`singular_snap`]: exact placement of singular vertices on the fixed
//!   sets of their holonomies;
//! - [`split`]: the barycentric split of faces of any dimension;
//! - [`cluster`]: collapsed clusters (vertices joined by zero-length map
//!   edges), moved as one by sanitization;
//! - [`bad_scan`]: the incremental bad-vertex scan of sanitization;
//! - [`near`]: closeness of a tet's vertices, edges and faces to the dual
//!   grid (D = 3; D = 2 in [`grid`]);
//! - [`sanitize`]: one sanitization for both dimensions (snap, then rounds
//!   of perturbation), its per-dimension predicates at `Dim<3, 2>` and
//!   `Dim<4, 3>`;
//! - [`sanitize_report`]: what sanitization did, its perturbation
//!   schedule, and the JSON helpers of the extraction stats;
//! - [`simplex`]: the per-dimension predicates (barycentric weights,
//!   facets pierced by an axis line, one step of the diagonal walk);
//! - [`nodes`]: the integer points strictly inside the simplices;
//! - [`trace`]: the walk of every node side along its iso-line;
//! - [`diagonal`]: the walk along a node diagonal that places a vertex.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bad_scan;
pub mod cluster;
pub mod diagonal;
pub mod grid;
pub mod grid_offset;
pub mod local;
pub mod near;
pub mod nodes;
pub mod sanitize;
pub mod sanitize_report;
pub mod simplex;
pub mod singular_snap;
pub mod split;
#[cfg(test)]
mod testmap;
pub mod trace;
