//! Closeness to the integer grid, shared by the sanitization of both
//! dimensions: values on an iso, 2D segments through a grid point.
//! Coordinates are local (see [`crate::local`]), so [`EPS`] is absolute.
//!
//! Input: local map coordinates. Output: predicates and nearest grid
//! points; nothing is stored. Invariant: hot loops of the whole crate (and
//! of the sanitizers) use the libm-free rounding of [`dualex_util::round`]
//! instead of `f64::round`, `ceil` and `floor`, and compare distances with
//! [`EPS`] without `hypot` unless the comparison is too close to call:
//! every function returns bit for bit what the `std` / `hypot` formulation
//! returns.

#[cfg(test)]
use dualex_util::round::floor;
use dualex_util::round::{ceil, nearest_even, round, FAST};

/// Distance below which a value counts as "on" an iso.
pub const EPS: f64 = 1e-9;

/// Whether `x` is within [`EPS`] of an integer.
#[inline]
pub fn near_int(x: f64) -> bool {
    if x.abs() < FAST {
        near_int_small(x)
    } else {
        (x - x.round()).abs() < EPS
    }
}

/// [`near_int`] for `|x| <` [`FAST`] (the caller's check), without the
/// library call of the other values (a call in a hot loop makes the
/// compiler spill its values on the common path too).
#[inline(always)]
pub fn near_int_small(x: f64) -> bool {
    // `x − nearest_even(x)` is exact and equals `x − x.round()` but at
    // ties, where both are ±½
    (x - nearest_even(x)).abs() < EPS
}

/// [`near_int`] of `x` given its [`box_bounds`] `b`: an `x` within `EPS`
/// of an integer `n` has `x − 2·EPS < n < x + 2·EPS`, so (the rounding of
/// the two sums being monotone) `n` lies in `b`; an empty `b` (the usual
/// case) answers without rounding `x` again.
#[inline]
pub fn near_int_in(x: f64, b: [f64; 2]) -> bool {
    b[0] <= b[1] && near_int(x)
}

/// `floor(x + 2·EPS)` up to the sign of zero: the greatest integer that
/// `x`'s range grown by `2·EPS` can hold (the `hi` of [`box_bounds`]).
#[inline]
pub fn floor_above(x: f64) -> f64 {
    if x.abs() < 0.5 * FAST {
        floor_above_small(x)
    } else {
        (x + 2.0 * EPS).floor()
    }
}

/// [`floor_above`] for `|x| < FAST/2` (the caller's check), without the
/// library call of the other values (see [`near_int_small`]).
#[inline(always)]
pub fn floor_above_small(x: f64) -> f64 {
    let z = x + 2.0 * EPS;
    let rz = nearest_even(z);
    if rz > z {
        rz - 1.0
    } else {
        rz
    }
}

/// `[ceil(x − 2·EPS), floor(x + 2·EPS)]` up to the sign of zero: the
/// integer bounds of `x`'s range grown by `2·EPS`, for [`box_spans`].
///
/// One rounding: with `hi` = [`floor_above`], the range (narrower than 1)
/// holds at most the integer `hi`, so `ceil(x − 2·EPS)` is `hi` when
/// `x − 2·EPS ≤ hi` and `hi + 1` otherwise.
#[inline]
pub fn box_bounds(x: f64) -> [f64; 2] {
    let (y, hi) = (x - 2.0 * EPS, floor_above(x));
    [if y > hi { hi + 1.0 } else { hi }, hi]
}

/// Whether the range of two values (their [`box_bounds`] `p`, `q`), grown
/// by `2·EPS`, holds an integer: `ceil(min − 2·EPS) ≤ max + 2·EPS` for
/// values that are not NaN. Ceil and floor commute with min and max, so
/// that is `min lo ≤ max hi`, and as `lo` and `hi` are both monotone in
/// the value, `lo_p ≤ hi_q ∨ lo_q ≤ hi_p`. A triangle's range holds an
/// integer iff one of its edges' does (its least and greatest values
/// belong to one edge).
#[inline]
pub fn box_spans(p: [f64; 2], q: [f64; 2]) -> bool {
    p[0] <= q[1] || q[0] <= p[1]
}

