//! Step 5: nodes — the integer points of the local shifted map strictly
//! inside each simplex (DESIGN §3.2), in any dimension.
//!
//! Input: the sanitized [`LocalMap`] (no integer point within `eps` of a
//! facet).
//!
//! 1. per simplex with a finite, non-zero `det` (zero-measure simplices
//!    hold no node): the integer points of its image's bounding box, in
//!    lexicographic order (`i`, then `j`, then `k`);
//! 2. those whose barycentric weights ([`Simplex::bary_weights`]) all
//!    have the sign of `det` are nodes;
//! 3. simplices in parallel (chunks of [`Simplex::NODE_CHUNK`]), joined
//!    in simplex order.
//!
//! Output: [`Nodes`]: per node its simplex, integer point in that
//! simplex's local chart, barycentric coordinates, reverted flag
//! (`det < 0`); and per simplex the range of its nodes (CSR). Invariant:
//! nodes are sorted by simplex, then by point. [`check_size`] refuses,
//! before any allocation, maps whose images span absurdly many grid points.

use crate::local::LocalMap;
use crate::simplex::{Dim, Simplex};
use dualex_map::{InputError, SimplexMap};
use dualex_util::round::{ceil, floor};

/// The nodes of the dual segmentation (`N` corners per simplex, `D` axes).
#[derive(Clone, Debug, Default)]
pub struct Nodes<const N: usize, const D: usize> {
    /// Simplex holding each node.
    pub simplex: Vec<u32>,
    /// Integer coordinates in the simplex's local chart.
    pub point: Vec<[i64; D]>,
    /// Barycentric coordinates in the simplex.
    pub bary: Vec<[f64; N]>,
    /// Whether the node lies in a reverted simplex.
    pub reverted: Vec<bool>,
    /// CSR offsets of the nodes of each simplex (nodes are sorted by simplex).
    pub offsets: Vec<u32>,
}

/// One node: simplex, integer point, barycentric coordinates, reverted.
type Found<const N: usize, const D: usize> = (u32, [i64; D], [f64; N], bool);

/// The integer box `[lo, hi]` of an image, per axis (empty when some
/// `lo > hi`).
/// `ceil` and `floor` are [`dualex_util::round`]'s (bit for bit `std`'s,
/// without a library call).
fn integer_box<const N: usize, const D: usize>(p: &[[f64; D]; N]) -> ([i64; D], [i64; D]) {
    let lo =
        std::array::from_fn(|k| ceil(p.iter().map(|c| c[k]).fold(f64::INFINITY, f64::min)) as i64);
    let hi = std::array::from_fn(|k| {
        floor(p.iter().map(|c| c[k]).fold(f64::NEG_INFINITY, f64::max)) as i64
    });
    (lo, hi)
}

/// Pushes the integer points strictly inside simplex `s` (image `p`,
/// signed measure `det`) onto `out`, in lexicographic order.
fn in_simplex<const N: usize, const D: usize>(
    s: usize,
    p: &[[f64; D]; N],
    det: f64,
    out: &mut Vec<Found<N, D>>,
) where
    Dim<N, D>: Simplex<N, D>,
{
    let (lo, hi) = integer_box(p);
    if (0..D).any(|k| lo[k] > hi[k]) {
        return;
    }
    let mut x = lo;
    loop {
        let q = x.map(|v| v as f64);
        let w = Dim::<N, D>::bary_weights(p, &q);
        if w.iter().all(|&v| v * det > 0.0) {
            out.push((s as u32, x, w.map(|v| v / det), det < 0.0));
        }
        // the next point: the last axis fastest
        let mut k = D;
        loop {
            if k == 0 {
                return;
            }
            k -= 1;
            if x[k] < hi[k] {
                x[k] += 1;
                break;
            }
            x[k] = lo[k];
        }
    }
}

impl<const N: usize, const D: usize> Nodes<N, D>
where
    Dim<N, D>: Simplex<N, D>,
{
    /// Finds the nodes of every simplex (in parallel over chunks of
    /// simplices, joined in simplex order).
    pub fn find(local: &LocalMap<N, D>) -> Self {
        let chunk = <Dim<N, D> as Simplex<N, D>>::NODE_CHUNK;
        let (items, offsets) = dualex_util::par::csr(local.coords.len(), chunk, |s, out| {
            let det = local.det(s);
            if det != 0.0 && det.is_finite() {
                in_simplex(s, &local.coords[s], det, out);
            }
        });
        let len = items.len();
        let mut n = Nodes {
            simplex: Vec::with_capacity(len),
            point: Vec::with_capacity(len),
            bary: Vec::with_capacity(len),
            reverted: Vec::with_capacity(len),
            offsets,
        };
        for (s, point, bary, reverted) in items {
            n.simplex.push(s);
            n.point.push(point);
            n.bary.push(bary);
            n.reverted.push(reverted);
        }
        n
    }
}

impl<const N: usize, const D: usize> Nodes<N, D> {
    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.simplex.len()
    }

    /// Whether there is no node.
    pub fn is_empty(&self) -> bool {
        self.simplex.is_empty()
    }

    /// The nodes of simplex `s`.
    pub fn of_simplex(&self, s: usize) -> std::ops::Range<usize> {
        self.offsets[s] as usize..self.offsets[s + 1] as usize
    }
}

pub use dualex_map::mesh::MAX_GRID_POINTS;

/// Refuses absurd maps before any allocation (see
/// [`dualex_map::SimplexMap::check_grid_size`]); returns the number of grid
/// points the map images span. Call it right after `map.validate()`.
pub fn check_size<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
) -> Result<f64, InputError> {
    map.check_grid_size()
}

#[cfg(test)]
#[path = "nodes_tests.rs"]
mod tests;
