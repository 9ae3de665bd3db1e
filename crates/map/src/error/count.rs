//! [`CountError`]: a count the file cannot hold, a record of the wrong
//! size, nothing to read.
//!
//! Input: the readers' and checks' counts (declared, found, needed).
//! Output: the message, naming the element kind counted and both numbers.
//! Invariants: one line, the readers' own wording.

use super::ElementKind;
use std::fmt;

/// A count or size that does not fit.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum CountError {
    /// More elements declared than the bytes left can hold (`.hexex`).
    ExceedsBytes {
        /// The element kind.
        what: ElementKind,
        /// The count declared.
        count: u64,
        /// The bytes left.
        bytes: usize,
        /// The numbers each element needs.
        numbers_each: u64,
    },
    /// A count beyond the platform's addresses.
    TooLarge {
        /// The element kind.
        what: ElementKind,
        /// The count declared.
        count: u64,
    },
    /// More records declared than lines follow (`.ovm` section).
    SectionExceedsLines {
        /// The section keyword.
        section: &'static str,
        /// The count declared.
        count: usize,
        /// The lines left.
        lines: usize,
    },
    /// More property values than lines follow (`.ovm`).
    PropertyExceedsLines {
        /// The property.
        property: String,
        /// The values it needs.
        count: usize,
        /// The lines left.
        lines: usize,
    },
    /// A count of more items than the tokens left (VTK; `what` names it).
    ExceedsFile {
        /// The count's name.
        what: &'static str,
        /// The count read.
        count: usize,
    },
    /// More elements declared than the file's bytes can hold (MEDIT).
    DoNotFit {
        /// The element kind.
        what: ElementKind,
        /// The count declared.
        count: usize,
    },
    /// A PLY element claiming more records than the bytes left.
    ElementExceedsBytes {
        /// The element.
        element: String,
        /// The records claimed.
        count: u64,
        /// The bytes left.
        bytes: usize,
    },
    /// VTK cells and cell types in different numbers.
    CellTypes {
        /// Cells.
        cells: usize,
        /// Cell types.
        types: usize,
    },
    /// Simplices and sets of map coordinates in different numbers.
    MapCoordinates {
        /// The simplex kind.
        simplex: ElementKind,
        /// Simplices.
        simplices: usize,
        /// Sets of map coordinates.
        coords: usize,
    },
    /// A `.ovm` index list shorter than its valence.
    Indices {
        /// The valence.
        declared: usize,
        /// The indices given.
        given: usize,
    },
    /// A `.ovm` value line with too few numbers.
    FewerValues {
        /// The numbers needed.
        expected: usize,
    },
    /// An OBJ `v` line with fewer than 3 coordinates.
    VertexCoordinates {
        /// The coordinates found.
        found: usize,
    },
    /// An OBJ `vt` line with fewer than 2 values.
    TextureValues {
        /// The values found.
        found: usize,
    },
    /// A PLY `texcoord` list of other than 6 values.
    Texcoords {
        /// The values found.
        values: usize,
    },
    /// A face of a size that is not read (`face`: its index, when the
    /// message names it).
    FaceSize {
        /// The face.
        face: Option<u64>,
        /// Its vertices.
        vertices: usize,
        /// What a face needs.
        need: FaceNeed,
    },
    /// No element of the kind at all.
    Empty {
        /// The element kind.
        what: ElementKind,
        /// Why, when the message says it.
        reason: Option<EmptyReason>,
    },
    /// More vertices than `u32` indices can address.
    TooManyVertices(usize),
}

/// What a face needs, as the message says it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FaceNeed {
    /// Not said (3 or more corners).
    Unstated,
    /// 3 corners (an OBJ triangle map, too few).
    Triangle,
    /// At least 3 corners.
    AtLeastThree,
    /// 3 corners (a triangle map, too many: triangulate it).
    OnlyTriangles,
}

/// Why there is nothing to read.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum EmptyReason {
    /// The OBJ file has no `f` line.
    NoFaceLine,
    /// The count of this name is 0.
    ZeroCount(&'static str),
    /// The PLY element of this name is empty.
    EmptyElement(&'static str),
}

impl fmt::Display for CountError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            CountError::ExceedsBytes {
                what,
                count,
                bytes,
                numbers_each,
            } => write!(
                f,
                "the file declares {count} {}, but only {bytes} bytes follow (each {what} needs {numbers_each} numbers): truncated file or wrong count",
                what.plural()
            ),
            CountError::TooLarge { what, count } => write!(f, "{what} count {count} is too large"),
            CountError::SectionExceedsLines {
                section,
                count,
                lines,
            } => write!(f, "{count} {section} declared but only {lines} lines follow"),
            CountError::PropertyExceedsLines {
                property,
                count,
                lines,
            } => write!(
                f,
                "property \"{property}\": {count} values expected but only {lines} lines follow"
            ),
            CountError::ExceedsFile { what, count } => {
                write!(f, "{what} {count} is more than the file holds")
            }
            CountError::DoNotFit { what, count } => {
                write!(f, "{count} {} do not fit in the file", what.plural())
            }
            CountError::ElementExceedsBytes {
                element,
                count,
                bytes,
            } => write!(
                f,
                "element `{element}` claims {count} records, but only {bytes} bytes follow (truncated or corrupt file)"
            ),
            CountError::CellTypes { cells, types } => {
                write!(f, "{cells} cells but {types} cell types")
            }
            CountError::MapCoordinates {
                simplex,
                simplices,
                coords,
            } => write!(
                f,
                "{simplices} {} but {coords} sets of map coordinates",
                simplex.plural()
            ),
            CountError::Indices { declared, given } => {
                write!(f, "{declared} indices declared, {given} given")
            }
            CountError::FewerValues { expected } => write!(f, "fewer than {expected} values"),
            CountError::VertexCoordinates { found } => write!(
                f,
                "vertex has {found} coordinates; expected `v x y z`"
            ),
            CountError::TextureValues { found } => write!(
                f,
                "texture coordinate has {found} values; expected `vt u v`"
            ),
            CountError::Texcoords { values } => write!(
                f,
                "texcoord list has {values} values; expected 6 (u0 v0 u1 v1 u2 v2)"
            ),
            CountError::FaceSize {
                face,
                vertices,
                need,
            } => {
                f.write_str("face")?;
                if let Some(i) = face {
                    write!(f, " {i}")?;
                }
                write!(f, " has {vertices} vertices")?;
                f.write_str(match need {
                    FaceNeed::Unstated => "",
                    FaceNeed::Triangle => "; a triangle needs 3",
                    FaceNeed::AtLeastThree => "; a face needs at least 3",
                    FaceNeed::OnlyTriangles => {
                        "; only triangles are supported (triangulate the mesh first)"
                    }
                })
            }
            CountError::Empty { what, reason } => {
                write!(f, "no {}", what.plural())?;
                match reason {
                    None => Ok(()),
                    Some(EmptyReason::NoFaceLine) => f.write_str(" (the file has no `f` line)"),
                    Some(EmptyReason::ZeroCount(name)) => write!(f, " (the {name} count is 0)"),
                    Some(EmptyReason::EmptyElement(name)) => {
                        write!(f, " (the `{name}` element is empty)")
                    }
                }
            }
            CountError::TooManyVertices(n) => {
                write!(f, "{n} vertices: more than u32 indices can address")
            }
        }
    }
}
