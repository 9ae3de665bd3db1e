//! Checks of an all-quad surface mesh.
//!
//! Input: the number of vertices and the quads as 4 vertex indices,
//! counter-clockwise seen from the front. Output: a [`QuadReport`].
//!
//! Conventions:
//! - a face with an index `>= n_vertices` is *out of range*, a face with a
//!   repeated vertex is *degenerate*; both are reported and then ignored, so
//!   every count below is over the remaining ("good") faces;
//! - *used* vertices are those of good faces; Euler characteristic is
//!   `V_used − E + F_good`;
//! - an edge is *boundary* with 1 face, *non-manifold* with more than 2, and
//!   *misoriented* when its 2 faces traverse it in the same direction;
//! - a vertex is *non-manifold* when the faces around it do not form a single
//!   fan (faces are linked when they share an edge at the vertex): a bowtie;
//! - boundary loops are the connected components of the graph of boundary
//!   edges (exact on a manifold mesh);
//! - a vertex is *boundary* when it lies on a boundary edge; valences
//!   (number of distinct edges at a vertex) are histogrammed separately for
//!   interior and boundary vertices.

use crate::classify::{classify, out_of_range, repeated, Class};
use crate::tally::Tally;
use dualex_util::bucket;
use dualex_util::union_find::UnionFind;
use std::collections::{BTreeMap, HashMap};

/// What [`check_quad_mesh`] found; see the module docs for definitions.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct QuadReport {
    /// Number of vertices given.
    pub n_vertices: usize,
    /// Number of faces given.
    pub faces: usize,
    /// Vertices used by good faces.
    pub vertices_used: usize,
    /// Vertices used by no good face.
    pub unused_vertices: usize,
    /// Distinct edges.
    pub edges: usize,
    /// Edges with exactly one face.
    pub boundary_edges: usize,
    /// Connected components of the boundary edges.
    pub boundary_loops: usize,
    /// Connected components of the good faces (through shared vertices).
    pub components: usize,
    /// `V_used − E + F_good`.
    pub euler: i64,
    /// Valence → number of interior vertices with it.
    pub interior_valence: BTreeMap<u32, usize>,
    /// Valence → number of boundary vertices with it.
    pub boundary_valence: BTreeMap<u32, usize>,
    /// Faces referring to a vertex `>= n_vertices`.
    pub out_of_range_faces: Vec<usize>,
    /// Faces with a repeated vertex.
    pub degenerate_faces: Vec<usize>,
    /// Edges (sorted vertex pair) with more than 2 faces.
    pub non_manifold_edges: Vec<[u32; 2]>,
    /// Vertices whose faces form more than one fan.
    pub non_manifold_vertices: Vec<u32>,
    /// Edges (sorted vertex pair) traversed twice in the same direction.
    pub misoriented_edges: Vec<[u32; 2]>,
}

/// Uses of an undirected edge `(lo, hi)`: faces going `lo → hi` and back.
#[derive(Clone, Copy, Default)]
struct EdgeUse {
    forward: u32,
    backward: u32,
}

impl EdgeUse {
    fn total(&self) -> u32 {
        self.forward + self.backward
    }
}

