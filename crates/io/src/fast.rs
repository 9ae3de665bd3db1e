//! Parallel fast paths of the OBJ and `.hexex` readers.
//!
//! Input: the bytes of a whole file. Output: `Some(map)` when the file has
//! the common layout below and is valid, `None` otherwise — then the
//! sequential reader ([`crate::parse_obj`], [`crate::parse_hexex`]) runs and
//! produces the result or the exact error, with its line. So the fast paths
//! never produce an error of their own, and accept exactly what the
//! sequential readers accept with the same result (tested on every file of
//! the shared data, generated maps and the fuzz corpus):
//! - OBJ: every `f` corner is `v/vt` or `v/vt/vn` with positive indices
//!   (negative, relative indices send the file to the sequential reader);
//! - `.hexex`: the vertex count alone on its line, one vertex per line (3
//!   numbers), the tet count alone on its line, one tet per line (`a b c d`
//!   and 12 numbers), as every writer we know produces; anything else
//!   (several vertices or tets per line, one split over lines, a blank line
//!   among them) goes to the sequential reader.
//!
//! The file is cut into chunks of ~[`CHUNK`] bytes at line ends; chunks are
//! parsed in parallel with rayon, and joined in file order, so the result
//! does not depend on the number of threads. Fields are read in place by a
//! [`Cursor`] (numbers by [`crate::decimal`], same bits as `str::parse`).
//! OBJ chunks are checked to be text (UTF-8, no NUL: skipped lines may
//! hold anything), each before it is parsed; a `.hexex` file needs no
//! such check, as every byte of an accepted file is whitespace or in an
//! accepted (ASCII) number.
//!
//! The map's invariants (`SimplexMap::validate`: a simplex at least,
//! finite positions and map coordinates, vertex indices in range and
//! distinct within a simplex) are checked as the fields are read, so the
//! map read is not walked again to validate it (a debug assertion does).

use crate::cursor::{count_lines, leading_digits, line_chunks, text_lines, Cursor};
use crate::scan::finite;
use dualex_map::mesh::distinct_corners;
use dualex_map::{TetMap, TriMap};
use rayon::prelude::*;

/// Target chunk size in bytes.
const CHUNK: usize = 1 << 20;

/// A positive decimal integer token (digits only, as `str::parse::<u64>`
/// without sign) minus one, or `None`.
#[inline]
fn one_based(tok: &[u8]) -> Option<u32> {
    let (i, n) = leading_digits(tok);
    if n == 0 || n > 10 || n != tok.len() {
        return None;
    }
    from_one(i)
}

/// A 1-based index made 0-based, or `None` for 0 or past `u32`.
#[inline]
fn from_one(i: u64) -> Option<u32> {
    u32::try_from(i.checked_sub(1)?).ok()
}

/// An OBJ corner `v/vt` or `v/vt/…` (as `corner.split('/')`: the first two
/// parts [`one_based`], the rest not read), or `None`.
#[inline]
fn corner(b: &[u8]) -> Option<(u32, u32)> {
    let slash = b.iter().position(|&c| c == b'/')?;
    let rest = b.get(slash + 1..)?;
    let end = rest.iter().position(|&c| c == b'/').unwrap_or(rest.len());
    Some((one_based(b.get(..slash)?)?, one_based(rest.get(..end)?)?))
}

/// What one OBJ chunk holds.
#[derive(Default)]
struct ObjChunk {
    positions: Vec<[f64; 3]>,
    uvs: Vec<[f64; 2]>,
    v: Vec<[u32; 3]>,
    vt: Vec<[u32; 3]>,
}

/// At least `K` finite numbers before the line end or a `#` field (the
/// rest of the line then skipped); the first `K`.
#[inline]
fn numbers<const K: usize>(t: &mut Cursor<'_>) -> Option<[f64; K]> {
    let mut out = [0.0; K];
    for slot in &mut out {
        *slot = t.float()?;
    }
    // the common end: the line's `\n` right after the last number (what
    // `field` then `end_line` would consume)
    if t.eat(b"\n") {
        return Some(out);
    }
    loop {
        match t.field() {
            [] => break t.end_line()?,
            [b'#', ..] => break t.skip_line(),
            tok => {
                finite(std::str::from_utf8(tok).ok()?)?;
            }
        }
    }
    Some(out)
}

