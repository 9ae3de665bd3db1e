//! `dualex quad` and `dualex hex`: read, extract, check, write.
//!
//! Order: every output path is checked first ([`crate::outputs`]); then
//! read, extract, the last check ([`crate::verify`]), the picture rendered
//! in memory; only then are the files written (mesh, stats, picture), so a
//! refused or failed run writes nothing. The summary line goes to stderr
//! and names the quality problems left ([`crate::summary`]).

use crate::args::{ExtractArgs, Global, HexArgs, QuadArgs};
use crate::error::CliError;
use crate::summary::{count, problems_suffix};
use crate::{geometry, outputs, progress, summary, timing, verify, warnings, EMBEDDED, PNG_SIZE};
use dualex::check::topology as topo;
use std::path::Path;

/// Checks the outputs of an extraction (mesh, stats, picture).
fn check_outputs(
    mesh: &Path,
    exts: &'static [&'static str],
    x: &ExtractArgs,
    png: Option<&Path>,
) -> Result<(), CliError> {
    let mut all = vec![(mesh, Some(exts))];
    if let Some(s) = &x.stats {
        all.push((s.as_path(), None));
    }
    if let Some(p) = png {
        all.push((p, None));
    }
    outputs::check_all(&all)
}

/// `dualex quad`.
pub fn quad(a: &QuadArgs, g: &Global) -> Result<(), CliError> {
    if a.uv {
        refuse_uv(&a.output);
    }
    check_outputs(
        &a.output,
        dualex::io::QUAD_MESH_EXTENSIONS,
        &a.extract,
        a.png.as_deref(),
    )?;
    let mut laps = timing::Laps::start();
    let (map, name) = match &a.input {
        Some(p) => (
            crate::read_2d(p, &a.weld, g, &mut laps)?,
            p.display().to_string(),
        ),
        None => {
            if !g.quiet {
                eprintln!("dualex: no INPUT given: running on the embedded map (a folded, noisy cube surface)");
            }
            let m = dualex::io::parse_obj(EMBEDDED).map_err(CliError::EmbeddedMap)?;
            let name = "embedded map".to_string();
            (crate::weld_if(m, &a.weld, g, &name), name)
        }
    };
    let done = if a.input.is_some() {
        "done"
    } else {
        "embedded map"
    };
    quad_map(&map, &name, done, a, g, laps, None)
}

/// The library's options of `quad` from the arguments; with `--stats`
/// or `-v` the report counts the input's singularities too.
fn quad_options(a: &QuadArgs, g: &Global) -> (dualex::Options, bool) {
    let x = &a.extract;
    (x.options(!a.no_fairing), x.stats.is_some() || g.verbose)
}

/// What the caller of [`quad_map`] made before: one more section of the
/// stats, and the map's extraction with `quad`'s options if it has it
/// (`remesh` extracts its maps to count their quads).
pub struct Before<'a> {
    /// The stats section (key, value).
    pub section: (&'a str, serde_json::Value),
    /// The extraction of this very map.
    pub extracted: Option<dualex::steps::QuadExtraction>,
    /// The geometric stage's report when it has run on `extracted`
    /// already (its quads moved): not run again.
    pub geometry: Option<dualex::geom::Report>,
}

