//! The linear algebra of [`crate::smooth`]: the energy on the free faces
//! assembled as a complex Hermitian system, its factorisations
//! `L + ε·M` and `L + μ·M`, the linear iteration and the unit steps.
//!
//! Input: a [`Surface`], the fixed direction of each face (or none) and
//! the [`FieldOptions`]. Output: `z = exp(4iθ)` per face (fixed faces
//! keep theirs). The method and its measurements are in the module docs
//! of [`crate::smooth`].

use super::{face_components, FieldOptions};
use crate::error::RemeshError;
use crate::sparse::HpdSolver;
use crate::surface::{dot, sub, Surface, NO_FACE};
use dualex_util::timing::Laps;
use faer::c64;

/// The energy on the free faces: `L`, `b` (from the fixed faces), the
/// mass, and which components are pinned by a fixed face.
struct System {
    /// Free faces, in unknown order.
    free: Vec<u32>,
    /// `L` as full Hermitian triplets.
    laplacian: Vec<(u32, u32, c64)>,
    /// The right-hand side from the fixed faces.
    b: Vec<c64>,
    /// Per unknown: the face area.
    mass: Vec<f64>,
    /// Per unknown: its component; per component: has a fixed face.
    comp: Vec<u32>,
    pinned: Vec<bool>,
    /// Mean edge weight over mean face area: the scale of the shifts.
    scale: f64,
}

/// `z` per face: fixed faces keep `exp(4i·angle)`, free faces are solved
/// for (see the module docs).
pub(super) fn solve_field(
    surface: &Surface,
    fixed: &[Option<f64>],
    opts: &FieldOptions,
    laps: &mut Laps,
) -> Result<Vec<c64>, RemeshError> {
    let mut z: Vec<c64> = fixed
        .iter()
        .map(|a| a.map_or(c64::new(0.0, 0.0), |a| c64::cis(4.0 * a)))
        .collect();
    let sys = system(surface, fixed, &z);
    if sys.free.is_empty() {
        return Ok(z);
    }
    laps.lap("field: assemble");
    let eps = 1e-6 * sys.scale;
    let solver = shifted(&sys, eps, None)?;
    laps.lap("field: factorise");
    // a fixed pseudo-random start (matters only without fixed faces)
    let mut x: Vec<c64> = sys
        .free
        .iter()
        .map(|&f| c64::cis(f64::from(f.wrapping_mul(2_654_435_761) >> 8) * 1e-3))
        .collect();
    for _ in 0..opts.max_iterations.max(1) {
        let rhs: Vec<c64> = (0..x.len())
            .map(|k| sys.b[k] + x[k] * (eps * sys.mass[k]))
            .collect();
        let mut y = solver.solve(&rhs).map_err(RemeshError::Field)?;
        normalise_components(&sys, &mut y);
        let change: f64 = y.iter().zip(&x).map(|(a, b)| (a - b).norm_sqr()).sum();
        let size: f64 = y.iter().map(|a| a.norm_sqr()).sum();
        x = y;
        if change <= 1e-12 * size.max(f64::MIN_POSITIVE) {
            break;
        }
    }
    laps.lap("field: linear iteration");
    if opts.unit_steps > 0 {
        // diffuse and project to unit length (see `FieldOptions::unit_steps`)
        let mu = opts.unit_shift * sys.scale;
        let solver = shifted(&sys, mu, Some(&solver))?;
        laps.lap("field: factorise (unit steps)");
        for _ in 0..opts.unit_steps {
            let rhs: Vec<c64> = (0..x.len())
                .map(|k| {
                    let r = x[k].norm();
                    let unit = if r > 0.0 { x[k] / r } else { x[k] };
                    sys.b[k] + unit * (mu * sys.mass[k])
                })
                .collect();
            x = solver.solve(&rhs).map_err(RemeshError::Field)?;
        }
        laps.lap("field: unit steps");
    }
    for (k, &f) in sys.free.iter().enumerate() {
        z[f as usize] = x[k];
    }
    Ok(z)
}

/// Numbers the free faces and assembles their [`System`].
fn system(surface: &Surface, fixed: &[Option<f64>], z: &[c64]) -> System {
    let nf = surface.triangles.len();
    let mut unknown = vec![u32::MAX; nf];
    let mut free = Vec::new();
    for f in 0..nf {
        if fixed[f].is_none() {
            unknown[f] = free.len() as u32;
            free.push(f as u32);
        }
    }
    let (laplacian, b, mean_w) = assemble(surface, &unknown, z);
    let mass = free.iter().map(|&f| surface.areas[f as usize]).collect();
    let (face_comp, ncomp) = face_components(surface);
    let mut pinned = vec![false; ncomp as usize];
    for f in 0..nf {
        pinned[face_comp[f] as usize] |= fixed[f].is_some();
    }
    let comp = free.iter().map(|&f| face_comp[f as usize]).collect();
    let mean_area = surface.areas.iter().sum::<f64>() / nf as f64;
    System {
        free,
        laplacian,
        b,
        mass,
        comp,
        pinned,
        scale: mean_w / mean_area,
    }
}

