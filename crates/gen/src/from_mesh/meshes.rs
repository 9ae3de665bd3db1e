//! Small quad and hex meshes with known singularities, for
//! [`super::from_quads`] / [`super::from_hexes`].
//!
//! Quads (consistently oriented, outward on closed surfaces):
//! - [`cube6`]: the cube surface, 8 poles of valence 3;
//! - [`ngon_disk`]: `n` quads around a centre of valence `n` (a disk);
//! - [`annulus`]: a ring of quads (two boundaries);
//! - [`prism_poles`]: the `n`-prism surface split linearly once (each
//!   `m`-gon into `m` quads): `2n` poles of valence 3 and 2 of valence `n`.
//!
//! Hexes (VTK order, positive Jacobian at corner 0):
//! - [`cubed_ball`]: an inner cube and 6 frustums: 12 interior edges of
//!   valence 3 meeting 3 by 3 at the 8 inner corners;
//! - [`cylinder`]: [`ngon_disk`] extruded: an interior axis of valence `n`
//!   (`cylinder6`: 6 hexes around the axis);
//! - [`polycube_l`]: 3 cubes in an L: a concave boundary edge of valence 3.

use dualex_cells::{HexMesh, QuadMesh};
use std::collections::HashMap;
use std::f64::consts::TAU;

/// Names of the quad meshes of [`quad_mesh_by_name`], in a stable order.
pub fn quad_mesh_names() -> Vec<String> {
    let mut out = vec!["cube6".to_string()];
    out.extend((3..=8).map(|n| format!("ngon{n}")));
    out.extend(["annulus", "prism3_poles", "prism5_poles"].map(String::from));
    out
}

/// The quad mesh called `name` (see [`quad_mesh_names`]).
pub fn quad_mesh_by_name(name: &str) -> Option<QuadMesh> {
    match name {
        "cube6" => Some(cube6()),
        "annulus" => Some(annulus(8, 2)),
        "prism3_poles" => Some(prism_poles(3)),
        "prism5_poles" => Some(prism_poles(5)),
        _ => {
            let n: usize = name.strip_prefix("ngon")?.parse().ok()?;
            (3..=8).contains(&n).then(|| ngon_disk(n))
        }
    }
}

/// Names of the hex meshes of [`hex_mesh_by_name`], in a stable order.
pub fn hex_mesh_names() -> Vec<String> {
    [
        "cubed_ball",
        "cylinder3",
        "cylinder5",
        "cylinder6",
        "polycube_l",
    ]
    .map(String::from)
    .to_vec()
}

/// The hex mesh called `name` (see [`hex_mesh_names`]; also the dense
/// meshes of [`super::dense::dense_mesh_names`]).
pub fn hex_mesh_by_name(name: &str) -> Option<HexMesh> {
    match name {
        "cubed_ball" => Some(cubed_ball()),
        "cylinder3" => Some(cylinder(3, 2)),
        "cylinder5" => Some(cylinder(5, 2)),
        "cylinder6" => Some(cylinder(6, 2)),
        "polycube_l" => Some(polycube_l()),
        _ => super::dense::dense_mesh_by_name(name),
    }
}

/// Each `m`-gon into `m` quads (corner, next edge midpoint, centroid,
/// previous edge midpoint): orientation kept.
pub fn linear_subdivision(positions: &[[f64; 3]], faces: &[Vec<u32>]) -> QuadMesh {
    let mut out = QuadMesh {
        positions: positions.to_vec(),
        cells: Vec::new(),
    };
    let mut mids: HashMap<(u32, u32), u32> = HashMap::new();
    let mut mid = |out: &mut QuadMesh, a: u32, b: u32| {
        *mids.entry((a.min(b), a.max(b))).or_insert_with(|| {
            let (p, q) = (positions[a as usize], positions[b as usize]);
            out.positions
                .push(std::array::from_fn(|i| 0.5 * (p[i] + q[i])));
            (out.positions.len() - 1) as u32
        })
    };
    for f in faces {
        let m = f.len();
        let mut c = [0.0; 3];
        for &v in f {
            for (i, x) in c.iter_mut().enumerate() {
                *x += positions[v as usize][i] / m as f64;
            }
        }
        out.positions.push(c);
        let centre = (out.positions.len() - 1) as u32;
        for i in 0..m {
            let (prev, v, next) = (f[(i + m - 1) % m], f[i], f[(i + 1) % m]);
            let a = mid(&mut out, v, next);
            let b = mid(&mut out, prev, v);
            out.cells.push([v, a, centre, b]);
        }
    }
    out
}

/// The surface of `[0,1]³`, faces outward.
pub fn cube6() -> QuadMesh {
    let positions = (0..8)
        .map(|b| [b & 1, b >> 1 & 1, b >> 2 & 1].map(|x| x as f64))
        .collect();
    QuadMesh {
        positions,
        cells: vec![
            [0, 2, 3, 1],
            [4, 5, 7, 6],
            [0, 1, 5, 4],
            [2, 6, 7, 3],
            [0, 4, 6, 2],
            [1, 3, 7, 5],
        ],
    }
}

fn ring(n: usize, r: f64, z: f64) -> impl Iterator<Item = [f64; 3]> {
    (0..n).map(move |i| {
        let t = TAU * i as f64 / n as f64;
        [r * t.cos(), r * t.sin(), z]
    })
}

/// The regular `n`-gon split into `n` quads (planar, counter-clockwise).
pub fn ngon_disk(n: usize) -> QuadMesh {
    let positions: Vec<[f64; 3]> = ring(n, 1.0, 0.0).collect();
    linear_subdivision(&positions, &[(0..n as u32).collect()])
}

