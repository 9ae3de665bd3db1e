//! Why a command failed: [`CliError`], printed by `main` as one line
//! `dualex: …` (exit 1).
//!
//! Every message names the file (the input read, the output refused)
//! and, where there is one, the element (a face, a vertex, a cell): the
//! readers' and writers' own errors already do
//! ([`dualex::map::InputError`], [`dualex::io::OutputError`]); the stages'
//! errors are wrapped with the file they ran on.

use std::fmt;
use std::path::PathBuf;

/// Why a command failed.
#[derive(Debug)]
pub enum CliError {
    /// A file could not be read or a map was refused (the error names the
    /// file and the line or element).
    Input(dualex::map::InputError),
    /// A plain surface could not be read (`remesh`; the error names the
    /// file and the line or element).
    ReadSurface(dualex::Error),
    /// The embedded map could not be read (a bug of the build).
    EmbeddedMap(dualex::map::InputError),
    /// An output could not be written or is refused up front.
    Output(dualex::io::OutputError),
    /// stdout could not be written (`--stats -`).
    Stdout(std::io::Error),
    /// One file named for two outputs.
    TwoOutputs(PathBuf),
    /// The library's pipeline (`remesh`) refused the input.
    Library {
        /// The input.
        file: String,
        /// Its error.
        error: dualex::Error,
    },
    /// A picture or page could not be made.
    Render {
        /// The input pictured.
        file: String,
        /// Its error.
        error: dualex::render::RenderError,
    },
    /// The extrusion refused the map.
    Extrude {
        /// The input.
        file: String,
        /// Its error.
        error: dualex::extrude::ExtrudeError,
    },
    /// A map could not be made from a mesh (`generate --from-mesh`).
    FromMesh {
        /// The mesh.
        file: String,
        /// Its error.
        error: dualex::gen::from_mesh::FromMeshError,
    },
    /// The output was refused by the checks before writing; nothing
    /// written.
    Refused {
        /// The input.
        file: String,
        /// Why.
        why: Refusal,
    },
    /// A mesh of a format `view`/`inspect` does not read.
    NotAMesh {
        /// The file.
        file: String,
        /// The subcommand.
        what: &'static str,
        /// Its extension.
        ext: String,
    },
    /// A face with the wrong number of sides.
    Face {
        /// The file.
        file: String,
        /// The face.
        face: usize,
        /// Its vertices.
        sides: usize,
        /// What the file must hold.
        need: Need,
    },
    /// A mesh read with a bad vertex or cell (its check is the
    /// pictures': [`dualex::render::valence::check_cells`]).
    Mesh {
        /// The file.
        file: String,
        /// The offender.
        error: dualex::render::RenderError,
    },
    /// The `--surface` file could not be read.
    SurfaceRead(dualex::map::InputError),
    /// The `--surface` file has a bad vertex.
    Surface {
        /// The file.
        file: String,
        /// The offender.
        error: dualex::render::RenderError,
    },
    /// `generate NAME` with a name it does not know.
    UnknownMap(String),
    /// Internal: the stats could not be serialised (`what`: which).
    Bug {
        /// Which text (`"stats: "` or empty).
        what: &'static str,
        /// The serialiser's reason.
        reason: String,
    },
}

/// What a file's faces must be ([`CliError::Face`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Need {
    /// Quads, read by the subcommand (`inspect` reads triangle maps too).
    Quads(&'static str),
    /// Quads, for `--from-mesh`.
    FromMesh,
    /// Triangles, for `--surface`.
    SurfaceTriangles,
}

/// Why the checks before writing refused an output ([`crate::verify`],
/// [`crate::geometry::check`]).
#[derive(Clone, Debug, PartialEq)]
pub enum Refusal {
    /// The mesh check failed (`cell`: `"quad"` or `"hex"`).
    Invalid {
        /// The cell kind.
        cell: &'static str,
        /// The checker's errors.
        errors: Vec<String>,
    },
    /// Nodes found but every cell lost.
    LostCells {
        /// The nodes found.
        nodes: usize,
        /// The cell kind.
        cell: String,
    },
    /// No node although the map covers a grid cell.
    NoNode {
        /// The grid cells the map covers.
        measure: f64,
    },
    /// More components out than in.
    Components {
        /// The output's.
        output: usize,
        /// The input's.
        input: usize,
    },
    /// Another topology, under `--strict`.
    Topology(String),
    /// Sanitization leftovers, under `--strict`.
    Leftovers(String),
    /// Inverted elements left, under `--strict`.
    Inverted {
        /// How many.
        count: usize,
        /// The cell's name, one and many (`("quad", "quads")`).
        cell: (&'static str, &'static str),
        /// The geometric stage's mode.
        mode: &'static str,
    },
}

