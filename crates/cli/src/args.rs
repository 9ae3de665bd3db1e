//! The command line (clap derive): one struct per subcommand, so an option
//! that does not apply to a subcommand is a usage error (exit 2), and
//! `dualex SUBCOMMAND --help` describes every option it takes. Values are
//! checked here (`--layers 0`, `--noise 2`): a bad value is a usage error
//! naming the option, never the input file.

pub use crate::extract_args::{ExtractArgs, GeometryArgs, RoundArgs, WeldArgs};
use clap::{Args, Parser, Subcommand};
use std::path::PathBuf;

/// dualex — quad and hex meshes from messy grid-preserving maps.
#[derive(Debug, Parser)]
#[command(
    name = "dualex",
    version,
    propagate_version = true,
    arg_required_else_help = true,
    after_help = "Exit code 0 on success, 1 on bad input (one line naming the file and the element), \
                  2 on a usage error. `dualex SUBCOMMAND --help` describes each subcommand's options."
)]
pub struct Cli {
    /// Options every subcommand takes.
    #[command(flatten)]
    pub global: Global,
    /// The subcommand.
    #[command(subcommand)]
    pub command: Command,
}

/// Options every subcommand takes.
#[derive(Debug, Args)]
pub struct Global {
    /// Worker threads (default: all cores); the output is byte-identical
    /// whatever N.
    #[arg(short = 'j', long = "threads", value_name = "N", global = true, value_parser = positive)]
    pub threads: Option<usize>,
    /// Per-stage counts and timings on stderr (a table).
    #[arg(short, long, global = true)]
    pub verbose: bool,
    /// Print nothing but errors and the warnings about the output itself
    /// (open interior faces, topology unlike the input's, subdivision).
    #[arg(short, long, global = true)]
    pub quiet: bool,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
pub enum Command {
    /// Quad mesh of a 2D map (triangles with a per-corner map).
    Quad(QuadArgs),
    /// Hex mesh of a 3D map (tets with a per-corner map, `.hexex` or `.ovm`).
    Hex(HexArgs),
    /// A 3D map from a 2D one: prisms over every triangle, tetrahedralized.
    Extrude(ExtrudeArgs),
    /// A self-contained HTML page to orbit a quad or hex mesh, coloured by
    /// valence or by quality.
    View(ViewArgs),
    /// Map report (counts, reverted simplices, transitions, singularities),
    /// or a quad or hex mesh's quality (scaled Jacobian).
    Inspect(InspectArgs),
    /// Writes a generated test map, or a map made from a mesh (an oracle).
    Generate(GenerateArgs),
    /// Quad mesh of a plain surface: cross field, seamless map, rounding,
    /// then `quad` on that map.
    Remesh(RemeshArgs),
}

/// `dualex quad`.
#[derive(Debug, Args)]
#[command(
    after_help = "INPUT: .obj (`f v/vt`, per-corner texture coordinates) or .ply \
                        (face `texcoord` list of 6, or vertex `u v` / `s t` / \
                        `texture_u texture_v`). OUTPUT: .obj, .ply or .vtk. \
                        --uv: each quad's corners get map coordinates in the chart \
                        of the input triangle that holds its node (the node ± ½ on \
                        each axis: integers with --grid-offset half, half-integers \
                        with zero), per corner since charts disagree on seams; \
                        .obj `vt` + `f v/vt`, .ply face `texcoord` (8 values); \
                        quads without their own cell (hole fills, merged doublets) \
                        get none."
)]
pub struct QuadArgs {
    /// The 2D map (.obj / .ply); without it, the embedded messy map (a
    /// folded, noisy cube surface) is used, and said.
    pub input: Option<PathBuf>,
    /// The quad mesh (.obj, .ply or .vtk).
    #[arg(short, long, value_name = "OUTPUT")]
    pub output: PathBuf,
    /// A picture of the mesh, vertices colored by valence (3 blue, 4 grey,
    /// 5 red, other green).
    #[arg(long, value_name = "QUADS.png")]
    pub png: Option<PathBuf>,
    /// Skip index fairing (the merging of degenerate valence-1/2 vertices
    /// with strongly negative singularities by saddle lifts).
    #[arg(long)]
    pub no_fairing: bool,
    /// Write the map coordinates of each quad's corners (.obj `vt`, .ply
    /// face `texcoord`; not .vtk): the node's chart, node ± ½ (see below).
    #[arg(long)]
    pub uv: bool,
    #[command(flatten)]
    pub extract: ExtractArgs,
    #[command(flatten)]
    pub weld: WeldArgs,
}

