//! Construction of [`Topology`]: facet adjacency by pairing facet keys.
//!
//! Input: a validated [`SimplexMap`] (indices in range, no repeated vertex in
//! a simplex). Output: [`Topology`] with `adj`, `adj_facet`, `nbr_corner`,
//! `boundary_facets`, or the first [`InputError`] among, in this order:
//! 1. a facet shared by more than two simplices (non-manifold facet);
//! 2. two neighbours with opposite orientations across their facet;
//! 3. a non-manifold vertex: the simplices around it are not connected
//!    through the facets that contain it (2D: more than one fan); left
//!    out by [`glue_with`] for a caller whose stars' walk makes it.
//!
//! Key of a facet: its sorted vertex ids (the unused last slot holds
//! `u32::MAX`). The half-facets `(key, s·N + f)` are bucketed by their
//! least vertex, found through that vertex's corners ([`VertexCorners`]),
//! and each bucket's equal keys are paired through a small hash table
//! ([`pair_bucket`]), or, in a small bucket, by comparing every two keys
//! ([`pair_small`]); a bucket with an error is sorted by
//! the other vertices and the half-facet id and glued in that order, the
//! order of one global sort, so the first error is the one of the least
//! key. Each half-facet carries its corners in key order and the parity
//! of that order with its apex last ([`rest_without`]): a pair's corner
//! map is read off the two orders and its orientation off the two
//! parities, without matching vertices. Blocks of vertices are bucketed
//! and glued in parallel: a glued
//! pair writes the other simplex's id and the corner map to it (whose
//! byte at the apex is the other's facet) into a per-half-facet `mate`
//! (each half-facet is in one bucket), each block stops at its first
//! error and the first block's error is returned; the adjacency is then
//! read off `mate` per simplex, in parallel.

use crate::corners::{split, VertexCorners};
use crate::error::{ElementKind, MapError};
#[cfg(test)]
use crate::facet_order::permutation_parity;
use crate::facet_order::{rest_without, CornerMaps, ODD};
use crate::topology::{Topology, NONE};
use crate::{InputError, SimplexMap};
use rayon::prelude::*;
use std::sync::atomic::{AtomicU64, Ordering::Relaxed};

/// A half-facet not glued (yet) in `mate`.
const UNGLUED: u64 = u64::MAX;

/// Vertices whose facet buckets are sorted by one parallel task.
const SORT_BLOCK: usize = 4096;

/// Most half-facets of a bucket paired by comparing every two keys
/// rather than hashed (a few comparisons cost less than clearing a table: the buckets of a triangle
/// mesh hold 3 on average, those of a tet mesh about 20).
const SMALL_BUCKET: usize = 8;

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
/// integer in the key's order ([`rest_without`] finds it without the key).
#[cfg(test)]
fn rest_of<const N: usize>(key: &[u32; N]) -> u64 {
    key[1..N - 1]
        .iter()
        .fold(0u64, |acc, &v| (acc << 32) | u64::from(v))
}

pub(crate) fn build<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
) -> Result<Topology<N>, InputError> {
    let corners = VertexCorners::build(&map.simplices, map.positions.len(), true);
    build_with(map, &corners)
}

/// [`build`] with the map's corner lists (built `indexed`).
pub(crate) fn build_with<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    corners: &VertexCorners,
) -> Result<Topology<N>, InputError> {
    let topo = glue_with(map, corners)?;
    check_vertices(map, &topo, corners)?;
    Ok(topo)
}

/// [`build_with`] without the vertex check (error 3 of the module docs),
/// for a caller that makes it otherwise (the stars' walk,
/// [`crate::Stars::build_checked`]).
pub(crate) fn glue_with<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    corners: &VertexCorners,
) -> Result<Topology<N>, InputError> {
    glue_into(map, corners, || ()).map(|(topo, ())| topo)
}

/// What a glue does with each pair it glues besides `mate`: nothing
/// (`()`), or the pair's transition fitted there
/// (`crate::transition_glue`). One sink per block of vertices, the
/// blocks' sinks combined in block order.
pub(crate) trait PairSink<const N: usize, const D: usize>: Send + Sized {
    /// Half-facets `h1 < h2` (ids `s·N + f`) glued, `corner` the corner
    /// map from `h1`'s simplex to `h2`'s (a `mate` word's high half).
    fn glued(&mut self, map: &SimplexMap<N, D>, h1: u32, h2: u32, corner: u32);
    /// This block's sink followed by a later block's.
    fn then(self, later: Self) -> Self;
}

