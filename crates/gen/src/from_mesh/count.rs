//! Expected counts of a refined mesh, by counting its combinatorics (no
//! extraction involved).
//!
//! Input: `M_k` as a quad or hex mesh. Output: [`Expected`] (quads,
//! interior valence histogram, Euler characteristic `V − E + F`, boundary
//! loops) or [`ExpectedHex`] (hexes, boundary surface components and Euler
//! characteristic). Boundary loops are the connected components of the
//! boundary edges (equal to the loops on a manifold boundary).

use crate::block::ExpectedHex;
use crate::expected::Expected;
use dualex_cells::{HexMesh, QuadMesh};
use dualex_util::union_find::UnionFind;
use std::collections::{BTreeMap, HashMap};

/// Counts of a quad (or any polygon) surface given as cycles of vertices.
struct Surface {
    vertices: usize,
    edges: usize,
    faces: usize,
    /// Faces around each used vertex.
    valence: HashMap<u32, u32>,
    /// Vertices on a boundary edge.
    boundary: Vec<u32>,
    /// Components of the boundary edges.
    boundary_loops: usize,
}

fn surface(n: usize, faces: &[Vec<u32>]) -> Surface {
    let mut edge_faces: HashMap<(u32, u32), usize> = HashMap::new();
    let mut valence: HashMap<u32, u32> = HashMap::new();
    for f in faces {
        for (i, &a) in f.iter().enumerate() {
            let b = f[(i + 1) % f.len()];
            *edge_faces.entry((a.min(b), a.max(b))).or_insert(0) += 1;
            *valence.entry(a).or_insert(0) += 1;
        }
    }
    let mut sets = UnionFind::new(n);
    let mut on_boundary = vec![false; n];
    for (&(a, b), &c) in &edge_faces {
        if c == 1 {
            sets.union(a as usize, b as usize);
            on_boundary[a as usize] = true;
            on_boundary[b as usize] = true;
        }
    }
    let boundary: Vec<u32> = (0..n as u32).filter(|&v| on_boundary[v as usize]).collect();
    let mut roots: Vec<usize> = boundary.iter().map(|&v| sets.find(v as usize)).collect();
    roots.sort_unstable();
    roots.dedup();
    Surface {
        vertices: valence.len(),
        edges: edge_faces.len(),
        faces: faces.len(),
        valence,
        boundary,
        boundary_loops: roots.len(),
    }
}

impl Surface {
    fn euler(&self) -> i64 {
        self.vertices as i64 - self.edges as i64 + self.faces as i64
    }

    fn interior_valence(&self) -> BTreeMap<u32, usize> {
        let mut h = BTreeMap::new();
        for (v, &val) in &self.valence {
            if self.boundary.binary_search(v).is_err() {
                *h.entry(val).or_insert(0) += 1;
            }
        }
        h
    }
}

/// The counts of `M_k` itself: what a map without half shift extracts to.
pub fn expected_quad(mesh: &QuadMesh) -> Expected {
    let faces: Vec<Vec<u32>> = mesh.cells.iter().map(|c| c.to_vec()).collect();
    let s = surface(mesh.positions.len(), &faces);
    Expected {
        quads: Some(s.faces),
        interior_valence: Some(s.interior_valence()),
        euler: Some(s.euler()),
        boundary_loops: Some(s.boundary_loops),
    }
}

/// The counts of the hex mesh `M_k`.
pub fn expected_hex(mesh: &HexMesh) -> ExpectedHex {
    let mut count: HashMap<[u32; 4], (usize, Vec<u32>)> = HashMap::new();
    for h in &mesh.cells {
        for f in dualex_cells::cells::HEX_FACES {
            let cyc: Vec<u32> = f.iter().map(|&i| h[i]).collect();
            let mut key = [cyc[0], cyc[1], cyc[2], cyc[3]];
            key.sort_unstable();
            count.entry(key).or_insert((0, cyc)).0 += 1;
        }
    }
    let boundary: Vec<Vec<u32>> = count
        .into_values()
        .filter(|(c, _)| *c == 1)
        .map(|(_, cyc)| cyc)
        .collect();
    let s = surface(mesh.positions.len(), &boundary);
    let mut sets = UnionFind::new(mesh.positions.len());
    for f in &boundary {
        for w in f.windows(2) {
            sets.union(w[0] as usize, w[1] as usize);
        }
    }
    let mut roots: Vec<usize> = s.valence.keys().map(|&v| sets.find(v as usize)).collect();
    roots.sort_unstable();
    roots.dedup();
    ExpectedHex {
        hexes: Some(mesh.cells.len()),
        boundary_components: Some(roots.len()),
        boundary_euler: Some(s.euler()),
    }
}
