//! The 3D mask ([`Predicates::mask`] at [`Dim<4, 3>`]) against two
//! oracles: the mask as it was before the face prefilter
//! ([`triangle_clear_of_grid`]) and the unfiltered tests of
//! [`crate::near::bad_vertices`], on random and adversarial tets: corners
//! on and just off integers, edges and faces through and next to grid
//! points, thin and flat faces, repeated corners, large coordinates; the
//! 2D mask against its unfiltered tests on the triangles of those tets'
//! corners, seen along two axes.

use super::{Dim, Predicates};
use crate::bad_scan::PARTIAL;
use crate::boxes::Boxes;
use crate::grid::{dist2d_below_eps, grid_point_near_segment, segment_clear_of_grid};
use crate::grid::{near_int_on, spanned_axes};
use crate::near::{
    face_corners, near_int, segment_near_iso_line, triangle_clear_of_grid,
    triangle_near_grid_point, EDGES, EPS, FACE_EDGES,
};
use dualex_util::rng::SplitMix;

/// The 3D mask before the face prefilter (the oracle, kept as it was).
fn mask_before(c: &[[f64; 3]; 4]) -> u8 {
    const FULL: u8 = 0b1111;
    let axes = spanned_axes(c);
    if axes & axes.wrapping_sub(1) == 0 {
        return if axes == 0 {
            0
        } else {
            near_int_on(c, axes.trailing_zeros() as usize)
        };
    }
    let boxes = Boxes::of(c);
    let mut mask = boxes.near_any(c);
    if mask == FULL {
        return mask;
    }
    let span = boxes.edge_spans(&EDGES);
    for (&[k, l], &bits) in EDGES.iter().zip(&span) {
        let ends = 1 << k | 1 << l;
        if bits & bits.wrapping_sub(1) == 0 || mask & ends == ends {
            continue;
        }
        let range = boxes.range(k, l);
        if let Some((at_k, at_l)) = segment_near_iso_line_in_box_before(&c[k], &c[l], &range) {
            mask |= u8::from(at_k || !at_l) << k | u8::from(at_l || !at_k) << l;
        }
    }
    if axes != 0b111 || mask == FULL {
        return mask;
    }
    for (f, [e0, e1, e2]) in FACE_EDGES.into_iter().enumerate() {
        let corners = FULL & !(1 << f);
        if span[e0] | span[e1] | span[e2] != 0b111 || mask & corners == corners {
            continue;
        }
        let [i, j, k] = face_corners(f);
        if triangle_near_grid_point(&[c[i], c[j], c[k]]) {
            mask |= 1 << i | 1 << j | 1 << k;
        }
    }
    mask
}

/// `near::segment_near_iso_line_in_box` before it took the spanned axes
/// (the oracle's, kept as it was).
fn segment_near_iso_line_in_box_before(
    a: &[f64; 3],
    b: &[f64; 3],
    range: &[[f64; 2]; 3],
) -> Option<(bool, bool)> {
    for [i, j] in [[0, 1], [0, 2], [1, 2]] {
        let (lo, hi) = ([range[i][0], range[j][0]], [range[i][1], range[j][1]]);
        if lo[0] > hi[0] || lo[1] > hi[1] {
            continue;
        }
        let (pa, pb) = ([a[i], a[j]], [b[i], b[j]]);
        if segment_clear_of_grid(&pa, &pb, lo, hi) {
            continue;
        }
        if let Some(g) = grid_point_near_segment(&pa, &pb) {
            return Some((dist2d_below_eps(&g, &pa), dist2d_below_eps(&g, &pb)));
        }
    }
    None
}

/// The unfiltered tests of [`crate::near::bad_vertices`] on one tet.
pub(super) fn mask_unfiltered(c: &[[f64; 3]; 4]) -> u8 {
    let mut want = 0u8;
    for k in 0..4 {
        want |= u8::from(c[k].iter().any(|&x| near_int(x))) << k;
        for l in k + 1..4 {
            if let Some((at_k, at_l)) = segment_near_iso_line(&c[k], &c[l]) {
                want |= u8::from(at_k || !at_l) << k | u8::from(at_l || !at_k) << l;
            }
        }
    }
    for f in 0..4 {
        let fc = face_corners(f);
        if triangle_near_grid_point(&fc.map(|i| c[i])) {
            want |= fc.iter().fold(0, |m, &i| m | 1 << i);
        }
    }
    want
}

/// The unfiltered tests of the 2D mask on one triangle: every corner's
/// coordinates, every edge by [`grid_point_near_segment`].
fn tri_mask_unfiltered(c: &[[f64; 2]; 3]) -> u8 {
    let mut want = 0u8;
    for k in 0..3 {
        let l = (k + 1) % 3;
        want |= u8::from(c[k].iter().any(|&x| near_int(x))) << k;
        if let Some(g) = grid_point_near_segment(&c[k], &c[l]) {
            let (at_k, at_l) = (dist2d_below_eps(&g, &c[k]), dist2d_below_eps(&g, &c[l]));
            want |= u8::from(at_k || !at_l) << k | u8::from(at_l || !at_k) << l;
        }
    }
    want
}

