//! End-to-end tests of [`crate::extrude`] with the real TetGen (skipped
//! with a notice when `tetgen` is not on PATH; `tests/extrude.rs` requires
//! it) and with the fallback.

use crate::chart::volume;
use crate::*;
use dualex_map::{InspectOptions, TriMap};
use std::collections::BTreeSet;

/// An `n × n` grid of the unit square (alternating diagonals), map =
/// `scale · (x, y) + 0.2`, optionally lifted into a bump (a surface).
fn grid(n: usize, scale: f64, bump: bool) -> TriMap {
    let mut m = TriMap::default();
    for j in 0..=n {
        for i in 0..=n {
            let (x, y) = (i as f64 / n as f64, j as f64 / n as f64);
            let z = if bump {
                0.3 * (3.0 * x).sin() * (2.0 * y).cos()
            } else {
                0.0
            };
            m.positions.push([x, y, z]);
        }
    }
    let id = |i: usize, j: usize| (j * (n + 1) + i) as u32;
    for j in 0..n {
        for i in 0..n {
            let (a, b, c, d) = (id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1));
            let tris = if (i + j) % 2 == 0 {
                [[a, b, c], [a, c, d]]
            } else {
                [[a, b, d], [b, c, d]]
            };
            for t in tris {
                let uv = t.map(|v| {
                    let p = m.positions[v as usize];
                    [scale * p[0] + 0.2, scale * p[1] + 0.2]
                });
                m.simplices.push(t);
                m.coords.push(uv);
            }
        }
    }
    m
}

fn have_tetgen() -> bool {
    let ok = std::process::Command::new("tetgen")
        .arg("-h")
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .is_ok();
    if !ok {
        eprintln!("NOTICE: tetgen is not on PATH: skipping the TetGen unit tests");
    }
    ok
}

fn sorted_tets(m: &dualex_map::TetMap) -> BTreeSet<[u32; 4]> {
    m.simplices
        .iter()
        .map(|t| {
            let mut k = *t;
            k.sort_unstable();
            k
        })
        .collect()
}

/// The extruded map is exactly GP, nowhere reverted, and fills the slab.
fn assert_valid_extrusion(m: &dualex_map::TetMap, r: &ExtrudeReport, what: &str) {
    assert!(m.validate().is_ok(), "{what}");
    assert!(
        (0..m.len()).all(|s| volume(&m.positions, &m.simplices[s]) > 0.0),
        "{what}"
    );
    let flat = (0..m.len()).filter(|&s| m.map_det(s) == 0.0).count();
    let reverted = (0..m.len()).filter(|&s| m.map_det(s) < 0.0).count();
    assert_eq!((flat, reverted), (r.flat_tets, r.reverted_tets), "{what}");
    assert!(
        !r.planar || flat + reverted == 0,
        "{what}: a bad tet in a planar slab"
    );
    assert!(
        r.steiner_points > 0 || reverted == 0,
        "{what}: reverted without Steiner points"
    );
    let opts = InspectOptions {
        weld: false,
        ..Default::default()
    };
    let rep = dualex_map::inspect(m, &opts).expect("valid map");
    assert!(rep.max_transition_residual < 1e-9, "{what}: {rep:?}");
    assert_eq!(rep.singular_edges.values().sum::<usize>(), 0, "{what}");
    assert_eq!(r.tets, m.len(), "{what}");
}

#[test]
fn tetgen_without_refinement_is_the_prism_split() {
    if !have_tetgen() {
        return;
    }
    for (bump, layers) in [(false, 1), (false, 3), (true, 2)] {
        let map = grid(5, 4.0, bump);
        let opts = ExtrudeOptions {
            layers,
            ..Default::default()
        };
        let (m, r) = extrude(&map, &opts).expect("tetgen");
        let what = format!("bump {bump}, {layers} layers");
        assert!(r.tetgen && r.planar != bump, "{what}");
        assert_eq!((r.prisms, r.steiner_points), (50 * layers, 0), "{what}");
        assert_valid_extrusion(&m, &r, &what);
        // tets = 3 per prism + one per interior (bent-wall) edge
        assert_eq!(r.tets, 3 * r.prisms + r.flat_tets, "{what}");
        let missing = ExtrudeOptions {
            program: "/nonexistent/tetgen".into(),
            fallback: true,
            ..opts
        };
        let (f, rf) = extrude(&map, &missing).expect("fallback");
        assert!(!rf.tetgen && rf.flat_tets == 0);
        if !bump {
            assert_eq!(sorted_tets(&m), sorted_tets(&f), "{what}");
        }
    }
}

#[test]
fn tetgen_refinement_adds_steiner_points_inside_prisms() {
    if !have_tetgen() {
        return;
    }
    for bump in [false, true] {
        refine(&grid(4, 3.0, bump), &format!("bump {bump}"));
    }
}

fn refine(map: &TriMap, what: &str) {
    let opts = ExtrudeOptions {
        layers: 2,
        quality: true,
        thickness: Some(0.1),
        ..Default::default()
    };
    let (m, r) = extrude(map, &opts).expect("tetgen");
    assert!(
        r.steiner_points > 0 && r.tets > 3 * r.prisms,
        "{what}: {r:?}"
    );
    assert_valid_extrusion(&m, &r, what);
    // the slab is filled: same volume as the Steiner-free split
    let (f, _) = extrude(
        map,
        &ExtrudeOptions {
            quality: false,
            ..opts
        },
    )
    .expect("tetgen");
    let vol = |m: &dualex_map::TetMap| -> f64 {
        m.simplices.iter().map(|t| volume(&m.positions, t)).sum()
    };
    assert!((vol(&m) - vol(&f)).abs() < 1e-9 * vol(&f));
}

#[test]
fn missing_tetgen_is_an_error_without_fallback() {
    let opts = ExtrudeOptions {
        program: "/nonexistent/tetgen".into(),
        ..Default::default()
    };
    let e = extrude(&grid(2, 2.0, false), &opts).expect_err("missing");
    assert!(matches!(e, ExtrudeError::TetgenMissing(_)), "{e}");
}
