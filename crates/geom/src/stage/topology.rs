//! The mesh's own topology, as the stage needs it: boundary vertices of
//! a quad mesh, the cells around each vertex, rings of cells.
//!
//! Input: cells (vertex indices). Output: per-vertex flags and CSR lists.

/// The edges of one cell, as that cell runs them (`[a, b]`), in the
/// order of their sorted keys.
pub(super) fn boundary_edges<const K: usize>(
    cells: &[[u32; K]],
    edges: &[[usize; 2]],
) -> Vec<[u32; 2]> {
    use rayon::prelude::*;
    // edges as sorted keys: an edge of one cell appears once
    let mut keys: Vec<(u64, [u32; 2])> = cells
        .par_iter()
        .flat_map_iter(|c| {
            edges.iter().map(move |e| {
                let (a, b) = (c[e[0]], c[e[1]]);
                ((u64::from(a.min(b)) << 32) | u64::from(a.max(b)), [a, b])
            })
        })
        .collect();
    keys.par_sort_unstable_by_key(|k| k.0);
    keys.chunk_by(|a, b| a.0 == b.0)
        .filter_map(|run| match run {
            [(_, ab)] => Some(*ab),
            _ => None,
        })
        .collect()
}

/// Vertices on edges of one quad.
pub(super) fn boundary_vertices(n: usize, cells: &[[u32; 4]], edges: &[[usize; 2]]) -> Vec<bool> {
    let mut out = vec![false; n];
    for [a, b] in boundary_edges(cells, edges) {
        out[a as usize] = true;
        out[b as usize] = true;
    }
    out
}

/// CSR of the cells around each vertex.
pub(super) fn vertex_cells<const K: usize>(n: usize, cells: &[[u32; K]]) -> (Vec<usize>, Vec<u32>) {
    let mut start = vec![0usize; n + 1];
    for c in cells {
        for &v in c {
            start[v as usize + 1] += 1;
        }
    }
    for i in 0..n {
        start[i + 1] += start[i];
    }
    let mut fill = start.clone();
    let mut list = vec![0u32; start[n]];
    for (ci, c) in cells.iter().enumerate() {
        for &v in c {
            list[fill[v as usize]] = ci as u32;
            fill[v as usize] += 1;
        }
    }
    (start, list)
}

/// Adds `rings` rings of cells around `region`.
pub(super) fn grow<const K: usize>(
    region: &mut [bool],
    around: &(Vec<usize>, Vec<u32>),
    cells: &[[u32; K]],
    rings: usize,
) {
    for _ in 0..rings {
        let now: Vec<usize> = (0..region.len()).filter(|&v| region[v]).collect();
        for v in now {
            for &c in &around.1[around.0[v]..around.0[v + 1]] {
                for &u in &cells[c as usize] {
                    region[u as usize] = true;
                }
            }
        }
    }
}
