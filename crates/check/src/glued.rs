//! The input's [`Shape`] read off the facet adjacency its extraction built
//! anyway (the map's `Topology`), instead of a pass of its own over the
//! simplices ([`topology::surface_shape`], [`topology::tet_shape_and_boundary`]);
//! of tets in two parts ([`tet_glued`] on the first pass, then [`tet_shape`]).
//!
//! Input: the simplices and their adjacency `adj[s][f]`: the simplex
//! across the facet opposite corner `f` of `s`, or [`NONE`]. Output: the
//! same [`Shape`] (and, of tets, the same faces of one tet, in another
//! order) as the functions above, provided that the adjacency is that of
//! a map the extraction accepted:
//! - facets are glued when their vertex sets are equal, never three at a
//!   time (a facet of one simplex is [`NONE`]): the faces of one tet are
//!   the unglued facets, and a triangle surface's edges are its glued
//!   pairs plus its unglued sides;
//! - the simplices around every vertex are connected through their
//!   facets: the components through shared vertices are those across
//!   facets.
//!
//! The components are counted by blocks in parallel
//! ([`facet_components_par`]).
//!
//! Tests (`glued_tests.rs`, and the facade's on whole extractions) compare
//! both ways on maps with boundaries, several components and pinched
//! vertices.

use crate::topology::{self, Shape};
use dualex_util::union_find::UnionFind;
use dualex_util::used::used_vertices;

/// No neighbour across a facet (a facet of one simplex).
pub const NONE: u32 = u32::MAX;

/// Components of the simplices joined across their glued facets: a flood
/// fill on one thread (each simplex pushed once); the reference of
/// [`facet_components_par`], which the callers use.
pub fn facet_components<const N: usize>(adj: &[[u32; N]]) -> usize {
    let mut seen = vec![false; adj.len()];
    let (mut stack, mut count) = (Vec::new(), 0);
    for s in 0..adj.len() {
        if seen[s] {
            continue;
        }
        (seen[s], count) = (true, count + 1);
        stack.push(s as u32);
        while let Some(t) = stack.pop() {
            for &n in &adj[t as usize] {
                if n != NONE && !seen[n as usize] {
                    seen[n as usize] = true;
                    stack.push(n);
                }
            }
        }
    }
    count
}

/// Simplices per block of [`facet_components_par`].
const BLOCK: usize = 1 << 14;

/// [`facet_components`] on all threads: each block of [`BLOCK`]
/// simplices is flood-filled on its own (a byte per simplex, as the
/// reference's `bool`: the first pass of 1M tets holds it at its peak;
/// [`fill_block`]), then the blocks' components are joined along the
/// facets from the simplices marked there to later blocks, each pair of
/// components once. A block of more components than the byte numbers (a
/// very fragmented input) falls back to the reference.
pub fn facet_components_par<const N: usize>(adj: &[[u32; N]]) -> usize {
    components_by_blocks(adj, BLOCK)
}

/// [`facet_components_par`] with blocks of `block ≥ 1` simplices (tests
/// vary it).
pub(crate) fn components_by_blocks<const N: usize>(adj: &[[u32; N]], block: usize) -> usize {
    use rayon::prelude::*;
    let mut label = vec![0u8; adj.len()];
    let counts: Option<Vec<usize>> = label
        .par_chunks_mut(block)
        .enumerate()
        .map(|(b, label)| fill_block(adj, b * block, label))
        .collect();
    let Some(counts) = counts else {
        drop(label);
        return facet_components(adj);
    };
    let mut first = Vec::with_capacity(counts.len());
    let mut total = 0;
    for count in &counts {
        first.push(total);
        total += count;
    }
    // the global component of simplex `s` of block `b`
    let global = |b: usize, s: usize| first[b] + usize::from(label[s] & !LATER) - 1;
    let pairs: Vec<Vec<(usize, usize)>> = label
        .par_chunks(block)
        .enumerate()
        .map(|(b, marks)| later_pairs(adj, (b, block), marks, &global))
        .collect();
    let mut joined = UnionFind::new(total);
    let merged = pairs
        .iter()
        .flatten()
        .filter(|&&(a, b)| joined.union(a, b))
        .count();
    total - merged
}

/// The bit of a [`fill_block`] label marking a simplex with a facet to a
/// later block.
const LATER: u8 = 0x80;

/// One block's flood fill: `label[s - lo]` becomes 1 + the index of the
/// block-local component of simplex `s`, with [`LATER`] set when `s` has
/// a facet to a simplex of a later block; returns the component count,
/// or `None` past 127 components.
fn fill_block<const N: usize>(adj: &[[u32; N]], lo: usize, label: &mut [u8]) -> Option<usize> {
    let (mut stack, mut count) = (Vec::new(), 0u8);
    let hi = lo + label.len();
    for s in lo..hi {
        if label[s - lo] != 0 {
            continue;
        }
        count += 1;
        if count >= LATER {
            return None;
        }
        label[s - lo] = count;
        stack.push(s as u32);
        while let Some(t) = stack.pop() {
            for &n in &adj[t as usize] {
                // outside the block (below it, wrapping, or above it) or NONE
                let i = (n as usize).wrapping_sub(lo);
                if i < label.len() {
                    if label[i] == 0 {
                        label[i] = count;
                        stack.push(n);
                    }
                } else if n != NONE && n as usize >= hi {
                    label[t as usize - lo] |= LATER;
                }
            }
        }
    }
    Some(usize::from(count))
}

