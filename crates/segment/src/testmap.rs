//! Test maps of the generic steps: a grid of triangles or a cube of tets
//! with an affine map (no grid point on an edge or a face), optionally
//! recharted, and their local maps.

use crate::local::LocalMap;
use dualex_map::test_maps::{grid, rechart, tet_cube};
use dualex_map::{SimplexMap, Topology, Transitions};

/// The map `x ↦ A x + b` (`A` near the identity, skewed so that no grid
/// point lies on a mesh edge or face).
pub fn image<const D: usize>(p: &[f64; 3]) -> [f64; D] {
    std::array::from_fn(|k| {
        let mut y = 0.93 * p[k] + 0.0137 + 0.011 * k as f64;
        for (l, pl) in p.iter().enumerate().take(D) {
            if l != k {
                y += (0.071 + 0.013 * (k * D + l) as f64) * pl;
            }
        }
        y
    })
}

/// Every corner's coordinates by [`image`].
fn affine<const N: usize, const D: usize>(map: &mut SimplexMap<N, D>) {
    for (s, c) in map.simplices.iter().zip(map.coords.iter_mut()) {
        for (v, x) in s.iter().zip(c.iter_mut()) {
            *x = image(&map.positions[*v as usize]);
        }
    }
}

/// A `n × n` grid of triangles with an affine map, recharted by `seed`
/// when given.
pub fn tri_grid(n: u32, seed: Option<u64>) -> SimplexMap<3, 2> {
    let mut m = grid(n);
    affine(&mut m);
    if let Some(seed) = seed {
        rechart(&mut m, seed);
    }
    m
}

/// A cube of `6·n³` tets with an affine map, recharted by `seed` when
/// given.
pub fn tet_grid(n: u32, seed: Option<u64>) -> SimplexMap<4, 3> {
    let mut m = tet_cube(n);
    affine(&mut m);
    if let Some(seed) = seed {
        rechart(&mut m, seed);
    }
    m
}

/// The topology, transitions and local map of `map`.
pub fn local_of<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
) -> (Topology<N>, Transitions<N, D>, LocalMap<N, D>) {
    let topo = Topology::build(map).unwrap_or_else(|e| panic!("{e}"));
    let (trans, _) =
        Transitions::derive(map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
    let local = LocalMap::new(map, &topo, &trans);
    (topo, trans, local)
}
