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

/// The problem of `n` interior vertices (2D) or edges (3D) of valence
/// ≤ 2 (`one`, `many`: what they are), if any.
pub fn low_valence((n, one, many): (usize, &str, &str)) -> Option<String> {
    (n > 0).then(|| format!("{} of valence ≤ 2", count(n, one, many)))
}

/// The problem of `n` transitions rounded, if any (the last one named).
pub fn rounded(n: usize) -> Option<String> {
    (n > 0).then(|| format!("{} rounded", count(n, "transition", "transitions")))
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
