//! Progress on stderr: a spinner naming the current stage, shown only when
//! stderr is a terminal and the input is large enough to take over a second
//! (indicatif stays silent otherwise, so pipes and tests see nothing).

use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};
use std::io::IsTerminal;
use std::time::Duration;

/// Simplices above which extraction takes about a second here.
pub const LARGE: usize = 300_000;

/// A spinner, or nothing.
pub struct Progress(Option<ProgressBar>);

impl Progress {
    /// A spinner when `simplices` is large, stderr a terminal and not `quiet`.
    pub fn new(simplices: usize, quiet: bool) -> Self {
        if quiet || simplices < LARGE || !std::io::stderr().is_terminal() {
            return Progress(None);
        }
        let bar = ProgressBar::with_draw_target(None, ProgressDrawTarget::stderr());
        bar.set_style(
            ProgressStyle::with_template("{spinner} {elapsed} {msg}")
                .unwrap_or_else(|_| ProgressStyle::default_spinner()),
        );
        bar.enable_steady_tick(Duration::from_millis(100));
        Progress(Some(bar))
    }

    /// Names the current stage.
    pub fn stage(&self, msg: &str) {
        if let Some(b) = &self.0 {
            b.set_message(msg.to_string());
        }
    }
}

impl Drop for Progress {
    fn drop(&mut self) {
        if let Some(b) = &self.0 {
            b.finish_and_clear();
        }
    }
}
