//! Step 1b: splitting edges that join two singular vertices and pass exactly
//! through a grid point of the shifted map (paper appendix, "Sanitization":
//! "if both edge extremities are singularities, it is not possible to apply
//! the perturbation, so we need to split the edge").
//!
//! Input: the map and its local shifted coordinates, the singular flags.
//! Output: a new map where each such edge is split at its midpoint (in 3D
//! and in the chart of each adjacent triangle), the two adjacent triangles
//! (one on the boundary) split in two each, orientation kept. The midpoint
//! is not singular (its ring rotation is the edge's transition and back), so
//! sanitization can move it. The map stays exactly as GP as before: a
//! midpoint of two corners related by a transition is related by the same
//! transition.

use crate::local::LocalMap;
use dualex_map::{Stars, Topology, TriMap};
use dualex_segment::grid::grid_point_near_segment as grid_point_near_edge;

/// Edges `(triangle, facet)` to split (one entry per edge, the smaller
/// triangle id of the two).
pub fn edges_to_split(
    map: &TriMap,
    topo: &Topology<3>,
    stars: &Stars<2>,
    local: &LocalMap,
) -> Vec<(usize, usize)> {
    let mut out = Vec::new();
    for (s, tri) in map.simplices.iter().enumerate() {
        for f in 0..3 {
            let (ca, cb) = ((f + 1) % 3, (f + 2) % 3);
            let (a, b) = (tri[ca] as usize, tri[cb] as usize);
            if !(stars.singular[a] && stars.singular[b]) {
                continue;
            }
            if topo.neighbour(s, f).is_some_and(|(n, _)| n < s) {
                continue;
            }
            let (pa, pb) = (local.coords[s][ca], local.coords[s][cb]);
            if let Some(g) = grid_point_near_edge(&pa, &pb) {
                let at_end = |p: &[f64; 2]| (p[0] - g[0]).hypot(p[1] - g[1]) < 1e-6;
                if !at_end(&pa) && !at_end(&pb) {
                    out.push((s, f));
                }
            }
        }
    }
    out
}

/// Splits the given edges (see the module docs) with the generic face
/// split of `dualex_segment::split`; returns the new map and the number of
/// edges split (an edge sharing a triangle with an earlier one waits for
/// the next pass).
pub fn split_edges(map: &TriMap, edges: &[(usize, usize)]) -> (TriMap, usize) {
    let (out, applied, _) = split_edges_traced(map, edges);
    (out, applied)
}

/// [`split_edges`], also returning the triangle of `map` each triangle of
/// the new map comes from (`dualex_segment::split::split_faces_traced`).
pub fn split_edges_traced(map: &TriMap, edges: &[(usize, usize)]) -> (TriMap, usize, Vec<u32>) {
    let faces: Vec<Vec<u32>> = edges
        .iter()
        .map(|&(s, f)| {
            let tri = map.simplices[s];
            vec![tri[(f + 1) % 3], tri[(f + 2) % 3]]
        })
        .collect();
    dualex_segment::split::split_faces_traced(map, &faces)
}
