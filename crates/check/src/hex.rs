//! Checks of an all-hex volume mesh.
//!
//! Input: the number of vertices, the hexes as 8 vertex indices in VTK order
//! (bottom face 0-1-2-3 counter-clockwise seen from the top, then 4-5-6-7
//! with `i + 4` above `i`), and optionally the vertex positions.
//! Output: a [`HexReport`].
//!
//! ```text
//!        7 --- 6        faces, outward:  0-3-2-1 (bottom)  4-5-6-7 (top)
//!       /|    /|                         0-1-5-4  1-2-6-5  2-3-7-6  3-0-4-7
//!      4 --- 5 |
//!      | 3 --|-2        corner (x,y,z) bits ↔ VTK index: [0,1,3,2][x+2y] + 4z
//!      |/    |/
//!      0 --- 1
//! ```
//! Conventions:
//! - cells with an index out of range or a repeated vertex (or two equal
//!   faces) are reported and ignored; all counts are over the good cells;
//! - a face (a set of 4 vertices) is *boundary* with 1 cell, *non-manifold*
//!   with more than 2, *misoriented* when its 2 cells do not traverse it in
//!   opposite directions (same direction, or a different cycle);
//! - with positions, a cell is *inverted* when the Jacobian determinant at
//!   one of its 8 corners is `<= 0`;
//! - *interior edges* are edges on no boundary face; their valence is the
//!   number of cells around them; one of valence 1 or 2 is an error (a
//!   doublet: its cells share two faces and cannot all be positive);
//! - the boundary faces, oriented outwards, are checked as a quad mesh
//!   ([`HexReport::boundary`]): its components, Euler characteristic and
//!   non-manifold edges/vertices are those of the boundary surface;
//! - the volume Euler characteristic is `V − E + F − C` over good cells.

use crate::classify::{classify, out_of_range, repeated, Class};
use crate::quad::{check_quad_mesh, QuadReport};
use crate::tally::Tally;
use dualex_util::bucket;
use dualex_util::union_find_par::AtomicUnionFind;
use std::collections::BTreeMap;

/// The 6 faces of a hex, oriented outwards for a positive hex (the one
/// copy: `dualex_cells::cells` re-exports it, the checker depending on no
/// crate it checks).
pub const HEX_FACES: [[usize; 4]; 6] = [
    [0, 3, 2, 1],
    [4, 5, 6, 7],
    [0, 1, 5, 4],
    [1, 2, 6, 5],
    [2, 3, 7, 6],
    [3, 0, 4, 7],
];

/// The 12 edges of a hex.
pub const HEX_EDGES: [[usize; 2]; 12] = [
    [0, 1],
    [1, 2],
    [2, 3],
    [3, 0],
    [4, 5],
    [5, 6],
    [6, 7],
    [7, 4],
    [0, 4],
    [1, 5],
    [2, 6],
    [3, 7],
];

/// What [`check_hex_mesh`] found; see the module docs for definitions.
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct HexReport {
    /// Number of vertices given.
    pub n_vertices: usize,
    /// Number of cells given.
    pub cells: usize,
    /// Vertices used by good cells.
    pub vertices_used: usize,
    /// Distinct faces of the good cells.
    pub faces: usize,
    /// Faces with exactly one cell.
    pub boundary_faces: usize,
    /// Distinct edges of the good cells.
    pub edges: usize,
    /// Connected components of the good cells (through shared vertices).
    pub components: usize,
    /// `V − E + F − C` over good cells.
    pub euler: i64,
    /// Valence (cells around) → number of interior edges with it.
    pub interior_edge_valence: BTreeMap<u32, usize>,
    /// Cells referring to a vertex `>= n_vertices`.
    pub out_of_range_cells: Vec<usize>,
    /// Cells with a repeated vertex or two equal faces.
    pub degenerate_cells: Vec<usize>,
    /// Faces (sorted vertices) with more than 2 cells.
    pub non_manifold_faces: Vec<[u32; 4]>,
    /// Faces (sorted vertices) whose 2 cells do not traverse them oppositely.
    pub misoriented_faces: Vec<[u32; 4]>,
    /// Cells with a corner Jacobian `<= 0`; `None` without positions.
    pub inverted_cells: Option<Vec<usize>>,
    /// Positions were given but fewer than `n_vertices`.
    pub missing_positions: bool,
    /// The boundary surface (faces oriented outwards) as a quad mesh.
    pub boundary: QuadReport,
}

