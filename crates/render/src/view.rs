//! A self-contained HTML page to orbit a quad mesh, or a hex mesh with a cut plane.
//!
//! Input: a [`QuadMesh`] (or a [`HexMesh`], shown by [`hex_boundary`]) and a
//! title. Output: one HTML string with the mesh embedded as JSON
//! (`<script type="application/json" id="mesh">`) and the viewer of
//! `viewer.js` inline: no network, no external script. The JSON holds
//! `positions` (flat `x y z`, f32 precision), `quads` (flat corner ids),
//! `valence` (one code per vertex, [`crate::ValenceClass::code`]) and `title`;
//! for a hex mesh also `hexes` (flat, 8 ids each) and `hex_faces` (the 6
//! faces of a hex as corner numbers), `quads` being its boundary on the
//! same vertex ids (interior vertices: valence code −1). The page then
//! says the hex count and offers a cut plane (axis and slider).
//!
//! With per-element quality ([`Quality`]: [`view_html_quality`],
//! [`view_html_hex_quality`]) the JSON also holds `quality` (one value
//! per quad, or per hex) and `quality_note`, and for a hex mesh
//! `quad_hex` (the hex of each boundary quad); the page then offers a
//! toggle (button or key `q`, `#quality` in the URL) between the valence
//! dots and elements coloured by quality (≤ 0 red).
//!
//! Invariant: the embedded JSON contains no `</` (escaped as `<\/`), so the
//! page's structure cannot be broken by a title.

use std::collections::HashMap;
use std::fmt::Write;

use dualex_cells::{HexMesh, QuadMesh};

use crate::error::RenderError;
use crate::valence::{check_quads, valence_classes};

const VIEWER_JS: &str = include_str!("viewer.js");

use dualex_cells::cells::HEX_FACES;

/// Per-element quality to colour the elements by (see the module docs).
#[derive(Clone, Copy, Debug)]
pub struct Quality<'a> {
    /// One value per quad of a quad mesh, or per hex of a hex mesh
    /// (the scaled Jacobian: ≤ 0 is inverted).
    pub values: &'a [f64],
    /// Shown under the legend, e.g. where the quad normals come from.
    pub note: &'a str,
}

impl Quality<'_> {
    /// Checks one finite value per element.
    fn check(
        &self,
        elements: usize,
        one: &'static str,
        many: &'static str,
    ) -> Result<(), RenderError> {
        if self.values.len() != elements {
            return Err(RenderError::QualityCount {
                values: self.values.len(),
                elements,
                many,
            });
        }
        match self.values.iter().position(|v| !v.is_finite()) {
            Some(element) => Err(RenderError::QualityNotNumber { one, element }),
            None => Ok(()),
        }
    }
}

/// The page showing `mesh` (see the module docs). Errors: a quad refers to
/// a missing vertex, or a position is not finite.
pub fn view_html(mesh: &QuadMesh, title: &str) -> Result<String, RenderError> {
    check_quads(mesh)?;
    let json = mesh_json(mesh, title, None, None);
    Ok(page(&html_escape(title), &json))
}

/// [`view_html`] with a quality value per quad to colour them by.
/// Errors: also a count of values other than the quads', a value not
/// finite.
pub fn view_html_quality(
    mesh: &QuadMesh,
    title: &str,
    quality: &Quality,
) -> Result<String, RenderError> {
    check_quads(mesh)?;
    quality.check(mesh.cells.len(), "quad", "quads")?;
    let json = mesh_json(mesh, title, None, Some((quality, None)));
    Ok(page(&html_escape(title), &json))
}

/// The page showing the hex mesh `mesh`: its boundary quads with their
/// valences, the hex count, and a cut plane to look inside (see the
/// module docs). Errors: a hex refers to a missing vertex, or a position
/// is not finite.
pub fn view_html_hex(mesh: &HexMesh, title: &str) -> Result<String, RenderError> {
    hex_page(mesh, title, None)
}

