//! Mesh formats through the command line: `view` of the `.vtk` files
//! `quad` and `hex` write (and a broken one, refused naming its line), and
//! OpenVolumeMesh `.ovm` tet maps and hex meshes (issue 14).

use super::{generated, stderr};
use crate::common::*;

#[test]
fn view_opens_its_own_vtk_outputs() {
    let dir = Scratch::new("vtk");
    let map = generated(&dir, "cube", "c.obj");
    let out = dualex(&["quad", &map, "-o", &dir.arg("q.vtk"), "-q"]);
    assert!(out.status.success(), "{}", text(&out));
    let out = dualex(&["view", &dir.arg("q.vtk"), "-o", &dir.arg("q.html")]);
    assert!(out.status.success(), "{}", text(&out));
    let b = generated(&dir, "block", "b.hexex");
    let out = dualex(&["hex", &b, "-o", &dir.arg("h.vtk"), "-q"]);
    assert!(out.status.success(), "{}", text(&out));
    let out = dualex(&["view", &dir.arg("h.vtk"), "-o", &dir.arg("h.html")]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(dir.path("q.html").exists() && dir.path("h.html").exists());
    std::fs::write(
        dir.path("bad.vtk"),
        "# vtk DataFile Version 3.0\nx\nASCII\nPOINTS 9999999 double\n",
    )
    .expect("write");
    let out = dualex(&["view", &dir.arg("bad.vtk"), "-o", &dir.arg("bad.html")]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(stderr(&out).contains("bad.vtk: line 4"), "{}", text(&out));
}

/// OpenVolumeMesh through the command line (issue 14): a generated map
/// and an extrusion written as `.ovm` tet maps and read back by `hex` give
/// the same hexes as their `.hexex` twins; hexes written as `.ovm` hold
/// that many polyhedra; `view` says which formats it reads.
#[test]
fn ovm_maps_and_hex_meshes_through_the_command_line() {
    let dir = Scratch::new("ovm");
    let hexes = |map: &str, out: &str| -> u64 {
        let o = dualex(&["hex", map, "-o", &dir.arg(out), "--stats", "-", "-q"]);
        assert!(o.status.success(), "{}", text(&o));
        let stats: serde_json::Value = serde_json::from_slice(&o.stdout).expect("stats JSON");
        stats["output"]["hexes"].as_u64().expect("output.hexes")
    };
    let polyhedra = |file: &str| -> u64 {
        let t = std::fs::read_to_string(dir.path(file)).expect("read the .ovm");
        assert!(t.starts_with("OVM ASCII"), "{file}");
        let mut lines = t.lines().skip_while(|l| l.trim() != "Polyhedra");
        lines.next();
        lines
            .next()
            .and_then(|n| n.trim().parse().ok())
            .expect("polyhedra count")
    };
    for name in ["block", "block_noise", "block_fold"] {
        let a = generated(&dir, name, &format!("{name}.hexex"));
        let b = generated(&dir, name, &format!("{name}.ovm"));
        let n = hexes(&a, &format!("{name}.mesh"));
        assert!(n > 0, "{name}");
        assert_eq!(hexes(&b, &format!("{name}_hex.ovm")), n, "{name}");
        assert_eq!(polyhedra(&format!("{name}_hex.ovm")), n, "{name}");
    }
    let map = generated(&dir, "cube", "cube.obj");
    let q = dualex(&[
        "quad",
        &map,
        "-o",
        &dir.arg("cube_q.obj"),
        "--stats",
        "-",
        "-q",
    ]);
    assert!(q.status.success(), "{}", text(&q));
    let stats: serde_json::Value = serde_json::from_slice(&q.stdout).expect("stats JSON");
    let quads = stats["output"]["quads"].as_u64().expect("output.quads");
    let e = dualex(&["extrude", &map, "-o", &dir.arg("cube.ovm"), "-q"]);
    assert!(e.status.success(), "{}", text(&e));
    assert_eq!(hexes(&dir.arg("cube.ovm"), "cube_hex.ovm"), quads);
    let v = dualex(&["view", &dir.arg("cube_hex.ovm"), "-o", &dir.arg("v.html")]);
    assert_eq!(v.status.code(), Some(1), "{}", text(&v));
    assert!(
        stderr(&v).contains(
            "cube_hex.ovm: view reads quad meshes (.obj, .ply, .vtk) and hex meshes (.mesh, .vtk)"
        ),
        "{}",
        text(&v)
    );
    assert!(!dir.path("v.html").exists());
}
