//! `dualex remesh` fails loudly where it cannot make quads (issue 23):
//!
//! - every option an error message suggests is one the subcommand
//!   accepts, and the suggested command line works (`--round-transitions`,
//!   suggested by the map check that `quad`, `inspect` and `remesh`'s own
//!   extraction run);
//! - (CAD-style tessellations, whose map collapsed until remesh split
//!   their long edges and spread the +1 of a fan cap into quarters, are
//!   `tests/remesh_cad.rs`, a validity test now; the collapse check
//!   itself is a unit test of the facade, `dualex::remesh`);
//! - a target of less than one quad is an error (`empty mesh`), never an
//!   empty file with exit 0.

mod common;
use common::*;

/// The `--options` a message suggests (words starting with `--`).
fn suggested(message: &str) -> Vec<String> {
    message
        .split(|c: char| c.is_whitespace() || c == ';' || c == ',' || c == ')')
        .filter(|w| w.starts_with("--") && w.len() > 2)
        .map(str::to_string)
        .collect()
}

#[test]
fn suggested_options_are_accepted_and_work() {
    let dir = Scratch::new("remesh-hints");
    // two triangles whose charts differ by a translation of 0.3: the map
    // check refuses it and suggests an option
    let m = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n\
             vt 0 0\nvt 1 0\nvt 0 1\nvt 1.3 0\nvt 0.3 1\nvt 1.3 1\n\
             f 1/1 2/2 3/3\nf 2/4 4/6 3/5\n";
    std::fs::write(dir.path("r.obj"), m).expect("write");
    let map = dir.arg("r.obj");
    let out = dir.arg("q.obj");
    let refused = dualex(&["quad", &map, "-o", &out]);
    assert!(!refused.status.success(), "{}", text(&refused));
    let hints = suggested(&String::from_utf8_lossy(&refused.stderr));
    assert_eq!(hints, ["--round-transitions"], "{}", text(&refused));
    let g = dualex(&["generate", "surface_sphere", "-o", &dir.arg("s.obj"), "-q"]);
    assert!(g.status.success(), "{}", text(&g));
    for hint in &hints {
        // the suggested command line, as the user would type it
        let q = dualex(&["quad", &map, "-o", &out, hint]);
        assert!(q.status.success(), "quad {hint}: {}", text(&q));
        let i = dualex(&["inspect", &map, hint]);
        assert!(i.status.success(), "inspect {hint}: {}", text(&i));
        // remesh runs the same map check on its own map: it takes the
        // option and passes it to its extraction
        let r = dualex(&[
            "remesh",
            &dir.arg("s.obj"),
            "-o",
            &dir.arg("r_q.obj"),
            "--quads",
            "100",
            "-q",
            hint,
        ]);
        assert!(r.status.success(), "remesh {hint}: {}", text(&r));
        // every subcommand that runs the map check lists it
        for sub in ["quad", "hex", "inspect", "remesh"] {
            let h = dualex(&[sub, "--help"]);
            let help = String::from_utf8_lossy(&h.stdout);
            assert!(help.contains(hint.as_str()), "{sub} --help lacks {hint}");
        }
    }
}

#[test]
fn less_than_one_quad_is_an_error() {
    let dir = Scratch::new("remesh-empty");
    let input = dir.arg("t.obj");
    let g = dualex(&["generate", "surface_torus", "-o", &input, "-q"]);
    assert!(g.status.success(), "{}", text(&g));
    let out = dir.path("t_q.obj");
    let o = dualex(&[
        "remesh",
        &input,
        "-o",
        &out.display().to_string(),
        "--scale",
        "100",
    ]);
    assert_eq!(o.status.code(), Some(1), "{}", text(&o));
    let err = String::from_utf8_lossy(&o.stderr);
    assert!(
        err.contains(&format!("{input}: empty mesh: the surface (area ")),
        "{err}"
    );
    assert!(!out.exists(), "an empty mesh was written");
}
