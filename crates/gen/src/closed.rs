//! Closed surfaces: the cube surface (8 cone singularities of index ¼ at
//! its corners) and the torus (no singularity, translation transitions).
//!
//! Both are exactly GP; [`Perturb`] adds a fold (one chart region) or
//! white noise (per vertex, carried to its other corners through the
//! transitions' rotations; the cube's 8 singular corners are never moved).

use crate::build::{carry, fold, snap, Diagonal, Grid};
use crate::expected::Expected;
use crate::rng::SplitMix64;
use dualex_map::{Rot2, TriMap};
use std::collections::HashMap;

/// A perturbation of a valid map that keeps it exactly GP.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub enum Perturb {
    /// The valid map.
    #[default]
    None,
    /// A C¹ fold of the given strength (see `square_fold`) in a disk of
    /// radius 0.3 (parameter units) at the centre of one chart.
    Fold {
        /// 1.5 reverts a part of the disk; below ~0.65 nothing is reverted.
        strength: f64,
    },
    /// A vector uniform in `[-amplitude, amplitude]²` (map units) per vertex.
    Noise {
        /// Half-width of the noise, in map units.
        amplitude: f64,
        /// PRNG seed.
        seed: u64,
    },
}

/// The surface of the cube `[0,1]³`, each face a `res × res` grid and its
/// own chart `(n·x_a, n·x_b)` (face axes `a × b` = outward normal), so an
/// edge is `n` map units long and the cube corners are grid points.
/// Expected: `6n²` quads, 8 vertices of valence 3, the others 4, Euler 2.
pub fn cube_surface(
    n: u32,
    res: usize,
    perturb: Perturb,
    diagonal: Diagonal,
) -> (TriMap, Expected) {
    let g = Grid::new(res, diagonal);
    let mut welded: HashMap<[usize; 3], u32> = HashMap::new();
    let mut map = TriMap::default();
    // per welded vertex: (face, clean chart value) of each face it is on
    let mut charts: Vec<Vec<(usize, [f64; 2])>> = Vec::new();
    let mut corners: Vec<[(u32, usize); 3]> = Vec::new();
    for face in 0..6 {
        let (axes, side) = face_frame(face);
        let mut local = Vec::with_capacity(g.param.len());
        for (v, p) in g.param.iter().enumerate() {
            let mut key = [side * g.res; 3];
            key[axes[0]] = v % (g.res + 1);
            key[axes[1]] = v / (g.res + 1);
            let id = *welded.entry(key).or_insert_with(|| {
                map.positions.push(key.map(|k| k as f64 / g.res as f64));
                charts.push(Vec::new());
                (map.positions.len() - 1) as u32
            });
            charts[id as usize].push((face, p.map(|x| f64::from(n) * x)));
            local.push(id);
        }
        for t in &g.tris {
            map.simplices.push(t.map(|v| local[v as usize]));
            corners.push(t.map(|v| (local[v as usize], face)));
        }
    }
    let value = cube_values(&charts, perturb, n);
    map.coords = corners
        .iter()
        .map(|t| t.map(|(v, face)| value(v, face)))
        .collect();
    let quads = 6 * (n as usize).pow(2);
    let expected = Expected::closed(quads, &[(3, 8), (4, quads.saturating_sub(6))], 2);
    (map, expected)
}

/// The perturbed value of each welded vertex in each of its faces' charts:
/// noise (not on the 8 corners) drawn in the first face's chart and carried
/// to the second through the edge transition; the fold acts on face 0's
/// interior only.
fn cube_values<'a>(
    charts: &'a [Vec<(usize, [f64; 2])>],
    perturb: Perturb,
    n: u32,
) -> impl Fn(u32, usize) -> [f64; 2] + 'a {
    let mut rng = SplitMix64::new(match perturb {
        Perturb::Noise { seed, .. } => seed,
        _ => 0,
    });
    let base: Vec<[f64; 2]> = charts
        .iter()
        .map(|c| {
            let (home, clean) = c[0];
            match perturb {
                Perturb::Noise { amplitude, .. } if c.len() <= 2 => {
                    let d = rng.vec2(amplitude);
                    snap([clean[0] + d[0], clean[1] + d[1]])
                }
                Perturb::Fold { strength } if home == 0 && c.len() == 1 => {
                    let p = clean.map(|x| x / f64::from(n));
                    snap(fold(p, [0.5, 0.5], 0.3, strength).map(|x| f64::from(n) * x))
                }
                _ => clean,
            }
        })
        .collect();
    move |v: u32, face: usize| -> [f64; 2] {
        let c = &charts[v as usize];
        let (home, home_clean) = c[0];
        let clean = c.iter().find(|x| x.0 == face).map_or(home_clean, |x| x.1);
        if face == home {
            base[v as usize]
        } else if c.len() > 2 {
            clean
        } else {
            carry(
                &edge_rotation(home, face),
                base[v as usize],
                home_clean,
                clean,
            )
        }
    }
}