/// The 3 corners of an `f` line, then the line end or a `#` field.
#[inline]
fn face(t: &mut Cursor<'_>) -> Option<([u32; 3], [u32; 3])> {
    let (mut v, mut vt) = ([0u32; 3], [0u32; 3]);
    for n in 0..3 {
        (v[n], vt[n]) = match t.slash_pair() {
            Some((a, b)) => (from_one(a)?, from_one(b)?),
            None => corner(t.field())?,
        };
    }
    if !t.eat(b"\n") {
        match t.field() {
            [] => t.end_line()?,
            [b'#', ..] => t.skip_line(),
            _ => return None,
        }
    }
    Some((v, vt))
}

/// Whether a line starting with `kw` is skipped: a comment or an
/// alphabetic keyword (`vn`, `g`, `usemtl`, …).
fn skippable(kw: &[u8]) -> bool {
    kw.first() == Some(&b'#')
        || kw.first().is_some_and(u8::is_ascii_alphabetic)
            && kw.iter().all(|&b| b.is_ascii_alphanumeric() || b == b'_')
}

/// An empty [`ObjChunk`] with room for `lines` elements (the lines of
/// `text`), of the kind its first line is (writers list the vertices, then
/// the texture coordinates, then the faces: most chunks hold one kind, and
/// their vectors then grow without a copy; the others grow as they go).
fn reserved(text: &[u8], lines: usize) -> ObjChunk {
    let mut c = ObjChunk::default();
    match Cursor::new(text).field() {
        b"v" => c.positions.reserve_exact(lines),
        b"vt" => c.uvs.reserve_exact(lines),
        b"f" => {
            c.v.reserve_exact(lines);
            c.vt.reserve_exact(lines);
        }
        _ => {}
    }
    c
}

/// One chunk of an OBJ file (cut after a `\n`: a char boundary of valid
/// UTF-8), if it is text (valid UTF-8, no NUL byte: [`text_lines`], while
/// the chunk is in cache) and every line has the common form.
fn obj_chunk(text: &[u8]) -> Option<ObjChunk> {
    let mut c = reserved(text, text_lines(text)?);
    let mut t = Cursor::new(text);
    while !t.rest().is_empty() {
        match line_start(&mut t) {
            Line::Vertex => c.positions.push(numbers::<3>(&mut t)?),
            Line::Uv => c.uvs.push(numbers::<2>(&mut t)?),
            Line::Face => {
                let (v, vt) = face(&mut t)?;
                c.v.push(v);
                c.vt.push(vt);
            }
            Line::Other([]) => t.end_line()?,
            Line::Other(kw) if skippable(kw) => t.skip_line(),
            Line::Other(_) => return None,
        }
    }
    Some(c)
}

/// What an OBJ line starts with, as the fast path reads it.
enum Line<'a> {
    /// `v`: a position.
    Vertex,
    /// `vt`: texture coordinates.
    Uv,
    /// `f`: a face.
    Face,
    /// Any other first field (empty on a blank line).
    Other(&'a [u8]),
}

/// The first field of the line at `t` ([`Cursor::field`], one space after
/// it consumed): `v `, `vt ` and `f ` compared whole, without the field's
/// byte loop (the cursor then stands where `field` leaves it).
#[inline]
fn line_start<'a>(t: &mut Cursor<'a>) -> Line<'a> {
    if t.eat(b"v ") {
        return Line::Vertex;
    }
    if t.eat(b"f ") {
        return Line::Face;
    }
    if t.eat(b"vt ") {
        return Line::Uv;
    }
    match t.field() {
        b"v" => Line::Vertex,
        b"vt" => Line::Uv,
        b"f" => Line::Face,
        kw => Line::Other(kw),
    }
}

/// The OBJ fast path (see the module docs).
pub(crate) fn obj(bytes: &[u8]) -> Option<TriMap> {
    obj_chunked(bytes, CHUNK)
}