/// The quad extraction of a map read or made (`quad`, `remesh`): extract
/// (unless `before` has it), check, write; `done` starts the summary
/// line.
pub fn quad_map(
    map: &dualex::map::TriMap,
    name: &str,
    done: &str,
    a: &QuadArgs,
    g: &Global,
    mut laps: timing::Laps,
    before: Option<Before>,
) -> Result<(), CliError> {
    // the user's own map (not remesh's): its repairs are said
    let own_map = before.is_none();
    let (extra, done_before, staged) = match before {
        Some(b) => (Some(b.section), b.extracted, b.geometry),
        None => (None, None, None),
    };
    let x = &a.extract;
    let progress = progress::Progress::new(map.len(), g.quiet);
    progress.stage("extracting quads");
    // 1. extracted (unless done before), checked
    let (mut ex, topology) = extract_quads(map, name, a, g, done_before, &mut laps)?;
    // 2. the geometric stage (unless run on `done_before` already)
    progress.stage("geometry");
    let geo = match staged {
        Some(geo) => geo,
        None => dualex::steps::quad_geometry(map, &mut ex, &x.geometry.options()),
    };
    laps.lap("geometry");
    geometry::check(name, &geo, ("quad", "quads"), x.strict)?;
    // 3. the picture, in memory
    let png = match (&a.png, ex.mesh.cells.is_empty()) {
        (Some(_), false) => Some(dualex::render::quad_png_bytes(&ex.mesh, PNG_SIZE).map_err(
            |error| CliError::Render {
                file: name.to_string(),
                error,
            },
        )?),
        _ => None,
    };
    // 4. the mesh written, then the stats and the picture
    progress.stage("writing");
    if a.uv {
        dualex::io::write_quad_mesh_uv(&a.output, &ex.mesh, &ex.corners)
    } else {
        dualex::io::write_quad_mesh(&a.output, &ex.mesh)
    }?;
    laps.lap("write");
    drop(progress);
    let json = stats_json(ex.stats.to_json(), &topology, &geo, extra);
    finish_stats(x, g, &json, &laps, &ex.stats.segment.time_ms)?;
    write_picture(a, png.as_deref())?;
    // 5. the warnings and the summary line
    let stats = &ex.stats;
    warnings::rounded(
        g,
        stats.segment.snapped_transitions,
        stats.segment.max_transition_residual,
    );
    geometry::warn(&geo, ("quad", "quads"));
    if own_map {
        warnings::degenerate(stats.folded_corners_collapsed, stats.doublets.dissolved);
    }
    warnings::quad_repairs(stats);
    if !g.quiet {
        eprintln!(
            "dualex: {}: {}, {}, {}, {}{} -> {}{}",
            done,
            count(stats.quads, "quad", "quads"),
            count(stats.vertices, "vertex", "vertices"),
            count(stats.boundary_loops, "boundary loop", "boundary loops"),
            count(stats.components, "component", "components"),
            geometry::done_words(&geo),
            a.output.display(),
            problems_suffix(&summary::quad_problems(stats)),
        );
    }
    Ok(())
}

/// Step 1 of [`quad_map`]: the extraction (`done_before`, or made
/// here), its validity and the last checks ([`crate::verify`]), with the
/// topology compared.
fn extract_quads(
    map: &dualex::map::TriMap,
    name: &str,
    a: &QuadArgs,
    g: &Global,
    done_before: Option<dualex::steps::QuadExtraction>,
    laps: &mut timing::Laps,
) -> Result<(dualex::steps::QuadExtraction, topo::Comparison), CliError> {
    let ex = match done_before {
        // the same map, extracted with the same options already
        Some(x) => x,
        None => {
            let (opts, singularities) = quad_options(a, g);
            dualex::steps::extract_quads(map, &opts, singularities)
                .map_err(|e| e.in_file(name.to_string()))?
        }
    };
    laps.lap("extract");
    let rep = dualex::check::check_quad_mesh(ex.mesh.positions.len(), &ex.mesh.cells);
    laps.lap("check");
    let topology = topo::Comparison {
        input: topo::surface_shape(map.positions.len(), &map.simplices),
        output: topo::quad_shape(&rep),
    };
    let out = verify::Output {
        cell: "quad",
        cells: ex.mesh.cells.len(),
        nodes: ex.stats.segment.nodes,
        measure: verify::measure(map),
        topology,
    };
    verify::before_writing(
        name,
        &out,
        rep.errors(),
        &ex.stats.segment.sanitize,
        a.extract.strict,
    )?;
    Ok((ex, topology))
}

