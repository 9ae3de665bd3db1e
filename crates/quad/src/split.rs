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
use crate::sanitize::grid_point_near_edge;
use dualex_map::{Stars, Topology, TriMap};

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

fn mid<const K: usize>(a: &[f64; K], b: &[f64; K]) -> [f64; K] {
    std::array::from_fn(|k| 0.5 * (a[k] + b[k]))
}

/// Splits the given edges (see the module docs).
pub fn split_edges(map: &TriMap, topo: &Topology<3>, edges: &[(usize, usize)]) -> TriMap {
    let mut out = map.clone();
    // per triangle: the facet to split there and the new vertex
    let mut cut: Vec<Option<(usize, u32)>> = vec![None; map.len()];
    for &(s, f) in edges {
        let tri = map.simplices[s];
        let (a, b) = (tri[(f + 1) % 3] as usize, tri[(f + 2) % 3] as usize);
        let nbr = topo.neighbour(s, f);
        if cut[s].is_some() || nbr.is_some_and(|(n, _)| cut[n].is_some()) {
            continue; // one split per triangle per pass; the next pass takes it
        }
        let m = out.positions.len() as u32;
        out.positions
            .push(mid(&map.positions[a], &map.positions[b]));
        cut[s] = Some((f, m));
        if let Some((n, g)) = nbr {
            cut[n] = Some((g, m));
        }
    }
    out.simplices.clear();
    out.coords.clear();
    for (s, cut_s) in cut.iter().enumerate() {
        let (tri, uv) = (map.simplices[s], map.coords[s]);
        let Some((f, m)) = *cut_s else {
            out.simplices.push(tri);
            out.coords.push(uv);
            continue;
        };
        let (ca, cb) = ((f + 1) % 3, (f + 2) % 3);
        let um = mid(&uv[ca], &uv[cb]);
        // (f, a, b) → (f, a, m) and (f, m, b), same orientation
        let mut t1 = tri;
        t1[cb] = m;
        let mut u1 = uv;
        u1[cb] = um;
        let mut t2 = tri;
        t2[ca] = m;
        let mut u2 = uv;
        u2[ca] = um;
        out.simplices.extend([t1, t2]);
        out.coords.extend([u1, u2]);
    }
    out
}