impl<const N: usize, const D: usize> PairSink<N, D> for () {
    #[inline]
    fn glued(&mut self, _: &SimplexMap<N, D>, _: u32, _: u32, _: u32) {}
    fn then(self, _: Self) -> Self {}
}

/// [`glue_with`], each glued pair also given to a sink made by `sink`
/// (one per block; a bucket with an error gives none of its pairs once
/// sorted: its error is returned).
pub(crate) fn glue_into<const N: usize, const D: usize, S: PairSink<N, D>>(
    map: &SimplexMap<N, D>,
    corners: &VertexCorners,
    sink: impl Fn() -> S + Sync,
) -> Result<(Topology<N>, S), InputError> {
    let (nv, ns) = (map.positions.len(), map.len());
    // the other simplex of each glued half-facet in the low 32 bits and
    // the corner map to it (`nbr_corner`, N ≤ 4 bytes) above, written by the
    // bucket that holds both (each half-facet is in exactly one bucket)
    let mate: Vec<AtomicU64> = (0..ns * N)
        .into_par_iter()
        .map(|_| AtomicU64::new(UNGLUED))
        .collect();
    let blocks: Vec<Result<(usize, S), InputError>> = (0..nv.div_ceil(SORT_BLOCK))
        .into_par_iter()
        .map(|b| {
            let (mut bucket, mut table) = (Vec::new(), Vec::new());
            let (mut boundary, mut out) = (0, sink());
            for v in b * SORT_BLOCK..nv.min((b + 1) * SORT_BLOCK) {
                facets_from(map, corners.of(v), v as u32, &mut bucket);
                let paired = if bucket.len() > SMALL_BUCKET {
                    pair_bucket(map, &bucket, &mate, &mut table, &mut out)
                } else {
                    pair_small(map, &bucket, &mate, &mut out)
                };
                boundary += match paired {
                    Some(boundary) => boundary,
                    None => {
                        // an error (the sorted bucket names the first;
                        // its pairs go to no sink)
                        bucket.sort_unstable();
                        glue_bucket(map, &bucket, &mate, &mut ())?
                    }
                };
            }
            Ok((boundary, out))
        })
        .collect();
    let (mut boundary_facets, mut fits) = (0, sink());
    for block in blocks {
        let (boundary, out) = block?;
        boundary_facets += boundary;
        fits = fits.then(out);
    }
    let (adj, (adj_facet, nbr_corner)) = mate
        .par_chunks(N)
        .map(|mates| {
            let mut adj = [NONE; N];
            let mut adj_facet = [0u8; N];
            let mut nbr = [[0u8; N]; N];
            for (f, m) in mates.iter().enumerate() {
                let m = m.load(Relaxed);
                if m != UNGLUED {
                    // the neighbour's facet is the corner the apex `f`
                    // maps to (no division of a half-facet id)
                    nbr[f] = std::array::from_fn(|c| (m >> (32 + 8 * c)) as u8);
                    adj[f] = m as u32;
                    adj_facet[f] = nbr[f][f];
                }
            }
            (adj, (adj_facet, nbr))
        })
        .unzip();
    let topo = Topology {
        adj,
        adj_facet,
        nbr_corner,
        boundary_facets,
    };
    Ok((topo, fits))
}

/// The half-facets `(rest, s·N + f, order)` ([`rest_without`]) whose least vertex is `v`,
/// found through `v`'s corners `star`, in corner order: the bucket of `v`.
fn facets_from<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    star: &[u32],
    v: u32,
    bucket: &mut Vec<Half>,
) {
    bucket.clear();
    for &id in star {
        let (s, c) = split::<N>(id);
        let simplex = &map.simplices[s];
        // the facets through corner c whose other vertices are all above v:
        // every one when no corner is below v, the one opposite the only
        // corner below v, none when two are below
        // (the corners below v as a bit set: no branch per corner)
        let below = simplex
            .iter()
            .enumerate()
            .fold(0u32, |m, (j, &w)| m | u32::from(w < v) << j);
        if below == 0 {
            for f in 0..N {
                if f != c {
                    let (rest, order) = rest_without(simplex, f, c);
                    bucket.push((rest, (s * N + f) as u32, order));
                }
            }
        } else if below & (below - 1) == 0 {
            let last = below.trailing_zeros() as usize;
            let (rest, order) = rest_without(simplex, last, c);
            bucket.push((rest, (s * N + last) as u32, order));
        }
    }
}

