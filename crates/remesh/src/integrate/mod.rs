//! Seamless integration: a per-corner `(u, v)` map from a cross field and
//! a cut.
//!
//! Input: a [`Surface`], a [`CrossField`], the cut (`is_cut` per edge: the
//! cut edges open the surface to disks and pass through every singular
//! vertex), the singular vertices and [`IntegrateOptions`]. Output: a
//! [`TriMap`] on the surface's own vertices and triangles whose corner
//! coordinates are the map (`dualex quad` extracts it), with an
//! [`IntegrateReport`].
//!
//! Steps, one module each:
//! 1. [`charts`]: comb the field across uncut edges, find the wedges
//!    (one `(u, v)` per wedge), the seams and their matchings;
//! 2. [`constraints`]: seams' transitions (rotation + translation), aligned
//!    boundary edges, gauge; the integer unknowns;
//! 3. [`system`]: the energy `Σ_f area_f·|∇(u, v) − s·(d_f, d_f⊥)|²`;
//! 4. [`crate::quantize`]: constraints eliminated by substitution
//!    ([`elim`]), SPD solves, rounding of the integer unknowns.
//!
//! Invariants of the output (rounded modes, consistent input): across
//! every interior edge the two triangles' coordinates of the shared
//! vertices differ by a rotation by a multiple of 90° plus an integer
//! translation; singular vertices (with `round_singularities`) sit on
//! integer points; aligned boundary edges lie on integer iso-lines.

pub mod charts;
pub mod constraints;
pub mod elim;
pub mod facing;
pub mod fit;
pub mod system;
#[cfg(test)]
mod test_cut;

use crate::field::CrossField;
use crate::integrate::constraints::Gauge;
use crate::integrate::elim::Form;
use crate::quantize::{quantize, Integers, QuantizeReport, Rounding};
use crate::separate::{Apart, NO_WALL};
use crate::surface::Surface;
use dualex_map::TriMap;

/// Options of [`integrate`].
#[derive(Clone, Debug)]
pub struct IntegrateOptions {
    /// Target number of quads `N`: the scale is `sqrt(N / area)` (quads of
    /// side `h = sqrt(area / N)`). Default: 1000. Ignored when `scale` is set.
    pub quads: Option<usize>,
    /// Map units per surface length (`1 / h`); overrides `quads`.
    pub scale: Option<f64>,
    /// How the integer unknowns are rounded. Default: [`Rounding::Direct`].
    pub rounding: Rounding,
    /// Put the singular vertices on integer points. Default: on.
    pub round_singularities: bool,
    /// Align boundary edges within this angle (radians) of a field
    /// direction to integer iso-lines; `None`: no alignment. Default:
    /// `Some(π/8)`.
    pub align_boundary: Option<f64>,
    /// Per edge: a sharp (feature) edge, aligned to an integer iso-line as
    /// a boundary edge is (same tolerance; nothing when
    /// `align_boundary` is `None`). Empty: none. When the rounding then
    /// leaves an integer unknown off the integers (a quantization
    /// conflict), the map is made again without them (one more
    /// integration). A feature curve left
    /// between grid lines makes quads that bend across it, inverted in
    /// the frame of either side (issue 21: 45 of the genus-3 plate's
    /// inverted quads at 100 quads). Default: empty.
    pub sharp: Vec<bool>,
    /// Where each component's gauge wedge sits before rounding (map units;
    /// default `(0, 0)`): a fractional offset moves the grid against the
    /// surface, so the rounding lands elsewhere.
    pub gauge_offset: [f64; 2],
    /// With `quads` (and no `scale`): fit the scale to the map's area.
    /// A continuous solve at `s = sqrt(N / area)` first measures the map's
    /// signed area `A` (the number of grid cells it covers); the map is
    /// then made at `s·sqrt(N / A)`. Without it a field that is not
    /// integrable (curl, many singularities) gives a smaller map than
    /// asked: 107 cells for 500 on the dragon, 457 on the horse. Default:
    /// on (one more solve).
    pub fit_area: bool,
    /// Most roundings of the area fit (the first and the re-roundings at
    /// the scales of [`fit::ScaleSearch`]; at least 1): each is a sparse
    /// solve, the integration's main cost. Default: [`ROUNDINGS`].
    pub max_roundings: usize,
    /// Roundings of an earlier integration of the same surface, field,
    /// cut and options but `quads` ([`IntegrateReport::roundings_seen`]):
    /// the area fit starts from them ([`fit::ScaleSearch::with_seen`]).
    /// Default: none.
    pub seen: Vec<(f64, f64)>,
}

