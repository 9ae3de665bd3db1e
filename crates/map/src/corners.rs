//! The corners around each vertex, built in parallel.
//!
//! Input: simplices (vertex ids below the vertex count). Output:
//! [`VertexCorners`], CSR: the corners `s·N + c` of vertex `v` are
//! `corners[offsets[v]..offsets[v + 1]]`, in simplex order; with
//! `indexed`, `position[s·N + c]` is the place of corner `s·N + c` in its
//! vertex's list (a walk around a vertex marks what it reached in an
//! array of the star's size, without hashing).
//!
//! Invariants: the result does not depend on the number of threads nor on
//! the chunking: the simplices are cut into at most [`CHUNKS`] chunks,
//! each counts its corners per vertex, the counts give every chunk its
//! first slot in each vertex's list (earlier chunks first; a prefix sum
//! over blocks of vertices, in parallel), then every
//! chunk writes its corners in simplex order. Those writes land anywhere
//! in the list, so they go through relaxed atomic stores (each slot is
//! written once, read after the parallel pass has joined).

use rayon::prelude::*;
use std::sync::atomic::{AtomicU32, Ordering::Relaxed};

/// Most chunks the simplices are cut into (each holds one count per vertex).
const CHUNKS: usize = 4;

/// Fewest simplices of a chunk (small maps stay in one).
const MIN_CHUNK: usize = 1 << 14;

/// The corners around each vertex (module docs).
#[derive(Clone, Debug, Default)]
pub struct VertexCorners {
    /// CSR offsets, one more than the vertex count.
    pub offsets: Vec<u32>,
    /// Corner ids `s·N + c`, per vertex in simplex order.
    pub corners: Vec<u32>,
    /// Per corner id, its place in its vertex's list (empty unless
    /// built `indexed`).
    pub position: Vec<u32>,
}

impl VertexCorners {
    /// The corner lists of `simplices` over `vertex_count` vertices, with
    /// the positions when `indexed`.
    pub fn build<const N: usize>(
        simplices: &[[u32; N]],
        vertex_count: usize,
        indexed: bool,
    ) -> Self {
        let nv = vertex_count;
        let chunk = simplices
            .len()
            .div_ceil(CHUNKS)
            .max(MIN_CHUNK)
            .min(simplices.len().max(1));
        let mut starts: Vec<Vec<u32>> = simplices
            .par_chunks(chunk)
            .map(|part| {
                let mut count = vec![0u32; nv];
                for simplex in part {
                    for &v in simplex {
                        count[v as usize] += 1;
                    }
                }
                count
            })
            .collect();
        let offsets = first_slots(&mut starts, nv);
        let corners: Vec<AtomicU32> = (0..offsets[nv] as usize)
            .into_par_iter()
            .map(|_| AtomicU32::new(0))
            .collect();
        let mut position: Vec<u32> = if indexed {
            (0..simplices.len() * N)
                .into_par_iter()
                .map(|_| 0)
                .collect()
        } else {
            Vec::new()
        };
        let positions: Vec<&mut [u32]> = if indexed {
            position.chunks_mut(chunk * N).collect()
        } else {
            Vec::new()
        };
        let fill = |k: usize, start: &mut Vec<u32>, mut place: Option<&mut [u32]>| {
            let first = k * chunk;
            let part = &simplices[first..simplices.len().min(first + chunk)];
            for (i, simplex) in part.iter().enumerate() {
                for (c, &v) in simplex.iter().enumerate() {
                    let slot = &mut start[v as usize];
                    corners[*slot as usize].store(((first + i) * N + c) as u32, Relaxed);
                    if let Some(place) = place.as_deref_mut() {
                        place[i * N + c] = *slot - offsets[v as usize];
                    }
                    *slot += 1;
                }
            }
        };
        if indexed {
            starts
                .par_iter_mut()
                .zip(positions)
                .enumerate()
                .for_each(|(k, (start, place))| fill(k, start, Some(place)));
        } else {
            starts
                .par_iter_mut()
                .enumerate()
                .for_each(|(k, start)| fill(k, start, None));
        }
        VertexCorners {
            offsets,
            corners: corners.into_iter().map(AtomicU32::into_inner).collect(),
            position,
        }
    }

    /// The corner ids `s·N + c` of vertex `v`.
    #[inline]
    pub fn of(&self, v: usize) -> &[u32] {
        &self.corners[self.offsets[v] as usize..self.offsets[v + 1] as usize]
    }
}

/// Vertices per task of [`first_slots`].
const PREFIX_BLOCK: usize = 1 << 14;

