//! Derivation of [`Transitions`] from the per-corner map coordinates.
//!
//! Input: a validated map and its [`Topology`]. Output: the transitions of
//! every interior facet (both directions, invariant of [`crate::transition`])
//! and a [`TransitionReport`], or an [`InputError`] naming the facet.
//!
//! Per interior facet, with `a_i` / `b_i` the facet's corners in the charts of
//! `s` and of its neighbour `n` (matched through `nbr_corner`):
//! 1. **Fit**: for each grid rotation `R`, the mismatch
//!    `max_i |R(a_i − a_0) − (b_i − b_0)|∞`. The best mismatch must be within
//!    the fit tolerance ([`TransitionOptions::fit_tolerance`]: the rounding
//!    limit below; with `round`, 1/4), else the charts differ by a reflection
//!    or a non-grid rotation.
//! 2. **Candidates**: the rotations whose mismatch is within `tol` of the
//!    best. More than one only when the facet's edge vectors do not determine
//!    `R` (zero-length edge in 2D, collapsed or collinear face in 3D).
//! 3. `T(R) = mean_i (b_i − R a_i)`; **residual** `= max |T − round(T)|`.
//!    Among several candidates keep those with an integral `T`; if several
//!    remain the facet is **ambiguous**, resolved by [`fix_ambiguous`].
//!
//! **Tolerance** (accepted residual) of a facet:
//! `opts.tolerance + 64·ulp(max |coordinate| of the facet's corners in both
//! charts)`, so that a map translated by 2^40 still derives while a residual
//! of 0.3 fails. A residual above it is rounded (`T` snapped, the facet
//! counted in `snapped`, for the caller to warn) up to `opts.round_limit`
//! (0.1 by default), or whatever it is with `opts.round`; a larger one is an
//! error naming the worst facet. The fit of step 1 accepts a mismatch up to
//! the same limit (1/4 with `round`), so that noise that would be rounded is
//! not refused as a non-grid rotation.

use crate::error::{ElementKind, MapError};
use crate::holonomy::ridge_rotation;
use crate::topology::NONE;
use crate::transition_fit::{fit_facet, Group};
use rayon::prelude::*;

/// Simplices whose facets are fitted in one parallel batch (bounds the
/// memory of the fits waiting to be written).
const BATCH: usize = 1 << 13;
use crate::transition_tally::{Ambiguous, Tally};
use crate::{
    InputError, Rot, SimplexMap, Topology, TransitionOptions, TransitionReport, Transitions,
};

/// Per simplex of a batch, the transition across each facet it owns.
type Owned<const N: usize, const D: usize> = [(Rot<D>, [i64; D]); N];

/// Distance from `x` to the next larger float (`x ≥ 0`).
pub(crate) fn ulp(x: f64) -> f64 {
    let x = x.abs();
    if !x.is_finite() {
        return f64::INFINITY;
    }
    f64::from_bits(x.to_bits() + 1) - x
}

/// A number for messages: rounded to 6 decimals, always with a point.
pub(crate) fn num(x: f64) -> String {
    let s = format!("{}", (x * 1e6).round() / 1e6);
    if s.contains('.') || s.contains('e') || !x.is_finite() {
        s
    } else {
        format!("{s}.0")
    }
}

pub(crate) fn derive<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    opts: &TransitionOptions,
) -> Result<(Transitions<N, D>, TransitionReport), InputError> {
    let ns = map.len();
    // every interior entry is written below, the boundary's stay as they
    // are
    let mut tr = identity_transitions(ns);
    let mut rep = TransitionReport::default();
    let group = Group::<D>::new();
    // the fits of a batch in parallel, in place into one buffer reused by
    // every batch (no new pages), counted per run of simplices and
    // combined in facet order (the first error returned is the one of a sequential
    // loop), then written into the batch's simplices in parallel
    let mut tally = Tally::<D>::default();
    let none: Owned<N, D> = [(Rot::IDENTITY, [0; D]); N];
    let mut fits: Vec<Owned<N, D>> = vec![none; BATCH.min(ns)];
    for lo in (0..ns).step_by(BATCH) {
        let hi = ns.min(lo + BATCH);
        // a slot's entries of the facets its simplex owns are written
        // here, the only ones `write_batch` reads (the others keep what
        // an earlier batch left)
        let batch = fits[..hi - lo]
            .par_iter_mut()
            .enumerate()
            .fold(Tally::default, |mut t, (i, slot)| {
                let s = lo + i;
                // the rows of `s`, read once for its facets
                let (adj, back) = (&topo.adj[s], &topo.adj_facet[s]);
                for (f, out) in slot.iter_mut().enumerate() {
                    if owns(adj[f], back[f], s, f) {
                        *out = t.add(s, f, fit_facet(map, topo, s, f, &group, opts), opts);
                    }
                }
                t
            })
            .reduce(Tally::default, Tally::then);
        tally = tally.then(batch);
        if let Some(e) = tally.error.take() {
            return Err(*e);
        }
        write_batch(topo, &mut tr, &fits[..hi - lo], lo);
    }
    rep.max_residual = tally.worst.map_or(0.0, |w| 0.0f64.max(w.0));
    rep.worst_facet = tally.worst.map(|w| (w.1, w.2));
    rep.snapped = tally.snapped;
    if let Some((res, tol, s, f)) = tally.failed {
        return Err(non_integral(topo, (s, f), res, tol, opts));
    }
    resolve(
        topo,
        &mut tr,
        &tally.ambiguous,
        tally.non_identity,
        &mut rep,
    );
    Ok((tr, rep))
}

