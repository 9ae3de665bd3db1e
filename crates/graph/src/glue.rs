//! Gluing: from the node graph to a mesh (DESIGN §3.4).
//!
//! Input: a [`NodeGraph`]. Output: [`Glued`], the vertex of every corner of
//! every alive node (union–find over corners), the cells in output order,
//! and counts read from the **graph**: unmatched sides, boundary components
//! (2D: boundary loops, 3D: boundary surfaces) and connected components.
//!
//! Corners are numbered by bits, bit i set ⇔ the corner is on the + side
//! of axis i:
//! ```text
//!   D = 2:  2 ── 3      D = 3: bottom (w = 0) as D = 2, top = bottom + 4
//!           │    │  v
//!           0 ── 1  └ u
//! ```
//! Rule: for a pair X.s ↔ Y.t with ρ, the corner of X between s and p
//! (p ⊥ s) is the corner of Y between t and ρ(p).
//!
//! Output order: quads counter-clockwise, corner codes [00, 01, 11, 10];
//! hexes in VTK order [000, 001, 011, 010, 100, 101, 111, 110] (bit0 = u).
//! A reverted node emits the mirrored order (quad reversed from its first
//! corner, hex with its two w-faces swapped), so that a consistently
//! oriented graph gives consistently oriented cells.

use crate::graph::NodeGraph;
use crate::ids::{axis, positive, Node, Side};
use dualex_map::Rot;
use dualex_util::union_find::UnionFind;
use dualex_util::union_find_par::AtomicUnionFind;
use rayon::prelude::*;

/// Marker for the corners of dead nodes in [`Glued::vertex_of`].
pub const NO_VERTEX: u32 = u32::MAX;

/// The mesh combinatorics obtained by gluing the alive nodes.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct Glued<const D: usize> {
    /// Per node corner (`node·2^D + code`): its vertex, [`NO_VERTEX`] for
    /// dead nodes.
    pub vertex_of: Vec<u32>,
    /// Number of vertices (ids `0..n_vertices`, by first corner).
    pub n_vertices: usize,
    /// Alive nodes, one cell each, in output order (node id order).
    pub nodes: Vec<Node>,
    /// Unmatched sides of alive nodes (boundary edges / faces).
    pub unmatched_sides: usize,
    /// Boundary components, from the graph: loops (D = 2), surfaces (D = 3).
    pub boundary_loops: usize,
    /// Connected components of alive nodes.
    pub components: usize,
    /// Pairs whose corners could not be matched (they break the label rule
    /// so badly that ρ(s) and t are on different axes); not glued.
    pub corner_mismatches: usize,
    /// Per cell: 2^D vertex ids in output order.
    cells: Vec<u32>,
}

/// Output position k ↦ corner code (see the module docs): the corner of a
/// node (reverted or not) that position `k` of its cell is.
pub fn cell_code<const D: usize>(k: usize, reverted: bool) -> usize {
    let code = (k & !3) | ((k & 3) ^ ((k & 3) >> 1));
    match (reverted, D) {
        (false, _) => code,
        (true, 2) => ((code & 1) << 1) | ((code >> 1) & 1),
        (true, _) => code ^ (1 << (D - 1)),
    }
}

/// The corner code of node(t) glued to corner `code` of node(s), for the
/// pair s ↔ t with rotation `rho`; `code` must lie on side s. `None` when
/// the pair is too broken to match corners.
pub(crate) fn corner_across<const D: usize>(
    s_dir: usize,
    t_dir: usize,
    rho: &Rot<D>,
    code: usize,
) -> Option<usize> {
    if rho.is_identity() {
        return corner_across_unrotated::<D>(s_dir, t_dir, code);
    }
    corner_across_rotated(s_dir, t_dir, rho, code)
}

/// [`corner_across`] with the identity (the common pair inside one
/// chart), without the rotation's tables: each axis but `t`'s keeps its
/// bit, `t`'s axis gets `t`'s side; `None` when `s` and `t` are on
/// different axes (then `s`'s axis, not `t`'s, keeps its bit, and `t`'s
/// axis is taken twice).
#[inline]
pub(crate) fn corner_across_unrotated<const D: usize>(
    s_dir: usize,
    t_dir: usize,
    code: usize,
) -> Option<usize> {
    let bit = 1usize << axis(t_dir);
    (axis(s_dir) == axis(t_dir)).then(|| code & !bit | if positive(t_dir) { bit } else { 0 })
}

