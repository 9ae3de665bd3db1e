//! [`relax`] on the test grids of both dimensions: one interior vertex
//! pushed through its neighbours (its star folds), relaxed back.

use super::*;
use crate::testmap::{local_of, tet_grid, tri_grid};
use dualex_map::Stars;

/// Pushes the vertex at `centre` by `push`, relaxes, and checks: the
/// fold is undone, vertices outside the region keep their corners, and a
/// second relaxation finds nothing to do.
fn unfolds<const N: usize, const D: usize>(map: &SimplexMap<N, D>, push: [f64; D]) {
    let (topo, trans, mut local) = local_of(map);
    let stars = Stars::build(map, &topo, &trans);
    let n = map.positions.len();
    let mid = map.positions.iter().map(|p| p[0]).fold(0.0, f64::max) / 2.0;
    let centre = (0..n)
        .find(|&v| map.positions[v][..D].iter().all(|&x| x == mid))
        .unwrap_or_else(|| panic!("no vertex at the centre"));
    let untouched = local.clone();
    local.move_vertex(&stars, centre, &push);
    let rep = relax(map, &stars, &vec![None; n], &mut local);
    assert!(rep.reverted_before > 0, "{rep:?}");
    assert_eq!(rep.reverted_after, 0, "{rep:?}");
    assert!(rep.rounds > 0 && rep.vertices > 0, "{rep:?}");
    assert!((0..local.coords.len()).all(|s| local.det(s) > 0.0));
    // far from the centre (beyond the region's rings) nothing moved
    let far = |s: usize| {
        map.simplices[s].iter().all(|&v| {
            map.positions[v as usize][..D]
                .iter()
                .any(|&x| (x - mid).abs() > 3.5)
        })
    };
    for s in (0..local.coords.len()).filter(|&s| far(s)) {
        assert_eq!(local.coords[s], untouched.coords[s], "simplex {s}");
    }
    let again = relax(map, &stars, &vec![None; n], &mut local);
    assert_eq!(
        (again.rounds, again.vertices, again.reverted_before),
        (0, 0, 0)
    );
}

#[test]
fn a_vertex_pushed_through_its_neighbours_comes_back_2d() {
    unfolds(&tri_grid(12, Some(3)), [2.6, 0.4]);
}

#[test]
fn a_vertex_pushed_through_its_neighbours_comes_back_3d() {
    unfolds(&tet_grid(8, Some(5)), [2.2, 0.3, -0.5]);
}

/// A map without a reverted simplex is left bit for bit.
#[test]
fn an_unfolded_map_is_untouched() {
    let map = tri_grid(6, None);
    let (topo, trans, mut local) = local_of(&map);
    let stars = Stars::build(&map, &topo, &trans);
    let before = local.clone();
    let rep = relax(&map, &stars, &[], &mut local);
    assert_eq!(rep, RelaxReport::default());
    assert_eq!(local.coords, before.coords);
}
