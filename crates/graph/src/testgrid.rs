//! Synthetic node graphs for tests: regular grids, grids with folds, and
//! chart relabelling. Used by this crate's tests and by other crates'.
//!
//! A grid is a sequence of **layers** along axis 0 (u), each layer a
//! regular grid over the other axes. A layer is normal or reverted; walking
//! along u, consecutive layers are glued by the label rule with identity
//! rotations:
//! ```text
//!   layers:  0   1   A   B   C   3 ...     fold at 2: layer 2 becomes
//!            F   F   F   T   F   F         normal / reverted / normal copies
//!   sides:  +u↔-u  +u↔+u  -u↔-u  +u↔-u     at the same integer coordinates
//! ```
//! A *fold-back* appends a reverted copy of the last layer (the map turns
//! back at the boundary, B.-u stays unmatched). Untangling a fold gives back
//! the regular grid; a fold-back removes the last layer.

use crate::graph::NodeGraph;
use crate::ids::{Node, Side};
use crate::rng::SplitMix;
use dualex_map::Rot;

/// A grid with folds along axis 0.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct GridSpec<const D: usize> {
    /// Layers along u (before folds) and extent of the other axes.
    pub dims: [usize; D],
    /// Layers (indices in `0..dims[0]`) replaced by a fold triple.
    pub folds: Vec<usize>,
    /// Whether a reverted copy of the last layer is appended.
    pub fold_back: bool,
}

impl<const D: usize> GridSpec<D> {
    /// A regular grid of `dims` nodes.
    pub fn regular(dims: [usize; D]) -> Self {
        GridSpec {
            dims,
            folds: Vec::new(),
            fold_back: false,
        }
    }

    /// Adds a fold at layer `k` (ignored if out of range).
    pub fn fold(mut self, k: usize) -> Self {
        self.folds.push(k);
        self
    }

    /// Makes the map turn back at the last layer.
    pub fn fold_back(mut self) -> Self {
        self.fold_back = true;
        self
    }

    /// The reverted flag of each layer along u.
    pub fn layers(&self) -> Vec<bool> {
        let mut out = Vec::new();
        for k in 0..self.dims[0] {
            if self.folds.contains(&k) {
                out.extend([false, true, false]);
            } else {
                out.push(false);
            }
        }
        if self.fold_back && self.dims[0] > 0 {
            out.push(true);
        }
        out
    }

    /// Nodes per layer.
    pub fn cross(&self) -> usize {
        self.dims[1..].iter().product()
    }

    /// The node of `layer` at coordinates `c` (`c[0]` ignored).
    pub fn node_at(&self, layer: usize, c: [usize; D]) -> Node {
        let mut ci = 0;
        for a in (1..D).rev() {
            ci = ci * self.dims[a] + c[a];
        }
        Node((layer * self.cross() + ci) as u32)
    }

    /// The dims of the regular grid that untangling must give back.
    pub fn untangled_dims(&self) -> [usize; D] {
        let mut d = self.dims;
        if self.fold_back {
            d[0] = d[0].saturating_sub(1);
        }
        d
    }

    /// Builds the graph (node ids: layer-major, then axis 1 fastest).
    pub fn build(&self) -> NodeGraph<D> {
        let layers = self.layers();
        let cross = self.cross();
        let flags: Vec<bool> = layers
            .iter()
            .flat_map(|&f| std::iter::repeat_n(f, cross))
            .collect();
        let mut g = NodeGraph::new(flags);
        for (l, &rev) in layers.iter().enumerate() {
            for c in cross_coords(&self.dims) {
                let x = self.node_at(l, c);
                for a in 1..D {
                    if c[a] + 1 < self.dims[a] {
                        let mut n = c;
                        n[a] += 1;
                        let y = self.node_at(l, n);
                        link(&mut g, x.side::<D>(2 * a), y.side::<D>(2 * a + 1));
                    }
                }
                if let Some(&next_rev) = layers.get(l + 1) {
                    let y = self.node_at(l + 1, c);
                    let out = usize::from(rev);
                    let back = usize::from(!next_rev);
                    link(&mut g, x.side::<D>(out), y.side::<D>(back));
                }
            }
        }
        g
    }
}

fn link<const D: usize>(g: &mut NodeGraph<D>, a: Side, b: Side) {
    if let Err(e) = g.link(a, b, Rot::IDENTITY) {
        panic!("bug: grid builder linked twice: {e}");
    }
}

/// All coordinates over axes 1..D (`c[0] = 0`).
fn cross_coords<const D: usize>(dims: &[usize; D]) -> Vec<[usize; D]> {
    let mut out = vec![[0usize; D]];
    for a in 1..D {
        out = out
            .into_iter()
            .flat_map(|c| {
                (0..dims[a]).map(move |i| {
                    let mut c = c;
                    c[a] = i;
                    c
                })
            })
            .collect();
    }
    out
}

