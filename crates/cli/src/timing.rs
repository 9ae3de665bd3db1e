//! Wall-clock laps of the whole process (read, weld, extract, check,
//! write), printed on stderr with `-v`: the extraction stats time only the
//! library's stages, the benchmarks of issue 6 need the rest too.

use std::time::Instant;

/// Laps since the process started its work.
pub struct Laps {
    start: Instant,
    last: Instant,
    laps: Vec<(&'static str, f64)>,
}

impl Laps {
    /// Starts the clock.
    pub fn start() -> Self {
        let now = Instant::now();
        Laps {
            start: now,
            last: now,
            laps: Vec::new(),
        }
    }

    /// Ends the lap `name` now.
    pub fn lap(&mut self, name: &'static str) {
        let now = Instant::now();
        self.laps
            .push((name, (now - self.last).as_secs_f64() * 1e3));
        self.last = now;
    }

    /// One line: `time: read 12.3 ms, extract 45.6 ms, …, total 78.9 ms`.
    pub fn line(&self) -> String {
        let mut parts: Vec<String> = self
            .laps
            .iter()
            .map(|(n, ms)| format!("{n} {ms:.1} ms"))
            .collect();
        let total = self.start.elapsed().as_secs_f64() * 1e3;
        parts.push(format!("total {total:.1} ms"));
        format!(
            "time ({} threads): {}",
            rayon::current_num_threads(),
            parts.join(", ")
        )
    }
}
