//! The one walk against the checks run one after the other: the same
//! answer, the same first error and the same counts, on every kind of
//! map (valid, folded, flat, reflected, mirrored, invalid anywhere, too
//! large, and at the bounds, where the sequential sums decide), for 1
//! and 3 threads.

use super::*;
use crate::mesh::{degenerate_bounded, degenerate_with, longest_edge};
use crate::singularity::{is_degenerate, quality};
use crate::test_maps::{grid, rechart, tet_cube};
use crate::transition_derive::ulp;
use dualex_util::rng::SplitMix;

/// The counts, or the error's debug text.
type Answer = Result<(usize, Option<usize>), String>;

/// `checked(m)` against the checks one after the other (`refuse`: the
/// dimension's last) and `quality`'s counts (`degenerate`: that one
/// too), on 1 and 3 threads; the answer.
fn same<const N: usize, const D: usize>(
    m: &SimplexMap<N, D>,
    what: &str,
    checked: impl Fn(&SimplexMap<N, D>) -> Result<InputCounts, InputError> + Sync,
    refuse: impl Fn(&SimplexMap<N, D>) -> Result<(), InputError>,
    degenerate: bool,
) -> Answer {
    let run = || {
        m.validate()?;
        m.check_grid_size()?;
        refuse(m)
    };
    let want = run().map_err(|e| format!("{e:?}")).map(|()| {
        let (r, d) = quality(m);
        (r, degenerate.then_some(d))
    });
    for threads in [1, 3] {
        let pool = rayon::ThreadPoolBuilder::new().num_threads(threads).build();
        let got = pool
            .unwrap_or_else(|e| panic!("{e}"))
            .install(|| checked(m));
        let got = got
            .map(|c| (c.reverted, c.degenerate))
            .map_err(|e| format!("{e:?}"));
        assert_eq!(got, want, "{what}, {threads} threads");
    }
    want
}

/// [`TriMap::checked`] against the checks in turn.
fn same_tri(m: &TriMap, what: &str) -> Answer {
    same(m, what, TriMap::checked, |_| Ok(()), false)
}

/// [`TetMap::checked`] against the checks in turn.
fn same_tet(m: &TetMap, what: &str) -> Answer {
    same(m, what, TetMap::checked, TetMap::check_not_reflected, true)
}

/// Asserts that `answer` is an error of kind `kind`.
fn refused(answer: Answer, kind: &str) {
    let e = answer
        .err()
        .unwrap_or_else(|| panic!("accepted, not {kind}"));
    assert!(e.contains(kind), "{e}");
}

/// Every corner's map moved by up to `amount` (a fold where it is large).
fn jitter<const N: usize, const D: usize>(m: &mut SimplexMap<N, D>, amount: f64, seed: u64) {
    let mut rng = SplitMix::new(seed);
    for x in m.coords.iter_mut().flatten().flatten() {
        *x += amount * (2.0 * rng.unit() - 1.0);
    }
}

/// Invalid maps: the first bad element in input order, whichever block
/// it falls in.
fn broken<const N: usize, const D: usize, T>(
    m: &SimplexMap<N, D>,
    same: impl Fn(&SimplexMap<N, D>, &str) -> T,
) {
    let n = m.len();
    for s in [0, 1, 4095, 4096, 5000, n - 1] {
        let mut b = m.clone();
        b.coords[s][N - 1][D - 1] = f64::NAN;
        same(&b, "NaN coordinate");
        b.simplices[n - 1][0] = m.positions.len() as u32;
        same(&b, "NaN, then an index out of range");
        let mut b = m.clone();
        b.simplices[s][1] = b.simplices[s][0];
        same(&b, "repeated vertex");
        b.coords[s / 2][0][0] = f64::INFINITY;
        same(&b, "an infinite coordinate first");
    }
    let mut b = m.clone();
    b.positions[3][1] = f64::NAN;
    b.coords[0][0][0] = f64::NAN;
    same(&b, "bad position before a bad simplex");
    let mut b = m.clone();
    b.coords.pop();
    same(&b, "counts differ");
    same(&SimplexMap::default(), "empty");
}

