//! OpenVolumeMesh ASCII `.ovm` input: a tet mesh with HexHex's map.
//!
//! Input, line by line (blank lines and `#` comments skipped, keywords in
//! any case), as OpenVolumeMesh's `FileManager` writes it:
//! ```text
//!   OVM ASCII
//!   Vertices   n_v  then  x y z                  × n_v
//!   Edges      n_e  then  from to                × n_e   (edge e: halfedges 2e = from→to, 2e+1)
//!   Faces      n_f  then  k he_1 … he_k          × n_f   (face f: halffaces 2f as listed, 2f+1 reversed)
//!   Polyhedra  n_c  then  k hf_1 … hf_k          × n_c
//!   <entity> <type> "<name>"  then one value per line, per entity
//! ```
//! The map is the halfface property `HFProp vec3d "HexHex::Parametrization"`,
//! in HexHex's convention: the value on a cell's halfface is the map
//! coordinate, in that cell's chart, of the cell's vertex *opposite* the
//! halfface. Other properties are skipped (one line per entity).
//!
//! Output: a [`TetMap`] whose tet `c` is cell `c`, with corners `a b c`
//! (the cell's first halfface, as listed) and `d` (the vertex off it) —
//! for a cell made by OpenVolumeMesh's `add_cell(v0, v1, v2, v3)`, as
//! HexHex's `.hexex` reader does, exactly `v0 v1 v2 v3`. Errors name the
//! line, or the cell when it is not a tet. Counts are checked against the
//! lines left before anything is allocated.

use crate::scan::{as_text, parse_finite, quote};
use dualex_map::{InputError, TetMap};

/// The halfface property holding the map.
pub const HEXHEX_PARAM: &str = "HexHex::Parametrization";

/// The non-empty, non-comment lines with their 1-based numbers.
struct Lines<'a> {
    lines: Vec<(usize, &'a str)>,
    at: usize,
}

impl<'a> Lines<'a> {
    fn new(text: &'a str) -> Self {
        let lines = text
            .lines()
            .enumerate()
            .map(|(i, l)| (i + 1, l.trim()))
            .filter(|(_, l)| !l.is_empty() && !l.starts_with('#'))
            .collect();
        Lines { lines, at: 0 }
    }

    fn next(&mut self, what: &str) -> Result<(usize, &'a str), InputError> {
        let l = self.lines.get(self.at).copied().ok_or_else(|| {
            let last = self.lines.last().map_or(1, |l| l.0);
            InputError::at_line(last, format!("file ends before {what}"))
        })?;
        self.at += 1;
        Ok(l)
    }

    fn peek(&self) -> Option<(usize, &'a str)> {
        self.lines.get(self.at).copied()
    }

    fn left(&self) -> usize {
        self.lines.len() - self.at
    }

    /// A section keyword line, then its count line (checked against the lines left).
    fn section(&mut self, keyword: &str) -> Result<usize, InputError> {
        let (line, l) = self.next(&format!("the {keyword} section"))?;
        if !l.eq_ignore_ascii_case(keyword) {
            return Err(InputError::at_line(
                line,
                format!("expected `{keyword}`, found {}", quote(l)),
            ));
        }
        let (line, l) = self.next(&format!("the {keyword} count"))?;
        let n: usize = l
            .parse()
            .map_err(|_| InputError::at_line(line, format!("bad {keyword} count {}", quote(l))))?;
        if n > self.left() {
            return Err(InputError::at_line(
                line,
                format!(
                    "{n} {keyword} declared but only {} lines follow",
                    self.left()
                ),
            ));
        }
        Ok(n)
    }
}

/// Parses one line of `N` numbers.
fn numbers<const N: usize>(line: usize, l: &str, what: &str) -> Result<[f64; N], InputError> {
    let mut out = [0.0; N];
    let mut toks = l.split_whitespace();
    for x in &mut out {
        let tok = toks
            .next()
            .ok_or_else(|| InputError::at_line(line, format!("{what}: fewer than {N} values")))?;
        *x = parse_finite(tok, what).map_err(|m| InputError::at_line(line, m))?;
    }
    Ok(out)
}