/// `dualex hex`.
#[derive(Debug, Args)]
#[command(
    after_help = "INPUT: .hexex (HexEx's format) or .ovm (OpenVolumeMesh ASCII with HexHex's \
                        `HexHex::Parametrization`). OUTPUT: .mesh (MEDIT), .vtk or .ovm. \
                        Free boundaries are supported (hexes whose centres lie inside the volume)."
)]
pub struct HexArgs {
    /// The 3D map (.hexex or .ovm).
    pub input: PathBuf,
    /// The hex mesh (.mesh, .vtk or .ovm).
    #[arg(short, long, value_name = "OUTPUT")]
    pub output: PathBuf,
    #[command(flatten)]
    pub extract: ExtractArgs,
}

/// `dualex extrude`.
#[derive(Debug, Args)]
#[command(
    after_help = "TetGen (1.5, `apt-get install tetgen`) is found at run time as `tetgen` \
                        or $DUALEX_TETGEN. A slab TetGen refuses is retried at T/2, T/4, T/8, \
                        then each prism is split into 3 tets, as is a self-intersecting surface \
                        at once (said on stderr). `dualex hex` of the result has L layers of the \
                        `dualex quad` mesh."
)]
pub struct ExtrudeArgs {
    /// The 2D map (.obj / .ply).
    pub input: PathBuf,
    /// The 3D map (.hexex, or .ovm with `HexHex::Parametrization`).
    #[arg(short, long, value_name = "OUT.hexex")]
    pub output: PathBuf,
    /// Layers: `w` runs from 0 to L (at least 1).
    #[arg(long, value_name = "L", default_value_t = 1, value_parser = at_least_one)]
    pub layers: usize,
    /// Slab thickness in model units (positive); default 0.05 × the mean
    /// edge length on a surface, 0.5 × on a planar map.
    #[arg(long, value_name = "T", value_parser = positive_number)]
    pub thickness: Option<f64>,
    /// Ask TetGen for quality tets (`-q`: bounded radius-edge ratio, which
    /// adds Steiner points inside the prisms). Bounded: TetGen may add at
    /// most 8 Steiner points per prism (`-S`); when it reaches the cap a
    /// warning says so (the tets are valid, less refined). Without it, no
    /// Steiner point is added (`-Y`), which is all `dualex hex` needs.
    #[arg(long)]
    pub quality: bool,
    /// Without TetGen, split each prism into 3 tets (vertex-index rule)
    /// instead of failing with the install hint.
    #[arg(long)]
    pub fallback: bool,
    #[command(flatten)]
    pub weld: WeldArgs,
}

/// How the integer unknowns of the map are rounded.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum RoundingArg {
    /// All at once, then one more solve (the cheap way real pipelines use).
    Direct,
    /// A batch at a time, the closest to an integer first, solving between.
    Greedy,
    /// No rounding: singularities and seams off the grid (a messy map).
    Off,
}

