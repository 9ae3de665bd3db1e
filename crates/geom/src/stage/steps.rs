//! The stage's driver ([`run`]) in numbered steps, one generic function
//! each for quads (`D` = 2, `K` = 4) and hexes (`D` = 3, `K` = 8).
//!
//! Input: the mesh's positions `x` (changed in place), what differs
//! between the dimensions ([`Input`]), the measure, the reference when
//! the caller built one already (else `make` builds it when needed) and
//! the options. Output: the [`Report`] (`time_ms` is the caller's).
//!
//! 1. measure before, the mean edge; nothing else when the mode is off or
//!    there is nothing to do (no boundary to put vertices onto and
//!    nothing inverted in `auto`) ([`measure_before`]);
//! 2. the reference, and quads measured again against the triangles
//!    nearest their centres ([`reframe`]); the constraints;
//! 3. the boundary vertices onto the input's boundary when
//!    [`to_boundary`] says so ([`onto_boundary`]); nothing else when that
//!    was all;
//! 4. the optimisation ([`optimise`]): a. smoothing (`Mode::Smooth`,
//!    [`Stage::smooth`]); b. the untangling attempts
//!    ([`Stage::untangle`], one [`Stage::attempt`] each: a wide fold
//!    spread ([`Stage::spread`]), growing rings, the feature release);
//! 5. the positions with the fewest inverted cells kept
//!    ([`Stage::keep_best`]);
//! 6. the report's moves and boundary distances
//!    ([`moves_and_distances`]).
//!
//! Invariants: the computations and their order are those of the single
//! function this was (floating-point results bit-identical); one measure
//! per state of `x` ([`Stage::remeasure`]: quads reframe only the cells
//! with a vertex moved since `framed_at`); the work is bounded by the
//! budgets in corner-simplex evaluations, the same for every thread
//! count.

use super::corners::{onto_boundary, release_features};
use super::frames::{all_frames, reframe_moved, Reframe};
use super::report::moves_and_distances;
use super::topology::{grow, vertex_cells};
use super::{
    spread, Input, Measure, Report, BUDGET_PER_SIMPLEX, ITERATIONS, MIN_BUDGET, ON_BOUNDARY, RINGS,
    SMOOTH_ITERATIONS, SMOOTH_MIN_BUDGET, SPREAD_ITERATIONS, SPREAD_RINGS, UNTANGLE_ROUNDS,
};
use crate::constraint::{Constraints, Kind};
use crate::optimize::{optimize, Cells, Params};
use crate::quality::{self, norm, sub, Summary};
use crate::reference::Reference;
use crate::{Mode, Options};

/// The stage's driver: steps 1 to 6 (module docs).
pub(super) fn run<const D: usize, const K: usize>(
    x: &mut [[f64; 3]],
    mut input: Input<D, K>,
    measure: &Measure<D>,
    reference: Option<Reference>,
    make: &dyn Fn() -> Reference,
    opts: &Options,
) -> Report {
    // 1. measure before
    let (mut rep, mut values) = measure_before(x, &input, measure, opts);
    let boundary = opts.boundary && rep.boundary_vertices > 0;
    if opts.mode == Mode::Off || (!boundary && rep.before.inverted == 0 && opts.mode == Mode::Auto)
    {
        return rep;
    }
    // 2. the reference, quads measured against it; the constraints
    let r = reference.unwrap_or_else(make);
    reframe(x, &mut input, measure, &r, &mut values, &mut rep);
    let tol = ON_BOUNDARY * rep.mean_edge.max(f64::MIN_POSITIVE);
    let mut cons =
        Constraints::classify(&r, x, &input.on_boundary, (input.hint)(), input.role, tol);
    let start = x.to_vec();
    let around = vertex_cells(x.len(), input.cells);
    // 3. boundary vertices onto the input's boundary
    if boundary && to_boundary(x, &input, &r, &cons, tol, opts, &rep) {
        onto_boundary(x, &input, &r, &around, &mut cons, &start, tol, &mut rep);
    }
    if rep.boundary_off == 0 && rep.before.inverted == 0 && opts.mode == Mode::Auto {
        return rep;
    }
    // 4. the optimisation, 5. the best positions kept
    let world = World {
        measure,
        r: &r,
        around: &around,
        start: &start,
    };
    let bad = optimise(x, &mut input, &world, &mut cons, values, opts, &mut rep);
    // 6. the report
    rep.after = Summary::of(&bad);
    moves_and_distances(x, &start, &input, &cons, &r, boundary, &mut rep);
    rep
}

