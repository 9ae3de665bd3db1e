//! Gluing: regular grids, rotated charts, boundary and components.

use super::support::{assert_oriented, assert_same_partition, counts, grid_counts};
use crate::glue::{corner_across, corner_across_rotated, corner_across_unrotated, corners_on};
use crate::ids::Node;
use crate::testgrid::{random_rotations, rotate_charts, rotate_corner, GridSpec};
use crate::NodeGraph;
use dualex_map::Rot;

fn regular_grid<const D: usize>(n: [usize; D]) {
    let g = GridSpec::regular(n).build();
    g.check().unwrap();
    let gl = g.glue();
    let c = counts(&gl);
    let (v, e, f, unmatched) = grid_counts(n);
    assert_eq!(
        (c.v, c.e, c.f, c.cells),
        (v, e, f, n.iter().product()),
        "{n:?}"
    );
    assert_eq!(c.euler, 1, "{n:?}");
    assert_eq!(
        (gl.unmatched_sides, g.unmatched_sides()),
        (unmatched, unmatched)
    );
    assert_eq!(
        (gl.boundary_loops, gl.components, gl.corner_mismatches),
        (1, 1, 0)
    );
    // interior vertices have valence 2·D
    let interior: usize = n.iter().map(|k| k - 1).product();
    let full = if n.iter().all(|&k| k >= 2) {
        interior
    } else {
        0
    };
    assert_eq!(c.valence.get(&(2 * D)).copied().unwrap_or(0), full, "{n:?}");
}

#[test]
fn regular_grids_2d() {
    for n in [[1, 1], [1, 4], [3, 2], [5, 5]] {
        regular_grid::<2>(n);
        let gl = GridSpec::regular(n).build().glue();
        assert_oriented(&gl);
    }
    // 4×3: 4 corners of valence 2, 2·(3+2) boundary of valence 3, 6 interior
    let c = counts(&GridSpec::regular([4, 3]).build().glue());
    assert_eq!(
        c.valence.into_iter().collect::<Vec<_>>(),
        [(2, 4), (3, 10), (4, 6)]
    );
}

#[test]
fn regular_grids_3d() {
    for n in [[1, 1, 1], [2, 1, 3], [3, 3, 3], [4, 2, 2]] {
        regular_grid::<3>(n);
    }
}

#[test]
fn cell_order_is_ccw_and_vtk() {
    let gl = GridSpec::regular([1, 1]).build().glue();
    let (_, q) = gl.cells().next().unwrap();
    assert_eq!(q, [0, 1, 3, 2]); // vertex ids follow corner codes 0,1,2,3
    let gl = GridSpec::regular([1, 1, 1]).build().glue();
    let (_, h) = gl.cells().next().unwrap();
    assert_eq!(h, [0, 1, 3, 2, 4, 5, 7, 6]);
    let g = NodeGraph::<2>::new(vec![true]);
    assert_eq!(g.glue().cells().next().unwrap().1, [0, 2, 3, 1]);
    let g = NodeGraph::<3>::new(vec![true]);
    assert_eq!(g.glue().cells().next().unwrap().1, [4, 5, 7, 6, 0, 1, 3, 2]);
}

/// Every rotation, every side, every corner: the glued corner lies on t,
/// and gluing back returns the corner (the rule is symmetric).
fn corner_rule_symmetric<const D: usize>() {
    for rho in Rot::<D>::all() {
        for s in 0..2 * D {
            for t in [rho.apply_dir(s), rho.apply_dir(s) ^ 1] {
                for c in corners_on::<D>(s) {
                    let ct = corner_across(s, t, &rho, c).unwrap();
                    assert!(corners_on::<D>(t).any(|x| x == ct), "{rho:?} {s} {c}");
                    let back = corner_across(t, s, &rho.inverse(), ct);
                    assert_eq!(back, Some(c), "{rho:?} s={s} t={t} c={c}");
                }
            }
        }
    }
}

#[test]
fn corner_rule_is_symmetric() {
    corner_rule_symmetric::<2>();
    corner_rule_symmetric::<3>();
}

fn rotated_charts_same_mesh<const D: usize>(spec: GridSpec<D>, seed: u64) {
    let g = spec.build();
    let rots = random_rotations::<D>(g.n_nodes(), seed);
    let r = rotate_charts(&g, &rots);
    r.check().unwrap();
    let (a, b) = (g.glue(), r.glue());
    assert_same_partition(&a, &b, |n, c| (n, rotate_corner(&rots[n.idx()], c)));
    assert_eq!(
        (a.unmatched_sides, a.boundary_loops, a.components),
        (b.unmatched_sides, b.boundary_loops, b.components)
    );
    assert_eq!(counts(&a), counts(&b));
}

