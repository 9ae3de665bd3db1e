//! Quantization: the integer unknowns rounded, the map solved again.
//!
//! Input: the integration [`Energy`], the rows always imposed, the
//! [`Gauge`] (imposed last, where still free), and the integer unknowns as forms over the map's unknowns (singular wedges'
//! coordinates, boundary iso-values, seam translations). Output: the
//! map's unknowns and a [`QuantizeReport`].
//!
//! - [`Rounding::Continuous`]: one solve, nothing rounded (a seamless map
//!   off the grid).
//! - [`Rounding::Direct`]: solve, round **every** integer unknown at once
//!   to its nearest integer, solve once more (two solves).
//! - [`Rounding::Greedy`]: in `rounds` batches, round the still-free
//!   integer unknowns closest to an integer first, re-solving between
//!   batches (`rounds + 1` solves).
//!
//! Integer unknowns are rounded in their order (singular first): one that
//! already follows from earlier ones is skipped (it is an integer
//! combination of integers when the seams are consistent); one that
//! contradicts them is counted in [`QuantizeReport::conflicts`] and not
//! imposed.

use crate::integrate::constraints::Gauge;
use crate::integrate::elim::{Eliminator, Form, RowOutcome};
use crate::integrate::system::{minimize, Energy};

/// How the integer unknowns are rounded (module docs).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Rounding {
    /// Nothing rounded.
    Continuous,
    /// All at once, then one more solve.
    Direct,
    /// In this many batches, closest to an integer first.
    Greedy {
        /// Number of batches (at least 1).
        rounds: usize,
    },
}

/// What the quantization did.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct QuantizeReport {
    /// Integer unknowns offered (with repeats along seam chains).
    pub integer_unknowns: usize,
    /// Independent integer unknowns imposed.
    pub rounded: usize,
    /// Integer unknowns that contradicted earlier ones (not imposed).
    pub conflicts: usize,
    /// Largest distance moved by a rounding.
    pub max_rounding: f64,
    /// Sparse solves.
    pub solves: usize,
}

/// Agreement asked of a redundant row.
const TOLERANCE: f64 = 1e-6;

/// Runs the quantization (module docs).
pub fn quantize(
    energy: &Energy,
    rows: &[Form],
    gauge: &Gauge,
    integers: &[Form],
    rounding: Rounding,
) -> Result<(Vec<f64>, QuantizeReport), String> {
    let n = energy.b.len();
    let mut report = QuantizeReport {
        integer_unknowns: integers.len(),
        ..QuantizeReport::default()
    };
    let mut fixed: Vec<Form> = Vec::new();
    let mut done = vec![false; integers.len()];
    let batches = match rounding {
        Rounding::Continuous => 0,
        Rounding::Direct => 1,
        Rounding::Greedy { rounds } => rounds.max(1),
    };
    for round in 0..=batches {
        let el = eliminate(n, rows, &fixed, &mut report);
        let mut gauged = el.clone();
        for g in gauge.rows(rows.iter().chain(&fixed)) {
            gauged.add_row(g, f64::INFINITY);
        }
        let (p, free) = gauged.finish();
        let x = minimize(energy, &p, free)?;
        report.solves += 1;
        if round == batches {
            return Ok((x, report));
        }
        // the still-free integer unknowns, closest to an integer first
        let mut pending: Vec<(f64, usize, f64)> = Vec::new();
        for (i, q) in integers.iter().enumerate() {
            if done[i] {
                continue;
            }
            if el.reduce(q.clone()).terms.is_empty() {
                done[i] = true;
                continue;
            }
            let value = q.eval(&x);
            pending.push(((value - value.round()).abs(), i, value));
        }
        if batches > 1 {
            pending.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        }
        let take = pending.len().div_ceil(batches - round);
        let mut batch: Vec<(usize, f64)> = pending[..take].iter().map(|t| (t.1, t.2)).collect();
        batch.sort_by_key(|t| t.0);
        for (i, value) in batch {
            done[i] = true;
            let mut row = integers[i].clone();
            row.constant -= value.round();
            report.max_rounding = report.max_rounding.max((value - value.round()).abs());
            fixed.push(row);
        }
    }
    Err("quantize: no solve".into())
}

/// The rows, then the rounded integer unknowns, eliminated (the gauge
/// comes after, in [`quantize`]).
fn eliminate(n: usize, rows: &[Form], fixed: &[Form], report: &mut QuantizeReport) -> Eliminator {
    let mut el = Eliminator::new(n);
    for r in rows {
        el.add_row(r.clone(), TOLERANCE);
    }
    report.rounded = 0;
    report.conflicts = 0;
    for r in fixed {
        match el.add_row(r.clone(), TOLERANCE) {
            RowOutcome::Eliminated => report.rounded += 1,
            RowOutcome::Redundant => {}
            RowOutcome::Conflict(_) => report.conflicts += 1,
        }
    }
    el
}
