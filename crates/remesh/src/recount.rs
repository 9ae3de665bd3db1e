//! The extraction's quad count in the loop of [`crate::remesh_counted`].
//!
//! Input: an integration (a closure from [`IntegrateOptions`] to a map and
//! its [`IntegrateReport`]), its options for `N` quads, and a count of the
//! quads the extraction makes of a map ([`CountQuads`]). Output: the map
//! kept, its report, the count of each map made, and the time spent
//! counting.
//!
//! The area fit makes the map's area `A` about `N`, but the extraction
//! does not make one quad per cell. When the first map's count `Q` misses
//! `N` by more than [`RECOUNT_TOLERANCE`] and `Q/A` is a repair's share
//! (within [`RECOUNT_MAX_RATIO`]), the map is made once more for the area
//! `N·A/Q`, its area fit starting from the first one's roundings
//! ([`IntegrateOptions::seen`]) with what they left of the budget
//! ([`ROUNDINGS`]; two at least).
//!
//! A first map the extraction refuses (on coarse grids over many
//! singularities the glued graph can shatter into pieces none of which
//! is most of the surface) is made again with the grid moved: the gauge
//! offset shifted by [`MOVES`], up to their number of times, until one is
//! taken; every map made is in the counts (`None` for a refused one).
//!
//! When the closer of the two maps still misses `N` by more than
//! [`SECANT_MISS`], a third is made at the area the two counts
//! interpolate ([`secant_target`]), with two roundings.
//!
//! (A refused second or third map is not made again: measured on the
//! shared surfaces, moving its grid brought no run within 10 % of `N`.)
//!
//! Invariants: at most `1 + MOVES.len()` maps for a refusal, then three
//! for the count; the one kept has the count closer to `N` (the first on a
//! tie); a map counted `None` never replaces one counted.

use crate::error::RemeshError;
use crate::integrate::{IntegrateOptions, IntegrateReport, ROUNDINGS};
use dualex_map::TriMap;
use std::time::{Duration, Instant};

/// How many quads the extraction makes of a map (`None`: it refuses
/// the map, or the mesh would not be written), for [`crate::remesh_counted`].
pub type CountQuads<'a> = dyn FnMut(&TriMap) -> Option<usize> + 'a;

/// The shifts of the gauge offset (map units, both axes) that move the
/// grid against the surface when the extraction refuses a map: half a
/// cell first (the farthest position), then a quarter and three quarters.
pub const MOVES: [[f64; 2]; 2] = [[0.5, 0.5], [0.25, 0.75]];

/// Most relative miss of the extraction's quad count that
/// [`crate::remesh_counted`] accepts without making the map again.
pub const RECOUNT_TOLERANCE: f64 = 0.05;

/// What [`integrate_counted`] made.
pub struct Counted {
    /// The map kept.
    pub map: TriMap,
    /// Its report.
    pub report: IntegrateReport,
    /// The count of each map made, in order (`None`: refused).
    pub counted: Vec<Option<usize>>,
    /// The index in `counted` of the map kept.
    pub kept: usize,
    /// The time spent counting.
    pub counting: Duration,
}

/// A map made by [`taken`], with its count and where that count stands.
struct Taken {
    map: TriMap,
    rep: IntegrateReport,
    count: Option<usize>,
    opts: IntegrateOptions,
    index: usize,
}