/// The error of facet `f` of `s` whose residual `res` is above its
/// tolerance `tol` and not rounded.
pub(crate) fn non_integral<const N: usize>(
    topo: &Topology<N>,
    (s, f): (usize, usize),
    res: f64,
    tol: f64,
    opts: &TransitionOptions,
) -> InputError {
    MapError::NonIntegralTransition {
        simplex: ElementKind::simplex(N).at(s),
        facet: f,
        neighbour: topo.adj[s][f] as usize,
        residual: res,
        tolerance: tol,
        round_limit: opts.round_limit,
    }
    .into()
}

/// Resolves the ambiguous facets (in facet order) and counts them and
/// the non-identity rotations (`non_identity` of the fits) in `rep`.
pub(crate) fn resolve<const N: usize, const D: usize>(
    topo: &Topology<N>,
    tr: &mut Transitions<N, D>,
    ambiguous: &[Ambiguous<D>],
    non_identity: usize,
    rep: &mut TransitionReport,
) {
    rep.ambiguous_facets = ambiguous.len();
    // the ambiguous facets' rotations may change: counted again after
    let changing = |tr: &Transitions<N, D>| {
        ambiguous
            .iter()
            .filter(|a| !tr.rot[a.s][a.f].is_identity())
            .count()
    };
    let non_identity = non_identity - changing(tr);
    fix_ambiguous(topo, tr, ambiguous, 3);
    rep.non_identity = non_identity + changing(tr);
}

/// The transitions of `ns` simplices, all the identity: the rotations
/// written as one block of zero bytes (the identity's rank is 0), the
/// translations zeroed by the allocator (fresh pages, first touched by
/// the writes of the fits).
pub(crate) fn identity_transitions<const N: usize, const D: usize>(ns: usize) -> Transitions<N, D> {
    Transitions {
        rot: vec![[Rot::<D>::IDENTITY; N]; ns],
        trans: vec![[[0i64; D]; N]; ns],
    }
}

/// Writes the transitions of simplices `lo..lo + fits.len()` (in
/// parallel, each simplex its own entries): across a facet it owns (the
/// greater side: `(n, g) > (s, f)`) its fit, across the others the
/// inverse of the owner's fit, which is in `fits` (same batch) or in `tr`
/// (an earlier batch).
fn write_batch<const N: usize, const D: usize>(
    topo: &Topology<N>,
    tr: &mut Transitions<N, D>,
    fits: &[Owned<N, D>],
    lo: usize,
) {
    let hi = lo + fits.len();
    let (done_rot, rot) = tr.rot.split_at_mut(lo);
    let (done_trans, trans) = tr.trans.split_at_mut(lo);
    let (done_rot, done_trans) = (&*done_rot, &*done_trans);
    rot[..hi - lo]
        .par_iter_mut()
        .zip(&mut trans[..hi - lo])
        .enumerate()
        .for_each(|(i, (rot, trans))| {
            let s = lo + i;
            let (adj, back) = (&topo.adj[s], &topo.adj_facet[s]);
            for f in 0..N {
                if adj[f] == NONE {
                    continue;
                }
                let (n, g) = (adj[f] as usize, usize::from(back[f]));
                (rot[f], trans[f]) = if owns(adj[f], back[f], s, f) {
                    fits[i][f]
                } else if n >= lo {
                    inverse(fits[n - lo][g])
                } else {
                    inverse((done_rot[n][g], done_trans[n][g]))
                };
            }
        });
}

/// Whether simplex `s` owns its facet `f`, whose neighbour is `n` (or
/// [`NONE`]) across its facet `g`: the facet is interior and `(n, g) >
/// (s, f)` (the owner's fit is the one derived).
#[inline]
pub(crate) fn owns(n: u32, g: u8, s: usize, f: usize) -> bool {
    n != NONE && (n as usize, usize::from(g)) > (s, f)
}

