//! Singularities and simplex quality.
//!
//! Input: a validated map, its topology and transitions. Output:
//! - 2D: [`vertex_singularities`], interior vertices whose ring rotation is
//!   not the identity, or whose index from the angle sum is non-zero on a
//!   fold-free ring. The ring rotation `k` (counter-clockwise quarter turns,
//!   walk of [`crate::holonomy`]) gives the index modulo 1: `index ≡ k/4`
//!   (cube corner: `k = 1`, index 1/4, quad valence `4 − 4·index = 3`). The
//!   integer part comes from the signed angle sum,
//!   `index = (2π − Σ angles) / 2π` rounded to quarters, **only** when the
//!   one-ring has no reverted or degenerate triangle and agrees with `k`;
//!   otherwise the index is unknown (`index_quarters == None`) and the vertex
//!   is reported only if `k ≠ 0`.
//! - 3D: [`edge_singularities`], interior edges whose rotation around them
//!   is not the identity, labelled by [`EdgeAngle`]: `+90°` is the analogue
//!   of index +1/4 (three right-angled tets around the edge).
//! - [`quality`]: reverted (`det < 0`) and degenerate simplices.
//!
//! Degenerate: `|det| ≤ max(1e-12·L^D, 8·ulp(c)·L^(D−1))`, with `L` the
//! longest map edge of the simplex and `c` its largest |coordinate| (the
//! second term is the float noise of the edge vectors of far-off maps).

use crate::corners::{split, VertexCorners};
use crate::holonomy::ridge_rotation;
use crate::mesh::{degenerate_with, det_of, longest_edge};
use crate::{Rot3, SimplexMap, TetMap, Topology, Transitions, TriMap};
use rayon::prelude::*;

/// A singular interior vertex of a triangle mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct VertexSingularity {
    /// The vertex.
    pub vertex: u32,
    /// Ring rotation in counter-clockwise quarter turns, in `0..4`.
    pub turns: i64,
    /// The index in quarters (`index = q/4`), when the ring is fold-free.
    pub index_quarters: Option<i64>,
}

/// Rotation angle around a singular edge, signed about the edge direction.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub enum EdgeAngle {
    /// +90° (like index +1/4, valence 3).
    Plus90,
    /// −90° (like index −1/4, valence 5).
    Minus90,
    /// 180°.
    Half,
    /// A 90° rotation whose axis is not along the edge in the map.
    OffAxis90,
    /// A 120° rotation (about a cube diagonal: not an edge rotation).
    Third,
}

impl EdgeAngle {
    /// Label used in reports.
    pub fn label(&self) -> &'static str {
        match self {
            EdgeAngle::Plus90 => "90",
            EdgeAngle::Minus90 => "-90",
            EdgeAngle::Half => "180",
            EdgeAngle::OffAxis90 => "90_off_axis",
            EdgeAngle::Third => "120",
        }
    }
}

/// A singular interior edge of a tet mesh.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct EdgeSingularity {
    /// The edge's vertices, in the walk's direction.
    pub edge: [u32; 2],
    /// Rotation around the edge, in the chart of its first tet.
    pub rot: Rot3,
    /// Its angle class.
    pub angle: EdgeAngle,
}

/// Whether simplex `p` is degenerate (see the module docs).
pub fn is_degenerate<const N: usize, const D: usize>(p: &[[f64; D]; N]) -> bool {
    degenerate_with(p, det_of::<N, D>(p), longest_edge(p))
}

/// `(reverted, degenerate)` simplex counts: `det < 0`, and [`is_degenerate`].
pub fn quality<const N: usize, const D: usize>(map: &SimplexMap<N, D>) -> (usize, usize) {
    let reverted = (0..map.len())
        .into_par_iter()
        .filter(|&s| map.map_det(s) < 0.0)
        .count();
    let degenerate = map.coords.par_iter().filter(|p| is_degenerate(p)).count();
    (reverted, degenerate)
}

/// Singular interior vertices of a triangle mesh (see the module docs).
pub fn vertex_singularities(
    map: &TriMap,
    topo: &Topology<3>,
    trans: &Transitions<3, 2>,
) -> Vec<VertexSingularity> {
    let lists = VertexCorners::build(&map.simplices, map.positions.len(), false);
    vertex_singularities_with(map, topo, trans, &lists)
}

/// [`vertex_singularities`] with the map's corner lists `lists` (built
/// with or without their positions: the same lists), for a caller that
/// holds them already (the extraction's model).
pub fn vertex_singularities_with(
    map: &TriMap,
    topo: &Topology<3>,
    trans: &Transitions<3, 2>,
    lists: &VertexCorners,
) -> Vec<VertexSingularity> {
    let fold_free = fold_free_bits(map);
    // per vertex in parallel, collected in vertex order
    (0..map.positions.len())
        .into_par_iter()
        .filter_map(|v| vertex_singularity(map, topo, trans, &fold_free, v as u32, lists.of(v)))
        .collect()
}

