//! Step 3 at D = 3 ([`Dim<4, 3>`]): the tet edges and faces that vertices
//! which cannot move span across the dual grid — the 3D analogue of the
//! 2D split of edges between two singular vertices (`dim2.rs`).
//!
//! Input: the map, its local shifted coordinates (singular vertices
//! already on their fixed sets, [`crate::singular_snap`]), the vertex
//! stars, the free axes ([`crate::sanitize::free_axes`]) and the singular
//! edges. Output: the faces to split:
//! - every edge whose two ends are singular (they lie on singular edges:
//!   at most one free axis each) and which passes through an iso-line of
//!   the dual grid away from its ends, unless the edge is itself a
//!   singular edge (its midpoint would be as stuck as its ends) or one of
//!   its ends can move across that iso-line (its free axis is one of the
//!   two axes the iso-line is integral on: sanitization moves it);
//! - every triangle of three singular vertices, one of them at least where
//!   singular edges meet (it cannot move at all), that holds a node
//!   strictly inside, unless one of them can move off the triangle's plane
//!   (its free axis is not parallel to the plane).
//!
//! The new vertex of the split ([`super::split_faces_traced`]) is inside
//! the edge or face, so it is not singular and sanitization can move it
//! off the grid. The passes stop when nothing is left (each splits at most
//! one face per tet) or once as many faces are split as the input has
//! tets.

use super::{Dim, Pass, ToSplit};
use crate::grid::{dist2d, EPS};
use crate::local::LocalMap;
use crate::near::{grid_point_near_segment, triangle_near_grid_point, EDGES};
use crate::simplex::face_corners;
use dualex_map::singularity::{edge_singularities_with_stars, EdgeSingularity};
use dualex_map::{Stars, TetMap, Topology, Transitions};
use std::collections::HashSet;

/// The free axis of singular vertex `v` in the chart of tet `s` (`None`:
/// it cannot move, or `s` is not in its star).
fn free_axis_in(stars: &Stars<3>, free: &[Option<usize>], v: u32, s: usize) -> Option<usize> {
    let a = free[v as usize]?;
    let e = stars
        .of(v as usize)
        .iter()
        .find(|e| e.simplex as usize == s)?;
    Some(e.rot.apply_dir(2 * a) >> 1)
}

/// Whether segment `a`–`b` passes through an iso-line (integral on the two
/// axes `pair`) away from its ends, for some pair no end can move across.
fn crosses_stuck(a: &[f64; 3], b: &[f64; 3], axes: [Option<usize>; 2]) -> bool {
    [[0, 1], [0, 2], [1, 2]].into_iter().any(|[i, j]| {
        let (pa, pb) = ([a[i], a[j]], [b[i], b[j]]);
        let Some(g) = grid_point_near_segment(&pa, &pb) else {
            return false;
        };
        let near = |p: &[f64; 2]| dist2d(&g, p) < EPS;
        let movable = axes.iter().flatten().any(|&k| k == i || k == j);
        !near(&pa) && !near(&pb) && !movable
    })
}

impl ToSplit<4, 3> for Dim<4, 3> {
    type Singular = Vec<EdgeSingularity>;

    fn singular(
        map: &TetMap,
        topo: &Topology<4>,
        trans: &Transitions<4, 3>,
        stars: &Stars<3>,
    ) -> Vec<EdgeSingularity> {
        edge_singularities_with_stars(map, topo, trans, stars)
    }

    fn free_axes(
        topo: &Topology<4>,
        stars: &Stars<3>,
        local: &LocalMap<4, 3>,
    ) -> Vec<Option<usize>> {
        crate::sanitize::free_axes(topo, stars, local)
    }

    fn faces(pass: &Pass<'_, 4, 3>, singular: &Vec<EdgeSingularity>) -> Vec<Vec<u32>> {
        let pairs = singular
            .iter()
            .map(|e| (e.edge[0].min(e.edge[1]), e.edge[0].max(e.edge[1])))
            .collect();
        faces_to_split(pass, &pairs)
    }

    fn max_split(input: usize, _current: usize) -> usize {
        input
    }
}

