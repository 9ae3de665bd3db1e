//! `dualex remesh`: quads from a plain surface, in one command.
//!
//! Order: every output path is checked first; the surface is read (OBJ or
//! PLY; polygons fanned into triangles); the library's pipeline
//! ([`dualex::remesh_map`]: weld, cross field, cut, seamless integration,
//! rounding, the extraction's count) makes the map, written (`--map-out`)
//! and pictured (`--png`) when asked; then the library's checks (a
//! collapsed map, a map the extraction refuses: remesh's bug; no quad: an
//! error) and the extraction kept are handed to the same code as `dualex
//! quad` ([`crate::extract::extract_map`]), whose checks and summary apply: a
//! refused output writes no mesh.

use crate::args::{ExtractArgs, Global, QuadArgs, RemeshArgs, RoundArgs, RoundingArg, WeldArgs};
use crate::error::CliError;
use crate::summary::count;
use crate::{outputs, timing, PNG_SIZE};
use dualex::{GridOffset, Quantization, Target};

/// The surface `dualex remesh` runs on without INPUT.
const EMBEDDED_SURFACE: &str = "a bumpy sphere of 5120 triangles";

/// `dualex remesh`: the outputs checked, the surface read, the map made
/// (written and pictured as it goes), the extraction handed on.
pub fn remesh(a: &RemeshArgs, g: &Global) -> Result<(), CliError> {
    if a.uv {
        crate::quad::refuse_uv(&a.output);
    }
    // 1. every output checked first
    check_outputs(a)?;
    let mut laps = timing::Laps::start();
    // 2. the surface read
    let (positions, triangles, name) = read_input(a, g)?;
    laps.lap("read");
    // 3. weld, map, the extraction's count, the geometric stage, at
    // another grid position while quads are left inverted (the library's
    // pipeline, as Python's `remesh` runs it); each map is described,
    // written and pictured before its checks, so that a refused one can
    // be inspected
    let mut written: Result<(), CliError> = Ok(());
    let mut last = 0;
    let mut show = |k: usize, made: &dualex::RemeshedMap| -> Result<(), dualex::Error> {
        last = k;
        describe(&name, k, made, a, g);
        written = write_map(&made.map, a, &name);
        // (the writer's own message is the run's, below; not a remesh bug,
        // which would send the run to the next grid position; the error
        // stays in `written`, this one only stops the run)
        written.as_ref().map_err(|e| {
            let stop = std::io::Error::other(e.to_string());
            dualex::Error::Input(dualex::InputErrorKind::from_source(stop).into())
        })?;
        Ok(())
    };
    let staged = dualex::remesh_staged(&positions, &triangles, &options(a), &mut show);
    written?;
    let staged = staged.map_err(|error| CliError::Library {
        file: name.clone(),
        error,
    })?;
    laps.lap("map");
    if staged.attempt != last {
        // a later attempt was written last: the map kept once more
        write_map(&staged.map, a, &name)?;
    }
    // 4. the extraction kept, checked and written as `dualex quad` does
    let dualex::Staged {
        map,
        stats,
        extracted,
        geometry,
        ..
    } = staged;
    let done = if a.input.is_some() {
        "done"
    } else {
        "embedded surface"
    };
    crate::extract::extract_map(
        &map,
        &name,
        done,
        &quad_args(a),
        g,
        laps,
        Some(crate::extract::Before {
            section: ("remesh", stats.to_json()),
            extracted: Some(extracted),
            geometry,
        }),
    )
}

/// Step 1 of [`remesh`]: the mesh, `--map-out`, `--png` and `--stats`
/// checked ([`outputs::check_all`]).
fn check_outputs(a: &RemeshArgs) -> Result<(), CliError> {
    let mut all = vec![(a.output.as_path(), Some(dualex::io::QUAD_MESH_EXTENSIONS))];
    if let Some(m) = &a.map_out {
        all.push((m.as_path(), Some(dualex::io::TRI_MAP_EXTENSIONS)));
    }
    for p in [&a.png, &a.stats].into_iter().flatten() {
        all.push((p.as_path(), None));
    }
    outputs::check_all(&all)
}

