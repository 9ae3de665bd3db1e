//! Test surfaces: generators used by the tests and by the command line.
//!
//! Each returns a [`Surface`] (consistently oriented, outward normals on
//! closed surfaces). Expected Euler characteristics: icosphere 2, torus 0,
//! cube 2, bumpy square 1, [`plate_with_holes`] `2 − 2·holes`.

use crate::surface::Surface;
use std::collections::HashMap;
use std::f64::consts::PI;

/// An icosahedron subdivided `subdivisions` times (each triangle into four),
/// projected to the unit sphere: `20·4^subdivisions` triangles.
pub fn icosphere(subdivisions: u32) -> Surface {
    let t = (1.0 + 5f64.sqrt()) / 2.0;
    let mut p: Vec<[f64; 3]> = vec![
        [-1.0, t, 0.0],
        [1.0, t, 0.0],
        [-1.0, -t, 0.0],
        [1.0, -t, 0.0],
        [0.0, -1.0, t],
        [0.0, 1.0, t],
        [0.0, -1.0, -t],
        [0.0, 1.0, -t],
        [t, 0.0, -1.0],
        [t, 0.0, 1.0],
        [-t, 0.0, -1.0],
        [-t, 0.0, 1.0],
    ];
    let mut tris: Vec<[u32; 3]> = vec![
        [0, 11, 5],
        [0, 5, 1],
        [0, 1, 7],
        [0, 7, 10],
        [0, 10, 11],
        [1, 5, 9],
        [5, 11, 4],
        [11, 10, 2],
        [10, 7, 6],
        [7, 1, 8],
        [3, 9, 4],
        [3, 4, 2],
        [3, 2, 6],
        [3, 6, 8],
        [3, 8, 9],
        [4, 9, 5],
        [2, 4, 11],
        [6, 2, 10],
        [8, 6, 7],
        [9, 8, 1],
    ];
    for _ in 0..subdivisions {
        let mut mid: HashMap<(u32, u32), u32> = HashMap::new();
        let mut next = Vec::with_capacity(4 * tris.len());
        for &[a, b, c] in &tris {
            let mut m = |u: u32, v: u32| {
                *mid.entry((u.min(v), u.max(v))).or_insert_with(|| {
                    let (pu, pv) = (p[u as usize], p[v as usize]);
                    p.push([0, 1, 2].map(|i| 0.5 * (pu[i] + pv[i])));
                    p.len() as u32 - 1
                })
            };
            let (ab, bc, ca) = (m(a, b), m(b, c), m(c, a));
            next.extend([[a, ab, ca], [b, bc, ab], [c, ca, bc], [ab, bc, ca]]);
        }
        tris = next;
    }
    for q in &mut p {
        let l = (q[0] * q[0] + q[1] * q[1] + q[2] * q[2]).sqrt();
        *q = q.map(|x| x / l);
    }
    build(p, tris)
}

/// A torus of radii `big > small` with an `nu × nv` grid (around the
/// axis × around the tube), each quad split into two triangles.
pub fn torus(big: f64, small: f64, nu: u32, nv: u32) -> Surface {
    let mut p = Vec::with_capacity((nu * nv) as usize);
    for i in 0..nu {
        let u = 2.0 * PI * f64::from(i) / f64::from(nu);
        for j in 0..nv {
            let v = 2.0 * PI * f64::from(j) / f64::from(nv);
            let r = big + small * v.cos();
            p.push([r * u.cos(), r * u.sin(), small * v.sin()]);
        }
    }
    let id = |i: u32, j: u32| (i % nu) * nv + (j % nv);
    let mut t = Vec::with_capacity(2 * (nu * nv) as usize);
    for i in 0..nu {
        for j in 0..nv {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    build(p, t)
}

/// The unit square `[0,1]²` as an `n × n` grid (two triangles per cell)
/// lifted by a smooth bump of height `amplitude`: a disk with boundary.
pub fn bumpy_square(n: u32, amplitude: f64) -> Surface {
    let mut p = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let (x, y) = (f64::from(i) / f64::from(n), f64::from(j) / f64::from(n));
            let z = amplitude * (PI * x).sin() * (PI * y).sin() * (3.0 * x + 2.0 * y).cos();
            p.push([x, y, z]);
        }
    }
    build(p, grid_triangles(n, n, |i, j| j * (n + 1) + i))
}

/// The two triangles of each cell `(i, j)` of an `ni × nj` grid (rows `j`
/// outer), split along the diagonal from corner `(i, j)` to `(i+1, j+1)`;
/// `id(i, j)` numbers the grid's vertices (`i` up to `ni`, `j` up to `nj`:
/// a wrapping grid maps `ni` back to 0).
pub(crate) fn grid_triangles(ni: u32, nj: u32, id: impl Fn(u32, u32) -> u32) -> Vec<[u32; 3]> {
    let mut t = Vec::with_capacity(2 * (ni * nj) as usize);
    for j in 0..nj {
        for i in 0..ni {
            t.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
            t.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
        }
    }
    t
}

