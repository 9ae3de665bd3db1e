//! Checks on the shared real data (`/work/shared/data`, skipped with a
//! notice when absent): reverted counts of its README, welding of cut meshes,
//! the broken HexEx files.

use crate::report::{inspect, InspectOptions};
use crate::test_maps::{data_file, read_hexex, read_obj};
use crate::weld::weld;
use crate::{Topology, TransitionOptions, Transitions};

fn report_2d(rel: &str, weld: bool) -> Option<crate::MapReport> {
    let path = data_file(rel)?;
    let m = read_obj(&path);
    let opts = InspectOptions {
        weld,
        ..Default::default()
    };
    let r = inspect(&m, &opts).unwrap_or_else(|e| panic!("{rel}: {e}"));
    eprintln!("{rel}: {r}");
    Some(r)
}

#[test]
fn qex_reverted_counts() {
    for (rel, reverted) in [
        ("qex/fandisk_param.obj", 9),
        ("qex/duck_miq_4_param.obj", 18),
        ("qex/duck_miq_8_param.obj", 92),
    ] {
        let Some(r) = report_2d(rel, false) else {
            continue;
        };
        assert_eq!(r.reverted, reverted, "{rel}");
        assert_eq!(r.welded_vertices, 0, "{rel}");
        assert!(r.max_transition_residual < 1e-3, "{rel}");
    }
}

#[test]
fn directional_after_welding() {
    for (rel, reverted) in [
        ("directional/decimated-knight-param.obj", 3),
        ("directional/dragon-param-full-seamless.obj", 549),
        ("directional/horsers-param-full-seamless.obj", 0),
        ("directional/lilium-param.obj", 0),
    ] {
        let Some(r) = report_2d(rel, true) else {
            continue;
        };
        assert_eq!(r.reverted, reverted, "{rel}");
        assert!(r.welded_vertices > 0, "{rel}");
    }
}

#[test]
fn weld_closes_sphere() {
    let Some(path) = data_file("directional/spherer-param.obj") else {
        return;
    };
    let m = read_obj(&path);
    let before = Topology::build(&m).expect("cut sphere");
    assert!(before.boundary_facets > 0);
    let (w, rep) = weld(&m);
    assert!(rep.welded_vertices > 0);
    let topo = Topology::build(&w).expect("welded sphere");
    assert_eq!(topo.boundary_facets, 0);
    assert_eq!(topo.components(), 1);
    // a closed sphere: V − E + F = 2 with E = 3F/2
    assert_eq!(2 * w.positions.len() as i64 - w.len() as i64, 4);
    let (_, trep) = Transitions::derive(&w, &topo, &TransitionOptions::default()).expect("GP");
    assert!(trep.max_residual < 1e-3);
}

#[test]
fn hexex_files() {
    for (rel, round) in [
        ("hexex/minimal.hexex", false),
        ("hexex/hand_q.hexex", false),
        ("hexex/fancy_ring_q.hexex", false),
        ("hexex/rockerarm_q.hexex", false),
        ("hexex/sphere.hexex", false),
        ("hexex/fancy_ring.hexex", true),
    ] {
        let Some(path) = data_file(rel) else { continue };
        let opts = InspectOptions {
            round,
            ..Default::default()
        };
        let r = inspect(&read_hexex(&path), &opts).unwrap_or_else(|e| panic!("{rel}: {e}"));
        eprintln!("{rel}: {r}");
        assert_eq!(r.components, 1, "{rel}");
    }
    // its charts agree across every face (vertex 1 moved to w = −1 in all
    // of them), but half the volume is reverted or flat: refused as
    // reflected charts (TetMap::check_not_reflected)
    if let Some(path) = data_file("hexex/minimal_invalid_charts.hexex") {
        let e = inspect(&read_hexex(&path), &InspectOptions::default()).expect_err("reflected");
        assert!(e.to_string().contains("reflected"), "{e}");
        // the valid minimal map passes the same rule
        let ok = data_file("hexex/minimal.hexex").expect("minimal.hexex beside it");
        read_hexex(&ok)
            .check_not_reflected()
            .expect("minimal is fine");
    }
}