/// Per axis `a` of a simplex's corners `c`, bit `a` set when
/// [`box_spans`] holds for some pair of its corners on that axis (for a
/// simplex, some edge), from the least and greatest value alone: `lo` and
/// `hi` of [`box_bounds`] are monotone, so the pairs' `lo_p ≤ hi_q` holds
/// for some pair iff `lo(min) ≤ hi(max)` (a corner with `lo ≤ hi` spans
/// with every other corner; at least two corners), that is (`hi` being an
/// integer) `min − 2·EPS ≤ hi(max)`: one rounding per axis. A corner
/// [`near_int`] on axis `a` sets the bit. Not NaN (validated input); a
/// NaN first corner sets every bit (the caller then tests everything).
#[inline]
pub fn spanned_axes<const N: usize, const D: usize>(c: &[[f64; D]; N]) -> u8 {
    spanned_axes_small(c).0
}

/// [`spanned_axes`], and whether every coordinate of `c` lies strictly
/// between `−FAST / 2` and `FAST / 2` (from the least and greatest value
/// per axis): the `small` of [`crate::boxes::Boxes::of_known`]. A NaN
/// (not in validated input) may pass unseen; its boxes are the same on
/// both paths (NaN, not near).
#[inline]
pub fn spanned_axes_small<const N: usize, const D: usize>(c: &[[f64; D]; N]) -> (u8, bool) {
    let (mut bits, mut small) = (0u8, true);
    for a in 0..D {
        let (lo, hi) = axis_range(c, a);
        small &= -0.5 * FAST < lo && hi < 0.5 * FAST;
        let (l, h) = (lo - 2.0 * EPS, floor_above(hi));
        bits |= u8::from(l.partial_cmp(&h) != Some(std::cmp::Ordering::Greater)) << a;
    }
    (bits, small)
}

/// The least and greatest value of the corners `c` on axis `a` (not NaN:
/// validated input; plain comparisons, cheaper than `f64::min`).
#[inline(always)]
pub fn axis_range<const N: usize, const D: usize>(c: &[[f64; D]; N], a: usize) -> (f64, f64) {
    let (mut lo, mut hi) = (c[0][a], c[0][a]);
    for p in &c[1..] {
        let x = p[a];
        lo = if x < lo { x } else { lo };
        hi = if x > hi { x } else { hi };
    }
    (lo, hi)
}

/// The corners of `c` [`near_int`] on axis `a`, as a mask (bit `k`: corner
/// `k`); for a simplex that spans at most that axis ([`spanned_axes`]),
/// the whole of what it makes bad.
#[inline]
pub fn near_int_on<const N: usize, const D: usize>(c: &[[f64; D]; N], a: usize) -> u8 {
    let mut mask = 0u8;
    for (k, p) in c.iter().enumerate() {
        mask |= u8::from(near_int(p[a])) << k;
    }
    mask
}

/// [`near_int_on`] for corners below [`FAST`] on axis `a` (the caller's
/// check), by [`near_int_small`].
#[inline(always)]
pub fn near_int_on_small<const N: usize, const D: usize>(c: &[[f64; D]; N], a: usize) -> u8 {
    let mut mask = 0u8;
    for (k, p) in c.iter().enumerate() {
        mask |= u8::from(near_int_small(p[a])) << k;
    }
    mask
}

/// Whether [`grid_point_near_segment`] certainly returns `None` for the
/// segment `a`–`b`, whose box holds the integers `lo[k]..=hi[k]` on axis
/// `k` (from [`box_bounds`] of its ends, grown by `2·EPS`: any grid point
/// it finds is one of them). True when every such point is farther than
/// `3·EPS` from the segment's line by the cross product; the rounding
/// errors of that test and of the distance computed by
/// [`grid_point_near_segment`] are below `1e-12` for coordinates under
/// 1024, far from the `2·EPS` margin. `false` when unsure (larger
/// coordinates, more than 4 points, a degenerate segment).
#[inline]
pub fn segment_clear_of_grid(a: &[f64; 2], b: &[f64; 2], lo: [f64; 2], hi: [f64; 2]) -> bool {
    const SMALL: f64 = 1024.0;
    if !(a[0].abs() < SMALL && a[1].abs() < SMALL && b[0].abs() < SMALL && b[1].abs() < SMALL) {
        return false;
    }
    if hi[0] < lo[0] || hi[1] < lo[1] {
        return true;
    }
    if (hi[0] - lo[0] + 1.0) * (hi[1] - lo[1] + 1.0) > 4.0 {
        return false;
    }
    let mut gx = lo[0];
    while gx <= hi[0] {
        let mut gy = lo[1];
        while gy <= hi[1] {
            if point_near_line(a, b, &[gx, gy]) {
                return false;
            }
            gy += 1.0;
        }
        gx += 1.0;
    }
    true
}

