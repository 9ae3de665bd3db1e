//! `dualex quad` and `dualex hex`: read, extract, check, write — one
//! sequence for both ([`extract_map`]), the per-dimension parts behind
//! [`ExtractCommand`] (one impl each: `quad.rs`, `hex.rs`).
//!
//! Order: every output path is checked first ([`check_outputs`]); then
//! read, extract, the last check ([`crate::verify`]), the geometric stage,
//! the picture rendered in memory; only then are the files written (mesh,
//! stats, picture), so a refused or failed run writes nothing. The
//! warnings and the summary line go to stderr; the line names the quality
//! problems left ([`crate::summary`]).

use crate::args::{ExtractArgs, Global};
use crate::error::CliError;
use crate::summary::problems_suffix;
use crate::{geometry, outputs, progress, summary, timing, verify, warnings};
use dualex::check::topology as topo;
use dualex::map::SimplexMap;
use dualex::steps::{self, Dimension, ExtractionOf, Report};
use std::path::Path;

/// The extraction of `K`-cornered cells from a map of `N`-cornered
/// simplices with `D` map coordinates.
pub type Extracted<const N: usize, const D: usize, const K: usize> =
    ExtractionOf<SimplexMap<N, D>, K, D>;

/// What the commands call their cells, and how their meshes are written.
pub struct Cells {
    /// One cell in messages: `"quad"`, `"hex"`.
    pub one: &'static str,
    /// More: `"quads"`, `"hexes"`.
    pub many: &'static str,
    /// The output mesh's extensions.
    pub extensions: &'static [&'static str],
}

/// The per-dimension parts of an extraction command: `dualex quad`
/// (`QuadArgs`, `N` = 3 corners a triangle, `D` = 2, `K` = 4 corners a
/// quad) and `dualex hex` (`HexArgs`: 4, 3, 8).
pub trait ExtractCommand<const N: usize, const D: usize, const K: usize>
where
    SimplexMap<N, D>: Dimension<K, D>,
{
    /// The cells' words and the output's extensions.
    const CELLS: Cells;
    /// The output mesh (`-o`).
    fn output(&self) -> &Path;
    /// The extraction's arguments.
    fn extract_args(&self) -> &ExtractArgs;
    /// The library's options, and whether the report counts the input's
    /// singularities (2D, with `--stats` or `-v`).
    fn options(&self, g: &Global) -> (dualex::Options, bool);
    /// `--png` (quads only).
    fn png(&self) -> Option<&Path>;
    /// The `--png` picture of `x`, in memory (`None`: not asked, or no
    /// cell); `name` names the input in errors.
    fn picture(&self, x: &Extracted<N, D, K>, name: &str) -> Result<Option<Vec<u8>>, CliError>;
    /// Writes the mesh of `x` to [`Self::output`].
    fn write(&self, x: &Extracted<N, D, K>) -> Result<(), CliError>;
    /// The warnings of what the extraction repaired (`own_map`: the
    /// user's map, not one `remesh` made).
    fn warn_repairs(x: &Extracted<N, D, K>, own_map: bool);
    /// The summary line's counts (cells, vertices, …).
    fn counts(x: &Extracted<N, D, K>) -> Vec<String>;
    /// The quality problems left in the output (empty: none), but for
    /// the transitions rounded (said by [`extract_map`] for both).
    fn problems(x: &Extracted<N, D, K>) -> Vec<String>;
}

/// Checks the outputs of an extraction command (mesh, stats, picture).
pub fn check_outputs<A, const N: usize, const D: usize, const K: usize>(
    a: &A,
) -> Result<(), CliError>
where
    A: ExtractCommand<N, D, K>,
    SimplexMap<N, D>: Dimension<K, D>,
{
    let mut all = vec![(a.output(), Some(A::CELLS.extensions))];
    if let Some(s) = &a.extract_args().stats {
        all.push((s.as_path(), None));
    }
    if let Some(p) = a.png() {
        all.push((p, None));
    }
    outputs::check_all(&all)
}

/// What the caller of [`extract_map`] made before: one more section of
/// the stats, and the map's extraction with the command's options if it
/// has it (`remesh` extracts its maps to count their quads).
pub struct Before<'a, X> {
    /// The stats section (key, value).
    pub section: (&'a str, serde_json::Value),
    /// The extraction of this very map.
    pub extracted: Option<X>,
    /// The geometric stage's report when it has run on `extracted`
    /// already (its cells moved): not run again.
    pub geometry: Option<dualex::geom::Report>,
}

