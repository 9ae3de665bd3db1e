//! HexEx `.hexex` input: a tet mesh with a 3D map.
//!
//! Input, a whitespace-insensitive token stream:
//! ```text
//!   n_v
//!   x y z                      × n_v
//!   n_t
//!   a b c d  u v w ×4          × n_t   (a..d: 0-based vertex indices)
//! ```
//! Numbers may be short decimals or scientific notation. Output: a
//! [`TetMap`]. Errors name the line of the offending token (or the last line
//! when the file ends early) and the vertex / tet, counted from 0. Counts are
//! checked against the bytes left before anything is allocated.

use crate::scan::{as_text, fits, parse_finite, Tokens};
use dualex_map::error::{
    Awaited, CountError, EmptyReason, Format, IndexError, Subject, SyntaxError, Token, Values,
};
use dualex_map::{Element, ElementKind, InputError, TetMap};

/// Parses a `.hexex` tet map (see the module docs).
pub fn parse_hexex(bytes: &[u8]) -> Result<TetMap, InputError> {
    if let Some(map) = crate::fast::hexex(bytes) {
        return Ok(map);
    }
    parse_hexex_sequential(bytes)
}

/// The sequential reader: the reference of [`crate::fast::hexex`], and the
/// one that reports errors.
pub(crate) fn parse_hexex_sequential(bytes: &[u8]) -> Result<TetMap, InputError> {
    let text = as_text(bytes, Format::Hexex)?;
    let mut t = Tokens::new(text, 1);
    let nv = read_count(&mut t, ElementKind::Vertex, 3)?;
    let mut positions = Vec::with_capacity(nv);
    for i in 0..nv {
        let mut p = [0.0; 3];
        let owner = ElementKind::Vertex.at(i);
        read_numbers(&mut t, &mut p, owner, Values::Coordinates)?;
        positions.push(p);
    }
    let nt = read_count(&mut t, ElementKind::Tet, 16)?;
    let mut map = TetMap {
        positions,
        simplices: Vec::with_capacity(nt),
        coords: Vec::with_capacity(nt),
    };
    for s in 0..nt {
        let tet = read_tet_indices(&mut t, s, nv)?;
        let mut uvw = [0.0; 12];
        let owner = ElementKind::Tet.at(s);
        read_numbers(&mut t, &mut uvw, owner, Values::MapCoordinates)?;
        map.simplices.push(tet);
        map.coords.push(std::array::from_fn(|c| {
            [uvw[3 * c], uvw[3 * c + 1], uvw[3 * c + 2]]
        }));
    }
    if let Some((tok, line)) = t.next_token() {
        let token = Token::new(tok);
        let declared = nt;
        return Err(InputError::at_line(
            line,
            SyntaxError::TrailingToken { token, declared },
        ));
    }
    if map.simplices.is_empty() {
        let empty = CountError::Empty {
            what: ElementKind::Tet,
            reason: Some(EmptyReason::ZeroCount("tet")),
        };
        return Err(InputError::at_line(t.last_line(), empty));
    }
    map.validate()?;
    Ok(map)
}

/// Reads a count of items of `tokens_per_item` tokens and checks that they
/// can fit in the bytes left (each token takes at least 2 bytes).
fn read_count(
    t: &mut Tokens<'_>,
    what: ElementKind,
    tokens_per_item: u64,
) -> Result<usize, InputError> {
    let Some((tok, line)) = t.next_token() else {
        let awaited = Awaited::Count(what);
        return Err(InputError::at_line(
            t.last_line(),
            SyntaxError::EndsBefore(awaited),
        ));
    };
    let Ok(count) = tok.parse::<u64>() else {
        let e = SyntaxError::NotANonNegativeInteger {
            what: Subject::Count(what),
            token: Token::new(tok),
            hint: false,
        };
        return Err(InputError::at_line(line, e));
    };
    if !fits(count, 2 * tokens_per_item, t.remaining(), 1) {
        let e = CountError::ExceedsBytes {
            what,
            count,
            bytes: t.remaining(),
            numbers_each: tokens_per_item,
        };
        return Err(InputError::at_line(line, e));
    }
    usize::try_from(count)
        .map_err(|_| InputError::at_line(line, CountError::TooLarge { what, count }))
}

/// Fills `out` with finite numbers of `owner` (a vertex / tet).
fn read_numbers(
    t: &mut Tokens<'_>,
    out: &mut [f64],
    owner: Element,
    values: Values,
) -> Result<(), InputError> {
    for k in 0..out.len() {
        let Some((tok, line)) = t.next_token() else {
            let e = SyntaxError::EndsIn {
                owner,
                expected: out.len(),
                values,
                found: k,
            };
            return Err(InputError::at_line(t.last_line(), e));
        };
        let x = parse_finite(tok, Subject::Value)
            .map_err(|e| InputError::at_line(line, owner.clone().error(e)))?;
        if let Some(slot) = out.get_mut(k) {
            *slot = x;
        }
    }
    Ok(())
}

