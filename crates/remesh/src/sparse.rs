//! Sparse symmetric positive definite solves (faer's supernodal Cholesky
//! with its fill-reducing ordering).
//!
//! Input: the matrix as triplets `(row, col, value)` of the **full**
//! symmetric matrix (both `(i, j)` and `(j, i)`; duplicates are summed;
//! only the lower triangle `row ≥ col` is read), and right-hand sides.
//! Output: the solution, or an error naming the cause (an index out of
//! range, a matrix that is not positive definite, a non-finite value).
//!
//! [`SpdFactor`] factors once and solves many right-hand sides (the
//! rounding re-solves with new right-hand sides when only constants
//! change). See README.md, "Sparse solver", for why faer.

use faer::linalg::solvers::Solve;
use faer::sparse::{SparseColMat, Triplet};

/// A Cholesky factorization `A = L·Lᵀ` to solve with many right-hand sides.
pub struct SpdFactor {
    n: usize,
    llt: faer::sparse::linalg::solvers::Llt<usize, f64>,
}

impl SpdFactor {
    /// Factors the `n × n` matrix given by `triplets` (module docs).
    pub fn new(n: usize, triplets: &[(usize, usize, f64)]) -> Result<Self, String> {
        let mut lower = Vec::with_capacity(triplets.len() / 2 + n);
        for &(r, c, v) in triplets {
            if r >= n || c >= n {
                return Err(format!("sparse matrix: entry ({r}, {c}) outside {n} × {n}"));
            }
            if !v.is_finite() {
                return Err(format!("sparse matrix: entry ({r}, {c}) is {v}"));
            }
            if r >= c {
                lower.push(Triplet::new(r, c, v));
            }
        }
        let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &lower)
            .map_err(|e| format!("sparse matrix: {e:?}"))?;
        let llt = a
            .sp_cholesky(faer::Side::Lower)
            .map_err(|e| format!("sparse Cholesky: {e:?} (matrix not positive definite?)"))?;
        Ok(SpdFactor { n, llt })
    }

    /// Size of the system.
    pub fn len(&self) -> usize {
        self.n
    }

    /// Whether the system is empty.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// Solves `A·x = rhs`.
    pub fn solve(&self, rhs: &[f64]) -> Result<Vec<f64>, String> {
        if rhs.len() != self.n {
            return Err(format!(
                "sparse solve: right-hand side of length {} for {} unknowns",
                rhs.len(),
                self.n
            ));
        }
        if self.n == 0 {
            return Ok(Vec::new());
        }
        let mut x = faer::Mat::<f64>::from_fn(self.n, 1, |i, _| rhs[i]);
        self.llt.solve_in_place(x.as_mut());
        let x: Vec<f64> = (0..self.n).map(|i| x[(i, 0)]).collect();
        if let Some(i) = x.iter().position(|v| !v.is_finite()) {
            return Err(format!("sparse solve: unknown {i} is not finite"));
        }
        Ok(x)
    }
}

/// Solves the SPD system `A·x = rhs`, `A` given by `triplets` (module docs).
pub fn solve_spd(
    n: usize,
    triplets: &[(usize, usize, f64)],
    rhs: &[f64],
) -> Result<Vec<f64>, String> {
    if n == 0 {
        return Ok(Vec::new());
    }
    SpdFactor::new(n, triplets)?.solve(rhs)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// 1D Laplacian with one end pinned: `x_i = i + 1` solves it with
    /// `rhs = e_last`.
    #[test]
    fn path_laplacian() {
        let n = 50;
        let mut t = vec![(0, 0, 1.0)];
        for i in 0..n - 1 {
            t.extend([
                (i, i, 1.0),
                (i + 1, i + 1, 1.0),
                (i, i + 1, -1.0),
                (i + 1, i, -1.0),
            ]);
        }
        let mut rhs = vec![0.0; n];
        rhs[n - 1] = 1.0;
        let x = solve_spd(n, &t, &rhs).unwrap();
        for (i, v) in x.iter().enumerate() {
            assert!((v - (i + 1) as f64).abs() < 1e-9, "x[{i}] = {v}");
        }
        let f = SpdFactor::new(n, &t).unwrap();
        let y = f.solve(&vec![0.0; n]).unwrap();
        assert!(y.iter().all(|v| v.abs() < 1e-12));
    }

    #[test]
    fn errors_name_the_cause() {
        assert!(solve_spd(2, &[(0, 0, 1.0), (2, 0, 1.0)], &[1.0, 1.0])
            .unwrap_err()
            .contains("outside"));
        // singular (no diagonal on unknown 1)
        let e = solve_spd(2, &[(0, 0, 1.0)], &[1.0, 1.0]).unwrap_err();
        assert!(e.contains("Cholesky"), "{e}");
        let e = solve_spd(1, &[(0, 0, -1.0)], &[1.0]).unwrap_err();
        assert!(e.contains("Cholesky"), "{e}");
        assert!(SpdFactor::new(1, &[(0, 0, 1.0)])
            .unwrap()
            .solve(&[1.0, 2.0])
            .is_err());
    }
}
