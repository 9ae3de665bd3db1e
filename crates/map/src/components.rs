//! Counting helpers on a built [`Topology`]: connected components (any
//! dimension) and boundary loops (triangle meshes).
//!
//! Input: the map and its topology (manifold, consistently oriented).
//! Output: counts only; nothing is modified.

use crate::{SimplexMap, Topology};
use dualex_util::union_find::UnionFind;

impl<const N: usize> Topology<N> {
    /// Number of connected components (simplices joined across facets).
    pub fn components(&self) -> usize {
        let mut uf = UnionFind::new(self.adj.len());
        for s in 0..self.adj.len() {
            for f in 0..N {
                if let Some((n, _)) = self.neighbour(s, f) {
                    uf.union(s, n);
                }
            }
        }
        (0..self.adj.len()).filter(|&s| uf.find(s) == s).count()
    }
}

impl Topology<3> {
    /// Number of boundary loops of a triangle mesh (cycles of boundary edges;
    /// each boundary vertex of a manifold mesh has exactly two boundary edges).
    pub fn boundary_loops<const D: usize>(&self, map: &SimplexMap<3, D>) -> usize {
        let mut uf = UnionFind::new(map.positions.len());
        let mut on_boundary = vec![false; map.positions.len()];
        for (s, simplex) in map.simplices.iter().enumerate() {
            for f in 0..3 {
                if self.neighbour(s, f).is_none() {
                    let (a, b) = (simplex[(f + 1) % 3], simplex[(f + 2) % 3]);
                    uf.union(a as usize, b as usize);
                    on_boundary[a as usize] = true;
                    on_boundary[b as usize] = true;
                }
            }
        }
        (0..map.positions.len())
            .filter(|&v| on_boundary[v] && uf.find(v) == v)
            .count()
    }
}

#[cfg(test)]
mod tests {
    use crate::{Topology, TriMap};

    /// An `n × n` grid of squares split into triangles, `holes` squares
    /// (given by index) left out.
    fn grid(n: u32, holes: &[u32]) -> TriMap {
        let mut m = TriMap::default();
        for j in 0..=n {
            for i in 0..=n {
                m.positions.push([i as f64, j as f64, 0.0]);
            }
        }
        for j in 0..n {
            for i in 0..n {
                if holes.contains(&(j * n + i)) {
                    continue;
                }
                let v = |a: u32, b: u32| (j + b) * (n + 1) + i + a;
                m.simplices.push([v(0, 0), v(1, 0), v(1, 1)]);
                m.simplices.push([v(0, 0), v(1, 1), v(0, 1)]);
            }
        }
        m.coords = vec![[[0.0; 2]; 3]; m.simplices.len()];
        m
    }

    #[test]
    fn loops_and_components() {
        let m = grid(3, &[]);
        let t = Topology::build(&m).expect("grid");
        assert_eq!(t.components(), 1);
        assert_eq!(t.boundary_loops(&m), 1);
        assert_eq!(t.boundary_facets, 12);
        let m = grid(3, &[4]);
        let t = Topology::build(&m).expect("grid with hole");
        assert_eq!(t.boundary_loops(&m), 2);
        assert_eq!(t.boundary_facets, 16);
        // two separate squares
        let mut m = grid(1, &[]);
        let k = m.positions.len() as u32;
        m.positions.extend_from_within(..);
        let extra: Vec<[u32; 3]> = m.simplices.iter().map(|s| s.map(|v| v + k)).collect();
        m.simplices.extend(extra);
        m.coords = vec![[[0.0; 2]; 3]; m.simplices.len()];
        let t = Topology::build(&m).expect("two squares");
        assert_eq!(t.components(), 2);
        assert_eq!(t.boundary_loops(&m), 2);
    }
}