/// Checks a hex mesh; never panics, whatever the input.
pub fn check_hex_mesh(
    n_vertices: usize,
    hexes: &[[u32; 8]],
    positions: Option<&[[f64; 3]]>,
) -> HexReport {
    let mut r = HexReport {
        n_vertices,
        cells: hexes.len(),
        ..HexReport::default()
    };
    let sorted = classify(hexes, |h| class_of(n_vertices, h));
    (r.out_of_range_cells, r.degenerate_cells) = (sorted.out_of_range, sorted.degenerate);
    let good = sorted.good;
    // independent passes, one after the other (side by side, their
    // buffers, allocated on the pool's threads, raised the peak); the
    // faces (the largest buffer, 192 bytes a cell) are gone before the
    // edges (96) are made
    let (used, components) = used_and_components(n_vertices, &good);
    let boundary_quads = face_stats(n_vertices, &good, &mut r);
    r.boundary_faces = boundary_quads.len();
    r.boundary = check_quad_mesh(n_vertices, &boundary_quads);
    let edges = sorted_edges(n_vertices, &good);
    edge_stats(&edges, &boundary_quads, &mut r);
    (r.vertices_used, r.components) = (used, components);
    r.euler = r.vertices_used as i64 - r.edges as i64 + r.faces as i64 - good.len() as i64;
    if let Some(p) = positions {
        r.missing_positions = p.len() < n_vertices;
        r.inverted_cells = Some(inverted_cells(hexes, p, &r));
    }
    r
}

/// The [`Class`] of hex `h` among `n` vertices.
fn class_of(n: usize, h: &[u32; 8]) -> Class {
    if out_of_range(n, h) {
        return Class::OutOfRange;
    }
    let repeated = repeated(h);
    let mut keys = HEX_FACES.map(|f| face_key(h, &f));
    keys.sort_unstable();
    let distinct = 1 + keys.windows(2).filter(|w| w[0] != w[1]).count();
    if repeated || distinct < 6 {
        Class::Degenerate
    } else {
        Class::Good
    }
}

/// The sorted vertices of face `f` of hex `h`.
fn face_key(h: &[u32; 8], f: &[usize; 4]) -> [u32; 4] {
    let mut k = f.map(|i| h[i]);
    k.sort_unstable();
    k
}

/// The faces of the cells (vertices below `n`, [`face_uses`]) counted
/// into `r` (faces, misoriented and non-manifold ones, sorted); returns
/// the boundary faces (one cell), as outward cycles, sorted. The runs
/// (one per face) are read in parallel; every list is sorted after, so
/// the result does not depend on the threads.
fn face_stats(n: usize, cells: &[[u32; 8]], r: &mut HexReport) -> Vec<[u32; 4]> {
    use rayon::prelude::*;
    let faces = face_uses(n, cells);
    let (count, mut lists) = faces
        .par_chunk_by(|x, y| x.0 == y.0)
        .fold(
            || (0, FaceLists::default()),
            |(count, mut l), uses| {
                let key = uses[0].0;
                match uses {
                    [one] => l.boundary.push(one.1),
                    [a, b] if !opposite(&a.1, &b.1) => l.misoriented.push(key),
                    [_, _] => {}
                    _ => l.non_manifold.push(key),
                }
                (count + 1, l)
            },
        )
        .reduce(
            || (0, FaceLists::default()),
            |(n, mut a), (m, b)| {
                a.append(b);
                (n + m, a)
            },
        );
    drop(faces);
    r.faces += count;
    r.misoriented_faces.append(&mut lists.misoriented);
    r.non_manifold_faces.append(&mut lists.non_manifold);
    r.misoriented_faces.par_sort_unstable();
    r.non_manifold_faces.par_sort_unstable();
    lists.boundary.par_sort_unstable();
    lists.boundary
}

/// Cells per parallel task of [`used_and_components`].
const CELL_TASK: usize = 1 << 12;

/// What [`face_stats`] collects from the face runs.
#[derive(Default)]
struct FaceLists {
    /// The faces of one cell, as their outward cycles.
    boundary: Vec<[u32; 4]>,
    /// The faces of two cells that run the same way.
    misoriented: Vec<[u32; 4]>,
    /// The faces of more than two cells.
    non_manifold: Vec<[u32; 4]>,
}

impl FaceLists {
    /// `other`'s faces added to these.
    fn append(&mut self, mut other: FaceLists) {
        self.boundary.append(&mut other.boundary);
        self.misoriented.append(&mut other.misoriented);
        self.non_manifold.append(&mut other.non_manifold);
    }
}

