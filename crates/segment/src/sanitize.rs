//! Sanitization of the local shifted map, both dimensions (paper appendix,
//! "Sanitization"; DESIGN §3.1): step 4, the last step of the segmentation
//! before the nodes.
//!
//! Input: a [`LocalMap`], its [`Topology`] and vertex [`Stars`], the free
//! axes of the singular vertices ([`free_axes`]). Output: the same map
//! with
//! - every non-singular vertex's corners **snapped** to one exactly-GP value
//!   ([`LocalMap::snap`]), so sign tests agree between charts;
//! - no vertex, edge or (in 3D) face on the dual grid: no corner coordinate
//!   within `EPS` of an integer, no edge within `EPS` of an integer point
//!   (2D, [`crate::grid`]) or of an iso-line (3D, [`crate::near`]), no tet
//!   face within `EPS` of a grid point. Offending vertices are moved by one
//!   small random vector in their reference chart, carried to every corner
//!   through the star's rotations (translations untouched: no transition
//!   changes). Collapsed clusters ([`Clusters`]) move as one;
//!
//! and a [`SanitizeReport`].
//!
//! The rounds follow [`amplitude`]: 40 ordinary rounds, then extra rounds
//! of growing amplitude (up to 0.1) while a non-singular vertex is still on
//! the grid. A stuck cluster (its rotations disagree: it surrounds a
//! singularity) waits for the extra rounds, where its members move one by
//! one (the last resort: each is non-singular, so consistent in its own
//! charts; the collapsed region opens into slivers).
//!
//! Singular vertices cannot move freely (their charts disagree around
//! them). In 3D, when all the holonomies around one fix one axis (a vertex
//! inside one singular edge, whose direction is that axis), it moves along
//! that axis only, in the ordinary rounds; in 2D no rotation fixes an axis.
//! What remains is in [`SanitizeReport::singular_on_iso`] (2D: by kind,
//! [`SanitizeReport::singular_kinds`]); the walks that meet them end
//! unmatched and the repairs close what they leave.
//!
//! The per-dimension parts, [`Predicates`] at [`Dim<3, 2>`] and
//! [`Dim<4, 3>`] (`dim2.rs`, `dim3.rs`): which corners a simplex makes bad,
//! the random step, the kinds of the singular vertices left. Coordinates
//! are local (see [`crate::local`]), so `EPS` is absolute.

use crate::bad_scan::BadScan;
use crate::cluster::Clusters;
use crate::local::LocalMap;
use crate::sanitize_report::{amplitude, ROUNDS};
pub use crate::sanitize_report::{SanitizeReport, AMPLITUDE};
use dualex_map::{Rot, SimplexMap, Stars, Topology, Transitions};
use dualex_util::rng::SplitMix;
use mover::Mover;
use rayon::prelude::*;
use std::collections::BTreeMap;

mod dim2;
mod dim3;
mod mover;

/// The dimension marker of every generic step ([`Predicates`] is
/// implemented at `Dim<3, 2>` and `Dim<4, 3>`).
pub use crate::simplex::Dim;

