//! Sanitization at D = 3 ([`Dim<4, 3>`]): the tet test of the scan (with
//! the predicates of [`crate::near`]) and the random step; no kinds of
//! singular vertices (the 3D report counts them only).

use super::{Dim, Predicates};
use crate::bad_scan::{partial, PARTIAL};
use crate::boxes::Boxes;
use crate::grid::{near_int_on, spanned_axes_small};
use crate::near::{
    face_corners, segment_near_iso_line_in_box, triangle_clear_of_grid, triangle_near_grid_point,
    EDGES, FACE_EDGES,
};
use dualex_util::rng::SplitMix;

/// Every corner of a tet bad.
const FULL: u8 = 0b1111;

impl Predicates<4, 3> for Dim<4, 3> {
    const MIN_TASK: usize = 512;
    const COUNT_ROUND_PAST_SCHEDULE: bool = false;

    /// The tests of [`crate::near::bad_vertices`]; edges whose box holds
    /// an integer on fewer than two axes, and faces whose box misses one,
    /// are skipped: they cannot be near an iso-line or a grid point.
    ///
    /// A face whose box holds one integer point far from its plane is
    /// skipped too ([`triangle_clear_of_grid`]: the exact test would skip
    /// that point, and no other can be near the face).
    ///
    /// A test that can only set bits already set is skipped (an edge
    /// whose ends, a face whose corners are already bad; everything once
    /// all four are): the mask is the same.
    ///
    /// A tet whose range spans at most one axis ([`crate::grid::spanned_axes`]: then
    /// no edge spans two, no face three) makes bad only its corners on
    /// that axis' isos. The boxes of the corners are computed once
    /// ([`Boxes`]).
    fn mask(c: &[[f64; 3]; 4]) -> u8 {
        tet_mask(c, 0)
    }

    fn mask_known(c: &[[f64; 3]; 4], known: u8) -> u8 {
        tet_mask(c, known)
    }

    fn step(rng: &mut SplitMix, amp: f64) -> [f64; 3] {
        rng.direction().map(|x| x * amp)
    }
}

/// [`Predicates::mask`] at D = 3, given the corners `known` to be bad
/// already ([`Predicates::mask_known`]: a test is skipped when the bits it
/// can set are all in the mask so far or in `known`; a result that may
/// miss a bit of `known` carries [`PARTIAL`]). With `known = 0`, the mask.
///
/// Out of line: one copy for both scans (two inlined copies made the
/// compiler call the boxes' helpers instead of inlining them).
#[inline(never)]
fn tet_mask(c: &[[f64; 3]; 4], known: u8) -> u8 {
    if known == FULL {
        return PARTIAL;
    }
    let (axes, small) = spanned_axes_small(c);
    if axes & axes.wrapping_sub(1) == 0 {
        return if axes == 0 {
            0
        } else {
            near_int_on(c, axes.trailing_zeros() as usize)
        };
    }
    // the other axis (if any): no corner on its isos, no span, empty
    // edge ranges
    let boxes = Boxes::of_known(c, small);
    let mut mask = boxes.near_any(c);
    if mask | known == FULL {
        return partial(mask, known);
    }
    let span = boxes.edge_spans(&EDGES);
    for (&[k, l], &bits) in EDGES.iter().zip(&span) {
        // fewer than two axes, or both ends already bad
        let ends = 1 << k | 1 << l;
        if bits & bits.wrapping_sub(1) == 0 || (mask | known) & ends == ends {
            continue;
        }
        let range = boxes.range(k, l);
        if let Some((at_k, at_l)) = segment_near_iso_line_in_box(&c[k], &c[l], &range) {
            mask |= u8::from(at_k || !at_l) << k | u8::from(at_l || !at_k) << l;
        }
    }
    if axes != 0b111 || mask | known == FULL {
        return partial(mask, known);
    }
    for (f, [e0, e1, e2]) in FACE_EDGES.into_iter().enumerate() {
        // the face's corners are all but corner `f`
        let corners = FULL & !(1 << f);
        if span[e0] | span[e1] | span[e2] != 0b111 || (mask | known) & corners == corners {
            continue;
        }
        let [i, j, k] = face_corners(f);
        let t = [c[i], c[j], c[k]];
        let (r, q) = (boxes.range(i, j), boxes.range(i, k));
        let (mut lo, mut hi) = ([0.0; 3], [0.0; 3]);
        for a in 0..3 {
            lo[a] = if q[a][0] < r[a][0] { q[a][0] } else { r[a][0] };
            hi[a] = if q[a][1] > r[a][1] { q[a][1] } else { r[a][1] };
        }
        if triangle_clear_of_grid(&t, lo, hi) {
            continue;
        }
        if triangle_near_grid_point(&t) {
            mask |= 1 << i | 1 << j | 1 << k;
        }
    }
    partial(mask, known)
}
