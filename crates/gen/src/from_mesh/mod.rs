//! Maps from meshes: exact oracles for extraction.
//!
//! Input: a quad mesh ([`QuadMesh`], consistently oriented, boundary
//! allowed) or a hex mesh ([`HexMesh`], VTK/MEDIT corner order of
//! [`dualex_cells::cells`], positive hexes), and [`FromMeshOptions`].
//!
//! Output ([`FromQuads`] / [`FromHexes`]): a [`TriMap`] / [`TetMap`] in
//! which every element is its own chart `[0,k]^D` (element corner `c` at
//! the cube corner of the same bits: VTK index `[0,1,3,2][x+2y] + 4z`),
//! refined into `k^D` sub-cells, each split into simplices
//! ([`Diagonal`] in 2D, [`TetSplit`] in 3D); the refined mesh `M_k` itself
//! ([`QuadMesh`] / [`HexMesh`]) and its counts ([`Expected`] /
//! [`ExpectedHex`]), computed by construction, never by extraction.
//!
//! Invariants (checked by the tests):
//! - sub-vertices on shared edges / faces are one global vertex (keyed by
//!   their multilinear weights on the element's corner vertices), so the
//!   simplex mesh is conformal and manifold wherever the input is;
//! - the map is exactly grid preserving: the transitions are the grid
//!   rotations + integer translations relating neighbouring elements'
//!   frames, and every perturbation but [`Jitter`] keeps them exact
//!   (noise is one displacement per vertex carried through every chart by
//!   the charts' relative rotations, projected onto the subspace fixed by
//!   the vertex's holonomy: free at regular vertices, along the edge on a
//!   3D singular edge, zero at singular vertices; boundary vertices are not
//!   displaced, so the boundary stays on the grid);
//! - every simplex is positively oriented in its clean chart.
//!
//! Without `half_shift` the mesh vertices sit on integer grid points and
//! the expected extraction is `M_k`. With `half_shift` (2D only) every
//! vertex, singular ones included, sits on a cell centre (on a dual node
//! under the usual ½ shift of the extraction); the map still carries
//! `M_k`, which an extraction that chooses its grid offset (0 instead of
//! ½: the singular vertices then sit on grid points again) gives exactly:
//! the expected mesh is `M_k` too.

mod classify;
mod count;
pub mod dense;
mod fold;
#[cfg(test)]
mod fold_tests;
pub mod meshes;
mod messy;
mod perturb;
mod refine;
mod split;
#[cfg(test)]
mod tests;

pub use classify::VertexClass;
pub use count::{expected_hex, expected_quad};

use crate::block::ExpectedHex;
use crate::expected::Expected;
use crate::Diagonal;
use dualex_cells::{HexMesh, QuadMesh};
use dualex_map::{TetMap, TriMap};

/// How each sub-cube is split into tets (both conformal across hexes
/// whatever their frames: they only depend on global vertex ids).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum TetSplit {
    /// Every sub-face along the diagonal through its least vertex id; the
    /// sub-cube coned from its least vertex over the 3 faces not holding
    /// it: 6 tets.
    #[default]
    LeastVertex,
    /// The same face diagonals, coned from a new vertex at the sub-cube
    /// centre: 12 tets. Without noise the centre is exactly a dual node
    /// (a half-integer point), a vertex of 12 tets and on their faces.
    Centre,
}

/// Independent per-corner perturbation of the map coordinates (breaks
/// exactness: transitions become non-integer by about `amplitude`).
#[derive(Clone, Debug, PartialEq)]
pub struct Jitter {
    /// Half-width per coordinate, map units (keep tiny: 1e-12 … 1e-3).
    pub amplitude: f64,
    /// Vertex classes whose corners are jittered.
    pub classes: Vec<VertexClass>,
    /// Probability that a vertex of a chosen class is jittered (1: all).
    pub fraction: f64,
}

/// Thin slivers next to singular vertices: `count` edges from a singular
/// vertex (boundary-free classes first) split at parameter `lambda`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Slivers {
    /// Number of edge splits.
    pub count: usize,
    /// Split parameter from the singular end (≈ 1e-9 … 1e-15).
    pub lambda: f64,
}

