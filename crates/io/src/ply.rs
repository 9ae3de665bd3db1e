//! PLY input (ascii, binary little and big endian): triangle maps and
//! polygon meshes.
//!
//! Input: a `vertex` element with scalar `x`, `y`, `z` (any PLY type) and a
//! `face` element with a `vertex_indices` (or `vertex_index`) list; for a
//! triangle map also its map coordinates, either per corner, a per-face
//! `texcoord` list of 6 values `u0 v0 u1 v1 u2 v2` (a map with seams), or
//! per vertex, a scalar pair `u v`, `s t` or `texture_u texture_v` of the
//! `vertex` element (a map without seams: each corner takes its vertex's
//! pair). When both are present the per-face list wins. Other elements and
//! properties (lists included) are skipped. Output: a [`TriMap`] or a
//! [`PolyMesh`].
//!
//! Guard: before reading an element (or a list), its claimed size is checked
//! against the bytes left, so a header claiming 10^14 vertices fails at once
//! and no allocation ever exceeds the file size. Errors name the header line,
//! or the body position (`line L` in ascii, `byte B` in binary) and the
//! record (`face 12`, counted from 0).

use crate::ply_header::{parse_header, texcoord_source, Element, Kind, PlyFormat, Scalar};
use crate::scan::{fits, Tokens};
use crate::PolyMesh;
use dualex_map::error::{
    CountError, EmptyReason, FaceNeed, Format, FormatError, IndexError, Subject, SyntaxError, Token,
};
use dualex_map::{ElementKind, InputError, InputErrorKind, Location, TriMap};

/// Where values come from: ascii tokens or binary bytes.
enum Body<'a> {
    Ascii(Tokens<'a>),
    Binary {
        bytes: &'a [u8],
        pos: usize,
        big: bool,
        base: usize,
    },
}

impl Body<'_> {
    /// The position for messages.
    fn here(&self) -> Location {
        match self {
            Body::Ascii(t) => Location::Line(t.last_line()),
            Body::Binary { pos, base, .. } => Location::Byte(base + pos),
        }
    }

    fn remaining(&self) -> usize {
        match self {
            Body::Ascii(t) => t.remaining(),
            Body::Binary { bytes, pos, .. } => bytes.len().saturating_sub(*pos),
        }
    }

    /// Whether `count` items of `size` binary bytes fit in what is left.
    fn fits(&self, count: u64, binary_size: u64, ascii_tokens: u64) -> bool {
        match self {
            Body::Ascii(_) => fits(count, 2 * ascii_tokens, self.remaining(), 1),
            Body::Binary { .. } => fits(count, binary_size, self.remaining(), 0),
        }
    }

    /// Reads one scalar of type `ty`.
    fn scalar(&mut self, ty: Scalar) -> Result<f64, InputErrorKind> {
        let early = || InputErrorKind::from(SyntaxError::EndsEarly);
        match self {
            Body::Ascii(t) => {
                let (tok, _) = t.next_token().ok_or_else(early)?;
                let (what, token) = (None, Token::new(tok));
                if ty.is_int() {
                    tok.parse::<i64>()
                        .map(|i| i as f64)
                        .map_err(|_| SyntaxError::NotAnInteger { what, token }.into())
                } else {
                    tok.parse::<f64>()
                        .map_err(|_| SyntaxError::NotANumber { what, token }.into())
                }
            }
            Body::Binary {
                bytes, pos, big, ..
            } => {
                let raw = bytes.get(*pos..*pos + ty.size()).ok_or_else(early)?;
                *pos += ty.size();
                Ok(decode(ty, raw, *big))
            }
        }
    }

    /// Reads a list length (a non-negative integer that fits in the bytes
    /// left for items of type `item`).
    fn list_len(
        &mut self,
        count: Scalar,
        item: Scalar,
        name: &str,
    ) -> Result<usize, InputErrorKind> {
        let n = self.scalar(count)?;
        let list = || name.to_string();
        if n < 0.0 || n.fract() != 0.0 {
            return Err(SyntaxError::BadListLength {
                list: list(),
                length: n,
            }
            .into());
        }
        if !self.fits(n as u64, item.size() as u64, 1) {
            return Err(SyntaxError::ListTruncated {
                list: list(),
                items: n,
            }
            .into());
        }
        Ok(n as usize)
    }
}