/// `dualex remesh`.
#[derive(Debug, Args)]
#[command(
    after_help = "INPUT: .obj or .ply triangles (any map in it is ignored; cut meshes are \
                        welded). OUTPUT: .obj, .ply or .vtk. The map: a smoothest cross field \
                        (aligned to the boundary and to feature curves of edges sharper \
                        than --sharp; solved on the surface denoised along its normals), \
                        a cut through its singularities, seamless least-squares \
                        integration at a scale fitted to about N quads, rounding; then \
                        `dualex quad` on it."
)]
pub struct RemeshArgs {
    /// The surface (.obj / .ply); without it, the embedded surface is
    /// used, and said.
    pub input: Option<PathBuf>,
    /// The quad mesh (.obj, .ply or .vtk).
    #[arg(short, long, value_name = "OUTPUT")]
    pub output: PathBuf,
    /// About this many quads [default: 1000].
    #[arg(long, value_name = "N", value_parser = at_least_one, conflicts_with = "scale")]
    pub quads: Option<usize>,
    /// Quad edge length in model units, instead of --quads.
    #[arg(long, value_name = "S", value_parser = positive_number)]
    pub scale: Option<f64>,
    /// Edges whose dihedral angle exceeds DEG degrees are features the
    /// field follows, when they form curves (≥ 8 edges or 10 % of the
    /// bounding box; shorter runs are noise); 180 turns them off.
    #[arg(long, value_name = "DEG", default_value_t = 35.0, value_parser = degrees)]
    pub sharp: f64,
    /// Rounding of the map's integer unknowns (seam translations,
    /// singular vertices, feature lines).
    #[arg(long, value_name = "direct|greedy|off", default_value = "direct")]
    pub rounding: RoundingArg,
    /// Also write the map (a triangle map, .obj or .ply) that is
    /// extracted; written before the extraction, so that a map the
    /// extraction refuses can be inspected (`dualex inspect`).
    #[arg(long, value_name = "MAP.obj")]
    pub map_out: Option<PathBuf>,
    /// A picture of the map in the (u, v) plane: reverted triangles
    /// purple, singularities marked by index.
    #[arg(long, value_name = "MAP.png")]
    pub png: Option<PathBuf>,
    /// Seed: where the grid falls on the surface (a random translation of
    /// the map before rounding) and the field's rotation on surfaces
    /// without features; also the sanitization's.
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub seed: u64,
    /// Write the stats (the extraction's, with a `remesh` section: field,
    /// singularities, flipped triangles, times) to this file; `-` writes
    /// them to stdout.
    #[arg(long, value_name = "STATS.json")]
    pub stats: Option<PathBuf>,
    /// Skip index fairing in the extraction.
    #[arg(long)]
    pub no_fairing: bool,
    /// Write the map coordinates of each quad's corners (.obj `vt`, .ply
    /// face `texcoord`), as `quad --uv`.
    #[arg(long)]
    pub uv: bool,
    /// An output whose topology differs from the surface's, or inverted
    /// quads left, are an error.
    #[arg(long)]
    pub strict: bool,
    // `--round-transitions`, as `quad`'s: the error that suggests it names
    // a map remesh made that fails the check as remesh's bug
    #[command(flatten)]
    pub round: RoundArgs,
    /// The geometric stage (remesh smooths by default).
    #[command(flatten)]
    pub geometry: GeometryArgs,
}

pub(crate) fn degrees(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if (0.0..=180.0).contains(&x) => Ok(x),
        _ => Err(format!(
            "expected an angle from 0 to 180 degrees, not {s:?}"
        )),
    }
}

/// `dualex view`.
#[derive(Debug, Args)]
#[command(
    after_help = "MESH: quads .obj/.ply/.vtk, hexes .mesh/.vtk (as `dualex quad`/`hex` \
                        write them). The page is self-contained (own WebGL viewer, no network). \
                        It colours vertices by valence; a button (or key q) colours the \
                        elements by their scaled Jacobian instead (inverted ones, <= 0, red; \
                        a hex mesh's faces by their hex), as `dualex inspect` measures it."
)]
pub struct ViewArgs {
    /// The mesh to show.
    pub mesh: PathBuf,
    /// The HTML page.
    #[arg(short, long, value_name = "PAGE.html")]
    pub output: PathBuf,
    /// Quad meshes: the surface the quads lie on (.obj / .ply triangles,
    /// e.g. the input map, whose map coordinates are ignored); each quad's
    /// scaled Jacobian is taken against the normal of the triangle nearest
    /// its centre. Without it, against the mesh's own normals (each quad
    /// and its edge neighbours; less reliable).
    #[arg(long, value_name = "SURFACE")]
    pub surface: Option<PathBuf>,
}

/// `dualex inspect`.
#[derive(Debug, Args)]
#[command(
    after_help = "INPUT: a map (triangles with a per-corner map, .obj/.ply; tets, .hexex/.ovm) \
                        gets the map report. A mesh (.obj/.ply whose faces are all quads, .vtk of \
                        quads or hexes, .mesh hexes) gets the scaled Jacobian of its elements \
                        (verdict's: the least over the corners, 1 for a square or cube): \
                        elements, inverted (<= 0), degenerate, min, 5th percentile, median."
)]
pub struct InspectArgs {
    /// The map (.obj / .ply 2D, .hexex / .ovm 3D) or the quad or hex mesh
    /// (.obj / .ply / .vtk quads, .mesh / .vtk hexes).
    pub input: PathBuf,
    /// The report as one JSON object on stdout instead of text.
    #[arg(long)]
    pub json: bool,
    /// A picture: of a 2D map, in the (u, v) plane (reverted triangles
    /// purple, singularities marked by index, with a legend); of a mesh,
    /// the histogram of its elements' scaled Jacobian over [-1, 1]
    /// (inverted elements red).
    #[arg(long, value_name = "PICTURE.png")]
    pub png: Option<PathBuf>,
    /// Quad meshes: the surface the quads lie on (.obj / .ply triangles,
    /// e.g. the input map, whose map coordinates are ignored); each quad's
    /// scaled Jacobian is taken against the normal of the triangle nearest
    /// its centre. Without it, against the mesh's own normals (each quad
    /// and its edge neighbours; less reliable, and said in the report).
    #[arg(long, value_name = "SURFACE")]
    pub surface: Option<PathBuf>,
    #[command(flatten)]
    pub weld: WeldArgs,
    #[command(flatten)]
    pub round: RoundArgs,
}

