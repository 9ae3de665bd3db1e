//! `dualex-tetra` (behind `tools/tetra-identity`): a closed surface
//! tetrahedralized by TetGen for real, with a scaled identity map, gives the
//! expected free-boundary hex block through `dualex hex` — exact and noisy.

mod common;
use common::*;

/// The unit cube's surface, outward triangles.
const CUBE: &str = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n\
f 1 3 2\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 2 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\nf 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n";

fn tetra(args: &[&str]) -> std::process::Output {
    std::process::Command::new(env!("CARGO_BIN_EXE_dualex-tetra"))
        .args(args)
        .output()
        .expect("run dualex-tetra")
}

#[test]
fn a_cube_volume_with_an_identity_map_gives_the_block() {
    let dir = Scratch::new("tetra");
    std::fs::write(dir.path("cube.obj"), CUBE).expect("write");
    for (noise, seed) in [("0", "1"), ("0.15", "2"), ("0.15", "3")] {
        let out = tetra(&[
            &dir.arg("cube.obj"),
            "-o",
            &dir.arg("c.hexex"),
            "--scale",
            "4",
            "--offset",
            "0.2,0.2,0.2",
            "--noise",
            noise,
            "--seed",
            seed,
        ]);
        assert!(out.status.success(), "tetra: {}", text(&out));
        let r = dualex(&[
            "hex",
            &dir.arg("c.hexex"),
            "-o",
            &dir.arg("c.vtk"),
            "--stats",
            &dir.arg("s.json"),
        ]);
        assert!(r.status.success(), "hex: {}", text(&r));
        let st = json(&dir.path("s.json"));
        // a map onto [0.2, 4.2]³: the hexes whose centres i + ½ lie inside
        assert_eq!(st["output"]["hexes"], 64, "noise {noise}: {st}");
        assert_eq!(st["output"]["components"], 1, "noise {noise}");
        assert_eq!(st["output"]["boundary_surfaces"], 1, "noise {noise}");
    }
}

#[test]
fn a_polygon_surface_is_refused() {
    let dir = Scratch::new("tetra-bad");
    std::fs::write(
        dir.path("q.obj"),
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n",
    )
    .expect("write");
    let out = tetra(&[&dir.arg("q.obj"), "-o", &dir.arg("x.hexex")]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(
        String::from_utf8_lossy(&out.stderr).contains("face 0"),
        "{}",
        text(&out)
    );
    assert!(!dir.path("x.hexex").exists());
}