/// The edges (2 vertex ids, sorted) and faces (3, sorted) to split, edges
/// first, each once, in the order of their first tet; `free` as
/// [`crate::sanitize::free_axes`], `singular_edges` the singular edges'
/// sorted vertex pairs. Blocks of tets are scanned in parallel
/// ([`tet_keys`]), then joined in tet order.
fn faces_to_split(pass: &Pass<'_, 4, 3>, singular_edges: &HashSet<(u32, u32)>) -> Vec<Vec<u32>> {
    faces_to_split_by(pass, singular_edges, 1 << 14)
}

/// [`faces_to_split`] with blocks of `block ≥ 1` tets (tests vary it).
fn faces_to_split_by(
    pass: &Pass<'_, 4, 3>,
    singular_edges: &HashSet<(u32, u32)>,
    block: usize,
) -> Vec<Vec<u32>> {
    use rayon::prelude::*;
    let blocks: Vec<Keys> = pass
        .map
        .simplices
        .par_chunks(block)
        .enumerate()
        .map(|(b, tets)| {
            let mut keys = Keys::default();
            for (i, tet) in tets.iter().enumerate() {
                tet_keys(pass, singular_edges, b * block + i, tet, &mut keys);
            }
            keys
        })
        .collect();
    let mut seen: HashSet<&[u32]> = HashSet::new();
    let (mut edges, mut faces) = (Vec::new(), Vec::new());
    for keys in &blocks {
        edges.extend(
            keys.edges
                .iter()
                .filter(|k| seen.insert(k.as_slice()))
                .cloned(),
        );
        faces.extend(
            keys.faces
                .iter()
                .filter(|k| seen.insert(k.as_slice()))
                .cloned(),
        );
    }
    edges.extend(faces);
    edges
}

/// The edges and faces to split that tets name, in their order (a key
/// may come again).
#[derive(Default)]
struct Keys {
    edges: Vec<Vec<u32>>,
    faces: Vec<Vec<u32>>,
}

/// Appends to `keys` the edges and faces of tet `s` to split
/// ([`faces_to_split`]).
fn tet_keys(
    pass: &Pass<'_, 4, 3>,
    singular_edges: &HashSet<(u32, u32)>,
    s: usize,
    tet: &[u32; 4],
    keys: &mut Keys,
) {
    let Pass {
        stars, local, free, ..
    } = *pass;
    let sing = |v: u32| stars.singular[v as usize];
    let singular_corners = tet.iter().filter(|&&v| sing(v)).count();
    if singular_corners < 2 {
        return;
    }
    let c = &local.coords[s];
    for [k, l] in EDGES {
        let (a, b) = (tet[k], tet[l]);
        if !(sing(a) && sing(b)) || singular_edges.contains(&(a.min(b), a.max(b))) {
            continue;
        }
        let axes = [a, b].map(|v| free_axis_in(stars, free, v, s));
        if crosses_stuck(&c[k], &c[l], axes) {
            keys.edges.push(vec![a.min(b), a.max(b)]);
        }
    }
    if singular_corners < 3 {
        return;
    }
    for f in 0..4 {
        let corners = face_corners(f);
        if !corners.iter().all(|&k| sing(tet[k])) {
            continue;
        }
        // (only faces with a vertex where singular edges meet: the
        // test is costly on large triangles, and a face spanned by
        // vertices inside singular edges alone can move with them)
        let axes = corners.map(|k| free_axis_in(stars, free, tet[k], s));
        if axes.iter().all(Option::is_some) {
            continue;
        }
        let t = corners.map(|k| c[k]);
        let n = normal(&t);
        let movable = axes.iter().flatten().any(|&a| n[a] != 0.0);
        if !movable && box_holds_grid_point(&t) && triangle_near_grid_point(&t) {
            let mut key: Vec<u32> = corners.iter().map(|&k| tet[k]).collect();
            key.sort_unstable();
            keys.faces.push(key);
        }
    }
}

/// Whether the box of `t`, grown by `EPS`, holds an integer on every axis
/// (else no grid point is near the triangle: a cheap prefilter).
fn box_holds_grid_point(t: &[[f64; 3]; 3]) -> bool {
    (0..3).all(|k| {
        let lo = t.iter().map(|p| p[k]).fold(f64::INFINITY, f64::min);
        let hi = t.iter().map(|p| p[k]).fold(f64::NEG_INFINITY, f64::max);
        (lo - EPS).ceil() <= hi + EPS
    })
}

