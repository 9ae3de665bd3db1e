//! **Stand-in cut for tests and measurements** — the `cut` module (being
//! written separately) replaces it.
//!
//! Input: a [`Surface`] and its singular vertices. Output: `is_cut` per
//! edge: the interior edges not crossed by a breadth-first dual spanning
//! tree of the faces (the rest opens the surface to one disk per
//! component), then pruned: a cut edge hanging from a vertex that is
//! neither singular nor on the boundary, with no other cut edge, is
//! removed, repeatedly. What stays is a disk-opening cut through every
//! singular vertex (for a closed surface of genus g: 2g loops joined with
//! the singularities).

use crate::surface::{Surface, NO_FACE};
use std::collections::VecDeque;

/// The cut (module docs).
pub fn cut(surface: &Surface, singular_vertices: &[u32]) -> Vec<bool> {
    let (nf, ne) = (surface.triangles.len(), surface.edges.len());
    let mut in_tree = vec![false; ne];
    let mut seen = vec![false; nf];
    let mut queue = VecDeque::new();
    for start in 0..nf {
        if seen[start] {
            continue;
        }
        seen[start] = true;
        queue.push_back(start);
        while let Some(f) = queue.pop_front() {
            for &e in &surface.face_edges[f] {
                let [f0, f1] = surface.edge_faces[e as usize];
                if f1 == NO_FACE {
                    continue;
                }
                let g = if f0 as usize == f { f1 } else { f0 } as usize;
                if !seen[g] {
                    seen[g] = true;
                    in_tree[e as usize] = true;
                    queue.push_back(g);
                }
            }
        }
    }
    let mut is_cut: Vec<bool> = (0..ne)
        .map(|e| !in_tree[e] && surface.edge_faces[e][1] != NO_FACE)
        .collect();
    let mut keep = surface.boundary_vertex.clone();
    for &v in singular_vertices {
        if let Some(k) = keep.get_mut(v as usize) {
            *k = true;
        }
    }
    let mut incident: Vec<Vec<u32>> = vec![Vec::new(); surface.positions.len()];
    let mut degree = vec![0usize; surface.positions.len()];
    for (e, &[a, b]) in surface.edges.iter().enumerate() {
        incident[a as usize].push(e as u32);
        incident[b as usize].push(e as u32);
        if is_cut[e] {
            degree[a as usize] += 1;
            degree[b as usize] += 1;
        }
    }
    let mut stack: Vec<usize> = (0..degree.len())
        .filter(|&v| degree[v] == 1 && !keep[v])
        .collect();
    while let Some(v) = stack.pop() {
        if degree[v] != 1 {
            continue;
        }
        let Some(&e) = incident[v].iter().find(|&&e| is_cut[e as usize]) else {
            continue;
        };
        is_cut[e as usize] = false;
        for w in surface.edges[e as usize] {
            let w = w as usize;
            degree[w] -= 1;
            if degree[w] == 1 && !keep[w] {
                stack.push(w);
            }
        }
    }
    is_cut
}