/// Turns each chunk's counts per vertex (`starts[k][v]`) into its first
/// slot in the vertex's list, earlier chunks first, and returns the CSR
/// offsets (`nv + 1`): the sum over vertices, then chunks, in two
/// parallel passes over blocks of vertices with the blocks' totals
/// summed in between (the same integers as one serial pass).
fn first_slots(starts: &mut [Vec<u32>], nv: usize) -> Vec<u32> {
    let blocks = nv.div_ceil(PREFIX_BLOCK);
    let range = |b: usize| b * PREFIX_BLOCK..nv.min((b + 1) * PREFIX_BLOCK);
    let totals: Vec<u32> = (0..blocks)
        .into_par_iter()
        .map(|b| {
            starts
                .iter()
                .map(|st| st[range(b)].iter().sum::<u32>())
                .sum()
        })
        .collect();
    let mut firsts = Vec::with_capacity(blocks);
    let mut at = 0u32;
    for t in totals {
        firsts.push(at);
        at += t;
    }
    // per block, its part of every chunk's counts
    let mut parts: Vec<Vec<&mut [u32]>> = (0..blocks).map(|_| Vec::new()).collect();
    for st in starts.iter_mut() {
        for (b, part) in st[..nv].chunks_mut(PREFIX_BLOCK).enumerate() {
            parts[b].push(part);
        }
    }
    let mut offsets = vec![0u32; nv + 1];
    offsets[nv] = at;
    offsets[..nv]
        .par_chunks_mut(PREFIX_BLOCK)
        .zip(parts)
        .zip(firsts)
        .for_each(|((off, mut parts), at)| block_slots(off, &mut parts, at));
    offsets
}

/// [`first_slots`] on one block of vertices whose first slot is `at`:
/// `off` gets the block's offsets and each chunk's counts `parts[k]`
/// their first slots, in passes over whole slices (vectorizable) and one
/// running sum over the vertices: the counts summed across the chunks in
/// place (each chunk then holds its own and the earlier ones'), the
/// offsets from the last chunk's sums, then from the last chunk down,
/// each chunk's first slot the offset plus the chunk before's sum.
fn block_slots(off: &mut [u32], parts: &mut [&mut [u32]], mut at: u32) {
    for k in 1..parts.len() {
        let (before, after) = parts.split_at_mut(k);
        for (x, &y) in after[0].iter_mut().zip(before[k - 1].iter()) {
            *x += y;
        }
    }
    if let Some(last) = parts.last() {
        for (o, &t) in off.iter_mut().zip(last.iter()) {
            *o = at;
            at += t;
        }
    }
    for k in (1..parts.len()).rev() {
        let (before, after) = parts.split_at_mut(k);
        for ((x, &y), &o) in after[0]
            .iter_mut()
            .zip(before[k - 1].iter())
            .zip(off.iter())
        {
            *x = o + y;
        }
    }
    if let Some(first) = parts.first_mut() {
        first.copy_from_slice(off);
    }
}

/// Simplex and corner of corner id `id = s·N + c`.
#[inline]
pub fn split<const N: usize>(id: u32) -> (usize, usize) {
    (id as usize / N, id as usize % N)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The lists as one growing list per vertex.
    fn reference<const N: usize>(simplices: &[[u32; N]], nv: usize) -> VertexCorners {
        let mut lists: Vec<Vec<u32>> = vec![Vec::new(); nv];
        let mut position = Vec::with_capacity(simplices.len() * N);
        for (s, simplex) in simplices.iter().enumerate() {
            for (c, &v) in simplex.iter().enumerate() {
                position.push(lists[v as usize].len() as u32);
                lists[v as usize].push((s * N + c) as u32);
            }
        }
        let offsets = std::iter::once(0)
            .chain(lists.iter().scan(0u32, |at, l| {
                *at += l.len() as u32;
                Some(*at)
            }))
            .collect();
        VertexCorners {
            offsets,
            corners: lists.concat(),
            position,
        }
    }

    #[test]
    fn same_lists_as_one_sequential_pass() {
        let mut rng = dualex_util::rng::SplitMix::new(7);
        for (ns, nv) in [
            (0usize, 3usize),
            (5, 9),
            (70_000, 900),
            (100_000, 60_000),
            (20_000, 40_000),
        ] {
            let tets: Vec<[u32; 4]> = (0..ns)
                .map(|_| std::array::from_fn(|_| rng.below(nv) as u32))
                .collect();
            let want = reference(&tets, nv);
            let got = VertexCorners::build(&tets, nv, true);
            assert_eq!(got.offsets, want.offsets, "{ns} tets");
            assert_eq!(got.corners, want.corners, "{ns} tets");
            assert_eq!(got.position, want.position, "{ns} tets");
            let plain = VertexCorners::build(&tets, nv, false);
            assert_eq!(plain.corners, want.corners);
            assert!(plain.position.is_empty());
        }
    }
}