/// [`corner_across`] for any rotation `rho`: the rule of the module docs,
/// axis by axis.
pub(crate) fn corner_across_rotated<const D: usize>(
    s_dir: usize,
    t_dir: usize,
    rho: &Rot<D>,
    code: usize,
) -> Option<usize> {
    let mut used = 1usize << axis(t_dir);
    let mut out = if positive(t_dir) { used } else { 0 };
    for a in (0..D).filter(|&a| a != axis(s_dir)) {
        let p = 2 * a + usize::from(code >> a & 1 == 0);
        let q = rho.apply_dir(p);
        if used & (1 << axis(q)) != 0 {
            return None;
        }
        used |= 1 << axis(q);
        if positive(q) {
            out |= 1 << axis(q);
        }
    }
    Some(out)
}

/// The corner code that corner `code` gets when its node's chart is
/// rotated by `r`.
pub fn rotate_corner<const D: usize>(r: &Rot<D>, code: usize) -> usize {
    (0..D).fold(0, |acc, a| {
        let q = r.apply_dir(2 * a + usize::from(code >> a & 1 == 0));
        acc | (usize::from(positive(q)) << axis(q))
    })
}

/// Corner codes of a node lying on side `dir`.
pub(crate) fn corners_on<const D: usize>(dir: usize) -> impl Iterator<Item = usize> {
    let bit = 1usize << axis(dir);
    (0..1usize << D).filter(move |c| (c & bit != 0) == positive(dir))
}

impl<const D: usize> NodeGraph<D> {
    /// Glues the alive nodes into a mesh (see the module docs).
    pub fn glue(&self) -> Glued<D> {
        self.glue_from(None)
    }

    /// [`Self::glue`], from `vertices` when the caller has them: what
    /// [`Self::glue_vertices`] returned for this very graph, unchanged
    /// since (index fairing's last count, `NodeGraph::fair_glued`); the
    /// whole-graph counts are added.
    pub fn glue_from(&self, vertices: Option<Glued<D>>) -> Glued<D> {
        // two independent reads of the graph, side by side (each result is
        // the same whatever the threads); the boundary after them, so that
        // its array over all sides is not held at the same time
        let (mut g, components) = match vertices {
            Some(g) => (g, self.components()),
            None => rayon::join(|| self.glue_vertices(), || self.components()),
        };
        g.boundary_loops = self.boundary_components();
        g.components = components;
        g
    }

    /// The corners glued across the pair `s` ↔ `t = opposite(s)`, as (corner
    /// code on `s`'s node, corner code on `t`'s node), first `n` entries of
    /// the array; `None` when some corner of the side does not match (then
    /// none is glued). The rule of [`Self::glue`], which applies it from the
    /// smaller side of each pair whose node is alive.
    pub(crate) fn matched_corners(&self, s: Side, t: Side) -> Option<([(usize, usize); 4], usize)> {
        let (sd, td, rho) = (self.dir_of(s), self.dir_of(t), self.rot[s.idx()]);
        let mut pairs = [(0usize, 0usize); 4];
        let mut n = 0;
        for c in corners_on::<D>(sd) {
            pairs[n] = (c, corner_across(sd, td, &rho, c)?);
            n += 1;
        }
        Some((pairs, n))
    }

    /// [`Self::glue`] without the whole-graph counts (`boundary_loops`
    /// and `components` left 0): for callers that only need the vertices
    /// (index fairing rebuilds them after every lift).
    pub(crate) fn glue_vertices(&self) -> Glued<D> {
        let k = 1usize << D;
        // the pairs in parallel, each uniting its corners (the sets, so the
        // vertices, do not depend on the order of the unions)
        let uf = AtomicUnionFind::new(self.n_nodes() * k);
        let corner_mismatches = (0..self.n_sides() as u32)
            .into_par_iter()
            .with_min_len(1024)
            .map(Side)
            .filter_map(|s| {
                let t = self.opposite(s)?;
                (t > s && self.is_alive(self.node_of(s))).then_some((s, t))
            })
            .map(|(s, t)| {
                let (x, y) = (self.node_of(s).idx(), self.node_of(t).idx());
                let Some((pairs, n)) = self.matched_corners(s, t) else {
                    return 1;
                };
                for &(c, ct) in &pairs[..n] {
                    uf.union(x * k + c, y * k + ct);
                }
                0
            })
            .sum();
        let nodes: Vec<Node> = self.alive_nodes().collect();
        let (vertex_of, n_vertices) = self.number_vertices(&uf, &nodes);
        let mut cells = vec![0u32; nodes.len() * k];
        cells.par_chunks_mut(k).zip(&nodes).for_each(|(cell, n)| {
            let rev = self.is_reverted(*n);
            for (j, v) in cell.iter_mut().enumerate() {
                *v = vertex_of[n.idx() * k + cell_code::<D>(j, rev)];
            }
        });
        Glued {
            vertex_of,
            n_vertices,
            unmatched_sides: self.unmatched_sides(),
            boundary_loops: 0,
            components: 0,
            corner_mismatches,
            nodes,
            cells,
        }
    }

