//! Bad input never panics: every malformed file gives a one-line error that
//! names the file and the line or element, a non-zero exit code, and no
//! output file.

mod common;
use common::*;

const GOOD_TRI: &str =
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.2 0.2\nvt 3.2 0.2\nvt 0.2 3.2\nf 1/1 2/2 3/3\n";

/// Runs `quad` (or `inspect` for .hexex) on a file with `content`; asserts
/// failure, a one-line message containing every `needles`, no output.
fn fails(file: &str, content: &[u8], needles: &[&str]) {
    let dir = Scratch::new(&format!("bad-{}", file.replace('.', "_")));
    let input = dir.path(file);
    std::fs::write(&input, content).expect("write input");
    let out_path = dir.path("out.obj");
    let input_s = input.display().to_string();
    let out_s = out_path.display().to_string();
    let out = if file.ends_with(".hexex") {
        dualex(&["inspect", &input_s])
    } else {
        dualex(&[
            "quad",
            &input_s,
            "-o",
            &out_s,
            "--stats",
            &dir.arg("s.json"),
        ])
    };
    let err = String::from_utf8_lossy(&out.stderr).to_string();
    assert_eq!(out.status.code(), Some(1), "{file}: {}", text(&out));
    assert_eq!(err.trim_end().lines().count(), 1, "{file}: one line: {err}");
    assert!(err.contains(file), "{file}: names the file: {err}");
    for n in needles {
        assert!(
            err.contains(n),
            "{file}: message should contain {n:?}: {err}"
        );
    }
    assert!(!err.contains("panicked"), "{file}: {err}");
    assert!(!out_path.exists(), "{file}: an output file was written");
    assert!(
        !dir.path("s.json").exists(),
        "{file}: a stats file was written"
    );
    let leftovers: Vec<_> = std::fs::read_dir(&dir.0)
        .expect("dir")
        .filter_map(|e| e.ok())
        .collect();
    assert_eq!(leftovers.len(), 1, "{file}: temp files left: {leftovers:?}");
}

#[test]
fn empty_and_garbage() {
    fails("empty.obj", b"", &["no triangles"]);
    fails(
        "garbage.obj",
        &[0u8, 159, 146, 150, 1, 2, 3, 0, 255, 254],
        &[],
    );
    fails("garbage.ply", b"\x7fELF\x02\x01\x01\0\0\0", &[]);
    fails("comments.obj", b"# nothing\n\n", &["no triangles"]);
}

#[test]
fn missing_texture_coordinates() {
    fails(
        "novt.obj",
        b"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n",
        &["line 4", "texture"],
    );
}

#[test]
fn non_finite_numbers() {
    fails(
        "nan.obj",
        GOOD_TRI.replace("v 1 0 0", "v nan 0 0").as_bytes(),
        &["line 2"],
    );
    fails(
        "inf.obj",
        GOOD_TRI.replace("vt 3.2 0.2", "vt inf 0.2").as_bytes(),
        &["line 5"],
    );
}

#[test]
fn indices_out_of_range() {
    fails(
        "range.obj",
        GOOD_TRI
            .replace("f 1/1 2/2 3/3", "f 1/1 2/2 9/3")
            .as_bytes(),
        &["line 7"],
    );
    fails(
        "vtrange.obj",
        GOOD_TRI
            .replace("f 1/1 2/2 3/3", "f 1/1 2/2 3/7")
            .as_bytes(),
        &["line 7"],
    );
}

#[test]
fn polygons_are_rejected() {
    let quad =
        "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n";
    fails("poly.obj", quad.as_bytes(), &["line 9", "triangles"]);
}

#[test]
fn non_manifold_and_misoriented() {
    let fan = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nvt 0 0\n\
               f 1/1 2/1 3/1\nf 2/1 1/1 4/1\nf 1/1 2/1 5/1\n";
    fails("nonmanifold.obj", fan.as_bytes(), &["non-manifold"]);
    let flip = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nvt 1 1\n\
                f 1/1 2/2 3/3\nf 2/2 3/3 4/4\n";
    fails("orientation.obj", flip.as_bytes(), &["orientation"]);
}

#[test]
fn non_grid_preserving_map() {
    // two triangles whose charts differ by a translation of 0.3
    let m = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n\
             vt 0 0\nvt 1 0\nvt 0 1\nvt 1.3 0\nvt 0.3 1\nvt 1.3 1\n\
             f 1/1 2/2 3/3\nf 2/4 4/6 3/5\n";
    fails("residual.obj", m.as_bytes(), &["residual"]);
    // with --round-transitions it is accepted and the snap reported
    let dir = Scratch::new("round");
    std::fs::write(dir.path("r.obj"), m).expect("write");
    let out = dualex(&[
        "quad",
        &dir.arg("r.obj"),
        "-o",
        &dir.arg("q.obj"),
        "--round-transitions",
        "--stats",
        &dir.arg("s.json"),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(
        json(&dir.path("s.json"))["input"]["snapped_transitions"]
            .as_u64()
            .unwrap_or(0)
            > 0
    );
}

#[test]
fn ply_absurd_count_and_truncation() {
    let header = "ply\nformat binary_little_endian 1.0\nelement vertex 100000000000000\n\
                  property float x\nproperty float y\nproperty float z\n\
                  element face 1\nproperty list uchar int vertex_indices\n\
                  property list uchar float texcoord\nend_header\n";
    fails("absurd.ply", header.as_bytes(), &[]);
    let mut trunc = header.replace("100000000000000", "3").into_bytes();
    trunc.extend_from_slice(&[0u8; 20]);
    fails("truncated.ply", &trunc, &[]);
}

#[test]
fn hexex_broken_files() {
    let good = "4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1\n0 1 2 3 0 0 0 1 0 0 0 1 0 0 0 1\n";
    fails(
        "truncated.hexex",
        &good.as_bytes()[..good.len() - 8],
        &["tets"],
    );
    fails("absurd.hexex", b"99999999999999\n0 0 0\n", &[]);
    fails(
        "index.hexex",
        good.replace("0 1 2 3", "0 1 2 7").as_bytes(),
        &["tet 0"],
    );
    fails(
        "float_index.hexex",
        good.replace("0 1 2 3", "0 1 2.5 3").as_bytes(),
        &["tet 0"],
    );
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn shared_broken_hexex_files() {
    let Some(root) = shared_data("hexex") else {
        return;
    };
    for f in [
        "minimal_missing_tets.hexex",
        "minimal_missing_uvw.hexex",
        "minimal_missing_vertices.hexex",
        "minimal_invalid_charts.hexex",
    ] {
        let content = std::fs::read(root.join(f)).expect("read");
        fails(f, &content, &[]);
    }
}

#[test]
fn unknown_output_extension_writes_nothing() {
    let dir = Scratch::new("ext");
    std::fs::write(dir.path("m.obj"), GOOD_TRI).expect("write");
    let out = dualex(&["quad", &dir.arg("m.obj"), "-o", &dir.arg("q.xyz")]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(!dir.path("q.xyz").exists());
}

#[test]
fn usage_errors() {
    for args in [&["frobnicate"][..], &["quad", "--bogus"], &[]] {
        let out = dualex(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}: {}", text(&out));
    }
}