/// Parses `k i_1 … i_k`, each index below `bound`.
fn index_list(line: usize, l: &str, bound: usize, what: &str) -> Result<Vec<usize>, InputError> {
    let bad = |m: String| InputError::at_line(line, format!("{what}: {m}"));
    let mut toks = l
        .split_whitespace()
        .map(|t| t.parse::<usize>().map_err(|_| t));
    let k = match toks.next() {
        Some(Ok(k)) if k <= 64 => k,
        _ => return Err(bad(format!("bad valence in {}", quote(l)))),
    };
    let list: Vec<usize> = toks
        .take(k)
        .map(|t| match t {
            Ok(i) if i < bound => Ok(i),
            Ok(i) => Err(bad(format!("index {i} out of range (there are {bound})"))),
            Err(t) => Err(bad(format!("bad index {}", quote(t)))),
        })
        .collect::<Result<_, _>>()?;
    if list.len() != k {
        return Err(bad(format!("{k} indices declared, {} given", list.len())));
    }
    Ok(list)
}

/// The topology read so far: edges, faces (as halfedge lists), cells.
struct Topology {
    edges: Vec<[u32; 2]>,
    faces: Vec<Vec<usize>>,
    cells: Vec<(usize, Vec<usize>)>,
}

impl Topology {
    /// Vertices of halfface `hf`, in its order.
    fn halfface(&self, hf: usize) -> Vec<u32> {
        let from = |he: usize| {
            let e = self.edges[he / 2];
            if he & 1 == 0 {
                e[0]
            } else {
                e[1]
            }
        };
        let mut vs: Vec<u32> = self.faces[hf / 2].iter().map(|&he| from(he)).collect();
        if hf & 1 == 1 {
            // the opposite halfedges in reverse order start at the to-vertices
            vs.reverse();
            vs.rotate_right(1);
        }
        vs
    }
}

/// Parses an OpenVolumeMesh ASCII tet map (see the module docs).
pub fn parse_ovm_tet_map(bytes: &[u8]) -> Result<TetMap, InputError> {
    let text = as_text(bytes, "ovm")?;
    let mut lines = Lines::new(text);
    if let Some((line, l)) = lines.peek() {
        let mut t = l.split_whitespace();
        if t.next().is_some_and(|w| w.eq_ignore_ascii_case("ovm")) {
            if t.next().is_some_and(|w| w.eq_ignore_ascii_case("binary")) {
                return Err(InputError::at_line(
                    line,
                    "binary .ovm files are not supported; write it as ASCII",
                ));
            }
            lines.at += 1;
        }
    }
    let nv = lines.section("Vertices")?;
    let mut positions = Vec::with_capacity(nv);
    for i in 0..nv {
        let (line, l) = lines.next("a vertex")?;
        positions.push(numbers::<3>(line, l, &format!("vertex {i}"))?);
    }
    let ne = lines.section("Edges")?;
    let mut topo = Topology {
        edges: Vec::with_capacity(ne),
        faces: Vec::new(),
        cells: Vec::new(),
    };
    for i in 0..ne {
        let (line, l) = lines.next("an edge")?;
        let mut ends = [0u32; 2];
        let mut toks = l.split_whitespace();
        for end in &mut ends {
            *end = toks
                .next()
                .and_then(|t| t.parse::<u32>().ok())
                .filter(|&v| (v as usize) < nv)
                .ok_or_else(|| {
                    InputError::at_line(line, format!("edge {i}: bad vertex index in {}", quote(l)))
                })?;
        }
        topo.edges.push(ends);
    }
    let nf = lines.section("Faces")?;
    for i in 0..nf {
        let (line, l) = lines.next("a face")?;
        topo.faces
            .push(index_list(line, l, 2 * ne, &format!("face {i}"))?);
    }
    let nc = lines.section("Polyhedra")?;
    for i in 0..nc {
        let (line, l) = lines.next("a cell")?;
        topo.cells
            .push((line, index_list(line, l, 2 * nf, &format!("cell {i}"))?));
    }
    let param = read_param(&mut lines, [nv, ne, nf, nc])?;
    let mut map = TetMap {
        positions,
        simplices: Vec::with_capacity(nc),
        coords: Vec::with_capacity(nc),
    };
    for (c, (line, hfs)) in topo.cells.iter().enumerate() {
        let (tet, uvw) = cell_tet(&topo, hfs, &param)
            .map_err(|m| InputError::at_line(*line, format!("cell {c}: {m}")))?;
        map.simplices.push(tet);
        map.coords.push(uvw);
    }
    if map.simplices.is_empty() {
        return Err(InputError::new("no cells (the Polyhedra count is 0)"));
    }
    map.validate()?;
    Ok(map)
}

