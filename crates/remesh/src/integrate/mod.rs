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
//! Steps, one module each; [`setup`] runs 1–3 (the pipeline's step 8,
//! [`crate::pipeline`]) and [`round`] runs 4–5 (its step 9):
//! 1. [`charts`]: comb the field across uncut edges, find the wedges
//!    (one `(u, v)` per wedge), the seams and their matchings;
//! 2. [`constraints`]: seams' transitions (rotation + translation), aligned
//!    boundary edges, gauge; the integer unknowns;
//! 3. [`system`]: the energy `Σ_f area_f·|∇(u, v) − s·(d_f, d_f⊥)|²`, at
//!    the scale fitted to the area by one continuous solve
//!    ([`IntegrateOptions::fit_area`]);
//! 4. [`crate::quantize`]: constraints eliminated by substitution
//!    ([`elim`]), SPD solves, rounding of the integer unknowns, at the
//!    scales of [`fit::ScaleSearch`], facing walls kept apart ([`facing`]);
//! 5. the map kept and its report.
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
mod rounding;
pub mod system;

pub use rounding::round;
#[cfg(test)]
mod test_cut;

use crate::error::RemeshError;
use crate::field::CrossField;
use crate::integrate::elim::Form;
use crate::quantize::{quantize, Integers, QuantizeReport, Rounding};
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
) -> Result<TriMap, RemeshError> {
    integrate_report(surface, field, is_cut, singular_vertices, opts).map(|r| r.0)
}

/// [`integrate`] with its report: steps 1–3 ([`setup`]), then steps
/// 4–5 ([`round`]).
pub fn integrate_report(
    surface: &Surface,
    field: &CrossField,
    is_cut: &[bool],
    singular_vertices: &[u32],
    opts: &IntegrateOptions,
) -> Result<(TriMap, IntegrateReport), RemeshError> {
    let setup = setup(surface, field, is_cut, singular_vertices, opts)?;
    round(surface, field, is_cut, singular_vertices, opts, setup)
}

/// What steps 1–3 made ([`setup`]), for the rounding ([`round`]).
pub struct Setup {
    /// Step 1: the cut-open surface.
    charts: charts::Charts,
    /// Step 2: the constraints, the gauge at its offset.
    cons: constraints::Constraints,
    /// Step 2: the integer unknowns (singular vertices first when they
    /// are rounded, then boundary, sharp edges, seams' translations).
    integers: Vec<Form>,
    /// The scale of the options ([`scale`]).
    first_scale: f64,
    /// Step 3: the scale fitted to the area, and the energy at it.
    scale: f64,
    energy: system::Energy,
    /// Step 3: the continuous map of the area fit (at `first_scale`).
    fit: Option<Vec<f64>>,
    /// Sparse solves made.
    solves: usize,
}

/// Steps 1–3 (module docs): the charts, the constraints and integer
/// unknowns, the energy at the scale fitted to the area (one continuous
/// solve).
pub fn setup(
    surface: &Surface,
    field: &CrossField,
    is_cut: &[bool],
    singular_vertices: &[u32],
    opts: &IntegrateOptions,
) -> Result<Setup, RemeshError> {
    let first_scale = scale(surface, opts)?;
    // 1. the cut-open surface
    let charts = charts::build(surface, field, is_cut)?;
    // 2. constraints and integer unknowns
    let (cons, integers) = constrain(surface, &charts, singular_vertices, opts)?;
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
    Ok(Setup {
        charts,
        cons,
        integers,
        first_scale,
        scale,
        energy,
        fit,
        solves,
    })
}

/// Step 2: the [`constraints`] with the gauge at its offset, and the
/// integer unknowns in their order ([`Setup::integers`]).
fn constrain(
    surface: &Surface,
    charts: &charts::Charts,
    singular_vertices: &[u32],
    opts: &IntegrateOptions,
) -> Result<(constraints::Constraints, Vec<Form>), RemeshError> {
    let mut cons = constraints::build(
        surface,
        charts,
        singular_vertices,
        opts.align_boundary,
        &opts.sharp,
    )?;
    if !opts.gauge_offset.iter().all(|x| x.is_finite()) {
        return Err(RemeshError::GaugeOffset(opts.gauge_offset));
    }
    cons.gauge.offset = opts.gauge_offset;
    let mut integers = Vec::new();
    if opts.round_singularities {
        integers.extend(cons.singular.iter().cloned());
    }
    integers.extend(cons.boundary.iter().cloned());
    integers.extend(cons.sharp.iter().cloned());
    integers.extend(cons.translations.iter().cloned());
    Ok((cons, integers))
}

/// The continuous map of `energy` under `cons`'s rows (no integer
/// unknown), the gauge at the origin: the area fit's, and the facing
/// walls' when there is no fit.
fn continuous(
    energy: &system::Energy,
    cons: &constraints::Constraints,
) -> Result<Vec<f64>, RemeshError> {
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

/// Default of [`IntegrateOptions::max_roundings`]: the first rounding and
/// at most 4 re-roundings.
pub const ROUNDINGS: usize = 5;

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
fn scale(surface: &Surface, opts: &IntegrateOptions) -> Result<f64, RemeshError> {
    let s = match (opts.scale, opts.quads) {
        (Some(s), _) => s,
        (None, Some(n)) => (n as f64 / surface.areas.iter().sum::<f64>()).sqrt(),
        (None, None) => return Err(RemeshError::NoScale),
    };
    if s.is_finite() && s > 0.0 {
        Ok(s)
    } else {
        Err(RemeshError::Scale(s))
    }
}

#[cfg(test)]
mod test_checks;
#[cfg(test)]
mod test_meshes;
#[cfg(test)]
mod tests;
#[cfg(test)]
mod tests_fit;
