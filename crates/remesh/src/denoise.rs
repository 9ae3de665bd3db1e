//! The surface the cross field is computed on: the input smoothed along
//! its normals, so that the field does not see the mesh's noise.
//!
//! Input: a [`Surface`], a number of steps and the feature edges.
//! Output: a [`Surface`] on the same triangles (same vertices, edges and
//! faces, so every index carries over), each interior vertex moved
//! `steps` times by half its umbrella Laplacian's normal part (vertices
//! on the boundary or on a feature edge stay: a cube stays a cube); and
//! [`frame_turn`], the angle that carries a direction of a face of one
//! surface to the same face of the other.
//!
//! Why: the smoothest field's singularities follow the Gaussian curvature
//! at the mesh's own scale. A scanned or decimated mesh has large angle
//! defects of both signs at single vertices (the dragon's scales and
//! teeth), each a ± singularity pair that no real tool's map has.
//! Measured (field only, no sharp edges, `FieldOptions::denoise_steps`):
//!
//! | surface | 0 steps | 2 steps | 5 steps | 10 steps | reference map |
//! |---|---|---|---|---|---|
//! | dragon (24 984 triangles) | 719 | 414 | 431 | 471 | 403 |
//! | decimated knight (1 000) | 130 | 97 | 112 | 131 | 124 |
//! | duck (19 720) | 55 | 40 | 48 | 56 | 36 |
//! | horse (6 000) | 46 | 44 | 46 | 43 | 44 |
//!
//! ("reference map": the singular vertices of the map shipped with the
//! file.) More steps do worse: the spikes shrink, then fold. Moving the
//! vertices along the surface too (the plain umbrella step) changes the
//! triangles' shapes so much that the carried-back field gets thousands
//! of singularities: only the normal part is used.
//!
//! Invariant: the field carried back with [`frame_turn`] has, on the
//! input surface, the singularities it had on the smoothed one wherever
//! no edge's jump crosses ±π/4 in the transfer (measured above: within
//! a few percent).

use crate::surface::{cross, dot, sub, Surface};

/// `surface` smoothed by `steps` normal steps (module docs); `None` when
/// `steps` is 0 or a smoothed triangle degenerates (then use the input).
pub fn smoothed(surface: &Surface, steps: u32, features: &[bool]) -> Option<Surface> {
    if steps == 0 {
        return None;
    }
    let n = surface.positions.len();
    let mut pinned = surface.boundary_vertex.clone();
    for (e, &[a, b]) in surface.edges.iter().enumerate() {
        if features.get(e).copied().unwrap_or(false) {
            pinned[a as usize] = true;
            pinned[b as usize] = true;
        }
    }
    let mut p = surface.positions.clone();
    for _ in 0..steps {
        let mut sum = vec![[0.0; 3]; n];
        let mut count = vec![0.0f64; n];
        for &[a, b] in &surface.edges {
            for (x, y) in [(a, b), (b, a)] {
                for i in 0..3 {
                    sum[x as usize][i] += p[y as usize][i];
                }
                count[x as usize] += 1.0;
            }
        }
        let mut normal = vec![[0.0; 3]; n];
        for t in &surface.triangles {
            let [a, b, c] = t.map(|v| p[v as usize]);
            let nt = cross(sub(b, a), sub(c, a));
            for &v in t {
                for i in 0..3 {
                    normal[v as usize][i] += nt[i];
                }
            }
        }
        for v in 0..n {
            let nn = dot(normal[v], normal[v]);
            if count[v] == 0.0 || pinned[v] || nn <= 0.0 {
                continue;
            }
            let d: [f64; 3] = std::array::from_fn(|i| sum[v][i] / count[v] - p[v][i]);
            let k = 0.5 * dot(d, normal[v]) / nn;
            for i in 0..3 {
                p[v][i] += k * normal[v][i];
            }
        }
    }
    Surface::new(p, surface.triangles.clone()).ok()
}

/// The angle to add to a direction of face `f` in `from`'s frame to get
/// the same direction in `to`'s frame (two surfaces on the same
/// triangles): the circular mean, over the face's three edges, of the
/// edge's angle in `to` minus its angle in `from`.
pub fn frame_turn(from: &Surface, to: &Surface, f: u32) -> f64 {
    let (mut c, mut s) = (0.0, 0.0);
    for &e in &from.face_edges[f as usize] {
        let d = to.edge_angle(e, f) - from.edge_angle(e, f);
        c += d.cos();
        s += d.sin();
    }
    s.atan2(c)
}