/// The `--png` picture written (made in memory before), or the warning
/// that the mesh is empty.
fn write_picture(a: &QuadArgs, png: Option<&[u8]>) -> Result<(), CliError> {
    if let (Some(path), Some(bytes)) = (&a.png, png) {
        outputs::write_png(path, bytes)?;
    } else if let Some(path) = &a.png {
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

/// `--uv` with an output format that cannot carry per-corner map
/// coordinates (`.vtk`) is a usage error (exit 2); an unknown extension is
/// left to the output check.
pub(crate) fn refuse_uv(output: &Path) {
    let ext = dualex::io::lower_extension(output);
    if dualex::io::QUAD_MESH_EXTENSIONS.contains(&ext.as_str())
        && !dualex::io::write_uv::UV_EXTENSIONS.contains(&ext.as_str())
    {
        crate::args::usage_error(&format!(
            "--uv does not apply to .{ext} output (no per-corner attribute): use .obj or .ply"
        ));
    }
}

/// `dualex hex`.
pub fn hex(a: &HexArgs, g: &Global) -> Result<(), CliError> {
    let x = &a.extract;
    check_outputs(&a.output, dualex::io::HEX_MESH_EXTENSIONS, x, None)?;
    let name = a.input.display().to_string();
    let mut laps = timing::Laps::start();
    let map = dualex::io::read_tet_map(&a.input)?;
    laps.lap("read");
    let progress = progress::Progress::new(map.len(), g.quiet);
    progress.stage("extracting hexes");
    // 1. extracted, checked
    let (mut mesh, stats, topology) = extract_hexes(&map, &name, x, &mut laps)?;
    // 2. the geometric stage
    progress.stage("geometry");
    let geo = dualex::steps::hex_geometry(&map, &mut mesh, &x.geometry.options());
    laps.lap("geometry");
    geometry::check(&name, &geo, ("hex", "hexes"), x.strict)?;
    // 3. the mesh written, then the stats
    progress.stage("writing");
    dualex::io::write_hex_mesh(&a.output, &mesh)?;
    laps.lap("write");
    drop(progress);
    let json = stats_json(stats.to_json(), &topology, &geo, None);
    finish_stats(x, g, &json, &laps, &stats.segment.time_ms)?;
    // 4. the warnings and the summary line
    warnings::rounded(
        g,
        stats.segment.snapped_transitions,
        stats.segment.max_transition_residual,
    );
    geometry::warn(&geo, ("hex", "hexes"));
    warnings::hex_repairs(&stats);
    if !g.quiet {
        eprintln!(
            "dualex: done: {}, {}{} -> {}{}",
            count(mesh.cells.len(), "hex", "hexes"),
            count(mesh.positions.len(), "vertex", "vertices"),
            geometry::done_words(&geo),
            a.output.display(),
            problems_suffix(&summary::hex_problems(&stats)),
        );
    }
    Ok(())
}

/// Step 1 of [`hex`]: the extraction, its combinatorial validity (hexes
/// of a messy map may be geometrically inverted: vertices sit on noisy
/// preimages) and the last checks ([`crate::verify`]), with the topology
/// compared.
fn extract_hexes(
    map: &dualex::map::TetMap,
    name: &str,
    x: &ExtractArgs,
    laps: &mut timing::Laps,
) -> Result<(dualex::HexMesh, dualex::steps::HexReport, topo::Comparison), CliError> {
    // (index fairing on columns always on, as the library's default)
    let x_all = dualex::steps::extract_hexes(map, &x.options(true))
        .map_err(|e| e.in_file(name.to_string()))?;
    let (mesh, stats) = (x_all.mesh, x_all.stats);
    laps.lap("extract");
    let rep = dualex::check::check_hex_mesh(mesh.positions.len(), &mesh.cells, None);
    laps.lap("check");
    let topology = topo::Comparison {
        input: topo::tet_shape(map.positions.len(), &map.simplices),
        output: topo::hex_shape(&rep),
    };
    let out = verify::Output {
        cell: "hex",
        cells: mesh.cells.len(),
        nodes: stats.segment.nodes,
        measure: verify::measure(map),
        topology,
    };
    verify::before_writing(name, &out, rep.errors(), &stats.segment.sanitize, x.strict)?;
    Ok((mesh, stats, topology))
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