/// 1. The report with the measure before and the mean edge length, and
///    the cells' values.
fn measure_before<const D: usize, const K: usize>(
    x: &[[f64; 3]],
    input: &Input<D, K>,
    measure: &Measure<D>,
    opts: &Options,
) -> (Report, Vec<f64>) {
    let values = measure(x, &input.frames);
    let mut rep = Report {
        mode: opts.mode.name(),
        before: Summary::of(&values),
        boundary_vertices: input.on_boundary.iter().filter(|&&b| b).count(),
        ..Default::default()
    };
    rep.after = rep.before;
    rep.mean_edge = spread::mean_edge(x, input.cells, input.edges);
    (rep, values)
}

/// 2. Quads: measured from here on against the triangle nearest each
///    quad's centre (the measure's definition; `inspect` measures so
///    too); hexes: nothing.
fn reframe<const D: usize, const K: usize>(
    x: &[[f64; 3]],
    input: &mut Input<D, K>,
    measure: &Measure<D>,
    r: &Reference,
    values: &mut Vec<f64>,
    rep: &mut Report,
) {
    if let Some(reframe) = input.reframe {
        input.frames = all_frames(reframe, x, input.cells.len(), r);
        *values = measure(x, &input.frames);
        rep.before = Summary::of(values);
        rep.after = rep.before;
    }
}

/// 3. Whether the boundary vertices go onto the input's boundary: all of
///    them (to 1e-9 of the bounding box) once one is farther than `tol`
///    or the stage untangles or smooths anyway; none when all are within
///    `tol` (a valid map's file rounds its numbers) and nothing else is to
///    be done.
fn to_boundary<const D: usize, const K: usize>(
    x: &[[f64; 3]],
    input: &Input<D, K>,
    r: &Reference,
    cons: &Constraints,
    tol: f64,
    opts: &Options,
    rep: &Report,
) -> bool {
    let far = (0..x.len()).any(|v| {
        input.on_boundary[v]
            && cons.kind[v] != Kind::Fixed
            && norm(sub(cons.project(r, v, x[v]), x[v])) > tol
    });
    far || rep.before.inverted > 0 || opts.mode != Mode::Auto
}

/// What the optimisation reads and never changes.
struct World<'w, const D: usize> {
    measure: &'w Measure<'w, D>,
    r: &'w Reference,
    around: &'w (Vec<usize>, Vec<u32>),
    /// The positions after step 2 (before step 3).
    start: &'w [[f64; 3]],
}

/// 4. and 5. The optimisation: its state ([`Stage`]) set up, smoothing
///    (`Mode::Smooth`), the untangling attempts, the best positions kept;
///    the cells' values at the final positions. The cells' frames move
///    from `input` to the optimisation.
fn optimise<const D: usize, const K: usize>(
    x: &mut [[f64; 3]],
    input: &mut Input<D, K>,
    world: &World<D>,
    cons: &mut Constraints,
    values: Vec<f64>,
    opts: &Options,
    rep: &mut Report,
) -> Vec<f64> {
    let cells = input.cells;
    let r = world.r;
    // each cell's target size: its mean edge (the median for the
    // stretched cells of a wide fold, while it is spread)
    let (h, stretched, median) = spread::sizes(cells, input.edges, world.start, rep.mean_edge);
    let reframe = input.reframe;
    let bound = reframe.map(|f| move |x: &[[f64; 3]], ci: usize| f(x, ci, r));
    let movable_kind: Vec<bool> = cons.kind.iter().map(|k| k.dof() > 0).collect();
    let region = |flagged: &[bool], rings: usize| {
        region_of(cells, world.around, &movable_kind, flagged, rings)
    };
    // the work allowed, in corner-simplex evaluations: the same for every
    // thread count (a time limit would not be)
    let budget = (BUDGET_PER_SIMPLEX * cells.len() * input.corners.len()).max(MIN_BUDGET);
    let mut s = Stage {
        c: Cells::<D, K> {
            cells,
            corners: input.corners,
            frames: std::mem::take(&mut input.frames),
            h,
            reframe: bound.as_ref().map(|b| b as &crate::optimize::Reframe<D>),
            region: Some(&region),
        },
        x,
        world,
        edges: input.edges,
        on_boundary: &input.on_boundary,
        reframe,
        cons,
        movable_kind: &movable_kind,
        framed_at: world.start.to_vec(),
        stretched,
        median,
        bad: Vec::new(),
        best: (0, Vec::new()),
        budget,
        rep,
    };
    // one measure per state of `x` (quads: a closest-point query each):
    // the mesh's own when nothing moved it since
    if *s.x == world.start[..] {
        s.bad = values;
    } else {
        s.remeasure();
    }
    // the positions with the fewest inverted elements are kept, those
    // before smoothing included (smoothing can bend a quad across a
    // sharp edge that the untangling then cannot unbend)
    s.best = (inverted_of(&s.bad), s.x.to_vec());
    if let Mode::Smooth(rounds) = opts.mode {
        s.smooth(rounds);
    }
    s.untangle();
    s.keep_best();
    s.bad
}

