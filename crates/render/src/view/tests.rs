use std::path::Path;
use std::process::{Command, Stdio};
use std::time::{Duration, Instant};

use super::*;
use crate::project::newell_normal;
use crate::test_png::{colours, has_near, read_png, temp_path};
use crate::valence::{cube_quads, V3_RGB};
use crate::ValenceClass;

/// An `n³` grid of unit hexes.
pub(crate) fn hex_grid(n: u32) -> HexMesh {
    let mut m = HexMesh::default();
    let id = |i: u32, j: u32, k: u32| (k * (n + 1) + j) * (n + 1) + i;
    for k in 0..=n {
        for j in 0..=n {
            for i in 0..=n {
                m.positions.push([i, j, k].map(f64::from));
            }
        }
    }
    for k in 0..n {
        for j in 0..n {
            for i in 0..n {
                let b = [
                    id(i, j, k),
                    id(i + 1, j, k),
                    id(i + 1, j + 1, k),
                    id(i, j + 1, k),
                ];
                m.cells.push([
                    b[0],
                    b[1],
                    b[2],
                    b[3],
                    b[0] + (n + 1) * (n + 1),
                    b[1] + (n + 1) * (n + 1),
                    b[2] + (n + 1) * (n + 1),
                    b[3] + (n + 1) * (n + 1),
                ]);
            }
        }
    }
    m
}

/// The JSON embedded in a page, parsed.
fn embedded(html: &str) -> serde_json::Value {
    let start = html.find("id=\"mesh\">").expect("no mesh script") + 10;
    let end = start + html[start..].find("</script>").expect("unterminated");
    serde_json::from_str(&html[start..end].replace("<\\/", "</")).expect("bad JSON")
}

#[test]
fn hex_boundary_of_a_cube_grid_is_closed_and_outward() {
    let b = hex_boundary(&hex_grid(2)).unwrap();
    assert_eq!(b.cells.len(), 24);
    assert_eq!(b.positions.len(), 26);
    let classes = valence_classes(&b);
    assert_eq!(
        classes.iter().filter(|&&c| c == ValenceClass::V3).count(),
        8
    );
    assert_eq!(
        classes.iter().filter(|&&c| c == ValenceClass::V4).count(),
        18
    );
    for q in &b.cells {
        let p = q.map(|v| b.positions[v as usize]);
        let n = newell_normal(&p);
        let out: f64 = (0..3)
            .map(|k| n[k] * (p.iter().map(|c| c[k]).sum::<f64>() / 4.0 - 1.0))
            .sum();
        assert!(out > 0.0, "face {q:?} points inwards");
    }
}

#[test]
fn hex_boundary_refuses_bad_ids() {
    let mut m = hex_grid(1);
    m.cells[0][7] = 8;
    assert_eq!(
        hex_boundary(&m).map_err(|e| e.to_string()),
        Err("hex 0 refers to vertex 8, but there are 8 vertices".into())
    );
}

#[test]
fn page_is_self_contained_and_embeds_the_mesh() {
    let mesh = cube_quads();
    let html = view_html(&mesh, "cube </script><b>&").unwrap();
    assert!(!html.contains("http://") && !html.contains("https://"));
    assert!(!html.contains("<script src"));
    assert!(html.contains("<title>cube &lt;/script&gt;&lt;b&gt;&amp;</title>"));
    let json = embedded(&html);
    assert_eq!(json["title"], "cube </script><b>&");
    assert_eq!(json["positions"].as_array().map(Vec::len), Some(3 * 26));
    assert_eq!(json["quads"].as_array().map(Vec::len), Some(4 * 24));
    let valence = json["valence"].as_array().unwrap();
    assert_eq!(valence.iter().filter(|v| v.as_i64() == Some(3)).count(), 8);
    assert_eq!(valence.iter().filter(|v| v.as_i64() == Some(4)).count(), 18);
    assert_eq!(json["positions"][0].as_f64(), Some(-1.0));
}

#[test]
fn page_refuses_bad_mesh() {
    let mut mesh = cube_quads();
    mesh.positions[3][0] = f64::INFINITY;
    assert!(view_html(&mesh, "x").is_err());
}

