//! PLY header: format, elements and their properties.
//!
//! Input: the bytes of a PLY file. Output: a [`Header`] and the byte offset
//! where the body starts (just after the `end_header` line); for a triangle
//! map, where its coordinates come from ([`texcoord_source`]). Counts are read
//! as `u64` and *not* trusted: the body reader checks each against the bytes
//! left before allocating anything.

use dualex_map::error::{Format, FormatError, Subject, SyntaxError, Token};
use dualex_map::{InputError, InputErrorKind};

/// Encoding of the body.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PlyFormat {
    /// `format ascii 1.0`
    Ascii,
    /// `format binary_little_endian 1.0`
    BinaryLittleEndian,
    /// `format binary_big_endian 1.0`
    BinaryBigEndian,
}

/// A scalar type of PLY.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Scalar {
    I8,
    U8,
    I16,
    U16,
    I32,
    U32,
    F32,
    F64,
}

impl Scalar {
    fn from_name(name: &str) -> Option<Scalar> {
        Some(match name {
            "char" | "int8" => Scalar::I8,
            "uchar" | "uint8" => Scalar::U8,
            "short" | "int16" => Scalar::I16,
            "ushort" | "uint16" => Scalar::U16,
            "int" | "int32" => Scalar::I32,
            "uint" | "uint32" => Scalar::U32,
            "float" | "float32" => Scalar::F32,
            "double" | "float64" => Scalar::F64,
            _ => return None,
        })
    }

    /// Size in bytes in a binary body.
    pub(crate) fn size(self) -> usize {
        match self {
            Scalar::I8 | Scalar::U8 => 1,
            Scalar::I16 | Scalar::U16 => 2,
            Scalar::I32 | Scalar::U32 | Scalar::F32 => 4,
            Scalar::F64 => 8,
        }
    }

    /// Whether the type holds integers.
    pub(crate) fn is_int(self) -> bool {
        !matches!(self, Scalar::F32 | Scalar::F64)
    }
}

/// A property: a scalar, or a list with its count and item types.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub(crate) enum Kind {
    Scalar(Scalar),
    List { count: Scalar, item: Scalar },
}

/// A property of an element.
#[derive(Clone, Debug)]
pub(crate) struct Property {
    pub(crate) name: String,
    pub(crate) kind: Kind,
}

/// An element: name, claimed record count, properties, header line.
#[derive(Clone, Debug)]
pub(crate) struct Element {
    pub(crate) name: String,
    pub(crate) count: u64,
    pub(crate) props: Vec<Property>,
    pub(crate) line: usize,
}

impl Element {
    /// Index of the property called one of `names`.
    pub(crate) fn find(&self, names: &[&str]) -> Option<usize> {
        self.props
            .iter()
            .position(|p| names.contains(&p.name.as_str()))
    }

    /// Smallest size of one record in a binary body (lists empty).
    pub(crate) fn min_binary_size(&self) -> u64 {
        let size = |p: &Property| match p.kind {
            Kind::Scalar(s) => s.size(),
            Kind::List { count, .. } => count.size(),
        };
        self.props.iter().map(|p| size(p) as u64).sum()
    }
}

/// The parsed header.
#[derive(Clone, Debug)]
pub(crate) struct Header {
    pub(crate) format: PlyFormat,
    pub(crate) elements: Vec<Element>,
    /// Byte offset of the body.
    pub(crate) body: usize,
    /// Line number of the first body line (for ascii messages).
    pub(crate) body_line: usize,
}

/// Parses the header; errors name the header line.
pub(crate) fn parse_header(bytes: &[u8]) -> Result<Header, InputError> {
    if !bytes.starts_with(b"ply") {
        return Err(InputError::at_line(1, FormatError::NotFormat(Format::Ply)));
    }
    let mut format = None;
    let mut elements: Vec<Element> = Vec::new();
    let mut pos = 0;
    let mut ln = 0;
    loop {
        ln += 1;
        let Some(len) = bytes
            .get(pos..)
            .and_then(|rest| rest.iter().position(|&b| b == b'\n'))
        else {
            return Err(InputError::at_line(ln, SyntaxError::NoEndHeader));
        };
        let raw = bytes.get(pos..pos + len).unwrap_or_default();
        pos += len + 1;
        let line = std::str::from_utf8(raw)
            .map_err(|_| InputError::at_line(ln, SyntaxError::HeaderLineNotText))?
            .trim_end_matches('\r');
        let at = |k: InputErrorKind| InputError::at_line(ln, k);
        let toks: Vec<&str> = line.split_ascii_whitespace().collect();
        match toks.as_slice() {
            ["end_header"] => break,
            ["ply"] if ln == 1 => {}
            [] | ["comment", ..] | ["obj_info", ..] => {}
            ["format", f, _version] => format = Some(parse_format(f).map_err(at)?),
            ["element", name, count] => elements.push(Element {
                name: name.to_string(),
                count: count.parse().map_err(|_| {
                    at(SyntaxError::NotANonNegativeInteger {
                        what: Subject::ElementCount,
                        token: Token::new(count),
                        hint: false,
                    }
                    .into())
                })?,
                props: Vec::new(),
                line: ln,
            }),
            ["property", rest @ ..] => {
                let el = elements
                    .last_mut()
                    .ok_or_else(|| at(SyntaxError::PropertyBeforeElement.into()))?;
                el.props.push(parse_property(rest).map_err(at)?);
            }
            _ => {
                let e = SyntaxError::UnexpectedHeaderLine(Token::new(line));
                return Err(at(e.into()));
            }
        }
    }
    let format = format.ok_or_else(|| InputError::at_line(ln, SyntaxError::NoFormatLine))?;
    Ok(Header {
        format,
        elements,
        body: pos,
        body_line: ln + 1,
    })
}

