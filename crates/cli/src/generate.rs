//! `dualex generate`: a named test map, a large one of a given size, or a
//! map made from a mesh ([`crate::generate_from_mesh`]).
//!
//! `--list` prints one line per name: the name, its size (triangles or
//! tets of the map; cells of a built-in mesh) and what it is. `--size N`
//! rebuilds the sizeable maps at grid resolution `N` (the benchmark cases
//! of `dualex-bench`: `2·N²` triangles for the squares, `N²` for the tori,
//! `6·N³` tets for the blocks, half a map unit per grid step).

use crate::args::{usage_error, GenerateArgs, Global};
use crate::error::CliError;
use crate::generate_from_mesh::{self, Input};
use crate::summary::count;
use dualex::gen::from_mesh::meshes;
use dualex::gen::{Diagonal, Perturb};
use dualex::map::{TetMap, TriMap};

/// The maps `--size` applies to.
const SIZEABLE: &[&str] = &[
    "square_identity",
    "square_noise",
    "torus",
    "torus_fold",
    "block",
    "block_noise",
];

/// What a name is, for `--list`.
fn describe(name: &str) -> &'static str {
    let sized = SIZEABLE.contains(&name);
    match name {
        _ if name.starts_with("square") && sized => "planar square, exact map (sizeable)",
        "square_identity_fixed" => "planar square, one diagonal direction",
        "square_fold" => "planar square with a fold (reverted triangles)",
        "square_collapsed" => "planar square with collapsed triangles",
        "square_half_rotated" => "planar square, map rotated by a half-turn with noise",
        "cube" => "cube surface, 8 singularities of index 1/4",
        "cube_fold" => "cube surface with folds",
        "cube_noise" => "cube surface with noise",
        "torus" | "torus_fold" => "torus, no singularity (sizeable)",
        "torus_noise" => "torus with noise",
        "invalid_quantization" => "disk whose map cannot be quantized (refused)",
        "multi_boundary" => "disk with several boundary loops",
        "block" | "block_noise" => "tet block, exact 3D map (sizeable)",
        "block_fold" => "tet block with a fold",
        "block_half_rotated" => "tet block, map rotated with noise",
        "block_degenerate" => "tet block with degenerate tets",
        "wedge_p1" | "wedge_m1" => "disk × 3 layers around a singular edge",
        _ if name.starts_with("disk_") && name.ends_with("_reverted") => {
            "disk with one singularity, reverted triangles around it"
        }
        _ if name.starts_with("disk_") => "disk with one singularity of the given index",
        _ => "",
    }
}

/// `dualex generate`.
pub fn generate(a: &GenerateArgs, g: &Global) -> Result<(), CliError> {
    if a.list {
        list(a.seed);
        return Ok(());
    }
    let Some(out) = &a.output else {
        usage_error("generate: missing -o OUTPUT");
    };
    if let Some(path) = &a.from_mesh {
        refuse_size(a, "--from-mesh");
        return generate_from_mesh::run(a, g, generate_from_mesh::read(path)?, out);
    }
    let Some(name) = &a.name else {
        usage_error("generate: missing NAME (see --list)");
    };
    if let Some(m) = meshes::quad_mesh_by_name(name) {
        refuse_size(a, name);
        return generate_from_mesh::run(a, g, Input::Quads(m, name.clone()), out);
    }
    if let Some(m) = meshes::hex_mesh_by_name(name) {
        refuse_size(a, name);
        return generate_from_mesh::run(a, g, Input::Hexes(m, name.clone()), out);
    }
    if let Some(surface) = dualex::remesh::shapes::by_name(name) {
        refuse_size(a, name);
        return write_surface(name, &surface, out, g);
    }
    if a.mesh_options() {
        usage_error(&format!(
            "--scale, --noise, --folds, --folds-at-singular, --magnify and --half-shift apply to --from-mesh and built-in meshes, not to the map {name:?}"
        ));
    }
    if let Some(map) = tri_map(name, a)? {
        crate::outputs::check(out, Some(dualex::io::TRI_MAP_EXTENSIONS))?;
        dualex::io::write_tri_map(out, &map)?;
        if !g.quiet {
            let n = map.len();
            eprintln!(
                "dualex: {name}: {} -> {}",
                count(n, "triangle", "triangles"),
                out.display()
            );
        }
        return Ok(());
    }
    let map = tet_map(name, a)?.ok_or_else(|| CliError::UnknownMap(name.clone()))?;
    crate::outputs::check(out, Some(dualex::io::TET_MAP_EXTENSIONS))?;
    dualex::io::write_tet_map(out, &map)?;
    if !g.quiet {
        eprintln!(
            "dualex: {name}: {} -> {}",
            count(map.len(), "tet", "tets"),
            out.display()
        );
    }
    Ok(())
}

fn refuse_size(a: &GenerateArgs, what: &str) {
    if a.size.is_some() {
        usage_error(&format!("--size does not apply to {what} (use --scale)"));
    }
}

