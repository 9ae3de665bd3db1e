//! Errors caused by the input (a bad file or an invalid map). Internal bugs
//! are not reported through this type: they panic with "bug:".
//!
//! Input: what a reader, the model's checks or a stage above found wrong.
//! Output: an [`InputError`]: the file (when known), the [`Location`] in it
//! (a line, or a byte of a binary body), and the [`InputErrorKind`], what
//! is wrong as data, by family:
//! - [`FormatError`]: not a file of its format, or a feature of the format
//!   not read (binary bodies, polygons, missing properties);
//! - [`SyntaxError`]: a token or line the format does not allow, or the
//!   file ending where more is expected;
//! - [`CountError`]: a count the file cannot hold, a record of the wrong
//!   size, nothing to read;
//! - [`IndexError`]: an index that names no element;
//! - [`MapError`]: the map itself (repeated vertex, non-manifold edge or
//!   vertex, opposite orientations, reflected or non-integral transition,
//!   a map too large or reflected);
//! - [`Extrusion`]: a map that cannot be extruded as asked;
//! - non-finite values, I/O failures, and errors of the crates above
//!   ([`InputErrorKind::Source`]).
//!
//! The element concerned (a vertex, a triangle, a face corner, a PLY
//! record, …, with its index) is an [`Element`]: either a field of the
//! variant or the context the kind is [`InputErrorKind::Within`].
//!
//! Invariants: displayed as one line, `FILE: line L: what` or
//! `FILE: triangle 17: what`; the texts are the readers' and checks' own
//! (tests and the CLI's stderr compare them byte for byte).

mod count;
mod element;
mod format;
mod index;
mod model;
mod syntax;
#[cfg(test)]
mod syntax_tests;
#[cfg(test)]
mod tests;

pub use count::{CountError, EmptyReason, FaceNeed};
pub use element::{Element, ElementKind, Subject, Token};
pub use format::{Format, FormatError, NotATet, NotTextReason};
pub use index::{IndexError, RangeStyle};
pub use model::{Extrusion, MapError};
pub use syntax::{Awaited, SyntaxError, Values};

use std::fmt;
use std::sync::Arc;

/// An error caused by the input, displayed as one line:
/// `FILE: line L: what` or `FILE: triangle 17: what`.
#[derive(Clone, Debug, PartialEq)]
pub struct InputError {
    /// The file the error is about, when known.
    pub file: Option<String>,
    /// Where in the file, when known.
    pub location: Option<Location>,
    /// What is wrong, naming the element (boxed: the error stays small
    /// in the `Result`s that carry it).
    pub kind: Box<InputErrorKind>,
}

/// Where in a file: a line of a text file or a byte of a binary body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Location {
    /// A line, counted from 1.
    Line(usize),
    /// A byte offset from the start of the file.
    Byte(usize),
}

/// What is wrong with the input (module docs).
#[derive(Clone, Debug, PartialEq)]
pub enum InputErrorKind {
    /// `error`, about `element` (displayed `element: error`, e.g.
    /// `tet 3: corner 1: vertex index 9 is out of range …`).
    Within {
        /// The element concerned.
        element: Element,
        /// What is wrong with it.
        error: Box<InputErrorKind>,
    },
    /// The file could not be read.
    Read(IoError),
    /// Not a file of its format, or a feature not read.
    Format(FormatError),
    /// A token or line the format does not allow.
    Syntax(SyntaxError),
    /// A count or size that does not fit.
    Count(CountError),
    /// An index that names no element.
    Index(IndexError),
    /// A value that is not finite (`token`: the value as written, when
    /// the message quotes it).
    NonFinite {
        /// The value.
        what: Subject,
        /// As written.
        token: Option<Token>,
    },
    /// A defect of the map.
    Map(MapError),
    /// A map that cannot be extruded as asked.
    Extrusion(Extrusion),
    /// The one catch-all: an error of a crate above this one that the
    /// input caused (the remesher's `SurfaceError` / `RemeshError`, a
    /// writer's error met inside a pipeline callback). This crate cannot
    /// name those types; the error is kept whole, not as text, and
    /// displayed as it displays itself.
    Source(SourceError),
}

/// An I/O error, shared so that the error stays [`Clone`]; compared by
/// kind and text.
#[derive(Clone, Debug)]
pub struct IoError(pub Arc<std::io::Error>);

/// An error of a crate above this one ([`InputErrorKind::Source`]);
/// compared by its text.
#[derive(Clone, Debug)]
pub struct SourceError(pub Arc<dyn std::error::Error + Send + Sync>);

