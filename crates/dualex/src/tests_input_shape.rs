//! The input's shape carried by an extraction (read off its first pass's
//! adjacency, `dualex_check::glued`) equals the one found afresh
//! ([`steps::input_shape`]) on every generated map, alone and two apart
//! (several components, boundaries), with unused vertices too.

use crate::steps::{self, Dimension, ExtractionOf};
use crate::Options;
use dualex_map::SimplexMap;

/// `a` and `b` as one map, `b`'s vertices after `a`'s and a stray
/// vertex between them (used by no simplex).
fn apart<const N: usize, const D: usize>(
    a: &SimplexMap<N, D>,
    b: &SimplexMap<N, D>,
) -> SimplexMap<N, D> {
    let mut m = a.clone();
    m.positions.push([1e3, 1e3, 1e3]);
    let offset = m.positions.len() as u32;
    m.positions
        .extend(b.positions.iter().map(|p| [p[0] + 100.0, p[1], p[2]]));
    m.simplices
        .extend(b.simplices.iter().map(|s| s.map(|v| v + offset)));
    m.coords.extend_from_slice(&b.coords);
    m
}

/// Whether `map` extracts; if so, asserts that the carried shape equals
/// the one found afresh (boundaries sorted); `name` names the map.
fn same_shape<const N: usize, const D: usize, const K: usize>(
    map: &SimplexMap<N, D>,
    name: &str,
    sorted: impl Fn(&mut <SimplexMap<N, D> as Dimension<K, D>>::Boundary),
) -> bool
where
    SimplexMap<N, D>: Dimension<K, D>,
    <SimplexMap<N, D> as Dimension<K, D>>::Boundary: PartialEq + std::fmt::Debug,
{
    let Ok(x): Result<ExtractionOf<SimplexMap<N, D>, K, D>, _> =
        steps::extract(map, &Options::default(), false)
    else {
        return false;
    };
    let mut carried = map.carried(&x).expect("carried");
    let mut fresh = steps::input_shape(map);
    sorted(&mut carried.boundary);
    sorted(&mut fresh.boundary);
    assert_eq!(carried, fresh, "{name}");
    true
}

/// [`same_shape`] on every map of `maps` alone and beside the map
/// `step` places on (`name + other`); more than half of each must
/// extract.
fn every_shape_the_same<const N: usize, const D: usize, const K: usize>(
    maps: &[(String, SimplexMap<N, D>)],
    step: usize,
    sorted: impl Fn(&mut <SimplexMap<N, D> as Dimension<K, D>>::Boundary) + Copy,
) where
    SimplexMap<N, D>: Dimension<K, D>,
    <SimplexMap<N, D> as Dimension<K, D>>::Boundary: PartialEq + std::fmt::Debug,
{
    let (mut extracted, mut pairs) = (0, 0);
    for (i, (name, map)) in maps.iter().enumerate() {
        extracted += usize::from(same_shape::<N, D, K>(map, name, sorted));
        let (other, b) = &maps[(i + step) % maps.len()];
        let both = apart(map, b);
        let two = same_shape::<N, D, K>(&both, &format!("{name} + {other}"), sorted);
        pairs += usize::from(two);
    }
    assert!(extracted > maps.len() / 2, "{extracted} of {}", maps.len());
    assert!(pairs > maps.len() / 2, "{pairs} of {}", maps.len());
}

#[test]
fn carried_surface_shapes_equal_the_fresh_ones() {
    let maps: Vec<_> = dualex_gen::registry::names()
        .iter()
        .filter_map(|n| dualex_gen::registry::by_name(n, 1).map(|(m, _)| (n.clone(), m)))
        .collect();
    every_shape_the_same::<3, 2, 4>(&maps, 3, |_| ());
}

#[test]
fn carried_tet_shapes_equal_the_fresh_ones() {
    let maps: Vec<_> = dualex_gen::registry::names_3d()
        .iter()
        .filter_map(|n| dualex_gen::registry::by_name_3d(n, 1).map(|(m, _)| (n.clone(), m)))
        .collect();
    every_shape_the_same::<4, 3, 8>(&maps, 1, |b| b.sort_unstable());
}
