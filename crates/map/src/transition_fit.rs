//! Fit of one interior facet's transition: steps 1–3 of
//! [`crate::transition_derive`] (mismatch of every grid rotation, the
//! candidates within `tol` of the best, their translations and residuals).
//!
//! Input: the map, its topology, an interior facet `(s, f)`, the rotation
//! group in [`Rot::all`] order and the options. Output: [`Fit`] (rotation,
//! translation, residual, tolerance, the integral candidates when
//! ambiguous), or the reflection / non-grid-rotation [`InputError`].
//!
//! Invariant: the result is the same, bit for bit, as scanning every
//! rotation in group order (the reference in the tests): the fast path
//! ([`unique_fit`]) only answers when exactly one rotation is within `tol`
//! of the best, and then both agree on it and on the best mismatch.

use crate::error::{ElementKind, MapError};
use crate::transition::ROUND_FIT_LIMIT;
use crate::{InputError, Rot, SimplexMap, Topology, TransitionOptions};
use dualex_util::round::round;

/// The chosen transition of one facet and what it measured.
pub(crate) struct Fit<const D: usize> {
    pub(crate) rot: Rot<D>,
    pub(crate) trans: [f64; D],
    pub(crate) residual: f64,
    pub(crate) tol: f64,
    pub(crate) ambiguous: Option<Vec<(Rot<D>, [i64; D])>>,
}

fn residual_of<const D: usize>(t: &[f64; D]) -> f64 {
    t.iter().map(|&x| (x - round(x)).abs()).fold(0.0, f64::max)
}

pub(crate) fn rounded<const D: usize>(t: &[f64; D]) -> [i64; D] {
    t.map(|x| round(x) as i64)
}

/// Size of the largest rotation group (24 in 3D).
const MAX_ROTATIONS: usize = 24;

/// Fits the rotation and translation of one interior facet (steps 1–3 of
/// the module docs), without heap allocation unless several rotations fit.
///
/// The mismatch of a rotation `R` is `max_j table[6·j + img[j]]` (see
/// [`mismatch_table`]): the same floats, maxed in another order, as
/// `max_{i,k} |(R·ea_i)_k − eb_i[k]|`; none is NaN after `max` (a NaN term
/// is skipped, as `f64::max` skips it).
pub(crate) fn fit_facet<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    s: usize,
    f: usize,
    all: &[Rot<D>],
    opts: &TransitionOptions,
) -> Result<Fit<D>, Box<InputError>> {
    let n = topo.adj[s][f] as usize;
    let m = N - 1;
    // a[i], b[i] for i < m: the facet's corners in the charts of s and n
    let (cs, cn, corner) = (&map.coords[s], &map.coords[n], &topo.nbr_corner[s][f]);
    let mut a = [[0.0f64; D]; N];
    let mut b = [[0.0f64; D]; N];
    let mut scale = 0.0f64;
    for i in 0..m {
        let c = (f + 1 + i) % N;
        a[i] = cs[c];
        b[i] = cn[corner[c] as usize];
        for k in 0..D {
            // `max` without its NaN branch: the same result from 0.0
            let (x, y) = (a[i][k].abs(), b[i][k].abs());
            if x > scale {
                scale = x;
            }
            if y > scale {
                scale = y;
            }
        }
    }
    let tol = opts.tolerance_at(scale);
    let table = mismatch_table(&a[..m], &b[..m]);
    let mut mis = [0.0f64; MAX_ROTATIONS];
    let (best, unique) = match unique_fit::<D>(&table, tol) {
        Some((r, best)) => (best, Some(r)),
        None => {
            let mut best = f64::INFINITY;
            for (e, r) in mis.iter_mut().zip(all) {
                let worst = mismatch_of(&table, &r.images());
                *e = worst;
                if worst < best {
                    best = worst;
                }
            }
            (best, None)
        }
    };
    if best > opts.fit_tolerance(tol) {
        // rounding accepts a mismatch up to ROUND_FIT_LIMIT: say so when it
        // would
        let round_hint = !opts.round && best <= opts.fit_tolerance(tol).max(ROUND_FIT_LIMIT);
        return Err(Box::new(
            MapError::ReflectedTransition {
                simplex: ElementKind::simplex(N).at(s),
                facet: f,
                neighbour: n,
                mismatch: best,
                round_hint,
            }
            .into(),
        ));
    }
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
    let mis = &mis[..all.len()];
    let mut fitting = all.iter().zip(mis).filter(|(_, &e)| e <= best + tol);
    let single = match unique {
        Some(r) => Some(r),
        None => match (fitting.next(), fitting.next()) {
            (Some((r, _)), None) => Some(*r),
            _ => None,
        },
    };
    if let Some(rot) = single {
        // the common case: the fit determines the rotation
        let trans = translation(&rot);
        return Ok(Fit {
            rot,
            trans,
            residual: residual_of(&trans),
            tol,
            ambiguous: None,
        });
    }
    // candidates in group order: (rotation, mismatch, translation, residual)
    let cands: Vec<(Rot<D>, f64, [f64; D], f64)> = all
        .iter()
        .zip(mis)
        .filter(|(_, &e)| e <= best + tol)
        .map(|(r, &e)| {
            let t = translation(r);
            (*r, e, t, residual_of(&t))
        })
        .collect();
    let integral: Vec<&(Rot<D>, f64, [f64; D], f64)> =
        cands.iter().filter(|c| c.3 <= tol).collect();
    let chosen = match integral.first() {
        None => {
            // no integral choice: best fit, then smallest residual (the
            // first of equal keys)
            let key = |c: &&(Rot<D>, f64, [f64; D], f64)| c.1 + c.3;
            let Some(c) = cands.iter().min_by(|x, y| key(x).total_cmp(&key(y))) else {
                panic!("bug: no rotation candidate on facet {f} of simplex {s}");
            };
            *c
        }
        Some(c) => **c,
    };
    let ambiguous =
        (integral.len() > 1).then(|| integral.iter().map(|c| (c.0, rounded(&c.2))).collect());
    Ok(Fit {
        rot: chosen.0,
        trans: chosen.2,
        residual: chosen.3,
        tol,
        ambiguous,
    })
}