fn parse_format(f: &str) -> Result<PlyFormat, InputErrorKind> {
    match f {
        "ascii" => Ok(PlyFormat::Ascii),
        "binary_little_endian" => Ok(PlyFormat::BinaryLittleEndian),
        "binary_big_endian" => Ok(PlyFormat::BinaryBigEndian),
        _ => Err(FormatError::PlyFormat(Token::new(f)).into()),
    }
}

/// `property TYPE NAME` or `property list CTYPE ITYPE NAME` (after `property`).
fn parse_property(toks: &[&str]) -> Result<Property, InputErrorKind> {
    let ty = |name: &str| {
        Scalar::from_name(name)
            .ok_or_else(|| InputErrorKind::from(FormatError::PlyType(Token::new(name))))
    };
    let (kind, name) = match toks {
        ["list", count, item, name] => {
            let count = ty(count)?;
            if !count.is_int() {
                return Err(SyntaxError::ListCountNotInteger(Token::new(name)).into());
            }
            (
                Kind::List {
                    count,
                    item: ty(item)?,
                },
                name,
            )
        }
        [t, name] => (Kind::Scalar(ty(t)?), name),
        _ => return Err(SyntaxError::MalformedProperty(toks.join(" ")).into()),
    };
    Ok(Property {
        name: name.to_string(),
        kind,
    })
}

/// The first `vertex` and `face` elements (the ones the body reader reads).
fn first<'h>(elements: &'h [Element], name: &str) -> Option<&'h Element> {
    elements.iter().find(|e| e.name == name)
}

/// Where a triangle map's coordinates come from: `None` for the per-face
/// `texcoord` list, else the `vertex` properties of the per-vertex pair.
/// Checked on the header, before any body is read.
pub(crate) fn texcoord_source(elements: &[Element]) -> Result<Option<[usize; 2]>, InputError> {
    const PAIRS: [[&str; 2]; 3] = [["u", "v"], ["s", "t"], ["texture_u", "texture_v"]];
    let (Some(face), Some(vertex)) = (first(elements, "face"), first(elements, "vertex")) else {
        return Ok(None); // `parse_body` names the missing element
    };
    let is_list = |p: usize| matches!(face.props[p].kind, Kind::List { .. });
    if face.find(&["texcoord"]).is_some_and(is_list) {
        return Ok(None);
    }
    let scalar = |name: &str| {
        vertex
            .find(&[name])
            .filter(|&p| matches!(vertex.props[p].kind, Kind::Scalar(_)))
    };
    let slots = PAIRS.map(|[a, b]| (scalar(a), scalar(b)));
    if let Some(&(Some(u), Some(v))) = slots.iter().find(|s| matches!(s, (Some(_), Some(_)))) {
        return Ok(Some([u, v]));
    }
    if let Some((k, (u, _))) = slots
        .iter()
        .enumerate()
        .find(|(_, s)| s.0.is_some() != s.1.is_some())
    {
        let [a, b] = PAIRS[k];
        let (has, lacks) = if u.is_some() { (a, b) } else { (b, a) };
        let e = FormatError::UnpairedTextureCoordinate { has, lacks };
        return Err(InputError::at_line(vertex.line, e));
    }
    Err(InputError::at_line(
        face.line,
        FormatError::NoPlyMapCoordinates,
    ))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_elements_and_properties() {
        let text = b"ply\r\nformat binary_big_endian 1.0\r\ncomment hi\r\nelement vertex 3\r\n\
            property float x\r\nproperty uint8 red\r\nelement face 1\r\n\
            property list uchar int vertex_indices\r\nend_header\r\nXYZ";
        let h = parse_header(text).unwrap();
        assert_eq!(h.format, PlyFormat::BinaryBigEndian);
        assert_eq!(h.elements.len(), 2);
        assert_eq!(h.elements[0].count, 3);
        assert_eq!(h.elements[0].min_binary_size(), 5);
        assert_eq!(
            h.elements[1].props[0].kind,
            Kind::List {
                count: Scalar::U8,
                item: Scalar::I32
            }
        );
        assert_eq!(&text[h.body..], b"XYZ");
        assert_eq!(h.body_line, 10);
    }

    #[test]
    fn bad_headers_name_the_line() {
        let e = |t: &[u8]| parse_header(t).unwrap_err().to_string();
        assert_eq!(
            e(b"obj\n"),
            "line 1: not a PLY file (it does not start with `ply`)"
        );
        assert_eq!(
            e(b"ply\nformat ascii 1.0\nelement vertex 3\n"),
            "line 4: PLY header has no `end_header` line (truncated file?)"
        );
        assert_eq!(e(b"ply\nformat text 1.0\nend_header\n"), "line 2: unknown PLY format `text` (expected ascii, binary_little_endian or binary_big_endian)");
        assert_eq!(
            e(b"ply\nformat ascii 1.0\nelement vertex -3\nend_header\n"),
            "line 3: element count `-3` is not a non-negative integer"
        );
        assert_eq!(
            e(b"ply\nformat ascii 1.0\nproperty float x\nend_header\n"),
            "line 3: property before any element"
        );
        assert_eq!(
            e(b"ply\nformat ascii 1.0\nelement v 1\nproperty quad x\nend_header\n"),
            "line 4: unknown PLY type `quad`"
        );
        assert_eq!(
            e(b"ply\nformat ascii 1.0\nelement v 1\nproperty list float int x\nend_header\n"),
            "line 4: list count type of `x` is not an integer type"
        );
        assert_eq!(
            e(b"ply\nelement v 1\nend_header\n"),
            "line 3: PLY header has no `format` line"
        );
    }
}