/// [`view_html_hex`] with a quality value per hex; the boundary faces
/// (and the faces a cut exposes) take their hex's. Errors: also a count
/// of values other than the hexes', a value not finite.
pub fn view_html_hex_quality(
    mesh: &HexMesh,
    title: &str,
    quality: &Quality,
) -> Result<String, RenderError> {
    quality.check(mesh.cells.len(), "hex", "hexes")?;
    hex_page(mesh, title, Some(quality))
}

fn hex_page(mesh: &HexMesh, title: &str, quality: Option<&Quality>) -> Result<String, RenderError> {
    let (cells, hex_of) = boundary_faces(mesh)?;
    let boundary = QuadMesh {
        positions: mesh.positions.clone(),
        cells,
    };
    check_quads(&boundary)?;
    let quality = quality.map(|q| (q, Some(hex_of.as_slice())));
    let json = mesh_json(&boundary, title, Some(mesh), quality);
    Ok(page(&html_escape(title), &json))
}

/// The embedded JSON (see the module docs), `</` escaped; `quality`
/// with, for a hex mesh, the hex of each boundary quad.
fn mesh_json(
    mesh: &QuadMesh,
    title: &str,
    hexes: Option<&HexMesh>,
    quality: Option<(&Quality, Option<&[u32]>)>,
) -> String {
    let class = valence_classes(mesh);
    let mut json = String::with_capacity(32 * mesh.positions.len() + 24 * mesh.cells.len());
    json.push_str("{\"title\":");
    json.push_str(&serde_json::Value::from(title).to_string());
    json.push_str(",\"positions\":[");
    let coords = mesh.positions.iter().flatten();
    join(&mut json, coords.map(|&x| x as f32), |s, x| {
        write!(s, "{x}")
    });
    json.push_str("],\"quads\":[");
    join(&mut json, mesh.cells.iter().flatten(), |s, v| {
        write!(s, "{v}")
    });
    json.push_str("],\"valence\":[");
    join(&mut json, class.iter().map(|c| c.code()), |s, c| {
        write!(s, "{c}")
    });
    json.push(']');
    if let Some(h) = hexes {
        json.push_str(",\"hexes\":[");
        join(&mut json, h.cells.iter().flatten(), |s, v| write!(s, "{v}"));
        json.push_str("],\"hex_faces\":");
        json.push_str(&serde_json::Value::from(HEX_FACES.map(|f| f.to_vec()).to_vec()).to_string());
    }
    if let Some((q, hex_of)) = quality {
        json.push_str(",\"quality\":[");
        // 5 decimals: the colour ramp needs less, the sign is kept
        join(&mut json, q.values.iter(), |s, v| {
            write!(s, "{}", round5(*v))
        });
        json.push_str("],\"quality_note\":");
        json.push_str(&serde_json::Value::from(q.note).to_string());
        if let Some(h) = hex_of {
            json.push_str(",\"quad_hex\":[");
            join(&mut json, h.iter(), |s, v| write!(s, "{v}"));
            json.push(']');
        }
    }
    json.push('}');
    json.replace("</", "<\\/")
}

/// The boundary quads of a hex mesh (faces used by one hex), outward,
/// with its vertices renumbered in order of first use. Errors: a hex
/// refers to a missing vertex.
pub fn hex_boundary(mesh: &HexMesh) -> Result<QuadMesh, RenderError> {
    let mut out = QuadMesh::default();
    let mut new_id: HashMap<u32, u32> = HashMap::new();
    for f in boundary_faces(mesh)?.0 {
        let cell = f.map(|v| {
            *new_id.entry(v).or_insert_with(|| {
                out.positions.push(mesh.positions[v as usize]);
                (out.positions.len() - 1) as u32
            })
        });
        out.cells.push(cell);
    }
    Ok(out)
}

