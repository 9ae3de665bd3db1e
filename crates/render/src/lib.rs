//! # dualex-render — results a person can look at
//!
//! Input: an output [`QuadMesh`](dualex_cells::QuadMesh) /
//! [`HexMesh`](dualex_cells::HexMesh), or an input
//! [`TriMap`](dualex_map::TriMap). Output: a PNG file or an HTML page.
//!
//! - [`quad_png`]: the quad mesh, vertices coloured by valence
//!   ([`valence`]); planar meshes seen from above, surfaces in a fixed
//!   orthographic view with Lambert shading (painter's algorithm);
//! - [`map_png`]: a triangle map drawn in the `(u, v)` plane, reverted
//!   triangles purple, the integer grid faint, singular vertices marked;
//! - [`quality_histogram_png`]: a histogram of per-element quality (the
//!   scaled Jacobian) over [−1, 1], inverted elements red;
//! - [`view_html`] / [`view_html_hex`]: a self-contained page (own WebGL
//!   viewer, no network) to orbit and zoom the mesh; with per-element
//!   quality ([`view_html_quality`], [`view_html_hex_quality`]) the page
//!   can colour the elements by it.
//!
//! Valence colours, shared by all outputs ([`valence::ValenceClass`]):
//! valence 3 blue `#1f66d1`, 4 dark grey `#4d4d4d`, 5 red `#d62728`,
//! any other green `#2ca02c`. Boundary vertices are not classified.
//!
//! Invariant: a PNG is written to a temporary file beside the target and
//! renamed over it, so the target is either the old file or the whole new
//! one. Bad input (index out of range, non-finite coordinate, nothing to
//! draw) is an `Err(`[`RenderError`]`)` naming the element, never a panic.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

mod canvas;
mod error;
mod glyphs;
mod map_png;
mod project;
mod quad_png;
pub mod quality_png;
pub mod valence;
mod view;

#[cfg(test)]
mod gallery;
#[cfg(test)]
mod test_png;

pub use error::RenderError;
pub use map_png::{map_png, map_png_bytes, map_png_marked, MapMark};
pub use quad_png::{quad_png, quad_png_bytes};
pub use quality_png::quality_histogram_png;
pub use valence::{valence_classes, ValenceClass};
pub use view::{
    hex_boundary, view_html, view_html_hex, view_html_hex_quality, view_html_quality, Quality,
};