/// The optimisation's state (steps 4 and 5).
struct Stage<'s, const D: usize, const K: usize> {
    c: Cells<'s, D, K>,
    x: &'s mut [[f64; 3]],
    world: &'s World<'s, D>,
    edges: &'s [[usize; 2]],
    on_boundary: &'s [bool],
    reframe: Option<&'s Reframe<'s, D>>,
    cons: &'s mut Constraints,
    /// The vertices their constraints let move.
    movable_kind: &'s [bool],
    /// The positions the frames were taken at.
    framed_at: Vec<[f64; 3]>,
    /// The cells stretched by a wide fold, and the median size.
    stretched: Vec<bool>,
    median: f64,
    /// The cells' values at `x`.
    bad: Vec<f64>,
    /// The fewest inverted cells yet, and their positions.
    best: (usize, Vec<[f64; 3]>),
    /// The untangling's work left.
    budget: usize,
    rep: &'s mut Report,
}

impl<const D: usize, const K: usize> Stage<'_, D, K> {
    /// `bad`: the values at `x`, quads measured against the triangles
    /// nearest their centres there: the frames of the cells with a vertex
    /// moved since `framed_at` are taken again (the others' would be the
    /// same).
    fn remeasure(&mut self) {
        if let Some(reframe) = self.reframe {
            let r = self.world.r;
            reframe_moved(
                reframe,
                self.x,
                &self.framed_at,
                self.c.cells,
                &mut self.c.frames,
                r,
            );
            self.framed_at.copy_from_slice(self.x);
        }
        self.bad = (self.world.measure)(self.x, &self.c.frames);
    }

    /// The movable vertices within `rings` rings of the flagged cells.
    fn region(&self, flagged: &[bool], rings: usize) -> Vec<bool> {
        region_of(
            self.c.cells,
            self.world.around,
            self.movable_kind,
            flagged,
            rings,
        )
    }

    /// 4a. Smoothing, in at most `rounds` rounds, with a budget of its own
    ///     (untangling after it needs one): 20 evaluations a corner
    ///     simplex, at least `SMOOTH_MIN_BUDGET`; the smoothed positions
    ///     replace the given ones unless worse.
    fn smooth(&mut self, rounds: usize) {
        let simplices = self.c.cells.len() * self.c.corners.len();
        let mut smooth_budget = (BUDGET_PER_SIMPLEX * simplices).max(SMOOTH_MIN_BUDGET);
        let p = Params {
            theta: 0.5,
            rounds: rounds.max(1),
            iterations: SMOOTH_ITERATIONS,
            stop_when_untangled: false,
            shrink_rings: 0,
        };
        let (movable, cons, r) = (self.movable_kind, &*self.cons, Some(self.world.r));
        self.rep.rounds = optimize(&self.c, self.x, movable, cons, r, p, &mut smooth_budget).rounds;
        self.remeasure();
        if inverted_of(&self.bad) <= self.best.0 {
            self.best = (inverted_of(&self.bad), self.x.to_vec());
        }
    }

    /// 4b. Untangling near what is still inverted (after smoothing too): a
    ///     wide fold's vertices spread out first (undone unless it leaves
    ///     fewer inverted cells); then growing rings (an attempt that
    ///     makes things worse is undone); then once more on the widest
    ///     region with the interior vertices of the cells still inverted
    ///     released from the feature curves (a vertex held on a sharp
    ///     ridge can pin a quad folded across it).
    fn untangle(&mut self) {
        let flagged = flagged(&self.bad);
        let fold = spread::fold(self.c.cells, self.world.around, &flagged, &self.stretched);
        let attempts = fold
            .map(Attempt::Spread)
            .into_iter()
            .chain(RINGS.iter().map(|&k| Attempt::Rings(k)))
            .chain([Attempt::Release]);
        for attempt in attempts {
            let now = inverted_of(&self.bad);
            if now < self.best.0 {
                self.best = (now, self.x.to_vec());
            }
            if now == 0 || self.budget == 0 || !self.attempt(attempt, now) {
                break;
            }
        }
    }

    /// 4b. One untangling attempt, with `now` cells inverted; false when
    ///     there was nothing to attempt (no feature vertex to release).
    fn attempt(&mut self, attempt: Attempt, now: usize) -> bool {
        let flagged = flagged(&self.bad);
        // a spread is undone unless it leaves fewer inverted cells
        let mut undo = None;
        let (movable, rings) = match attempt {
            Attempt::Rings(rings) => (self.region(&flagged, rings), rings),
            Attempt::Spread(fold) => {
                undo = Some((self.x.to_vec(), self.c.h.clone(), now));
                (self.spread(&fold), RINGS[RINGS.len() - 1])
            }
            Attempt::Release => {
                let released =
                    release_features(self.cons, self.c.cells, &flagged, self.on_boundary);
                if released == 0 {
                    return false;
                }
                self.rep.features_released = released;
                let rings = RINGS[RINGS.len() - 1];
                (self.region(&flagged, rings), rings)
            }
        };
        let p = Params {
            theta: 0.5,
            rounds: UNTANGLE_ROUNDS,
            iterations: ITERATIONS,
            stop_when_untangled: true,
            shrink_rings: rings,
        };
        let (cons, r) = (&*self.cons, Some(self.world.r));
        self.rep.rounds += optimize(&self.c, self.x, &movable, cons, r, p, &mut self.budget).rounds;
        self.rep.rings = rings;
        self.remeasure();
        if let Some((x0, h0, n0)) = undo.filter(|u| inverted_of(&self.bad) >= u.2) {
            self.x.copy_from_slice(&x0);
            self.c.h = h0;
            self.remeasure();
            debug_assert_eq!(inverted_of(&self.bad), n0);
        }
        true
    }

    /// 4b. A wide fold (these cells) spread out: its stretched cells aim
    ///     at the median size, its surface and free vertices within
    ///     `SPREAD_RINGS` rings move harmonically, then onto their
    ///     constraints; the vertices its untangling moves.
    fn spread(&mut self, fold: &[bool]) -> Vec<bool> {
        for (h, (&f, &s)) in self.c.h.iter_mut().zip(fold.iter().zip(&self.stretched)) {
            if f && s {
                *h = self.median;
            }
        }
        let mut inside = self.region(fold, SPREAD_RINGS);
        for (v, m) in inside.iter_mut().enumerate() {
            *m &= matches!(self.cons.kind[v], Kind::Surface | Kind::Free);
        }
        spread::harmonic(self.x, self.c.cells, self.edges, &inside, SPREAD_ITERATIONS);
        for v in (0..self.x.len()).filter(|&v| inside[v]) {
            self.x[v] = self.cons.project(self.world.r, v, self.x[v]);
        }
        self.region(fold, SPREAD_RINGS + 2)
    }

    /// 5. The best positions kept (a feature release only when it removed
    ///    something).
    fn keep_best(&mut self) {
        let now = inverted_of(&self.bad);
        if now > self.best.0 || (self.rep.features_released > 0 && now == self.best.0) {
            self.x.copy_from_slice(&self.best.1);
            self.remeasure();
            self.rep.features_released = 0;
        }
    }
}

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

/// The movable vertices within `rings` rings of the flagged cells.
fn region_of<const K: usize>(
    cells: &[[u32; K]],
    around: &(Vec<usize>, Vec<u32>),
    movable_kind: &[bool],
    flagged: &[bool],
    rings: usize,
) -> Vec<bool> {
    let mut region = vec![false; movable_kind.len()];
    for (cell, _) in cells.iter().zip(flagged).filter(|(_, &f)| f) {
        for &u in cell {
            region[u as usize] = true;
        }
    }
    grow(&mut region, around, cells, rings);
    for (r, m) in region.iter_mut().zip(movable_kind) {
        *r &= *m;
    }
    region
}

/// The flat (within `DEGENERATE` of 0) or inverted cells: as bad as each
/// other.
fn flagged(values: &[f64]) -> Vec<bool> {
    values.iter().map(|&v| v <= quality::DEGENERATE).collect()
}

/// How many cells are flat or inverted.
fn inverted_of(values: &[f64]) -> usize {
    values.iter().filter(|&&v| v <= quality::DEGENERATE).count()
}
