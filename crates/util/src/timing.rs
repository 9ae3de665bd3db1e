//! Wall-clock laps: the per-stage `time_ms` of the extraction stats and
//! the whole-process laps of the CLI's `-v`.

use std::time::Instant;

/// Named laps since a start.
#[derive(Clone, Debug)]
pub struct Laps {
    start: Instant,
    last: Instant,
    laps: Vec<(String, f64)>,
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
    pub fn lap(&mut self, name: &str) {
        let now = Instant::now();
        let ms = (now - self.last).as_secs_f64() * 1e3;
        self.laps.push((name.to_string(), ms));
        self.last = now;
    }

    /// The laps so far: (name, milliseconds).
    pub fn laps(&self) -> &[(String, f64)] {
        &self.laps
    }

    /// Milliseconds since the start.
    pub fn total_ms(&self) -> f64 {
        self.start.elapsed().as_secs_f64() * 1e3
    }

    /// The laps, taken.
    pub fn into_laps(self) -> Vec<(String, f64)> {
        self.laps
    }
}