/// Mismatch of the rotation with images `img` (see [`mismatch_table`]).
#[inline]
fn mismatch_of<const D: usize>(table: &[f64; 18], img: &[u8; D]) -> f64 {
    let mut worst = 0.0f64;
    for (j, &d) in img.iter().enumerate() {
        let x = table[6 * j + d as usize];
        if x > worst {
            worst = x;
        }
    }
    worst
}

/// The image of the last axis that completes the images `img[..D-1]` of the
/// other axes into a rotation (determinant +1), or `None` when two of them
/// share an axis.
#[inline]
fn last_image<const D: usize>(img: &[u8; D]) -> Option<u8> {
    let (mut used, mut odd) = (0u8, 0u8);
    for &d in &img[..D - 1] {
        let bit = 1u8 << (d >> 1);
        if used & bit != 0 {
            return None;
        }
        used |= bit;
        odd ^= d & 1;
    }
    let last = (!used).trailing_zeros() as u8;
    // parity of the axis permutation (img[0] >> 1, …, last)
    for i in 0..D - 1 {
        for j in i + 1..D {
            let aj = if j == D - 1 { last } else { img[j] >> 1 };
            odd ^= u8::from(img[i] >> 1 > aj);
        }
    }
    Some(2 * last + odd)
}

/// The best mismatch and the only rotation within `tol` of it, if there is
/// exactly one, found without scanning the whole group: the identity and a
/// guess `G` (the first axes to their least entries, completed into a
/// rotation) bound the best mismatch by `U = min(mis(I), mis(G))`; every
/// rotation within `tol` of the best sends each axis to a direction whose
/// entry is `≤ U + tol`, and those few are scanned. `None`: too many
/// directions pass, or several rotations fit (then the whole group is
/// scanned, in its order).
fn unique_fit<const D: usize>(table: &[f64; 18], tol: f64) -> Option<(Rot<D>, f64)> {
    if tol.is_nan() || tol < 0.0 {
        return None;
    }
    let mut guess = [0u8; D];
    for (j, g) in guess.iter_mut().enumerate().take(D - 1) {
        let row = &table[6 * j..6 * j + 2 * D];
        for (d, &x) in row.iter().enumerate() {
            if x < row[*g as usize] {
                *g = d as u8;
            }
        }
    }
    let mut bound = mismatch_of(table, &Rot::<D>::IDENTITY.images());
    if let Some(last) = last_image(&guess) {
        guess[D - 1] = last;
        bound = bound.min(mismatch_of(table, &guess));
    }
    let cut = bound + tol;
    // per axis but the last, the directions within the cut
    let mut allowed = [[0u8; 6]; D];
    let mut len = [0usize; D];
    for j in 0..D - 1 {
        for d in 0..2 * D {
            if table[6 * j + d] <= cut {
                allowed[j][len[j]] = d as u8;
                len[j] += 1;
            }
        }
        if len[j] == 0 || len[j] > 2 {
            return None;
        }
    }
    let (mut found, mut count, mut best) = ([(Rot::<D>::IDENTITY, 0.0f64); 4], 0, f64::INFINITY);
    let mut idx = [0usize; D];
    loop {
        let mut img: [u8; D] = std::array::from_fn(|j| allowed[j][idx[j]]);
        if let Some(last) = last_image(&img) {
            img[D - 1] = last;
            if table[6 * (D - 1) + last as usize] <= cut {
                let e = mismatch_of(table, &img);
                best = best.min(e);
                found[count] = (Rot::from_images(img)?, e);
                count += 1;
            }
        }
        // next combination of the first D - 1 axes' directions
        let mut j = 0;
        while j < D - 1 {
            idx[j] += 1;
            if idx[j] < len[j] {
                break;
            }
            idx[j] = 0;
            j += 1;
        }
        if j == D - 1 {
            break;
        }
    }
    let mut within = found[..count].iter().filter(|x| x.1 <= best + tol);
    match (within.next(), within.next()) {
        (Some(&(r, _)), None) => Some((r, best)),
        _ => None,
    }
}

