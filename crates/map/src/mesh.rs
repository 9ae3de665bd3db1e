//! The input model: a simplicial mesh (triangles in 3-space or tetrahedra)
//! with map coordinates per simplex corner.
//!
//! `N` is the number of corners of a simplex and `D` the map dimension
//! (`N = D + 1`; stable Rust cannot express that, so both are parameters and
//! only [`TriMap`] and [`TetMap`] are used).
//!
//! Numbering, shared by every crate:
//! ```text
//!   corner c of simplex s: simplices[s][c] (vertex), coords[s][c] (map value)
//!   facet f of simplex s:  the facet opposite corner f
//!        triangle: edge f = (c[f+1], c[f+2])      tet: face f = the other 3
//! ```
//! Invariants checked by [`SimplexMap::validate`]: indices in range, no
//! repeated vertex in a simplex, every position and map coordinate finite.

use crate::error::{CountError, ElementKind, IndexError, InputError, InputErrorKind, MapError};
use crate::transition_derive::ulp;
use rayon::prelude::*;

pub use crate::reflect::{FOLDED_FLAT, FOLDED_SIGNED};

/// A simplicial mesh with per-corner map coordinates.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct SimplexMap<const N: usize, const D: usize> {
    /// Vertex positions in 3-space.
    pub positions: Vec<[f64; 3]>,
    /// Vertex indices of each simplex (consistently oriented).
    pub simplices: Vec<[u32; N]>,
    /// Map coordinates of each corner of each simplex, in that simplex's chart.
    pub coords: Vec<[[f64; D]; N]>,
}

/// Most grid points the simplices' map images may span in total; beyond
/// it a map is refused up front (see [`SimplexMap::check_grid_size`]).
pub const MAX_GRID_POINTS: f64 = (1u64 << 28) as f64;

/// A triangle mesh with a 2D map (`u, v` per corner).
pub type TriMap = SimplexMap<3, 2>;
/// A tetrahedral mesh with a 3D map (`u, v, w` per corner).
pub type TetMap = SimplexMap<4, 3>;

impl<const N: usize, const D: usize> SimplexMap<N, D> {
    /// Number of simplices.
    pub fn len(&self) -> usize {
        self.simplices.len()
    }

    /// Whether there is no simplex.
    pub fn is_empty(&self) -> bool {
        self.simplices.is_empty()
    }

    /// Checks the invariants of the module docs; the error names the element.
    pub fn validate(&self) -> Result<(), InputError> {
        self.validate_vertices()?;
        match first_where(self.len(), |s| !self.simplex_ok(s)) {
            Some(s) => Err(self.simplex_error(s)),
            None => Ok(()),
        }
    }

    /// The checks of [`SimplexMap::validate`] before the simplices': the
    /// counts agree, there is a simplex, every position is finite.
    pub(crate) fn validate_vertices(&self) -> Result<(), InputError> {
        let w = ElementKind::simplex(N);
        if self.coords.len() != self.simplices.len() {
            return Err(CountError::MapCoordinates {
                simplex: w,
                simplices: self.simplices.len(),
                coords: self.coords.len(),
            }
            .into());
        }
        if self.simplices.is_empty() {
            return Err(CountError::Empty {
                what: w,
                reason: None,
            }
            .into());
        }
        // the first bad element found in parallel, its error as the
        // sequential loops name it
        let bad_position = |i: usize| self.positions[i].iter().any(|x| !x.is_finite());
        match first_where(self.positions.len(), bad_position) {
            Some(i) => {
                let p = self.positions[i];
                let e = ElementKind::Vertex
                    .at(i)
                    .error(MapError::NonFinitePosition(p));
                Err(e.into())
            }
            None => Ok(()),
        }
    }

    /// Whether simplex `s` keeps the invariants of the module docs.
    #[inline(always)]
    pub(crate) fn simplex_ok(&self, s: usize) -> bool {
        let simplex = &self.simplices[s];
        let nv = self.positions.len();
        let mut ok = distinct_corners(simplex);
        for &v in simplex {
            ok &= (v as usize) < nv;
        }
        // (no early exit: the tests are branch-free)
        for c in &self.coords[s] {
            for x in c {
                ok &= x.is_finite();
            }
        }
        ok
    }

