//! The stage's driver, one generic function for quads and hexes
//! ([`quads`] and [`hexes`] only gather what differs: corner tables,
//! frames, the measure, the reference and which vertices lie on it).

use crate::constraint::{Constraints, Kind, Role};
use crate::optimize::{optimize, Cells, Params};
use crate::quality::{self, cross, norm, sub, unit, Summary, HEX_CORNER_EDGES, QUAD_CORNER_EDGES};
use crate::reference::Reference;
use crate::{Mode, Options};
use dualex_cells::cells::{HEX_EDGES, HEX_FACES};

mod corners;
mod frames;
mod report;
mod spread;
mod topology;
use corners::{onto_boundary, release_features};
use frames::{all_frames, quad_frame, reframe_moved, Reframe};
pub use report::Report;
use std::time::Instant;
use topology::{boundary_vertices, grow, vertex_cells};

/// The stage on a quad mesh lying on the triangle surface
/// (`surface_positions`, `triangles`); `sources[q]`: the triangle holding
/// quad `q`'s node (`u32::MAX`: none). A quad is measured against the
/// triangle nearest its centre ([`Reference::quad_normal`], as `inspect`
/// does); the source triangles only screen a mesh for work (no search:
/// a mesh the screen finds nothing to do on is returned as it is).
pub fn quads(
    positions: &mut [[f64; 3]],
    cells: &[[u32; 4]],
    surface_positions: &[[f64; 3]],
    triangles: &[[u32; 3]],
    sources: &[u32],
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
    let mut normals = Vec::with_capacity(cells.len());
    for (q, cell) in cells.iter().enumerate() {
        let n = match source(q) {
            Some(s) => tri_normal(s),
            None => {
                let r = reference.get_or_insert_with(make);
                r.quad_normal(&quality::corners(positions, cell))
            }
        };
        normals.push(n);
    }
    let on_boundary = boundary_vertices(positions.len(), cells, &QUAD_EDGES);
    let mut hint = vec![[0.0; 3]; positions.len()];
    for (cell, n) in cells.iter().zip(&normals) {
        for &v in cell {
            for k in 0..3 {
                hint[v as usize][k] += n[k];
            }
        }
    }
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
        hint,
    };
    let mut rep = run(positions, input, &measure, reference, &make, opts);
    rep.time_ms = t.elapsed().as_secs_f64() * 1e3;
    rep
}

