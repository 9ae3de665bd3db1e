//! Folds centred on singular vertices (exactly GP).
//!
//! Input: the clean map of [`super::from_quads`] / [`super::from_hexes`]
//! (simplices in element order, `per_element` of them per element, each
//! in its element's chart `[0,k]^D`), the refined mesh, the vertex stars
//! and classes, a count `n` and a seed. Output: a displacement per vertex
//! in its home chart (see [`super::classify`]), to be projected and added
//! by [`super::perturb`].
//!
//! Up to `n` interior singular vertices are drawn as centres `c`, no
//! element holding two (a drawn vertex whose elements are taken is
//! skipped), so that the folds do not overlap at their centres. Around
//! each, every vertex `v` of an element holding `c` moves radially, in
//! that element's chart (`x = v − c`, `r = |x|`, `k` cells per element):
//!
//! ```text
//!   d(v) = ± A·sin(π r / R)·x / r   for 0 < r < R,   else 0
//!   A = 3k (amplitude), R = 1.5k (radius): the same fold, in element
//!   units, at every scale k (the map at k is the map at 1 scaled by k)
//!   −: pulled through c (the simplices around c turn inside out)
//!   +: pushed outwards (a folded shell); centres alternate − / +
//! ```
//!
//! Invariants: two elements holding both `c` and `v` are related by a
//! transition fixing `c`, so `x` (and `d`) differ by their rotation
//! exactly: `d`, carried to the home chart, does not depend on the
//! element it was computed in. `c` itself never moves (`r = 0`); the
//! projection of [`super::perturb`] keeps vertices on singular edges on
//! them and singular / boundary vertices still.

use super::classify::{Star, VertexClass};
use super::refine::Refined;
use crate::rng::SplitMix64;
use dualex_map::SimplexMap;
use std::collections::HashMap;

/// Fold amplitude, in elements (module docs).
const AMPLITUDE: f64 = 3.0;
/// Fold radius, in elements (module docs).
const RADIUS: f64 = 1.5;

/// Interior singular vertices that are element corners, in id order.
fn candidates<const D: usize>(r: &Refined<D>, classes: &[VertexClass]) -> Vec<u32> {
    let mut out: Vec<u32> = (0..r.elements)
        .flat_map(|e| (0..1usize << D).map(move |bits| r.id(e, corner_lattice(r.k, bits))))
        .filter(|&v| classes[v as usize] == VertexClass::Singular)
        .collect();
    out.sort_unstable();
    out.dedup();
    out
}

/// Lattice point of the element corner with bits `bits`.
fn corner_lattice<const D: usize>(k: usize, bits: usize) -> [usize; D] {
    std::array::from_fn(|a| k * (bits >> a & 1))
}

/// `n` distinct centres drawn with `seed` (all when fewer).
pub(crate) fn centres<const D: usize>(
    r: &Refined<D>,
    classes: &[VertexClass],
    n: usize,
    seed: u64,
) -> Vec<u32> {
    let mut cand = candidates(r, classes);
    let mut rng = SplitMix64::new(seed ^ 0xf01d_5e17);
    // elements around each candidate: no element holds two centres
    let mut around: HashMap<u32, Vec<usize>> = HashMap::new();
    for e in 0..r.elements {
        for bits in 0..1usize << D {
            let v = r.id(e, corner_lattice(r.k, bits));
            around.entry(v).or_default().push(e);
        }
    }
    let mut taken = vec![false; r.elements];
    let mut out = Vec::new();
    while out.len() < n && !cand.is_empty() {
        let c = cand.swap_remove((rng.next_u64() % cand.len() as u64) as usize);
        let elements = around.get(&c).map_or(&[][..], |v| &v[..]);
        if elements.iter().all(|&e| !taken[e]) {
            elements.iter().for_each(|&e| taken[e] = true);
            out.push(c);
        }
    }
    out
}

/// The radial displacement of `x = v − c` (module docs), `sign` ±1.
fn radial<const D: usize>(x: [f64; D], k: f64, sign: f64) -> [f64; D] {
    let r = x.iter().map(|a| a * a).sum::<f64>().sqrt();
    let radius = RADIUS * k;
    if r == 0.0 || r >= radius {
        return [0.0; D];
    }
    let m = sign * AMPLITUDE * k * (std::f64::consts::PI * r / radius).sin() / r;
    x.map(|a| a * m)
}

/// Home-chart displacements of the folds around `centres` (module docs).
pub(crate) fn displacements<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    r: &Refined<D>,
    stars: &[Star<D>],
    centres: &[u32],
    per_element: usize,
) -> Vec<[f64; D]> {
    let mut d = vec![[0.0; D]; map.positions.len()];
    // element → (centre index, the centre's chart coordinates there)
    let mut at: HashMap<usize, Vec<(usize, [f64; D])>> = HashMap::new();
    for e in 0..r.elements {
        for bits in 0..1usize << D {
            let lat = corner_lattice::<D>(r.k, bits);
            if let Some(i) = centres.iter().position(|&c| c == r.id(e, lat)) {
                at.entry(e).or_default().push((i, lat.map(|x| x as f64)));
            }
        }
    }
    let k = r.k as f64;
    for (v, star) in stars.iter().enumerate() {
        // one displacement per centre, whichever element gives it
        let mut done = vec![false; centres.len()];
        for &(s, corner, rot) in &star.corners {
            let Some(list) = at.get(&(s / per_element)) else {
                continue;
            };
            for &(i, xc) in list {
                if std::mem::replace(&mut done[i], true) {
                    continue;
                }
                let xv = map.coords[s][corner];
                let sign = if i % 2 == 0 { -1.0 } else { 1.0 };
                let ds = radial(std::array::from_fn(|a| xv[a] - xc[a]), k, sign);
                let dh = rot.inverse().apply(&ds);
                for (y, z) in d[v].iter_mut().zip(dh) {
                    *y += z;
                }
            }
        }
    }
    d
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_radial_profile_vanishes_at_the_centre_and_beyond_the_radius() {
        for k in [1.0, 2.0, 3.0] {
            assert_eq!(radial([0.0, 0.0, 0.0], k, -1.0), [0.0; 3]);
            assert_eq!(radial([1.5 * k, 0.0, 0.0], k, 1.0), [0.0; 3]);
            // pulled through: a vertex at distance k lands beyond the centre
            let d = radial([k, 0.0], k, -1.0);
            assert!(k + d[0] < 0.0, "k {k}: {d:?}");
            // scaled with k: the same fold in element units
            let d1 = radial([0.5, 0.3], 1.0, 1.0);
            let dk = radial([0.5 * k, 0.3 * k], k, 1.0);
            for a in 0..2 {
                assert!((dk[a] - k * d1[a]).abs() < 1e-12);
            }
        }
    }
}
