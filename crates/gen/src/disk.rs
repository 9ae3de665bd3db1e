//! A disk with one cone singularity of index `k/4` at its centre.
//!
//! Mesh: a polar grid of the unit disk, `rings` rings of `sectors`
//! vertices plus the centre; sector `j` spans `θ ∈ [2πj/S, 2π(j+1)/S]`.
//! Map: `w = scale · f(r)^α · e^{iαθ}`, `α = 1 − k/4`, the angle unwrapped
//! per triangle from 0 to 2π; the corners at `θ = 2π` (the seam) get
//! `R·w(θ = 0)` with `R` the quarter turns of `e^{i2πα}`, so the map is
//! exactly GP with one seam of transitions `(R, 0)`. The centre maps to
//! the origin, a grid point (SoG).
//!
//! `f` is the identity, or, `reverted`, a piecewise-linear fold
//! `f(0, 0.3, 0.55, 1) = (0, 0.55, 0.08, 1)`: the rings in `r ∈ (0.3, 0.55)`
//! are reverted (`f' < 0`), and their image folds back over the centre's
//! neighbourhood down to map radius `scale·0.08^α`. A radial change commutes
//! with the seam rotation, so the map stays GP; the centre's one-ring itself
//! is never reverted by a radial change.
//!
//! Expected: the quads are the unit cells of the cone (`4α` quadrants)
//! whose centres lie inside the boundary polygon; the centre has valence
//! `4α = 4 − k`, every other interior vertex valence 4, also when
//! reverted (the paper reports that its method loses the single −5/4
//! singularity of the reverted `k = −5` disk; dualex recovers it on the
//! registry's `disk_m5_reverted`, checked end to end).

use crate::expected::Expected;
use dualex_map::{Rot2, TriMap};
use std::collections::BTreeMap;
use std::f64::consts::{FRAC_PI_2, TAU};

/// The disk map of index `index_quarters / 4`; `None` unless
/// `index_quarters < 4` (the cone angle `2π(1 − k/4)` must be positive),
/// `rings >= 2`, `sectors >= 8` and `scale > 1`.
pub fn singular_disk(
    index_quarters: i32,
    reverted: bool,
    rings: usize,
    sectors: usize,
    scale: f64,
) -> Option<(TriMap, Expected)> {
    if index_quarters >= 4 || rings < 2 || sectors < 8 || scale.is_nan() || scale <= 1.0 {
        return None;
    }
    let quarters = (4 - index_quarters) as u32; // 4α
    let knots: &[(f64, f64)] = if reverted { &FOLD } else { &IDENTITY };
    let map = disk_map(quarters, knots, rings, sectors, scale, false);
    Some((map, cone_expected(quarters, scale, sectors)))
}

/// The polar mesh and its map (module docs). With `split`, the centre is
/// two vertices `A = (−ε, 0)` (fan sectors with `θ ∈ [π/2, 3π/2)`) and
/// `B = (ε, 0)` (the others, last index), both mapped to the origin and
/// joined by the two triangles `B, v(π/2), A` and `A, v(3π/2), B`;
/// `sectors` must then be a multiple of 4.
pub(crate) fn disk_map(
    quarters: u32,
    knots: &[(f64, f64)],
    rings: usize,
    sectors: usize,
    scale: f64,
    split: bool,
) -> TriMap {
    let alpha = f64::from(quarters) / 4.0;
    let b_id = (1 + rings * sectors) as u32;
    let id = |k: usize, j: usize| {
        if k == 0 {
            let on_a = !split || (sectors / 4..3 * sectors / 4).contains(&j);
            if on_a {
                0
            } else {
                b_id
            }
        } else {
            (1 + (k - 1) * sectors + j % sectors) as u32
        }
    };
    let (positions, base) = disk_vertices(alpha, knots, rings, sectors, scale, split);
    let seam = Rot2::quarter_turns(i64::from(quarters));
    let corner = |k: usize, j: usize| -> [f64; 2] {
        let w = base[id(k, j) as usize];
        if j == sectors {
            seam.apply(&w)
        } else {
            w
        }
    };
    let mut map = TriMap {
        positions,
        ..TriMap::default()
    };
    let mut add = |t: [(usize, usize); 3]| {
        map.simplices.push(t.map(|(k, j)| id(k, j)));
        map.coords.push(t.map(|(k, j)| corner(k, j)));
    };
    for j in 0..sectors {
        add([(0, j), (1, j), (1, j + 1)]);
        for k in 1..rings {
            add([(k, j), (k + 1, j), (k + 1, j + 1)]);
            add([(k, j), (k + 1, j + 1), (k, j + 1)]);
        }
    }
    if split {
        let (top, bottom) = (sectors / 4, 3 * sectors / 4);
        // (0, 0) is B (sector 0 is on B's side), (0, top) is A
        add([(0, 0), (1, top), (0, top)]);
        add([(0, top), (1, bottom), (0, 0)]);
    }
    map
}

