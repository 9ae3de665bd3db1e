//! # dualex-geom — usable geometry for extracted meshes
//!
//! The geometric stage after gluing, one piece of code for quads (D = 2)
//! and hexes (D = 3). It moves vertex positions and never changes the
//! combinatorics.
//!
//! 1. [`quality`]: the scaled Jacobian of every element (verdict's
//!    definitions; a quad's against the normal of the input surface under
//!    it) and its [`Summary`]: inverted, degenerate, min, 5th percentile,
//!    median — before and after the stage.
//! 2. [`reference`]: what the vertices stay on: the input surface (quads)
//!    or the input volume's boundary surface (hexes), its boundary and
//!    feature curves and their corners; [`constraint`]: each vertex's set.
//! 3. Boundary on the boundary: output boundary vertices off the input's
//!    boundary (farther than 1e-9 of the bounding box) are projected onto
//!    it (2D: its boundary curves; 3D: its boundary surface).
//! 4. [`optimize`]: the untangling functional of Garanzha et al. (2021,
//!    [`energy`]) on the corner simplices (a quad's 4 corner triangles in
//!    its tangent plane, a hex's 8 corner tets), minimised by [`lbfgs`] in
//!    each vertex's tangent basis, then projected back onto its set.
//!
//! [`Mode::Auto`] (the default) moves only the vertices within a few rings
//! of inverted elements and of boundary vertices it projected, growing the
//! rings while inverted elements remain; a mesh with neither is returned
//! untouched (bit for bit). [`Mode::Smooth`] optimises the whole mesh.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

pub mod bvh;
pub mod constraint;
pub mod energy;
pub mod lbfgs;
pub mod optimize;
pub mod quality;
pub mod reference;
pub mod stage;
#[cfg(test)]
mod tests;

pub use quality::Summary;
pub use reference::Reference;
pub use stage::{hexes, quads, Report};

/// What the stage does.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    /// Keep the map's positions (measure only).
    Off,
    /// Boundary vertices onto the boundary; untangle near inverted
    /// elements only.
    Auto,
    /// Optimise the shape of every element, in at most this many rounds.
    Smooth(usize),
}

impl Mode {
    /// Its name in the stats.
    pub fn name(self) -> &'static str {
        match self {
            Mode::Off => "off",
            Mode::Auto => "auto",
            Mode::Smooth(_) => "smooth",
        }
    }
}

/// Rounds of [`Mode::Smooth`] when none are given.
pub const SMOOTH_ROUNDS: usize = 10;

/// Options of the stage.
#[derive(Clone, Copy, Debug)]
pub struct Options {
    /// What to do. Default: [`Mode::Auto`].
    pub mode: Mode,
    /// Put output boundary vertices on the input's boundary. Default: on.
    pub boundary: bool,
    /// Edges of the reference whose faces' normals differ by more than
    /// this many degrees are feature curves. Default: 60 (a coarse smooth
    /// surface has edges of 35° and more that are no features).
    pub feature_angle: f64,
}

impl Default for Options {
    fn default() -> Self {
        Options {
            mode: Mode::Auto,
            boundary: true,
            feature_angle: 60.0,
        }
    }
}
