//! What the commands say on stderr: the summary line with the quality
//! problems left in the output, singular/plural wording, and the `-v`
//! table of stage times and counts.

use serde_json::Value;
use std::fmt::Write;

/// `one` or `many` by `n`.
pub fn plural<'a>(n: usize, one: &'a str, many: &'a str) -> &'a str {
    if n == 1 {
        one
    } else {
        many
    }
}

/// `"1 quad"`, `"2 quads"`.
pub fn count(n: usize, one: &str, many: &str) -> String {
    format!("{n} {}", plural(n, one, many))
}

/// Quality problems a quad output still has, from its stats (empty: none):
/// interior vertices of valence ≤ 2, a subdivision, dropped cells, open
/// holes, rounded transitions.
pub fn quad_problems(st: &dualex::steps::QuadReport) -> Vec<String> {
    let mut p = Vec::new();
    if st.quads == 0 {
        p.push("empty mesh: the map covers less than one grid cell".into());
    }
    let low: usize = st.valence_interior.range(..=2).map(|(_, n)| n).sum();
    if low > 0 {
        p.push(format!(
            "{} of valence ≤ 2",
            count(low, "interior vertex", "interior vertices")
        ));
    }
    if st.subdivided {
        p.push("subdivided once (quads could not represent the map)".into());
    }
    if st.repair_paths > 0 {
        p.push(format!(
            "repaired locally along {} (quads could not represent the map)",
            count(st.repair_paths, "path", "paths")
        ));
    }
    if st.repair_dropped > 0 {
        p.push(format!(
            "{} dropped",
            count(st.repair_dropped, "degenerate cell", "degenerate cells")
        ));
    }
    if st.holes_left_open > 0 {
        p.push(format!(
            "{} left open",
            count(st.holes_left_open, "hole", "holes")
        ));
    }
    rounded(&mut p, st.segment.snapped_transitions);
    p
}

/// The same for a hex output: interior edges of valence ≤ 2, open
/// interior faces, rounded transitions.
pub fn hex_problems(st: &dualex::steps::HexReport) -> Vec<String> {
    let mut p = Vec::new();
    let low: usize = st.edge_valence_interior.range(..=2).map(|(_, n)| n).sum();
    if low > 0 {
        p.push(format!(
            "{} of valence ≤ 2",
            count(low, "interior edge", "interior edges")
        ));
    }
    if st.columns.holes > 0 {
        p.push(format!(
            "repaired locally along {} of columns, {} split (hexes could not represent the map)",
            count(st.columns.paths, "path", "paths"),
            count(st.columns.split, "column", "columns"),
        ));
    }
    if st.open_interior_faces > 0 {
        p.push(format!(
            "{} left open",
            count(st.open_interior_faces, "interior face", "interior faces")
        ));
    }
    rounded(&mut p, st.segment.snapped_transitions);
    p
}

fn rounded(p: &mut Vec<String>, n: usize) {
    if n > 0 {
        p.push(format!("{} rounded", count(n, "transition", "transitions")));
    }
}

/// `"; check: a, b"` or nothing.
pub fn problems_suffix(p: &[String]) -> String {
    if p.is_empty() {
        String::new()
    } else {
        format!(" (check: {})", p.join(", "))
    }
}

/// The `-v` table: the process laps with the library's stages nested under
/// `extract`, then one line of non-zero counts per stats section.
pub fn verbose_table(
    laps: &[(String, f64)],
    stages: &[(String, f64)],
    total: f64,
    json: &Value,
) -> String {
    let mut s = String::new();
    let threads = rayon::current_num_threads();
    let _ = writeln!(
        s,
        "{:<22}{:>10}   ({})",
        "stage",
        "ms",
        count(threads, "thread", "threads")
    );
    for (name, ms) in laps {
        let _ = writeln!(s, "{name:<22}{ms:>10.1}");
        if name == "extract" {
            for (n, ms) in stages {
                let _ = writeln!(s, "  {n:<20}{ms:>10.1}");
            }
        }
    }
    let _ = writeln!(s, "{:<22}{total:>10.1}", "total");
    if let Some(obj) = json.as_object() {
        for (section, v) in obj {
            if section == "time_ms" {
                continue;
            }
            let line = counts_line(v);
            if !line.is_empty() {
                let _ = writeln!(s, "{section:<22} {line}");
            }
        }
    }
    s.trim_end().to_string()
}

/// Non-zero scalars of `v` as `key value`, nested objects as
/// `key{…}`; a scalar alone as itself.
fn counts_line(v: &Value) -> String {
    match v {
        Value::Object(o) => o
            .iter()
            .filter_map(|(k, v)| {
                let t = match v {
                    Value::Object(_) => {
                        let inner = counts_line(v);
                        (!inner.is_empty()).then(|| format!("{{{inner}}}"))
                    }
                    _ => scalar(v),
                };
                t.map(|t| format!("{k} {t}"))
            })
            .collect::<Vec<_>>()
            .join(", "),
        _ => scalar(v).unwrap_or_default(),
    }
}

fn scalar(v: &Value) -> Option<String> {
    match v {
        Value::Number(n) if n.as_f64() == Some(0.0) => None,
        Value::Number(n) => Some(match n.as_f64() {
            Some(x) if n.is_f64() => format!("{x:.3e}"),
            _ => n.to_string(),
        }),
        Value::Bool(true) => Some("yes".into()),
        Value::String(s) => Some(s.clone()),
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wording_and_tables() {
        assert_eq!(count(1, "thread", "threads"), "1 thread");
        assert_eq!(count(2, "hex", "hexes"), "2 hexes");
        let json = serde_json::json!({"input": {"triangles": 8, "reverted": 0, "x": 0.5},
                                      "output": {"valence": {"3": 2, "4": 0}}, "time_ms": {"a": 1.0}});
        let t = verbose_table(
            &[("read".into(), 1.0), ("extract".into(), 2.0)],
            &[("nodes".into(), 1.5)],
            3.0,
            &json,
        );
        assert!(t.contains("  nodes"), "{t}");
        assert!(t.contains("triangles 8, x 5.000e-1"), "{t}");
        assert!(t.contains("valence {3 2}"), "{t}");
        assert!(!t.contains("reverted"), "{t}");
    }
}
