//! Whether a 2D segment certainly passes through a grid point at neither
//! of its ends, for the edge tests of the sanitization scan (both
//! dimensions; in 3D per axis pair): a cheap stand-in for
//! [`grid_point_near_segment`] and the distances of its point to the ends,
//! for edges that [`segment_clear_of_grid`] did not clear.
//!
//! Input: the segment `a`–`b` and the integers `lo[k]..=hi[k]` of its box,
//! grown by `2·EPS`, per axis `k`. Output: `true` only when
//! [`grid_point_near_segment`] returns a point farther than `EPS` from
//! both ends; `false` when unsure. Invariant: every bound keeps a margin
//! far above the rounding errors (below `1e-12` for coordinates under
//! 1024; larger ones are `false`).

use crate::grid::EPS;
#[cfg(doc)]
use crate::grid::{grid_point_near_segment, segment_clear_of_grid};
use dualex_util::round::nearest_even;

/// Coordinates below this magnitude keep the rounding errors below
/// `1e-12` (as in [`segment_clear_of_grid`]).
const SMALL: f64 = 1024.0;

/// Whether [`grid_point_near_segment`] certainly returns `Some(g)` for
/// `a`–`b` with `g` farther than `EPS` from `a` and from `b`.
///
/// Some integer point `g` of the box (at most 4) lies within `EPS / 2` of
/// the segment's line and projects between its ends: then `g` is within
/// `EPS / 2` of the segment, and [`grid_point_near_segment`], walking the
/// integers of the segment's range on each axis, meets `g` on the axis
/// along which the segment is longer (the segment's point there is within
/// `0.71·EPS` of `g`, so rounds to it) and accepts it, if it did not stop
/// earlier. Each end is farther than `1.5·EPS` from every integer on some
/// axis ([`off_grid_point`]), so from every grid point: whichever point it
/// returns is at neither end.
///
/// Out of line: it runs only where the clear test fails, and inlined it
/// slowed the scan's hot loop.
#[inline(never)]
pub fn segment_through_grid(a: &[f64; 2], b: &[f64; 2], lo: [f64; 2], hi: [f64; 2]) -> bool {
    if !(a[0].abs() < SMALL && a[1].abs() < SMALL && b[0].abs() < SMALL && b[1].abs() < SMALL) {
        return false;
    }
    if !off_grid_point(a) || !off_grid_point(b) {
        return false;
    }
    if (hi[0] - lo[0] + 1.0) * (hi[1] - lo[1] + 1.0) > 4.0 {
        return false;
    }
    let d = [b[0] - a[0], b[1] - a[1]];
    let l2 = d[0] * d[0] + d[1] * d[1];
    // not NaN: the coordinates are small
    if l2 <= 1e-200 {
        return false;
    }
    let lim = 0.25 * EPS * EPS * l2;
    let mut gx = lo[0];
    while gx <= hi[0] {
        let mut gy = lo[1];
        while gy <= hi[1] {
            let cr = d[0] * (gy - a[1]) - d[1] * (gx - a[0]);
            let s = d[0] * (gx - a[0]) + d[1] * (gy - a[1]);
            if cr * cr <= lim && 0.0 <= s && s <= l2 {
                return true;
            }
            gy += 1.0;
        }
        gx += 1.0;
    }
    false
}

/// Whether `p` (coordinates under 1024) is farther than `1.5·EPS` from
/// every integer on some axis: then no grid point is within `EPS` of it.
#[inline]
fn off_grid_point(p: &[f64; 2]) -> bool {
    (p[0] - nearest_even(p[0])).abs() > 1.5 * EPS || (p[1] - nearest_even(p[1])).abs() > 1.5 * EPS
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::grid::{box_bounds, dist2d_below_eps, grid_point_near_segment};
    use dualex_util::rng::SplitMix;

    /// On segments through, next to and ending at (or next to) grid
    /// points, short and long, near and far from the origin: whenever
    /// [`segment_through_grid`] holds, [`grid_point_near_segment`] finds
    /// a point at neither end; it holds often.
    #[test]
    fn through_agrees_with_the_exact_test() {
        let mut rng = SplitMix::new(41);
        let mut through = 0;
        for k in 0..300000 {
            let shift = [0.0, 0.0, -7.0, 1000.0, 1023.5, 5000.0][k % 6];
            let g = [0, 1].map(|_| (rng.unit() * 8.0 - 4.0).floor() + shift);
            let dir = std::f64::consts::TAU * rng.unit();
            let (u, v) = (dir.cos(), dir.sin());
            let off_line = EPS * [0.0, 0.3, 0.5, 0.6, 1.0, 3.0, 4.0][k % 7] * rng.unit();
            let len = [1e-9, 1e-6, 0.3, 1.0, 2.5][k % 5];
            let (s0, s1) = (-len * rng.unit(), len * rng.unit());
            // an end at, or a few EPS from, the grid point
            let s0 = match k % 13 {
                0 => 0.0,
                1 => -EPS * (4.0 * rng.unit()),
                _ => s0,
            };
            let p = |t: f64| [g[0] + t * u - off_line * v, g[1] + t * v + off_line * u];
            let (a, b) = (p(s0), p(s1));
            let lo = [0, 1].map(|x| box_bounds(a[x])[0].min(box_bounds(b[x])[0]));
            let hi = [0, 1].map(|x| box_bounds(a[x])[1].max(box_bounds(b[x])[1]));
            if segment_through_grid(&a, &b, lo, hi) {
                let q = grid_point_near_segment(&a, &b).expect("a grid point");
                assert!(!dist2d_below_eps(&q, &a), "{a:?} {b:?}");
                assert!(!dist2d_below_eps(&q, &b), "{a:?} {b:?}");
                through += 1;
            }
        }
        assert!(through > 50000, "{through}");
    }
}
