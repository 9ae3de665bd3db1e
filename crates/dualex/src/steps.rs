//! The pipeline one step at a time, for tools that report on every step
//! (the CLI: its own checks, messages and `--stats` JSON); [`quad()`] and
//! [`hex()`] run these same steps in this order, one generic code for both
//! dimensions:
//!
//! - weld ([`weld`]: coincident boundary vertices merged, a cut mesh
//!   made whole), before the pipeline's step 1;
//! - extract ([`extract`], the pipeline's steps 1–11, numbered as in
//!   ARCHITECTURE.md's "The steps of an extraction"): the mesh, the
//!   extraction's own detailed report ([`QuadReport`], [`HexReport`]: every
//!   stage's counts, its JSON, the sanitization's leftovers), the cells'
//!   sources and corner map coordinates, as one [`Extraction`];
//! - check ([`check`]: the output's validity and its topology compared
//!   with the input's), between steps 11 and 12;
//! - the geometric stage ([`geometry`], step 12): positions moved, cells
//!   untouched.
//!
//! What the check and the geometric stage read of the input map, its
//! [`InputShape`] (the topology the check compares with the output's; a
//! tet map's faces of one tet, the geometric stage's reference too), is
//! found once and handed to both: by [`input_shape`] (of the map only), or
//! as the extraction found it on its first pass ([`input_shape_of`]). The
//! check's judgement of the output stays its own (the output's faces and
//! edges are counted by the checker itself).
//!
//! What differs by dimension (which extraction, checker, topology and
//! geometric stage runs) is the map's [`Dimension`], one impl for
//! [`TriMap`] (quads) and one for [`TetMap`] (hexes); what the two
//! extractions' own reports share ([`SegmentStats`]) is read through
//! [`Report`].
//!
//! Input: a map and the facade's [`Options`]; nothing here fails on bad
//! input other than by an [`InputError`] naming the element.
//!
//! [`quad()`]: crate::quad()
//! [`hex()`]: crate::hex()
//! [`TriMap`]: crate::TriMap
//! [`TetMap`]: crate::TetMap

use crate::{GeometryOptions, GeometryReport, InputError, Options, Stats};
/// What [`check`] and [`geometry`] read of the input map (see the module
/// docs), found once: by [`input_shape`], or carried by the extraction
/// ([`input_shape_of`]). Its `boundary`: of a tet map, its faces of one
/// tet (places `4·tet + f`, in no order); of a triangle map, nothing
/// (`()`: the geometric stage's curves find its boundary edges among all
/// the edges they visit anyway).
pub use dualex_check::topology::InputShape;
use dualex_check::topology::{Comparison, Shape};
use dualex_map::SimplexMap;

pub use dualex_hex::HexStats as HexReport;
pub use dualex_quad::QuadStats as QuadReport;
pub use dualex_segment::sanitize_report::SanitizeReport;
pub use dualex_segment::stats::SegmentStats;
/// The clock of the reports' `time_ms` (laps by name), for a tool's own.
pub use dualex_util::timing::Laps;

/// In [`Extraction::sources`]: a cell held by no simplex (a quad that
/// closes a hole); never a simplex index (the map's topology numbers
/// simplex facets in `u32`).
pub const NO_SOURCE: u32 = u32::MAX;
const _: () = assert!(dualex_quad::NO_SOURCE == NO_SOURCE);

/// The weld (before step 1): `map` with its coincident boundary vertices merged (the seams of
/// a cut mesh), and how many were merged; the simplices and their order are
/// kept. A map with nothing to merge is returned as it is.
pub fn weld<const N: usize, const D: usize>(map: SimplexMap<N, D>) -> (SimplexMap<N, D>, usize) {
    let (map, rep) = dualex_map::weld::weld_owned(map);
    (map, rep.welded_vertices)
}

/// The extraction's result (steps 1–11) in either dimension (`K` corners a cell, `D` map
/// coordinates, `R` the extraction's own report), the extraction crates'
/// one type: `mesh` (positions as the map places them), `stats` (the
/// report), `sources` (per cell, the input simplex holding its node;
/// [`NO_SOURCE`] for a quad that closes a hole) and `corners` (per cell,
/// its corners' map coordinates in that simplex's chart, in the cell's
/// corner order; `None` for a cell made by a repair).
pub type Extraction<const K: usize, const D: usize, R> = dualex_segment::place::Extracted<D, K, R>;

/// The quad extraction (step 2 on a [`TriMap`](crate::TriMap)).
pub type QuadExtraction = Extraction<4, 2, QuadReport>;
/// The hex extraction (step 2 on a [`TetMap`](crate::TetMap)).
pub type HexExtraction = Extraction<8, 3, HexReport>;
/// The extraction of a map `M` of `K`-cornered cells in `D` dimensions.
pub type ExtractionOf<M, const K: usize, const D: usize> =
    Extraction<K, D, <M as Dimension<K, D>>::Report>;

/// The last check's result: the output checked.
#[derive(Clone, Debug)]
pub struct Check {
    /// The checker's findings; empty for a valid mesh.
    pub errors: Vec<String>,
    /// The input's and the output's components, Euler characteristic and
    /// boundary components.
    pub topology: Comparison,
    /// The output's boundary facets as the checker counts them (edges of
    /// one quad, faces of one hex).
    pub boundary_facets: usize,
}

