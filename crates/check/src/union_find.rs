//! A minimal union–find (path halving, union by index) over `0..n`.

/// Disjoint sets over `0..n`.
pub(crate) struct UnionFind {
    parent: Vec<usize>,
}

impl UnionFind {
    /// `n` singleton sets.
    pub(crate) fn new(n: usize) -> Self {
        UnionFind {
            parent: (0..n).collect(),
        }
    }

    /// Representative of the set of `x` (`x < n`).
    pub(crate) fn find(&mut self, mut x: usize) -> usize {
        while self.parent[x] != x {
            self.parent[x] = self.parent[self.parent[x]];
            x = self.parent[x];
        }
        x
    }

    /// Merges the sets of `a` and `b`; whether they were distinct.
    pub(crate) fn union(&mut self, a: usize, b: usize) -> bool {
        let (ra, rb) = (self.find(a), self.find(b));
        if ra == rb {
            return false;
        }
        let (lo, hi) = if ra < rb { (ra, rb) } else { (rb, ra) };
        self.parent[hi] = lo;
        true
    }

    /// Number of distinct sets among the given elements.
    pub(crate) fn count_sets(&mut self, elements: impl Iterator<Item = usize>) -> usize {
        let mut roots: Vec<usize> = elements.map(|x| self.find(x)).collect();
        roots.sort_unstable();
        roots.dedup();
        roots.len()
    }
}
