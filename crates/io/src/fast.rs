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
//! - `.hexex`: after the tet count, one tet per line (`a b c d` and 12
//!   numbers), as every writer we know produces; anything else (several
//!   tets per line, a tet split over lines) goes to the sequential reader.
//!
//! The file is cut into chunks of ~[`CHUNK`] bytes at line ends; chunks are
//! checked (text, no NUL) and parsed in parallel with rayon, and joined in
//! file order, so the result does not depend on the number of threads.

use crate::scan::{finite, Tokens};
use dualex_map::{TetMap, TriMap};
use rayon::prelude::*;

/// Target chunk size in bytes.
const CHUNK: usize = 1 << 20;

/// `text` cut after a `\n` every ~[`CHUNK`] bytes (the last chunk may end
/// without one; a cut after `\n` is a char boundary).
fn line_chunks(text: &str, chunk: usize) -> Vec<&str> {
    let chunk = chunk.max(1);
    let mut out = Vec::with_capacity(text.len() / chunk + 1);
    let mut rest = text;
    while rest.len() > chunk {
        let cut = rest.as_bytes()[chunk..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(rest.len(), |i| chunk + i + 1);
        let (head, tail) = rest.split_at(cut);
        out.push(head);
        rest = tail;
    }
    if !rest.is_empty() {
        out.push(rest);
    }
    out
}

/// `bytes` as text chunks, if it is text (valid UTF-8, no NUL byte).
fn text_chunks(bytes: &[u8], chunk: usize) -> Option<(&str, Vec<&str>)> {
    let text = std::str::from_utf8(bytes).ok()?;
    let chunks = line_chunks(text, chunk);
    let no_nul = chunks.par_iter().all(|c| !c.as_bytes().contains(&0));
    no_nul.then_some((text, chunks))
}

/// A positive decimal integer token (digits only, as `str::parse::<u64>`
/// without sign) minus one, or `None`.
#[inline]
fn one_based(tok: &[u8]) -> Option<u32> {
    if tok.is_empty() || tok.len() > 10 {
        return None;
    }
    let mut i = 0u64;
    for &b in tok {
        if !b.is_ascii_digit() {
            return None;
        }
        i = 10 * i + u64::from(b - b'0');
    }
    u32::try_from(i.checked_sub(1)?).ok()
}

/// An OBJ corner `v/vt` or `v/vt/…` (as `corner.split('/')`: the first two
/// parts [`one_based`], the rest not read), or `None`.
#[inline]
fn corner(tok: &str) -> Option<(u32, u32)> {
    let b = tok.as_bytes();
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

/// At least `n` finite numbers before the end or a `#`; the first `K`.
fn numbers<'a, const K: usize>(toks: impl Iterator<Item = &'a str>) -> Option<[f64; K]> {
    let mut out = [0.0; K];
    let mut n = 0;
    for tok in toks {
        if tok.starts_with('#') {
            break;
        }
        let x = finite(tok)?;
        if let Some(slot) = out.get_mut(n) {
            *slot = x;
        }
        n += 1;
    }
    (n >= K).then_some(out)
}

fn obj_chunk(text: &str) -> Option<ObjChunk> {
    let mut c = ObjChunk::default();
    for line in text.lines() {
        let mut toks = Fields { text: line, pos: 0 };
        let Some(kw) = toks.next() else { continue };
        match kw {
            "v" => c.positions.push(numbers::<3>(toks)?),
            "vt" => c.uvs.push(numbers::<2>(toks)?),
            "f" => {
                let (mut v, mut vt) = ([0u32; 3], [0u32; 3]);
                let mut n = 0;
                for tok in toks.take_while(|t| !t.starts_with('#')) {
                    if n == 3 {
                        return None;
                    }
                    (v[n], vt[n]) = corner(tok)?;
                    n += 1;
                }
                if n != 3 {
                    return None;
                }
                c.v.push(v);
                c.vt.push(vt);
            }
            _ => {
                let skippable = kw.starts_with('#')
                    || kw.starts_with(|ch: char| ch.is_ascii_alphabetic())
                        && kw.chars().all(|ch| ch.is_ascii_alphanumeric() || ch == '_');
                if !skippable {
                    return None;
                }
            }
        }
    }
    Some(c)
}

/// The OBJ fast path (see the module docs).
pub(crate) fn obj(bytes: &[u8]) -> Option<TriMap> {
    obj_chunked(bytes, CHUNK)
}

/// [`obj`] with chunks of ~`chunk` bytes.
pub(crate) fn obj_chunked(bytes: &[u8], chunk: usize) -> Option<TriMap> {
    let (_, texts) = text_chunks(bytes, chunk)?;
    let parts: Vec<ObjChunk> = texts
        .par_iter()
        .map(|t| obj_chunk(t))
        .collect::<Option<_>>()?;
    let total = |f: fn(&ObjChunk) -> usize| parts.iter().map(f).sum::<usize>();
    let mut positions = Vec::with_capacity(total(|c| c.positions.len()));
    let mut uvs = Vec::with_capacity(total(|c| c.uvs.len()));
    let nt = total(|c| c.v.len());
    if nt == 0 {
        return None;
    }
    for c in &parts {
        positions.extend_from_slice(&c.positions);
        uvs.extend_from_slice(&c.uvs);
    }
    let (nv, nvt) = (positions.len(), uvs.len());
    let in_range = parts.par_iter().all(|c| {
        c.v.iter().flatten().all(|&i| (i as usize) < nv)
            && c.vt.iter().flatten().all(|&i| (i as usize) < nvt)
    });
    if !in_range {
        return None;
    }
    let mut map = TriMap {
        positions,
        simplices: Vec::with_capacity(nt),
        coords: Vec::with_capacity(nt),
    };
    for c in &parts {
        map.simplices.extend_from_slice(&c.v);
        map.coords
            .extend(c.vt.iter().map(|t| t.map(|i| uvs[i as usize])));
    }
    map.validate().ok()?;
    Some(map)
}

/// One tet line: 4 vertex indices below `nv` and 12 finite numbers.
fn tet_line(line: &str, nv: usize) -> Option<([u32; 4], [[f64; 3]; 4])> {
    let mut toks = Fields { text: line, pos: 0 };
    let mut tet = [0u32; 4];
    for slot in &mut tet {
        let tok = toks.next()?;
        // digits only (as `str::parse::<u64>` without a sign), below nv
        if tok.is_empty() || tok.len() > 10 {
            return None;
        }
        let mut i = 0u64;
        for b in tok.bytes() {
            if !b.is_ascii_digit() {
                return None;
            }
            i = 10 * i + u64::from(b - b'0');
        }
        if i >= nv as u64 {
            return None;
        }
        *slot = i as u32;
    }
    let mut uvw = [[0.0; 3]; 4];
    for corner in &mut uvw {
        for x in corner {
            let v: f64 = toks.next()?.parse().ok()?;
            if !v.is_finite() {
                return None;
            }
            *x = v;
        }
    }
    toks.next().is_none().then_some((tet, uvw))
}

/// The ASCII-whitespace-separated fields of a line (what
/// `str::split_ascii_whitespace` yields, with less machinery).
struct Fields<'a> {
    text: &'a str,
    pos: usize,
}

