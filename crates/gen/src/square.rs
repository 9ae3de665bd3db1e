//! Maps of the unit square (planar positions, `z = 0`), one chart except
//! [`square_half_rotated`]. Every generator maps the square affinely onto
//! `[lo, hi]²` and then perturbs **interior** vertices only, so the boundary
//! and hence the expected quad mesh is the grid of the identity map:
//! `c × c` quads, `c = cells_between(lo, hi)`.
//!
//! The triangulation is the `res × res` grid described in [`Diagonal`], split as
//! chosen by [`Diagonal`].

use crate::build::{fold, single_chart, snap, Diagonal, Grid};
use crate::expected::{cells_between, Expected};
use crate::rng::SplitMix64;
use dualex_map::{Rot2, TriMap};

/// The affine map of the square onto `[lo, hi]²`, per vertex, snapped to
/// multiples of 2⁻³² so that later integer translations are exact.
fn affine(g: &Grid, lo: f64, hi: f64) -> Vec<[f64; 2]> {
    g.param
        .iter()
        .map(|p| snap([lo + (hi - lo) * p[0], lo + (hi - lo) * p[1]]))
        .collect()
}

fn expected(lo: f64, hi: f64) -> Expected {
    let c = cells_between(lo, hi);
    Expected::grid(c, c)
}

/// The identity (affine) map onto `[lo, hi]²`; no reverted triangle.
pub fn square_identity(res: usize, lo: f64, hi: f64, diagonal: Diagonal) -> (TriMap, Expected) {
    let g = Grid::new(res, diagonal);
    let value = affine(&g, lo, hi);
    (
        single_chart(g.positions(), &g.tris, &value),
        expected(lo, hi),
    )
}

/// A smooth fold: the affine map composed with a C¹ fold (a bump displacement along `u`) of
/// the square, centred at `(½, ½)`, radius `0.3`. `strength` 1.5 reverts
/// about 5–15% of the triangles (tested); GP trivially (one chart).
pub fn square_fold(
    res: usize,
    lo: f64,
    hi: f64,
    strength: f64,
    diagonal: Diagonal,
) -> (TriMap, Expected) {
    let g = Grid::new(res, diagonal);
    let value: Vec<[f64; 2]> = g
        .param
        .iter()
        .map(|&p| {
            let q = fold(p, [0.5, 0.5], 0.3, strength);
            [lo + (hi - lo) * q[0], lo + (hi - lo) * q[1]]
        })
        .collect();
    (
        single_chart(g.positions(), &g.tris, &value),
        expected(lo, hi),
    )
}

/// White noise: every interior vertex moved by a vector uniform in
/// `[-amplitude, amplitude]²` (map units). At `res = 2·(hi − lo)` an
/// amplitude of 1.0 reverts about 40% of the triangles (tested).
pub fn square_noise(
    res: usize,
    lo: f64,
    hi: f64,
    amplitude: f64,
    seed: u64,
    diagonal: Diagonal,
) -> (TriMap, Expected) {
    let g = Grid::new(res, diagonal);
    let value = noisy(&g, affine(&g, lo, hi), amplitude, seed);
    (
        single_chart(g.positions(), &g.tris, &value),
        expected(lo, hi),
    )
}

/// Adds noise to the interior vertices.
fn noisy(g: &Grid, mut value: Vec<[f64; 2]>, amplitude: f64, seed: u64) -> Vec<[f64; 2]> {
    let mut rng = SplitMix64::new(seed);
    for (v, m) in value.iter_mut().enumerate() {
        let d = rng.vec2(amplitude);
        if !g.on_boundary(v) {
            *m = snap([m[0] + d[0], m[1] + d[1]]);
        }
    }
    value
}

/// Every interior vertex mapped to the centre `((lo+hi)/2, (lo+hi)/2)`:
/// all interior triangles are degenerate, the boundary ring of triangles
/// spans the whole image.
pub fn square_collapsed(res: usize, lo: f64, hi: f64, diagonal: Diagonal) -> (TriMap, Expected) {
    let g = Grid::new(res, diagonal);
    let c = 0.5 * (lo + hi);
    let mut value = affine(&g, lo, hi);
    for (v, m) in value.iter_mut().enumerate() {
        if !g.on_boundary(v) {
            *m = [c, c];
        }
    }
    (
        single_chart(g.positions(), &g.tris, &value),
        expected(lo, hi),
    )
}

/// The rotation and integer translation of the right half's chart.
pub const HALF_ROTATION_TURNS: i64 = 1;
/// See [`HALF_ROTATION_TURNS`].
pub const HALF_TRANSLATION: [f64; 2] = [11.0, -4.0];

/// Noise as in [`square_noise`], then the triangles whose centroid has
/// `x > ½` get the chart `R·m + T` (`R` a quarter turn, `T = (11, −4)`).
/// A vertex's noise is applied before the chart change, so its corners in
/// the two charts differ exactly by `(R, T)`: the map is exactly GP, with a
/// seam of transitions `(R, T)` along the middle.
pub fn square_half_rotated(
    res: usize,
    lo: f64,
    hi: f64,
    amplitude: f64,
    seed: u64,
    diagonal: Diagonal,
) -> (TriMap, Expected) {
    let g = Grid::new(res, diagonal);
    let value = noisy(&g, affine(&g, lo, hi), amplitude, seed);
    let mut map = single_chart(g.positions(), &g.tris, &value);
    let r = Rot2::quarter_turns(HALF_ROTATION_TURNS);
    for (t, coords) in map.simplices.iter().zip(map.coords.iter_mut()) {
        let cx: f64 = t.iter().map(|&v| g.param[v as usize][0]).sum::<f64>() / 3.0;
        if cx > 0.5 {
            for c in coords.iter_mut() {
                let p = r.apply(c);
                *c = [p[0] + HALF_TRANSLATION[0], p[1] + HALF_TRANSLATION[1]];
            }
        }
    }
    (map, expected(lo, hi))
}

#[cfg(test)]
mod tests;