/// The faces used by one hex, outward, on the vertex ids of `mesh`, and
/// the hex of each. Errors: a hex refers to a missing vertex.
fn boundary_faces(mesh: &HexMesh) -> Result<(Vec<[u32; 4]>, Vec<u32>), RenderError> {
    let nv = mesh.positions.len();
    for (h, cell) in mesh.cells.iter().enumerate() {
        if let Some(&v) = cell.iter().find(|&&v| v as usize >= nv) {
            return Err(RenderError::CellOutOfRange {
                kind: "hex",
                cell: h,
                vertex: v,
                vertices: nv,
            });
        }
    }
    let mut count: HashMap<[u32; 4], u32> = HashMap::new();
    let faces = || {
        mesh.cells
            .iter()
            .enumerate()
            .flat_map(|(h, c)| HEX_FACES.iter().map(move |f| (f.map(|k| c[k]), h as u32)))
    };
    let key = |f: &[u32; 4]| {
        let mut k = *f;
        k.sort_unstable();
        k
    };
    for (f, _) in faces() {
        *count.entry(key(&f)).or_insert(0) += 1;
    }
    Ok(faces()
        .filter(|(f, _)| count.get(&key(f)) == Some(&1))
        .unzip())
}

/// `v` rounded to 5 decimals, without a negative zero turning positive
/// (a value of −0.000001 stays below 0: inverted).
fn round5(v: f64) -> f64 {
    let r = (v * 1e5).round() / 1e5;
    if v < 0.0 && r >= 0.0 {
        -1e-5
    } else if v > 0.0 && r <= 0.0 {
        1e-5
    } else {
        r
    }
}

/// Writes the items separated by commas.
fn join<T>(
    s: &mut String,
    items: impl Iterator<Item = T>,
    mut each: impl FnMut(&mut String, T) -> std::fmt::Result,
) {
    for (i, x) in items.enumerate() {
        if i > 0 {
            s.push(',');
        }
        // writing to a String cannot fail
        let _ = each(s, x);
    }
}

fn html_escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
        .replace('"', "&quot;")
}

fn page(title: &str, json: &str) -> String {
    format!(
        r#"<!DOCTYPE html>
<html lang="en">
<head>
<meta charset="utf-8">
<meta name="viewport" content="width=device-width, initial-scale=1">
<title>{title}</title>
<style>
html, body {{ margin: 0; height: 100%; overflow: hidden; background: #fff;
  font: 13px/1.4 system-ui, sans-serif; color: #222; }}
#view {{ position: absolute; inset: 0; width: 100%; height: 100%; display: block; }}
#panel {{ position: absolute; left: 10px; top: 8px; background: rgba(255,255,255,0.85);
  padding: 6px 10px; border-radius: 4px; pointer-events: none; max-width: calc(100% - 40px); }}
#panel summary {{ font-size: 14px; font-weight: bold; margin: 0 0 4px; cursor: pointer;
  pointer-events: auto; }}
#panel:not([open]) summary {{ margin: 0; }}
#controls, #colour {{ pointer-events: auto; margin-top: 4px; }}
#colour button {{ font: inherit; padding: 1px 8px; }}
#legend .note {{ color: #555; max-width: 18em; }}
.bar {{ display: inline-block; width: 10px; height: 10px; margin-right: 6px; vertical-align: -1px; }}
#controls input {{ vertical-align: middle; width: 10em; }}
@media (max-width: 560px), (max-height: 420px) {{
  #panel {{ left: 0; top: 0; border-radius: 0 0 4px 0; font-size: 11px; padding: 3px 6px; }}
  #status {{ display: none; }}
}}
.swatch {{ display: inline-block; width: 10px; height: 10px; border-radius: 50%;
  margin-right: 6px; vertical-align: -1px; }}
#status {{ color: #555; margin-top: 4px; max-width: 18em; }}
</style>
</head>
<body>
<canvas id="view"></canvas>
<details id="panel" open><summary>{title}</summary><div id="legend"></div><div id="colour"></div><div id="controls"></div><div id="status"></div></details>
<script type="application/json" id="mesh">{json}</script>
<script>
{VIEWER_JS}
</script>
</body>
</html>
"#
    )
}

#[cfg(test)]
pub(crate) mod tests;
