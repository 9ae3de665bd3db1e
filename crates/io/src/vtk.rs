//! Legacy ASCII VTK unstructured grids of quads (cell type 9) or hexes
//! (cell type 12), as [`crate::write_cells`] writes them: `POINTS n
//! <type>`, `CELLS m size`, `CELL_TYPES m`; other sections are ignored.
//!
//! Output: [`VtkMesh`], quads or hexes (every cell of one type; mixed or
//! other cell types are refused naming the cell). Counts are checked
//! against the tokens left before any allocation; every error names the
//! line.

use dualex_cells::{HexMesh, QuadMesh};
use dualex_map::error::{
    CountError, Format, FormatError, IndexError, RangeStyle, Subject, SyntaxError,
};
use dualex_map::{ElementKind, InputError, InputErrorKind};

/// A mesh read from VTK.
#[derive(Clone, Debug, PartialEq)]
pub enum VtkMesh {
    /// Cell type 9.
    Quads(QuadMesh),
    /// Cell type 12.
    Hexes(HexMesh),
}

/// Tokens with their line numbers.
struct Tokens<'a> {
    toks: Vec<(usize, &'a str)>,
    next: usize,
}

impl<'a> Tokens<'a> {
    fn new(text: &'a str) -> Self {
        let toks = text
            .lines()
            .enumerate()
            .flat_map(|(i, l)| l.split_whitespace().map(move |t| (i + 1, t)))
            .collect();
        Tokens { toks, next: 0 }
    }

    fn line(&self) -> usize {
        self.toks
            .get(self.next.min(self.toks.len().saturating_sub(1)))
            .map_or(0, |t| t.0)
    }

