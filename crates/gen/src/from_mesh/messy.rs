//! Messier inputs: slivers (still exactly GP) and jitter (not).
//!
//! Slivers: an edge `(a, b)` from a singular vertex `a` (a vertex on a
//! singular edge when there is none) is split at `p = a + λ(b − a)`: every
//! simplex holding the edge becomes two, and `p` gets, in each chart,
//! `c_a + δ` with `δ = λ(c_b − c_a)` rounded to a multiple of one global
//! quantum `g = 2^(e−52)`, `2^e` above every map coordinate. Rounding is
//! symmetric and rotations are signed permutations, so `δ` in two charts
//! differ by their rotation exactly and every sum is exact: the map stays
//! exactly GP (transitions unchanged). The splits pick distinct edges
//! around singular vertices; the new vertex's class is that of its edge.
//!
//! Jitter: every corner of a selected vertex (class in the list, then kept
//! with probability `fraction`) moves by its own uniform vector in
//! `[-amplitude, amplitude]^D`: charts then disagree by ~amplitude.

use super::classify::VertexClass;
use super::{Jitter, Slivers};
use crate::rng::SplitMix64;
use dualex_map::SimplexMap;

/// Independent per-corner jitter (module docs).
pub(crate) fn jitter<const N: usize, const D: usize>(
    map: &mut SimplexMap<N, D>,
    classes: &[VertexClass],
    j: &Jitter,
    seed: u64,
) {
    let mut rng = SplitMix64::new(seed ^ 0x6a17_7e12);
    let chosen: Vec<bool> = classes
        .iter()
        .map(|c| rng.next_f64() < j.fraction && j.classes.contains(c))
        .collect();
    for (s, simplex) in map.simplices.iter().enumerate() {
        for (c, &v) in simplex.iter().enumerate() {
            if chosen[v as usize] {
                for x in map.coords[s][c].iter_mut() {
                    *x += rng.symmetric(j.amplitude);
                }
            }
        }
    }
}

/// Candidate edges `(a, b)` with `a` of class `class`, sorted, distinct.
fn edges_from<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    classes: &[VertexClass],
    class: VertexClass,
) -> Vec<(u32, u32)> {
    let mut out = Vec::new();
    for s in &map.simplices {
        for &a in s.iter().filter(|&&a| classes[a as usize] == class) {
            out.extend(s.iter().filter(|&&b| b != a).map(|&b| (a, b)));
        }
    }
    out.sort_unstable();
    out.dedup();
    out
}

/// Splits `count` edges next to singular vertices (module docs).
pub(crate) fn slivers<const N: usize, const D: usize>(
    map: &mut SimplexMap<N, D>,
    classes: &mut Vec<VertexClass>,
    s: Slivers,
    seed: u64,
) {
    let biggest = map
        .coords
        .iter()
        .flatten()
        .flatten()
        .fold(1.0f64, |m, x| m.max(x.abs()));
    let quantum = 2f64.powi(biggest.log2().floor() as i32 + 1 - 52);
    let mut edges = edges_from(map, classes, VertexClass::Singular);
    if edges.is_empty() {
        edges = edges_from(map, classes, VertexClass::SingularEdge);
    }
    let mut rng = SplitMix64::new(seed ^ 0x51_1e75);
    for _ in 0..s.count {
        if edges.is_empty() {
            break;
        }
        let (a, b) = edges.swap_remove((rng.next_u64() % edges.len() as u64) as usize);
        if split_edge(map, a, b, s.lambda, quantum) {
            classes.push(sliver_class::<D>(classes[a as usize], classes[b as usize]));
        }
    }
}

/// The class of a vertex inside edge `(a, b)` (approximate: the edge is
/// taken as singular when both ends are, on the boundary when both are).
fn sliver_class<const D: usize>(a: VertexClass, b: VertexClass) -> VertexClass {
    use VertexClass::*;
    let singular = |c: VertexClass| matches!(c, Singular | SingularEdge);
    match (a, b) {
        (Boundary, Boundary) => Boundary,
        (x, y) if D == 3 && singular(x) && singular(y) => SingularEdge,
        _ => Regular,
    }
}

/// Splits edge `(a, b)` at `lambda` from `a` in every simplex holding it.
fn split_edge<const N: usize, const D: usize>(
    map: &mut SimplexMap<N, D>,
    a: u32,
    b: u32,
    lambda: f64,
    quantum: f64,
) -> bool {
    if !map
        .simplices
        .iter()
        .any(|t| t.contains(&a) && t.contains(&b))
    {
        return false; // split away by an earlier sliver
    }
    let p = map.positions.len() as u32;
    let (pa, pb) = (map.positions[a as usize], map.positions[b as usize]);
    map.positions
        .push(std::array::from_fn(|i| pa[i] + lambda * (pb[i] - pa[i])));
    for s in 0..map.simplices.len() {
        let t = map.simplices[s];
        let (Some(ca), Some(cb)) = (
            t.iter().position(|&v| v == a),
            t.iter().position(|&v| v == b),
        ) else {
            continue;
        };
        let (xa, xb) = (map.coords[s][ca], map.coords[s][cb]);
        let xp: [f64; D] =
            std::array::from_fn(|i| xa[i] + (lambda * (xb[i] - xa[i]) / quantum).round() * quantum);
        // near a: (…a…p…), near b: (…p…b…); same orientation as t
        let (mut near_a, mut near_b) = ((t, map.coords[s]), (t, map.coords[s]));
        near_a.0[cb] = p;
        near_a.1[cb] = xp;
        near_b.0[ca] = p;
        near_b.1[ca] = xp;
        map.simplices[s] = near_a.0;
        map.coords[s] = near_a.1;
        map.simplices.push(near_b.0);
        map.coords.push(near_b.1);
    }
    true
}
