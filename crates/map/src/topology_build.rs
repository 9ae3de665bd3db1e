//! Construction of [`Topology`]: facet adjacency by sorting facet keys.
//!
//! Input: a validated [`SimplexMap`] (indices in range, no repeated vertex in
//! a simplex). Output: [`Topology`] with `adj`, `adj_facet`, `nbr_corner`,
//! `boundary_facets`, or the first [`InputError`] among, in this order:
//! 1. a facet shared by more than two simplices (non-manifold facet);
//! 2. two neighbours with opposite orientations across their facet;
//! 3. a non-manifold vertex: the simplices around it are not connected
//!    through the facets that contain it (2D: more than one fan).
//!
//! Key of a facet: its sorted vertex ids (the unused last slot holds
//! `u32::MAX`). The half-facets `(key, s·N + f)` are visited in sorted
//! order (so the first error is the one of the least key): bucketed by
//! their least vertex, each bucket sorted by the other vertices and the
//! half-facet id, which is the order of one global sort.

use crate::error::{ElementKind, MapError};
use crate::topology::{Topology, NONE};
use crate::{InputError, SimplexMap};
use rayon::prelude::*;

/// Vertices whose facet buckets are sorted by one parallel task.
const SORT_BLOCK: usize = 4096;

/// Sorted vertex ids of facet `f` of `simplex` (last slot `u32::MAX`).
pub(crate) fn facet_key<const N: usize>(simplex: &[u32; N], f: usize) -> [u32; N] {
    let mut key = [u32::MAX; N];
    for i in 0..N - 1 {
        key[i] = simplex[(f + 1 + i) % N];
    }
    key[..N - 1].sort_unstable();
    key
}

/// All half-facets `(key, s·N + f)` sorted by key.
pub(crate) fn sorted_facets<const N: usize>(simplices: &[[u32; N]]) -> Vec<([u32; N], u32)> {
    let mut keys: Vec<([u32; N], u32)> = Vec::with_capacity(simplices.len() * N);
    for (s, simplex) in simplices.iter().enumerate() {
        for f in 0..N {
            keys.push((facet_key(simplex, f), (s * N + f) as u32));
        }
    }
    keys.sort_unstable();
    keys
}

/// The other vertices of a facet key (all but the least), packed into one
/// integer in the key's order.
#[inline]
fn rest_of<const N: usize>(key: &[u32; N]) -> u64 {
    key[1..N - 1]
        .iter()
        .fold(0u64, |acc, &v| (acc << 32) | u64::from(v))
}

/// All half-facets as CSR buckets by their least vertex:
/// `(offsets, (rest_of(key), s·N + f))`, each bucket sorted.
fn facet_buckets<const N: usize>(
    simplices: &[[u32; N]],
    vertex_count: usize,
) -> (Vec<u32>, Vec<(u64, u32)>) {
    let least = |simplex: &[u32; N], f: usize| {
        (0..N)
            .filter(|&c| c != f)
            .map(|c| simplex[c])
            .min()
            .unwrap_or(u32::MAX)
    };
    let mut offsets = vec![0u32; vertex_count + 1];
    for simplex in simplices {
        for f in 0..N {
            offsets[least(simplex, f) as usize + 1] += 1;
        }
    }
    for v in 0..vertex_count {
        offsets[v + 1] += offsets[v];
    }
    let mut fill: Vec<u32> = offsets[..vertex_count].to_vec();
    let mut half = vec![(0u64, 0u32); offsets[vertex_count] as usize];
    for (s, simplex) in simplices.iter().enumerate() {
        for f in 0..N {
            let key = facet_key(simplex, f);
            let slot = &mut fill[key[0] as usize];
            half[*slot as usize] = (rest_of(&key), (s * N + f) as u32);
            *slot += 1;
        }
    }
    // the buckets of blocks of vertices sorted in parallel, each block in
    // its own slice
    let mut blocks: Vec<(usize, &mut [(u64, u32)])> = Vec::new();
    let mut rest = &mut half[..];
    for first in (0..vertex_count).step_by(SORT_BLOCK) {
        let end = vertex_count.min(first + SORT_BLOCK);
        let len = (offsets[end] - offsets[first]) as usize;
        let (block, tail) = std::mem::take(&mut rest).split_at_mut(len);
        rest = tail;
        blocks.push((first, block));
    }
    blocks.into_par_iter().for_each(|(first, block)| {
        let base = offsets[first] as usize;
        for v in first..vertex_count.min(first + SORT_BLOCK) {
            block[offsets[v] as usize - base..offsets[v + 1] as usize - base].sort_unstable();
        }
    });
    (offsets, half)
}