/// The extraction of a map read or made (`quad`, `hex`, `remesh`):
/// extract (unless `before` has it), check, the geometric stage, write;
/// `done` starts the summary line.
pub fn extract_map<A, const N: usize, const D: usize, const K: usize>(
    map: &SimplexMap<N, D>,
    name: &str,
    done: &str,
    a: &A,
    g: &Global,
    mut laps: timing::Laps,
    before: Option<Before<Extracted<N, D, K>>>,
) -> Result<(), CliError>
where
    A: ExtractCommand<N, D, K>,
    SimplexMap<N, D>: Dimension<K, D>,
{
    // the user's own map (not remesh's): its repairs are said
    let own_map = before.is_none();
    let (extra, done_before, staged) = match before {
        Some(b) => (Some(b.section), b.extracted, b.geometry),
        None => (None, None, None),
    };
    let x = a.extract_args();
    let progress = progress::Progress::new(map.len(), g.quiet);
    progress.stage(&format!("extracting {}", A::CELLS.many));
    // 1. extracted (unless done before), checked; the input's shape and
    // boundary found once for the check and the geometric stage
    let (mut ex, topology, input) = extract_checked(map, name, a, g, done_before, &mut laps)?;
    // 2. the geometric stage (unless run on `done_before` already)
    progress.stage("geometry");
    let geo = match staged {
        Some(geo) => geo,
        None => steps::geometry(map, &input, &mut ex, &x.geometry.options()),
    };
    laps.lap("geometry");
    let cells = (A::CELLS.one, A::CELLS.many);
    geometry::check(name, &geo, cells, x.strict)?;
    // 3. the picture, in memory
    let png = a.picture(&ex, name)?;
    // 4. the mesh written, then the stats and the picture
    progress.stage("writing");
    a.write(&ex)?;
    laps.lap("write");
    drop(progress);
    let json = stats_json(ex.stats.to_json(), &topology, &geo, extra);
    finish_stats(x, g, &json, &laps, &ex.stats.segment().time_ms)?;
    write_picture(a.png(), png.as_deref())?;
    // 5. the warnings and the summary line
    let segment = ex.stats.segment();
    warnings::rounded(
        g,
        segment.snapped_transitions,
        segment.max_transition_residual,
    );
    geometry::warn(&geo, cells);
    warnings::relaxed(segment.relax.map(|r| (r.reverted_before, r.vertices)));
    A::warn_repairs(&ex, own_map);
    if !g.quiet {
        // the command's problems, then the transitions rounded
        let mut problems = A::problems(&ex);
        problems.extend(summary::rounded(segment.snapped_transitions));
        eprintln!(
            "dualex: {done}: {}{} -> {}{}",
            A::counts(&ex).join(", "),
            geometry::done_words(&geo),
            a.output().display(),
            problems_suffix(&problems),
        );
    }
    Ok(())
}

/// Step 1 of [`extract_map`]: the extraction (`done_before`, or made
/// here), its validity (hexes combinatorially: those of a messy map may
/// be geometrically inverted) and the last checks ([`crate::verify`]),
/// with the topology compared; also the input's shape and boundary
/// ([`steps::input_shape_of`]: as the extraction found it on its first
/// pass; for the geometric stage too).
fn extract_checked<A, const N: usize, const D: usize, const K: usize>(
    map: &SimplexMap<N, D>,
    name: &str,
    a: &A,
    g: &Global,
    done_before: Option<Extracted<N, D, K>>,
    laps: &mut timing::Laps,
) -> Result<Checked<N, D, K>, CliError>
where
    A: ExtractCommand<N, D, K>,
    SimplexMap<N, D>: Dimension<K, D>,
{
    let ex = match done_before {
        // the same map, extracted with the same options already
        Some(x) => x,
        None => {
            let (opts, singularities) = a.options(g);
            steps::extract(map, &opts, singularities).map_err(|e| e.in_file(name.to_string()))?
        }
    };
    laps.lap("extract");
    let input = steps::input_shape_of(map, &ex);
    laps.lap("input_shape");
    let check = steps::check(map, &input, &ex);
    laps.lap("check");
    let out = verify::Output {
        cell: A::CELLS.one,
        cells: ex.mesh.cells.len(),
        nodes: ex.stats.segment().nodes,
        measure: Box::new(|| verify::measure(map)),
        topology: check.topology,
    };
    let strict = a.extract_args().strict;
    verify::before_writing(
        name,
        &out,
        check.errors,
        &ex.stats.segment().sanitize,
        strict,
    )?;
    Ok((ex, check.topology, input))
}

/// What [`extract_checked`] returns: the extraction, its topology
/// compared with the input's, the input's shape and boundary.
type Checked<const N: usize, const D: usize, const K: usize> = (
    Extracted<N, D, K>,
    topo::Comparison,
    steps::InputShape<<SimplexMap<N, D> as Dimension<K, D>>::Boundary>,
);

/// The `--png` picture written (made in memory before), or the warning
/// that the mesh is empty.
fn write_picture(path: Option<&Path>, png: Option<&[u8]>) -> Result<(), CliError> {
    if let (Some(path), Some(bytes)) = (path, png) {
        outputs::write_png(path, bytes)?;
    } else if let Some(path) = path {
        eprintln!(
            "dualex: warning: {}: not written: the mesh is empty",
            path.display()
        );
    }
    Ok(())
}

/// The stats JSON of an extraction: its own, the topology compared, the
/// geometric stage's report and time, and the caller's section.
fn stats_json(
    mut json: serde_json::Value,
    topology: &topo::Comparison,
    geo: &dualex::geom::Report,
    extra: Option<(&str, serde_json::Value)>,
) -> serde_json::Value {
    verify::add_to_stats(&mut json, topology);
    if let Some(obj) = json.as_object_mut() {
        obj.insert("geometry".to_string(), geo.to_json());
        if let Some(t) = obj.get_mut("time_ms").and_then(|t| t.as_object_mut()) {
            t.insert("geometry".to_string(), geo.time_ms.into());
        }
        if let Some((key, value)) = extra {
            obj.insert(key.to_string(), value);
        }
    }
    json
}

/// Writes `--stats`, and prints the `-v` table.
fn finish_stats(
    x: &ExtractArgs,
    g: &Global,
    json: &serde_json::Value,
    laps: &timing::Laps,
    stages: &[(String, f64)],
) -> Result<(), CliError> {
    if let Some(s) = &x.stats {
        outputs::write_stats(s, json)?;
    }
    if g.verbose {
        eprintln!(
            "{}",
            summary::verbose_table(laps.laps(), stages, laps.total_ms(), json)
        );
    }
    Ok(())
}