/// The flat unit disk: an `n × n` grid of `[−1, 1]²` mapped onto it by
/// `(x·√(1 − y²/2), y·√(1 − x²/2))` (the square's corners land on the
/// circle), two triangles per cell. A field following its round boundary
/// needs interior singularities of total index 1.
pub fn flat_disk(n: u32) -> Surface {
    let mut p = Vec::new();
    for j in 0..=n {
        for i in 0..=n {
            let x = 2.0 * f64::from(i) / f64::from(n) - 1.0;
            let y = 2.0 * f64::from(j) / f64::from(n) - 1.0;
            p.push([
                x * (1.0 - y * y / 2.0).sqrt(),
                y * (1.0 - x * x / 2.0).sqrt(),
                0.0,
            ]);
        }
    }
    let id = |i: u32, j: u32| j * (n + 1) + i;
    let mut t = Vec::new();
    for j in 0..n {
        for i in 0..n {
            // diagonals away from the corners, where the cells flatten
            if (i < n / 2) == (j < n / 2) {
                t.push([id(i, j), id(i + 1, j), id(i + 1, j + 1)]);
                t.push([id(i, j), id(i + 1, j + 1), id(i, j + 1)]);
            } else {
                t.push([id(i, j), id(i + 1, j), id(i, j + 1)]);
                t.push([id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)]);
            }
        }
    }
    build(p, t)
}

/// The flat ring `1 ≤ |(x, y)| ≤ 2` with `nr` rings of `nphi` cells (two
/// triangles per cell): an annulus, two boundary loops.
pub fn annulus(nphi: u32, nr: u32) -> Surface {
    let mut p = Vec::new();
    for j in 0..=nr {
        let r = 1.0 + f64::from(j) / f64::from(nr);
        for i in 0..nphi {
            let a = 2.0 * PI * f64::from(i) / f64::from(nphi);
            p.push([r * a.cos(), r * a.sin(), 0.0]);
        }
    }
    build(p, grid_triangles(nphi, nr, |i, j| j * nphi + i % nphi))
}

/// Two surfaces as one (the second's vertices renumbered after the
/// first's): a surface of two components.
pub fn disjoint_union(a: &Surface, b: &Surface) -> Surface {
    let off = a.positions.len() as u32;
    let mut p = a.positions.clone();
    p.extend_from_slice(&b.positions);
    let mut t = a.triangles.clone();
    t.extend(b.triangles.iter().map(|t| t.map(|v| v + off)));
    build(p, t)
}

/// The cube `[0,1]³`, each face an `n × n` grid: sharp edges and eight
/// corners of angle defect `π/2`.
pub fn cube(n: u32) -> Surface {
    voxel_surface(&[[0, 0, 0]], n)
}

/// A plate of `2·holes + 1 × 3 × 1` unit voxels with `holes` square
/// holes through it, each unit face an `n × n` grid: a polycube surface
/// of genus `holes`.
pub fn plate_with_holes(holes: u32, n: u32) -> Surface {
    let mut voxels = Vec::new();
    for x in 0..(2 * holes + 1) as i32 {
        for y in 0..3 {
            if y == 1 && x % 2 == 1 {
                continue;
            }
            voxels.push([x, y, 0]);
        }
    }
    voxel_surface(&voxels, n)
}

/// The boundary of a set of unit voxels, each boundary square an `n × n`
/// grid, welded by lattice coordinates. The voxel set must not touch
/// itself along an edge or a corner only (the surface would not be a
/// manifold).
pub fn voxel_surface(voxels: &[[i32; 3]], n: u32) -> Surface {
    let set: std::collections::HashSet<[i32; 3]> = voxels.iter().copied().collect();
    let n = n.max(1) as i32;
    let mut index: HashMap<[i32; 3], u32> = HashMap::new();
    let mut p = Vec::new();
    let mut vertex = |q: [i32; 3]| {
        *index.entry(q).or_insert_with(|| {
            p.push(q.map(|c| f64::from(c) / f64::from(n)));
            p.len() as u32 - 1
        })
    };
    let mut t = Vec::new();
    for &v in voxels {
        for axis in 0..3 {
            for positive in [false, true] {
                let mut nb = v;
                nb[axis] += if positive { 1 } else { -1 };
                if set.contains(&nb) {
                    continue;
                }
                // the square's grid: u, v the other two axes, u × v = +axis
                let (ua, va) = ((axis + 1) % 3, (axis + 2) % 3);
                let at = |i: i32, j: i32| {
                    let mut q = v.map(|c| c * n);
                    q[axis] += if positive { n } else { 0 };
                    q[ua] += i;
                    q[va] += j;
                    q
                };
                for i in 0..n {
                    for j in 0..n {
                        let c = [at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)];
                        let [a, b, c, d] = c.map(&mut vertex);
                        if positive {
                            t.push([a, b, c]);
                            t.push([a, c, d]);
                        } else {
                            t.push([a, c, b]);
                            t.push([a, d, c]);
                        }
                    }
                }
            }
        }
    }
    build(p, t)
}