impl<'a> Iterator for Fields<'a> {
    type Item = &'a str;

    #[inline]
    fn next(&mut self) -> Option<&'a str> {
        let b = self.text.as_bytes();
        let mut i = self.pos;
        while i < b.len() && b[i].is_ascii_whitespace() {
            i += 1;
        }
        let start = i;
        while i < b.len() && !b[i].is_ascii_whitespace() {
            i += 1;
        }
        self.pos = i;
        // ASCII bytes around the field: char boundaries
        (start < i).then(|| self.text.get(start..i)).flatten()
    }
}

/// The `.hexex` fast path (see the module docs).
pub(crate) fn hexex(bytes: &[u8]) -> Option<TetMap> {
    hexex_chunked(bytes, CHUNK)
}

/// [`hexex`] with chunks of ~`chunk` bytes.
pub(crate) fn hexex_chunked(bytes: &[u8], chunk: usize) -> Option<TetMap> {
    let (text, _) = text_chunks(bytes, chunk)?;
    // the header and vertices (a fifth of the file or less): sequential,
    // with the reader's own token stream, up to the tet count
    let mut t = Tokens::new(text, 1);
    let nv: usize = t.next_token()?.0.parse().ok()?;
    let mut positions = Vec::with_capacity(nv.min(bytes.len() / 6));
    for _ in 0..nv {
        let mut p = [0.0; 3];
        for x in &mut p {
            *x = finite(t.next_token()?.0)?;
        }
        positions.push(p);
    }
    let nt: usize = t.next_token()?.0.parse().ok()?;
    // the rest of the tet count's line must be blank
    let after = &text[text.len() - t.remaining()..];
    let eol = after.find('\n')?;
    if !after[..eol].trim().is_empty() || nt == 0 || nt > bytes.len() / 32 {
        return None;
    }
    let body = &after[eol + 1..];
    let body_chunks = line_chunks(body, chunk);
    let lines: Vec<usize> = body_chunks
        .par_iter()
        .map(|c| c.bytes().filter(|&b| b == b'\n').count() + usize::from(!c.ends_with('\n')))
        .collect();
    let mut simplices = vec![[0u32; 4]; nt];
    let mut coords = vec![[[0.0f64; 3]; 4]; nt];
    // per chunk: its text, and the slices of the tets its lines fill
    let mut jobs = Vec::with_capacity(body_chunks.len());
    let (mut rest_s, mut rest_c) = (&mut simplices[..], &mut coords[..]);
    for (c, &n) in body_chunks.iter().zip(&lines) {
        let take = n.min(rest_s.len());
        let (s, rs) = rest_s.split_at_mut(take);
        let (k, rc) = rest_c.split_at_mut(take);
        jobs.push((*c, s, k));
        (rest_s, rest_c) = (rs, rc);
    }
    if !rest_s.is_empty() {
        return None; // fewer lines than tets
    }
    let ok = jobs.into_par_iter().all(|(text, s, k)| {
        let mut lines = text.lines();
        for (slot_s, slot_c) in s.iter_mut().zip(k.iter_mut()) {
            let Some((tet, uvw)) = lines.next().and_then(|l| tet_line(l, nv)) else {
                return false;
            };
            (*slot_s, *slot_c) = (tet, uvw);
        }
        // lines after the last tet: blank only
        lines.all(|l| l.trim().is_empty())
    });
    if !ok {
        return None;
    }
    let map = TetMap {
        positions,
        simplices,
        coords,
    };
    map.validate().ok()?;
    Some(map)
}
