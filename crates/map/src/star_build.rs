//! Construction of [`Stars`]: per vertex, a breadth-first walk over the
//! simplices containing it, across the facets that contain it, composing
//! the transitions crossed.
//!
//! Input: map, topology (manifold: each vertex star is connected through its
//! facets), transitions (the one back across a facet the inverse of the
//! one across it, [`crate::transition`]'s invariant). Output: [`Stars`]; the first entry of each vertex is
//! its reference chart (identity). A vertex is singular when some simplex is
//! reached with two different rotations; on the boundary when one of its
//! facets has no neighbour. Vertices used by no simplex have an empty star.
//!
//! On a topology built without its vertex check
//! ([`Topology::glue_with`]) the walk makes it: a star reached in more
//! than one piece is a non-manifold vertex, the first one named
//! ([`build_checked`]).
//!
//! Every simplex around a vertex gets exactly one entry, so the stars have
//! the layout of the vertices' corner lists: blocks of vertices are walked
//! in parallel, each into its own slice of the entries (the same entries,
//! in the same order, as one sequential walk).
//!
//! In 2D a vertex whose triangles form one fan is walked by
//! [`crate::star_fan`], which reads no corner positions. The walk also
//! takes corner lists built without positions: a corner is then found by
//! a binary search of its vertex's list (in simplex order, so sorted).
//! The model still builds them (without them, t1000's peak rose by
//! ~30 MB through glibc's dynamic mmap threshold; BENCHMARKS.md).

use crate::corners::{split, VertexCorners};
use crate::star_fan::fan_of;
use crate::topology::NONE;
use crate::{InputError, Rot, SimplexMap, StarEntry, Stars, Topology, Transitions};
use rayon::prelude::*;

/// A corner not reached yet by [`star_of`] (no queue slot has this index).
const UNREACHED: u64 = u64::MAX;

/// Vertices walked by one parallel task.
const BLOCK: usize = 2048;

/// One parallel task: vertices `first..`, and their slices of the outputs.
type Job<'a, const D: usize> = (
    usize,
    &'a mut [StarEntry<D>],
    &'a mut [bool],
    &'a mut [bool],
);

pub(crate) fn build<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
) -> Stars<D> {
    let corners = VertexCorners::build(&map.simplices, map.positions.len(), true);
    build_with(map, topo, trans, &corners)
}

/// [`build`] with the map's corner lists (built `indexed` or not: module docs).
pub(crate) fn build_with<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
    corners: &VertexCorners,
) -> Stars<D> {
    walk(map, topo, trans, corners, N == 3).0
}

/// [`build_with`] on a topology whose vertices were not checked
/// ([`Topology::glue_with`]): the error of that check
/// ([`crate::topology_build::check_vertices`]) for the first vertex whose
/// star the walk finds in more than one piece.
pub(crate) fn build_checked<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
    corners: &VertexCorners,
) -> Result<Stars<D>, InputError> {
    match walk(map, topo, trans, corners, N == 3) {
        (_, Some(v)) => Err(crate::topology_build::non_manifold_vertex::<N>(v)),
        (stars, None) => Ok(stars),
    }
}

