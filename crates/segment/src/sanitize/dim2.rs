//! Sanitization at D = 2 ([`Dim<3, 2>`]): the triangle test of the scan,
//! the random step, the kinds of the singular vertices left on isos.

use super::{Dim, Predicates};
use crate::bad_scan::{partial, PARTIAL};
use crate::boxes::Boxes;
#[cfg(doc)]
use crate::grid::spanned_axes_small;
use crate::grid::{
    axis_range, dist2d_below_eps as below_eps, floor_above, floor_above_small,
    grid_point_near_segment, near_int, near_int_on, near_int_on_small, point_near_line,
    segment_clear_of_grid, EPS,
};
use crate::local::LocalMap;
use dualex_map::{Stars, Topology};
use dualex_util::rng::SplitMix;
use dualex_util::round::FAST;
use std::collections::BTreeMap;

/// Every corner of a triangle bad.
const FULL: u8 = 0b111;

/// Below it in magnitude, a triangle's range may be tested against its
/// one grid point ([`Span`]).
const SMALL: f64 = 1024.0;

impl Predicates<3, 2> for Dim<3, 2> {
    const MIN_TASK: usize = 1024;
    const COUNT_ROUND_PAST_SCHEDULE: bool = true;

    /// An edge is skipped unless its box, grown by `2·EPS`, holds an
    /// integer on both axes ([`Boxes::spans`]) and one of those integer points
    /// is near its line ([`segment_clear_of_grid`]), or when both its ends
    /// are already bad (it cannot add a bit: the mask is the same).
    ///
    /// A triangle whose range spans at most one axis ([`crate::grid::spanned_axes`]:
    /// then no edge spans both) makes bad only its corners on that axis'
    /// isos. The boxes of the corners are computed once ([`Boxes`]).
    fn mask(c: &[[f64; 2]; 3]) -> u8 {
        tri_mask(c, 0)
    }

    fn mask_known(c: &[[f64; 2]; 3], known: u8) -> u8 {
        tri_mask(c, known)
    }

    fn step(rng: &mut SplitMix, amp: f64) -> [f64; 2] {
        let a = rng.angle();
        [amp * a.cos(), amp * a.sin()]
    }

    /// `"{angle}_{place}"`: the holonomy's angle (90, 180) and where the
    /// vertex is (`node`: both coordinates on isos, `iso`: one, `edge`:
    /// none, only an edge through a grid point).
    fn kinds(
        topo: &Topology<3>,
        stars: &Stars<2>,
        local: &LocalMap<3, 2>,
        left: &[u32],
    ) -> BTreeMap<String, usize> {
        let mut out = BTreeMap::new();
        for &v in left {
            let v = v as usize;
            let Some(first) = stars.of(v).first() else {
                continue;
            };
            let x = local.coords[first.simplex as usize][first.corner as usize];
            let on = (0..2).filter(|&k| near_int(x[k])).count();
            let turns = dualex_map::holonomy::ridge_rotation(
                topo,
                &local.trans,
                first.simplex as usize,
                &[first.corner as usize],
            )
            .map_or(0, |h| h.turns());
            let angle = [0, 90, 180, 90][turns as usize];
            let place = ["edge", "iso", "node"][on];
            *out.entry(format!("{angle}_{place}")).or_insert(0) += 1;
        }
        out
    }
}

/// [`Predicates::mask`] at D = 2, given the corners `known` to be bad
/// already ([`Predicates::mask_known`]: an edge is skipped when both its
/// ends are in the mask so far or in `known`; a result that may miss a
/// bit of `known` carries [`PARTIAL`]). With `known = 0`, the mask.
/// A triangle whose range holds one grid point ([`Span`]: most that span
/// both axes) is tested against that point alone ([`one_point_mask`]),
/// without the corners' boxes.
///
/// Out of line: one copy for both scans (two inlined copies made the
/// compiler call the boxes' helpers instead of inlining them).
#[inline(never)]
fn tri_mask(c: &[[f64; 2]; 3], known: u8) -> u8 {
    if known == FULL {
        return PARTIAL;
    }
    let span = Span::of(c);
    if span.axes != 0b11 {
        let a = span.axes.trailing_zeros() as usize;
        return match (span.axes, span.small) {
            (0, _) => 0,
            (_, true) => near_int_on_small(c, a),
            (_, false) => near_int_on(c, a),
        };
    }
    match span.point {
        Some(g) => one_point_mask(c, g, known),
        None => both_axes_mask(c, known, span.small),
    }
}

/// What [`tri_mask`] needs of a triangle's range per axis, grown by
/// `2·EPS`, from its least and greatest value: the spanned axes and
/// `small` as [`spanned_axes_small`] finds them, and the one grid point
/// of the range when it holds exactly one integer on each axis and every
/// coordinate is below 1024 in magnitude.
struct Span {
    axes: u8,
    small: bool,
    point: Option<[f64; 2]>,
}

impl Span {
    /// The span of the corners `c` (not NaN: validated input). Corners
    /// below `FAST/2` (those of every local map) take a path without a
    /// library call ([`floor_above_small`]: the call's spills slowed every
    /// triangle); the others [`Self::of_large`].
    #[inline(always)]
    fn of(c: &[[f64; 2]; 3]) -> Self {
        let range = [axis_range(c, 0), axis_range(c, 1)];
        let small = range.iter().fold(true, |s, &(lo, hi)| {
            s & (-0.5 * FAST < lo) & (hi < 0.5 * FAST)
        });
        if !small {
            return Self::of_large(range);
        }
        Self::of_ranges(range, true, floor_above_small)
    }