/// Integrates with `opts` (for `n` quads), counts, and integrates once
/// more when the count asks for it (module docs).
pub fn integrate_counted(
    mut integrate: impl FnMut(&IntegrateOptions) -> Result<(TriMap, IntegrateReport), RemeshError>,
    opts: IntegrateOptions,
    n: usize,
    count: &mut CountQuads<'_>,
) -> Result<Counted, RemeshError> {
    let mut counting = Duration::ZERO;
    let mut count = |m: &TriMap| {
        let t = Instant::now();
        let q = count(m);
        counting += t.elapsed();
        q
    };
    let mut counted = Vec::new();
    let mut best = taken(&mut integrate, &mut count, &opts, MOVES.len(), &mut counted)?;
    let area_target = best
        .count
        .and_then(|q| recount_target(n, best.rep.map_area, q));
    if let (Some(q), Some(area)) = (best.count, area_target) {
        // the second map shares the first's budget of roundings (the
        // integration's cost): `ROUNDINGS` in all, but two at least
        // (one at what the first search left unseen, one more step)
        let mut opts = IntegrateOptions {
            quads: Some(area),
            max_roundings: ROUNDINGS.saturating_sub(best.rep.roundings).max(2),
            seen: best.rep.roundings_seen.clone(),
            ..best.opts.clone()
        };
        let second = taken(&mut integrate, &mut count, &opts, 0, &mut counted)?;
        let (a1, a2) = (best.rep.map_area, second.rep.map_area);
        // (what the second search saw, for a third)
        opts.seen.extend(second.rep.roundings_seen.iter().cloned());
        let q2 = second.count;
        if q2.is_some_and(|q2| q2.abs_diff(n) < q.abs_diff(n)) {
            best = second;
        }
        // still more than 10 % off: one more map, at the area the two
        // counts interpolate (a secant step), from what both searches saw
        let third = q2.and_then(|q2| secant_target(n, (a1, q), (a2, q2)));
        let miss = |t: &Taken| t.count.map_or(usize::MAX, |q| q.abs_diff(n));
        if let Some(area) = third.filter(|_| miss(&best) as f64 > SECANT_MISS * n as f64) {
            opts.quads = Some(area);
            opts.max_roundings = 2;
            let third = taken(&mut integrate, &mut count, &opts, 0, &mut counted)?;
            if miss(&third) < miss(&best) {
                best = third;
            }
        }
    }
    Ok(Counted {
        map: best.map,
        report: best.rep,
        counted,
        kept: best.index,
        counting,
    })
}

/// The map of `opts` and its count, made again with the grid moved
/// ([`MOVES`], at most `moves` of them) while the extraction refuses it;
/// every count is pushed to `counted`. Returns the map taken (the first
/// one when every one is refused) with its report, count, options and
/// index in `counted`.
fn taken(
    integrate: &mut impl FnMut(&IntegrateOptions) -> Result<(TriMap, IntegrateReport), RemeshError>,
    count: &mut impl FnMut(&TriMap) -> Option<usize>,
    opts: &IntegrateOptions,
    moves: usize,
    counted: &mut Vec<Option<usize>>,
) -> Result<Taken, RemeshError> {
    let (map, rep) = integrate(opts)?;
    let first = Taken {
        count: count(&map),
        map,
        rep,
        opts: opts.clone(),
        index: counted.len(),
    };
    counted.push(first.count);
    if first.count.is_some() {
        return Ok(first);
    }
    let gauge = opts.gauge_offset;
    for shift in MOVES.iter().take(moves) {
        // refused: the grid moved against the surface
        let moved = IntegrateOptions {
            gauge_offset: [0, 1].map(|i| (gauge[i] + shift[i]).rem_euclid(1.0)),
            ..opts.clone()
        };
        let (map, rep) = integrate(&moved)?;
        let q = count(&map);
        counted.push(q);
        if q.is_some() {
            return Ok(Taken {
                map,
                rep,
                count: q,
                opts: moved,
                index: counted.len() - 1,
            });
        }
    }
    Ok(first)
}

/// Relative miss of the closer of two maps above which a third is made
/// at the area their counts interpolate ([`secant_target`]).
pub const SECANT_MISS: f64 = 0.10;

/// The area whose count the two maps' (area, count) points interpolate
/// to `n`: `None` when the counts do not grow with the area, or the
/// area is outside the two by more than their gap (no extrapolation far
/// out), or is one already made.
fn secant_target(n: usize, (a1, q1): (f64, usize), (a2, q2): (f64, usize)) -> Option<usize> {
    let (dq, da) = (q2 as f64 - q1 as f64, a2 - a1);
    if dq == 0.0 || da == 0.0 || dq / da <= 0.0 || !(a1.is_finite() && a2.is_finite()) {
        return None;
    }
    let a = a1 + (n as f64 - q1 as f64) * da / dq;
    let (lo, hi) = (a1.min(a2), a1.max(a2));
    let gap = hi - lo;
    if !(lo - gap..=hi + gap).contains(&a) || a < 1.0 {
        return None;
    }
    let t = a.round() as usize;
    (t != a1.round() as usize && t != a2.round() as usize).then_some(t)
}

