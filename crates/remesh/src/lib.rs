//! # dualex-remesh — a grid-preserving map for a plain triangle surface
//!
//! The cheap pipeline real tools use, as the paper's evaluation did
//! ("field integration as geometric objective and rounding as
//! quantization"). The steps are numbered as the driver [`pipeline`] runs them, one call
//! each:
//!
//! | step | module | input → output |
//! |---|---|---|
//! | 0. connectivity, face frames (the input) | [`surface`] | positions, triangles → [`Surface`] |
//! | 1. long edges split (fans, strips) | [`refine`] | [`Surface`] → the same surface, edges ≤ 2 quad edges |
//! | 2. feature curves | [`features`] | dihedral threshold → the sharp edges on curves (noise dropped) |
//! | 3. denoised surface for the field | [`denoise`] | [`Surface`] → the same smoothed along its normals |
//! | 4. smoothest 4-RoSy field | [`smooth`] (type in [`field`]) | [`Surface`] → [`CrossField`] (angle per face, matching per edge), aligned to boundary and sharp edges |
//! | 4. its singular vertices | [`singularity`] | field → `(vertex, index·4)` |
//! | 5. quarters for +½ and +1 | [`quarters`] | a singular vertex's star fixed, the field solved again |
//! | 6. the seed's turn of free components | [`pipeline`] | the field turned where nothing fixes it |
//! | 7. cut to a disk | [`cut`] | singularities → cut edges leaving a disk; the field combed on it |
//! | 8. seamless integration | [`integrate`](mod@integrate) | field + cut → per-corner `(u, v)` |
//! | 9. facing boundary walls | [`integrate::facing`] | continuous map → walls across a strip, to round apart ([`separate`]) |
//! | 9. rounding | [`quantize`] | integer unknowns rounded at once, one more solve |
//! | 10. the extraction's count | [`recount`] | a count that misses `N` → the map once more for the area it asks |
//! | 11. the numbers | [`pipeline`] | → [`RemeshStats`] |
//!
//! The output is a [`dualex_map::TriMap`] that `dualex quad` extracts.
//! Errors are [`RemeshError`] (and [`SolveError`] beneath), naming the
//! step and the element ([`error`]).
//!
//! Beside the steps: [`sparse`] (the sparse Cholesky solves, over `faer`)
//! and [`shapes`] (generated test surfaces: sphere, torus, cube, polycube
//! of genus `g`, patches with boundary; [`shapes_cad`]: CAD-style
//! tessellations, fan caps and strips; [`shapes_sweep`]: genus 0–8 and
//! 1–8 close holes, the sweep's surfaces).
//!
//! Invariants: [`Surface`] is an oriented 2-manifold (with or without
//! boundary) without degenerate triangles; every edge has one or two faces.
#![forbid(unsafe_code)]

pub mod cut;
pub mod denoise;
pub mod error;
pub mod features;
pub mod field;
pub mod integrate;
pub mod pipeline;
pub mod quantize;
pub mod quarters;
pub mod recount;
pub mod refine;
pub mod separate;
pub mod shapes;
pub mod shapes_cad;
pub mod shapes_sweep;
pub mod singularity;
pub mod smooth;
pub mod sparse;
mod stats_json;
pub mod surface;
pub mod weld;

pub use cut::{cut_to_disk, Cut};
pub use error::{RemeshError, SolveError};
pub use field::CrossField;
pub use integrate::{integrate, integrate_report, IntegrateOptions, IntegrateReport};
pub use pipeline::{
    remesh, remesh_counted, Quantization, RemeshOptions, RemeshStats, Remeshed, Target,
};
pub use quantize::Rounding;
pub use recount::CountQuads;
pub use smooth::{cross_field, FieldOptions, FieldResult};
pub use surface::{Surface, SurfaceError, NO_FACE};