/// The 2D mask (with its one-grid-point shortcut and box filters) equals
/// its unfiltered tests on the triangles of adversarial tets' corners,
/// along every pair of axes, and with a corner moved onto a grid point
/// and the next onto its iso; given known corners too ([`check_known`]).
#[test]
fn triangle_mask_equals_unfiltered_tests() {
    let mut rng = SplitMix::new(37);
    let mut bad = 0usize;
    for n in 0..100000 {
        let c = tet(&mut rng, n);
        for [i, j, k] in [[0, 1, 2], [0, 1, 3], [3, 2, 1]] {
            for [x, y] in [[0, 1], [1, 2], [2, 0]] {
                let t = [i, j, k].map(|p| [c[p][x], c[p][y]]);
                // also: a corner exactly on a grid point, with the next
                // corner on its iso
                let mut on = t;
                on[0] = on[0].map(f64::round);
                on[1][n % 2] = on[0][n % 2];
                for t in [t, on] {
                    let got = <Dim<3, 2>>::mask(&t);
                    assert_eq!(got, tri_mask_unfiltered(&t), "{t:?}");
                    check_known(&t);
                    bad += usize::from(got != 0);
                }
            }
        }
    }
    assert!(bad > 200000, "{bad}");
}

/// Offsets from the grid: on it, a few `EPS` off, `1e-5` off.
const OFFSETS: [f64; 12] = [
    0.0,
    0.5 * EPS,
    EPS,
    -EPS,
    2.0 * EPS,
    -2.0 * EPS,
    3.0 * EPS,
    -3.0 * EPS,
    4.0 * EPS,
    1e-5,
    -1e-5,
    1e-7,
];

/// Shifts that take coordinates past every "small" bound (1024) and far.
const SHIFTS: [f64; 7] = [0.0, 0.0, 0.0, -3.0, 1021.0, 1e6, 1099511627776.0];

fn pick<T: Copy>(rng: &mut SplitMix, of: &[T]) -> T {
    of[((rng.unit() * of.len() as f64) as usize).min(of.len() - 1)]
}

/// A random adversarial tet (`kind` cycles through the families).
fn tet(rng: &mut SplitMix, kind: usize) -> [[f64; 3]; 4] {
    let g: [f64; 3] = std::array::from_fn(|_| (rng.unit() * 6.0 - 3.0).floor());
    let size = pick(rng, &[1e-3, 0.05, 0.5, 1.0, 2.5]);
    let mut c: [[f64; 3]; 4] =
        std::array::from_fn(|_| std::array::from_fn(|a| g[a] + size * (rng.unit() - 0.5)));
    match kind % 7 {
        // corners on or just off integers, per coordinate
        0 => {
            for x in c.iter_mut().flatten() {
                if rng.unit() < 0.5 {
                    *x = x.round() + pick(rng, &OFFSETS);
                }
            }
        }
        // a face through (or next to) g: its centroid at g, moved
        // across by an offset along an axis
        1 | 2 => {
            let (a, o) = ((rng.unit() * 3.0) as usize % 3, pick(rng, &OFFSETS));
            let [i, j, k] = face_corners((rng.unit() * 4.0) as usize % 4);
            c[i] = std::array::from_fn(|x| 3.0 * g[x] - c[j][x] - c[k][x]);
            for p in [i, j, k] {
                c[p][a] += o;
            }
        }
        // an edge through (or next to) g, on its line
        3 => {
            let (t, o) = (rng.unit(), pick(rng, &OFFSETS));
            let d = c[1].map(|x| x);
            c[0] = std::array::from_fn(|x| g[x] - t * (d[x] - g[x]));
            c[0][(rng.unit() * 3.0) as usize % 3] += o;
        }
        // a thin face: one corner almost on the line of two others
        4 => {
            let (t, w) = (
                rng.unit() * 1.5 - 0.25,
                pick(rng, &[0.0, 1e-12, 1e-8, 1e-4]),
            );
            c[3] = std::array::from_fn(|x| c[1][x] + t * (c[2][x] - c[1][x]) + w * rng.unit());
        }
        // flat, or repeated corners
        5 => {
            if rng.unit() < 0.5 {
                c[3] = std::array::from_fn(|x| c[0][x] + c[1][x] - c[2][x]);
            } else {
                c[3] = c[(rng.unit() * 3.0) as usize % 3];
            }
        }
        // the lattice of the benchmark block: x.7 / x.2, jittered
        _ => {
            let jitter = pick(rng, &[0.0, 1e-5, 1e-9]);
            for x in c.iter_mut().flatten() {
                *x = (2.0 * *x).round() / 2.0 + 0.2 + jitter * (rng.unit() - 0.5);
            }
        }
    }
    let shift = pick(rng, &SHIFTS);
    c.map(|p| p.map(|x| x + shift))
}