/// A normal of triangle `t` (not normalized).
fn normal(t: &[[f64; 3]; 3]) -> [f64; 3] {
    let (u, v) = (
        std::array::from_fn::<f64, 3, _>(|k| t[1][k] - t[0][k]),
        std::array::from_fn::<f64, 3, _>(|k| t[2][k] - t[0][k]),
    );
    [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ]
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex_gen::from_mesh::{from_hexes, meshes, FromMeshOptions, TetSplit};

    /// What the driver's first pass finds on a map.
    fn to_split(map: &TetMap) -> Vec<Vec<u32>> {
        with_pass(map, Dim::<4, 3>::faces)
    }

    /// `f` of the driver's first pass on a map and its singular edges.
    fn with_pass<T>(
        map: &TetMap,
        f: impl FnOnce(&Pass<'_, 4, 3>, &Vec<EdgeSingularity>) -> T,
    ) -> T {
        let topo = Topology::build(map).unwrap_or_else(|e| panic!("{e}"));
        let (trans, _) =
            Transitions::derive(map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
        let stars = Stars::build(map, &topo, &trans);
        let singular = Dim::<4, 3>::singular(map, &topo, &trans, &stars);
        let mut local = LocalMap::new(map, &topo, &trans);
        crate::singular_snap::snap_singular(&mut local, &topo, &stars);
        let free = Dim::<4, 3>::free_axes(&topo, &stars, &local);
        let pass = Pass {
            map,
            topo: &topo,
            stars: &stars,
            local: &local,
            free: &free,
        };
        f(&pass, &singular)
    }

    /// The cubed ball's map at k = 1.
    fn cubed_ball_k1() -> TetMap {
        let o = FromMeshOptions {
            scale: 1,
            ..Default::default()
        };
        from_hexes(&meshes::cubed_ball(), &o)
            .unwrap_or_else(|e| panic!("{e:?}"))
            .map
    }

    /// Blocks of any size find the same keys in the same order as one
    /// block (the serial scan), on a map with keys in many tets: the cubed
    /// ball's diagonals (each in several tets) at k = 1.
    #[test]
    fn blocks_join_in_tet_order() {
        let map = cubed_ball_k1();
        with_pass(&map, |pass, singular| {
            let pairs = singular
                .iter()
                .map(|e| (e.edge[0].min(e.edge[1]), e.edge[0].max(e.edge[1])))
                .collect();
            let whole = faces_to_split_by(pass, &pairs, map.len());
            assert!(!whole.is_empty(), "nothing to compare");
            for block in [1, 2, 5, 64] {
                assert_eq!(
                    faces_to_split_by(pass, &pairs, block),
                    whole,
                    "block {block}"
                );
            }
        });
    }

    /// The cubed ball at k = 1: every hex's main diagonal joins two
    /// vertices that cannot move across the node at its centre (the inner
    /// cube's corners are fixed; the outer corners move only along their
    /// radial singular edge, parallel to the iso-line): 7 diagonals are
    /// split, and the split map has nothing left to split.
    #[test]
    fn cubed_ball_diagonals_through_nodes_are_split() {
        let map = cubed_ball_k1();
        let first = to_split(&map);
        assert!(first.iter().all(|f| f.len() == 2), "{first:?}");
        assert!(first.len() >= 7, "{first:?}");
        let mut m = map;
        for _ in 0..8 {
            let faces = to_split(&m);
            if faces.is_empty() {
                break;
            }
            let (next, applied) = super::super::split_faces(&m, &faces);
            assert!(applied > 0);
            m = next;
        }
        assert!(to_split(&m).is_empty());
        m.validate().unwrap_or_else(|e| panic!("{e}"));
    }

    /// A refined block with no singular vertex splits nothing; the cubed
    /// ball at k = 2 with the centre split (nodes are tet vertices, not on
    /// edges between fixed vertices) splits nothing either.
    #[test]
    fn nothing_to_split_without_stuck_crossings() {
        for (mesh, split) in [
            (meshes::polycube_l(), TetSplit::LeastVertex),
            (meshes::cubed_ball(), TetSplit::Centre),
        ] {
            let o = FromMeshOptions {
                scale: 2,
                tet_split: split,
                ..Default::default()
            };
            let map = from_hexes(&mesh, &o)
                .unwrap_or_else(|e| panic!("{e:?}"))
                .map;
            assert_eq!(to_split(&map), Vec::<Vec<u32>>::new(), "{split:?}");
        }
    }
}
