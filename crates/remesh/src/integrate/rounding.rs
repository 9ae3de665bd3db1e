//! Steps 4–5 of the integration (module docs of [`crate::integrate`]):
//! the integer unknowns rounded ([`crate::quantize`]) at the scales of
//! the area fit ([`super::fit::ScaleSearch`]), the facing boundary walls
//! kept apart ([`super::facing`], [`crate::separate`]); then the map and
//! its report.
//!
//! Input: the [`Setup`] of steps 1–3. Output: the map whose area is
//! closest to `N` (the first rounding without a target) and its
//! [`IntegrateReport`].

use super::constraints::{self, Gauge};
use super::elim::Form;
use super::{charts, continuous, facing, fit, integrate_report, signed_area, system};
use super::{IntegrateOptions, IntegrateReport, Setup};
use crate::error::RemeshError;
use crate::field::CrossField;
use crate::quantize::{quantize, Integers, QuantizeReport};
use crate::separate::{Apart, NO_WALL};
use crate::surface::Surface;
use dualex_map::TriMap;

/// A rounded map.
struct Rounded {
    /// Its relative miss of the area asked (0 without a target).
    miss: f64,
    /// The unknowns (`(u, v)` per wedge).
    x: Vec<f64>,
    /// The rounding's report.
    quantize: QuantizeReport,
    /// The scale it was made at.
    scale: f64,
}

/// The `(scale, signed area)` of every rounding made, in order.
type Seen = Vec<(f64, f64)>;

/// Steps 4–5 (module docs): the integer unknowns rounded
/// ([`crate::quantize`]) at the scales of the area fit, the map closest
/// to the area kept; then the map and its report. When the rounding
/// leaves an integer unknown off the integers with sharp edges on
/// iso-lines, the whole integration again without them.
pub fn round(
    surface: &Surface,
    field: &CrossField,
    is_cut: &[bool],
    singular_vertices: &[u32],
    opts: &IntegrateOptions,
    mut s: Setup,
) -> Result<(TriMap, IntegrateReport), RemeshError> {
    let (best, roundings_seen) = roundings(surface, opts, &mut s)?;
    let Some(Rounded {
        x,
        mut quantize,
        scale,
        ..
    }) = best
    else {
        return Err(RemeshError::NoSolve);
    };
    // sharp edges on iso-lines only where the rounding keeps every
    // integer unknown whole (constraints' module docs): else without them
    if quantize.conflicts > 0 && !s.cons.sharp.is_empty() {
        let mut o = opts.clone();
        o.sharp = Vec::new();
        return integrate_report(surface, field, is_cut, singular_vertices, &o);
    }
    quantize.solves = s.solves;
    // 5. the map and its report
    let coords = s
        .charts
        .corner_wedge
        .chunks_exact(3)
        .map(|w| std::array::from_fn(|i| [x[2 * w[i] as usize], x[2 * w[i] as usize + 1]]))
        .collect();
    let map = TriMap {
        positions: surface.positions.clone(),
        simplices: surface.triangles.clone(),
        coords,
    };
    let charts = &s.charts;
    let report = IntegrateReport {
        scale,
        first_scale: s.first_scale,
        map_area: signed_area(&charts.corner_wedge, &x),
        roundings: roundings_seen.len(),
        roundings_seen,
        wedges: charts.wedges,
        seams: charts.seam.iter().flatten().count(),
        rotated_seams: charts.seam.iter().flatten().filter(|&&p| p != 0).count(),
        aligned_edges: s.cons.aligned_edges,
        quantize,
    };
    Ok((map, report))
}

/// Step 4: solve, round, solve ([`crate::quantize`]) at the scales of
/// [`fit::ScaleSearch`] (at most `max_roundings` in all): the map whose
/// area is closest to `N`, and the `(scale, area)` of every rounding.
fn roundings(
    surface: &Surface,
    opts: &IntegrateOptions,
    s: &mut Setup,
) -> Result<(Option<Rounded>, Seen), RemeshError> {
    let first = if opts.round_singularities {
        s.cons.singular.len()
    } else {
        0
    };
    // the facing walls need a continuous map: the one of the area fit, or
    // one solved here, the first rounding's start then
    if s.fit.is_none() && !s.cons.boundary.is_empty() {
        s.fit = Some(continuous(&s.energy, &s.cons)?);
        s.solves += 1;
    }
    let walls = Walls::find(
        surface,
        &s.charts,
        &s.cons,
        s.fit.as_deref(),
        first,
        s.integers.len(),
    );
    // the rounding moves the area again: round anew at the scales of
    // [`fit::ScaleSearch`] (at most `max_roundings` in all), keeping the map whose
    // area is closest to `N`
    let target = match (opts.fit_area, opts.scale, opts.quads) {
        (true, None, Some(n)) => Some(n as f64),
        _ => None,
    };
    let mut best: Option<Rounded> = None;
    let mut search = None;
    if let Some(n) = target {
        let (seeded, again) = fit::ScaleSearch::with_seen(n, &opts.seen, REFIT_TOLERANCE);
        search = Some(seeded);
        if let Some(scale) = again {
            s.scale = scale;
            s.energy = system::energy(surface, &s.charts, s.scale);
        }
    }
    let mut roundings_seen = Vec::new();
    for _ in 0..opts.max_roundings.max(1) {
        let (x, q) = round_once(opts, s, &walls, first)?;
        let area = signed_area(&s.charts.corner_wedge, &x);
        roundings_seen.push((s.scale, area));
        let miss = target.map_or(0.0, |n| (area - n).abs() / n);
        if best.as_ref().is_none_or(|b| miss < b.miss) {
            best = Some(Rounded {
                miss,
                x,
                quantize: q,
                scale: s.scale,
            });
        }
        match search.as_mut() {
            Some(search) if miss > REFIT_TOLERANCE => {
                let next = search.next(s.scale, area);
                if next == s.scale {
                    break;
                }
                s.scale = next;
                s.energy = system::energy(surface, &s.charts, s.scale);
            }
            _ => break,
        }
    }
    Ok((best, roundings_seen))
}

/// One rounding ([`crate::quantize`]) at the scale of `s`, started from
/// the area fit's continuous map scaled to it, the facing walls within
/// reach kept apart; its solves counted in `s`.
fn round_once(
    opts: &IntegrateOptions,
    s: &mut Setup,
    walls: &Walls,
    first: usize,
) -> Result<(Vec<f64>, QuantizeReport), RemeshError> {
    let ratio = s.scale / s.first_scale;
    let start = s
        .fit
        .as_ref()
        .and_then(|x0| scaled_start(x0, ratio, &s.cons.rows, &s.cons.gauge));
    let pairs = walls.pairs(ratio);
    let ints = Integers {
        forms: &s.integers,
        first,
        apart: Apart {
            wall: &walls.wall,
            pairs: &pairs,
        },
    };
    let (x, q) = quantize(
        &s.energy,
        &s.cons.rows,
        &s.cons.gauge,
        &ints,
        opts.rounding,
        start,
    )?;
    s.solves += q.solves;
    Ok((x, q))
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

/// Relative miss of the rounded map's area that asks for a re-rounding.
const REFIT_TOLERANCE: f64 = 0.05;