    fn word(&mut self, what: &'static str) -> Result<&'a str, InputError> {
        let t = self.toks.get(self.next).ok_or_else(|| {
            InputError::at_line(self.line(), SyntaxError::Truncated { expected: what })
        })?;
        self.next += 1;
        Ok(t.1)
    }

    fn parse<T: std::str::FromStr>(&mut self, what: &'static str) -> Result<T, InputError> {
        let line = self.line();
        let w = self.word(what)?;
        w.parse().map_err(|_| {
            let found = w.to_string();
            InputError::at_line(line, SyntaxError::ExpectedValue { what, found })
        })
    }

    /// A count of items of `per` tokens each, checked against what is left.
    fn count(&mut self, what: &'static str, per: usize) -> Result<usize, InputError> {
        let line = self.line();
        let count: usize = self.parse(what)?;
        if count.saturating_mul(per) > self.toks.len() - self.next {
            return Err(InputError::at_line(
                line,
                CountError::ExceedsFile { what, count },
            ));
        }
        Ok(count)
    }
}

/// Parses a legacy ASCII VTK file (module docs).
pub fn parse_vtk(bytes: &[u8]) -> Result<VtkMesh, InputError> {
    let text = std::str::from_utf8(bytes).map_err(|_| {
        let (format, reason) = (Format::Vtk, None);
        InputError::new(FormatError::NotText { format, reason })
    })?;
    if !text.starts_with("# vtk DataFile") {
        return Err(InputError::at_line(1, FormatError::NotFormat(Format::Vtk)));
    }
    let mut t = Tokens::new(text);
    let mut positions = Vec::new();
    let mut cells: Vec<Vec<u32>> = Vec::new();
    let mut types: Vec<u8> = Vec::new();
    while t.next < t.toks.len() {
        let (line, word) = t.toks[t.next];
        t.next += 1;
        match word {
            "BINARY" => return Err(InputError::at_line(line, FormatError::Binary(Format::Vtk))),
            "POINTS" => {
                let n = t.count("point count", 3)?;
                t.word("coordinate type")?;
                positions = Vec::with_capacity(n);
                for _ in 0..n {
                    let p = [t.parse("x")?, t.parse("y")?, t.parse("z")?];
                    if !p.iter().all(|c: &f64| c.is_finite()) {
                        let what = Subject::Coordinate;
                        let e = InputErrorKind::NonFinite { what, token: None };
                        return Err(InputError::at_line(t.line(), e));
                    }
                    positions.push(p);
                }
            }
            "CELLS" => {
                let m = t.count("cell count", 2)?;
                t.parse::<usize>("cell list size")?;
                cells = Vec::with_capacity(m);
                for _ in 0..m {
                    let k = t.count("cell size", 1)?;
                    let c = (0..k)
                        .map(|_| t.parse::<u32>("vertex index"))
                        .collect::<Result<Vec<_>, _>>()?;
                    cells.push(c);
                }
            }
            "CELL_TYPES" => {
                let m = t.count("cell type count", 1)?;
                types = (0..m)
                    .map(|_| t.parse::<u8>("cell type"))
                    .collect::<Result<_, _>>()?;
            }
            _ => {}
        }
    }
    build(positions, cells, &types)
}

fn build(
    positions: Vec<[f64; 3]>,
    cells: Vec<Vec<u32>>,
    types: &[u8],
) -> Result<VtkMesh, InputError> {
    if cells.is_empty() {
        let what = ElementKind::Cell;
        return Err(CountError::Empty { what, reason: None }.into());
    }
    if types.len() != cells.len() {
        return Err(CountError::CellTypes {
            cells: cells.len(),
            types: types.len(),
        }
        .into());
    }
    let nv = positions.len();
    for (i, c) in cells.iter().enumerate() {
        let cell = |e: InputErrorKind| InputError::new(ElementKind::Cell.at(i).error(e));
        if let Some(&v) = c.iter().find(|&&v| v as usize >= nv) {
            return Err(cell(
                IndexError::VertexOutOfRange {
                    vertex: v.into(),
                    count: nv,
                    style: RangeStyle::Points,
                }
                .into(),
            ));
        }
        let want = match types[i] {
            9 => 4,
            12 => 8,
            t => return Err(cell(FormatError::CellType(t).into())),
        };
        if c.len() != want || types[i] != types[0] {
            return Err(cell(
                FormatError::MixedCells {
                    vertices: c.len(),
                    cell_type: types[i],
                }
                .into(),
            ));
        }
    }
    Ok(if types[0] == 9 {
        VtkMesh::Quads(QuadMesh {
            positions,
            cells: cells.iter().map(|c| [c[0], c[1], c[2], c[3]]).collect(),
        })
    } else {
        VtkMesh::Hexes(HexMesh {
            positions,
            cells: cells
                .iter()
                .map(|c| [c[0], c[1], c[2], c[3], c[4], c[5], c[6], c[7]])
                .collect(),
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn written_meshes_read_back() {
        let quads = QuadMesh {
            positions: vec![
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [1.0, 1.0, 0.5],
                [0.0, 1.0, 0.0],
            ],
            cells: vec![[0, 1, 2, 3]],
        };
        let mut buf = Vec::new();
        crate::write_cells::quad_vtk(&mut buf, &quads).unwrap();
        assert_eq!(parse_vtk(&buf).unwrap(), VtkMesh::Quads(quads));
        let hexes = HexMesh {
            positions: (0..8)
                .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2) as f64])
                .collect(),
            cells: vec![[0, 1, 3, 2, 4, 5, 7, 6]],
        };
        let mut buf = Vec::new();
        crate::write_cells::hex_vtk(&mut buf, &hexes).unwrap();
        assert_eq!(parse_vtk(&buf).unwrap(), VtkMesh::Hexes(hexes));
    }

    #[test]
    fn bad_files_are_refused() {
        let head = "# vtk DataFile Version 3.0\nx\nASCII\nDATASET UNSTRUCTURED_GRID\n";
        for (body, needle) in [
            ("POINTS 99999999999 double\n", "more than the file holds"),
            (
                "POINTS 1 double\n0 0 0\nCELLS 1 5\n4 0 0 0 9\nCELL_TYPES 1\n9\n",
                "out of range",
            ),
            (
                "POINTS 1 double\n0 0 0\nCELLS 1 4\n3 0 0 0\nCELL_TYPES 1\n5\n",
                "type 5",
            ),
            ("POINTS 1 double\n0 nan 0\n", "not finite"),
        ] {
            let e = parse_vtk(format!("{head}{body}").as_bytes()).unwrap_err();
            assert!(e.to_string().contains(needle), "{body}: {e}");
        }
        assert!(parse_vtk(b"hello").is_err());
    }
}
