//! The stage's driver, one generic function for quads and hexes
//! ([`quads`] and [`hexes`] only gather what differs: corner tables,
//! frames, the measure, the reference and which vertices lie on it), in
//! numbered steps (`stage/steps.rs`):
//!
//! 1. measure before, the mean edge; nothing else when the mode is off or
//!    there is nothing to do;
//! 2. the reference, quads measured again against the triangles nearest
//!    their centres; the constraints;
//! 3. the boundary vertices onto the input's boundary;
//! 4. the optimisation: a. smoothing (`--smooth`); b. the untangling
//!    attempts (a wide fold spread, growing rings, the feature release);
//! 5. the positions with the fewest inverted cells kept;
//! 6. the report's moves and boundary distances.

use crate::constraint::Role;
use crate::quality::{self, cross, sub, unit, HEX_CORNER_EDGES, QUAD_CORNER_EDGES};
use crate::reference::Reference;
use crate::Options;
use dualex_cells::cells::{HEX_EDGES, HEX_FACES};
use rayon::prelude::*;

mod corners;
mod frames;
mod report;
mod spread;
mod steps;
mod topology;
use frames::{quad_frame, Reframe};
pub use report::Report;
use std::time::Instant;
use steps::run;
use topology::boundary_vertices;

/// The stage on a quad mesh lying on the triangle surface
/// (`surface_positions`, `triangles`); `sources[q]`: the triangle holding
/// quad `q`'s node (`u32::MAX`: none). A quad is measured against the
/// triangle nearest its centre ([`Reference::quad_normal`], as `inspect`
/// does); the source triangles only screen a mesh for work (no search:
/// a mesh the screen finds nothing to do on is returned as it is).
/// `closed`: the caller knows that every edge has two quads (its check of
/// these cells found no boundary edge and no face with a repeated or
/// missing vertex), so no vertex is on the boundary and the edges are not
/// matched here; `false` when not known.
pub fn quads(
    positions: &mut [[f64; 3]],
    cells: &[[u32; 4]],
    surface_positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    sources: &[u32],
    closed: bool,
    opts: &Options,
) -> Report {
    let t = Instant::now();
    let mut reference: Option<Reference> = None;
    let make = || Reference::surface(surface_positions, triangles, opts.feature_angle);
    let tri_normal = |t: u32| {
        let [a, b, c] = triangles[t as usize].map(|v| surface_positions[v as usize]);
        unit(cross(sub(b, a), sub(c, a)))
    };
    // the screen: each quad against its source triangle (no search); once
    // the reference exists, against the triangle nearest its centre
    // quad `q`'s source triangle, when it has one
    let source = |q: usize| {
        sources
            .get(q)
            .copied()
            .filter(|&s| (s as usize) < triangles.len())
    };
    // the source triangles' normals in parallel; the reference, built
    // only if a quad has no source, gives the others
    let sourced: Vec<Option<[f64; 3]>> = (0..cells.len())
        .into_par_iter()
        .map(|q| source(q).map(tri_normal))
        .collect();
    let normals: Vec<[f64; 3]> = sourced
        .into_iter()
        .zip(cells)
        .map(|(n, cell)| {
            n.unwrap_or_else(|| {
                let r = reference.get_or_insert_with(make);
                r.quad_normal(&quality::corners(positions, cell))
            })
        })
        .collect();
    let on_boundary = if closed {
        vec![false; positions.len()]
    } else {
        boundary_vertices(positions.len(), cells, &QUAD_EDGES)
    };
    // summed only when the stage goes past its first step
    let nv = positions.len();
    let hint = || {
        let mut hint = vec![[0.0; 3]; nv];
        for (cell, n) in cells.iter().zip(&normals) {
            for &v in cell {
                for k in 0..3 {
                    hint[v as usize][k] += n[k];
                }
            }
        }
        hint
    };
    // each quad's nearest-triangle search starts from the last one found,
    // first its source (less work, the same answer)
    let feet: Vec<std::sync::atomic::AtomicU32> = (0..cells.len())
        .map(|q| std::sync::atomic::AtomicU32::new(source(q).unwrap_or(u32::MAX)))
        .collect();
    let reframe = |x: &[[f64; 3]], ci: usize, r: &Reference| {
        quad_frame(r.quad_normal_cached(&quality::corners(x, &cells[ci]), feet.get(ci)))
    };
    let measure = |x: &[[f64; 3]], frames: &[[[f64; 3]; 2]]| {
        let normals: Vec<[f64; 3]> = frames.iter().map(|f| cross(f[0], f[1])).collect();
        quality::quad_values(x, cells, &normals)
    };
    let input = Input {
        cells,
        corners: &QUAD_CORNER_EDGES.map(|[c, a, b]| [c, a, b, 0]),
        frames: normals.iter().map(|&n| quad_frame(n)).collect(),
        reframe: Some(&reframe),
        edges: &QUAD_EDGES,
        role: Role::Surface,
        on_boundary,
        hint: &hint,
    };
    let mut rep = run(positions, input, &measure, reference, &make, opts);
    rep.time_ms = t.elapsed().as_secs_f64() * 1e3;
    rep
}

