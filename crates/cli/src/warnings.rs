//! The warnings of `quad` and `hex` after writing: what the extraction
//! repaired or rounded, where the mesh may differ from the map's own.
//! Repairs are printed under `-q` too: the output is not the map's own
//! mesh there.

use crate::args::Global;
use crate::summary::{self, count};

/// The warnings of the quad extraction's repairs: faces made quads along
/// paths (local repair), or one step of subdivision of the whole mesh.
pub fn quad_repairs(stats: &dualex::steps::QuadReport) {
    if stats.repair_paths > 0 {
        // printed under -q too: the output is not the map's own mesh
        if stats.repair_triangles + stats.holes_filled == 0 {
            // the odd faces came from step 8a's splits (parallel edges,
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

/// The warning for the faces quads cannot represent (triangles at
/// singular vertices, holes), made quads `how`.
fn faces_made_quads(stats: &dualex::steps::QuadReport, how: &str) {
    let faces = stats.repair_triangles + stats.holes_filled;
    eprintln!(
        "dualex: warning: {} that quads cannot represent ({} at singular vertices on dual nodes, {} closed by polygons) {} made quads {how}",
        count(faces, "face", "faces"),
        count(stats.repair_triangles, "triangle", "triangles"),
        count(stats.holes_filled, "hole", "holes"),
        summary::plural(faces, "was", "were"),
    );
}

/// The warnings of the hex extraction's repairs: holes through columns
/// filled, interior faces left open.
pub fn hex_repairs(stats: &dualex::steps::HexReport) {
    if stats.columns.holes > 0 {
        // printed under -q too: the output is not the map's own mesh
        let c = &stats.columns;
        eprintln!(
            "dualex: warning: {} through {} that hexes cannot represent (singular edges through dual nodes) {} filled, and {} split along {} between them (local repair on columns, as in 2D)",
            count(c.holes, "hole", "holes"),
            count(c.layers, "layer", "layers"),
            summary::plural(c.holes, "was", "were"),
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

/// The warning for valence-1 and 2 vertices index fairing could not
/// merge (collapsed, dissolved), printed under -q too: such a repair is
/// where a messy map's mesh may differ from the map's own (a singularity
/// split by the untangling, docs/messy-cases.md).
pub fn degenerate(folded: usize, doublets: usize) {
    let parts: Vec<String> = [
        (folded, "folded corner", "folded corners", "collapsed"),
        (doublets, "doublet", "doublets", "dissolved"),
    ]
    .into_iter()
    .filter(|p| p.0 > 0)
    .map(|(n, one, many, done)| format!("{} {done}", count(n, one, many)))
    .collect();
    if !parts.is_empty() {
        eprintln!(
            "dualex: warning: {}: degenerate vertices that index fairing found no partner for (the mesh may differ from the map's there); see \"folded_corners_collapsed\" and \"doublets\" in the stats",
            parts.join(" and ")
        );
    }
}

/// The warning for transitions rounded without `--round-transitions`
/// (or with it): how many, and the largest residual.
pub fn rounded(g: &Global, rounded: usize, max_residual: f64) {
    if rounded > 0 && !g.quiet {
        eprintln!(
            "dualex: warning: rounded {} that {} not integral (largest residual {max_residual:.3e}); the map is not exactly grid-preserving",
            count(rounded, "transition translation", "transition translations"),
            summary::plural(rounded, "was", "were"),
        );
    }
}
