//! PNG picture of a quad mesh, vertices coloured by valence.
//!
//! Input: a [`QuadMesh`], an output path, a size in pixels. Output: a
//! `size × size` PNG, white background:
//! - quads light grey (`#dcdcdc` at full light) with dark edges (left out
//!   when the quads are under 2 px wide: they would only darken); on a
//!   surface each quad is Lambert-shaded (two-sided, light from the upper
//!   left of the eye) and the quads are painted far to near;
//! - every classified vertex ([`crate::valence`]) a dot in its valence
//!   colour, drawn right after the nearest quad around it, so dots on the
//!   hidden side stay hidden; regular dots are small and drawn only when the
//!   quads are at least 8 px wide, irregular ones are larger.

use std::path::Path;

use dualex_cells::QuadMesh;
use tiny_skia::{FillRule, PathBuilder, Pixmap, Stroke, Transform};

use crate::canvas::{bbox, paint, white, write_png, Fit};
use crate::error::RenderError;
use crate::project::{newell_normal, View};
use crate::valence::{check_quads, valence_classes, ValenceClass};

/// Renders `mesh` to a `size`² PNG at `path` (see the module docs).
/// Errors: a quad referring to a missing vertex, a non-finite position, no
/// quad, a size outside 16..=16384, or the file cannot be written.
pub fn quad_png(mesh: &QuadMesh, path: &Path, size: u32) -> Result<(), RenderError> {
    let pix = draw_quads(mesh, size)?;
    write_png(&pix, path)
}

/// The PNG bytes of [`quad_png`], for the caller to write (errors name no
/// file).
pub fn quad_png_bytes(mesh: &QuadMesh, size: u32) -> Result<Vec<u8>, RenderError> {
    crate::canvas::encode(&draw_quads(mesh, size)?)
}

/// Quads in view coordinates with their paint order.
struct Scene {
    view: Vec<[f64; 3]>,
    /// Quad ids, far to near.
    order: Vec<usize>,
    fit: Fit,
    /// Flat mesh: no shading.
    planar: bool,
    /// Median on-screen edge length in pixels.
    edge_px: f64,
}

/// Draws the picture of [`quad_png`] into a pixmap.
pub(crate) fn draw_quads(mesh: &QuadMesh, size: u32) -> Result<Pixmap, RenderError> {
    check_quads(mesh)?;
    if mesh.cells.is_empty() {
        return Err(RenderError::NoQuads);
    }
    let mut pix = white(size)?;
    let scene = scene(mesh, size);
    let class = valence_classes(mesh);
    // after which painted quad each vertex's dot goes (its nearest quad)
    let mut last = vec![usize::MAX; mesh.positions.len()];
    for (rank, &q) in scene.order.iter().enumerate() {
        for &v in &mesh.cells[q] {
            last[v as usize] = rank;
        }
    }
    let mut dots_after: Vec<Vec<u32>> = vec![Vec::new(); scene.order.len()];
    for (v, &rank) in last.iter().enumerate() {
        if let Some(list) = dots_after.get_mut(rank) {
            list.push(v as u32);
        }
    }
    let width = (0.06 * scene.edge_px).clamp(0.25, 1.6 * f64::from(size) / 1000.0 + 0.4);
    let stroke = Stroke {
        width: width as f32,
        ..Stroke::default()
    };
    let edge_paint = paint([0x30, 0x30, 0x30], 255);
    for (rank, &q) in scene.order.iter().enumerate() {
        let corners = mesh.cells[q].map(|v| scene.view[v as usize]);
        let Some(path) = polygon(&corners.map(|p| scene.fit.px([p[0], p[1]]))) else {
            continue;
        };
        let light = if scene.planar { 1.0 } else { shade(&corners) };
        let grey = (220.0 * light).round() as u8;
        let fill = paint([grey, grey, grey], 255);
        pix.fill_path(&path, &fill, FillRule::Winding, Transform::identity(), None);
        if scene.edge_px >= 2.0 {
            pix.stroke_path(&path, &edge_paint, &stroke, Transform::identity(), None);
        }
        for &v in &dots_after[rank] {
            let c = class[v as usize];
            let p = scene.view[v as usize];
            draw_dot(&mut pix, scene.fit.px([p[0], p[1]]), c, scene.edge_px, size);
        }
    }
    Ok(pix)
}

/// The view, the paint order and the fit of `mesh` (checked, non-empty).
fn scene(mesh: &QuadMesh, size: u32) -> Scene {
    let view = View::fixed(&mesh.positions);
    let pts: Vec<[f64; 3]> = mesh.positions.iter().map(|p| view.apply(p)).collect();
    let used = mesh.cells.iter().flatten().map(|&v| pts[v as usize]);
    let (lo, hi) = bbox(used.map(|p| [p[0], p[1]])).unwrap_or(([0.0; 2], [1.0; 2]));
    let fit = Fit::new(lo, hi, size);
    let depth = |q: usize| {
        mesh.cells[q]
            .iter()
            .map(|&v| pts[v as usize][2])
            .sum::<f64>()
    };
    let mut order: Vec<usize> = (0..mesh.cells.len()).collect();
    if !view.planar {
        order.sort_by(|&a, &b| depth(a).total_cmp(&depth(b)));
    }
    let mut lens: Vec<f64> = mesh
        .cells
        .iter()
        .flat_map(|c| (0..4).map(move |k| (c[k], c[(k + 1) % 4])))
        .map(|(a, b)| {
            let (p, q) = (pts[a as usize], pts[b as usize]);
            ((p[0] - q[0]).powi(2) + (p[1] - q[1]).powi(2)).sqrt() * fit.scale()
        })
        .collect();
    let mid = lens.len() / 2;
    let edge_px = *lens.select_nth_unstable_by(mid, f64::total_cmp).1;
    Scene {
        view: pts,
        order,
        fit,
        planar: view.planar,
        edge_px,
    }
}

