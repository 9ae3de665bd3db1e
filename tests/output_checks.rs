//! The CLI never writes a silently wrong mesh: an empty output from a map
//! that covers a grid cell is an error, an output whose topology differs
//! from the input's is a loud warning (even with `-q`), recorded in the
//! stats, and an error with `--strict`; noisy transitions are rounded with
//! a warning. The CLI runs as a process.

mod common;
use common::*;

/// A planar map as OBJ text: the squares of a grid of step `h` over
/// `[x0, x1] × [y0, y1]` (positions = map coordinates), two triangles
/// each, minus the squares whose lower-left corner `keep` refuses;
/// unused vertices are left out.
fn grid_obj(x: [f64; 2], y: [f64; 2], h: f64, keep: impl Fn(f64, f64) -> bool) -> String {
    let (nx, ny) = (
        ((x[1] - x[0]) / h).round() as usize,
        ((y[1] - y[0]) / h).round() as usize,
    );
    let at = |i: usize, j: usize| [x[0] + i as f64 * h, y[0] + j as f64 * h];
    let mut index = std::collections::BTreeMap::new();
    let mut tris = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            let p = at(i, j);
            if !keep(p[0], p[1]) {
                continue;
            }
            let [a, b, c, d] = [(i, j), (i + 1, j), (i + 1, j + 1), (i, j + 1)];
            tris.push([a, b, c]);
            tris.push([a, c, d]);
        }
    }
    for t in &tris {
        for v in t {
            let n = index.len();
            index.entry(*v).or_insert(n);
        }
    }
    let mut order: Vec<_> = index.iter().collect();
    order.sort_by_key(|(_, &k)| k);
    let mut s = String::new();
    for ((i, j), _) in &order {
        let p = at(*i, *j);
        s += &format!("v {} {} 0\n", p[0], p[1]);
    }
    for ((i, j), _) in &order {
        let p = at(*i, *j);
        s += &format!("vt {} {}\n", p[0], p[1]);
    }
    for t in &tris {
        let k = t.map(|v| index[&v] + 1);
        s += &format!("f {0}/{0} {1}/{1} {2}/{2}\n", k[0], k[1], k[2]);
    }
    s
}

fn write(dir: &Scratch, file: &str, text: &str) -> String {
    std::fs::write(dir.path(file), text).expect("write map");
    dir.arg(file)
}