/// Relabels every node's sides by a chart rotation: node n's new chart is
/// `rots[n]` applied to its old one, so side d becomes side `rots[n](d)`
/// and a pair's rotation becomes `rots[x]⁻¹` then ρ then `rots[y]`. The
/// glued mesh is unchanged up to [`rotate_corner`].
pub fn rotate_charts<const D: usize>(g: &NodeGraph<D>, rots: &[Rot<D>]) -> NodeGraph<D> {
    assert_eq!(
        rots.len(),
        g.n_nodes(),
        "bug: one rotation per node expected"
    );
    let mut out = g.clone();
    for s in 0..out.n_sides() {
        out.clear(Side(s as u32));
    }
    for s in (0..g.n_sides() as u32).map(Side) {
        let Some(t) = g.opposite(s) else { continue };
        if t < s {
            continue;
        }
        let (x, y) = (g.node_of(s), g.node_of(t));
        let (rx, ry) = (rots[x.idx()], rots[y.idx()]);
        let rho = rx.inverse().then(&g.rot[s.idx()]).then(&ry);
        let s2 = out.side(x, rx.apply_dir(g.dir_of(s)));
        let t2 = out.side(y, ry.apply_dir(g.dir_of(t)));
        out.set_pair(s2, t2, rho);
    }
    out
}

/// Renumbers the nodes: node `n` becomes node `perm[n]` (`perm` a
/// permutation of the node ids), with its flags, sides and rotations.
pub fn renumber<const D: usize>(g: &NodeGraph<D>, perm: &[u32]) -> NodeGraph<D> {
    let n = g.n_nodes();
    let mut seen = vec![false; n];
    let is_perm = perm.len() == n
        && perm
            .iter()
            .all(|&p| (p as usize) < n && !std::mem::replace(&mut seen[p as usize], true));
    assert!(is_perm, "bug: not a permutation of the {n} nodes");
    let mut out = NodeGraph::new(vec![false; n]);
    for (x, &p) in perm.iter().enumerate() {
        out.reverted[p as usize] = g.reverted[x];
        out.alive[p as usize] = g.alive[x];
    }
    let to = |s: Side| Node(perm[g.node_of(s).idx()]).side::<D>(g.dir_of(s));
    for s in (0..g.n_sides() as u32).map(Side) {
        if let Some(t) = g.opposite(s).filter(|&t| s < t) {
            out.set_pair(to(s), to(t), g.rot[s.idx()]);
        }
    }
    out
}

/// A permutation of `0..n` drawn uniformly (seeded).
pub fn random_permutation(n: usize, seed: u64) -> Vec<u32> {
    let mut p: Vec<u32> = (0..n as u32).collect();
    SplitMix::new(seed).shuffle(&mut p);
    p
}

pub use crate::glue::rotate_corner;

/// `n` rotations drawn uniformly from the group (seeded).
pub fn random_rotations<const D: usize>(n: usize, seed: u64) -> Vec<Rot<D>> {
    let all = Rot::<D>::all();
    let mut rng = SplitMix::new(seed);
    (0..n).map(|_| all[rng.below(all.len())]).collect()
}

/// A disk of `sectors` square sectors of `k × k` nodes around one vertex
/// (2D): sector i's row y = 0 (-v sides) is glued to sector i+1's column
/// x = 0 (-u sides) with a quarter turn, so the common corner 0 of the
/// sectors' (0, 0) nodes is an interior vertex of valence `sectors`
/// (index 1 − sectors/4); every other interior vertex is regular.
///
/// ```text
///   sector i+1        node id = i·k² + y·k + x  (sector i, column x, row y)
///   ┌──┬──┐
///   │  │  │
///   ●──┴──┘  sector i below, rotated: its x runs along sector i+1's y
/// ```
pub fn singular_disk(sectors: usize, k: usize) -> NodeGraph<2> {
    let id = |s: usize, x: usize, y: usize| Node(((s % sectors) * k * k + y * k + x) as u32);
    let mut g = NodeGraph::new(vec![false; sectors * k * k]);
    let quarter = Rot::<2>::quarter_turns(1);
    for s in 0..sectors {
        for y in 0..k {
            for x in 0..k {
                if x + 1 < k {
                    link(
                        &mut g,
                        id(s, x, y).side::<2>(0),
                        id(s, x + 1, y).side::<2>(1),
                    );
                }
                if y + 1 < k {
                    link(
                        &mut g,
                        id(s, x, y).side::<2>(2),
                        id(s, x, y + 1).side::<2>(3),
                    );
                }
            }
            let (a, b) = (id(s, y, 0).side::<2>(3), id(s + 1, 0, y).side::<2>(1));
            if let Err(e) = g.link(a, b, quarter) {
                panic!("bug: disk builder linked twice: {e}");
            }
        }
    }
    g
}
