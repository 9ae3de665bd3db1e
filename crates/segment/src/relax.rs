//! Relaxation of the local map where it folds (issue 22): a retry of the
//! drivers, never the first try.
//!
//! When the graph path fails on a folded map (3D: the glued mesh is
//! invalid; 2D: fairing leaves degenerate vertices it finds no partner
//! for), the drivers run steps 1–3 again, relax the local map in its fold
//! regions ([`relax`]) and run steps 4–7 on the result
//! ([`retry`]); they keep the result only if it passes every check.
//!
//! Input: the prepared map of steps 1–3 ([`Prepared`]: the map, its stars
//! and the free axes of its singular vertices, the local map not yet
//! sanitized). Output: the local map with the vertices of the region
//! moved, and a [`RelaxReport`].
//!
//! The region: the vertices of the reverted simplices (det < 0 in the
//! local map), grown by [`RINGS`] rings of neighbours. Each round moves
//! every movable vertex of the region, in increasing order, to the mean of
//! its neighbours as seen from its own corners (a Gauss–Seidel step of
//! the uniform Laplacian; each neighbour read in the chart of the simplex
//! they share, brought into the vertex's reference chart). Invariants:
//! - a singular vertex without a free axis, a boundary vertex and every
//!   vertex outside the region do not move; a singular vertex with a free
//!   axis moves along it only;
//! - a vertex moves by [`LocalMap::move_vertex`]: the same vector in
//!   every chart of its star, no transition changes (the map stays GP);
//! - rounds stop when no simplex of the region is reverted, when a count
//!   (every [`CHECK_EVERY`] rounds) finds no fewer than the last, or after
//!   [`MAX_ROUNDS`] (the folds of issue 22 unfold in 8–16); sequential, in a fixed order: deterministic whatever
//!   the number of threads.

use crate::local::LocalMap;
use crate::simplex::Dim;
use crate::split::ToSplit;
use crate::stats::SegmentStats;
use crate::steps::{self, Dimension, Model, Options, Prepared, Segmented};
use dualex_map::{SimplexMap, Stars};
use dualex_util::timing::Laps;

/// Rings of neighbours added around the vertices of the reverted
/// simplices.
pub const RINGS: usize = 2;

/// Most relaxation rounds.
pub const MAX_ROUNDS: usize = 64;

/// Rounds between two counts of the reverted simplices.
pub const CHECK_EVERY: usize = 8;

/// What [`relax`] did (the stats' `relax` object, written only when a
/// driver kept the result of its retry).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct RelaxReport {
    /// Vertices of the region that may move.
    pub vertices: usize,
    /// Rounds run.
    pub rounds: usize,
    /// Reverted simplices before.
    pub reverted_before: usize,
    /// Reverted simplices of the region after.
    pub reverted_after: usize,
}

impl RelaxReport {
    /// The report as JSON (`relaxed_vertices`, `relax_rounds`, …).
    pub fn to_json(&self) -> serde_json::Value {
        serde_json::json!({
            "relaxed_vertices": self.vertices,
            "relax_rounds": self.rounds,
            "reverted_before": self.reverted_before,
            "reverted_after": self.reverted_after,
        })
    }
}

