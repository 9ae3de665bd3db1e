//! The stars' walk of a 2D vertex whose triangles form one fan, without
//! the corner lists' positions.
//!
//! Input: as [`crate::star_build`]'s walk, for triangles (`N = 3`): the
//! vertex's corner ids (its first the root), the topology (each edge in at
//! most two triangles, glued both ways; no repeated vertex in a triangle),
//! the transitions. Output: the entries of the breadth-first walk of
//! `star_build::star_of`, the same entries in the same order with the same
//! singular and boundary flags, or `None` when the walk from the root does
//! not reach every corner (the vertex has more than one fan: the caller
//! walks it the general way).
//!
//! Why no lookup of what was reached is needed: around a vertex every
//! triangle has two edges through it, each with at most one neighbour, so
//! the triangles form paths and cycles. The breadth-first walk from the
//! root grows two arms, one entry per step, alternately; after an entry is
//! taken from the queue, the queue holds at most the other arm's tip
//! (`out[len - 1]`). An arm's next triangle is either new, or that tip
//! (the two arms meet around a cycle, or, from the root, both edges lead
//! to the same triangle); any other triangle already reached would have a
//! third neighbour through the vertex. Triangles are told apart by their
//! ids: a triangle holds the vertex at one corner only.

use crate::corners::split;
use crate::topology::NONE;
use crate::{Rot, StarEntry, Topology, Transitions};

/// [`crate::star_build`]'s walk of one vertex with corner ids `corners`
/// into `out` (one entry per corner), when its triangles form one fan:
/// `Some((singular, boundary))`; `None` when they do not (module docs).
/// `done` is the walk's per-entry mask of facets not to cross, as there.
pub(crate) fn fan_of<const N: usize, const D: usize>(
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
    corners: &[u32],
    out: &mut [StarEntry<D>],
    done: &mut Vec<u8>,
) -> Option<(bool, bool)> {
    debug_assert_eq!(N, 3);
    let (mut singular, mut boundary) = (false, false);
    let Some(&root) = corners.first() else {
        return Some((false, false));
    };
    if done.len() < corners.len() {
        done.resize(corners.len(), 0);
    }
    let (s0, c0) = split::<N>(root);
    out[0] = StarEntry {
        simplex: s0 as u32,
        corner: c0 as u8,
        rot: Rot::IDENTITY,
    };
    done[0] = 0;
    let (mut head, mut len) = (0, 1);
    while head < len {
        let (e, mask) = (out[head], done[head]);
        head += 1;
        let (s, c) = (e.simplex as usize, e.corner as usize);
        let (adj, steps, nbr) = (&topo.adj[s], &trans.rot[s], &topo.nbr_corner[s]);
        let mut cross = ((1u32 << N) - 1) & !(1u32 << c | u32::from(mask));
        while cross != 0 {
            let f = cross.trailing_zeros() as usize;
            cross &= cross - 1;
            if adj[f] == NONE {
                boundary = true;
                continue;
            }
            let step = &steps[f];
            let rot = if step.is_identity() {
                e.rot
            } else {
                e.rot.then(step)
            };
            let back = 1u8 << nbr[f][f];
            // the only triangle reached before: the other arm's tip
            if head < len && out[len - 1].simplex == adj[f] {
                singular |= out[len - 1].rot.rank() != rot.rank();
                done[len - 1] |= back;
                continue;
            }
            if len == out.len() {
                return None;
            }
            out[len] = StarEntry {
                simplex: adj[f],
                corner: nbr[f][c],
                rot,
            };
            done[len] = back;
            len += 1;
        }
    }
    (len == out.len()).then_some((singular, boundary))
}

#[cfg(test)]
mod tests {
    use super::fan_of;
    use crate::corners::VertexCorners;
    use crate::star_build::{star_of, walk};
    use crate::test_maps::{cone, cube_surface, flat_torus, grid, rechart, Lcg};
    use crate::{Topology, TransitionOptions, Transitions, TriMap};