/// What sanitization does differently per dimension.
pub trait Predicates<const N: usize, const D: usize> {
    /// Simplices per parallel task of the scan (below it, splitting costs
    /// more than it saves).
    const MIN_TASK: usize;
    /// Whether a round that finds nothing left to move is counted in
    /// [`SanitizeReport::rounds`] also once the schedule is spent (2D: yes,
    /// 3D: no; as the two sanitizers always counted, so reports stay).
    const COUNT_ROUND_PAST_SCHEDULE: bool;
    /// The corners that a simplex (corners `c`) makes bad, as a mask: bit
    /// `k` set when corner `k` is on an iso, is an endpoint of an edge
    /// through the grid (a grid point at an endpoint is that endpoint's
    /// problem only), or (3D) a corner of a face through a grid point.
    fn mask(c: &[[f64; D]; N]) -> u8;
    /// [`Self::mask`] for the first scan, given the corners `known` (bit
    /// `k`: corner `k`) that other simplices already made bad: a test that
    /// can only set bits of `known` (or of the mask so far) is skipped.
    /// The mask when it holds every bit of `known`; otherwise possibly
    /// only part of it, marked with [`crate::bad_scan::PARTIAL`] (the scan
    /// tests such a simplex again before its mask is read).
    fn mask_known(c: &[[f64; D]; N], known: u8) -> u8;
    /// A random vector of length `amp`.
    fn step(rng: &mut SplitMix, amp: f64) -> [f64; D];
    /// The kinds of the singular vertices `left` on isos (2D: `"90_node"`,
    /// …; by default, as in 3D, none).
    fn kinds(
        _topo: &Topology<N>,
        _stars: &Stars<D>,
        _local: &LocalMap<N, D>,
        _left: &[u32],
    ) -> BTreeMap<String, usize> {
        BTreeMap::new()
    }
}

/// Sanitizes `local` in place (module docs); `free_axis` as [`free_axes`]
/// (empty: no singular vertex moves, as in 2D).
pub fn sanitize<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    stars: &Stars<D>,
    free_axis: &[Option<usize>],
    local: &mut LocalMap<N, D>,
    seed: u64,
) -> SanitizeReport
where
    Dim<N, D>: Predicates<N, D>,
{
    let mut rep = SanitizeReport::default();
    (rep.snapped_vertices, rep.max_snap) = local.snap(stars);
    // the clusters beside the first scan (both read the snapped corners
    // only): the clusters' serial part overlaps the scan's tasks
    let (clusters, mut scan) = rayon::join(
        || Clusters::build(map, stars, &local.coords),
        || Scan::new(map, &local.coords),
    );
    rep.clusters = clusters.count_nontrivial();
    let mut mv = Mover::new(stars, &clusters, free_axis, seed);
    let mut bad = scan.list();
    let mut executed: usize = 0;
    for round in 0.. {
        let last_resort = round >= ROUNDS;
        let todo = mv.movable(&bad, last_resort);
        let amp = amplitude(round);
        if todo.is_empty() {
            if amp.is_some() || <Dim<N, D>>::COUNT_ROUND_PAST_SCHEDULE {
                rep.rounds = round;
            }
            break;
        }
        let Some(amp) = amp else {
            break;
        };
        rep.rounds = round;
        executed += 1;
        mv.touched.clear();
        mv.deltas.clear();
        mv.round::<N>(&todo, amp, last_resort);
        move_all(&mut local.coords, stars, &mv.touched, &mv.deltas);
        scan.update(map, stars, &local.coords, &mv.touched);
        bad = scan.list();
    }
    rep.extra_rounds = executed.saturating_sub(ROUNDS);
    rep.stuck_clusters = mv.stuck.len();
    rep.clusters_moved_apart = mv.apart.len();
    rep.unresolved = bad.iter().filter(|&&v| !stars.singular[v as usize]).count();
    rep.singular_on_iso = bad
        .into_iter()
        .filter(|&v| stars.singular[v as usize])
        .collect();
    rep.singular_kinds = <Dim<N, D>>::kinds(topo, stars, local, &rep.singular_on_iso);
    rep.singular_moved = mv.moved_singular.len();
    rep.perturbed_vertices = mv.moved.iter().filter(|&&m| m).count();
    rep
}

/// Corners moved below which [`move_all`] runs as one task.
const MOVE_TASK: usize = 1 << 15;

