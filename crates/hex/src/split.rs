//! Step 1b: splitting the tet edges and faces that vertices which cannot
//! move span across the dual grid — the 3D analogue of the 2D split of
//! edges between two singular vertices (`dualex_quad::split`).
//!
//! Input: the map, its local shifted coordinates (singular vertices already
//! on their fixed sets, `dualex_map::singular_snap`), the vertex stars and
//! the singular edges. Output: the faces to split:
//! - every edge whose two ends are singular (they lie on singular edges:
//!   at most one free axis each) and which passes through an iso-line of
//!   the dual grid away from its ends, unless the edge is itself a
//!   singular edge (its midpoint would be as stuck as its ends);
//! - every triangle of three singular vertices that holds a node strictly
//!   inside.
//!
//! The split itself is the dimension-generic `dualex_map::split`: the new
//! vertex is inside the edge or face, so it is not singular and
//! sanitization can move it off the grid. The driver repeats until nothing
//! is left (each pass splits at most one face per tet).

use crate::local::LocalMap;
use crate::near::{segment_near_iso_line, triangle_near_grid_point, EDGES};
use crate::simplex::face_corners;
use dualex_map::{Stars, TetMap};
use std::collections::HashSet;

/// The edges (2 vertex ids, sorted) and faces (3, sorted) to split, edges
/// first, each once, in the order of their first tet.
pub fn faces_to_split(
    map: &TetMap,
    stars: &Stars<3>,
    singular_edges: &HashSet<(u32, u32)>,
    local: &LocalMap,
) -> Vec<Vec<u32>> {
    let sing = |v: u32| stars.singular[v as usize];
    let mut seen: HashSet<Vec<u32>> = HashSet::new();
    let (mut edges, mut faces) = (Vec::new(), Vec::new());
    for (s, tet) in map.simplices.iter().enumerate() {
        let singular_corners = tet.iter().filter(|&&v| sing(v)).count();
        if singular_corners < 2 {
            continue;
        }
        let c = &local.coords[s];
        for [k, l] in EDGES {
            let (a, b) = (tet[k], tet[l]);
            if !(sing(a) && sing(b)) || singular_edges.contains(&(a.min(b), a.max(b))) {
                continue;
            }
            if let Some((at_a, at_b)) = segment_near_iso_line(&c[k], &c[l]) {
                if !at_a && !at_b {
                    let key = vec![a.min(b), a.max(b)];
                    if seen.insert(key.clone()) {
                        edges.push(key);
                    }
                }
            }
        }
        if singular_corners < 3 {
            continue;
        }
        for f in 0..4 {
            let corners = face_corners(f);
            if !corners.iter().all(|&k| sing(tet[k])) {
                continue;
            }
            if triangle_near_grid_point(&corners.map(|k| c[k])) {
                let mut key: Vec<u32> = corners.iter().map(|&k| tet[k]).collect();
                key.sort_unstable();
                if seen.insert(key.clone()) {
                    faces.push(key);
                }
            }
        }
    }
    edges.extend(faces);
    edges
}