/// [`obj`] with chunks of ~`chunk` bytes.
pub(crate) fn obj_chunked(bytes: &[u8], chunk: usize) -> Option<TriMap> {
    let parts: Vec<ObjChunk> = line_chunks(bytes, chunk)
        .into_par_iter()
        .map(obj_chunk)
        .collect::<Option<_>>()?;
    let nt = parts.iter().map(|c| c.v.len()).sum::<usize>();
    if nt == 0 {
        return None;
    }
    let positions = joined(&parts, |c| &c.positions, [0.0; 3]);
    let uvs = joined(&parts, |c| &c.uvs, [0.0; 2]);
    let nv = positions.len();
    // every chunk's triangles into their own slices, in parallel: indices
    // checked (in range, distinct), texture coordinates looked up
    let mut simplices = vec![[0u32; 3]; nt];
    let mut coords = vec![[[0.0f64; 2]; 3]; nt];
    let mut jobs = Vec::with_capacity(parts.len());
    let (mut rest_s, mut rest_c) = (&mut simplices[..], &mut coords[..]);
    for c in &parts {
        let (s, rs) = rest_s.split_at_mut(c.v.len());
        let (k, rc) = rest_c.split_at_mut(c.v.len());
        jobs.push((c, s, k));
        (rest_s, rest_c) = (rs, rc);
    }
    let ok = jobs
        .into_par_iter()
        .all(|(c, s, k)| chunk_triangles(c, nv, &uvs, s, k));
    // the chunks freed on the pool's threads, not after on this one
    parts.into_par_iter().for_each(drop);
    if !ok {
        return None;
    }
    let map = TriMap {
        positions,
        simplices,
        coords,
    };
    debug_assert!(
        map.validate().is_ok(),
        "the OBJ fast path read an invalid map"
    );
    Some(map)
}

/// The chunks' pieces `of` joined in file order, each copied into its
/// place in parallel (`zero`: the value the vector starts with).
fn joined<T: Copy + Send + Sync>(parts: &[ObjChunk], of: fn(&ObjChunk) -> &[T], zero: T) -> Vec<T> {
    let mut out = vec![zero; parts.iter().map(|c| of(c).len()).sum()];
    let mut rest = &mut out[..];
    let mut jobs = Vec::with_capacity(parts.len());
    for c in parts {
        let (s, r) = std::mem::take(&mut rest).split_at_mut(of(c).len());
        jobs.push((s, of(c)));
        rest = r;
    }
    jobs.into_par_iter()
        .for_each(|(s, src)| s.copy_from_slice(src));
    out
}

/// Writes chunk `c`'s triangles into `s` and their texture coordinates
/// (looked up in `uvs`) into `k`; whether every index is in range (below
/// `nv` and `uvs.len()`) and every triangle's vertices are distinct.
fn chunk_triangles(
    c: &ObjChunk,
    nv: usize,
    uvs: &[[f64; 2]],
    s: &mut [[u32; 3]],
    k: &mut [[[f64; 2]; 3]],
) -> bool {
    let ok = |t: &[u32; 3]| t.iter().all(|&i| (i as usize) < nv) && distinct_corners(t);
    if !c.v.iter().all(ok) {
        return false;
    }
    s.copy_from_slice(&c.v);
    for (slot, t) in k.iter_mut().zip(&c.vt) {
        for (x, &i) in slot.iter_mut().zip(t) {
            let Some(uv) = uvs.get(i as usize) else {
                return false;
            };
            *x = *uv;
        }
    }
    true
}

/// The `.hexex` fast path (see the module docs).
pub(crate) fn hexex(bytes: &[u8]) -> Option<TetMap> {
    hexex_chunked(bytes, CHUNK)
}

