//! Remeshing: quads from a plain triangle surface, the pipeline that
//! `dualex remesh` and the Python `remesh` run (one piece of code).
//!
//! Input: positions and triangles (no map) and [`RemeshOptions`]. Steps:
//!
//! 1. the input checked as [`crate::tri_map_from_slices`] checks it
//!    (indices in range, no vertex twice in a triangle, finite positions),
//!    then welded (boundary vertices at equal positions merged:
//!    `dualex_remesh::weld`) and built into a surface (a 2-manifold,
//!    consistently oriented, no zero-area triangle): [`Error::Input`]
//!    otherwise;
//! 2. the map made by `dualex_remesh` (cross field, cut, seamless
//!    integration, rounding), the extraction's quad count in the loop
//!    (only a mesh the extraction would give — valid, the surface's
//!    topology — counts): [`remesh_map`] → [`RemeshedMap`];
//! 3. [`RemeshedMap::check`]: a collapsed map (signed area below a tenth of
//!    the target's, or most triangles flipped) is remesh's bug,
//!    [`Error::Bug`], caught before the extraction;
//! 4. [`RemeshedMap::extract`]: the extraction of the map kept (made in the
//!    count already, else made now); a map the extraction refuses is
//!    remesh's bug ([`Error::Bug`]: remesh must make grid-preserving maps),
//!    no quad at all is [`Error::Empty`];
//! 5. the geometric stage on the quads, as [`crate::quad()`] runs it; when
//!    it leaves inverted quads (a coarse map's flipped triangles can give
//!    a fold no move of the vertices undoes), or the quads' topology is
//!    not the surface's (holes a sixth of a quad apart whose strip the
//!    map still loses), steps 2–5 again at another grid position (the
//!    seed's attempt `k`, [`attempt_seed`]), at most [`GRID_ATTEMPTS`] in
//!    all; the first with the surface's topology and the fewest inverted
//!    quads is kept, and every attempt's inverted count is in
//!    [`RemeshStats::grid_attempts`]. Only runs that leave inverted quads
//!    pay for it: 3 of the 120 runs of `tests/remesh.rs` before it
//!    (genus-3 plate and torus at 100 quads, all fixed by the second
//!    position). Not with [`GeometryMode::Off`](crate::GeometryMode),
//!    which keeps the map's positions: [`remesh_staged`];
//! 6. ([`remesh()`] only) the output check and the topology comparison, as
//!    [`crate::quad()`] runs them.
//!
//! The CLI runs 1–5 here (writing the map, `--map-out`, between 2 and 3 of
//! each attempt, so that a map refused can be inspected); its own writer
//! follows.
//!
//! Invariants: the map is over the welded surface (its `positions` and
//! `simplices`); a result is never an empty mesh.

use crate::extract::finish;
use crate::steps::{self, QuadExtraction};
use crate::{
    Error, GeometryMode, GeometryReport, InputError, Options, QuadOutput, TriMap, SMOOTH_ROUNDS,
};
use dualex_check::topology;
use dualex_map::InputErrorKind;
pub use dualex_remesh::{
    shapes, Quantization, RemeshOptions as MapOptions, RemeshStats, Surface, Target,
};

/// Options of [`remesh()`] and [`remesh_map`].
#[derive(Clone, Debug)]
pub struct RemeshOptions {
    /// The map: target size, sharp-edge angle, rounding, seed (the seed is
    /// the extraction's too). Default: about 1000 quads, 35°, direct
    /// rounding, seed 1.
    pub map: MapOptions,
    /// The extraction and geometric stage (`weld` and `seed` are not
    /// read: the surface is welded by position, the seed is the map's).
    /// Default: [`Options::default`] with smoothing
    /// ([`GeometryMode::Smooth`] with [`SMOOTH_ROUNDS`]).
    pub extract: Options,
}

impl Default for RemeshOptions {
    fn default() -> Self {
        let mut extract = Options::default();
        extract.geometry.mode = GeometryMode::Smooth(SMOOTH_ROUNDS);
        RemeshOptions {
            map: MapOptions::default(),
            extract,
        }
    }
}

impl RemeshOptions {
    /// The extraction's options (the seed is the map's).
    fn quad_options(&self) -> Options {
        Options {
            weld: false,
            seed: self.map.seed,
            ..self.extract.clone()
        }
    }
}

