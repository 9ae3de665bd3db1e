//! Step 3: nodes — the integer points of the local shifted map strictly
//! inside each tet (DESIGN §3.2).
//!
//! Input: the sanitized [`LocalMap`] (no integer point within `eps` of a
//! face). Output: [`Nodes`]: per node its tet, integer coordinates in that
//! tet's local chart, barycentric coordinates, reverted flag (`det < 0`);
//! and per tet the range of its nodes (CSR). Zero-volume tets hold no node.

use crate::local::LocalMap;
use crate::simplex::{bary_weights, det};
use dualex_map::{InputError, TetMap};

/// The nodes of the dual segmentation.
#[derive(Clone, Debug, Default)]
pub struct Nodes {
    /// Tet holding each node.
    pub tet: Vec<u32>,
    /// Integer coordinates in the tet's local chart.
    pub ijk: Vec<[i64; 3]>,
    /// Barycentric coordinates in the tet.
    pub bary: Vec<[f64; 4]>,
    /// Whether the node lies in a reverted tet.
    pub reverted: Vec<bool>,
    /// CSR offsets of the nodes of each tet (nodes are sorted by tet).
    pub tet_offsets: Vec<u32>,
}

/// One node: tet, integer point, barycentric coordinates, reverted.
type Found = (u32, [i64; 3], [f64; 4], bool);

/// Pushes the integer points strictly inside tet `s` (image `p`, signed
/// volume `d`) onto `out`, in (i, j, k) order.
fn in_tet(s: usize, p: &[[f64; 3]; 4], d: f64, out: &mut Vec<Found>) {
    let lo = |k: usize| p.iter().map(|c| c[k]).fold(f64::INFINITY, f64::min).ceil() as i64;
    let hi = |k: usize| {
        p.iter()
            .map(|c| c[k])
            .fold(f64::NEG_INFINITY, f64::max)
            .floor() as i64
    };
    for i in lo(0)..=hi(0) {
        for j in lo(1)..=hi(1) {
            for k in lo(2)..=hi(2) {
                let q = [i as f64, j as f64, k as f64];
                let w = bary_weights(p, &q);
                if w.iter().all(|&x| x * d > 0.0) {
                    out.push((s as u32, [i, j, k], w.map(|x| x / d), d < 0.0));
                }
            }
        }
    }
}

impl Nodes {
    /// Finds the nodes of every tet (in parallel over chunks of tets,
    /// joined in tet order).
    pub fn find(local: &LocalMap) -> Self {
        let (items, tet_offsets) = dualex_util::par::csr(local.coords.len(), 2048, |s, out| {
            let p = &local.coords[s];
            let d = det(p);
            if d != 0.0 && d.is_finite() {
                in_tet(s, p, d, out);
            }
        });
        let mut n = Nodes {
            tet_offsets,
            ..Default::default()
        };
        for (s, ijk, bary, reverted) in items {
            n.tet.push(s);
            n.ijk.push(ijk);
            n.bary.push(bary);
            n.reverted.push(reverted);
        }
        n
    }

    /// Number of nodes.
    pub fn len(&self) -> usize {
        self.tet.len()
    }

    /// Whether there is no node.
    pub fn is_empty(&self) -> bool {
        self.tet.is_empty()
    }

    /// The nodes of tet `s`.
    pub fn of_tet(&self, s: usize) -> std::ops::Range<usize> {
        self.tet_offsets[s] as usize..self.tet_offsets[s + 1] as usize
    }
}

pub use dualex_map::mesh::MAX_GRID_POINTS;

/// Refuses absurd maps before any allocation (see
/// [`dualex_map::SimplexMap::check_grid_size`]); returns the number of grid
/// points the map images span. Call it right after `map.validate()`.
pub fn check_size(map: &TetMap) -> Result<f64, InputError> {
    map.check_grid_size()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one_tet(p: [[f64; 3]; 4]) -> TetMap {
        TetMap {
            positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
            simplices: vec![[0, 1, 2, 3]],
            coords: vec![p],
        }
    }

    const UNIT: [[f64; 3]; 4] = [[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];

    #[test]
    fn the_estimate_is_the_boxes_grid_points() {
        let m = one_tet([[0.5; 3], [3.5, 0.5, 0.5], [0.5, 2.5, 0.5], [0.5, 0.5, 1.5]]);
        assert_eq!(check_size(&m), Ok(4.0 * 3.0 * 2.0));
    }

    #[test]
    fn an_absurd_map_is_refused_naming_its_largest_tet() {
        let mut m = one_tet(UNIT.map(|c| c.map(|x| x * 1e6)));
        m.simplices.push([0, 1, 2, 3]);
        m.coords.insert(0, UNIT);
        let e = check_size(&m).err().unwrap_or_else(|| panic!("accepted"));
        assert_eq!(e.location.as_deref(), Some("tet 1"));
        assert!(e.to_string().starts_with("tet 1: map too large"), "{e}");
        let e = crate::extract(&m, &Default::default()).err();
        assert!(e.is_some_and(|e| e.message.starts_with("map too large")));
    }
}
