//! Test surfaces and fields: a jittered square, a cube, a torus, and the
//! singular vertices of a field by its matchings.

use crate::field::CrossField;
use crate::surface::Surface;
use std::collections::HashMap;

/// A field along a 3D direction field `dir(centroid)`, projected per face.
pub fn field_along(s: &Surface, dir: impl Fn([f64; 3]) -> [f64; 3]) -> CrossField {
    let angles = (0..s.triangles.len())
        .map(|f| {
            let t = s.triangles[f];
            let c: [f64; 3] = std::array::from_fn(|k| {
                t.iter().map(|&v| s.positions[v as usize][k]).sum::<f64>() / 3.0
            });
            let [x, y] = s.in_frame(f as u32, dir(c));
            y.atan2(x)
        })
        .collect();
    CrossField::from_angles(s, angles)
}

/// The unit square as a `k × k` grid of triangle pairs, interior vertices
/// moved by up to `jitter / k`.
pub fn square(k: usize, jitter: f64) -> Surface {
    let mut p = Vec::new();
    for j in 0..=k {
        for i in 0..=k {
            let inner = i > 0 && j > 0 && i < k && j < k;
            let d = if inner { jitter / k as f64 } else { 0.0 };
            let (x, y) = (i as f64 / k as f64, j as f64 / k as f64);
            p.push([
                x + d * ((i * 7 + j * 3) as f64).sin(),
                y + d * ((i * 5 + j) as f64).cos(),
                0.0,
            ]);
        }
    }
    Surface::new(
        p,
        grid_triangles(k, k, |i, j| (j % (k + 1)) * (k + 1) + i % (k + 1)),
    )
    .unwrap()
}

/// Two triangles per cell `(i, j)` of an `nu × nv` grid, vertex ids by `id`.
pub fn grid_triangles(nu: usize, nv: usize, id: impl Fn(usize, usize) -> usize) -> Vec<[u32; 3]> {
    let mut t = Vec::new();
    for j in 0..nv {
        for i in 0..nu {
            let [a, b, c, d] =
                [id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)].map(|v| v as u32);
            t.push([a, b, c]);
            t.push([a, c, d]);
        }
    }
    t
}

/// The unit cube's surface, each face a `k × k` grid.
pub fn cube(k: usize) -> Surface {
    let mut ids: HashMap<[usize; 3], u32> = HashMap::new();
    let mut p = Vec::new();
    let mut t = Vec::new();
    for axis in 0..3 {
        for side in [0, k] {
            let (b, c) = ((axis + 1) % 3, (axis + 2) % 3);
            // (e_b × e_c) = e_axis: outward on the far side
            let (b, c) = if side == k { (b, c) } else { (c, b) };
            let mut id = |i: usize, j: usize| {
                let mut q = [0; 3];
                q[axis] = side;
                q[b] = i;
                q[c] = j;
                *ids.entry(q).or_insert_with(|| {
                    p.push(q.map(|x| x as f64 / k as f64));
                    p.len() as u32 - 1
                }) as usize
            };
            let mut local = vec![0; (k + 1) * (k + 1)];
            for j in 0..=k {
                for i in 0..=k {
                    local[j * (k + 1) + i] = id(i, j);
                }
            }
            t.extend(grid_triangles(k, k, |i, j| local[j * (k + 1) + i]));
        }
    }
    Surface::new(p, t).unwrap()
}

/// The cube's field: per face, the first tangent axis.
pub fn cube_field(s: &Surface) -> CrossField {
    let normals: Vec<usize> = s
        .frames
        .iter()
        .map(|fr| {
            (0..3)
                .max_by(|&a, &b| fr[2][a].abs().total_cmp(&fr[2][b].abs()))
                .unwrap()
        })
        .collect();
    let angles = (0..s.triangles.len())
        .map(|f| {
            let mut d = [0.0; 3];
            d[(normals[f] + 1) % 3] = 1.0;
            let [x, y] = s.in_frame(f as u32, d);
            y.atan2(x)
        })
        .collect();
    CrossField::from_angles(s, angles)
}

/// The cube's corners.
pub fn cube_corners(s: &Surface) -> Vec<u32> {
    (0..s.positions.len() as u32)
        .filter(|&v| {
            s.positions[v as usize]
                .iter()
                .all(|&x| x == 0.0 || x == 1.0)
        })
        .collect()
}

/// A torus (radii 2 and 0.7) as an `nu × nv` grid.
pub fn torus(nu: usize, nv: usize) -> Surface {
    let mut p = Vec::new();
    for j in 0..nv {
        for i in 0..nu {
            let (u, v) = (
                i as f64 * std::f64::consts::TAU / nu as f64,
                j as f64 * std::f64::consts::TAU / nv as f64,
            );
            let r = 2.0 + 0.7 * v.cos();
            p.push([r * u.cos(), r * u.sin(), 0.7 * v.sin()]);
        }
    }
    Surface::new(p, grid_triangles(nu, nv, |i, j| (j % nv) * nu + i % nu)).unwrap()
}

/// Interior vertices whose matchings around them do not add up to a whole
/// turn (valid for small angle defects and jumps, as on a fine sphere).
pub fn singular_by_matchings(s: &Surface, field: &CrossField) -> Vec<u32> {
    let mut sum = vec![0i64; s.positions.len()];
    for (e, &[a, b]) in s.edges.iter().enumerate() {
        if s.is_boundary_edge(e as u32) {
            continue;
        }
        // going counter-clockwise around a vertex crosses the edge from
        // the face holding the half-edge into it to the other
        let p = i64::from(field.matching[e]);
        sum[a as usize] -= p;
        sum[b as usize] += p;
    }
    (0..s.positions.len() as u32)
        .filter(|&v| !s.boundary_vertex[v as usize] && sum[v as usize].rem_euclid(4) != 0)
        .collect()
}

/// The unit square as a `k × k` grid without the cells `lo..hi` in both
/// directions (an annulus), unused vertices dropped.
pub fn square_with_hole(k: usize, lo: usize, hi: usize) -> Surface {
    let id = |i: usize, j: usize| j * (k + 1) + i;
    let mut t = Vec::new();
    for j in 0..k {
        for i in 0..k {
            if (lo..hi).contains(&i) && (lo..hi).contains(&j) {
                continue;
            }
            t.extend(grid_triangles(1, 1, |a, b| id(i + a, j + b)));
        }
    }
    let mut new = vec![u32::MAX; (k + 1) * (k + 1)];
    let mut p = Vec::new();
    for tri in &mut t {
        for v in tri.iter_mut() {
            if new[*v as usize] == u32::MAX {
                new[*v as usize] = p.len() as u32;
                let (i, j) = (*v as usize % (k + 1), *v as usize / (k + 1));
                p.push([i as f64 / k as f64, j as f64 / k as f64, 0.0]);
            }
            *v = new[*v as usize];
        }
    }
    Surface::new(p, t).unwrap()
}