impl InputError {
    /// An error of `kind`, with no file or location yet.
    pub fn new(kind: impl Into<InputErrorKind>) -> Self {
        InputError {
            file: None,
            location: None,
            kind: Box::new(kind.into()),
        }
    }

    /// An error at a line of a text file.
    pub fn at_line(line: usize, kind: impl Into<InputErrorKind>) -> Self {
        Self::at(Location::Line(line), kind)
    }

    /// An error at a location of a file.
    pub fn at(location: Location, kind: impl Into<InputErrorKind>) -> Self {
        InputError {
            file: None,
            location: Some(location),
            kind: Box::new(kind.into()),
        }
    }

    /// Attaches the file name (keeps an existing one).
    pub fn in_file(mut self, file: impl Into<String>) -> Self {
        if self.file.is_none() {
            self.file = Some(file.into());
        }
        self
    }

    /// The element the error names first (the outermost context), if any.
    pub fn element(&self) -> Option<&Element> {
        self.kind.element()
    }

    /// What is wrong, below the elements' contexts.
    pub fn cause(&self) -> &InputErrorKind {
        self.kind.cause()
    }
}

impl InputErrorKind {
    /// An error of a crate above this one (see [`InputErrorKind::Source`]).
    pub fn from_source(error: impl std::error::Error + Send + Sync + 'static) -> Self {
        InputErrorKind::Source(SourceError(Arc::new(error)))
    }

    /// The outermost element of [`InputErrorKind::Within`], if any.
    pub fn element(&self) -> Option<&Element> {
        match self {
            InputErrorKind::Within { element, .. } => Some(element),
            _ => None,
        }
    }

    /// What is wrong, below the elements' contexts.
    pub fn cause(&self) -> &InputErrorKind {
        match self {
            InputErrorKind::Within { error, .. } => error.cause(),
            other => other,
        }
    }
}

impl fmt::Display for InputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if let Some(file) = &self.file {
            write!(f, "{file}: ")?;
        }
        if let Some(loc) = &self.location {
            write!(f, "{loc}: ")?;
        }
        // one line, whatever a token or a source error contains
        write!(f, "{}", self.kind.to_string().replace('\n', " "))
    }
}

impl fmt::Display for Location {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Location::Line(l) => write!(f, "line {l}"),
            Location::Byte(b) => write!(f, "byte {b}"),
        }
    }
}

impl fmt::Display for InputErrorKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            InputErrorKind::Within { element, error } => write!(f, "{element}: {error}"),
            InputErrorKind::Read(e) => write!(f, "cannot read: {e}"),
            InputErrorKind::Format(e) => e.fmt(f),
            InputErrorKind::Syntax(e) => e.fmt(f),
            InputErrorKind::Count(e) => e.fmt(f),
            InputErrorKind::Index(e) => e.fmt(f),
            InputErrorKind::NonFinite { what, token } => {
                write!(f, "{what} is not finite")?;
                match token {
                    Some(t) => write!(f, " ({t})"),
                    None => Ok(()),
                }
            }
            InputErrorKind::Map(e) => e.fmt(f),
            InputErrorKind::Extrusion(e) => e.fmt(f),
            InputErrorKind::Source(e) => e.fmt(f),
        }
    }
}

impl fmt::Display for IoError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

impl PartialEq for IoError {
    fn eq(&self, other: &Self) -> bool {
        self.0.kind() == other.0.kind() && self.0.to_string() == other.0.to_string()
    }
}

impl fmt::Display for SourceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        self.0.fmt(f)
    }
}

impl PartialEq for SourceError {
    fn eq(&self, other: &Self) -> bool {
        self.0.to_string() == other.0.to_string()
    }
}

impl std::error::Error for InputError {}

impl From<std::io::Error> for InputErrorKind {
    fn from(e: std::io::Error) -> Self {
        InputErrorKind::Read(IoError(Arc::new(e)))
    }
}

/// `From` each family into [`InputErrorKind`] and [`InputError`].
macro_rules! families {
    ($($family:ident => $variant:ident),* $(,)?) => {$(
        impl From<$family> for InputErrorKind {
            fn from(e: $family) -> Self {
                InputErrorKind::$variant(e)
            }
        }
        impl From<$family> for InputError {
            fn from(e: $family) -> Self {
                InputError::new(e)
            }
        }
    )*};
}

families!(
    FormatError => Format,
    SyntaxError => Syntax,
    CountError => Count,
    IndexError => Index,
    MapError => Map,
    Extrusion => Extrusion,
);

impl From<InputErrorKind> for InputError {
    fn from(kind: InputErrorKind) -> Self {
        InputError::new(kind)
    }
}
