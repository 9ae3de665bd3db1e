//! The last check before writing a quad or hex mesh: never a silent wrong
//! mesh.
//!
//! Input: the map, the extracted mesh's cell count, node count and
//! topology [`Comparison`] with the input, and `--strict`. Output: `Ok`
//! with the warnings printed (and the comparison to add to the stats), or
//! an error line (nothing is written then).
//!
//! Rules:
//! - an empty output is an error when nodes were found (every cell lost:
//!   all sides unmatched) or when the map covers at least one grid cell's
//!   worth of map area/volume (`Σ |det| / D!` ≥ 1: on average over grid
//!   offsets a region holds as many nodes as its measure) and no node was
//!   found; a map smaller than one cell gives an empty mesh with a warning
//!   (printed even with `-q`: an empty file is not an ordinary result);
//! - more components than the input is an error (an extraction can lose a
//!   component smaller than a cell, never create one);
//! - any other topology difference (components, Euler characteristic,
//!   boundary components) is a warning printed even with `-q` (the output
//!   is suspect, so it is not chatter), and an error with `--strict`;
//! - so is anything sanitization left on the dual grid
//!   ([`SanitizeReport::leftovers`]: non-singular vertices still on an iso
//!   after every round, singular vertices on an iso, singular vertices not
//!   snapped): the mesh near them may be wrong ([`sanitize_check`]).

use crate::error::{CliError, Refusal};
use dualex::check::topology::Comparison;
use dualex::map::SimplexMap;
use dualex::steps::SanitizeReport;

/// Map measure (area in 2D, volume in 3D, unsigned) in grid cells.
pub fn measure<const N: usize, const D: usize>(map: &SimplexMap<N, D>) -> f64 {
    let fact: f64 = (1..=D).map(|k| k as f64).product();
    (0..map.len()).map(|s| map.map_det(s).abs()).sum::<f64>() / fact
}

/// What the extraction gave, for [`last_check`].
pub struct Output<'a> {
    /// `"quad"` or `"hex"` (names the cells in messages).
    pub cell: &'static str,
    /// Cells written.
    pub cells: usize,
    /// Nodes the extraction found.
    pub nodes: usize,
    /// The map's measure in cells ([`measure`]), taken when a rule reads
    /// it: only for an empty output (it walks every simplex).
    pub measure: Box<dyn Fn() -> f64 + 'a>,
    /// Input and output topology.
    pub topology: Comparison,
}

/// Applies the rules of the module docs; prints the warnings.
pub fn last_check(name: &str, out: &Output, strict: bool) -> Result<(), CliError> {
    let (i, o) = (out.topology.input, out.topology.output);
    if out.cells == 0 {
        if out.nodes > 0 {
            return Err(refused(
                name,
                Refusal::LostCells {
                    nodes: out.nodes,
                    cell: out.cell.to_string(),
                },
            ));
        }
        let measure = (out.measure)();
        if measure >= 1.0 {
            return Err(refused(name, Refusal::NoNode { measure }));
        }
        eprintln!(
            "dualex: warning: {name}: the map covers less than one grid cell ({measure:.3}): no node, empty mesh"
        );
        return Ok(());
    }
    if o.components > i.components {
        return Err(refused(
            name,
            Refusal::Components {
                output: o.components,
                input: i.components,
            },
        ));
    }
    if let Some(what) = out.topology.mismatch() {
        if strict {
            return Err(refused(name, Refusal::Topology(what.to_string())));
        }
        // loud: printed even with -q
        eprintln!(
            "dualex: WARNING: {name}: the output's topology differs from the input's: {what}; see \"topology\" in the stats (--strict makes this an error)"
        );
    }
    Ok(())
}

/// What sanitization left on the dual grid: a warning printed even with
/// `-q`, an error with `--strict` (nothing written then).
pub fn sanitize_check(name: &str, rep: &SanitizeReport, strict: bool) -> Result<(), CliError> {
    let Some(what) = rep.leftovers() else {
        return Ok(());
    };
    if strict {
        return Err(refused(name, Refusal::Leftovers(what.to_string())));
    }
    // loud: printed even with -q
    eprintln!(
        "dualex: warning: {name}: sanitization left vertices on the dual grid ({what}); the mesh near them may be wrong (see \"sanitize\" in the stats; --strict makes this an error)"
    );
    Ok(())
}

