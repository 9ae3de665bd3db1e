//! Stress of singular configurations, built only on `dualex_gen::from_mesh`
//! (expected meshes from construction): the built-in quad and hex meshes at
//! k = 2 with noise 0.3 and
//! - per-corner jitter of 1e-12 … 1e-3 on a random half of one vertex class
//!   (regular, boundary, singular edge, singular): charts no longer agree
//!   exactly;
//! - 4 slivers at λ = 1e-9 … 1e-15 next to singular vertices (exactly GP).
//!
//! Each case must give the exact expected mesh, or a refusal (`Err` from
//! extract) if it is in [`ALLOW_REFUSAL`]. Cases without a vertex of the
//! jittered class (or without singular vertices for slivers) are skipped
//! and counted. Totals are printed: run, exact, refused (allowed), wrong,
//! skipped. [`KNOWN_FAILING`] cases are run and reported, not asserted
//! ("NOW PASSES: …" when they pass). One seed by default (< 60 s in
//! `--profile ci`); `DUALEX_STRESS_CASES=N` runs seeds 1, 2, … until N
//! cases have been run, for long runs by hand (`DUALEX_STRESS_FIRST_SEED`
//! starts at another seed).

mod mesh_oracle;
use dualex_gen::from_mesh::{self, meshes, FromMeshOptions, Jitter, Slivers, VertexClass};
use mesh_oracle::*;

/// Cases allowed to be refused with an error: jitter of 1e-3 puts the
/// charts 1e-3 apart, above the transition tolerance; extract refuses them
/// in one line ("the charts of … differ by a reflection or a non-grid
/// rotation (mismatch 0.001…)"), as documented for non-GP input.
const ALLOW_REFUSAL: &[&str] = &[
    "cube6/jitter1e-3/Regular",
    "cube6/jitter1e-3/Singular",
    "ngon3/jitter1e-3/Regular",
    "ngon3/jitter1e-3/Boundary",
    "ngon3/jitter1e-3/Singular",
    "ngon5/jitter1e-3/Regular",
    "ngon5/jitter1e-3/Boundary",
    "ngon5/jitter1e-3/Singular",
    "annulus/jitter1e-3/Regular",
    "annulus/jitter1e-3/Boundary",
    "prism5_poles/jitter1e-3/Regular",
    "prism5_poles/jitter1e-3/Singular",
    "cubed_ball/jitter1e-3/Regular",
    "cubed_ball/jitter1e-3/Boundary",
    "cubed_ball/jitter1e-3/SingularEdge",
    "cubed_ball/jitter1e-3/Singular",
    "cylinder3/jitter1e-3/Regular",
    "cylinder3/jitter1e-3/Boundary",
    "cylinder3/jitter1e-3/SingularEdge",
    "cylinder5/jitter1e-3/Regular",
    "cylinder5/jitter1e-3/Boundary",
    "cylinder5/jitter1e-3/SingularEdge",
    "polycube_l/jitter1e-3/Regular",
    "polycube_l/jitter1e-3/Boundary",
];

/// Cases that fail today (see the report printed by the test).
const KNOWN_FAILING: &[&str] = &[];

const CLASSES: [VertexClass; 4] = [
    VertexClass::Regular,
    VertexClass::Boundary,
    VertexClass::SingularEdge,
    VertexClass::Singular,
];

enum Case {
    Jitter(f64, VertexClass),
    Slivers(f64),
}

fn variants() -> Vec<(String, Case)> {
    let mut out = Vec::new();
    for amp in [1e-12, 1e-9, 1e-6, 1e-3] {
        for c in CLASSES {
            out.push((format!("jitter{amp:e}/{c:?}"), Case::Jitter(amp, c)));
        }
    }
    for l in [1e-9, 1e-12, 1e-15] {
        out.push((format!("slivers{l:e}"), Case::Slivers(l)));
    }
    out
}

