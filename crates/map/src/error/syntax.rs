//! [`SyntaxError`]: a token or line the format does not allow, or the file
//! ending where the syntax expects more; with what was expected.
//!
//! Input: the readers' token and line checks. Output: the message, quoting
//! the token ([`Token`]) and naming the value ([`Subject`]) or the element
//! awaited ([`Awaited`]). Invariants: one line, the readers' own wording.

use super::{Element, ElementKind, Subject, Token};
use std::fmt;

/// A token or line the format does not allow.
#[derive(Clone, Debug, PartialEq)]
pub enum SyntaxError {
    /// Not a number (`what`, when the message names the value).
    NotANumber {
        /// The value.
        what: Option<Subject>,
        /// As written.
        token: Token,
    },
    /// Not an integer.
    NotAnInteger {
        /// The value.
        what: Option<Subject>,
        /// As written.
        token: Token,
    },
    /// Not a non-negative integer (`hint`: the tokens look shifted, a
    /// number missing or extra earlier).
    NotANonNegativeInteger {
        /// The value.
        what: Subject,
        /// As written.
        token: Token,
        /// Whether the token is a number (a count is probably wrong).
        hint: bool,
    },
    /// Not a valid number (MEDIT; the token as written, whole).
    NotAValidNumber {
        /// The value.
        what: Subject,
        /// As written.
        token: String,
    },
    /// A PLY list length that is negative or not an integer.
    BadListLength {
        /// The list property.
        list: String,
        /// The length read.
        length: f64,
    },
    /// A PLY list longer than the bytes left.
    ListTruncated {
        /// The list property.
        list: String,
        /// The length read.
        items: f64,
    },
    /// An OBJ statement that is neither known nor skippable.
    UnknownStatement(Token),
    /// An OBJ face corner without its `vt` (`corner` counted from 1).
    NoTextureCoordinate {
        /// The corner.
        corner: usize,
    },
    /// A PLY header line of no known form.
    UnexpectedHeaderLine(Token),
    /// A PLY `property` line of no known form (its words after `property`).
    MalformedProperty(String),
    /// A PLY `property` line before any `element` line.
    PropertyBeforeElement,
    /// A PLY header line that is not UTF-8.
    HeaderLineNotText,
    /// A PLY header without a `format` line.
    NoFormatLine,
    /// A PLY header without an `end_header` line.
    NoEndHeader,
    /// A PLY list whose count type is not an integer type.
    ListCountNotInteger(Token),
    /// Another line than the section keyword expected (`.ovm`).
    ExpectedKeyword {
        /// The keyword.
        keyword: &'static str,
        /// The line found.
        found: Token,
    },
    /// Another line than a property header (`.ovm`).
    ExpectedPropertyHeader(Token),
    /// Another token than the value expected (VTK; `what` names it).
    ExpectedValue {
        /// The value expected.
        what: &'static str,
        /// The token found, whole.
        found: String,
    },
    /// A `.ovm` index list whose valence is not a small integer.
    BadValence(Token),
    /// A `.ovm` index that is not an integer.
    BadIndex(Token),
    /// A `.ovm` edge line without two vertex indices in range.
    BadVertexIndexIn(Token),
    /// A `.ovm` section count that is not an integer.
    BadSectionCount {
        /// The section keyword.
        section: &'static str,
        /// The line found.
        token: Token,
    },
    /// A token after the last tet of a `.hexex` file.
    TrailingToken {
        /// The token.
        token: Token,
        /// The tets the file declares.
        declared: usize,
    },
    /// The file ends before something awaited.
    EndsBefore(Awaited),
    /// The file ends inside an element's values.
    EndsIn {
        /// The element.
        owner: Element,
        /// Values it needs.
        expected: usize,
        /// What they are.
        values: Values,
        /// Values found.
        found: usize,
    },
    /// The file ends early (PLY body).
    EndsEarly,
    /// The file ends while reading a value (MEDIT).
    EndsWhileReading(Subject),
    /// The file ends where a value is expected (VTK; `expected` names it).
    Truncated {
        /// The value expected.
        expected: &'static str,
    },
}

/// What the file ends before.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Awaited {
    /// A section (`the Vertices section`).
    Section(&'static str),
    /// A section's count (`the Vertices count`).
    SectionCount(&'static str),
    /// The count of an element kind (`the tet count`).
    Count(ElementKind),
    /// A record (`a vertex`, `an edge`).
    Record(ElementKind),
    /// A value of a property (`a parameter`).
    Parameter,
}

/// The values of an element.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Values {
    /// Position coordinates.
    Coordinates,
    /// Map coordinates.
    MapCoordinates,
    /// Vertex indices.
    VertexIndices,
}

