//! Wavefront OBJ input: triangle maps (`f v/vt`) and polygon meshes.
//!
//! Input: bytes of a text OBJ file. Read statements: `v x y z [w…]`,
//! `vt u v [w]`, `f c1 c2 c3 …` with corners `v`, `v/vt`, `v//vn`,
//! `v/vt/vn`; indices are 1-based, negative ones count back from the last
//! element defined before the line. Comments, blank lines, CRLF and every
//! other keyword (`vn`, `g`, `o`, `s`, `usemtl`, `mtllib`, `l`, …) are
//! skipped. Output: a [`TriMap`] whose corner `c` of triangle `s` carries
//! the `vt` of that corner, or a [`PolyMesh`]. Every error names its line;
//! corners in messages are counted from 1 as on the line.

use crate::scan::{as_text, parse_finite};
use crate::PolyMesh;
use dualex_map::error::{
    CountError, EmptyReason, FaceNeed, Format, IndexError, Subject, SyntaxError, Token,
};
use dualex_map::{ElementKind, InputError, InputErrorKind, TriMap};

/// One `f` line of a triangle map: vertex and texture indices (0-based,
/// not yet range-checked against the final counts) and its line.
struct RawTri {
    v: [u32; 3],
    vt: [u32; 3],
    line: usize,
}

/// Parses a text OBJ triangle map (see the module docs).
pub fn parse_obj(bytes: &[u8]) -> Result<TriMap, InputError> {
    if let Some(map) = crate::fast::obj(bytes) {
        return Ok(map);
    }
    parse_obj_sequential(bytes)
}

/// The sequential OBJ reader: the reference of [`crate::fast::obj`], and
/// the one that reports errors.
pub(crate) fn parse_obj_sequential(bytes: &[u8]) -> Result<TriMap, InputError> {
    let text = as_text(bytes, Format::Obj)?;
    let mut positions = Vec::new();
    let mut uvs: Vec<[f64; 2]> = Vec::new();
    let mut tris: Vec<RawTri> = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let ln = i + 1;
        let mut toks = line.split_ascii_whitespace();
        let Some(kw) = toks.next() else { continue };
        let at = |k: InputErrorKind| InputError::at_line(ln, k);
        match kw {
            "v" => positions.push(read_position(toks).map_err(at)?),
            "vt" => uvs.push(read_uv(toks).map_err(at)?),
            "f" => {
                let (v, vt) = read_tri(toks, positions.len(), uvs.len()).map_err(at)?;
                tris.push(RawTri { v, vt, line: ln });
            }
            _ => check_skippable(kw).map_err(at)?,
        }
    }
    if tris.is_empty() {
        return Err(no_faces(ElementKind::Triangle));
    }
    let mut map = TriMap {
        positions,
        simplices: Vec::with_capacity(tris.len()),
        coords: Vec::with_capacity(tris.len()),
    };
    for t in &tris {
        let at = |k: InputErrorKind| InputError::at_line(t.line, k);
        for c in 0..3 {
            check_range(t.v[c], map.positions.len(), c, ElementKind::Vertex).map_err(at)?;
            let vt = ElementKind::TextureCoordinate;
            check_range(t.vt[c], uvs.len(), c, vt).map_err(at)?;
        }
        map.simplices.push(t.v);
        map.coords.push(t.vt.map(|i| uvs[i as usize]));
    }
    map.validate()?;
    Ok(map)
}

/// Parses a text OBJ polygon mesh: positions and faces of 3 or more
/// vertices (texture and normal indices are ignored).
pub fn parse_polygon_obj(bytes: &[u8]) -> Result<PolyMesh, InputError> {
    let text = as_text(bytes, Format::Obj)?;
    let mut mesh = PolyMesh::default();
    let mut lines = Vec::new();
    for (i, line) in text.lines().enumerate() {
        let ln = i + 1;
        let mut toks = line.split_ascii_whitespace();
        let Some(kw) = toks.next() else { continue };
        let at = |k: InputErrorKind| InputError::at_line(ln, k);
        match kw {
            "v" => mesh.positions.push(read_position(toks).map_err(at)?),
            "f" => {
                let face = read_polygon(toks, mesh.positions.len()).map_err(at)?;
                mesh.faces.push(face);
                lines.push(ln);
            }
            _ => check_skippable(kw).map_err(at)?,
        }
    }
    if mesh.faces.is_empty() {
        return Err(no_faces(ElementKind::Face));
    }
    for (face, &ln) in mesh.faces.iter().zip(&lines) {
        for (c, &v) in face.iter().enumerate() {
            check_range(v, mesh.positions.len(), c, ElementKind::Vertex)
                .map_err(|k| InputError::at_line(ln, k))?;
        }
    }
    Ok(mesh)
}

/// No `what` read: the file has no `f` line.
fn no_faces(what: ElementKind) -> InputError {
    let reason = Some(EmptyReason::NoFaceLine);
    CountError::Empty { what, reason }.into()
}

