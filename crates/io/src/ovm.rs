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

use crate::scan::{as_text, parse_finite};
use dualex_map::error::{
    Awaited, CountError, EmptyReason, Format, FormatError, IndexError, NotATet, Subject,
    SyntaxError, Token,
};
use dualex_map::{Element, ElementKind, InputError, InputErrorKind, TetMap};

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

    fn next(&mut self, awaited: Awaited) -> Result<(usize, &'a str), InputError> {
        let l = self.lines.get(self.at).copied().ok_or_else(|| {
            let last = self.lines.last().map_or(1, |l| l.0);
            InputError::at_line(last, SyntaxError::EndsBefore(awaited))
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
    fn section(&mut self, keyword: &'static str) -> Result<usize, InputError> {
        let (line, l) = self.next(Awaited::Section(keyword))?;
        if !l.eq_ignore_ascii_case(keyword) {
            let found = Token::new(l);
            let e = SyntaxError::ExpectedKeyword { keyword, found };
            return Err(InputError::at_line(line, e));
        }
        let (line, l) = self.next(Awaited::SectionCount(keyword))?;
        let Ok(count) = l.parse::<usize>() else {
            let token = Token::new(l);
            let e = SyntaxError::BadSectionCount {
                section: keyword,
                token,
            };
            return Err(InputError::at_line(line, e));
        };
        if count > self.left() {
            let e = CountError::SectionExceedsLines {
                section: keyword,
                count,
                lines: self.left(),
            };
            return Err(InputError::at_line(line, e));
        }
        Ok(count)
    }
}

/// Parses one line of `N` numbers, the values of `what`.
fn numbers<const N: usize>(line: usize, l: &str, what: Element) -> Result<[f64; N], InputError> {
    let mut out = [0.0; N];
    let mut toks = l.split_whitespace();
    for x in &mut out {
        let Some(tok) = toks.next() else {
            let fewer = CountError::FewerValues { expected: N };
            return Err(InputError::at_line(line, what.error(fewer)));
        };
        *x = parse_finite(tok, Subject::Element(what.clone()))
            .map_err(|e| InputError::at_line(line, e))?;
    }
    Ok(out)
}

/// Parses `k i_1 … i_k`, each index below `bound`, the list of `what`.
fn index_list(line: usize, l: &str, bound: usize, what: Element) -> Result<Vec<usize>, InputError> {
    let bad = |e: InputErrorKind| InputError::at_line(line, what.clone().error(e));
    let mut toks = l
        .split_whitespace()
        .map(|t| t.parse::<usize>().map_err(|_| t));
    let k = match toks.next() {
        Some(Ok(k)) if k <= 64 => k,
        _ => return Err(bad(SyntaxError::BadValence(Token::new(l)).into())),
    };
    let list: Vec<usize> = toks
        .take(k)
        .map(|t| match t {
            Ok(i) if i < bound => Ok(i),
            Ok(index) => Err(bad(IndexError::ListOutOfRange { index, bound }.into())),
            Err(t) => Err(bad(SyntaxError::BadIndex(Token::new(t)).into())),
        })
        .collect::<Result<_, _>>()?;
    if list.len() != k {
        let given = list.len();
        return Err(bad(CountError::Indices { declared: k, given }.into()));
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
    let text = as_text(bytes, Format::Ovm)?;
    let mut lines = Lines::new(text);
    if let Some((line, l)) = lines.peek() {
        let mut t = l.split_whitespace();
        if t.next().is_some_and(|w| w.eq_ignore_ascii_case("ovm")) {
            if t.next().is_some_and(|w| w.eq_ignore_ascii_case("binary")) {
                return Err(InputError::at_line(line, FormatError::Binary(Format::Ovm)));
            }
            lines.at += 1;
        }
    }
    let nv = lines.section("Vertices")?;
    let mut positions = Vec::with_capacity(nv);
    for i in 0..nv {
        let (line, l) = lines.next(Awaited::Record(ElementKind::Vertex))?;
        positions.push(numbers::<3>(line, l, ElementKind::Vertex.at(i))?);
    }
    let ne = lines.section("Edges")?;
    let mut topo = Topology {
        edges: Vec::with_capacity(ne),
        faces: Vec::new(),
        cells: Vec::new(),
    };
    for i in 0..ne {
        let (line, l) = lines.next(Awaited::Record(ElementKind::Edge))?;
        let mut ends = [0u32; 2];
        let mut toks = l.split_whitespace();
        for end in &mut ends {
            *end = toks
                .next()
                .and_then(|t| t.parse::<u32>().ok())
                .filter(|&v| (v as usize) < nv)
                .ok_or_else(|| {
                    let bad = SyntaxError::BadVertexIndexIn(Token::new(l));
                    InputError::at_line(line, ElementKind::Edge.at(i).error(bad))
                })?;
        }
        topo.edges.push(ends);
    }
    let nf = lines.section("Faces")?;
    for i in 0..nf {
        let (line, l) = lines.next(Awaited::Record(ElementKind::Face))?;
        topo.faces
            .push(index_list(line, l, 2 * ne, ElementKind::Face.at(i))?);
    }
    let nc = lines.section("Polyhedra")?;
    for i in 0..nc {
        let (line, l) = lines.next(Awaited::Record(ElementKind::Cell))?;
        topo.cells
            .push((line, index_list(line, l, 2 * nf, ElementKind::Cell.at(i))?));
    }
    let param = read_param(&mut lines, [nv, ne, nf, nc])?;
    let mut map = TetMap {
        positions,
        simplices: Vec::with_capacity(nc),
        coords: Vec::with_capacity(nc),
    };
    for (c, (line, hfs)) in topo.cells.iter().enumerate() {
        let (tet, uvw) = cell_tet(&topo, hfs, &param).map_err(|why| {
            let e = ElementKind::Cell.at(c).error(FormatError::NotATet(why));
            InputError::at_line(*line, e)
        })?;
        map.simplices.push(tet);
        map.coords.push(uvw);
    }
    if map.simplices.is_empty() {
        return Err(CountError::Empty {
            what: ElementKind::Cell,
            reason: Some(EmptyReason::ZeroCount("Polyhedra")),
        }
        .into());
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
                let e = SyntaxError::ExpectedPropertyHeader(Token::new(l));
                return Err(InputError::at_line(line, e));
            }
        };
        // older writers repeat the quoted name before the values
        if lines.peek().is_some_and(|(_, l)| l.starts_with('"')) {
            lines.at += 1;
        }
        if count > lines.left() {
            let e = CountError::PropertyExceedsLines {
                property: name.to_string(),
                count,
                lines: lines.left(),
            };
            return Err(InputError::at_line(line, e));
        }
        if entity == "hfprop" && name == HEXHEX_PARAM {
            if kind != "vec3d" && kind != "vec3f" {
                let e = FormatError::PropertyType {
                    property: HEXHEX_PARAM,
                    found: kind,
                };
                return Err(InputError::at_line(line, e));
            }
            let mut values = Vec::with_capacity(count);
            for i in 0..count {
                let (line, l) = lines.next(Awaited::Parameter)?;
                values.push(numbers::<3>(line, l, ElementKind::Halfface.at(i))?);
            }
            param = Some(values);
        } else {
            lines.at += count;
        }
    }
    param.ok_or_else(|| FormatError::NoHalffaceProperty(HEXHEX_PARAM).into())
}

/// The tet of one cell and its corners' map coordinates.
fn cell_tet(
    topo: &Topology,
    hfs: &[usize],
    param: &[[f64; 3]],
) -> Result<([u32; 4], [[f64; 3]; 4]), NotATet> {
    if hfs.len() != 4 {
        return Err(NotATet::Halffaces(hfs.len()));
    }
    let faces: Vec<Vec<u32>> = hfs.iter().map(|&hf| topo.halfface(hf)).collect();
    if faces.iter().any(|f| f.len() != 3) {
        return Err(NotATet::NonTriangleFace);
    }
    let [a, b, c] = [faces[0][0], faces[0][1], faces[0][2]];
    let d = faces[1..]
        .iter()
        .flatten()
        .copied()
        .find(|v| ![a, b, c].contains(v))
        .ok_or(NotATet::ThreeVertices)?;
    let tet = [a, b, c, d];
    let mut uvw = [[0.0; 3]; 4];
    for (k, &v) in tet.iter().enumerate() {
        let mut off = hfs.iter().zip(&faces).filter(|(_, f)| !f.contains(&v));
        match (off.next(), off.next()) {
            (Some((&hf, _)), None) => uvw[k] = param[hf],
            _ => return Err(NotATet::NotOpposite { vertex: v }),
        }
    }
    if faces.iter().any(|f| f.iter().any(|v| !tet.contains(v))) {
        return Err(NotATet::MoreThanFourVertices);
    }
    Ok((tet, uvw))
}
