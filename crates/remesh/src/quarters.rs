//! Quarter singularities in place of a +1/2 or a +1.
//!
//! Input: the surface the field is solved on, its field (`z = exp(4iθ)`
//! per face, [`crate::smooth`]), the faces already fixed, and a vertex of
//! index `q/4` with `q ≥ 2`. Output: the faces of the vertex's star fixed
//! to directions that turn by `q'·π/2` around it, with `q' ≤ 1` the
//! quarters closest to the vertex's angle defect (0 on a flat or smooth
//! spot, 1 at a cone apex sharper than 45° of defect). Solved again with
//! those faces fixed, the field turns by the rest of `q/4` around the
//! star instead of at its centre: in quarter singularities nearby.
//!
//! Why: a singular vertex of index `q/4` is a cone of angle
//! `2π − q·π/2` of the map: 0 for a +1, which collapses the map around
//! it, and a vertex of valence `4 − q` of the quad mesh, ≤ 2 for
//! `q ≥ 2`, which no valid quad mesh has inside. The smoothest field of
//! the relaxed energy ([`crate::smooth`]) makes such vertices on a disc
//! bounded by a feature loop: on a flat cap its solution is `z ≈ w⁴` (`w`
//! the position from the centre), one zero of order 4, and projecting to
//! unit length does not split it. A quad mesh of the disc has four
//! vertices of valence 3 instead. With the star around the centre fixed
//! to a field that does not turn, the harmonic `z` between the star and
//! the rim is `c₀(r) + c₄(r)·e^{4iφ}`: four simple zeros, at the four
//! angles where the two terms cancel, about 2/3 of the way to the rim
//! (`ln(R/r)/ln(R/ρ) = (r/R)⁴`, `ρ` the star's radius), the irregular
//! vertices of the quad mesh of a disc.
//!
//! Negative indices (−1/2, −1: vertices of valence 6 and 8) are valid
//! in a quad mesh and left as they are.
//!
//! Invariants: only free faces are fixed, and only around an interior
//! vertex whose whole star is free; the fixed directions differ between
//! two neighbours of the star by less than π/4 after transport, so the
//! matchings of the star's edges are 0 and its turning is `q'·π/2`.

use crate::surface::{dot, norm, sub, Surface};
use faer::c64;
use std::f64::consts::{FRAC_PI_2, PI};

/// Fixes the star of interior vertex `v` to a field of `q' ≤ 1` quarter
/// turns around it (module docs), starting from the direction `z` has on
/// the first face of the star. Returns whether it did (`false`: `v` is
/// on the boundary, or a face of its star is fixed already).
pub fn pin_star(surface: &Surface, z: &[c64], fixed: &mut [Option<f64>], v: u32) -> bool {
    let Some(ring) = star(surface, v) else {
        return false;
    };
    if ring.iter().any(|&(f, _)| fixed[f as usize].is_some()) {
        return false;
    }
    let defect = 2.0 * PI - corner_angles(surface, &ring, v);
    let quarters = (defect / FRAC_PI_2).round().min(1.0);
    // the star's faces counter-clockwise: each one the last transported,
    // turned by `step`
    let step = (quarters * FRAC_PI_2 - defect) / ring.len() as f64;
    let (f0, _) = ring[0];
    let mut theta = z[f0 as usize].arg() / 4.0;
    fixed[f0 as usize] = Some(theta);
    for k in 1..ring.len() {
        let ((f, _), (g, e)) = (ring[k - 1], ring[k]);
        theta = theta - surface.edge_angle(e, f) + surface.edge_angle(e, g) + step;
        fixed[g as usize] = Some(theta);
    }
    true
}

