//! Reader of MEDIT `.mesh` hex meshes (ASCII): the `Vertices` and
//! `Hexahedra` sections (1-based indices, a reference number after each
//! record); other sections are skipped by their counts. Used by
//! `dualex view` to show a hex mesh written by `dualex hex`.

use dualex_cells::HexMesh;
use dualex_map::error::{
    CountError, Format, FormatError, IndexError, RangeStyle, Subject, SyntaxError,
};
use dualex_map::{ElementKind, InputError};

struct Tokens<'a> {
    it: std::iter::Peekable<std::iter::Enumerate<std::str::Lines<'a>>>,
    line: Vec<&'a str>,
    line_no: usize,
}

impl<'a> Tokens<'a> {
    fn next(&mut self) -> Option<(&'a str, usize)> {
        loop {
            if let Some(t) = self.line.pop() {
                return Some((t, self.line_no));
            }
            let (i, l) = self.it.next()?;
            let l = l.split('#').next().unwrap_or("");
            self.line = l.split_whitespace().rev().collect();
            self.line_no = i + 1;
        }
    }

    /// The next token as a number; `what` names it in errors.
    fn number<T: std::str::FromStr>(&mut self, what: Subject) -> Result<T, InputError> {
        let Some((t, l)) = self.next() else {
            return Err(SyntaxError::EndsWhileReading(what).into());
        };
        t.parse().map_err(|_| {
            let token = t.to_string();
            InputError::at_line(l, SyntaxError::NotAValidNumber { what, token })
        })
    }
}

/// Parses a MEDIT `.mesh` with hexahedra.
pub fn parse_medit_hex(bytes: &[u8]) -> Result<HexMesh, InputError> {
    let text = std::str::from_utf8(bytes).map_err(|_| {
        let (format, reason) = (Format::Medit, None);
        InputError::new(FormatError::NotText { format, reason })
    })?;
    let mut tok = Tokens {
        it: text.lines().enumerate().peekable(),
        line: Vec::new(),
        line_no: 0,
    };
    let mut mesh = HexMesh::default();
    let left = |n: usize, per: usize| n.saturating_mul(per) <= bytes.len();
    while let Some((word, line)) = tok.next() {
        match word {
            "MeshVersionFormatted" | "Dimension" => {
                tok.number::<f64>(Subject::Keyword(word.to_string()))?;
            }
            "Vertices" => {
                let n: usize = tok.number(Subject::Count(ElementKind::Vertex))?;
                if !left(n, 6) {
                    return Err(InputError::at_line(
                        line,
                        do_not_fit(ElementKind::Vertex, n),
                    ));
                }
                for v in 0..n {
                    let vertex = || Subject::Element(ElementKind::Vertex.at(v));
                    let p: [f64; 3] = [
                        tok.number(vertex())?,
                        tok.number(vertex())?,
                        tok.number(vertex())?,
                    ];
                    tok.number::<f64>(Subject::Reference(ElementKind::Vertex.at(v)))?;
                    mesh.positions.push(p);
                }
            }
            "Hexahedra" => {
                let n: usize = tok.number(Subject::Count(ElementKind::Hexahedron))?;
                if !left(n, 18) {
                    let e = do_not_fit(ElementKind::Hexahedron, n);
                    return Err(InputError::at_line(line, e));
                }
                for h in 0..n {
                    let hex = || ElementKind::Hexahedron.at(h);
                    let mut cell = [0u32; 8];
                    for c in cell.iter_mut() {
                        let i: u64 = tok.number(Subject::Element(hex()))?;
                        if i == 0 || i > mesh.positions.len() as u64 {
                            let e = IndexError::VertexOutOfRange {
                                vertex: i,
                                count: mesh.positions.len(),
                                style: RangeStyle::OneBased,
                            };
                            return Err(hex().error(e).into());
                        }
                        *c = (i - 1) as u32;
                    }
                    tok.number::<f64>(Subject::Reference(hex()))?;
                    mesh.cells.push(cell);
                }
            }
            "End" => break,
            other => {
                let section = FormatError::MeditSection(other.to_string());
                return Err(InputError::at_line(line, section));
            }
        }
    }
    if mesh.cells.is_empty() {
        let what = ElementKind::Hexahedron;
        return Err(CountError::Empty { what, reason: None }.into());
    }
    Ok(mesh)
}

/// More `what` declared than the file's bytes can hold.
fn do_not_fit(what: ElementKind, count: usize) -> CountError {
    CountError::DoNotFit { what, count }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn round_trip_through_the_writer() {
        let mesh = HexMesh {
            positions: (0..8)
                .map(|i| [(i & 1) as f64, ((i >> 1) & 1) as f64, (i >> 2) as f64 * 0.5])
                .collect(),
            cells: vec![[0, 1, 3, 2, 4, 5, 7, 6]],
        };
        let mut buf = Vec::new();
        crate::write_cells::hex_medit(&mut buf, &mesh).expect("write");
        assert_eq!(parse_medit_hex(&buf).expect("read"), mesh);
    }

    #[test]
    fn bad_files_name_the_element() {
        let e = parse_medit_hex(b"Vertices 1 0 0 0 0 Hexahedra 1 1 2 3 4 5 6 7 8 0")
            .expect_err("range");
        assert!(e.to_string().contains("hexahedron 0"), "{e}");
        let e = parse_medit_hex(b"Vertices 99999999999 0 0").expect_err("count");
        assert!(e.to_string().contains("do not fit"), "{e}");
        assert!(parse_medit_hex(b"").is_err());
    }
}