/// A map made by [`remesh_map`], not yet extracted.
#[derive(Debug)]
pub struct RemeshedMap {
    /// The map, over the welded surface.
    pub map: TriMap,
    /// The remesher's numbers.
    pub stats: RemeshStats,
    /// Vertices merged by the weld of step 1.
    pub welded: usize,
    /// The surface's area (model units²).
    pub surface_area: f64,
    /// The extraction of `map` made while counting, if it was taken.
    extracted: Option<QuadExtraction>,
    /// The options it was made with.
    opts: RemeshOptions,
    /// The welded surface's topology.
    shape: topology::Shape,
}

/// Steps 1–2 (module docs): the map of a plain surface, counted.
pub fn remesh_map(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    opts: &RemeshOptions,
) -> Result<RemeshedMap, Error> {
    // the checks of a map from slices (the weld trusts the indices)
    crate::tri_map_from_slices(positions, triangles, &vec![[[0.0; 2]; 3]; triangles.len()])?;
    let welded = dualex_remesh::weld::weld(positions, triangles);
    let surface = dualex_remesh::Surface::new(welded.positions, welded.triangles)
        .map_err(|e| InputError::new(InputErrorKind::from_source(e)))?;
    let inner = opts.quad_options();
    let shape = topology::surface_shape(surface.positions.len(), &surface.triangles);
    // one extraction per map counted, in the order of `stats.counted`
    let mut extracted: Vec<Option<QuadExtraction>> = Vec::new();
    let mut quads_of = |m: &TriMap| {
        let x = steps::extract(m, &inner, true).ok();
        let n = x.as_ref().and_then(|x| {
            let rep = dualex_check::check_quad_mesh(x.mesh.positions.len(), &x.mesh.cells);
            let same = rep.is_valid() && topology::quad_shape(&rep) == shape;
            same.then_some(x.mesh.cells.len())
        });
        extracted.push(x);
        n
    };
    let made = dualex_remesh::remesh_counted(&surface, &opts.map, &mut quads_of)
        // (an option out of range, a solve that fails on this surface:
        // said as the remesher says it, as before the library had it)
        .map_err(|e| InputError::new(InputErrorKind::from_source(e)))?;
    let kept = made.stats.kept.and_then(|k| extracted.into_iter().nth(k));
    Ok(RemeshedMap {
        map: made.map,
        stats: made.stats,
        welded: welded.merged,
        surface_area: surface.areas.iter().sum(),
        extracted: kept.flatten(),
        opts: opts.clone(),
        shape,
    })
}

impl RemeshedMap {
    /// The map's area the target asks for (map units², about the quads).
    pub fn target_area(&self) -> f64 {
        match self.opts.map.target {
            Target::Quads(n) => n as f64,
            Target::EdgeLength(h) => self.surface_area / (h * h),
        }
    }

    /// Step 3: a target of less than one quad is [`Error::Empty`]; a
    /// collapsed map is remesh's bug (module docs): its signed area below
    /// a tenth of the target's, its unsigned area (folds count twice)
    /// above ten times the target's, or most triangles flipped.
    pub fn check(&self) -> Result<(), Error> {
        let s = &self.stats;
        let target = self.target_area();
        // (NaN compares false: caught too)
        if target.partial_cmp(&1.0).is_none_or(|o| o.is_lt()) {
            return Err(Error::Empty(format!(
                "the surface (area {:.3e}) holds {target:.3} quads of that size: ask for smaller quads",
                self.surface_area
            )));
        }
        let (signed, unsigned) = map_areas(&self.map);
        let small = signed
            .partial_cmp(&(0.1 * target))
            .is_none_or(|o| o.is_lt());
        let folded = unsigned
            .partial_cmp(&(10.0 * target))
            .is_none_or(|o| o.is_gt());
        let collapsed = small || folded;
        if collapsed || 2 * s.flipped > s.triangles {
            let index: Vec<String> = s
                .singularity_index
                .iter()
                .map(|(q, n)| format!("{n} of index {q}/4"))
                .collect();
            return Err(Error::Bug(format!(
                "the map collapsed: area {signed:.3e} (unsigned {unsigned:.3e}) for a target of \
                 {target:.1}, {} of {} triangles flipped (field singularities: {})",
                s.flipped,
                s.triangles,
                if index.is_empty() {
                    "none".to_string()
                } else {
                    index.join(", ")
                }
            )));
        }
        Ok(())
    }