/// Checks a quad mesh; never panics, whatever the input.
pub fn check_quad_mesh(n_vertices: usize, quads: &[[u32; 4]]) -> QuadReport {
    let mut r = QuadReport {
        n_vertices,
        faces: quads.len(),
        ..QuadReport::default()
    };
    let sorted = classify(quads, |q| class_of(n_vertices, q));
    (r.out_of_range_faces, r.degenerate_faces) = (sorted.out_of_range, sorted.degenerate);
    let good = sorted.good;
    let mut used = vec![false; n_vertices];
    for q in good.iter() {
        for &v in q {
            used[v as usize] = true;
        }
    }
    // the corners by vertex beside the components; the edges and the fans
    // read from the same corners, side by side
    let (corners, components) = rayon::join(
        || corner_groups(n_vertices, &good),
        || components(n_vertices, &good, &used),
    );
    let (edges, non_manifold) =
        rayon::join(|| edge_uses(&corners), || non_manifold_vertices(&corners));
    drop(corners);
    r.edges = edges.len();
    let mut on_boundary = vec![false; n_vertices];
    let mut valence = vec![0u32; n_vertices];
    let mut boundary_uf = UnionFind::new(n_vertices);
    for &((a, b), u) in &edges {
        valence[a as usize] += 1;
        valence[b as usize] += 1;
        match u.total() {
            1 => {
                r.boundary_edges += 1;
                on_boundary[a as usize] = true;
                on_boundary[b as usize] = true;
                boundary_uf.union(a as usize, b as usize);
            }
            2 if u.forward != 1 => r.misoriented_edges.push([a, b]),
            2 => {}
            _ => r.non_manifold_edges.push([a, b]),
        }
    }
    r.misoriented_edges.sort_unstable();
    r.non_manifold_edges.sort_unstable();
    let (mut boundary, mut interior) = (Tally::default(), Tally::default());
    for v in (0..n_vertices).filter(|&v| used[v]) {
        let hist = if on_boundary[v] {
            &mut boundary
        } else {
            &mut interior
        };
        hist.add(valence[v]);
    }
    boundary.into_map(&mut r.boundary_valence);
    interior.into_map(&mut r.interior_valence);
    r.vertices_used = used.iter().filter(|&&u| u).count();
    r.unused_vertices = n_vertices - r.vertices_used;
    r.boundary_loops = boundary_uf.count_sets((0..n_vertices).filter(|&v| on_boundary[v]));
    r.components = components;
    r.euler = r.vertices_used as i64 - r.edges as i64 + good.len() as i64;
    r.non_manifold_vertices = non_manifold;
    r
}

/// The [`Class`] of face `q` among `n` vertices.
fn class_of(n: usize, q: &[u32; 4]) -> Class {
    if out_of_range(n, q) {
        Class::OutOfRange
    } else if repeated(q) {
        Class::Degenerate
    } else {
        Class::Good
    }
}

/// (vertex, previous vertex, next vertex) for every corner of every face
/// (vertices below `n`), bucketed by vertex, each vertex's few corners
/// sorted (no sort of them all).
fn corner_groups(n: usize, faces: &[[u32; 4]]) -> Vec<(u32, u32, u32)> {
    let (_, corners) = bucket::sorted(n, |emit| {
        for q in faces {
            for i in 0..4 {
                emit(q[i] as usize, (q[i], q[(i + 3) % 4], q[(i + 1) % 4]));
            }
        }
    });
    corners
}

/// Directed uses of every undirected edge `(lo, hi)` of the faces, in
/// `(lo, hi)` order, read from the corners by vertex ([`corner_groups`]):
/// a side `a → b` is the next of `a`'s corner and the previous of `b`'s,
/// so it is counted once, at its lower end: `lo → next` forward,
/// `prev → lo` backward.
fn edge_uses(corners: &[(u32, u32, u32)]) -> Vec<((u32, u32), EdgeUse)> {
    let mut edges = Vec::new();
    // (hi, backward) of the sides at one vertex
    let mut ends: Vec<(u32, bool)> = Vec::new();
    for group in corners.chunk_by(|a, b| a.0 == b.0) {
        let lo = group[0].0;
        ends.clear();
        for &(_, prev, next) in group {
            if next > lo {
                ends.push((next, false));
            }
            if prev > lo {
                ends.push((prev, true));
            }
        }
        ends.sort_unstable();
        for run in ends.chunk_by(|x, y| x.0 == y.0) {
            let backward = run.iter().filter(|e| e.1).count() as u32;
            let forward = run.len() as u32 - backward;
            edges.push(((lo, run[0].0), EdgeUse { forward, backward }));
        }
    }
    edges
}

