//! `dualex-tetra SURFACE -o OUT.hexex [--scale S] [--offset X,Y,Z] [--noise A] [--seed N]`:
//! tetrahedralizes the volume inside a closed triangle surface (OBJ or PLY)
//! with TetGen and puts a scaled, optionally noisy identity map on it — real
//! shapes for `dualex hex` with free boundaries. Wrapped by `tools/tetra-identity`.
#![forbid(unsafe_code)]

use std::path::PathBuf;
use std::process::ExitCode;

const USAGE: &str = "usage: dualex-tetra SURFACE.obj -o OUT.hexex [--scale S] [--offset X,Y,Z] [--noise A] [--seed N]";

/// Why `dualex-tetra` failed: one line naming the option, or the file
/// and the element.
#[derive(Debug)]
enum TetraError {
    /// An option without its value.
    NeedsValue(String),
    /// An option's value is not a number.
    NotANumber {
        /// The option.
        option: String,
        /// Its value.
        value: String,
    },
    /// `--seed` is not an integer.
    Seed,
    /// `--offset` is not `X,Y,Z`.
    Offset(String),
    /// An option this tool does not have.
    Unknown(String),
    /// SURFACE or `-o` missing.
    Usage,
    /// The surface could not be read.
    Input(dualex::map::InputError),
    /// A face of the surface is not a triangle.
    Face {
        /// The surface.
        file: String,
        /// The face.
        face: usize,
        /// Its vertices.
        sides: usize,
    },
    /// TetGen or the identity map failed.
    Extrude {
        /// The surface.
        file: String,
        /// Why.
        error: dualex::extrude::ExtrudeError,
    },
    /// The map could not be written.
    Output(dualex::io::OutputError),
}

impl std::fmt::Display for TetraError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            TetraError::NeedsValue(a) => write!(f, "{a} needs a value; {USAGE}"),
            TetraError::NotANumber { option, value } => {
                write!(f, "{option}: not a number: {value}")
            }
            TetraError::Seed => write!(f, "--seed: not an integer"),
            TetraError::Offset(v) => write!(f, "--offset: want X,Y,Z, got {v}"),
            TetraError::Unknown(s) => write!(f, "unknown option {s}; {USAGE}"),
            TetraError::Usage => write!(f, "{USAGE}"),
            TetraError::Input(e) => write!(f, "{e}"),
            TetraError::Face { file, face, sides } => write!(
                f,
                "{file}: face {face} has {sides} vertices; a triangle surface is needed"
            ),
            TetraError::Extrude { file, error } => write!(f, "{file}: {error}"),
            TetraError::Output(e) => write!(f, "{e}"),
        }
    }
}

/// The command line read: SURFACE, `-o`, the map's options; `None` for
/// `--help`.
type Parsed = Option<(PathBuf, PathBuf, dualex::extrude::volume::IdentityOptions)>;

/// Reads the command line (module docs).
fn parse(argv: &[String]) -> Result<Parsed, TetraError> {
    let (mut input, mut output) = (None::<PathBuf>, None::<PathBuf>);
    let mut opts = dualex::extrude::volume::IdentityOptions {
        scale: 1.0,
        offset: [0.0; 3],
        noise: 0.0,
        seed: 1,
    };
    let mut it = argv.iter();
    while let Some(a) = it.next() {
        let mut val = || it.next().cloned().ok_or(TetraError::NeedsValue(a.clone()));
        let num = |s: String| {
            s.parse::<f64>().map_err(|_| TetraError::NotANumber {
                option: a.clone(),
                value: s,
            })
        };
        match a.as_str() {
            "-o" => output = Some(val()?.into()),
            "--scale" => opts.scale = num(val()?)?,
            "--noise" => opts.noise = num(val()?)?,
            "--seed" => opts.seed = val()?.parse().map_err(|_| TetraError::Seed)?,
            "--offset" => {
                let v = val()?;
                let parts: Result<Vec<f64>, _> =
                    v.split(',').map(|x| x.trim().parse::<f64>()).collect();
                match parts.as_deref() {
                    Ok(&[x, y, z]) => opts.offset = [x, y, z],
                    _ => return Err(TetraError::Offset(v)),
                }
            }
            "-h" | "--help" => return Ok(None),
            s if s.starts_with('-') => return Err(TetraError::Unknown(s.to_string())),
            s => input = Some(s.into()),
        }
    }
    let input = input.ok_or(TetraError::Usage)?;
    let output = output.ok_or(TetraError::Usage)?;
    Ok(Some((input, output, opts)))
}

/// Runs the command line; the line to print on success.
fn run(argv: &[String]) -> Result<String, TetraError> {
    let Some((input, output, opts)) = parse(argv)? else {
        return Ok(USAGE.into());
    };
    let name = input.display().to_string();
    let poly = dualex::io::read_polygon_mesh(&input).map_err(TetraError::Input)?;
    let mut tris = Vec::with_capacity(poly.faces.len());
    for (i, f) in poly.faces.iter().enumerate() {
        let [a, b, c] = f[..] else {
            return Err(TetraError::Face {
                file: name,
                face: i,
                sides: f.len(),
            });
        };
        tris.push([a, b, c]);
    }
    let program: PathBuf = std::env::var_os("DUALEX_TETGEN").map_or("tetgen".into(), Into::into);
    let map =
        dualex::extrude::volume::tetrahedralize_identity(&poly.positions, &tris, &opts, &program)
            .map_err(|error| TetraError::Extrude {
            file: name.clone(),
            error,
        })?;
    dualex::io::write_tet_map(&output, &map).map_err(TetraError::Output)?;
    Ok(format!(
        "{name}: {} tets, {} vertices -> {}",
        map.len(),
        map.positions.len(),
        output.display()
    ))
}

fn main() -> ExitCode {
    let argv: Vec<String> = std::env::args().skip(1).collect();
    match run(&argv) {
        Ok(msg) => {
            println!("{msg}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("dualex-tetra: {}", e.to_string().replace('\n', " "));
            ExitCode::from(1)
        }
    }
}
