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
//! - [`Rounding::Greedy`]: in at most `rounds` batches of equally many
//!   independent integer unknowns, round the still-free ones closest to an
//!   integer first, re-solving after each batch (at most `rounds + 1`
//!   solves; `rounds` at least the number of independent integer
//!   unknowns rounds one at a time).
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
        let left = batches - round;
        let batch = next_batch(&el, integers, &mut done, &x, left, batches > 1);
        if batch.is_empty() {
            return Ok((x, report));
        }
        for (i, value) in batch {
            report.max_rounding = report.max_rounding.max((value - value.round()).abs());
            let mut row = integers[i].clone();
            row.constant -= value.round();
            fixed.push(row);
        }
    }
    Err("quantize: no solve".into())
}

/// The next integer unknowns to round, with their current values; marks
/// them (and the ones already
/// determined) `done`. Direct: every pending one, in order. Greedy: the
/// closest to an integer first, until `⌈independent / rounds_left⌉`
/// independent ones are taken (ties in order), so that `rounds_left = 1`
/// takes all and enough rounds make it one at a time.
fn next_batch(
    el: &Eliminator,
    integers: &[Form],
    done: &mut [bool],
    x: &[f64],
    rounds_left: usize,
    greedy: bool,
) -> Vec<(usize, f64)> {
    let mut pending: Vec<(f64, usize, f64)> = Vec::new();
    for (i, q) in integers.iter().enumerate() {
        if done[i] {
            continue;
        }
        if el.reduce(q.clone()).terms.is_empty() {
            done[i] = true;
            continue;
        }
        let value = q.eval(x);
        pending.push(((value - value.round()).abs(), i, value));
    }
    let rounded = |i: usize, value: f64| {
        let mut row = integers[i].clone();
        row.constant -= value.round();
        row
    };
    let mut limit = usize::MAX;
    if greedy {
        pending.sort_by(|a, b| a.0.total_cmp(&b.0).then(a.1.cmp(&b.1)));
        let mut trial = el.clone();
        let independent = pending
            .iter()
            .filter(|t| trial.add_row(rounded(t.1, t.2), TOLERANCE) == RowOutcome::Eliminated)
            .count();
        limit = independent.div_ceil(rounds_left.max(1));
    }
    let mut trial = el.clone();
    let mut batch = Vec::new();
    for &(_, i, value) in &pending {
        if limit == 0 {
            break;
        }
        done[i] = true;
        if trial.add_row(rounded(i, value), TOLERANCE) == RowOutcome::Eliminated {
            limit -= 1;
        }
        batch.push((i, value));
    }
    batch
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
