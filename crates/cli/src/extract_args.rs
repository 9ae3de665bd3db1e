//! The arguments every extraction takes (`quad`, `hex`, and `remesh`'s
//! own copy of them): welding, rounding, the grid offset, the seed,
//! `--strict`, `--stats`, the geometric stage; and their reading as the
//! library's one [`dualex::Options`] for both dimensions.

use crate::args::{at_least_one, degrees};
use clap::Args;
use dualex::GridOffset;
use std::path::PathBuf;

/// Welding of cut meshes (2D inputs).
#[derive(Debug, Args)]
pub struct WeldArgs {
    /// Keep coincident boundary vertices of cut meshes apart (by default
    /// they are welded and the count reported).
    #[arg(long)]
    pub no_weld: bool,
}

/// Transition rounding.
#[derive(Debug, Args)]
pub struct RoundArgs {
    /// Snap non-integer transition translations of any residual instead of
    /// failing (residuals up to 0.1 map units are rounded by default, with
    /// a warning giving the largest).
    #[arg(long = "round-transitions")]
    pub round: bool,
}

/// Options shared by `quad` and `hex`.
#[derive(Debug, Args)]
pub struct ExtractArgs {
    /// Write the stats (one JSON object: input counts, sanitization,
    /// nodes, tracing, untangling, output counts and valences, topology,
    /// time per stage) to this file; `-` writes them to stdout.
    #[arg(long, value_name = "STATS.json")]
    pub stats: Option<PathBuf>,
    /// Where the dual grid sits: `half` puts the nodes at the map's
    /// half-integers (output vertices at its integer points), `zero` the
    /// reverse; `auto` takes `zero` only when fewer singular vertices then
    /// sit on nodes (then on isos, then fewer boundary facets in an iso).
    #[arg(long, value_name = "auto|half|zero", default_value = "auto", value_parser = grid_offset)]
    pub grid_offset: GridOffset,
    /// An output whose topology (components, Euler characteristic, boundary
    /// components) differs from the input's, vertices that sanitization
    /// left on the dual grid, or inverted elements the geometric stage
    /// could not remove, are an error (nothing written) instead of a
    /// warning.
    #[arg(long)]
    pub strict: bool,
    /// Seed of the sanitization perturbations.
    #[arg(long, value_name = "N", default_value_t = 1)]
    pub seed: u64,
    #[command(flatten)]
    pub round: RoundArgs,
    #[command(flatten)]
    pub geometry: GeometryArgs,
}

/// The geometric stage after the extraction (`dualex_geom`): it moves
/// vertices, never the mesh's combinatorics.
#[derive(Clone, Debug, Default, Args)]
pub struct GeometryArgs {
    /// `auto` (the default of quad and hex): untangle only where elements
    /// are inverted (scaled Jacobian ≤ 0), moving the vertices within a
    /// few rings of them, and put boundary vertices on the input's
    /// boundary; a mesh with neither is written as the map places it.
    /// `off`: keep the map's positions (as --no-untangle).
    #[arg(long, value_name = "auto|off", value_parser = ["auto", "off"], conflicts_with_all = ["smooth", "no_untangle"])]
    pub untangle: Option<String>,
    /// Keep the map's positions: measure the elements only.
    #[arg(long, conflicts_with = "smooth")]
    pub no_untangle: bool,
    /// Optimise the shape of every element (the same functional, on the
    /// whole mesh), in at most ITER rounds [default ITER: 10]; the
    /// default of remesh.
    #[arg(long, value_name = "ITER", num_args = 0..=1, default_missing_value = "10", value_parser = at_least_one)]
    pub smooth: Option<usize>,
    /// Leave boundary vertices where the map puts them, even off the
    /// input's boundary.
    #[arg(long)]
    pub keep_boundary: bool,
    /// Input edges whose faces' normals differ by more than DEG degrees
    /// are feature curves: vertices on them stay on them.
    #[arg(long, value_name = "DEG", default_value_t = 60.0, value_parser = degrees)]
    pub feature_angle: f64,
}

impl GeometryArgs {
    /// These, smoothing when no mode is given (remesh's default).
    pub fn smooth_by_default(&self) -> Self {
        let mut g = self.clone();
        if g.smooth.is_none() && !g.no_untangle && g.untangle.is_none() {
            g.smooth = Some(dualex::geom::SMOOTH_ROUNDS);
        }
        g
    }

    /// The stage's options.
    pub fn options(&self) -> dualex::geom::Options {
        use dualex::geom::Mode;
        let mode = match (self.smooth, self.no_untangle, self.untangle.as_deref()) {
            (Some(n), _, _) => Mode::Smooth(n),
            (None, true, _) | (None, _, Some("off")) => Mode::Off,
            _ => Mode::Auto,
        };
        dualex::geom::Options {
            mode,
            boundary: !self.keep_boundary,
            feature_angle: self.feature_angle,
        }
    }
}

impl ExtractArgs {
    /// The library's options of this extraction (`fairing`: not
    /// `--no-fairing`; the map is welded, or not, by the caller).
    pub fn options(&self, fairing: bool) -> dualex::Options {
        dualex::Options {
            weld: false,
            fairing,
            round_transitions: self.round.round,
            grid_offset: self.grid_offset,
            seed: self.seed,
            strict: self.strict,
            geometry: self.geometry.options(),
        }
    }
}

/// `--grid-offset`: the library's one parser ([`GridOffset::parse`]).
fn grid_offset(s: &str) -> Result<GridOffset, String> {
    GridOffset::parse(s).ok_or_else(|| format!("expected auto, half or zero, not {s:?}"))
}
