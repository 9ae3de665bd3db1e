//! The tests of [`crate::grid`]: the rounding and closeness helpers bit for
//! bit against `std`, the box tests against their references.

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
        if x.abs() < FAST {
            let r = dualex_util::round::round_small(x);
            assert_eq!(r.to_bits(), x.round().to_bits(), "round_small {x:e}");
        }
        assert_eq!(ceil(x).to_bits(), x.ceil().to_bits(), "ceil {x:e}");
        assert_eq!(floor(x).to_bits(), x.floor().to_bits(), "floor {x:e}");
        assert_eq!(near_int(x), (x - x.round()).abs() < EPS, "near {x:e}");
        if x.abs() < FAST {
            assert_eq!(near_int_small(x), near_int(x), "near_int_small {x:e}");
        }
        if x.abs() < 0.5 * FAST {
            let (got, want) = (floor_above_small(x), floor_above(x));
            assert_eq!(got.to_bits(), want.to_bits(), "floor_above_small {x:e}");
        }
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