    /// The first invariant simplex `s` breaks (module docs), in corner
    /// order; `s` must break one.
    #[cold]
    pub(crate) fn simplex_error(&self, s: usize) -> InputError {
        let w = ElementKind::simplex(N);
        let nv = self.positions.len();
        let simplex = &self.simplices[s];
        let at = |what: InputErrorKind| InputError::new(w.clone().at(s).error(what));
        for (c, &v) in simplex.iter().enumerate() {
            if v as usize >= nv {
                return IndexError::RefersToVertex {
                    owner: w.clone().at(s),
                    corner: Some(c),
                    vertex: v.into(),
                    count: nv,
                }
                .into();
            }
            if simplex[..c].contains(&v) {
                return at(MapError::RepeatedVertex { vertex: v }.into());
            }
            if self.coords[s][c].iter().any(|x| !x.is_finite()) {
                return at(MapError::NonFiniteMapCoordinate { corner: c }.into());
            }
        }
        panic!("bug: simplex {s} keeps the invariants")
    }

    /// Vertex indices of facet `f` of simplex `s` (the corners other than `f`,
    /// in cyclic order starting after `f`).
    pub fn facet_corners(f: usize) -> [usize; N]
    where
        [usize; N]: Sized,
    {
        std::array::from_fn(|i| (f + 1 + i) % N)
    }

    /// Estimates, before any allocation, how many grid points the map
    /// images span (per simplex the product over the axes of extent + 1,
    /// summed): the work of node finding and sanitization, and a bound on
    /// the node count. Returns it, or an error naming the largest simplex
    /// when it exceeds [`MAX_GRID_POINTS`] (e.g. a triangle spanning
    /// 10⁹ × 10⁹ map units): absurd maps are refused up front.
    pub fn check_grid_size(&self) -> Result<f64, InputError> {
        // per simplex in parallel, summed in simplex order
        let points: Vec<f64> = self.coords.par_iter().map(grid_points).collect();
        let (mut total, mut largest) = (0.0f64, (0.0f64, 0usize));
        for (s, &n) in points.iter().enumerate() {
            total += n;
            if n.is_nan() || n > largest.0 {
                largest = (n, s);
            }
        }
        if total <= MAX_GRID_POINTS {
            return Ok(total);
        }
        let (n, s) = largest;
        let too_large = MapError::TooLarge { points: n, total };
        Err(ElementKind::simplex(N).at(s).error(too_large).into())
    }

    /// Signed volume of the map image of simplex `s` (area in 2D, 6× volume
    /// in 3D up to a positive factor): `< 0` means reverted.
    pub fn map_det(&self, s: usize) -> f64 {
        det_of::<N, D>(&self.coords[s])
    }
}

/// The least `i < len` with `bad(i)`: blocks of elements tested in
/// parallel, the first block with one searched in order.
fn first_where(len: usize, bad: impl Fn(usize) -> bool + Sync) -> Option<usize> {
    const BLOCK: usize = 4096;
    let block = (0..len.div_ceil(BLOCK))
        .into_par_iter()
        .find_first(|&b| (b * BLOCK..len.min((b + 1) * BLOCK)).any(&bad))?;
    (block * BLOCK..len.min((block + 1) * BLOCK)).find(|&i| bad(i))
}

/// Grid points the image `p` of a simplex spans, at most: the product
/// over the axes of its extent + 1 ([`SimplexMap::check_grid_size`]).
#[inline]
pub(crate) fn grid_points<const N: usize, const D: usize>(p: &[[f64; D]; N]) -> f64 {
    let (mut lo, mut hi) = ([f64::INFINITY; D], [f64::NEG_INFINITY; D]);
    // (`min` and `max` of floats as comparisons: a NaN is skipped as by
    // `f64::min`, a zero's sign does not change the product)
    for c in p {
        for k in 0..D {
            lo[k] = if c[k] < lo[k] { c[k] } else { lo[k] };
            hi[k] = if c[k] > hi[k] { c[k] } else { hi[k] };
        }
    }
    let mut n = 1.0;
    for k in 0..D {
        n *= hi[k] - lo[k] + 1.0;
    }
    n
}

/// Whether the vertex indices of a simplex are pairwise distinct (one of
/// the invariants [`SimplexMap::validate`] checks; branch-free, for the
/// walks that check every simplex: the validation's and the fast
/// readers').
#[inline]
pub fn distinct_corners<const N: usize>(simplex: &[u32; N]) -> bool {
    let mut ok = true;
    for c in 1..N {
        for d in 0..c {
            ok &= simplex[c] != simplex[d];
        }
    }
    ok
}

