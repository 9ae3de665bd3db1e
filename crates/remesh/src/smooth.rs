//! The smoothest 4-RoSy field, aligned to the boundary and sharp edges.
//!
//! Input: a [`Surface`] and [`FieldOptions`]. Output: a [`FieldResult`]:
//! the [`CrossField`] (angles, matchings by [`CrossField::from_angles`]),
//! its singular vertices ([`crate::singularity`]) and the feature edges.
//!
//! Method: each face carries `z_f = exp(4iθ_f)` (the four directions of a
//! cross as one complex number). The energy is
//! `Σ_e w_e·|z_f1 − r_e·z_f0|²` over the interior edges, with the
//! connection `r_e = exp(4i·(edge_angle(e, f1) − edge_angle(e, f0)))`
//! (the transport of [`crate::field`]) and `w_e = |e|² / (A_f0 + A_f1)`.
//! Faces beside a boundary edge or a sharp edge (dihedral angle above
//! [`FieldOptions::sharp_degrees`]) are fixed to that edge's direction
//! (the longest such edge of the face); sharp edges count only on
//! feature curves ([`crate::features`]). The energy is that of the
//! surface smoothed along its normals ([`crate::denoise`],
//! [`FieldOptions::denoise_steps`]); the field is carried back to the
//! input's frames, and its matchings and singularities are the input's. The complex system is written as
//! a real one of twice the size and solved by sparse Cholesky
//! ([`crate::sparse`]) of `L + ε·M` (`M` the face areas, `ε` tiny, which
//! makes the matrix definite everywhere), iterated as
//! `x ← (L + εM)⁻¹ (b + εM·x)`:
//! - in a connected component with fixed faces this converges (at rate
//!   `ε/(λ_min + ε)`, a few steps) to the constrained minimiser;
//! - in a component without any (a closed smooth surface) `b = 0` there
//!   and the step is inverse iteration, normalised per component: it
//!   converges to the smallest eigenvector of `L z = λ M z`, the
//!   smoothest unit field, from a fixed pseudo-random start. Inverse
//!   iteration was chosen over "fix one face" because the latter biases
//!   the field near the fixed face.
//!
//! The minimiser of this relaxed energy lets `|z|` shrink where the field
//! must turn, which raises the energy of the unit field `z/|z|` that is
//! kept. [`FieldOptions::unit_steps`] then alternates "project to unit
//! length" and one implicit diffusion step `(L + μM) z' = b + μM·z/|z|`
//! (a second numeric factorisation, the symbolic one reused): measured
//! with six steps of `μ = 0.1`, the unit energy drops by 3 % (icosphere,
//! 20k faces) to 15 % (torus); more steps or other `μ` gain little. The
//! linear iteration stops after six solves: on the sphere and the torus
//! fewer leave extra singularity pairs, more change nothing.
//! Neither step removes the ± singularity pairs that the smoothest field
//! of a torus of revolution has on its inner side (four to six pairs
//! on the test tori of radii 3 and 1): their index sum is right (0), but the
//! principal-direction field, without singularities, has a lower unit
//! energy. Curvature alignment would be the fix; it is not done here.
//!
//! Quarter singularities: a singular vertex of index +½ or more (a
//! valence ≤ 2 vertex of the quad mesh, a collapsed map at +1) has its
//! star fixed to a field turning by at most a quarter and the field is
//! solved again, up to [`QUARTER_ROUNDS`] times ([`crate::quarters`]):
//! on a fan cap's disc the +1 becomes four +¼.
//!
//! Cost, measured (`cargo test -p dualex-remesh --profile ci --test
//! field_cut -- --ignored --nocapture`, one thread, 2 shared cores at a
//! load of ~2): 0.52 s on an 82k-face icosphere, 0.69 s on a 100k-face
//! torus (two factorisations 0.22 + 0.17 s, twelve solves 0.25 s),
//! 2.6 s on 328k faces (the fill-in grows faster than the size). Under
//! a load of ~8 the same runs took about twice as long.

pub use crate::features::sharp_edges;
use crate::features::{feature_edges, MinCurve};
use crate::field::CrossField;
use crate::singularity::{boundary_indices, vertex_indices};
use crate::sparse::HpdSolver;
use crate::surface::{dot, norm, sub, Surface, NO_FACE};
use dualex_util::timing::Laps;
use faer::c64;

