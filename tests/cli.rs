//! The command line as a user meets it (issue 13, items 4–12), run as a
//! process: help and version, exit codes, options refused where they do
//! not apply, stdout clean data and the summary on stderr, outputs checked
//! before any work, results said where people look, `generate --list` /
//! `--size`; mesh formats (`view` of `.vtk`, `.ovm` maps and hex meshes)
//! in `formats`; the warning of a map relaxed where it folds in `relax`.

mod common;
#[path = "cli/formats.rs"]
mod formats;
#[path = "cli/relax.rs"]
mod relax;
use common::*;
use std::process::Output;

fn stderr(out: &Output) -> String {
    String::from_utf8_lossy(&out.stderr).to_string()
}

fn stdout(out: &Output) -> String {
    String::from_utf8_lossy(&out.stdout).to_string()
}

/// `generate NAME -o DIR/FILE`, asserting success; the path.
fn generated(dir: &Scratch, name: &str, file: &str) -> String {
    let p = dir.arg(file);
    let out = dualex(&["generate", name, "-o", &p, "-q"]);
    assert!(out.status.success(), "{}", text(&out));
    p
}

#[test]
fn help_version_and_the_subcommand_list() {
    let out = dualex(&[]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    let all = format!("{}{}", stdout(&out), stderr(&out));
    for sub in [
        "quad", "hex", "extrude", "view", "inspect", "generate", "remesh",
    ] {
        assert!(
            all.contains(&format!("  {sub} ")),
            "bare dualex lists {sub}: {all}"
        );
    }
    let out = dualex(&["--version"]);
    assert!(
        out.status.success() && stdout(&out).starts_with("dualex "),
        "{}",
        text(&out)
    );
    let options: &[(&str, &[&str])] = &[
        (
            "remesh",
            &[
                "--quads",
                "--scale",
                "--sharp",
                "--rounding",
                "--map-out",
                "--png",
                "--seed",
                "--stats",
                "--no-fairing",
                "--uv",
                "--strict",
            ],
        ),
        (
            "quad",
            &[
                "--stats",
                "--png",
                "--no-fairing",
                "--grid-offset",
                "--strict",
                "--round-transitions",
                "--no-weld",
                "--seed",
                "--threads",
                "--verbose",
                "--quiet",
            ],
        ),
        (
            "hex",
            &[
                "--stats",
                "--grid-offset",
                "--strict",
                "--round-transitions",
                "--seed",
            ],
        ),
        (
            "extrude",
            &[
                "--layers",
                "--thickness",
                "--quality",
                "--fallback",
                "--no-weld",
                "Steiner",
            ],
        ),
        (
            "inspect",
            &[
                "--json",
                "--png",
                "--no-weld",
                "--round-transitions",
                "--surface",
                "scaled Jacobian",
            ],
        ),
        (
            "generate",
            &[
                "--list",
                "--size",
                "--from-mesh",
                "--scale",
                "--noise",
                "--folds",
                "--half-shift",
                "--seed",
            ],
        ),
        (
            "view",
            &["--output", ".vtk", "--surface", "scaled Jacobian"],
        ),
    ];
    for (sub, opts) in options {
        let out = dualex(&[sub, "--help"]);
        assert!(out.status.success(), "{sub}: {}", text(&out));
        let help = stdout(&out);
        for o in *opts {
            assert!(help.contains(o), "{sub} --help describes {o}: {help}");
        }
    }
}

#[test]
fn usage_errors_exit_2_and_blame_the_option_not_the_file() {
    let dir = Scratch::new("usage");
    let map = generated(&dir, "square_identity", "m.obj");
    let o = dir.arg("o.hexex");
    for args in [
        vec!["extrude", &map, "-o", &o, "--layers", "0"],
        vec!["extrude", &map, "-o", &o, "--thickness", "-1"],
        vec!["quad", &map, "-o", &o, "--grid-offset", "third"],
        vec!["quad", &map, "-o", &o, "-j", "0"],
        vec!["generate", "cube6", "-o", &o, "--noise", "2"],
    ] {
        let out = dualex(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", text(&out));
        let err = stderr(&out);
        assert!(
            !err.contains("m.obj"),
            "{args:?}: the input is not to blame: {err}"
        );
        assert!(err.contains("--"), "{args:?}: names the option: {err}");
    }
    assert!(!dir.path("o.hexex").exists());
}

#[test]
fn options_that_do_not_apply_are_refused() {
    let dir = Scratch::new("refused");
    let map = generated(&dir, "square_identity", "m.obj");
    let hexex = generated(&dir, "block", "b.hexex");
    let o = dir.arg("o.mesh");
    let png = dir.arg("p.png");
    for args in [
        vec!["hex", &hexex, "-o", &o, "--png", &png],
        vec!["hex", &hexex, "-o", &o, "--no-fairing"],
        vec!["hex", &hexex, "-o", &o, "--layers", "2"],
        vec!["view", &o, "-o", &o, "--stats", &png],
        vec!["generate", "cube", "-o", &map, "--png", &png],
        vec!["generate", "cube", "-o", &map, "--scale", "3"],
        vec!["generate", "cube", "-o", &map, "--size", "30"],
        vec!["inspect", &hexex, "--png", &png],
        vec!["quad", &map, "-o", &o, "--layers", "2"],
    ] {
        let out = dualex(&args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", text(&out));
    }
    assert!(!dir.path("o.mesh").exists() && !dir.path("p.png").exists());
}

#[test]
fn stdout_is_data_and_the_summary_is_on_stderr() {
    let dir = Scratch::new("streams");
    let map = generated(&dir, "cube", "c.obj");
    let out = dualex(&["quad", &map, "-o", &dir.arg("q.obj"), "--stats", "-"]);
    assert!(out.status.success(), "{}", text(&out));
    let st: serde_json::Value = serde_json::from_slice(&out.stdout).expect("stdout is the JSON");
    assert_eq!(st["output"]["quads"], 54);
    let err = stderr(&out);
    assert!(
        err.contains("done: 54 quads, 56 vertices, 0 boundary loops, 1 component, scaled Jacobian min 1.00 ->"),
        "{err}"
    );
    let out = dualex(&["quad", &map, "-o", &dir.arg("q.obj")]);
    assert!(out.stdout.is_empty(), "{}", text(&out));
    let out = dualex(&["generate", "cube", "-o", &dir.arg("c2.obj")]);
    assert!(
        out.stdout.is_empty() && stderr(&out).contains("432 triangles"),
        "{}",
        text(&out)
    );
}

#[test]
fn symlinks_and_devices_are_written_through() {
    let dir = Scratch::new("links");
    let map = generated(&dir, "cube", "c.obj");
    std::fs::write(dir.path("real.json"), "old").expect("write");
    std::os::unix::fs::symlink(dir.path("real.json"), dir.path("link.json")).expect("link");
    let out = dualex(&[
        "quad",
        &map,
        "-o",
        &dir.arg("q.obj"),
        "--stats",
        &dir.arg("link.json"),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    let meta = std::fs::symlink_metadata(dir.path("link.json")).expect("link");
    assert!(meta.file_type().is_symlink(), "the link stays a link");
    assert_eq!(json(&dir.path("real.json"))["output"]["quads"], 54);
    let out = dualex(&[
        "quad",
        &map,
        "-o",
        &dir.arg("q2.obj"),
        "--stats",
        "/dev/stdout",
    ]);
    assert!(out.status.success(), "{}", text(&out));
    let st: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON on stdout");
    assert_eq!(st["output"]["quads"], 54);
}

#[test]
fn outputs_are_checked_before_any_work() {
    let dir = Scratch::new("upfront");
    let map = generated(&dir, "cube", "c.obj");
    let q = dir.arg("q.obj");
    let nodir = dir.arg("nodir/s.json");
    for args in [
        vec!["quad", &map, "-o", &q, "--stats", &nodir],
        vec!["quad", &map, "-o", &q, "--png", &nodir],
        vec!["quad", &map, "-o", &nodir.replace(".json", ".obj")],
        vec![
            "extrude",
            &map,
            "-o",
            &nodir.replace(".json", ".hexex"),
            "--fallback",
        ],
    ] {
        let out = dualex(&args);
        assert_eq!(out.status.code(), Some(1), "{args:?}: {}", text(&out));
        let err = stderr(&out);
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains("does not exist"), "{err}");
        assert_eq!(err.matches("nodir").count(), 1, "the path once: {err}");
        assert!(!dir.path("q.obj").exists(), "{args:?}: nothing written");
    }
    // a map that does not parse is still reported as the input's fault
    let out = dualex(&["quad", &dir.arg("missing.obj"), "-o", &q]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
}

#[test]
fn results_are_said_where_people_look() {
    let dir = Scratch::new("said");
    let map = generated(&dir, "cube", "c.obj");
    let stats = dir.arg("s.json");
    let out = dualex(&[
        "quad",
        &map,
        "-o",
        &dir.arg("q.obj"),
        "--stats",
        &stats,
        "-v",
        "-j",
        "1",
    ]);
    assert!(out.status.success(), "{}", text(&out));
    assert_eq!(
        json(&dir.path("s.json"))["input"]["singularities"],
        serde_json::json!({"1/4": 8})
    );
    let err = stderr(&out);
    assert!(
        err.contains("(1 thread)") && !err.contains("1 threads"),
        "{err}"
    );
    assert!(
        err.contains("\n  sanitize ") && err.contains("\nwrite "),
        "a table: {err}"
    );
    assert!(err.lines().count() < 40, "not 110 lines of JSON: {err}");
    assert!(
        !err.contains('{') || err.contains("valence_interior {"),
        "{err}"
    );
    // 3D: singular edges by angle
    let w = generated(&dir, "wedge_p1", "w.hexex");
    let out = dualex(&["hex", &w, "-o", &dir.arg("w.mesh"), "--stats", &stats]);
    assert!(out.status.success(), "{}", text(&out));
    let st = json(&dir.path("s.json"));
    assert!(
        !st["input"]["singularities"]
            .as_object()
            .expect("object")
            .is_empty(),
        "{st}"
    );
    assert!(stderr(&out).contains("hexes,"), "{}", text(&out));
    // rounded transitions named in the done line; the error suggests the option
    let m = |d: f64| {
        format!(
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt {a} 0\nvt {d} 1\nvt {a} 1\n\
             f 1/1 2/2 3/3\nf 2/4 4/6 3/5\n",
            a = 1.0 + d
        )
    };
    std::fs::write(dir.path("r.obj"), m(0.05)).expect("write");
    let out = dualex(&["quad", &dir.arg("r.obj"), "-o", &dir.arg("r_q.obj")]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(
        stderr(&out).contains("1 transition rounded"),
        "{}",
        text(&out)
    );
    std::fs::write(dir.path("big.obj"), m(0.3)).expect("write");
    let out = dualex(&["quad", &dir.arg("big.obj"), "-o", &dir.arg("b_q.obj")]);
    assert!(
        stderr(&out).contains("--round-transitions"),
        "{}",
        text(&out)
    );
}

#[test]
fn the_repair_warning_survives_q() {
    let dir = Scratch::new("subdiv");
    // disk_p1 under the offset 0: a hole only polygons close, made quads
    // by the local repair (a path to the boundary), not by subdividing
    let p = generated(&dir, "disk_p1", "d.obj");
    let q = dir.arg("q.obj");
    let st = dir.arg("s.json");
    let args = [
        "quad",
        &p,
        "-o",
        &q,
        "--grid-offset",
        "zero",
        "--stats",
        &st,
    ];
    let out = dualex(&[&args[..], &["-q"]].concat());
    assert!(out.status.success(), "{}", text(&out));
    let st = json(&dir.path("s.json"));
    assert_eq!(st["repair"]["subdivided"], false, "{st}");
    assert_eq!(st["repair"]["local_paths"], 1, "{st}");
    assert!(
        stderr(&out).contains("1 face that quads cannot represent"),
        "{}",
        text(&out)
    );
    assert!(
        stderr(&out).contains("was made quads along 1 path between them (local repair)"),
        "{}",
        text(&out)
    );
    let out = dualex(&args);
    assert!(
        stderr(&out).contains("(check: repaired locally along 1 path"),
        "{}",
        text(&out)
    );
}

#[test]
fn generate_lists_sizes_and_makes_large_maps() {
    let out = dualex(&["generate", "--list"]);
    assert!(out.status.success(), "{}", text(&out));
    let list = stdout(&out);
    let cube = list
        .lines()
        .find(|l| l.starts_with("cube "))
        .expect("cube listed");
    assert!(
        cube.contains("432 triangles") && cube.contains("cube surface"),
        "{cube}"
    );
    assert!(
        list.lines()
            .any(|l| l.starts_with("block ") && l.contains("tets")),
        "{list}"
    );
    let dir = Scratch::new("size");
    let p = dir.arg("big.obj");
    let out = dualex(&["generate", "square_identity", "--size", "100", "-o", &p]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(stderr(&out).contains("20000 triangles"), "{}", text(&out));
    let p = dir.arg("big.hexex");
    let out = dualex(&["generate", "block", "--size", "10", "-o", &p]);
    assert!(stderr(&out).contains("6000 tets"), "{}", text(&out));
}

#[test]
fn a_map_smaller_than_a_cell_is_not_silent() {
    let dir = Scratch::new("tiny");
    let tiny = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.6 0.6\nvt 1.2 0.6\nvt 0.6 1.2\nf 1/1 2/2 3/3\n";
    std::fs::write(dir.path("t.obj"), tiny).expect("write");
    let out = dualex(&["quad", &dir.arg("t.obj"), "-o", &dir.arg("q.obj"), "-q"]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(
        stderr(&out).contains("less than one grid cell"),
        "even with -q: {}",
        text(&out)
    );
    let out = dualex(&["quad", &dir.arg("t.obj"), "-o", &dir.arg("q.obj")]);
    assert!(stderr(&out).contains("empty mesh"), "{}", text(&out));
}
