//! [`Simplex::pierced`] (built on [`Simplex::crossed`] and
//! [`Simplex::crossing_at`]) against the one-pass version it replaced,
//! kept here as the oracle: bit for bit on random simplices and lines —
//! corners on integers (lines through corners and edges), flat and
//! inverted simplices, large and non-finite coordinates.

use super::*;
use dualex_util::rng::SplitMix;

/// The former 2D `pierced`.
fn oracle_2d(p: &[[f64; 2]; 3], line: &Line<2>) -> ([Pierce; 3], usize) {
    let (mv, fixed) = (line.axis, 1 - line.axis);
    let v = line.val[fixed] as f64;
    let d = p.map(|c| c[fixed] - v);
    let mut out = [NO_PIERCE; 3];
    let mut n = 0;
    for f in 0..3 {
        let (i, j) = ((f + 1) % 3, (f + 2) % 3);
        let (da, db) = (d[i], d[j]);
        if (da > 0.0) != (db > 0.0) {
            let (a, b) = (p[i][mv], p[j][mv]);
            out[n] = Pierce {
                face: f,
                at: a + (b - a) * da / (da - db),
                at_corner: da == 0.0 || db == 0.0,
            };
            n += 1;
        }
    }
    (out, n)
}

/// The former 3D `pierced`.
fn oracle_3d(p: &[[f64; 3]; 4], line: &Line<3>) -> ([Pierce; 4], usize) {
    let a = line.axis;
    let [b, c] = fixed_axes(a);
    let (vb, vc) = (line.val[b] as f64, line.val[c] as f64);
    let mut out = [NO_PIERCE; 4];
    let mut n = 0;
    for f in 0..4 {
        let k = face_corners(f);
        let q = k.map(|i| [p[i][b] - vb, p[i][c] - vc]);
        let lam: [f64; 3] = std::array::from_fn(|i| {
            let (u, v) = (q[(i + 1) % 3], q[(i + 2) % 3]);
            u[0] * v[1] - u[1] * v[0]
        });
        let pos = lam.iter().all(|&l| l > 0.0);
        if pos || lam.iter().all(|&l| l < 0.0) {
            let sum = lam[0] + lam[1] + lam[2];
            let at = (0..3).map(|i| lam[i] * p[k[i]][a]).sum::<f64>() / sum;
            out[n] = Pierce {
                face: f,
                at,
                at_corner: false,
            };
            n += 1;
        }
    }
    (out, n)
}

/// The hits as comparable bits: `at` by its bit pattern, any NaN as one
/// (a NaN's sign and payload are up to code generation, which may swap the
/// operands of a sum or product, and no comparison sees them).
fn bits<const N: usize>((hits, n): ([Pierce; N], usize)) -> Vec<(usize, u64, bool)> {
    let canonical = |x: f64| if x.is_nan() { u64::MAX } else { x.to_bits() };
    hits[..n]
        .iter()
        .map(|h| (h.face, canonical(h.at), h.at_corner))
        .collect()
}

/// A random coordinate of one of several kinds, by `kind`.
fn coord(rng: &mut SplitMix, kind: usize) -> f64 {
    let small = rng.below(7) as f64 - 3.0;
    match kind {
        // on integers: lines through corners and edges
        0 => small,
        // on half-integers and integers
        1 => small + 0.5 * rng.below(2) as f64,
        2 => 8.0 * rng.unit() - 4.0,
        3 => (rng.unit() - 0.5) * 1e15,
        4 => (rng.unit() - 0.5) * 1e300,
        _ => [f64::INFINITY, f64::NEG_INFINITY, f64::NAN, small][rng.below(4)],
    }
}

/// Random corners, sometimes flat (a corner repeated or on a line through
/// two others), and the line's fixed values near them.
fn case<const N: usize, const D: usize>(rng: &mut SplitMix) -> ([[f64; D]; N], Line<D>) {
    let kind = [0, 0, 1, 1, 2, 3, 4, 5][rng.below(8)];
    let mut p: [[f64; D]; N] = std::array::from_fn(|_| std::array::from_fn(|_| coord(rng, kind)));
    match rng.below(6) {
        0 => p[rng.below(N)] = p[rng.below(N)],
        1 => {
            let (i, j, k) = (rng.below(N), rng.below(N), rng.below(N));
            p[k] = std::array::from_fn(|x| 2.0 * p[i][x] - p[j][x]);
        }
        2 => p.swap(0, 1),
        _ => {}
    }
    let line = Line {
        axis: rng.below(D),
        sgn: 1.0,
        val: std::array::from_fn(|_| rng.below(7) as i64 - 3),
    };
    (p, line)
}

/// A `pierced` function of one dimension.
type PiercedFn<const N: usize, const D: usize> =
    fn(&[[f64; D]; N], &Line<D>) -> ([Pierce; N], usize);

/// `pierced` against `oracle` on 400 000 random cases from `seed`.
fn matches_oracle<const N: usize, const D: usize>(seed: u64, oracle: PiercedFn<N, D>)
where
    Dim<N, D>: Simplex<N, D>,
{
    let mut rng = SplitMix::new(seed);
    for i in 0..400_000 {
        let (p, line) = case::<N, D>(&mut rng);
        let got = Dim::<N, D>::pierced(&p, &line);
        assert_eq!(
            bits(got),
            bits(oracle(&p, &line)),
            "case {i}: {p:?} {line:?}"
        );
    }
}

#[test]
fn pierced_matches_the_former_one_pass_version_2d() {
    matches_oracle::<3, 2>(25, oracle_2d);
}

#[test]
fn pierced_matches_the_former_one_pass_version_3d() {
    matches_oracle::<4, 3>(17, oracle_3d);
}

#[test]
fn the_exit_is_the_other_of_exactly_two_facets() {
    let c = |facets| Crossed { facets, corners: 0 };
    assert_eq!(c(0b0101).exit(0), Some(2));
    assert_eq!(c(0b0101).exit(2), Some(0));
    assert_eq!(c(0b0101).exit(1), None);
    assert_eq!(c(0b0111).exit(0), None);
    assert_eq!(c(0b0001).exit(0), None);
    assert_eq!(c(0).exit(3), None);
}
