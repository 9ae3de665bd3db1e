//! Step 11: doublet removal on the mesh — the fallback of the graph's
//! (`dualex_graph::doublet`, step 8e) for the interior vertices of valence
//! 2 that it did not merge: those made after it (a zipped hole's folded
//! corner collapsed, the repairs of step 10) and those whose vertex the
//! gluing identified beyond the graph's corners (union–find over corners).
//!
//! A valence-2 interior vertex `v` lies in exactly two quads that share
//! the two edges at `v`:
//!
//! ```text
//!   X = [v, a, x, b]        Y = [v, b, y, a]     →     [a, x, b, y]
//! ```
//!
//! Dissolving `v` replaces `X` and `Y` by the one quad `[a, x, b, y]`: it
//! uses the four outer edges of the pair, which exist already, so no edge
//! is created and manifoldness and orientation are kept; `v` and the edges
//! `v–a`, `v–b` disappear (V − 1, E − 2, F − 1: the Euler characteristic is
//! unchanged). `a` and `b` lose one edge each and may become doublets
//! themselves: they are queued.
//!
//! Input: a valid all-quad mesh. Output: the same surface without interior
//! valence-2 vertices, and the number dissolved. Preconditions are checked
//! per vertex before any write: exactly two quads, each with `v` once,
//! sharing both edges at `v` in opposite directions, and `x ≠ y` (a pair
//! sharing three vertices is a closed two-quad pillow, left alone and
//! counted in [`Doublets::left`]). Unused vertices are removed at the end
//! and the others renumbered in order.

use dualex_cells::QuadMesh;
use dualex_segment::place::Placed;
use std::collections::VecDeque;

/// What doublet removal did (the graph's merges, step 8e, and this
/// fallback on the mesh, step 11).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Doublets {
    /// Valence-2 interior vertices dissolved (in the graph and on the mesh).
    pub dissolved: usize,
    /// Interior vertices of valence ≤ 2 left (preconditions not met).
    pub left: usize,
    /// Of `dissolved`, those merged in the graph
    /// (`NodeGraph::dissolve_doublets`).
    pub in_graph: usize,
}

/// The quads around each vertex (alive ones, by index into `cells`).
fn incidence(nv: usize, cells: &[[u32; 4]], alive: &[bool]) -> Vec<Vec<usize>> {
    let mut around = vec![Vec::new(); nv];
    for (c, q) in cells.iter().enumerate().filter(|&(c, _)| alive[c]) {
        for &v in q {
            around[v as usize].push(c);
        }
    }
    around
}

/// Position of `v` in `q`.
fn at(q: &[u32; 4], v: u32) -> Option<usize> {
    q.iter().position(|&w| w == v)
}

/// Whether `v` is an interior vertex: every edge at it is shared by two
/// alive quads.
fn is_interior(v: u32, around: &[Vec<usize>], cells: &[[u32; 4]], alive: &[bool]) -> bool {
    // v is interior when each of its edges is shared by two quads
    let mut count: std::collections::HashMap<u32, usize> = Default::default();
    for &c in &around[v as usize] {
        if !alive[c] {
            continue;
        }
        let q = &cells[c];
        if let Some(k) = at(q, v) {
            *count.entry(q[(k + 1) % 4]).or_default() += 1;
            *count.entry(q[(k + 3) % 4]).or_default() += 1;
        }
    }
    !count.is_empty() && count.values().all(|&n| n == 2)
}

/// The merged quad of doublet `v`, if its preconditions hold.
fn merged(v: u32, pair: [usize; 2], cells: &[[u32; 4]]) -> Option<[u32; 4]> {
    let (qx, qy) = (&cells[pair[0]], &cells[pair[1]]);
    let (kx, ky) = (at(qx, v)?, at(qy, v)?);
    let (a, x, b) = (qx[(kx + 1) % 4], qx[(kx + 2) % 4], qx[(kx + 3) % 4]);
    // Y = [v, b, y, a]: opposite traversal of both shared edges
    let (b2, y, a2) = (qy[(ky + 1) % 4], qy[(ky + 2) % 4], qy[(ky + 3) % 4]);
    if (a, b) != (a2, b2) || x == y {
        return None;
    }
    Some([a, x, b, y])
}

/// Dissolves the interior valence-2 vertices of `mesh` (module docs).
pub fn dissolve(mesh: &QuadMesh) -> (QuadMesh, Doublets) {
    let (out, rep, _) = dissolve_traced(mesh);
    (out, rep)
}

