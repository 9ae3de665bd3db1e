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

use crate::stats::{GridOffset, HexStats, QuadStats, TopologyComparison};
use crate::{Error, GeometryOptions, GeometryReport, HexMesh, QuadMesh, TetMap, TriMap};
use dualex_check::topology as topo;
use dualex_map::{SimplexMap, TransitionOptions};
use std::borrow::Cow;

/// Options of [`quad`](crate::quad()).
#[derive(Clone, Debug)]
pub struct QuadOptions {
    /// Merge coincident boundary vertices (cut meshes) first. Default: on.
    pub weld: bool,
    /// Index fairing after untangling. Default: on.
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
    /// vertices onto the input's boundary, inverted elements untangled
    /// (only the vertices near them move); a mesh with neither is left as
    /// the map places it.
    pub geometry: GeometryOptions,
}

impl Default for QuadOptions {
    fn default() -> Self {
        let d = dualex_quad::QuadOptions::default();
        QuadOptions {
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

/// Options of [`hex`](crate::hex()).
#[derive(Clone, Debug)]
pub struct HexOptions {
    /// Merge coincident boundary vertices (cut meshes) first. Default: on.
    pub weld: bool,
    /// As [`QuadOptions::round_transitions`].
    pub round_transitions: bool,
    /// Where the dual grid sits. Default: [`GridOffset::Auto`].
    pub grid_offset: GridOffset,
    /// Seed of the sanitization perturbations. Default: 1.
    pub seed: u64,
    /// As [`QuadOptions::strict`].
    pub strict: bool,
    /// As [`QuadOptions::geometry`] (boundary vertices onto the boundary
    /// surface of the input's tets).
    pub geometry: GeometryOptions,
}

impl Default for HexOptions {
    fn default() -> Self {
        let d = dualex_hex::HexOptions::default();
        HexOptions {
            weld: true,
            round_transitions: false,
            grid_offset: d.grid_offset,
            seed: d.seed,
            strict: false,
            geometry: GeometryOptions::default(),
        }
    }
}

/// The result of [`quad`](crate::quad()).
#[derive(Clone, Debug)]
pub struct QuadOutput {
    /// The quad mesh: positions (as the geometric stage left them) and
    /// cells (4 vertex indices, counter-clockwise seen from the side the
    /// map's orientation makes the front).
    pub mesh: QuadMesh,
    /// Its counts.
    pub stats: QuadStats,
    /// For each quad, the input triangle that holds its node (an index
    /// into the map's triangles, welded or not); `None` for a face that
    /// closes a hole. After a subdivision (`stats.repairs.subdivided`) the
    /// four quads of a cell name its triangle; a quad merged from two
    /// (doublet removal) names the first one's.
    pub sources: Vec<Option<u32>>,
    /// For each quad, the map coordinates of its 4 corners (in its cell
    /// order) in the chart of its source triangle: its node ± ½ on each
    /// axis, exact grid points of the input map (integers with the grid
    /// offset `half`, half-integers with `zero`). A seam vertex may have
    /// different coordinates in the quads around it. `None` for a quad
    /// without its own cell: a face closing a hole, a quad merged from a
    /// doublet or made along a local repair path; after a subdivision each
    /// quad is a half-size square of its cell.
    pub corner_uv: Vec<Option<[[f64; 2]; 4]>>,
}

/// The result of [`hex`](crate::hex()).
#[derive(Clone, Debug)]
pub struct HexOutput {
    /// The hex mesh: positions (as the geometric stage left them) and cells
    /// (8 vertex indices, VTK order).
    pub mesh: HexMesh,
    /// Its counts.
    pub stats: HexStats,
    /// For each hex, the input tet that holds its node (an index into the
    /// map's tets); a hex merged from a pair names the first one's.
    pub sources: Vec<u32>,
    /// For each hex, the map coordinates of its 8 corners (VTK order) in
    /// the chart of its source tet, as [`QuadOutput::corner_uv`]; `None`
    /// for a hex merged from a doublet chain.
    pub corner_uvw: Vec<Option<[[f64; 3]; 8]>>,
}

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

fn transitions(round: bool) -> TransitionOptions {
    TransitionOptions {
        round,
        ..Default::default()
    }
}

fn topology_check(t: &TopologyComparison, strict: bool) -> Result<(), Error> {
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

/// Extracts the quad mesh of a triangle map (see the [crate] example),
/// then runs the geometric stage ([`QuadOptions::geometry`]) on it against
/// the (welded) map's surface; its report is [`QuadStats::geometry`].
pub fn quad(map: &TriMap, opts: &QuadOptions) -> Result<QuadOutput, Error> {
    let (map, welded) = welded(map, opts.weld);
    let x = dualex_quad::extract_full(&map, &inner_quad_options(opts))?;
    finish_quads(&map, x, welded, opts)
}

/// The extraction's own options from the facade's (singularity stats on).
pub(crate) fn inner_quad_options(opts: &QuadOptions) -> dualex_quad::QuadOptions {
    dualex_quad::QuadOptions {
        fairing: opts.fairing,
        transitions: transitions(opts.round_transitions),
        seed: opts.seed,
        grid_offset: opts.grid_offset,
        singularity_stats: true,
    }
}

/// What follows the extraction of `map` (as [`quad`](crate::quad()) and
/// [`remesh`](crate::remesh()) run it): the output check, the topology
/// comparison, the geometric stage; `welded` vertices were merged before.
pub(crate) fn finish_quads(
    map: &TriMap,
    x: dualex_quad::Extracted,
    welded: usize,
    opts: &QuadOptions,
) -> Result<QuadOutput, Error> {
    finish_staged_quads(map, x, welded, opts, None)
}

/// The geometric stage on an extraction of `map` (its quads' positions
/// moved in place), as [`quad`] runs it.
pub(crate) fn quad_stage(
    map: &TriMap,
    x: &mut dualex_quad::Extracted,
    opts: &GeometryOptions,
) -> GeometryReport {
    // the stage's "none" is u32::MAX, the extraction's NO_SOURCE
    const _: () = assert!(dualex_quad::NO_SOURCE == u32::MAX);
    dualex_geom::quads(
        &mut x.mesh.positions,
        &x.mesh.cells,
        &map.positions,
        &map.simplices,
        &x.sources,
        opts,
    )
}

/// [`finish_quads`], the geometric stage's report given when it has run
/// on `x` already ([`quad_stage`]).
pub(crate) fn finish_staged_quads(
    map: &TriMap,
    mut x: dualex_quad::Extracted,
    welded: usize,
    opts: &QuadOptions,
    staged: Option<GeometryReport>,
) -> Result<QuadOutput, Error> {
    let rep = dualex_check::check_quad_mesh(x.mesh.positions.len(), &x.mesh.cells);
    if !rep.is_valid() {
        return Err(Error::InvalidOutput(rep.errors().join("; ")));
    }
    let t = TopologyComparison {
        input: topo::surface_shape(map.positions.len(), &map.simplices).into(),
        output: topo::quad_shape(&rep).into(),
    };
    topology_check(&t, opts.strict)?;
    let geometry = match staged {
        Some(g) => g,
        None => quad_stage(map, &mut x, &opts.geometry),
    };
    inverted_check(&geometry, opts.strict)?;
    let dualex_quad::Extracted {
        mesh,
        stats,
        sources,
        corner_uv,
    } = x;
    let sources = sources
        .into_iter()
        .map(|s| (s != dualex_quad::NO_SOURCE).then_some(s))
        .collect();
    Ok(QuadOutput {
        stats: QuadStats::new(&stats, welded, t, geometry),
        mesh,
        sources,
        corner_uv,
    })
}

/// Extracts the hex mesh of a tet map, then runs the geometric stage
/// ([`HexOptions::geometry`]) on it against the (welded) map's tets; its
/// report is [`HexStats::geometry`].
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
/// let out = dualex::hex(&map, &dualex::HexOptions::default())?;
/// assert_eq!(out.stats.hexes, 8);
/// // the tet holding each hex's node (the hex's centre)
/// assert_eq!(out.sources.len(), 8);
/// assert_eq!(out.mesh.cells.len(), 8);
/// assert!(out.stats.topology.matches());
/// # Ok::<(), dualex::Error>(())
/// ```
pub fn hex(map: &TetMap, opts: &HexOptions) -> Result<HexOutput, Error> {
    let (map, welded) = welded(map, opts.weld);
    let inner = dualex_hex::HexOptions {
        transitions: transitions(opts.round_transitions),
        seed: opts.seed,
        grid_offset: opts.grid_offset,
        ..dualex_hex::HexOptions::default()
    };
    let dualex_hex::Extracted {
        mut mesh,
        stats,
        sources,
        corner_uvw,
    } = dualex_hex::extract_full(&map, &inner)?;
    let rep = dualex_check::check_hex_mesh(mesh.positions.len(), &mesh.cells, None);
    if !rep.is_valid() {
        return Err(Error::InvalidOutput(rep.errors().join("; ")));
    }
    let t = TopologyComparison {
        input: topo::tet_shape(map.positions.len(), &map.simplices).into(),
        output: topo::hex_shape(&rep).into(),
    };
    topology_check(&t, opts.strict)?;
    let geometry = dualex_geom::hexes(
        &mut mesh.positions,
        &mesh.cells,
        &map.positions,
        &map.simplices,
        &opts.geometry,
    );
    inverted_check(&geometry, opts.strict)?;
    Ok(HexOutput {
        stats: HexStats::new(&stats, welded, t, geometry),
        mesh,
        sources,
        corner_uvw,
    })
}