impl fmt::Display for Refusal {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Refusal::Invalid { cell, errors } => {
                write!(
                    f,
                    "could not make a valid {cell} mesh ({}); nothing written",
                    errors.join("; ")
                )?;
                if *cell == "quad" {
                    write!(f, " — please report this input")?;
                }
                Ok(())
            }
            Refusal::LostCells { nodes, cell } => write!(
                f,
                "empty output: {nodes} nodes found but no {cell} survived (all sides unmatched); nothing written"
            ),
            Refusal::NoNode { measure } => write!(
                f,
                "empty output: no node found although the map covers {measure:.3} grid cells (try --grid-offset); nothing written"
            ),
            Refusal::Components { output, input } => write!(
                f,
                "the output has {output} components, the input {input}: a wrong mesh; nothing written — please report this input"
            ),
            Refusal::Topology(what) => write!(
                f,
                "the output's topology differs from the input's: {what} (--strict); nothing written"
            ),
            Refusal::Leftovers(what) => write!(
                f,
                "sanitization left vertices on the dual grid ({what}) (--strict); nothing written"
            ),
            Refusal::Inverted { count, cell, mode } => write!(
                f,
                "{} (scaled Jacobian ≤ 0) {} after the geometric stage ({mode}); nothing written (--strict)",
                crate::summary::count(
                    *count,
                    &format!("inverted {}", cell.0),
                    &format!("inverted {}", cell.1)
                ),
                crate::summary::plural(*count, "remains", "remain"),
            ),
        }
    }
}

impl fmt::Display for CliError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use CliError as E;
        match self {
            E::Input(e) => write!(f, "{e}"),
            E::ReadSurface(e) => write!(f, "{e}"),
            E::EmbeddedMap(e) => write!(f, "embedded map: {e}"),
            E::Output(e) => write!(f, "{e}"),
            E::Stdout(e) => write!(f, "stdout: {e}"),
            E::TwoOutputs(p) => write!(f, "{}: named for two outputs", p.display()),
            E::Library { file, error } => write!(f, "{file}: {error}"),
            E::Render { file, error } => write!(f, "{file}: {error}"),
            E::Extrude { file, error } => write!(f, "{file}: {error}"),
            E::FromMesh { file, error } => write!(f, "{file}: {error}"),
            E::Refused { file, why } => write!(f, "{file}: {why}"),
            E::NotAMesh { file, what, ext } => write!(
                f,
                "{file}: {what} reads quad meshes (.obj, .ply, .vtk) and hex meshes (.mesh, .vtk), not `.{ext}`"
            ),
            E::Face {
                file,
                face,
                sides,
                need,
            } => match need {
                Need::Quads(what) => write!(
                    f,
                    "{file}: face {face} has {sides} vertices; {what} reads quad meshes (4 per face){}",
                    if *what == "inspect" {
                        " and triangle maps"
                    } else {
                        ""
                    }
                ),
                Need::FromMesh => write!(
                    f,
                    "{file}: face {face} has {sides} vertices; --from-mesh needs a quad mesh"
                ),
                Need::SurfaceTriangles => write!(
                    f,
                    "--surface: {file}: face {face} has {sides} vertices; the surface must be triangles"
                ),
            },
            E::Mesh { file, error } => write!(f, "{file}: {error}"),
            E::SurfaceRead(e) => write!(f, "--surface: {e}"),
            E::Surface { file, error } => write!(f, "--surface: {file}: {error}"),
            E::UnknownMap(name) => write!(f, "generate: unknown map {name:?} (see --list)"),
            E::Bug { what, reason } => write!(f, "bug: {what}{reason}"),
        }
    }
}

impl std::error::Error for CliError {}

impl From<dualex::map::InputError> for CliError {
    fn from(e: dualex::map::InputError) -> Self {
        CliError::Input(e)
    }
}

impl From<dualex::io::OutputError> for CliError {
    fn from(e: dualex::io::OutputError) -> Self {
        CliError::Output(e)
    }
}
