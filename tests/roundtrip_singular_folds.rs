//! Round trip mesh → map → mesh with folds centred on singular vertices
//! (`FromMeshOptions::singular_folds`, issue 22): the same fold, in element
//! units, at k = 1, 2 and 3, compared exactly with `M_k` (the oracle of
//! `mesh_oracle`: counts, valences, Euler characteristics, built from the
//! input mesh only).
//!
//! Meshes: hexes: the dense singular meshes (ball cut-outs with padding,
//! the padded notched polycube, the subdivided cubed ball) and the cubed
//! ball (its singular nodes one hex from the boundary); quads: n-gon disks
//! (a centre of valence n), the prism surfaces (poles of valence 3 and n)
//! and the cube surface. Seeds 1..=2 in CI (`DUALEX_FOLDS_SEEDS=N` for
//! N seeds, from `DUALEX_FOLDS_SEED_FROM`, default 1: the long run goes
//! on block by block); `DUALEX_FOLDS_ONLY=substring` runs a subset,
//! `DUALEX_FOLDS_CENTRES=N` folds at N centres instead of 8. The smallest
//! case that needs the relaxed retry (`dualex_segment::relax`):
//! `DUALEX_FOLDS_CENTRES=2 DUALEX_FOLDS_ONLY=ball_hole69/k2/s`.
//!
//! Every outcome is one of exact / refused (exit with an error, nothing
//! written) / wrong (a mesh that differs from `M_k`, or a panic). Any failure
//! outside [`KNOWN_FAILING`] fails the test; the known ones are run and
//! reported with their kind ("NOW PASSES" names the ones to move out).

mod mesh_oracle;
use dualex_gen::from_mesh::{self, meshes, FromMeshOptions, TetSplit};
use mesh_oracle::*;
use std::collections::BTreeMap;
use std::time::Instant;

/// Cases that fail today (issue 22; see docs/messy-cases.md, "Folds
/// centred on singular vertices"): run and reported, not asserted. None
/// now: the refined k ≥ 2 maps of ball_cutout5, ball_hole69 and
/// polycube_notch (degenerate cells) and the quad maps prism5_poles s696
/// and s918 (a pole split) came back exact once the drivers relaxed the
/// folded map and extracted again (`dualex_segment::relax`); ball_cutout4
/// at k ≥ 2 (over half of its volume reverted, refused as reflected
/// charts) once the input check took a map whose signed volume stays
/// positive for a folded one (`TetMap::check_not_reflected`).
const KNOWN_FAILING: &[&str] = &[];

/// Seeds on which the long runs found a quad map coming back wrong: 442,
/// 483, 1209 and 1385 came back exact once other untangling orders were
/// tried (`NodeGraph::untangle_best`); 696 and 918 once the folded map was
/// relaxed (`dualex_segment::relax`).
const QUAD_SEEDS_FOUND: [u64; 6] = [442, 483, 696, 918, 1209, 1385];

/// Fold centres per map (all of them on the smaller meshes);
/// `DUALEX_FOLDS_CENTRES=N` for fewer (two already broke the graph path
/// on the refined ball_hole69 at k = 2, one never did: docs/messy-cases.md).
/// [`KNOWN_FAILING`] is the list for the default 8.
fn centres() -> usize {
    env_usize("DUALEX_FOLDS_CENTRES", 8) as usize
}

fn env_usize(name: &str, default: u64) -> u64 {
    std::env::var(name)
        .ok()
        .and_then(|v| v.parse().ok())
        .unwrap_or(default)
}

fn hex_meshes() -> Vec<String> {
    [
        "ball_hole69",
        "ball_cutout4",
        "ball_cutout5",
        "polycube_notch",
        "cubed_ball_sub",
        "cubed_ball",
    ]
    .map(String::from)
    .to_vec()
}

fn quad_meshes() -> Vec<String> {
    let mut out: Vec<String> = (3..=8).map(|n| format!("ngon{n}")).collect();
    out.extend(["prism3_poles", "prism5_poles", "cube6"].map(String::from));
    out
}

/// The seeds `DUALEX_FOLDS_SEEDS` and `DUALEX_FOLDS_SEED_FROM` ask for, or
/// `default` (then `1..=default`, and `extra`).
fn seeds(default: u64, extra: &[u64]) -> Vec<u64> {
    let n = env_usize("DUALEX_FOLDS_SEEDS", default);
    // the first seed (long runs go on from where the last one stopped)
    let from = env_usize("DUALEX_FOLDS_SEED_FROM", 1);
    let mut out: Vec<u64> = (from..from + n).collect();
    if std::env::var_os("DUALEX_FOLDS_SEEDS").is_none() {
        out.extend(extra);
    }
    out
}