    /// Step 4: the map's extraction (module docs); the map and the
    /// remesher's numbers come back with it.
    #[doc(hidden)]
    pub fn extract(self) -> Result<(TriMap, RemeshStats, QuadExtraction), Error> {
        let x = match self.extracted {
            Some(x) => x,
            None => {
                let inner = self.opts.quad_options();
                steps::extract(&self.map, &inner, true).map_err(|e| {
                    Error::Bug(format!("the extraction refuses the map remesh made: {e}"))
                })?
            }
        };
        if x.mesh.cells.is_empty() {
            return Err(Error::Empty(format!(
                "the map covers less than one grid cell (area {:.3}): ask for more quads",
                self.stats.map_area
            )));
        }
        Ok((self.map, self.stats, x))
    }
}

/// What [`remesh()`] made.
#[derive(Clone, Debug)]
pub struct RemeshOutput {
    /// The quad mesh, its stats, sources and corner coordinates (the
    /// sources index the welded surface's triangles, [`Self::map`]'s).
    pub quads: QuadOutput,
    /// The remesher's numbers (field, cut, map).
    pub remesh: RemeshStats,
    /// The map extracted, over the welded surface.
    pub map: TriMap,
}

/// Quads from a plain triangle surface (module docs, steps 1–5).
///
/// ```
/// // a closed cube of 48 triangles (sharp edges), at about 24 quads
/// let s = dualex_remesh::shapes::cube(2);
/// let mut opts = dualex::RemeshOptions::default();
/// opts.map.target = dualex::Target::Quads(24);
/// let out = dualex::remesh(&s.positions, &s.triangles, &opts)?;
/// assert!(out.quads.stats.cells > 0);
/// assert!(out.quads.stats.topology.matches());
/// // bad input is an error naming the element
/// let e = dualex::remesh(&s.positions, &[[0, 1, 99]], &opts).unwrap_err();
/// assert!(e.to_string().starts_with("triangle 0: corner 2 refers to vertex 99"));
/// # Ok::<(), dualex::Error>(())
/// ```
pub fn remesh(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    opts: &RemeshOptions,
) -> Result<RemeshOutput, Error> {
    let s = remesh_staged(positions, triangles, opts, &mut |_, _| Ok(()))?;
    let quads = finish(
        &s.map,
        s.extracted,
        s.welded,
        &s.opts.quad_options(),
        s.geometry,
        None,
    )?;
    Ok(RemeshOutput {
        quads,
        remesh: s.stats,
        map: s.map,
    })
}

/// Grid positions step 5 tries at most (module docs).
pub const GRID_ATTEMPTS: usize = 6;

/// The seed of attempt `k` of step 5: the user's for `k = 0`, then seeds
/// drawn from it (the seed places the grid on the surface).
pub fn attempt_seed(seed: u64, k: usize) -> u64 {
    if k == 0 {
        seed
    } else {
        dualex_util::rng::SplitMix::new(seed ^ (k as u64).rotate_left(32)).next_u64()
    }
}

/// Steps 1–5 done (module docs): what the output checks and the writer
/// take.
#[doc(hidden)]
pub struct Staged {
    /// The map kept, over the welded surface.
    pub map: TriMap,
    /// Its remesher's numbers, [`RemeshStats::grid_attempts`] filled.
    pub stats: RemeshStats,
    /// Its extraction, the quads moved by the geometric stage.
    pub extracted: QuadExtraction,
    /// The stage's report; `None` when the extraction is not a valid
    /// quad mesh (the stage did not run: the output check says why).
    pub geometry: Option<GeometryReport>,
    /// Vertices merged by the weld of step 1.
    pub welded: usize,
    /// The attempt kept (0: the seed's grid position).
    pub attempt: usize,
    /// Its extraction is a valid quad mesh with the surface's topology.
    pub same_shape: bool,
    /// The options of the attempt kept (its seed is [`attempt_seed`]'s).
    pub opts: RemeshOptions,
}

