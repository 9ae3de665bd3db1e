//! Sub-cells into simplices.
//!
//! Input: a [`Refined`] mesh. Output: simplices (global vertex ids) and
//! their corner coordinates in their element's chart (the lattice point,
//! plus `shift` on every axis in 2D).
//!
//! 2D: [`Diagonal`] in the element's frame (any split of a square is
//! conformal: sub-cells only share edges). 3D: every sub-face is split
//! along the diagonal through its least *global* vertex id, so the two
//! sub-cubes sharing a face (in one hex or in two, whatever their frames)
//! split it the same way; [`TetSplit::LeastVertex`] cones the sub-cube from
//! its least vertex over the 3 faces not holding it (the faces holding it
//! are split through it, as the cone requires), [`TetSplit::Centre`] cones
//! all 6 faces from a new centre vertex. Every simplex is positively
//! oriented in its chart (two corners swapped otherwise).
//!
//! ```text
//!   d ---- c    sub-square corners by bits: a = 0, b = 1, c = 3, d = 2
//!   |      |    Fixed (and even i + j): a-b-c, a-c-d; odd: a-b-d, b-c-d
//!   a ---- b
//! ```

use super::refine::Refined;
use super::TetSplit;
use crate::Diagonal;
use dualex_map::mesh::det_of;

/// Triangles of the refined quads and their chart coordinates.
pub(crate) type Tris = (Vec<[u32; 3]>, Vec<[[f64; 2]; 3]>);
/// Positions (with added centres), tets and their chart coordinates.
pub(crate) type Tets = (Vec<[f64; 3]>, Vec<[u32; 4]>, Vec<[[f64; 3]; 4]>);

/// The triangles of every sub-square (module docs).
pub(crate) fn triangles(r: &Refined<2>, diagonal: Diagonal, shift: f64) -> Tris {
    let (mut tris, mut coords) = (Vec::new(), Vec::new());
    for (e, min) in r.sub_cells() {
        let corner = |bits: usize| {
            let lat = Refined::<2>::corner(min, bits);
            (r.id(e, lat), lat.map(|x| x as f64 + shift))
        };
        let [a, b, d, c] = [0, 1, 2, 3].map(corner);
        let split = if diagonal == Diagonal::Fixed || (min[0] + min[1]) % 2 == 0 {
            [[a, b, c], [a, c, d]]
        } else {
            [[a, b, d], [b, c, d]]
        };
        for t in split {
            tris.push(t.map(|x| x.0));
            coords.push(t.map(|x| x.1));
        }
    }
    (tris, coords)
}

/// Cube faces by corner bits, each in cyclic order: `FACES[2·axis + side]`.
fn face(axis: usize, side: usize) -> [usize; 4] {
    let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
    [(0, 0), (1, 0), (1, 1), (0, 1)].map(|(x, y)| side << axis | x << b | y << c)
}

/// The two triangles of a face (corner bits), split through its least id.
fn face_triangles(f: [usize; 4], g: &[u32; 8]) -> [[usize; 3]; 2] {
    let m = (0..4).min_by_key(|&i| g[f[i]]).unwrap_or(0);
    let at = |i: usize| f[(m + i) % 4];
    [[at(0), at(1), at(2)], [at(0), at(2), at(3)]]
}

/// Pushes the tet `t`, positively oriented.
fn push_tet(out: &mut (Vec<[u32; 4]>, Vec<[[f64; 3]; 4]>), mut t: [u32; 4], mut c: [[f64; 3]; 4]) {
    if det_of::<4, 3>(&c) < 0.0 {
        t.swap(2, 3);
        c.swap(2, 3);
    }
    out.0.push(t);
    out.1.push(c);
}

/// The tets of every sub-cube (module docs).
pub(crate) fn tets(r: &Refined<3>, split: TetSplit) -> Tets {
    let mut positions = r.positions.clone();
    let mut out = (Vec::new(), Vec::new());
    for (e, min) in r.sub_cells() {
        let lat: [[usize; 3]; 8] = std::array::from_fn(|b| Refined::<3>::corner(min, b));
        let g: [u32; 8] = lat.map(|l| r.id(e, l));
        let c: [[f64; 3]; 8] = lat.map(|l| l.map(|x| x as f64));
        match split {
            TetSplit::LeastVertex => {
                let v0 = (0..8).min_by_key(|&b| g[b]).unwrap_or(0);
                for axis in 0..3 {
                    let far = face(axis, 1 - (v0 >> axis & 1));
                    for t in face_triangles(far, &g) {
                        let tet = [v0, t[0], t[1], t[2]];
                        push_tet(&mut out, tet.map(|b| g[b]), tet.map(|b| c[b]));
                    }
                }
            }
            TetSplit::Centre => {
                let centre = positions.len() as u32;
                let mut p = [0.0; 3];
                for &v in &g {
                    for (a, x) in p.iter_mut().enumerate() {
                        *x += positions[v as usize][a] / 8.0;
                    }
                }
                positions.push(p);
                let cc = min.map(|x| x as f64 + 0.5);
                for axis in 0..3 {
                    for side in 0..2 {
                        for t in face_triangles(face(axis, side), &g) {
                            push_tet(
                                &mut out,
                                [centre, g[t[0]], g[t[1]], g[t[2]]],
                                [cc, c[t[0]], c[t[1]], c[t[2]]],
                            );
                        }
                    }
                }
            }
        }
    }
    (positions, out.0, out.1)
}
