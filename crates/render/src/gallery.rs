//! Pictures for a person to look at (`#[ignore]`d; run with
//! `DUALEX_GALLERY=DIR cargo test -p dualex-render gallery -- --ignored`):
//! the small test meshes, and the shared real data when present.

use std::path::{Path, PathBuf};

use dualex_cells::QuadMesh;
use dualex_map::TriMap;

use crate::valence::cube_quads;
use crate::{map_png, quad_png, view_html};

/// Positions, texture coordinates, faces as `(v, vt)` per corner.
type Obj = (Vec<[f64; 3]>, Vec<[f64; 2]>, Vec<Vec<(u32, u32)>>);

/// A minimal OBJ reader: `v`, `vt`, and `f` with `v` or `v/vt` corners.
fn read_obj(path: &Path) -> Obj {
    let text = std::fs::read_to_string(path).unwrap();
    let (mut v, mut vt, mut f) = (Vec::new(), Vec::new(), Vec::new());
    for line in text.lines() {
        let mut it = line.split_whitespace();
        let nums = |it: std::str::SplitWhitespace| -> Vec<f64> {
            it.map(|x| x.parse().unwrap()).collect()
        };
        match it.next() {
            Some("v") => {
                let n = nums(it);
                v.push([n[0], n[1], n[2]]);
            }
            Some("vt") => {
                let n = nums(it);
                vt.push([n[0], n[1]]);
            }
            Some("f") => f.push(
                it.map(|c| {
                    let mut p = c.split('/').map(|x| x.parse::<u32>().unwrap_or(1) - 1);
                    let a = p.next().unwrap();
                    (a, p.next().unwrap_or(a))
                })
                .collect(),
            ),
            _ => {}
        }
    }
    (v, vt, f)
}

fn quads(path: &Path) -> QuadMesh {
    let (positions, _, f) = read_obj(path);
    let cells = f.iter().map(|c| [c[0].0, c[1].0, c[2].0, c[3].0]).collect();
    QuadMesh { positions, cells }
}

fn tri_map(path: &Path) -> TriMap {
    let (positions, vt, f) = read_obj(path);
    TriMap {
        positions,
        simplices: f.iter().map(|c| [c[0].0, c[1].0, c[2].0]).collect(),
        coords: f
            .iter()
            .map(|c| [0, 1, 2].map(|k| vt[c[k].1 as usize]))
            .collect(),
    }
}

/// A torus of `n × m` quads.
fn torus(n: u32, m: u32) -> QuadMesh {
    let mut mesh = QuadMesh::default();
    for j in 0..m {
        for i in 0..n {
            let (a, b) = (
                std::f64::consts::TAU * f64::from(i) / f64::from(n),
                std::f64::consts::TAU * f64::from(j) / f64::from(m),
            );
            let r = 3.0 + b.cos();
            mesh.positions.push([r * a.cos(), b.sin(), r * a.sin()]);
            let id = |di: u32, dj: u32| ((j + dj) % m) * n + (i + di) % n;
            mesh.cells.push([id(0, 0), id(0, 1), id(1, 1), id(1, 0)]);
        }
    }
    mesh
}

#[test]
#[ignore]
fn gallery() {
    let Some(dir) = std::env::var_os("DUALEX_GALLERY").map(PathBuf::from) else {
        eprintln!("set DUALEX_GALLERY=DIR");
        return;
    };
    std::fs::create_dir_all(&dir).unwrap();
    quad_png(&cube_quads(), &dir.join("cube.png"), 400).unwrap();
    let hexes = crate::view::tests::hex_grid(3);
    let html = crate::view_html_hex(&hexes, "3×3×3 hexes").unwrap();
    std::fs::write(dir.join("hexes.html"), html).unwrap();
    let boundary = crate::hex_boundary(&hexes).unwrap();
    quad_png(&boundary, &dir.join("hexes.png"), 400).unwrap();
    let torus = torus(400, 200);
    let t = std::time::Instant::now();
    quad_png(&torus, &dir.join("torus.png"), 1000).unwrap();
    eprintln!("torus: {} quads, {:?}", torus.cells.len(), t.elapsed());
    let t = std::time::Instant::now();
    let html = view_html(&torus, "torus").unwrap();
    eprintln!("torus page: {} bytes, {:?}", html.len(), t.elapsed());
    std::fs::write(dir.join("torus.html"), html).unwrap();
    let data = Path::new("/work/shared/data");
    for name in ["fandisk_quad", "duck_miq_4_quad"] {
        let p = data.join(format!("qex/{name}.obj"));
        if p.exists() {
            let m = quads(&p);
            let t = std::time::Instant::now();
            quad_png(&m, &dir.join(format!("{name}.png")), 800).unwrap();
            eprintln!("{name}: {} quads, {:?}", m.cells.len(), t.elapsed());
            let html = view_html(&m, name).unwrap();
            std::fs::write(dir.join(format!("{name}.html")), html).unwrap();
        }
    }
    for (sub, name) in [
        ("qex", "fandisk_param"),
        ("directional", "decimated-knight-param"),
        ("directional", "dragon-param-full-seamless"),
    ] {
        let p = data.join(format!("{sub}/{name}.obj"));
        if p.exists() {
            let m = tri_map(&p);
            let t = std::time::Instant::now();
            let r = map_png(&m, &dir.join(format!("{name}.png")), 1000);
            eprintln!("{name}: {} triangles, {r:?} {:?}", m.len(), t.elapsed());
        }
    }
}
