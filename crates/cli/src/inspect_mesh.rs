//! `dualex inspect` on a quad or hex mesh: the scaled-Jacobian report.
//!
//! Input: a mesh read by [`crate::quality`], the `inspect` options.
//! Output on stdout, as text or one JSON object:
//! `{"mesh": "quads"|"hexes", "elements", "vertices", "normals":
//! "surface"|"mesh" (quads only), "scaled_jacobian": {elements, inverted,
//! degenerate, min, p5, median}}`; with `--png`, a histogram of the values
//! ([`dualex::render::quality_histogram_png`]).

use dualex::geom::Summary;

use crate::args::InspectArgs;
use crate::error::CliError;
use crate::quality::{elements, hex_quality, quad_quality, Mesh, Normals};
use crate::{outputs, PNG_SIZE};

/// The report of `mesh` read from `name` (see the module docs).
pub fn inspect_mesh(mesh: &Mesh, a: &InspectArgs, name: &str) -> Result<(), CliError> {
    let (values, normals, vertices) = match mesh {
        Mesh::Quads(m) => {
            let (v, n) = quad_quality(m, a.surface.as_deref())?;
            (v, Some(n), m.positions.len())
        }
        Mesh::Hexes(m) => (hex_quality(m), None, m.positions.len()),
    };
    let s = Summary::of(&values);
    let what = elements(mesh);
    if let Some(png) = &a.png {
        let title = format!(
            "scaled jacobian of {what}\n{} inverted, {} degenerate, min {:.3}, median {:.3}",
            s.inverted, s.degenerate, s.min, s.median
        );
        let bytes =
            dualex::render::quality_histogram_png(&values, &title, PNG_SIZE, PNG_SIZE * 5 / 8)
                .map_err(|error| CliError::Render {
                    file: name.to_string(),
                    error,
                })?;
        outputs::write_png(png, &bytes)?;
    }
    if a.json {
        let mut j = serde_json::json!({
            "mesh": if normals.is_some() { "quads" } else { "hexes" },
            "elements": s.elements,
            "vertices": vertices,
            "scaled_jacobian": s.to_json(),
        });
        if let Some(n) = normals {
            j["normals"] = n.key().into();
        }
        println!("{j}");
    } else {
        println!("{}", text(&what, vertices, normals, &s));
    }
    Ok(())
}

/// The text report.
fn text(what: &str, vertices: usize, normals: Option<Normals>, s: &Summary) -> String {
    let mut t = format!("mesh: {what}, {vertices} vertices\n");
    if let Some(n) = normals {
        t.push_str(&format!("normals: {}\n", n.note()));
    }
    t.push_str(&format!(
        "scaled Jacobian:\n  inverted (<= 0): {}\n  degenerate: {}\n  min: {:.4}\n  5th percentile: {:.4}\n  median: {:.4}",
        s.inverted, s.degenerate, s.min, s.p5, s.median
    ));
    t
}
