//! The untangling functional of Garanzha, Kaporin, Kudryavtseva, Protais,
//! Ray & Sokolov, *Foldover-free maps in 50 lines of code* (2021), for one
//! corner simplex of any dimension `D` (2: a quad's corner triangle, 3: a
//! hex's corner tet).
//!
//! Input: the simplex's Jacobian `J` (D×D: its `D` edges from the corner,
//! in the element's frame, over the element's reference edge length), the
//! regularisation `ε > 0` and the weight `θ` of the size term. Output:
//! `E = (1−θ) f + θ g` and `∂E/∂J`, with
//! - `f = tr(JᵀJ) / χ(det J, ε)^(2/D)` (shape: least for a similarity),
//! - `g = (1 + det² J) / χ(det J, ε)` (size: least for det J = 1),
//! - `χ(d, ε) = (d + √(ε² + d²)) / 2`, positive for every `d`, so that `E`
//!   is finite on tangled meshes too and tends to the barrier
//!   `tr(JᵀJ)/det^(2/D)` as `ε → 0` where `det > 0`.

/// `χ(d, ε)`, in the form that stays accurate for `d ≪ 0`.
pub fn chi(d: f64, eps: f64) -> f64 {
    let r = (eps * eps + d * d).sqrt();
    if d > 0.0 {
        0.5 * (d + r)
    } else {
        0.5 * eps * eps / (r - d)
    }
}

/// `∂χ/∂d`.
pub fn chi_deriv(d: f64, eps: f64) -> f64 {
    0.5 + d / (2.0 * (eps * eps + d * d).sqrt())
}

/// The determinant of `j` and its cofactor matrix (`∂ det / ∂ j`).
pub fn det_cofactor<const D: usize>(j: &[[f64; D]; D]) -> (f64, [[f64; D]; D]) {
    let mut c = [[0.0; D]; D];
    match D {
        2 => {
            c[0][0] = j[1][1];
            c[0][1] = -j[1][0];
            c[1][0] = -j[0][1];
            c[1][1] = j[0][0];
        }
        3 => {
            for (r, row) in c.iter_mut().enumerate() {
                for (k, x) in row.iter_mut().enumerate() {
                    let (r1, r2) = ((r + 1) % 3, (r + 2) % 3);
                    let (k1, k2) = ((k + 1) % 3, (k + 2) % 3);
                    *x = j[r1][k1] * j[r2][k2] - j[r1][k2] * j[r2][k1];
                }
            }
        }
        _ => unreachable!("dimension {D}: only 2 and 3"),
    }
    let det = (0..D).map(|k| j[0][k] * c[0][k]).sum();
    (det, c)
}

/// The cube root of `x > 0` (finite): a bit-level first guess (within
/// ~6 %), then two steps of Halley's iteration (cubic convergence: within
/// ~1e-11, relative; the energy and its gradient share it). `f64::cbrt` is a software routine here and cost a sixth of the
/// untangling.
pub fn cbrt(x: f64) -> f64 {
    if !(x >= f64::MIN_POSITIVE && x.is_finite()) {
        return x.cbrt();
    }
    let mut c = f64::from_bits(x.to_bits() / 3 + 0x2a9f_7893_782d_a1ce);
    for _ in 0..2 {
        let c3 = c * c * c;
        c *= (c3 + 2.0 * x) / (2.0 * c3 + x);
    }
    c
}

/// `E(J)` and `∂E/∂J` (see the module docs).
pub fn energy<const D: usize>(j: &[[f64; D]; D], eps: f64, theta: f64) -> (f64, [[f64; D]; D]) {
    let (e, grad, _) = energy_det(j, eps, theta);
    (e, grad)
}