/// The generators build valid surfaces by construction.
fn build(p: Vec<[f64; 3]>, t: Vec<[u32; 3]>) -> Surface {
    match Surface::new(p, t) {
        Ok(s) => s,
        Err(e) => unreachable!("generated surface is invalid: {e}"),
    }
}

/// An icosphere with bumps: each vertex moved along its direction `d` to
/// radius `1 + amplitude·sin(3·d.x)·sin(2·d.y + 1)·cos(d.z)`.
pub fn bumpy_sphere(subdivisions: u32, amplitude: f64) -> Surface {
    let s = icosphere(subdivisions);
    let positions = s
        .positions
        .iter()
        .map(|&[x, y, z]| {
            let r = 1.0 + amplitude * (3.0 * x).sin() * (2.0 * y + 1.0).sin() * z.cos();
            [r * x, r * y, r * z]
        })
        .collect();
    Surface::new(positions, s.triangles).expect("a bumpy sphere is a surface")
}

/// The surface `dualex remesh` runs on without INPUT: a bumpy sphere of
/// 5 120 triangles, as positions and triangles.
pub fn embedded() -> (Vec<[f64; 3]>, Vec<[u32; 3]>) {
    let s = bumpy_sphere(4, 0.25);
    (s.positions, s.triangles)
}

/// The generated surfaces by name (`dualex generate surface_NAME`), with
/// what each is: the inputs of the remesher's tests besides the shared
/// surfaces.
pub const NAMED: &[(&str, &str)] = &[
    (
        "surface_sphere",
        "icosphere, 5120 triangles (smooth, closed)",
    ),
    (
        "surface_bumpy_sphere",
        "bumpy icosphere, 5120 triangles (dualex remesh's embedded surface)",
    ),
    ("surface_torus", "torus, 6144 triangles (genus 1)"),
    (
        "surface_torus_large",
        "torus, 98304 triangles (the speed benchmark's surface)",
    ),
    (
        "surface_genus3",
        "polycube plate with 3 holes (genus 3, sharp edges)",
    ),
    ("surface_cube", "cube, 8×8 per face (sharp edges)"),
    (
        "surface_disk",
        "bumpy square, 48×48 (open: one boundary loop)",
    ),
    (
        "surface_cad_cylinder",
        "closed cylinder as CAD exports it: 96 sectors, side strips, fan caps, sharp rims",
    ),
    (
        "surface_cad_cone",
        "closed cone as CAD exports it: an apex fan and a base fan of 96 sectors",
    ),
    (
        "surface_cad_plate_holes",
        "plate with 3 round through-holes as CAD exports it: corner fans around each hole rim (genus 3)",
    ),
    (
        "surface_cad_box_boss",
        "box with a round boss as CAD exports it: faces of two triangles, corner fans, a fan on the boss",
    ),
    (
        "surface_cad_filleted",
        "slab with filleted vertical edges as CAD exports it: one strip of long triangles, fan caps",
    ),
    (
        "surface_cad_needles",
        "cylinder of 1000 sectors in one strip: needle triangles of aspect ratio 1000, fan caps",
    ),
    ("surface_sweep_genus0", "smoothed polycube plate of genus 0, thin handles (sweep)"),
    ("surface_sweep_genus1", "smoothed polycube plate of genus 1, thin handles (sweep)"),
    ("surface_sweep_genus2", "smoothed polycube plate of genus 2, thin handles (sweep)"),
    ("surface_sweep_genus3", "smoothed polycube plate of genus 3, thin handles (sweep)"),
    ("surface_sweep_genus4", "smoothed polycube plate of genus 4, thin handles (sweep)"),
    ("surface_sweep_genus5", "smoothed polycube plate of genus 5, thin handles (sweep)"),
    ("surface_sweep_genus6", "smoothed polycube plate of genus 6, thin handles (sweep)"),
    ("surface_sweep_genus7", "smoothed polycube plate of genus 7, thin handles (sweep)"),
    ("surface_sweep_genus8", "smoothed polycube plate of genus 8, thin handles (sweep)"),
    (
        "surface_sweep_holes1",
        "bumpy square, 1 hole 3 cells from the border (sweep)",
    ),
    (
        "surface_sweep_holes2",
        "bumpy square, 2 holes: 3 cells from the border, then 1 cell apart (sweep)",
    ),
    (
        "surface_sweep_holes3",
        "bumpy square, 3 holes: 3 cells from the border, then 1, 2 cells apart (sweep)",
    ),
    (
        "surface_sweep_holes4",
        "bumpy square, 4 holes: 3 cells from the border, then 1, 2, 3 cells apart (sweep)",
    ),
    (
        "surface_sweep_holes5",
        "bumpy square, 5 holes: 3 cells from the border, then 1, 2, 3, 5 cells apart (sweep)",
    ),
    (
        "surface_sweep_holes6",
        "bumpy square, 6 holes: 3 cells from the border, then 1, 2, 3, 5, 8 cells apart (sweep)",
    ),
    (
        "surface_sweep_holes7",
        "bumpy square, 7 holes: 3 cells from the border, then 1, 2, 3, 5, 8, 12 cells apart (sweep)",
    ),
    (
        "surface_sweep_holes8",
        "bumpy square, 8 holes: 3 cells from the border, then 1, 2, 3, 5, 8, 12, 17 cells apart (sweep)",
    ),
];

