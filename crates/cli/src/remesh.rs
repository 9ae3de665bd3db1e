//! `dualex remesh`: quads from a plain surface, in one command.
//!
//! Order: every output path is checked first; the surface is read (OBJ or
//! PLY; polygons fanned into triangles; cut meshes welded), the map made
//! by [`dualex_remesh::remesh`] (cross field, cut, seamless integration,
//! rounding), written (`--map-out`) and pictured (`--png`) when asked, then
//! extracted by the same code as `dualex quad` ([`crate::extract::quad_map`]),
//! whose checks and summary apply: a refused output writes no mesh.

use crate::args::{ExtractArgs, Global, QuadArgs, RemeshArgs, RoundArgs, RoundingArg, WeldArgs};
use crate::summary::count;
use crate::{outputs, timing, PNG_SIZE};
use dualex_check::topology;
use dualex_map::grid_offset::GridOffset;
use dualex_remesh::{Quantization, Target};

/// The surface `dualex remesh` runs on without INPUT.
const EMBEDDED_SURFACE: &str = "a bumpy sphere of 5120 triangles";

/// `dualex remesh`.
pub fn remesh(a: &RemeshArgs, g: &Global) -> Result<(), String> {
    if a.uv {
        crate::extract::refuse_uv(&a.output);
    }
    let mut all = vec![(a.output.as_path(), Some(dualex_io::QUAD_MESH_EXTENSIONS))];
    if let Some(m) = &a.map_out {
        all.push((m.as_path(), Some(dualex_io::TRI_MAP_EXTENSIONS)));
    }
    for p in [&a.png, &a.stats].into_iter().flatten() {
        all.push((p.as_path(), None));
    }
    outputs::check_all(&all)?;
    let mut laps = timing::Laps::start();
    let (positions, triangles, name) = match &a.input {
        Some(p) => {
            let name = p.display().to_string();
            let poly = dualex_io::read_polygon_mesh(p).map_err(|e| e.to_string())?;
            let (tris, fanned) = fan(&poly.faces, &name)?;
            if fanned > 0 && !g.quiet {
                eprintln!(
                    "dualex: {name}: {} split into triangles",
                    count(fanned, "polygon", "polygons")
                );
            }
            (poly.positions, tris, name)
        }
        None => {
            if !g.quiet {
                eprintln!(
                    "dualex: no INPUT given: running on the embedded surface ({EMBEDDED_SURFACE})"
                );
            }
            let (p, t) = dualex_remesh::shapes::embedded();
            (p, t, "embedded surface".to_string())
        }
    };
    laps.lap("read");
    let welded = dualex_remesh::weld::weld(&positions, &triangles);
    if welded.merged > 0 && !g.quiet {
        eprintln!(
            "dualex: {name}: welded {} of the cut",
            count(welded.merged, "vertex", "vertices")
        );
    }
    let surface = dualex_remesh::Surface::new(welded.positions, welded.triangles)
        .map_err(|e| format!("{name}: {e}"))?;
    laps.lap("weld");
    let opts = dualex_remesh::RemeshOptions {
        target: match (a.scale, a.quads) {
            (Some(s), _) => Target::EdgeLength(s),
            (None, n) => Target::Quads(n.unwrap_or(1000)),
        },
        sharp_degrees: a.sharp,
        quantization: match a.rounding {
            RoundingArg::Direct => Quantization::Direct,
            RoundingArg::Greedy => Quantization::Greedy,
            RoundingArg::Off => Quantization::SingularitiesOff,
        },
        seed: a.seed,
    };
    let quad = QuadArgs {
        input: a.input.clone(),
        output: a.output.clone(),
        png: None,
        no_fairing: a.no_fairing,
        uv: a.uv,
        extract: ExtractArgs {
            stats: a.stats.clone(),
            grid_offset: GridOffset::Auto,
            strict: a.strict,
            seed: a.seed,
            round: RoundArgs { round: false },
            geometry: a.geometry.smooth_by_default(),
        },
        weld: WeldArgs { no_weld: true },
    };
    // the extraction's quad count steers the quad count (see
    // `remesh_counted`): the extraction below, and only a mesh it would
    // write counts (valid, the surface's topology); the extraction of each
    // map counted is kept, so the map kept is not extracted again
    let qopts = crate::extract::quad_options(&quad, g);
    let shape = topology::surface_shape(surface.positions.len(), &surface.triangles);
    // (one entry per map counted, in the order of `remesh.counted`)
    let mut extracted: Vec<Option<dualex_quad::Extracted>> = Vec::new();
    let mut quads_of = |m: &dualex_map::TriMap| {
        let x = dualex_quad::extract_full(m, &qopts).ok();
        let n = x.as_ref().and_then(|x| {
            let rep = dualex_check::check_quad_mesh(x.mesh.positions.len(), &x.mesh.cells);
            let same = rep.is_valid() && topology::quad_shape(&rep) == shape;
            same.then_some(x.mesh.cells.len())
        });
        extracted.push(x);
        n
    };
    let made = dualex_remesh::remesh_counted(&surface, &opts, &mut quads_of)
        .map_err(|e| format!("{name}: {e}"))?;
    laps.lap("map");
    let s = &made.stats;
    if !g.quiet {
        eprintln!(
            "dualex: {name}: map: {}, {} ({} of {} triangles flipped), {} rounding",
            count(s.singularities, "singularity", "singularities"),
            count(s.cut_edges, "cut edge", "cut edges"),
            s.flipped,
            s.triangles,
            match a.rounding {
                RoundingArg::Direct => "direct",
                RoundingArg::Greedy => "greedy",
                RoundingArg::Off => "no singularity",
            }
        );
    }
    let refused = s.counted.iter().take_while(|c| c.is_none()).count();
    if refused > 0 && refused < s.counted.len() && !g.quiet {
        eprintln!(
            "dualex: {name}: the extraction refused the map at the seed's grid position; the grid was moved {} (remesh.counted in the stats)",
            count(refused, "time", "times")
        );
    }
    if let Some(path) = &a.map_out {
        dualex_io::write_tri_map(path, &made.map).map_err(|e| e.to_string())?;
    }
    if let Some(path) = &a.png {
        let bytes = dualex_render::map_png_bytes(&made.map, PNG_SIZE)
            .map_err(|e| format!("{name}: {e}"))?;
        outputs::write_png(path, &bytes)?;
    }
    let done_before = made
        .stats
        .kept
        .and_then(|k| extracted.into_iter().nth(k))
        .flatten();
    let done = if a.input.is_some() {
        "done"
    } else {
        "embedded surface"
    };
    crate::extract::quad_map(
        &made.map,
        &name,
        done,
        &quad,
        g,
        laps,
        Some(crate::extract::Before {
            section: ("remesh", stats_json(s)),
            extracted: done_before,
        }),
    )
}