/// Relaxes `local` in the fold regions of `map` (module docs); `free` as
/// [`crate::sanitize::free_axes`].
pub fn relax<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    stars: &Stars<D>,
    free: &[Option<usize>],
    local: &mut LocalMap<N, D>,
) -> RelaxReport {
    let reverted: Vec<usize> = (0..local.coords.len())
        .filter(|&s| local.det(s) < 0.0)
        .collect();
    let mut rep = RelaxReport {
        reverted_before: reverted.len(),
        ..RelaxReport::default()
    };
    let nv = stars.singular.len();
    let mut inside = vec![false; nv];
    for &s in &reverted {
        for &v in &map.simplices[s] {
            inside[v as usize] = true;
        }
    }
    for _ in 0..RINGS {
        let ring: Vec<usize> = (0..nv).filter(|&v| inside[v]).collect();
        for v in ring {
            for e in stars.of(v) {
                for &w in &map.simplices[e.simplex as usize] {
                    inside[w as usize] = true;
                }
            }
        }
    }
    // the movable vertices, with the axis a singular one is held to
    let movable: Vec<(usize, Option<usize>)> = (0..nv)
        .filter(|&v| inside[v] && !stars.boundary[v])
        .filter_map(
            |v| match (stars.singular[v], free.get(v).copied().flatten()) {
                (false, _) => Some((v, None)),
                (true, Some(a)) => Some((v, Some(a))),
                (true, None) => None,
            },
        )
        .collect();
    rep.vertices = movable.len();
    let mut region: Vec<usize> = movable
        .iter()
        .flat_map(|&(v, _)| stars.of(v).iter().map(|e| e.simplex as usize))
        .chain(reverted.iter().copied())
        .collect();
    region.sort_unstable();
    region.dedup();
    let count = |l: &LocalMap<N, D>| region.iter().filter(|&&s| l.det(s) < 0.0).count();
    rep.reverted_after = count(local);
    while rep.reverted_after > 0 && rep.rounds < MAX_ROUNDS {
        for &(v, axis) in &movable {
            let mut delta = mean_offset(stars, local, map, v);
            if let Some(a) = axis {
                delta = std::array::from_fn(|k| if k == a { delta[k] } else { 0.0 });
            }
            local.move_vertex(stars, v, &delta);
        }
        rep.rounds += 1;
        if rep.rounds.is_multiple_of(CHECK_EVERY) {
            let now = count(local);
            let stalled = now >= rep.reverted_after;
            rep.reverted_after = now;
            if stalled {
                break;
            }
        }
    }
    rep.reverted_after = count(local);
    rep
}

/// The mean of `v`'s neighbours minus `v`, in `v`'s reference chart (each
/// simplex of its star read in its own chart, rotated back).
fn mean_offset<const N: usize, const D: usize>(
    stars: &Stars<D>,
    local: &LocalMap<N, D>,
    map: &SimplexMap<N, D>,
    v: usize,
) -> [f64; D] {
    let mut sum = [0.0; D];
    let mut n = 0usize;
    for e in stars.of(v) {
        let s = e.simplex as usize;
        let c = &local.coords[s];
        let x = c[e.corner as usize];
        let back = e.rot.inverse();
        for (k, y) in c.iter().enumerate() {
            if k == e.corner as usize || map.simplices[s][k] as usize == v {
                continue;
            }
            let d = back.apply(&std::array::from_fn(|a| y[a] - x[a]));
            for (sk, dk) in sum.iter_mut().zip(d) {
                *sk += dk;
            }
            n += 1;
        }
    }
    if n == 0 {
        return [0.0; D];
    }
    sum.map(|x| x / n as f64)
}

/// The drivers' retry (module docs): steps 1–3 again (the input's own
/// counts were read on the first try), the local map relaxed, and only
/// when no simplex of the region is left reverted, steps 4–7 and the
/// driver's `rest` (untangling to its last step) on it. `before`: the
/// driver's stats as steps 1–7 of the first try left them (their shared
/// half, `AsMut`, takes the report: [`SegmentStats::relax`]). `Some` when `good` accepts the result; else
/// the driver keeps its first result (the retry shows in the laps only:
/// `relax`).
pub fn retry<'a, const N: usize, const D: usize, S, T>(
    map: &'a SimplexMap<N, D>,
    opts: &Options<'_>,
    before: S,
    laps: &mut Laps,
    rest: impl FnOnce(Segmented<'a, N, D>, &mut S, &mut Laps) -> T,
    good: impl Fn(&S) -> bool,
) -> Option<(T, S)>
where
    Dim<N, D>: Dimension<N, D>,
    S: AsMut<SegmentStats>,
{
    let mut st = before;
    let seg = st.as_mut();
    seg.split = 0;
    let skip =
        |_: &SimplexMap<N, D>, _: &Model<N, D>, _: &<Dim<N, D> as ToSplit<N, D>>::Singular| {};
    let mut prepared: Prepared<'a, N, D> = steps::prepare(map, opts, seg, skip).ok()?;
    let rep = relax(
        &prepared.map,
        &prepared.stars,
        &prepared.free,
        &mut prepared.local,
    );
    laps.lap("relax");
    if rep.reverted_after > 0 {
        return None;
    }
    seg.relax = Some(rep);
    let segmented = steps::segment_prepared(prepared, opts.seed, seg, laps);
    let out = rest(segmented, &mut st, laps);
    good(&st).then_some((out, st))
}

#[cfg(test)]
#[path = "relax_tests.rs"]
mod tests;
