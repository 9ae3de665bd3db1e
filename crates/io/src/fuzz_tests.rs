//! Deterministic mutation fuzzing: corrupted versions of valid files must
//! give `Ok` or a one-line error, never a panic or a runaway allocation.

use crate::write_map::{tet_map_hexex, tri_map_obj, tri_map_ply};
use crate::{parse_hexex, parse_obj, parse_ply, parse_polygon_obj, parse_polygon_ply, PlyFormat};
use dualex_map::{TetMap, TriMap};

fn square() -> TriMap {
    TriMap {
        positions: vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, 0.0],
        ],
        simplices: vec![[0, 1, 2], [0, 2, 3]],
        coords: vec![
            [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]],
            [[0.0, 0.0], [1.0, 1.0], [0.0, 1.0]],
        ],
    }
}

fn tet() -> TetMap {
    TetMap {
        positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        simplices: vec![[0, 1, 2, 3]],
        coords: vec![[[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]]],
    }
}

/// `n` mutants of `base`: byte overwrites (often digits, spaces, 0xff),
/// truncations and duplicated spans.
pub(crate) fn mutants(base: &[u8], n: usize) -> Vec<Vec<u8>> {
    let mut s = 0x9e3779b97f4a7c15u64;
    let mut next = move |m: usize| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s % m.max(1) as u64) as usize
    };
    let alphabet = b"0123456789 -+.e\n/#\t\xff\x00\x7f9";
    (0..n)
        .map(|_| {
            let mut b = base.to_vec();
            for _ in 0..1 + next(3) {
                let i = next(b.len());
                match next(4) {
                    0 => b.truncate(i),
                    1 => {
                        let span: Vec<u8> = b[i..(i + next(16)).min(b.len())].to_vec();
                        b.splice(i..i, span);
                    }
                    _ if i < b.len() => b[i] = alphabet[next(alphabet.len())],
                    _ => {}
                }
            }
            b
        })
        .collect()
}

fn bytes(f: impl FnOnce(&mut Vec<u8>) -> std::io::Result<()>) -> Vec<u8> {
    let mut out = Vec::new();
    f(&mut out).unwrap();
    out
}

/// Checks the error is one line; returns whether it was an error.
fn one_line<T>(r: Result<T, dualex_map::InputError>) -> bool {
    match r {
        Err(e) => {
            assert!(!e.to_string().contains('\n'), "{e}");
            true
        }
        Ok(_) => false,
    }
}

#[test]
fn mutated_files_never_panic() {
    let obj = bytes(|w| tri_map_obj(w, &square()));
    let hexex = bytes(|w| tet_map_hexex(w, &tet()));
    // (errors, oks) per reader: both outcomes must occur, or the mutants
    // are not exercising the error paths
    let mut seen = Vec::new();
    let mut count =
        |name: &str, errs: usize, n: usize| seen.push((name.to_string(), errs, n - errs));
    let errs = mutants(&obj, 3000)
        .iter()
        .filter(|m| one_line(parse_obj(m)) | one_line(parse_polygon_obj(m)))
        .count();
    count("obj", errs, 3000);
    let errs = mutants(&hexex, 3000)
        .iter()
        .filter(|m| one_line(parse_hexex(m)))
        .count();
    count("hexex", errs, 3000);
    for format in [
        PlyFormat::Ascii,
        PlyFormat::BinaryLittleEndian,
        PlyFormat::BinaryBigEndian,
    ] {
        let ply = bytes(|w| tri_map_ply(w, &square(), format));
        let errs = mutants(&ply, 3000)
            .iter()
            .filter(|m| one_line(parse_ply(m)) | one_line(parse_polygon_ply(m)))
            .count();
        count(&format!("{format:?}"), errs, 3000);
    }
    for (name, errs, oks) in &seen {
        eprintln!("{name}: {errs} errors, {oks} ok");
        assert!(*errs > 300 && *oks > 30, "{name}: {errs} errors, {oks} ok");
    }
}
