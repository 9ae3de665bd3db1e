//! # dualex-remesh — a grid-preserving map for a plain triangle surface
//!
//! The cheap pipeline real tools use, as the paper's evaluation did
//! ("field integration as geometric objective and rounding as
//! quantization"):
//!
//! | step | module | input → output |
//! |---|---|---|
//! | connectivity, face frames | [`surface`] | positions, triangles → [`Surface`] |
//! | smoothest 4-RoSy field | `field` | [`Surface`] → `CrossField` (angle per face, matching per edge, singularities) |
//! | cut to a disk | `cut` | field → cut edges through every singularity |
//! | seamless integration | [`integrate`](mod@integrate) | field + cut → per-corner `(u, v)` |
//! | direct rounding | [`quantize`] | integer unknowns rounded at once, one more solve |
//!
//! [`sparse`] holds the sparse SPD solves (faer's Cholesky) the field and
//! the integration use.
//!
//! The output is a [`dualex_map::TriMap`] that `dualex quad` extracts.
//!
//! Invariants: [`Surface`] is an oriented 2-manifold (with or without
//! boundary) without degenerate triangles; every edge has one or two faces.
#![forbid(unsafe_code)]

pub mod field;
pub mod integrate;
pub mod quantize;
pub mod sparse;
pub mod surface;
pub mod weld;

pub use field::CrossField;
pub use integrate::{integrate, integrate_report, IntegrateOptions, IntegrateReport};
pub use quantize::Rounding;
pub use surface::{Surface, SurfaceError, NO_FACE};
