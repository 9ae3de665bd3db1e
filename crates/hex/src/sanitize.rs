//! Step 2: sanitization of the local shifted map (paper appendix,
//! "Sanitization"; DESIGN §3.1).
//!
//! Input: [`LocalMap`], vertex [`Stars`]. Output: the same map with
//! - every non-singular vertex's corners **snapped** to one exactly-GP value
//!   (the reference corner carried through the star's rotations plus the
//!   nearest integer translation), so sign tests agree between charts;
//! - no vertex on an iso-surface, no edge on an iso-line, no face on a grid
//!   point (see [`crate::near`]). Offending vertices are moved by one small
//!   random vector in their reference chart, carried to every corner
//!   through the star's rotations (translations untouched: no transition
//!   changes). Collapsed clusters move as one ([`crate::clusters`]).
//!
//! Vertices on singular edges cannot move freely: when all the holonomies
//! around such a vertex fix one axis (a vertex inside one singular edge,
//! whose direction is that axis), it moves along that axis only, which
//! clears an iso-surface across the edge. What remains is reported in
//! [`SanitizeReport::singular_on_iso`]; the tracer stops the walks that
//! meet them ("inconsistent") and leaves those sides unmatched.

use crate::clusters::Clusters;
use crate::local::LocalMap;
use crate::near::bad_vertices;
use crate::rng::SplitMix;
use dualex_map::{Rot3, Stars, TetMap, Topology, Transitions};
use std::collections::HashSet;

/// Initial perturbation amplitude (map units).
pub const AMPLITUDE: f64 = 1e-5;
/// Perturbation rounds before giving up on a vertex.
const ROUNDS: usize = 40;

/// What sanitization did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SanitizeReport {
    /// Vertices whose corners were snapped to one GP value.
    pub snapped_vertices: usize,
    /// Largest distance a snap moved a corner.
    pub max_snap: f64,
    /// Distinct vertices perturbed.
    pub perturbed_vertices: usize,
    /// Collapsed clusters (more than one vertex) found.
    pub clusters: usize,
    /// Cluster moves refused (the cluster holds a singular vertex or its
    /// rotations disagree).
    pub stuck_clusters: usize,
    /// Rounds used.
    pub rounds: usize,
    /// Singular vertices moved along their singular edge's axis.
    pub singular_moved: usize,
    /// Singular vertices left bad (cannot be perturbed).
    pub singular_on_iso: Vec<u32>,
    /// Non-singular vertices still bad after all rounds (0 expected).
    pub unresolved: usize,
}

/// Sanitizes `local` in place.
pub fn sanitize(
    map: &TetMap,
    topo: &Topology<4>,
    stars: &Stars<3>,
    local: &mut LocalMap,
    seed: u64,
) -> SanitizeReport {
    let mut rep = SanitizeReport::default();
    snap(stars, local, &mut rep);
    let clusters = Clusters::build(map, stars, local);
    rep.clusters = clusters.count_nontrivial();
    let free_axis: Vec<Option<usize>> = (0..stars.singular.len())
        .map(|v| {
            stars.singular[v]
                .then(|| singular_free_axis(topo, stars, &local.trans, v))
                .flatten()
        })
        .collect();
    let mut mv = Mover {
        stars,
        clusters: &clusters,
        free_axis: &free_axis,
        rng: SplitMix::new(seed),
        moved: vec![false; map.positions.len()],
        moved_singular: HashSet::new(),
    };
    let mut amp = AMPLITUDE;
    let mut bad = bad_vertices(map, &local.coords);
    for round in 0..ROUNDS {
        rep.rounds = round;
        if !mv.round(local, &bad, amp, &mut rep) {
            break;
        }
        if round % 8 == 7 {
            amp *= 2.0;
        }
        bad = bad_vertices(map, &local.coords);
    }
    rep.unresolved = bad.iter().filter(|&&v| !stars.singular[v as usize]).count();
    rep.singular_on_iso = bad
        .into_iter()
        .filter(|&v| stars.singular[v as usize])
        .collect();
    rep.singular_moved = mv.moved_singular.len();
    rep.perturbed_vertices = mv.moved.iter().filter(|&&m| m).count();
    rep
}

