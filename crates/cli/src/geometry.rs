//! What `quad`, `hex` and `remesh` say of the geometric stage (the
//! library's [`dualex::steps::geometry`], with the options of
//! [`crate::args::GeometryArgs::options`]): its result (the done line's quality, the warning or `--strict` error
//! for inverted elements left).

use crate::error::{CliError, Refusal};
use crate::summary::{count, plural};
use dualex::geom::Report;

/// Inverted elements left: an error under `strict` (nothing written),
/// else `Ok` (the warning is [`warn`]'s, after writing).
pub fn check(
    name: &str,
    r: &Report,
    cell: (&'static str, &'static str),
    strict: bool,
) -> Result<(), CliError> {
    let n = r.after.inverted;
    if strict && n > 0 {
        return Err(crate::verify::refused(
            name,
            Refusal::Inverted {
                count: n,
                cell,
                mode: r.mode,
            },
        ));
    }
    Ok(())
}

/// The warnings for inverted elements left and for vertices taken off
/// the input's sharp edges to untangle, printed under `-q` too.
pub fn warn(r: &Report, cell: (&str, &str)) {
    if r.features_released > 0 {
        eprintln!(
            "dualex: warning: {} released from the input's sharp edges to untangle the {} at them (the mesh's edges leave those curves there); see \"features_released\" in the stats",
            count(r.features_released, "vertex", "vertices"),
            cell.1,
        );
    }
    let n = r.after.inverted;
    if n == 0 {
        return;
    }
    let why = if r.mode == "off" {
        "--no-untangle kept the map's positions"
    } else {
        "the untangler could not remove them, or the combinatorics force them: see docs/messy-cases.md"
    };
    eprintln!(
        "dualex: WARNING: {} (scaled Jacobian ≤ 0) {} ({why}); see \"geometry\" in the stats",
        count(
            n,
            &format!("inverted {}", cell.0),
            &format!("inverted {}", cell.1)
        ),
        plural(n, "remains", "remain"),
    );
}

/// The done line's words on quality: the least scaled Jacobian, and what
/// the stage changed.
pub fn done_words(r: &Report) -> String {
    let mut s = format!(", scaled Jacobian min {:.2}", r.after.min);
    if r.moved() {
        s += &format!(
            " (was {:.2}; {} inverted before, {} after",
            r.before.min, r.before.inverted, r.after.inverted
        );
        if r.boundary_off > 0 {
            s += &format!(
                ", {} put on the input's boundary",
                count(r.boundary_off, "boundary vertex", "boundary vertices")
            );
        }
        if r.features_released > 0 {
            s += &format!(
                ", {} released from sharp edges",
                count(r.features_released, "vertex", "vertices")
            );
        }
        s += &format!("; moved ≤ {:.2} edge lengths)", r.max_move_edges());
    }
    s
}
