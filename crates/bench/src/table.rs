//! The Markdown table of benchmark records (see [`dualex_bench::cases::run`]).

use serde_json::Value;

/// Stage names of both pipelines, in pipeline order.
const STAGES: [&str; 7] = [
    "map",
    "sanitize",
    "nodes",
    "trace",
    "untangle",
    "fairing",
    "glue_geometry",
];

/// Time of stage `name` in record `r`, in ms (`stats.time_ms.NAME`).
fn stage_ms(r: &Value, name: &str) -> Option<f64> {
    r["stats"]["time_ms"][name].as_f64()
}

fn num(r: &Value, key: &str) -> f64 {
    r[key].as_f64().unwrap_or(0.0)
}

/// Case name without the directory of a file case.
fn short(case: &str) -> &str {
    case.rsplit('/').next().unwrap_or(case)
}

/// One line per finished case, for the progress output.
pub fn progress(r: &Value) -> String {
    format!(
        "{}: {} simplices, {:.1} ms, {} cells",
        short(r["case"].as_str().unwrap_or("?")),
        r["simplices"],
        num(r, "extract_ms"),
        r["cells"]
    )
}

/// The table: one row per record.
pub fn markdown(records: &[Value]) -> String {
    let mut s = String::from(
        "| case | simplices | input ms | map | sanitize | nodes | trace | untangle | fairing | glue+geom | extract ms | k simplices/s | cells | peak MiB | B/simplex | hash |\n",
    );
    s.push_str(&"|---".repeat(16));
    s.push_str("|\n");
    for r in records {
        let n = num(r, "simplices");
        let ms = num(r, "extract_ms");
        let peak = num(r, "hwm_kib") * 1024.0;
        let stages: Vec<String> = STAGES
            .iter()
            .map(|st| stage_ms(r, st).map_or("–".to_string(), |v| format!("{v:.1}")))
            .collect();
        s.push_str(&format!(
            "| {} | {} | {:.1} | {} | {:.1} | {:.0} | {} | {:.1} | {:.0} | {} |\n",
            short(r["case"].as_str().unwrap_or("?")),
            n,
            num(r, "input_ms"),
            stages.join(" | "),
            ms,
            if ms > 0.0 { n / ms } else { 0.0 },
            r["cells"],
            peak / (1024.0 * 1024.0),
            if n > 0.0 { peak / n } else { 0.0 },
            r["hash"].as_str().unwrap_or("?"),
        ));
    }
    s
}

#[cfg(test)]
mod tests {
    use super::*;
    use serde_json::json;

    #[test]
    fn a_row_shows_throughput_and_bytes_per_simplex() {
        let r = json!({
            "case": "file:/a/b/x.obj", "simplices": 2000, "input_ms": 1.0,
            "extract_ms": 4.0, "stats": {"time_ms": {"map": 1.0, "nodes": 3.0}},
            "cells": 10, "hash": "ab", "hwm_kib": 4000,
        });
        let t = markdown(&[r]);
        let row = t.lines().nth(2).unwrap_or("");
        assert_eq!(
            row,
            "| x.obj | 2000 | 1.0 | 1.0 | – | 3.0 | – | – | – | – | 4.0 | 500 | 10 | 3.9 | 2048 | ab |"
        );
    }
}