pub(crate) fn build<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
) -> Result<Topology<N>, InputError> {
    let ns = map.simplices.len();
    let mut topo = Topology {
        adj: vec![[NONE; N]; ns],
        adj_facet: vec![[0u8; N]; ns],
        nbr_corner: vec![[[0u8; N]; N]; ns],
        boundary_facets: 0,
    };
    let (offsets, half) = facet_buckets(&map.simplices, map.positions.len());
    for v in 0..map.positions.len() {
        let bucket = &half[offsets[v] as usize..offsets[v + 1] as usize];
        let mut i = 0;
        while i < bucket.len() {
            let mut j = i + 1;
            while j < bucket.len() && bucket[j].0 == bucket[i].0 {
                j += 1;
            }
            match j - i {
                1 => topo.boundary_facets += 1,
                2 => glue(
                    map,
                    &mut topo,
                    bucket[i].1 as usize,
                    bucket[i + 1].1 as usize,
                )?,
                n => {
                    let h = bucket[i].1 as usize;
                    let key = facet_key(&map.simplices[h / N], h % N);
                    let mut owners: Vec<usize> =
                        bucket[i..j].iter().map(|k| k.1 as usize / N).collect();
                    owners.sort_unstable();
                    debug_assert_eq!(owners.len(), n);
                    return Err(MapError::NonManifoldFacet {
                        simplex: ElementKind::simplex(N),
                        vertices: key[..N - 1].to_vec(),
                        simplices: owners,
                    }
                    .into());
                }
            }
            i = j;
        }
    }
    check_vertices(map, &topo)?;
    Ok(topo)
}

/// Links half-facets `h1 = s·N + f` and `h2 = n·N + g` (same key); checks
/// that the two simplices are consistently oriented.
fn glue<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &mut Topology<N>,
    h1: usize,
    h2: usize,
) -> Result<(), InputError> {
    let (s, f) = (h1 / N, h1 % N);
    let (n, g) = (h2 / N, h2 % N);
    let (vs, vn) = (&map.simplices[s], &map.simplices[n]);
    let mut corner_sn = [0u8; N];
    let mut corner_ns = [0u8; N];
    corner_sn[f] = g as u8;
    corner_ns[g] = f as u8;
    for c in (0..N).filter(|&c| c != f) {
        let Some(cn) = vn.iter().position(|&v| v == vs[c]) else {
            panic!(
                "bug: facet key matched but vertex {} is not in simplex {n}",
                vs[c]
            );
        };
        corner_sn[c] = cn as u8;
        corner_ns[cn] = c as u8;
    }
    // consistent orientation <=> putting s's apex in place of n's apex gives
    // an odd permutation of s's corners (the two lie on opposite sides)
    if permutation_parity(&corner_ns) == 0 {
        let a = s.min(n);
        let b = s.max(n);
        let mut key = [0u32; N];
        key[..N - 1].copy_from_slice(&facet_key(vs, f)[..N - 1]);
        return Err(MapError::OppositeOrientations {
            simplex: ElementKind::simplex(N),
            simplices: [a, b],
            vertices: key[..N - 1].to_vec(),
        }
        .into());
    }
    topo.adj[s][f] = n as u32;
    topo.adj[n][g] = s as u32;
    topo.adj_facet[s][f] = g as u8;
    topo.adj_facet[n][g] = f as u8;
    topo.nbr_corner[s][f] = corner_sn;
    topo.nbr_corner[n][g] = corner_ns;
    Ok(())
}

/// Parity (0 even, 1 odd) of a permutation of `0..N`.
fn permutation_parity<const N: usize>(p: &[u8; N]) -> u32 {
    let mut inv = 0;
    for i in 0..N {
        for j in i + 1..N {
            if p[i] > p[j] {
                inv += 1;
            }
        }
    }
    inv % 2
}