/// A generated surface by its name in [`NAMED`].
pub fn by_name(name: &str) -> Option<Surface> {
    Some(match name {
        "surface_sphere" => icosphere(4),
        "surface_bumpy_sphere" => bumpy_sphere(4, 0.25),
        "surface_torus" => torus(1.0, 0.4, 96, 32),
        "surface_torus_large" => torus(1.0, 0.4, 384, 128),
        "surface_genus3" => plate_with_holes(3, 4),
        "surface_cube" => cube(8),
        "surface_disk" => bumpy_square(48, 0.2),
        "surface_cad_cylinder" => crate::shapes_cad::cad_cylinder(96, 32, 2.0),
        "surface_cad_cone" => crate::shapes_cad::cad_cone(96, 1.5),
        "surface_cad_plate_holes" => crate::shapes_cad::cad_plate_with_holes(3, 6, 0.3),
        "surface_cad_box_boss" => crate::shapes_cad::cad_box_with_boss(8, 0.5),
        "surface_cad_filleted" => crate::shapes_cad::cad_filleted_slab(2.0, 1.0, 0.3, 8, 0.4),
        "surface_cad_needles" => crate::shapes_cad::cad_cylinder(1000, 1, 6.3),
        _ => return sweep_by_name(name),
    })
}

/// A surface of [`crate::shapes_sweep`] by its name in [`NAMED`].
fn sweep_by_name(name: &str) -> Option<Surface> {
    use crate::shapes_sweep::{smooth_genus, square_with_holes};
    let number = |prefix: &str| name.strip_prefix(prefix)?.parse::<u32>().ok();
    match (number("surface_sweep_genus"), number("surface_sweep_holes")) {
        (Some(g), _) if g <= 8 => Some(smooth_genus(g)),
        (_, Some(k)) if (1..=8).contains(&k) => Some(square_with_holes(k)),
        _ => None,
    }
}

/// The signed volume a closed surface encloses (> 0 with outward normals).
#[cfg(test)]
pub(crate) fn signed_volume(s: &Surface) -> f64 {
    s.triangles
        .iter()
        .map(|t| {
            let [a, b, c] = t.map(|v| s.positions[v as usize]);
            crate::surface::dot(a, crate::surface::cross(b, c)) / 6.0
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn euler_characteristics_and_sizes() {
        let s = icosphere(2);
        assert_eq!(s.triangles.len(), 320);
        assert_eq!(s.euler_characteristic(), 2);
        assert_eq!(torus(3.0, 1.0, 12, 8).euler_characteristic(), 0);
        assert_eq!(bumpy_square(6, 0.2).euler_characteristic(), 1);
        assert_eq!(annulus(12, 3).euler_characteristic(), 0);
        assert_eq!(flat_disk(8).euler_characteristic(), 1);
        let two = disjoint_union(&icosphere(0), &bumpy_square(2, 0.0));
        assert_eq!(two.euler_characteristic(), 3);
        assert_eq!(two.triangles.len(), 28);
        let c = cube(3);
        assert_eq!(c.triangles.len(), 6 * 9 * 2);
        assert_eq!(c.euler_characteristic(), 2);
        assert!(c.boundary_vertex.iter().all(|&b| !b));
        for holes in 1..=3 {
            let s = plate_with_holes(holes, 2);
            assert_eq!(s.euler_characteristic(), 2 - 2 * i64::from(holes));
            assert!(s.boundary_vertex.iter().all(|&b| !b));
        }
    }

    #[test]
    fn closed_surfaces_face_outward() {
        // signed volume > 0 with outward normals
        for s in [
            icosphere(1),
            torus(3.0, 1.0, 10, 6),
            cube(2),
            plate_with_holes(3, 1),
        ] {
            let vol = signed_volume(&s);
            assert!(vol > 0.0, "volume {vol}");
        }
    }
}
