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
//! ([`unique_fit`], and before it [`identity_fit`] for the identity
//! transitions of most facets) only answers when exactly one rotation is
//! within `tol` of the best, and then both agree on it and on the best
//! mismatch.

use crate::error::{ElementKind, MapError};
use crate::transition::ROUND_FIT_LIMIT;
use crate::transition_same::{same_charts_fit, same_fits};
use crate::{InputError, Rot, SimplexMap, Topology, TransitionOptions};
use dualex_util::round::round;

/// The chosen transition of one facet and what it measured.
pub(crate) struct Fit<const D: usize> {
    pub(crate) rot: Rot<D>,
    /// The translation before rounding (read by the tests).
    #[cfg(test)]
    pub(crate) trans: [f64; D],
    /// The translation rounded to the nearest integers.
    pub(crate) rounded: [i64; D],
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

/// [`rounded`] and [`residual_of`] with one rounding per coordinate.
fn rounded_with_residual<const D: usize>(t: &[f64; D]) -> ([i64; D], f64) {
    let mut residual = 0.0f64;
    let r = t.map(|x| {
        let r = round(x);
        residual = residual.max((x - r).abs());
        r as i64
    });
    (r, residual)
}

/// Size of the largest rotation group (24 in 3D).
const MAX_ROTATIONS: usize = 24;

/// The rotation group in [`Rot::all`] order (identity first) and, per
/// axis `j` and direction `d`, the set of its rotations sending `j` to
/// `d` as bits (bit `r` for `all[r]`): the rotations whose every axis goes
/// to an allowed direction are the AND over the axes of the OR of their
/// allowed directions' sets, with no scan of the group.
pub(crate) struct Group<const D: usize> {
    /// The rotations, identity first.
    pub(crate) all: Vec<Rot<D>>,
    /// `by_dir[j][d]`: the rotations sending axis `j` to direction `d`.
    by_dir: [[u32; 6]; D],
    /// Per set of terms within the cut of a facet with equal charts, as
    /// bits: whether a rotation other than the identity fits
    /// ([`crate::transition_same`]).
    pub(crate) same_fits: [u64; 8],
}

impl<const D: usize> Group<D> {
    /// The group of dimension `D` and its direction sets.
    pub(crate) fn new() -> Self {
        let all = Rot::<D>::all();
        let mut by_dir = [[0u32; 6]; D];
        for (r, rot) in all.iter().enumerate() {
            for (j, &d) in rot.images().iter().enumerate() {
                by_dir[j][d as usize] |= 1 << r;
            }
        }
        let same_fits = same_fits(&all);
        Group {
            all,
            by_dir,
            same_fits,
        }
    }
}

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
    group: &Group<D>,
    opts: &TransitionOptions,
) -> Result<Fit<D>, Box<InputError>> {
    let n = topo.adj[s][f] as usize;
    let pair = Pair {
        s,
        f,
        n,
        corner: &topo.nbr_corner[s][f],
    };
    fit_pair(map, pair, group, opts)
}

/// An interior facet to fit: facet `f` of `s`, its neighbour `n` and the
/// corner map to it (`corner[c]`: the corner of `n` holding corner `c`'s
/// vertex, as in `Topology::nbr_corner`).
#[derive(Clone, Copy)]
pub(crate) struct Pair<'a, const N: usize> {
    pub(crate) s: usize,
    pub(crate) f: usize,
    pub(crate) n: usize,
    pub(crate) corner: &'a [u8; N],
}

/// [`fit_facet`] of the facet `pair`, given its neighbour and corner map
/// (where a pair is glued, before the topology is read off).
#[inline]
pub(crate) fn fit_pair<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    Pair { s, f, n, corner }: Pair<'_, N>,
    group: &Group<D>,
    opts: &TransitionOptions,
) -> Result<Fit<D>, Box<InputError>> {
    let all = &group.all[..];
    let m = N - 1;
    // a[i], b[i] for i < m: the facet's corners in the charts of s and n
    let (cs, cn) = (&map.coords[s], &map.coords[n]);
    let mut a = [[0.0f64; D]; N];
    let mut b = [[0.0f64; D]; N];
    let mut scale = 0.0f64;
    // any bit where the two charts' corners differ
    let mut differ = 0u64;
    for i in 0..m {
        let c = (f + 1 + i) % N;
        a[i] = cs[c];
        b[i] = cn[corner[c] as usize];
        for k in 0..D {
            // `max` without its NaN branch: the same result from 0.0
            let x = a[i][k].abs();
            if x > scale {
                scale = x;
            }
            differ |= a[i][k].to_bits() ^ b[i][k].to_bits();
        }
    }
    if differ != 0 {
        // the other chart's corners (the same floats when none differs)
        scale = b[..m].iter().flatten().fold(
            scale,
            |scale, y| {
                if y.abs() > scale {
                    y.abs()
                } else {
                    scale
                }
            },
        );
    }
    let tol = opts.tolerance_at(scale);
    if differ == 0 && scale <= SAME_LIMIT {
        if let Some(fit) = same_charts_fit(&a[..m], tol, group) {
            return Ok(fit);
        }
    }
    let table = mismatch_table(&a[..m], &b[..m]);
    let mut mis = [0.0f64; MAX_ROTATIONS];
    let fast = match identity_fit::<D>(&table, tol, group) {
        Some(best) => Some((Rot::IDENTITY, best)),
        None => unique_fit::<D>(&table, tol),
    };
    let (best, unique) = match fast {
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
        let identity = r.is_identity();
        for i in 0..m {
            // the identity copies `a[i]`: the same floats without the
            // signed permutation
            let ra = if identity { a[i] } else { r.apply(&a[i]) };
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
        let (rounded, residual) = rounded_with_residual(&trans);
        return Ok(Fit {
            rot,
            #[cfg(test)]
            trans,
            rounded,
            residual,
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
        #[cfg(test)]
        trans: chosen.2,
        rounded: rounded(&chosen.2),
        residual: chosen.3,
        tol,
        ambiguous,
    })
}

/// Largest coordinate of a facet taken by [`same_charts_fit`]: its edge
/// vectors and their sums stay finite (no NaN in the table).
const SAME_LIMIT: f64 = 1e300;

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

/// The fast path of the common case, an identity transition: `Some(best)`
/// when the identity is the only rotation within `tol` of the best
/// mismatch, which is then its own, `mis(I)` (what scanning the whole
/// group finds): when no other rotation of the group sends every axis `j`
/// to a direction whose entry is within the cut `mis(I) + tol` (the
/// rotations that do are found by their bits, [`Group`]). `None` leaves
/// the facet to [`unique_fit`].
#[inline]
fn identity_fit<const D: usize>(table: &[f64; 18], tol: f64, group: &Group<D>) -> Option<f64> {
    if tol.is_nan() || tol < 0.0 {
        return None;
    }
    let best = mismatch_of(table, &Rot::<D>::IDENTITY.images());
    let cut = best + tol;
    // the rotations other than the identity (bit 0) that send every axis
    // within the cut
    debug_assert!(group.all.first().is_some_and(Rot::is_identity));
    let mut fits = !1u32;
    for (row, sets) in table.chunks_exact(6).zip(&group.by_dir) {
        let mut axis = 0u32;
        for (&x, &set) in row[..2 * D].iter().zip(sets) {
            axis |= set & 0u32.wrapping_sub(u32::from(x <= cut));
        }
        fits &= axis;
    }
    (fits == 0).then_some(best)
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
#[path = "transition_fit_tests.rs"]
mod tests;