#[test]
fn triangle_maps_answer_as_the_checks_in_turn() {
    let m = grid(70); // 9800 triangles: 3 blocks
    assert_eq!(same_tri(&m, "identity"), Ok((0, None)));
    for (amount, seed, reverted) in [(0.1, 1, 0), (0.7, 2, 1086), (3.0, 3, 4547)] {
        let mut j = m.clone();
        jitter(&mut j, amount, seed);
        rechart(&mut j, seed);
        assert_eq!(same_tri(&j, "jittered"), Ok((reverted, None)));
    }
    broken(&m, same_tri);
    let mut big = m.clone();
    big.coords
        .iter_mut()
        .flatten()
        .flatten()
        .for_each(|x| *x *= 200.0);
    refused(same_tri(&big, "too large"), "TooLarge");
    big.coords[7000][1] = [1e300, -1e300];
    refused(same_tri(&big, "one huge triangle"), "TooLarge");
}

#[test]
fn tet_maps_answer_as_the_checks_in_turn() {
    let m = tet_cube(10); // 6000 tets: 2 blocks
    assert_eq!(same_tet(&m, "identity"), Ok((0, Some(0))));
    for (amount, seed, reverted) in [(0.1, 1, 0), (0.4, 2, 77), (0.8, 3, 1492), (5.0, 4, 2946)] {
        let mut j = m.clone();
        jitter(&mut j, amount, seed);
        rechart(&mut j, seed);
        // folded, up to half the tets
        assert_eq!(same_tet(&j, "jittered"), Ok((reverted, Some(0))));
    }
    // reflected charts, mirrored geometry, both
    let mirror = |p: &mut [f64; 3]| p[0] = -p[0];
    let mut r = m.clone();
    r.coords.iter_mut().flatten().for_each(mirror);
    refused(same_tet(&r, "reflected charts"), "Reflected");
    let mut g = m.clone();
    g.positions.iter_mut().for_each(mirror);
    refused(same_tet(&g, "mirrored geometry"), "Reflected");
    g.coords.iter_mut().flatten().for_each(mirror);
    assert_eq!(same_tet(&g, "both mirrored"), Ok((6000, Some(0))));
    // flat: the map of a slab collapsed, then that slab reflected
    let mut f = m.clone();
    for (s, c) in f.coords.iter_mut().enumerate() {
        if s % 3 == 0 {
            c.iter_mut().for_each(|p| p[2] = 0.0);
        }
    }
    assert_eq!(same_tet(&f, "a third flat"), Ok((0, Some(2000))));
    broken(&m, same_tet);
}

/// Maps at the bounds, where only the sequential sums can decide: the
/// grid points' total at the limit and just above it, exactly half the
/// volume reflected, and the geometric total zero.
#[test]
fn at_the_bounds_the_sequential_checks_decide() {
    // (2^14 - 1)(2^14 + 1) + 1 = 2^28 points, then one more
    let mut t = grid(1);
    t.coords = vec![[[0.0, 0.0], [16382.0, 0.0], [0.0, 16384.0]]; 2];
    t.coords[1] = [[0.0, 0.0], [0.0, 0.0], [0.0, 0.0]];
    assert_eq!(t.check_grid_size(), Ok(MAX_GRID_POINTS));
    assert_eq!(same_tri(&t, "at the limit"), Ok((0, None)));
    t.coords[1] = [[0.0, 0.0], [0.0, 0.0], [1.0, 0.0]];
    refused(same_tri(&t, "one point over the limit"), "TooLarge");
    let m = tet_cube(10);
    let mut half = m.clone();
    for (s, c) in half.coords.iter_mut().enumerate() {
        let x = (0..4)
            .map(|i| m.positions[m.simplices[s][i] as usize][0])
            .sum::<f64>();
        if x < 20.0 {
            c.iter_mut().for_each(|p| p[1] = -p[1]);
        }
    }
    refused(same_tet(&half, "half reflected"), "Reflected");
    // a mesh that is its own mirror image: total zero, either sign
    let mut twin = m.clone();
    let nv = m.positions.len() as u32;
    twin.positions
        .extend(m.positions.iter().map(|p| [-p[0] - 1.0, p[1], p[2]]));
    twin.simplices
        .extend(m.simplices.iter().map(|t| t.map(|v| v + nv)));
    twin.coords
        .extend(m.coords.iter().map(|c| c.map(|p| [-p[0], p[1], p[2]])));
    assert_eq!(same_tet(&twin, "a mirrored twin"), Ok((6000, Some(0))));
    twin.coords.iter_mut().flatten().for_each(|p| p[0] = -p[0]);
    refused(
        same_tet(&twin, "a mirrored twin, charts reflected"),
        "Reflected",
    );
}

