//! [`IndexError`]: an index that names no element (zero in a 1-based
//! format, before the first, beyond the last, not an index at all).
//!
//! Input: the readers' and checks' index tests. Output: the message,
//! naming the element kind indexed, the index as the file writes it and
//! the count. Invariants: one line, the readers' own wording.

use super::{Element, ElementKind};
use std::fmt;

/// An index that names no element.
#[derive(Clone, Debug, PartialEq)]
pub enum IndexError {
    /// Index 0 in OBJ's 1-based numbering.
    Zero {
        /// The element kind indexed.
        what: ElementKind,
    },
    /// A negative OBJ index reaching before the first element.
    BeforeFirst {
        /// The element kind indexed.
        what: ElementKind,
        /// The index as written.
        index: i64,
        /// Elements defined before the line.
        defined: usize,
    },
    /// An index beyond `u32`.
    TooLarge {
        /// The element kind indexed.
        what: ElementKind,
        /// The index as written.
        index: i64,
    },
    /// An index beyond the last element (`counted`: the kind the count is
    /// said of, when the message says it).
    OutOfRange {
        /// The element kind indexed.
        what: ElementKind,
        /// The index as the file numbers it.
        index: u64,
        /// Elements in the file.
        count: usize,
        /// The kind counted, when said.
        counted: Option<ElementKind>,
    },
    /// A cell's vertex beyond the last (VTK, MEDIT: `style` as each says it).
    VertexOutOfRange {
        /// The vertex as the file numbers it.
        vertex: u64,
        /// Vertices in the file.
        count: usize,
        /// The range as the format says it.
        style: RangeStyle,
    },
    /// A corner of `owner` referring to a vertex the mesh does not have.
    RefersToVertex {
        /// The face or simplex.
        owner: Element,
        /// The corner, when the message names it.
        corner: Option<usize>,
        /// The vertex index.
        vertex: u64,
        /// Vertices in the mesh.
        count: usize,
    },
    /// A PLY vertex index that is negative, fractional or beyond `u32`.
    NotValid {
        /// The value read.
        value: f64,
    },
    /// A `.ovm` index beyond its bound.
    ListOutOfRange {
        /// The index.
        index: usize,
        /// The number of elements it indexes.
        bound: usize,
    },
}

/// How a format states a vertex range.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RangeStyle {
    /// `(N points)`, 0-based (VTK).
    Points,
    /// `1..=N` (MEDIT).
    OneBased,
}

impl fmt::Display for IndexError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            IndexError::Zero { what } => {
                write!(f, "{what} index 0 is invalid (OBJ indices start at 1)")
            }
            IndexError::BeforeFirst {
                what,
                index,
                defined,
            } => write!(
                f,
                "{what} index {index} points before the first {what} ({defined} defined so far)"
            ),
            IndexError::TooLarge { what, index } => {
                write!(f, "{what} index {index} is too large")
            }
            IndexError::OutOfRange {
                what,
                index,
                count,
                counted,
            } => {
                write!(
                    f,
                    "{what} index {index} is out of range (the file has {count}"
                )?;
                if let Some(kind) = counted {
                    write!(f, " {}", kind.plural())?;
                }
                f.write_str(")")
            }
            IndexError::VertexOutOfRange {
                vertex,
                count,
                style,
            } => match style {
                RangeStyle::Points => {
                    write!(f, "vertex {vertex} out of range ({count} points)")
                }
                RangeStyle::OneBased => write!(f, "vertex {vertex} out of range 1..={count}"),
            },
            IndexError::RefersToVertex {
                owner,
                corner,
                vertex,
                count,
            } => {
                write!(f, "{owner}")?;
                if let Some(c) = corner {
                    write!(f, ": corner {c}")?;
                }
                write!(
                    f,
                    " refers to vertex {vertex}, but there are {count} vertices"
                )
            }
            IndexError::NotValid { value } => {
                write!(f, "vertex index {value} is not a valid index")
            }
            IndexError::ListOutOfRange { index, bound } => {
                write!(f, "index {index} out of range (there are {bound})")
            }
        }
    }
}
