//! Why a picture or a page could not be made: [`RenderError`], one line
//! naming the offending element (a vertex, a quad, a hex, a value) or
//! the file.

use std::fmt;
use std::path::PathBuf;

/// Why a picture or a page could not be made.
#[derive(Debug)]
pub enum RenderError {
    /// The map is invalid ([`dualex_map::TriMap::validate`]).
    Map(dualex_map::InputError),
    /// A mark on a vertex the map does not have.
    MarkOutOfRange {
        /// The vertex marked.
        vertex: u32,
        /// The map's vertices.
        vertices: usize,
    },
    /// A vertex whose position is not finite.
    VertexNotFinite {
        /// The vertex.
        vertex: usize,
    },
    /// A cell refers to a vertex the mesh does not have.
    CellOutOfRange {
        /// `"quad"` or `"hex"`.
        kind: &'static str,
        /// The cell.
        cell: usize,
        /// The vertex it names.
        vertex: u32,
        /// The mesh's vertices.
        vertices: usize,
    },
    /// The map has no triangle.
    NoTriangles,
    /// The mesh has no quad.
    NoQuads,
    /// A square picture's side outside 16..=16384 pixels.
    Size(u32),
    /// A picture's width or height outside 16..=16384 pixels.
    Sides {
        /// Its width.
        width: u32,
        /// Its height.
        height: u32,
    },
    /// A picture too small for the histogram's plot.
    TooSmall {
        /// Its width.
        width: u32,
        /// Its height.
        height: u32,
    },
    /// The pixels could not be allocated (`side` or `width×height`).
    Allocate(String),
    /// Quality values counted otherwise than the elements.
    QualityCount {
        /// The values given.
        values: usize,
        /// The elements.
        elements: usize,
        /// The elements' plural (`"quads"`, `"hexes"`).
        many: &'static str,
    },
    /// An element's quality is not a number (pages).
    QualityNotNumber {
        /// The element's name (`"quad"`, `"hex"`).
        one: &'static str,
        /// The element.
        element: usize,
    },
    /// An element's quality value is not a number (histogram).
    QualityValue {
        /// The element.
        element: usize,
        /// Its value.
        value: f64,
    },
    /// The PNG encoder failed (`file`: the file it was for, if any).
    Encode {
        /// The file.
        file: Option<PathBuf>,
        /// The encoder's reason.
        reason: String,
    },
    /// The path names no file.
    NotAFileName(PathBuf),
    /// The file could not be written.
    Write {
        /// The file.
        file: PathBuf,
        /// The system's reason.
        error: std::io::Error,
    },
}

impl fmt::Display for RenderError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use crate::canvas::SIZE_RANGE as R;
        use RenderError as E;
        match self {
            E::Map(e) => write!(f, "{e}"),
            E::MarkOutOfRange { vertex, vertices } => write!(
                f,
                "mark on vertex {vertex}, but there are {vertices} vertices"
            ),
            E::VertexNotFinite { vertex } => write!(f, "vertex {vertex}: position is not finite"),
            E::CellOutOfRange {
                kind,
                cell,
                vertex,
                vertices,
            } => write!(
                f,
                "{kind} {cell} refers to vertex {vertex}, but there are {vertices} vertices"
            ),
            E::NoTriangles => write!(f, "nothing to draw: the map has no triangles"),
            E::NoQuads => write!(f, "nothing to draw: the mesh has no quads"),
            E::Size(s) => write!(
                f,
                "picture size {s} is outside {}..={} pixels",
                R.start(),
                R.end()
            ),
            E::Sides { width, height } => write!(
                f,
                "picture size {width}×{height} is outside {}..={} pixels",
                R.start(),
                R.end()
            ),
            E::TooSmall { width, height } => {
                write!(f, "picture size {width}×{height} is too small")
            }
            E::Allocate(what) => write!(f, "cannot allocate {what}"),
            E::QualityCount {
                values,
                elements,
                many,
            } => write!(f, "{values} quality values for {elements} {many}"),
            E::QualityNotNumber { one, element } => {
                write!(f, "{one} {element}: its quality is not a number")
            }
            E::QualityValue { element, value } => {
                write!(f, "element {element}: its quality {value} is not a number")
            }
            E::Encode { file: None, reason } => write!(f, "cannot encode PNG: {reason}"),
            E::Encode {
                file: Some(p),
                reason,
            } => write!(f, "{}: cannot encode PNG: {reason}", p.display()),
            E::NotAFileName(p) => write!(f, "{}: not a file name", p.display()),
            E::Write { file, error } => write!(f, "{}: {error}", file.display()),
        }
    }
}

impl std::error::Error for RenderError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            RenderError::Write { error, .. } => Some(error),
            _ => None,
        }
    }
}

impl From<dualex_map::InputError> for RenderError {
    fn from(e: dualex_map::InputError) -> Self {
        RenderError::Map(e)
    }
}
