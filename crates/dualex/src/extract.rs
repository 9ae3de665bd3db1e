//! The two extractions as the CLI runs them: weld (by default), extract,
//! check the output, compare its topology with the input's, then the
//! geometric stage (`dualex_geom`: measure the elements' scaled Jacobian,
//! put boundary vertices on the input's boundary, untangle inverted
//! elements, optionally smooth; it moves vertices, never the
//! combinatorics).
//!
//! Input: a map (not modified) and options. Output: the mesh and its typed
//! stats, or an [`Error`]: [`Error::Input`] for a map the extraction
//! refuses, [`Error::InvalidOutput`] when no valid mesh could be made (as
//! the CLI, which then writes nothing), [`Error::TopologyChanged`] when
//! `strict` is set and the output's topology differs from the input's,
//! [`Error::InvertedElements`] when `strict` is set and inverted elements
//! remain after the geometric stage.
//!
//! Welding merges boundary vertices at exactly the same position (the
//! seams of a cut mesh, see `dualex_map::weld`); without it a cut mesh is
//! extracted chart by chart (Directional's dragon: 46 components instead
//! of 1). It keeps the simplices and their order, so simplex indices in
//! the output refer to the caller's map either way.

use crate::stats::{GridOffset, Stats, TopologyComparison};
use crate::steps::{self, Dimension, Extraction, InputShape, Report, NO_SOURCE};
use crate::{Error, GeometryOptions, GeometryReport, TetMap, TriMap};
use dualex_cells::CellMesh;
use dualex_map::SimplexMap;
use std::borrow::Cow;

/// Options of [`quad`](crate::quad()) and [`hex`](crate::hex()) (and of
/// the extraction in [`remesh`](crate::remesh())): every knob applies to
/// both dimensions.
#[derive(Clone, Debug)]
pub struct Options {
    /// Merge coincident boundary vertices (cut meshes) first. Default: on.
    pub weld: bool,
    /// Index fairing after untangling (in 3D: on columns, the extruded
    /// maps, the 2D fairing in every layer). Default: on.
    pub fairing: bool,
    /// Round transition translations of any residual instead of refusing
    /// the map (residuals up to 0.1 are always rounded). Default: off.
    pub round_transitions: bool,
    /// Where the dual grid sits. Default: [`GridOffset::Auto`].
    pub grid_offset: GridOffset,
    /// Seed of the sanitization perturbations. Default: 1.
    pub seed: u64,
    /// An output whose topology differs from the input's, or with
    /// inverted elements left after the geometric stage, is an error
    /// ([`Error::TopologyChanged`], [`Error::InvertedElements`]) instead of
    /// being reported in the stats. Default: off.
    pub strict: bool,
    /// The geometric stage after the extraction (as the CLI's
    /// `--untangle`, `--smooth`, `--keep-boundary`, `--feature-angle`).
    /// Default: [`GeometryMode::Auto`](crate::GeometryMode::Auto): boundary
    /// vertices onto the input's boundary (curves of a surface, the
    /// boundary surface of tets), inverted elements untangled (only the
    /// vertices near them move); a mesh with neither is left as the map
    /// places it.
    pub geometry: GeometryOptions,
}

impl Default for Options {
    fn default() -> Self {
        let d = dualex_quad::QuadOptions::default();
        Options {
            weld: true,
            fairing: d.fairing,
            round_transitions: false,
            grid_offset: d.grid_offset,
            seed: d.seed,
            strict: false,
            geometry: GeometryOptions::default(),
        }
    }
}

/// The result of [`quad`](crate::quad()) ([`QuadOutput`]: `K` = 4 corners,
/// `D` = 2 map coordinates) or [`hex`](crate::hex()) ([`HexOutput`]: 8, 3).
#[derive(Clone, Debug)]
pub struct Output<const K: usize, const D: usize> {
    /// The mesh: positions (as the geometric stage left them) and cells
    /// (quads: 4 vertex indices, counter-clockwise seen from the side the
    /// map's orientation makes the front; hexes: 8, VTK order).
    pub mesh: CellMesh<K>,
    /// Its counts.
    pub stats: Stats,
    /// For each cell, the input simplex that holds its node (an index
    /// into the map's triangles or tets, welded or not). `Option` in both
    /// dimensions, so that "no source" is a type, not a sentinel: `None`
    /// for a quad that closes a hole (a hex always has one). After a
    /// subdivision (`stats.repairs.subdivided`) the four quads of a cell
    /// name its triangle; a cell merged from two (doublet removal) names
    /// the first one's.
    pub sources: Vec<Option<u32>>,
    /// For each cell, the map coordinates of its corners (in its cell
    /// order) in the chart of its source simplex: its node ± ½ on each
    /// axis, exact grid points of the input map (integers with the grid
    /// offset `half`, half-integers with `zero`). A seam vertex may have
    /// different coordinates in the cells around it. `None` for a cell
    /// without its own: a face closing a hole, a cell merged from a
    /// doublet (chain) or made along a local repair path; after a
    /// subdivision each quad is a half-size square of its cell.
    pub corners: Vec<Option<[[f64; D]; K]>>,
}

