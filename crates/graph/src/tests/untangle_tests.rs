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

/// The preview reads what a removal does, writes nothing, and the
/// removal agrees with it (check() after each removal).
fn preview_agrees<const D: usize>(spec: &GridSpec<D>, seed: u64) {
    let rots = random_rotations::<D>(spec.build().n_nodes(), seed);
    let g = rotate_charts(&spec.build(), &rots);
    let sides = g.pleat_sides();
    assert!(!sides.is_empty());
    for s in sides {
        let before = g.clone();
        let Some(p) = g.pleat_preview(s) else {
            panic!("a fold's pleat is removable: {s:?}");
        };
        assert_eq!(g, before);
        let mut h = g.clone();
        let done = h.remove_pleat(s).unwrap();
        h.check().unwrap();
        assert_eq!(p.op2, done.op2, "{spec:?} {s:?}");
        assert!(p.op2 < 2 * D);
        if done.partner_in_pleat == 0 {
            assert_eq!(p.self_loops, done.self_loops);
        }
    }
    // not applicable: an unmatched side, a same-flag pair
    let s = (0..g.n_sides() as u32)
        .map(crate::Side)
        .find(|&s| g.opposite(s).is_none())
        .unwrap();
    assert_eq!(g.pleat_preview(s), None);
    let t = (0..g.n_sides() as u32)
        .map(crate::Side)
        .find(|&s| g.opposite(s).is_some() && !g.is_pleat(s))
        .unwrap();
    assert_eq!(g.pleat_preview(t), None);
}

#[test]
fn pleat_preview_agrees_with_the_removal() {
    for seed in 0..3 {
        for spec in specs([4, 3]) {
            preview_agrees(&spec, seed);
        }
        for spec in specs([3, 2, 2]) {
            preview_agrees(&spec, seed);
        }
    }
}

/// X normal, Y reverted, pleat X.+w ↔ Y.+w (w the last axis); Z normal
/// with Z.+w ↔ X.-w and Z.-w ↔ Y.-w (a pleat too): every removal closes a
/// node on itself.
fn closing_pair<const D: usize>() -> crate::NodeGraph<D> {
    use crate::ids::Node;
    use dualex_map::Rot;
    let mut g = crate::NodeGraph::<D>::new(vec![false, true, false]);
    let (p, m) = (2 * D - 2, 2 * D - 1);
    let s = |n: u32, d: usize| Node(n).side::<D>(d);
    g.link(s(0, p), s(1, p), Rot::IDENTITY).unwrap();
    g.link(s(2, p), s(0, m), Rot::IDENTITY).unwrap();
    g.link(s(2, m), s(1, m), Rot::IDENTITY).unwrap();
    g
}

/// A removal that would glue a node to itself is put off, then done
/// when nothing else is left: deferred, never dropped (both dimensions).
fn deferred_not_dropped<const D: usize>() {
    let mut g = closing_pair::<D>();
    g.check().unwrap();
    for p in g.pleat_sides() {
        assert_eq!(g.pleat_preview(p).map(|p| p.self_loops), Some(1));
    }
    let st = g.untangle();
    g.check().unwrap();
    assert!(st.deferred >= 1, "{st:?}");
    assert_eq!((st.pleats_removed, st.self_loops), (1, 1));
    assert_eq!((st.pleats_left, st.reverted_left, g.n_alive()), (0, 0, 1));
}

#[test]
fn self_loop_removals_are_deferred_not_dropped() {
    deferred_not_dropped::<2>();
    deferred_not_dropped::<3>();
}

/// A pillow (two nodes facing on every side: a pure OP1) among folds is
/// removed with no saddle lift and changes nothing else, in both dimensions:
/// the folds' figures are those of the folds alone.
fn pillow_first<const D: usize>(spec: &GridSpec<D>) {
    use dualex_map::Rot;
    let alone = {
        let mut g = spec.build();
        g.untangle()
    };
    let base = spec.build();
    let n = base.n_nodes();
    let mut flags: Vec<bool> = (0..n)
        .map(|i| base.is_reverted(crate::Node(i as u32)))
        .collect();
    flags.extend([false, true]);
    let mut g = crate::NodeGraph::<D>::new(flags);
    for s in 0..base.n_sides() as u32 {
        let s = crate::Side(s);
        if let (Some(o), Some(r)) = (base.opposite(s), base.rotation(s)) {
            if s < o {
                g.link(s, o, r).unwrap();
            }
        }
    }
    let (x, y) = (crate::Node(n as u32), crate::Node(n as u32 + 1));
    for d in 0..2 * D {
        g.link(x.side::<D>(d), y.side::<D>(d), Rot::IDENTITY)
            .unwrap();
    }
    g.check().unwrap();
    assert_eq!(g.pleat_preview(x.side::<D>(0)).map(|p| p.op2), Some(0));
    let st = g.untangle();
    g.check().unwrap();
    assert!(!g.is_alive(x) && !g.is_alive(y));
    assert_eq!(st.pleats_removed, alone.pleats_removed + 1);
    assert_eq!((st.op2, st.self_loops), (alone.op2, alone.self_loops));
    assert_eq!(st.bigon_sides, alone.bigon_sides + 2 * D - 1);
}

#[test]
fn a_pillow_among_folds_is_one_pure_op1() {
    for spec in specs([4, 3]) {
        pillow_first(&spec);
    }
    for spec in specs([3, 2, 2]) {
        pillow_first(&spec);
    }
}

/// `untangle_best`: while the next step leaves degenerate vertices, other
/// orders are tried from the graph as it was (each one untangles it
/// completely), and the first with the fewest is kept; a graph without
/// pleats is not copied and no order is tried.
fn best_order<const D: usize>(dims: [usize; D]) {
    let spec = GridSpec::regular(dims).fold(2).fold_back();
    // the first order "leaves" 2, seed 1 leaves 1, seed 2 leaves 0
    let mut g = spec.build();
    let mut calls = 0;
    let (st, last) = g.untangle_best(4, |g| {
        g.check().unwrap();
        assert_eq!(g.pleat_sides().len(), 0);
        calls += 1;
        (calls, 3 - calls)
    });
    g.check().unwrap();
    assert_eq!((calls, last), (3, 3), "stops at the first order leaving 0");
    assert_eq!((st.orders_tried, st.order_kept), (2, Some(2)));
    assert_eq!((st.pleats_left, st.reverted_left), (0, 0));
    // no order better than the first: the first is kept
    let mut g = spec.build();
    let (st, ()) = g.untangle_best(3, |_| ((), 1));
    assert_eq!((st.orders_tried, st.order_kept), (3, None));
    g.check().unwrap();
    // no pleat: nothing tried, even when the next step leaves some
    let mut g = GridSpec::regular(dims).build();
    let (st, _) = g.untangle_best(4, |_| ((), 5));
    assert_eq!((st.pleats_found, st.orders_tried), (0, 0));
}

#[test]
fn untangle_best_keeps_the_first_order_leaving_fewest() {
    best_order([6, 5]);
    best_order([5, 4, 3]);
}