/// Positions and map values (`θ ∈ [0, 2π)`) of the vertices of
/// [`disk_map`], in index order.
fn disk_vertices(
    alpha: f64,
    knots: &[(f64, f64)],
    rings: usize,
    sectors: usize,
    scale: f64,
    split: bool,
) -> (Vec<[f64; 3]>, Vec<[f64; 2]>) {
    let eps = 0.3 / rings as f64;
    let mut positions = vec![if split { [-eps, 0.0, 0.0] } else { [0.0; 3] }];
    let mut base = vec![[0.0; 2]];
    for k in 1..=rings {
        let r = k as f64 / rings as f64;
        let rho = scale * radial(r, knots).powf(alpha);
        for j in 0..sectors {
            let th = TAU * j as f64 / sectors as f64;
            positions.push([r * th.cos(), r * th.sin(), 0.0]);
            base.push([rho * (alpha * th).cos(), rho * (alpha * th).sin()]);
        }
    }
    if split {
        positions.push([eps, 0.0, 0.0]);
        base.push([0.0; 2]);
    }
    (positions, base)
}

/// Invalid quantization: the disk of [`singular_disk`] (not reverted) with
/// its centre split into two singular vertices `A` and `B` joined by a mesh
/// edge but mapped to the same grid point (the origin), so no iso of the
/// map separates them (module docs of `disk_map`). The rotations across the
/// zero-length map edge `A–B` are undetermined; the holonomies around `A`
/// and `B` compose to the cone's `e^{i2πα}`, so they can always be chosen
/// to make one of them regular. As the paper reports for every method,
/// the singularities are merged: expected as `singular_disk(k)`, one
/// vertex of valence `4 − k`. `None` under the conditions of
/// [`singular_disk`] or when `sectors` is not a multiple of 4.
pub fn invalid_quantization(
    index_quarters: i32,
    rings: usize,
    sectors: usize,
    scale: f64,
) -> Option<(TriMap, Expected)> {
    let (_, expected) = singular_disk(index_quarters, false, rings, sectors, scale)?;
    if sectors & 3 != 0 {
        return None;
    }
    let quarters = (4 - index_quarters) as u32;
    Some((
        disk_map(quarters, &IDENTITY, rings, sectors, scale, true),
        expected,
    ))
}

/// The identity radial parametrisation.
pub(crate) const IDENTITY: [(f64, f64); 2] = [(0.0, 0.0), (1.0, 1.0)];
/// The fold of the module docs.
const FOLD: [(f64, f64); 4] = [(0.0, 0.0), (0.3, 0.55), (0.55, 0.08), (1.0, 1.0)];
/// The layer lift of [`multi_boundary`].
const LIFT: [(f64, f64); 4] = [(0.0, 0.0), (0.25, 0.2), (0.5, 0.03), (1.0, 1.0)];