/// Options of [`cross_field`].
#[derive(Clone, Debug)]
pub struct FieldOptions {
    /// Interior edges whose faces' normals differ by more than this (in
    /// degrees) are sharp: the field follows them.
    pub sharp_degrees: f64,
    /// Shortest feature curve followed: sharp edges on shorter curves are
    /// noise ([`crate::features`]; `edges` 0 or 1: every sharp edge).
    pub min_feature: MinCurve,
    /// Normal smoothing steps of the surface the field is solved on
    /// ([`crate::denoise`]; 0: the input itself).
    pub denoise_steps: u32,
    /// Whether faces beside the boundary follow it.
    pub align_boundary: bool,
    /// Most solves of the linear iteration (one factorisation for all).
    pub max_iterations: u32,
    /// Steps of "project to unit length, then diffuse" after the linear
    /// solve (0: none).
    pub unit_steps: u32,
    /// The diffusion of those steps: `(L + μM) z' = b + μM·z/|z|` with
    /// `μ = unit_shift · mean edge weight / mean face area`.
    pub unit_shift: f64,
}

impl Default for FieldOptions {
    fn default() -> Self {
        FieldOptions {
            sharp_degrees: 35.0,
            min_feature: MinCurve {
                edges: 8,
                fraction: 0.1,
            },
            denoise_steps: 2,
            align_boundary: true,
            max_iterations: 6,
            unit_steps: 6,
            unit_shift: 0.1,
        }
    }
}

/// Most rounds of "fix the star of every singular vertex of index +1/2
/// or more, solve again" ([`crate::quarters`]): one splits a disc's +1
/// into four quarters; a second catches a +1/2 the first left beside it.
pub const QUARTER_ROUNDS: usize = 3;

/// A cross field with its singularities and the edges it follows.
#[derive(Clone, Debug)]
pub struct FieldResult {
    /// The field and its matchings.
    pub field: CrossField,
    /// Interior vertices of nonzero index, as `(vertex, quarters)`: the
    /// index is `quarters / 4` (see [`crate::singularity`]).
    pub singularities: Vec<(u32, i32)>,
    /// Boundary vertices of nonzero index, as `(vertex, quarters)` (see
    /// [`crate::singularity::boundary_indices`]; empty unless the field
    /// follows the boundary).
    pub boundary_singularities: Vec<(u32, i32)>,
    /// Per edge: a sharp interior edge (boundary edges are `false`).
    pub sharp: Vec<bool>,
    /// Per face: its direction was fixed to a boundary or sharp edge.
    pub fixed: Vec<bool>,
    /// Wall-clock laps of the steps: (name, milliseconds).
    pub laps: Vec<(String, f64)>,
}

/// The smoothest cross field of `surface`; see the module docs.
pub fn cross_field(surface: &Surface, opts: &FieldOptions) -> Result<FieldResult, String> {
    let nf = surface.triangles.len();
    if nf == 0 {
        return Err("cross field: the surface has no triangle".into());
    }
    if !(opts.sharp_degrees.is_finite() && opts.sharp_degrees > 0.0) {
        return Err(format!(
            "cross field: sharp angle {} is not a positive number of degrees",
            opts.sharp_degrees
        ));
    }
    if opts.unit_steps > 0 && !(opts.unit_shift.is_finite() && opts.unit_shift > 0.0) {
        return Err(format!(
            "cross field: unit-step shift {} is not a positive number",
            opts.unit_shift
        ));
    }
    let mut laps = Laps::start();
    check_manifold_vertices(surface)?;
    let sharp = feature_edges(surface, opts.sharp_degrees, opts.min_feature);
    let fixed_angle = fixed_directions(surface, &sharp, opts.align_boundary);
    // the field is solved on the denoised surface, then carried back
    let denoised = crate::denoise::smoothed(surface, opts.denoise_steps, &sharp);
    let on = denoised.as_ref().unwrap_or(surface);
    let mut fixed_on = match &denoised {
        Some(d) => fixed_directions(d, &sharp, opts.align_boundary),
        None => fixed_angle.clone(),
    };
    laps.lap("field: checks, constraints, denoising");
    let mut z = solve_field(on, &fixed_on, opts, &mut laps)?;
    let angles = |z: &[c64]| -> Vec<f64> {
        (0..nf)
            .map(|f| match fixed_angle[f] {
                Some(a) => a,
                None => {
                    z[f].arg() / 4.0
                        + denoised
                            .as_ref()
                            .map_or(0.0, |d| crate::denoise::frame_turn(d, surface, f as u32))
                }
            })
            .collect()
    };
    let mut field = CrossField::from_angles(surface, angles(&z));
    let mut singularities = vertex_indices(surface, &field);
    // quarter singularities in place of +1/2 and +1 (crate::quarters)
    for _ in 0..QUARTER_ROUNDS {
        let mut pinned = false;
        for &(v, q) in &singularities {
            if q >= 2 {
                pinned |= crate::quarters::pin_star(on, &z, &mut fixed_on, v);
            }
        }
        if !pinned {
            break;
        }
        z = solve_field(on, &fixed_on, opts, &mut laps)?;
        field = CrossField::from_angles(surface, angles(&z));
        singularities = vertex_indices(surface, &field);
    }
    let boundary_singularities = if opts.align_boundary {
        boundary_indices(surface, &field)
    } else {
        Vec::new()
    };
    laps.lap("field: matchings, singularities");
    let fixed = fixed_angle.iter().map(Option::is_some).collect();
    Ok(FieldResult {
        field,
        singularities,
        boundary_singularities,
        sharp,
        fixed,
        laps: laps.into_laps(),
    })
}