/// `table[6·j + d]`: the largest `|σ·ea_i[j] − eb_i[d >> 1]|` over the edges
/// `i ≥ 1` of the facet (`ea_i = a_i − a_0`, `eb_i = b_i − b_0`, `σ = −1`
/// for odd `d`): the mismatch of sending axis `j` to direction `d`.
fn mismatch_table<const D: usize>(a: &[[f64; D]], b: &[[f64; D]]) -> [f64; 18] {
    let mut table = [0.0f64; 18];
    for i in 1..a.len() {
        let ea: [f64; D] = std::array::from_fn(|k| a[i][k] - a[0][k]);
        let eb: [f64; D] = std::array::from_fn(|k| b[i][k] - b[0][k]);
        for (j, row) in table.chunks_exact_mut(6).take(D).enumerate() {
            for (l, &ebl) in eb.iter().enumerate() {
                // `max` without its NaN branch (an entry is never NaN)
                let (plus, minus) = ((ea[j] - ebl).abs(), (-ea[j] - ebl).abs());
                if plus > row[2 * l] {
                    row[2 * l] = plus;
                }
                if minus > row[2 * l + 1] {
                    row[2 * l + 1] = minus;
                }
            }
        }
    }
    table
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::transition_derive::num;
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
    /// rotated, translated, perturbed copy, with collapsed corners at times.
    fn compare<const N: usize, const D: usize>(seed: u64, cases: usize) {
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
                let got = fit_facet(&map, &topo, 0, 0, &all, &opts);
                let want = reference(&map, &topo, 0, 0, &all, &opts);
                match (got, want) {
                    (Ok(g), Ok(w)) => {
                        assert_eq!(g.rot, w.0, "{map:?}");
                        assert_eq!(g.trans.map(f64::to_bits), w.1.map(f64::to_bits), "{map:?}");
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
        assert!(
            unique > 0 && several > 0 && errors > 0,
            "{unique} {several} {errors}"
        );
    }

    #[test]
    fn fit_matches_the_full_scan_2d() {
        compare::<3, 2>(1, 20000);
    }

    #[test]
    fn fit_matches_the_full_scan_3d() {
        compare::<4, 3>(2, 20000);
    }
}
