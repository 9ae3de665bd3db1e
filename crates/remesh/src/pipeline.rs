//! The whole remesher: a plain surface in, a grid-preserving map out.
//!
//! Input: a [`Surface`] and [`RemeshOptions`]. Output: [`Remeshed`], the
//! per-corner map (a [`TriMap`] over the surface's own vertices and
//! triangles, which `dualex quad` extracts) and [`RemeshStats`].
//!
//! Steps, one call each in the driver `make` (numbered alike there), each its
//! own module:
//! 1. **refine** ([`crate::refine`]): the edges longer than two target
//!    quad edges split (a CAD fan cap or cone gets free faces inside its
//!    feature rim; the map is over this refined surface, which is the
//!    input's exactly);
//! 2. **features** ([`smooth::features`], [`crate::features`]): the
//!    options and the surface checked, the feature curves, the
//!    directions they and the boundary fix;
//! 3. **denoise** ([`smooth::denoise`], [`crate::denoise`]): the surface
//!    smoothed along its normals, which the field is solved on;
//! 4. **cross field** ([`smooth::solve`], [`crate::smooth`]): the
//!    smoothest field aligned to the boundary and feature curves,
//!    carried back to the surface, its singular vertices
//!    ([`crate::singularity`]);
//! 5. **quarters** ([`smooth::quarters`], [`crate::quarters`]): +½ and +1
//!    singularities split into quarters, the field solved again;
//! 6. **seed**: the field of every free component turned (below);
//! 7. **cut** ([`crate::cut`]): a cut through the singular vertices to a
//!    disk per component;
//! 8. **integrate** ([`integrate::setup`]): seamless least-squares
//!    integration at a scale fitted so that the map covers about `N`
//!    cells ([`IntegrateOptions::fit_area`]);
//! 9. **quantize** ([`integrate::round`], [`crate::quantize`]): the
//!    integer unknowns rounded, at the scales of the area fit;
//! 10. **recount** ([`crate::recount`]): with [`remesh_counted`] the
//!     extraction's quad count of that map is measured and, when it
//!     misses `N` by more than [`recount::RECOUNT_TOLERANCE`], steps 8–9
//!     run once more for the area that count asks (`dualex remesh` does;
//!     the extraction is not a dependency of this crate);
//! 11. **stats**: the numbers ([`RemeshStats`]).
//!
//! Measured defaults (crate README, "Realistic maps"): on the shared real
//! surfaces 4–483 singularities (reference maps: 30–403) and 0–3.4 %
//! flipped triangles at 2 000 quads on all but the dragon (5.7 %; 3.2 %
//! at 5 000 quads), quad counts within 5 % of `N` at 2 000.
//!
//! The seed moves the grid against the surface (the gauge of every
//! component: a random translation before rounding) and turns the field
//! of every component that has no boundary and no sharp edge (its
//! smoothest field is only known up to a rotation). So seeds 1, 2, …
//! give different, equally cheap maps of one surface: the messy maps the
//! tests run (see the "maps made the cheap way").

use crate::cut::{cut_to_disk, Cut};
use crate::error::RemeshError;
use crate::field::CrossField;
use crate::integrate::{self, IntegrateOptions, IntegrateReport};
use crate::quantize::Rounding;
use crate::recount::{self, CountQuads, Counted};
use crate::smooth::{self, FieldOptions, FieldResult};
use crate::surface::{Surface, NO_FACE};
use dualex_map::TriMap;
use dualex_util::timing::Laps;
use dualex_util::union_find::{find, union};
use std::collections::BTreeMap;
use std::time::{Duration, Instant};

/// How big the quads are.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Target {
    /// About this many quads.
    Quads(usize),
    /// Quad edge length in model units.
    EdgeLength(f64),
}

/// How the map's integer unknowns are made integers.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Quantization {
    /// Seams, feature lines and singular vertices rounded all at once,
    /// then one more solve.
    Direct,
    /// The same in batches, closest to an integer first.
    Greedy,
    /// Seams and feature lines rounded (the map must be grid-preserving),
    /// singular vertices left where the solve puts them: off the grid.
    SingularitiesOff,
}