#[test]
fn empty_output_of_a_map_covering_a_cell_is_an_error() {
    let dir = Scratch::new("empty");
    // a strip u ∈ [0.6, 1.4], v ∈ [0, 10]: 8 cells of area, but no
    // half-integer u, so no node with the offset ½
    let map = write(
        &dir,
        "strip.obj",
        &grid_obj([0.6, 1.4], [0.0, 10.0], 0.2, |_, _| true),
    );
    let q = dir.arg("q.obj");
    let out = dualex(&["quad", &map, "-o", &q, "-q"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("empty output: no node found"), "{err}");
    assert!(!dir.path("q.obj").exists(), "nothing written");
    // the offset 0 puts nodes on u = 1: a column of 10 quads
    let out = dualex(&[
        "quad",
        &map,
        "-o",
        &q,
        "--grid-offset",
        "zero",
        "--stats",
        &dir.arg("s.json"),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    let st = json(&dir.path("s.json"));
    assert_eq!(st["output"]["quads"], 10, "{st}");
    assert_eq!(st["topology_matches_input"], true, "{st}");
}

#[test]
fn map_smaller_than_a_cell_gives_an_empty_mesh_with_a_warning() {
    let dir = Scratch::new("tiny");
    let map = write(
        &dir,
        "tiny.obj",
        &grid_obj([0.6, 1.4], [0.6, 1.4], 0.2, |_, _| true),
    );
    let out = dualex(&["quad", &map, "-o", &dir.arg("q.obj")]);
    assert!(out.status.success(), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("less than one grid cell"), "{err}");
}

#[test]
fn topology_mismatch_warns_is_recorded_and_fails_with_strict() {
    let dir = Scratch::new("mismatch");
    // [0.2, 7.2]² with a 0.3 × 0.3 hole at [2.6, 2.9]²: between the isos
    // u, v = 2.5 and 3.5 and away from the output vertex (3, 3), so the
    // quads cannot see it: the output is a disk, the input an annulus
    let inside = |a: f64| (2.55..2.85).contains(&a);
    let map = write(
        &dir,
        "annulus.obj",
        &grid_obj([0.2, 7.2], [0.2, 7.2], 0.1, |x, y| {
            !(inside(x) && inside(y))
        }),
    );
    let stats = dir.arg("s.json");
    let out = dualex(&[
        "quad",
        &map,
        "-o",
        &dir.arg("q.obj"),
        "--stats",
        &stats,
        "-q",
    ]);
    assert!(out.status.success(), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("WARNING") && err.contains("topology differs from the input's"),
        "printed even with -q: {err}"
    );
    assert!(err.contains("Euler characteristic 1 (input 0)"), "{err}");
    assert!(err.contains("boundary components 1 (input 2)"), "{err}");
    let st = json(&dir.path("s.json"));
    assert_eq!(st["output"]["quads"], 49, "{st}");
    assert_eq!(st["topology_matches_input"], false);
    assert_eq!(st["topology"]["input"]["euler"], 0);
    assert_eq!(st["topology"]["input"]["boundary_components"], 2);
    assert_eq!(st["topology"]["output"]["euler"], 1);
    assert_eq!(st["topology"]["output"]["boundary_components"], 1);

    let q2 = dir.arg("strict.obj");
    let out = dualex(&[
        "quad",
        &map,
        "-o",
        &q2,
        "--strict",
        "--stats",
        &dir.arg("s2.json"),
    ]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("--strict") && err.contains("nothing written"),
        "{err}"
    );
    assert!(!dir.path("strict.obj").exists() && !dir.path("s2.json").exists());

    // the full square matches
    let full = write(
        &dir,
        "full.obj",
        &grid_obj([0.2, 7.2], [0.2, 7.2], 0.5, |_, _| true),
    );
    let out = dualex(&[
        "quad",
        &full,
        "-o",
        &dir.arg("f.obj"),
        "--strict",
        "--stats",
        &stats,
    ]);
    assert!(out.status.success(), "{}", text(&out));
    assert_eq!(json(&dir.path("s.json"))["topology_matches_input"], true);
}

#[test]
fn small_residuals_are_rounded_with_a_warning() {
    // two triangles whose charts differ by a translation of `d`
    let m = |d: f64| {
        format!(
            "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n\
             vt 0 0\nvt 1 0\nvt 0 1\nvt {a} 0\nvt {d} 1\nvt {a} 1\n\
             f 1/1 2/2 3/3\nf 2/4 4/6 3/5\n",
            a = 1.0 + d
        )
    };
    let dir = Scratch::new("rounded");
    let map = write(&dir, "r.obj", &m(0.05));
    let stats = dir.arg("s.json");
    let out = dualex(&["quad", &map, "-o", &dir.arg("q.obj"), "--stats", &stats]);
    assert!(out.status.success(), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("warning: rounded 1 transition") && err.contains("5.000e-2"),
        "{err}"
    );
    let st = json(&dir.path("s.json"));
    assert_eq!(st["input"]["transitions_rounded"], 1, "{st}");
    assert!(
        (st["input"]["max_transition_residual"]
            .as_f64()
            .unwrap_or(0.0)
            - 0.05)
            .abs()
            < 1e-9
    );
    // 0.3: refused, with the way out
    let map = write(&dir, "big.obj", &m(0.3));
    let out = dualex(&["quad", &map, "-o", &dir.arg("q2.obj")]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("residual 0.3") && err.contains("--round-transitions"),
        "{err}"
    );
}

/// A disk with a 180° cone at its centre, every chart translated by
/// `(0, ½)`: the cone (a half-integer point, exactly GP: the seam's
/// translation becomes `(0, 1)`) lies on one iso under either grid offset
/// and cannot move.
fn half_cone_on_iso_obj(dir: &Scratch) -> String {
    let (mut map, _) = dualex_gen::singular_disk(2, false, 4, 16, 4.0).expect("disk");
    for tri in &mut map.coords {
        for c in tri {
            c[1] += 0.5;
        }
    }
    let path = dir.path("cone.obj");
    dualex_io::write_tri_map(&path, &map).expect("write map");
    path.display().to_string()
}

#[test]
fn sanitization_leftovers_warn_under_q_and_fail_with_strict() {
    let dir = Scratch::new("leftovers");
    let map = half_cone_on_iso_obj(&dir);
    for offset in ["zero", "half"] {
        let stats = dir.arg(&format!("{offset}.json"));
        let out = dualex(&[
            "quad",
            &map,
            "-o",
            &dir.arg("q.obj"),
            "--grid-offset",
            offset,
            "--stats",
            &stats,
            "-q",
        ]);
        assert!(out.status.success(), "{}", text(&out));
        let st = json(&dir.path(&format!("{offset}.json")));
        let san = &st["sanitize"];
        assert_eq!(san["singular_on_iso"], 1, "{offset}: {san}");
        assert_eq!(
            san["singular_on_iso_kinds"]["180_iso"], 1,
            "{offset}: {san}"
        );
        assert_eq!(san["unresolved"], 0, "{offset}: {san}");
        assert_eq!(san["singular_left_unsnapped"], 0, "{offset}: {san}");
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(
            err.contains("warning")
                && err.contains("sanitization left vertices on the dual grid")
                && err.contains("1 singular on an iso, which cannot move"),
            "printed even with -q: {err}"
        );
    }
    let out = dualex(&["quad", &map, "-o", &dir.arg("s.obj"), "--strict", "-q"]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(
        err.contains("sanitization left") && err.contains("--strict"),
        "{err}"
    );
    assert!(!dir.path("s.obj").exists(), "nothing written");
}

/// `-o` and `--stats` through symbolic links whose targets do not exist
/// yet (issue 24): the targets are created, as `cat > LINK` would, and
/// the links stay links; a relative link is read from the link's folder,
/// a link to a dangling link is followed.
#[cfg(unix)]
#[test]
fn dangling_symlinks_are_written_through() {
    use std::os::unix::fs::symlink;
    let dir = Scratch::new("dangling");
    dir.generate("cube");
    std::fs::create_dir(dir.path("sub")).expect("folder");
    // relative (from the link's folder) and absolute targets, and a chain
    symlink("../q_real.obj", dir.path("sub/q.obj")).expect("link");
    symlink(dir.path("s_real.json"), dir.path("s_mid.json")).expect("link");
    symlink(dir.path("s_mid.json"), dir.path("s.json")).expect("link");
    let out = dualex(&[
        "quad",
        &dir.arg("cube.obj"),
        "-o",
        &dir.arg("sub/q.obj"),
        "--stats",
        &dir.arg("s.json"),
        "-q",
    ]);
    assert!(out.status.success(), "{}", text(&out));
    for link in ["sub/q.obj", "s.json", "s_mid.json"] {
        let meta = std::fs::symlink_metadata(dir.path(link)).expect("link");
        assert!(meta.file_type().is_symlink(), "{link} stays a link");
    }
    assert_eq!(json(&dir.path("s_real.json"))["output"]["quads"], 54);
    let obj = std::fs::read_to_string(dir.path("q_real.obj")).expect("the mesh");
    assert_eq!(obj.lines().filter(|l| l.starts_with("f ")).count(), 54);
    // a dangling link into a missing folder: refused before any work
    symlink(dir.path("nodir/x.json"), dir.path("bad.json")).expect("link");
    let out = dualex(&[
        "quad",
        &dir.arg("cube.obj"),
        "-o",
        &dir.arg("q2.obj"),
        "--stats",
        &dir.arg("bad.json"),
    ]);
    assert_eq!(out.status.code(), Some(1), "{}", text(&out));
    assert!(stderr_of(&out).contains("bad.json"), "{}", text(&out));
    assert!(!dir.path("q2.obj").exists());
}

/// stderr of a run as text.
fn stderr_of(out: &std::process::Output) -> String {
    String::from_utf8_lossy(&out.stderr).into_owned()
}