/// Runs one case: `None` when skipped.
fn run(mesh: &str, three: bool, case: &Case, seed: u64) -> Option<Outcome> {
    let mut o = FromMeshOptions {
        scale: 2,
        noise: 0.3,
        seed,
        ..Default::default()
    };
    let classes = if three {
        let m = meshes::hex_mesh_by_name(mesh)?;
        from_mesh::from_hexes(&m, &o).ok()?.classes
    } else {
        let m = meshes::quad_mesh_by_name(mesh)?;
        from_mesh::from_quads(&m, &o).ok()?.classes
    };
    let has = |c: VertexClass| classes.contains(&c);
    match *case {
        Case::Jitter(amplitude, c) => {
            if !has(c) {
                return None;
            }
            o.jitter = Some(Jitter {
                amplitude,
                classes: vec![c],
                fraction: 0.5,
            });
        }
        Case::Slivers(lambda) => {
            if !has(VertexClass::Singular) && !has(VertexClass::SingularEdge) {
                return None;
            }
            o.slivers = Some(Slivers { count: 4, lambda });
        }
    }
    Some(catch(|| {
        if three {
            hex_case(mesh, &o)
        } else {
            quad_case(mesh, &o)
        }
    }))
}

#[test]
fn singular_configurations_extract_exactly() {
    let wanted: usize = std::env::var("DUALEX_STRESS_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(0);
    let meshes_2d = ["cube6", "ngon3", "ngon5", "annulus", "prism5_poles"];
    let meshes_3d = ["cubed_ball", "cylinder3", "cylinder5", "polycube_l"];
    let all: Vec<(&str, bool)> = meshes_2d
        .iter()
        .map(|m| (*m, false))
        .chain(meshes_3d.iter().map(|m| (*m, true)))
        .collect();
    let (mut run_, mut exact, mut refused, mut skipped) = (0, 0, 0, 0);
    let (mut wrong, mut known, mut now_pass) = (Vec::new(), Vec::new(), Vec::new());
    // `DUALEX_STRESS_FIRST_SEED=S` starts a long run at seed S (to go on
    // from where an earlier run stopped)
    let mut seed: u64 = std::env::var("DUALEX_STRESS_FIRST_SEED")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(1);
    let first = seed;
    loop {
        for &(mesh, three) in &all {
            for (tag, case) in variants() {
                let name = if seed == 1 {
                    format!("{mesh}/{tag}")
                } else {
                    format!("{mesh}/{tag}/seed{seed}")
                };
                let Some(r) = run(mesh, three, &case, seed) else {
                    skipped += 1;
                    eprintln!("skipped       {name}");
                    continue;
                };
                run_ += 1;
                // the allow-list names cases without their seed
                let base = format!("{mesh}/{tag}");
                let is_known = KNOWN_FAILING.contains(&name.as_str());
                match r {
                    Ok(()) if is_known => {
                        eprintln!("NOW PASSES: {name}");
                        now_pass.push(name);
                    }
                    Ok(()) => exact += 1,
                    Err(e)
                        if e.starts_with("refused") && ALLOW_REFUSAL.contains(&base.as_str()) =>
                    {
                        refused += 1;
                        eprintln!("refused (ok)  {name}: {e}");
                    }
                    Err(e) if is_known => {
                        eprintln!("known failing {name}: {e}");
                        known.push(name);
                    }
                    Err(e) => {
                        eprintln!("WRONG         {name}: {e}");
                        wrong.push(name);
                    }
                }
            }
        }
        #[allow(clippy::manual_is_multiple_of)] // `is_multiple_of` needs Rust 1.87
        if wanted > 0 && seed % 20 == 0 {
            // progress of long runs (a killed run still has its totals)
            eprintln!(
                "progress: seed {seed}: {run_} run, {exact} exact, {refused} refused, {} wrong, {skipped} skipped",
                wrong.len()
            );
        }
        seed += 1;
        if run_ >= wanted {
            break;
        }
    }
    eprintln!(
        "stress: seeds {first}–{}: {run_} run, {exact} exact, {refused} refused (allowed), {} wrong, {} known failing, {} now pass, {skipped} skipped",
        seed - 1,
        wrong.len(),
        known.len(),
        now_pass.len()
    );
    assert!(wrong.is_empty(), "wrong (not in KNOWN_FAILING): {wrong:?}");
}