    /// The vertex of every corner of the alive `nodes` (the corners' sets
    /// in `uf`), numbered by first corner in node order, [`NO_VERTEX`] for
    /// dead nodes; and the number of vertices. The roots are read in
    /// parallel (no path is changed). A set's root is its smallest corner
    /// (`node·2^D + code`, the node order's), so when every alive corner's
    /// root is an alive node's, the first corners are the roots and their
    /// numbers a parallel prefix count; otherwise one serial pass numbers
    /// them ([`Self::number_serial`]).
    fn number_vertices(&self, uf: &AtomicUnionFind, nodes: &[Node]) -> (Vec<u32>, usize) {
        let k = 1usize << D;
        let mut vertex_of = vec![NO_VERTEX; self.n_nodes() * k];
        let roots_alive = vertex_of
            .par_chunks_mut(k)
            .enumerate()
            .filter(|(n, _)| self.is_alive(Node(*n as u32)))
            .map(|(n, corners)| {
                let mut alive = true;
                for (c, v) in corners.iter_mut().enumerate() {
                    *v = uf.root(n * k + c) as u32;
                    alive &= self.is_alive(Node(*v / k as u32));
                }
                alive
            })
            .reduce(|| true, |a, b| a && b);
        let mut id_of_root = vec![NO_VERTEX; self.n_nodes() * k];
        if !roots_alive {
            let n_vertices = Self::number_serial(&mut vertex_of, &mut id_of_root, nodes);
            return (vertex_of, n_vertices);
        }
        // per block of nodes its first corners (the roots), counted, then
        // numbered from the blocks' prefix sums
        const BLOCK: usize = 4096;
        // the first corners (roots) of node `n`, whose roots are `corners`
        fn is_first((n, corners): (usize, &[u32])) -> impl Iterator<Item = usize> + '_ {
            let at = n * corners.len();
            (at..at + corners.len()).filter(move |&i| corners[i - at] as usize == i)
        }
        let counts: Vec<u32> = vertex_of
            .par_chunks(BLOCK * k)
            .enumerate()
            .map(|(b, block)| {
                let nodes = block.chunks(k).enumerate().map(|(j, c)| (b * BLOCK + j, c));
                nodes.flat_map(is_first).count() as u32
            })
            .collect();
        let mut base = Vec::with_capacity(counts.len());
        let mut n_vertices = 0u32;
        for c in counts {
            base.push(n_vertices);
            n_vertices += c;
        }
        id_of_root
            .par_chunks_mut(BLOCK * k)
            .zip(vertex_of.par_chunks(BLOCK * k))
            .zip(base)
            .enumerate()
            .for_each(|(b, ((ids, block), mut next))| {
                let nodes = block.chunks(k).enumerate().map(|(j, c)| (b * BLOCK + j, c));
                for i in nodes.flat_map(is_first) {
                    ids[i - b * BLOCK * k] = next;
                    next += 1;
                }
            });
        vertex_of.par_iter_mut().for_each(|v| {
            if *v != NO_VERTEX {
                *v = id_of_root[*v as usize];
            }
        });
        (vertex_of, n_vertices as usize)
    }

    /// The numbering of [`Self::number_vertices`] in one serial pass over
    /// the alive `nodes`' corners (`vertex_of`: their roots on entry; the
    /// vertices on return); the number of vertices.
    fn number_serial(vertex_of: &mut [u32], id_of_root: &mut [u32], nodes: &[Node]) -> usize {
        let k = 1usize << D;
        let mut n_vertices = 0u32;
        for n in nodes {
            for v in &mut vertex_of[n.idx() * k..(n.idx() + 1) * k] {
                let id = &mut id_of_root[*v as usize];
                if *id == NO_VERTEX {
                    *id = n_vertices;
                    n_vertices += 1;
                }
                *v = *id;
            }
        }
        n_vertices as usize
    }

    /// The nodes' sets through glued pairs, united in parallel (once per
    /// pair, from its smaller side: the link is mutual); the sets do not
    /// depend on the order of the unions.
    pub(crate) fn node_sets(&self) -> AtomicUnionFind {
        let uf = AtomicUnionFind::new(self.n_nodes());
        (0..self.n_sides() as u32)
            .into_par_iter()
            .with_min_len(1024)
            .map(Side)
            .for_each(|s| {
                if let Some(t) = self.opposite(s).filter(|&t| t > s) {
                    uf.union(self.node_of(s).idx(), self.node_of(t).idx());
                }
            });
        uf
    }

    /// Connected components of alive nodes (through glued pairs).
    pub fn components(&self) -> usize {
        let uf = self.node_sets();
        // a set's root is its smallest node: when every alive node's root
        // is alive, the components are the alive roots, counted in parallel
        let (roots, roots_alive) = (0..self.n_nodes())
            .into_par_iter()
            .with_min_len(1024)
            .filter(|&x| self.is_alive(Node(x as u32)))
            .map(|x| {
                let r = uf.root(x);
                (usize::from(r == x), self.is_alive(Node(r as u32)))
            })
            .reduce(|| (0, true), |a, b| (a.0 + b.0, a.1 && b.1));
        if roots_alive {
            return roots;
        }
        let mut roots: Vec<usize> = self.alive_nodes().map(|n| uf.root(n.idx())).collect();
        roots.sort_unstable();
        roots.dedup();
        roots.len()
    }

    /// Boundary components counted on unmatched sides of alive nodes: two
    /// unmatched sides are adjacent when the fan of nodes around their
    /// common corner (2D) / edge (3D) leads from one to the other.
    pub fn boundary_components(&self) -> usize {
        let free: Vec<Side> = (0..self.n_sides() as u32)
            .map(Side)
            .filter(|&s| self.opposite(s).is_none() && self.is_alive(self.node_of(s)))
            .collect();
        // none (a closed graph): no union–find over every side to build
        if free.is_empty() {
            return 0;
        }
        let mut uf = UnionFind::new(self.n_sides());
        for &s in &free {
            let sd = self.dir_of(s);
            for p in (0..2 * D).filter(|&p| axis(p) != axis(sd)) {
                if let Some(u) = self.fan_walk(self.node_of(s), sd, p) {
                    uf.union(s.idx(), u.idx());
                }
            }
        }
        let mut roots: Vec<usize> = free.iter().map(|s| uf.find(s.idx())).collect();
        roots.sort_unstable();
        roots.dedup();
        roots.len()
    }

    /// Turns around the corner/edge between sides `sin` and `sout` of `x`,
    /// leaving through `sout`, until an unmatched side is reached.
    fn fan_walk(&self, x: Node, sin: usize, sout: usize) -> Option<Side> {
        let (mut x, mut sin, mut sout) = (x, sin, sout);
        for _ in 0..=self.n_sides() {
            let s = self.side(x, sout);
            let Some(t) = self.opposite(s) else {
                return Some(s);
            };
            let rho = self.rot[s.idx()];
            (x, sin, sout) = (self.node_of(t), self.dir_of(t), rho.apply_dir(sin));
            if axis(sin) == axis(sout) {
                return None;
            }
        }
        None
    }
}

