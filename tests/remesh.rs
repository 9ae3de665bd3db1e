//! `dualex remesh` as a user runs it (issue 15): a plain surface in, a
//! quad mesh out, through the map made the cheap way (smoothest cross
//! field, cut, seamless integration, rounding).
//!
//! The bounded subset CI runs: every generated surface (`dualex generate
//! surface_*`: sphere, bumpy sphere, torus, genus 3, cube with sharp
//! edges, disk with boundary) at about 100 and 500 quads, seeds 1–5,
//! direct rounding and singularities off the grid. Each run must give a
//! valid mesh (all quads, manifold, oriented), closed where the surface
//! is, one component per surface component, the surface's Euler
//! characteristic, at most one interior vertex of valence ≤ 2 per
//! singularity of index ≥ +½, and a quad count within 10 % of the target,
//! with either rounding (with singularities off the grid the extraction's
//! local repair adds quads along paths between them, up to ~25 % at 100
//! quads, which `dualex remesh` measures and corrects: the map is made
//! once more for the area that count asks). The runs that do not are
//! listed in `KNOWN`, which must match exactly.
//! `DUALEX_REMESH_FULL=1` adds 2000 quads and the shared surfaces'
//! geometry (the closing note's table; also `tools/remesh-table`).

mod common;
use common::*;
use std::collections::BTreeSet;

/// Runs that fail a property, as `surface quads rounding seed: what`.
const KNOWN: &[&str] = &[];

/// The generated surfaces and their (components, Euler characteristic,
/// boundary loops).
const SURFACES: &[(&str, usize, i64, usize)] = &[
    ("surface_sphere", 1, 2, 0),
    ("surface_bumpy_sphere", 1, 2, 0),
    ("surface_torus", 1, 0, 0),
    ("surface_genus3", 1, -4, 0),
    ("surface_cube", 1, 2, 0),
    ("surface_disk", 1, 1, 1),
];

/// One run: `None` when every property holds, else what failed.
fn run(
    dir: &Scratch,
    surface: &str,
    quads: usize,
    rounding: &str,
    seed: u64,
    shape: (usize, i64, usize),
) -> Option<String> {
    let out = dir.arg(&format!("{surface}-{quads}-{rounding}-{seed}.obj"));
    let stats = dir.path(&format!("{surface}-{quads}-{rounding}-{seed}.json"));
    let o = Remesh {
        input: &dir.arg(&format!("{surface}.obj")),
        output: &out,
        quads,
        rounding,
        seed,
        stats: &stats.display().to_string(),
    }
    .run();
    if !o.status.success() {
        let err = String::from_utf8_lossy(&o.stderr);
        return Some(format!(
            "exit {:?}: {}",
            o.status.code(),
            err.lines().next().unwrap_or("")
        ));
    }
    let (mesh, rep) = read_valid_quads(std::path::Path::new(&out), surface);
    let s = json(&stats);
    let n = mesh.faces.len();
    let mut problems = remesh_problems(&rep, &s, shape);
    let off = (n as f64 - quads as f64).abs() / quads as f64;
    if off > 0.10 {
        problems.push(format!(
            "{n} quads for {quads} ({:+.0} %)",
            100.0 * (n as f64 / quads as f64 - 1.0)
        ));
    }
    (!problems.is_empty()).then(|| problems.join("; "))
}

#[test]
fn generated_surfaces_give_valid_meshes() {
    let dir = Scratch::new("remesh");
    let full = std::env::var_os("DUALEX_REMESH_FULL").is_some();
    let sizes: &[usize] = if full { &[100, 500, 2000] } else { &[100, 500] };
    let mut failures = BTreeSet::new();
    let mut runs = 0;
    for &(surface, c, e, b) in SURFACES {
        dir.generate(surface);
        for &n in sizes {
            for rounding in ["direct", "off"] {
                for seed in 1..=5 {
                    runs += 1;
                    if let Some(what) = run(&dir, surface, n, rounding, seed, (c, e, b)) {
                        failures.insert(format!("{surface} {n} {rounding} {seed}: {what}"));
                    }
                }
            }
        }
    }
    eprintln!("remesh: {runs} runs, {} with a problem", failures.len());
    for f in &failures {
        eprintln!("  {f}");
    }
    let known: BTreeSet<String> = KNOWN.iter().map(|s| s.to_string()).collect();
    let keys = |set: &BTreeSet<String>| -> BTreeSet<String> {
        set.iter()
            .map(|s| s.split(':').next().unwrap_or("").to_string())
            .collect()
    };
    if !full {
        assert_eq!(
            keys(&failures),
            keys(&known),
            "the failing runs differ from KNOWN"
        );
    }
}