/// Runs `cmd` until it exits or `limit` passes (then kills it).
fn run_with_limit(cmd: &mut Command, limit: Duration) -> bool {
    let Ok(mut child) = cmd.stdout(Stdio::null()).stderr(Stdio::null()).spawn() else {
        return false;
    };
    let start = Instant::now();
    loop {
        if let Ok(Some(status)) = child.try_wait() {
            return status.success();
        }
        if start.elapsed() > limit {
            let _ = child.kill();
            let _ = child.wait();
            return false;
        }
        std::thread::sleep(Duration::from_millis(100));
    }
}

/// Screenshot of `html` by headless Chromium, `None` when not installed.
fn screenshot(html: &str, name: &str) -> Option<std::path::PathBuf> {
    chromium(html, name, "", "800,600", None)
}

/// Headless Chromium on `html` opened with `hash` appended to its URL, in a
/// window of `size` ("w,h"): a screenshot path, or the DOM after the
/// scripts ran when `dom` is given (written there). `None` when Chromium is
/// not installed.
fn chromium(
    html: &str,
    name: &str,
    hash: &str,
    size: &str,
    dom: Option<&mut String>,
) -> Option<std::path::PathBuf> {
    let found = Command::new("chromium").arg("--version").output().is_ok();
    if !found {
        eprintln!(
            "NOTICE: chromium is not installed: skipping the headless rendering of the viewer"
        );
        return None;
    }
    let dir = temp_path(&format!("chromium-{name}"));
    std::fs::create_dir_all(dir.join("profile")).unwrap();
    let page = dir.join("page.html");
    std::fs::write(&page, html).unwrap();
    let shot = dir.join("out.png");
    let url = format!("file://{}{hash}", page.display());
    let what = match dom {
        Some(_) => "--dump-dom".to_string(),
        None => format!("--screenshot={}", shot.display()),
    };
    let mut cmd = Command::new("chromium");
    cmd.args([
        "--headless",
        "--disable-gpu",
        "--use-angle=swiftshader",
        "--enable-unsafe-swiftshader",
        "--no-sandbox",
        "--disable-background-networking",
        "--no-first-run",
        "--disable-component-update",
        "--disable-sync",
        &format!("--user-data-dir={}", dir.join("profile").display()),
        &what,
        &format!("--window-size={size}"),
        &url,
    ]);
    if let Some(out) = dom {
        let o = cmd.stderr(Stdio::null()).output().expect("chromium");
        assert!(o.status.success(), "chromium failed on {}", page.display());
        *out = String::from_utf8_lossy(&o.stdout).into_owned();
        return Some(dir);
    }
    let ok = run_with_limit(&mut cmd, Duration::from_secs(120));
    assert!(ok, "chromium failed or timed out on {}", page.display());
    Some(shot)
}

fn check_screenshot(shot: &Path) {
    let pix = read_png(shot);
    assert_eq!((pix.width(), pix.height()), (800, 600));
    let cols = colours(&pix);
    assert!(cols.len() >= 20, "blank screenshot: {} colours", cols.len());
    assert!(
        has_near(&pix, V3_RGB, 6),
        "no valence-3 dot in the screenshot"
    );
    // shaded faces: several distinct greys covering a fair share of the picture
    let grey: usize = cols
        .iter()
        .filter(|(c, _)| c[0] == c[1] && c[1] == c[2] && (60..235).contains(&c[0]))
        .map(|(_, n)| n)
        .sum();
    assert!(grey > 800 * 600 / 20, "faces cover {grey} pixels only");
}

#[test]
fn chromium_renders_the_quad_viewer() {
    let html = view_html(&cube_quads(), "cube").unwrap();
    if let Some(shot) = screenshot(&html, "quads") {
        check_screenshot(&shot);
        if std::env::var_os("DUALEX_KEEP_SCREENSHOT").is_none() {
            let _ = std::fs::remove_dir_all(shot.parent().unwrap());
        }
    }
}

#[test]
fn chromium_renders_the_hex_viewer() {
    let html = view_html_hex(&hex_grid(3), "hexes").unwrap();
    if let Some(shot) = screenshot(&html, "hexes") {
        check_screenshot(&shot);
        let _ = std::fs::remove_dir_all(shot.parent().unwrap());
    }
}

