//! Traced sides in both dimensions, on affine maps with and without
//! random charts: walks link sides in pairs, with inverse rotations, and
//! the charts do not change what the walks find.

use super::*;
use crate::testmap::{local_of, tet_grid, tri_grid};
use dualex_map::SimplexMap;

/// The walks of every side of `map`'s nodes.
fn walks<const N: usize, const D: usize>(map: &SimplexMap<N, D>) -> (Vec<End<D>>, TraceReport)
where
    Dim<N, D>: Simplex<N, D>,
{
    let (topo, _, local) = local_of(map);
    let nodes = Nodes::find(&local);
    trace_all(&local, &topo, &nodes)
}

/// Every walk reaching a side is that side's walk reversed.
fn assert_paired<const D: usize>(ends: &[End<D>], what: &str) {
    for (s, end) in ends.iter().enumerate() {
        let End::Node { side, rho } = end else {
            continue;
        };
        let back = &ends[*side as usize];
        let want = End::Node {
            side: s as u32,
            rho: rho.inverse(),
        };
        assert_eq!(back, &want, "{what}: side {s}");
    }
}

/// The walks of `make(None)` pair the sides, end on nodes and on the
/// boundary only, and random charts (`make(Some(seed))`) change neither.
fn assert_chart_free<const N: usize, const D: usize>(
    make: impl Fn(Option<u64>) -> SimplexMap<N, D>,
    what: &str,
) where
    Dim<N, D>: Simplex<N, D>,
{
    let (ends, plain) = walks(&make(None));
    assert_paired(&ends, what);
    assert!(
        plain.to_node > 0 && plain.to_boundary > 0,
        "{what}: {plain:?}"
    );
    assert_eq!(
        (plain.inconsistent, plain.loops),
        (0, 0),
        "{what}: {plain:?}"
    );
    for seed in [1, 2] {
        let (ends, rep) = walks(&make(Some(seed)));
        assert_paired(&ends, what);
        let counts = (rep.to_node, rep.to_boundary);
        assert_eq!(counts, (plain.to_node, plain.to_boundary), "{what} {seed}");
    }
}

#[test]
fn walks_pair_the_sides_whatever_the_charts() {
    assert_chart_free(|seed| tri_grid(7, seed), "triangles");
    assert_chart_free(|seed| tet_grid(3, seed), "tets");
}
