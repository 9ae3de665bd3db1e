//! `dualex generate` + `dualex quad` as processes on every generated map:
//! the output is always a valid quad mesh (independent checker), and equals
//! the expected mesh (counts, interior valences, Euler characteristic,
//! boundary loops) wherever the generator knows it.

mod common;
use common::*;

fn run_one(name: &str, seed: u64, extra: &[&str]) -> (dualex_check::QuadReport, serde_json::Value) {
    let dir = Scratch::new(&format!("gen-{name}-{seed}-{}", extra.len()));
    let map = dir.arg("map.obj");
    let out = dualex(&["generate", name, "-o", &map, "--seed", &seed.to_string()]);
    assert!(out.status.success(), "generate {name}: {}", text(&out));
    let quads = dir.arg("quads.obj");
    let stats = dir.arg("stats.json");
    let mut args = vec!["quad", &map, "-o", &quads, "--stats", &stats];
    args.extend_from_slice(extra);
    let out = dualex(&args);
    assert!(out.status.success(), "quad {name}: {}", text(&out));
    let (_, rep) = read_valid_quads(&dir.path("quads.obj"), name);
    (rep, json(&dir.path("stats.json")))
}

fn check_expected(name: &str, seed: u64, rep: &dualex_check::QuadReport, st: &serde_json::Value) {
    let (_, exp) = dualex_gen::by_name(name, seed).expect("known generator");
    let ctx = format!("{name} (seed {seed}): stats {st}");
    if let Some(q) = exp.quads {
        assert_eq!(rep.faces, q, "quads of {ctx}");
    }
    if let Some(v) = &exp.interior_valence {
        assert_eq!(&rep.interior_valence, v, "interior valences of {ctx}");
    }
    if let Some(e) = exp.euler {
        assert_eq!(rep.euler, e, "Euler characteristic of {ctx}");
    }
    if let Some(b) = exp.boundary_loops {
        assert_eq!(rep.boundary_loops, b, "boundary loops of {ctx}");
        assert_eq!(
            st["output"]["boundary_loops"], b,
            "graph boundary loops of {ctx}"
        );
    }
    assert_eq!(rep.components, 1, "components of {ctx}");
    assert_eq!(st["untangle"]["pleats_left"], 0, "pleats left in {ctx}");
    assert_eq!(st["trace"]["label_violations"], 0, "label rule in {ctx}");
    assert_eq!(
        st["trace"]["rotation_mismatches"], 0,
        "rotation symmetry in {ctx}"
    );
}

#[test]
fn every_generated_map_gives_its_expected_mesh() {
    for name in dualex_gen::names() {
        let (rep, st) = run_one(&name, 1, &[]);
        check_expected(&name, 1, &rep, &st);
    }
}

#[test]
fn noisy_maps_over_several_seeds() {
    for name in dualex_gen::names()
        .iter()
        .filter(|n| n.contains("noise") || n.contains("rotated"))
    {
        for seed in 2..6 {
            let (rep, st) = run_one(name, seed, &[]);
            check_expected(name, seed, &rep, &st);
        }
    }
}

#[test]
fn messy_maps_really_are_messy() {
    // the untangling path is exercised, not bypassed
    for name in [
        "square_noise",
        "square_half_rotated",
        "disk_p1_reverted",
        "disk_m3_reverted",
    ] {
        let (_, st) = run_one(name, 1, &[]);
        assert!(
            st["reverted_nodes"].as_u64().unwrap_or(0) > 0,
            "{name}: {st}"
        );
        assert!(
            st["untangle"]["pleats_removed"].as_u64().unwrap_or(0) > 0,
            "{name}: {st}"
        );
        assert_eq!(st["output"]["holes"], 0);
    }
}

#[test]
fn embedded_map_runs_without_input() {
    let dir = Scratch::new("embedded");
    let q = dir.arg("q.ply");
    let out = dualex(&["quad", "-o", &q]);
    assert!(out.status.success(), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("embedded"),
        "says it runs on the embedded map: {err}"
    );
    let (_, rep) = read_valid_quads(&dir.path("q.ply"), "embedded");
    // the embedded map is a closed cube surface: 8 valence-3 vertices
    assert_eq!(rep.boundary_loops, 0);
    assert_eq!(rep.euler, 2);
    assert_eq!(rep.interior_valence.get(&3), Some(&8));
}

#[test]
fn every_output_format() {
    let dir = Scratch::new("formats");
    let map = dir.arg("m.obj");
    assert!(dualex(&["generate", "torus_noise", "-o", &map])
        .status
        .success());
    for ext in ["obj", "ply", "vtk"] {
        let q = dir.arg(&format!("q.{ext}"));
        let out = dualex(&["quad", &map, "-o", &q]);
        assert!(out.status.success(), "{ext}: {}", text(&out));
        let text = std::fs::read(&q).expect("output written");
        assert!(!text.is_empty());
        if ext != "vtk" {
            let (_, rep) = read_valid_quads(&dir.path(&format!("q.{ext}")), ext);
            assert_eq!(rep.faces, 32);
        } else {
            let s = String::from_utf8_lossy(&text);
            assert!(
                s.contains("CELLS 32 160"),
                "vtk cells: {}",
                &s[..s.len().min(400)]
            );
        }
    }
}

#[test]
fn output_is_deterministic() {
    // the same input and seed give byte-identical meshes and the same counts
    let dir = Scratch::new("determinism");
    let m = dir.arg("m.obj");
    assert!(
        dualex(&["generate", "square_noise", "-o", &m, "--seed", "7"])
            .status
            .success()
    );
    let mut outputs = Vec::new();
    for run in 0..2 {
        let q = dir.arg(&format!("q{run}.ply"));
        let out = dualex(&["quad", &m, "-o", &q]);
        assert!(out.status.success(), "{}", text(&out));
        outputs.push(std::fs::read(&q).expect("output"));
    }
    assert_eq!(outputs[0], outputs[1]);
}

#[test]
fn fairing_can_be_turned_off() {
    let (rep, st) = run_one("disk_m2_reverted", 1, &["--no-fairing"]);
    assert!(st["fairing"].is_null(), "{st}");
    assert_eq!(rep.faces, 180);
    let (_, st) = run_one("disk_m2_reverted", 1, &[]);
    assert!(st["fairing"].is_object(), "{st}");
}