/// Polygons fanned into triangles (from their first corner); how many
/// polygons were split. A face of fewer than 3 corners is an error.
fn fan(faces: &[Vec<u32>], name: &str) -> Result<(Vec<[u32; 3]>, usize), String> {
    let mut tris = Vec::with_capacity(faces.len());
    let mut fanned = 0;
    for (i, f) in faces.iter().enumerate() {
        if f.len() < 3 {
            return Err(format!("{name}: face {i} has {} vertices", f.len()));
        }
        if f.len() > 3 {
            fanned += 1;
        }
        for k in 1..f.len() - 1 {
            tris.push([f[0], f[k], f[k + 1]]);
        }
    }
    Ok((tris, fanned))
}

/// The `remesh` section of the stats.
fn stats_json(s: &dualex_remesh::RemeshStats) -> serde_json::Value {
    let index: serde_json::Map<String, serde_json::Value> = s
        .singularity_index
        .iter()
        .map(|(q, n)| (format!("{q}/4"), (*n).into()))
        .collect();
    serde_json::json!({
        "triangles": s.triangles,
        "singularities": s.singularities,
        "singularity_index": index,
        "boundary_singularities": s.boundary_singularities,
        "sharp_edges": s.sharp_edges,
        "cut_edges": s.cut_edges,
        "flipped": s.flipped,
        "degenerate": s.degenerate,
        "scale": s.scale,
        "first_scale": s.first_scale,
        "map_area": s.map_area,
        "roundings": s.roundings,
        "rounded": s.rounded,
        "off_grid": s.off_grid,
        "max_rounding": s.max_rounding,
        "counted": s.counted,
        "kept": s.kept,
        "time_ms": {
            "field": s.time_ms[0],
            "cut": s.time_ms[1],
            "integrate": s.time_ms[2],
            "count": s.time_ms[3],
        },
    })
}