/// `(case name, mesh, options)` for every mesh, k ∈ 1..=3 and seed.
fn cases(
    names: Vec<String>,
    splits: &[TetSplit],
    seeds: &[u64],
) -> Vec<(String, String, FromMeshOptions)> {
    let only = std::env::var("DUALEX_FOLDS_ONLY").unwrap_or_default();
    let mut out = Vec::new();
    for m in names {
        for k in 1..=3 {
            for &tet_split in splits {
                for (seed, magnify) in seeds.iter().flat_map(|&s| [(s, false), (s, true)]) {
                    let (scale, magnify) = if magnify { (1, k) } else { (k, 1) };
                    let o = FromMeshOptions {
                        scale,
                        magnify,
                        singular_folds: centres(),
                        seed,
                        tet_split,
                        ..Default::default()
                    };
                    let centre = if tet_split == TetSplit::Centre {
                        "/centre"
                    } else {
                        ""
                    };
                    let how = if magnify > 1 { "/magnified" } else { "" };
                    let name = format!("{m}/k{k}{how}{centre}/s{seed}");
                    if name.contains(&only) {
                        out.push((name, m.clone(), o));
                    }
                }
            }
        }
    }
    out
}

/// The stats that name the failing stage, in one line.
fn symptoms(st: &Option<serde_json::Value>) -> String {
    let Some(s) = st else {
        return "no stats".into();
    };
    let keys = [
        ("sanitize", "unresolved"),
        ("trace", "inconsistent"),
        ("untangle", "reverted_left"),
        ("output", "folded_collapsed"),
        ("output", "doublet_edges_left"),
        ("repair", "columns_split"),
        ("output", "open_interior_faces"),
        ("output", "hexes"),
    ];
    let mut out = format!("reverted_nodes={}", s["reverted_nodes"]);
    for (a, b) in keys {
        out += &format!(" {b}={}", s[a][b]);
    }
    out + &format!(" untangle={}", s["untangle"])
}

/// An extraction error, or an invalid mesh (which `dualex hex` / `quad`
/// refuse to write: "could not make a valid mesh").
fn refusal(e: &str) -> bool {
    e.starts_with("refused") || e.starts_with("invalid")
}

/// Prints the table; asserts no wrong output and no unknown refusal.
fn report(what: &str, table: &BTreeMap<String, (Outcome, f64)>) {
    let (mut bad, mut now_pass) = (Vec::new(), Vec::new());
    let (mut exact, mut refused, mut wrong) = (0, 0, 0);
    for (name, (r, secs)) in table {
        let known = KNOWN_FAILING.contains(&name.as_str());
        match r {
            Ok(()) => exact += 1,
            Err(e) if refusal(e) => refused += 1,
            Err(_) => wrong += 1,
        }
        match (r, known) {
            (Ok(()), false) => eprintln!("exact         {name} ({secs:.2} s)"),
            (Ok(()), true) => {
                eprintln!("NOW PASSES: {name}");
                now_pass.push(name.clone());
            }
            (Err(e), true) if refusal(e) => {
                eprintln!("known refused {name} ({secs:.2} s): {e}")
            }
            (Err(e), true) => eprintln!("known WRONG   {name} ({secs:.2} s): {e}"),
            (Err(e), _) => {
                let kind = if refusal(e) { "refused" } else { "WRONG" };
                eprintln!("FAIL {kind:8} {name} ({secs:.2} s): {e}");
                bad.push(name.clone());
            }
        }
    }
    let secs: f64 = table.values().map(|r| r.1).sum();
    eprintln!(
        "{what}: {} maps, {exact} exact, {refused} refused, {wrong} wrong, {} now pass ({secs:.1} s)",
        table.len(),
        now_pass.len()
    );
    assert!(bad.is_empty(), "{what}: not exact: {bad:?}");
}

fn timed(f: impl FnOnce() -> Outcome) -> (Outcome, f64) {
    let t = Instant::now();
    let r = catch(f);
    (r, t.elapsed().as_secs_f64())
}

#[test]
fn hexes_folded_at_singular_nodes_come_back_at_every_scale() {
    let mut table = BTreeMap::new();
    let mut built = BTreeMap::new();
    let splits = [TetSplit::LeastVertex, TetSplit::Centre];
    for (name, mesh, o) in cases(hex_meshes(), &splits, &seeds(2, &[])) {
        let m = built
            .entry(mesh.clone())
            .or_insert_with(|| meshes::hex_mesh_by_name(&mesh).expect("a built-in mesh"));
        table.insert(
            name,
            timed(|| {
                let g = from_mesh::from_hexes(m, &o).map_err(|e| format!("generate: {e}"))?;
                let (r, st) = check_hexes_stats(&g);
                r.map_err(|e| format!("{e} [{}]", symptoms(&st)))
            }),
        );
    }
    report("hex folds at singular nodes", &table);
}

#[test]
fn quads_folded_at_singular_vertices_come_back_at_every_scale() {
    let mut table = BTreeMap::new();
    // quads are cheap (2 ms a map): 200 seeds, and those the long runs
    // found a split pole on (fixed by other untangling orders, or not:
    // KNOWN_FAILING)
    let seeds = seeds(200, &QUAD_SEEDS_FOUND);
    for (name, mesh, o) in cases(quad_meshes(), &[TetSplit::LeastVertex], &seeds) {
        table.insert(name, timed(|| quad_case(&mesh, &o)));
    }
    report("quad folds at singular vertices", &table);
}