/// Most quads per cell (and least, its inverse) that [`crate::remesh_counted`]
/// corrects for: the extraction's local repairs add or take a fraction of
/// the quads, but a count 4× the area is the global fallback's
/// subdivision, a different event: asking for a quarter of the cells
/// would give a mesh of a quarter of the quads whenever the coarser map
/// is not subdivided (measured: 16–27 quads for 100 on the horse).
pub const RECOUNT_MAX_RATIO: f64 = 1.5;

/// The area to make the map again for, when the extraction made `quads`
/// of a map of area `area` for `n` ([`crate::remesh_counted`]); `None` when the
/// count is within [`RECOUNT_TOLERANCE`], when quads per cell are beyond
/// [`RECOUNT_MAX_RATIO`], when the new area would be the old target (the
/// same map again) or is not a count.
fn recount_target(n: usize, area: f64, quads: usize) -> Option<usize> {
    let miss = (quads as f64 - n as f64).abs() / n as f64;
    if miss <= RECOUNT_TOLERANCE || quads == 0 || !(area.is_finite() && area > 0.0) {
        return None;
    }
    let ratio = quads as f64 / area;
    if !(1.0 / RECOUNT_MAX_RATIO..=RECOUNT_MAX_RATIO).contains(&ratio) {
        return None;
    }
    let target = (n as f64 * area / quads as f64).round();
    (target >= 1.0 && target != n as f64).then_some(target as usize)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A map the extraction refuses is made again with the grid moved by
    /// each of [`MOVES`] in turn until one is counted; when all are
    /// refused, the first is taken. (The shared surfaces no longer reach
    /// this path at sizes 100–2000, seeds 1–6.)
    #[test]
    fn a_refused_map_is_made_again_with_the_grid_moved() {
        let opts = IntegrateOptions::default();
        for (accept_from, index) in [(1, 0), (3, 2), (99, 0)] {
            let mut offsets = Vec::new();
            let mut integrate = |o: &IntegrateOptions| {
                offsets.push(o.gauge_offset);
                Ok((TriMap::default(), IntegrateReport::default()))
            };
            let mut made = 0;
            let mut count = |_: &TriMap| {
                made += 1;
                (made >= accept_from).then_some(40 + made)
            };
            let mut counted = Vec::new();
            let t = taken(&mut integrate, &mut count, &opts, MOVES.len(), &mut counted)
                .expect("no integration error");
            assert_eq!(t.index, index);
            assert_eq!(t.count, counted[index]);
            assert_eq!(t.opts.gauge_offset, offsets[index]);
            let tried = counted.len();
            assert_eq!(tried, accept_from.min(1 + MOVES.len()));
            for (k, shift) in MOVES.iter().enumerate().take(tried - 1) {
                let moved = [0, 1].map(|i| (offsets[0][i] + shift[i]).rem_euclid(1.0));
                assert_eq!(offsets[k + 1], moved);
            }
        }
    }

    #[test]
    fn secant_targets() {
        // 88 quads at area 100, 112 at 120: 100 quads at area 110
        assert_eq!(secant_target(100, (100.0, 88), (120.0, 112)), Some(110));
        // counts that fall as the area grows: no step
        assert_eq!(secant_target(100, (100.0, 112), (120.0, 88)), None);
        // far outside the two areas: no step
        assert_eq!(secant_target(100, (100.0, 10), (101.0, 11)), None);
        // the same count twice: no step
        assert_eq!(secant_target(100, (100.0, 90), (110.0, 90)), None);
    }

    #[test]
    fn recount_targets() {
        // 5 % off or closer: no second map
        assert_eq!(recount_target(100, 100.0, 105), None);
        assert_eq!(recount_target(100, 100.0, 95), None);
        // 20 % more quads than cells: 100 · 100 / 120
        assert_eq!(recount_target(100, 100.0, 120), Some(83));
        // 40 % more quads than cells: 500 · 490 / 686
        assert_eq!(recount_target(500, 490.0, 686), Some(357));
        // subdivided once (4 quads per cell), or a third of a quad per
        // cell: not a repair's share, no second map
        assert_eq!(recount_target(500, 490.0, 1960), None);
        assert_eq!(recount_target(500, 490.0, 160), None);
        // the same target again: the same map, not made
        assert_eq!(recount_target(100, 89.0, 89), None);
        // nothing to go by
        assert_eq!(recount_target(100, 100.0, 0), None);
        assert_eq!(recount_target(100, f64::NAN, 130), None);
        assert_eq!(recount_target(100, -3.0, 130), None);
    }
}
