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
//! Invariants: at most `1 + MOVES.len()` maps for a refusal, then two for
//! the count; the one kept has the count closer to `N` (the first on a
//! tie); a map counted `None` never replaces one counted.

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

/// A map, its report, the count of each map made, the time counting.
pub type Counted = (TriMap, IntegrateReport, Vec<Option<usize>>, Duration);

/// Integrates with `opts` (for `n` quads), counts, and integrates once
/// more when the count asks for it (module docs).
pub fn integrate_counted(
    mut integrate: impl FnMut(&IntegrateOptions) -> Result<(TriMap, IntegrateReport), String>,
    mut opts: IntegrateOptions,
    n: usize,
    count: &mut CountQuads<'_>,
) -> Result<Counted, String> {
    let mut counting = Duration::ZERO;
    let mut count = |m: &TriMap| {
        let t = Instant::now();
        let q = count(m);
        counting += t.elapsed();
        q
    };
    let (mut map, mut rep) = integrate(&opts)?;
    let mut first = count(&map);
    let mut counted = vec![first];
    let gauge = opts.gauge_offset;
    for shift in MOVES {
        if first.is_some() {
            break;
        }
        // refused: the grid moved against the surface
        let moved = IntegrateOptions {
            gauge_offset: [0, 1].map(|i| (gauge[i] + shift[i]).rem_euclid(1.0)),
            ..opts.clone()
        };
        let (m, r) = integrate(&moved)?;
        first = count(&m);
        counted.push(first);
        if first.is_some() {
            (map, rep, opts) = (m, r, moved);
        }
    }
    let area_target = first.and_then(|q| recount_target(n, rep.map_area, q));
    if let (Some(q), Some(area)) = (first, area_target) {
        // the second map shares the first's budget of roundings (the
        // integration's cost): `ROUNDINGS` in all, but two at least
        // (one at what the first search left unseen, one more step)
        opts.quads = Some(area);
        opts.max_roundings = ROUNDINGS.saturating_sub(rep.roundings).max(2);
        opts.seen = rep.roundings_seen.clone();
        let (map2, rep2) = integrate(&opts)?;
        let second = count(&map2);
        counted.push(second);
        if second.is_some_and(|q2| q2.abs_diff(n) < q.abs_diff(n)) {
            (map, rep) = (map2, rep2);
        }
    }
    Ok((map, rep, counted, counting))
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
