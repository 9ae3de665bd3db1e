//! `dualex quad` and `dualex hex`: read, extract, check, write.
//!
//! Order: every output path is checked first ([`crate::outputs`]); then
//! read, extract, the last check ([`crate::verify`]), the picture rendered
//! in memory; only then are the files written (mesh, stats, picture), so a
//! refused or failed run writes nothing. The summary line goes to stderr
//! and names the quality problems left ([`crate::summary`]).

use crate::args::{ExtractArgs, Global, HexArgs, QuadArgs};
use crate::summary::{count, problems_suffix};
use crate::{geometry, outputs, progress, summary, timing, verify, EMBEDDED, PNG_SIZE};
use dualex_check::topology as topo;
use std::path::Path;

/// Checks the outputs of an extraction (mesh, stats, picture).
fn check_outputs(
    mesh: &Path,
    exts: &'static [&'static str],
    x: &ExtractArgs,
    png: Option<&Path>,
) -> Result<(), String> {
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
pub fn quad(a: &QuadArgs, g: &Global) -> Result<(), String> {
    if a.uv {
        refuse_uv(&a.output);
    }
    check_outputs(
        &a.output,
        dualex_io::QUAD_MESH_EXTENSIONS,
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
            let m = dualex_io::parse_obj(EMBEDDED).map_err(|e| format!("embedded map: {e}"))?;
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

/// The extraction options of `quad` (and `remesh`) from the arguments.
pub fn quad_options(a: &QuadArgs, g: &Global) -> dualex_quad::QuadOptions {
    let x = &a.extract;
    dualex_quad::QuadOptions {
        fairing: !a.no_fairing,
        transitions: dualex_map::TransitionOptions {
            round: x.round.round,
            ..Default::default()
        },
        seed: x.seed,
        grid_offset: x.grid_offset,
        singularity_stats: x.stats.is_some() || g.verbose,
    }
}

/// What the caller of [`quad_map`] made before: one more section of the
/// stats, and the map's extraction with [`quad_options`] if it has it
/// (`remesh` extracts its maps to count their quads).
pub struct Before<'a> {
    /// The stats section (key, value).
    pub section: (&'a str, serde_json::Value),
    /// The extraction of this very map.
    pub extracted: Option<dualex_quad::Extracted>,
    /// The geometric stage's report when it has run on `extracted`
    /// already (its quads moved): not run again.
    pub geometry: Option<dualex_geom::Report>,
}

/// The quad extraction of a map read or made (`quad`, `remesh`): extract
/// (unless `before` has it), check, write; `done` starts the summary
/// line.
pub fn quad_map(
    map: &dualex_map::TriMap,
    name: &str,
    done: &str,
    a: &QuadArgs,
    g: &Global,
    mut laps: timing::Laps,
    before: Option<Before>,
) -> Result<(), String> {
    // the user's own map (not remesh's): its repairs are said
    let own_map = before.is_none();
    let (extra, done_before, staged) = match before {
        Some(b) => (Some(b.section), b.extracted, b.geometry),
        None => (None, None, None),
    };
    let x = &a.extract;
    let name = name.to_string();
    let progress = progress::Progress::new(map.len(), g.quiet);
    progress.stage("extracting quads");
    let dualex_quad::Extracted {
        mut mesh,
        stats,
        corner_uv,
        sources,
    } = match done_before {
        // the same map, extracted with the same options already
        Some(x) => x,
        None => dualex_quad::extract_full(map, &quad_options(a, g))
            .map_err(|e| e.in_file(name.clone()).to_string())?,
    };
    laps.lap("extract");
    let rep = dualex_check::check_quad_mesh(mesh.positions.len(), &mesh.cells);
    laps.lap("check");
    if !rep.is_valid() {
        return Err(format!(
            "{name}: could not make a valid quad mesh ({}); nothing written — please report this input",
            rep.errors().join("; ")
        ));
    }
    let topology = topo::Comparison {
        input: topo::surface_shape(map.positions.len(), &map.simplices),
        output: topo::quad_shape(&rep),
    };
    let summary = verify::Output {
        cell: "quad",
        cells: mesh.cells.len(),
        nodes: stats.nodes,
        measure: verify::measure(map),
        topology,
    };
    verify::last_check(&name, &summary, x.strict)?;
    verify::sanitize_check(&name, &stats.sanitize, x.strict)?;
    progress.stage("geometry");
    let geo = match staged {
        Some(geo) => geo,
        None => geometry::quads(&mut mesh, map, &sources, &x.geometry),
    };
    laps.lap("geometry");
    geometry::check(&name, &geo, ("quad", "quads"), x.strict)?;
    let png = match (&a.png, mesh.cells.is_empty()) {
        (Some(_), false) => Some(
            dualex_render::quad_png_bytes(&mesh, PNG_SIZE).map_err(|e| format!("{name}: {e}"))?,
        ),
        _ => None,
    };
    progress.stage("writing");
    if a.uv {
        dualex_io::write_quad_mesh_uv(&a.output, &mesh, &corner_uv)
    } else {
        dualex_io::write_quad_mesh(&a.output, &mesh)
    }
    .map_err(|e| e.to_string())?;
    laps.lap("write");
    drop(progress);
    let mut json = stats.to_json();
    verify::add_to_stats(&mut json, &topology);
    if let Some(obj) = json.as_object_mut() {
        obj.insert("geometry".to_string(), geo.to_json());
        if let Some(t) = obj.get_mut("time_ms").and_then(|t| t.as_object_mut()) {
            t.insert("geometry".to_string(), geo.time_ms.into());
        }
        if let Some((key, value)) = extra {
            obj.insert(key.to_string(), value);
        }
    }
    finish_stats(x, g, &json, &laps, &stats.time_ms)?;
    if let (Some(path), Some(bytes)) = (&a.png, &png) {
        outputs::write_png(path, bytes)?;
    } else if let Some(path) = &a.png {
        eprintln!(
            "dualex: warning: {}: not written: the mesh is empty",
            path.display()
        );
    }
    warn_rounded(g, stats.snapped_transitions, stats.max_transition_residual);
    geometry::warn(&geo, ("quad", "quads"));
    if own_map {
        warn_degenerate(stats.folded_corners_collapsed, stats.doublets.dissolved);
    }
    let faces = stats.repair_triangles + stats.holes_filled;
    if stats.repair_paths > 0 {
        // printed under -q too: the output is not the map's own mesh
        if faces == 0 {
            // the odd faces came from step 8a's splits (parallel edges,
            // folded cells), not from triangles or holes: said as such
            eprintln!(
                "dualex: warning: faces with an odd number of sides (left by splitting parallel edges and folded cells) were made quads along {} (local repair)",
                count(stats.repair_paths, "path", "paths"),
            );
        } else {
            eprintln!(
                "dualex: warning: {} that quads cannot represent ({} at singular vertices on dual nodes, {} closed by polygons) {} made quads along {} between them (local repair)",
                count(faces, "face", "faces"),
                count(stats.repair_triangles, "triangle", "triangles"),
                count(stats.holes_filled, "hole", "holes"),
                summary::plural(faces, "was", "were"),
                count(stats.repair_paths, "path", "paths"),
            );
        }
    }
    if stats.subdivided {
        // printed under -q too: the output is not the map's own mesh
        eprintln!(
            "dualex: warning: {} that quads cannot represent ({} at singular vertices on dual nodes, {} closed by polygons) {} made quads by one step of subdivision of the whole mesh",
            count(faces, "face", "faces"),
            count(stats.repair_triangles, "triangle", "triangles"),
            count(stats.holes_filled, "hole", "holes"),
            summary::plural(faces, "was", "were"),
        );
    }
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
            problems_suffix(&summary::quad_problems(&stats)),
        );
    }
    Ok(())
}

/// `--uv` with an output format that cannot carry per-corner map
/// coordinates (`.vtk`) is a usage error (exit 2); an unknown extension is
/// left to the output check.
pub(crate) fn refuse_uv(output: &Path) {
    let ext = dualex_io::lower_extension(output);
    if dualex_io::QUAD_MESH_EXTENSIONS.contains(&ext.as_str())
        && !dualex_io::write_uv::UV_EXTENSIONS.contains(&ext.as_str())
    {
        crate::args::usage_error(&format!(
            "--uv does not apply to .{ext} output (no per-corner attribute): use .obj or .ply"
        ));
    }
}

/// `dualex hex`.
pub fn hex(a: &HexArgs, g: &Global) -> Result<(), String> {
    let x = &a.extract;
    check_outputs(&a.output, dualex_io::HEX_MESH_EXTENSIONS, x, None)?;
    let name = a.input.display().to_string();
    let mut laps = timing::Laps::start();
    let map = dualex_io::read_tet_map(&a.input).map_err(|e| e.to_string())?;
    laps.lap("read");
    let opts = dualex_hex::HexOptions {
        transitions: dualex_map::TransitionOptions {
            round: x.round.round,
            ..Default::default()
        },
        seed: x.seed,
        grid_offset: x.grid_offset,
        ..dualex_hex::HexOptions::default()
    };
    let progress = progress::Progress::new(map.len(), g.quiet);
    progress.stage("extracting hexes");
    let (mut mesh, stats) =
        dualex_hex::extract(&map, &opts).map_err(|e| e.in_file(name.clone()).to_string())?;
    laps.lap("extract");
    // combinatorial validity (hexes of a messy map may be geometrically
    // inverted: vertices sit on noisy preimages)
    let rep = dualex_check::check_hex_mesh(mesh.positions.len(), &mesh.cells, None);
    laps.lap("check");
    if !rep.is_valid() {
        return Err(format!(
            "{name}: could not make a valid hex mesh ({}); nothing written",
            rep.errors().join("; ")
        ));
    }
    let topology = topo::Comparison {
        input: topo::tet_shape(map.positions.len(), &map.simplices),
        output: topo::hex_shape(&rep),
    };
    let summary = verify::Output {
        cell: "hex",
        cells: mesh.cells.len(),
        nodes: stats.nodes,
        measure: verify::measure(&map),
        topology,
    };
    verify::last_check(&name, &summary, x.strict)?;
    verify::sanitize_check(&name, &stats.sanitize, x.strict)?;
    progress.stage("geometry");
    let geo = geometry::hexes(&mut mesh, &map, &x.geometry);
    laps.lap("geometry");
    geometry::check(&name, &geo, ("hex", "hexes"), x.strict)?;
    progress.stage("writing");
    dualex_io::write_hex_mesh(&a.output, &mesh).map_err(|e| e.to_string())?;
    laps.lap("write");
    drop(progress);
    let mut json = stats.to_json();
    verify::add_to_stats(&mut json, &topology);
    if let Some(obj) = json.as_object_mut() {
        obj.insert("geometry".to_string(), geo.to_json());
        if let Some(t) = obj.get_mut("time_ms").and_then(|t| t.as_object_mut()) {
            t.insert("geometry".to_string(), geo.time_ms.into());
        }
    }
    finish_stats(x, g, &json, &laps, &stats.time_ms)?;
    warn_rounded(g, stats.snapped_transitions, stats.max_transition_residual);
    geometry::warn(&geo, ("hex", "hexes"));
    if stats.columns.holes > 0 {
        // printed under -q too: the output is not the map's own mesh
        let c = &stats.columns;
        eprintln!(
            "dualex: warning: {} through {} that hexes cannot represent (singular edges through dual nodes) {} filled, and {} split along {} between them (local repair on columns, as in 2D)",
            count(c.holes, "hole", "holes"),
            count(c.layers, "layer", "layers"),
            summary::plural(c.holes, "was", "were"),
            count(c.split, "column", "columns"),
            count(c.paths, "path", "paths"),
        );
    }
    if stats.open_interior_faces > 0 {
        // loud: printed even with -q (a crack is a wrong mesh, not noise)
        eprintln!(
            "dualex: WARNING: {} left open (walks lost at singular edges: cracks, not input boundary); see \"holes\" in the stats",
            count(stats.open_interior_faces, "interior face", "interior faces")
        );
    }
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

/// Writes `--stats`, and prints the `-v` table.
fn finish_stats(
    x: &ExtractArgs,
    g: &Global,
    json: &serde_json::Value,
    laps: &timing::Laps,
    stages: &[(String, f64)],
) -> Result<(), String> {
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

/// The warning for valence-1 and 2 vertices index fairing could not
/// merge (collapsed, dissolved), printed under -q too: such a repair is
/// where a messy map's mesh may differ from the map's own (a singularity
/// split by the untangling, docs/messy-cases.md).
fn warn_degenerate(folded: usize, doublets: usize) {
    let parts: Vec<String> = [
        (folded, "folded corner", "folded corners", "collapsed"),
        (doublets, "doublet", "doublets", "dissolved"),
    ]
    .into_iter()
    .filter(|p| p.0 > 0)
    .map(|(n, one, many, done)| format!("{} {done}", count(n, one, many)))
    .collect();
    if !parts.is_empty() {
        eprintln!(
            "dualex: warning: {}: degenerate vertices that index fairing found no partner for (the mesh may differ from the map's there); see \"folded_corners_collapsed\" and \"doublets\" in the stats",
            parts.join(" and ")
        );
    }
}

/// The warning for transitions rounded without `--round-transitions`
/// (or with it): how many, and the largest residual.
fn warn_rounded(g: &Global, rounded: usize, max_residual: f64) {
    if rounded > 0 && !g.quiet {
        eprintln!(
            "dualex: warning: rounded {} that {} not integral (largest residual {max_residual:.3e}); the map is not exactly grid-preserving",
            count(rounded, "transition translation", "transition translations"),
            summary::plural(rounded, "was", "were"),
        );
    }
}
