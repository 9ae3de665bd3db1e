//! [`FormatError`]: a file that is not of its format, or uses a part of
//! the format that is not read.
//!
//! Input: the readers' findings on the whole file, its header or a record.
//! Output: the message, naming the format, the element, property or
//! feature. Invariants: one line, the readers' own wording.

use super::Token;
use std::fmt;

/// A file format read by `dualex-io`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Format {
    /// Wavefront OBJ.
    Obj,
    /// PLY.
    Ply,
    /// HexEx `.hexex`.
    Hexex,
    /// OpenVolumeMesh ASCII `.ovm`.
    Ovm,
    /// MEDIT `.mesh`.
    Medit,
    /// Legacy ASCII VTK.
    Vtk,
}

/// Why bytes are not text.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NotTextReason {
    /// A NUL byte.
    NulByte,
    /// Bytes that are not UTF-8.
    InvalidUtf8,
}

/// Not a file of its format, or a feature of the format not read.
#[derive(Clone, Debug, PartialEq)]
pub enum FormatError {
    /// A file extension no reader takes (`extension` without its dot).
    UnsupportedExtension {
        /// The extension, lower case.
        extension: String,
        /// The extensions the reader takes.
        allowed: &'static [&'static str],
    },
    /// Not a text file (`reason`: what was found first, when told).
    NotText {
        /// The format expected.
        format: Format,
        /// What makes the bytes not text.
        reason: Option<NotTextReason>,
    },
    /// The file does not start as the format does (PLY's `ply`, VTK's
    /// `# vtk DataFile`).
    NotFormat(Format),
    /// A binary body (VTK, `.ovm`).
    Binary(Format),
    /// A MEDIT section other than `Vertices` and `Hexahedra`.
    MeditSection(String),
    /// A PLY `format` other than ascii and the two binary ones.
    PlyFormat(Token),
    /// A PLY property type that is not one of PLY's.
    PlyType(Token),
    /// A VTK cell type other than quads (9) and hexes (12).
    CellType(u8),
    /// A VTK cell unlike the first (other type, or wrong vertex count).
    MixedCells {
        /// Its vertices.
        vertices: usize,
        /// Its VTK type.
        cell_type: u8,
    },
    /// An OpenVolumeMesh cell that is not a tet.
    NotATet(NotATet),
    /// A PLY file without the `vertex` or the `face` element.
    MissingElement(&'static str),
    /// A PLY element without a scalar property it needs.
    MissingScalarProperty {
        /// The element.
        element: &'static str,
        /// The property.
        property: &'static str,
    },
    /// A PLY element without a list property it needs.
    MissingListProperty {
        /// The element.
        element: &'static str,
        /// The property.
        property: &'static str,
    },
    /// One of a PLY vertex's texture coordinate pair without the other.
    UnpairedTextureCoordinate {
        /// The property present.
        has: &'static str,
        /// The one missing.
        lacks: &'static str,
    },
    /// A PLY file with neither per-corner nor per-vertex map coordinates.
    NoPlyMapCoordinates,
    /// An `.ovm` property of another type than `vec3d`.
    PropertyType {
        /// The property.
        property: &'static str,
        /// Its type in the file.
        found: String,
    },
    /// An `.ovm` file without the halfface property holding the map.
    NoHalffaceProperty(&'static str),
}

/// Why an OpenVolumeMesh cell is not a tet.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum NotATet {
    /// Not 4 halffaces.
    Halffaces(usize),
    /// A face that is not a triangle.
    NonTriangleFace,
    /// All faces on three vertices.
    ThreeVertices,
    /// A vertex not opposite exactly one face.
    NotOpposite {
        /// The vertex.
        vertex: u32,
    },
    /// Faces spanning more than 4 vertices.
    MoreThanFourVertices,
}

impl Format {
    /// The name in messages.
    pub fn name(self) -> &'static str {
        match self {
            Format::Obj => "OBJ",
            Format::Ply => "PLY",
            Format::Hexex => "hexex",
            Format::Ovm => "ovm",
            Format::Medit => "MEDIT",
            Format::Vtk => "VTK",
        }
    }
}