#[test]
fn rotated_charts_give_the_same_mesh() {
    for seed in 0..5 {
        rotated_charts_same_mesh(GridSpec::regular([4, 3]), seed);
        rotated_charts_same_mesh(GridSpec::regular([3, 2, 2]), seed);
        rotated_charts_same_mesh(GridSpec::regular([3, 3]).fold(1), seed);
        rotated_charts_same_mesh(GridSpec::regular([3, 2, 2]).fold(0), seed);
        let g = GridSpec::regular([4, 3]).build();
        let r = rotate_charts(&g, &random_rotations(g.n_nodes(), seed));
        assert_oriented(&r.glue());
    }
}

/// Glues the +u sides of the last layer to the -u sides of the first.
fn wrap_u<const D: usize>(spec: &GridSpec<D>, g: &mut NodeGraph<D>) {
    let last = spec.layers().len() - 1;
    for ci in 0..spec.cross() {
        let a = Node((last * spec.cross() + ci) as u32);
        let b = Node(ci as u32);
        g.link(g.side(a, 0), g.side(b, 1), Rot::IDENTITY).unwrap();
    }
}

#[test]
fn cylinder_torus_and_hole() {
    // cylinder: 2 boundary loops, Euler 0
    let spec = GridSpec::regular([4, 3]);
    let mut g = spec.build();
    wrap_u(&spec, &mut g);
    g.check().unwrap();
    let gl = g.glue();
    assert_eq!(
        (gl.boundary_loops, gl.unmatched_sides, counts(&gl).euler),
        (2, 8, 0)
    );
    assert_oriented(&gl);
    // torus: wrap v too
    for x in 0..4u32 {
        let (a, b) = (Node(3 * x + 2), Node(3 * x));
        g.link(g.side(a, 2), g.side(b, 3), Rot::IDENTITY).unwrap();
    }
    let gl = g.glue();
    let c = counts(&gl);
    assert_eq!((gl.boundary_loops, gl.unmatched_sides, c.euler), (0, 0, 0));
    assert_eq!(c.valence.into_iter().collect::<Vec<_>>(), [(4, 12)]);
    // hole: delete the centre of a 3×3 grid
    let mut g = GridSpec::regular([3, 3]).build();
    for d in 0..4 {
        g.unlink(g.side(Node(4), d)).unwrap();
    }
    g.alive[4] = false;
    g.check().unwrap();
    let gl = g.glue();
    assert_eq!(
        (gl.boundary_loops, gl.components, counts(&gl).euler),
        (2, 1, 0)
    );
    // two unglued halves: 2 components, 2 loops
    let g = NodeGraph::<2>::new(vec![false; 2]);
    assert_eq!((g.glue().components, g.glue().boundary_loops), (2, 2));
}

#[test]
fn solid_torus_3d() {
    let spec = GridSpec::regular([4, 2, 2]);
    let mut g = spec.build();
    wrap_u(&spec, &mut g);
    g.check().unwrap();
    let gl = g.glue();
    let c = counts(&gl);
    assert_eq!((gl.boundary_loops, gl.components, c.euler), (1, 1, 0));
    assert_eq!(gl.unmatched_sides, 4 * 2 * 4);
}

#[test]
fn boundary_is_counted_on_the_graph_not_the_mesh() {
    // a ring of 2 quads: both top edges join the same two vertices, so the
    // mesh alone sees them as one interior edge (Euler 2, "closed"); the
    // graph still has 4 unmatched sides forming 2 loops
    let spec = GridSpec::regular([2, 1]);
    let mut g = spec.build();
    wrap_u(&spec, &mut g);
    let gl = g.glue();
    let c = counts(&gl);
    assert_eq!((gl.n_vertices, c.e, c.euler), (4, 4, 2));
    assert_eq!((gl.unmatched_sides, gl.boundary_loops), (4, 2));
}

/// The identity's shortcut of `corner_across` answers as the rule axis by
/// axis does, for every pair of directions and every corner on `s`'s
/// side, in both dimensions.
fn unrotated_corners_follow_the_rule<const D: usize>() {
    for s_dir in 0..2 * D {
        for t_dir in 0..2 * D {
            for code in corners_on::<D>(s_dir) {
                assert_eq!(
                    corner_across_unrotated::<D>(s_dir, t_dir, code),
                    corner_across_rotated(s_dir, t_dir, &Rot::<D>::IDENTITY, code),
                    "D = {D}, {s_dir} -> {t_dir}, corner {code}"
                );
            }
        }
    }
}

#[test]
fn unrotated_corners_follow_the_rule_2d_3d() {
    unrotated_corners_follow_the_rule::<2>();
    unrotated_corners_follow_the_rule::<3>();
}