/// The checks before writing, in order: the mesh's validity (`errors`:
/// the checker's, empty when valid), [`last_check`], [`sanitize_check`].
pub fn before_writing(
    name: &str,
    out: &Output,
    errors: Vec<String>,
    sanitize: &SanitizeReport,
    strict: bool,
) -> Result<(), CliError> {
    if !errors.is_empty() {
        let cell = out.cell;
        return Err(refused(name, Refusal::Invalid { cell, errors }));
    }
    last_check(name, out, strict)?;
    sanitize_check(name, sanitize, strict)
}

/// The refusal `why` of the output of `name`.
pub fn refused(name: &str, why: Refusal) -> CliError {
    CliError::Refused {
        file: name.to_string(),
        why,
    }
}

/// Adds the comparison to the stats JSON (`topology_matches_input`,
/// `topology`).
pub fn add_to_stats(json: &mut serde_json::Value, c: &Comparison) {
    if let Some(obj) = json.as_object_mut() {
        obj.insert("topology_matches_input".into(), c.matches().into());
        obj.insert("topology".into(), c.to_json());
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use dualex::check::topology::Shape;

    fn out(
        cells: usize,
        nodes: usize,
        measure: f64,
        input: Shape,
        output: Shape,
    ) -> Output<'static> {
        Output {
            cell: "quad",
            cells,
            nodes,
            measure: Box::new(move || measure),
            topology: Comparison { input, output },
        }
    }

    #[test]
    fn the_last_check_refuses_wrong_meshes() {
        let disk = Shape {
            components: 1,
            euler: 1,
            boundary_components: 1,
        };
        let two = Shape {
            components: 2,
            euler: 2,
            boundary_components: 2,
        };
        let empty = Shape::default();
        let lost = last_check("m", &out(0, 5, 0.5, disk, empty), false).expect_err("lost cells");
        assert!(
            matches!(&lost, CliError::Refused { file, why: Refusal::LostCells { nodes: 5, .. } } if file == "m"),
            "{lost}"
        );
        let e = lost.to_string();
        assert!(e.contains("all sides unmatched"), "{e}");
        let e = last_check("m", &out(0, 0, 3.0, disk, empty), false)
            .expect_err("no node")
            .to_string();
        assert!(e.contains("no node found"), "{e}");
        last_check("m", &out(0, 0, 0.5, disk, empty), true).expect("smaller than a cell");
        let e = last_check("m", &out(9, 9, 9.0, disk, two), false)
            .expect_err("components")
            .to_string();
        assert!(e.contains("2 components, the input 1"), "{e}");
        last_check("m", &out(9, 9, 9.0, two, disk), false).expect("a warning");
        let e = last_check("m", &out(9, 9, 9.0, two, disk), true)
            .expect_err("strict")
            .to_string();
        assert!(e.contains("components 1 (input 2)"), "{e}");
        last_check("m", &out(9, 9, 9.0, disk, disk), true).expect("same topology");
    }

    #[test]
    fn sanitization_leftovers_warn_or_fail_with_strict() {
        let mut rep = SanitizeReport::default();
        sanitize_check("m", &rep, true).expect("nothing left");
        rep.unresolved = 3;
        rep.extra_rounds = 2;
        rep.singular_on_iso = vec![7];
        rep.singular_snap.left = 1;
        sanitize_check("m", &rep, false).expect("a warning");
        let e = sanitize_check("m", &rep, true)
            .expect_err("strict")
            .to_string();
        assert!(
            e.contains("3 non-singular on an iso after 42 rounds")
                && e.contains("1 singular on an iso")
                && e.contains("1 singular not snapped"),
            "{e}"
        );
    }

    #[test]
    fn measure_counts_cells() {
        let (map, _) = dualex::gen::by_name("square_identity", 1).expect("generator");
        assert!((measure(&map) - 49.0).abs() < 1e-9, "{}", measure(&map));
    }
}