/// Options of [`from_quads`] / [`from_hexes`].
#[derive(Clone, Debug, PartialEq)]
pub struct FromMeshOptions {
    /// Grid cells per element edge (`k >= 1`).
    pub scale: usize,
    /// Noise half-width per axis, grid units (0 … 1).
    pub noise: f64,
    /// A few large (±1.5) displacements next to singular vertices / edges.
    pub folds: bool,
    /// Folds centred on this many interior singular vertices (radius 1.5,
    /// amplitude 3 elements, scaled by `k`; see `fold.rs`), exactly GP.
    pub singular_folds: usize,
    /// Multiply every chart coordinate by this (≥ 1) at the end: the same
    /// simplices, grid points inside them; the expected mesh is then
    /// `M_{scale·magnify}` ("the same map scaled by k").
    pub magnify: usize,
    /// Seed of every random choice.
    pub seed: u64,
    /// Add ½ to every chart coordinate (2D only).
    pub half_shift: bool,
    /// Sub-cell split in 2D.
    pub diagonal: Diagonal,
    /// Sub-cube split in 3D.
    pub tet_split: TetSplit,
    /// Non-exact per-corner jitter.
    pub jitter: Option<Jitter>,
    /// Slivers near singular vertices (exactly GP).
    pub slivers: Option<Slivers>,
}

impl Default for FromMeshOptions {
    fn default() -> Self {
        FromMeshOptions {
            scale: 1,
            noise: 0.0,
            folds: false,
            singular_folds: 0,
            magnify: 1,
            seed: 1,
            half_shift: false,
            diagonal: Diagonal::Alternating,
            tet_split: TetSplit::LeastVertex,
            jitter: None,
            slivers: None,
        }
    }
}

/// Why a mesh cannot be turned into a map.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum FromMeshError {
    /// `scale` is 0 or too large (more than 2²⁴ sub-cells).
    Scale(usize),
    /// The mesh has no element.
    Empty,
    /// An element refers to a missing vertex or repeats one.
    BadElement {
        /// Element index.
        element: usize,
    },
    /// A vertex position is not finite.
    NonFinite {
        /// Vertex index.
        vertex: usize,
    },
    /// An option value is out of range.
    Option(String),
}

impl std::fmt::Display for FromMeshError {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            FromMeshError::Scale(k) => write!(f, "scale {k}: must be 1 or more (and small)"),
            FromMeshError::Empty => write!(f, "the mesh has no element"),
            FromMeshError::BadElement { element } => {
                write!(f, "element {element}: vertex out of range or repeated")
            }
            FromMeshError::NonFinite { vertex } => {
                write!(f, "vertex {vertex}: position is not finite")
            }
            FromMeshError::Option(m) => write!(f, "{m}"),
        }
    }
}

impl std::error::Error for FromMeshError {}

/// A triangle map made from a quad mesh.
#[derive(Clone, Debug)]
pub struct FromQuads {
    /// The map (one chart per quad).
    pub map: TriMap,
    /// The input refined `k` times (`M_k`).
    pub refined: QuadMesh,
    /// What extraction should give (see the module docs for `half_shift`).
    pub expected: Expected,
    /// Class of every map vertex.
    pub classes: Vec<VertexClass>,
}

/// A tet map made from a hex mesh.
#[derive(Clone, Debug)]
pub struct FromHexes {
    /// The map (one chart per hex).
    pub map: TetMap,
    /// The input refined `k` times (`M_k`).
    pub refined: HexMesh,
    /// What extraction should give.
    pub expected: ExpectedHex,
    /// Class of every map vertex.
    pub classes: Vec<VertexClass>,
}

fn check_options(opts: &FromMeshOptions, elements: usize, dim: u32) -> Result<(), FromMeshError> {
    let k = opts.scale.saturating_mul(opts.magnify);
    if opts.magnify == 0 || k == 0 || k > 256 || elements.saturating_mul(k.pow(dim)) > 1 << 24 {
        return Err(FromMeshError::Scale(k));
    }
    if !(0.0..=1.0).contains(&opts.noise) {
        return Err(FromMeshError::Option(format!(
            "noise {}: must be in [0, 1]",
            opts.noise
        )));
    }
    if let Some(j) = &opts.jitter {
        if !(j.amplitude >= 0.0 && j.amplitude <= 0.5) {
            return Err(FromMeshError::Option(format!(
                "jitter {}: must be in [0, 0.5]",
                j.amplitude
            )));
        }
    }
    if opts.slivers.is_some() && opts.magnify > 1 {
        // sliver offsets use all 52 bits: times 3 would round
        return Err(FromMeshError::Option(
            "slivers and magnify: not together (magnifying would round)".into(),
        ));
    }
    if let Some(s) = opts.slivers {
        if !(s.lambda > 0.0 && s.lambda < 0.5) {
            return Err(FromMeshError::Option(format!(
                "sliver parameter {}: must be in (0, 0.5)",
                s.lambda
            )));
        }
    }
    Ok(())
}