/// `E(J)`, `∂E/∂J` and `det J`.
pub fn energy_det<const D: usize>(
    j: &[[f64; D]; D],
    eps: f64,
    theta: f64,
) -> (f64, [[f64; D]; D], f64) {
    let (det, cof) = det_cofactor(j);
    let c1 = chi(det, eps);
    // χ^(2/D) without `powf`
    let c2 = match D {
        2 => c1,
        _ => {
            let c = cbrt(c1);
            c * c
        }
    };
    let c3 = chi_deriv(det, eps);
    let tr: f64 = j.iter().flatten().map(|x| x * x).sum();
    let f = tr / c2;
    let g = (1.0 + det * det) / c1;
    let df_cof = -(2.0 / D as f64) * f * c3 / c1;
    let dg_cof = (2.0 * det - g * c3) / c1;
    let mut grad = [[0.0; D]; D];
    for r in 0..D {
        for k in 0..D {
            grad[r][k] = (1.0 - theta) * (2.0 * j[r][k] / c2 + df_cof * cof[r][k])
                + theta * dg_cof * cof[r][k];
        }
    }
    ((1.0 - theta) * f + theta * g, grad, det)
}

#[cfg(test)]
mod tests {
    use super::*;

    fn check_gradient<const D: usize>(j: [[f64; D]; D], eps: f64) {
        let (_, g) = energy(&j, eps, 0.5);
        for r in 0..D {
            for k in 0..D {
                let h = 1e-6;
                let (mut a, mut b) = (j, j);
                a[r][k] += h;
                b[r][k] -= h;
                let fd = (energy(&a, eps, 0.5).0 - energy(&b, eps, 0.5).0) / (2.0 * h);
                assert!(
                    (fd - g[r][k]).abs() < 1e-5 * (1.0 + fd.abs()),
                    "D={D} ({r},{k}): {fd} vs {}",
                    g[r][k]
                );
            }
        }
    }

    #[test]
    fn cbrt_is_within_1e_11() {
        let mut x = 1e-300;
        while x < 1e300 {
            for m in [1.0, 1.37, 2.0, 3.3, 5.9] {
                let c = cbrt(x * m);
                let r = (x * m).cbrt();
                assert!((c - r).abs() <= 1e-11 * r, "{}: {c} vs {r}", x * m);
            }
            x *= 1e7;
        }
    }

    #[test]
    fn gradients_match_finite_differences() {
        check_gradient([[1.0, 0.2], [-0.3, 0.8]], 0.1);
        check_gradient([[-1.0, 0.2], [0.3, 0.8]], 0.5); // inverted
        check_gradient([[1.0, 0.2, 0.1], [0.0, 0.9, -0.2], [0.3, 0.1, 1.1]], 0.1);
        check_gradient([[1.0, 0.2, 0.1], [0.0, -0.9, -0.2], [0.3, 0.1, 1.1]], 1.0);
    }

    #[test]
    fn the_identity_is_the_minimum() {
        // ε → 0: E(I) = (1−θ)·D + θ·2, and nothing nearby is lower
        let e0 = energy(&[[1.0, 0.0], [0.0, 1.0]], 1e-12, 0.5).0;
        assert!((e0 - 2.0).abs() < 1e-9);
        for (a, b) in [(1.1, 0.0), (0.9, 0.1), (1.0, -0.2)] {
            assert!(energy(&[[a, b], [0.0, 1.0]], 1e-12, 0.5).0 > e0);
        }
        let e3 = energy(&[[1.0, 0., 0.], [0., 1.0, 0.], [0., 0., 1.0]], 1e-12, 0.5).0;
        assert!((e3 - 2.5).abs() < 1e-9);
    }

    #[test]
    fn chi_is_positive_and_accurate_for_negative_determinants() {
        for d in [-1e8, -1.0, -1e-3, 0.0, 1e-3, 1.0] {
            let c = chi(d, 1e-4);
            assert!(c > 0.0, "{d}");
        }
        // d ≪ 0: χ ≈ ε² / (4|d|), not 0 from cancellation
        let c = chi(-1e8, 1e-4);
        assert!((c - 1e-8 / 4e8).abs() < 1e-3 * c);
    }
}