/// The result of [`quad`](crate::quad()).
pub type QuadOutput = Output<4, 2>;
/// The result of [`hex`](crate::hex()).
pub type HexOutput = Output<8, 3>;

/// Welds `map` when asked; the number of vertices merged.
fn welded<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    weld: bool,
) -> (Cow<'_, SimplexMap<N, D>>, usize) {
    if !weld {
        return (Cow::Borrowed(map), 0);
    }
    let (m, rep) = dualex_map::weld::weld(map);
    (Cow::Owned(m), rep.welded_vertices)
}

/// The output check of either dimension: its errors (an invalid mesh),
/// then the topology compared (an error under `strict`).
fn checked(errors: &[String], t: &TopologyComparison, strict: bool) -> Result<(), Error> {
    if !errors.is_empty() {
        return Err(Error::InvalidOutput(errors.join("; ")));
    }
    if strict && !t.matches() {
        return Err(Error::TopologyChanged {
            input: t.input,
            output: t.output,
        });
    }
    Ok(())
}

/// Inverted elements left by the geometric stage: an error under `strict`.
fn inverted_check(r: &GeometryReport, strict: bool) -> Result<(), Error> {
    let count = r.after.inverted;
    if strict && count > 0 {
        return Err(Error::InvertedElements { count });
    }
    Ok(())
}

/// [`quad`](crate::quad()) and [`hex`](crate::hex()) in one: weld, then
/// the steps of [`finish`] after the extraction.
fn run<const N: usize, const D: usize, const K: usize>(
    map: &SimplexMap<N, D>,
    opts: &Options,
) -> Result<Output<K, D>, Error>
where
    SimplexMap<N, D>: Dimension<K, D>,
{
    let (map, welded) = welded(map, opts.weld);
    let x = steps::extract(&*map, opts, true)?;
    let input = steps::input_shape_of(&*map, &x);
    finish(&*map, x, welded, opts, None, Some(input))
}

/// What follows the extraction `x` of `map` (as [`quad`](crate::quad()),
/// [`hex`](crate::hex()) and [`remesh`](crate::remesh()) run it): the
/// output check, the topology comparison, the geometric stage (unless its
/// report is `staged`: it has run on `x` already); `welded` vertices were
/// merged before; `input`: the map's [`InputShape`] when found already.
pub(crate) fn finish<M: Dimension<K, D>, const K: usize, const D: usize>(
    map: &M,
    mut x: Extraction<K, D, M::Report>,
    welded: usize,
    opts: &Options,
    staged: Option<GeometryReport>,
    input: Option<InputShape<M::Boundary>>,
) -> Result<Output<K, D>, Error> {
    let input = input.unwrap_or_else(|| steps::input_shape_of(map, &x));
    let check = steps::check(map, &input, &x);
    let mut stats = x.stats.stats(&check);
    checked(&check.errors, &stats.topology, opts.strict)?;
    let geometry = match staged {
        Some(g) => g,
        None => steps::geometry(map, &input, &mut x, &opts.geometry),
    };
    inverted_check(&geometry, opts.strict)?;
    stats.welded_vertices = welded;
    stats.geometry = geometry;
    Ok(Output {
        stats,
        sources: x
            .sources
            .iter()
            .map(|&s| (s != NO_SOURCE).then_some(s))
            .collect(),
        mesh: x.mesh,
        corners: x.corners,
    })
}

/// Extracts the quad mesh of a triangle map (see the [crate] example),
/// then runs the geometric stage ([`Options::geometry`]) on it against
/// the (welded) map's surface; its report is [`Stats::geometry`].
pub fn quad(map: &TriMap, opts: &Options) -> Result<QuadOutput, Error> {
    run(map, opts)
}

/// Extracts the hex mesh of a tet map, then runs the geometric stage
/// ([`Options::geometry`]) on it against the (welded) map's tets; its
/// report is [`Stats::geometry`].
///
/// ```
/// // a unit cube of 6 tets around the diagonal 0–7, mapped onto [0, 2]³
/// let positions: Vec<[f64; 3]> = (0..8)
///     .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64])
///     .collect();
/// let tets = [
///     [0, 1, 3, 7], [0, 3, 2, 7], [0, 2, 6, 7],
///     [0, 6, 4, 7], [0, 4, 5, 7], [0, 5, 1, 7],
/// ];
/// let uvw: Vec<[[f64; 3]; 4]> = tets
///     .iter()
///     .map(|t| t.map(|v| positions[v as usize].map(|x| 2.0 * x)))
///     .collect();
/// let map = dualex::tet_map_from_slices(&positions, &tets, &uvw)?;
/// let out = dualex::hex(&map, &dualex::Options::default())?;
/// assert_eq!(out.stats.cells, 8);
/// // the tet holding each hex's node (the hex's centre)
/// assert_eq!(out.sources.len(), 8);
/// assert_eq!(out.mesh.cells.len(), 8);
/// assert!(out.stats.topology.matches());
/// # Ok::<(), dualex::Error>(())
/// ```
pub fn hex(map: &TetMap, opts: &Options) -> Result<HexOutput, Error> {
    run(map, opts)
}