/// The piecewise-linear radial parametrisation through `knots`.
fn radial(r: f64, knots: &[(f64, f64)]) -> f64 {
    for w in knots.windows(2) {
        let ((r0, f0), (r1, f1)) = (w[0], w[1]);
        if r <= r1 {
            return f0 + (f1 - f0) * (r - r0) / (r1 - r0);
        }
    }
    1.0
}

/// The failure case of the paper's appendix (figure "failure"), as a
/// radial layer lift around a regular grid point: a disk without
/// singularity (`α = 1`) whose radius is reparametrised by
/// `f(0, 0.25, 0.5, 1) = (0, 0.2, 0.03, 1)` (map radius `scale·f`). The
/// inner disk maps beyond the centre's dual cell (`|u|, |v| < ½`), the
/// reverted band comes back to radius `0.03·scale < ½` inside it, so the
/// preimage of that cell is a disk plus an **annulus** (the reverted band
/// and the next sheet joined at the inner fold): a chart with two
/// boundaries, lifting one layer of iso-`u` and one of iso-`v` at once.
/// Expected: the plain disk (`singular_disk(0, …)`'s counts). The paper's
/// own failure figure (one lift per dimension, two separate lifts) may be
/// a harder configuration than this concentric one: dualex recovers this
/// one (checked end to end on the registry's `multi_boundary`). `None` under the
/// conditions of [`singular_disk`] or when `0.03·scale >= ½` or
/// `0.2·scale <= √½` (no annulus).
pub fn multi_boundary(rings: usize, sectors: usize, scale: f64) -> Option<(TriMap, Expected)> {
    singular_disk(0, false, rings, sectors, scale)?;
    if 0.03 * scale >= 0.5 || 0.2 * scale <= std::f64::consts::FRAC_1_SQRT_2 {
        return None;
    }
    let map = disk_map(4, &LIFT, rings, sectors, scale, false);
    Some((map, cone_expected(4, scale, sectors)))
}

/// Whether the map point at radius `rho` and cone angle `phi` (any real,
/// taken modulo the cone angle `2πα`) lies inside the boundary polygon.
fn inside(rho: f64, phi: f64, alpha: f64, scale: f64, sectors: usize) -> bool {
    let step = TAU * alpha / sectors as f64;
    let phi = phi.rem_euclid(TAU * alpha);
    let mid = (phi / step).floor() * step + 0.5 * step;
    rho < scale * (0.5 * step).cos() / (phi - mid).cos()
}

/// Counts cells and interior vertices of the cone (see the module docs).
fn cone_expected(quarters: u32, scale: f64, sectors: usize) -> Expected {
    let alpha = f64::from(quarters) / 4.0;
    let reach = scale.ceil() as i64 + 1;
    let cell_in = |q: u32, x: f64, y: f64| {
        inside(
            x.hypot(y),
            f64::from(q) * FRAC_PI_2 + y.atan2(x),
            alpha,
            scale,
            sectors,
        )
    };
    let (mut quads, mut regular) = (0usize, 0usize);
    for q in 0..quarters {
        for i in 0..reach {
            for j in 0..reach {
                let (x, y) = (i as f64, j as f64);
                if cell_in(q, x + 0.5, y + 0.5) {
                    quads += 1;
                }
                // vertex (i, j) with i >= 1 belongs to quadrant q
                let around = [(0.5, 0.5), (-0.5, 0.5), (-0.5, -0.5), (0.5, -0.5)];
                if i >= 1 && around.iter().all(|&(dx, dy)| cell_in(q, x + dx, y + dy)) {
                    regular += 1;
                }
            }
        }
    }
    let mut valence = BTreeMap::new();
    if (0..quarters).all(|q| cell_in(q, 0.5, 0.5)) {
        valence.insert(quarters, 1);
    }
    if regular > 0 {
        *valence.entry(4).or_insert(0) += regular;
    }
    Expected {
        quads: Some(quads),
        interior_valence: Some(valence),
        euler: Some(1),
        boundary_loops: Some(1),
    }
}

#[cfg(test)]
mod tests;