/// Decodes a binary scalar; `raw` has exactly `ty.size()` bytes.
fn decode(ty: Scalar, raw: &[u8], big: bool) -> f64 {
    fn arr<const K: usize>(raw: &[u8], big: bool) -> [u8; K] {
        let mut a = [0u8; K];
        a.copy_from_slice(raw.get(..K).unwrap_or(&[0; K][..]));
        if big {
            a.reverse();
        }
        a
    }
    match ty {
        Scalar::I8 => i8::from_le_bytes(arr(raw, big)) as f64,
        Scalar::U8 => u8::from_le_bytes(arr(raw, big)) as f64,
        Scalar::I16 => i16::from_le_bytes(arr(raw, big)) as f64,
        Scalar::U16 => u16::from_le_bytes(arr(raw, big)) as f64,
        Scalar::I32 => i32::from_le_bytes(arr(raw, big)) as f64,
        Scalar::U32 => u32::from_le_bytes(arr(raw, big)) as f64,
        Scalar::F32 => f32::from_le_bytes(arr(raw, big)) as f64,
        Scalar::F64 => f64::from_le_bytes(arr(raw, big)),
    }
}

/// One face record: its vertex indices and its texcoord values (if any).
struct FaceRecord<'b> {
    index: usize,
    vertices: &'b [u32],
    texcoord: Option<&'b [f64]>,
}

/// What the body gave: positions and, per face, a callback result.
struct Parsed {
    positions: Vec<[f64; 3]>,
    /// Per-vertex map coordinates, read only when a triangle map needs them
    /// (no per-face `texcoord`).
    vertex_uv: Option<Vec<[f64; 2]>>,
    saw_vertices: bool,
    saw_faces: bool,
}

/// Parses a PLY triangle map (see the module docs).
pub fn parse_ply(bytes: &[u8]) -> Result<TriMap, InputError> {
    let mut simplices = Vec::new();
    let mut coords = Vec::new();
    let parsed = parse_body(bytes, true, |f| {
        let [a, b, c] = f.vertices else {
            return Err(face_size(&f, FaceNeed::OnlyTriangles));
        };
        simplices.push([*a, *b, *c]);
        // without a per-face list the corners take their vertices' pairs (below)
        let Some(uv) = f.texcoord else {
            return Ok(());
        };
        let face = ElementKind::Face.at(f.index);
        let [u0, v0, u1, v1, u2, v2] = uv else {
            return Err(face.error(CountError::Texcoords { values: uv.len() }));
        };
        if uv.iter().any(|x| !x.is_finite()) {
            let what = Subject::Texcoord;
            return Err(face.error(InputErrorKind::NonFinite { what, token: None }));
        }
        coords.push([[*u0, *v0], [*u1, *v1], [*u2, *v2]]);
        Ok(())
    })?;
    if let Some(uv) = &parsed.vertex_uv {
        // an index out of range gets (0, 0) here and fails `validate` below
        let at = |v: u32| uv.get(v as usize).copied().unwrap_or_default();
        coords = simplices.iter().map(|s| s.map(at)).collect();
    }
    if simplices.is_empty() {
        return Err(CountError::Empty {
            what: ElementKind::Triangle,
            reason: Some(EmptyReason::EmptyElement("face")),
        }
        .into());
    }
    let map = TriMap {
        positions: parsed.positions,
        simplices,
        coords,
    };
    map.validate()?;
    Ok(map)
}

/// Parses a PLY polygon mesh: positions and faces of 3 or more vertices.
pub fn parse_polygon_ply(bytes: &[u8]) -> Result<PolyMesh, InputError> {
    let mut faces = Vec::new();
    let parsed = parse_body(bytes, false, |f| {
        if f.vertices.len() < 3 {
            return Err(face_size(&f, FaceNeed::AtLeastThree));
        }
        faces.push(f.vertices.to_vec());
        Ok(())
    })?;
    let nv = parsed.positions.len();
    for (i, face) in faces.iter().enumerate() {
        if let Some(&v) = face.iter().find(|&&v| v as usize >= nv) {
            return Err(IndexError::RefersToVertex {
                owner: ElementKind::Face.at(i),
                corner: None,
                vertex: v.into(),
                count: nv,
            }
            .into());
        }
    }
    Ok(PolyMesh {
        positions: parsed.positions,
        faces,
    })
}

