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
//! imposed; if it follows as a non-integer it is a conflict.
//!
//! **Conflicts.** Singular vertices rounded one by one to integer points
//! do not always agree: each fixes the translations around it up to the
//! sublattice `(I − M)·ℤ²` (of index 2 for a quarter turn), and around a
//! handle a translation can follow from several of them as a
//! half-integer (issue 23: the smoothed genus-7 plate at 5000 quads, seed
//! 1, left 84 integer unknowns at ½ — translations of seams with no
//! rotation along the handle loops — and the extraction refused the map:
//! `the transition … is not integral (residual 0.5)`). A map with a
//! translation off the integers is not grid-preserving, while a singular
//! vertex off the grid only costs the extraction a local repair. So each
//! conflict is traced back to the rounded unknowns it follows from
//! ([`trace_conflicts`]), and one singular coordinate it depends on by a
//! fraction is left free (not rounded; [`QuantizeReport::freed`]), until
//! no conflict is left or none can be traced to a singular vertex (those
//! stay counted in [`QuantizeReport::conflicts`]). Maps without a
//! conflict are not touched.
//!
//! **Facing walls.** Boundary iso-values of walls facing each other across
//! a strip narrower than a unit would round to one integer and lose the
//! strip (issue 23: holes merged); each batch's targets are directed so
//! that such walls end at least 1 apart ([`crate::separate`]). When that
//! leaves more conflicts than the nearest rounding, the nearest rounding
//! is kept ([`QuantizeReport::walls_moved`] then 0).

use crate::error::SolveError;
use crate::integrate::constraints::Gauge;
use crate::integrate::elim::{Eliminator, Form, RowOutcome};
use crate::integrate::system::{minimize, Energy};
use crate::separate::Apart;

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
    /// Singular coordinates left free to resolve conflicts (module docs).
    pub freed: usize,
    /// Integer unknowns whose final value is off the integers by more
    /// than 10⁻⁶ (0 for a consistent input when rounding).
    pub off_grid: usize,
    /// Boundary walls moved off their nearest integer to keep a strip
    /// between facing walls ([`crate::separate`]; 0 when that made a
    /// conflict and the nearest rounding was kept).
    pub walls_moved: usize,
    /// Largest distance moved by a rounding.
    pub max_rounding: f64,
    /// Sparse solves (in [`crate::integrate::IntegrateReport`]: of the
    /// whole integration, area fit and re-roundings included).
    pub solves: usize,
}

/// The integer unknowns of [`quantize`]: forms over the map's unknowns,
/// the first `first` rounded before the others (module docs), and the
/// facing boundary walls to round apart.
#[derive(Clone, Copy, Debug)]
pub struct Integers<'a> {
    /// The integer unknowns.
    pub forms: &'a [Form],
    /// How many come first (singular coordinates).
    pub first: usize,
    /// Facing walls ([`crate::separate`]).
    pub apart: Apart<'a>,
}

impl<'a> Integers<'a> {
    /// `forms`, the first `first` first, no walls.
    pub fn new(forms: &'a [Form], first: usize) -> Self {
        Integers {
            forms,
            first,
            apart: Apart::default(),
        }
    }
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
    integers: &Integers,
    rounding: Rounding,
    start: Option<Vec<f64>>,
) -> Result<(Vec<f64>, QuantizeReport), SolveError> {
    let system = (energy, rows, gauge);
    let separated = round(system, integers, rounding, start.clone())?;
    if separated.1.conflicts == 0 || separated.1.walls_moved == 0 {
        return Ok(separated);
    }
    // the walls moved apart made a conflict the trace did not resolve:
    // the nearest rounding instead
    let plain = Integers {
        apart: Apart::default(),
        ..*integers
    };
    let (x, mut report) = round(system, &plain, rounding, start)?;
    if report.conflicts >= separated.1.conflicts {
        let (x, mut kept) = separated;
        kept.solves += report.solves;
        return Ok((x, kept));
    }
    report.solves += separated.1.solves;
    Ok((x, report))
}