impl fmt::Display for FormatError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            FormatError::UnsupportedExtension { extension, allowed } => {
                let list: Vec<String> = allowed.iter().map(|e| format!(".{e}")).collect();
                write!(
                    f,
                    "unsupported input format `.{extension}`; use {}",
                    list.join(", ")
                )
            }
            FormatError::NotText { format, reason } => {
                let name = format.name();
                match (format, reason) {
                    (_, Some(NotTextReason::NulByte)) => {
                        write!(f, "not a text {name} file (NUL byte)")
                    }
                    (_, Some(NotTextReason::InvalidUtf8)) => {
                        write!(f, "not a text {name} file (invalid UTF-8)")
                    }
                    (Format::Vtk, None) => f.write_str("not a text file (legacy ASCII VTK expected)"),
                    (_, None) => write!(f, "not a text {name} file"),
                }
            }
            FormatError::NotFormat(format) => match format {
                Format::Ply => f.write_str("not a PLY file (it does not start with `ply`)"),
                Format::Vtk => f.write_str("not a VTK file (no `# vtk DataFile` header)"),
                other => write!(f, "not a {} file", other.name()),
            },
            FormatError::Binary(format) => match format {
                Format::Ovm => {
                    f.write_str("binary .ovm files are not supported; write it as ASCII")
                }
                other => write!(f, "binary {} is not supported", other.name()),
            },
            FormatError::MeditSection(s) => write!(
                f,
                "unsupported MEDIT section `{s}` (only Vertices and Hexahedra)"
            ),
            FormatError::PlyFormat(t) => write!(
                f,
                "unknown PLY format {t} (expected ascii, binary_little_endian or binary_big_endian)"
            ),
            FormatError::PlyType(t) => write!(f, "unknown PLY type {t}"),
            FormatError::CellType(t) => {
                write!(f, "type {t}; only quads (9) and hexes (12) are read")
            }
            FormatError::MixedCells {
                vertices,
                cell_type,
            } => write!(
                f,
                "{vertices} vertices of type {cell_type}; all cells must be quads or all hexes"
            ),
            FormatError::NotATet(why) => why.fmt(f),
            FormatError::MissingElement(e) => write!(f, "PLY file has no `{e}` element"),
            FormatError::MissingScalarProperty { element, property } => write!(
                f,
                "element `{element}` has no scalar property `{property}`"
            ),
            FormatError::MissingListProperty { element, property } => {
                write!(f, "element `{element}` has no `{property}` list property")
            }
            FormatError::UnpairedTextureCoordinate { has, lacks } => write!(
                f,
                "element `vertex` has property `{has}` but no `{lacks}` (per-vertex texture coordinates need both)"
            ),
            FormatError::NoPlyMapCoordinates => f.write_str(
                "element `face` has no `texcoord` list property (per-corner u0 v0 u1 v1 u2 v2), \
                 and element `vertex` no `u v`, `s t` or `texture_u texture_v` pair",
            ),
            FormatError::PropertyType { property, found } => write!(
                f,
                "property \"{property}\" has type `{found}`, expected `vec3d`"
            ),
            FormatError::NoHalffaceProperty(p) => write!(
                f,
                "no halfface property \"{p}\" (vec3d): not a HexHex map"
            ),
        }
    }
}

impl fmt::Display for NotATet {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            NotATet::Halffaces(n) => write!(f, "{n} halffaces; only tets (4) are supported"),
            NotATet::NonTriangleFace => f.write_str("a face that is not a triangle"),
            NotATet::ThreeVertices => f.write_str("all faces on three vertices"),
            NotATet::NotOpposite { vertex } => write!(
                f,
                "not a tet: vertex {vertex} is not opposite exactly one face"
            ),
            NotATet::MoreThanFourVertices => {
                f.write_str("not a tet: its faces span more than 4 vertices")
            }
        }
    }
}