/// The corners around each vertex, as CSR: `(offsets, (simplex, corner))`,
/// each vertex's corners in simplex order.
pub(crate) fn vertex_corners<const N: usize>(
    simplices: &[[u32; N]],
    vertex_count: usize,
) -> (Vec<u32>, Vec<(u32, u8)>) {
    let (offsets, corners, _) = corners_of(simplices, vertex_count, false);
    (offsets, corners)
}

/// [`vertex_corners`], and the position of each corner `s·N + c` in its
/// vertex's list (`corners[offsets[v] + position]`): a walk around a
/// vertex marks what it reached in an array of the star's size, without
/// hashing.
pub(crate) fn vertex_corners_indexed<const N: usize>(
    simplices: &[[u32; N]],
    vertex_count: usize,
) -> (Vec<u32>, Vec<(u32, u8)>, Vec<u32>) {
    corners_of(simplices, vertex_count, true)
}

/// [`vertex_corners`], with the positions when `indexed` (else empty).
fn corners_of<const N: usize>(
    simplices: &[[u32; N]],
    vertex_count: usize,
    indexed: bool,
) -> (Vec<u32>, Vec<(u32, u8)>, Vec<u32>) {
    let mut offsets = vec![0u32; vertex_count + 1];
    for simplex in simplices {
        for &v in simplex {
            offsets[v as usize + 1] += 1;
        }
    }
    for v in 0..vertex_count {
        offsets[v + 1] += offsets[v];
    }
    let mut fill: Vec<u32> = offsets[..vertex_count].to_vec();
    let mut corners = vec![(0u32, 0u8); offsets[vertex_count] as usize];
    let mut position = vec![0u32; if indexed { simplices.len() * N } else { 0 }];
    for (s, simplex) in simplices.iter().enumerate() {
        for (c, &v) in simplex.iter().enumerate() {
            let slot = &mut fill[v as usize];
            corners[*slot as usize] = (s as u32, c as u8);
            if indexed {
                position[s * N + c] = *slot - offsets[v as usize];
            }
            *slot += 1;
        }
    }
    (offsets, corners, position)
}

/// Checks that the simplices around each vertex are connected through the
/// facets that contain the vertex (blocks of vertices in parallel; the
/// error names the first vertex that fails).
fn check_vertices<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
) -> Result<(), InputError> {
    let nv = map.positions.len();
    let (offsets, corners, position) = vertex_corners_indexed(&map.simplices, nv);
    let first_bad = (0..nv.div_ceil(SORT_BLOCK))
        .into_par_iter()
        .map(|b| {
            let mut reached = Vec::new();
            let mut stack: Vec<(usize, usize)> = Vec::new();
            (b * SORT_BLOCK..nv.min((b + 1) * SORT_BLOCK)).find(|&v| {
                let star = &corners[offsets[v] as usize..offsets[v + 1] as usize];
                !connected(topo, star, &position, &mut reached, &mut stack)
            })
        })
        .collect::<Vec<Option<usize>>>()
        .into_iter()
        .flatten()
        .next();
    let Some(v) = first_bad else {
        return Ok(());
    };
    Err(MapError::NonManifoldVertex {
        vertex: v,
        simplex: ElementKind::simplex(N),
    }
    .into())
}

