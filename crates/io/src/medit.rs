//! Reader of MEDIT `.mesh` hex meshes (ASCII): the `Vertices` and
//! `Hexahedra` sections (1-based indices, a reference number after each
//! record); other sections are skipped by their counts. Used by
//! `dualex view` to show a hex mesh written by `dualex hex`.

use dualex_cells::HexMesh;
use dualex_map::InputError;

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

    fn number<T: std::str::FromStr>(&mut self, what: &str) -> Result<T, InputError> {
        let (t, l) = self
            .next()
            .ok_or_else(|| InputError::new(format!("file ends while reading {what}")))?;
        t.parse()
            .map_err(|_| InputError::at_line(l, format!("{what}: `{t}` is not a valid number")))
    }
}

/// Parses a MEDIT `.mesh` with hexahedra.
pub fn parse_medit_hex(bytes: &[u8]) -> Result<HexMesh, InputError> {
    let text = std::str::from_utf8(bytes).map_err(|_| InputError::new("not a text MEDIT file"))?;
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
                tok.number::<f64>(word)?;
            }
            "Vertices" => {
                let n: usize = tok.number("vertex count")?;
                if !left(n, 6) {
                    return Err(InputError::at_line(
                        line,
                        format!("{n} vertices do not fit in the file"),
                    ));
                }
                for v in 0..n {
                    let p: [f64; 3] = [
                        tok.number(&format!("vertex {v}"))?,
                        tok.number(&format!("vertex {v}"))?,
                        tok.number(&format!("vertex {v}"))?,
                    ];
                    tok.number::<f64>(&format!("vertex {v} reference"))?;
                    mesh.positions.push(p);
                }
            }
            "Hexahedra" => {
                let n: usize = tok.number("hexahedron count")?;
                if !left(n, 18) {
                    return Err(InputError::at_line(
                        line,
                        format!("{n} hexahedra do not fit in the file"),
                    ));
                }
                for h in 0..n {
                    let mut cell = [0u32; 8];
                    for c in cell.iter_mut() {
                        let i: u64 = tok.number(&format!("hexahedron {h}"))?;
                        if i == 0 || i > mesh.positions.len() as u64 {
                            return Err(InputError::new(format!(
                                "hexahedron {h}: vertex {i} out of range 1..={}",
                                mesh.positions.len()
                            )));
                        }
                        *c = (i - 1) as u32;
                    }
                    tok.number::<f64>(&format!("hexahedron {h} reference"))?;
                    mesh.cells.push(cell);
                }
            }
            "End" => break,
            other => {
                return Err(InputError::at_line(
                    line,
                    format!("unsupported MEDIT section `{other}` (only Vertices and Hexahedra)"),
                ))
            }
        }
    }
    if mesh.cells.is_empty() {
        return Err(InputError::new("no hexahedra"));
    }
    Ok(mesh)
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
