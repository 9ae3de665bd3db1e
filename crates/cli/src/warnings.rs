//! The warnings of `quad` and `hex` after writing: what the extraction
//! repaired or rounded, where the mesh may differ from the map's own.
//! Repairs are printed under `-q` too: the output is not the map's own
//! mesh there. The repairs of each dimension are said by its command
//! (`quad.rs`, `hex.rs`: `ExtractCommand::warn_repairs`).

use crate::args::Global;
use crate::summary::{self, count};

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

/// The warning for a map relaxed where it folded (issue 22's retry:
/// `relax` in the stats), printed under -q too: the mesh is the one of
/// the relaxed map there, not of the map as given. `relax`: the reverted
/// simplices before, the vertices that could move.
pub fn relaxed(relax: Option<(usize, usize)>) {
    if let Some((reverted, vertices)) = relax {
        eprintln!(
            "dualex: warning: the map folds over {} that the untangling could not resolve; {} moved in map space until none was left reverted, and the mesh extracted again (see \"relax\" in the stats)",
            count(reverted, "reverted simplex", "reverted simplices"),
            count(vertices, "vertex of the fold region was", "vertices of the fold region were"),
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
