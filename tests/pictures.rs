//! `--png` on quad and inspect, and `dualex view`, as processes: the files
//! exist, have the requested size, are not blank, and show the valence
//! colors (3 blue, 5 red) where the mesh has such vertices. The HTML page is
//! checked to be self-contained; rendering it in headless Chromium is tested
//! in `dualex-render`. `inspect --png` of a mesh is a histogram with red
//! bars exactly when an element is inverted; `view` pages carry each
//! element's scaled Jacobian for their quality toggle.

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

/// Pixels that are clearly red (the inverted bars; never the blue-grey
/// bars, the grey axes or their anti-aliased edges).
fn red_pixels(path: &std::path::Path) -> (u32, u32, usize) {
    let pix =
        tiny_skia::Pixmap::load_png(path).unwrap_or_else(|e| panic!("{}: {e}", path.display()));
    let red = pix.pixels().iter().filter(|p| {
        let c = p.demultiply();
        c.red() > 150 && c.green() < 90 && c.blue() < 90
    });
    (pix.width(), pix.height(), red.count())
}

#[test]
fn inspect_png_of_a_mesh_is_a_histogram_red_when_inverted() {
    let dir = Scratch::new("png-histogram");
    for flip in [false, true] {
        let (p, q) = quad_grid(flip);
        let faces: Vec<Vec<u32>> = q.iter().map(|c| c.to_vec()).collect();
        write_obj(&dir.path("q.obj"), &p, &faces);
        let png = dir.path("q.png");
        let out = dualex(&["inspect", &dir.arg("q.obj"), "--png", &dir.arg("q.png")]);
        assert!(out.status.success(), "{}", text(&out));
        let (w, h, red) = red_pixels(&png);
        assert_eq!((w, h), (1000, 625));
        assert_eq!(red > 0, flip, "flipped {flip}: {red} red pixels");
    }
    for (inverted, degenerate) in [(false, false), (false, true), (true, false)] {
        let (p, h) = hex_trio(inverted, degenerate);
        write_medit(&dir.path("h.mesh"), &p, &h);
        let out = dualex(&[
            "inspect",
            &dir.arg("h.mesh"),
            "--png",
            &dir.arg("h.png"),
            "--json",
        ]);
        assert!(out.status.success(), "{}", text(&out));
        let (w, _, red) = red_pixels(&dir.path("h.png"));
        assert_eq!(w, 1000);
        assert_eq!(
            red > 0,
            inverted || degenerate,
            "{inverted} {degenerate}: {red} red pixels"
        );
    }
}

/// The JSON embedded in a page written by `dualex view`.
fn page_json(path: &std::path::Path) -> serde_json::Value {
    let html = std::fs::read_to_string(path).expect("page");
    let start = html.find("id=\"mesh\">").expect("no mesh script") + 10;
    let end = start + html[start..].find("</script>").expect("unterminated");
    serde_json::from_str(&html[start..end].replace("<\\/", "</")).expect("bad JSON")
}

/// The values ≤ 0 among the page's quality values, and their count.
fn page_quality(json: &serde_json::Value) -> (usize, usize) {
    let v = json["quality"].as_array().expect("no quality");
    let values: Vec<f64> = v.iter().filter_map(|x| x.as_f64()).collect();
    assert_eq!(values.len(), v.len(), "non-numbers: {v:?}");
    (values.len(), values.iter().filter(|&&x| x <= 0.0).count())
}

#[test]
fn view_pages_carry_the_quality_of_each_element() {
    let dir = Scratch::new("view-quality");
    let (p, q) = quad_grid(true);
    write_obj(
        &dir.path("q.obj"),
        &p,
        &q.iter().map(|c| c.to_vec()).collect::<Vec<_>>(),
    );
    square_surface(&dir.path("down.obj"), false);
    let page = dir.arg("q.html");
    let out = dualex(&["view", &dir.arg("q.obj"), "-o", &page]);
    assert!(out.status.success(), "{}", text(&out));
    let j = page_json(&dir.path("q.html"));
    assert_eq!(page_quality(&j), (9, 1));
    assert!(
        j["quality_note"]
            .as_str()
            .is_some_and(|s| s.contains("own")),
        "{j}"
    );
    let html = std::fs::read_to_string(dir.path("q.html")).expect("page");
    assert!(html.contains("quality-toggle"), "no toggle in the page");
    assert!(!html.contains("http://") && !html.contains("https://"));
    // against a surface facing the other way, the other 8 are inverted
    let out = dualex(&[
        "view",
        &dir.arg("q.obj"),
        "-o",
        &page,
        "--surface",
        &dir.arg("down.obj"),
    ]);
    assert!(out.status.success(), "{}", text(&out));
    assert_eq!(page_quality(&page_json(&dir.path("q.html"))), (9, 8));
    // hexes: one value per hex, each boundary quad names its hex
    let (p, h) = hex_trio(true, true);
    write_medit(&dir.path("h.mesh"), &p, &h);
    let out = dualex(&["view", &dir.arg("h.mesh"), "-o", &dir.arg("h.html")]);
    assert!(out.status.success(), "{}", text(&out));
    let j = page_json(&dir.path("h.html"));
    assert_eq!(page_quality(&j), (3, 2));
    let quad_hex: Vec<u64> = j["quad_hex"]
        .as_array()
        .expect("quad_hex")
        .iter()
        .filter_map(|v| v.as_u64())
        .collect();
    assert_eq!(quad_hex.len(), 18, "3 separate hexes, 6 faces each");
    for hex in 0..3 {
        assert_eq!(
            quad_hex.iter().filter(|&&k| k == hex).count(),
            6,
            "{quad_hex:?}"
        );
    }
}
