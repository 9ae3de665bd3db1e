//! What an error names: an element of the input ([`Element`]: its kind and
//! index), a token as written ([`Token`]), a value ([`Subject`]).
//!
//! Input: indices and tokens from the readers and checks. Output: their
//! words in messages (`triangle 17`, `` `nan` ``, `vertex coordinate`).
//! Invariants: an element's index is the one the message shows (0-based,
//! except OBJ face corners, counted from 1 as on the line); a token keeps
//! at most the characters its quotation shows.

use super::InputErrorKind;
use std::fmt;

/// The kind of an element of the input.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum ElementKind {
    /// A vertex.
    Vertex,
    /// A texture coordinate (an OBJ `vt`).
    TextureCoordinate,
    /// An edge (a facet of a triangle, an OpenVolumeMesh edge).
    Edge,
    /// A triangle.
    Triangle,
    /// A face (a facet of a tet, a polygon, a PLY `face` record).
    Face,
    /// A tetrahedron.
    Tet,
    /// An OpenVolumeMesh halfface.
    Halfface,
    /// A cell of a volume mesh.
    Cell,
    /// A hexahedron.
    Hexahedron,
    /// A corner of a simplex, counted from 0.
    Corner,
    /// A corner on an OBJ `f` line, counted from 1 as on the line.
    FaceCorner,
    /// A record of a PLY element of another name.
    Named(String),
}

/// An element of the input: its kind and index (`triangle 17`).
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Element {
    /// What it is.
    pub kind: ElementKind,
    /// Its index, as the message shows it.
    pub index: u64,
}

/// A token of the input as messages quote it: in backquotes, at most 24
/// characters (a longer one cut to its first 20 and `…`). Holds no more
/// than that needs.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Token(String);

/// A value a message names: what is not a number, not finite, missing.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Subject {
    /// `vertex coordinate` (OBJ `v`).
    VertexCoordinate,
    /// `texture coordinate` (OBJ `vt`).
    TextureCoordinate,
    /// `texture coordinate `u`` (a PLY vertex property).
    NamedTextureCoordinate(String),
    /// `coordinate`.
    Coordinate,
    /// `texcoord` (a PLY face list).
    Texcoord,
    /// `value`.
    Value,
    /// An element's values (`vertex 3`).
    Element(Element),
    /// An element's reference number (`vertex 3 reference`, MEDIT).
    Reference(Element),
    /// An index of an element kind (`vertex index`).
    Index(ElementKind),
    /// The count of an element kind (`tet count`).
    Count(ElementKind),
    /// `element count` (a PLY header line).
    ElementCount,
    /// A keyword of the format and its value (`Dimension`, MEDIT).
    Keyword(String),
}

impl ElementKind {
    /// The simplex of `n` corners: a triangle or a tet.
    pub fn simplex(n: usize) -> Self {
        if n == 3 {
            ElementKind::Triangle
        } else {
            ElementKind::Tet
        }
    }

    /// The kind of a PLY element of this name (`vertex`, `face`, `edge`
    /// typed, any other by name).
    pub fn from_name(name: &str) -> Self {
        match name {
            "vertex" => ElementKind::Vertex,
            "face" => ElementKind::Face,
            "edge" => ElementKind::Edge,
            other => ElementKind::Named(other.to_string()),
        }
    }

    /// Element `index` of this kind.
    pub fn at(self, index: usize) -> Element {
        Element {
            kind: self,
            index: index as u64,
        }
    }

    /// The facet of a simplex of this kind: an edge of a triangle, a face
    /// of a tet.
    pub fn facet(&self) -> ElementKind {
        if *self == ElementKind::Triangle {
            ElementKind::Edge
        } else {
            ElementKind::Face
        }
    }

    /// The word in messages.
    pub fn word(&self) -> &str {
        match self {
            ElementKind::Vertex => "vertex",
            ElementKind::TextureCoordinate => "texture coordinate",
            ElementKind::Edge => "edge",
            ElementKind::Triangle => "triangle",
            ElementKind::Face => "face",
            ElementKind::Tet => "tet",
            ElementKind::Halfface => "halfface",
            ElementKind::Cell => "cell",
            ElementKind::Hexahedron => "hexahedron",
            ElementKind::Corner => "corner",
            ElementKind::FaceCorner => "face corner",
            ElementKind::Named(name) => name,
        }
    }

    /// The word in the plural (`vertices`, `hexahedra`).
    pub fn plural(&self) -> String {
        match self {
            ElementKind::Vertex => "vertices".into(),
            ElementKind::Hexahedron => "hexahedra".into(),
            other => format!("{}s", other.word()),
        }
    }

    /// The word with its indefinite article (`a vertex`, `an edge`).
    pub fn with_article(&self) -> String {
        let word = self.word();
        let vowel = word.starts_with(['a', 'e', 'i', 'o', 'u']);
        format!("{} {word}", if vowel { "an" } else { "a" })
    }
}

impl Element {
    /// `what`, about this element (an [`InputErrorKind::Within`]).
    pub fn error(self, what: impl Into<InputErrorKind>) -> InputErrorKind {
        InputErrorKind::Within {
            element: self,
            error: Box::new(what.into()),
        }
    }
}

impl Token {
    /// The token `text`, as far as its quotation shows it.
    pub fn new(text: &str) -> Self {
        Token(text.chars().take(25).collect())
    }
}

impl fmt::Display for ElementKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.word())
    }
}

impl fmt::Display for Element {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} {}", self.kind, self.index)
    }
}

impl fmt::Display for Token {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.0.chars().count() <= 24 {
            write!(f, "`{}`", self.0)
        } else {
            let head: String = self.0.chars().take(20).collect();
            write!(f, "`{head}…`")
        }
    }
}

impl fmt::Display for Subject {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Subject::VertexCoordinate => f.write_str("vertex coordinate"),
            Subject::TextureCoordinate => f.write_str("texture coordinate"),
            Subject::NamedTextureCoordinate(name) => write!(f, "texture coordinate `{name}`"),
            Subject::Coordinate => f.write_str("coordinate"),
            Subject::Texcoord => f.write_str("texcoord"),
            Subject::Value => f.write_str("value"),
            Subject::Element(e) => write!(f, "{e}"),
            Subject::Reference(e) => write!(f, "{e} reference"),
            Subject::Index(kind) => write!(f, "{kind} index"),
            Subject::Count(kind) => write!(f, "{kind} count"),
            Subject::ElementCount => f.write_str("element count"),
            Subject::Keyword(word) => f.write_str(word),
        }
    }
}