    /// [`Self::of`] for corners at or beyond `FAST/2` (out of line, rarely
    /// taken): the library's floor.
    #[cold]
    #[inline(never)]
    fn of_large(range: [(f64, f64); 2]) -> Self {
        Self::of_ranges(range, false, floor_above)
    }

    /// The span of the per-axis ranges `range` (`small`: whether they are
    /// below `FAST/2`), the integers below a range's top by `floor`.
    #[inline(always)]
    fn of_ranges(range: [(f64, f64); 2], small: bool, floor: impl Fn(f64) -> f64) -> Self {
        let (mut axes, mut one) = (0u8, true);
        let mut g = [0.0; 2];
        for (a, (ga, &(lo, hi))) in g.iter_mut().zip(&range).enumerate() {
            one &= -SMALL < lo && hi < SMALL;
            // the range's integers: `ceil(l)..=h`
            let (l, h) = (lo - 2.0 * EPS, floor(hi));
            axes |= u8::from(l.partial_cmp(&h) != Some(std::cmp::Ordering::Greater)) << a;
            one &= l > h - 1.0;
            *ga = h;
        }
        Span {
            axes,
            small,
            point: one.then_some(g),
        }
    }
}

/// [`tri_mask`] of a triangle spanning both axes whose range holds one
/// grid point `g` only ([`Span`]), given the corners `known` to be bad:
/// the corners within `EPS` of `g`'s isos (as [`near_int`]: the nearest
/// integer of such a coordinate is in the range, so it is `g`'s), then
/// each edge. An edge farther than `3·EPS` from `g` by
/// [`segment_clear_of_grid`]'s cross product is clear (that test clears
/// every edge whose box holds `g`, and no other grid point is in reach);
/// the others ([`edge_bits`]) are skipped when both ends are bad already.
#[inline(always)]
fn one_point_mask(c: &[[f64; 2]; 3], g: [f64; 2], known: u8) -> u8 {
    let mut mask = 0u8;
    let mut near_edges = 0u8;
    for k in 0..3 {
        let (a, b) = (&c[k], &c[(k + 1) % 3]);
        near_edges |= u8::from(point_near_line(a, b, &g)) << k;
        mask |= u8::from((g[0] - a[0]).abs() < EPS || (g[1] - a[1]).abs() < EPS) << k;
    }
    for k in (0..3).filter(|&k| near_edges >> k & 1 == 1) {
        let l = (k + 1) % 3;
        // both ends already bad: the edge cannot add a bit
        let ends = 1 << k | 1 << l;
        if (mask | known) & ends != ends {
            mask |= edge_bits(c, k, l, g);
        }
    }
    partial(mask, known)
}

/// The corners that the edge `k`–`l` of `c` makes bad through a grid
/// point near it, as [`both_axes_mask`] finds them
/// ([`grid_point_near_segment`], whose answer the box filters never
/// change), when `g` is the only grid point in reach ([`Span`]). An end
/// exactly at `g` is the grid point found (at distance 0): the other end
/// is bad only when within `EPS` of it too.
#[inline(never)]
fn edge_bits(c: &[[f64; 2]; 3], k: usize, l: usize, g: [f64; 2]) -> u8 {
    let (a, b) = (&c[k], &c[l]);
    let (at_k, at_l) = if *a == g {
        (true, below_eps(&g, b))
    } else if *b == g {
        (below_eps(&g, a), true)
    } else if let Some(p) = grid_point_near_segment(a, b) {
        (below_eps(&p, a), below_eps(&p, b))
    } else {
        return 0;
    };
    u8::from(at_k || !at_l) << k | u8::from(at_l || !at_k) << l
}

/// [`tri_mask`] of a triangle that spans both axes, `small` as
/// [`spanned_axes_small`] finds: the corners' boxes, then the edges.
///
/// Out of line: its many live values (spilled to the stack) and saved
/// registers stay off the early answers, about half the triangles.
#[inline(never)]
fn both_axes_mask(c: &[[f64; 2]; 3], known: u8, small: bool) -> u8 {
    let boxes = Boxes::of_known(c, small);
    let mut mask = boxes.near_any(c);
    for k in 0..3 {
        let l = (k + 1) % 3;
        // both ends already bad: the edge cannot add a bit
        let ends = 1 << k | 1 << l;
        if (mask | known) & ends == ends || boxes.spans(k, l) != 0b11 {
            continue;
        }
        // the integer range of the edge's grown box per axis
        let range = boxes.range(k, l);
        let (lo, hi) = (range.map(|r| r[0]), range.map(|r| r[1]));
        if segment_clear_of_grid(&c[k], &c[l], lo, hi) {
            continue;
        }
        if let Some(g) = grid_point_near_segment(&c[k], &c[l]) {
            let (at_k, at_l) = (below_eps(&g, &c[k]), below_eps(&g, &c[l]));
            mask |= u8::from(at_k || !at_l) << k | u8::from(at_l || !at_k) << l;
        }
    }
    partial(mask, known)
}
