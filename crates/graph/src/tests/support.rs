//! Mesh counts and mesh comparison used by the tests.

use crate::glue::Glued;
use crate::ids::Node;
use crate::testgrid::GridSpec;
use crate::NodeGraph;
use std::collections::{BTreeMap, HashMap};

/// Counts of a glued mesh, computed from its corners.
#[derive(Debug, PartialEq, Eq)]
pub struct Counts {
    pub v: usize,
    pub e: usize,
    /// Unique quads (D = 3: faces of hexes; D = 2: the cells).
    pub f: usize,
    pub cells: usize,
    pub euler: i64,
    /// Edge valence per vertex → number of vertices.
    pub valence: BTreeMap<usize, usize>,
}

pub fn counts<const D: usize>(g: &Glued<D>) -> Counts {
    let edges = g.edges();
    let mut deg = vec![0usize; g.n_vertices];
    for &(a, b) in &edges {
        deg[a as usize] += 1;
        deg[b as usize] += 1;
    }
    let mut valence = BTreeMap::new();
    for d in deg {
        *valence.entry(d).or_insert(0) += 1;
    }
    let mut quads = Vec::new();
    for n in &g.nodes {
        for a in 0..D {
            for side in [0, 1usize << a] {
                let mut q: Vec<u32> = (0..1usize << D)
                    .filter(|c| c & (1 << a) == side)
                    .map(|c| g.vertex(*n, c))
                    .collect();
                q.sort_unstable();
                quads.push(q);
            }
        }
    }
    quads.sort();
    quads.dedup();
    let f = if D == 2 { g.n_cells() } else { quads.len() };
    let (v, e, c) = (g.n_vertices as i64, edges.len() as i64, g.n_cells() as i64);
    let euler = if D == 2 {
        v - e + c
    } else {
        v - e + f as i64 - c
    };
    Counts {
        v: g.n_vertices,
        e: edges.len(),
        f,
        cells: g.n_cells(),
        euler,
        valence,
    }
}

/// Exact counts of a regular grid of `n` cells per axis.
pub fn grid_counts<const D: usize>(n: [usize; D]) -> (usize, usize, usize, usize) {
    let prod = |f: &dyn Fn(usize) -> usize| (0..D).map(f).product::<usize>();
    let v = prod(&|a| n[a] + 1);
    let e: usize = (0..D)
        .map(|a| prod(&|b| if a == b { n[b] } else { n[b] + 1 }))
        .sum();
    let f: usize = if D == 2 {
        prod(&|a| n[a])
    } else {
        (0..D)
            .map(|a| prod(&|b| if a == b { n[b] + 1 } else { n[b] }))
            .sum()
    };
    let unmatched = (0..D)
        .map(|a| 2 * prod(&|b| if a == b { 1 } else { n[b] }))
        .sum();
    (v, e, f, unmatched)
}

/// Asserts that two glued meshes have the same corner partition under a
/// map of (node, corner code) from `a` to `b`.
pub fn assert_same_partition<const D: usize>(
    a: &Glued<D>,
    b: &Glued<D>,
    map: impl Fn(Node, usize) -> (Node, usize),
) {
    assert_eq!(a.n_vertices, b.n_vertices, "vertex counts differ");
    assert_eq!(a.n_cells(), b.n_cells(), "cell counts differ");
    let mut fwd: HashMap<u32, u32> = HashMap::new();
    let mut back: HashMap<u32, u32> = HashMap::new();
    for n in &a.nodes {
        for c in 0..1usize << D {
            let (va, (nb, cb)) = (a.vertex(*n, c), map(*n, c));
            let vb = b.vertex(nb, cb);
            assert_ne!(vb, crate::NO_VERTEX, "node {nb:?} is not alive in b");
            assert_eq!(*fwd.entry(va).or_insert(vb), vb, "vertex {va} split");
            assert_eq!(*back.entry(vb).or_insert(va), va, "vertex {vb} merged");
        }
    }
}

/// For an untangled folded grid: the surviving node of each node of the
/// regular grid of `spec.untangled_dims()` (built by `GridSpec::regular`).
pub fn survivors<const D: usize>(spec: &GridSpec<D>, g: &NodeGraph<D>) -> Vec<Node> {
    let reg = GridSpec::regular(spec.untangled_dims());
    let mut first_layer = Vec::new();
    let mut l = 0;
    for k in 0..spec.dims[0] {
        let copies = if spec.folds.contains(&k) { 3 } else { 1 };
        first_layer.push((l, copies));
        l += copies;
    }
    let mut out = vec![Node(u32::MAX); reg.dims.iter().product()];
    for (k, &(l0, copies)) in first_layer.iter().enumerate().take(reg.dims[0]) {
        for ci in 0..reg.cross() {
            let alive: Vec<Node> = (l0..l0 + copies)
                .map(|l| Node((l * spec.cross() + ci) as u32))
                .filter(|&n| g.is_alive(n))
                .collect();
            assert_eq!(alive.len(), 1, "layer {k}, cross {ci}: survivors {alive:?}");
            out[k * reg.cross() + ci] = alive[0];
        }
    }
    out
}

/// Each directed edge of the quads appears at most once; interior edges in
/// both directions (consistent orientation).
pub fn assert_oriented(g: &Glued<2>) {
    let mut seen = HashMap::new();
    for (_, q) in g.cells() {
        for k in 0..4 {
            let e = (q[k], q[(k + 1) % 4]);
            assert!(
                seen.insert(e, ()).is_none(),
                "directed edge {e:?} used twice"
            );
        }
    }
}