    /// Cones of `ks` triangles around their apices (`apex[j]`; cones that
    /// share one are a vertex of several fans), their rims apart.
    fn cones(ks: &[u32], apex: &[u32]) -> TriMap {
        let mut m = TriMap::default();
        let nv = apex.iter().max().map_or(0, |&a| a + 1);
        m.positions = vec![[0.0; 3]; nv as usize];
        for (&k, &a) in ks.iter().zip(apex) {
            let rim = m.positions.len() as u32;
            m.positions.extend((0..k).map(|i| [f64::from(i), 1.0, 0.0]));
            for i in 0..k {
                m.simplices.push([a, rim + i, rim + (i + 1) % k]);
                m.coords.push([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
            }
        }
        m
    }

    /// The triangles shuffled (the roots move), each dropped with
    /// probability `drop`/100 (boundaries, vertices of several fans,
    /// unused vertices).
    fn shuffled(m: &TriMap, seed: u64, drop: u64) -> TriMap {
        let mut rng = Lcg(seed);
        let mut order: Vec<usize> = (0..m.simplices.len()).collect();
        for i in (1..order.len()).rev() {
            order.swap(i, rng.below(i as u64 + 1) as usize);
        }
        order.retain(|_| rng.below(100) >= drop);
        TriMap {
            positions: m.positions.clone(),
            simplices: order.iter().map(|&s| m.simplices[s]).collect(),
            coords: order.iter().map(|&s| m.coords[s]).collect(),
        }
    }

    /// The fan walk without positions against the general walk with them
    /// (the former form, kept as the oracle); returns the singular and
    /// boundary vertices and whether a vertex of several fans was named.
    fn same(m: &TriMap) -> (usize, usize, bool) {
        let nv = m.positions.len();
        let indexed = VertexCorners::build(&m.simplices, nv, true);
        let plain = VertexCorners::build(&m.simplices, nv, false);
        let topo = Topology::glue_with(m, &indexed).expect("glued");
        let opts = TransitionOptions::default();
        let (tr, _) = Transitions::derive(m, &topo, &opts).expect("derived");
        let (want, want_apart) = walk(m, &topo, &tr, &indexed, false);
        for corners in [&plain, &indexed] {
            let (got, apart) = walk(m, &topo, &tr, corners, true);
            assert_eq!(got.offsets, want.offsets);
            assert_eq!(got.entries, want.entries);
            assert_eq!(got.singular, want.singular);
            assert_eq!(got.boundary, want.boundary);
            assert_eq!(apart, want_apart);
        }
        // each vertex of one fan is walked here, not left to the general walk
        let (mut reached, mut done) = (Vec::new(), Vec::new());
        for v in 0..nv {
            let mut out = want.of(v).to_vec();
            let (_, _, one) = star_of(
                &topo,
                &tr,
                indexed.of(v),
                &indexed.position,
                &mut out,
                &mut reached,
                &mut done,
            );
            let fan = fan_of(&topo, &tr, plain.of(v), &mut out, &mut done);
            assert_eq!(fan.is_some(), one, "vertex {v}");
            if let Some(flags) = fan {
                assert_eq!(flags, (want.singular[v], want.boundary[v]));
                assert_eq!(out, want.of(v));
            }
        }
        let count = |f: &[bool]| f.iter().filter(|&&x| x).count();
        let (singular, boundary) = (count(&want.singular), count(&want.boundary));
        (singular, boundary, want_apart.is_some())
    }

    #[test]
    fn same_stars_as_the_general_walk() {
        let (mut singular, mut boundary, mut apart) = (0, 0, 0);
        let mut tally = |(s, b, a): (usize, usize, bool)| {
            singular += s;
            boundary += b;
            apart += usize::from(a);
        };
        let mut g = grid(30);
        rechart(&mut g, 5);
        let mut cube = cube_surface(4);
        rechart(&mut cube, 6);
        let mut torus = flat_torus(12);
        rechart(&mut torus, 7);
        // cones of several indices (2: two triangles glued along both
        // edges through the apex), some sharing their apex
        let ks = [2, 3, 4, 5, 6, 7, 8, 3, 5, 9, 2, 6];
        let mut many = cones(&ks, &[0, 1, 2, 3, 4, 5, 6, 0, 1, 1, 7, 7]);
        rechart(&mut many, 8);
        for k in 2..10 {
            tally(same(&cone(k)));
        }
        for (i, m) in [g, cube, torus, many].iter().enumerate() {
            tally(same(m));
            for seed in 0..12 {
                let drop = [0, 3, 10, 30][seed as usize % 4];
                tally(same(&shuffled(m, seed * 31 + i as u64, drop)));
            }
        }
        // every kind of vertex met
        assert!(singular > 100 && boundary > 100 && apart > 10);
    }
}