/// The stars, and the first vertex whose star is in more than one piece;
/// with `fan` (triangles only), each vertex first by [`fan_of`].
pub(crate) fn walk<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
    corners: &VertexCorners,
    fan: bool,
) -> (Stars<D>, Option<usize>) {
    let nv = map.positions.len();
    let offsets = corners.offsets.clone();
    let (corners, position) = (&corners.corners, &corners.position);
    let blank = StarEntry {
        simplex: 0,
        corner: 0,
        rot: Rot::IDENTITY,
    };
    let mut stars = Stars {
        // every entry is written by the walks below; filled in parallel
        // (the pages touched by both threads)
        entries: (0..corners.len()).into_par_iter().map(|_| blank).collect(),
        offsets,
        singular: vec![false; nv],
        boundary: vec![false; nv],
    };
    let mut jobs: Vec<Job<D>> = Vec::with_capacity(nv.div_ceil(BLOCK));
    let mut entries = &mut stars.entries[..];
    let mut singular = &mut stars.singular[..];
    let mut boundary = &mut stars.boundary[..];
    for first in (0..nv).step_by(BLOCK) {
        let end = nv.min(first + BLOCK);
        let len = (stars.offsets[end] - stars.offsets[first]) as usize;
        let (e, e_rest) = std::mem::take(&mut entries).split_at_mut(len);
        let (s, s_rest) = std::mem::take(&mut singular).split_at_mut(end - first);
        let (b, b_rest) = std::mem::take(&mut boundary).split_at_mut(end - first);
        (entries, singular, boundary) = (e_rest, s_rest, b_rest);
        jobs.push((first, e, s, b));
    }
    let offsets = &stars.offsets;
    let pieces: Vec<Option<usize>> = jobs
        .into_par_iter()
        .map(|(first, e, s, b)| {
            let base = offsets[first] as usize;
            let (mut reached, mut done) = (Vec::new(), Vec::new());
            let mut apart = None;
            for (i, (sv, bv)) in s.iter_mut().zip(b.iter_mut()).enumerate() {
                let v = first + i;
                let (lo, hi) = (offsets[v] as usize, offsets[v + 1] as usize);
                let out = &mut e[lo - base..hi - base];
                let star = &corners[lo..hi];
                let one;
                if let Some((sing, bound)) = fan
                    .then(|| fan_of(topo, trans, star, out, &mut done))
                    .flatten()
                {
                    (*sv, *bv, one) = (sing, bound, true);
                } else {
                    (*sv, *bv, one) =
                        star_of(topo, trans, star, position, out, &mut reached, &mut done);
                }
                if !one && apart.is_none() {
                    apart = Some(v);
                }
            }
            apart
        })
        .collect();
    let apart = pieces.into_iter().flatten().next();
    (stars, apart)
}

/// Walks the star of one vertex, whose corner ids are `corners`, into `out`
/// (one entry per corner): breadth-first from each corner not reached yet
/// (more than one only when the topology was not checked; each new
/// component's first simplex is its own reference chart). `position` (of
/// [`VertexCorners`]; empty: a binary search) finds a corner in `corners`; `reached[k]`
/// is the queue slot of corner `k`'s entry times 256 plus the rank of its
/// rotation ([`Rot::rank`]), or [`UNREACHED`]. Returns
/// `(singular, boundary, one piece)`.
///
/// An entry does not cross the facets set in its mask (`done`, per queue
/// slot): the one it was reached through, and those through which a
/// crossing from an entry walked earlier landed on it. Crossing such a
/// facet back lands on that entry with the rotation it was compared
/// against (the transitions back are the inverses, [`crate::transition`]'s
/// invariant): the same comparison again, never boundary, never a new
/// entry. Each facet between two entries of the star is thus crossed once.
pub(crate) fn star_of<const N: usize, const D: usize>(
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
    corners: &[u32],
    position: &[u32],
    out: &mut [StarEntry<D>],
    reached: &mut Vec<u64>,
    done: &mut Vec<u8>,
) -> (bool, bool, bool) {
    let (mut singular, mut boundary, mut pieces) = (false, false, 0);
    reached.clear();
    reached.resize(corners.len(), UNREACHED);
    // every slot is written when its entry is queued (no clearing)
    if done.len() < corners.len() {
        done.resize(corners.len(), 0);
    }
    let mut len = 0;
    for (k0, &id) in corners.iter().enumerate() {
        if reached[k0] != UNREACHED {
            continue;
        }
        pieces += 1;
        let (s0, c0) = split::<N>(id);
        let mut head = len;
        out[len] = StarEntry {
            simplex: s0 as u32,
            corner: c0 as u8,
            rot: Rot::IDENTITY,
        };
        reached[k0] = (len as u64) << 8 | u64::from(Rot::<D>::IDENTITY.rank());
        // a root has no facet it was reached through
        done[len] = 0;
        len += 1;
        while head < len {
            let (e, mask) = (out[head], done[head]);
            head += 1;
            let (s, c) = (e.simplex as usize, e.corner as usize);
            // the rows of `s`, read once for its facets
            let (adj, steps, nbr) = (&topo.adj[s], &trans.rot[s], &topo.nbr_corner[s]);
            // the facets crossed, as bits taken in increasing order: all
            // but the one opposite the vertex and those of the mask
            let mut cross = ((1u32 << N) - 1) & !(1u32 << c | u32::from(mask));
            while cross != 0 {
                let f = cross.trailing_zeros() as usize;
                cross &= cross - 1;
                let n = adj[f] as usize;
                if adj[f] == NONE {
                    boundary = true;
                    continue;
                }
                // crossing an identity transition keeps the rotation
                let step = &steps[f];
                let rot = if step.is_identity() {
                    e.rot
                } else {
                    e.rot.then(step)
                };
                let corner = nbr[f][c];
                let k = place_of(corners, position, (n * N) as u32 + u32::from(corner));
                // the neighbour's facet back to `s`: its corner opposite
                // (`nbr_corner`'s entry `f`)
                let back = 1u8 << nbr[f][f];
                let q = reached[k];
                if q != UNREACHED {
                    singular |= q as u8 != rot.rank();
                    // not to be compared again from that entry's side
                    done[(q >> 8) as usize] |= back;
                    continue;
                }
                out[len] = StarEntry {
                    simplex: n as u32,
                    corner,
                    rot,
                };
                done[len] = back;
                reached[k] = (len as u64) << 8 | u64::from(rot.rank());
                len += 1;
            }
        }
    }
    debug_assert_eq!(len, out.len());
    (singular, boundary, pieces <= 1)
}