/// `v x y z [w …]` after the keyword: the first three must be finite numbers.
fn read_position<'a>(toks: impl Iterator<Item = &'a str>) -> Result<[f64; 3], InputErrorKind> {
    let mut p = [0.0; 3];
    let mut n = 0;
    for tok in toks {
        if tok.starts_with('#') {
            break;
        }
        let x = parse_finite(tok, Subject::VertexCoordinate)?;
        if let Some(slot) = p.get_mut(n) {
            *slot = x;
        }
        n += 1;
    }
    if n < 3 {
        return Err(CountError::VertexCoordinates { found: n }.into());
    }
    Ok(p)
}

/// `vt u v [w]` after the keyword: `u` and `v` must be finite numbers.
fn read_uv<'a>(toks: impl Iterator<Item = &'a str>) -> Result<[f64; 2], InputErrorKind> {
    let mut uv = [0.0; 2];
    let mut n = 0;
    for tok in toks {
        if tok.starts_with('#') {
            break;
        }
        let x = parse_finite(tok, Subject::TextureCoordinate)?;
        if let Some(slot) = uv.get_mut(n) {
            *slot = x;
        }
        n += 1;
    }
    if n < 2 {
        return Err(CountError::TextureValues { found: n }.into());
    }
    Ok(uv)
}

/// The corners of an `f` line of a triangle map, given the numbers of `v`
/// and `vt` defined so far (for negative indices).
fn read_tri<'a>(
    toks: impl Iterator<Item = &'a str>,
    nv: usize,
    nvt: usize,
) -> Result<([u32; 3], [u32; 3]), InputErrorKind> {
    let corners: Vec<&str> = toks.take_while(|t| !t.starts_with('#')).collect();
    if corners.len() != 3 {
        let need = if corners.len() < 3 {
            FaceNeed::Triangle
        } else {
            FaceNeed::OnlyTriangles
        };
        return Err(face_size(corners.len(), need));
    }
    let mut v = [0; 3];
    let mut vt = [0; 3];
    for (c, corner) in corners.iter().enumerate() {
        let mut parts = corner.split('/');
        let vi = parts.next().unwrap_or("");
        v[c] = resolve(vi, nv, c, ElementKind::Vertex)?;
        match parts.next() {
            Some(ti) if !ti.is_empty() => {
                vt[c] = resolve(ti, nvt, c, ElementKind::TextureCoordinate)?
            }
            _ => return Err(SyntaxError::NoTextureCoordinate { corner: c + 1 }.into()),
        }
    }
    Ok((v, vt))
}

/// The vertex indices of an `f` line of a polygon mesh.
fn read_polygon<'a>(
    toks: impl Iterator<Item = &'a str>,
    nv: usize,
) -> Result<Vec<u32>, InputErrorKind> {
    let corners = toks.take_while(|t| !t.starts_with('#'));
    let vertex = |(c, corner): (usize, &str)| {
        resolve(
            corner.split('/').next().unwrap_or(""),
            nv,
            c,
            ElementKind::Vertex,
        )
    };
    let face = corners
        .enumerate()
        .map(vertex)
        .collect::<Result<Vec<u32>, InputErrorKind>>()?;
    if face.len() < 3 {
        return Err(face_size(face.len(), FaceNeed::AtLeastThree));
    }
    Ok(face)
}

/// A face of `vertices` corners, not what a face needs.
fn face_size(vertices: usize, need: FaceNeed) -> InputErrorKind {
    let face = None;
    CountError::FaceSize {
        face,
        vertices,
        need,
    }
    .into()
}

/// A 1-based or negative OBJ index to a 0-based one; `defined` is the number
/// of elements defined so far. Positive indices are range-checked later.
fn resolve(
    tok: &str,
    defined: usize,
    corner: usize,
    what: ElementKind,
) -> Result<u32, InputErrorKind> {
    let at = |e: InputErrorKind| ElementKind::FaceCorner.at(corner + 1).error(e);
    let Ok(index) = tok.parse::<i64>() else {
        let what = Some(Subject::Index(what));
        let token = Token::new(tok);
        return Err(at(SyntaxError::NotAnInteger { what, token }.into()));
    };
    let zero_based = if index > 0 {
        index - 1
    } else if index < 0 {
        defined as i64 + index
    } else {
        return Err(at(IndexError::Zero { what }.into()));
    };
    if zero_based < 0 {
        let e = IndexError::BeforeFirst {
            what,
            index,
            defined,
        };
        return Err(at(e.into()));
    }
    u32::try_from(zero_based).map_err(|_| at(IndexError::TooLarge { what, index }.into()))
}

/// Checks a resolved index against the number of elements in the file.
fn check_range(
    i: u32,
    count: usize,
    corner: usize,
    what: ElementKind,
) -> Result<(), InputErrorKind> {
    if (i as usize) < count {
        return Ok(());
    }
    let e = IndexError::OutOfRange {
        what,
        index: u64::from(i) + 1,
        count,
        counted: None,
    };
    Err(ElementKind::FaceCorner.at(corner + 1).error(e))
}