/// The transition back across a facet, from the one across it.
#[inline]
pub(crate) fn inverse<const D: usize>((rot, t): (Rot<D>, [i64; D])) -> (Rot<D>, [i64; D]) {
    // the identity is its own inverse and leaves `t` as it is
    let (inv, back) = if rot.is_identity() {
        (rot, t)
    } else {
        let inv = rot.inverse();
        (inv, inv.apply_i(&t))
    };
    (inv, back.map(|x| -x))
}

/// Stores the transition across facet `f` of `s` and its inverse.
pub(crate) fn set<const N: usize, const D: usize>(
    topo: &Topology<N>,
    tr: &mut Transitions<N, D>,
    s: usize,
    f: usize,
    rot: Rot<D>,
    t: [i64; D],
) {
    let Some((n, g)) = topo.neighbour(s, f) else {
        panic!("bug: transition on boundary facet {f} of simplex {s}");
    };
    tr.rot[s][f] = rot;
    tr.trans[s][f] = t;
    (tr.rot[n][g], tr.trans[n][g]) = inverse((rot, t));
}

/// Chooses, for each ambiguous facet, the candidate that minimises the number
/// of singular ridges through it (2D: its endpoints; 3D: its edges), a few
/// passes until nothing changes.
fn fix_ambiguous<const N: usize, const D: usize>(
    topo: &Topology<N>,
    tr: &mut Transitions<N, D>,
    ambiguous: &[Ambiguous<D>],
    passes: usize,
) {
    for _ in 0..passes {
        let mut changed = 0;
        for amb in ambiguous {
            let current = tr.rot[amb.s][amb.f];
            let mut best: Option<(usize, usize)> = None;
            for (i, (r, t)) in amb.cands.iter().enumerate() {
                set(topo, tr, amb.s, amb.f, *r, *t);
                let score = singular_ridges(topo, tr, amb.s, amb.f);
                if best.is_none_or(|b| score < b.0) {
                    best = Some((score, i));
                }
            }
            let Some((_, i)) = best else { continue };
            let (r, t) = amb.cands[i];
            set(topo, tr, amb.s, amb.f, r, t);
            if r != current {
                changed += 1;
            }
        }
        if changed == 0 {
            break;
        }
    }
}