/// Reads the properties, keeps `HexHex::Parametrization` (one value per
/// halfface), skips the others.
fn read_param(
    lines: &mut Lines<'_>,
    [nv, ne, nf, nc]: [usize; 4],
) -> Result<Vec<[f64; 3]>, InputError> {
    let mut param = None;
    while let Some((line, l)) = lines.peek() {
        lines.at += 1;
        let mut t = l.split_whitespace();
        let entity = t.next().unwrap_or_default().to_ascii_lowercase();
        let kind = t.next().unwrap_or_default().to_ascii_lowercase();
        let name = l.split('"').nth(1).unwrap_or_default();
        let count = match entity.as_str() {
            "vprop" => nv,
            "eprop" => ne,
            "heprop" => 2 * ne,
            "fprop" => nf,
            "hfprop" => 2 * nf,
            "cprop" => nc,
            "mprop" => 1,
            _ => {
                return Err(InputError::at_line(
                    line,
                    format!(
                        "expected a property header (`HFProp vec3d \"name\"`), found {}",
                        quote(l)
                    ),
                ))
            }
        };
        // older writers repeat the quoted name before the values
        if lines.peek().is_some_and(|(_, l)| l.starts_with('"')) {
            lines.at += 1;
        }
        if count > lines.left() {
            return Err(InputError::at_line(
                line,
                format!(
                    "property \"{name}\": {count} values expected but only {} lines follow",
                    lines.left()
                ),
            ));
        }
        if entity == "hfprop" && name == HEXHEX_PARAM {
            if kind != "vec3d" && kind != "vec3f" {
                return Err(InputError::at_line(
                    line,
                    format!("property \"{HEXHEX_PARAM}\" has type `{kind}`, expected `vec3d`"),
                ));
            }
            let mut values = Vec::with_capacity(count);
            for i in 0..count {
                let (line, l) = lines.next("a parameter")?;
                values.push(numbers::<3>(line, l, &format!("halfface {i}"))?);
            }
            param = Some(values);
        } else {
            lines.at += count;
        }
    }
    param.ok_or_else(|| {
        InputError::new(format!(
            "no halfface property \"{HEXHEX_PARAM}\" (vec3d): not a HexHex map"
        ))
    })
}

/// The tet of one cell and its corners' map coordinates.
fn cell_tet(
    topo: &Topology,
    hfs: &[usize],
    param: &[[f64; 3]],
) -> Result<([u32; 4], [[f64; 3]; 4]), String> {
    if hfs.len() != 4 {
        return Err(format!(
            "{} halffaces; only tets (4) are supported",
            hfs.len()
        ));
    }
    let faces: Vec<Vec<u32>> = hfs.iter().map(|&hf| topo.halfface(hf)).collect();
    if faces.iter().any(|f| f.len() != 3) {
        return Err("a face that is not a triangle".to_string());
    }
    let [a, b, c] = [faces[0][0], faces[0][1], faces[0][2]];
    let d = faces[1..]
        .iter()
        .flatten()
        .copied()
        .find(|v| ![a, b, c].contains(v))
        .ok_or("all faces on three vertices")?;
    let tet = [a, b, c, d];
    let mut uvw = [[0.0; 3]; 4];
    for (k, &v) in tet.iter().enumerate() {
        let mut off = hfs.iter().zip(&faces).filter(|(_, f)| !f.contains(&v));
        match (off.next(), off.next()) {
            (Some((&hf, _)), None) => uvw[k] = param[hf],
            _ => {
                return Err(format!(
                    "not a tet: vertex {v} is not opposite exactly one face"
                ))
            }
        }
    }
    if faces.iter().any(|f| f.iter().any(|v| !tet.contains(v))) {
        return Err("not a tet: its faces span more than 4 vertices".to_string());
    }
    Ok((tet, uvw))
}
