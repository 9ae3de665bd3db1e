//! The sweep of issue 23: `dualex remesh` on surfaces of genus 0–8
//! (`surface_sweep_genus*`: smoothed polycube plates, thin handles),
//! bumpy squares with 1–8 holes 1–17 cells apart (`surface_sweep_holes*`:
//! ½ to 3 target quad edges at each size) and the CAD-style tessellations
//! (`surface_cad_*`).
//!
//! Valid means: exit 0, all quads, a manifold oriented mesh, the input's
//! components, Euler characteristic and boundary loops, at most one
//! interior vertex of valence ≤ 2 per singularity of index ≥ +½ (as
//! `tests/remesh.rs` counts them), and no inverted quad.
//!
//! CI runs a subset of a few seconds ([`CI`]), whose failing runs must be
//! exactly [`KNOWN`]. `DUALEX_REMESH_SWEEP=1` runs every surface at 300,
//! 1000 and 5000 quads, seeds 1–20, on
//! `DUALEX_REMESH_SWEEP_JOBS` threads (default 1); `DUALEX_REMESH_SWEEP_ONLY`
//! keeps the surfaces whose name contains it, `DUALEX_REMESH_SWEEP_SEEDS`
//! (`a-b`) the seeds. The full sweep prints one line per surface and size
//! (valid runs, median time, median interior irregular vertices) and fails
//! on any invalid run.

mod common;
use common::*;
use std::sync::Mutex;
use std::time::Instant;

/// The runs CI makes: `(surface, quads, seed)`. Genus 7 at 5000 quads,
/// seed 1, left a seam translation at ½ (the extraction refused the map)
/// before the quantization traced its conflicts.
/// Holes 1 cell apart (a sixth of a target edge at 300 quads) merged
/// before facing boundary walls were rounded apart
/// (`crates/remesh/src/separate.rs`); holes5 at 300 quads has gaps of
/// ⅙–⅚ of a target edge, holes8 at 1000 of 0.3–5.
const CI: &[(&str, usize, u64)] = &[
    ("surface_sweep_genus1", 300, 1),
    ("surface_sweep_genus3", 1000, 1),
    ("surface_sweep_genus7", 5000, 1),
    ("surface_sweep_genus8", 300, 1),
    ("surface_sweep_holes2", 300, 1),
    ("surface_sweep_holes5", 300, 1),
    // its first grid position loses the 1-cell strip (⅙ of a quad); the
    // second keeps it (`remesh_staged`)
    ("surface_sweep_holes2", 300, 7),
    ("surface_sweep_holes8", 1000, 1),
    ("surface_sweep_holes8", 5000, 1),
];

/// CI runs that fail today, as `surface quads seed` (must match
/// exactly): two inverted quads on the thin handles of genus 8 at 300
/// quads (docs/messy-cases.md).
const KNOWN: &[&str] = &["surface_sweep_genus8 300 1"];

/// (name, components, Euler characteristic, boundary loops) of every
/// surface of the sweep.
fn surfaces() -> Vec<(String, usize, i64, usize)> {
    let mut s = Vec::new();
    for g in 0..=8i64 {
        s.push((format!("surface_sweep_genus{g}"), 1, 2 - 2 * g, 0));
    }
    for k in 1..=8i64 {
        s.push((format!("surface_sweep_holes{k}"), 1, 1 - k, k as usize + 1));
    }
    for (name, chi) in [
        ("surface_cad_cylinder", 2),
        ("surface_cad_cone", 2),
        ("surface_cad_plate_holes", -4),
        ("surface_cad_box_boss", 2),
        ("surface_cad_filleted", 2),
        ("surface_cad_needles", 2),
    ] {
        s.push((name.to_string(), 1, chi, 0));
    }
    s
}

/// What one run gave.
struct Outcome {
    /// `None` when valid, else what failed.
    problem: Option<String>,
    /// Wall-clock seconds of the run.
    seconds: f64,
    /// Interior vertices of valence other than 4.
    irregular: u64,
}

/// Interior vertices of valence other than 4.
fn irregular(s: &serde_json::Value) -> u64 {
    s["output"]["valence_interior"]
        .as_object()
        .map(|h| {
            h.iter()
                .filter(|(k, _)| k.as_str() != "4")
                .filter_map(|(_, v)| v.as_u64())
                .sum()
        })
        .unwrap_or(0)
}

/// One run of `dualex remesh` and its checks (module docs).
fn run(dir: &Scratch, surface: &(String, usize, i64, usize), quads: usize, seed: u64) -> Outcome {
    let (name, components, euler, loops) = surface;
    let tag = format!("{name}-{quads}-{seed}");
    let out = dir.arg(&format!("{tag}.obj"));
    let stats = dir.path(&format!("{tag}.json"));
    let t = Instant::now();
    let o = Remesh {
        input: &dir.arg(&format!("{name}.obj")),
        output: &out,
        quads,
        rounding: "direct",
        seed,
        stats: &stats.display().to_string(),
    }
    .run();
    let seconds = t.elapsed().as_secs_f64();
    let fail = |p: String| Outcome {
        problem: Some(p),
        seconds,
        irregular: 0,
    };
    if !o.status.success() {
        let err = String::from_utf8_lossy(&o.stderr);
        let first = err.lines().next().unwrap_or("").to_string();
        return fail(format!("exit {:?}: {first}", o.status.code()));
    }
    let mesh = match dualex_io::read_polygon_mesh(std::path::Path::new(&out)) {
        Ok(m) => m,
        Err(e) => return fail(format!("unreadable output: {e}")),
    };
    let quads_only: Option<Vec<[u32; 4]>> = mesh
        .faces
        .iter()
        .map(|f| (f.len() == 4).then(|| [f[0], f[1], f[2], f[3]]))
        .collect();
    let Some(cells) = quads_only else {
        return fail("a face that is not a quad".into());
    };
    let rep = dualex_check::check_quad_mesh(mesh.positions.len(), &cells);
    if !rep.is_valid() {
        return fail(format!("invalid quad mesh: {:?}", rep.errors()));
    }
    let s = json(&stats);
    let problems = remesh_problems(&rep, &s, (*components, *euler, *loops));
    Outcome {
        problem: (!problems.is_empty()).then(|| problems.join("; ")),
        seconds,
        irregular: irregular(&s),
    }
}

