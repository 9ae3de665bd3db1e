//! Command-line parsing (hand-written: four subcommands and a few flags do
//! not justify a parser dependency; every error is one line).

use std::path::PathBuf;

/// Global usage text.
pub const USAGE: &str = "\
dualex — quad meshes from messy grid-preserving maps

usage:
  dualex quad    [INPUT] -o OUTPUT [--stats STATS.json] [--png QUADS.png] [--no-fairing] [options]
  dualex hex     INPUT.hexex -o OUTPUT [--stats STATS.json] [options]
  dualex inspect INPUT [--json] [--png MAP.png] [options]
  dualex view    MESH -o PAGE.html                (MESH: quads .obj/.ply, hexes .mesh)
  dualex extrude INPUT -o OUT.hexex [--layers L] [--thickness T] [--quality] [--fallback]
                        (prisms over every triangle, tetrahedralized by TetGen
                        found at run time (`tetgen`, or $DUALEX_TETGEN);
                        T default: 0.05 × the mean edge length on a surface,
                        0.5 × on a planar map; a slab TetGen refuses is retried
                        at T/2, T/4, T/8, then each prism split into 3 tets, as
                        is a self-intersecting surface at once (said on stderr);
                        --fallback: that split also when TetGen is missing)
  dualex generate NAME -o OUTPUT [--seed N]     (NAME: see `dualex generate --list`;
                                                2D maps → .obj/.ply, 3D maps → .hexex)
  dualex generate --from-mesh MESH -o MAP [--scale K] [--noise A] [--folds] [--seed N] [--half-shift]
                        (MESH: quads .obj/.ply or hexes .mesh, each element one chart
                        [0,K]^D; noise A in [0,1] grid units, exactly GP; writes MAP and
                        MAP.expected.json + the refined mesh MAP.expected.obj/.mesh;
                        NAME may also be a built-in mesh of `--list`, e.g. cubed_ball)

INPUT:   triangle mesh with per-corner map: .obj (f v/vt) or .ply (face texcoord);
         tet mesh with 3D map: .hexex
