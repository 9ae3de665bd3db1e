//! Tests of the fit of one facet's transition: the same rotation,
//! translation, residual, tolerance and ambiguity as the fit as it was
//! first written (every rotation scanned, heap-allocated candidates), on
//! random rotated and perturbed charts (ties, noise, far coordinates,
//! collapsed corners), errors included.

use super::*;
use crate::transition_derive::num;
use crate::transition_same::{
    mismatch_table_same, only_identity, same_terms, table_of_terms, within_tol,
};
use dualex_util::rng::SplitMix;

/// The fit as it was first written: every rotation scanned in group
/// order, with heap-allocated candidate lists and `f64::round`.
#[allow(clippy::type_complexity)]
fn reference<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    s: usize,
    f: usize,
    all: &[Rot<D>],
    opts: &TransitionOptions,
) -> Result<(Rot<D>, [f64; D], f64, f64, Option<Vec<(Rot<D>, [i64; D])>>), String> {
    let n = topo.adj[s][f] as usize;
    let m = N - 1;
    let a: Vec<[f64; D]> = (1..N).map(|i| map.coords[s][(f + i) % N]).collect();
    let b: Vec<[f64; D]> = (1..N)
        .map(|i| map.coords[n][topo.nbr_corner[s][f][(f + i) % N] as usize])
        .collect();
    let scale = a
        .iter()
        .chain(&b)
        .flatten()
        .fold(0.0f64, |acc, x| acc.max(x.abs()));
    let tol = opts.tolerance_at(scale);
    let residual = |t: &[f64; D]| t.iter().map(|x| (x - x.round()).abs()).fold(0.0, f64::max);
    let mismatch = |r: &Rot<D>| {
        let mut worst = 0.0f64;
        for i in 1..m {
            let ea: [f64; D] = std::array::from_fn(|k| a[i][k] - a[0][k]);
            let ra = r.apply(&ea);
            for k in 0..D {
                worst = worst.max((ra[k] - (b[i][k] - b[0][k])).abs());
            }
        }
        worst
    };
    let translation = |r: &Rot<D>| -> [f64; D] {
        let mut t = [0.0; D];
        for i in 0..m {
            let ra = r.apply(&a[i]);
            for k in 0..D {
                t[k] += (b[i][k] - ra[k]) / m as f64;
            }
        }
        t
    };
    let mis: Vec<f64> = all.iter().map(mismatch).collect();
    let best = mis.iter().copied().fold(f64::INFINITY, f64::min);
    if best > opts.fit_tolerance(tol) {
        return Err(format!("mismatch {}", num(best)));
    }
    let cands: Vec<(Rot<D>, [f64; D])> = all
        .iter()
        .zip(&mis)
        .filter(|(_, &e)| e <= best + tol)
        .map(|(r, _)| (*r, translation(r)))
        .collect();
    let integral: Vec<&(Rot<D>, [f64; D])> =
        cands.iter().filter(|(_, t)| residual(t) <= tol).collect();
    let chosen = match (cands.len(), integral.first()) {
        (1, _) | (_, None) => {
            let key = |c: &&(Rot<D>, [f64; D])| mismatch(&c.0) + residual(&c.1);
            *cands
                .iter()
                .min_by(|x, y| key(x).total_cmp(&key(y)))
                .expect("a candidate")
        }
        (_, Some(c)) => **c,
    };
    let ambiguous = (cands.len() > 1 && integral.len() > 1).then(|| {
        integral
            .iter()
            .map(|(r, t)| (*r, t.map(|x| x.round() as i64)))
            .collect()
    });
    Ok((chosen.0, chosen.1, residual(&chosen.1), tol, ambiguous))
}

/// A coordinate drawn to make ties likely: small halves and quarters,
/// sometimes noise at the scale of the tolerance, sometimes far off.
fn coordinate(rng: &mut SplitMix, far: f64) -> f64 {
    let base = (rng.below(9) as f64 - 4.0) * 0.25;
    let noise = match rng.below(6) {
        0 => (rng.unit() - 0.5) * 4e-3,
        1 => (rng.unit() - 0.5) * 1e-9,
        2 => rng.unit() - 0.5,
        _ => 0.0,
    };
    base + noise + far
}