/// `what ` when the message names the value.
fn subject(f: &mut fmt::Formatter<'_>, what: &Option<Subject>) -> fmt::Result {
    match what {
        Some(w) => write!(f, "{w} "),
        None => Ok(()),
    }
}

impl fmt::Display for SyntaxError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SyntaxError::NotANumber { what, token } => {
                subject(f, what)?;
                write!(f, "{token} is not a number")
            }
            SyntaxError::NotAnInteger { what, token } => {
                subject(f, what)?;
                write!(f, "{token} is not an integer")
            }
            SyntaxError::NotANonNegativeInteger { what, token, hint } => {
                write!(f, "{what} {token} is not a non-negative integer")?;
                if *hint {
                    f.write_str(
                        " (a number is missing or extra earlier in the file, or a count is wrong)",
                    )?;
                }
                Ok(())
            }
            SyntaxError::NotAValidNumber { what, token } => {
                write!(f, "{what}: `{token}` is not a valid number")
            }
            SyntaxError::BadListLength { list, length } => write!(
                f,
                "list `{list}` length {length} is not a non-negative integer"
            ),
            SyntaxError::ListTruncated { list, items } => write!(
                f,
                "list `{list}` claims {items} items but the file ends before (truncated file?)"
            ),
            SyntaxError::UnknownStatement(t) => write!(f, "unknown statement {t}"),
            SyntaxError::NoTextureCoordinate { corner } => write!(
                f,
                "face corner {corner} has no texture coordinate (expected f v/vt)"
            ),
            SyntaxError::UnexpectedHeaderLine(t) => write!(f, "unexpected PLY header line {t}"),
            SyntaxError::MalformedProperty(words) => {
                write!(f, "malformed property line `property {words}`")
            }
            SyntaxError::PropertyBeforeElement => f.write_str("property before any element"),
            SyntaxError::HeaderLineNotText => f.write_str("PLY header line is not text"),
            SyntaxError::NoFormatLine => f.write_str("PLY header has no `format` line"),
            SyntaxError::NoEndHeader => {
                f.write_str("PLY header has no `end_header` line (truncated file?)")
            }
            SyntaxError::ListCountNotInteger(t) => {
                write!(f, "list count type of {t} is not an integer type")
            }
            SyntaxError::ExpectedKeyword { keyword, found } => {
                write!(f, "expected `{keyword}`, found {found}")
            }
            SyntaxError::ExpectedPropertyHeader(t) => write!(
                f,
                "expected a property header (`HFProp vec3d \"name\"`), found {t}"
            ),
            SyntaxError::ExpectedValue { what, found } => {
                write!(f, "expected {what}, found {found:?}")
            }
            SyntaxError::BadValence(t) => write!(f, "bad valence in {t}"),
            SyntaxError::BadIndex(t) => write!(f, "bad index {t}"),
            SyntaxError::BadVertexIndexIn(t) => write!(f, "bad vertex index in {t}"),
            SyntaxError::BadSectionCount { section, token } => {
                write!(f, "bad {section} count {token}")
            }
            SyntaxError::TrailingToken { token, declared } => write!(
                f,
                "unexpected {token} after the last tet (the file declares {declared} tets)"
            ),
            SyntaxError::EndsBefore(a) => write!(f, "file ends before {a}"),
            SyntaxError::EndsIn {
                owner,
                expected,
                values,
                found,
            } => write!(
                f,
                "file ends in {owner}: expected {expected} {values}, found {found}"
            ),
            SyntaxError::EndsEarly => f.write_str("file ends early (truncated file?)"),
            SyntaxError::EndsWhileReading(what) => write!(f, "file ends while reading {what}"),
            SyntaxError::Truncated { expected } => write!(f, "truncated: expected {expected}"),
        }
    }
}

impl fmt::Display for Awaited {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Awaited::Section(keyword) => write!(f, "the {keyword} section"),
            Awaited::SectionCount(keyword) => write!(f, "the {keyword} count"),
            Awaited::Count(kind) => write!(f, "the {kind} count"),
            Awaited::Record(kind) => f.write_str(&kind.with_article()),
            Awaited::Parameter => f.write_str("a parameter"),
        }
    }
}

impl fmt::Display for Values {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(match self {
            Values::Coordinates => "coordinates",
            Values::MapCoordinates => "map coordinates",
            Values::VertexIndices => "vertex indices",
        })
    }
}