/// The stage on a hex mesh inside the tet mesh (`volume_positions`,
/// `tets`): boundary vertices on its boundary surface.
pub fn hexes(
    positions: &mut [[f64; 3]],
    cells: &[[u32; 8]],
    volume_positions: &[[f64; 3]],
    tets: &[[u32; 4]],
    opts: &Options,
) -> Report {
    let t = Instant::now();
    let make = || Reference::volume_boundary(volume_positions, tets, opts.feature_angle);
    let faces = HEX_FACES;
    let mut count = std::collections::HashMap::new();
    for (h, cell) in cells.iter().enumerate() {
        for (f, face) in faces.iter().enumerate() {
            let mut key = face.map(|k| cell[k]);
            key.sort_unstable();
            count.entry(key).or_insert((0u32, h, f)).0 += 1;
        }
    }
    let mut on_boundary = vec![false; positions.len()];
    let mut hint = vec![[0.0; 3]; positions.len()];
    let mut outer: Vec<(usize, usize)> = count
        .into_values()
        .filter(|c| c.0 == 1)
        .map(|c| (c.1, c.2))
        .collect();
    outer.sort_unstable();
    for (h, f) in outer {
        let q = faces[f].map(|k| cells[h][k]);
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
        hint,
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
    hint: Vec<[f64; 3]>,
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

/// One untangling attempt.
enum Attempt {
    /// The vertices within this many rings of the inverted cells.
    Rings(usize),
    /// A wide fold (these cells) spread out, then untangled.
    Spread(Vec<bool>),
    /// The widest rings, with the vertices of inverted cells released from
    /// the feature curves.
    Release,
}

#[allow(clippy::needless_range_loop)] // vertices index several arrays
fn run<const D: usize, const K: usize>(
    x: &mut [[f64; 3]],
    mut input: Input<D, K>,
    measure: &Measure<D>,
    reference: Option<Reference>,
    make: &dyn Fn() -> Reference,
    opts: &Options,
) -> Report {
    let cells = input.cells;
    let mut values = measure(x, &input.frames);
    let mut rep = Report {
        mode: opts.mode.name(),
        before: Summary::of(&values),
        boundary_vertices: input.on_boundary.iter().filter(|&&b| b).count(),
        ..Default::default()
    };
    rep.after = rep.before;
    let (mut sum, mut n) = (0.0, 0usize);
    for c in cells {
        for e in input.edges {
            sum += norm(sub(x[c[e[1]] as usize], x[c[e[0]] as usize]));
            n += 1;
        }
    }
    rep.mean_edge = if n > 0 { sum / n as f64 } else { 0.0 };
    let boundary = opts.boundary && rep.boundary_vertices > 0;
    if opts.mode == Mode::Off || (!boundary && rep.before.inverted == 0 && opts.mode == Mode::Auto)
    {
        return rep;
    }
    let r = reference.unwrap_or_else(make);
    // quads: measured from here on against the triangle nearest each
    // quad's centre (the measure's definition; `inspect` measures so too)
    if let Some(reframe) = input.reframe {
        input.frames = all_frames(reframe, x, cells.len(), &r);
        values = measure(x, &input.frames);
        rep.before = Summary::of(&values);
        rep.after = rep.before;
    }
    let tol = ON_BOUNDARY * rep.mean_edge.max(f64::MIN_POSITIVE);
    let mut cons = Constraints::classify(
        &r,
        x,
        &input.on_boundary,
        input.hint.clone(),
        input.role,
        tol,
    );
    let start = x.to_vec();
    let around = vertex_cells(x.len(), cells);
    // 3. boundary vertices onto the input's boundary: all of them (to
    // 1e-9 of the bounding box) once one is farther than `tol` or the
    // stage untangles or smooths anyway; none when all are within `tol` (a
    // valid map's file rounds its numbers) and nothing else is to be done
    if boundary {
        let far = (0..x.len()).any(|v| {
            input.on_boundary[v]
                && cons.kind[v] != Kind::Fixed
                && norm(sub(cons.project(&r, v, x[v]), x[v])) > tol
        });
        if far || rep.before.inverted > 0 || opts.mode != Mode::Auto {
            onto_boundary(x, &input, &r, &around, &mut cons, &start, tol, &mut rep);
        }
    }
    if rep.boundary_off == 0 && rep.before.inverted == 0 && opts.mode == Mode::Auto {
        return rep;
    }
    // 4. the optimisation
    // each cell's target size: its mean edge (the median for the
    // stretched cells of a wide fold, while it is spread)
    let (h, stretched, median) = spread::sizes(cells, input.edges, &start, rep.mean_edge);
    let reframe = input.reframe;
    let bound = reframe.map(|f| {
        let r = &r;
        move |x: &[[f64; 3]], ci: usize| f(x, ci, r)
    });
    let mut c = Cells::<D, K> {
        cells,
        corners: input.corners,
        frames: input.frames,
        h,
        reframe: bound.as_ref().map(|b| b as &crate::optimize::Reframe<D>),
        region: None,
    };
    // the values at `x`, quads measured against the triangles nearest
    // their centres there: the frames of the cells with a vertex moved
    // since `framed_at` are taken again (the others' would be the same)
    let mut framed_at = start.clone();
    let remeasure = |x: &[[f64; 3]], c: &mut Cells<D, K>, framed_at: &mut Vec<[f64; 3]>| {
        if let Some(reframe) = reframe {
            reframe_moved(reframe, x, framed_at, cells, &mut c.frames, &r);
            framed_at.copy_from_slice(x);
        }
        measure(x, &c.frames)
    };
    let movable_kind: Vec<bool> = cons.kind.iter().map(|k| k.dof() > 0).collect();
    // the movable vertices within `rings` rings of the flagged cells
    let region = |flagged: &[bool], rings: usize| {
        let mut region = vec![false; movable_kind.len()];
        for (cell, _) in cells.iter().zip(flagged).filter(|(_, &f)| f) {
            for &u in cell {
                region[u as usize] = true;
            }
        }
        grow(&mut region, &around, cells, rings);
        for (r, m) in region.iter_mut().zip(&movable_kind) {
            *r &= *m;
        }
        region
    };
    c.region = Some(&region);
    // the work allowed, in corner-simplex evaluations: the same for every
    // thread count (a time limit would not be)
    let mut budget = (BUDGET_PER_SIMPLEX * cells.len() * input.corners.len()).max(MIN_BUDGET);
    // flat cells (within `DEGENERATE` of 0) are as bad as inverted ones
    let inverted_of = |v: &[f64]| v.iter().filter(|&&v| v <= quality::DEGENERATE).count();
    // one measure per state of `x` (quads: a closest-point query each):
    // the mesh's own when nothing moved it since
    let mut bad = if *x == start[..] {
        values
    } else {
        remeasure(x, &mut c, &mut framed_at)
    };
    // the positions with the fewest inverted elements are kept, those
    // before smoothing included (smoothing can bend a quad across a
    // sharp edge that the untangling then cannot unbend)
    let mut best = (inverted_of(&bad), x.to_vec());
    if let Mode::Smooth(rounds) = opts.mode {
        // smoothing has a budget of its own (untangling after it needs
        // one): 20 evaluations a corner simplex, at least
        // `SMOOTH_MIN_BUDGET`
        let mut smooth_budget =
            (BUDGET_PER_SIMPLEX * cells.len() * input.corners.len()).max(SMOOTH_MIN_BUDGET);
        let p = Params {
            theta: 0.5,
            rounds: rounds.max(1),
            iterations: SMOOTH_ITERATIONS,
            stop_when_untangled: false,
            shrink_rings: 0,
        };
        rep.rounds = optimize(&c, x, &movable_kind, &cons, Some(&r), p, &mut smooth_budget).rounds;
        bad = remeasure(x, &mut c, &mut framed_at);
        // the smoothed positions replace the given ones unless worse
        if inverted_of(&bad) <= best.0 {
            best = (inverted_of(&bad), x.to_vec());
        }
    }
    // untangling near what is still inverted (after smoothing too): a
    // wide fold's vertices spread out first (undone unless it leaves
    // fewer inverted cells); then growing rings (an attempt that makes
    // things worse is undone); then once more on the widest region with
    // the interior vertices of the cells still inverted released from the
    // feature curves (a vertex held on a sharp ridge can pin a quad
    // folded across it)
    let flagged: Vec<bool> = bad.iter().map(|&v| v <= quality::DEGENERATE).collect();
    let fold = spread::fold(cells, &around, &flagged, &stretched);
    let attempts = fold
        .map(Attempt::Spread)
        .into_iter()
        .chain(RINGS.iter().map(|&k| Attempt::Rings(k)))
        .chain([Attempt::Release]);
    for attempt in attempts {
        let now = inverted_of(&bad);
        if now < best.0 {
            best = (now, x.to_vec());
        }
        if now == 0 || budget == 0 {
            break;
        }
        let flagged: Vec<bool> = bad.iter().map(|&v| v <= quality::DEGENERATE).collect();
        // a spread is undone unless it leaves fewer inverted cells
        let mut undo = None;
        let (movable, rings) = match attempt {
            Attempt::Rings(rings) => (region(&flagged, rings), rings),
            Attempt::Spread(fold) => {
                undo = Some((x.to_vec(), c.h.clone(), now));
                // the fold's stretched cells aim at the median size
                for (h, (&f, &s)) in c.h.iter_mut().zip(fold.iter().zip(&stretched)) {
                    if f && s {
                        *h = median;
                    }
                }
                let mut inside = region(&fold, SPREAD_RINGS);
                for (v, m) in inside.iter_mut().enumerate() {
                    *m &= matches!(cons.kind[v], Kind::Surface | Kind::Free);
                }
                spread::harmonic(x, cells, input.edges, &inside, SPREAD_ITERATIONS);
                for v in (0..x.len()).filter(|&v| inside[v]) {
                    x[v] = cons.project(&r, v, x[v]);
                }
                (region(&fold, SPREAD_RINGS + 2), RINGS[RINGS.len() - 1])
            }
            Attempt::Release => {
                let released = release_features(&mut cons, cells, &flagged, &input.on_boundary);
                if released == 0 {
                    break;
                }
                rep.features_released = released;
                let rings = RINGS[RINGS.len() - 1];
                (region(&flagged, rings), rings)
            }
        };
        let p = Params {
            theta: 0.5,
            rounds: UNTANGLE_ROUNDS,
            iterations: ITERATIONS,
            stop_when_untangled: true,
            shrink_rings: rings,
        };
        rep.rounds += optimize(&c, x, &movable, &cons, Some(&r), p, &mut budget).rounds;
        rep.rings = rings;
        bad = remeasure(x, &mut c, &mut framed_at);
        if let Some((x0, h0, n0)) = undo.filter(|u| inverted_of(&bad) >= u.2) {
            x.copy_from_slice(&x0);
            c.h = h0;
            bad = remeasure(x, &mut c, &mut framed_at);
            debug_assert_eq!(inverted_of(&bad), n0);
        }
    }
    // (a feature release is kept only when it removed something)
    let now = inverted_of(&bad);
    if now > best.0 || (rep.features_released > 0 && now == best.0) {
        x.copy_from_slice(&best.1);
        bad = remeasure(x, &mut c, &mut framed_at);
        rep.features_released = 0;
    }
    rep.after = Summary::of(&bad);
    for v in 0..x.len() {
        let d = norm(sub(x[v], start[v]));
        if d > 0.0 {
            rep.moved_vertices += 1;
            rep.max_move = rep.max_move.max(d);
        }
        // the distance to the input's boundary (curves in 2D, surface in
        // 3D) of the boundary vertices kept on it
        let on_it = match input.role {
            Role::Surface => matches!(cons.kind[v], Kind::Curve { boundary: true }),
            Role::Volume => cons.kind[v] != Kind::Free,
        };
        if boundary && input.on_boundary[v] && on_it {
            let d = match input.role {
                Role::Surface => r.closest_on_curves(x[v], true).map_or(0.0, |c| c.2),
                Role::Volume => r.closest(x[v], None).map_or(0.0, |f| f.distance),
            };
            rep.boundary_distance[1] = rep.boundary_distance[1].max(d);
        }
    }
    rep
}
