//! The transitions fitted where the topology glues a pair of facets: one
//! visit per interior facet, instead of a glue pass, a read-off pass and
//! a pass of fits over the read-off topology
//! ([`crate::transition_derive`], kept as the reference).
//!
//! Input: a validated map, its corner lists, the options. Output: its
//! [`Topology`] (or the glue's error), then its [`Transitions`] and
//! [`TransitionReport`] or the transitions' error: the same values, bit
//! for bit, and the same error, as `Topology::glue_with` followed by
//! `Transitions::derive`.
//!
//! Each glued pair `h1 < h2` (half-facet ids `s·N + f`; `h1`'s simplex
//! owns the facet, as in `derive`) is fitted by
//! [`crate::transition_fit::fit_pair`] in the glue's bucket order, not in
//! facet order: the counts go to an [`Unordered`] tally, whose merge is
//! commutative and gives what `derive`'s tally in facet order gives (the
//! ties and the first error by the least facet id). Only the fits that
//! are not the identity with a zero translation are kept, in a list
//! written into the transitions once the topology is read off (the rest
//! stay as initialised).

use crate::corners::{split, VertexCorners};
use crate::topology_build::{glue_into, PairSink};
use crate::transition::Derived;
use crate::transition_derive::{identity_transitions, non_integral, owns, resolve, set};
use crate::transition_fit::{fit_pair, Group, Pair};
use crate::transition_tally::{Ambiguous, FitResult};
use crate::{
    InputError, Rot, SimplexMap, Topology, TransitionOptions, TransitionReport, Transitions,
};

/// The topology (or the glue's error) and the transitions fitted where
/// each pair is glued (module docs).
pub(crate) fn glue_derive<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    corners: &VertexCorners,
    opts: &TransitionOptions,
) -> Result<(Topology<N>, Derived<N, D>), InputError> {
    let group = Group::<D>::new();
    let sink = || PairFits {
        group: &group,
        opts,
        tally: Unordered::default(),
    };
    let (topo, fits) = glue_into(map, corners, sink)?;
    let derived = fits.tally.finish(&topo, map.len(), opts);
    Ok((topo, derived))
}

/// The glue's sink of [`glue_derive`]: fits each glued pair.
struct PairFits<'a, const D: usize> {
    group: &'a Group<D>,
    opts: &'a TransitionOptions,
    tally: Unordered<D>,
}

impl<const N: usize, const D: usize> PairSink<N, D> for PairFits<'_, D> {
    #[inline]
    fn glued(&mut self, map: &SimplexMap<N, D>, h1: u32, h2: u32, corner: u32) {
        let ((s, f), (n, _)) = (split::<N>(h1), split::<N>(h2));
        let corner: [u8; N] = std::array::from_fn(|c| (corner >> (8 * c)) as u8);
        let pair = Pair {
            s,
            f,
            n,
            corner: &corner,
        };
        let fit = fit_pair(map, pair, self.group, self.opts);
        self.tally.add(h1, fit, self.opts);
    }

    fn then(mut self, later: Self) -> Self {
        self.tally = self.tally.merge(later.tally);
        self
    }
}

/// An ambiguous facet's candidates (`crate::transition_tally::Ambiguous`).
type Candidates<const D: usize> = Vec<(Rot<D>, [i64; D])>;

/// A fit other than the identity with a zero translation: the owner's
/// half-facet and the transition from the owner.
type Moved<const D: usize> = (u32, Rot<D>, [i64; D]);

/// What the fits of any set of facets found, in any order: `derive`'s
/// tally in facet order (`crate::transition_tally::Tally`) with each
/// "first" made "of the least facet id".
pub(crate) struct Unordered<const D: usize> {
    /// Fits whose rotation is not the identity.
    non_identity: usize,
    /// Residuals above the tolerance that are rounded.
    snapped: usize,
    /// The largest residual other than NaN, its least facet.
    worst: Option<(f64, u32)>,
    /// The least facet whose residual is NaN (the worst when it is the
    /// first fitted facet: a NaN is never replaced, nor replaces).
    nan: Option<u32>,
    /// The largest residual refused, its tolerance, its least facet.
    failed: Option<(f64, f64, u32)>,
    /// The error of the least facet.
    error: Option<(u32, Box<InputError>)>,
    /// The ambiguous facets, in any order.
    ambiguous: Vec<(u32, Candidates<D>)>,
    /// The fits to write ([`Moved`]).
    moved: Vec<Moved<D>>,
}

impl<const D: usize> Default for Unordered<D> {
    fn default() -> Self {
        Unordered {
            non_identity: 0,
            snapped: 0,
            worst: None,
            nan: None,
            failed: None,
            error: None,
            ambiguous: Vec::new(),
            moved: Vec::new(),
        }
    }
}

/// Whether `(x, h)` comes before `(y, k)`: a larger value, or an equal
/// one of a lesser facet.
#[inline]
fn before(x: f64, h: u32, y: f64, k: u32) -> bool {
    x > y || (x == y && h < k)
}

