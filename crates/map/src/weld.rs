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

use crate::corners::{split, VertexCorners};
use crate::shared_key;
use crate::topology_build::sorted_facets;
use crate::SimplexMap;
use dualex_util::union_find::UnionFind;
use dualex_util::used::used_vertices;

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
    weld_pairs(map, &coincident_boundary_pairs(map))
}

/// [`weld`] taking the map: when there is nothing to merge or drop (no two
/// boundary vertices at one position, every vertex used — a closed or
/// uncut mesh), the map itself is returned, without building a copy.
pub fn weld_owned<const N: usize, const D: usize>(
    map: SimplexMap<N, D>,
) -> (SimplexMap<N, D>, WeldReport) {
    let pairs = coincident_boundary_pairs(&map);
    if pairs.is_empty() && used_vertices(map.positions.len(), &map.simplices) == map.positions.len()
    {
        return (map, WeldReport::default());
    }
    weld_pairs(&map, &pairs)
}

/// Pairs of boundary vertices at exactly the same position (consecutive
/// in position order). Whether any two vertices share a position is told
/// first, over all vertices, by a parallel hash set ([`shared_key`]): most
/// maps have none (an uncut mesh, or seams in the texture coordinates
/// only, as OBJ's `v/vt`). Only then are the groups found by a parallel
/// sort, and the boundary, a walk over the simplices.
fn coincident_boundary_pairs<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
) -> Vec<(u32, u32)> {
    use rayon::prelude::*;
    let nv = map.positions.len();
    let key = |v: usize| position_key(&map.positions[v]);
    if !shared_key::any_equal(nv, key, shared_key::hash3) {
        return Vec::new();
    }
    let mut by_pos: Vec<([u64; 3], u32)> = (0..nv)
        .into_par_iter()
        .map(|v| (key(v), v as u32))
        .collect();
    by_pos.par_sort_unstable();
    let shared: Vec<&[([u64; 3], u32)]> = by_pos
        .chunk_by(|a, b| a.0 == b.0)
        .filter(|g| g.len() > 1)
        .collect();
    let boundary = boundary_vertices(&map.simplices, nv);
    let mut pairs = Vec::new();
    for group in shared {
        let mut on = group.iter().filter(|x| boundary[x.1 as usize]);
        let Some(mut last) = on.next() else {
            continue;
        };
        for x in on {
            pairs.push((last.1, x.1));
            last = x;
        }
    }
    pairs
}