/// Per triangle, bit `s % 64` of word `s / 64`: whether its image is
/// neither reverted nor degenerate (`det > 0`, not [`is_degenerate`]),
/// found once per triangle rather than once per corner.
fn fold_free_bits(map: &TriMap) -> Vec<u64> {
    map.coords
        .par_chunks(64)
        .map(|chunk| {
            chunk.iter().enumerate().fold(0u64, |w, (i, p)| {
                w | u64::from(det_of::<3, 2>(p) > 0.0 && !is_degenerate(p)) << i
            })
        })
        .collect()
}

/// Vertex `v`'s singularity (module docs) from its corners `ring` and the
/// triangles' [`fold_free_bits`]; `None` for a boundary, unused or
/// regular vertex.
fn vertex_singularity(
    map: &TriMap,
    topo: &Topology<3>,
    trans: &Transitions<3, 2>,
    fold_free: &[u64],
    v: u32,
    ring: &[u32],
) -> Option<VertexSingularity> {
    let (s0, c0) = split::<3>(*ring.first()?);
    // `None`: a boundary vertex
    let rot = ridge_rotation(topo, trans, s0, &[c0])?;
    let turns = rot.turns();
    let fold_free = ring.iter().all(|&id| {
        let s = split::<3>(id).0;
        fold_free[s / 64] >> (s % 64) & 1 == 1
    });
    // the angle sum only where it is read (a fold-free ring)
    let q = if fold_free {
        crate::angle_sum::quarters(ring.iter().map(|&id| {
            let (s, c) = split::<3>(id);
            (&map.coords[s], c)
        }))
    } else {
        0
    };
    let index_quarters = (fold_free && q.rem_euclid(4) == turns).then_some(q);
    (turns != 0 || index_quarters.is_some_and(|q| q != 0)).then_some(VertexSingularity {
        vertex: v,
        turns,
        index_quarters,
    })
}

/// Angle class of a rotation `r` around an edge with map direction `dir`.
pub fn edge_angle(r: &Rot3, dir: &[f64; 3]) -> Option<EdgeAngle> {
    let img = r.images();
    let mut trace = 0;
    let mut axis = None;
    for (i, &d) in img.iter().enumerate() {
        if (d >> 1) as usize == i {
            trace += if d & 1 == 0 { 1 } else { -1 };
            if d & 1 == 0 {
                axis = Some(i);
            }
        }
    }
    match (trace, axis) {
        (3, _) => None,
        (-1, _) => Some(EdgeAngle::Half),
        (1, Some(a)) => {
            // +90° about +a maps e_{a+1} to e_{a+2}
            let positive = img[(a + 1) % 3] == (2 * ((a + 2) % 3)) as u8;
            let along: f64 = dir[a];
            let off: f64 = (0..3)
                .filter(|&k| k != a)
                .map(|k| dir[k].abs())
                .fold(0.0, f64::max);
            if along == 0.0 || off > along.abs() {
                Some(EdgeAngle::OffAxis90)
            } else if positive == (along > 0.0) {
                Some(EdgeAngle::Plus90)
            } else {
                Some(EdgeAngle::Minus90)
            }
        }
        _ => Some(EdgeAngle::Third),
    }
}

/// Every edge of a tet mesh once, ordered by its sorted vertex pair, as
/// `(s, i, j)`: the first tet `s` holding it and its corners `i < j` there.
/// Found around each vertex (through its corners, in tet order) among the
/// edges to larger vertices: no global sort.
fn first_tet_of_edges(map: &TetMap) -> Vec<(u32, u8, u8)> {
    let lists = VertexCorners::build(&map.simplices, map.positions.len(), false);
    let mut out = Vec::with_capacity(map.len() * 2);
    let mut around: Vec<(u32, u32, u8, u8)> = Vec::new();
    // seen[b] == a: edge (a, b) already has its first tet
    let mut seen = vec![u32::MAX; map.positions.len()];
    for a in 0..map.positions.len() {
        around.clear();
        for &id in lists.of(a) {
            let (s, c) = split::<4>(id);
            let (s, c) = (s as u32, c as u8);
            let t = &map.simplices[s as usize];
            for (d, &b) in t.iter().enumerate() {
                if b as usize > a && seen[b as usize] != a as u32 {
                    seen[b as usize] = a as u32;
                    let (i, j) = (c.min(d as u8), c.max(d as u8));
                    around.push((b, s, i, j));
                }
            }
        }
        around.sort_unstable_by_key(|e| e.0);
        out.extend(around.iter().map(|&(_, s, i, j)| (s, i, j)));
    }
    out
}

