//! The two sides of the 2D-versus-3D comparison: the quad mesh `dualex
//! quad` makes of a map (its counts, and the hex edge valences it predicts
//! for L layers) and the hex mesh `dualex hex` makes of its extrusion (its
//! edge valences and boundary faces, from the MEDIT file).

use crate::common::*;
use std::collections::{BTreeMap, HashMap};
use std::path::Path;

/// Reads a MEDIT `.mesh` written by dualex (vertices + hexahedra only).
pub fn read_medit(path: &Path) -> (Vec<[f64; 3]>, Vec<[u32; 8]>) {
    let s = std::fs::read_to_string(path).expect("read .mesh");
    let mut tok = s.split_whitespace();
    let (mut pos, mut hexes) = (Vec::new(), Vec::new());
    let num = |t: &mut std::str::SplitWhitespace| -> f64 {
        t.next().and_then(|x| x.parse().ok()).expect("number")
    };
    while let Some(t) = tok.next() {
        match t {
            "Vertices" => {
                let n = num(&mut tok) as usize;
                for _ in 0..n {
                    let p: Vec<f64> = (0..4).map(|_| num(&mut tok)).collect();
                    pos.push([p[0], p[1], p[2]]);
                }
            }
            "Hexahedra" => {
                let n = num(&mut tok) as usize;
                for _ in 0..n {
                    let h: Vec<u32> = (0..9).map(|_| num(&mut tok) as u32).collect();
                    hexes.push(std::array::from_fn(|k| h[k] - 1));
                }
            }
            _ => {}
        }
    }
    (pos, hexes)
}

/// An undirected edge.
fn key2(a: u32, b: u32) -> (u32, u32) {
    (a.min(b), a.max(b))
}

/// The 2D side: quads, vertices, boundary edges, and the predicted hex
/// edge valence histogram for `layers`.
pub struct Quad2 {
    pub quads: usize,
    pub vertices: usize,
    pub boundary_edges: usize,
    /// faces per vertex, faces per edge
    vertex_faces: Vec<usize>,
    edge_faces: Vec<usize>,
}

/// The 2D side of `input`: `dualex quad`'s mesh, counted.
pub fn quad_side(input: &Path, dir: &Scratch) -> Quad2 {
    let out = dualex(&[
        "quad",
        &input.display().to_string(),
        "-o",
        &dir.arg("q.obj"),
        "-q",
    ]);
    assert!(out.status.success(), "{}: {}", input.display(), text(&out));
    let (mesh, _) = read_valid_quads(&dir.path("q.obj"), &input.display().to_string());
    let mut vf = vec![0; mesh.positions.len()];
    let mut ef: HashMap<(u32, u32), usize> = HashMap::new();
    for f in &mesh.faces {
        for k in 0..4 {
            vf[f[k] as usize] += 1;
            *ef.entry(key2(f[k], f[(k + 1) % 4])).or_insert(0) += 1;
        }
    }
    let vertex_faces: Vec<usize> = vf.into_iter().filter(|&n| n > 0).collect();
    Quad2 {
        quads: mesh.faces.len(),
        vertices: vertex_faces.len(),
        boundary_edges: ef.values().filter(|&&n| n == 1).count(),
        vertex_faces,
        edge_faces: ef.into_values().collect(),
    }
}

/// The hex edge valence histogram the quad mesh predicts for `layers`
/// layers (module docs of the test).
pub fn predicted_histogram(q: &Quad2, layers: usize) -> BTreeMap<usize, usize> {
    let mut h = BTreeMap::new();
    for &k in &q.vertex_faces {
        *h.entry(k).or_insert(0) += layers;
    }
    for &c in &q.edge_faces {
        *h.entry(c).or_insert(0) += 2;
        if layers > 1 {
            *h.entry(2 * c).or_insert(0) += layers - 1;
        }
    }
    h
}

/// The 3D side: hex edges (VTK order) → number of hexes; boundary faces. → number of hexes; boundary faces.
pub fn hex_side(cells: &[[u32; 8]]) -> (BTreeMap<usize, usize>, usize) {
    const EDGES: [(usize, usize); 12] = [
        (0, 1),
        (1, 2),
        (2, 3),
        (3, 0),
        (4, 5),
        (5, 6),
        (6, 7),
        (7, 4),
        (0, 4),
        (1, 5),
        (2, 6),
        (3, 7),
    ];
    const FACES: [[usize; 4]; 6] = [
        [0, 1, 2, 3],
        [4, 5, 6, 7],
        [0, 1, 5, 4],
        [1, 2, 6, 5],
        [2, 3, 7, 6],
        [3, 0, 4, 7],
    ];
    let mut e: HashMap<(u32, u32), usize> = HashMap::new();
    let mut f: HashMap<[u32; 4], usize> = HashMap::new();
    for c in cells {
        for (a, b) in EDGES {
            *e.entry(key2(c[a], c[b])).or_insert(0) += 1;
        }
        for face in FACES {
            let mut k = face.map(|i| c[i]);
            k.sort_unstable();
            *f.entry(k).or_insert(0) += 1;
        }
    }
    let mut h = BTreeMap::new();
    for n in e.into_values() {
        *h.entry(n).or_insert(0) += 1;
    }
    (h, f.values().filter(|&&n| n == 1).count())
}
