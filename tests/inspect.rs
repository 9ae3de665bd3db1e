//! `dualex inspect --json` as a process: the counts of the shared data's
//! README, singularities of generated closed surfaces; the scaled
//! Jacobian of quad and hex meshes written by the tests (known inverted
//! and degenerate elements), with and without `--surface`, and their bad
//! input.

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

/// `inspect --json` of a mesh: its `scaled_jacobian` section and `normals`.
fn quality(path: &str, extra: &[&str]) -> (serde_json::Value, serde_json::Value) {
    let j = inspect(path, extra);
    (j["scaled_jacobian"].clone(), j["normals"].clone())
}

#[test]
fn quad_meshes_report_their_inverted_quads() {
    let dir = Scratch::new("inspect-quads");
    let (p, q) = quad_grid(true);
    let faces: Vec<Vec<u32>> = q.iter().map(|c| c.to_vec()).collect();
    let mesh = dir.arg("grid.obj");
    write_obj(&dir.path("grid.obj"), &p, &faces);
    write_vtk(&dir.path("grid.vtk"), &p, &q, 9);
    let (up, down) = (dir.arg("up.obj"), dir.arg("down.obj"));
    square_surface(&dir.path("up.obj"), true);
    square_surface(&dir.path("down.obj"), false);
    // against the surface: the flipped middle quad only, value −1
    let (s, n) = quality(&mesh, &["--surface", &up]);
    assert_eq!(n, "surface");
    assert_eq!(s["elements"], 9, "{s}");
    assert_eq!(s["inverted"], 1, "{s}");
    assert_eq!(s["degenerate"], 0, "{s}");
    assert_eq!(s["min"], -1.0, "{s}");
    assert_eq!(s["median"], 1.0, "{s}");
    // a surface facing the other way: the 8 others are the inverted ones
    let (s, _) = quality(&mesh, &["--surface", &down]);
    assert_eq!(
        (s["inverted"].as_u64(), s["median"].as_f64()),
        (Some(8), Some(-1.0)),
        "{s}"
    );
    // the mesh's own normals: its neighbours outvote the flipped quad
    for file in [&mesh, &dir.arg("grid.vtk")] {
        let (s, n) = quality(file, &[]);
        assert_eq!(n, "mesh", "{file}");
        assert_eq!(
            (s["elements"].as_u64(), s["inverted"].as_u64()),
            (Some(9), Some(1)),
            "{file}: {s}"
        );
    }
    let (p, q) = quad_grid(false);
    write_obj(
        &dir.path("good.obj"),
        &p,
        &q.iter().map(|c| c.to_vec()).collect::<Vec<_>>(),
    );
    let (s, _) = quality(&dir.arg("good.obj"), &[]);
    assert_eq!(
        (s["inverted"].as_u64(), s["min"].as_f64()),
        (Some(0), Some(1.0)),
        "{s}"
    );
    // the text report says where the normals come from
    let out = dualex(&["inspect", &mesh]);
    assert!(out.status.success(), "{}", text(&out));
    let t = String::from_utf8_lossy(&out.stdout);
    assert!(
        t.contains("9 quads") && t.contains("inverted (<= 0): 1"),
        "{t}"
    );
    assert!(
        t.contains("mesh's own") && t.contains("less reliable"),
        "{t}"
    );
    let out = dualex(&["inspect", &mesh, "--surface", &up]);
    assert!(
        !String::from_utf8_lossy(&out.stdout).contains("mesh's own"),
        "{}",
        text(&out)
    );
}

#[test]
fn hex_meshes_report_their_inverted_and_degenerate_hexes() {
    let dir = Scratch::new("inspect-hexes");
    let (p, h) = hex_trio(true, true);
    write_medit(&dir.path("h.mesh"), &p, &h);
    write_vtk(&dir.path("h.vtk"), &p, &h, 12);
    for file in ["h.mesh", "h.vtk"] {
        let j = inspect(&dir.arg(file), &[]);
        assert_eq!(j["mesh"], "hexes", "{file}: {j}");
        assert!(j.get("normals").is_none(), "{file}: {j}");
        let s = &j["scaled_jacobian"];
        assert_eq!(s["elements"], 3, "{file}: {s}");
        assert_eq!(s["inverted"], 2, "{file}: {s}");
        assert_eq!(s["degenerate"], 1, "{file}: {s}");
        assert_eq!(s["min"], -1.0, "{file}: {s}");
        assert_eq!(s["median"], 0.0, "{file}: {s}");
    }
    let (p, h) = hex_trio(false, false);
    write_medit(&dir.path("good.mesh"), &p, &h);
    let (s, _) = quality(&dir.arg("good.mesh"), &[]);
    assert_eq!(
        (s["inverted"].as_u64(), s["min"].as_f64()),
        (Some(0), Some(1.0)),
        "{s}"
    );
}

#[test]
fn bad_meshes_and_surfaces_are_one_line_errors() {
    let dir = Scratch::new("inspect-bad-mesh");
    let (p, q) = quad_grid(false);
    let mut faces: Vec<Vec<u32>> = q.iter().map(|c| c.to_vec()).collect();
    faces[4].push(0);
    write_obj(&dir.path("five.obj"), &p, &faces);
    faces[4].pop();
    write_obj(&dir.path("grid.obj"), &p, &faces);
    square_surface(&dir.path("up.obj"), true);
    write_obj(&dir.path("quads.obj"), &p, &faces);
    let missing = dir.arg("missing.obj");
    let cases: [(Vec<String>, &str, &[&str]); 3] = [
        (
            vec![dir.arg("five.obj")],
            "five.obj",
            &["face 4 has 5 vertices"],
        ),
        (
            vec![dir.arg("grid.obj"), "--surface".into(), missing.clone()],
            "missing.obj",
            &["--surface", "cannot read"],
        ),
        (
            vec![
                dir.arg("grid.obj"),
                "--surface".into(),
                dir.arg("quads.obj"),
            ],
            "quads.obj",
            &["--surface", "face 0 has 4 vertices"],
        ),
    ];
    for (args, file, needles) in cases {
        let mut all = vec!["inspect".to_string()];
        all.extend(args);
        let argv: Vec<&str> = all.iter().map(String::as_str).collect();
        let out = dualex(&argv);
        let err = String::from_utf8_lossy(&out.stderr).to_string();
        assert_eq!(out.status.code(), Some(1), "{file}: {}", text(&out));
        assert_eq!(err.trim_end().lines().count(), 1, "{file}: {err}");
        assert!(err.contains(file), "{file}: names the file: {err}");
        for n in needles {
            assert!(err.contains(n), "{file}: {n:?} missing: {err}");
        }
        assert!(
            !err.contains("panicked") && out.stdout.is_empty(),
            "{}",
            text(&out)
        );
    }
    // --surface on a map or a hex mesh, map options on a mesh: usage errors
    let map = dir.arg("map.obj");
    assert!(dualex(&["generate", "square_identity", "-o", &map])
        .status
        .success());
    let (hp, hh) = hex_trio(false, false);
    write_medit(&dir.path("h.mesh"), &hp, &hh);
    let (up, grid, hex) = (dir.arg("up.obj"), dir.arg("grid.obj"), dir.arg("h.mesh"));
    for args in [
        vec!["inspect", &map, "--surface", &up],
        vec!["inspect", &hex, "--surface", &up],
        vec!["inspect", &grid, "--no-weld"],
        vec!["view", &hex, "-o", &map, "--surface", &up],
    ] {
        let out = dualex(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", text(&out));
    }
}
