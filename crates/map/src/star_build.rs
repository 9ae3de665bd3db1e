//! Construction of [`Stars`]: per vertex, a breadth-first walk over the
//! simplices containing it, across the facets that contain it, composing
//! the transitions crossed.
//!
//! Input: map, topology (manifold: each vertex star is connected through its
//! facets), transitions. Output: [`Stars`]; the first entry of each vertex is
//! its reference chart (identity). A vertex is singular when some simplex is
//! reached with two different rotations; on the boundary when one of its
//! facets has no neighbour. Vertices used by no simplex have an empty star.

use crate::topology_build::vertex_corners;
use crate::{Rot, SimplexMap, StarEntry, Stars, Topology, Transitions};

pub(crate) fn build<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
) -> Stars<D> {
    let nv = map.positions.len();
    let (offsets, corners) = vertex_corners(&map.simplices, nv);
    let mut stars = Stars {
        offsets: vec![0u32; nv + 1],
        entries: Vec::with_capacity(corners.len()),
        singular: vec![false; nv],
        boundary: vec![false; nv],
    };
    // per simplex: (vertex stamp, index of its entry in `entries`)
    let mut seen = vec![(u32::MAX, 0u32); map.simplices.len()];
    for v in 0..nv {
        let start = stars.entries.len();
        for &(s0, c0) in &corners[offsets[v] as usize..offsets[v + 1] as usize] {
            if seen[s0 as usize].0 == v as u32 {
                continue;
            }
            // a new component of the star (only when the topology was not
            // checked); its first simplex is its own reference chart
            walk(
                topo,
                trans,
                &mut stars,
                &mut seen,
                v,
                s0 as usize,
                c0 as usize,
            );
        }
        stars.offsets[v + 1] = stars.entries.len() as u32;
        debug_assert_eq!(
            stars.entries.len() - start,
            (offsets[v + 1] - offsets[v]) as usize
        );
    }
    stars
}

/// Breadth-first walk around `v` from corner `c0` of `s0`.
fn walk<const N: usize, const D: usize>(
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
    stars: &mut Stars<D>,
    seen: &mut [(u32, u32)],
    v: usize,
    s0: usize,
    c0: usize,
) {
    let mut head = stars.entries.len();
    seen[s0] = (v as u32, head as u32);
    stars.entries.push(StarEntry {
        simplex: s0 as u32,
        corner: c0 as u8,
        rot: Rot::IDENTITY,
    });
    while head < stars.entries.len() {
        let e = stars.entries[head];
        head += 1;
        let (s, c) = (e.simplex as usize, e.corner as usize);
        for f in (0..N).filter(|&f| f != c) {
            let Some((n, _)) = topo.neighbour(s, f) else {
                stars.boundary[v] = true;
                continue;
            };
            let rot = e.rot.then(&trans.rot[s][f]);
            if seen[n].0 == v as u32 {
                if stars.entries[seen[n].1 as usize].rot != rot {
                    stars.singular[v] = true;
                }
                continue;
            }
            seen[n] = (v as u32, stars.entries.len() as u32);
            stars.entries.push(StarEntry {
                simplex: n as u32,
                corner: topo.nbr_corner[s][f][c],
                rot,
            });
        }
    }
}
