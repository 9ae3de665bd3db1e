//! Step 10c: vertices where the surface is pinched, split into one vertex
//! per fan.
//!
//! After the repair, a vertex whose faces form several fans (faces linked
//! when they share an edge at the vertex) is a point where two pieces of
//! the surface touch: the gluing identified corners that the surface
//! keeps apart (on messy maps, a pocket of a fold closed against the rest
//! by the hole fills). A file cannot hold such a vertex as a manifold one,
//! so each fan but the first gets a copy of the vertex (same position).
//! This changes the Euler characteristic by one per copy; the caller
//! compares the output's topology with the input's and says so.
//!
//! Input: a quad mesh whose edges each join two distinct vertices and
//! are used at most twice (checked: the split is skipped otherwise).
//! Output: the number of copies made. Invariant: cells keep their count,
//! order and corner order; only vertex ids of the pinched fans change.

use dualex_cells::QuadMesh;
use dualex_util::union_find::UnionFind;
use std::collections::HashMap;

/// Splits the pinched vertices of `mesh` (module docs); returns how many
/// vertex copies were made.
pub fn split_pinched(mesh: &mut QuadMesh) -> usize {
    let cells = &mesh.cells;
    // corners: 4 · cell + k; two corners at one vertex are in one fan
    // when they share the edge to the same other vertex
    let mut uf = UnionFind::new(4 * cells.len());
    let mut at_edge: HashMap<(u32, u32), Vec<usize>> = HashMap::new();
    for (c, q) in cells.iter().enumerate() {
        for k in 0..4 {
            let (v, next, prev) = (q[k], q[(k + 1) % 4], q[(k + 3) % 4]);
            if v == next || v == prev {
                return 0;
            }
            at_edge.entry((v, next)).or_default().push(4 * c + k);
            at_edge.entry((v, prev)).or_default().push(4 * c + k);
        }
    }
    for corners in at_edge.values() {
        match corners[..] {
            [_] => {} // a boundary edge
            [a, b] => {
                uf.union(a, b);
            }
            _ => return 0, // an edge used more than twice: not ours to fix
        }
    }
    // the fans of each vertex, the first (by its smallest corner) keeps it
    let mut first_root: HashMap<u32, usize> = HashMap::new();
    let mut copy_of_root: HashMap<usize, u32> = HashMap::new();
    let mut copies = 0;
    for c in 0..cells.len() {
        for k in 0..4 {
            let v = mesh.cells[c][k];
            let r = uf.find(4 * c + k);
            let keep = *first_root.entry(v).or_insert(r);
            if keep == r {
                continue;
            }
            let w = *copy_of_root.entry(r).or_insert_with(|| {
                copies += 1;
                mesh.positions.push(mesh.positions[v as usize]);
                (mesh.positions.len() - 1) as u32
            });
            mesh.cells[c][k] = w;
        }
    }
    copies
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn two_quads_touching_at_a_corner_are_split_apart() {
        let mut m = QuadMesh {
            positions: vec![[0.0; 3]; 7],
            cells: vec![[0, 1, 2, 3], [0, 4, 5, 6]],
        };
        assert_eq!(split_pinched(&mut m), 1);
        assert_eq!(m.cells, vec![[0, 1, 2, 3], [7, 4, 5, 6]]);
        assert_eq!(m.positions.len(), 8);
        let r = dualex_check::check_quad_mesh(m.positions.len(), &m.cells);
        assert!(r.non_manifold_vertices.is_empty());
    }

    #[test]
    fn a_manifold_fan_is_left_alone() {
        // four quads around vertex 0
        let mut m = QuadMesh {
            positions: vec![[0.0; 3]; 9],
            cells: vec![[0, 1, 2, 3], [0, 3, 4, 5], [0, 5, 6, 7], [0, 7, 8, 1]],
        };
        let before = m.clone();
        assert_eq!(split_pinched(&mut m), 0);
        assert_eq!(m, before);
    }
}
