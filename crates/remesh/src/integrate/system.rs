//! The integration energy and its constrained minimization.
//!
//! Input: the [`Surface`], the [`Charts`] (combed angles, wedges) and a
//! scale `s`; unknowns `2·w + c` are coordinate `c` (0: u, 1: v) of wedge
//! `w`. Energy: `Σ_f area_f · |∇(u, v) − s·(d_f, d_f⊥)|²` with `d_f` the
//! unit vector at the combed angle of face `f` and `d_f⊥` it turned by a
//! quarter turn counter-clockwise (so the map keeps the orientation).
//! Output: the minimizer subject to the eliminated constraints
//! (`x = P·y + c`, see [`super::elim`]): the reduced system
//! `Pᵀ·K·P·y = Pᵀ·(b − K·c)` is SPD once every component has a gauge.

use super::charts::Charts;
use super::elim::Form;
use crate::error::SolveError;
use crate::sparse::solve_spd;
use crate::surface::Surface;

/// The energy's quadratic part `K` (triplets over the unknowns, both
/// triangles) and linear part `b` (the energy is `xᵀKx − 2bᵀx + const`).
pub struct Energy {
    /// Triplets of `K`.
    pub k: Vec<(u32, u32, f64)>,
    /// `b`.
    pub b: Vec<f64>,
}

/// Assembles the [`Energy`] (module docs).
pub fn energy(surface: &Surface, charts: &Charts, scale: f64) -> Energy {
    let nf = surface.triangles.len();
    let mut k = Vec::with_capacity(18 * nf);
    let mut b = vec![0.0; 2 * charts.wedges];
    for f in 0..nf {
        let t = surface.triangles[f];
        let o = surface.positions[t[0] as usize];
        let p = t.map(|v| {
            let q = surface.positions[v as usize];
            surface.in_frame(f as u32, [q[0] - o[0], q[1] - o[1], q[2] - o[2]])
        });
        let area = surface.areas[f];
        // ∇φ_i = (p_{i+2} − p_{i+1}) turned by +90°, over 2·area
        let grad: [[f64; 2]; 3] = std::array::from_fn(|i| {
            let (a, c) = (p[(i + 1) % 3], p[(i + 2) % 3]);
            [-(c[1] - a[1]) / (2.0 * area), (c[0] - a[0]) / (2.0 * area)]
        });
        let (sn, cs) = charts.angle[f].sin_cos();
        let target = [[scale * cs, scale * sn], [-scale * sn, scale * cs]];
        let w: [u32; 3] = std::array::from_fn(|i| charts.corner_wedge[3 * f + i]);
        for i in 0..3 {
            for j in 0..3 {
                let kij = area * (grad[i][0] * grad[j][0] + grad[i][1] * grad[j][1]);
                for c in 0..2 {
                    k.push((2 * w[i] + c, 2 * w[j] + c, kij));
                }
            }
            for c in 0..2 {
                let g = target[c];
                b[2 * w[i] as usize + c] += area * (grad[i][0] * g[0] + grad[i][1] * g[1]);
            }
        }
    }
    Energy { k, b }
}

/// Minimizes the [`Energy`] over `x = P·y + c` (`p` per unknown, `free`
/// unknowns `y`); returns `x`.
pub fn minimize(energy: &Energy, p: &[Form], free: usize) -> Result<Vec<f64>, SolveError> {
    let n = p.len();
    // b − K·c
    let mut rhs_full = energy.b.clone();
    for &(i, j, v) in &energy.k {
        rhs_full[i as usize] -= v * p[j as usize].constant;
    }
    let mut rhs = vec![0.0; free];
    for (i, form) in p.iter().enumerate() {
        for &(y, c) in &form.terms {
            rhs[y as usize] += c * rhs_full[i];
        }
    }
    let mut triplets = Vec::with_capacity(energy.k.len() + energy.k.len() / 4);
    for &(i, j, v) in &energy.k {
        for &(a, ca) in &p[i as usize].terms {
            for &(b, cb) in &p[j as usize].terms {
                triplets.push((a, b, v * ca * cb));
            }
        }
    }
    let y = solve_spd(free, &triplets, &rhs)?;
    debug_assert_eq!(p.len(), n);
    Ok(p.iter().map(|f| f.eval(&y)).collect())
}