/// Options of [`remesh`].
#[derive(Clone, Debug)]
pub struct RemeshOptions {
    /// Quad size.
    pub target: Target,
    /// Edges sharper than this (degrees between the normals) are
    /// features when they form feature curves ([`crate::features`]).
    pub sharp_degrees: f64,
    /// Rounding.
    pub quantization: Quantization,
    /// Seed (module docs).
    pub seed: u64,
}

impl Default for RemeshOptions {
    fn default() -> Self {
        RemeshOptions {
            target: Target::Quads(1000),
            sharp_degrees: 35.0,
            quantization: Quantization::Direct,
            seed: 1,
        }
    }
}

/// What [`remesh`] made, in numbers.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct RemeshStats {
    /// Triangles of the map: the surface's, with its long edges split
    /// ([`crate::refine`]).
    pub triangles: usize,
    /// Triangles of the surface given.
    pub input_triangles: usize,
    /// Interior singular vertices of the field.
    pub singularities: usize,
    /// Their indices, in quarter turns: count per index.
    pub singularity_index: BTreeMap<i32, usize>,
    /// Boundary vertices where the field turns (corners).
    pub boundary_singularities: usize,
    /// Sharp edges the field follows.
    pub sharp_edges: usize,
    /// Edges of the cut.
    pub cut_edges: usize,
    /// Triangles whose map is reverted (negative area).
    pub flipped: usize,
    /// Triangles whose map has zero area.
    pub degenerate: usize,
    /// Map units per model unit.
    pub scale: f64,
    /// The scale before it was fitted to the map's area
    /// ([`IntegrateOptions::fit_area`]).
    pub first_scale: f64,
    /// Signed area of the map (map units²): about the quad count.
    pub map_area: f64,
    /// Roundings made (the area fit may round again at another scale).
    pub roundings: usize,
    /// Integer unknowns rounded.
    pub rounded: usize,
    /// Integer unknowns left off the integers (0 when rounding).
    pub off_grid: usize,
    /// Largest move of a rounding, in map units.
    pub max_rounding: f64,
    /// The extraction's quad count of each map made
    /// ([`remesh_counted`]: one, or two when the first missed `N`, after
    /// the maps refused with the grid where the seed puts it;
    /// `None`: the extraction refused that map); empty without a count.
    pub counted: Vec<Option<usize>>,
    /// The index in `counted` of the map kept (`None` without a count).
    pub kept: Option<usize>,
    /// Set by the facade's `remesh` (`dualex::remesh`, `dualex remesh`):
    /// the inverted quads its geometric stage left at each grid position
    /// tried, the seed's first (another is tried while quads are left
    /// inverted, a few times at most; the first with the fewest is kept).
    /// Empty when only the map was made.
    pub grid_attempts: Vec<usize>,
    /// Wall-clock milliseconds: field, cut, integration (with rounding;
    /// both maps when made twice), the extraction's counts
    /// ([`remesh_counted`]).
    pub time_ms: [f64; 4],
}

/// A map and its numbers.
#[derive(Clone, Debug)]
pub struct Remeshed {
    /// The map, one chart per triangle corner.
    pub map: TriMap,
    /// Its numbers.
    pub stats: RemeshStats,
}

/// The map of `surface` (module docs).
pub fn remesh(surface: &Surface, opts: &RemeshOptions) -> Result<Remeshed, RemeshError> {
    make(surface, opts, None)
}

/// [`remesh`] with the extraction's quad count in the loop (for
/// [`Target::Quads`]). `count` tells how many quads the extraction makes
/// of a map (`None`: it cannot tell, e.g. it refuses the map). The area
/// fit makes the map's area about `N`, but the extraction does not make
/// one quad per cell: its repair adds quads near singular vertices off
/// the grid (up to ~25 % at 100 quads), its doublet removal takes some,
/// a global fallback subdivides (×4). When the first map's count `Q`
/// misses `N` by more than [`recount::RECOUNT_TOLERANCE`] with a share of quads per
/// cell within [`recount::RECOUNT_MAX_RATIO`] (not a subdivision), the quads are taken as
/// proportional to the area `A` (`Q/A` quads per cell) and the map is
/// made once more for the area `N·A/Q` (field and cut reused; the area
/// fit starts from the first map's roundings and has what they left of
/// its budget, two roundings at least);
/// the map whose count is closer to `N` is kept, and a map the extraction
/// refuses never replaces one it takes.
pub fn remesh_counted(
    surface: &Surface,
    opts: &RemeshOptions,
    count: &mut CountQuads<'_>,
) -> Result<Remeshed, RemeshError> {
    make(surface, opts, Some(count))
}