/// The stage on a hex mesh inside the tet mesh (`volume_positions`,
/// `tets`): boundary vertices on its boundary surface, whose triangles are
/// the tets' faces `lone` (their places `4·tet + f`, in any order:
/// `dualex_check::topology::lone_tet_faces`, which the caller has for its
/// check already).
pub fn hexes(
    positions: &mut [[f64; 3]],
    cells: &[[u32; 8]],
    volume_positions: &[[f64; 3]],
    tets: &[[u32; 4]],
    lone: &[usize],
    opts: &Options,
) -> Report {
    let t = Instant::now();
    let make = || Reference::volume_boundary_of(volume_positions, tets, lone, opts.feature_angle);
    let mut on_boundary = vec![false; positions.len()];
    let mut hint = vec![[0.0; 3]; positions.len()];
    // the faces of one hex, in (hex, face) order: the checker's
    for (h, f) in dualex_check::hex::lone_hex_faces(cells) {
        let q = HEX_FACES[f].map(|k| cells[h][k]);
        let p = q.map(|v| positions[v as usize]);
        let n = cross(sub(p[2], p[0]), sub(p[3], p[1]));
        for v in q {
            on_boundary[v as usize] = true;
            for k in 0..3 {
                hint[v as usize][k] += n[k];
            }
        }
    }
    let measure = |x: &[[f64; 3]], _: &[[[f64; 3]; 3]]| quality::hex_values(x, cells);
    let id = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]];
    let input = Input {
        cells,
        corners: &HEX_CORNER_EDGES,
        frames: vec![id; cells.len()],
        reframe: None,
        edges: &HEX_EDGES,
        role: Role::Volume,
        on_boundary,
        hint: &|| hint.clone(),
    };
    let mut rep = run(positions, input, &measure, None, &make, opts);
    rep.time_ms = t.elapsed().as_secs_f64() * 1e3;
    rep
}

type Measure<'a, const D: usize> = dyn Fn(&[[f64; 3]], &[[[f64; 3]; D]]) -> Vec<f64> + 'a;

/// What differs between the dimensions.
struct Input<'a, const D: usize, const K: usize> {
    cells: &'a [[u32; K]],
    corners: &'a [[usize; 4]],
    /// Per cell, its frame (quads: the tangent plane of the normal they
    /// are measured against; hexes: the identity).
    frames: Vec<[[f64; 3]; D]>,
    /// Quads: the frames again from positions, against the triangle of the
    /// reference nearest each quad's centre (the measure's definition);
    /// `None` for hexes.
    reframe: Option<&'a Reframe<'a, D>>,
    edges: &'a [[usize; 2]],
    role: Role,
    on_boundary: Vec<bool>,
    /// Per vertex, the sum of its cells' normals (quads) or boundary
    /// faces' normals (hexes): the side of the surface it faces; made only
    /// when the stage goes past step 1.
    hint: &'a (dyn Fn() -> Vec<[f64; 3]> + Sync),
}

/// A quad's edges (corner pairs, cell order).
const QUAD_EDGES: [[usize; 2]; 4] = [[0, 1], [1, 2], [2, 3], [3, 0]];

/// A boundary vertex nearer the input's boundary than this many mean edge
/// lengths is on it (a valid map's file rounds its numbers: its boundary
/// grid points lie within ~1e-7 edge lengths of the boundary, and are left
/// where they are).
pub const ON_BOUNDARY: f64 = 1e-4;

/// A corner of a quad mesh (a boundary vertex of one quad) goes onto a
/// corner of the input's boundary only where the input's interior angle is
/// at most this (degrees).
pub const MESH_CORNER_ANGLE: f64 = 150.0;

/// A cell at a corner of the mesh whose value is at most this once its
/// boundary vertices are on the input's boundary is flat there.
pub const FLAT: f64 = 0.1;

/// Most rounds of one untangling attempt (one ring count).
const UNTANGLE_ROUNDS: usize = 100;

/// L-BFGS iterations per round: few, so that a vertex on the reference
/// stays near its tangent plane between projections.
const ITERATIONS: usize = 20;

/// L-BFGS iterations per smoothing round: a smooth mesh needs few, and
/// the whole mesh is optimised.
const SMOOTH_ITERATIONS: usize = 8;

/// The stage's work (corner-simplex evaluations) is at most this many per
/// corner simplex of the mesh, or [`MIN_BUDGET`] on small meshes.
const BUDGET_PER_SIMPLEX: usize = 20;

/// The least work allowed (about 3 s on the machine of BENCHMARKS.md).
const MIN_BUDGET: usize = 40_000_000;

/// The least work allowed to smoothing: the 10 rounds of `--smooth` on
/// meshes of up to ~50 000 corner simplices (the 6 912 hexes of the
/// round trips, 12 000 quads); a mesh of 100 000 quads gets one round.
const SMOOTH_MIN_BUDGET: usize = 6_000_000;

/// Rings tried around the inverted elements, then the whole mesh.
const RINGS: [usize; 4] = [1, 2, 4, 8];

/// A wide fold's spread covers its cells and this many rings around them
/// (its untangling two more).
const SPREAD_RINGS: usize = 2;

/// Most conjugate-gradient steps of a spread (a fold `w` cells wide needs
/// about `w` of them).
const SPREAD_ITERATIONS: usize = 300;