/// A half-facet in a bucket: the rest of its key ([`rest_without`]), its
/// id `s·N + f`, its order ([`rest_without`]).
type Half = (u64, u32, u8);

/// Marks a key of [`pair_bucket`]'s table whose two half-facets are glued.
const PAIRED: u32 = 1 << 31;

/// Glues the pairs of a bucket in any order (writes `mate`) through a
/// hash table of its keys (`table[slot]`: 1 + the bucket index of the
/// key's first half-facet, [`PAIRED`] once its second came, 0 for none;
/// open addressing, at most half full); returns the number of boundary
/// facets, or `None` when a key comes a third time or a pair is
/// misoriented, for [`glue_bucket`] to name the bucket's first error in
/// key order (its writes are those of this one).
fn pair_bucket<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    bucket: &[Half],
    mate: &[AtomicU64],
    table: &mut Vec<u32>,
    sink: &mut impl PairSink<N, D>,
) -> Option<usize> {
    let size = (2 * bucket.len()).next_power_of_two().max(8);
    let shift = 64 - size.trailing_zeros();
    table.clear();
    table.resize(size, 0);
    let mut pairs = 0;
    for (i, &(key, h, order)) in bucket.iter().enumerate() {
        // Fibonacci hashing: the top bits of the key times 2^64/φ
        let mut at = (key.wrapping_mul(0x9E37_79B9_7F4A_7C15) >> shift) as usize;
        loop {
            let slot = table[at];
            if slot == 0 {
                table[at] = i as u32 + 1;
                break;
            }
            let (first_key, first, first_order) = bucket[(slot & !PAIRED) as usize - 1];
            if first_key == key {
                if slot & PAIRED != 0 {
                    return None;
                }
                table[at] = slot | PAIRED;
                glue_pair(map, (first, first_order), (h, order), mate, sink).ok()?;
                pairs += 1;
                break;
            }
            at = (at + 1) & (size - 1);
        }
    }
    Some(bucket.len() - 2 * pairs)
}

/// Glues the pairs of a bucket of at most [`SMALL_BUCKET`] half-facets
/// (writes `mate`) by comparing each key not yet glued with the keys after
/// it, without sorting; returns the number of boundary facets, or `None`
/// as [`pair_bucket`] does. A bucket lists its half-facets by increasing
/// id ([`facets_from`]), so each pair is glued in the order of one sort.
fn pair_small<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    bucket: &[Half],
    mate: &[AtomicU64],
    sink: &mut impl PairSink<N, D>,
) -> Option<usize> {
    debug_assert!(bucket.len() <= SMALL_BUCKET);
    let (mut glued, mut pairs) = (0u32, 0);
    for (i, &(key, h, order)) in bucket.iter().enumerate() {
        if glued >> i & 1 != 0 {
            continue;
        }
        let mut other = None;
        for (j, second) in bucket.iter().enumerate().skip(i + 1) {
            if second.0 == key {
                if other.is_some() {
                    return None;
                }
                other = Some((j, second));
            }
        }
        if let Some((j, &(_, h2, o2))) = other {
            glued |= 1 << j;
            glue_pair(map, (h, order), (h2, o2), mate, sink).ok()?;
            pairs += 1;
        }
    }
    Some(bucket.len() - 2 * pairs)
}