/// `dualex generate`.
#[derive(Debug, Args)]
#[command(
    after_help = "2D maps are written as .obj/.ply, 3D maps as .hexex or .ovm. With --from-mesh \
                        (or NAME a built-in mesh), each element becomes its own chart [0,K]^D; \
                        the expected extraction is written beside the map as MAP.expected.json \
                        and MAP.expected.obj/.mesh."
)]
pub struct GenerateArgs {
    /// The generated map or built-in mesh (see --list).
    #[arg(required_unless_present_any = ["list", "from_mesh"], conflicts_with = "from_mesh")]
    pub name: Option<String>,
    /// The map to write.
    #[arg(short, long, value_name = "OUT", required_unless_present = "list")]
    pub output: Option<PathBuf>,
    /// List the generated maps and built-in meshes, with sizes and what
    /// they are.
    #[arg(long, exclusive = true)]
    pub list: bool,
    /// Seed of the generator (noise, folds).
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub seed: u64,
    /// Size parameter of the sizeable generated maps (cells per side of
    /// the grid; see --list): large maps for timing.
    #[arg(long, value_name = "N", value_parser = at_least_one)]
    pub size: Option<usize>,
    /// A quad mesh (.obj/.ply) or hex mesh (.mesh) to turn into a map.
    #[arg(long, value_name = "MESH")]
    pub from_mesh: Option<PathBuf>,
    /// Mesh maps: each element is the chart [0,K]^D (at least 1; default 2).
    #[arg(long, value_name = "K", value_parser = at_least_one)]
    pub scale: Option<usize>,
    /// Mesh maps: move every vertex once in map space by up to A grid
    /// units (0 ≤ A ≤ 1); the map stays exactly grid-preserving.
    #[arg(long, value_name = "A", value_parser = unit_interval)]
    pub noise: Option<f64>,
    /// Mesh maps: add folds.
    #[arg(long)]
    pub folds: bool,
    /// Mesh maps: fold the map around N interior singular vertices (no
    /// element holding two): radial, radius 1.5 and amplitude 3 elements,
    /// alternately pulled through the vertex and pushed outwards; exactly
    /// grid-preserving. Separate from --folds, whose maps stay as they are.
    #[arg(long, value_name = "N")]
    pub folds_at_singular: Option<usize>,
    /// Mesh maps: multiply the map's coordinates by M at the end (the same
    /// simplices; grid points inside them); expected: the mesh refined
    /// K·M times.
    #[arg(long, value_name = "M", value_parser = at_least_one)]
    pub magnify: Option<usize>,
    /// Mesh maps (quads): put every vertex, singular ones included, at a
    /// cell centre.
    #[arg(long)]
    pub half_shift: bool,
}

impl GenerateArgs {
    /// Whether an option of mesh maps was given.
    pub fn mesh_options(&self) -> bool {
        self.scale.is_some()
            || self.noise.is_some()
            || self.folds
            || self.folds_at_singular.is_some()
            || self.magnify.is_some()
            || self.half_shift
    }
}

fn positive(s: &str) -> Result<usize, String> {
    match s.parse::<usize>() {
        Ok(n) if n > 0 => Ok(n),
        _ => Err(format!("expected a positive count, not {s:?}")),
    }
}

pub(crate) fn at_least_one(s: &str) -> Result<usize, String> {
    positive(s).map_err(|_| format!("must be a whole number of at least 1, not {s:?}"))
}

fn positive_number(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if x.is_finite() && x > 0.0 => Ok(x),
        _ => Err(format!("expected a positive number, not {s:?}")),
    }
}

fn unit_interval(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(x) if (0.0..=1.0).contains(&x) => Ok(x),
        _ => Err(format!("expected a number from 0 to 1, not {s:?}")),
    }
}

/// A usage error found after parsing (e.g. an option that does not apply
/// to the chosen NAME): printed like clap's, exit code 2.
pub fn usage_error(msg: &str) -> ! {
    use clap::CommandFactory;
    Cli::command()
        .error(clap::error::ErrorKind::ArgumentConflict, msg)
        .exit()
}

#[cfg(test)]
mod tests {
    use super::*;
    use clap::CommandFactory;

    #[test]
    fn the_command_line_is_consistent() {
        Cli::command().debug_assert();
    }
}
