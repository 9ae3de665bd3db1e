//! # dualex-map — the input map model
//!
//! Step 1 of the pipeline: a triangle mesh with a 2D map or a tet mesh with
//! a 3D map, its adjacency, the transitions between the charts of adjacent
//! simplices, singularities and reverted simplices.
//!
//! - [`rotation`]: the grid rotation groups (4 in 2D, 24 in 3D);
//! - [`mesh`]: [`TriMap`] / [`TetMap`], the raw input;
//! - [`topology`]: facet adjacency, boundary, manifoldness, orientation;
//! - [`transition`]: per-facet rotation and integer translation;
//! - [`star`]: vertex stars with rotations; singular vertices;
//! - [`holonomy`]: rotation around a vertex (2D) or an edge (3D);
//! - [`singularity`]: singular vertices (2D) and edges (3D), their indices;
//! - [`grid_offset`]: the dual grid's offset (½ or 0), chosen from the
//!   singular vertices;
//! - [`weld`]: welding of cut meshes (vertices duplicated along seams);
//! - [`report`]: `inspect`, all of the above in one report.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bad_scan;
pub mod cells;
pub mod cluster;
mod components;
pub mod corners;
pub mod error;
pub mod grid;
pub mod grid_offset;
pub mod holonomy;
pub mod local;
pub mod mesh;
pub mod par;
pub mod report;
// rotation.rs is owned elsewhere; its index loops read clearer than iterators
pub mod rng;
#[allow(clippy::needless_range_loop)]
pub mod rotation;
pub mod sanitize_report;
pub mod singular_snap;
pub mod singularity;
pub mod split;
pub mod star;
mod star_build;
pub mod timing;
pub mod topology;
mod topology_build;
pub mod transition;
mod transition_derive;
mod transition_fit;
pub mod weld;

#[cfg(test)]
mod data_tests;
#[cfg(test)]
mod test_maps;

pub use cells::{CellMesh, HexMesh, QuadMesh};
pub use error::InputError;
pub use mesh::{SimplexMap, TetMap, TriMap};
pub use report::{inspect, InspectOptions, MapReport};
pub use rotation::{Rot, Rot2, Rot3};
pub use star::{StarEntry, Stars};
pub use topology::{Topology, NONE};
pub use transition::{TransitionOptions, TransitionReport, Transitions};