#[test]
fn hex_page_embeds_hexes_and_boundary_on_the_same_ids() {
    let mesh = hex_grid(2);
    let json = embedded(&view_html_hex(&mesh, "h").unwrap());
    assert_eq!(json["hexes"].as_array().map(Vec::len), Some(8 * 8));
    assert_eq!(json["hex_faces"].as_array().map(Vec::len), Some(6));
    assert_eq!(json["positions"].as_array().map(Vec::len), Some(3 * 27));
    assert_eq!(json["quads"].as_array().map(Vec::len), Some(4 * 24));
    let valence = json["valence"].as_array().unwrap();
    // the centre vertex (13) is inside: not marked
    assert_eq!(valence[13].as_i64(), Some(-1));
    assert_eq!(valence.iter().filter(|v| v.as_i64() == Some(3)).count(), 8);
    let quad_json = embedded(&view_html(&cube_quads(), "q").unwrap());
    assert!(quad_json.get("hexes").is_none());
}

#[test]
fn chromium_hex_viewer_says_hexes_and_cuts() {
    let html = view_html_hex(&hex_grid(3), "hexes").unwrap();
    let mut dom = String::new();
    let Some(dir) = chromium(&html, "hex-dom", "", "800,600", Some(&mut dom)) else {
        return;
    };
    let _ = std::fs::remove_dir_all(dir);
    assert!(dom.contains("27 hexes (54 boundary quads)"), "{dom}");
    assert!(dom.contains("id=\"cut-at\""), "no cut slider");
    assert!(
        dom.contains("<details id=\"panel\" open"),
        "panel collapsed"
    );
    let whole = chromium(&html, "hex-whole", "", "800,600", None).unwrap();
    let cut = chromium(&html, "hex-cut", "#cut=z:0.5", "800,600", None).unwrap();
    let (a, b) = (read_png(&whole), read_png(&cut));
    check_screenshot(&whole);
    let differ = a
        .pixels()
        .iter()
        .zip(b.pixels())
        .filter(|(p, q)| p != q)
        .count();
    assert!(
        differ > 800 * 600 / 50,
        "the cut changed {differ} pixels only"
    );
    // the cut face has its 3 × 3 grid of edges, drawn as quads: GL lines,
    // which software rendering partly drops there, gave 988 edge pixels
    // in the cut picture (1484 whole), the quads give about 1400 (2200)
    let ink = |p: &tiny_skia::Pixmap| {
        let edge = p.pixels().iter().filter(|c| {
            [c.red(), c.green(), c.blue()]
                .iter()
                .all(|&x| x.abs_diff(48) <= 8)
        });
        edge.count()
    };
    let (ink_a, ink_b) = (ink(&a), ink(&b));
    eprintln!("edge pixels: whole {ink_a}, cut {ink_b}");
    assert!(
        ink_b > 1200,
        "edges missing: {ink_b} edge pixels (whole: {ink_a})"
    );
    for shot in [whole, cut] {
        if std::env::var_os("DUALEX_KEEP_SCREENSHOT").is_none() {
            let _ = std::fs::remove_dir_all(shot.parent().unwrap());
        } else {
            eprintln!("kept {}", shot.display());
        }
    }
}

#[test]
fn chromium_small_window_collapses_the_panel() {
    let html = view_html_hex(&hex_grid(2), "hexes").unwrap();
    let mut dom = String::new();
    let Some(dir) = chromium(&html, "small-dom", "", "400,300", Some(&mut dom)) else {
        return;
    };
    let _ = std::fs::remove_dir_all(dir);
    assert!(dom.contains("<details id=\"panel\">"), "panel open");
}

#[test]
fn quality_is_embedded_per_quad_and_per_hex() {
    let mesh = cube_quads();
    let mut values = vec![1.0; mesh.cells.len()];
    values[3] = -0.5;
    values[4] = -1e-9;
    let q = Quality {
        values: &values,
        note: "normals: the mesh's own",
    };
    let json = embedded(&view_html_quality(&mesh, "q", &q).unwrap());
    let got: Vec<f64> = json["quality"]
        .as_array()
        .unwrap()
        .iter()
        .filter_map(|v| v.as_f64())
        .collect();
    assert_eq!(got.len(), 24);
    assert_eq!(got.iter().filter(|&&v| v <= 0.0).count(), 2, "{got:?}");
    assert_eq!(json["quality_note"], "normals: the mesh's own");
    assert!(json.get("quad_hex").is_none());
    // hexes: one value per hex, each boundary quad names its hex
    let hexes = hex_grid(2);
    let hv: Vec<f64> = (0..8).map(|h| h as f64 / 8.0).collect();
    let q = Quality {
        values: &hv,
        note: "",
    };
    let json = embedded(&view_html_hex_quality(&hexes, "h", &q).unwrap());
    assert_eq!(json["quality"].as_array().map(Vec::len), Some(8));
    let quad_hex = json["quad_hex"].as_array().unwrap();
    assert_eq!(quad_hex.len(), 24);
    // each of the 8 corner hexes of a 2³ grid has 3 boundary faces
    for h in 0..8 {
        assert_eq!(quad_hex.iter().filter(|v| v.as_u64() == Some(h)).count(), 3);
    }
    // no quality, no toggle data
    assert!(embedded(&view_html_hex(&hexes, "h").unwrap())
        .get("quality")
        .is_none());
}

