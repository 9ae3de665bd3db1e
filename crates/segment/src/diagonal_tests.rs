//! Diagonal walks in both dimensions, on affine maps with and without
//! random charts: inside the mesh every walk reaches its target exactly,
//! a point the map sends to an integer point.

use super::*;
use crate::testmap::{image, local_of, tet_grid, tri_grid};

/// Every diagonal of every node: (exact walks, all walks); asserts that
/// exact candidates map onto integer points and the others are closer
/// than the start.
fn walk_all<const N: usize, const D: usize>(map: &SimplexMap<N, D>) -> (usize, usize)
where
    Dim<N, D>: Simplex<N, D> + DiagonalStep<N, D>,
{
    let (topo, _, local) = local_of(map);
    let nodes = Nodes::find(&local);
    let (mut exact, mut all) = (0, 0);
    for n in 0..nodes.len() {
        for code in 0..1usize << D {
            let sgn = std::array::from_fn(|a| if code >> a & 1 == 1 { 1.0 } else { -1.0 });
            let c = diagonal(map, &local, &topo, &nodes, n, sgn);
            all += 1;
            if c.dist == 0.0 {
                exact += 1;
                let x: [f64; D] = image(&c.pos);
                assert!(
                    x.iter().all(|v| (v - v.round()).abs() < 1e-9),
                    "node {n} code {code}: {c:?} maps to {x:?}"
                );
            } else {
                assert!(c.dist < Dim::<N, D>::half_diagonal(), "{c:?}");
            }
        }
    }
    (exact, all)
}

#[test]
fn inside_the_mesh_the_walks_reach_integer_points() {
    let (exact, all) = walk_all(&tri_grid(7, None));
    assert!(exact > all / 2 && exact < all, "{exact} of {all}");
    for seed in [1, 2] {
        assert_eq!(walk_all(&tri_grid(7, Some(seed))), (exact, all));
    }
    let (exact, all) = walk_all(&tet_grid(3, None));
    assert!(exact > all / 4 && exact < all, "{exact} of {all}");
    for seed in [1, 2] {
        assert_eq!(walk_all(&tet_grid(3, Some(seed))), (exact, all));
    }
}
