//! `dualex quad --uv` as a process (issue 13): every quad's corners carry
//! map coordinates in the chart of the triangle holding its node — an
//! axis-aligned unit square `c ± ½` of exact grid points of the input map
//! (integers with `--grid-offset half`, half-integers with `zero`); on an
//! identity map they are the map's value at each output vertex.

mod common;
use common::*;

/// A parsed `dualex quad --uv` OBJ: positions, `vt`, faces as
/// (vertex, vt) pairs (0-based; vt `None` when the face has none).
struct UvObj {
    v: Vec<[f64; 3]>,
    vt: Vec<[f64; 2]>,
    faces: Vec<Vec<(usize, Option<usize>)>>,
}

fn floats<const K: usize>(rest: &str, line: &str) -> [f64; K] {
    let xs: Vec<f64> = rest
        .split_whitespace()
        .map(|t| t.parse().unwrap_or_else(|e| panic!("{line}: {e}")))
        .collect();
    xs.try_into()
        .unwrap_or_else(|_| panic!("{line}: expected {K} numbers"))
}

fn parse_uv_obj(path: &str) -> UvObj {
    let text = std::fs::read_to_string(path).expect("read the OBJ");
    let mut o = UvObj {
        v: vec![],
        vt: vec![],
        faces: vec![],
    };
    let index = |t: &str| t.parse::<usize>().map(|i| i - 1).expect("1-based index");
    for line in text.lines() {
        if let Some(r) = line.strip_prefix("v ") {
            o.v.push(floats(r, line));
        } else if let Some(r) = line.strip_prefix("vt ") {
            o.vt.push(floats(r, line));
        } else if let Some(r) = line.strip_prefix("f ") {
            let f = r
                .split_whitespace()
                .map(|c| match c.split_once('/') {
                    Some((v, t)) => (index(v), Some(index(t))),
                    None => (index(c), None),
                })
                .collect();
            o.faces.push(f);
        }
    }
    o
}

/// Runs `quad --uv` on `input` with `extra` options; the parsed output.
fn quad_uv(dir: &Scratch, input: &str, extra: &[&str]) -> UvObj {
    let out_path = dir.arg("q.obj");
    let mut args = vec!["quad", input, "-o", &out_path, "--uv", "-q"];
    args.extend_from_slice(extra);
    let out = dualex(&args);
    assert!(out.status.success(), "{args:?}: {}", text(&out));
    parse_uv_obj(&out_path)
}

/// Asserts that every face has 4 `vt` or none, and that those with form
/// `c ± ½` with all values on the grid `frac` (0: integers, 0.5:
/// half-integers); the numbers of faces with and without.
fn unit_squares(o: &UvObj, frac: f64, what: &str) -> (usize, usize) {
    assert!(!o.faces.is_empty(), "{what}: no face");
    let mut without = 0;
    for (i, f) in o.faces.iter().enumerate() {
        assert_eq!(f.len(), 4, "{what}: face {i}");
        let uv: Vec<[f64; 2]> = f.iter().filter_map(|&(_, t)| Some(o.vt[t?])).collect();
        if uv.is_empty() {
            without += 1;
            continue;
        }
        assert_eq!(uv.len(), 4, "{what}: face {i} has some vt, not 4");
        let c = [0, 1].map(|a| uv.iter().map(|p| p[a]).sum::<f64>() / 4.0);
        let mut signs = Vec::new();
        for (k, p) in uv.iter().enumerate() {
            for x in p {
                let g = x - frac;
                assert_eq!(
                    g,
                    g.round(),
                    "{what}: face {i} corner {k}: {x} is off the grid"
                );
            }
            let d = [p[0] - c[0], p[1] - c[1]];
            assert!(
                d.iter().all(|x| x.abs() == 0.5),
                "{what}: face {i}: {uv:?} is not a unit square"
            );
            // consecutive corners differ on exactly one axis
            let q = uv[(k + 1) % 4];
            let moved = (0..2).filter(|&a| p[a] != q[a]).count();
            assert_eq!(moved, 1, "{what}: face {i}: {uv:?} is not a cycle");
            signs.push((d[0] > 0.0, d[1] > 0.0));
        }
        signs.sort_unstable();
        signs.dedup();
        assert_eq!(signs.len(), 4, "{what}: face {i}: {uv:?}");
    }
    (o.faces.len() - without, without)
}

/// [`unit_squares`], asserting that every face has `vt`; their number.
fn assert_unit_squares(o: &UvObj, frac: f64, what: &str) -> usize {
    let (with, without) = unit_squares(o, frac, what);
    assert_eq!(without, 0, "{what}: faces without vt");
    with
}