/// Glues half-facets `h1 = s·N + f` and `h2 = n·N + g` of the same key,
/// with their orders ([`rest_without`]; writes both `mate`s), or the error
/// of a misoriented pair: consistent orientation <=> putting `s`'s apex
/// in place of `n`'s apex gives an odd permutation of `s`'s corners (the
/// two lie on opposite sides), the corner map `there`. With `P1`, `P2`
/// the two orders (key position → corner, the apex last), `there = P2 ∘
/// P1⁻¹`, whose parity is that of `P1` xor that of `P2`.
#[inline]
fn glue_pair<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    (h1, o1): (u32, u8),
    (h2, o2): (u32, u8),
    mate: &[AtomicU64],
    sink: &mut impl PairSink<N, D>,
) -> Result<(), InputError> {
    debug_assert!(h1 < h2, "a bucket lists its half-facets by id");
    let ((s, f), (n, g)) = (split::<N>(h1), split::<N>(h2));
    if (o1 ^ o2) & ODD == 0 {
        return Err(opposite_orientations(map, s, f, n));
    }
    // `mate` words: corner `c` of one side to the corner of the other in
    // byte `c` above the other simplex's id (the apexes `f` and `g` are
    // the corners the orders leave out: byte `f` holds `g`)
    debug_assert!(f < N && g < N);
    let maps = &CornerMaps::<N>::TABLE;
    let (o1, o2) = (usize::from(o1 & 63), usize::from(o2 & 63));
    let there = n as u64 | u64::from(maps[o1][o2]) << 32;
    let back = s as u64 | u64::from(maps[o2][o1]) << 32;
    mate[h1 as usize].store(there, Relaxed);
    mate[h2 as usize].store(back, Relaxed);
    sink.glued(map, h1, h2, maps[o1][o2]);
    Ok(())
}

/// The error of simplices `s` and `n` glued across facet `f` of `s` with
/// opposite orientations.
#[cold]
#[inline(never)]
fn opposite_orientations<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    s: usize,
    f: usize,
    n: usize,
) -> InputError {
    let key = facet_key(&map.simplices[s], f);
    MapError::OppositeOrientations {
        simplex: ElementKind::simplex(N),
        simplices: [s.min(n), s.max(n)],
        vertices: key[..N - 1].to_vec(),
    }
    .into()
}

/// Glues the pairs of a sorted bucket (writes `mate`), checking that each
/// pair is consistently oriented; returns the number of boundary facets,
/// or the bucket's first error in key order.
fn glue_bucket<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    bucket: &[Half],
    mate: &[AtomicU64],
    sink: &mut impl PairSink<N, D>,
) -> Result<usize, InputError> {
    let mut boundary = 0;
    let mut i = 0;
    while i < bucket.len() {
        let mut j = i + 1;
        while j < bucket.len() && bucket[j].0 == bucket[i].0 {
            j += 1;
        }
        match j - i {
            1 => boundary += 1,
            2 => {
                let (a, b) = (&bucket[i], &bucket[i + 1]);
                glue_pair(map, (a.1, a.2), (b.1, b.2), mate, sink)?;
            }
            n => {
                let (s, f) = split::<N>(bucket[i].1);
                let key = facet_key(&map.simplices[s], f);
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
    Ok(boundary)
}

/// Checks that the simplices around each vertex are connected through the
/// facets that contain the vertex (blocks of vertices in parallel; the
/// error names the first vertex that fails).
pub(crate) fn check_vertices<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    corners: &VertexCorners,
) -> Result<(), InputError> {
    let nv = map.positions.len();
    let first_bad = (0..nv.div_ceil(SORT_BLOCK))
        .into_par_iter()
        .map(|b| {
            let mut reached = Vec::new();
            let mut stack: Vec<(usize, usize)> = Vec::new();
            (b * SORT_BLOCK..nv.min((b + 1) * SORT_BLOCK)).find(|&v| {
                let star = corners.of(v);
                !connected(topo, star, &corners.position, &mut reached, &mut stack)
            })
        })
        .collect::<Vec<Option<usize>>>()
        .into_iter()
        .flatten()
        .next();
    match first_bad {
        Some(v) => Err(non_manifold_vertex::<N>(v)),
        None => Ok(()),
    }
}

/// The error of a vertex whose simplices are not connected through its
/// facets.
pub(crate) fn non_manifold_vertex<const N: usize>(vertex: usize) -> InputError {
    MapError::NonManifoldVertex {
        vertex,
        simplex: ElementKind::simplex(N),
    }
    .into()
}

/// Whether a depth-first walk from the first corner of `star` (the corner
/// ids of one vertex; `position` as in [`VertexCorners`]) across the
/// facets that contain the vertex reaches all of them (an empty star is
/// connected).
fn connected<const N: usize>(
    topo: &Topology<N>,
    star: &[u32],
    position: &[u32],
    reached: &mut Vec<bool>,
    stack: &mut Vec<(usize, usize)>,
) -> bool {
    let Some(&first) = star.first() else {
        return true;
    };
    reached.clear();
    reached.resize(star.len(), false);
    reached[0] = true;
    stack.clear();
    stack.push(split::<N>(first));
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
#[path = "topology_build_tests.rs"]
mod tests;