impl Default for IntegrateOptions {
    fn default() -> Self {
        IntegrateOptions {
            quads: Some(1000),
            scale: None,
            rounding: Rounding::Direct,
            round_singularities: true,
            align_boundary: Some(std::f64::consts::FRAC_PI_8),
            sharp: Vec::new(),
            gauge_offset: [0.0, 0.0],
            fit_area: true,
            max_roundings: ROUNDINGS,
            seen: Vec::new(),
        }
    }
}

/// What [`integrate_report`] did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct IntegrateReport {
    /// The scale used (map units per length).
    pub scale: f64,
    /// The scale before the area fit (`sqrt(N / area)`; equal to `scale`
    /// without [`IntegrateOptions::fit_area`]).
    pub first_scale: f64,
    /// Signed area of the final map (map units²): about the quad count.
    pub map_area: f64,
    /// Roundings made (1 + re-roundings of [`IntegrateOptions::fit_area`]).
    pub roundings: usize,
    /// `(scale, signed area)` of every rounding made, in order.
    pub roundings_seen: Vec<(f64, f64)>,
    /// Wedges (chart vertices); the unknowns are twice as many.
    pub wedges: usize,
    /// Seam edges (cut interior edges).
    pub seams: usize,
    /// Seam edges with a nonzero rotation.
    pub rotated_seams: usize,
    /// Boundary edges aligned to iso-lines.
    pub aligned_edges: usize,
    /// The rounding's report.
    pub quantize: QuantizeReport,
}

/// The map (module docs).
pub fn integrate(
    surface: &Surface,
    field: &CrossField,
    is_cut: &[bool],
    singular_vertices: &[u32],
    opts: &IntegrateOptions,
) -> Result<TriMap, String> {
    integrate_report(surface, field, is_cut, singular_vertices, opts).map(|r| r.0)
}