/// `sectors × rings` quads between radii 1 and 2 (planar, counter-clockwise).
pub fn annulus(sectors: usize, rings: usize) -> QuadMesh {
    let mut positions = Vec::new();
    for r in 0..=rings {
        positions.extend(ring(sectors, 1.0 + r as f64 / rings as f64, 0.0));
    }
    let id = |r: usize, s: usize| (r * sectors + s % sectors) as u32;
    let mut cells = Vec::new();
    for r in 0..rings {
        for s in 0..sectors {
            cells.push([id(r, s), id(r, s + 1), id(r + 1, s + 1), id(r + 1, s)]);
        }
    }
    QuadMesh { positions, cells }
}

/// The `n`-prism surface (module docs) split linearly once.
pub fn prism_poles(n: usize) -> QuadMesh {
    let positions: Vec<[f64; 3]> = ring(n, 1.0, 0.0).chain(ring(n, 1.0, 1.0)).collect();
    let n32 = n as u32;
    let mut faces: Vec<Vec<u32>> = vec![(0..n32).rev().collect(), (n32..2 * n32).collect()];
    for i in 0..n32 {
        let j = (i + 1) % n32;
        faces.push(vec![i, j, j + n32, i + n32]);
    }
    linear_subdivision(&positions, &faces)
}

/// The hex with corners `c`, reversed (bottom and top cycles) if its
/// Jacobian at corner 0 is negative.
fn oriented(positions: &[[f64; 3]], c: [u32; 8]) -> [u32; 8] {
    let p = |i: usize| positions[c[i] as usize];
    let e = |i: usize| std::array::from_fn::<f64, 3, _>(|a| p(i)[a] - p(0)[a]);
    let (a, b, d) = (e(1), e(3), e(4));
    let det = a[0] * (b[1] * d[2] - b[2] * d[1]) - a[1] * (b[0] * d[2] - b[2] * d[0])
        + a[2] * (b[0] * d[1] - b[1] * d[0]);
    if det < 0.0 {
        [0, 3, 2, 1, 4, 7, 6, 5].map(|i| c[i])
    } else {
        c
    }
}

/// A cube `[-1,1]³` inside `[-2,2]³`, the shell cut into 6 frustums.
pub fn cubed_ball() -> HexMesh {
    let corner = |b: usize, r: f64| [b & 1, b >> 1 & 1, b >> 2 & 1].map(|x| r * (2 * x) as f64 - r);
    let positions: Vec<[f64; 3]> = (0..8)
        .map(|b| corner(b, 1.0))
        .chain((0..8).map(|b| corner(b, 2.0)))
        .collect();
    const BIT_TO_VTK: [usize; 8] = [0, 1, 3, 2, 4, 5, 7, 6];
    let mut cells = vec![oriented(
        &positions,
        std::array::from_fn(|i| BIT_TO_VTK[i] as u32),
    )];
    for axis in 0..3 {
        let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
        for side in 0..2 {
            let face =
                [(0, 0), (1, 0), (1, 1), (0, 1)].map(|(x, y)| side << axis | x << b | y << c);
            let hex: [u32; 8] = std::array::from_fn(|i| (face[i % 4] + 8 * (i / 4)) as u32);
            cells.push(oriented(&positions, hex));
        }
    }
    HexMesh { positions, cells }
}

/// A planar quad mesh extruded into `layers` layers of height `1/layers`.
pub fn extrude(mesh: &QuadMesh, layers: usize) -> HexMesh {
    let nv = mesh.positions.len();
    let mut positions = Vec::with_capacity(nv * (layers + 1));
    for l in 0..=layers {
        let z = l as f64 / layers as f64;
        positions.extend(mesh.positions.iter().map(|p| [p[0], p[1], z]));
    }
    let mut cells = Vec::new();
    for l in 0..layers {
        for q in &mesh.cells {
            let hex = std::array::from_fn(|i| q[i % 4] + ((l + i / 4) * nv) as u32);
            cells.push(oriented(&positions, hex));
        }
    }
    HexMesh { positions, cells }
}

/// [`ngon_disk`] extruded: `n·layers` hexes around an axis of valence `n`.
pub fn cylinder(n: usize, layers: usize) -> HexMesh {
    extrude(&ngon_disk(n), layers)
}

/// Three unit cubes in an L (one layer).
pub fn polycube_l() -> HexMesh {
    let positions = (0..9)
        .map(|v| [(v % 3) as f64, (v / 3) as f64, 0.0])
        .collect();
    let sq = |i: u32, j: u32| [3 * j + i, 3 * j + i + 1, 3 * j + i + 4, 3 * j + i + 3];
    let flat = QuadMesh {
        positions,
        cells: vec![sq(0, 0), sq(1, 0), sq(0, 1)],
    };
    extrude(&flat, 1)
}

/// A 3×3 grid of quads whose centre cell is two quads around an interior
/// vertex of valence 2 (vertex 16, sharing the edges 16–5 and 16–10): the
/// smallest doublet, for the tests of doublet removal in both dimensions
/// (extruded in 3D).
pub fn grid_with_doublet() -> QuadMesh {
    let mut m = QuadMesh::default();
    for j in 0..4 {
        for i in 0..4 {
            m.positions.push([i as f64, j as f64, 0.0]);
        }
    }
    let id = |i: u32, j: u32| j * 4 + i;
    for j in 0..3 {
        for i in 0..3 {
            if (i, j) != (1, 1) {
                m.cells
                    .push([id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
    }
    m.positions.push([1.5, 1.5, 0.0]);
    m.cells.push([16, 5, 6, 10]);
    m.cells.push([16, 10, 9, 5]);
    m
}
