//! The serial union–find of the workspace: disjoint sets over `0..n` with
//! path halving, stored as one flat `u32` parent array (its parallel twin,
//! with the same representatives: [`crate::union_find_par`]).
//!
//! Input: `n` (elements are `0..n`, `n < 2^32`) and unions of pairs.
//! Output: a representative per element ([`UnionFind::find`]), counts of
//! sets and dense labels. Invariants: `parent[x] == x` exactly at the
//! roots; nothing else is stored (no sizes or ranks), so the
//! representative of a set depends only on the sequence of unions and on
//! the rule of the union called (path halving never changes it):
//!
//! - [`UnionFind::union`]: the smaller root wins, so the representative
//!   of a set is its smallest element whatever the order of the unions
//!   (welding numbers the merged vertices by it; the gluing of the node
//!   graph, the checker and the surface pipeline use it too — the rule was
//!   chosen by timing the gluing, see `BENCHMARKS.md`);
//! - [`UnionFind::union_into`]: `b`'s root stays the root (the collapsed
//!   clusters of the segmentation keep the chart of that root).
//!
//! ```text
//!   union(3, 1):   3   1        1          union_into(1, 3):  3
//!                             /                                \
//!                            3                                  1
//! ```
//!
//! [`find`] / [`union`] are the same on a bare parent slice, for callers
//! that keep their own `Vec<u32>`.

/// Disjoint sets over `0..n` (module docs).
#[derive(Clone, Debug)]
pub struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    /// `n` singleton sets.
    pub fn new(n: usize) -> Self {
        UnionFind {
            parent: (0..n as u32).collect(),
        }
    }

    /// Number of elements.
    pub fn len(&self) -> usize {
        self.parent.len()
    }

    /// Whether there is no element.
    pub fn is_empty(&self) -> bool {
        self.parent.is_empty()
    }

    /// The representative of `x`'s set, halving the path on the way.
    #[inline]
    pub fn find(&mut self, x: usize) -> usize {
        find(&mut self.parent, x as u32) as usize
    }

    /// The representative of `x`'s set, without touching the paths.
    pub fn root(&self, x: usize) -> usize {
        let mut x = x as u32;
        while self.parent[x as usize] != x {
            x = self.parent[x as usize];
        }
        x as usize
    }

    /// Merges the sets of `a` and `b`, the smaller root becoming the root
    /// of both; whether they were distinct.
    #[inline]
    pub fn union(&mut self, a: usize, b: usize) -> bool {
        union(&mut self.parent, a as u32, b as u32)
    }

    /// Merges the set of `a` into that of `b`: `b`'s root stays the root;
    /// whether they were distinct.
    pub fn union_into(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        self.parent[ra] = rb as u32;
        true
    }

    /// Number of distinct sets among the given elements.
    /// (Each root met is marked once: no sort of the elements' roots.)
    pub fn count_sets(&mut self, elements: impl Iterator<Item = usize>) -> usize {
        let mut seen = vec![false; self.parent.len()];
        let mut count = 0;
        for x in elements {
            let r = self.find(x);
            count += usize::from(!seen[r]);
            seen[r] = true;
        }
        count
    }

    /// Dense labels `0..count` per element, in order of first appearance;
    /// and `count`.
    pub fn labels(&mut self) -> (Vec<u32>, usize) {
        let n = self.parent.len();
        let mut label = vec![u32::MAX; n];
        let mut out = Vec::with_capacity(n);
        let mut count = 0;
        for x in 0..n {
            let r = self.find(x);
            if label[r] == u32::MAX {
                label[r] = count;
                count += 1;
            }
            out.push(label[r]);
        }
        (out, count as usize)
    }
}

/// The root of `x` in the parent array `parent`, halving the path on the
/// way.
#[inline]
pub fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        let gp = parent[parent[x as usize] as usize];
        parent[x as usize] = gp;
        x = gp;
    }
    x
}

/// Joins the sets of `a` and `b` in the parent array `parent`, the smaller
/// root winning (the result does not depend on the order of the unions);
/// whether they were distinct.
#[inline]
pub fn union(parent: &mut [u32], a: u32, b: u32) -> bool {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra == rb {
        return false;
    }
    parent[ra.max(rb) as usize] = ra.min(rb);
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn smaller_root_wins_whatever_the_order() {
        for order in [[(0, 1), (2, 3), (3, 1)], [(3, 1), (1, 0), (2, 0)]] {
            let mut uf = UnionFind::new(5);
            for (a, b) in order {
                assert!(uf.union(a, b));
            }
            assert!(!uf.union(2, 1));
            assert_eq!(
                (0..5).map(|x| uf.find(x)).collect::<Vec<_>>(),
                [0, 0, 0, 0, 4]
            );
            assert_eq!(uf.count_sets(0..5), 2);
            assert_eq!(uf.labels(), (vec![0, 0, 0, 0, 1], 2));
        }
    }

    #[test]
    fn union_into_keeps_the_second_root() {
        let mut uf = UnionFind::new(4);
        assert!(uf.union_into(0, 3));
        assert!(uf.union_into(3, 2));
        assert!(!uf.union_into(0, 2));
        assert_eq!((0..4).map(|x| uf.root(x)).collect::<Vec<_>>(), [2, 1, 2, 2]);
    }

    #[test]
    fn bare_parent_array() {
        let mut p: Vec<u32> = (0..6).collect();
        assert!(union(&mut p, 5, 4));
        assert!(union(&mut p, 4, 2));
        assert!(!union(&mut p, 2, 5));
        assert_eq!(find(&mut p, 5), 2);
        assert_eq!(find(&mut p, 3), 3);
    }
}
