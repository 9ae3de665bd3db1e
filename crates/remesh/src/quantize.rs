//! Quantization: the integer unknowns rounded, the map solved again.
//!
//! Input: the integration [`Energy`], the rows always imposed, the
//! [`Gauge`] (imposed last, where still free), and the integer unknowns as
//! forms over the map's unknowns, the first `first` of them (the
//! coordinates of one wedge per singular vertex) to be rounded before the
//! rest (boundary
//! iso-values, seam translations). Output: the map's unknowns and a
//! [`QuantizeReport`].
//!
//! - [`Rounding::Continuous`]: one solve, nothing rounded (a seamless map
//!   off the grid).
//! - [`Rounding::Direct`]: solve, round **every** integer unknown at once
//!   to its nearest integer, solve once more (two solves).
//! - [`Rounding::Greedy`]: in at most `rounds` batches of equally many
//!   independent integer unknowns, round the still-free ones closest to an
//!   integer first (the first `first` before the others), re-solving after
//!   each batch (at most `rounds + 1` solves; `rounds` at least the number
//!   of independent integer unknowns rounds one at a time).
//!
//! Why singular vertices first: a singular vertex `S` is the fixed point
//! of a quarter or half turn composed with translations, `(I − M)·S =`
//! (integer combination of translations); `S` on an integer point makes
//! that combination an integer, while integer translations rounded first
//! may put `S` only on the half-integer lattice. One wedge per singular
//! vertex: its other wedges follow from it and the translations, and
//! rounding them on their own could break the parity that `(I − M)`
//! asks of the translations.
//!
//! An integer unknown that already follows from earlier ones is not
//! imposed; if it follows as a non-integer it is counted in
//! [`QuantizeReport::conflicts`].

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
    /// Integer unknowns that followed from earlier ones as non-integers.
    pub conflicts: usize,
    /// Integer unknowns whose final value is off the integers by more
    /// than 10⁻⁶ (0 for a consistent input when rounding).
    pub off_grid: usize,
    /// Largest distance moved by a rounding.
    pub max_rounding: f64,
    /// Sparse solves (in [`crate::integrate::IntegrateReport`]: of the
    /// whole integration, area fit and re-roundings included).
    pub solves: usize,
}

/// Agreement asked of a redundant row.
const TOLERANCE: f64 = 1e-6;

/// Runs the quantization (module docs). `start`, when given, is the
/// continuous minimizer already known (the caller's business to be
/// right): the first solve is skipped.
pub fn quantize(
    energy: &Energy,
    rows: &[Form],
    gauge: &Gauge,
    integers: &[Form],
    first: usize,
    rounding: Rounding,
    start: Option<Vec<f64>>,
) -> Result<(Vec<f64>, QuantizeReport), String> {
    let mut start = start;
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
    let mut round = 0;
    loop {
        let el = eliminate(n, rows, &fixed, &mut report);
        let x = match start.take() {
            Some(x) if x.len() == n => x,
            _ => {
                let mut gauged = el.clone();
                for g in gauge.rows(rows.iter().chain(&fixed)) {
                    gauged.add_row(g, f64::INFINITY);
                }
                let (p, free) = gauged.finish();
                report.solves += 1;
                minimize(energy, &p, free)?
            }
        };
        let batch = if round < batches {
            let pending = Pending {
                el: &el,
                integers,
                first,
            };
            pending.next_batch(&mut done, &x, batches - round, batches > 1)
        } else {
            Vec::new()
        };
        if batch.is_empty() {
            if batches > 0 {
                report.off_grid = integers
                    .iter()
                    .filter(|q| {
                        let v = q.eval(&x);
                        (v - v.round()).abs() > TOLERANCE
                    })
                    .count();
            }
            return Ok((x, report));
        }
        for (i, value) in batch {
            report.max_rounding = report.max_rounding.max((value - value.round()).abs());
            let mut row = integers[i].clone();
            row.constant -= value.round();
            fixed.push(row);
        }
        round += 1;
    }
}

/// The integer unknowns not yet rounded, against the eliminations so far.
struct Pending<'a> {
    el: &'a Eliminator,
    integers: &'a [Form],
    first: usize,
}

impl Pending<'_> {
    /// The next integer unknowns to round, with their current values;
    /// marks them (and the ones already determined) `done`. Direct: every
    /// pending one, in order. Greedy: by priority, then closest to an
    /// integer first, until `⌈independent / rounds_left⌉` independent
    /// ones are taken, so that `rounds_left = 1` takes all and enough
    /// rounds make it one at a time.
    fn next_batch(
        &self,
        done: &mut [bool],
        x: &[f64],
        rounds_left: usize,
        greedy: bool,
    ) -> Vec<(usize, f64)> {
        let mut pending: Vec<(bool, f64, usize, f64)> = Vec::new();
        for (i, q) in self.integers.iter().enumerate() {
            if done[i] {
                continue;
            }
            if self.el.reduce(q.clone()).terms.is_empty() {
                done[i] = true;
                continue;
            }
            let value = q.eval(x);
            pending.push((i >= self.first, (value - value.round()).abs(), i, value));
        }
        let rounded = |i: usize, value: f64| {
            let mut row = self.integers[i].clone();
            row.constant -= value.round();
            row
        };
        let mut limit = usize::MAX;
        if greedy {
            pending.sort_by(|a, b| {
                (a.0, a.1, a.2)
                    .partial_cmp(&(b.0, b.1, b.2))
                    .unwrap_or(std::cmp::Ordering::Equal)
            });
            let mut trial = self.el.clone();
            let independent = pending
                .iter()
                .filter(|t| trial.add_row(rounded(t.2, t.3), TOLERANCE) == RowOutcome::Eliminated)
                .count();
            limit = independent.div_ceil(rounds_left.max(1));
        }
        let mut trial = self.el.clone();
        let mut batch = Vec::new();
        for &(_, _, i, value) in &pending {
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
            // it follows as `rounding + c`: a conflict unless c is whole
            RowOutcome::Conflict(c) => {
                if (c - c.round()).abs() > TOLERANCE {
                    report.conflicts += 1;
                }
            }
        }
    }
    el
}