/// Reads the 4 vertex indices of tet `s`.
fn read_tet_indices(t: &mut Tokens<'_>, s: usize, nv: usize) -> Result<[u32; 4], InputError> {
    let mut tet = [0u32; 4];
    for (c, slot) in tet.iter_mut().enumerate() {
        let Some((tok, line)) = t.next_token() else {
            let e = SyntaxError::EndsIn {
                owner: ElementKind::Tet.at(s),
                expected: 4,
                values: Values::VertexIndices,
                found: c,
            };
            return Err(InputError::at_line(t.last_line(), e));
        };
        let at = |e: dualex_map::InputErrorKind| {
            let corner = ElementKind::Corner.at(c).error(e);
            InputError::at_line(line, ElementKind::Tet.at(s).error(corner))
        };
        let Ok(i) = tok.parse::<u64>() else {
            let e = SyntaxError::NotANonNegativeInteger {
                what: Subject::Index(ElementKind::Vertex),
                token: Token::new(tok),
                hint: tok.parse::<f64>().is_ok(),
            };
            return Err(at(e.into()));
        };
        if i >= nv as u64 {
            let e = IndexError::OutOfRange {
                what: ElementKind::Vertex,
                index: i,
                count: nv,
                counted: Some(ElementKind::Vertex),
            };
            return Err(at(e.into()));
        }
        *slot = i as u32;
    }
    Ok(tet)
}

#[cfg(test)]
mod tests {
    use super::*;

    const TET: &str = "4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1\n0 1 2 3 0 0 0 1e0 0 0 0 .5 0 0 0 2.5E-1\n";

    fn err(text: &str) -> String {
        parse_hexex(text.as_bytes()).unwrap_err().to_string()
    }

    #[test]
    fn reads_one_tet() {
        let m = parse_hexex(TET.as_bytes()).unwrap();
        assert_eq!(m.positions.len(), 4);
        assert_eq!(m.simplices, vec![[0, 1, 2, 3]]);
        assert_eq!(
            m.coords[0],
            [
                [0.0, 0.0, 0.0],
                [1.0, 0.0, 0.0],
                [0.0, 0.5, 0.0],
                [0.0, 0.0, 0.25]
            ]
        );
        // whitespace-insensitive: all on one line, tabs, CRLF
        let flat = TET.replace('\n', "\t\r\n ").replace("\r\n", " ");
        assert_eq!(parse_hexex(flat.as_bytes()).unwrap(), m);
    }

    #[test]
    fn truncations_name_the_element() {
        let cut = "4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1\n0 1 2 3 0.0 0.0 0.0 1.0 0.0 0.0 0.0 1.0 0.0\n";
        assert_eq!(
            err(cut),
            "line 7: file ends in tet 0: expected 12 map coordinates, found 9"
        );
        let e = err("4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1\n0 1\n");
        assert_eq!(e, "line 6: the file declares 1 tets, but only 5 bytes follow (each tet needs 16 numbers): truncated file or wrong count");
        assert_eq!(
            err("4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"),
            "line 5: file ends before the tet count"
        );
        assert_eq!(
            err("2\n0.0 0.0 0.0 1.0 0.0\n"),
            "line 2: file ends in vertex 1: expected 3 coordinates, found 2"
        );
        assert_eq!(err(""), "line 1: file ends before the vertex count");
    }

    #[test]
    fn bad_tokens_name_their_line() {
        let e = err(&TET.replace("0 1 2 3", "0 1 2.0 3"));
        assert!(e.starts_with("line 7: tet 0: corner 2: vertex index `2.0` is not a non-negative integer (a number"), "{e}");
        assert_eq!(
            err(&TET.replace("0 1 2 3", "0 1 7 3")),
            "line 7: tet 0: corner 2: vertex index 7 is out of range (the file has 4 vertices)"
        );
        assert_eq!(
            err(&TET.replace("1 0 0\n", "1 x 0\n")),
            "line 3: vertex 1: value `x` is not a number"
        );
        assert_eq!(
            err(&TET.replace("2.5E-1", "nan")),
            "line 7: tet 0: value is not finite (`nan`)"
        );
        assert_eq!(
            err(&format!("{TET}\n7\n")),
            "line 9: unexpected `7` after the last tet (the file declares 1 tets)"
        );
        assert_eq!(
            err(&TET.replace("\n1\n", "\n-1\n")),
            "line 6: tet count `-1` is not a non-negative integer"
        );
        assert_eq!(
            err("4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0\n"),
            "line 6: no tets (the tet count is 0)"
        );
        assert_eq!(
            err(&TET.replace("0 1 2 3", "0 1 1 3")),
            "tet 0: vertex 1 appears twice"
        );
    }

    #[test]
    fn absurd_counts_fail_before_allocating() {
        let e = err("100000000000000\n0 0 0\n");
        assert_eq!(e, "line 1: the file declares 100000000000000 vertices, but only 7 bytes follow (each vertex needs 3 numbers): truncated file or wrong count");
        let e = err("18446744073709551615\n");
        assert!(
            e.starts_with("line 1: the file declares 18446744073709551615 vertices"),
            "{e}"
        );
        let e = err(&TET.replace("\n1\n", "\n99999999999\n"));
        assert!(
            e.starts_with("line 6: the file declares 99999999999 tets, but only"),
            "{e}"
        );
    }
}