/// Step 2 of [`remesh`]: the surface of INPUT (OBJ or PLY; polygons
/// fanned into triangles) or the embedded one, with its name.
fn read_input(a: &RemeshArgs, g: &Global) -> Result<Input, CliError> {
    match &a.input {
        Some(p) => {
            let name = p.display().to_string();
            let read = dualex::read_surface(p).map_err(CliError::ReadSurface)?;
            if read.fanned > 0 && !g.quiet {
                eprintln!(
                    "dualex: {name}: {} split into triangles",
                    count(read.fanned, "polygon", "polygons")
                );
            }
            Ok((read.positions, read.triangles, name))
        }
        None => {
            if !g.quiet {
                eprintln!(
                    "dualex: no INPUT given: running on the embedded surface ({EMBEDDED_SURFACE})"
                );
            }
            let (p, t) = dualex::remesh::shapes::embedded();
            Ok((p, t, "embedded surface".to_string()))
        }
    }
}

/// A surface read: positions, triangles, the name said.
type Input = (Vec<[f64; 3]>, Vec<[u32; 3]>, String);

/// The library's options of `remesh` from the arguments.
fn options(a: &RemeshArgs) -> dualex::RemeshOptions {
    dualex::RemeshOptions {
        map: dualex::MapOptions {
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
        },
        extract: dualex::Options {
            weld: false,
            fairing: !a.no_fairing,
            round_transitions: a.round.round,
            grid_offset: GridOffset::Auto,
            seed: a.seed,
            strict: a.strict,
            geometry: a.geometry.smooth_by_default().options(),
        },
    }
}

/// The arguments of `dualex quad` that `remesh` hands its extraction to
/// ([`crate::extract::extract_map`]).
fn quad_args(a: &RemeshArgs) -> QuadArgs {
    QuadArgs {
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
            round: RoundArgs {
                round: a.round.round,
            },
            geometry: a.geometry.smooth_by_default(),
        },
        weld: WeldArgs { no_weld: true },
    }
}

/// What the map of attempt `k` is (stderr, unless quiet).
fn describe(name: &str, k: usize, made: &dualex::RemeshedMap, a: &RemeshArgs, g: &Global) {
    if g.quiet {
        return;
    }
    if k > 0 {
        eprintln!(
            "dualex: {name}: the last grid position left inverted quads, a topology unlike the surface's or a map remesh could not use: another one (attempt {} of at most {}; remesh.grid_attempts in the stats)",
            k + 1,
            dualex::GRID_ATTEMPTS
        );
    }
    if made.welded > 0 {
        eprintln!(
            "dualex: {name}: welded {} of the cut",
            count(made.welded, "vertex", "vertices")
        );
    }
    let s = &made.stats;
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
    let refused = s.counted.iter().take_while(|c| c.is_none()).count();
    if refused > 0 && refused < s.counted.len() {
        eprintln!(
            "dualex: {name}: the extraction refused the map at the seed's grid position; the grid was moved {} (remesh.counted in the stats)",
            count(refused, "time", "times")
        );
    }
}

/// The map (`--map-out`) and its picture (`--png`), when asked.
fn write_map(map: &dualex::TriMap, a: &RemeshArgs, name: &str) -> Result<(), CliError> {
    if let Some(path) = &a.map_out {
        dualex::io::write_tri_map(path, map)?;
    }
    if let Some(path) = &a.png {
        let bytes =
            dualex::render::map_png_bytes(map, PNG_SIZE).map_err(|error| CliError::Render {
                file: name.to_string(),
                error,
            })?;
        outputs::write_png(path, &bytes)?;
    }
    Ok(())
}