/// The mask equals both oracles on adversarial tets, and the face
/// prefilter decides many of the faces it sees.
#[test]
fn mask_equals_oracles_on_adversarial_tets() {
    let mut rng = SplitMix::new(29);
    let (mut found, mut cleared) = (0usize, 0usize);
    for n in 0..300000 {
        let c = tet(&mut rng, n);
        let got = <Dim<4, 3>>::mask(&c);
        assert_eq!(got, mask_before(&c), "{c:?}");
        assert_eq!(got, mask_unfiltered(&c), "{c:?}");
        let boxes = Boxes::of(&c);
        for f in 0..4 {
            let [i, j, k] = face_corners(f);
            let t = [c[i], c[j], c[k]];
            let (r, q) = (boxes.range(i, j), boxes.range(i, k));
            let lo = std::array::from_fn(|a| r[a][0].min(q[a][0]));
            let hi = std::array::from_fn(|a| r[a][1].max(q[a][1]));
            let near = triangle_near_grid_point(&t);
            let clear = triangle_clear_of_grid(&t, lo, hi);
            assert!(!(near && clear), "{t:?}");
            found += usize::from(near);
            cleared += usize::from(clear);
        }
    }
    assert!(found > 10000 && cleared > 100000, "{found} {cleared}");
}

/// [`Predicates::mask_known`] of `c` under every `known`: no bit the mask
/// lacks, no bit of the mask lost unless in `known`, and the mask itself
/// unless marked [`PARTIAL`] (then it lacks a bit of `known`).
fn check_known<const N: usize, const D: usize>(c: &[[f64; D]; N])
where
    Dim<N, D>: Predicates<N, D>,
{
    let want = <Dim<N, D>>::mask(c);
    for known in 0..1u8 << N {
        let got = <Dim<N, D>>::mask_known(c, known);
        let bits = got & !PARTIAL;
        assert_eq!(bits & !want, 0, "{c:?} {known:b}");
        assert_eq!(want & !(bits | known), 0, "{c:?} {known:b}");
        if got & PARTIAL == 0 {
            assert_eq!(got, want, "{c:?} {known:b}");
        } else {
            assert_ne!(known & !bits, 0, "{c:?} {known:b}");
        }
    }
}

/// The first scan's test given known corners ([`check_known`]) on the
/// adversarial tets, and on triangles of the same lattices: on, next to
/// and off integers and half-integers, edges through grid points.
#[test]
fn mask_given_known_corners_keeps_every_bit() {
    let mut rng = SplitMix::new(31);
    let mut bad = 0usize;
    for n in 0..60000 {
        let c = tet(&mut rng, n);
        check_known(&c);
        let c: [[f64; 2]; 3] = std::array::from_fn(|_| {
            std::array::from_fn(|_| {
                let x = (rng.unit() * 8.0).floor() * 0.5 + 0.2;
                match (rng.unit() * 8.0) as u32 {
                    0 => x.round(),
                    1 => x.round() + EPS * (rng.unit() * 4.0 - 2.0),
                    2 => x + 1e-5 * (rng.unit() - 0.5),
                    3 => x + 0.3,
                    _ => x,
                }
            })
        });
        check_known(&c);
        bad += usize::from(<Dim<3, 2>>::mask(&c) != 0);
    }
    assert!(bad > 10000, "{bad}");
}

/// The 2D mask equals its unfiltered tests on triangles at and past the
/// bounds of its call-free path (`FAST/2` = 2^50; every double past 2^52
/// is an integer): whole triangles shifted (one corner shifted alone
/// makes the oracle walk 2^50 grid points).
#[test]
fn triangle_mask_equals_unfiltered_tests_on_large_coordinates() {
    let p = |e: i32| 2f64.powi(e);
    let shifts = [
        p(49),
        p(50) - 8.0,
        p(50),
        p(50) + 0.5,
        p(51),
        -p(51),
        p(53),
        -p(60),
    ];
    let mut rng = SplitMix::new(41);
    let mut bad = 0usize;
    for n in 0..20000 {
        let c = tet(&mut rng, n);
        let s = pick(&mut rng, &shifts);
        let t = [0, 1, 2].map(|k| [c[k][0] + s, c[k][1] + s]);
        let got = <Dim<3, 2>>::mask(&t);
        assert_eq!(got, tri_mask_unfiltered(&t), "{t:?}");
        bad += usize::from(got != 0);
    }
    assert!(bad > 5000, "{bad}");
}
