//! Linear constraints eliminated by substitution.
//!
//! Input: constraint rows `Σ cᵢ·xᵢ + k = 0` over the unknowns, added one
//! at a time. Output: each unknown either **free** or an affine function
//! of the free ones, `x = P·y + c`, so that minimizing the energy over the
//! free unknowns `y` is an unconstrained SPD solve.
//!
//! Each row is first reduced by the eliminations so far; a row that
//! reduces to nothing is redundant (or, with a nonzero constant, in
//! conflict with earlier rows: reported, not applied). Otherwise the
//! unknown with the largest coefficient is eliminated. Our rows have small
//! integer coefficients (0, ±1, ±2 from the seams' rotations) so the
//! elimination is exact up to the constants.
//!
//! Invariant: an expression stored when its unknown is eliminated only
//! names unknowns not yet eliminated then; [`Eliminator::finish`] resolves
//! them in reverse order so that every expression names free unknowns only.

/// A sparse affine form `Σ cᵢ·xᵢ + constant`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Form {
    /// `(unknown, coefficient)`, each unknown once.
    pub terms: Vec<(u32, f64)>,
    /// The constant.
    pub constant: f64,
}

#[cfg(test)]
/// A form of `terms` and `constant` (the tests' shorthand).
pub(crate) fn form(terms: &[(u32, f64)], constant: f64) -> Form {
    Form {
        terms: terms.to_vec(),
        constant,
    }
}

/// Coefficients below this are zero.
const EPS: f64 = 1e-10;

impl Form {
    /// Adds `c·x`.
    pub fn add(&mut self, x: u32, c: f64) {
        match self.terms.iter_mut().find(|t| t.0 == x) {
            Some(t) => t.1 += c,
            None => self.terms.push((x, c)),
        }
    }

    /// The form's value at `x`.
    pub fn eval(&self, x: &[f64]) -> f64 {
        self.constant
            + self
                .terms
                .iter()
                .map(|&(i, c)| c * x[i as usize])
                .sum::<f64>()
    }

    fn prune(&mut self) {
        self.terms.retain(|t| t.1.abs() > EPS);
    }
}

/// What became of a row.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RowOutcome {
    /// An unknown was eliminated.
    Eliminated,
    /// The row follows from earlier ones.
    Redundant,
    /// The row contradicts earlier ones by this much; not applied.
    Conflict(f64),
}

/// Eliminations so far (module docs).
#[derive(Clone, Debug)]
pub struct Eliminator {
    expr: Vec<Option<Form>>,
    order: Vec<u32>,
}

impl Eliminator {
    /// No constraint on `n` unknowns.
    pub fn new(n: usize) -> Self {
        Eliminator {
            expr: vec![None; n],
            order: Vec::new(),
        }
    }

    /// Whether `x` is eliminated.
    pub fn is_eliminated(&self, x: u32) -> bool {
        self.expr[x as usize].is_some()
    }

    /// `form` with every eliminated unknown substituted.
    pub fn reduce(&self, mut form: Form) -> Form {
        while let Some(pos) = form.terms.iter().position(|t| self.is_eliminated(t.0)) {
            let (x, c) = form.terms.swap_remove(pos);
            if let Some(e) = &self.expr[x as usize] {
                for &(y, cy) in &e.terms {
                    form.add(y, c * cy);
                }
                form.constant += c * e.constant;
            }
        }
        form.prune();
        form
    }

    /// Imposes `row = 0` (module docs).
    pub fn add_row(&mut self, row: Form, tolerance: f64) -> RowOutcome {
        self.add_row_pivot_below(row, tolerance, u32::MAX)
    }

    /// [`Self::add_row`] eliminating only an unknown below `limit` (the
    /// others are parameters: a row naming only them is redundant or in
    /// conflict by its constant alone when it has no other term).
    pub fn add_row_pivot_below(&mut self, row: Form, tolerance: f64, limit: u32) -> RowOutcome {
        let mut r = self.reduce(row);
        let candidates: Vec<usize> = (0..r.terms.len())
            .filter(|&i| r.terms[i].0 < limit)
            .collect();
        let Some(pivot) = candidates.into_iter().max_by(|&i, &j| {
            let (a, b) = (r.terms[i], r.terms[j]);
            a.1.abs().total_cmp(&b.1.abs()).then(a.0.cmp(&b.0))
        }) else {
            return if r.constant.abs() <= tolerance {
                RowOutcome::Redundant
            } else {
                RowOutcome::Conflict(r.constant)
            };
        };
        let (x, c) = r.terms.swap_remove(pivot);
        for t in &mut r.terms {
            t.1 /= -c;
        }
        r.constant /= -c;
        self.expr[x as usize] = Some(r);
        self.order.push(x);
        RowOutcome::Eliminated
    }

    /// Resolves the expressions (module docs) and numbers the free
    /// unknowns: `P` as, per unknown, its form over free-unknown numbers,
    /// and the count of free unknowns.
    pub fn finish(mut self) -> (Vec<Form>, usize) {
        for k in (0..self.order.len()).rev() {
            let x = self.order[k] as usize;
            if let Some(e) = self.expr[x].take() {
                let resolved = self.reduce(e);
                self.expr[x] = Some(resolved);
            }
        }
        let mut number = vec![u32::MAX; self.expr.len()];
        let mut free = 0u32;
        for (x, e) in self.expr.iter().enumerate() {
            if e.is_none() {
                number[x] = free;
                free += 1;
            }
        }
        let p = self
            .expr
            .into_iter()
            .enumerate()
            .map(|(x, e)| match e {
                None => Form {
                    terms: vec![(number[x], 1.0)],
                    constant: 0.0,
                },
                Some(mut e) => {
                    for t in &mut e.terms {
                        t.0 = number[t.0 as usize];
                    }
                    e
                }
            })
            .collect();
        (p, free as usize)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn chain_resolves_to_free_unknowns() {
        // x0 = x1 + 1, x1 = x2 + 1, x2 free
        let mut el = Eliminator::new(3);
        assert_eq!(
            el.add_row(form(&[(0, 1.0), (1, -1.0)], -1.0), 1e-9),
            RowOutcome::Eliminated
        );
        assert_eq!(
            el.add_row(form(&[(1, 1.0), (2, -1.0)], -1.0), 1e-9),
            RowOutcome::Eliminated
        );
        // x0 − x2 = 2 follows; x0 − x2 = 3 conflicts
        assert_eq!(
            el.add_row(form(&[(0, 1.0), (2, -1.0)], -2.0), 1e-9),
            RowOutcome::Redundant
        );
        assert_eq!(
            el.add_row(form(&[(0, 1.0), (2, -1.0)], -3.0), 1e-9),
            RowOutcome::Conflict(-1.0)
        );
        let (p, free) = el.finish();
        assert_eq!(free, 1);
        let x: Vec<f64> = p.iter().map(|f| f.eval(&[5.0])).collect();
        assert!(x.contains(&5.0), "{x:?}");
        assert_eq!((x[0] - x[1], x[1] - x[2]), (1.0, 1.0));
    }
}