/// `M_{scale·magnify}`: `base` (`M_scale`, whose vertices are the map's),
/// or the input refined again.
fn magnified<const D: usize, const K: usize, M>(
    base: M,
    opts: &FromMeshOptions,
    mesh_of: impl Fn(&refine::Refined<D>) -> M,
    input: &dualex_cells::cells::CellMesh<K>,
) -> Result<M, FromMeshError> {
    if opts.magnify == 1 {
        return Ok(base);
    }
    let k = opts.scale * opts.magnify;
    Ok(mesh_of(&refine::Refined::<D>::new(
        &input.positions,
        &input.cells,
        k,
    )?))
}

/// Every chart coordinate times `m` (exact: integers times values with
/// at most 32 fractional bits, well below 2⁵³).
fn magnify<const N: usize, const D: usize>(map: &mut dualex_map::SimplexMap<N, D>, m: usize) {
    if m == 1 {
        return;
    }
    for x in map.coords.iter_mut().flatten().flatten() {
        *x *= m as f64;
    }
}

/// The displacements of the folds at singular vertices, if asked for
/// (`per_cell` simplices per sub-cell).
fn singular_folds<const N: usize, const D: usize>(
    map: &dualex_map::SimplexMap<N, D>,
    r: &refine::Refined<D>,
    stars: &[classify::Star<D>],
    classes: &[VertexClass],
    opts: &FromMeshOptions,
    per_cell: usize,
) -> Option<Vec<[f64; D]>> {
    if opts.singular_folds == 0 {
        return None;
    }
    let centres = fold::centres(r, classes, opts.singular_folds, opts.seed);
    let per_element = per_cell * r.k.pow(D as u32);
    debug_assert_eq!(map.simplices.len(), r.elements * per_element);
    Some(fold::displacements(map, r, stars, &centres, per_element))
}

/// The triangle map of a quad mesh (module docs).
pub fn from_quads(mesh: &QuadMesh, opts: &FromMeshOptions) -> Result<FromQuads, FromMeshError> {
    check_options(opts, mesh.cells.len(), 2)?;
    let r = refine::Refined::<2>::new(&mesh.positions, &mesh.cells, opts.scale)?;
    let base = r.quad_mesh();
    let shift = if opts.half_shift { 0.5 } else { 0.0 };
    let (simplices, coords) = split::triangles(&r, opts.diagonal, shift);
    let mut map = TriMap {
        positions: r.positions.clone(),
        simplices,
        coords,
    };
    let stars = classify::stars(&map);
    let mut classes = classify::classify(&stars, &classify::from_quad_mesh(&base));
    let extra = singular_folds(&map, &r, &stars, &classes, opts, 2);
    perturb::perturb(&mut map, &classes, &stars, opts, extra.as_deref());
    if let Some(s) = opts.slivers {
        messy::slivers(&mut map, &mut classes, s, opts.seed);
    }
    if let Some(j) = &opts.jitter {
        messy::jitter(&mut map, &classes, j, opts.seed);
    }
    magnify(&mut map, opts.magnify);
    let refined = magnified(base, opts, |r| r.quad_mesh(), mesh)?;
    let expected = expected_quad(&refined);
    Ok(FromQuads {
        map,
        refined,
        expected,
        classes,
    })
}

/// The tet map of a hex mesh (module docs; `half_shift` is refused).
pub fn from_hexes(mesh: &HexMesh, opts: &FromMeshOptions) -> Result<FromHexes, FromMeshError> {
    check_options(opts, mesh.cells.len(), 3)?;
    if opts.half_shift {
        return Err(FromMeshError::Option(
            "half shift: only for quad meshes".into(),
        ));
    }
    let r = refine::Refined::<3>::new(&mesh.positions, &mesh.cells, opts.scale)?;
    let base = r.hex_mesh();
    let (positions, simplices, coords) = split::tets(&r, opts.tet_split);
    let mut map = TetMap {
        positions,
        simplices,
        coords,
    };
    let stars = classify::stars(&map);
    let mut classes = classify::classify(&stars, &classify::from_hex_mesh(&base));
    let per_cube = match opts.tet_split {
        TetSplit::LeastVertex => 6,
        TetSplit::Centre => 12,
    };
    let extra = singular_folds(&map, &r, &stars, &classes, opts, per_cube);
    perturb::perturb(&mut map, &classes, &stars, opts, extra.as_deref());
    if let Some(s) = opts.slivers {
        messy::slivers(&mut map, &mut classes, s, opts.seed);
    }
    if let Some(j) = &opts.jitter {
        messy::jitter(&mut map, &classes, j, opts.seed);
    }
    magnify(&mut map, opts.magnify);
    let refined = magnified(base, opts, |r| r.hex_mesh(), mesh)?;
    let expected = expected_hex(&refined);
    Ok(FromHexes {
        map,
        refined,
        expected,
        classes,
    })
}