/// [`integrate`] with its report.
pub fn integrate_report(
    surface: &Surface,
    field: &CrossField,
    is_cut: &[bool],
    singular_vertices: &[u32],
    opts: &IntegrateOptions,
) -> Result<(TriMap, IntegrateReport), String> {
    let first_scale = scale(surface, opts)?;
    // 1. the cut-open surface
    let charts = charts::build(surface, field, is_cut)?;
    // 2. constraints and integer unknowns
    let mut cons = constraints::build(
        surface,
        &charts,
        singular_vertices,
        opts.align_boundary,
        &opts.sharp,
    )?;
    if !opts.gauge_offset.iter().all(|x| x.is_finite()) {
        return Err(format!(
            "gauge offset {:?} is not finite",
            opts.gauge_offset
        ));
    }
    cons.gauge.offset = opts.gauge_offset;
    let mut integers = Vec::new();
    if opts.round_singularities {
        integers.extend(cons.singular.iter().cloned());
    }
    integers.extend(cons.boundary.iter().cloned());
    integers.extend(cons.sharp.iter().cloned());
    integers.extend(cons.translations.iter().cloned());
    // 3. energy, the scale fitted to the area (one continuous solve)
    let mut scale = first_scale;
    let mut energy = system::energy(surface, &charts, scale);
    let mut fit = None;
    let mut solves = 0;
    if let (true, None, Some(n)) = (opts.fit_area, opts.scale, opts.quads) {
        let x = continuous(&energy, &cons)?;
        let area = signed_area(&charts.corner_wedge, &x);
        // the continuous map is linear in s: its area goes as s²
        if area > 0.0 && area.is_finite() {
            scale *= (n as f64 / area).sqrt();
            energy = system::energy(surface, &charts, scale);
        }
        fit = Some(x);
        solves += 1;
    }
    // 4. solve, round, solve
    let first = if opts.round_singularities {
        cons.singular.len()
    } else {
        0
    };
    // the facing walls need a continuous map: the one of the area fit, or
    // one solved here, the first rounding's start then
    if fit.is_none() && !cons.boundary.is_empty() {
        fit = Some(continuous(&energy, &cons)?);
        solves += 1;
    }
    let walls = Walls::find(
        surface,
        &charts,
        &cons,
        fit.as_deref(),
        first,
        integers.len(),
    );
    // the rounding moves the area again: round anew at the scales of
    // [`fit::ScaleSearch`] (at most `max_roundings` in all), keeping the map whose
    // area is closest to `N`
    let target = match (opts.fit_area, opts.scale, opts.quads) {
        (true, None, Some(n)) => Some(n as f64),
        _ => None,
    };
    let mut best: Option<(f64, Vec<f64>, QuantizeReport, f64)> = None;
    let mut search = None;
    if let Some(n) = target {
        let (seeded, again) = fit::ScaleSearch::with_seen(n, &opts.seen, REFIT_TOLERANCE);
        search = Some(seeded);
        if let Some(s) = again {
            scale = s;
            energy = system::energy(surface, &charts, scale);
        }
    }
    let mut roundings_seen = Vec::new();
    for _ in 0..opts.max_roundings.max(1) {
        let start = fit
            .as_ref()
            .and_then(|x0| scaled_start(x0, scale / first_scale, &cons.rows, &cons.gauge));
        let pairs = walls.pairs(scale / first_scale);
        let ints = Integers {
            forms: &integers,
            first,
            apart: Apart {
                wall: &walls.wall,
                pairs: &pairs,
            },
        };
        let (x, q) = quantize(
            &energy,
            &cons.rows,
            &cons.gauge,
            &ints,
            opts.rounding,
            start,
        )?;
        solves += q.solves;
        let area = signed_area(&charts.corner_wedge, &x);
        roundings_seen.push((scale, area));
        let miss = target.map_or(0.0, |n| (area - n).abs() / n);
        if best.as_ref().is_none_or(|b| miss < b.0) {
            best = Some((miss, x, q, scale));
        }
        match search.as_mut() {
            Some(search) if miss > REFIT_TOLERANCE => {
                let next = search.next(scale, area);
                if next == scale {
                    break;
                }
                scale = next;
                energy = system::energy(surface, &charts, scale);
            }
            _ => break,
        }
    }
    let Some((_, x, mut quantize, scale)) = best else {
        return Err("integrate: no solve".into());
    };
    // sharp edges on iso-lines only where the rounding keeps every
    // integer unknown whole (constraints' module docs): else without them
    if quantize.conflicts > 0 && !cons.sharp.is_empty() {
        let mut o = opts.clone();
        o.sharp = Vec::new();
        return integrate_report(surface, field, is_cut, singular_vertices, &o);
    }
    quantize.solves = solves;
    let coords = charts
        .corner_wedge
        .chunks_exact(3)
        .map(|w| std::array::from_fn(|i| [x[2 * w[i] as usize], x[2 * w[i] as usize + 1]]))
        .collect();
    let map = TriMap {
        positions: surface.positions.clone(),
        simplices: surface.triangles.clone(),
        coords,
    };
    let report = IntegrateReport {
        scale,
        first_scale,
        map_area: signed_area(&charts.corner_wedge, &x),
        roundings: roundings_seen.len(),
        roundings_seen,
        wedges: charts.wedges,
        seams: charts.seam.iter().flatten().count(),
        rotated_seams: charts.seam.iter().flatten().filter(|&&p| p != 0).count(),
        aligned_edges: cons.aligned_edges,
        quantize,
    };
    Ok((map, report))
}

/// The continuous minimizer at `k` times the scale of `x0` (the
/// minimizer with the gauge at the origin), with the gauge at its offset:
/// the energy is quadratic with a target linear in the scale and the rows
/// are homogeneous, so the minimizer is `k·x0` plus the minimizer without
/// target, which is the uniform translation to the offset whenever that
/// translation satisfies every row (checked; `None` otherwise: solve).
fn scaled_start(x0: &[f64], k: f64, rows: &[Form], gauge: &Gauge) -> Option<Vec<f64>> {
    let x: Vec<f64> = x0
        .iter()
        .enumerate()
        .map(|(i, &v)| k * v + gauge.offset[i % 2])
        .collect();
    let size = x.iter().fold(1.0f64, |m, v| m.max(v.abs()));
    let feasible = rows
        .iter()
        .chain(&gauge.rows(rows.iter()))
        .all(|r| r.eval(&x).abs() <= 1e-9 * size);
    feasible.then_some(x)
}

