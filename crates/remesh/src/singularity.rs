//! Singular vertices of a cross field: the index of every interior vertex.
//!
//! Input: a [`Surface`] and a [`CrossField`]. Output: `(vertex, quarters)`
//! for the interior vertices of nonzero index `quarters / 4`.
//!
//! The index of vertex `v` is the turning of the field along a small loop
//! around `v`, counter-clockwise seen from outside, over `2π`:
//! `(d(v) + Σ ±jump(e)) / 2π`, where `d(v) = 2π − Σ corner angles` is the
//! angle defect (the holonomy of the loop) and the sum runs over the
//! edges at `v`: the loop crosses edge `e = [a, b]` from `f0` to `f1`
//! around `b` (sign `+`) and from `f1` to `f0` around `a` (sign `−`).
//! [`CrossField::jump`] is already the rotation of the followed direction
//! across the edge (the matching only says which of the four directions
//! it lands on), so the matchings do not enter. Summed over a closed
//! surface, every jump appears once with each sign and the defects add up
//! to `2π·χ` (Gauss–Bonnet): `Σ index = χ` (Poincaré–Hopf), which the
//! tests check.
//!
//! Boundary vertices have their own index ([`boundary_indices`]), for a
//! field that follows the boundary: the turning from the first boundary
//! edge to the last one through the fan, `(π − Σ corner angles + Σ ±jump)
//! / 2π` (a square's corner `+1/4`, a straight boundary `0`, a concave
//! right angle `−1/4`). With them Poincaré–Hopf holds on surfaces with
//! boundary too: `Σ interior + Σ boundary = χ`.

use crate::field::CrossField;
use crate::surface::{dot, norm, sub, Surface, NO_FACE};
use std::f64::consts::{FRAC_PI_2, PI};

/// The turning `d(v) + Σ ±jump` of every vertex, in radians, with
/// `d(v) = 2π − Σ angles` inside and `π − Σ angles` on the boundary
/// (`2π` for a vertex of no triangle).
pub fn vertex_turning(surface: &Surface, field: &CrossField) -> Vec<f64> {
    let mut turn: Vec<f64> = surface
        .boundary_vertex
        .iter()
        .map(|&b| if b { PI } else { 2.0 * PI })
        .collect();
    for t in &surface.triangles {
        for i in 0..3 {
            let [v, a, b] =
                [t[i], t[(i + 1) % 3], t[(i + 2) % 3]].map(|k| surface.positions[k as usize]);
            let (x, y) = (sub(a, v), sub(b, v));
            let c = (dot(x, y) / (norm(x) * norm(y))).clamp(-1.0, 1.0);
            turn[t[i] as usize] -= c.acos();
        }
    }
    for e in 0..surface.edges.len() as u32 {
        if surface.edge_faces[e as usize][1] == NO_FACE {
            continue;
        }
        let j = field.jump(surface, e);
        let [a, b] = surface.edges[e as usize];
        turn[b as usize] += j;
        turn[a as usize] -= j;
    }
    turn
}

/// Interior vertices of nonzero index, as `(vertex, quarters)`.
pub fn vertex_indices(surface: &Surface, field: &CrossField) -> Vec<(u32, i32)> {
    indices(surface, field, false)
}

/// Boundary vertices of nonzero index, as `(vertex, quarters)`:
/// meaningful when the field follows the boundary (the faces on both
/// boundary edges of the vertex), as [`crate::cross_field`] makes it by
/// default.
pub fn boundary_indices(surface: &Surface, field: &CrossField) -> Vec<(u32, i32)> {
    indices(surface, field, true)
}

/// The vertices used by a triangle get an index; the others are skipped.
fn indices(surface: &Surface, field: &CrossField, boundary: bool) -> Vec<(u32, i32)> {
    let mut used = vec![false; surface.positions.len()];
    for t in &surface.triangles {
        for &v in t {
            used[v as usize] = true;
        }
    }
    vertex_turning(surface, field)
        .iter()
        .enumerate()
        .filter(|&(v, _)| used[v] && surface.boundary_vertex[v] == boundary)
        .filter_map(|(v, &t)| {
            let q = (t / FRAC_PI_2).round() as i32;
            (q != 0).then_some((v as u32, q))
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A flat fan of `k` triangles around vertex 0 with a field turning
    /// `quarters/4` times around it.
    fn fan(k: u32, quarters: i32) -> (Surface, CrossField) {
        let mut p = vec![[0.0, 0.0, 0.0]];
        for i in 0..k {
            let a = 2.0 * PI * f64::from(i) / f64::from(k);
            p.push([a.cos(), a.sin(), 0.0]);
        }
        let t: Vec<[u32; 3]> = (0..k).map(|i| [0, 1 + i, 1 + (i + 1) % k]).collect();
        let s = Surface::new(p, t).unwrap();
        let angle = (0..k)
            .map(|f| {
                let phi = 2.0 * PI * (f64::from(f) + 0.5) / f64::from(k);
                // global angle quarters·φ/4, written in the face frame
                let g = f64::from(quarters) * phi / 4.0;
                let [x, y] = s.in_frame(f, [g.cos(), g.sin(), 0.0]);
                y.atan2(x)
            })
            .collect();
        let field = CrossField::from_angles(&s, angle);
        (s, field)
    }

    #[test]
    fn fan_index_has_the_turning_sign() {
        for q in [-2, -1, 0, 1, 2] {
            let (s, f) = fan(24, q);
            let t = vertex_turning(&s, &f)[0];
            assert!((t - f64::from(q) * FRAC_PI_2).abs() < 1e-9, "{q}: {t}");
            let sing: Vec<_> = vertex_indices(&s, &f);
            let want = if q == 0 { vec![] } else { vec![(0, q)] };
            assert_eq!(sing, want, "quarters {q}");
        }
    }
}