impl<const D: usize> Glued<D> {
    /// Number of cells.
    pub fn n_cells(&self) -> usize {
        self.nodes.len()
    }

    /// Every cell's `K = 2^D` vertices in output order, in cell order
    /// (borrowed: no copy).
    pub fn cell_array<const K: usize>(&self) -> &[[u32; K]] {
        assert_eq!(K, 1 << D, "bug: a cell of dimension {D} has 2^{D} corners");
        self.cells.as_chunks::<K>().0
    }

    /// The vertices of cell `i` in output order (`None` out of range).
    pub fn cell(&self, i: usize) -> Option<&[u32]> {
        let k = 1 << D;
        self.cells.get(i * k..(i + 1) * k)
    }

    /// The vertex of corner `code` of `node` ([`NO_VERTEX`] if dead or out
    /// of range).
    pub fn vertex(&self, node: Node, code: usize) -> u32 {
        let k = 1usize << D;
        if code >= k {
            return NO_VERTEX;
        }
        self.vertex_of
            .get(node.idx() * k + code)
            .copied()
            .unwrap_or(NO_VERTEX)
    }

    /// Unique mesh edges (sorted vertex pairs, sorted), from the corners of
    /// each cell that differ in one bit.
    pub fn edges(&self) -> Vec<(u32, u32)> {
        let k = 1usize << D;
        let mut out = Vec::with_capacity(self.nodes.len() * D * k / 2);
        for n in &self.nodes {
            for c in 0..k {
                for bit in (0..D).map(|a| 1usize << a).filter(|b| c & b == 0) {
                    let (p, q) = (self.vertex(*n, c), self.vertex(*n, c | bit));
                    out.push((p.min(q), p.max(q)));
                }
            }
        }
        out.sort_unstable();
        out.dedup();
        out
    }
}

impl Glued<2> {
    /// The quads, counter-clockwise, with their nodes.
    pub fn cells(&self) -> impl Iterator<Item = (Node, [u32; 4])> + '_ {
        self.nodes
            .iter()
            .zip(self.cells.chunks_exact(4))
            .map(|(n, c)| (*n, [c[0], c[1], c[2], c[3]]))
    }
}

impl Glued<3> {
    /// The hexes, in VTK order, with their nodes.
    pub fn cells(&self) -> impl Iterator<Item = (Node, [u32; 8])> + '_ {
        self.nodes
            .iter()
            .zip(self.cells.chunks_exact(8))
            .map(|(n, c)| (*n, std::array::from_fn(|i| c[i])))
    }
}