/// Steps 1–5 (module docs). `each` sees every attempt's map, with the
/// attempt's index, before its checks (the CLI writes and describes it
/// there); its error ends the run. A remesh bug (a collapsed map, a map
/// the extraction refuses) sends the run to the next grid position, and
/// the last such error is the run's when no position gives a mesh (its
/// map is the last `each` saw); any other error of
/// the first attempt is the run's; a later attempt's error ends the
/// attempts (the best so far is kept). `remesh.grid_attempts` lists the
/// attempts that gave a mesh.
#[doc(hidden)]
pub fn remesh_staged(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    opts: &RemeshOptions,
    each: &mut dyn FnMut(usize, &RemeshedMap) -> Result<(), Error>,
) -> Result<Staged, Error> {
    let retry = opts.extract.geometry.mode != GeometryMode::Off;
    let mut best: Option<Staged> = None;
    let mut inverted = Vec::new();
    let mut last_error = None;
    for k in 0..if retry { GRID_ATTEMPTS } else { 1 } {
        let mut o = opts.clone();
        o.map.seed = attempt_seed(opts.map.seed, k);
        let attempt = attempt(positions, triangles, o, k, each);
        let staged = match (attempt, &best) {
            (Ok(s), _) => s,
            // a map of its own collapsed or refused (remesh's bug): the
            // next grid position, the error kept for when none works (the
            // last one's: its map is the one `each` saw last)
            (Err(e @ Error::Bug(_)), None) => {
                last_error = Some(e);
                continue;
            }
            (Err(e), None) => return Err(e),
            (Err(_), Some(_)) => break,
        };
        let Some(n) = staged.geometry.as_ref().map(|g| g.after.inverted) else {
            // not a valid mesh: the output check refuses it
            best = Some(staged);
            break;
        };
        inverted.push(n);
        // a topology unlike the surface's (holes merged) is worse than
        // any inverted count
        let worse = |s: &Staged| {
            (
                !s.same_shape,
                s.geometry.as_ref().map_or(usize::MAX, |g| g.after.inverted),
            )
        };
        let key = worse(&staged);
        if best.as_ref().is_none_or(|b| key < worse(b)) {
            best = Some(staged);
        }
        if key == (false, 0) {
            break;
        }
    }
    let Some(mut best) = best else {
        return Err(last_error.unwrap_or_else(|| Error::Bug("remesh: no attempt was made".into())));
    };
    best.stats.grid_attempts = inverted;
    Ok(best)
}

/// One attempt of [`remesh_staged`]: steps 1–5 with `opts`.
fn attempt(
    positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    opts: RemeshOptions,
    k: usize,
    each: &mut dyn FnMut(usize, &RemeshedMap) -> Result<(), Error>,
) -> Result<Staged, Error> {
    let made = remesh_map(positions, triangles, &opts)?;
    each(k, &made)?;
    made.check()?;
    let (welded, made_shape) = (made.welded, made.shape);
    let (map, stats, mut extracted) = made.extract()?;
    let m = &extracted.mesh;
    let report = dualex_check::check_quad_mesh(m.positions.len(), &m.cells);
    let same_shape = report.is_valid() && topology::quad_shape(&report) == made_shape;
    // (the quad stage reads nothing of the input's shape: the surface's)
    let input = steps::InputShape {
        shape: made_shape,
        boundary: (),
    };
    let geometry = report
        .is_valid()
        .then(|| steps::geometry(&map, &input, &mut extracted, &opts.extract.geometry));
    Ok(Staged {
        map,
        stats,
        extracted,
        geometry,
        welded,
        attempt: k,
        same_shape,
        opts,
    })
}

/// The signed and the unsigned area of a map (map units²).
fn map_areas(map: &TriMap) -> (f64, f64) {
    map.coords.iter().fold((0.0, 0.0), |(s, u), [a, b, c]| {
        let x = 0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]));
        (s + x, u + x.abs())
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The collapse check (step 3) on a good map of the cube, then on the
    /// same map shrunk a billion times (area far below the target's) and
    /// mirrored (every triangle flipped): remesh's bug, said as one.
    #[test]
    fn a_collapsed_map_is_a_bug() {
        let s = dualex_remesh::shapes::cube(2);
        let mut opts = RemeshOptions::default();
        opts.map.target = Target::Quads(24);
        let mut made = remesh_map(&s.positions, &s.triangles, &opts).expect("the cube's map");
        made.check().expect("a good map");
        let good = made.map.coords.clone();
        for c in made.map.coords.iter_mut().flatten() {
            *c = [c[0] * 1e-9, c[1] * 1e-9];
        }
        let e = made.check().expect_err("a shrunk map");
        assert!(matches!(e, Error::Bug(_)), "{e}");
        assert!(e.to_string().contains("the map collapsed: area"), "{e}");
        made.map.coords = good;
        for c in made.map.coords.iter_mut().flatten() {
            c[0] = -c[0];
        }
        made.stats.flipped = made.stats.triangles;
        let e = made.check().expect_err("a mirrored map");
        assert!(e.to_string().contains("triangles flipped"), "{e}");
    }
}