/// Comments and alphabetic keywords are skipped; anything else is an error.
fn check_skippable(kw: &str) -> Result<(), InputErrorKind> {
    if kw.starts_with('#')
        || kw.chars().all(|c| c.is_ascii_alphanumeric() || c == '_')
            && kw.starts_with(|c: char| c.is_ascii_alphabetic())
    {
        return Ok(());
    }
    Err(SyntaxError::UnknownStatement(Token::new(kw)).into())
}

#[cfg(test)]
mod tests {
    use super::*;

    const SQUARE: &str = "# two triangles\r\nmtllib a.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n\
        vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1 0\nvn 0 0 1\ng x\ns off\nusemtl m\n\
        f 1/1/1 2/2/1 3/3/1\nf -4/-4 -2/-2 -1/-1 # comment\n";

    fn err(text: &str) -> String {
        parse_obj(text.as_bytes()).unwrap_err().to_string()
    }

    #[test]
    fn reads_corners_and_relative_indices() {
        let m = parse_obj(SQUARE.as_bytes()).unwrap();
        assert_eq!(m.positions.len(), 4);
        assert_eq!(m.simplices, vec![[0, 1, 2], [0, 2, 3]]);
        assert_eq!(m.coords[1], [[0.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
        assert_eq!(m.positions[2], [1.0, 1.0, 0.0]);
    }

    #[test]
    fn bad_faces_name_the_line() {
        let head = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\n";
        assert_eq!(
            err(&format!("{head}f 1/1 2/1 3/1 4/1\n")),
            "line 6: face has 4 vertices; only triangles are supported (triangulate the mesh first)"
        );
        assert_eq!(
            err(&format!("{head}f 1/1 2 3/1\n")),
            "line 6: face corner 2 has no texture coordinate (expected f v/vt)"
        );
        assert_eq!(
            err(&format!("{head}f 1//1 2/1 3/1\n")),
            "line 6: face corner 1 has no texture coordinate (expected f v/vt)"
        );
        assert_eq!(
            err(&format!("{head}f 1/1 2/1 9/1\n")),
            "line 6: face corner 3: vertex index 9 is out of range (the file has 4)"
        );
        assert_eq!(
            err(&format!("{head}f 1/1 2/2 3/1\n")),
            "line 6: face corner 2: texture coordinate index 2 is out of range (the file has 1)"
        );
        assert_eq!(
            err(&format!("{head}f 1/1 -7/1 3/1\n")),
            "line 6: face corner 2: vertex index -7 points before the first vertex (4 defined so far)"
        );
        assert_eq!(
            err(&format!("{head}f 0/1 2/1 3/1\n")),
            "line 6: face corner 1: vertex index 0 is invalid (OBJ indices start at 1)"
        );
        assert_eq!(
            err(&format!("{head}f 1/1 2.5/1 3/1\n")),
            "line 6: face corner 2: vertex index `2.5` is not an integer"
        );
        assert_eq!(
            err(&format!("{head}f 1/1 1/1 3/1\n")),
            "triangle 0: vertex 0 appears twice"
        );
    }

    #[test]
    fn bad_numbers_and_files_name_the_line() {
        assert_eq!(
            err("v 0 0 0\nv 1 nan 0\n"),
            "line 2: vertex coordinate is not finite (`nan`)"
        );
        assert_eq!(
            err("v 0 0 0\n\nv 1 inf 0\n"),
            "line 3: vertex coordinate is not finite (`inf`)"
        );
        assert_eq!(
            err("v 0 0 0\nv 1 0x1 0\n"),
            "line 2: vertex coordinate `0x1` is not a number"
        );
        assert_eq!(
            err("v 0 0\n"),
            "line 1: vertex has 2 coordinates; expected `v x y z`"
        );
        assert_eq!(
            err("vt 0 1e999\n"),
            "line 1: texture coordinate is not finite (`1e999`)"
        );
        assert_eq!(
            err("vt 0\n"),
            "line 1: texture coordinate has 1 values; expected `vt u v`"
        );
        assert_eq!(err("v 0 0 0\n3 4 5\n"), "line 2: unknown statement `3`");
        assert_eq!(err(""), "no triangles (the file has no `f` line)");
        assert_eq!(
            err("# only a comment\nv 1 2 3\n"),
            "no triangles (the file has no `f` line)"
        );
        let garbage: Vec<u8> = b"v 1 2 3\n\x7fELF\x02\x01\x01\0\0\0".to_vec();
        assert_eq!(
            parse_obj(&garbage).unwrap_err().to_string(),
            "line 2: not a text OBJ file (NUL byte)"
        );
    }

    #[test]
    fn polygons_keep_their_size() {
        let text = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nf 1 2 3 4\nf 2/7 5 3\n";
        let m = parse_polygon_obj(text.as_bytes()).unwrap();
        assert_eq!(m.faces, vec![vec![0, 1, 2, 3], vec![1, 4, 2]]);
        let e = parse_polygon_obj(b"v 0 0 0\nf 1 2\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 2: face has 2 vertices; a face needs at least 3"
        );
        let e = parse_polygon_obj(b"v 0 0 0\nf 1 2 1\n").unwrap_err();
        assert_eq!(
            e.to_string(),
            "line 2: face corner 2: vertex index 2 is out of range (the file has 1)"
        );
    }
}
