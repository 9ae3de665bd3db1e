//! Which tetrahedralization: TetGen on the slab, else the same slab thinner,
//! else the built-in prism split.
//!
//! Input: the map, the options. Output: the slab actually used, its tets
//! and a [`Method`] with a one-line [`Outcome::note`] saying why TetGen's
//! first answer was not kept (`None` when it was).
//!
//! The chain:
//! 0. a surface whose own triangles cross ([`crate::intersect`], a few
//!    ms) goes straight to the split: TetGen aborts on any slab over it
//!    (QEx's ducks: 6 pairs of triangles around vertices 99 and 4605;
//!    Directional's dragon: 23 pairs; the ducks abort down to 1e-4 × the
//!    default thickness);
//! 1. TetGen on the slab;
//! 2. when it refuses, TetGen's own check (`-d`) on the base surface alone
//!    catches crossings the cheap check missed (then the split);
//! 3. otherwise the slab halved up to [`MAX_HALVINGS`] times (offset
//!    surfaces meet where the thickness exceeds the local feature size:
//!    fandisk at 0.5 × the mean edge is refused, accepted at a quarter);
//! 4. the built-in 3-tet split of every prism ([`crate::split`]), which
//!    needs no geometry: its tets take their orientation from their
//!    triangle, so an inverted or intersecting slab still gives a valid
//!    map.
//!
//! A missing TetGen is an error unless `fallback` is set (then step 3).

use crate::slab::Slab;
use crate::tetgen::{self, TetgenMesh};
use crate::{intersect, plc, split, ExtrudeError, ExtrudeOptions};
use dualex_map::TriMap;

/// Thinner slabs tried after a refusal: thickness / 2, / 4, / 8.
pub const MAX_HALVINGS: u32 = 3;

/// How the tets were made.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    /// TetGen on the slab of the requested thickness.
    TetGen,
    /// TetGen on the slab halved `halvings` times, after a refusal.
    Thinner {
        /// How many times the thickness was halved (1..=[`MAX_HALVINGS`]).
        halvings: u32,
    },
    /// The built-in 3-tet prism split.
    Split,
}

/// The chain's result (module docs).
pub struct Outcome {
    /// The slab the tets fill.
    pub slab: Slab,
    /// The tets.
    pub mesh: TetgenMesh,
    /// How they were made.
    pub method: Method,
    /// Why not TetGen on the first slab (one line), if so.
    pub note: Option<String>,
    /// Base triangles that cross another one ([`intersect`], else TetGen's
    /// `-d` after a refusal; 0 when TetGen accepted the slab).
    pub intersecting_triangles: usize,
}

/// The last words of TetGen's failure (the exit status and message).
fn short(e: &ExtrudeError) -> String {
    let m = e.to_string();
    match m.find("exited with ") {
        Some(i) => m[i + "exited with ".len()..].to_string(),
        None => m,
    }
}

/// Runs the chain (module docs).
pub fn tetrahedralize(map: &TriMap, opts: &ExtrudeOptions) -> Result<Outcome, ExtrudeError> {
    let slab = Slab::new(map, opts.layers, opts.thickness)?;
    let outcome = |slab, mesh, method, note, intersecting_triangles| Outcome {
        slab,
        mesh,
        method,
        note,
        intersecting_triangles,
    };
    let prog = &opts.program;
    let crossing = if slab.planar {
        Vec::new()
    } else {
        intersect::crossing_pairs(&slab.points[..slab.nv], &slab.tris)
    };
    if let Some(&(i, j)) = crossing.first() {
        let mesh = split::prism_split(&slab);
        let note = format!(
            "the surface itself self-intersects ({} pairs of triangles cross, e.g. {i} and {j}), so TetGen would refuse any slab over it: TetGen not run; built-in prism split used",
            crossing.len()
        );
        let mut tris: Vec<u32> = crossing.iter().flat_map(|&(i, j)| [i, j]).collect();
        tris.sort_unstable();
        tris.dedup();
        return Ok(outcome(slab, mesh, Method::Split, Some(note), tris.len()));
    }
    let refusal = match tetgen::run(prog, &plc::poly_text(&slab), &slab, opts.quality) {
        Ok(mesh) => return Ok(outcome(slab, mesh, Method::TetGen, None, 0)),
        Err(e @ ExtrudeError::TetgenMissing(_)) if opts.fallback => {
            let mesh = split::prism_split(&slab);
            let note = format!("{e}; built-in prism split used");
            return Ok(outcome(slab, mesh, Method::Split, Some(note), 0));
        }
        Err(e @ ExtrudeError::TetgenFailed(_)) => e,
        Err(e) => return Err(e),
    };
    let head = format!(
        "TetGen refused the slab (T = {:.3e}: {})",
        slab.thickness,
        short(&refusal)
    );
    let bad =
        tetgen::intersecting_triangles(prog, &plc::surface_poly_text(&slab)).unwrap_or_default();
    let why = if let Some(t) = bad.first() {
        format!(
            "the surface itself self-intersects ({} triangles, e.g. vertices {} {} {}), so no thinner slab can help",
            bad.len(),
            t[0],
            t[1],
            t[2]
        )
    } else {
        for halvings in 1..=MAX_HALVINGS {
            let t = slab.thickness / f64::from(1u32 << halvings);
            let thin = Slab::new(map, opts.layers, Some(t))?;
            match tetgen::run(prog, &plc::poly_text(&thin), &thin, opts.quality) {
                Ok(mesh) => {
                    let note = format!("{head}; thinner slab (T = {t:.3e}) accepted");
                    let method = Method::Thinner { halvings };
                    return Ok(outcome(thin, mesh, method, Some(note), 0));
                }
                Err(ExtrudeError::TetgenFailed(_)) => {}
                Err(e) => return Err(e),
            }
        }
        let t = slab.thickness / f64::from(1u32 << MAX_HALVINGS);
        format!("thinner slabs down to T = {t:.3e} refused too")
    };
    let mesh = split::prism_split(&slab);
    let note = format!("{head}; {why}; built-in prism split used");
    Ok(outcome(slab, mesh, Method::Split, Some(note), bad.len()))
}
