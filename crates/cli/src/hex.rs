//! `dualex hex`: the 3D map read, then the one extraction sequence
//! ([`crate::extract::extract_map`]); here its 3D parts
//! ([`ExtractCommand`] for [`HexArgs`]): no picture, the repairs hexes
//! need (holes through columns, interior faces left open) said as
//! warnings and as problems on the summary line.
//!
//! Input: the arguments; output: the files written and stderr, or an
//! error (nothing written then).

use crate::args::{ExtractArgs, Global, HexArgs};
use crate::error::CliError;
use crate::extract::{self, Cells, ExtractCommand, Extracted};
use crate::summary::{count, plural};
use crate::timing;
use std::path::Path;

/// `dualex hex`.
pub fn hex(a: &HexArgs, g: &Global) -> Result<(), CliError> {
    extract::check_outputs(a)?;
    let name = a.input.display().to_string();
    let mut laps = timing::Laps::start();
    let map = dualex::io::read_tet_map(&a.input)?;
    laps.lap("read");
    extract::extract_map(&map, &name, "done", a, g, laps, None)
}

impl ExtractCommand<4, 3, 8> for HexArgs {
    const CELLS: Cells = Cells {
        one: "hex",
        many: "hexes",
        extensions: dualex::io::HEX_MESH_EXTENSIONS,
    };

    /// Index fairing on columns always on, as the library's default.
    fn options(&self, _: &Global) -> (dualex::Options, bool) {
        (self.extract.options(true), false)
    }

    fn output(&self) -> &Path {
        &self.output
    }

    fn png(&self) -> Option<&Path> {
        None
    }

    fn extract_args(&self) -> &ExtractArgs {
        &self.extract
    }

    fn picture(&self, _: &Extracted<4, 3, 8>, _: &str) -> Result<Option<Vec<u8>>, CliError> {
        Ok(None)
    }

    fn write(&self, x: &Extracted<4, 3, 8>) -> Result<(), CliError> {
        Ok(dualex::io::write_hex_mesh(&self.output, &x.mesh)?)
    }

    /// Holes through columns filled, interior faces left open.
    fn warn_repairs(x: &Extracted<4, 3, 8>, _own_map: bool) {
        let stats = &x.stats;
        if stats.columns.holes > 0 {
            // printed under -q too: the output is not the map's own mesh
            let c = &stats.columns;
            eprintln!(
                "dualex: warning: {} through {} that hexes cannot represent (singular edges through dual nodes) {} filled, and {} split along {} between them (local repair on columns, as in 2D)",
                count(c.holes, "hole", "holes"),
                count(c.layers, "layer", "layers"),
                plural(c.holes, "was", "were"),
                count(c.split, "column", "columns"),
                count(c.paths, "path", "paths"),
            );
        }
        if stats.open_interior_faces > 0 {
            // loud: printed even with -q (a crack is a wrong mesh, not noise)
            eprintln!(
                "dualex: WARNING: {} left open (walks lost at singular edges: cracks, not input boundary); see \"holes\" in the stats",
                count(stats.open_interior_faces, "interior face", "interior faces")
            );
        }
    }

    fn counts(x: &Extracted<4, 3, 8>) -> Vec<String> {
        vec![
            count(x.mesh.cells.len(), "hex", "hexes"),
            count(x.mesh.positions.len(), "vertex", "vertices"),
        ]
    }

    /// Interior edges of valence ≤ 2, open interior faces.
    fn problems(x: &Extracted<4, 3, 8>) -> Vec<String> {
        let st = &x.stats;
        let low: usize = st.edge_valence_interior.range(..=2).map(|(_, n)| n).sum();
        let mut p: Vec<String> =
            crate::summary::low_valence((low, "interior edge", "interior edges"))
                .into_iter()
                .collect();
        if st.columns.holes > 0 {
            p.push(format!(
                "repaired locally along {} of columns, {} split (hexes could not represent the map)",
                count(st.columns.paths, "path", "paths"),
                count(st.columns.split, "column", "columns"),
            ));
        }
        if st.open_interior_faces > 0 {
            let faces = count(st.open_interior_faces, "interior face", "interior faces");
            p.push(format!("{faces} left open"));
        }
        p
    }
}
