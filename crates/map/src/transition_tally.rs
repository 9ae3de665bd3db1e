//! What the fits of a run of facets found, for the report and the errors
//! of [`crate::transition_derive`], gathered per simplex in parallel and
//! combined in facet order.
//!
//! Input: the fits ([`Fit`]) or errors of interior facets, in facet order
//! (a simplex's facets in order, simplices in order). Output: [`Tally`]:
//! the counts, the first facet with the largest residual, the first with
//! the largest residual that is neither within the tolerance nor rounded,
//! the first error, the ambiguous facets in order.
//!
//! Invariant: [`Tally::then`] is associative, and folding the facets one
//! by one ([`Tally::add`]) in any grouping gives what one sequential loop
//! in facet order gives (ties keep the earlier facet).

use crate::transition_fit::Fit;
use crate::{InputError, Rot, TransitionOptions};

/// The fit of one interior facet, or the error it found.
pub(crate) type FitResult<const D: usize> = Result<Fit<D>, Box<InputError>>;

/// A facet whose rotation is not determined by its edge vectors.
pub(crate) struct Ambiguous<const D: usize> {
    pub(crate) s: usize,
    pub(crate) f: usize,
    /// Rotations with an integral translation, and that translation.
    pub(crate) cands: Vec<(Rot<D>, [i64; D])>,
}

/// What the fits of a run of facets found (module docs).
#[derive(Default)]
pub(crate) struct Tally<const D: usize> {
    /// Fits whose rotation is not the identity.
    pub(crate) non_identity: usize,
    /// Residuals above the tolerance that are rounded.
    pub(crate) snapped: usize,
    /// The largest residual and its first facet `(residual, s, f)`.
    pub(crate) worst: Option<(f64, usize, usize)>,
    /// The largest residual refused, its first facet and its tolerance
    /// `(residual, tol, s, f)`.
    pub(crate) failed: Option<(f64, f64, usize, usize)>,
    /// The first error.
    pub(crate) error: Option<Box<InputError>>,
    /// The ambiguous facets, in order.
    pub(crate) ambiguous: Vec<Ambiguous<D>>,
}

impl<const D: usize> Tally<D> {
    /// Counts the fit of facet `f` of `s` (the next facet in order) and
    /// returns its transition (the identity and zero for an error).
    pub(crate) fn add(
        &mut self,
        s: usize,
        f: usize,
        fit: FitResult<D>,
        opts: &TransitionOptions,
    ) -> (Rot<D>, [i64; D]) {
        let fit = match fit {
            Ok(fit) => fit,
            Err(e) => {
                self.error.get_or_insert(e);
                return (Rot::IDENTITY, [0; D]);
            }
        };
        self.non_identity += usize::from(!fit.rot.is_identity());
        if self.worst.is_none_or(|w| fit.residual > w.0) {
            self.worst = Some((fit.residual, s, f));
        }
        if fit.residual > fit.tol {
            if opts.rounds(fit.residual) {
                self.snapped += 1;
            } else if self.failed.is_none_or(|w| fit.residual > w.0) {
                self.failed = Some((fit.residual, fit.tol, s, f));
            }
        }
        if let Some(cands) = fit.ambiguous {
            self.ambiguous.push(Ambiguous { s, f, cands });
        }
        (fit.rot, fit.rounded)
    }

    /// This run followed by `later` (the facets after it).
    pub(crate) fn then(mut self, later: Self) -> Self {
        if self.error.is_some() {
            return self;
        }
        if later.error.is_some() {
            return later;
        }
        self.non_identity += later.non_identity;
        self.snapped += later.snapped;
        if let Some(w) = later.worst {
            if self.worst.is_none_or(|v| w.0 > v.0) {
                self.worst = Some(w);
            }
        }
        if let Some(w) = later.failed {
            if self.failed.is_none_or(|v| w.0 > v.0) {
                self.failed = Some(w);
            }
        }
        self.ambiguous.extend(later.ambiguous);
        self
    }
}