/// Face `f` of a size that is not read.
fn face_size(f: &FaceRecord<'_>, need: FaceNeed) -> InputErrorKind {
    CountError::FaceSize {
        face: Some(f.index as u64),
        vertices: f.vertices.len(),
        need,
    }
    .into()
}

/// Reads header and body; `on_face` receives each face record.
fn parse_body(
    bytes: &[u8],
    want_texcoord: bool,
    mut on_face: impl FnMut(FaceRecord<'_>) -> Result<(), InputErrorKind>,
) -> Result<Parsed, InputError> {
    let header = parse_header(bytes)?;
    let rest = bytes.get(header.body..).unwrap_or_default();
    let mut body = match header.format {
        PlyFormat::Ascii => {
            let text = crate::scan::as_text(bytes, Format::Ply)?;
            Body::Ascii(Tokens::new(
                text.get(header.body..).unwrap_or_default(),
                header.body_line,
            ))
        }
        f => Body::Binary {
            bytes: rest,
            pos: 0,
            big: f == PlyFormat::BinaryBigEndian,
            base: header.body,
        },
    };
    let uv_slots = if want_texcoord {
        texcoord_source(&header.elements)?
    } else {
        None
    };
    let mut parsed = Parsed {
        positions: Vec::new(),
        vertex_uv: None,
        saw_vertices: false,
        saw_faces: false,
    };
    for el in &header.elements {
        check_fits(&body, el)?;
        match el.name.as_str() {
            "vertex" if !parsed.saw_vertices => {
                (parsed.positions, parsed.vertex_uv) = read_vertices(&mut body, el, uv_slots)?;
                parsed.saw_vertices = true;
            }
            "face" if !parsed.saw_faces => {
                read_faces(&mut body, el, &mut on_face)?;
                parsed.saw_faces = true;
            }
            _ => skip_element(&mut body, el)?,
        }
    }
    if !parsed.saw_vertices || !parsed.saw_faces {
        let missing = if parsed.saw_vertices {
            "face"
        } else {
            "vertex"
        };
        return Err(FormatError::MissingElement(missing).into());
    }
    Ok(parsed)
}

/// Fails fast when an element's claimed count cannot fit in the bytes left.
fn check_fits(body: &Body<'_>, el: &Element) -> Result<(), InputError> {
    let n_props = el.props.len() as u64;
    if el.count == 0 || n_props == 0 || body.fits(el.count, el.min_binary_size(), n_props) {
        return Ok(());
    }
    let e = CountError::ElementExceedsBytes {
        element: el.name.clone(),
        count: el.count,
        bytes: body.remaining(),
    };
    Err(InputError::at_line(el.line, e))
}

/// An error at the current body position, about record `i` of `el`.
fn at(body: &Body<'_>, el: &Element, i: u64, what: InputErrorKind) -> InputError {
    let record = dualex_map::Element {
        kind: ElementKind::from_name(&el.name),
        index: i,
    };
    InputError::at(body.here(), record.error(what))
}

/// Positions and, when asked, per-vertex map coordinates.
type Vertices = (Vec<[f64; 3]>, Option<Vec<[f64; 2]>>);

/// Positions, and per-vertex map coordinates when `uv_slots` names them.
fn read_vertices(
    body: &mut Body<'_>,
    el: &Element,
    uv_slots: Option<[usize; 2]>,
) -> Result<Vertices, InputError> {
    let mut slots = [usize::MAX; 3];
    for (k, name) in ["x", "y", "z"].iter().enumerate() {
        let p = el
            .find(&[name])
            .filter(|&p| matches!(el.props[p].kind, Kind::Scalar(_)));
        slots[k] = p.ok_or_else(|| {
            let e = FormatError::MissingScalarProperty {
                element: "vertex",
                property: name,
            };
            InputError::at_line(el.line, e)
        })?;
    }
    // `check_fits` bounded `count` by the file size: this allocation is safe.
    let mut positions = Vec::with_capacity(el.count as usize);
    let mut uvs = Vec::with_capacity(if uv_slots.is_some() {
        positions.capacity()
    } else {
        0
    });
    for i in 0..el.count {
        let (mut p, mut uv) = ([0.0; 3], [0.0; 2]);
        for (j, prop) in el.props.iter().enumerate() {
            match prop.kind {
                Kind::Scalar(ty) => {
                    let x = body.scalar(ty).map_err(|m| at(body, el, i, m))?;
                    if let Some(k) = slots.iter().position(|&s| s == j) {
                        if !x.is_finite() {
                            let what = Subject::Coordinate;
                            let e = InputErrorKind::NonFinite { what, token: None };
                            return Err(at(body, el, i, e));
                        }
                        p[k] = x;
                    } else if let Some(k) = uv_slots.and_then(|s| s.iter().position(|&s| s == j)) {
                        if !x.is_finite() {
                            let what = Subject::NamedTextureCoordinate(prop.name.clone());
                            let e = InputErrorKind::NonFinite { what, token: None };
                            return Err(at(body, el, i, e));
                        }
                        uv[k] = x;
                    }
                }
                Kind::List { count, item } => {
                    skip_list(body, count, item, &prop.name).map_err(|m| at(body, el, i, m))?
                }
            }
        }
        positions.push(p);
        if uv_slots.is_some() {
            uvs.push(uv);
        }
    }
    Ok((positions, uv_slots.map(|_| uvs)))
}

fn read_faces(
    body: &mut Body<'_>,
    el: &Element,
    on_face: &mut impl FnMut(FaceRecord<'_>) -> Result<(), InputErrorKind>,
) -> Result<(), InputError> {
    let list = |names: &[&str]| {
        el.find(names)
            .filter(|&p| matches!(el.props[p].kind, Kind::List { .. }))
    };
    let vi = list(&["vertex_indices", "vertex_index"]).ok_or_else(|| {
        let e = FormatError::MissingListProperty {
            element: "face",
            property: "vertex_indices",
        };
        InputError::at_line(el.line, e)
    })?;
    let tc = list(&["texcoord"]);
    let (mut verts, mut uvs) = (Vec::new(), Vec::new());
    for i in 0..el.count {
        for (j, prop) in el.props.iter().enumerate() {
            let r = match prop.kind {
                Kind::Scalar(ty) => body.scalar(ty).map(|_| ()),
                Kind::List { count, item } if j == vi => {
                    read_indices(body, count, item, &mut verts)
                }
                Kind::List { count, item } if Some(j) == tc => {
                    read_list(body, count, item, &mut uvs)
                }
                Kind::List { count, item } => skip_list(body, count, item, &prop.name),
            };
            r.map_err(|m| at(body, el, i, m))?;
        }
        let record = FaceRecord {
            index: i as usize,
            vertices: &verts,
            texcoord: tc.map(|_| uvs.as_slice()),
        };
        on_face(record).map_err(|e| InputError::at(body.here(), e))?;
    }
    Ok(())
}

fn read_list(
    body: &mut Body<'_>,
    count: Scalar,
    item: Scalar,
    out: &mut Vec<f64>,
) -> Result<(), InputErrorKind> {
    out.clear();
    let n = body.list_len(count, item, "texcoord")?;
    for _ in 0..n {
        out.push(body.scalar(item)?);
    }
    Ok(())
}

fn read_indices(
    body: &mut Body<'_>,
    count: Scalar,
    item: Scalar,
    out: &mut Vec<u32>,
) -> Result<(), InputErrorKind> {
    out.clear();
    let n = body.list_len(count, item, "vertex_indices")?;
    for _ in 0..n {
        let x = body.scalar(item)?;
        if !(0.0..=u32::MAX as f64).contains(&x) || x.fract() != 0.0 {
            return Err(IndexError::NotValid { value: x }.into());
        }
        out.push(x as u32);
    }
    Ok(())
}

fn skip_list(
    body: &mut Body<'_>,
    count: Scalar,
    item: Scalar,
    name: &str,
) -> Result<(), InputErrorKind> {
    let n = body.list_len(count, item, name)?;
    for _ in 0..n {
        body.scalar(item)?;
    }
    Ok(())
}

fn skip_element(body: &mut Body<'_>, el: &Element) -> Result<(), InputError> {
    if el.props.is_empty() {
        return Ok(());
    }
    for i in 0..el.count {
        for prop in &el.props {
            let r = match prop.kind {
                Kind::Scalar(ty) => body.scalar(ty).map(|_| ()),
                Kind::List { count, item } => skip_list(body, count, item, &prop.name),
            };
            r.map_err(|m| at(body, el, i, m))?;
        }
    }
    Ok(())
}

#[cfg(test)]
#[path = "ply_tests.rs"]
mod tests;