/// [`remesh`], and [`remesh_counted`] when `count` is given: the steps
/// of the module docs, one call each, in their order.
fn make(
    surface: &Surface,
    opts: &RemeshOptions,
    count: Option<&mut CountQuads<'_>>,
) -> Result<Remeshed, RemeshError> {
    let t0 = Instant::now();
    // 1. long edges split: fans and strips get room (crate::refine)
    let longest = crate::refine::QUAD_EDGES * quad_edge(surface, opts.target);
    let refined = crate::refine::split_long_edges(surface, longest);
    let input = surface;
    let surface = refined.as_ref().unwrap_or(surface);
    let fopts = FieldOptions {
        sharp_degrees: opts.sharp_degrees,
        ..FieldOptions::default()
    };
    // (the field's laps are its own: the stats time the field as a whole)
    let mut laps = Laps::start();
    // 2. feature curves, and the directions they and the boundary fix
    let features = smooth::features(surface, &fopts)?;
    // 3. the surface denoised along its normals, the field's
    let mut on = smooth::denoise(surface, &fopts, features);
    // 4. the smoothest cross field, carried back, its singular vertices
    let mut solved = smooth::solve(surface, &on, &fopts, &mut laps)?;
    // 5. quarter singularities in place of +1/2 and +1
    smooth::quarters(surface, &mut on, &fopts, &mut solved, &mut laps)?;
    let mut f = solved.result(surface, on, &fopts, laps);
    // 6. the seed turns the field of every free component
    let mut rng = dualex_util::rng::SplitMix::new(opts.seed);
    let angle = rng.unit() * std::f64::consts::FRAC_PI_2;
    turn_free_components(surface, &mut f.field, &f.fixed, angle);
    let t1 = Instant::now();
    // 7. a cut through the singular vertices to a disk per component
    let cut = cut_to_disk(surface, &f.singularities)?;
    let t2 = Instant::now();
    let iopts = integrate_options(opts, [rng.unit(), rng.unit()], &f.sharp);
    let singular: Vec<u32> = f.singularities.iter().map(|&(v, _)| v).collect();
    let run = |o: &IntegrateOptions| {
        // 8. seamless integration at the scale fitted to the area
        let setup = integrate::setup(surface, &f.field, &cut.is_cut, &singular, o)?;
        // 9. the integer unknowns rounded (crate::quantize)
        integrate::round(surface, &f.field, &cut.is_cut, &singular, o, setup)
    };
    // 10. the extraction's count: steps 8–9 again when it misses N
    let (made, kept) = counted(run, iopts, opts.target, count)?;
    let t3 = Instant::now();
    // 11. the numbers
    let ms = |a: Instant, b: Instant| (b - a).as_secs_f64() * 1e3;
    let counting = made.counting.as_secs_f64() * 1e3;
    let time_ms = [ms(t0, t1), ms(t1, t2), ms(t2, t3) - counting, counting];
    let stats = stats(input, surface, &f, &cut, &made, kept, time_ms);
    Ok(Remeshed {
        map: made.map,
        stats,
    })
}

/// The options of steps 8–9: the target, the rounding, the gauge offset
/// drawn from the seed, the sharp edges the field follows.
fn integrate_options(opts: &RemeshOptions, gauge: [f64; 2], sharp: &[bool]) -> IntegrateOptions {
    IntegrateOptions {
        quads: match opts.target {
            Target::Quads(n) => Some(n),
            Target::EdgeLength(_) => None,
        },
        scale: match opts.target {
            Target::EdgeLength(h) => Some(1.0 / h),
            Target::Quads(_) => None,
        },
        rounding: match opts.quantization {
            Quantization::Greedy => Rounding::Greedy { rounds: 4 },
            _ => Rounding::Direct,
        },
        round_singularities: opts.quantization != Quantization::SingularitiesOff,
        gauge_offset: gauge,
        sharp: sharp.to_vec(),
        ..IntegrateOptions::default()
    }
}