OUTPUT:  quads: .obj .ply .vtk; hexes: .mesh (MEDIT) .vtk
options:
  --no-weld             keep coincident boundary vertices of cut meshes apart
  --round-transitions   snap non-integer transition translations of any residual
                        (residuals up to 0.1 are rounded by default, with a warning)
  --grid-offset G       quad, hex: where the dual grid sits: auto (default), half
                        (nodes at the map's half-integers, output vertices at its
                        integer points) or zero (the reverse); auto takes zero only
                        when fewer singular vertices then sit on nodes (then isos)
  --strict              quad, hex: an output whose topology (components, Euler
                        characteristic, boundary components) differs from the
                        input's is an error (nothing written) instead of a warning
  --png FILE            quad: picture of the mesh colored by valence (3 blue, 4 grey,
                        5 red, other green); inspect: the map in the plane, reverted
                        triangles purple, singularities marked
  --seed N              seed of the sanitization perturbations (default 1)
  -j, --threads N       worker threads (default: all cores); the output is
                        byte-identical whatever N
  -v, --verbose         per-stage counts and timings on stderr
  -q, --quiet           print nothing but errors and the warnings about the output
                        itself (open interior faces, topology unlike the input's)
  -h, --help            this text";

/// Parsed command line.
#[derive(Debug, Default)]
pub struct Args {
    /// Subcommand.
    pub command: String,
    /// Positional argument (input file or generator name).
    pub input: Option<PathBuf>,
    /// `-o`.
    pub output: Option<PathBuf>,
    /// `--stats`.
    pub stats: Option<PathBuf>,
    /// `--json`.
    pub json: bool,
    /// `--no-fairing`.
    pub no_fairing: bool,
    /// `--no-weld`.
    pub no_weld: bool,
    /// `--round-transitions`.
    pub round: bool,
    /// `--grid-offset` (quad, hex).
    pub grid_offset: dualex_map::grid_offset::GridOffset,
    /// `--strict` (quad, hex): a topology mismatch is an error.
    pub strict: bool,
    /// `--seed`.
    pub seed: u64,
    /// `--png`.
    pub png: Option<PathBuf>,
    /// `--list`.
    pub list: bool,
    /// `--layers` (extrude).
    pub layers: Option<usize>,
    /// `--thickness` (extrude).
    pub thickness: Option<f64>,
    /// `--quality` (extrude).
    pub quality: bool,
    /// `--fallback` (extrude).
    pub fallback: bool,
    /// `-j` / `--threads` (None: all cores).
    pub threads: Option<usize>,
    /// `-v`.
    pub verbose: bool,
    /// `-q`.
    pub quiet: bool,
    /// `--from-mesh` (generate).
    pub from_mesh: Option<PathBuf>,
    /// `--scale` (generate --from-mesh).
    pub scale: Option<usize>,
    /// `--noise` (generate --from-mesh).
    pub noise: Option<f64>,
    /// `--folds` (generate --from-mesh).
    pub folds: bool,
    /// `--half-shift` (generate --from-mesh).
    pub half_shift: bool,
}

/// Parses `argv[1..]`.
pub fn parse(argv: &[String]) -> Result<Args, String> {
    let mut a = Args {
        seed: 1,
        ..Default::default()
    };
    let mut it = argv.iter();
    let Some(cmd) = it.next() else {
        return Err("missing subcommand (quad, hex, inspect, generate); see --help".into());
    };
    if cmd == "-h" || cmd == "--help" {
        a.command = "help".into();
        return Ok(a);
    }
    a.command = cmd.clone();
    while let Some(x) = it.next() {
        let mut value = |name: &str| {
            it.next()
                .cloned()
                .ok_or_else(|| format!("option {name} needs a value"))
        };
        match x.as_str() {
            "-o" | "--output" => a.output = Some(value(x)?.into()),
            "--stats" => a.stats = Some(value(x)?.into()),
            "--png" => a.png = Some(value(x)?.into()),
            "--seed" => {
                let v = value(x)?;
                a.seed = v
                    .parse()
                    .map_err(|_| format!("--seed: not an integer: {v}"))?;
            }
            "--json" => a.json = true,
            "--no-fairing" => a.no_fairing = true,
            "--no-weld" => a.no_weld = true,
            "--round-transitions" => a.round = true,
            "--strict" => a.strict = true,
            "--grid-offset" => {
                let v = value(x)?;
                a.grid_offset =
                    dualex_map::grid_offset::GridOffset::parse(&v).ok_or_else(|| {
                        format!("--grid-offset: expected auto, half or zero, not {v:?}")
                    })?;
            }
            "--list" => a.list = true,
            "--layers" => {
                let v = value(x)?;
                a.layers = Some(
                    v.parse()
                        .map_err(|_| format!("--layers: not a count: {v}"))?,
                );
            }
            "--thickness" => {
                let v = value(x)?;
                a.thickness = Some(
                    v.parse()
                        .map_err(|_| format!("--thickness: not a number: {v}"))?,
                );
            }
            "-j" | "--threads" => {
                let v = value(x)?;
                a.threads = Some(
                    v.parse()
                        .ok()
                        .filter(|&n: &usize| n > 0)
                        .ok_or_else(|| format!("{x}: not a positive count: {v}"))?,
                );
            }
            "--from-mesh" => a.from_mesh = Some(value(x)?.into()),
            "--scale" => {
                let v = value(x)?;
                a.scale = Some(
                    v.parse()
                        .map_err(|_| format!("--scale: not a count: {v}"))?,
                );
            }
            "--noise" => {
                let v = value(x)?;
                a.noise = Some(
                    v.parse()
                        .map_err(|_| format!("--noise: not a number: {v}"))?,
                );
            }
            "--folds" => a.folds = true,
            "--half-shift" => a.half_shift = true,
            "--quality" => a.quality = true,
            "--fallback" => a.fallback = true,
            "-v" | "--verbose" => a.verbose = true,
            "-q" | "--quiet" => a.quiet = true,
            "-h" | "--help" => a.command = "help".into(),
            s if s.starts_with('-') && s.len() > 1 => return Err(format!("unknown option {s}")),
            s => {
                if a.input.is_some() {
                    return Err(format!("unexpected argument {s}"));
                }
                a.input = Some(s.into());
            }
        }
    }
    Ok(a)
}
