use super::*;
use dualex_map::test_maps::{cone, cube_surface, edge_fan, rechart, Lcg};
use dualex_map::{SimplexMap, Transitions};

/// Global shifted coordinates (local + offset) of every corner of `v`.
fn global_corners<const N: usize, const D: usize>(
    local: &LocalMap<N, D>,
    stars: &Stars<D>,
    v: usize,
) -> Vec<[f64; D]> {
    stars
        .of(v)
        .iter()
        .map(|e| {
            let s = e.simplex as usize;
            let x = local.coords[s][e.corner as usize];
            std::array::from_fn(|k| x[k] + local.offset[s][k] as f64)
        })
        .collect()
}

/// Builds the local map of `map` and its stars.
fn local_of<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
) -> (Topology<N>, Stars<D>, LocalMap<N, D>) {
    let topo = Topology::build(map).unwrap_or_else(|e| panic!("{e}"));
    let (trans, _) =
        Transitions::derive(map, &topo, &Default::default()).unwrap_or_else(|e| panic!("{e}"));
    let stars = Stars::build(map, &topo, &trans);
    let local = LocalMap::new(map, &topo, &trans);
    (topo, stars, local)
}

/// Adds independent noise of half-width `amp` to every corner coordinate
/// of the vertices `which`.
fn jitter<const N: usize, const D: usize>(
    map: &mut SimplexMap<N, D>,
    which: &[bool],
    amp: f64,
    seed: u64,
) {
    let mut rng = Lcg(seed);
    for (s, c) in map.simplices.iter().zip(map.coords.iter_mut()) {
        for k in 0..N {
            if which[s[k] as usize] {
                for x in c[k].iter_mut() {
                    *x += (rng.below(2_000_001) as f64 / 1e6 - 1.0) * amp;
                }
            }
        }
    }
}

/// Jittered singular corners of a recharted cube surface come back bit for
/// bit to the exact map's (the fixed points of 90° holonomies).
#[test]
fn jittered_cube_corners_snap_to_the_exact_fixed_points() {
    for (n, seed) in [(1, 3), (2, 5), (3, 7)] {
        let mut clean = cube_surface(n);
        rechart(&mut clean, seed);
        let (_, stars0, local0) = local_of(&clean);
        let singular = stars0.singular.clone();
        assert_eq!(singular.iter().filter(|&&s| s).count(), 8);
        for amp in [1e-12, 1e-9, 1e-7, 1e-4] {
            let mut map = clean.clone();
            jitter(&mut map, &singular, amp, seed);
            let (topo, stars, mut local) = local_of(&map);
            let rep = snap_singular(&mut local, &topo, &stars);
            assert_eq!((rep.snapped, rep.left), (8, 0), "n {n} amp {amp}");
            assert!(rep.max_move <= 2.0 * amp, "{rep:?}");
            for v in (0..singular.len()).filter(|&v| singular[v]) {
                let got = global_corners(&local, &stars, v);
                let want = global_corners(&local0, &stars0, v);
                assert_eq!(got, want, "n {n} amp {amp} vertex {v}");
            }
        }
    }
}

/// A cone of 3 right angles (a 90° singularity): the apex goes to the
/// fixed point in every chart, which an exact map already satisfies.
#[test]
fn exact_cone_is_unchanged() {
    let map = cone(3);
    let (topo, stars, mut local) = local_of(&map);
    let before = local.coords.clone();
    let rep = snap_singular(&mut local, &topo, &stars);
    assert_eq!(rep.snapped, 1);
    assert_eq!(rep.max_move, 0.0);
    assert_eq!(local.coords, before);
}

/// A vertex on a singular edge (3 tets around the w axis) goes onto the
/// axis: u and v exact, w kept from its reference corner.
#[test]
fn vertex_on_a_singular_edge_goes_onto_its_axis() {
    let clean = edge_fan(3);
    let (_, stars0, local0) = local_of(&clean);
    assert!(stars0.singular[0] && stars0.singular[1]);
    let mut map = clean.clone();
    let which: Vec<bool> = (0..map.positions.len()).map(|v| v < 2).collect();
    jitter(&mut map, &which, 1e-6, 11);
    let (topo, stars, mut local) = local_of(&map);
    let w_ref: Vec<f64> = (0..2)
        .map(|v| {
            let e = stars.of(v)[0];
            let s = e.simplex as usize;
            local.coords[s][e.corner as usize][2] + local.offset[s][2] as f64
        })
        .collect();
    let rep = snap_singular(&mut local, &topo, &stars);
    assert_eq!(rep.left, 0);
    for (v, &w_ref_v) in w_ref.iter().enumerate() {
        let got = global_corners(&local, &stars, v);
        let want = global_corners(&local0, &stars0, v);
        for (g, w) in got.iter().zip(&want) {
            // the axis is w in every chart of the fan
            assert_eq!(&g[..2], &w[..2], "vertex {v}");
            assert!((g[2] - w_ref_v).abs() < 1e-12, "vertex {v} keeps w");
        }
    }
}

/// Two equations `x = 1/2` (as `2x = 1`) and `x + y = 3` fix the point
/// exactly; a contradiction is refused.
#[test]
fn echelon_is_exact_and_refuses_contradictions() {
    let mut e = Echelon::<2>::default();
    assert!(e.add([2, 0], 1));
    assert!(e.add([1, 1], 3));
    assert!(e.add([4, 4], 12)); // dependent, consistent
    assert_eq!(e.project(&[0.3, 7.0]), [0.5, 2.5]);
    assert!(!e.add([0, 2], 1));
    // a line: the nearest point of x − y = 0 to (1, 0)
    let mut l = Echelon::<2>::default();
    assert!(l.add([-1, 1], 0));
    assert_eq!(l.project(&[1.0, 0.0]), [0.5, 0.5]);
}
