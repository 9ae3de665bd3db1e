//! Transitions between the charts of adjacent simplices.
//!
//! Across facet `f` of simplex `s` with neighbour `n`:
//! `chart(n) = rot[s][f] · chart(s) + trans[s][f]` (a point given in `s`'s
//! chart, re-expressed in `n`'s chart). The rotation is the one that best
//! matches the facet's edge vectors; the translation is rounded to the
//! nearest integer and the rounding error is the **residual**.
//!
//! Zero-length map facets (collapsed in both charts) do not determine the
//! rotation: it is chosen so that the translation is integral, then, where
//! still ambiguous, to minimise the number of singular endpoints (DESIGN §2b).
//!
//! Invariants: `rot[n][g] == rot[s][f].inverse()` and
//! `trans[n][g] == -(rot[n][g] · trans[s][f])` for each interior facet pair.

use crate::{topology::Topology, InputError, Rot, SimplexMap};

/// The transitions and their report, or the transitions' error
/// ([`Transitions::glue_derive`]).
pub type Derived<const N: usize, const D: usize> =
    Result<(Transitions<N, D>, TransitionReport), InputError>;

/// Options of transition derivation.
#[derive(Clone, Copy, Debug)]
pub struct TransitionOptions {
    /// Largest accepted residual of the translations at small coordinates;
    /// it grows with the float spacing of large ones, see
    /// [`TransitionOptions::tolerance_at`].
    pub tolerance: f64,
    /// Snap non-integer translations of any residual instead of failing
    /// (`--round-transitions`).
    pub round: bool,
    /// Largest residual rounded without `round` (counted in
    /// [`TransitionReport::snapped`], which callers report as a warning).
    pub round_limit: f64,
}

/// Residuals (map units) rounded by default: a noisy export of an exact
/// map (independent noise of a few 1e-3 on every corner) derives, with a
/// warning, while a chart off by a sizeable fraction of a cell is refused.
pub const ROUND_LIMIT: f64 = 0.1;

/// Largest rotation mismatch accepted with `round` (beyond it the charts
/// differ by more than noise: a reflection or a non-grid rotation).
pub const ROUND_FIT_LIMIT: f64 = 0.25;

impl Default for TransitionOptions {
    fn default() -> Self {
        TransitionOptions {
            tolerance: 1e-3,
            round: false,
            round_limit: ROUND_LIMIT,
        }
    }
}

impl TransitionOptions {
    /// Accepted residual where coordinates reach `magnitude` in absolute
    /// value: `tolerance + 64·ulp(magnitude)` (a map translated by 2^40 has
    /// float spacing 2^-12 there).
    pub fn tolerance_at(&self, magnitude: f64) -> f64 {
        self.tolerance + 64.0 * crate::transition_derive::ulp(magnitude)
    }

    /// Largest rotation mismatch accepted where the residual tolerance is
    /// `tol`: [`ROUND_FIT_LIMIT`] with `round`, else `round_limit` (noise
    /// that would be rounded must not be refused as a non-grid rotation).
    pub fn fit_tolerance(&self, tol: f64) -> f64 {
        tol.max(if self.round {
            ROUND_FIT_LIMIT
        } else {
            self.round_limit
        })
    }

    /// Whether a residual above the tolerance is rounded (else refused).
    pub fn rounds(&self, residual: f64) -> bool {
        self.round || residual <= self.round_limit
    }
}

/// Per-facet transitions (boundary facets hold the identity and zero).
#[derive(Clone, Debug, Default)]
pub struct Transitions<const N: usize, const D: usize> {
    /// Rotation across each facet.
    pub rot: Vec<[Rot<D>; N]>,
    /// Integer translation across each facet.
    pub trans: Vec<[[i64; D]; N]>,
}

/// What the derivation measured.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct TransitionReport {
    /// Largest residual of a translation from its nearest integer vector.
    pub max_residual: f64,
    /// Simplex and facet of the largest residual.
    pub worst_facet: Option<(usize, usize)>,
    /// Interior facet pairs whose translation was rounded: residual above
    /// the tolerance, up to `round_limit` (or any, with `round`).
    pub snapped: usize,
    /// Zero-length facets whose rotation was ambiguous.
    pub ambiguous_facets: usize,
    /// Interior facet pairs with a non-identity rotation.
    pub non_identity: usize,
}

impl<const N: usize, const D: usize> Transitions<N, D> {
    /// Derives the transitions; fails when a residual exceeds the tolerance
    /// (unless `round`), naming the worst facet and its residual.
    pub fn derive(
        map: &SimplexMap<N, D>,
        topo: &Topology<N>,
        opts: &TransitionOptions,
    ) -> Result<(Self, TransitionReport), InputError> {
        crate::transition_derive::derive(map, topo, opts)
    }

    /// The topology ([`Topology::glue_with`]: the vertex check left out)
    /// and the transitions ([`Self::derive`]) in one glue, each facet's
    /// transition fitted where its pair is glued: the glue's error, or
    /// the topology and the transitions or their error, the same values
    /// and errors as the two calls.
    pub fn glue_derive(
        map: &SimplexMap<N, D>,
        corners: &crate::corners::VertexCorners,
        opts: &TransitionOptions,
    ) -> Result<(Topology<N>, Derived<N, D>), InputError> {
        crate::transition_glue::glue_derive(map, corners, opts)
    }

    /// Maps a point of `s`'s chart into the chart of the neighbour across `f`.
    #[inline]
    pub fn apply(&self, s: usize, f: usize, p: &[f64; D]) -> [f64; D] {
        let mut q = self.rot[s][f].apply(p);
        for (k, qk) in q.iter_mut().enumerate() {
            *qk += self.trans[s][f][k] as f64;
        }
        q
    }
}