/// The continuous map of `energy` under `cons`'s rows (no integer
/// unknown), the gauge at the origin: the area fit's, and the facing
/// walls' when there is no fit.
fn continuous(
    energy: &system::Energy,
    cons: &constraints::Constraints,
) -> Result<Vec<f64>, String> {
    let mut origin = cons.gauge.clone();
    origin.offset = [0.0, 0.0];
    let none = Integers::new(&[], 0);
    let (x, _) = quantize(
        energy,
        &cons.rows,
        &origin,
        &none,
        Rounding::Continuous,
        None,
    )?;
    Ok(x)
}

/// The facing boundary walls of one integration ([`facing`]), found once
/// in the continuous map at the first scale.
struct Walls {
    /// Per integer unknown: its wall or [`NO_WALL`].
    wall: Vec<u32>,
    /// [`facing::Facing::pairs`] at the first scale.
    pairs: Vec<(u32, u32, f64)>,
}

impl Walls {
    /// The walls of `cons`'s boundary unknowns (at `offset` among the
    /// `count` integer unknowns) in `x0`, the continuous map at the first
    /// scale (none without it).
    fn find(
        surface: &Surface,
        charts: &charts::Charts,
        cons: &constraints::Constraints,
        x0: Option<&[f64]>,
        offset: usize,
        count: usize,
    ) -> Walls {
        let mut walls = Walls {
            wall: vec![NO_WALL; count],
            pairs: Vec::new(),
        };
        let Some(x0) = x0 else {
            return walls;
        };
        let facing = facing::find(surface, charts, cons, x0, WALL_REACH * FIRST_TO_LAST);
        for (k, &w) in facing.wall.iter().enumerate() {
            if let Some(slot) = walls.wall.get_mut(offset + k) {
                *slot = w;
            }
        }
        walls.pairs = facing.pairs;
        walls
    }

    /// The pairs within [`WALL_REACH`] at `ratio` times the first scale.
    fn pairs(&self, ratio: f64) -> Vec<(u32, u32)> {
        self.pairs
            .iter()
            .filter(|p| p.2 * ratio < WALL_REACH)
            .map(|p| (p.0, p.1))
            .collect()
    }
}

/// Facing walls further apart than this (map units) are left to the
/// nearest rounding: it keeps walls 1 apart apart, and [`crate::separate`]
/// moves a wall by less than 1.5.
const WALL_REACH: f64 = 3.0;

/// Largest ratio of a rounding's scale to the first scale whose facing
/// walls are all found.
const FIRST_TO_LAST: f64 = 2.5;

/// Default of [`IntegrateOptions::max_roundings`]: the first rounding and
/// at most 4 re-roundings.
pub const ROUNDINGS: usize = 5;

/// Relative miss of the rounded map's area that asks for a re-rounding.
const REFIT_TOLERANCE: f64 = 0.05;

/// The map's signed area: `Σ_t` of its triangles' signed areas, with
/// `x` the wedges' `(u, v)` and `corner_wedge` the wedge of every corner.
fn signed_area(corner_wedge: &[u32], x: &[f64]) -> f64 {
    let uv = |w: u32| [x[2 * w as usize], x[2 * w as usize + 1]];
    corner_wedge
        .chunks_exact(3)
        .map(|w| {
            let (a, b, c) = (uv(w[0]), uv(w[1]), uv(w[2]));
            0.5 * ((b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]))
        })
        .sum()
}

/// The scale from the options (module docs of [`IntegrateOptions`]).
fn scale(surface: &Surface, opts: &IntegrateOptions) -> Result<f64, String> {
    let s = match (opts.scale, opts.quads) {
        (Some(s), _) => s,
        (None, Some(n)) => (n as f64 / surface.areas.iter().sum::<f64>()).sqrt(),
        (None, None) => return Err("integrate: neither a scale nor a quad count".into()),
    };
    if s.is_finite() && s > 0.0 {
        Ok(s)
    } else {
        Err(format!(
            "integrate: scale {s} (needs a positive finite number)"
        ))
    }
}

#[cfg(test)]
mod test_meshes;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_fit;