/// An error naming the first vertex whose faces form more than one fan
/// (two sheets touching at a vertex): its index would be meaningless.
fn check_manifold_vertices(surface: &Surface) -> Result<(), String> {
    let uncut = crate::cut::Cut {
        is_cut: vec![false; surface.edges.len()],
    };
    let (corners, count) = uncut.corner_vertices(surface);
    let mut owner = vec![u32::MAX; count as usize];
    for (t, c) in surface.triangles.iter().zip(&corners) {
        for i in 0..3 {
            owner[c[i] as usize] = t[i];
        }
    }
    let mut fans = vec![0u32; surface.positions.len()];
    for v in owner {
        fans[v as usize] += 1;
        if fans[v as usize] > 1 {
            return Err(format!(
                "cross field: vertex {v} is not manifold (its triangles form several fans)"
            ));
        }
    }
    Ok(())
}

/// Per face: the direction of its longest boundary or sharp edge, if any.
fn fixed_directions(surface: &Surface, sharp: &[bool], boundary: bool) -> Vec<Option<f64>> {
    (0..surface.triangles.len() as u32)
        .map(|f| {
            let mut best: Option<(f64, u32)> = None;
            for &e in &surface.face_edges[f as usize] {
                let feature = sharp[e as usize] || (boundary && surface.is_boundary_edge(e));
                if !feature {
                    continue;
                }
                let [a, b] = surface.edges[e as usize];
                let len = norm(sub(
                    surface.positions[b as usize],
                    surface.positions[a as usize],
                ));
                if best.is_none_or(|(l, _)| len > l) {
                    best = Some((len, e));
                }
            }
            best.map(|(_, e)| surface.edge_angle(e, f))
        })
        .collect()
}

/// Connected components of the faces across interior edges.
pub(crate) fn face_components(surface: &Surface) -> (Vec<u32>, u32) {
    let nf = surface.triangles.len();
    let mut comp = vec![u32::MAX; nf];
    let mut count = 0;
    let mut stack = Vec::new();
    for start in 0..nf {
        if comp[start] != u32::MAX {
            continue;
        }
        comp[start] = count;
        stack.push(start as u32);
        while let Some(f) = stack.pop() {
            for &e in &surface.face_edges[f as usize] {
                let [f0, f1] = surface.edge_faces[e as usize];
                let g = if f0 == f { f1 } else { f0 };
                if g != NO_FACE && comp[g as usize] == u32::MAX {
                    comp[g as usize] = count;
                    stack.push(g);
                }
            }
        }
        count += 1;
    }
    (comp, count)
}

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
fn solve_field(
    surface: &Surface,
    fixed: &[Option<f64>],
    opts: &FieldOptions,
    laps: &mut Laps,
) -> Result<Vec<c64>, String> {
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
        let mut y = solver
            .solve(&rhs)
            .map_err(|e| format!("cross field: {e}"))?;
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
            x = solver
                .solve(&rhs)
                .map_err(|e| format!("cross field: {e}"))?;
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
fn shifted(sys: &System, shift: f64, like: Option<&HpdSolver>) -> Result<HpdSolver, String> {
    let mut t = sys.laplacian.clone();
    for (k, &m) in sys.mass.iter().enumerate() {
        t.push((k as u32, k as u32, c64::new(shift * m, 0.0)));
    }
    match like {
        Some(s) => s.refactor(&t),
        None => HpdSolver::new(sys.mass.len(), &t),
    }
    .map_err(|e| format!("cross field: {e}"))
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
