//! Step 3: nodes — the integer points of the local shifted map strictly
//! inside each tet (DESIGN §3.2).
//!
//! Input: the sanitized [`LocalMap`] (no integer point within `eps` of a
//! face). Output: [`Nodes`]: per node its tet, integer coordinates in that
//! tet's local chart, barycentric coordinates, reverted flag (`det < 0`);
//! and per tet the range of its nodes (CSR). Zero-volume tets hold no node.

use crate::local::LocalMap;
use crate::simplex::{bary_weights, det};

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

impl Nodes {
    /// Finds the nodes of every tet.
    pub fn find(local: &LocalMap) -> Self {
        let mut n = Nodes::default();
        n.tet_offsets.push(0);
        for (s, p) in local.coords.iter().enumerate() {
            let d = det(p);
            if d != 0.0 && d.is_finite() {
                n.in_tet(s, p, d);
            }
            n.tet_offsets.push(n.tet.len() as u32);
        }
        n
    }

    fn in_tet(&mut self, s: usize, p: &[[f64; 3]; 4], d: f64) {
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
                        self.tet.push(s as u32);
                        self.ijk.push([i, j, k]);
                        self.bary.push(w.map(|x| x / d));
                        self.reverted.push(d < 0.0);
                    }
                }
            }
        }
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