/// Two simplices sharing facet 0 of simplex 0; simplex 1's chart is a
/// rotated, translated, perturbed copy, with collapsed corners at times;
/// with `same`, the facet's corners are copied as they are (a facet off
/// the seams).
fn compare<const N: usize, const D: usize>(seed: u64, cases: usize, same: bool) {
    let all = Rot::<D>::all();
    let mut rng = SplitMix::new(seed);
    let (mut unique, mut several, mut errors) = (0, 0, 0);
    for _ in 0..cases {
        let far = if rng.below(8) == 0 { 1e9 } else { 0.0 };
        let mut coords0 = [[0.0f64; D]; N];
        for p in coords0.iter_mut() {
            for x in p.iter_mut() {
                *x = coordinate(&mut rng, far);
            }
        }
        if rng.below(3) == 0 {
            let (i, j) = (1 + rng.below(N - 1), 1 + rng.below(N - 1));
            coords0[i] = coords0[j];
        }
        let r = all[rng.below(all.len())];
        let t: [f64; D] = std::array::from_fn(|_| rng.below(7) as f64 - 3.0);
        // simplex 1 = (corners 1.. of simplex 0 reversed, apex): its
        // corner c holds simplex 0's corner N - 1 - c (c < N - 1)
        let mut coords1 = [[0.0f64; D]; N];
        for c in 0..N - 1 {
            let p = r.apply(&coords0[N - 1 - c]);
            coords1[c] = std::array::from_fn(|k| {
                p[k] + t[k] + coordinate(&mut rng, 0.0) * 0.01 * (rng.below(2) as f64)
            });
        }
        if same {
            for c in 0..N - 1 {
                coords1[c] = coords0[N - 1 - c];
            }
        }
        coords1[N - 1] = [7.0; D];
        let mut simplex1 = [0u32; N];
        for (c, v) in simplex1.iter_mut().enumerate() {
            *v = (N - 1 - c) as u32;
        }
        simplex1[N - 1] = N as u32;
        if N == 4 {
            // keep the orientation consistent: swap two facet corners
            simplex1.swap(0, 1);
            coords1.swap(0, 1);
        }
        let map = SimplexMap::<N, D> {
            positions: vec![[0.0; 3]; N + 1],
            simplices: vec![std::array::from_fn(|c| c as u32), simplex1],
            coords: vec![coords0, coords1],
        };
        let topo = Topology::build(&map).expect("topology");
        assert_eq!(topo.adj[0][0], 1);
        // strict (no rounding: errors are frequent), default, round
        for (round, round_limit) in [(false, 0.0), (false, 0.1), (true, 0.1)] {
            let opts = TransitionOptions {
                round,
                round_limit,
                ..Default::default()
            };
            let got = fit_facet(&map, &topo, 0, 0, &Group::new(), &opts);
            let want = reference(&map, &topo, 0, 0, &all, &opts);
            match (got, want) {
                (Ok(g), Ok(w)) => {
                    assert_eq!(g.rot, w.0, "{map:?}");
                    assert_eq!(g.trans.map(f64::to_bits), w.1.map(f64::to_bits), "{map:?}");
                    assert_eq!(g.rounded, rounded(&g.trans), "{map:?}");
                    assert_eq!(g.residual.to_bits(), w.2.to_bits(), "{map:?}");
                    assert_eq!(g.tol.to_bits(), w.3.to_bits(), "{map:?}");
                    assert_eq!(g.ambiguous, w.4, "{map:?}");
                    if g.ambiguous.is_some() {
                        several += 1;
                    } else {
                        unique += 1;
                    }
                }
                (Err(g), Err(w)) => {
                    // the message may go on with a hint
                    assert!(g.to_string().contains(&format!("({w})")), "{g} vs {w}");
                    errors += 1;
                }
                (g, w) => panic!("{:?} vs {w:?} on {map:?}", g.map(|f| f.rot)),
            }
        }
    }
    // equal charts fit the identity: no error
    assert!(
        unique > 0 && several > 0 && (errors > 0) != same,
        "{unique} {several} {errors}"
    );
}

#[test]
fn fit_matches_the_full_scan_2d() {
    compare::<3, 2>(1, 20000, false);
    compare::<3, 2>(3, 20000, true);
}

#[test]
fn fit_matches_the_full_scan_3d() {
    compare::<4, 3>(2, 20000, false);
    compare::<4, 3>(4, 20000, true);
}

