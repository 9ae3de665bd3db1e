//! The surfaces of the remesher's sweep (issue 23): smooth surfaces of
//! genus 0–8 and bumpy squares with 1–8 holes close to each other and to
//! the outer boundary.
//!
//! - [`smooth_genus`]: a polycube plate with `g` one-voxel holes (one row
//!   up to 4 holes, two rows beyond: bars one voxel wide and thick, thin
//!   handles), smoothed (Laplacian steps) until no edge is sharp: a smooth
//!   closed surface of genus `g`, outward normals.
//! - [`square_with_holes`]: the bumpy square of [`crate::shapes`] on a
//!   104 × 96 grid with `k` rectangular holes of 6 × 10 cells in a row;
//!   the first 3 cells from the outer boundary, then gaps of
//!   [`HOLE_GAPS`] cells. At 300, 1000 and 5000 quads a target quad edge
//!   is about 6, 3.3 and 1.5 cells, so the gaps cover ½ to 3 target edges
//!   at each size.
//!
//! Every one stays under 20 000 triangles.

use crate::shapes::{grid_triangles, voxel_surface};
use crate::surface::Surface;
use std::f64::consts::PI;

/// Gaps between consecutive holes of [`square_with_holes`], in cells.
pub const HOLE_GAPS: [u32; 7] = [1, 2, 3, 5, 8, 12, 17];

/// Grid of [`square_with_holes`]: cells along x and y.
const HOLES_GRID: (u32, u32) = (104, 96);

/// A hole of [`square_with_holes`]: cells along x and y.
const HOLE: (u32, u32) = (6, 10);

/// A smooth closed surface of genus `g ≤ 8` (module docs).
pub fn smooth_genus(g: u32) -> Surface {
    let g = g.min(8);
    let rows = if g <= 4 { 1 } else { 2 };
    let per_row = g.div_ceil(rows).max(1);
    let (nx, ny) = (2 * per_row as i32 + 1, 2 * rows as i32 + 1);
    let mut voxels = Vec::new();
    let mut holes = 0;
    for y in 0..ny {
        for x in 0..nx {
            let hole = x % 2 == 1 && y % 2 == 1 && holes < g;
            if hole {
                holes += 1;
            } else {
                voxels.push([x, y, 0]);
            }
        }
    }
    let s = voxel_surface(&voxels, 6);
    let positions = laplacian(&s, 60, 0.5);
    Surface::new(positions, s.triangles).expect("a smoothed polycube is a surface")
}

/// Laplacian smoothing (uniform weights): `rounds` steps of `λ`
/// towards the neighbours' mean. It shrinks the plate (its thickness to
/// about 0.7 voxel at 60 rounds of ½: thinner handles) and rounds every
/// edge: the steepest dihedral angle of [`smooth_genus`] is about 31°.
fn laplacian(s: &Surface, rounds: usize, lambda: f64) -> Vec<[f64; 3]> {
    let nv = s.positions.len();
    let mut nbrs: Vec<Vec<u32>> = vec![Vec::new(); nv];
    for &[a, b] in &s.edges {
        nbrs[a as usize].push(b);
        nbrs[b as usize].push(a);
    }
    let mut p = s.positions.clone();
    for _ in 0..rounds {
        p = (0..nv)
            .map(|v| {
                let mut m = [0.0; 3];
                for &w in &nbrs[v] {
                    for i in 0..3 {
                        m[i] += p[w as usize][i];
                    }
                }
                let d = nbrs[v].len().max(1) as f64;
                std::array::from_fn(|i| p[v][i] + lambda * (m[i] / d - p[v][i]))
            })
            .collect();
    }
    p
}

