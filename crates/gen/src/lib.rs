//! # dualex-gen — generators of test maps (valid and messy)
//!
//! Deterministic (seeded by a built-in splitmix64) generators of triangle
//! meshes with a 2D map ([`dualex_map::TriMap`]), each returned with the
//! [`Expected`] quad mesh when known, and a registry ([`by_name`],
//! [`names`]) for the CLI and the end-to-end tests.
//!
//! Every map passes [`dualex_map::SimplexMap::validate`] and is exactly grid preserving by
//! construction (rotations are signed permutations, translations integers,
//! applied to per-vertex values).
//!
//! - [`square`]: identity, fold, white noise, collapsed interior,
//!   half-rotated + noise;
//! - [`closed`]: cube surface and torus (with folds and noise);
//! - [`disk`]: a cone singularity of index k/4 at the centre of a disk,
//!   optionally under a fold; two singularities on one grid point
//!   (invalid quantization); a chart with two boundaries (multi-boundary);
//! - [`block`]: 3D tet maps of a box (identity, noise, fold, half-rotated,
//!   degenerate) with [`block::ExpectedHex`];
//! - [`prism`]: extrusion of 2D maps into tet maps; a singular edge;
//! - [`from_mesh`]: any quad / hex mesh as a map (one chart per element),
//!   refined, with exactly-GP noise, folds, slivers and non-exact jitter:
//!   exact oracles for extraction;
//! - [`registry`]: names → generators with default parameters.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod block;
mod build;
pub mod closed;
pub mod disk;
pub mod expected;
pub mod from_mesh;
pub mod prism;
pub mod registry;
pub mod rng;
pub mod square;
#[cfg(test)]
mod testing;

pub use build::Diagonal;
pub use closed::{cube_surface, torus, Perturb};
pub use disk::{invalid_quantization, multi_boundary, singular_disk};
pub use expected::Expected;
pub use registry::{by_name, by_name_3d, names, names_3d};
pub use square::{
    square_collapsed, square_fold, square_half_rotated, square_identity, square_noise,
};