/// The place of corner id `id` in its vertex's list `corners`: read in
/// `position` when built, else found by a binary search of the list (in
/// simplex order: sorted). The corner must be in the list (the walk
/// reaches only corners of the vertex).
#[inline]
fn place_of(corners: &[u32], position: &[u32], id: u32) -> usize {
    if !position.is_empty() {
        return position[id as usize] as usize;
    }
    match corners.binary_search(&id) {
        Ok(k) => k,
        Err(_) => unreachable!("a corner reached around a vertex is in its list"),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_maps::{cone, cube_surface, edge_fan, grid, rechart, tet_cube};
    use crate::TransitionOptions;

    /// The stars as first written: one sequential walk per vertex with a
    /// per-simplex stamp.
    fn reference<const N: usize, const D: usize>(
        map: &SimplexMap<N, D>,
        topo: &Topology<N>,
        trans: &Transitions<N, D>,
    ) -> Stars<D> {
        let nv = map.positions.len();
        let lists = VertexCorners::build(&map.simplices, nv, false);
        let mut stars = Stars {
            offsets: vec![0u32; nv + 1],
            entries: Vec::new(),
            singular: vec![false; nv],
            boundary: vec![false; nv],
        };
        let mut seen = vec![(u32::MAX, 0u32); map.simplices.len()];
        for v in 0..nv {
            for &id in lists.of(v) {
                let (s0, c0) = split::<N>(id);
                let (s0, c0) = (s0 as u32, c0 as u8);
                if seen[s0 as usize].0 == v as u32 {
                    continue;
                }
                let mut head = stars.entries.len();
                seen[s0 as usize] = (v as u32, head as u32);
                stars.entries.push(StarEntry {
                    simplex: s0,
                    corner: c0,
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
            stars.offsets[v + 1] = stars.entries.len() as u32;
        }
        stars
    }

    fn same<const N: usize, const D: usize>(map: &SimplexMap<N, D>) {
        let topo = Topology::build(map).expect("topology");
        let (tr, _) = Transitions::derive(map, &topo, &TransitionOptions::default()).expect("tr");
        let (got, want) = (build(map, &topo, &tr), reference(map, &topo, &tr));
        assert_eq!(got.offsets, want.offsets);
        assert_eq!(got.entries, want.entries);
        assert_eq!(got.singular, want.singular);
        assert_eq!(got.boundary, want.boundary);
    }

    #[test]
    fn same_stars_as_one_sequential_walk() {
        let mut m = grid(70);
        rechart(&mut m, 3);
        same(&m);
        same(&cube_surface(3));
        same(&cone(300));
        same(&edge_fan(5));
        let mut t = tet_cube(4);
        rechart(&mut t, 4);
        same(&t);
    }
}
