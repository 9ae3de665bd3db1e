//! Sparse Cholesky on a 2D grid Laplacian (+ 1e-3·I): faer against
//! nalgebra-sparse, assembly + factorization + one solve.
//!
//! `sparse-choice SOLVER K [shuffle]`: SOLVER `faer` or `nalgebra`, a
//! `K × K` grid (K = 316: ~100k unknowns, 548: ~300k), `shuffle` numbers
//! the unknowns at random as a mesh would.

use std::time::Instant;

/// 5-point Laplacian + small diagonal shift on a k×k grid, with an
/// optional permutation of the unknowns (a mesh's vertex order is not a grid's).
fn system(k: usize, shuffle: bool) -> (usize, Vec<(usize, usize, f64)>, Vec<f64>) {
    let n = k * k;
    let mut perm: Vec<usize> = (0..n).collect();
    if shuffle {
        let mut s = 0x9e3779b97f4a7c15u64;
        for i in (1..n).rev() {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            perm.swap(i, (s % (i as u64 + 1)) as usize);
        }
    }
    let id = |i: usize, j: usize| perm[i * k + j];
    let mut t = Vec::new();
    for i in 0..k {
        for j in 0..k {
            let a = id(i, j);
            t.push((a, a, 1e-3));
            for (di, dj) in [(0, 1), (1, 0)] {
                if i + di < k && j + dj < k {
                    let b = id(i + di, j + dj);
                    t.push((a, a, 1.0));
                    t.push((b, b, 1.0));
                    t.push((a, b, -1.0));
                    t.push((b, a, -1.0));
                }
            }
        }
    }
    let rhs = (0..n)
        .map(|i| ((i * 7919) % 1000) as f64 / 1000.0 - 0.5)
        .collect();
    (n, t, rhs)
}

fn residual(n: usize, t: &[(usize, usize, f64)], x: &[f64], b: &[f64]) -> f64 {
    let mut r = b.to_vec();
    for &(i, j, v) in t {
        r[i] -= v * x[j];
    }
    let _ = n;
    r.iter().map(|v| v * v).sum::<f64>().sqrt() / b.iter().map(|v| v * v).sum::<f64>().sqrt()
}

fn faer_solve(n: usize, t: &[(usize, usize, f64)], b: &[f64]) -> Vec<f64> {
    use faer::linalg::solvers::Solve;
    use faer::sparse::{SparseColMat, Triplet};
    let trip: Vec<Triplet<usize, usize, f64>> = t
        .iter()
        .filter(|e| e.0 >= e.1)
        .map(|&(r, c, v)| Triplet::new(r, c, v))
        .collect();
    let a = SparseColMat::<usize, f64>::try_new_from_triplets(n, n, &trip).unwrap();
    let llt = a.sp_cholesky(faer::Side::Lower).unwrap();
    let mut x = faer::Mat::<f64>::from_fn(n, 1, |i, _| b[i]);
    llt.solve_in_place(x.as_mut());
    (0..n).map(|i| x[(i, 0)]).collect()
}

fn nalgebra_solve(n: usize, t: &[(usize, usize, f64)], b: &[f64]) -> Vec<f64> {
    use nalgebra_sparse::{coo::CooMatrix, csc::CscMatrix, factorization::CscCholesky};
    let mut coo = CooMatrix::new(n, n);
    for &(r, c, v) in t {
        coo.push(r, c, v);
    }
    let a = CscMatrix::from(&coo);
    let ch = CscCholesky::factor(&a).unwrap();
    let rhs = nalgebra::DMatrix::from_column_slice(n, 1, b);
    let x = ch.solve(&rhs);
    x.column(0).iter().copied().collect()
}

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let which = args[1].as_str();
    let k: usize = args[2].parse().unwrap();
    let shuffle = args.get(3).map(|s| s == "shuffle").unwrap_or(false);
    let (n, t, b) = system(k, shuffle);
    let t0 = Instant::now();
    let x = match which {
        "faer" => faer_solve(n, &t, &b),
        _ => nalgebra_solve(n, &t, &b),
    };
    let dt = t0.elapsed().as_secs_f64();
    println!(
        "{which} n={n} shuffle={shuffle}: {dt:.3} s (assemble+factor+solve), rel. residual {:.1e}",
        residual(n, &t, &x, &b)
    );
}
