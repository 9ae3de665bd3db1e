//! `dualex quad`: the 2D map read (or the embedded one) and welded, then
//! the one extraction sequence ([`crate::extract::extract_map`]); here its
//! 2D parts ([`ExtractCommand`] for [`QuadArgs`]): `--uv`, the `--png`
//! picture, the repairs quads need (triangles, holes, subdivision) said
//! as warnings and as problems on the summary line.
//!
//! Input: the arguments; output: the files written and stderr, or an
//! error (nothing written then).

use crate::args::{ExtractArgs, Global, QuadArgs};
use crate::error::CliError;
use crate::extract::{self, Cells, ExtractCommand, Extracted};
use crate::summary::{count, plural};
use crate::{timing, warnings, EMBEDDED, PNG_SIZE};
use std::path::Path;

/// `dualex quad`.
pub fn quad(a: &QuadArgs, g: &Global) -> Result<(), CliError> {
    if a.uv {
        refuse_uv(&a.output);
    }
    extract::check_outputs(a)?;
    let mut laps = timing::Laps::start();
    let (map, name) = match &a.input {
        Some(p) => (
            crate::read_2d(p, &a.weld, g, &mut laps)?,
            p.display().to_string(),
        ),
        None => {
            if !g.quiet {
                eprintln!("dualex: no INPUT given: running on the embedded map (a folded, noisy cube surface)");
            }
            let m = dualex::io::parse_obj(EMBEDDED).map_err(CliError::EmbeddedMap)?;
            let name = "embedded map".to_string();
            (crate::weld_if(m, &a.weld, g, &name), name)
        }
    };
    let done = if a.input.is_some() {
        "done"
    } else {
        "embedded map"
    };
    extract::extract_map(&map, &name, done, a, g, laps, None)
}

/// `--uv` with an output format that cannot carry per-corner map
/// coordinates (`.vtk`) is a usage error (exit 2); an unknown extension is
/// left to the output check.
pub(crate) fn refuse_uv(output: &Path) {
    let ext = dualex::io::lower_extension(output);
    if dualex::io::QUAD_MESH_EXTENSIONS.contains(&ext.as_str())
        && !dualex::io::write_uv::UV_EXTENSIONS.contains(&ext.as_str())
    {
        crate::args::usage_error(&format!(
            "--uv does not apply to .{ext} output (no per-corner attribute): use .obj or .ply"
        ));
    }
}

impl ExtractCommand<3, 2, 4> for QuadArgs {
    const CELLS: Cells = Cells {
        one: "quad",
        many: "quads",
        extensions: dualex::io::QUAD_MESH_EXTENSIONS,
    };

    fn output(&self) -> &Path {
        &self.output
    }

    fn extract_args(&self) -> &ExtractArgs {
        &self.extract
    }

    /// With `--stats` or `-v` the report counts the input's
    /// singularities too.
    fn options(&self, g: &Global) -> (dualex::Options, bool) {
        let x = &self.extract;
        (x.options(!self.no_fairing), x.stats.is_some() || g.verbose)
    }

    fn png(&self) -> Option<&Path> {
        self.png.as_deref()
    }

    fn picture(&self, x: &Extracted<3, 2, 4>, name: &str) -> Result<Option<Vec<u8>>, CliError> {
        if self.png.is_none() || x.mesh.cells.is_empty() {
            return Ok(None);
        }
        let png = dualex::render::quad_png_bytes(&x.mesh, PNG_SIZE);
        png.map(Some).map_err(|error| CliError::Render {
            file: name.to_string(),
            error,
        })
    }

    fn write(&self, x: &Extracted<3, 2, 4>) -> Result<(), CliError> {
        if self.uv {
            dualex::io::write_quad_mesh_uv(&self.output, &x.mesh, &x.corners)
        } else {
            dualex::io::write_quad_mesh(&self.output, &x.mesh)
        }?;
        Ok(())
    }

    /// Valence-1 and 2 vertices left (of the user's own map), then faces
    /// made quads along paths (local repair), or one step of subdivision
    /// of the whole mesh.
    fn warn_repairs(x: &Extracted<3, 2, 4>, own_map: bool) {
        let stats = &x.stats;
        if own_map {
            warnings::degenerate(stats.folded_corners_collapsed, stats.doublets.dissolved);
        }
        if stats.repair_paths > 0 {
            // printed under -q too: the output is not the map's own mesh
            if stats.repair_triangles + stats.holes_filled == 0 {
                // the odd faces came from step 10a's splits (parallel edges,
                // folded cells), not from triangles or holes: said as such
                eprintln!(
                    "dualex: warning: faces with an odd number of sides (left by splitting parallel edges and folded cells) were made quads along {} (local repair)",
                    count(stats.repair_paths, "path", "paths"),
                );
            } else {
                let paths = count(stats.repair_paths, "path", "paths");
                faces_made_quads(stats, &format!("along {paths} between them (local repair)"));
            }
        }
        if stats.subdivided {
            // printed under -q too: the output is not the map's own mesh
            faces_made_quads(stats, "by one step of subdivision of the whole mesh");
        }
    }

    fn counts(x: &Extracted<3, 2, 4>) -> Vec<String> {
        let s = &x.stats;
        vec![
            count(s.quads, "quad", "quads"),
            count(s.vertices, "vertex", "vertices"),
            count(s.boundary_loops, "boundary loop", "boundary loops"),
            count(s.components, "component", "components"),
        ]
    }

    /// Interior vertices of valence ≤ 2, a subdivision, dropped cells,
    /// open holes.
    fn problems(x: &Extracted<3, 2, 4>) -> Vec<String> {
        let st = &x.stats;
        let mut p = Vec::new();
        if st.quads == 0 {
            p.push("empty mesh: the map covers less than one grid cell".into());
        }
        let low: usize = st.valence_interior.range(..=2).map(|(_, n)| n).sum();
        let low = (low, "interior vertex", "interior vertices");
        p.extend(crate::summary::low_valence(low));
        if st.subdivided {
            p.push("subdivided once (quads could not represent the map)".into());
        }
        if st.repair_paths > 0 {
            p.push(format!(
                "repaired locally along {} (quads could not represent the map)",
                count(st.repair_paths, "path", "paths")
            ));
        }
        if st.repair_dropped > 0 {
            let cells = count(st.repair_dropped, "degenerate cell", "degenerate cells");
            p.push(format!("{cells} dropped"));
        }
        if st.holes_left_open > 0 {
            let holes = count(st.holes_left_open, "hole", "holes");
            p.push(format!("{holes} left open"));
        }
        p
    }
}

/// The warning for the faces quads cannot represent (triangles at
/// singular vertices, holes), made quads `how`.
fn faces_made_quads(stats: &dualex::steps::QuadReport, how: &str) {
    let faces = stats.repair_triangles + stats.holes_filled;
    eprintln!(
        "dualex: warning: {} that quads cannot represent ({} at singular vertices on dual nodes, {} closed by polygons) {} made quads {how}",
        count(faces, "face", "faces"),
        count(stats.repair_triangles, "triangle", "triangles"),
        count(stats.holes_filled, "hole", "holes"),
        plural(faces, "was", "were"),
    );
}