/// Every face of every cell (vertices below `n`) as (sorted vertices,
/// outward cycle), sorted (bucketed by the least vertex, each bucket
/// sorted: no sort of them all): one run per vertex set.
fn face_uses(n: usize, cells: &[[u32; 8]]) -> Vec<([u32; 4], [u32; 4])> {
    let (_, faces) = bucket::sorted(n, |emit| {
        for h in cells {
            for f in &HEX_FACES {
                let key = face_key(h, f);
                emit(key[0] as usize, (key, f.map(|i| h[i])));
            }
        }
    });
    faces
}

/// The faces of one cell (the boundary) of `hexes`, as (cell, face of
/// [`HEX_FACES`]), sorted; faces are equal when their four vertices are,
/// whatever their order. Every cell counts, good or not (the geometric
/// stage's boundary vertices; [`check_hex_mesh`] judges the cells). The
/// faces are bucketed by their least vertex ([`bucket::sorted`]), as the
/// tets' in [`crate::topology::lone_tet_faces`].
pub fn lone_hex_faces(hexes: &[[u32; 8]]) -> Vec<(usize, usize)> {
    let (_, faces) = bucket::sorted(hexes.len(), |emit| {
        for (h, cell) in hexes.iter().enumerate() {
            for (f, face) in HEX_FACES.iter().enumerate() {
                let key = face_key(cell, face);
                emit(key[0] as usize, (key, h, f));
            }
        }
    });
    let mut lone: Vec<(usize, usize)> = faces
        .chunk_by(|x, y| x.0 == y.0)
        .filter_map(|run| match run {
            [(_, h, f)] => Some((*h, *f)),
            _ => None,
        })
        .collect();
    lone.sort_unstable();
    lone
}

/// Whether cycle `b` is cycle `a` traversed backwards.
fn opposite(a: &[u32; 4], b: &[u32; 4]) -> bool {
    (0..4).any(|s| (0..4).all(|i| a[i] == b[(s + 4 - i) % 4]))
}

/// The undirected edges of the cells (vertices below `n`), one entry per
/// cell edge, sorted (bucketed by the smaller vertex, each bucket
/// sorted): one run per edge.
fn sorted_edges(n: usize, cells: &[[u32; 8]]) -> Vec<u64> {
    let key = crate::topology::edge_key;
    let (_, edges) = bucket::sorted(n, |emit| {
        for h in cells {
            for e in &HEX_EDGES {
                let (a, b) = (h[e[0]], h[e[1]]);
                emit(a.min(b) as usize, key(a, b));
            }
        }
    });
    edges
}

/// The number of vertices used by the cells, and of the cells' connected
/// components (through shared vertices); the unions in parallel (the
/// shared union–find's representative of a set is its smallest element,
/// whatever the order: a set is counted at its representative).
fn used_and_components(n_vertices: usize, cells: &[[u32; 8]]) -> (usize, usize) {
    use rayon::prelude::*;
    use std::sync::atomic::{AtomicBool, Ordering::Relaxed};
    let used: Vec<AtomicBool> = (0..n_vertices).map(|_| AtomicBool::new(false)).collect();
    let uf = AtomicUnionFind::new(n_vertices);
    cells.par_chunks(CELL_TASK).for_each(|part| {
        for h in part {
            for &v in h {
                used[v as usize].store(true, Relaxed);
                uf.union(h[0] as usize, v as usize);
            }
        }
    });
    (0..n_vertices)
        .into_par_iter()
        .with_min_len(1 << 14)
        .filter(|&v| used[v].load(Relaxed))
        .map(|v| (1, usize::from(uf.root(v) == v)))
        .reduce(|| (0, 0), |a, b| (a.0 + b.0, a.1 + b.1))
}

/// Edge count and the valence histogram of interior edges, from the
/// sorted cell edges ([`sorted_edges`]) and the boundary quads.
fn edge_stats(edges: &[u64], boundary: &[[u32; 4]], r: &mut HexReport) {
    use rayon::prelude::*;
    let key = crate::topology::edge_key;
    let mut on_boundary: Vec<u64> = boundary
        .iter()
        .flat_map(|q| (0..4).map(move |i| key(q[i], q[(i + 1) % 4])))
        .collect();
    on_boundary.par_sort_unstable();
    // runs (one per edge) counted in parallel
    let (count, valences) = edges
        .par_chunk_by(|x, y| x == y)
        .fold(
            || (0, Tally::default()),
            |(count, mut valences), run| {
                if on_boundary.binary_search(&run[0]).is_err() {
                    valences.add(run.len() as u32);
                }
                (count + 1, valences)
            },
        )
        .reduce(
            || (0, Tally::default()),
            |(n, mut a), (m, b)| {
                a.merge(b);
                (n + m, a)
            },
        );
    r.edges += count;
    valences.into_map(&mut r.interior_edge_valence);
}