/// Whether a depth-first walk from the first corner of `star` (the corners
/// of one vertex; `position` as in [`vertex_corners_indexed`]) across the
/// facets that contain the vertex reaches all of them (an empty star is
/// connected).
fn connected<const N: usize>(
    topo: &Topology<N>,
    star: &[(u32, u8)],
    position: &[u32],
    reached: &mut Vec<bool>,
    stack: &mut Vec<(usize, usize)>,
) -> bool {
    let Some(&(s0, c0)) = star.first() else {
        return true;
    };
    reached.clear();
    reached.resize(star.len(), false);
    reached[0] = true;
    stack.clear();
    stack.push((s0 as usize, c0 as usize));
    let mut count = 1;
    while let Some((s, c)) = stack.pop() {
        for f in (0..N).filter(|&f| f != c) {
            let Some((n, _)) = topo.neighbour(s, f) else {
                continue;
            };
            let cn = topo.nbr_corner[s][f][c] as usize;
            let seen = &mut reached[position[n * N + cn] as usize];
            if !*seen {
                *seen = true;
                count += 1;
                stack.push((n, cn));
            }
        }
    }
    count == star.len()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TriMap;

    fn tri(simplices: Vec<[u32; 3]>, nv: usize) -> TriMap {
        TriMap {
            positions: vec![[0.0; 3]; nv],
            coords: vec![[[0.0; 2]; 3]; simplices.len()],
            simplices,
        }
    }

    #[test]
    fn two_triangles() {
        let m = tri(vec![[0, 1, 2], [2, 1, 3]], 4);
        let t = Topology::build(&m).expect("valid");
        assert_eq!(t.boundary_facets, 4);
        // edge 1-2 is facet 0 of triangle 0 and facet 2 of triangle 1
        assert_eq!(t.neighbour(0, 0), Some((1, 2)));
        assert_eq!(t.neighbour(1, 2), Some((0, 0)));
        assert_eq!(t.nbr_corner[0][0], [2, 1, 0]);
        assert_eq!(t.neighbour(0, 1), None);
    }

    #[test]
    fn tets_share_face() {
        let m = crate::TetMap {
            positions: vec![[0.0; 3]; 5],
            simplices: vec![[0, 1, 2, 3], [1, 2, 3, 4]],
            coords: vec![[[0.0; 3]; 4]; 2],
        };
        // (1,2,3,4) vs (0,1,2,3): s's apex 0 in place of 4 gives (1,2,3,0): odd
        let t = Topology::build(&m).expect("valid");
        assert_eq!(t.neighbour(0, 0), Some((1, 3)));
        assert_eq!(t.nbr_corner[0][0], [3, 0, 1, 2]);
        assert_eq!(t.boundary_facets, 6);
        let bad = crate::TetMap {
            simplices: vec![[0, 1, 2, 3], [2, 1, 3, 4]],
            ..m
        };
        let e = Topology::build(&bad).expect_err("misoriented");
        assert_eq!(
            e.to_string(),
            "tets 0 and 1 have opposite orientations across face 1-2-3"
        );
    }

    #[test]
    fn errors() {
        let e = Topology::build(&tri(vec![[0, 1, 2], [1, 0, 3], [0, 1, 4]], 5)).expect_err("nm");
        assert_eq!(
            e.to_string(),
            "edge 0-1 is shared by 3 triangles (0, 1, 2): non-manifold"
        );
        let e = Topology::build(&tri(vec![[0, 1, 2], [1, 2, 3]], 4)).expect_err("orient");
        assert_eq!(
            e.to_string(),
            "triangles 0 and 1 have opposite orientations across edge 1-2"
        );
        // bow tie: two fans at vertex 0
        let e = Topology::build(&tri(vec![[0, 1, 2], [0, 3, 4]], 5)).expect_err("bow tie");
        assert_eq!(
            e.to_string(),
            "vertex 0 is non-manifold: its triangles form more than one fan"
        );
    }

    #[test]
    fn the_first_pinched_vertex_is_named() {
        // bow ties pinched at vertices 9000 and 5000 (blocks of 4096
        // vertices checked in parallel): the least is reported
        let mut simplices = Vec::new();
        for v in [9000u32, 5000] {
            let o = 10000 + 4 * v;
            simplices.extend([[v, o, o + 1], [v, o + 2, o + 3]]);
        }
        let e = Topology::build(&tri(simplices, 50000)).expect_err("pinched");
        assert_eq!(
            e.to_string(),
            "vertex 5000 is non-manifold: its triangles form more than one fan"
        );
    }

    #[test]
    fn tets_touching_at_a_vertex() {
        let m = crate::TetMap {
            positions: vec![[0.0; 3]; 7],
            simplices: vec![[0, 1, 2, 3], [0, 4, 5, 6]],
            coords: vec![[[0.0; 3]; 4]; 2],
        };
        let e = Topology::build(&m).expect_err("pinched");
        assert_eq!(
            e.to_string(),
            "vertex 0 is non-manifold: its tets are not connected through the faces around it"
        );
    }

    #[test]
    fn parity() {
        assert_eq!(permutation_parity(&[0u8, 1, 2]), 0);
        assert_eq!(permutation_parity(&[1u8, 0, 2]), 1);
        assert_eq!(permutation_parity(&[1u8, 2, 0]), 0);
        assert_eq!(permutation_parity(&[3u8, 0, 1, 2]), 1);
    }
}