/// [`quantize`] of `(energy, rows, gauge)` with the walls of
/// `integers.apart` moved apart as asked.
fn round(
    (energy, rows, gauge): (&Energy, &[Form], &Gauge),
    integers: &Integers,
    rounding: Rounding,
    start: Option<Vec<f64>>,
) -> Result<(Vec<f64>, QuantizeReport), SolveError> {
    let Integers {
        forms: integers,
        first,
        apart,
    } = *integers;
    let mut start = start;
    let n = energy.b.len();
    let mut report = QuantizeReport {
        integer_unknowns: integers.len(),
        ..QuantizeReport::default()
    };
    let mut fixed: Vec<Form> = Vec::new();
    // per row of `fixed`: the integer unknown it rounds
    let mut fixed_ids: Vec<usize> = Vec::new();
    let mut done = vec![false; integers.len()];
    let batches = match rounding {
        Rounding::Continuous => 0,
        Rounding::Direct => 1,
        Rounding::Greedy { rounds } => rounds.max(1),
    };
    let mut round = 0;
    loop {
        let mut el = eliminate(n, rows, &fixed, &mut report);
        while report.conflicts > 0 {
            let free = trace_conflicts(n, rows, &fixed, &fixed_ids, first);
            if free.is_empty() {
                break;
            }
            report.freed += free.len();
            let keep = |k: &usize| !free.contains(k);
            fixed = (0..fixed.len())
                .filter(keep)
                .map(|k| fixed[k].clone())
                .collect();
            fixed_ids = (0..fixed_ids.len())
                .filter(keep)
                .map(|k| fixed_ids[k])
                .collect();
            el = eliminate(n, rows, &fixed, &mut report);
        }
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
        let mut batch: Vec<(usize, f64, f64)> =
            batch.into_iter().map(|(i, v)| (i, v, v.round())).collect();
        if !apart.pairs.is_empty() {
            let before: Vec<(usize, f64)> = fixed_ids
                .iter()
                .map(|&i| (i, integers[i].eval(&x)))
                .collect();
            report.walls_moved += apart.separate(&mut batch, &before);
        }
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
        for (i, value, target) in batch {
            report.max_rounding = report.max_rounding.max((value - target).abs());
            let mut row = integers[i].clone();
            row.constant -= target;
            fixed.push(row);
            fixed_ids.push(i);
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

/// The rows of `fixed` (rounded integer unknowns, `ids` the unknowns'
/// indices) to leave free so that the conflicts go (module docs): per
/// conflict that follows from none of those already chosen with a
/// fractional coefficient, the first singular one (index below `first`)
/// it follows from so. Each rounded row `k` gets a
/// parameter `z_k` (unknown `n + k`, never eliminated), `row_k − z_k = 0`:
/// a dependent row reduces to `Σ α_k·z_k + c`, its dependencies.
fn trace_conflicts(
    n: usize,
    rows: &[Form],
    fixed: &[Form],
    ids: &[usize],
    first: usize,
) -> Vec<usize> {
    let mut el = Eliminator::new(n + fixed.len());
    for r in rows {
        el.add_row(r.clone(), TOLERANCE);
    }
    let mut free: Vec<usize> = Vec::new();
    for (k, r) in fixed.iter().enumerate() {
        let mut row = r.clone();
        row.add((n + k) as u32, -1.0);
        let reduced = el.reduce(row);
        if reduced.terms.iter().any(|t| (t.0 as usize) < n) {
            el.add_row_pivot_below(reduced, TOLERANCE, n as u32);
            continue;
        }
        // dependent: `z_k` follows from earlier parameters
        let c = reduced.constant;
        if (c - c.round()).abs() <= TOLERANCE {
            continue;
        }
        let fractional = |a: f64| (a - a.round()).abs() > TOLERANCE;
        // one already left free may resolve it (the next pass tells)
        let resolved = reduced
            .terms
            .iter()
            .any(|&(z, a)| free.contains(&(z as usize - n)) && fractional(a));
        if resolved {
            continue;
        }
        let culprit = reduced.terms.iter().find(|&&(z, a)| {
            let j = z as usize - n;
            j != k && ids[j] < first && fractional(a) && !free.contains(&j)
        });
        if let Some(&(z, _)) = culprit {
            free.push(z as usize - n);
        }
    }
    free
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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::integrate::elim::form;

    /// Two singular coordinates rounded to 0 and 1 make a translation
    /// `t = (s₀ + s₁)/2` a half-integer: the conflict is traced to one of
    /// them, which is left free, and every integer unknown ends integral
    /// (the freed one too, as it happens: `2·t` minus the other). Without
    /// the trace, `t` stayed at ½.
    #[test]
    fn a_half_integer_translation_frees_a_singular_coordinate() {
        // unknowns s₀, s₁, t, and a free one; the energy pulls x to b
        let b = vec![0.2, 0.9, 0.55, 0.3];
        let energy = Energy {
            k: (0..4).map(|i| (i, i, 1.0)).collect(),
            b: b.clone(),
        };
        let rows = vec![form(&[(2, 2.0), (0, -1.0), (1, -1.0)], 0.0)];
        let gauge = Gauge {
            wedge: vec![0],
            component: vec![0, 0],
            offset: [0.0, 0.0],
        };
        let integers: Vec<Form> = (0..3).map(|i| form(&[(i, 1.0)], 0.0)).collect();
        let (x, report) = quantize(
            &energy,
            &rows,
            &gauge,
            &Integers::new(&integers, 2),
            Rounding::Direct,
            Some(b),
        )
        .expect("solve");
        assert_eq!((report.conflicts, report.freed, report.off_grid), (0, 1, 0));
        for (i, v) in x[..3].iter().enumerate() {
            assert!((v - v.round()).abs() < 1e-9, "unknown {i}: {v}");
        }
        assert!((x[2] - 1.0).abs() < 1e-9, "t rounded to 1: {x:?}");
        assert!(
            (2.0 * x[2] - x[0] - x[1]).abs() < 1e-9,
            "the row holds: {x:?}"
        );
    }
}
