//! Sparse symmetric positive definite solves (glue over `faer`).
//!
//! Input: the matrix as `(row, column, value)` triplets (duplicates are
//! summed; both triangles may be given, only the lower one is read) and
//! right-hand sides. Output: the solution, or an error naming why the
//! factorisation failed (the matrix is not positive definite, or an index
//! is out of range).
//!
//! Why `faer`: a maintained pure-Rust crate with a supernodal sparse
//! Cholesky and a fill-reducing ordering (AMD), building with the
//! workspace's Rust 1.85 (faer 0.24 declares `rust-version = 1.84`).
//! The factorisation is kept ([`SpdSolver`]) so that repeated solves with
//! one matrix (inverse iteration, rounding) pay for it once.

use crate::error::SolveError;
use faer::linalg::solvers::Solve;
use faer::sparse::linalg::solvers::{Llt, SymbolicLlt};
use faer::sparse::{SparseColMat, Triplet};
use faer::{c64, MatMut, Side};

/// A sparse Cholesky factorisation `A = L·Lᵀ`, ready to solve with.
pub struct SpdSolver {
    n: usize,
    llt: Llt<usize, f64>,
}

impl SpdSolver {
    /// Factorises the `n × n` matrix given by `triplets` (lower triangle
    /// read, duplicates summed).
    pub fn new(n: usize, triplets: &[(u32, u32, f64)]) -> Result<Self, SolveError> {
        let a = lower(n, triplets)?;
        let llt = a
            .sp_cholesky(Side::Lower)
            .map_err(|e| SolveError::Factorise {
                hermitian: false,
                unknowns: n,
                reason: e.to_string(),
            })?;
        Ok(SpdSolver { n, llt })
    }

    /// Solves `A·x = rhs`.
    pub fn solve(&self, rhs: &[f64]) -> Result<Vec<f64>, SolveError> {
        solve_with(&self.llt, self.n, rhs)
    }
}

/// A sparse Cholesky factorisation `A = L·Lᴴ` of a complex Hermitian
/// positive definite matrix (the cross field's system: half the unknowns
/// of its real form and, measured on an 82k-face sphere, a factorisation
/// six times faster: 0.22 s against 1.45 s).
pub struct HpdSolver {
    n: usize,
    /// The pattern (column starts, row indices) of the lower triangle.
    pattern: (Vec<usize>, Vec<usize>),
    symbolic: SymbolicLlt<usize>,
    llt: Llt<usize, c64>,
}

impl HpdSolver {
    /// Factorises the `n × n` matrix given by `triplets` (lower triangle
    /// read, duplicates summed).
    pub fn new(n: usize, triplets: &[(u32, u32, c64)]) -> Result<Self, SolveError> {
        let a = lower(n, triplets)?;
        let symbolic =
            SymbolicLlt::try_new(a.symbolic(), Side::Lower).map_err(|e| SolveError::Factorise {
                hermitian: true,
                unknowns: n,
                reason: format!("{e:?}"),
            })?;
        Self::numeric(n, a, symbolic)
    }

    /// Factorises another matrix with the same pattern (the same triplet
    /// positions), reusing the fill-reducing ordering and the symbolic
    /// factorisation (a quarter of the cost, measured).
    pub fn refactor(&self, triplets: &[(u32, u32, c64)]) -> Result<Self, SolveError> {
        let a = lower(self.n, triplets)?;
        let sym = a.symbolic();
        if sym.col_ptr() != self.pattern.0.as_slice() || sym.row_idx() != self.pattern.1.as_slice()
        {
            return Err(SolveError::PatternDiffers);
        }
        Self::numeric(self.n, a, self.symbolic.clone())
    }

    fn numeric(
        n: usize,
        a: SparseColMat<usize, c64>,
        symbolic: SymbolicLlt<usize>,
    ) -> Result<Self, SolveError> {
        let llt =
            Llt::try_new_with_symbolic(symbolic.clone(), a.as_ref(), Side::Lower).map_err(|e| {
                SolveError::Factorise {
                    hermitian: true,
                    unknowns: n,
                    reason: e.to_string(),
                }
            })?;
        let pattern = (
            a.symbolic().col_ptr().to_vec(),
            a.symbolic().row_idx().to_vec(),
        );
        Ok(HpdSolver {
            n,
            pattern,
            symbolic,
            llt,
        })
    }

    /// Solves `A·x = rhs`.
    pub fn solve(&self, rhs: &[c64]) -> Result<Vec<c64>, SolveError> {
        solve_with(&self.llt, self.n, rhs)
    }
}

/// The matrix entries both solvers take: real (SPD) or complex (HPD).
trait Entry: faer::traits::ComplexField + Copy {
    fn finite(&self) -> bool;
}

impl Entry for f64 {
    fn finite(&self) -> bool {
        self.is_finite()
    }
}

impl Entry for c64 {
    fn finite(&self) -> bool {
        self.re.is_finite() && self.im.is_finite()
    }
}

