//! A self-contained HTML page to orbit a quad mesh or a hex mesh's boundary.
//!
//! Input: a [`QuadMesh`] (or a [`HexMesh`], shown by [`hex_boundary`]) and a
//! title. Output: one HTML string with the mesh embedded as JSON
//! (`<script type="application/json" id="mesh">`) and the viewer of
//! `viewer.js` inline: no network, no external script. The JSON holds
//! `positions` (flat `x y z`, f32 precision), `quads` (flat corner ids),
//! `valence` (one code per vertex, [`crate::ValenceClass::code`]) and `title`.
//!
//! Invariant: the embedded JSON contains no `</` (escaped as `<\/`), so the
//! page's structure cannot be broken by a title.

use std::collections::HashMap;
use std::fmt::Write;

use dualex_map::{HexMesh, QuadMesh};

use crate::valence::{check_quads, valence_classes};

const VIEWER_JS: &str = include_str!("viewer.js");

use dualex_map::cells::HEX_FACES;

/// The page showing `mesh` (see the module docs). Errors: a quad refers to
/// a missing vertex, or a position is not finite.
pub fn view_html(mesh: &QuadMesh, title: &str) -> Result<String, String> {
    check_quads(mesh)?;
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
    json.push_str("]}");
    let json = json.replace("</", "<\\/");
    Ok(page(&html_escape(title), &json))
}

/// The page showing the boundary of the hex mesh `mesh`.
pub fn view_html_hex(mesh: &HexMesh, title: &str) -> Result<String, String> {
    view_html(&hex_boundary(mesh)?, title)
}

/// The boundary quads of a hex mesh (faces used by one hex), outward,
/// with its vertices renumbered in order of first use. Errors: a hex
/// refers to a missing vertex.
pub fn hex_boundary(mesh: &HexMesh) -> Result<QuadMesh, String> {
    let nv = mesh.positions.len();
    for (h, cell) in mesh.cells.iter().enumerate() {
        if let Some(&v) = cell.iter().find(|&&v| v as usize >= nv) {
            return Err(format!(
                "hex {h} refers to vertex {v}, but there are {nv} vertices"
            ));
        }
    }
    let mut count: HashMap<[u32; 4], u32> = HashMap::new();
    let faces = || {
        mesh.cells
            .iter()
            .flat_map(|c| HEX_FACES.iter().map(move |f| f.map(|k| c[k])))
    };
    let key = |f: &[u32; 4]| {
        let mut k = *f;
        k.sort_unstable();
        k
    };
    for f in faces() {
        *count.entry(key(&f)).or_insert(0) += 1;
    }
    let mut out = QuadMesh::default();
    let mut new_id: HashMap<u32, u32> = HashMap::new();
    for f in faces().filter(|f| count.get(&key(f)) == Some(&1)) {
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
  padding: 6px 10px; border-radius: 4px; pointer-events: none; }}
#panel h1 {{ font-size: 14px; margin: 0 0 4px; }}
.swatch {{ display: inline-block; width: 10px; height: 10px; border-radius: 50%;
  margin-right: 6px; vertical-align: -1px; }}
#status {{ color: #555; margin-top: 4px; max-width: 28em; }}
</style>
</head>
<body>
<canvas id="view"></canvas>
<div id="panel"><h1>{title}</h1><div id="legend"></div><div id="status"></div></div>
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
