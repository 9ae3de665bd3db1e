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

/// A stand-in TetGen that refuses every slab (exits 1 on `-p…`, finds no
/// crossing on `-d…`): the chain tries T/2, T/4, T/8, then splits, and
/// says so; a surface whose triangles cross is split without running it.
#[cfg(unix)]
#[test]
fn a_refusing_tetgen_ends_in_the_prism_split() {
    use std::os::unix::fs::PermissionsExt;
    let dir = std::env::temp_dir().join(format!("dualex-chain-test-{}", std::process::id()));
    std::fs::create_dir_all(&dir).expect("temp dir");
    let fake = dir.join("refusing-tetgen");
    let log = dir.join("calls");
    let script = format!(
        "#!/bin/sh\necho \"$1\" >> '{}'\ncase \"$1\" in -d*) exit 0;; esac\necho 'terminate called' >&2\nexit 1\n",
        log.display()
    );
    std::fs::write(&fake, script).expect("script");
    std::fs::set_permissions(&fake, std::fs::Permissions::from_mode(0o755)).expect("chmod");
    let opts = ExtrudeOptions {
        program: fake.clone(),
        ..Default::default()
    };
    let map = grid(3, 2.0, true);
    let (m, r) = extrude(&map, &opts).expect("split");
    assert_eq!((r.method, r.tetgen, r.tets), (Method::Split, false, 3 * 18));
    let note = r.note.clone().unwrap_or_default();
    assert!(
        note.starts_with("TetGen refused the slab (T = ")
            && note.contains("thinner slabs down to")
            && note.ends_with("built-in prism split used"),
        "{note}"
    );
    assert_valid_extrusion(&m, &r, "refused bump");
    let calls = std::fs::read_to_string(&log).unwrap_or_default();
    assert_eq!(
        calls.lines().collect::<Vec<_>>(),
        ["-pYzQFN", "-dzQ", "-pYzQFN", "-pYzQFN", "-pYzQFN"]
    );
    // a fold through the surface: triangle 0 pierced by a new one
    let mut crossing = map.clone();
    let n = crossing.positions.len() as u32;
    crossing
        .positions
        .extend([[0.1, 0.1, -1.0], [0.2, 0.15, 1.0], [0.3, 0.05, 1.0]]);
    crossing.simplices.push([n, n + 1, n + 2]);
    crossing.coords.push([[0.0, 0.0], [1.0, 0.0], [0.0, 1.0]]);
    std::fs::write(&log, "").expect("log");
    let (_, r) = extrude(&crossing, &opts).expect("split");
    assert_eq!((r.method, r.intersecting_triangles), (Method::Split, 2));
    assert!(r.note.unwrap_or_default().contains("TetGen not run"));
    assert_eq!(std::fs::read_to_string(&log).unwrap_or_default(), "");
    let _ = std::fs::remove_dir_all(&dir);
}