/// Number of interior ridges of facet `f` of `s` with a non-identity holonomy.
fn singular_ridges<const N: usize, const D: usize>(
    topo: &Topology<N>,
    tr: &Transitions<N, D>,
    s: usize,
    f: usize,
) -> usize {
    let corners: Vec<usize> = (1..N).map(|i| (f + i) % N).collect();
    let singular =
        |ridge: &[usize]| ridge_rotation(topo, tr, s, ridge).is_some_and(|r| !r.is_identity());
    if N == 3 {
        corners.iter().filter(|&&c| singular(&[c])).count()
    } else {
        let mut count = 0;
        for i in 0..corners.len() {
            for j in i + 1..corners.len() {
                count += usize::from(singular(&[corners[i], corners[j]]));
            }
        }
        count
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_maps::{grid, rechart, tet_cube};
    use crate::Stars;

    /// Derives and checks every interior transition against the known
    /// per-simplex re-charting: `rot = R_s⁻¹ then R_n`, `T = t_n − rot·t_s`.
    fn check_rechart<const N: usize, const D: usize>(
        map: &mut SimplexMap<N, D>,
        seed: u64,
        offset: f64,
    ) {
        let charts = rechart(map, seed);
        for p in map.coords.iter_mut().flatten().flatten() {
            *p += offset;
        }
        let topo = Topology::build(map).expect("topology");
        let opts = TransitionOptions::default();
        let (tr, rep) = derive(map, &topo, &opts).expect("transitions");
        assert_eq!(rep.max_residual, 0.0);
        assert_eq!(rep.snapped, 0);
        let mut seen = std::collections::BTreeSet::new();
        for s in 0..map.len() {
            for f in 0..N {
                let Some((n, _)) = topo.neighbour(s, f) else {
                    continue;
                };
                let (rs, ts) = charts[s];
                let (rn, tn) = charts[n];
                let rot = rs.inverse().then(&rn);
                // the offset o is added in both charts: T gains o − rot·o
                let o = [offset; D];
                let ro = rot.apply(&o);
                let rts = rot.apply_i(&ts);
                let t: [i64; D] = std::array::from_fn(|k| tn[k] - rts[k] + (o[k] - ro[k]) as i64);
                assert_eq!(tr.rot[s][f], rot, "simplex {s} facet {f}");
                assert_eq!(tr.trans[s][f], t, "simplex {s} facet {f}");
                seen.insert(rot);
            }
        }
        assert_eq!(seen.len(), Rot::<D>::all().len(), "every rotation occurs");
        let stars = Stars::build(map, &topo, &tr);
        assert!(stars.singular.iter().all(|&x| !x), "no singular vertex");
    }

    #[test]
    fn all_rotations_2d() {
        for seed in 1..4 {
            check_rechart(&mut grid(6), seed, 0.0);
        }
    }

    #[test]
    fn all_rotations_3d() {
        check_rechart(&mut tet_cube(3), 7, 0.0);
    }

    #[test]
    fn far_translation_still_derives() {
        let big = (1u64 << 40) as f64;
        check_rechart(&mut grid(6), 3, big);
        check_rechart(&mut tet_cube(3), 5, big);
    }

    #[test]
    fn residual_fails_or_snaps() {
        let mut m = grid(4);
        rechart(&mut m, 2);
        // an interior triangle (its 3 edges are interior)
        let s = 2 * (4 + 1);
        for p in m.coords[s].iter_mut() {
            p[0] += 0.3;
        }
        let topo = Topology::build(&m).expect("topology");
        let e = derive(&m, &topo, &TransitionOptions::default()).expect_err("residual 0.3");
        assert!(
            e.to_string()
                .contains("is not integral (residual 0.3 > tolerance 0.001"),
            "{e}"
        );
        assert!(e.to_string().starts_with("triangle "), "{e}");
        let opts = TransitionOptions {
            round: true,
            ..Default::default()
        };
        let (_, rep) = derive(&m, &topo, &opts).expect("rounded");
        assert_eq!(rep.snapped, 3);
        assert!((rep.max_residual - 0.3).abs() < 1e-12);
    }

    /// Residuals up to the rounding limit are rounded without `round`; a
    /// noisy rotation is not refused as a non-grid one, and the message for
    /// a larger mismatch suggests `--round-transitions` when it would help.
    #[test]
    fn small_residuals_round_by_default() {
        let mut m = grid(4);
        rechart(&mut m, 2);
        let s = 2 * (4 + 1);
        for p in m.coords[s].iter_mut() {
            p[0] += 0.05;
        }
        let topo = Topology::build(&m).expect("topology");
        let (_, rep) = derive(&m, &topo, &TransitionOptions::default()).expect("rounded");
        assert_eq!(rep.snapped, 3);
        assert!((rep.max_residual - 0.05).abs() < 1e-12);
        // one corner moved by 0.2: a mismatch of 0.2 (above 0.1, below ¼)
        m.coords[s][0][1] += 0.2;
        let e = derive(&m, &topo, &TransitionOptions::default()).expect_err("mismatch 0.2");
        assert!(
            e.to_string().contains("non-grid rotation (mismatch 0.2"),
            "{e}"
        );
        assert!(
            e.to_string()
                .contains("--round-transitions would accept it"),
            "{e}"
        );
        let opts = TransitionOptions {
            round: true,
            ..Default::default()
        };
        derive(&m, &topo, &opts).expect("rounded with --round-transitions");
    }

    #[test]
    fn reflection_is_an_error() {
        let m = SimplexMap::<3, 2> {
            positions: vec![[0.0; 3]; 4],
            simplices: vec![[0, 1, 2], [2, 1, 3]],
            // triangle 1: vertices 1, 2 swapped in u and v (a mirror image)
            coords: vec![
                [[0.0, 0.0], [2.0, 0.0], [0.0, 1.0]],
                [[1.0, 0.0], [0.0, 2.0], [2.0, 1.0]],
            ],
        };
        let topo = Topology::build(&m).expect("topology");
        let e = derive(&m, &topo, &TransitionOptions::default()).expect_err("reflection");
        assert_eq!(
            e.to_string(),
            "triangle 0 edge 0: the charts of triangles 0 and 1 differ by a reflection or a \
             non-grid rotation (mismatch 1.0)"
        );
    }

    #[test]
    fn collapsed_edge_is_resolved() {
        // collapse interior edge (6, 12) of a 4×4 grid onto the grid point of
        // vertex 6, then re-chart: the edge's rotation is ambiguous
        let mut m = grid(4);
        let target = [1.0, 1.0];
        for (s, simplex) in m.simplices.iter().enumerate() {
            for (c, &v) in simplex.iter().enumerate() {
                if v == 12 {
                    m.coords[s][c] = target;
                }
            }
        }
        rechart(&mut m, 11);
        let topo = Topology::build(&m).expect("topology");
        let (tr, rep) = derive(&m, &topo, &TransitionOptions::default()).expect("derive");
        assert_eq!(rep.ambiguous_facets, 1);
        let stars = Stars::build(&m, &topo, &tr);
        let singular: Vec<usize> = (0..stars.singular.len())
            .filter(|&v| stars.singular[v])
            .collect();
        assert_eq!(singular, Vec::<usize>::new());
    }

    #[test]
    fn tolerance_scales() {
        assert_eq!(ulp(1.0), f64::EPSILON);
        assert_eq!(ulp((1u64 << 40) as f64), 2f64.powi(-12));
        assert_eq!(num(2.0), "2.0");
        assert_eq!(num(0.3), "0.3");
    }
}