/// The state of the perturbation rounds.
struct Mover<'a> {
    stars: &'a Stars<3>,
    clusters: &'a Clusters,
    /// Per vertex: the only axis a singular vertex may move along.
    free_axis: &'a [Option<usize>],
    rng: SplitMix,
    moved: Vec<bool>,
    moved_singular: HashSet<u32>,
}

impl Mover<'_> {
    /// Moves every movable vertex of `bad` (its whole cluster, once) by a
    /// random vector of length `amp`; `false` when none is movable.
    fn round(
        &mut self,
        local: &mut LocalMap,
        bad: &[u32],
        amp: f64,
        rep: &mut SanitizeReport,
    ) -> bool {
        let movable =
            |v: &&u32| !self.stars.singular[**v as usize] || self.free_axis[**v as usize].is_some();
        let todo: Vec<u32> = bad.iter().filter(movable).copied().collect();
        let mut done_root = HashSet::new();
        for &v in &todo {
            if let Some(axis) = self.free_axis[v as usize] {
                let mut d = [0.0; 3];
                d[axis] = if self.rng.unit() < 0.5 { amp } else { -amp };
                move_vertex(self.stars, local, v as usize, &d);
                self.moved_singular.insert(v);
                continue;
            }
            let root = self.clusters.root(v);
            if !done_root.insert(root) {
                continue;
            }
            let delta = self.rng.direction().map(|x| x * amp);
            match self.clusters.members_rot(root) {
                Some(members) => {
                    for (w, r) in members {
                        self.moved[w as usize] = true;
                        move_vertex(self.stars, local, w as usize, &r.apply(&delta));
                    }
                }
                None => rep.stuck_clusters += 1,
            }
        }
        !todo.is_empty()
    }
}

/// Holonomies around vertex `v`, as rotations of its reference chart: one
/// per face of its star where the star's rotations disagree.
fn holonomies(
    topo: &Topology<4>,
    stars: &Stars<3>,
    trans: &Transitions<4, 3>,
    v: usize,
) -> Vec<Rot3> {
    let star = stars.of(v);
    let mut out = Vec::new();
    for e in star {
        let s = e.simplex as usize;
        for f in (0..4).filter(|&f| f != e.corner as usize) {
            let Some((n, _)) = topo.neighbour(s, f) else {
                continue;
            };
            let expected = e.rot.then(&trans.rot[s][f]);
            if let Some(o) = star.iter().find(|o| o.simplex as usize == n) {
                if o.rot != expected {
                    out.push(expected.then(&o.rot.inverse()));
                }
            }
        }
    }
    out
}

/// The axis (of `v`'s reference chart) that every holonomy around `v`
/// fixes with its sign, if exactly one does: moving along it is consistent
/// in every chart.
fn singular_free_axis(
    topo: &Topology<4>,
    stars: &Stars<3>,
    trans: &Transitions<4, 3>,
    v: usize,
) -> Option<usize> {
    let h = holonomies(topo, stars, trans, v);
    if h.is_empty() {
        return None;
    }
    let fixed: Vec<usize> = (0..3)
        .filter(|&a| h.iter().all(|r| r.apply_dir(2 * a) == 2 * a))
        .collect();
    match fixed[..] {
        [a] => Some(a),
        _ => None,
    }
}

/// Snaps every non-singular vertex's corners to one GP value.
fn snap(stars: &Stars<3>, local: &mut LocalMap, rep: &mut SanitizeReport) {
    for v in 0..stars.singular.len() {
        if stars.singular[v] {
            continue;
        }
        let star = stars.of(v);
        let Some(first) = star.first() else { continue };
        let x_ref = local.coords[first.simplex as usize][first.corner as usize];
        for e in star {
            let y = e.rot.apply(&x_ref);
            let x = &mut local.coords[e.simplex as usize][e.corner as usize];
            for k in 0..3 {
                let snapped = y[k] + (x[k] - y[k]).round();
                rep.max_snap = rep.max_snap.max((snapped - x[k]).abs());
                x[k] = snapped;
            }
        }
        rep.snapped_vertices += 1;
    }
}

/// Adds `delta` (in `v`'s reference chart) to every corner of `v`.
fn move_vertex(stars: &Stars<3>, local: &mut LocalMap, v: usize, delta: &[f64; 3]) {
    for e in stars.of(v) {
        let d = e.rot.apply(delta);
        let x = &mut local.coords[e.simplex as usize][e.corner as usize];
        for k in 0..3 {
            x[k] += d[k];
        }
    }
}
