//! # dualex-check — independent validity checkers for quad and hex meshes
//!
//! Input: plain slices (vertex count, cells as vertex indices); no dependency
//! on the other dualex crates, so a bug there cannot hide here.
//! Output: a report of counts (faces, edges, boundary, components, Euler
//! characteristic, valences) and of defects (degenerate cells, non-manifold
//! edges/faces/vertices, inconsistent orientation), with `is_valid()` and
//! `errors()`.
//!
//! - [`quad`]: [`check_quad_mesh`] → [`QuadReport`];
//! - [`hex`]: [`check_hex_mesh`] → [`HexReport`] (its boundary surface is
//!   checked as a quad mesh);
//! - [`topology`]: the output's topology against the input's (components,
//!   Euler characteristic, boundary components);
//! - [`glued`]: the input's shape read off the facet adjacency of a map
//!   its extraction accepted (the same as [`topology`]'s);
//! - [`handover`]: a report kept with a print of its mesh ([`Checked`]),
//!   read again instead of checking the same mesh twice.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod classify;
pub mod glued;
#[cfg(test)]
mod glued_tests;
pub mod handover;
pub mod hex;
pub mod quad;
mod tally;
#[cfg(test)]
mod test_meshes;
pub mod topology;

pub use handover::Checked;
pub use hex::{check_hex_mesh, HexReport};
pub use quad::{check_quad_mesh, QuadReport};