/// Brightness in `0.35..=1` of a quad in view coordinates: ambient plus
/// two-sided Lambert with the light towards the upper left of the eye.
fn shade(corners: &[[f64; 3]; 4]) -> f64 {
    let n = newell_normal(corners);
    let l = [-0.3, 0.45, 1.0];
    let len: f64 = l[0] * l[0] + l[1] * l[1] + l[2] * l[2];
    let dot = (n[0] * l[0] + n[1] * l[1] + n[2] * l[2]) / len.sqrt();
    0.35 + 0.65 * dot.abs()
}

/// A closed polygon path; `None` when degenerate to a point or non-finite.
pub(crate) fn polygon(p: &[(f32, f32)]) -> Option<tiny_skia::Path> {
    let mut pb = PathBuilder::new();
    let (first, rest) = p.split_first()?;
    pb.move_to(first.0, first.1);
    for q in rest {
        pb.line_to(q.0, q.1);
    }
    pb.close();
    pb.finish()
}

/// A dot of the valence colour of `c` at `at`, sized from the edge length.
fn draw_dot(pix: &mut Pixmap, at: (f32, f32), c: ValenceClass, edge_px: f64, size: u32) {
    let Some(rgb) = c.rgb() else { return };
    let big = 0.012 * f64::from(size) + 1.0;
    let r = if c == ValenceClass::V4 {
        if edge_px < 8.0 {
            return;
        }
        (0.09 * edge_px).clamp(1.0, 0.4 * big)
    } else {
        (0.3 * edge_px).clamp(2.5, big)
    };
    if let Some(circle) = PathBuilder::from_circle(at.0, at.1, r as f32) {
        let p = paint(rgb, 255);
        pix.fill_path(&circle, &p, FillRule::Winding, Transform::identity(), None);
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_png::{colours, has_colour, read_png};
    use crate::valence::{cube_quads, grid_quads, V3_RGB, V4_RGB, V5_RGB};

    #[test]
    fn cube_shows_valence_three_and_shaded_faces() {
        let path = crate::test_png::temp_path("cube.png");
        quad_png(&cube_quads(), &path, 300).unwrap();
        let pix = read_png(&path);
        assert_eq!((pix.width(), pix.height()), (300, 300));
        assert!(has_colour(&pix, V3_RGB), "no valence-3 blue");
        assert!(has_colour(&pix, V4_RGB), "no valence-4 grey");
        assert!(!has_colour(&pix, V5_RGB), "valence-5 red on a cube");
        // three visible faces with three different shades, plus white
        let greys: Vec<_> = colours(&pix)
            .into_iter()
            .filter(|(c, n)| c[0] == c[1] && c[1] == c[2] && c[0] > 60 && c[0] < 230 && *n > 500)
            .collect();
        assert!(greys.len() >= 3, "{greys:?}");
        let _ = std::fs::remove_file(path);
    }

    #[test]
    fn grid_with_a_valence_five_vertex_shows_red() {
        // a fan of five quads around vertex 0
        let mut mesh = QuadMesh::default();
        mesh.positions.push([0.0; 3]);
        for k in 0..10 {
            let a = std::f64::consts::TAU * k as f64 / 10.0;
            let r = if k % 2 == 0 { 1.0 } else { 1.3 };
            mesh.positions.push([r * a.cos(), r * a.sin(), 0.0]);
        }
        for k in 0..5u32 {
            mesh.cells
                .push([0, 1 + 2 * k, 2 + 2 * k, 1 + (2 * k + 2) % 10]);
        }
        let pix = draw_quads(&mesh, 200).unwrap();
        assert!(has_colour(&pix, V5_RGB));
        assert!(!has_colour(&pix, V3_RGB));
    }

    #[test]
    fn planar_grid_is_flat_grey_with_regular_dots() {
        let pix = draw_quads(&grid_quads(6, 4), 240).unwrap();
        assert!(has_colour(&pix, V4_RGB));
        assert!(has_colour(&pix, [220, 220, 220]));
        assert!(!has_colour(&pix, V3_RGB));
    }

    #[test]
    fn bad_inputs_are_errors() {
        assert!(draw_quads(&QuadMesh::default(), 100).is_err());
        let mut m = grid_quads(1, 1);
        m.cells[0][2] = 7;
        assert!(draw_quads(&m, 100).is_err());
        assert!(draw_quads(&grid_quads(1, 1), 4).is_err());
        // all vertices at one point: drawn, no panic
        let mut m = grid_quads(2, 2);
        m.positions.iter_mut().for_each(|p| *p = [1.0; 3]);
        assert!(draw_quads(&m, 64).is_ok());
    }
}
