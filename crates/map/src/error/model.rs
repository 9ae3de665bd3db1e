//! [`MapError`]: defects of the map itself, found by its checks
//! (validation, topology, transitions, size, reflection); [`Extrusion`]:
//! a map that cannot be extruded as asked.
//!
//! Input: the model's checks. Output: the message, naming the simplex,
//! facet or vertex and the numbers measured. Invariants: one line, the
//! checks' own wording (numbers formatted as before).

use super::{Element, ElementKind};
use crate::mesh::MAX_GRID_POINTS;
use crate::transition_derive::num;
use std::fmt;

/// A defect of the map.
#[derive(Clone, Debug, PartialEq)]
pub enum MapError {
    /// A vertex position that is not finite.
    NonFinitePosition([f64; 3]),
    /// A vertex twice in one simplex.
    RepeatedVertex {
        /// The vertex.
        vertex: u32,
    },
    /// A corner whose map coordinate is not finite.
    NonFiniteMapCoordinate {
        /// The corner.
        corner: usize,
    },
    /// A map whose images span more grid points than the limit.
    TooLarge {
        /// Grid points of the largest simplex's image.
        points: f64,
        /// Grid points of all images.
        total: f64,
    },
    /// Reverted or flat tets make up at least half the volume, some of
    /// them reverted: reflected or collapsed charts.
    Reflected {
        /// Their share of the volume, in percent.
        percent: f64,
    },
    /// A facet shared by more than two simplices.
    NonManifoldFacet {
        /// The simplex kind (the facet's is its facet).
        simplex: ElementKind,
        /// The facet's vertices, sorted.
        vertices: Vec<u32>,
        /// The simplices sharing it, sorted.
        simplices: Vec<usize>,
    },
    /// Two simplices oriented oppositely across their shared facet.
    OppositeOrientations {
        /// The simplex kind.
        simplex: ElementKind,
        /// The two simplices, the lesser first.
        simplices: [usize; 2],
        /// The facet's vertices, sorted.
        vertices: Vec<u32>,
    },
    /// A vertex whose simplices do not form one fan / one connected star.
    NonManifoldVertex {
        /// The vertex.
        vertex: usize,
        /// The simplex kind.
        simplex: ElementKind,
    },
    /// The charts of two simplices differ by a reflection or a rotation
    /// that is not a grid rotation.
    ReflectedTransition {
        /// The simplex.
        simplex: Element,
        /// Its facet.
        facet: usize,
        /// The simplex across it.
        neighbour: usize,
        /// The best fit's mismatch.
        mismatch: f64,
        /// Whether `--round-transitions` would accept it.
        round_hint: bool,
    },
    /// A transition whose translation is not integral, beyond rounding.
    NonIntegralTransition {
        /// The simplex.
        simplex: Element,
        /// Its facet.
        facet: usize,
        /// The simplex across it.
        neighbour: usize,
        /// The residual.
        residual: f64,
        /// The tolerance.
        tolerance: f64,
        /// The largest residual rounded by default.
        round_limit: f64,
    },
}

/// A map that cannot be extruded as asked.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Extrusion {
    /// `--layers 0`.
    NoLayers,
    /// A thickness that is not positive.
    Thickness(f64),
    /// A vertex whose area-weighted normal vanishes.
    VanishingNormal,
}

/// A facet's vertices as `a-b(-c)`.
fn key(vertices: &[u32]) -> String {
    let parts: Vec<String> = vertices.iter().map(|v| v.to_string()).collect();
    parts.join("-")
}

impl fmt::Display for MapError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            MapError::NonFinitePosition(p) => {
                write!(f, "position is not finite ({} {} {})", p[0], p[1], p[2])
            }
            MapError::RepeatedVertex { vertex } => write!(f, "vertex {vertex} appears twice"),
            MapError::NonFiniteMapCoordinate { corner } => {
                write!(f, "corner {corner} has a non-finite map coordinate")
            }
            MapError::TooLarge { points, total } => write!(
                f,
                "map too large: its image spans {points:.3e} grid points, the whole map {total:.3e} \
                 (limit {MAX_GRID_POINTS:.3e}); scale the map down"
            ),
            MapError::Reflected { percent } => write!(
                f,
                "reverted or degenerate tets make up {percent:.0}% of the volume: the charts are reflected or collapsed, not a map of this volume"
            ),
            MapError::NonManifoldFacet {
                simplex,
                vertices,
                simplices,
            } => {
                let list: Vec<String> = simplices.iter().map(|s| s.to_string()).collect();
                write!(
                    f,
                    "{} {} is shared by {} {} ({}): non-manifold",
                    simplex.facet(),
                    key(vertices),
                    simplices.len(),
                    simplex.plural(),
                    list.join(", ")
                )
            }
            MapError::OppositeOrientations {
                simplex,
                simplices: [a, b],
                vertices,
            } => write!(
                f,
                "{} {a} and {b} have opposite orientations across {} {}",
                simplex.plural(),
                simplex.facet(),
                key(vertices)
            ),
            MapError::NonManifoldVertex { vertex, simplex } => {
                let parts = if *simplex == ElementKind::Triangle {
                    "its triangles form more than one fan"
                } else {
                    "its tets are not connected through the faces around it"
                };
                write!(f, "vertex {vertex} is non-manifold: {parts}")
            }
            MapError::ReflectedTransition {
                simplex,
                facet,
                neighbour,
                mismatch,
                round_hint,
            } => {
                write!(
                    f,
                    "{simplex} {} {facet}: the charts of {} {} and {neighbour} differ by a \
                     reflection or a non-grid rotation (mismatch {})",
                    simplex.kind.facet(),
                    simplex.kind.plural(),
                    simplex.index,
                    num(*mismatch)
                )?;
                if *round_hint {
                    f.write_str(
                        "; if the charts are only noisy, --round-transitions would accept it",
                    )?;
                }
                Ok(())
            }
            MapError::NonIntegralTransition {
                simplex,
                facet,
                neighbour,
                residual,
                tolerance,
                round_limit,
            } => write!(
                f,
                "{simplex} {} {facet}: the transition to {} {neighbour} is not integral \
                 (residual {} > tolerance {}, and above {}, the largest rounded by default); \
                 --round-transitions would round it",
                simplex.kind.facet(),
                simplex.kind,
                num(*residual),
                num(*tolerance),
                num(*round_limit)
            ),
        }
    }
}

impl fmt::Display for Extrusion {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Extrusion::NoLayers => f.write_str("--layers must be at least 1"),
            Extrusion::Thickness(t) => write!(f, "thickness {t} is not positive"),
            Extrusion::VanishingNormal => {
                f.write_str("its area-weighted normal vanishes: cannot offset the surface there")
            }
        }
    }
}