/// [`hexex`] with chunks of ~`chunk` bytes.
pub(crate) fn hexex_chunked(bytes: &[u8], chunk: usize) -> Option<TetMap> {
    // the vertex count alone on its line, then one line per vertex, the
    // tet count's line and one line per tet: the lines after the first
    // cut into chunks and counted in parallel, then every chunk parsed in
    // parallel into the slices of the vertices and tets its lines hold
    let mut t = Cursor::new(bytes);
    t.skip_space();
    let nv = usize::try_from(t.integer(19)?).ok()?;
    t.end_line()?;
    if nv > bytes.len() / 6 {
        return None;
    }
    let chunks = line_chunks(t.rest(), chunk);
    let lines: Vec<usize> = chunks.par_iter().map(|c| count_lines(c)).collect();
    let nt = tet_count(&chunks, &lines, nv)?;
    if nt == 0 || nt > bytes.len() / 32 {
        return None;
    }
    let mut positions = vec![[0.0f64; 3]; nv];
    let mut simplices = vec![[0u32; 4]; nt];
    let mut coords = vec![[[0.0f64; 3]; 4]; nt];
    // per chunk: its bytes, its vertices' slice, whether it holds the tet
    // count's line, its tets' slices
    let mut jobs = Vec::with_capacity(chunks.len());
    let (mut rest_p, mut rest_s, mut rest_c) =
        (&mut positions[..], &mut simplices[..], &mut coords[..]);
    let mut counted = false;
    for (c, &n) in chunks.iter().zip(&lines) {
        let verts = n.min(rest_p.len());
        let (p, rp) = std::mem::take(&mut rest_p).split_at_mut(verts);
        // the tet count's line: the first line after the last vertex's
        let count = !counted && rp.is_empty() && verts < n;
        counted |= count;
        let take = (n - verts - usize::from(count)).min(rest_s.len());
        let (s, rs) = std::mem::take(&mut rest_s).split_at_mut(take);
        let (k, rc) = std::mem::take(&mut rest_c).split_at_mut(take);
        jobs.push((*c, p, count, s, k));
        (rest_p, rest_s, rest_c) = (rp, rs, rc);
    }
    if !rest_s.is_empty() {
        return None; // fewer lines than tets
    }
    let ok = jobs
        .into_par_iter()
        .all(|(text, p, count, s, k)| body_lines(text, p, count.then_some(nt), s, k, nv));
    if !ok {
        return None;
    }
    let map = TetMap {
        positions,
        simplices,
        coords,
    };
    debug_assert!(
        map.validate().is_ok(),
        "the .hexex fast path read an invalid map"
    );
    Some(map)
}

/// The tet count: line `nv` of the lines after the vertex count (`lines`
/// per chunk), an integer alone on its line.
fn tet_count(chunks: &[&[u8]], lines: &[usize], nv: usize) -> Option<usize> {
    let mut first = 0;
    for (c, &n) in chunks.iter().zip(lines) {
        if nv < first + n {
            let mut t = Cursor::new(c);
            (first..nv).for_each(|_| t.skip_line());
            let nt = usize::try_from(t.integer(19)?).ok()?;
            t.end_line()?;
            return Some(nt);
        }
        first += n;
    }
    None
}

/// Fills `p` from the first lines of `text`, one vertex per line (3 finite
/// numbers); then, with `count`, reads the tet count's line (that
/// integer alone); then fills `s` and `k`, one tet per line (4 vertex
/// indices below `nv` and 12 finite numbers); the lines after them must be
/// blank.
fn body_lines(
    text: &[u8],
    p: &mut [[f64; 3]],
    count: Option<usize>,
    s: &mut [[u32; 4]],
    k: &mut [[[f64; 3]; 4]],
    nv: usize,
) -> bool {
    let mut t = Cursor::new(text);
    for slot in p.iter_mut() {
        let Some(v) = vertex_line(&mut t) else {
            return false;
        };
        *slot = v;
    }
    if let Some(nt) = count {
        if t.integer(19) != Some(nt as u64) || t.end_line().is_none() {
            return false;
        }
    }
    for (slot_s, slot_c) in s.iter_mut().zip(k.iter_mut()) {
        if tet_line(&mut t, nv, slot_s, slot_c).is_none() {
            return false;
        }
    }
    t.skip_space();
    t.rest().is_empty()
}

/// One vertex line: 3 finite numbers, then the line end.
#[inline]
fn vertex_line(t: &mut Cursor<'_>) -> Option<[f64; 3]> {
    let mut p = [0.0; 3];
    for x in &mut p {
        *x = t.float()?;
    }
    t.end_line()?;
    Some(p)
}

/// One tet line: 4 distinct vertex indices below `nv` into `tet` and 12
/// finite numbers into `uvw` (written where they go: on `None` the caller
/// drops the whole map), then the line end.
#[inline]
fn tet_line(
    t: &mut Cursor<'_>,
    nv: usize,
    tet: &mut [u32; 4],
    uvw: &mut [[f64; 3]; 4],
) -> Option<()> {
    for slot in tet.iter_mut() {
        // digits only (as `str::parse::<u64>` without a sign), below nv
        let i = t.integer(10)?;
        if i >= nv as u64 {
            return None;
        }
        *slot = i as u32;
    }
    if !distinct_corners(tet) {
        return None;
    }
    for corner in uvw.iter_mut() {
        *corner = [t.float()?, t.float()?, t.float()?];
    }
    t.end_line()
}