impl Check {
    /// The checker's `errors`, the (input, output) `shapes`, and the
    /// output's `boundary_facets`.
    pub fn new(errors: Vec<String>, shapes: (Shape, Shape), boundary_facets: usize) -> Self {
        let (input, output) = shapes;
        Check {
            errors,
            topology: Comparison { input, output },
            boundary_facets,
        }
    }
}

/// The per-dimension parts of steps 2–4, one impl per map type:
/// [`TriMap`](crate::TriMap) → quads (`K` = 4, `D` = 2) and
/// [`TetMap`](crate::TetMap) → hexes (8, 3), in `dims.rs`. Call them
/// through [`extract`], [`input_shape`] (or [`input_shape_of`]),
/// [`check`] and [`geometry`].
pub trait Dimension<const K: usize, const D: usize> {
    /// The extraction's own report: [`QuadReport`] or [`HexReport`].
    type Report: Report + Send;
    /// The input's boundary as the geometric stage reads it (see
    /// [`InputShape::boundary`]).
    type Boundary: Send;
    /// The input's shape (see [`input_shape`]).
    fn input_shape(&self) -> InputShape<Self::Boundary>;
    /// The input's shape as the extraction `x` found it on its first
    /// pass (see [`input_shape_of`]).
    fn carried(&self, x: &Extraction<K, D, Self::Report>) -> Option<InputShape<Self::Boundary>>;
    /// Steps 1–11 (see [`extract`]).
    fn extract(
        &self,
        opts: &Options,
        singularities: bool,
    ) -> Result<Extraction<K, D, Self::Report>, InputError>;
    /// The last check (see [`check`]).
    fn check(
        &self,
        input: &InputShape<Self::Boundary>,
        x: &Extraction<K, D, Self::Report>,
    ) -> Check;
    /// Step 12 (see [`geometry`]).
    fn geometry(
        &self,
        input: &InputShape<Self::Boundary>,
        x: &mut Extraction<K, D, Self::Report>,
        opts: &GeometryOptions,
    ) -> GeometryReport;
}

/// The extraction's own report of either dimension ([`QuadReport`],
/// [`HexReport`]), one impl each in `dims.rs`.
pub trait Report {
    /// The counts of steps 1–7, alike in both dimensions.
    fn segment(&self) -> &SegmentStats;
    /// The report as the CLI's `--stats` JSON (before the CLI's sections).
    fn to_json(&self) -> serde_json::Value;
    /// The facade's [`Stats`] of this report and the output `check`
    /// (welded vertices and the geometric stage's report left at their
    /// defaults: the steps around the extraction fill them).
    fn stats(&self, check: &Check) -> Stats;
}

/// Steps 1–11: the extraction of `map` (not welded here) with `opts`'
/// extraction knobs (`fairing`: in 3D on columns, `round_transitions`,
/// `grid_offset`, `seed`); `singularities` (2D): count the input's
/// singularities by index in [`QuadReport::singularities`] (about 10 % of
/// the extraction; the CLI does where stats are shown; 3D always counts
/// its singular edges).
pub fn extract<M: Dimension<K, D>, const K: usize, const D: usize>(
    map: &M,
    opts: &Options,
    singularities: bool,
) -> Result<Extraction<K, D, M::Report>, InputError> {
    Dimension::extract(map, opts, singularities)
}

/// The input's shape and boundary ([`InputShape`]), read by [`check`] and
/// [`geometry`]: of the map only (found after the extraction: beside it,
/// the peak memory grew, BENCHMARKS.md).
pub fn input_shape<M: Dimension<K, D>, const K: usize, const D: usize>(
    map: &M,
) -> InputShape<M::Boundary> {
    Dimension::input_shape(map)
}

/// [`input_shape`] of `map` as its extraction `x` found it (from the
/// adjacency of its first pass: `dualex_check::glued`), or found afresh
/// when `x` carries none; `x` must be the extraction of `map`.
pub fn input_shape_of<M: Dimension<K, D>, const K: usize, const D: usize>(
    map: &M,
    x: &Extraction<K, D, M::Report>,
) -> InputShape<M::Boundary> {
    map.carried(x).unwrap_or_else(|| map.input_shape())
}

/// The last check: the output mesh of `x`, extracted from `map`, checked
/// (quads: manifold, oriented; hexes: combinatorially valid) and its
/// topology compared with the map's (`input`: [`input_shape`]'s). The
/// extraction's own checker report of its output is read instead of a
/// new check while `x.mesh` is the mesh it was made of (its vertex count
/// and cells: [`dualex_check::Checked`]).
pub fn check<M: Dimension<K, D>, const K: usize, const D: usize>(
    map: &M,
    input: &InputShape<M::Boundary>,
    x: &Extraction<K, D, M::Report>,
) -> Check {
    Dimension::check(map, input, x)
}

/// Step 12: the geometric stage on the cells of `x` (their positions moved
/// in place) against `map`'s surface or tets (the map `x` was extracted
/// from; `input`: [`input_shape`]'s).
pub fn geometry<M: Dimension<K, D>, const K: usize, const D: usize>(
    map: &M,
    input: &InputShape<M::Boundary>,
    x: &mut Extraction<K, D, M::Report>,
    opts: &GeometryOptions,
) -> GeometryReport {
    Dimension::geometry(map, input, x, opts)
}
