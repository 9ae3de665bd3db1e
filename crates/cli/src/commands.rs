//! `dualex view`, `dualex inspect` and `dualex extrude`.

use crate::args::{ExtrudeArgs, Global, InspectArgs, ViewArgs};
use crate::error::CliError;
use crate::quality::{self, Mesh};
use crate::summary::count;
use crate::{outputs, timing, PNG_SIZE};

/// `dualex view`: a quad (`.obj`/`.ply`/`.vtk`) or hex (`.mesh`/`.vtk`)
/// mesh as a self-contained HTML page, with each element's scaled
/// Jacobian for the page's quality colouring.
pub fn view(a: &ViewArgs, g: &Global) -> Result<(), CliError> {
    outputs::check(&a.output, None)?;
    let input = &a.mesh;
    let name = input.display().to_string();
    let title = input
        .file_name()
        .map_or(name.clone(), |f| f.to_string_lossy().to_string());
    let mesh = quality::read_mesh(input, "view")?;
    let page = match &mesh {
        Mesh::Quads(m) => {
            let (values, normals) = quality::quad_quality(m, a.surface.as_deref())?;
            let q = dualex::render::Quality {
                values: &values,
                note: normals.short(),
            };
            dualex::render::view_html_quality(m, &title, &q)
        }
        Mesh::Hexes(m) => {
            if a.surface.is_some() {
                crate::args::usage_error("view --surface applies to quad meshes only");
            }
            let values = quality::hex_quality(m);
            let q = dualex::render::Quality {
                values: &values,
                note: "",
            };
            dualex::render::view_html_hex_quality(m, &title, &q)
        }
    }
    .map_err(|error| CliError::Render {
        file: name.clone(),
        error,
    })?;
    dualex::io::write_text(&a.output, &page)?;
    if !g.quiet {
        eprintln!("dualex: view: {} -> {}", name, a.output.display());
    }
    Ok(())
}

/// `dualex inspect`: the map report on stdout (text or `--json`), or a
/// mesh's quality report ([`crate::inspect_mesh`]).
pub fn inspect(a: &InspectArgs, _g: &Global) -> Result<(), CliError> {
    let path = &a.input;
    let name = path.display().to_string();
    let ext = dualex::io::lower_extension(path);
    let map_3d = ext == "hexex" || ext == "ovm";
    if a.png.is_some() && map_3d {
        crate::args::usage_error(
            "inspect --png: pictures of 3D maps are not supported; use a 2D map or a mesh",
        );
    }
    if let Some(png) = &a.png {
        outputs::check(png, None)?;
    }
    if let Some(mesh) = quality::inspected_mesh(path)? {
        if a.weld.no_weld || a.round.round {
            crate::args::usage_error(
                "inspect: --no-weld and --round-transitions apply to maps, not to meshes",
            );
        }
        if a.surface.is_some() && matches!(mesh, Mesh::Hexes(_)) {
            crate::args::usage_error("inspect --surface applies to quad meshes only");
        }
        return crate::inspect_mesh::inspect_mesh(&mesh, a, &name);
    }
    if a.surface.is_some() {
        crate::args::usage_error("inspect --surface applies to quad meshes, not to maps");
    }
    let opts = dualex::map::report::InspectOptions {
        weld: !a.weld.no_weld,
        round: a.round.round,
        ..Default::default()
    };
    let report = if map_3d {
        let m = dualex::io::read_tet_map(path)?;
        dualex::map::report::inspect(&m, &opts)
    } else {
        let m = dualex::io::read_tri_map(path)?;
        if let Some(png) = &a.png {
            let bytes =
                dualex::render::map_png_bytes(&m, PNG_SIZE).map_err(|error| CliError::Render {
                    file: name.clone(),
                    error,
                })?;
            outputs::write_png(png, &bytes)?;
        }
        dualex::map::report::inspect(&m, &opts)
    }
    .map_err(|e| e.in_file(name))?;
    if a.json {
        println!("{}", dualex::map_report_json(&report));
    } else {
        println!("{report}");
    }
    Ok(())
}

/// `dualex extrude`: a 2D map into a 3D one (prisms tetrahedralized by
/// TetGen, run as an external program; see dualex-extrude).
pub fn extrude(a: &ExtrudeArgs, g: &Global) -> Result<(), CliError> {
    outputs::check(&a.output, Some(dualex::io::TET_MAP_EXTENSIONS))?;
    let name = a.input.display().to_string();
    let map = crate::read_2d(&a.input, &a.weld, g, &mut timing::Laps::start())?;
    let opts = dualex::extrude::ExtrudeOptions {
        layers: a.layers,
        thickness: a.thickness,
        quality: a.quality,
        program: std::env::var_os("DUALEX_TETGEN").map_or("tetgen".into(), Into::into),
        fallback: a.fallback,
    };
    let (tets, rep) = dualex::extrude::extrude(&map, &opts).map_err(|error| CliError::Extrude {
        file: name.clone(),
        error,
    })?;
    dualex::io::write_tet_map(&a.output, &tets)?;
    if let Some(note) = rep.note.as_deref().filter(|_| !g.quiet) {
        eprintln!("dualex: {name}: {note}");
    }
    if rep.uv_shifted && !g.quiet {
        eprintln!(
            "dualex: {name}: charts shifted by (½, ½): `dualex quad` takes the grid offset 0 on this map, and `dualex hex` the offset ½, so the 3D grid is the 2D one"
        );
    }
    let cap = dualex::extrude::tetgen::steiner_cap(rep.prisms);
    if a.quality && rep.steiner_points >= cap {
        eprintln!(
            "dualex: warning: {name}: --quality stopped at its cap of {cap} Steiner points ({} per prism): the tets are valid but not all of TetGen's quality",
            dualex::extrude::tetgen::STEINER_PER_PRISM
        );
    }
    if !g.quiet {
        eprintln!(
            "dualex: done: {} -> {} ({}, {}, {} flat, {} reverted), thickness {:.3e}, {:.0} ms ({:.0} ms tetrahedralizing) -> {}",
            count(rep.prisms, "prism", "prisms"),
            count(rep.tets, "tet", "tets"),
            match rep.method {
                dualex::extrude::Method::TetGen => "TetGen",
                dualex::extrude::Method::Thinner { .. } => "TetGen, thinner slab",
                dualex::extrude::Method::Split => "prism split",
            },
            count(rep.steiner_points, "Steiner point", "Steiner points"),
            rep.flat_tets,
            rep.reverted_tets,
            rep.thickness,
            rep.total_ms,
            rep.tetrahedralize_ms,
            a.output.display()
        );
    }
    Ok(())
}
