//! `dualex inspect --json` as a process: the counts of the shared data's
//! README, singularities of generated closed surfaces.

mod common;
use common::*;

fn inspect(path: &str, extra: &[&str]) -> serde_json::Value {
    let mut args = vec!["inspect", path, "--json"];
    args.extend_from_slice(extra);
    let out = dualex(&args);
    assert!(out.status.success(), "inspect {path}: {}", text(&out));
    serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("inspect {path}: not JSON: {e}: {}", text(&out)))
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn shared_data_reverted_counts_match_the_readme() {
    let Some(root) = shared_data("") else { return };
    let cases = [
        ("qex/fandisk_param.obj", 14454, 9),
        ("qex/duck_miq_4_param.obj", 19720, 18),
        ("qex/duck_miq_8_param.obj", 19720, 92),
        ("directional/spherer-param.obj", 1280, 0),
        ("directional/decimated-knight-param.obj", 1000, 3),
        ("directional/dragon-param-full-seamless.obj", 24984, 549),
        ("directional/horsers-param-full-seamless.obj", 6000, 0),
        ("directional/lilium-param.obj", 6590, 0),
    ];
    for (file, simplices, reverted) in cases {
        let j = inspect(&root.join(file).display().to_string(), &[]);
        assert_eq!(j["simplices"], simplices, "{file}: {j}");
        assert_eq!(j["reverted"], reverted, "{file}: {j}");
        for key in ["degenerate", "max_transition_residual", "singularities"] {
            assert!(j.get(key).is_some(), "{file}: key {key} missing: {j}");
        }
    }
    for (file, tets) in [
        ("hexex/hand_q.hexex", 11472),
        ("hexex/fancy_ring_q.hexex", 14640),
        ("hexex/rockerarm_q.hexex", 20988),
        ("hexex/fancy_ring.hexex", 14640),
    ] {
        let j = inspect(&root.join(file).display().to_string(), &[]);
        assert_eq!(j["simplices"], tets, "{file}: {j}");
        assert!(j.get("singular_edges").is_some(), "{file}: {j}");
    }
    let j = inspect(&root.join("hexex/sphere.hexex").display().to_string(), &[]);
    assert_eq!(j["degenerate"], 2, "sphere: {j}");
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn cut_meshes_are_welded_and_reported() {
    let Some(root) = shared_data("directional") else {
        return;
    };
    let f = root.join("spherer-param.obj").display().to_string();
    let welded = inspect(&f, &[]);
    assert!(
        welded["welded_vertices"].as_u64().unwrap_or(0) > 0,
        "{welded}"
    );
    assert_eq!(welded["boundary_loops"], 0, "{welded}");
    assert_eq!(
        welded["singularities"],
        serde_json::json!({"1/4": 8}),
        "{welded}"
    );
    let raw = inspect(&f, &["--no-weld"]);
    assert_eq!(raw["welded_vertices"], 0);
    assert!(raw["boundary_loops"].as_u64().unwrap_or(0) > 0, "{raw}");
}

#[test]
fn generated_closed_surfaces() {
    let dir = Scratch::new("inspect-gen");
    for (name, sing) in [
        ("cube", serde_json::json!({"1/4": 8})),
        ("torus", serde_json::json!({})),
        ("disk_m3", serde_json::json!({"-3/4": 1})),
        ("disk_m5", serde_json::json!({"-5/4": 1})),
    ] {
        let m = dir.arg(&format!("{name}.obj"));
        assert!(dualex(&["generate", name, "-o", &m]).status.success());
        let j = inspect(&m, &[]);
        assert_eq!(j["singularities"], sing, "{name}: {j}");
        assert_eq!(j["reverted"], 0, "{name}: {j}");
    }
    // a noisy cube: 8 singular vertices of index 1/4 mod 1; where noise folds
    // a one-ring the integer part is unknown and reported separately
    let m = dir.arg("cube_noise.obj");
    assert!(dualex(&["generate", "cube_noise", "-o", &m])
        .status
        .success());
    let j = inspect(&m, &[]);
    assert!(j["reverted"].as_u64().unwrap_or(0) > 0, "{j}");
    assert_eq!(j["singular_vertices"], 8, "{j}");
    let known = j["singularities"]["1/4"].as_u64().unwrap_or(0);
    let unknown = j["singularities_integer_part_unknown"]["1/4"]
        .as_u64()
        .unwrap_or(0);
    assert_eq!(known + unknown, 8, "{j}");
}

#[test]
fn human_readable_report() {
    let dir = Scratch::new("inspect-text");
    let m = dir.arg("c.obj");
    assert!(dualex(&["generate", "cube", "-o", &m]).status.success());
    let out = dualex(&["inspect", &m]);
    assert!(out.status.success(), "{}", text(&out));
    let s = String::from_utf8_lossy(&out.stdout);
    assert!(s.contains("triangles"), "{s}");
    assert!(s.contains("1/4"), "{s}");
}