/// Wherever the identity fast path answers, scanning the whole group
/// finds the same best mismatch, bit for bit, and the identity as the only
/// rotation within `tol` of it (random tables: small diagonal entries,
/// other entries near the cut, ties and free axes included).
fn identity_fast_path_agrees<const D: usize>(seed: u64) {
    let group = Group::<D>::new();
    let all = &group.all;
    let mut rng = SplitMix::new(seed);
    let mut hits = 0;
    for _ in 0..20_000 {
        let mut table = [0.0f64; 18];
        for (i, x) in table.iter_mut().enumerate() {
            let diagonal = i % 6 == 2 * (i / 6);
            *x = match (diagonal, rng.below(5)) {
                (true, 0) | (false, 0) => 0.0,
                (true, _) => rng.unit() * 1e-2,
                (false, 1) => 1e-2 + rng.below(3) as f64 * 1e-3,
                (false, _) => rng.unit() * 2.0,
            };
        }
        for tol in [0.0, 1e-3, 0.05] {
            let Some(best) = identity_fit::<D>(&table, tol, &group) else {
                continue;
            };
            hits += 1;
            let mis: Vec<f64> = all
                .iter()
                .map(|r| mismatch_of(&table, &r.images()))
                .collect();
            let least = mis.iter().copied().fold(f64::INFINITY, f64::min);
            assert_eq!(best.to_bits(), least.to_bits(), "{table:?} {tol}");
            let within: Vec<Rot<D>> = all
                .iter()
                .zip(&mis)
                .filter(|(_, &e)| e <= least + tol)
                .map(|(r, _)| *r)
                .collect();
            assert_eq!(within, vec![Rot::IDENTITY], "{table:?} {tol}");
        }
    }
    assert!(hits > 1000, "{hits}");
}

#[test]
fn identity_fast_path_agrees_2d_3d() {
    identity_fast_path_agrees::<2>(5);
    identity_fast_path_agrees::<3>(6);
}

/// The half table of equal charts is the whole table, bit for bit
/// (random corners: ties, collapsed corners, far coordinates).
fn same_table_agrees<const D: usize>(seed: u64) {
    let mut rng = SplitMix::new(seed);
    for _ in 0..20_000 {
        let far = if rng.below(4) == 0 { 1e9 } else { 0.0 };
        let mut a = [[0.0f64; D]; D];
        for x in a.iter_mut().flatten() {
            *x = coordinate(&mut rng, far);
        }
        if rng.below(3) == 0 {
            a[rng.below(D)] = a[rng.below(D)];
        }
        let (got, want) = (mismatch_table_same(&a), mismatch_table(&a, &a));
        assert_eq!(got.map(f64::to_bits), want.map(f64::to_bits), "{a:?}");
        for tol in [0.0, 1e-3, 0.05, 0.25] {
            let terms = same_terms(&a);
            assert_eq!(
                within_tol(&a, tol),
                within_of::<D>(&terms, tol),
                "{a:?} {tol}"
            );
        }
    }
}

#[test]
fn same_table_agrees_2d_3d() {
    same_table_agrees::<2>(7);
    same_table_agrees::<3>(8);
}

/// The set of equal charts' terms within `tol` tells what
/// [`identity_fit`] finds on their table (random terms: 0, near the
/// tolerances, above them; every set of terms in 2D and 3D is met).
fn same_lookup_agrees<const D: usize>(seed: u64) {
    let group = Group::<D>::new();
    let mut rng = SplitMix::new(seed);
    let (mut yes, mut no) = (0, 0);
    for _ in 0..40_000 {
        let mut terms = [0.0f64; 9];
        for x in terms[..D * D].iter_mut() {
            *x = match rng.below(4) {
                0 => 0.0,
                1 => [1e-3, 0.05][rng.below(2)],
                2 => rng.unit() * 1e-2,
                _ => rng.unit() * 2.0,
            };
        }
        for tol in [0.0, 1e-3, 0.05, -1.0, f64::NAN] {
            let want = identity_fit::<D>(&table_of_terms::<D>(&terms), tol, &group).is_some();
            let got = !(tol.is_nan() || tol < 0.0)
                && only_identity::<D>(within_of::<D>(&terms, tol), &group);
            assert_eq!(got, want, "{terms:?} {tol}");
            if want {
                yes += 1;
            } else {
                no += 1;
            }
        }
    }
    assert!(yes > 1000 && no > 1000, "{yes} {no}");
}

#[test]
fn same_lookup_agrees_2d_3d() {
    same_lookup_agrees::<2>(9);
    same_lookup_agrees::<3>(10);
}

/// The set of `terms` within `tol` (bit `k` for term `k`).
fn within_of<const D: usize>(terms: &[f64; 9], tol: f64) -> usize {
    (0..D * D).fold(0, |w, k| w | usize::from(terms[k] <= tol) << k)
}
