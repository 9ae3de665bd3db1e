//! Union–find over `u32` elements (path halving), shared by the steps
//! that group faces, corners and edges: the free functions on a plain
//! parent array, and [`UnionFind`] with dense labels.

/// The root of `x`, halving the path on the way.
pub(crate) fn find(parent: &mut [u32], mut x: u32) -> u32 {
    while parent[x as usize] != x {
        parent[x as usize] = parent[parent[x as usize] as usize];
        x = parent[x as usize];
    }
    x
}

/// Joins the sets of `a` and `b` (the smaller root wins, so the result
/// does not depend on the order of the unions).
pub(crate) fn union(parent: &mut [u32], a: u32, b: u32) {
    let (ra, rb) = (find(parent, a), find(parent, b));
    if ra != rb {
        parent[ra.max(rb) as usize] = ra.min(rb);
    }
}

/// Union–find with path halving, for corners and faces.
pub(crate) struct UnionFind {
    parent: Vec<u32>,
}

impl UnionFind {
    pub(crate) fn new(n: usize) -> Self {
        UnionFind {
            parent: (0..n as u32).collect(),
        }
    }

    pub(crate) fn find(&mut self, x: usize) -> usize {
        find(&mut self.parent, x as u32) as usize
    }

    pub(crate) fn union(&mut self, a: usize, b: usize) {
        union(&mut self.parent, a as u32, b as u32);
    }

    /// Dense labels `0..count` per element, in order of first appearance.
    pub(crate) fn labels(&mut self) -> (Vec<u32>, usize) {
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
