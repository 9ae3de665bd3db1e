//! Step 3: nodes — the integer points of the local shifted map strictly
//! inside each triangle (DESIGN §3.2).
//!
//! Input: the sanitized [`LocalMap`] (no integer point within `eps` of an
//! edge). Output: [`Nodes`]: per node its triangle, integer coordinates in
//! that triangle's local chart, barycentric coordinates, reverted flag
//! (`det < 0`); and per triangle the list of its nodes (CSR).
//! Zero-area triangles hold no node. [`check_size`] refuses, before any
//! allocation, maps whose images span absurdly many grid points.

use crate::local::LocalMap;
use dualex_map::{InputError, TriMap};

/// The nodes of the dual segmentation.
#[derive(Clone, Debug, Default)]
pub struct Nodes {
    /// Triangle holding each node.
    pub tri: Vec<u32>,
    /// Integer coordinates in the triangle's local chart.
    pub ij: Vec<[i64; 2]>,
    /// Barycentric coordinates in the triangle.
    pub bary: Vec<[f64; 3]>,
    /// Whether the node lies in a reverted triangle.
    pub reverted: Vec<bool>,
    /// CSR offsets of the nodes of each triangle (nodes are sorted by triangle).
    pub tri_offsets: Vec<u32>,
}

/// One node: triangle, integer point, barycentric coordinates, reverted.
type Found = (u32, [i64; 2], [f64; 3], bool);

/// Pushes the integer points strictly inside triangle `s` (image `p`,
/// signed double area `det`) onto `out`, in (i, j) order.
fn in_triangle(s: usize, p: &[[f64; 2]; 3], det: f64, out: &mut Vec<Found>) {
    let lo = |k: usize| p.iter().map(|c| c[k]).fold(f64::INFINITY, f64::min);
    let hi = |k: usize| p.iter().map(|c| c[k]).fold(f64::NEG_INFINITY, f64::max);
    let (i0, i1) = (lo(0).ceil() as i64, hi(0).floor() as i64);
    let (j0, j1) = (lo(1).ceil() as i64, hi(1).floor() as i64);
    for i in i0..=i1 {
        for j in j0..=j1 {
            let q = [i as f64, j as f64];
            let w: [f64; 3] = std::array::from_fn(|c| {
                let a = p[(c + 1) % 3];
                let b = p[(c + 2) % 3];
                (a[0] - q[0]) * (b[1] - q[1]) - (a[1] - q[1]) * (b[0] - q[0])
            });
            if w.iter().all(|&x| x * det > 0.0) {
                out.push((s as u32, [i, j], w.map(|x| x / det), det < 0.0));
            }
        }
    }
}

impl Nodes {
    /// Finds the nodes of every triangle (in parallel over chunks of
    /// triangles, joined in triangle order).
    pub fn find(local: &LocalMap) -> Self {
        let (items, tri_offsets) = dualex_util::par::csr(local.coords.len(), 4096, |s, out| {
            let det = local.det(s);
            if det != 0.0 && det.is_finite() {
                in_triangle(s, &local.coords[s], det, out);
            }
        });
        let mut n = Nodes {
            tri_offsets,
            ..Default::default()
        };
        for (s, ij, bary, reverted) in items {
            n.tri.push(s);
            n.ij.push(ij);
            n.bary.push(bary);
            n.reverted.push(reverted);
        }
        n
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.tri.len()
    }

    /// Whether there is no node.
    pub fn is_empty(&self) -> bool {
        self.tri.is_empty()
    }

    /// The nodes of triangle `s`.
    pub fn of_tri(&self, s: usize) -> std::ops::Range<usize> {
        self.tri_offsets[s] as usize..self.tri_offsets[s + 1] as usize
    }
}

pub use dualex_map::mesh::MAX_GRID_POINTS;

/// Refuses absurd maps before any allocation (see
/// [`dualex_map::SimplexMap::check_grid_size`]); returns the number of grid
/// points the map images span. Call it right after `map.validate()`.
pub fn check_size(map: &TriMap) -> Result<f64, InputError> {
    map.check_grid_size()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one_triangle(p: [[f64; 2]; 3]) -> TriMap {
        TriMap {
            positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0]],
            simplices: vec![[0, 1, 2]],
            coords: vec![p],
        }
    }

    #[test]
    fn the_estimate_is_the_boxes_grid_points() {
        let m = one_triangle([[0.5, 0.5], [3.5, 0.5], [0.5, 2.5]]);
        assert_eq!(check_size(&m), Ok(4.0 * 3.0));
    }

    #[test]
    fn an_absurd_map_is_refused_naming_its_largest_triangle() {
        let mut m = one_triangle([[0.0, 0.0], [1e9, 0.0], [0.0, 1e9]]);
        m.simplices.push([0, 1, 2]);
        m.coords.insert(0, [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
        let e = check_size(&m).err().unwrap_or_else(|| panic!("accepted"));
        assert_eq!(e.location.as_deref(), Some("triangle 1"));
        assert!(
            e.to_string().starts_with("triangle 1: map too large"),
            "{e}"
        );
        // extract refuses it before any work
        let e = crate::extract(&m, &Default::default()).err();
        assert!(e.is_some_and(|e| e.message.starts_with("map too large")));
        let nan = one_triangle([[0.0, 0.0], [f64::INFINITY, 0.0], [0.0, 1.0]]);
        assert!(check_size(&nan).is_err());
    }
}