#[test]
fn the_embedded_surface_and_the_options() {
    let dir = Scratch::new("remesh-cli");
    // no input: the embedded surface, said on stderr
    let o = dualex(&[
        "remesh",
        "-o",
        &dir.arg("q.obj"),
        "--map-out",
        &dir.arg("m.obj"),
        "--png",
        &dir.arg("m.png"),
        "--stats",
        "-",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("embedded surface"), "{err}");
    let stats: serde_json::Value = serde_json::from_slice(&o.stdout).expect("stats JSON on stdout");
    let quads = stats["output"]["quads"].as_u64().expect("output.quads");
    assert!(
        (900..=1100).contains(&quads),
        "{quads} quads for about 1000"
    );
    assert_eq!(
        stats["remesh"]["singularity_index"]["1/4"], 8,
        "a sphere's 8 singularities"
    );
    let (_, rep) = read_valid_quads(&dir.path("q.obj"), "embedded");
    assert_eq!((rep.components, rep.euler, rep.boundary_loops), (1, 2, 0));
    // the map written is the one extracted: `quad` on it gives the same mesh
    let q = dualex(&[
        "quad",
        &dir.arg("m.obj"),
        "-o",
        &dir.arg("q2.obj"),
        "--stats",
        "-",
        "-q",
    ]);
    assert!(q.status.success(), "{}", text(&q));
    let s2: serde_json::Value = serde_json::from_slice(&q.stdout).expect("stats JSON");
    assert_eq!(s2["output"]["quads"].as_u64(), Some(quads));
    let png = std::fs::read(dir.path("m.png")).expect("the map picture");
    assert!(png.starts_with(b"\x89PNG"));
    // greedy rounding, --scale, --uv
    let o = dualex(&[
        "remesh",
        "-o",
        &dir.arg("g.obj"),
        "--rounding",
        "greedy",
        "--scale",
        "0.1",
        "--uv",
        "-q",
    ]);
    assert!(o.status.success(), "{}", text(&o));
    let t = std::fs::read_to_string(dir.path("g.obj")).expect("read");
    assert!(t.lines().any(|l| l.starts_with("vt ")), "--uv writes vt");
    // usage errors: exit 2, nothing written
    for args in [
        vec!["remesh", "-o", "x.obj", "--quads", "10", "--scale", "1"],
        vec!["remesh", "-o", "x.obj", "--sharp", "200"],
        vec!["remesh", "-o", "x.obj", "--quads", "0"],
        vec!["remesh", "-o", "x.obj", "--rounding", "sometimes"],
        vec!["remesh", "-o", "x.vtk", "--uv"],
    ] {
        let o = dualex(&args);
        assert_eq!(o.status.code(), Some(2), "{args:?}: {}", text(&o));
    }
    // bad input: one line naming the file, exit 1, nothing written
    std::fs::write(
        dir.path("bad.obj"),
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\n",
    )
    .expect("write");
    let o = dualex(&["remesh", &dir.arg("bad.obj"), "-o", &dir.arg("bad_q.obj")]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(err.contains("bad.obj") && err.lines().count() == 1, "{err}");
    assert!(!dir.path("bad_q.obj").exists());
}

/// Inverted quads left by the geometric stage send `remesh` to another
/// grid position (issue 21): the stats list every attempt's count, the
/// first with the fewest is kept, and the map written (`--map-out`) is
/// the one kept, also when a later attempt was worse.
#[test]
fn another_grid_position_while_quads_stay_inverted() {
    let dir = Scratch::new("remesh-attempts");
    let surface = dir.arg("g3.obj");
    let g = dualex(&["generate", "surface_genus3", "-o", &surface, "-q"]);
    assert!(g.status.success(), "{}", text(&g));
    let mut retried = 0;
    for rounding in ["direct", "off"] {
        for seed in 1..=5 {
            let run = format!("{rounding} {seed}");
            let (q, m) = (dir.arg("q.obj"), dir.arg("m.obj"));
            let o = dualex(&[
                "remesh",
                &surface,
                "-o",
                &q,
                "--map-out",
                &m,
                "--quads",
                "100",
                "--rounding",
                rounding,
                "--seed",
                &seed.to_string(),
                "--stats",
                "-",
                "-q",
            ]);
            assert!(o.status.success(), "{run}: {}", text(&o));
            let s: serde_json::Value = serde_json::from_slice(&o.stdout).expect("stats JSON");
            let attempts: Vec<u64> = s["remesh"]["grid_attempts"]
                .as_array()
                .expect("remesh.grid_attempts")
                .iter()
                .filter_map(|v| v.as_u64())
                .collect();
            assert!(!attempts.is_empty(), "{run}");
            let fewest = attempts.iter().min().copied();
            assert_eq!(s["geometry"]["after"]["inverted"].as_u64(), fewest, "{run}");
            // more only while quads are left inverted
            let first_zero = attempts.iter().position(|&n| n == 0);
            assert!(
                first_zero.is_none_or(|z| z + 1 == attempts.len()),
                "{run}: {attempts:?}"
            );
            if attempts.len() > 1 {
                retried += 1;
                let x = dualex(&["quad", &m, "-o", &dir.arg("q2.obj"), "--stats", "-", "-q"]);
                assert!(x.status.success(), "{run}: {}", text(&x));
                let s2: serde_json::Value = serde_json::from_slice(&x.stdout).expect("stats JSON");
                assert_eq!(
                    s2["output"]["quads"], s["output"]["quads"],
                    "{run}: the map written is the one kept"
                );
            }
        }
    }
    // two of these ten runs need it today (seed 1 direct, seed 4 off):
    // if none does, the attempts are no longer exercised here
    assert!(retried > 0, "no run tried another grid position");
}
