//! Exactly-GP perturbations: noise and folds.
//!
//! Input: a clean map, the vertex classes, the options. Output: the map
//! with every non-boundary vertex moved in map space by one displacement
//! `d` (drawn in its home chart, projected onto the subspace fixed by its
//! holonomy, rounded to a multiple of 2⁻³²), added as `R·d` to its corner
//! in every chart (`R` = the chart's rotation relative to home, see
//! [`super::classify`]). Transitions are unchanged, exactly: rotations are
//! signed permutations and the sums are exact (values < 2²⁰).
//!
//! Noise: `d` uniform in `[-a, a]^D`. Folds: up to 3 vertices next to a
//! singular vertex or edge (else any free vertex) get `|d| = 1.5` per
//! axis instead, which reverts the simplices around them. Boundary and
//! singular vertices never move; vertices on a singular edge move along it
//! (or not at all when its holonomy is trivial: a whole number of turns).
//! The folds centred on singular vertices ([`super::fold`]) come in as
//! `extra` displacements and are projected the same way.

use super::classify::{Star, VertexClass};
use super::FromMeshOptions;
use crate::rng::SplitMix64;
use dualex_map::SimplexMap;

/// Rounds to a multiple of 2⁻³².
pub(crate) fn snap<const D: usize>(x: [f64; D]) -> [f64; D] {
    const S: f64 = 4_294_967_296.0;
    x.map(|c| (c * S).round() / S)
}

/// Adds `R·d` to every corner of the star.
fn displace<const N: usize, const D: usize>(
    map: &mut SimplexMap<N, D>,
    star: &Star<D>,
    d: [f64; D],
) {
    for &(s, c, r) in &star.corners {
        let rd = r.apply(&d);
        for (x, y) in map.coords[s][c].iter_mut().zip(rd) {
            *x += y;
        }
    }
}

/// Vertices next to a singular one that can move (fold centres).
fn fold_candidates<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    classes: &[VertexClass],
) -> Vec<usize> {
    let free = |v: usize| matches!(classes[v], VertexClass::Regular | VertexClass::SingularEdge);
    let mut near = vec![false; classes.len()];
    for s in &map.simplices {
        let singular = s.iter().any(|&v| {
            matches!(
                classes[v as usize],
                VertexClass::Singular | VertexClass::SingularEdge
            )
        });
        if singular {
            for &v in s {
                near[v as usize] = true;
            }
        }
    }
    let close: Vec<usize> = (0..classes.len()).filter(|&v| free(v) && near[v]).collect();
    if close.is_empty() {
        (0..classes.len()).filter(|&v| free(v)).collect()
    } else {
        close
    }
}

/// Noise, folds and the `extra` home-chart displacements (those of
/// [`super::fold`]) (module docs).
pub(crate) fn perturb<const N: usize, const D: usize>(
    map: &mut SimplexMap<N, D>,
    classes: &[VertexClass],
    stars: &[Star<D>],
    opts: &FromMeshOptions,
    extra: Option<&[[f64; D]]>,
) {
    if opts.noise == 0.0 && !opts.folds && extra.is_none() {
        return;
    }
    let mut rng = SplitMix64::new(opts.seed);
    let mut d: Vec<[f64; D]> = (0..classes.len())
        .map(|_| std::array::from_fn(|_| rng.symmetric(opts.noise)))
        .collect();
    if opts.folds {
        let cand = fold_candidates(map, classes);
        for _ in 0..3.min(cand.len()) {
            let v = cand[(rng.next_u64() % cand.len() as u64) as usize];
            d[v] = std::array::from_fn(|_| if rng.next_u64() & 1 == 0 { 1.5 } else { -1.5 });
        }
    }
    for (dv, e) in d.iter_mut().zip(extra.unwrap_or(&[])) {
        for (x, y) in dv.iter_mut().zip(e) {
            *x += y;
        }
    }
    for (v, star) in stars.iter().enumerate() {
        // singular edges with a trivial holonomy (a whole number of turns)
        // do not tell their direction: such vertices stay too
        let stays = match classes[v] {
            VertexClass::Boundary | VertexClass::Singular => true,
            VertexClass::SingularEdge => star.group.len() == 1,
            VertexClass::Regular => false,
        };
        if stays {
            continue;
        }
        let dv = snap(star.project(d[v]));
        if dv.iter().any(|&x| x != 0.0) {
            displace(map, star, dv);
        }
    }
}
