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

use crate::error::RemeshError;
pub use crate::features::sharp_edges;
use crate::features::{feature_edges, MinCurve};
use crate::field::CrossField;
use crate::singularity::{boundary_indices, vertex_indices};
use crate::surface::{norm, sub, Surface, NO_FACE};
use dualex_util::timing::Laps;
use faer::c64;
pub use solve::field_energy;
use solve::solve_field;

mod solve;

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

/// The smoothest cross field of `surface`; see the module docs. Steps
/// 2–5 of the pipeline ([`crate::pipeline`]), in its order:
/// [`features`], [`denoise`], [`solve`], [`quarters`], then
/// [`Solved::result`].
pub fn cross_field(surface: &Surface, opts: &FieldOptions) -> Result<FieldResult, RemeshError> {
    let mut laps = Laps::start();
    let features = features(surface, opts)?;
    let mut on = denoise(surface, opts, features);
    laps.lap("field: checks, constraints, denoising");
    let mut solved = solve(surface, &on, opts, &mut laps)?;
    quarters(surface, &mut on, opts, &mut solved, &mut laps)?;
    Ok(solved.result(surface, on, opts, laps))
}

/// What step 2 ([`features`]) finds: the feature edges and the
/// directions they and the boundary fix on the input.
pub struct Features {
    /// Per edge: a sharp interior edge on a feature curve.
    pub sharp: Vec<bool>,
    /// Per face: the direction of its longest boundary or sharp edge.
    fixed: Vec<Option<f64>>,
}

/// The surface the field is solved on (step 3, [`denoise`]) with the
/// [`Features`] of the input.
pub struct FieldInput {
    /// The input's features.
    features: Features,
    /// The denoised surface (`None`: the input itself).
    denoised: Option<Surface>,
    /// Per face of the surface solved on: its fixed direction, the stars
    /// pinned by [`quarters`] included.
    fixed_on: Vec<Option<f64>>,
}

impl FieldInput {
    /// The surface the field is solved on.
    fn on<'a>(&'a self, surface: &'a Surface) -> &'a Surface {
        self.denoised.as_ref().unwrap_or(surface)
    }
}

/// The field solved (steps 4–5): `z` per face of the surface solved on,
/// the field carried back to the input and its singular vertices.
pub struct Solved {
    z: Vec<c64>,
    field: CrossField,
    singularities: Vec<(u32, i32)>,
}

/// Step 2: the options and the surface checked (a triangle at least,
/// manifold vertices), the feature curves ([`crate::features`]) and the
/// directions fixed by them and the boundary.
pub fn features(surface: &Surface, opts: &FieldOptions) -> Result<Features, RemeshError> {
    if surface.triangles.is_empty() {
        return Err(RemeshError::NoTriangle);
    }
    if !(opts.sharp_degrees.is_finite() && opts.sharp_degrees > 0.0) {
        return Err(RemeshError::SharpAngle(opts.sharp_degrees));
    }
    if opts.unit_steps > 0 && !(opts.unit_shift.is_finite() && opts.unit_shift > 0.0) {
        return Err(RemeshError::UnitShift(opts.unit_shift));
    }
    check_manifold_vertices(surface)?;
    let sharp = feature_edges(surface, opts.sharp_degrees, opts.min_feature);
    let fixed = fixed_directions(surface, &sharp, opts.align_boundary);
    Ok(Features { sharp, fixed })
}

/// Step 3: the surface denoised along its normals ([`crate::denoise`]),
/// with its fixed directions; the field is solved on it, then carried
/// back.
pub fn denoise(surface: &Surface, opts: &FieldOptions, features: Features) -> FieldInput {
    let denoised = crate::denoise::smoothed(surface, opts.denoise_steps, &features.sharp);
    let fixed_on = match &denoised {
        Some(d) => fixed_directions(d, &features.sharp, opts.align_boundary),
        None => features.fixed.clone(),
    };
    FieldInput {
        features,
        denoised,
        fixed_on,
    }
}

/// Step 4: the smoothest field on the surface of `input`, carried back
/// to `surface`, and its singular vertices ([`crate::singularity`]).
pub fn solve(
    surface: &Surface,
    input: &FieldInput,
    opts: &FieldOptions,
    laps: &mut Laps,
) -> Result<Solved, RemeshError> {
    let z = solve_field(input.on(surface), &input.fixed_on, opts, laps)?;
    let field = CrossField::from_angles(surface, angles(surface, input, &z));
    let singularities = vertex_indices(surface, &field);
    Ok(Solved {
        z,
        field,
        singularities,
    })
}

/// Step 5: quarter singularities in place of +1/2 and +1
/// ([`crate::quarters`]): their stars pinned and the field solved again,
/// up to [`QUARTER_ROUNDS`] times.
pub fn quarters(
    surface: &Surface,
    input: &mut FieldInput,
    opts: &FieldOptions,
    solved: &mut Solved,
    laps: &mut Laps,
) -> Result<(), RemeshError> {
    for _ in 0..QUARTER_ROUNDS {
        let mut pinned = false;
        let on = input.denoised.as_ref().unwrap_or(surface);
        for &(v, q) in &solved.singularities {
            if q >= 2 {
                pinned |= crate::quarters::pin_star(on, &solved.z, &mut input.fixed_on, v);
            }
        }
        if !pinned {
            break;
        }
        *solved = solve(surface, input, opts, laps)?;
    }
    Ok(())
}

impl Solved {
    /// The [`FieldResult`]: the field, its interior and boundary
    /// singularities, the features.
    pub fn result(
        self,
        surface: &Surface,
        input: FieldInput,
        opts: &FieldOptions,
        mut laps: Laps,
    ) -> FieldResult {
        let boundary_singularities = if opts.align_boundary {
            boundary_indices(surface, &self.field)
        } else {
            Vec::new()
        };
        laps.lap("field: matchings, singularities");
        let Features { sharp, fixed } = input.features;
        FieldResult {
            field: self.field,
            singularities: self.singularities,
            boundary_singularities,
            sharp,
            fixed: fixed.iter().map(Option::is_some).collect(),
            laps: laps.into_laps(),
        }
    }
}

/// The field's angle per face of `surface` from `z` on the surface of
/// `input`: a fixed face keeps its direction, a free one turns by the
/// denoised frame's turn ([`crate::denoise::frame_turn`]).
fn angles(surface: &Surface, input: &FieldInput, z: &[c64]) -> Vec<f64> {
    let fixed = &input.features.fixed;
    (0..surface.triangles.len())
        .map(|f| match fixed[f] {
            Some(a) => a,
            None => {
                z[f].arg() / 4.0
                    + input
                        .denoised
                        .as_ref()
                        .map_or(0.0, |d| crate::denoise::frame_turn(d, surface, f as u32))
            }
        })
        .collect()
}

/// An error naming the first vertex whose faces form more than one fan
/// (two sheets touching at a vertex): its index would be meaningless.
fn check_manifold_vertices(surface: &Surface) -> Result<(), RemeshError> {
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
            return Err(RemeshError::NonManifoldVertex { vertex: v });
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
