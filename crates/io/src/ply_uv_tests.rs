//! PLY maps with per-vertex texture coordinates (`u v`, `s t`,
//! `texture_u texture_v`): ascii and binary, extraction, errors.

use crate::test_scratch::ScratchFile;
use crate::{parse_ply, parse_polygon_ply, read_tri_map, write_tri_map};
use dualex_map::TriMap;

/// The pair names the reader accepts.
const NAMINGS: [[&str; 2]; 3] = [["u", "v"], ["s", "t"], ["texture_u", "texture_v"]];

/// An `n × n` grid of unit squares split into triangles, positions in the
/// plane `z = 1`, map `(x, y) · scale` per vertex: a map without seams.
fn grid(n: u32, scale: f64) -> TriMap {
    let mut m = TriMap::default();
    for j in 0..=n {
        for i in 0..=n {
            m.positions.push([i as f64, j as f64, 1.0]);
        }
    }
    for j in 0..n {
        for i in 0..n {
            let v = |a: u32, b: u32| (j + b) * (n + 1) + i + a;
            m.simplices.push([v(0, 0), v(1, 0), v(1, 1)]);
            m.simplices.push([v(0, 0), v(1, 1), v(0, 1)]);
        }
    }
    let uv = |v: u32| {
        let p = m.positions[v as usize];
        [p[0] * scale, p[1] * scale]
    };
    m.coords = m.simplices.iter().map(|s| s.map(uv)).collect();
    m
}

/// Writes `m`'s positions and per-vertex map (taken from the corners) as a
/// PLY: vertex `x y z <first> red <second>` (the map as `double`, or
/// `float` in binary when `float`), face `vertex_indices`.
fn per_vertex_ply(m: &TriMap, names: [&str; 2], binary: bool, float: bool) -> Vec<u8> {
    let mut uv = vec![[0.0; 2]; m.positions.len()];
    for (s, c) in m.simplices.iter().zip(&m.coords) {
        for k in 0..3 {
            uv[s[k] as usize] = c[k];
        }
    }
    let ty = if float { "float" } else { "double" };
    let format = if binary {
        "binary_little_endian"
    } else {
        "ascii"
    };
    let [a, b] = names;
    let mut out = format!(
        "ply\nformat {format} 1.0\nelement vertex {}\nproperty double x\nproperty double y\n\
         property double z\nproperty {ty} {a}\nproperty uchar red\nproperty {ty} {b}\n\
         element face {}\nproperty list uchar int vertex_indices\nend_header\n",
        m.positions.len(),
        m.simplices.len()
    )
    .into_bytes();
    let real = |out: &mut Vec<u8>, x: f64, narrow: bool| match (binary, narrow) {
        (false, _) => out.extend_from_slice(format!("{x:?} ").as_bytes()),
        (true, true) => out.extend_from_slice(&(x as f32).to_le_bytes()),
        (true, false) => out.extend_from_slice(&x.to_le_bytes()),
    };
    for (p, t) in m.positions.iter().zip(&uv) {
        p.iter().for_each(|&x| real(&mut out, x, false));
        real(&mut out, t[0], float);
        out.extend_from_slice(if binary { &[7] } else { b"7 " });
        real(&mut out, t[1], float);
        if !binary {
            out.push(b'\n');
        }
    }
    for s in &m.simplices {
        if binary {
            out.push(3);
            s.iter()
                .for_each(|&v| out.extend_from_slice(&(v as i32).to_le_bytes()));
        } else {
            out.extend_from_slice(format!("3 {} {} {}\n", s[0], s[1], s[2]).as_bytes());
        }
    }
    out
}

fn err(bytes: &[u8]) -> String {
    parse_ply(bytes).unwrap_err().to_string()
}

#[test]
fn every_naming_in_ascii_and_binary() {
    let m = grid(3, 0.5);
    for names in NAMINGS {
        for (binary, float) in [(false, false), (true, false), (true, true)] {
            let bytes = per_vertex_ply(&m, names, binary, float);
            let got = parse_ply(&bytes).unwrap_or_else(|e| panic!("{names:?} {binary}: {e}"));
            assert_eq!(got, m, "{names:?} binary {binary} float {float}");
        }
    }
}