impl<const D: usize> Unordered<D> {
    /// Counts the fit of the facet `h1` (the owner's half-facet).
    #[inline]
    pub(crate) fn add(&mut self, h1: u32, fit: FitResult<D>, opts: &TransitionOptions) {
        let fit = match fit {
            Ok(fit) => fit,
            Err(e) => {
                self.keep_error(h1, e);
                return;
            }
        };
        let r = fit.residual;
        let identity = fit.rot.is_identity();
        self.non_identity += usize::from(!identity);
        if r.is_nan() {
            self.keep_nan(h1);
        } else {
            self.keep_worst(r, h1);
        }
        if r > fit.tol {
            if opts.rounds(r) {
                self.snapped += 1;
            } else {
                self.keep_failed(r, fit.tol, h1);
            }
        }
        if let Some(cands) = fit.ambiguous {
            self.ambiguous.push((h1, cands));
        }
        if !identity || fit.rounded != [0; D] {
            self.moved.push((h1, fit.rot, fit.rounded));
        }
    }

    /// The tally of both sets of facets (commutative).
    pub(crate) fn merge(mut self, other: Self) -> Self {
        self.non_identity += other.non_identity;
        self.snapped += other.snapped;
        if let Some((r, h)) = other.worst {
            self.keep_worst(r, h);
        }
        if let Some(h) = other.nan {
            self.keep_nan(h);
        }
        if let Some((r, tol, h)) = other.failed {
            self.keep_failed(r, tol, h);
        }
        if let Some((h, e)) = other.error {
            self.keep_error(h, e);
        }
        self.ambiguous.extend(other.ambiguous);
        self.moved.extend(other.moved);
        self
    }

    /// The residual `r` of facet `h` kept as the worst if it comes before
    /// ([`before`]) the one kept.
    #[inline]
    fn keep_worst(&mut self, r: f64, h: u32) {
        if self.worst.is_none_or(|(w, k)| before(r, h, w, k)) {
            self.worst = Some((r, h));
        }
    }

    /// Facet `h`, whose residual is NaN, kept if it is the least.
    #[inline]
    fn keep_nan(&mut self, h: u32) {
        self.nan = Some(self.nan.map_or(h, |k| k.min(h)));
    }

    /// The refused residual `r` (tolerance `tol`) of facet `h` kept if it
    /// comes before ([`before`]) the one kept.
    #[inline]
    fn keep_failed(&mut self, r: f64, tol: f64, h: u32) {
        if self.failed.is_none_or(|(w, _, k)| before(r, h, w, k)) {
            self.failed = Some((r, tol, h));
        }
    }

    /// The error of facet `h` kept if `h` is the least.
    #[inline]
    fn keep_error(&mut self, h: u32, e: Box<InputError>) {
        if self.error.as_ref().is_none_or(|x| h < x.0) {
            self.error = Some((h, e));
        }
    }

    /// The transitions of a map of `ns` simplices glued as `topo`, and
    /// their report, or the error `derive` returns.
    pub(crate) fn finish<const N: usize>(
        self,
        topo: &Topology<N>,
        ns: usize,
        opts: &TransitionOptions,
    ) -> Result<(Transitions<N, D>, TransitionReport), InputError> {
        if let Some((_, e)) = self.error {
            return Err(*e);
        }
        let mut tr = identity_transitions::<N, D>(ns);
        for &(h1, rot, t) in &self.moved {
            let (s, f) = split::<N>(h1);
            set(topo, &mut tr, s, f, rot, t);
        }
        // a NaN residual is the worst only as the first facet fitted
        let worst = match (self.nan, self.worst) {
            (Some(h), _) if h == first_owned(topo) => Some((f64::NAN, h)),
            (_, w) => w,
        };
        let mut rep = TransitionReport {
            max_residual: worst.map_or(0.0, |w| 0.0f64.max(w.0)),
            worst_facet: worst.map(|w| split::<N>(w.1)),
            snapped: self.snapped,
            ..Default::default()
        };
        if let Some((res, tol, h)) = self.failed {
            return Err(non_integral(topo, split::<N>(h), res, tol, opts));
        }
        let mut ambiguous = self.ambiguous;
        ambiguous.sort_unstable_by_key(|a| a.0);
        let ambiguous: Vec<Ambiguous<D>> = ambiguous
            .into_iter()
            .map(|(h, cands)| {
                let (s, f) = split::<N>(h);
                Ambiguous { s, f, cands }
            })
            .collect();
        resolve(topo, &mut tr, &ambiguous, self.non_identity, &mut rep);
        Ok((tr, rep))
    }
}

/// The least id `s·N + f` of a facet its simplex owns (interior, the
/// lesser side), `u32::MAX` when there is none.
fn first_owned<const N: usize>(topo: &Topology<N>) -> u32 {
    for (s, (adj, back)) in topo.adj.iter().zip(&topo.adj_facet).enumerate() {
        for f in 0..N {
            if owns(adj[f], back[f], s, f) {
                return (s * N + f) as u32;
            }
        }
    }
    u32::MAX
}

#[cfg(test)]
#[path = "transition_glue_tests.rs"]
mod tests;