#[test]
fn quality_of_the_wrong_length_or_not_finite_is_refused() {
    let mesh = cube_quads();
    let short = Quality {
        values: &[1.0; 3],
        note: "",
    };
    assert_eq!(
        view_html_quality(&mesh, "q", &short)
            .unwrap_err()
            .to_string(),
        "3 quality values for 24 quads"
    );
    let mut values = vec![1.0; 8];
    values[5] = f64::NAN;
    let nan = Quality {
        values: &values,
        note: "",
    };
    assert_eq!(
        view_html_hex_quality(&hex_grid(2), "h", &nan)
            .unwrap_err()
            .to_string(),
        "hex 5: its quality is not a number"
    );
}

/// Clearly red pixels right of the panel (whose legend has a red swatch)
/// in a Chromium screenshot of `html` opened with `hash` (`#quality`:
/// the quality colouring on); `None` without Chromium.
fn red_right_of_panel(html: &str, name: &str, hash: &str) -> Option<usize> {
    let shot = chromium(html, name, hash, "800,600", None)?;
    let pix = read_png(&shot);
    let w = pix.width() as usize;
    let n = pix
        .pixels()
        .iter()
        .enumerate()
        .filter(|(i, c)| {
            let (r, g, b) = (c.red() as u32, c.green() as u32, c.blue() as u32);
            i % w >= 300 && r > 60 && 100 * g < 45 * r && 100 * b < 45 * r
        })
        .count();
    if std::env::var_os("DUALEX_KEEP_SCREENSHOT").is_none() {
        let _ = std::fs::remove_dir_all(shot.parent().unwrap());
    } else {
        eprintln!("kept {}", shot.display());
    }
    Some(n)
}

#[test]
fn chromium_quality_colouring_shows_inverted_hexes_red() {
    let mesh = hex_grid(3);
    let mut values = vec![0.9; mesh.cells.len()];
    let page = |values: &[f64]| {
        let q = Quality { values, note: "" };
        view_html_hex_quality(&mesh, "hexes", &q).unwrap()
    };
    let Some(none) = red_right_of_panel(&page(&values), "quality-valid", "#quality") else {
        return;
    };
    assert_eq!(none, 0, "red pixels without an inverted hex");
    // the 8 corner hexes (i, j, k in {0, 2}): some are in view whatever
    // the camera
    for h in [0, 2, 6, 8, 18, 20, 24, 26] {
        values[h] = -0.3;
    }
    let some = red_right_of_panel(&page(&values), "quality-inverted", "#quality").unwrap_or(0);
    assert!(some > 500, "the inverted hexes show {some} red pixels");
}

#[test]
fn chromium_quality_colouring_shows_inverted_quads_red() {
    let mesh = cube_quads();
    // every other quad inverted (value 0 counts): some face the camera
    let values: Vec<f64> = (0..mesh.cells.len())
        .map(|q| if q % 2 == 0 { 0.0 } else { 0.7 })
        .collect();
    let q = Quality {
        values: &values,
        note: "normals: the mesh's own",
    };
    let html = view_html_quality(&mesh, "cube", &q).unwrap();
    let Some(red) = red_right_of_panel(&html, "quality-quads", "#quality") else {
        return;
    };
    assert!(red > 500, "the inverted quads show {red} red pixels");
    // the same page with the valence colouring (no #quality): no red
    // faces, and no valence-5 dots on a cube
    let off = red_right_of_panel(&html, "quality-off", "").unwrap_or(usize::MAX);
    assert_eq!(off, 0, "red without the toggle");
}
