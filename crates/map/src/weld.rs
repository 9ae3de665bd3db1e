//! Welding of cut meshes: vertices duplicated along seams (each copy
//! carrying one chart's coordinates) are merged so that the transitions
//! across the seams become visible.
//!
//! Input: any map (indices in range). Output: a new map and a
//! [`WeldReport`]. Rule: two **boundary** vertices (on a facet with no
//! neighbour in the input) are merged when their positions are **exactly**
//! equal (`-0.0 == 0.0`). Exact equality is what cut-mesh writers produce
//! (the copies are printed from one value) and never merges two distinct
//! vertices of a fine mesh. A group whose merge would put one vertex twice
//! into a simplex is left unmerged. Afterwards unused vertices are dropped;
//! simplices keep their order and their per-corner coordinates.

use crate::components::UnionFind;
use crate::topology_build::sorted_facets;
use crate::SimplexMap;

/// What [`weld`] did.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct WeldReport {
    /// Vertices merged into another one.
    pub welded_vertices: usize,
    /// Vertices used by no simplex, dropped.
    pub dropped_vertices: usize,
}

/// Bits of a position with `-0.0` read as `0.0`.
fn position_key(p: &[f64; 3]) -> [u64; 3] {
    p.map(|x| if x == 0.0 { 0 } else { x.to_bits() })
}

/// Merges coincident boundary vertices (see the module docs).
pub fn weld<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
) -> (SimplexMap<N, D>, WeldReport) {
    let nv = map.positions.len();
    let mut boundary = vec![false; nv];
    let keys = sorted_facets(&map.simplices);
    let mut i = 0;
    while i < keys.len() {
        let mut j = i + 1;
        while j < keys.len() && keys[j].0 == keys[i].0 {
            j += 1;
        }
        if j - i == 1 {
            for &v in &keys[i].0[..N - 1] {
                boundary[v as usize] = true;
            }
        }
        i = j;
    }
    let mut by_pos: Vec<([u64; 3], u32)> = (0..nv)
        .filter(|&v| boundary[v])
        .map(|v| (position_key(&map.positions[v]), v as u32))
        .collect();
    by_pos.sort_unstable();
    let mut uf = UnionFind::new(nv);
    for w in by_pos.windows(2) {
        if w[0].0 == w[1].0 {
            uf.union(w[0].1, w[1].1);
        }
    }
    unmerge_conflicts(map, &mut uf);
    let mut rep = WeldReport::default();
    let rep_of: Vec<u32> = (0..nv as u32).map(|v| uf.find(v)).collect();
    rep.welded_vertices = (0..nv).filter(|&v| rep_of[v] != v as u32).count();
    // compaction: new ids in order of first use by a representative
    let mut used = vec![false; nv];
    for simplex in &map.simplices {
        for &v in simplex {
            used[rep_of[v as usize] as usize] = true;
        }
    }
    let mut new_id = vec![u32::MAX; nv];
    let mut out = SimplexMap::<N, D> {
        coords: map.coords.clone(),
        ..Default::default()
    };
    for v in 0..nv {
        if used[v] {
            new_id[v] = out.positions.len() as u32;
            out.positions.push(map.positions[v]);
        }
    }
    rep.dropped_vertices = nv - rep.welded_vertices - out.positions.len();
    out.simplices = map
        .simplices
        .iter()
        .map(|s| s.map(|v| new_id[rep_of[v as usize] as usize]))
        .collect();
    (out, rep)
}

/// Splits every merge class that would put two corners of one simplex on
/// the same vertex back into singletons.
fn unmerge_conflicts<const N: usize, const D: usize>(map: &SimplexMap<N, D>, uf: &mut UnionFind) {
    let nv = map.positions.len();
    let mut bad_root = vec![false; nv];
    for simplex in &map.simplices {
        let roots = simplex.map(|v| uf.find(v));
        for i in 0..N {
            if roots[..i].contains(&roots[i]) {
                bad_root[roots[i] as usize] = true;
            }
        }
    }
    if !bad_root.contains(&true) {
        return;
    }
    let roots: Vec<u32> = (0..nv as u32).map(|v| uf.find(v)).collect();
    let mut fresh = UnionFind::new(nv);
    for (v, &r) in roots.iter().enumerate() {
        if !bad_root[r as usize] {
            fresh.union(v as u32, r);
        }
    }
    *uf = fresh;
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::{Topology, TriMap};

    /// A unit square of 2×1 cells cut along x = 1: the middle column of
    /// vertices is duplicated (copies carry the other chart).
    fn cut_square() -> TriMap {
        let mut m = TriMap::default();
        for half in 0..2 {
            for j in 0..2 {
                for i in 0..2 {
                    m.positions.push([(half + i) as f64, j as f64, 0.0]);
                }
            }
        }
        for half in 0..2u32 {
            let o = 4 * half;
            m.simplices.push([o, o + 1, o + 3]);
            m.simplices.push([o, o + 3, o + 2]);
        }
        m.coords = m
            .simplices
            .iter()
            .map(|s| s.map(|v| [m.positions[v as usize][0], m.positions[v as usize][1]]))
            .collect();
        m.positions.push([9.0, 9.0, 9.0]); // unused
        m
    }

    #[test]
    fn welds_cut_square() {
        let m = cut_square();
        let before = Topology::build(&m).expect("cut");
        assert_eq!(before.boundary_facets, 8);
        assert_eq!(before.components(), 2);
        let (w, rep) = weld(&m);
        assert_eq!(rep.welded_vertices, 2);
        assert_eq!(rep.dropped_vertices, 1);
        assert_eq!(w.positions.len(), 6);
        assert_eq!(w.coords, m.coords);
        let t = Topology::build(&w).expect("welded");
        assert_eq!(t.boundary_facets, 6);
        assert_eq!(t.components(), 1);
        assert_eq!(t.boundary_loops(&w), 1);
    }

    #[test]
    fn leaves_conflicting_merge() {
        // a triangle whose two corners sit at one position stays as is
        let m = TriMap {
            positions: vec![[0.0; 3], [0.0; 3], [1.0, 0.0, 0.0]],
            simplices: vec![[0, 1, 2]],
            coords: vec![[[0.0; 2]; 3]],
        };
        let (w, rep) = weld(&m);
        assert_eq!(rep.welded_vertices, 0);
        assert_eq!(w.simplices, m.simplices);
    }
}