/// The lower triangle of the `n × n` matrix given by `triplets`
/// (duplicates summed; indices and values checked).
fn lower<T: Entry>(
    n: usize,
    triplets: &[(u32, u32, T)],
) -> Result<SparseColMat<usize, T>, SolveError> {
    let mut lower = Vec::with_capacity(triplets.len());
    for &(r, c, v) in triplets {
        let (r, c) = (r as usize, c as usize);
        if r >= n || c >= n {
            return Err(SolveError::EntryOutside {
                row: r,
                column: c,
                size: n,
            });
        }
        if !v.finite() {
            return Err(SolveError::EntryNotFinite { row: r, column: c });
        }
        if r >= c {
            lower.push(Triplet::new(r, c, v));
        }
    }
    SparseColMat::<usize, T>::try_new_from_triplets(n, n, &lower)
        .map_err(|e| SolveError::Matrix(format!("{e:?}")))
}

/// Solves `A·x = rhs` with a factorisation of `A` (`n` unknowns).
fn solve_with<T: Entry>(llt: &Llt<usize, T>, n: usize, rhs: &[T]) -> Result<Vec<T>, SolveError> {
    if rhs.len() != n {
        return Err(SolveError::RhsLength {
            len: rhs.len(),
            unknowns: n,
        });
    }
    let mut x = rhs.to_vec();
    llt.solve_in_place(MatMut::from_column_major_slice_mut(&mut x, n, 1));
    if x.iter().all(Entry::finite) {
        Ok(x)
    } else {
        Err(SolveError::NonFinite { unknowns: n })
    }
}

/// Solves the symmetric positive definite system `A·x = rhs`, `A` given
/// by `triplets` as for [`SpdSolver::new`].
pub fn solve_spd(
    n: usize,
    triplets: &[(u32, u32, f64)],
    rhs: &[f64],
) -> Result<Vec<f64>, SolveError> {
    SpdSolver::new(n, triplets)?.solve(rhs)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn solves_a_path_laplacian_with_duplicates() {
        // (L + I) x = b on a path of 4 nodes, entries given twice (summed)
        let n = 4;
        let mut t = Vec::new();
        for i in 0..n as u32 {
            t.push((i, i, 0.5));
            t.push((i, i, 0.5));
        }
        for i in 0..n as u32 - 1 {
            t.extend([
                (i, i, 1.0),
                (i + 1, i + 1, 1.0),
                (i + 1, i, -1.0),
                (i, i + 1, -1.0),
            ]);
        }
        let b = [1.0, 2.0, 3.0, 4.0];
        let x = solve_spd(n, &t, &b).unwrap();
        // check A x = b with the full matrix
        let mut ax = [0.0; 4];
        for &(r, c, v) in &t {
            ax[r as usize] += v * x[c as usize];
        }
        for i in 0..n {
            assert!((ax[i] - b[i]).abs() < 1e-12, "{ax:?}");
        }
    }

    #[test]
    fn solves_a_hermitian_system() {
        // [[2, −i], [i, 2]] x = [1, 0]  →  x = [2, −i] / 3
        let i = c64::new(0.0, 1.0);
        let two = c64::new(2.0, 0.0);
        let t = [(0, 0, two), (1, 1, two), (1, 0, i), (0, 1, -i)];
        let x = HpdSolver::new(2, &t)
            .unwrap()
            .solve(&[c64::new(1.0, 0.0), c64::new(0.0, 0.0)])
            .unwrap();
        assert!((x[0] - c64::new(2.0 / 3.0, 0.0)).norm() < 1e-12, "{x:?}");
        assert!((x[1] - c64::new(0.0, -1.0 / 3.0)).norm() < 1e-12, "{x:?}");
        // the same pattern with other values: [[3, −i], [i, 3]] x = [1, 0]
        let three = c64::new(3.0, 0.0);
        let solver = HpdSolver::new(2, &t).unwrap();
        let t3 = [(0, 0, three), (1, 1, three), (1, 0, i), (0, 1, -i)];
        let x = solver
            .refactor(&t3)
            .unwrap()
            .solve(&[c64::new(1.0, 0.0), c64::new(0.0, 0.0)])
            .unwrap();
        assert!((x[0] - c64::new(3.0 / 8.0, 0.0)).norm() < 1e-12, "{x:?}");
        assert!((x[1] - c64::new(0.0, -1.0 / 8.0)).norm() < 1e-12, "{x:?}");
        let e = solver.refactor(&[(0, 0, three), (1, 1, three)]).err();
        assert_eq!(e, Some(SolveError::PatternDiffers));
    }

    #[test]
    fn rejects_indefinite_and_out_of_range() {
        assert!(solve_spd(2, &[(0, 0, 1.0), (1, 1, -1.0)], &[1.0, 1.0]).is_err());
        let e = solve_spd(2, &[(0, 2, 1.0)], &[1.0, 1.0]).unwrap_err();
        assert_eq!(
            e,
            SolveError::EntryOutside {
                row: 0,
                column: 2,
                size: 2
            }
        );
        let e = solve_spd(1, &[(0, 0, 1.0)], &[1.0, 1.0]).unwrap_err();
        assert_eq!(e.to_string(), "right-hand side of length 2 for 1 unknowns");
    }
}
