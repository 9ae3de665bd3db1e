//! The incremental bad-vertex scan of sanitization at D = 3
//! (`dualex_segment::sanitize::Scan`) on this crate's test blocks.

type LocalMap = dualex_segment::local::LocalMap<4, 3>;
use crate::rng::SplitMix;
use dualex_map::{Stars, Topology, Transitions};
use dualex_segment::near::bad_vertices;
use dualex_segment::sanitize::Scan as BadScan;

/// The incremental scan equals a full scan after arbitrary moves,
/// including moves onto isos, grid lines and grid points.
#[test]
fn incremental_scan_equals_full_scan() {
    use crate::testblock::{block, even, identity};
    // 0.2 + 0.7·4 = 3: a grid plane of vertices on isos
    let map = block(
        &[even(0.2, 3.7, 5), even(0.2, 3.7, 5), even(0.2, 3.7, 5)],
        identity,
    );
    let topo = Topology::build(&map).unwrap_or_else(|e| panic!("{e}"));
    let (trans, _) =
        Transitions::derive(&map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
    let stars = Stars::build(&map, &topo, &trans);
    let mut local = LocalMap::new(&map, &topo, &trans);
    let mut scan = BadScan::new(&map, &local.coords);
    assert_eq!(scan.list(), bad_vertices(&map, &local.coords));
    assert!(!scan.list().is_empty());
    let mut rng = SplitMix::new(5);
    let nv = map.positions.len();
    for round in 0..20 {
        let moved: Vec<u32> = (0..1 + round % 4)
            .map(|_| (rng.unit() * nv as f64) as u32 % nv as u32)
            .collect();
        for &v in &moved {
            let first = stars.of(v as usize)[0];
            let x = local.coords[first.simplex as usize][first.corner as usize];
            // alternately onto an integer coordinate, or a random step
            let d = if round % 2 == 0 {
                [x[0].round() - x[0], 0.0, 0.0]
            } else {
                rng.direction().map(|t| t * 0.4)
            };
            local.move_vertex(&stars, v as usize, &d);
        }
        scan.update(&map, &stars, &local.coords, &moved);
        let full = bad_vertices(&map, &local.coords);
        assert!(!full.is_empty() || round % 2 == 1);
        assert_eq!(scan.list(), full, "round {round}");
    }
}
