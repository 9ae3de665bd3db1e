//! Step 3 at D = 2 ([`Dim<3, 2>`]): the edges that join two singular
//! vertices and pass exactly through a grid point of the shifted map
//! (paper appendix, "Sanitization": "if both edge extremities are
//! singularities, it is not possible to apply the perturbation, so we need
//! to split the edge").
//!
//! Input: the map, its local shifted coordinates, the singular flags.
//! Output: each such edge once (from the smaller triangle id of its two),
//! as its two vertex ids; the split ([`super::split_faces_traced`]) puts
//! its midpoint in the chart of each adjacent triangle, which is not
//! singular (its ring rotation is the edge's transition and back), so
//! sanitization can move it. The passes stop once as many edges are split
//! as the current map has triangles.

use super::{Dim, Pass, ToSplit};
use crate::grid::grid_point_near_segment as grid_point_near_edge;
use crate::local::LocalMap;
use dualex_map::{Stars, Topology, Transitions, TriMap};
use rayon::prelude::*;

impl ToSplit<3, 2> for Dim<3, 2> {
    type Singular = ();

    fn singular(_: &TriMap, _: &Topology<3>, _: &Transitions<3, 2>, _: &Stars<2>) {}

    /// No rotation of the plane but the identity fixes an axis.
    fn free_axes(_: &Topology<3>, _: &Stars<2>, _: &LocalMap<3, 2>) -> Vec<Option<usize>> {
        Vec::new()
    }

    fn faces(pass: &Pass<'_, 3, 2>, _: &()) -> Vec<Vec<u32>> {
        let Pass {
            map,
            topo,
            stars,
            local,
            ..
        } = *pass;
        // blocks of triangles in parallel, joined in triangle order
        let edges_of = |s: usize, out: &mut Vec<Vec<u32>>| {
            let tri = &map.simplices[s];
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
                        out.push(vec![tri[ca], tri[cb]]);
                    }
                }
            }
        };
        const BLOCK: usize = 8192;
        let ns = map.simplices.len();
        let blocks: Vec<Vec<Vec<u32>>> = (0..ns.div_ceil(BLOCK))
            .into_par_iter()
            .map(|b| {
                let mut out = Vec::new();
                for s in b * BLOCK..ns.min((b + 1) * BLOCK) {
                    edges_of(s, &mut out);
                }
                out
            })
            .collect();
        blocks.concat()
    }

    fn max_split(_input: usize, current: usize) -> usize {
        current
    }
}