/// Whether point `g` is within `3·EPS` of the line through `a` and `b` by
/// the cross product: [`segment_clear_of_grid`]'s test of one grid point,
/// shared by the sanitization's shortcuts that test one point alone (the
/// same operations in the same order, so the same answer).
#[inline(always)]
pub fn point_near_line(a: &[f64; 2], b: &[f64; 2], g: &[f64; 2]) -> bool {
    let d = [b[0] - a[0], b[1] - a[1]];
    let lim = 9.0 * EPS * EPS * (d[0] * d[0] + d[1] * d[1]);
    let cr = d[0] * (g[1] - a[1]) - d[1] * (g[0] - a[0]);
    cr * cr <= lim
}

/// Distance between two points of the plane.
pub fn dist2d(a: &[f64; 2], b: &[f64; 2]) -> f64 {
    (a[0] - b[0]).hypot(a[1] - b[1])
}

/// `dist2d(a, b) < EPS`, without `hypot` unless the comparison is too close
/// to call from the squared distance (which is within a few ulps of exact:
/// a relative margin of 1e-6 decides every other case exactly).
#[inline]
pub fn dist2d_below_eps(a: &[f64; 2], b: &[f64; 2]) -> bool {
    below_eps(a[0] - b[0], a[1] - b[1])
}

/// `dx.hypot(dy) < EPS` (see [`dist2d_below_eps`]).
#[inline]
fn below_eps(dx: f64, dy: f64) -> bool {
    const LO2: f64 = EPS * EPS * (1.0 - 1e-6);
    const HI2: f64 = EPS * EPS * (1.0 + 1e-6);
    let s = dx * dx + dy * dy;
    if s < LO2 {
        true
    } else if s > HI2 {
        false
    } else {
        dx.hypot(dy) < EPS
    }
}

/// The point of segment `a`–`b` nearest to `p`.
#[inline]
fn nearest_on_segment(p: &[f64; 2], a: &[f64; 2], b: &[f64; 2]) -> [f64; 2] {
    let d = [b[0] - a[0], b[1] - a[1]];
    let l2 = d[0] * d[0] + d[1] * d[1];
    let t = if l2 == 0.0 {
        0.0
    } else {
        (((p[0] - a[0]) * d[0] + (p[1] - a[1]) * d[1]) / l2).clamp(0.0, 1.0)
    };
    [a[0] + t * d[0], a[1] + t * d[1]]
}

/// Distance from `p` to the segment `a`–`b`.
pub fn point_segment_dist(p: &[f64; 2], a: &[f64; 2], b: &[f64; 2]) -> f64 {
    dist2d(&nearest_on_segment(p, a, b), p)
}

/// `point_segment_dist(p, a, b) < EPS` (see [`dist2d_below_eps`]).
#[inline]
fn point_segment_below_eps(p: &[f64; 2], a: &[f64; 2], b: &[f64; 2]) -> bool {
    dist2d_below_eps(&nearest_on_segment(p, a, b), p)
}

/// An integer point within [`EPS`] of the segment `a`–`b`, if any: for each
/// axis, the integers in the segment's range on it, each with the nearest
/// integer on the other axis at that place (terminates: the loop runs over
/// the integers of a bounded range; callers bound map sizes up front).
pub fn grid_point_near_segment(a: &[f64; 2], b: &[f64; 2]) -> Option<[f64; 2]> {
    for axis in 0..2 {
        let o = 1 - axis;
        let (lo, hi) = (a[axis].min(b[axis]), a[axis].max(b[axis]));
        let len = b[axis] - a[axis];
        let mut i = ceil(lo - EPS);
        while i <= hi + EPS {
            let t = if len == 0.0 {
                0.0
            } else {
                ((i - a[axis]) / len).clamp(0.0, 1.0)
            };
            let mut g = [0.0; 2];
            g[axis] = i;
            g[o] = round(a[o] + t * (b[o] - a[o]));
            if point_segment_below_eps(&g, a, b) {
                return Some(g);
            }
            i += 1.0;
        }
    }
    None
}

#[cfg(test)]
#[path = "grid_tests.rs"]
pub(crate) mod tests;