/// [`dissolve`], also returning for each output cell the input cell it
/// is (a merged quad takes the place of the first of its two cells).
pub fn dissolve_traced(mesh: &QuadMesh) -> (QuadMesh, Doublets, Vec<u32>) {
    let nv = mesh.positions.len();
    let mut cells = mesh.cells.clone();
    let mut alive = vec![true; cells.len()];
    let mut around = incidence(nv, &cells, &alive);
    let mut rep = Doublets::default();
    let mut queue: VecDeque<u32> = (0..nv as u32)
        .filter(|&v| around[v as usize].len() == 2)
        .collect();
    let mut removed = vec![false; nv];
    while let Some(v) = queue.pop_front() {
        let list: Vec<usize> = around[v as usize]
            .iter()
            .copied()
            .filter(|&c| alive[c])
            .collect();
        if removed[v as usize] || list.len() != 2 || !is_interior(v, &around, &cells, &alive) {
            continue;
        }
        let Some(q) = merged(v, [list[0], list[1]], &cells) else {
            continue;
        };
        alive[list[1]] = false;
        cells[list[0]] = q;
        removed[v as usize] = true;
        around[v as usize].clear();
        // y gains cell list[0]; a and b lose one cell (list[1] dies)
        around[q[3] as usize].push(list[0]);
        rep.dissolved += 1;
        for w in [q[0], q[2]] {
            let n = around[w as usize].iter().filter(|&&c| alive[c]).count();
            if n == 2 {
                queue.push_back(w);
            }
        }
    }
    // renumber the vertices still used
    let mut used = vec![false; nv];
    for (q, _) in cells.iter().zip(&alive).filter(|(_, &a)| a) {
        for &v in q {
            used[v as usize] = true;
        }
    }
    let mut new_id = vec![u32::MAX; nv];
    let mut out = QuadMesh::default();
    for v in (0..nv).filter(|&v| used[v]) {
        new_id[v] = out.positions.len() as u32;
        out.positions.push(mesh.positions[v]);
    }
    out.cells = cells
        .iter()
        .zip(&alive)
        .filter(|(_, &a)| a)
        .map(|(q, _)| q.map(|v| new_id[v as usize]))
        .collect();
    let final_around = incidence(
        out.positions.len(),
        &out.cells,
        &vec![true; out.cells.len()],
    );
    let all = vec![true; out.cells.len()];
    rep.left = (0..out.positions.len() as u32)
        .filter(|&v| {
            final_around[v as usize].len() <= 2 && is_interior(v, &final_around, &out.cells, &all)
        })
        .count();
    let kept = (0..cells.len() as u32)
        .filter(|&c| alive[c as usize])
        .collect();
    (out, rep, kept)
}

/// Step 11 on the placed quads: the doublets left dissolved, their
/// counts added to `st`, the sources and corners carried.
pub fn dissolve_left(out: &mut Placed<2, 4>, st: &mut crate::QuadStats) {
    let (dissolved, rep, kept) = dissolve_traced(&out.mesh);
    st.doublets.dissolved += rep.dissolved;
    st.doublets.left = rep.left;
    if rep.dissolved > 0 {
        out.remake(dissolved, &kept);
        st.finish_mesh(&out.mesh);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 3×3 grid whose centre cell is split into two quads by a vertex of
    /// valence 2: dissolving it gives the 3×3 grid back (9 quads, one
    /// vertex less), valid.
    #[test]
    fn a_doublet_in_a_grid_is_dissolved() {
        let m = dualex_gen::from_mesh::meshes::grid_with_doublet();
        let before = dualex_check::check_quad_mesh(m.positions.len(), &m.cells);
        assert!(before.is_valid(), "{:?}", before.errors());
        assert_eq!(before.interior_valence.get(&2), Some(&1));
        let (out, rep, kept) = dissolve_traced(&m);
        assert_eq!(
            rep,
            Doublets {
                dissolved: 1,
                left: 0,
                in_graph: 0,
            }
        );
        assert_eq!((out.cells.len(), out.positions.len()), (9, 16));
        // the merged quad takes the place of X (cell 8), Y (cell 9) is gone
        assert_eq!(kept, (0..9).collect::<Vec<u32>>());
        let after = dualex_check::check_quad_mesh(out.positions.len(), &out.cells);
        assert!(after.is_valid(), "{:?}", after.errors());
        assert_eq!(after.euler, before.euler);
        assert_eq!(after.interior_valence.get(&4), Some(&4));
    }

    /// A closed pillow of two quads sharing all four vertices: every
    /// vertex has valence 2 and `x = y`; nothing is dissolved, all 4 are
    /// reported as left.
    #[test]
    fn a_pillow_is_left_alone() {
        let m = QuadMesh {
            positions: vec![[0.0; 3]; 4],
            cells: vec![[0, 1, 2, 3], [0, 3, 2, 1]],
        };
        let (out, rep) = dissolve(&m);
        assert_eq!(
            rep,
            Doublets {
                dissolved: 0,
                left: 4,
                in_graph: 0,
            }
        );
        assert_eq!(out.cells, m.cells);
    }

    /// Boundary corners of valence 2 are not doublets.
    #[test]
    fn boundary_corners_stay() {
        let m = QuadMesh {
            positions: vec![[0.0; 3]; 6],
            cells: vec![[0, 1, 4, 3], [1, 2, 5, 4]],
        };
        let (out, rep) = dissolve(&m);
        assert_eq!(rep, Doublets::default());
        assert_eq!(out.cells, m.cells);
    }
}