/// Connected components of the faces through shared vertices.
fn components(n: usize, faces: &[[u32; 4]], used: &[bool]) -> usize {
    let mut uf = UnionFind::new(n);
    for q in faces {
        for i in 1..4 {
            uf.union(q[0] as usize, q[i] as usize);
        }
    }
    uf.count_sets((0..n).filter(|&v| used[v]))
}

/// Vertices whose incident faces form more than one fan, from the
/// corners by vertex ([`corner_groups`]).
fn non_manifold_vertices(corners: &[(u32, u32, u32)]) -> Vec<u32> {
    let mut out = Vec::new();
    for group in corners.chunk_by(|a, b| a.0 == b.0) {
        if fans(group) > 1 {
            out.push(group[0].0);
        }
    }
    out
}

/// Number of fans among the corners at one vertex (linked by a shared edge).
fn fans(group: &[(u32, u32, u32)]) -> usize {
    const SMALL: usize = 32;
    if group.len() > SMALL {
        return fans_large(group);
    }
    // pairwise on the stack: two corners are linked when they share an
    // edge, i.e. a neighbour vertex
    let mut parent: [usize; SMALL] = std::array::from_fn(|i| i);
    fn root(parent: &mut [usize; SMALL], mut i: usize) -> usize {
        while parent[i] != i {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        i
    }
    for (i, &(_, pi, ni)) in group.iter().enumerate() {
        for (j, &(_, pj, nj)) in group[..i].iter().enumerate() {
            if pi == pj || pi == nj || ni == pj || ni == nj {
                let (ri, rj) = (root(&mut parent, i), root(&mut parent, j));
                parent[ri] = rj;
            }
        }
    }
    (0..group.len())
        .filter(|&i| root(&mut parent, i) == i)
        .count()
}

/// [`fans`] for a vertex with many corners.
fn fans_large(group: &[(u32, u32, u32)]) -> usize {
    let mut uf = UnionFind::new(group.len());
    let mut first_with: HashMap<u32, usize> = HashMap::new();
    for (i, &(_, prev, next)) in group.iter().enumerate() {
        for w in [prev, next] {
            match first_with.get(&w) {
                Some(&j) => {
                    uf.union(i, j);
                }
                None => {
                    first_with.insert(w, i);
                }
            }
        }
    }
    uf.count_sets(0..group.len())
}

impl QuadReport {
    /// No out-of-range or degenerate face, manifold edges and vertices,
    /// consistent orientation.
    pub fn is_valid(&self) -> bool {
        self.errors().is_empty()
    }

    /// One line per kind of defect (empty when valid).
    pub fn errors(&self) -> Vec<String> {
        let mut out = Vec::new();
        let mut push = |n: usize, what: &str, first: String| {
            if n > 0 {
                out.push(format!("{n} {what} (first: {first})"));
            }
        };
        let first = |v: Option<String>| v.unwrap_or_default();
        push(
            self.out_of_range_faces.len(),
            "faces with a vertex index out of range",
            first(self.out_of_range_faces.first().map(|f| format!("face {f}"))),
        );
        push(
            self.degenerate_faces.len(),
            "degenerate faces (repeated vertex)",
            first(self.degenerate_faces.first().map(|f| format!("face {f}"))),
        );
        push(
            self.non_manifold_edges.len(),
            "non-manifold edges (more than 2 faces)",
            first(
                self.non_manifold_edges
                    .first()
                    .map(|e| format!("edge {e:?}")),
            ),
        );
        push(
            self.non_manifold_vertices.len(),
            "non-manifold vertices (more than one fan)",
            first(
                self.non_manifold_vertices
                    .first()
                    .map(|v| format!("vertex {v}")),
            ),
        );
        push(
            self.misoriented_edges.len(),
            "inconsistently oriented edges",
            first(
                self.misoriented_edges
                    .first()
                    .map(|e| format!("edge {e:?}")),
            ),
        );
        out
    }
}

#[cfg(test)]
mod tests;
