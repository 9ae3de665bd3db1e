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
        // `x − nearest_even(x)` is exact and equals `x − x.round()` but at
        // ties, where both are ±½
        (x - nearest_even(x)).abs() < EPS
    } else {
        (x - x.round()).abs() < EPS
    }
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
    let z = x + 2.0 * EPS;
    if x.abs() < 0.5 * FAST {
        let rz = nearest_even(z);
        if rz > z {
            rz - 1.0
        } else {
            rz
        }
    } else {
        z.floor()
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
pub(crate) mod tests {
    use super::*;
    use crate::boxes::Boxes;

    #[test]
    fn segments_through_grid_points() {
        assert!(grid_point_near_segment(&[0.5, 0.5], &[1.5, 1.5]).is_some());
        assert!(grid_point_near_segment(&[0.5, 0.6], &[1.5, 1.7]).is_none());
        assert!(grid_point_near_segment(&[2.0, 0.3], &[2.0, 0.3]).is_none());
        let g = grid_point_near_segment(&[3.0, -1.5], &[3.0, 1.5]).expect("on the segment");
        assert!(g[0] == 3.0 && [-1.0, 0.0, 1.0].contains(&g[1]), "{g:?}");
        assert!(grid_point_near_segment(&[4.0, 4.0], &[4.0, 4.0]).is_some());
        assert!(near_int(2.0 + 0.5 * EPS) && !near_int(2.0 + 2.0 * EPS));
    }

    /// Values around every kind of boundary of the rounding functions:
    /// integers, ties, either side of them by one ulp, signed zeros,
    /// magnitudes around 2^51 / 2^52 / 2^53, infinities and NaN.
    fn probes() -> Vec<f64> {
        let mut out = vec![0.0, -0.0, f64::INFINITY, f64::NEG_INFINITY, f64::NAN];
        out.extend([f64::MIN_POSITIVE, 5e-324, f64::MAX, f64::EPSILON]);
        let mut base: Vec<f64> = (-40..=40).map(|k| f64::from(k) * 0.25).collect();
        base.extend([0.1, 0.3, 0.7, 1e-9, 2e-9, 1e-12, 123.456, 1e6 + 0.5]);
        for e in [49, 50, 51, 52, 53, 54] {
            let p = 2f64.powi(e);
            base.extend([p, p + 0.5, p - 0.5, p + 1.0, p - 1.0, p + 1.5]);
        }
        for x in base {
            for y in [x, -x] {
                out.extend([y, f64::from_bits(y.to_bits() + 1)]);
                if y.to_bits() > 0 {
                    out.push(f64::from_bits(y.to_bits() - 1));
                }
            }
        }
        let mut z = 0x9e37_79b9_7f4a_7c15_u64;
        for _ in 0..20000 {
            z = z
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            let u = (z >> 11) as f64 / (1u64 << 53) as f64;
            out.push((u - 0.5) * 2f64.powi((z % 60) as i32));
        }
        out
    }

    /// [`box_bounds`] (one rounding) equals `ceil` and `floor` of the
    /// grown range, as values, on probes and next to integers.
    #[test]
    fn box_bounds_equal_ceil_floor() {
        let mut vals = probes();
        for k in -4..=4 {
            for n in [-2.0, 0.0, 1.0, 7.0, 1e6, 2f64.powi(50)] {
                vals.push(n + f64::from(k) * EPS);
                vals.push(n + f64::from(k) * 0.5 * EPS);
            }
        }
        for x in vals.into_iter().filter(|x| !x.is_nan()) {
            let want = [(x - 2.0 * EPS).ceil(), (x + 2.0 * EPS).floor()];
            assert_eq!(box_bounds(x), want, "{x:e}");
        }
    }

    #[test]
    fn rounding_is_bit_identical_to_std() {
        for x in probes() {
            assert_eq!(round(x).to_bits(), x.round().to_bits(), "round {x:e}");
            assert_eq!(ceil(x).to_bits(), x.ceil().to_bits(), "ceil {x:e}");
            assert_eq!(floor(x).to_bits(), x.floor().to_bits(), "floor {x:e}");
            assert_eq!(near_int(x), (x - x.round()).abs() < EPS, "near {x:e}");
            let y = x + 0.5 * EPS;
            assert_eq!(near_int(y), (y - y.round()).abs() < EPS, "near {y:e}");
        }
    }

    /// [`box_spans`] equals its reference on pairs of probes, and on
    /// pairs within a few `EPS` of integers.
    #[test]
    fn box_test_equals_reference() {
        let reference = |x: f64, y: f64| (x.min(y) - 2.0 * EPS).ceil() <= x.max(y) + 2.0 * EPS;
        let mut vals: Vec<f64> = probes().into_iter().filter(|x| !x.is_nan()).collect();
        for k in -3..=3 {
            for n in [-2.0, 0.0, 1.0, 7.0, 1e6] {
                vals.push(n + f64::from(k) * EPS);
                vals.push(n + 0.5 + f64::from(k) * EPS);
            }
        }
        for (i, &x) in vals.iter().enumerate() {
            let step = 1 + i % 13;
            for &y in vals.iter().step_by(step) {
                let got = box_spans(box_bounds(x), box_bounds(y));
                assert_eq!(got, reference(x, y), "{x:e} {y:e}");
            }
        }
    }

    /// The probes without NaN, and values within a few `EPS` of integers
    /// and of ties.
    pub(crate) fn near_values() -> Vec<f64> {
        let mut vals: Vec<f64> = probes().into_iter().filter(|x| !x.is_nan()).collect();
        for k in -5..=5 {
            for n in [-3.0, 0.0, 1.0, 2.0, 1e6] {
                vals.push(n + f64::from(k) * EPS);
                vals.push(n + 0.5 + f64::from(k) * EPS);
            }
        }
        vals
    }

    /// A pseudo-random pick among `vals` per call (an LCG from `seed`).
    pub(crate) fn picker(vals: &[f64], seed: u64) -> impl FnMut() -> f64 + '_ {
        let mut z = seed;
        move || {
            z = z
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            vals[(z >> 33) as usize % vals.len()]
        }
    }

    /// Per axis, whether some pair of corners of `c` spans an integer by
    /// [`box_spans`] (the reference of [`spanned_axes`]).
    pub(crate) fn pairs<const N: usize, const D: usize>(c: &[[f64; D]; N]) -> u8 {
        let mut bits = 0u8;
        for k in 0..N {
            for l in k + 1..N {
                for (a, (&x, &y)) in c[k].iter().zip(&c[l]).enumerate() {
                    bits |= u8::from(box_spans(box_bounds(x), box_bounds(y))) << a;
                }
            }
        }
        bits
    }

    /// [`spanned_axes`] and [`Boxes::spanned`] equal "some pair spans" by
    /// [`box_spans`], on triangles and tets of probes and of values near
    /// integers and ties.
    #[test]
    fn spanned_axes_equal_pairs() {
        let vals = near_values();
        for &x in &vals {
            assert_eq!(near_int_in(x, box_bounds(x)), near_int(x), "{x:e}");
        }
        let mut pick = picker(&vals, 5);
        for _ in 0..100000 {
            let t: [[f64; 2]; 3] = std::array::from_fn(|_| [pick(), pick()]);
            assert_eq!(spanned_axes(&t), pairs(&t), "{t:?}");
            assert_eq!(Boxes::of(&t).spanned(), pairs(&t), "{t:?}");
            let t: [[f64; 3]; 4] = std::array::from_fn(|_| [pick(), pick(), pick()]);
            assert_eq!(spanned_axes(&t), pairs(&t), "{t:?}");
            assert_eq!(Boxes::of(&t).spanned(), pairs(&t), "{t:?}");
            let small = t.iter().flatten().all(|x| x.abs() < 0.5 * FAST);
            assert_eq!(spanned_axes_small(&t).1, small, "{t:?}");
            for a in 0..3 {
                let on = near_int_on(&t, a);
                assert!(on == 0 || spanned_axes(&t) >> a & 1 == 1, "{t:?}");
            }
        }
    }

    /// [`segment_clear_of_grid`] never hides a grid point that
    /// [`grid_point_near_segment`] finds, on segments through, next to and
    /// ending at grid points, and clears most segments away from them.
    #[test]
    fn clear_segments_have_no_grid_point() {
        let mut z = 11u64;
        let mut next = || {
            z = z
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (z >> 11) as f64 / (1u64 << 53) as f64
        };
        let (mut found, mut cleared) = (0, 0);
        for k in 0..200000 {
            let g = [(8.0 * next() - 4.0).round(), (8.0 * next() - 4.0).round()];
            let dir = std::f64::consts::TAU * next();
            let (u, v) = (dir.cos(), dir.sin());
            // offset from the grid point across the segment: 0 to 4 EPS
            let off = EPS * (4.0 * next()) * if k % 3 == 0 { 0.0 } else { 1.0 };
            let (s0, s1) = (-2.0 * next(), 2.0 * next());
            let (s0, s1) = if k % 5 == 0 { (0.0, s1) } else { (s0, s1) };
            let p = |t: f64| [g[0] + t * u - off * v, g[1] + t * v + off * u];
            let (a, b) = (p(s0), p(s1));
            let lo = [0, 1].map(|x| box_bounds(a[x])[0].min(box_bounds(b[x])[0]));
            let hi = [0, 1].map(|x| box_bounds(a[x])[1].max(box_bounds(b[x])[1]));
            let near = grid_point_near_segment(&a, &b).is_some();
            let clear = segment_clear_of_grid(&a, &b, lo, hi);
            assert!(!(near && clear), "{a:?} {b:?}");
            found += usize::from(near);
            cleared += usize::from(clear);
        }
        assert!(found > 50000 && cleared > 20000, "{found} {cleared}");
    }

    #[test]
    fn eps_comparison_is_identical_to_hypot() {
        let mut z = 7u64;
        let mut next = || {
            z = z
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            (z >> 11) as f64 / (1u64 << 53) as f64
        };
        for k in 0..200000 {
            // lengths spread around EPS, plus exact hits on it
            let r = EPS * (0.5 + next()) * if k % 7 == 0 { 1.0 } else { 2.0 * next() };
            let r = if k % 11 == 0 { EPS } else { r };
            let a = std::f64::consts::TAU * next();
            let (dx, dy) = (r * a.cos(), r * a.sin());
            assert_eq!(below_eps(dx, dy), dx.hypot(dy) < EPS, "{dx:e} {dy:e}");
        }
        for (dx, dy) in [
            (0.0, 0.0),
            (EPS, 0.0),
            (0.0, -EPS),
            (f64::NAN, 0.0),
            (1e300, 1e300),
        ] {
            assert_eq!(below_eps(dx, dy), dx.hypot(dy) < EPS, "{dx:e} {dy:e}");
        }
    }
}