/// The bumpy square with `k ≤ 8` holes (module docs): one boundary loop
/// per hole plus the outer one, Euler characteristic `1 − k`.
pub fn square_with_holes(k: u32) -> Surface {
    let (ni, nj) = HOLES_GRID;
    let k = k.min(HOLE_GAPS.len() as u32 + 1);
    let j0 = (nj - HOLE.1) / 2;
    let mut removed = vec![false; (ni * nj) as usize];
    let mut i0 = 3;
    for h in 0..k {
        for j in j0..j0 + HOLE.1 {
            for i in i0..i0 + HOLE.0 {
                removed[(j * ni + i) as usize] = true;
            }
        }
        i0 += HOLE.0 + HOLE_GAPS.get(h as usize).copied().unwrap_or(0);
    }
    let id = |i: u32, j: u32| j * (ni + 1) + i;
    let all = grid_triangles(ni, nj, id);
    // two triangles per cell, cells row by row
    let kept: Vec<[u32; 3]> = all
        .chunks_exact(2)
        .zip(&removed)
        .filter(|(_, &r)| !r)
        .flat_map(|(t, _)| [t[0], t[1]])
        .collect();
    let mut index = vec![u32::MAX; ((ni + 1) * (nj + 1)) as usize];
    let mut positions = Vec::new();
    let triangles = kept
        .iter()
        .map(|t| {
            t.map(|v| {
                if index[v as usize] == u32::MAX {
                    index[v as usize] = positions.len() as u32;
                    let (i, j) = (v % (ni + 1), v / (ni + 1));
                    let (x, y) = (f64::from(i) / f64::from(ni), f64::from(j) / f64::from(nj));
                    let z = 0.2 * (PI * x).sin() * (PI * y).sin() * (3.0 * x + 2.0 * y).cos();
                    positions.push([x, y, z]);
                }
                index[v as usize]
            })
        })
        .collect();
    Surface::new(positions, triangles).expect("a square with holes is a surface")
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Boundary loops of a surface (its boundary edges joined at vertices).
    fn boundary_loops(s: &Surface) -> usize {
        let mut uf = dualex_util::union_find::UnionFind::new(s.positions.len());
        let mut on = vec![false; s.positions.len()];
        for (e, &[a, b]) in s.edges.iter().enumerate() {
            if s.is_boundary_edge(e as u32) {
                uf.union(a as usize, b as usize);
                on[a as usize] = true;
                on[b as usize] = true;
            }
        }
        let (label, _) = uf.labels();
        let mut roots: Vec<u32> = (0..s.positions.len())
            .filter(|&v| on[v])
            .map(|v| label[v])
            .collect();
        roots.sort_unstable();
        roots.dedup();
        roots.len()
    }

    #[test]
    fn genus_holes_and_sizes() {
        for g in 0..=8 {
            let s = smooth_genus(g);
            assert_eq!(s.euler_characteristic(), 2 - 2 * i64::from(g), "genus {g}");
            assert!(
                s.triangles.len() < 20_000,
                "genus {g}: {}",
                s.triangles.len()
            );
            assert!(crate::shapes::signed_volume(&s) > 0.0, "genus {g}");
            assert_eq!(boundary_loops(&s), 0);
        }
        for k in 1..=8 {
            let s = square_with_holes(k);
            assert_eq!(s.euler_characteristic(), 1 - i64::from(k), "{k} holes");
            assert_eq!(boundary_loops(&s), 1 + k as usize, "{k} holes");
            assert!(s.triangles.len() < 20_000);
        }
    }

    /// No edge of a smoothed polycube is sharp at the remesher's default
    /// 35°: the field is free, as on a scan.
    #[test]
    fn smoothed_polycubes_have_no_sharp_edge() {
        let s = smooth_genus(8);
        let mut worst: f64 = 0.0;
        for &[f0, f1] in &s.edge_faces {
            if f1 != crate::surface::NO_FACE {
                let (a, b) = (s.frames[f0 as usize][2], s.frames[f1 as usize][2]);
                let c = crate::surface::dot(a, b).clamp(-1.0, 1.0);
                worst = worst.max(c.acos().to_degrees());
            }
        }
        assert!(worst < 35.0, "dihedral {worst:.1}°");
    }
}