/// [`LocalMap::move_vertex`] of every vertex `moved[i]` by `deltas[i]`, in
/// that order: the simplices are cut into one range per thread and each
/// range adds, in the moves' order, the moved corners it holds, so every
/// corner gets the same additions in the same order whatever the cut.
fn move_all<const N: usize, const D: usize>(
    coords: &mut [[[f64; D]; N]],
    stars: &Stars<D>,
    moved: &[u32],
    deltas: &[[f64; D]],
) {
    let corners: usize = moved.iter().map(|&v| stars.of(v as usize).len()).sum();
    let parts = if corners < MOVE_TASK {
        1
    } else {
        rayon::current_num_threads().max(1)
    };
    let len = coords.len().div_ceil(parts).max(1);
    coords
        .par_chunks_mut(len)
        .enumerate()
        .for_each(|(i, part)| {
            let lo = i * len;
            for (&v, delta) in moved.iter().zip(deltas) {
                for e in stars.of(v as usize) {
                    let Some(x) = (e.simplex as usize)
                        .checked_sub(lo)
                        .and_then(|s| part.get_mut(s))
                    else {
                        continue;
                    };
                    let d = e.rot.apply(delta);
                    for (xk, dk) in x[e.corner as usize].iter_mut().zip(d) {
                        *xk += dk;
                    }
                }
            }
        });
}

/// The free axis (reference chart) of every singular vertex that has one
/// ([`singular_free_axis`]; `None` for the others). The hex driver
/// computes it once for its split and for [`sanitize`].
pub fn free_axes<const N: usize, const D: usize>(
    topo: &Topology<N>,
    stars: &Stars<D>,
    local: &LocalMap<N, D>,
) -> Vec<Option<usize>> {
    (0..stars.singular.len())
        .map(|v| {
            stars.singular[v]
                .then(|| singular_free_axis(topo, stars, &local.trans, v))
                .flatten()
        })
        .collect()
}

/// Holonomies around vertex `v`, as rotations of its reference chart: one
/// per facet of its star where the star's rotations disagree.
fn holonomies<const N: usize, const D: usize>(
    topo: &Topology<N>,
    stars: &Stars<D>,
    trans: &Transitions<N, D>,
    v: usize,
) -> Vec<Rot<D>> {
    let star = stars.of(v);
    let mut out = Vec::new();
    for e in star {
        let s = e.simplex as usize;
        for f in (0..N).filter(|&f| f != e.corner as usize) {
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
pub fn singular_free_axis<const N: usize, const D: usize>(
    topo: &Topology<N>,
    stars: &Stars<D>,
    trans: &Transitions<N, D>,
    v: usize,
) -> Option<usize> {
    let h = holonomies(topo, stars, trans, v);
    if h.is_empty() {
        return None;
    }
    let fixed: Vec<usize> = (0..D)
        .filter(|&a| h.iter().all(|r| r.apply_dir(2 * a) == 2 * a))
        .collect();
    match fixed[..] {
        [a] => Some(a),
        _ => None,
    }
}

/// [`BadScan`] with the dimension's tests ([`Predicates::mask_known`] in
/// the first scan, [`Predicates::mask`] after).
pub struct Scan(BadScan);

impl Scan {
    /// Tests every simplex.
    pub fn new<const N: usize, const D: usize>(
        map: &SimplexMap<N, D>,
        coords: &[[[f64; D]; N]],
    ) -> Self
    where
        Dim<N, D>: Predicates<N, D>,
    {
        let (mask, min_task) = (<Dim<N, D>>::mask_known, <Dim<N, D>>::MIN_TASK);
        Scan(BadScan::new(map, coords, mask, min_task))
    }

    /// The bad vertices, in increasing order.
    pub fn list(&self) -> Vec<u32> {
        self.0.list()
    }

    /// Re-tests after the vertices `moved` (corners in their stars) moved.
    pub fn update<const N: usize, const D: usize>(
        &mut self,
        map: &SimplexMap<N, D>,
        stars: &Stars<D>,
        coords: &[[[f64; D]; N]],
        moved: &[u32],
    ) where
        Dim<N, D>: Predicates<N, D>,
    {
        self.0.update(map, stars, coords, <Dim<N, D>>::mask, moved);
    }
}

#[cfg(test)]
mod mask_tests;
#[cfg(test)]
mod mover_tests;
#[cfg(test)]
mod tests;
