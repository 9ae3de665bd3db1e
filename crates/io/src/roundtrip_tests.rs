//! Round trips of the map writers through the map readers, with exact
//! equality of every coordinate.

use crate::write_map::{tet_map_hexex, tri_map_obj, tri_map_ply};
use crate::{
    parse_hexex, parse_obj, parse_ply, read_tet_map, read_tri_map, write_tet_map, write_tri_map,
    PlyFormat,
};
use dualex_map::{TetMap, TriMap};

/// Deterministic awkward floats: full-precision, tiny, huge, negative zero.
fn values(n: usize, seed: u64) -> Vec<f64> {
    let mut s = seed;
    (0..n)
        .map(|i| {
            s = s
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let x = (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            match i % 7 {
                0 => x * 1e-300,
                1 => x * 1e300,
                2 => -0.0,
                3 => 5e-324,
                _ => x * 37.0,
            }
        })
        .collect()
}

/// An n×n grid of triangle pairs with awkward coordinates.
fn tri_map(n: u32) -> TriMap {
    let mut m = TriMap::default();
    let vals = values(((n + 1) * (n + 1) * 3) as usize, 7);
    m.positions = vals.chunks(3).map(|c| [c[0], c[1], c[2]]).collect();
    let uv = values((n * n * 12) as usize, 11);
    let mut k = 0;
    for i in 0..n {
        for j in 0..n {
            let v = i * (n + 1) + j;
            for t in [[v, v + 1, v + n + 2], [v, v + n + 2, v + n + 1]] {
                m.simplices.push(t);
                m.coords.push([
                    [uv[k], uv[k + 1]],
                    [uv[k + 2], uv[k + 3]],
                    [uv[k + 4], uv[k + 5]],
                ]);
                k += 6;
            }
        }
    }
    m
}

fn tet_map() -> TetMap {
    let vals = values(5 * 3 + 2 * 12, 3);
    TetMap {
        positions: vals.chunks(3).take(5).map(|c| [c[0], c[1], c[2]]).collect(),
        simplices: vec![[0, 1, 2, 3], [1, 2, 3, 4]],
        coords: vals[15..]
            .chunks(12)
            .map(|c| std::array::from_fn(|i| [c[3 * i], c[3 * i + 1], c[3 * i + 2]]))
            .collect(),
    }
}

fn bytes(f: impl FnOnce(&mut Vec<u8>) -> std::io::Result<()>) -> Vec<u8> {
    let mut out = Vec::new();
    f(&mut out).unwrap();
    out
}

#[test]
fn tri_map_obj_is_exact() {
    let m = tri_map(4);
    assert_eq!(parse_obj(&bytes(|w| tri_map_obj(w, &m))).unwrap(), m);
}

#[test]
fn tri_map_ply_is_exact_in_every_format() {
    let m = tri_map(4);
    for format in [
        PlyFormat::Ascii,
        PlyFormat::BinaryLittleEndian,
        PlyFormat::BinaryBigEndian,
    ] {
        let b = bytes(|w| tri_map_ply(w, &m, format));
        assert_eq!(parse_ply(&b).unwrap(), m, "{format:?}");
        // truncated files give a clean error (an ascii cut inside the last
        // number still parses, as a shorter number: only cut whole records)
        let cuts = match format {
            PlyFormat::Ascii => vec![b.len() / 2, b.len() - 20],
            _ => vec![b.len() - 1, b.len() - 9, b.len() / 2],
        };
        for cut in cuts {
            assert!(parse_ply(&b[..cut]).is_err(), "{format:?} cut at {cut}");
        }
    }
}

#[test]
fn tet_map_hexex_is_exact() {
    let m = tet_map();
    let b = bytes(|w| tet_map_hexex(w, &m));
    assert_eq!(parse_hexex(&b).unwrap(), m);
    let text = String::from_utf8(b).unwrap();
    let cut = text.trim_end().rsplitn(4, ' ').last().unwrap();
    let e = parse_hexex(cut.as_bytes()).unwrap_err().to_string();
    assert!(
        e.contains("line 9: file ends in tet 1: expected 12 map coordinates, found 9"),
        "{e}"
    );
}

#[test]
fn files_round_trip_and_name_the_file() {
    let scratch = crate::test_scratch::ScratchDir::new("maps");
    let dir = scratch.path();
    let m = tri_map(3);
    for ext in ["obj", "ply"] {
        let p = dir.join(format!("m.{ext}"));
        write_tri_map(&p, &m).unwrap();
        assert_eq!(read_tri_map(&p).unwrap(), m, "{ext}");
    }
    let t = tet_map();
    let p = dir.join("t.hexex");
    write_tet_map(&p, &t).unwrap();
    assert_eq!(read_tet_map(&p).unwrap(), t);
    let bad = dir.join("bad.obj");
    std::fs::write(&bad, "v 0 0 0\nf 1/1 1/1 1/1 1/1\n").unwrap();
    let e = read_tri_map(&bad).unwrap_err().to_string();
    assert_eq!(e, format!("{}: line 2: face has 4 vertices; only triangles are supported (triangulate the mesh first)", bad.display()));
    let e = read_tri_map(&dir.join("m.stl")).unwrap_err().to_string();
    assert!(
        e.ends_with("m.stl: unsupported input format `.stl`; use .obj, .ply"),
        "{e}"
    );
    let e = read_tet_map(&dir.join("missing.hexex"))
        .unwrap_err()
        .to_string();
    assert!(e.contains("missing.hexex: cannot read:"), "{e}");
    let mut broken = m.clone();
    broken.simplices[0][1] = 99;
    let e = write_tri_map(&dir.join("broken.obj"), &broken)
        .unwrap_err()
        .to_string();
    assert!(
        e.ends_with(
            "cannot write: triangle 0: corner 1 refers to vertex 99, but there are 16 vertices"
        ),
        "{e}"
    );
    assert!(!dir.join("broken.obj").exists());
}