/// Singular interior edges of a tet mesh (see the module docs).
pub fn edge_singularities(
    map: &TetMap,
    topo: &Topology<4>,
    trans: &Transitions<4, 3>,
) -> Vec<EdgeSingularity> {
    edges_walked(map, topo, trans, None)
}

/// [`edge_singularities`], given the vertex stars: only the edges whose
/// two ends are singular vertices are walked (none when no vertex is).
/// Same result: the loop of tets around an edge lies in the star of each
/// end, and a star whose rotations agree across every facet of it (a
/// non-singular vertex) has identity holonomy around every loop in it.
pub fn edge_singularities_with_stars(
    map: &TetMap,
    topo: &Topology<4>,
    trans: &Transitions<4, 3>,
    stars: &crate::Stars<3>,
) -> Vec<EdgeSingularity> {
    if !stars.singular.contains(&true) {
        return Vec::new();
    }
    edges_walked(map, topo, trans, Some(&stars.singular))
}

/// The walks around the edges (those between two singular vertices when
/// `singular` is given) in parallel, collected in edge order.
fn edges_walked(
    map: &TetMap,
    topo: &Topology<4>,
    trans: &Transitions<4, 3>,
    singular: Option<&[bool]>,
) -> Vec<EdgeSingularity> {
    first_tet_of_edges(map)
        .into_par_iter()
        .filter(|&(s, i, j)| {
            singular.is_none_or(|sing| {
                let t = &map.simplices[s as usize];
                sing[t[i as usize] as usize] && sing[t[j as usize] as usize]
            })
        })
        .filter_map(|(s, i, j)| {
            let (s, i, j) = (s as usize, i as usize, j as usize);
            let rot = ridge_rotation(topo, trans, s, &[i, j])?;
            let p = &map.coords[s];
            let dir: [f64; 3] = std::array::from_fn(|k| p[j][k] - p[i][k]);
            let t = &map.simplices[s];
            edge_angle(&rot, &dir).map(|angle| EdgeSingularity {
                edge: [t[i], t[j]],
                rot,
                angle,
            })
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_maps::{cone, cube_surface, edge_fan, flat_torus, grid, rechart};
    use crate::{Stars, TransitionOptions};

    fn derive<const N: usize, const D: usize>(
        m: &SimplexMap<N, D>,
    ) -> (Topology<N>, Transitions<N, D>) {
        let topo = Topology::build(m).expect("topology");
        let (tr, _) = Transitions::derive(m, &topo, &TransitionOptions::default()).expect("derive");
        (topo, tr)
    }

    fn sing(m: &TriMap) -> Vec<VertexSingularity> {
        let (topo, tr) = derive(m);
        vertex_singularities(m, &topo, &tr)
    }

    #[test]
    fn cones_have_known_index() {
        // k right angles around the centre: index (4 − k)/4, turns ≡ 4 − k
        for k in [2u32, 3, 5, 6, 7] {
            let mut s = sing(&cone(k));
            if k == 2 {
                // two triangles closing into a sphere: Gauss–Bonnet, Σ = 2
                let total: i64 = s.iter().filter_map(|v| v.index_quarters).sum();
                assert_eq!(total, 8);
            }
            s.retain(|v| v.vertex == 0);
            let q = 4 - k as i64;
            assert_eq!(
                s,
                vec![VertexSingularity {
                    vertex: 0,
                    turns: q.rem_euclid(4),
                    index_quarters: Some(q)
                }],
                "cone of {k} right angles"
            );
        }
        assert!(sing(&cone(4)).is_empty());
        // 8 right angles: rotation identity but index −1 (a saddle)
        let s = sing(&cone(8));
        assert_eq!(s.len(), 1);
        assert_eq!((s[0].turns, s[0].index_quarters), (0, Some(-4)));
    }

    #[test]
    fn folded_cone_has_unknown_integer_part() {
        let mut m = cone(3);
        // fold triangle 1 over: its centre angle becomes −90°; angle sum
        // 90°, rotation −90° + 90° − 90° ≡ 3 quarter turns
        m.coords[1] = [[0.0, 0.0], [1.0, 0.0], [0.0, -1.0]];
        let s = sing(&m);
        assert_eq!(s.len(), 1);
        assert_eq!((s[0].turns, s[0].index_quarters), (3, None));
        let (reverted, degenerate) = quality(&m);
        assert_eq!((reverted, degenerate), (1, 0));
    }

    #[test]
    fn cube_has_eight_quarter_cones() {
        let m = cube_surface(2);
        let (topo, tr) = derive(&m);
        assert_eq!(topo.boundary_facets, 0);
        let s = vertex_singularities(&m, &topo, &tr);
        assert_eq!(s.len(), 8);
        for v in &s {
            assert_eq!((v.turns, v.index_quarters), (1, Some(1)));
            let p = m.positions[v.vertex as usize];
            assert!(p.iter().all(|&x| x == 0.0 || x == 2.0), "corner {p:?}");
        }
        let stars = Stars::build(&m, &topo, &tr);
        assert_eq!(stars.singular.iter().filter(|&&x| x).count(), 8);
        assert!(stars.boundary.iter().all(|&b| !b));
        // the same after re-charting every triangle
        let mut m2 = m.clone();
        rechart(&mut m2, 5);
        assert_eq!(sing(&m2), s);
    }

    #[test]
    fn torus_and_grid_have_none() {
        let t = flat_torus(4);
        let (topo, tr) = derive(&t);
        assert_eq!((topo.boundary_facets, topo.components()), (0, 1));
        assert!(vertex_singularities(&t, &topo, &tr).is_empty());
        assert!(sing(&grid(3)).is_empty());
    }

    /// The corner lists handed in (the model's, built with positions)
    /// give what the function's own build gives.
    #[test]
    fn the_models_corner_lists_give_the_same_singularities() {
        let mut singular = 0;
        for mut m in [cube_surface(3), cone(7), cone(2), grid(6)] {
            rechart(&mut m, 3);
            let (topo, tr) = derive(&m);
            let lists = VertexCorners::build(&m.simplices, m.positions.len(), true);
            let got = vertex_singularities_with(&m, &topo, &tr, &lists);
            assert_eq!(got, vertex_singularities(&m, &topo, &tr));
            singular += got.len();
        }
        assert!(singular > 0);
    }

    #[test]
    fn edges_between_singular_vertices_are_all_the_singular_edges() {
        for m in [
            edge_fan(3),
            edge_fan(5),
            edge_fan(6),
            crate::test_maps::tet_cube(3),
        ] {
            let (topo, tr) = derive(&m);
            let stars = Stars::build(&m, &topo, &tr);
            assert_eq!(
                edge_singularities_with_stars(&m, &topo, &tr, &stars),
                edge_singularities(&m, &topo, &tr)
            );
        }
    }

    #[test]
    fn singular_edges_by_angle() {
        let labels = |k: u32| -> Vec<EdgeAngle> {
            let m = edge_fan(k);
            let (topo, tr) = derive(&m);
            edge_singularities(&m, &topo, &tr)
                .iter()
                .map(|e| e.angle)
                .collect()
        };
        assert_eq!(labels(3), vec![EdgeAngle::Plus90]);
        assert_eq!(labels(4), vec![]);
        assert_eq!(labels(5), vec![EdgeAngle::Minus90]);
        assert_eq!(labels(6), vec![EdgeAngle::Half]);
        let m = edge_fan(3);
        let (topo, tr) = derive(&m);
        let e = edge_singularities(&m, &topo, &tr);
        assert_eq!(e[0].edge, [0, 1]);
        let stars = Stars::build(&m, &topo, &tr);
        assert_eq!(stars.singular, vec![true, true, false, false, false]);
    }

    #[test]
    fn edges_in_sorted_order_with_their_first_tet() {
        let mut m = crate::test_maps::tet_cube(3);
        // shuffle vertex ids so that corner order and vertex order differ
        let nv = m.positions.len() as u32;
        for t in m.simplices.iter_mut() {
            for v in t.iter_mut() {
                *v = (*v * 7 + 3) % nv;
            }
        }
        let mut want: Vec<([u32; 2], u32, u8, u8)> = Vec::new();
        for (s, t) in m.simplices.iter().enumerate() {
            for i in 0..4u8 {
                for j in i + 1..4u8 {
                    let (a, b) = (t[i as usize], t[j as usize]);
                    want.push(([a.min(b), a.max(b)], s as u32, i, j));
                }
            }
        }
        want.sort_unstable();
        want.dedup_by_key(|e| e.0);
        let want: Vec<(u32, u8, u8)> = want.iter().map(|e| (e.1, e.2, e.3)).collect();
        assert_eq!(first_tet_of_edges(&m), want);
    }

    #[test]
    fn degenerate_scales_with_coordinates() {
        let flat = [[0.0, 0.0], [1.0, 0.0], [2.0, 0.0]];
        assert!(is_degenerate::<3, 2>(&flat));
        assert!(is_degenerate::<3, 2>(&[[3.0, 3.0]; 3]));
        let ok = [[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]];
        assert!(!is_degenerate::<3, 2>(&ok));
        let big = (1u64 << 40) as f64;
        let far = ok.map(|p| [p[0] + big, p[1] + big]);
        assert!(!is_degenerate::<3, 2>(&far));
    }
}