/// The distinct pairs `(component of s, component of t)` (`component`:
/// global indices, of a simplex and its block) of the facets from a
/// simplex `s` of block `b` (of `block` simplices; `marks`: its labels,
/// [`LATER`] set on the simplices to look at) to a simplex `t` of a later
/// block, sorted.
fn later_pairs<const N: usize>(
    adj: &[[u32; N]],
    (b, block): (usize, usize),
    marks: &[u8],
    component: &(impl Fn(usize, usize) -> usize + Sync),
) -> Vec<(usize, usize)> {
    let lo = b * block;
    let hi = lo + marks.len();
    let mut pairs = Vec::new();
    for (i, _) in marks.iter().enumerate().filter(|(_, &m)| m & LATER != 0) {
        let s = lo + i;
        let of_s = component(b, s);
        for &n in &adj[s] {
            let t = n as usize;
            if n != NONE && t >= hi {
                // most often the next block (no division)
                let bt = if t - hi < block { b + 1 } else { t / block };
                let pair = (of_s, component(bt, t));
                if pairs.last() != Some(&pair) {
                    pairs.push(pair);
                }
            }
        }
    }
    pairs.sort_unstable();
    pairs.dedup();
    pairs
}

/// The unglued facets, as places `N·s + f` (the facet opposite corner
/// `f` of `s`), in that order.
pub fn lone_facets<const N: usize>(adj: &[[u32; N]]) -> Vec<usize> {
    let mut out = Vec::new();
    for (s, a) in adj.iter().enumerate() {
        for (f, &n) in a.iter().enumerate() {
            if n == NONE {
                out.push(N * s + f);
            }
        }
    }
    out
}

/// [`topology::surface_shape`] of an accepted triangle map (module docs):
/// `E = (3F + B) / 2` edges for `B` unglued sides, the vertices used
/// counted, the boundary loops joined along the unglued sides; the
/// components are counted beside the rest, by blocks.
pub fn surface_shape(n_vertices: usize, triangles: &[[u32; 3]], adj: &[[u32; 3]]) -> Shape {
    let (components, (n_used, lone, loops)) = rayon::join(
        || facet_components_par(adj),
        || {
            let lone = lone_facets(adj);
            let loops = boundary_loops(n_vertices, triangles, &lone);
            (used_vertices(n_vertices, triangles), lone, loops)
        },
    );
    let n_faces = triangles.len() as i64;
    let n_edges = (3 * n_faces + lone.len() as i64) / 2;
    Shape {
        components,
        euler: n_used as i64 - n_edges + n_faces,
        boundary_components: loops,
    }
}

/// Components of the sides `lone` (places `3·t + f`, the side opposite
/// corner `f`) through their ends; 0 without any.
fn boundary_loops(n_vertices: usize, triangles: &[[u32; 3]], lone: &[usize]) -> usize {
    if lone.is_empty() {
        return 0;
    }
    let mut loops = UnionFind::new(n_vertices);
    let mut on_boundary = vec![false; n_vertices];
    for &p in lone {
        let t = &triangles[p / 3];
        let (a, b) = (t[(p + 1) % 3] as usize, t[(p + 2) % 3] as usize);
        loops.union(a, b);
        (on_boundary[a], on_boundary[b]) = (true, true);
    }
    loops.count_sets((0..n_vertices).filter(|&v| on_boundary[v]))
}

/// What a tet map's first pass reads off its adjacency (module docs):
/// the rest of its shape, the boundary surface's, is found later by
/// [`tet_shape`], when the pass's model is no longer held (its arrays
/// are as long as the vertices: found beside the model, they raised the
/// peak memory).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct TetGlued {
    /// Components of the tets across their faces.
    pub components: usize,
    /// The faces of one tet, places `4·tet + f`, in tet order.
    pub lone: Vec<usize>,
}

/// [`TetGlued`] of an accepted tet map: the components and the faces of
/// one tet, in parallel.
pub fn tet_glued(adj: &[[u32; 4]]) -> TetGlued {
    let (components, lone) = rayon::join(|| facet_components_par(adj), || lone_facets(adj));
    TetGlued { components, lone }
}

/// [`topology::tet_shape_and_boundary`]'s shape of an accepted tet map
/// from its [`TetGlued`] `g`: the components across faces, the boundary
/// surface's shape as there.
pub fn tet_shape(n_vertices: usize, tets: &[[u32; 4]], g: &TetGlued) -> Shape {
    let (m, faces) = renumbered(n_vertices, topology::tet_boundary_of(tets, &g.lone));
    let b = topology::surface_shape(m, &faces);
    topology::volume_shape(g.components, b)
}

/// `faces` with their vertices numbered `0..m` in order of first use, and
/// `m`; as they are when a vertex is `n_vertices` or more (not in an
/// accepted map). A surface's shape (components, Euler characteristic and
/// boundary loops, over the vertices it uses) does not depend on the
/// numbering: [`topology::surface_shape`]'s arrays are then as long as
/// the boundary's vertices, not the volume's (one array of the volume's
/// here).
fn renumbered(n_vertices: usize, mut faces: Vec<[u32; 3]>) -> (usize, Vec<[u32; 3]>) {
    if faces.iter().flatten().any(|&v| v as usize >= n_vertices) {
        return (n_vertices, faces);
    }
    let (mut id, mut m) = (vec![u32::MAX; n_vertices], 0u32);
    for v in faces.iter_mut().flatten() {
        let i = &mut id[*v as usize];
        if *i == u32::MAX {
            (*i, m) = (m, m + 1);
        }
        *v = *i;
    }
    (m as usize, faces)
}
