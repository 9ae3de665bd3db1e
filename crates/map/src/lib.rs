//! # dualex-map — the input map model
//!
//! Step 1 of the pipeline: a triangle mesh with a 2D map or a tet mesh with
//! a 3D map, its adjacency, the transitions between the charts of adjacent
//! simplices, singularities and reverted simplices. This crate holds the
//! model only: the segmentation steps that read it live in
//! `dualex-segment`, the output meshes in `dualex-cells`, the shared
//! utilities in `dualex-util`.
//!
//! Input: vertex positions, simplices and per-corner map coordinates (from
//! `dualex-io` or slices). Output: the derived structures below, each built
//! once and read-only afterwards. Invariants: a map that passes
//! [`SimplexMap::validate`] and [`Topology::build`] is manifold and
//! consistently oriented; its [`Transitions`] satisfy
//! `chart(n) = rot · chart(s) + trans` on every interior facet within the
//! GP residual; errors caused by the input are [`InputError`]s, never
//! panics.
//!
//! - [`rotation`]: the grid rotation groups (4 in 2D, 24 in 3D);
//! - [`mesh`]: [`TriMap`] / [`TetMap`], the raw input, and its validation;
//!   `reflect` (private): the refusal of reflected 3D charts;
//! - [`scan`]: step 1's input checks (validation, size, reflected charts)
//!   and counts in one walk;
//! - [`error`]: [`InputError`], the errors caused by the input: what is
//!   wrong as a typed [`InputErrorKind`] naming the [`Element`] (vertex,
//!   triangle, tet, face, …, and its index), the file and the [`Location`];
//! - [`topology`]: facet adjacency, boundary, manifoldness, orientation
//!   (built by `topology_build`, private);
//! - `components` (private): connected components and boundary loops of a
//!   built topology;
//! - [`transition`]: per-facet rotation and integer translation (derived
//!   by `transition_derive`, one facet fitted by `transition_fit`, or by
//!   `transition_same` when its corners are equal in both charts, the fits
//!   counted by `transition_tally`; or each fitted where the topology
//!   glues its pair, by `transition_glue`; all private);
//! - [`star`]: vertex stars with rotations; singular vertices (built by
//!   `star_build`, private);
//! - [`holonomy`]: rotation around a vertex (2D) or an edge (3D);
//! - [`singularity`]: singular vertices (2D) and edges (3D), their indices;
//!   reverted and degenerate simplices;
//! - [`weld`]: welding of cut meshes (vertices duplicated along seams);
//! - [`report`]: `inspect`, all of the above in one report;
//! - `test_maps` (tests, and the `test-maps` feature for the tests of the
//!   crates above): small generated maps and tiny readers of the shared
//!   data;
//! - `data_tests` (tests): reverted counts, welding and broken files of the
//!   shared real data.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod angle_sum;
mod components;
pub mod corners;
pub mod error;
mod facet_order;
pub mod holonomy;
pub mod mesh;
mod reflect;
pub mod report;
// rotation.rs is owned elsewhere; its index loops read clearer than iterators
#[allow(clippy::needless_range_loop)]
pub mod rotation;
pub mod scan;
mod shared_key;
pub mod singularity;
pub mod star;
mod star_build;
mod star_fan;
pub mod topology;
mod topology_build;
pub mod transition;
mod transition_derive;
mod transition_fit;
mod transition_glue;
mod transition_same;
mod transition_tally;
pub mod weld;

#[cfg(test)]
mod data_tests;
#[cfg(any(test, feature = "test-maps"))]
#[doc(hidden)]
pub mod test_maps;

pub use error::{Element, ElementKind, InputError, InputErrorKind, Location};
pub use mesh::{SimplexMap, TetMap, TriMap};
pub use report::{inspect, InspectOptions, MapReport};
pub use rotation::{Rot, Rot2, Rot3};
pub use scan::InputCounts;
pub use star::{StarEntry, Stars};
pub use topology::{Topology, NONE};
pub use transition::{TransitionOptions, TransitionReport, Transitions};