/// Factorises `L + shift·M` (reusing the symbolic factorisation of
/// `like`, a matrix of the same pattern, when given).
fn shifted(sys: &System, shift: f64, like: Option<&HpdSolver>) -> Result<HpdSolver, RemeshError> {
    let mut t = sys.laplacian.clone();
    for (k, &m) in sys.mass.iter().enumerate() {
        t.push((k as u32, k as u32, c64::new(shift * m, 0.0)));
    }
    match like {
        Some(s) => s.refactor(&t),
        None => HpdSolver::new(sys.mass.len(), &t),
    }
    .map_err(RemeshError::Field)
}

/// The Hermitian matrix `L` of the energy on the free faces (full, as
/// triplets), its right-hand side `b` from the fixed ones, and the mean
/// edge weight.
fn assemble(
    surface: &Surface,
    unknown: &[u32],
    z: &[c64],
) -> (Vec<(u32, u32, c64)>, Vec<c64>, f64) {
    let n = unknown.iter().filter(|&&u| u != u32::MAX).count();
    let mut t = Vec::with_capacity(8 * n);
    let mut b = vec![c64::new(0.0, 0.0); n];
    let (mut wsum, mut wcount) = (0.0, 0usize);
    for e in 0..surface.edges.len() as u32 {
        let [f0, f1] = surface.edge_faces[e as usize];
        if f1 == NO_FACE {
            continue;
        }
        let w = edge_weight(surface, e);
        wsum += w;
        wcount += 1;
        let r = c64::cis(4.0 * (surface.edge_angle(e, f1) - surface.edge_angle(e, f0)));
        let (u0, u1) = (unknown[f0 as usize], unknown[f1 as usize]);
        // w·|z1 − r z0|²: L00 = L11 = w, L10 = −w r, L01 = −w r̄
        for u in [u0, u1] {
            if u != u32::MAX {
                t.push((u, u, c64::new(w, 0.0)));
            }
        }
        match (u0 != u32::MAX, u1 != u32::MAX) {
            (true, true) => {
                t.push((u1, u0, -r * w));
                t.push((u0, u1, -r.conj() * w));
            }
            (true, false) => b[u0 as usize] += r.conj() * z[f1 as usize] * w,
            (false, true) => b[u1 as usize] += r * z[f0 as usize] * w,
            (false, false) => {}
        }
    }
    (
        t,
        b,
        if wcount > 0 {
            wsum / wcount as f64
        } else {
            1.0
        },
    )
}

/// The weight `|e|² / (A_f0 + A_f1)` of interior edge `e`.
fn edge_weight(surface: &Surface, e: u32) -> f64 {
    let [f0, f1] = surface.edge_faces[e as usize];
    let [p, q] = surface.edges[e as usize];
    let d = sub(surface.positions[q as usize], surface.positions[p as usize]);
    dot(d, d) / (surface.areas[f0 as usize] + surface.areas[f1 as usize])
}

/// Scales the unknowns of every component without a fixed face to unit
/// area-weighted norm.
fn normalise_components(sys: &System, x: &mut [c64]) {
    let mut norm2 = vec![0.0; sys.pinned.len()];
    let mut area = vec![0.0; sys.pinned.len()];
    for (k, z) in x.iter().enumerate() {
        norm2[sys.comp[k] as usize] += sys.mass[k] * z.norm_sqr();
        area[sys.comp[k] as usize] += sys.mass[k];
    }
    for (k, z) in x.iter_mut().enumerate() {
        let c = sys.comp[k] as usize;
        if !sys.pinned[c] && norm2[c] > 0.0 {
            *z *= (area[c] / norm2[c]).sqrt();
        }
    }
}

/// The energy `Σ_e w_e·|z_f1 − r_e·z_f0|²` of the angles `angle` (one per
/// face), as minimised by [`cross_field`] (for tests and reports).
pub fn field_energy(surface: &Surface, angle: &[f64]) -> f64 {
    let mut total = 0.0;
    for e in 0..surface.edges.len() as u32 {
        let [_, f1] = surface.edge_faces[e as usize];
        if f1 == NO_FACE {
            continue;
        }
        let w = edge_weight(surface, e);
        let t = crate::field::transported(surface, angle, e);
        let a = 4.0 * (angle[f1 as usize] - t);
        // |z1 − r z0|² with |z| = 1
        total += w * (2.0 - 2.0 * a.cos());
    }
    total
}