/// The faces around interior vertex `v`, counter-clockwise seen from
/// outside, each with the edge it shares with the one before it (the
/// first: with the last); `None` for a boundary vertex or a vertex of no
/// face.
fn star(surface: &Surface, v: u32) -> Option<Vec<(u32, u32)>> {
    if surface.boundary_vertex[v as usize] {
        return None;
    }
    // per face of the star: (the corner after v, the face, the edge from
    // v to the corner after v)
    let mut around: Vec<(u32, u32, u32)> = Vec::new();
    for (f, t) in surface.triangles.iter().enumerate() {
        if let Some(i) = t.iter().position(|&w| w == v) {
            around.push((t[(i + 1) % 3], f as u32, surface.face_edges[f][i]));
        }
    }
    around.sort_unstable();
    let first = *around.first()?;
    let mut ring = Vec::with_capacity(around.len());
    let mut at = first;
    loop {
        // face [v, a, b]: the next one counter-clockwise is [v, b, c],
        // across the edge v–b, which is its edge from v to its next corner
        let (_, f, _) = at;
        let t = surface.triangles[f as usize];
        let i = t.iter().position(|&w| w == v)?;
        let b = t[(i + 2) % 3];
        let k = around.binary_search_by_key(&b, |x| x.0).ok()?;
        ring.push((f, 0));
        at = around[k];
        if at.1 == first.1 || ring.len() > around.len() {
            break;
        }
    }
    if ring.len() != around.len() {
        return None;
    }
    // the edge shared with the one before: the next face's edge from v
    let n = ring.len();
    let edges: Vec<u32> = ring
        .iter()
        .map(|&(f, _)| around.iter().find(|x| x.1 == f).expect("in the star").2)
        .collect();
    for k in 0..n {
        ring[k].1 = edges[k];
    }
    Some(ring)
}

/// The sum of the corner angles at `v` of the faces of `ring`.
fn corner_angles(surface: &Surface, ring: &[(u32, u32)], v: u32) -> f64 {
    ring.iter()
        .map(|&(f, _)| {
            let t = surface.triangles[f as usize];
            let i = t.iter().position(|&w| w == v).expect("in the star");
            let p = |k: usize| surface.positions[t[(i + k) % 3] as usize];
            let (x, y) = (sub(p(1), p(0)), sub(p(2), p(0)));
            (dot(x, y) / (norm(x) * norm(y))).clamp(-1.0, 1.0).acos()
        })
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::field::CrossField;
    use crate::singularity::vertex_turning;

    /// A fan of `k` triangles around vertex 0, its centre raised by `h`
    /// (a cone: defect > 0 for `h ≠ 0`).
    fn fan(k: u32, h: f64) -> Surface {
        let mut p = vec![[0.0, 0.0, h]];
        for i in 0..k {
            let a = 2.0 * PI * f64::from(i) / f64::from(k);
            p.push([a.cos(), a.sin(), 0.0]);
        }
        let t: Vec<[u32; 3]> = (0..k).map(|i| [0, 1 + i, 1 + (i + 1) % k]).collect();
        Surface::new(p, t).expect("a fan")
    }

    /// The pinned star turns by 0 around a flat centre and by one quarter
    /// around cone apices of defects from 0.5 to 2.8 rad (whatever the
    /// index of the field it started from), and only the star is fixed.
    #[test]
    fn the_pinned_star_turns_by_at_most_a_quarter() {
        for (h, want) in [(0.0, 0), (1.0, 1), (3.0, 1), (0.2, 0)] {
            let s = fan(24, h);
            let defect = 2.0 * PI - corner_angles(&s, &star(&s, 0).unwrap(), 0);
            for start in [0.0, 1.0, 2.5] {
                let z: Vec<c64> = (0..24)
                    .map(|f| c64::cis(start + 4.0 * f64::from(f) * PI / 12.0))
                    .collect();
                let mut fixed = vec![None; 24];
                assert!(pin_star(&s, &z, &mut fixed, 0));
                let angle: Vec<f64> = fixed.iter().map(|a| a.expect("pinned")).collect();
                let field = CrossField::from_angles(&s, angle);
                let turn = vertex_turning(&s, &field)[0];
                let q = turn / FRAC_PI_2;
                assert!(
                    (q - f64::from(want)).abs() < 1e-9,
                    "h {h} (defect {defect:.3}), start {start}: {q} quarters"
                );
            }
        }
        // a boundary vertex is not pinned
        let s = fan(6, 0.0);
        let mut fixed = vec![None; 6];
        assert!(!pin_star(&s, &[c64::new(1.0, 0.0); 6], &mut fixed, 1));
        assert!(fixed.iter().all(Option::is_none));
    }
}
