//! Outputs checked before any work, and the stats written.
//!
//! Every file a command will write is checked first
//! ([`dualex_io::check_output`]: extension, folder exists and takes a new
//! file), so a missing folder or a bad `--stats` path fails at once, with
//! nothing written, instead of after the extraction or after the mesh.
//! `--stats -` writes the JSON to stdout (the summary line is on stderr).

use std::path::Path;

/// The path meaning stdout for `--stats`.
pub const STDOUT: &str = "-";

/// Checks `path` for a writer accepting `allowed` extensions (any
/// extension when `None`); `-` (stdout) passes.
pub fn check(path: &Path, allowed: Option<&'static [&'static str]>) -> Result<(), String> {
    if path.as_os_str() == STDOUT {
        return Ok(());
    }
    match allowed {
        Some(exts) => dualex_io::check_output(path, exts),
        None => dualex_io::check_writable(path),
    }
    .map_err(|e| e.to_string())
}

/// Checks every path of `outputs` (module docs); two outputs on one
/// file are refused too.
pub fn check_all(outputs: &[(&Path, Option<&'static [&'static str]>)]) -> Result<(), String> {
    for (k, (p, exts)) in outputs.iter().enumerate() {
        if outputs[..k].iter().any(|(q, _)| q == p) && p.as_os_str() != STDOUT {
            return Err(format!("{}: named for two outputs", p.display()));
        }
        check(p, *exts)?;
    }
    Ok(())
}

/// Writes the stats JSON to `path` (`-`: stdout).
pub fn write_stats(path: &Path, json: &serde_json::Value) -> Result<(), String> {
    let text = serde_json::to_string_pretty(json).map_err(|e| format!("bug: stats: {e}"))?;
    if path.as_os_str() == STDOUT {
        use std::io::Write;
        let mut out = std::io::stdout().lock();
        return writeln!(out, "{text}")
            .and_then(|()| out.flush())
            .map_err(|e| format!("stdout: {e}"));
    }
    dualex_io::write_text(path, &text).map_err(|e| e.to_string())
}

/// Writes PNG bytes to `path`.
pub fn write_png(path: &Path, png: &[u8]) -> Result<(), String> {
    dualex_io::write_bytes(path, png).map_err(|e| e.to_string())
}