/// The identity map on `[lo, hi] × [lo + 0.03, hi + 0.01]`, `m × (m − 2)`
/// cells of two triangles, vertices off the grid and off the diagonals
/// of the dual cells (which would make sanitization move them), as an OBJ.
fn identity_square(lo: f64, hi: f64, m: usize) -> String {
    let mut s = String::new();
    let x = |i: usize| lo + (hi - lo) * i as f64 / m as f64;
    let y = |j: usize| lo + 0.03 + (hi - lo - 0.02) * j as f64 / (m - 2) as f64;
    for j in 0..=m - 2 {
        for i in 0..=m {
            s += &format!("v {} {} 0\nvt {} {}\n", x(i), y(j), x(i), y(j));
        }
    }
    let id = |i: usize, j: usize| j * (m + 1) + i + 1;
    for j in 0..m - 2 {
        for i in 0..m {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            s += &format!("f {a}/{a} {b}/{b} {c}/{c}\nf {a}/{a} {c}/{c} {d}/{d}\n");
        }
    }
    s
}

#[test]
fn identity_map_corners_are_the_map_at_the_vertices() {
    let dir = Scratch::new("uv-identity");
    let map = dir.path("id.obj");
    let (lo, hi) = (-0.3, 5.3);
    std::fs::write(&map, identity_square(lo, hi, 13)).expect("write the map");
    let map = map.display().to_string();
    for (offset, frac, quads) in [("half", 0.0, 25), ("zero", 0.5, 36)] {
        // the map's own positions (by default the geometric stage puts the
        // boundary vertices, here 0.3 inside, onto the square's boundary)
        let o = quad_uv(&dir, &map, &["--grid-offset", offset, "--keep-boundary"]);
        assert_eq!(assert_unit_squares(&o, frac, offset), quads, "{offset}");
        // corners inside the map's domain: the map's value at the vertex
        // (outside it, boundary vertices are placed on the boundary)
        let mut checked = 0;
        for f in &o.faces {
            for &(v, t) in f {
                let (p, uv) = (o.v[v], o.vt[t.expect("vt")]);
                if uv.iter().all(|&x| x > lo && x < hi) {
                    checked += 1;
                    for a in 0..2 {
                        assert!(
                            (p[a] - uv[a]).abs() < 1e-9,
                            "{offset}: vertex {v} at {p:?}, vt {uv:?}"
                        );
                    }
                }
            }
        }
        let all = 4 * quads;
        // zero: the 5 × 5 vertices at 0.5 … 4.5, 4 quads each
        let expect = if offset == "half" { all } else { 4 * 25 };
        assert_eq!(checked, expect, "{offset}: corners inside the domain");
    }
}

#[test]
fn generated_maps_get_unit_squares_in_their_charts() {
    let dir = Scratch::new("uv-generated");
    // (map, faces without vt with the offset zero: singular vertices on
    // isos leave holes, closed by polygons and local repair paths, which
    // have no cell of their own; the chosen offset, auto = half here,
    // leaves none)
    for (name, zero_holes) in [
        ("square_noise", 0),
        ("cube", 24),
        ("torus", 0),
        ("disk_m1", 14),
    ] {
        let map = dir.arg(&format!("{name}.obj"));
        let out = dualex(&["generate", name, "-o", &map, "-q"]);
        assert!(out.status.success(), "{}", text(&out));
        let o = quad_uv(&dir, &map, &[]);
        assert_unit_squares(&o, 0.0, &format!("{name} auto"));
        let o = quad_uv(&dir, &map, &["--grid-offset", "zero"]);
        let (_, without) = unit_squares(&o, 0.5, &format!("{name} zero"));
        assert_eq!(without, zero_holes, "{name} zero: faces without vt");
    }
}

#[test]
fn ply_carries_texcoord_and_vtk_is_refused() {
    let dir = Scratch::new("uv-formats");
    let map = dir.arg("m.obj");
    let out = dualex(&["generate", "square_identity", "-o", &map, "-q"]);
    assert!(out.status.success(), "{}", text(&out));
    let ply = dir.arg("q.ply");
    let out = dualex(&["quad", &map, "-o", &ply, "--uv", "-q"]);
    assert!(out.status.success(), "{}", text(&out));
    let bytes = std::fs::read(&ply).expect("read the PLY");
    let head = String::from_utf8_lossy(&bytes[..bytes.len().min(400)]).to_string();
    assert!(
        head.contains("property list uchar double texcoord"),
        "{head}"
    );
    let vtk = dir.arg("q.vtk");
    let out = dualex(&["quad", &map, "-o", &vtk, "--uv"]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("--uv"),
        "{}",
        text(&out)
    );
    assert!(!dir.path("q.vtk").exists());
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn fandisk_quads_are_unit_squares_across_its_seams() {
    let Some(root) = shared_data("qex") else {
        return;
    };
    let dir = Scratch::new("uv-fandisk");
    let map = root.join("fandisk_param.obj").display().to_string();
    let o = quad_uv(&dir, &map, &[]);
    // a cut mesh: seam vertices have different coordinates around them
    assert_eq!(assert_unit_squares(&o, 0.0, "fandisk"), 897);
    let mut per_vertex: std::collections::HashMap<usize, Vec<[f64; 2]>> = Default::default();
    for f in &o.faces {
        for &(v, t) in f {
            per_vertex.entry(v).or_default().push(o.vt[t.expect("vt")]);
        }
    }
    let split = per_vertex
        .values()
        .filter(|uvs| uvs.iter().any(|u| u != &uvs[0]))
        .count();
    assert!(split > 0, "fandisk: no vertex on a seam?");
}
