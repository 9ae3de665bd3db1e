//! Sanitization at D = 3 ([`Dim<4, 3>`]): the tet test of the scan (with
//! the predicates of [`crate::near`]) and the random step; no kinds of
//! singular vertices (the 3D report counts them only).

use super::{Dim, Predicates};
use crate::bad_scan::{partial, PARTIAL};
use crate::boxes::Boxes;
#[cfg(doc)]
use crate::grid::segment_clear_of_grid;
use crate::grid::{near_int_on, point_near_line, spanned_axes_small};
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
    /// ([`Boxes`]). When the tet's box holds one integer on each axis it
    /// spans ([`single_point`]: a tet smaller than a grid cell, the usual
    /// case), the edges' and faces' prefilters test that point at once,
    /// without their own ranges (the same tests of the same point).
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
    let single = single_point(&boxes, axes);
    for (&[k, l], &bits) in EDGES.iter().zip(&span) {
        // fewer than two axes, or both ends already bad
        let ends = 1 << k | 1 << l;
        if bits & bits.wrapping_sub(1) == 0 || (mask | known) & ends == ends {
            continue;
        }
        if single.is_some_and(|g| edge_clear_at(&c[k], &c[l], &g, bits)) {
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
        let ijk = face_corners(f);
        let t = ijk.map(|i| c[i]);
        if face_clear_of_grid(&t, ijk, &boxes, single) {
            continue;
        }
        if triangle_near_grid_point(&t) {
            mask |= ijk.iter().fold(0, |m, &i| m | 1 << i);
        }
    }
    partial(mask, known)
}

/// The integer point of the tet's box (its corners' ranges grown by
/// `2·EPS`, [`Boxes`]) when the box holds exactly one integer on every
/// axis of `axes` (the axes it spans, [`spanned_axes_small`]: none on the
/// others), each within `±1022`; else `None`.
///
/// Then every edge's or face's box holds that point on an axis or no
/// integer there, and every coordinate on the axes of `axes` is below 1024
/// in magnitude (a corner's `hi` is the point or one less): the bound
/// under which [`segment_clear_of_grid`] and [`triangle_clear_of_grid`]
/// decide.
#[inline(always)]
fn single_point(boxes: &Boxes<4, 3>, axes: u8) -> Option<[f64; 3]> {
    let (mut g, mut one) = ([0.0; 3], true);
    for (a, g) in g.iter_mut().enumerate() {
        let (mut lo, mut hi) = (f64::INFINITY, f64::NEG_INFINITY);
        for (h, near) in boxes.hi.iter().zip(&boxes.near) {
            // `ceil(x − 2·EPS)`: `hi` when near, else `hi + 1`
            let l = h[a] + f64::from(near >> a & 1 ^ 1);
            lo = if l < lo { l } else { lo };
            hi = if h[a] > hi { h[a] } else { hi };
        }
        *g = hi;
        one &= axes >> a & 1 == 0 || (lo == hi && hi.abs() <= 1022.0);
    }
    one.then_some(g)
}

/// Whether [`segment_clear_of_grid`] clears the segment `a`–`b` on every
/// axis pair of `bits` (the axes on which its box holds an integer), when
/// that box holds only the point `g` there ([`single_point`]): the same
/// test of the same point, computed the same way.
#[inline(always)]
fn edge_clear_at(a: &[f64; 3], b: &[f64; 3], g: &[f64; 3], bits: u8) -> bool {
    for [i, j] in [[0, 1], [0, 2], [1, 2]] {
        if bits >> i & 1 == 0 || bits >> j & 1 == 0 {
            continue;
        }
        if point_near_line(&[a[i], a[j]], &[b[i], b[j]], &[g[i], g[j]]) {
            return false;
        }
    }
    true
}

/// [`triangle_clear_of_grid`] of the tet's face with corners `ijk`
/// (`t`), given that its edges span every axis: its box is the tet's one
/// point when there is one ([`single_point`]: the face's box holds it and
/// nothing else), else the union of the ranges of two of its edges.
#[inline(always)]
fn face_clear_of_grid(
    t: &[[f64; 3]; 3],
    [i, j, k]: [usize; 3],
    boxes: &Boxes<4, 3>,
    single: Option<[f64; 3]>,
) -> bool {
    if let Some(g) = single {
        return triangle_clear_of_grid(t, g, g);
    }
    let (r, q) = (boxes.range(i, j), boxes.range(i, k));
    let (mut lo, mut hi) = ([0.0; 3], [0.0; 3]);
    for a in 0..3 {
        lo[a] = if q[a][0] < r[a][0] { q[a][0] } else { r[a][0] };
        hi[a] = if q[a][1] > r[a][1] { q[a][1] } else { r[a][1] };
    }
    triangle_clear_of_grid(t, lo, hi)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::{box_bounds, spanned_axes, EPS};
    use dualex_util::rng::SplitMix;

    /// [`single_point`] is the one integer of the tet's box on each
    /// spanned axis (by [`box_bounds`] of every coordinate), whenever there
    /// is one and it is within ±1022; on tets of every size, near and far
    /// from the grid, and near the ±1024 bound.
    #[test]
    fn single_point_is_the_box_s_one_integer() {
        let mut rng = SplitMix::new(37);
        let mut found = 0usize;
        for n in 0..200000 {
            let size = [1e-9, 1e-3, 0.05, 0.3, 0.9, 1.5][n % 6];
            let base = [0.0, 0.5, -3.0, 1021.3, -1022.6, 5e6][n / 6 % 6];
            let g: [f64; 3] = std::array::from_fn(|_| base + (rng.unit() * 6.0 - 3.0).floor());
            let c: [[f64; 3]; 4] = std::array::from_fn(|_| {
                std::array::from_fn(|a| {
                    let x = g[a] + size * (rng.unit() - 0.5);
                    if rng.unit() < 0.1 {
                        x.round() + [0.0, EPS, -2.0 * EPS, 3.0 * EPS][n % 4]
                    } else {
                        x
                    }
                })
            });
            let axes = spanned_axes(&c);
            let want = (0..3).try_fold([0.0; 3], |mut p, a| {
                let lo = c
                    .iter()
                    .map(|q| box_bounds(q[a])[0])
                    .fold(f64::INFINITY, f64::min);
                let hi = c
                    .iter()
                    .map(|q| box_bounds(q[a])[1])
                    .fold(f64::NEG_INFINITY, f64::max);
                p[a] = hi;
                let one = axes >> a & 1 == 0 || (lo == hi && hi.abs() <= 1022.0);
                one.then_some(p)
            });
            let got = single_point(&Boxes::of(&c), axes);
            let on_axes = |p: [f64; 3]| {
                (0..3)
                    .map(|a| (axes >> a & 1) as f64 * p[a])
                    .collect::<Vec<_>>()
            };
            assert_eq!(got.map(on_axes), want.map(on_axes), "{c:?}");
            found += usize::from(got.is_some() && axes.count_ones() >= 2);
        }
        assert!(found > 20000, "{found}");
    }
}