/// Merges the classes of `pairs` (see the module docs).
fn weld_pairs<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    pairs: &[(u32, u32)],
) -> (SimplexMap<N, D>, WeldReport) {
    let nv = map.positions.len();
    let mut uf = UnionFind::new(nv);
    for &(a, b) in pairs {
        uf.union(a as usize, b as usize);
    }
    unmerge_conflicts(map, &mut uf);
    let mut rep = WeldReport::default();
    let rep_of: Vec<u32> = (0..nv).map(|v| uf.find(v) as u32).collect();
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

/// Whether each vertex lies on a boundary facet (a facet of no other
/// simplex). Simplices without a repeated vertex: a facet is shared when
/// another simplex around its smallest vertex contains all its vertices
/// (in parallel over simplices); with a repeated vertex anywhere (not a
/// valid map, but `weld` takes any map), by sorting all facet keys.
fn boundary_vertices<const N: usize>(simplices: &[[u32; N]], nv: usize) -> Vec<bool> {
    use rayon::prelude::*;
    let mut boundary = vec![false; nv];
    let distinct = |t: &[u32; N]| (0..N).all(|i| !t[..i].contains(&t[i]));
    if !simplices.par_iter().all(distinct) {
        let keys = sorted_facets(simplices);
        for group in keys.chunk_by(|a, b| a.0 == b.0) {
            if let [(key, _)] = group {
                for &v in &key[..N - 1] {
                    boundary[v as usize] = true;
                }
            }
        }
        return boundary;
    }
    let lists = VertexCorners::build(simplices, nv, false);
    let open: Vec<[bool; N]> = simplices
        .par_iter()
        .enumerate()
        .with_min_len(4096)
        .map(|(s, simplex)| {
            std::array::from_fn(|f| {
                let facet: [u32; N] = std::array::from_fn(|i| simplex[(f + 1 + i) % N]);
                let facet = &facet[..N - 1];
                let Some(&v0) = facet.iter().min() else {
                    return false;
                };
                !lists.of(v0 as usize).iter().any(|&id| {
                    let t = split::<N>(id).0;
                    t != s && facet.iter().all(|v| simplices[t].contains(v))
                })
            })
        })
        .collect();
    for (simplex, open) in simplices.iter().zip(&open) {
        for f in (0..N).filter(|&f| open[f]) {
            for i in 1..N {
                boundary[simplex[(f + i) % N] as usize] = true;
            }
        }
    }
    boundary
}

/// Splits every merge class that would put two corners of one simplex on
/// the same vertex back into singletons.
fn unmerge_conflicts<const N: usize, const D: usize>(map: &SimplexMap<N, D>, uf: &mut UnionFind) {
    let nv = map.positions.len();
    let mut bad_root = vec![false; nv];
    for simplex in &map.simplices {
        let roots = simplex.map(|v| uf.find(v as usize));
        for i in 0..N {
            if roots[..i].contains(&roots[i]) {
                bad_root[roots[i]] = true;
            }
        }
    }
    if !bad_root.contains(&true) {
        return;
    }
    let roots: Vec<usize> = (0..nv).map(|v| uf.find(v)).collect();
    let mut fresh = UnionFind::new(nv);
    for (v, &r) in roots.iter().enumerate() {
        if !bad_root[r] {
            fresh.union(v, r);
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

    /// The sort-based reference: vertices of facet keys that occur once.
    fn boundary_by_sort<const N: usize>(simplices: &[[u32; N]], nv: usize) -> Vec<bool> {
        let mut b = vec![false; nv];
        for group in sorted_facets(simplices).chunk_by(|x, y| x.0 == y.0) {
            if group.len() == 1 {
                for &v in &group[0].0[..N - 1] {
                    b[v as usize] = true;
                }
            }
        }
        b
    }

    #[test]
    fn boundary_vertices_match_the_sort() {
        use crate::test_maps::{cone, edge_fan, grid, tet_cube};
        let mut cut = cut_square();
        let check = |m: &TriMap| {
            let nv = m.positions.len();
            assert_eq!(
                boundary_vertices(&m.simplices, nv),
                boundary_by_sort(&m.simplices, nv)
            );
        };
        check(&cut);
        check(&grid(5));
        check(&cone(5));
        // a non-manifold edge (three triangles) and a repeated vertex
        cut.simplices.push([0, 1, 8]);
        check(&cut);
        cut.simplices.push([2, 2, 3]);
        check(&cut);
        for m in [tet_cube(3), edge_fan(5)] {
            let nv = m.positions.len();
            assert_eq!(
                boundary_vertices(&m.simplices, nv),
                boundary_by_sort(&m.simplices, nv)
            );
        }
    }

    /// The pairs as first found: the boundary vertices sorted by position,
    /// consecutive equal ones paired.
    fn pairs_by_boundary_sort(m: &TriMap) -> Vec<(u32, u32)> {
        let boundary = boundary_vertices(&m.simplices, m.positions.len());
        let mut by_pos: Vec<([u64; 3], u32)> = (0..m.positions.len())
            .filter(|&v| boundary[v])
            .map(|v| (position_key(&m.positions[v]), v as u32))
            .collect();
        by_pos.sort_unstable();
        by_pos
            .windows(2)
            .filter(|w| w[0].0 == w[1].0)
            .map(|w| (w[0].1, w[1].1))
            .collect()
    }

    #[test]
    fn pairs_as_the_boundary_sort_finds_them() {
        use crate::test_maps::{cube_surface, grid};
        // an interior vertex at a boundary pair's position (not merged), a
        // third copy on the boundary, `-0.0` beside `0.0`, and none at all
        let mut m = cut_square();
        m.positions[0][0] = -0.0;
        m.positions.push([1.0, 0.0, 0.0]);
        let extra = m.positions.len() as u32 - 1;
        m.simplices.push([extra, 2, 6]);
        m.coords.push([[0.0; 2]; 3]);
        let mut inner = grid(4);
        let p = inner.positions[0];
        inner.positions[6] = p; // grid(4)'s vertex 6 is interior
        for m in [cut_square(), m, inner, grid(4), cube_surface(3)] {
            assert_eq!(coincident_boundary_pairs(&m), pairs_by_boundary_sort(&m));
        }
    }

    #[test]
    fn owned_weld_returns_the_map_when_nothing_merges() {
        use crate::test_maps::{cube_surface, grid};
        for m in [grid(4), cube_surface(3), cut_square()] {
            let (a, ra) = weld(&m);
            let (b, rb) = weld_owned(m.clone());
            assert_eq!((a, ra), (b, rb));
        }
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
