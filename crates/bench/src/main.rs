//! `dualex-bench`: scale benchmark of quad and hex extraction.
//!
//! `cargo run --release -p dualex-bench -- [--long] [--json] [CASE…]`
//!
//! Every case (see [`cases`]) runs in its own child process (this binary
//! with `--child CASE`), so that its peak memory is its own: the child
//! reads its `VmHWM` (peak resident set, whole process including the input
//! map) from `/proc/self/status`. The parent prints a Markdown table: per
//! case the input size, the time of every extraction stage (from the
//! extraction stats), the whole extraction, throughput, peak memory per
//! simplex, output cells and an output hash. Default sizes go up to ~300k
//! triangles / ~400k tets; `--long` adds ~1M and ~2M. Without CASE
//! arguments the generated cases run, then the shared data in
//! `../shared/data` when it exists.
#![forbid(unsafe_code)]
#![warn(missing_docs)]

use dualex_bench::cases;
mod table;

use serde_json::Value;
use std::path::Path;
use std::process::{Command, ExitCode};

const USAGE: &str = "usage: dualex-bench [--long] [--json] [--repeat N] [CASE...]\n\
       dualex-bench --write CASE PATH   (write the case's input map to a file)\n\
  --repeat N: run each case N times (default 3), keep the fastest run\n\
  CASE: KIND:SIZE (square, square_noise, torus, torus_fold: grid resolution;\n\
  block, block_noise: cells per side) or file:PATH (.obj / .hexex)";

fn main() -> ExitCode {
    let argv: Vec<String> = std::env::args().skip(1).collect();
    if let [flag, case] = &argv[..] {
        if flag == "--child" {
            return child(case);
        }
    }
    if let [flag, case, path] = &argv[..] {
        if flag == "--write" {
            return write(case, Path::new(path));
        }
    }
    let (mut long, mut json, mut named, mut repeat) = (false, false, Vec::new(), 3);
    let mut it = argv.iter();
    while let Some(a) = it.next() {
        match a.as_str() {
            "--repeat" => match it.next().and_then(|n| n.parse().ok()) {
                Some(n) if n > 0 => repeat = n,
                _ => {
                    eprintln!("dualex-bench: --repeat needs a positive count\n{USAGE}");
                    return ExitCode::from(2);
                }
            },
            "--long" => long = true,
            "--json" => json = true,
            "-h" | "--help" => {
                println!("{USAGE}");
                return ExitCode::SUCCESS;
            }
            s if s.starts_with('-') => {
                eprintln!("dualex-bench: unknown option {s:?}\n{USAGE}");
                return ExitCode::from(2);
            }
            s => named.push(s.to_string()),
        }
    }
    let list = if named.is_empty() {
        default_cases(long)
    } else {
        named
    };
    parent(&list, json, repeat)
}

/// Writes the input map of case `case` to `path` (`.obj`/`.ply` for a
/// triangle map, `.hexex` for a tet map), for timing the CLI as a process
/// (`tools/bench-cli`).
fn write(case: &str, path: &Path) -> ExitCode {
    let done = cases::build(case).and_then(|input| {
        match input {
            cases::Input::Tri(map) => dualex_io::write_tri_map(path, &map),
            cases::Input::Tet(map) => dualex_io::write_tet_map(path, &map),
        }
        .map_err(|e| e.to_string())
    });
    match done {
        Ok(()) => ExitCode::SUCCESS,
        Err(e) => {
            eprintln!("dualex-bench: {e}");
            ExitCode::from(1)
        }
    }
}

/// Runs one case in this process and prints its record as one JSON line.
fn child(case: &str) -> ExitCode {
    match cases::run(case) {
        Ok(r) => {
            println!("{r}");
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("dualex-bench: {e}");
            ExitCode::from(1)
        }
    }
}

/// The generated cases (4 sizes each, ≥ 100× apart), then the shared data.
fn default_cases(long: bool) -> Vec<String> {
    let mut sizes: Vec<(&str, Vec<usize>)> = vec![
        ("square", vec![30, 80, 200, 380]),
        ("square_noise", vec![30, 80, 200, 380]),
        ("torus", vec![45, 110, 280, 540]),
        ("torus_fold", vec![45, 110, 280, 540]),
        ("block", vec![6, 14, 26, 40]),
        ("block_noise", vec![6, 14, 26, 40]),
    ];
    if long {
        for (kind, s) in &mut sizes {
            s.extend(match *kind {
                "square" | "square_noise" => [710, 1000],
                "torus" | "torus_fold" => [1000, 1420],
                _ => [56, 70],
            });
        }
    }
    let mut out: Vec<String> = sizes
        .iter()
        .flat_map(|(k, s)| s.iter().map(move |n| format!("{k}:{n}")))
        .collect();
    let data = Path::new("../shared/data");
    for f in [
        "qex/fandisk_param.obj",
        "qex/duck_miq_4_param.obj",
        "directional/dragon-param-full-seamless.obj",
        "hexex/hand_q.hexex",
        "hexex/rockerarm_q.hexex",
        "hexex/fancy_ring.hexex",
    ] {
        let p = data.join(f);
        if p.exists() {
            out.push(format!("file:{}", p.display()));
        }
    }
    out
}

/// Runs `case` `repeat` times, each in a fresh child process; the record
/// of the fastest extraction (the machine is shared: the minimum is the
/// least disturbed run), `None` (reported) on failure.
fn run_child(exe: &Path, case: &str, repeat: usize) -> Option<Value> {
    let mut best: Option<Value> = None;
    for _ in 0..repeat {
        let rec = match Command::new(exe).args(["--child", case]).output() {
            Ok(o) if o.status.success() => serde_json::from_slice::<Value>(&o.stdout).ok(),
            Ok(o) => {
                eprintln!("{case}: {}", String::from_utf8_lossy(&o.stderr).trim());
                None
            }
            Err(e) => {
                eprintln!("{case}: cannot run: {e}");
                None
            }
        }?;
        let ms = |r: &Value| r["extract_ms"].as_f64().unwrap_or(f64::INFINITY);
        if best.as_ref().is_none_or(|b| ms(&rec) < ms(b)) {
            best = Some(rec);
        }
    }
    best
}

/// Runs every case in child processes and prints the table.
fn parent(list: &[String], json: bool, repeat: usize) -> ExitCode {
    let exe = match std::env::current_exe() {
        Ok(e) => e,
        Err(e) => {
            eprintln!("dualex-bench: cannot find own executable: {e}");
            return ExitCode::from(1);
        }
    };
    let mut records: Vec<Value> = Vec::new();
    let mut failed = false;
    for case in list {
        let rec = run_child(&exe, case, repeat);
        match rec {
            Some(r) => {
                if json {
                    println!("{r}");
                } else {
                    eprintln!("{}", table::progress(&r));
                }
                records.push(r);
            }
            None => failed = true,
        }
    }
    if !json {
        println!("{}", table::markdown(&records));
    }
    if failed {
        ExitCode::from(1)
    } else {
        ExitCode::SUCCESS
    }
}
