//! `dualex generate --from-mesh MESH -o MAP`: a quad or hex mesh as a map
//! (one chart per element, see `dualex::gen::from_mesh`), written with its
//! expected extraction beside it: `MAP.expected.json` (counts) and the
//! refined mesh `MAP.expected.obj` (quads) / `MAP.expected.mesh` (hexes).
//! Every file is written atomically; errors are one line naming the file.

use crate::args::{GenerateArgs, Global};
use crate::error::{CliError, Need};
use crate::summary::plural;
use dualex::gen::from_mesh::{from_hexes, from_quads, FromMeshError, FromMeshOptions};
use dualex::{HexMesh, QuadMesh};
use std::path::Path;

/// The mesh to turn into a map, with its name for messages.
pub enum Input {
    /// A quad mesh.
    Quads(QuadMesh, String),
    /// A hex mesh.
    Hexes(HexMesh, String),
}

/// Reads MESH: `.mesh` hexes, `.obj` / `.ply` quads (other faces refused).
pub fn read(path: &Path) -> Result<Input, CliError> {
    let name = path.display().to_string();
    let ext = dualex::io::lower_extension(path);
    if ext == "mesh" {
        let m = dualex::io::read_hex_mesh(path)?;
        return Ok(Input::Hexes(m, name));
    }
    let poly = dualex::io::read_polygon_mesh(path)?;
    let mut cells = Vec::with_capacity(poly.faces.len());
    for (i, f) in poly.faces.iter().enumerate() {
        let [a, b, c, d] = f[..] else {
            return Err(CliError::Face {
                file: name,
                face: i,
                sides: f.len(),
                need: Need::FromMesh,
            });
        };
        cells.push([a, b, c, d]);
    }
    Ok(Input::Quads(
        QuadMesh {
            positions: poly.positions,
            cells,
        },
        name,
    ))
}

fn options(args: &GenerateArgs) -> FromMeshOptions {
    FromMeshOptions {
        scale: args.scale.unwrap_or(2),
        noise: args.noise.unwrap_or(0.0),
        folds: args.folds,
        singular_folds: args.folds_at_singular.unwrap_or(0),
        magnify: args.magnify.unwrap_or(1),
        seed: args.seed,
        half_shift: args.half_shift,
        ..Default::default()
    }
}

fn json_of(pairs: impl Iterator<Item = (u32, usize)>) -> serde_json::Value {
    let mut m = serde_json::Map::new();
    for (k, v) in pairs {
        m.insert(k.to_string(), v.into());
    }
    serde_json::Value::Object(m)
}

/// The expected counts of a quad mesh's map (`MAP.expected.json`).
fn expected_quads(e: &dualex::gen::Expected, o: &FromMeshOptions) -> serde_json::Value {
    serde_json::json!({
        "dimension": 2,
        "scale": o.scale * o.magnify,
        "half_shift": o.half_shift,
        "quads": e.quads,
        "interior_valence": e.interior_valence.as_ref()
            .map(|h| json_of(h.iter().map(|(k, v)| (*k, *v)))),
        "euler": e.euler,
        "boundary_loops": e.boundary_loops,
    })
}

/// The expected counts of a hex mesh's map.
fn expected_hexes(e: &dualex::gen::block::ExpectedHex, o: &FromMeshOptions) -> serde_json::Value {
    serde_json::json!({
        "dimension": 3,
        "scale": o.scale * o.magnify,
        "hexes": e.hexes,
        "boundary_components": e.boundary_components,
        "boundary_euler": e.boundary_euler,
    })
}

/// Generates and writes (module docs).
pub fn run(args: &GenerateArgs, g: &Global, input: Input, out: &Path) -> Result<(), CliError> {
    let o = options(args);
    let json_path = out.with_extension("expected.json");
    let (map_exts, refined, simplices): (&'static [&'static str], _, _) = match &input {
        Input::Quads(..) => (
            dualex::io::TRI_MAP_EXTENSIONS,
            out.with_extension("expected.obj"),
            ("triangle", "triangles"),
        ),
        Input::Hexes(..) => (
            dualex::io::TET_MAP_EXTENSIONS,
            out.with_extension("expected.mesh"),
            ("tet", "tets"),
        ),
    };
    crate::outputs::check_all(&[(out, Some(map_exts)), (&json_path, None), (&refined, None)])?;
    // the map and the refined mesh written, the expected counts kept
    let (count, json) = match &input {
        Input::Quads(m, name) => {
            let gen = from_quads(m, &o).map_err(|error| from_mesh(name, error))?;
            dualex::io::write_tri_map(out, &gen.map)?;
            dualex::io::write_quad_mesh(&refined, &gen.refined)?;
            (gen.map.len(), expected_quads(&gen.expected, &o))
        }
        Input::Hexes(m, name) => {
            let gen = from_hexes(m, &o).map_err(|error| from_mesh(name, error))?;
            dualex::io::write_tet_map(out, &gen.map)?;
            dualex::io::write_hex_mesh(&refined, &gen.refined)?;
            (gen.map.len(), expected_hexes(&gen.expected, &o))
        }
    };
    let what = plural(count, simplices.0, simplices.1);
    let text = serde_json::to_string_pretty(&json).map_err(|e| CliError::Bug {
        what: "",
        reason: e.to_string(),
    })?;
    dualex::io::write_text(&json_path, &text)?;
    if !g.quiet {
        eprintln!(
            "dualex: {count} {what} -> {} (expected: {})",
            out.display(),
            json_path.display()
        );
    }
    Ok(())
}

/// The error of making a map from the mesh `name`.
fn from_mesh(name: &str, error: FromMeshError) -> CliError {
    CliError::FromMesh {
        file: name.to_string(),
        error,
    }
}
