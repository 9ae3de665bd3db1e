//! `dualex-tetra SURFACE -o OUT.hexex [--scale S] [--offset X,Y,Z] [--noise A] [--seed N]`:
//! tetrahedralizes the volume inside a closed triangle surface (OBJ or PLY)
//! with TetGen and puts a scaled, optionally noisy identity map on it — real
//! shapes for `dualex hex` with free boundaries. Wrapped by `tools/tetra-identity`.
#![forbid(unsafe_code)]

use std::path::PathBuf;
use std::process::ExitCode;

const USAGE: &str = "usage: dualex-tetra SURFACE.obj -o OUT.hexex [--scale S] [--offset X,Y,Z] [--noise A] [--seed N]";

fn run(argv: &[String]) -> Result<String, String> {
    let (mut input, mut output) = (None::<PathBuf>, None::<PathBuf>);
    let mut opts = dualex_extrude::volume::IdentityOptions {
        scale: 1.0,
        offset: [0.0; 3],
        noise: 0.0,
        seed: 1,
    };
    let mut it = argv.iter();
    while let Some(a) = it.next() {
        let mut val = || {
            it.next()
                .cloned()
                .ok_or_else(|| format!("{a} needs a value; {USAGE}"))
        };
        let num = |s: String| {
            s.parse::<f64>()
                .map_err(|_| format!("{a}: not a number: {s}"))
        };
        match a.as_str() {
            "-o" => output = Some(val()?.into()),
            "--scale" => opts.scale = num(val()?)?,
            "--noise" => opts.noise = num(val()?)?,
            "--seed" => {
                opts.seed = val()?
                    .parse()
                    .map_err(|_| "--seed: not an integer".to_string())?
            }
            "--offset" => {
                let v = val()?;
                let parts: Vec<f64> = v
                    .split(',')
                    .map(|x| x.trim().parse::<f64>())
                    .collect::<Result<_, _>>()
                    .map_err(|_| format!("--offset: want X,Y,Z, got {v}"))?;
                let [x, y, z] = parts[..] else {
                    return Err(format!("--offset: want X,Y,Z, got {v}"));
                };
                opts.offset = [x, y, z];
            }
            "-h" | "--help" => return Ok(USAGE.into()),
            s if s.starts_with('-') => return Err(format!("unknown option {s}; {USAGE}")),
            s => input = Some(s.into()),
        }
    }
    let input = input.ok_or(USAGE)?;
    let output = output.ok_or(USAGE)?;
    let name = input.display().to_string();
    let poly = dualex_io::read_polygon_mesh(&input).map_err(|e| e.to_string())?;
    let mut tris = Vec::with_capacity(poly.faces.len());
    for (i, f) in poly.faces.iter().enumerate() {
        let [a, b, c] = f[..] else {
            return Err(format!(
                "{name}: face {i} has {} vertices; a triangle surface is needed",
                f.len()
            ));
        };
        tris.push([a, b, c]);
    }
    let program: PathBuf = std::env::var_os("DUALEX_TETGEN").map_or("tetgen".into(), Into::into);
    let map =
        dualex_extrude::volume::tetrahedralize_identity(&poly.positions, &tris, &opts, &program)
            .map_err(|e| format!("{name}: {e}"))?;
    dualex_io::write_tet_map(&output, &map).map_err(|e| e.to_string())?;
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
            eprintln!("dualex-tetra: {}", e.replace('\n', " "));
            ExitCode::from(1)
        }
    }
}