/// Determinant of the edge vectors `p1-p0, …, pD-p0` of a simplex image.
pub fn det_of<const N: usize, const D: usize>(p: &[[f64; D]; N]) -> f64 {
    let e = |i: usize, k: usize| p[i][k] - p[0][k];
    match D {
        2 => e(1, 0) * e(2, 1) - e(1, 1) * e(2, 0),
        3 => {
            e(1, 0) * (e(2, 1) * e(3, 2) - e(2, 2) * e(3, 1))
                - e(1, 1) * (e(2, 0) * e(3, 2) - e(2, 2) * e(3, 0))
                + e(1, 2) * (e(2, 0) * e(3, 1) - e(2, 1) * e(3, 0))
        }
        _ => f64::NAN,
    }
}

/// The longest edge of a simplex image `p` (the square root of the
/// largest squared length: the largest length, as square roots are
/// monotone and correctly rounded).
#[inline]
pub(crate) fn longest_edge<const N: usize, const D: usize>(p: &[[f64; D]; N]) -> f64 {
    let mut l = 0.0f64;
    for (i, a) in p.iter().enumerate() {
        for b in &p[..i] {
            // (0 + the first square is that square: a sum's rounding)
            let mut d2 = 0.0;
            for (x, y) in a.iter().zip(b) {
                d2 += (x - y).powi(2);
            }
            l = if d2 > l { d2 } else { l }; // as `l.max(d2)`
        }
    }
    l.sqrt()
}

/// `1e-12·L^D`: a determinant of at most this size is flat for a simplex
/// of longest edge `L` ([`crate::singularity::is_degenerate`],
/// [`TetMap::check_not_reflected`]).
#[inline]
pub(crate) fn flat_bound<const D: usize>(len: f64) -> f64 {
    1e-12 * len.powi(D as i32)
}

/// [`degenerate_with`], without its scale (the largest |coordinate|, a
/// pass over all of them) when `|det|` lies above a bound of its
/// tolerance: `S = (max_k |p₀ₖ| + len)·(1 + 2⁻⁴⁰)` is at least every
/// |coordinate| (a corner differs from `p₀` by at most the longest edge
/// on each axis; `len` is that edge within a few ulps), `ulp` does not
/// decrease with its argument and each operation of the tolerance rounds
/// monotonically, so `|det|` above the tolerance taken with `ulp(S)` is
/// above the exact one. Otherwise (and for any overflow or NaN, which
/// fail the comparison) [`degenerate_with`] decides: the same answer.
#[inline]
pub(crate) fn degenerate_bounded<const N: usize, const D: usize>(
    p: &[[f64; D]; N],
    det: f64,
    len: f64,
) -> bool {
    let s = (largest_abs(&p[0]) + len) * (1.0 + 1.0 / (1u64 << 40) as f64);
    if det.abs() > flat_tolerance::<D>(s, len) {
        return false;
    }
    degenerate_with(p, det, len)
}

/// Whether simplex image `p` of determinant `det` and longest edge `len`
/// is degenerate ([`crate::singularity::is_degenerate`]).
#[inline]
pub(crate) fn degenerate_with<const N: usize, const D: usize>(
    p: &[[f64; D]; N],
    det: f64,
    len: f64,
) -> bool {
    det.abs() <= flat_tolerance::<D>(largest_abs(p.iter().flatten()), len)
}

/// The largest `|x|` of `xs`, 0 for none (as `scale.max(x.abs())` in
/// turn).
#[inline]
fn largest_abs<'a>(xs: impl IntoIterator<Item = &'a f64>) -> f64 {
    let mut scale = 0.0f64;
    for x in xs {
        scale = if x.abs() > scale { x.abs() } else { scale };
    }
    scale
}

/// The flatness tolerance of a simplex image of longest edge `len` whose
/// coordinates are at most `scale` in size: `max(1e-12·len^D,
/// 8·ulp(scale)·len^(D−1))`.
#[inline]
fn flat_tolerance<const D: usize>(scale: f64, len: f64) -> f64 {
    flat_bound::<D>(len).max(8.0 * ulp(scale) * len.powi(D as i32 - 1))
}
