//! The whole-process laps (read, weld, extract, check, write) printed on
//! stderr with `-v`: the extraction stats time only the library's stages,
//! the benchmarks of issue 6 need the rest too.

pub use dualex_map::timing::Laps;

/// One line: `time (N threads): read 12.3 ms, …, total 78.9 ms`.
pub fn line(laps: &Laps) -> String {
    let mut parts: Vec<String> = laps
        .laps()
        .iter()
        .map(|(n, ms)| format!("{n} {ms:.1} ms"))
        .collect();
    parts.push(format!("total {:.1} ms", laps.total_ms()));
    format!(
        "time ({} threads): {}",
        rayon::current_num_threads(),
        parts.join(", ")
    )
}
