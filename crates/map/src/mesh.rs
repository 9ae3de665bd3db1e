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
use rayon::prelude::*;

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
        if let Some(i) = first_where(self.positions.len(), bad_position) {
            let p = self.positions[i];
            let e = ElementKind::Vertex
                .at(i)
                .error(MapError::NonFinitePosition(p));
            return Err(e.into());
        }
        match first_where(self.len(), |s| !self.simplex_ok(s)) {
            Some(s) => Err(self.simplex_error(s)),
            None => Ok(()),
        }
    }

    /// Whether simplex `s` keeps the invariants of the module docs.
    #[inline]
    fn simplex_ok(&self, s: usize) -> bool {
        let simplex = &self.simplices[s];
        let nv = self.positions.len();
        let mut ok = true;
        for c in 0..N {
            ok &= (simplex[c] as usize) < nv;
            for d in 0..c {
                ok &= simplex[c] != simplex[d];
            }
        }
        ok && self.coords[s].iter().flatten().all(|x| x.is_finite())
    }

    /// The first invariant simplex `s` breaks (module docs), in corner
    /// order; `s` must break one.
    #[cold]
    fn simplex_error(&self, s: usize) -> InputError {
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
        let points: Vec<f64> = self
            .coords
            .par_iter()
            .map(|p| {
                let mut n = 1.0;
                for k in 0..D {
                    let lo = p.iter().map(|c| c[k]).fold(f64::INFINITY, f64::min);
                    let hi = p.iter().map(|c| c[k]).fold(f64::NEG_INFINITY, f64::max);
                    n *= hi - lo + 1.0;
                }
                n
            })
            .collect();
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

/// The least share of the map's unsigned volume (the sum of the map's
/// |determinants|) its signed volume keeps in a map taken as folded, not
/// reflected ([`TetMap::check_not_reflected`]).
pub const FOLDED_SIGNED: f64 = 1e-3;

/// The largest share of the geometric volume flat tets make up in a map
/// taken as folded, not reflected ([`TetMap::check_not_reflected`]).
pub const FOLDED_FLAT: f64 = 1e-3;

impl TetMap {
    /// Refuses a 3D map whose charts are reflected: when tets whose map is
    /// reverted (orientation opposite to the geometry's) or flat make up at
    /// least half of the mesh's geometric volume, and some of them are
    /// reverted (e.g. HexEx's `minimal_invalid_charts`), the map turns the
    /// volume inside out as a whole rather than folding it locally — unless
    /// the map is folded: its signed volume (the sum of the map's
    /// determinants, each tet oriented by the geometry) stays positive
    /// ([`FOLDED_SIGNED`] of the unsigned sum; moving vertices inside the
    /// volume does not change it, reflecting the charts makes it negative)
    /// and almost none of the volume is flat ([`FOLDED_FLAT`]; HexEx's map,
    /// a third of it flat, stays refused). Issue 22's refined folds on a
    /// small mesh revert over half its volume. Folds over less than half
    /// the volume, and collapsed maps (flat tets, none reverted: the
    /// paper's collapsed stress test), are the messy maps that extraction
    /// repairs.
    pub fn check_not_reflected(&self) -> Result<(), InputError> {
        let geo = |s: usize| {
            let p: [[f64; 3]; 4] = self.simplices[s].map(|v| self.positions[v as usize]);
            det_of::<4, 3>(&p)
        };
        // "degenerate": |det| below 1e-12 of the cube of the longest edge
        let scale = |p: &[[f64; 3]; 4]| {
            let mut l = 0.0f64;
            for i in 0..4 {
                for j in 0..i {
                    l = l.max((0..3).map(|k| (p[i][k] - p[j][k]).powi(2)).sum::<f64>());
                }
            }
            l.sqrt().powi(3) * 1e-12
        };
        // per tet (in parallel): geometric det, map det, degeneracy bound;
        // the sums below stay sequential, in tet order
        let per_tet: Vec<(f64, f64, f64)> = (0..self.len())
            .into_par_iter()
            .map(|s| (geo(s), self.map_det(s), scale(&self.coords[s])))
            .collect();
        let total: f64 = per_tet.iter().map(|t| t.0).sum();
        let sign = if total < 0.0 { -1.0 } else { 1.0 };
        let (mut bad, mut all, mut worst, mut reverted) = (0.0, 0.0, None, 0.0);
        let (mut signed, mut unsigned) = (0.0, 0.0);
        for (s, &(geo_s, map_s, tiny)) in per_tet.iter().enumerate() {
            let g = (geo_s * sign).max(0.0);
            all += g;
            let m = map_s * sign;
            signed += m;
            unsigned += m.abs();
            if m <= tiny {
                bad += g;
                if m < -tiny {
                    reverted += g;
                    worst.get_or_insert(s);
                }
            }
        }
        // a fold inside the volume keeps the map's signed volume: positive,
        // where reflected charts make it negative; flat tets are no fold
        let folded = signed > FOLDED_SIGNED * unsigned && bad - reverted < FOLDED_FLAT * all;
        match worst {
            Some(s) if all > 0.0 && bad >= 0.5 * all && reverted > 0.0 && !folded => {
                let percent = 100.0 * bad / all;
                let e = ElementKind::Tet
                    .at(s)
                    .error(MapError::Reflected { percent });
                Err(e.into())
            }
            _ => Ok(()),
        }
    }
}
