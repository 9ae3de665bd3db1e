//! `--png` on quad and inspect, and `dualex view`, as processes: the files
//! exist, have the requested size, are not blank, and show the valence
//! colors (3 blue, 5 red) where the mesh has such vertices. The HTML page is
//! checked to be self-contained; rendering it in headless Chromium is tested
//! in `dualex-render`.

mod common;
use common::*;

/// Width, height and the set of distinct RGB colors of a PNG.
fn png_colors(path: &std::path::Path) -> (u32, u32, std::collections::HashSet<[u8; 3]>) {
    let pix =
        tiny_skia::Pixmap::load_png(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let colors = pix.pixels().iter().map(|p| {
        let c = p.demultiply();
        [c.red(), c.green(), c.blue()]
    });
    (pix.width(), pix.height(), colors.collect())
}

#[test]
fn quad_png_shows_valences() {
    let dir = Scratch::new("png-quad");
    let m = dir.arg("cube.obj");
    assert!(dualex(&["generate", "cube", "-o", &m]).status.success());
    let out = dualex(&[
        "quad",
        &m,
        "-o",
        &dir.arg("q.obj"),
        "--png",
        &dir.arg("q.png"),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    let (w, h, colors) = png_colors(&dir.path("q.png"));
    assert_eq!((w, h), (1000, 1000));
    assert!(colors.len() > 20, "{} colors", colors.len());
    assert!(
        colors.contains(&[0x1f, 0x66, 0xd1]),
        "valence-3 blue present"
    );
    assert!(
        !colors.contains(&[0xd6, 0x27, 0x28]),
        "no valence-5 red on a cube"
    );
}

#[test]
fn inspect_png_shows_reverted_triangles() {
    let dir = Scratch::new("png-map");
    let m = dir.arg("noise.obj");
    assert!(dualex(&["generate", "square_noise", "-o", &m])
        .status
        .success());
    let out = dualex(&["inspect", &m, "--png", &dir.arg("m.png")]);
    assert!(out.status.success(), "{}", text(&out));
    let (w, _, colors) = png_colors(&dir.path("m.png"));
    assert_eq!(w, 1000);
    // purple-ish fill of reverted triangles: red and blue above green
    assert!(
        colors.iter().any(|c| c[0] > c[1] + 40 && c[2] > c[1] + 40),
        "no purple among {} colors",
        colors.len()
    );
}

#[test]
fn view_writes_a_self_contained_page() {
    let dir = Scratch::new("view");
    let m = dir.arg("t.obj");
    assert!(dualex(&["generate", "torus_noise", "-o", &m])
        .status
        .success());
    assert!(dualex(&["quad", &m, "-o", &dir.arg("q.obj")])
        .status
        .success());
    let out = dualex(&["view", &dir.arg("q.obj"), "-o", &dir.arg("q.html")]);
    assert!(out.status.success(), "{}", text(&out));
    let page = std::fs::read_to_string(dir.path("q.html")).expect("page");
    assert!(
        page.contains("<canvas") || page.contains("canvas"),
        "has a canvas"
    );
    assert!(
        !page.contains("http://") && !page.contains("https://"),
        "no network reference"
    );
    // hexes too
    let b = dir.arg("b.hexex");
    assert!(dualex(&["generate", "block", "-o", &b]).status.success());
    assert!(dualex(&["hex", &b, "-o", &dir.arg("h.mesh")])
        .status
        .success());
    let out = dualex(&["view", &dir.arg("h.mesh"), "-o", &dir.arg("h.html")]);
    assert!(out.status.success(), "{}", text(&out));
    assert!(std::fs::metadata(dir.path("h.html")).expect("page").len() > 1000);
}
