//! # dualex-segment — the dual segmentation's shared steps
//!
//! Steps 2–7 of the pipeline (ARCHITECTURE.md), and step 1's model and
//! step 9's placement, the part both extractions share: from the map
//! model (`dualex-map`) to a map whose vertices are off the dual grid,
//! its nodes, their traced sides linked into the node graph
//! (`dualex-graph`), and the diagonal walks that place the vertices, for
//! `dualex-quad` and `dualex-hex`. Every module is generic over the
//! dimension (`N` corners per simplex, `D` map dimension); the few
//! predicates that differ sit in one `impl` block per dimension on one
//! marker, [`simplex::Dim`] (fidget's way: [`simplex`], [`diagonal`],
//! [`sanitize`], [`split`]). [`steps`] runs them as the numbered steps
//! both drivers call:
//!
//! 1. the map model ([`steps::check`], [`steps::model`]);
//! 2. the local map, built once with the grid offset chosen, singular
//!    vertices snapped ([`grid_offset::local_map`]);
//! 3. the faces that vertices which cannot move span across the grid,
//!    split ([`split`]; steps 1–3 repeated by [`steps::prepare`]);
//! 4. sanitization ([`steps::sanitize`], [`sanitize`]);
//! 5. the nodes ([`steps::nodes`], [`nodes`]);
//! 6. the walk of every node side ([`steps::trace`], [`trace`]);
//! 7. the opposite relation ([`steps::link`]; untangling: the drivers,
//!    by `dualex-graph`);
//!
//! 9c. (after the graph's steps 8–9) the cells placed by the diagonal
//! walks, with their source simplices and corners ([`place`]).
//!
//! Input: a map, the transition options, the grid offset and the seed.
//! Output: the (split) map, local charts, nodes, walk ends, the linked
//! graph, the placed cells, and the shared half of the stats
//! ([`stats::SegmentStats`]). Invariants: local coordinates stay small
//! (exact integer offsets), transitions between local charts are
//! integral, and every step is deterministic whatever the number of
//! threads.
//!
//! - [`steps`]: steps 1–7, one function each, generic over the dimension
//!   ([`steps::Dimension`]: what a dimension implements);
//! - [`stats`]: the counts of steps 1–7 and their JSON keys;
//! - [`grid_offset`]: the dual grid's offset (½ or 0), chosen from the
//!   singular vertices once, and the local map built with it
//!   ([`grid_offset::local_map`], step 2);
//! - [`local`]: local shifted coordinates ([`local::LocalMap`]) and the
//!   input-chart coordinates of an output cell's corners
//!   ([`local::node_corner`]);
//! - [`grid`]: closeness to the integer grid (values on an iso, segments
//!   through a grid point);
//! - [`singular_snap`]: exact placement of singular vertices on the fixed
//!   sets of their holonomies;
//! - [`split`]: the barycentric split of faces of any dimension, and what
//!   each dimension splits ([`split::ToSplit`]);
//! - [`cluster`]: collapsed clusters (vertices joined by zero-length map
//!   edges), moved as one by sanitization;
//! - [`bad_scan`]: the incremental bad-vertex scan of sanitization;
//! - [`boxes`]: the integer boxes of a simplex's corners, the scan's
//!   prefilters;
//! - [`contact`]: a segment certainly through a grid point, at neither
//!   end (the scan's shortcut for edges through the grid);
//! - [`near`]: closeness of a tet's vertices, edges and faces to the dual
//!   grid (D = 3; D = 2 in [`grid`]);
//! - [`sanitize`]: one sanitization for both dimensions (snap, then rounds
//!   of perturbation), its per-dimension predicates at `Dim<3, 2>` and
//!   `Dim<4, 3>`;
//! - [`relax`]: the drivers' retry on a folded map whose graph path
//!   failed: the local map relaxed in its fold regions (issue 22);
//! - [`sanitize_report`]: what sanitization did, its perturbation
//!   schedule, and the JSON helpers of the extraction stats;
//! - [`simplex`]: the per-dimension predicates (barycentric weights,
//!   facets pierced by an axis line, one step of the diagonal walk);
//! - [`nodes`]: the integer points strictly inside the simplices;
//! - [`trace`]: the walk of every node side along its iso-line;
//! - [`diagonal`]: the walk along a node diagonal that places a vertex;
//! - [`place`]: the glued cells placed, their sources and corners.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bad_scan;
pub mod boxes;
pub mod cluster;
pub mod contact;
pub mod diagonal;
pub mod grid;
pub mod grid_offset;
pub mod local;
pub mod near;
pub mod nodes;
pub mod place;
pub mod relax;
pub mod sanitize;
pub mod sanitize_report;
pub mod scatter;
pub mod simplex;
pub mod singular_snap;
pub mod split;
pub mod stats;
pub mod steps;
#[cfg(test)]
mod testmap;
pub mod trace;