/// Face `f` of the cube: axes `[a, b, normal]` with `a × b` outward, and
/// the side (0 or 1) of the normal axis.
fn face_frame(f: usize) -> ([usize; 3], usize) {
    let (axis, side) = (f / 2, f % 2);
    let (a, b) = ((axis + 1) % 3, (axis + 2) % 3);
    if side == 0 {
        ([b, a, axis], 0)
    } else {
        ([a, b, axis], 1)
    }
}

/// The rotation from face `fa`'s chart to face `fb`'s across their edge.
fn edge_rotation(fa: usize, fb: usize) -> Rot2 {
    let (a, b) = (face_frame(fa).0, face_frame(fb).0);
    let edge_axis = 3 - a[2] - b[2];
    let dir = |axes: [usize; 3]| -> [f64; 2] {
        [
            f64::from(u8::from(axes[0] == edge_axis)),
            f64::from(u8::from(axes[1] == edge_axis)),
        ]
    };
    let (da, db) = (dir(a), dir(b));
    Rot2::all()
        .into_iter()
        .find(|r| r.apply(&da) == db)
        .unwrap_or_else(|| panic!("bug: no rotation between faces {fa} and {fb}"))
}

/// A torus (radii 1 and 0.4) with a `res_u × res_v` periodic grid and the
/// map `(n·s, m·t)` for parameters `(s, t) ∈ [0,1]²`, unwrapped per
/// triangle: transitions are the translations `(n, 0)` and `(0, m)`.
/// Expected: `n·m` quads, all of valence 4, Euler 0.
pub fn torus(
    n: u32,
    m: u32,
    res_u: usize,
    res_v: usize,
    perturb: Perturb,
    diagonal: Diagonal,
) -> (TriMap, Expected) {
    let (ru, rv) = (res_u.max(3), res_v.max(3));
    let id = |i: usize, j: usize| ((j % rv) * ru + (i % ru)) as u32;
    let mut map = TriMap {
        positions: torus_positions(ru, rv),
        ..TriMap::default()
    };
    let base = torus_values(n, m, ru, rv, perturb);
    // unwrapped: the vertex's value plus whole periods
    let value = |i: usize, j: usize| -> [f64; 2] {
        let b = base[id(i, j) as usize];
        [
            b[0] + f64::from(n) * (i / ru) as f64,
            b[1] + f64::from(m) * (j / rv) as f64,
        ]
    };
    for j in 0..rv {
        for i in 0..ru {
            let cells: [[(usize, usize); 3]; 2] = if diagonal == Diagonal::Fixed || (i + j) % 2 == 0
            {
                [
                    [(i, j), (i + 1, j), (i + 1, j + 1)],
                    [(i, j), (i + 1, j + 1), (i, j + 1)],
                ]
            } else {
                [
                    [(i, j), (i + 1, j), (i, j + 1)],
                    [(i + 1, j), (i + 1, j + 1), (i, j + 1)],
                ]
            };
            for tri in cells {
                map.simplices.push(tri.map(|(x, y)| id(x, y)));
                map.coords.push(tri.map(|(x, y)| value(x, y)));
            }
        }
    }
    let quads = (n * m) as usize;
    (map, Expected::closed(quads, &[(4, quads)], 0))
}

/// Positions of the `ru × rv` torus vertices (radii 1 and 0.4).
fn torus_positions(ru: usize, rv: usize) -> Vec<[f64; 3]> {
    let mut positions = Vec::with_capacity(ru * rv);
    for j in 0..rv {
        for i in 0..ru {
            let a = std::f64::consts::TAU * i as f64 / ru as f64;
            let b = std::f64::consts::TAU * j as f64 / rv as f64;
            let r = 1.0 + 0.4 * b.cos();
            positions.push([r * a.cos(), r * a.sin(), 0.4 * b.sin()]);
        }
    }
    positions
}

/// The perturbed map value of each torus vertex in the fundamental domain.
fn torus_values(n: u32, m: u32, ru: usize, rv: usize, perturb: Perturb) -> Vec<[f64; 2]> {
    let mut rng = SplitMix64::new(match perturb {
        Perturb::Noise { seed, .. } => seed,
        _ => 0,
    });
    (0..ru * rv)
        .map(|v| {
            let p = [(v % ru) as f64 / ru as f64, (v / ru) as f64 / rv as f64];
            let (q, d) = match perturb {
                Perturb::Fold { strength } => (fold(p, [0.5, 0.5], 0.3, strength), [0.0; 2]),
                Perturb::Noise { amplitude, .. } => (p, rng.vec2(amplitude)),
                Perturb::None => (p, [0.0; 2]),
            };
            snap([f64::from(n) * q[0] + d[0], f64::from(m) * q[1] + d[1]])
        })
        .collect()
}

#[cfg(test)]
mod tests;