fn sized(name: &str, a: &GenerateArgs) -> Result<Option<usize>, CliError> {
    match a.size {
        Some(_) if !SIZEABLE.contains(&name) => {
            if dualex::gen::by_name(name, a.seed).is_some()
                || dualex::gen::by_name_3d(name, a.seed).is_some()
            {
                usage_error(&format!(
                    "--size applies to {}, not to {name:?}",
                    SIZEABLE.join(", ")
                ));
            }
            Ok(None)
        }
        Some(r) if r < 2 => usage_error("--size must be at least 2"),
        s => Ok(s),
    }
}

/// Grid span of resolution `r`: half a map unit per step (as the benchmarks).
fn span(r: usize) -> (f64, f64) {
    (0.2, 0.2 + r as f64 / 2.0)
}

fn tri_map(name: &str, a: &GenerateArgs) -> Result<Option<TriMap>, CliError> {
    let Some(r) = sized(name, a)? else {
        return Ok(dualex::gen::by_name(name, a.seed).map(|(m, _)| m));
    };
    let alt = Diagonal::Alternating;
    let (lo, hi) = span(r);
    let (ru, rv) = (r, (r / 2).max(3));
    let (n, m) = ((ru / 2).max(1) as u32, (rv / 2).max(1) as u32);
    Ok(match name {
        "square_identity" => Some(dualex::gen::square_identity(r, lo, hi, alt).0),
        "square_noise" => Some(dualex::gen::square_noise(r, lo, hi, 0.3, a.seed, alt).0),
        "torus" => Some(dualex::gen::torus(n, m, ru, rv, Perturb::None, alt).0),
        "torus_fold" => {
            let fold = Perturb::Fold { strength: 1.5 };
            Some(dualex::gen::torus(n, m, ru, rv, fold, alt).0)
        }
        _ => None,
    })
}

fn tet_map(name: &str, a: &GenerateArgs) -> Result<Option<TetMap>, CliError> {
    let Some(r) = sized(name, a)? else {
        return Ok(dualex::gen::by_name_3d(name, a.seed).map(|(m, _)| m));
    };
    let (lo, hi) = span(r);
    Ok(match name {
        "block" => Some(dualex::gen::block::block(r, r, r, lo, hi).0),
        "block_noise" => Some(dualex::gen::block::block_noise(r, lo, hi, 0.3, a.seed).0),
        _ => None,
    })
}

/// `--list` (module docs).
fn list(seed: u64) {
    let line = |name: &str, size: String, what: &str| println!("{name:<24}{size:<18}{what}");
    for n in dualex::gen::names() {
        let len = dualex::gen::by_name(&n, seed).map_or(0, |(m, _)| m.len());
        line(&n, count(len, "triangle", "triangles"), describe(&n));
    }
    for n in dualex::gen::names_3d() {
        let len = dualex::gen::by_name_3d(&n, seed).map_or(0, |(m, _)| m.len());
        line(&n, count(len, "tet", "tets"), describe(&n));
    }
    for n in meshes::quad_mesh_names() {
        let len = meshes::quad_mesh_by_name(&n).map_or(0, |m| m.cells.len());
        line(&n, count(len, "quad", "quads"), "quad mesh: a map with its expected extraction (--scale, --noise, --folds, --folds-at-singular, --magnify, --half-shift)");
    }
    for n in meshes::hex_mesh_names() {
        let len = meshes::hex_mesh_by_name(&n).map_or(0, |m| m.cells.len());
        line(
            &n,
            count(len, "hex", "hexes"),
            "hex mesh: a map with its expected extraction (--scale, --noise, --folds, --folds-at-singular, --magnify)",
        );
    }
    for (n, what) in dualex::remesh::shapes::NAMED {
        let len = dualex::remesh::shapes::by_name(n).map_or(0, |s| s.triangles.len());
        line(
            n,
            count(len, "triangle", "triangles"),
            &format!("plain surface for `dualex remesh`: {what}"),
        );
    }
    println!(
        "\n--size N rebuilds {} at grid resolution N (2·N² triangles for squares, N² for tori, 6·N³ tets for blocks)",
        SIZEABLE.join(", ")
    );
}

/// Writes a generated plain surface (no map) as OBJ `v` / `f` lines.
fn write_surface(
    name: &str,
    s: &dualex::remesh::Surface,
    out: &std::path::Path,
    g: &Global,
) -> Result<(), CliError> {
    use std::fmt::Write as _;
    crate::outputs::check(out, Some(&["obj"]))?;
    let mut text = format!("# {name}: a plain surface (dualex generate)\n");
    for p in &s.positions {
        let _ = writeln!(text, "v {} {} {}", p[0], p[1], p[2]);
    }
    for t in &s.triangles {
        let _ = writeln!(text, "f {} {} {}", t[0] + 1, t[1] + 1, t[2] + 1);
    }
    dualex::io::write_text(out, &text)?;
    if !g.quiet {
        eprintln!(
            "dualex: {name}: {} -> {}",
            count(s.triangles.len(), "triangle", "triangles"),
            out.display()
        );
    }
    Ok(())
}
