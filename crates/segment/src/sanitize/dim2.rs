//! Sanitization at D = 2 ([`Dim<3, 2>`]): the triangle test of the scan,
//! the random step, the kinds of the singular vertices left on isos.

use super::{Dim, Predicates};
use crate::bad_scan::{partial, PARTIAL};
use crate::boxes::Boxes;
use crate::grid::{
    dist2d_below_eps as below_eps, grid_point_near_segment, near_int, near_int_on,
    segment_clear_of_grid, spanned_axes_small,
};
use crate::local::LocalMap;
use dualex_map::{Stars, Topology};
use dualex_util::rng::SplitMix;
use std::collections::BTreeMap;

/// Every corner of a triangle bad.
const FULL: u8 = 0b111;

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
///
/// Out of line: one copy for both scans (two inlined copies made the
/// compiler call the boxes' helpers instead of inlining them).
#[inline(never)]
fn tri_mask(c: &[[f64; 2]; 3], known: u8) -> u8 {
    if known == FULL {
        return PARTIAL;
    }
    let (axes, small) = spanned_axes_small(c);
    if axes != 0b11 {
        return if axes == 0 {
            0
        } else {
            near_int_on(c, axes.trailing_zeros() as usize)
        };
    }
    both_axes_mask(c, known, small)
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
