//! Untangling folded grids: exactly the pleats go, the regular grid stays.

use super::support::{assert_oriented, assert_same_partition, counts, survivors};
use crate::testgrid::{random_rotations, rotate_charts, rotate_corner, GridSpec};
use crate::UntangleStats;

/// Untangles `spec`'s graph (shuffled when `seed` is given) and checks the
/// result against the regular grid of `spec.untangled_dims()`.
fn untangle_gives_grid<const D: usize>(spec: &GridSpec<D>, seed: Option<u64>) -> UntangleStats {
    let mut g = spec.build();
    g.check().unwrap();
    let cross = spec.cross();
    let pleats = cross * (2 * spec.folds.len() + usize::from(spec.fold_back));
    assert_eq!(g.pleat_sides().len(), pleats, "{spec:?}");
    let st = match seed {
        Some(s) => g.untangle_shuffled(s),
        None => g.untangle(),
    };
    g.check().unwrap();
    let removed = cross * (spec.folds.len() + usize::from(spec.fold_back));
    assert_eq!(st.pleats_found, pleats);
    assert_eq!(st.pleats_removed, removed, "{spec:?} {st:?}");
    assert_eq!(
        (st.pleats_left, st.reverted_left, st.not_applicable),
        (0, 0, 0)
    );
    assert!(st.iterations <= pleats + g.n_nodes() * D);
    let dims = spec.untangled_dims();
    assert_eq!(g.n_alive(), dims.iter().product::<usize>());
    let reg = GridSpec::regular(dims).build().glue();
    let got = g.glue();
    let map = survivors(spec, &g);
    assert_same_partition(&reg, &got, |n, c| (map[n.idx()], c));
    assert_eq!(counts(&reg), counts(&got));
    assert_eq!(
        (got.unmatched_sides, got.boundary_loops, got.components),
        (reg.unmatched_sides, 1, 1)
    );
    st
}

fn specs<const D: usize>(dims: [usize; D]) -> Vec<GridSpec<D>> {
    let last = dims[0] - 1;
    vec![
        GridSpec::regular(dims).fold(1),
        GridSpec::regular(dims).fold(0),
        GridSpec::regular(dims).fold(last),
        GridSpec::regular(dims).fold(0).fold(last),
        GridSpec::regular(dims).fold(1).fold(2),
        GridSpec::regular(dims).fold_back(),
        GridSpec::regular(dims).fold(1).fold_back(),
    ]
}

#[test]
fn folds_2d() {
    for dims in [[4, 3], [3, 1], [4, 5]] {
        for spec in specs(dims) {
            let st = untangle_gives_grid(&spec, None);
            assert_eq!(
                st.op2 + st.bigon_sides + st.pleats_removed,
                4 * st.pleats_removed
            );
        }
    }
    // a strip one node wide: the v sides are boundary on both nodes
    let st = untangle_gives_grid(&GridSpec::regular([3, 1]).fold(1), None);
    assert_eq!(st.both_boundary, 2);
    // folding back at the u boundary: one former partner (B.-u) is
    // unmatched per row; the top and bottom rows have both v partners free
    let st = untangle_gives_grid(&GridSpec::regular([3, 2]).fold_back(), None);
    assert_eq!(
        (st.one_boundary, st.both_boundary, st.new_pleats),
        (2, 2, 1)
    );
}

#[test]
fn folds_3d() {
    for dims in [[4, 2, 3], [3, 1, 1], [3, 3, 2]] {
        for spec in specs(dims) {
            untangle_gives_grid(&spec, None);
        }
    }
}

#[test]
fn random_worklist_orders_give_the_same_grid() {
    for seed in 0..8 {
        for spec in specs([4, 4]) {
            untangle_gives_grid(&spec, Some(seed));
        }
        for spec in specs([3, 3, 2]) {
            untangle_gives_grid(&spec, Some(seed));
        }
    }
}

fn rotated_fold<const D: usize>(spec: &GridSpec<D>, seed: u64) -> crate::NodeGraph<D> {
    let rots = random_rotations::<D>(spec.build().n_nodes(), seed);
    let mut g = rotate_charts(&spec.build(), &rots);
    let st = g.untangle_shuffled(seed);
    g.check().unwrap();
    assert_eq!((st.pleats_left, st.reverted_left), (0, 0));
    let reg = GridSpec::regular(spec.untangled_dims()).build().glue();
    let got = g.glue();
    let map = survivors(spec, &g);
    assert_same_partition(&reg, &got, |n, c| {
        let s = map[n.idx()];
        (s, rotate_corner(&rots[s.idx()], c))
    });
    assert_eq!((got.boundary_loops, got.components), (1, 1));
    g
}

#[test]
fn folds_in_rotated_charts() {
    for seed in 0..6 {
        for spec in specs([4, 3]) {
            assert_oriented(&rotated_fold(&spec, seed).glue());
        }
        for spec in specs([3, 2, 2]) {
            rotated_fold(&spec, seed);
        }
    }
}

#[test]
fn every_rotation_on_a_fold() {
    for (i, _) in dualex_map::Rot::<3>::all().iter().enumerate() {
        let spec = GridSpec::regular([3, 2, 2]).fold(1);
        let n = spec.build().n_nodes();
        let all = dualex_map::Rot::<3>::all();
        let rots: Vec<_> = (0..n).map(|k| all[(k + i) % 24]).collect();
        let mut g = rotate_charts(&spec.build(), &rots);
        let st = g.untangle();
        g.check().unwrap();
        assert_eq!((st.pleats_removed, st.pleats_left, g.n_alive()), (4, 0, 12));
    }
}

/// Timing on large grids: `cargo test --release -- --ignored --nocapture`.
#[test]
#[ignore]
fn large_grids_timing() {
    let spec = GridSpec::regular([400, 400])
        .fold(50)
        .fold(200)
        .fold(399)
        .fold_back();
    let t = std::time::Instant::now();
    let mut g = spec.build();
    let st = g.untangle_shuffled(7);
    let t_untangle = t.elapsed();
    let gl = g.glue();
    println!(
        "2D {} nodes: untangle {:?} ({} pleats), glue {:?}",
        g.n_nodes(),
        t_untangle,
        st.pleats_removed,
        t.elapsed() - t_untangle
    );
    assert_eq!(
        (st.pleats_left, gl.n_cells(), gl.boundary_loops),
        (0, 399 * 400, 1)
    );
    let t = std::time::Instant::now();
    let mut g = spec.build();
    let st = g.fair(10);
    println!("2D fair (no candidates) {:?}", t.elapsed());
    assert_eq!(st.lifts, 0);
    let spec = GridSpec::regular([40, 40, 40]).fold(10).fold(30);
    let t = std::time::Instant::now();
    let mut g = spec.build();
    let st = g.untangle();
    let t_untangle = t.elapsed();
    let gl = g.glue();
    println!(
        "3D {} nodes: untangle {:?} ({} pleats), glue {:?}",
        g.n_nodes(),
        t_untangle,
        st.pleats_removed,
        t.elapsed() - t_untangle
    );
    assert_eq!(
        (st.pleats_left, gl.n_cells(), gl.boundary_loops),
        (0, 64000, 1)
    );
}
