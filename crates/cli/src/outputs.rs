//! Outputs checked before any work, and the stats written.
//!
//! Every file a command will write is checked first
//! ([`dualex::io::check_output`]: extension, folder exists and takes a new
//! file), so a missing folder or a bad `--stats` path fails at once, with
//! nothing written, instead of after the extraction or after the mesh.
//! `--stats -` writes the JSON to stdout (the summary line is on stderr).

use crate::error::CliError;
use std::path::Path;

/// The path meaning stdout for `--stats`.
pub const STDOUT: &str = "-";

/// Checks `path` for a writer accepting `allowed` extensions (any
/// extension when `None`); `-` (stdout) passes.
pub fn check(path: &Path, allowed: Option<&'static [&'static str]>) -> Result<(), CliError> {
    if path.as_os_str() == STDOUT {
        return Ok(());
    }
    match allowed {
        Some(exts) => dualex::io::check_output(path, exts),
        None => dualex::io::check_writable(path),
    }
    .map_err(CliError::Output)
}

/// Checks every path of `outputs` (module docs); two outputs on one
/// file are refused too.
pub fn check_all(outputs: &[(&Path, Option<&'static [&'static str]>)]) -> Result<(), CliError> {
    for (k, (p, exts)) in outputs.iter().enumerate() {
        if outputs[..k].iter().any(|(q, _)| q == p) && p.as_os_str() != STDOUT {
            return Err(CliError::TwoOutputs(p.to_path_buf()));
        }
        check(p, *exts)?;
    }
    Ok(())
}

/// Writes the stats JSON to `path` (`-`: stdout).
pub fn write_stats(path: &Path, json: &serde_json::Value) -> Result<(), CliError> {
    let text = serde_json::to_string_pretty(json).map_err(|e| CliError::Bug {
        what: "stats: ",
        reason: e.to_string(),
    })?;
    if path.as_os_str() == STDOUT {
        use std::io::Write;
        let mut out = std::io::stdout().lock();
        return writeln!(out, "{text}")
            .and_then(|()| out.flush())
            .map_err(CliError::Stdout);
    }
    Ok(dualex::io::write_text(path, &text)?)
}

/// Writes PNG bytes to `path`.
pub fn write_png(path: &Path, png: &[u8]) -> Result<(), CliError> {
    Ok(dualex::io::write_bytes(path, png)?)
}