/// [`is_degenerate`] as it was written before it shared its parts with
/// the walk: the longest edge as the largest square root.
fn degenerate_before<const N: usize, const D: usize>(p: &[[f64; D]; N]) -> bool {
    let (mut len, mut scale) = (0.0f64, 0.0f64);
    for i in 0..N {
        scale = p[i].iter().fold(scale, |acc, x| acc.max(x.abs()));
        for j in i + 1..N {
            let d2: f64 = (0..D).map(|k| (p[j][k] - p[i][k]).powi(2)).sum();
            len = len.max(d2.sqrt());
        }
    }
    let tol = (1e-12 * len.powi(D as i32)).max(8.0 * ulp(scale) * len.powi(D as i32 - 1));
    det_of::<N, D>(p).abs() <= tol
}

#[test]
fn the_shared_degeneracy_test_is_the_old_one() {
    let mut rng = SplitMix::new(11);
    let mut flips = 0;
    for case in 0..20_000 {
        let far = [0.0, 1.0, 1e6, 1e12][case % 4];
        let size = [1.0, 1e-5, 1e-9, 0.0][(case / 4) % 4];
        let mut p = [[0.0; 3]; 4];
        for x in p.iter_mut().flatten() {
            *x = far + size * (2.0 * rng.unit() - 1.0);
        }
        if case % 3 == 0 {
            // a corner on an edge: flat
            p[3] = std::array::from_fn(|k| (p[1][k] + p[2][k]) * 0.5);
        }
        let q: [[f64; 2]; 3] = std::array::from_fn(|i| [p[i][0], p[i][1]]);
        assert_eq!(is_degenerate(&p), degenerate_before(&p), "{p:?}");
        assert_eq!(is_degenerate(&q), degenerate_before(&q), "{q:?}");
        let len = longest_edge(&p);
        assert_eq!(degenerate_with(&p, det_of(&p), len), is_degenerate(&p));
        flips += usize::from(is_degenerate(&p));
    }
    assert!(flips > 1000 && flips < 19_000, "{flips}");
}

#[test]
fn the_bounded_degeneracy_test_is_the_shared_one() {
    let mut rng = SplitMix::new(12);
    let (mut flat, mut near) = (0, 0);
    for case in 0..40_000 {
        let far = [0.0, 1.0, -1e6, 1e12, -3e15][case % 5];
        let size = [1.0, 1e-5, 1e-9, 0.0, 1e3][(case / 5) % 5];
        let mut p = [[0.0; 3]; 4];
        for x in p.iter_mut().flatten() {
            *x = far + size * (2.0 * rng.unit() - 1.0);
        }
        match case % 4 {
            // a corner on an edge: flat
            0 => p[3] = std::array::from_fn(|k| (p[1][k] + p[2][k]) * 0.5),
            // the first corner at the origin, the others far
            1 => p[0] = [0.0; 3],
            // a corner barely off the face of the others
            2 => p[3] = std::array::from_fn(|k| (p[1][k] + p[2][k]) * 0.5 + 1e-13 * size),
            _ => {}
        }
        let (det, len) = (det_of(&p), longest_edge(&p));
        let want = degenerate_with(&p, det, len);
        assert_eq!(degenerate_bounded(&p, det, len), want, "{p:?}");
        flat += usize::from(want);
        near += usize::from(!want && det.abs() <= 1e-9 * len.powi(3));
    }
    assert!(flat > 5_000 && flat < 35_000, "{flat}");
    assert!(near > 0, "{near}");
}

#[test]
fn every_non_finite_coordinate_is_found() {
    let mut m = tet_cube(1);
    assert!((0..m.len()).all(|s| m.simplex_ok(s)));
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY] {
        for (c, k) in (0..4).flat_map(|c| (0..3).map(move |k| (c, k))) {
            let keep = m.coords[0][c][k];
            m.coords[0][c][k] = bad;
            assert!(!m.simplex_ok(0), "{bad} at {c}, {k}");
            m.coords[0][c][k] = keep;
        }
    }
    m.coords[0][1][2] = f64::MAX;
    m.coords[0][2][0] = -f64::MAX;
    assert!(m.simplex_ok(0));
}