/// VTK index of the corner with coordinate bits `(x, y, z)`.
fn vtk(x: usize, y: usize, z: usize) -> usize {
    [0, 1, 3, 2][x + 2 * y] + 4 * z
}

/// Good cells (not out of range, not degenerate) with a corner Jacobian
/// `<= 0`, or whose positions are missing.
fn inverted_cells(hexes: &[[u32; 8]], p: &[[f64; 3]], r: &HexReport) -> Vec<usize> {
    let skip = |c: usize| r.out_of_range_cells.contains(&c) || r.degenerate_cells.contains(&c);
    let mut out = Vec::new();
    for (c, h) in hexes.iter().enumerate() {
        if skip(c) {
            continue;
        }
        let pos: Option<Vec<[f64; 3]>> = h.iter().map(|&v| p.get(v as usize).copied()).collect();
        let ok = pos.is_some_and(|pos| min_corner_jacobian(&pos) > 0.0);
        if !ok {
            out.push(c);
        }
    }
    out
}

/// Smallest determinant of the three edge vectors at a corner, each edge
/// pointing towards growing `x`, `y`, `z` of the reference cube.
fn min_corner_jacobian(pos: &[[f64; 3]]) -> f64 {
    let mut min = f64::INFINITY;
    for z in 0..2 {
        for y in 0..2 {
            for x in 0..2 {
                let p = pos[vtk(x, y, z)];
                let e = |q: usize, s: usize| -> [f64; 3] {
                    let sign = if s == 0 { 1.0 } else { -1.0 };
                    std::array::from_fn(|k| sign * (pos[q][k] - p[k]))
                };
                let ex = e(vtk(1 - x, y, z), x);
                let ey = e(vtk(x, 1 - y, z), y);
                let ez = e(vtk(x, y, 1 - z), z);
                let det = ex[0] * (ey[1] * ez[2] - ey[2] * ez[1])
                    - ex[1] * (ey[0] * ez[2] - ey[2] * ez[0])
                    + ex[2] * (ey[0] * ez[1] - ey[1] * ez[0]);
                min = min.min(det);
            }
        }
    }
    min
}

impl HexReport {
    /// No out-of-range, degenerate or inverted cell, manifold and
    /// consistently oriented faces, a manifold oriented boundary surface.
    pub fn is_valid(&self) -> bool {
        self.errors().is_empty()
    }

    /// One line per kind of defect (empty when valid).
    pub fn errors(&self) -> Vec<String> {
        let mut out = Vec::new();
        let mut push = |n: usize, what: &str, first: Option<String>| {
            if n > 0 {
                out.push(format!("{n} {what} (first: {})", first.unwrap_or_default()));
            }
        };
        let cell = |c: Option<&usize>| c.map(|c| format!("cell {c}"));
        let face = |f: Option<&[u32; 4]>| f.map(|f| format!("face {f:?}"));
        push(
            self.out_of_range_cells.len(),
            "cells with a vertex index out of range",
            cell(self.out_of_range_cells.first()),
        );
        push(
            self.degenerate_cells.len(),
            "degenerate cells",
            cell(self.degenerate_cells.first()),
        );
        push(
            self.non_manifold_faces.len(),
            "non-manifold faces (more than 2 cells)",
            face(self.non_manifold_faces.first()),
        );
        push(
            self.misoriented_faces.len(),
            "inconsistently oriented faces",
            face(self.misoriented_faces.first()),
        );
        let inverted = self.inverted_cells.as_deref().unwrap_or(&[]);
        push(
            inverted.len(),
            "inverted cells (corner Jacobian <= 0)",
            cell(inverted.first()),
        );
        if self.missing_positions {
            out.push("fewer positions than vertices".to_string());
        }
        // an interior edge needs 3 cells at least: in 2, they share two
        // faces (a doublet) and are flat or inverted wherever they lie
        let thin: usize = self.interior_edge_valence.range(..3).map(|(_, n)| n).sum();
        if thin > 0 {
            out.push(format!(
                "{thin} interior edges in fewer than 3 cells (doublets: two hexes sharing two faces)"
            ));
        }
        for e in self.boundary.errors() {
            out.push(format!("boundary surface: {e}"));
        }
        out
    }
}

#[cfg(test)]
mod tests;
