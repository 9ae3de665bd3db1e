//! Step 4: tracing the sides of every node along its iso-line — the
//! dimension-generic [`dualex_segment::trace`] at D = 2 (4 sides a node).

pub use dualex_segment::trace::{trace_all, TraceReport};

/// How a walk ended.
pub type End = dualex_segment::trace::End<2>;