/// Step 10: the map of `run` counted by the extraction and made again
/// when the count misses `N` ([`recount`]), with a count and a quad
/// target (`Some` index of the map kept); else the one map of `run`.
fn counted(
    mut run: impl FnMut(&IntegrateOptions) -> Result<(TriMap, IntegrateReport), RemeshError>,
    iopts: IntegrateOptions,
    target: Target,
    count: Option<&mut CountQuads<'_>>,
) -> Result<(Counted, Option<usize>), RemeshError> {
    match (target, count) {
        (Target::Quads(n), Some(count)) => {
            let c = recount::integrate_counted(run, iopts, n, count)?;
            let kept = Some(c.kept);
            Ok((c, kept))
        }
        _ => {
            let (map, report) = run(&iopts)?;
            let one = Counted {
                map,
                report,
                counted: Vec::new(),
                kept: 0,
                counting: Duration::ZERO,
            };
            Ok((one, None))
        }
    }
}

/// Step 11: the numbers of the map made (`input`: the surface given,
/// `surface`: refined; `kept`: the index of the map kept among those
/// counted).
fn stats(
    input: &Surface,
    surface: &Surface,
    f: &FieldResult,
    cut: &Cut,
    made: &Counted,
    kept: Option<usize>,
    time_ms: [f64; 4],
) -> RemeshStats {
    let mut singularity_index = BTreeMap::new();
    for &(_, q) in &f.singularities {
        *singularity_index.entry(q).or_insert(0) += 1;
    }
    let (flipped, degenerate) = orientation_counts(&made.map);
    let rep = &made.report;
    RemeshStats {
        triangles: surface.triangles.len(),
        input_triangles: input.triangles.len(),
        singularities: f.singularities.len(),
        singularity_index,
        boundary_singularities: f.boundary_singularities.len(),
        sharp_edges: f.sharp.iter().filter(|&&s| s).count(),
        cut_edges: cut.is_cut.iter().filter(|&&c| c).count(),
        flipped,
        degenerate,
        scale: rep.scale,
        first_scale: rep.first_scale,
        map_area: rep.map_area,
        roundings: rep.roundings,
        rounded: rep.quantize.rounded,
        off_grid: rep.quantize.off_grid,
        max_rounding: rep.quantize.max_rounding,
        counted: made.counted.clone(),
        kept,
        grid_attempts: Vec::new(),
        time_ms,
    }
}

/// The target's quad edge length in model units ([`crate::refine`] splits
/// the edges longer than [`crate::refine::QUAD_EDGES`] of them).
fn quad_edge(surface: &Surface, target: Target) -> f64 {
    match target {
        Target::EdgeLength(h) => h,
        Target::Quads(n) => (surface.areas.iter().sum::<f64>() / n.max(1) as f64).sqrt(),
    }
}

/// Turns the field by `angle` on every component with no fixed face
/// (no boundary, no sharp edge): the matchings stay as they are.
fn turn_free_components(surface: &Surface, field: &mut CrossField, fixed: &[bool], angle: f64) {
    let nf = surface.triangles.len();
    let mut parent: Vec<u32> = (0..nf as u32).collect();
    for &[a, b] in &surface.edge_faces {
        if b != NO_FACE {
            union(&mut parent, a, b);
        }
    }
    let mut pinned = vec![false; nf];
    for f in 0..nf as u32 {
        if fixed[f as usize] {
            let r = find(&mut parent, f);
            pinned[r as usize] = true;
        }
    }
    for f in 0..nf as u32 {
        let r = find(&mut parent, f);
        if !pinned[r as usize] {
            field.angle[f as usize] += angle;
        }
    }
}

/// Reverted and zero-area triangles of a map.
pub fn orientation_counts(map: &TriMap) -> (usize, usize) {
    let mut flipped = 0;
    let mut degenerate = 0;
    for c in &map.coords {
        let [a, b, d] = *c;
        let area = (b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0]);
        if area < 0.0 {
            flipped += 1;
        } else if area == 0.0 {
            degenerate += 1;
        }
    }
    (flipped, degenerate)
}

#[cfg(test)]
mod tests;