#[test]
fn per_vertex_map_extracts_through_read_tri_map() {
    // [0, 4]² under the identity map: a 4 × 4 grid of quads
    let m = grid(2, 2.0);
    let per_face = ScratchFile::new("uv-per-face.ply");
    write_tri_map(&per_face, &m).unwrap();
    let opts = dualex_quad::QuadOptions::default();
    let (expected, _) = dualex_quad::extract(&read_tri_map(&per_face).unwrap(), &opts).unwrap();
    for (names, binary) in [(NAMINGS[0], false), (NAMINGS[2], true)] {
        let file = ScratchFile::new(&format!("uv-{}-{binary}.ply", names[0]));
        std::fs::write(&file, per_vertex_ply(&m, names, binary, false)).unwrap();
        let map = read_tri_map(&file).unwrap();
        let (mesh, _) = dualex_quad::extract(&map, &opts).unwrap();
        assert_eq!(mesh.cells.len(), 16, "{names:?} binary {binary}");
        assert_eq!(mesh.cells.len(), expected.cells.len());
        assert_eq!(mesh.positions.len(), expected.positions.len());
    }
}

#[test]
fn per_face_texcoord_wins() {
    let m = grid(1, 1.0);
    let text = String::from_utf8(per_vertex_ply(&m, ["u", "v"], false, false)).unwrap();
    let both = text
        .replace(
            "vertex_indices\n",
            "vertex_indices\nproperty list uchar float texcoord\n",
        )
        .replace("3 0 1 3\n", "3 0 1 3 6 0 0 2 0 2 2\n")
        .replace("3 0 3 2\n", "3 0 3 2 6 0 0 2 2 0 2\n");
    let got = parse_ply(both.as_bytes()).unwrap();
    assert_eq!(got.coords, grid(1, 2.0).coords);
    // a half pair does not matter then
    let half = both.replace("property double v\n", "property double w\n");
    assert_eq!(parse_ply(half.as_bytes()).unwrap().coords, got.coords);
}

#[test]
fn face_element_first_still_reads_per_vertex_pairs() {
    let text = "ply\nformat ascii 1.0\nelement face 1\nproperty list uchar int vertex_indices\n\
        element vertex 3\nproperty float x\nproperty float y\nproperty float z\n\
        property float s\nproperty float t\nend_header\n3 0 1 2\n\
        0 0 0 0 0\n1 0 0 1 0\n0 1 0 0 1\n";
    let m = parse_ply(text.as_bytes()).unwrap();
    assert_eq!(m.coords, vec![[[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]]);
}

#[test]
fn half_pairs_and_bad_values_are_named() {
    let m = grid(1, 1.0);
    let text = String::from_utf8(per_vertex_ply(&m, ["u", "v"], false, false)).unwrap();
    let no_v = text.replace("property double v\n", "property double w\n");
    assert_eq!(
        err(no_v.as_bytes()),
        "line 3: element `vertex` has property `u` but no `v` (per-vertex texture coordinates need both)"
    );
    let file = ScratchFile::new("uv-half.ply");
    std::fs::write(&file, no_v.replace("double u", "double t")).unwrap();
    assert_eq!(
        read_tri_map(&file).unwrap_err().to_string(),
        format!(
            "{}: line 3: element `vertex` has property `t` but no `s` (per-vertex texture coordinates need both)",
            file.display()
        )
    );
    // a polygon mesh does not need a map
    assert_eq!(parse_polygon_ply(no_v.as_bytes()).unwrap().faces.len(), 2);
    let neither = text
        .replace("double u\n", "double a\n")
        .replace("double v\n", "double b\n");
    assert_eq!(
        err(neither.as_bytes()),
        "line 10: element `face` has no `texcoord` list property (per-corner u0 v0 u1 v1 u2 v2), \
         and element `vertex` no `u v`, `s t` or `texture_u texture_v` pair"
    );
    let nan = text.replace("1.0 0.0 1.0 1.0 7 0.0", "1.0 0.0 1.0 1.0 7 nan");
    assert_eq!(
        err(nan.as_bytes()),
        "line 14: vertex 1: texture coordinate `v` is not finite"
    );
    let range = text.replace("3 0 1 3\n", "3 0 1 9\n");
    assert_eq!(
        err(range.as_bytes()),
        "triangle 0: corner 2 refers to vertex 9, but there are 4 vertices"
    );
}