fn median(mut x: Vec<f64>) -> f64 {
    x.sort_by(f64::total_cmp);
    x.get(x.len() / 2).copied().unwrap_or(f64::NAN)
}

/// The seeds of `DUALEX_REMESH_SWEEP_SEEDS` (`a-b`), else `1..=last`.
fn seeds(last: u64) -> Vec<u64> {
    let range = std::env::var("DUALEX_REMESH_SWEEP_SEEDS").ok();
    let parsed = range.as_deref().and_then(|r| {
        let (a, b) = r.split_once('-')?;
        Some((a.parse::<u64>().ok()?, b.parse::<u64>().ok()?))
    });
    let (a, b) = parsed.unwrap_or((1, last));
    (a..=b).collect()
}

#[test]
fn every_run_of_the_sweep_is_valid() {
    let dir = Scratch::new("remesh-sweep");
    let full = std::env::var_os("DUALEX_REMESH_SWEEP").is_some();
    let only = std::env::var("DUALEX_REMESH_SWEEP_ONLY").unwrap_or_default();
    let jobs: usize = std::env::var("DUALEX_REMESH_SWEEP_JOBS")
        .ok()
        .and_then(|j| j.parse().ok())
        .unwrap_or(1);
    let mut cases = Vec::new();
    for s in surfaces() {
        if !s.0.contains(&only) || !(full || CI.iter().any(|c| c.0 == s.0)) {
            continue;
        }
        dir.generate(&s.0);
        if !full {
            for &(_, n, seed) in CI.iter().filter(|c| c.0 == s.0) {
                cases.push((s.clone(), n, seed));
            }
            continue;
        }
        for n in [300, 1000, 5000] {
            for seed in seeds(20) {
                cases.push((s.clone(), n, seed));
            }
        }
    }
    let next = Mutex::new(0usize);
    let results = Mutex::new(Vec::new());
    let t = Instant::now();
    std::thread::scope(|scope| {
        for _ in 0..jobs.max(1) {
            scope.spawn(|| loop {
                let i = {
                    let mut k = next.lock().expect("the case counter");
                    *k += 1;
                    *k - 1
                };
                let Some((s, n, seed)) = cases.get(i) else {
                    break;
                };
                let o = run(&dir, s, *n, *seed);
                if let Some(p) = &o.problem {
                    eprintln!("  {} {n} {seed}: {p}", s.0);
                }
                results
                    .lock()
                    .expect("the results")
                    .push((s.0.clone(), *n, *seed, o));
            });
        }
    });
    let results = results.into_inner().expect("the results");
    let mut failures = Vec::new();
    let mut keys: Vec<(String, usize)> = results.iter().map(|r| (r.0.clone(), r.1)).collect();
    keys.sort();
    keys.dedup();
    for (name, n) in &keys {
        let group: Vec<&Outcome> = results
            .iter()
            .filter(|r| &r.0 == name && r.1 == *n)
            .map(|r| &r.3)
            .collect();
        let valid = group.iter().filter(|o| o.problem.is_none()).count();
        eprintln!(
            "{name} {n}: {valid}/{} valid, median {:.2} s, median {} irregular",
            group.len(),
            median(group.iter().map(|o| o.seconds).collect()),
            median(group.iter().map(|o| o.irregular as f64).collect()),
        );
    }
    for (name, n, seed, o) in &results {
        if let Some(p) = &o.problem {
            failures.push(format!("{name} {n} {seed}: {p}"));
        }
    }
    failures.sort();
    eprintln!(
        "remesh sweep: {} runs, {} invalid, {:.0} s",
        results.len(),
        failures.len(),
        t.elapsed().as_secs_f64()
    );
    if full {
        assert!(failures.is_empty(), "{}", failures.join("\n"));
    } else {
        let keys: Vec<String> = failures
            .iter()
            .map(|f| f.split(':').next().unwrap_or("").to_string())
            .collect();
        assert_eq!(keys, KNOWN, "the failing CI runs differ from KNOWN");
    }
}

/// A hole smaller than a quad (holes1's 6 × 10 cells at 10 quads, a
/// fifth by a third of a target edge) is lost: the run warns and exits 0,
/// and with `--strict` it exits 1 and writes nothing.
#[test]
fn strict_refuses_a_lost_hole() {
    let dir = Scratch::new("remesh-strict");
    let name = "surface_sweep_holes1";
    dir.generate(name);
    let input = dir.arg(&format!("{name}.obj"));
    let run = |out: &str, strict: bool| {
        let mut args = vec!["remesh", &input, "-o", out, "--quads", "10", "-q"];
        if strict {
            args.push("--strict");
        }
        dualex(&args)
    };
    let loose = dir.arg("loose.obj");
    let out = run(&loose, false);
    assert!(out.status.success(), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("WARNING") && err.contains("boundary components 1 (input 2)"),
        "{err}"
    );
    let strict = dir.arg("strict.obj");
    let out = run(&strict, true);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("--strict") && err.contains("nothing written"),
        "{err}"
    );
    assert!(!dir.path("strict.obj").exists());
}
