//! The optimisation loop, generic over the dimension `D` of the corner
//! simplices and the corner count `K` of the cells.
//!
//! Input: cells with a frame per cell (`D` orthonormal rows: the tangent
//! plane of a quad, the identity for a hex), a reference edge length per
//! cell, the movable vertices and their [`Constraints`]. Output: new
//! positions of the movable vertices, on their sets. Each round minimises
//! the [`energy`](crate::energy) of every corner simplex of the cells that
//! touch a movable vertex by L-BFGS in the vertices' tangent bases, then
//! projects the moved vertices onto their sets and lowers ε by the rule of
//! Garanzha et al. (2021). Vertices that do not move are never written.

use crate::constraint::Constraints;
use crate::energy::energy_det;
use crate::lbfgs;
use crate::quality::sub;
use crate::reference::Reference;
use rayon::prelude::*;

/// The cells and their per-cell data.
pub struct Cells<'a, const D: usize, const K: usize> {
    /// Cells (vertex indices).
    pub cells: &'a [[u32; K]],
    /// The corner simplices of a cell: corner, then its `D` neighbours
    /// (right-handed); entries past `D` unused.
    pub corners: &'a [[usize; 4]],
    /// Per cell, the `D` rows of its frame.
    pub frames: Vec<[[f64; 3]; D]>,
    /// Per cell, its reference edge length.
    pub h: Vec<f64>,
    /// The frame of a cell again from positions (quads: the tangent plane
    /// of the input triangle nearest the quad's centre), taken at the
    /// start of every round; `None`: the frames stay.
    pub reframe: Option<&'a Reframe<'a, D>>,
    /// The movable vertices within `rings` rings of the flagged cells
    /// (per cell); `None`: the region never shrinks
    /// ([`Params::shrink_rings`]).
    pub region: Option<&'a Region<'a>>,
}

/// The vertices within `rings` rings of the flagged cells, movable ones
/// only.
pub type Region<'a> = dyn Fn(&[bool], usize) -> Vec<bool> + Sync + 'a;

/// The frame of cell `c` from positions `x`.
pub type Reframe<'a, const D: usize> = dyn Fn(&[[f64; 3]], usize) -> [[f64; 3]; D] + Sync + 'a;

/// Parameters of [`optimize`].
#[derive(Clone, Copy, Debug)]
pub struct Params {
    /// Weight of the size term.
    pub theta: f64,
    /// Most rounds.
    pub rounds: usize,
    /// Most L-BFGS iterations per round.
    pub iterations: usize,
    /// Stop once nothing is inverted (untangling) instead of when the
    /// energy settles (smoothing).
    pub stop_when_untangled: bool,
    /// Untangling: after a round, the region becomes the vertices within
    /// this many rings of the cells still inverted ([`Cells::region`])
    /// when that is at most half of it: the later rounds, on a few folds
    /// left, cost a fraction of the first. 0: the region stays.
    pub shrink_rings: usize,
}

/// What [`optimize`] did.
#[derive(Clone, Copy, Debug, Default)]
pub struct Outcome {
    /// Rounds made.
    pub rounds: usize,
    /// The least corner determinant at the end (> 0: none inverted).
    pub det_min: f64,
}

/// Corner simplices per chunk of an evaluation (a fixed size: the sum's
/// order does not depend on the thread count).
const CHUNK: usize = 4096;

/// Most a vertex on the reference moves in one round, in mean edge
/// lengths of the cells optimised.
const MAX_STEP: f64 = 0.25;

/// The work of re-framing one cell (a closest-point query), in
/// corner-simplex evaluations.
const REFRAME_COST: usize = 16;

/// Smoothing stops once a round lowers the energy by less than this
/// fraction.
const SETTLED: f64 = 1e-3;

/// The least starting ε when something is inverted.
const EPS_MIN_START: f64 = 1e-3;

/// Untangling: ε falls at least this much a round (the rule of the paper alone lowers
/// it by a few per cent a round while a fold resists, and each round
/// costs an optimisation and a projection).
const EPS_FALL: f64 = 0.7;

/// The longest L-BFGS step of a coordinate, in mean edge lengths.
const LBFGS_MAX_STEP: f64 = 0.5;

/// Rounds without fewer inverted corners after which untangling stops
/// (the next, larger region is tried).
const STALL: usize = 12;

struct Local<'a, const D: usize, const K: usize> {
    c: &'a Cells<'a, D, K>,
    /// Active cells (touching a movable vertex).
    cells: Vec<u32>,
    /// Per active cell, its frame.
    frames: Vec<[[f64; 3]; D]>,
    /// Per corner simplex of the active cells: (active cell, corner).
    simplices: Vec<(u32, u8)>,
    /// Movable vertices (global ids).
    vars: Vec<u32>,
    /// CSR: per var, the (simplex, slot) pairs it appears in.
    start: Vec<usize>,
    uses: Vec<(u32, u8)>,
    /// Inverted corner simplices at the last evaluation.
    inverted: std::sync::atomic::AtomicUsize,
    /// Every frame is the identity (hexes): the Jacobian is the edges'
    /// coordinates, no projection.
    identity: bool,
}

impl<'a, const D: usize, const K: usize> Local<'a, D, K> {
    fn new(c: &'a Cells<'a, D, K>, movable: &[bool], n: usize) -> Self {
        let cells: Vec<u32> = (0..c.cells.len() as u32)
            .filter(|&i| c.cells[i as usize].iter().any(|&v| movable[v as usize]))
            .collect();
        let mut var_of = vec![u32::MAX; n];
        let mut vars = Vec::new();
        for &ci in &cells {
            for &v in &c.cells[ci as usize] {
                if movable[v as usize] && var_of[v as usize] == u32::MAX {
                    var_of[v as usize] = vars.len() as u32;
                    vars.push(v);
                }
            }
        }
        let simplices: Vec<(u32, u8)> = (0..cells.len() as u32)
            .flat_map(|a| (0..c.corners.len() as u8).map(move |k| (a, k)))
            .collect();
        let mut count = vec![0usize; vars.len() + 1];
        let slot_var = |s: &(u32, u8), slot: usize| {
            let cell = &c.cells[cells[s.0 as usize] as usize];
            var_of[cell[c.corners[s.1 as usize][slot]] as usize]
        };
        for s in &simplices {
            for slot in 0..=D {
                let v = slot_var(s, slot);
                if v != u32::MAX {
                    count[v as usize + 1] += 1;
                }
            }
        }
        for i in 0..vars.len() {
            count[i + 1] += count[i];
        }
        let mut fill = count.clone();
        let mut uses = vec![(0u32, 0u8); count[vars.len()]];
        for (si, s) in simplices.iter().enumerate() {
            for slot in 0..=D {
                let v = slot_var(s, slot);
                if v != u32::MAX {
                    uses[fill[v as usize]] = (si as u32, slot as u8);
                    fill[v as usize] += 1;
                }
            }
        }
        let frames: Vec<[[f64; 3]; D]> = cells.iter().map(|&ci| c.frames[ci as usize]).collect();
        let identity = D == 3
            && c.reframe.is_none()
            && frames.iter().all(|f| {
                f.iter()
                    .enumerate()
                    .all(|(r, row)| (0..3).all(|a| row[a] == f64::from(u8::from(a == r))))
            });
        Local {
            identity,
            c,
            frames,
            cells,
            simplices,
            vars,
            start: count,
            uses,
            inverted: Default::default(),
        }
    }

    /// The Jacobian of simplex `s` at positions `x`.
    fn jacobian(&self, s: (u32, u8), x: &[[f64; 3]]) -> [[f64; D]; D] {
        let ci = self.cells[s.0 as usize] as usize;
        let cell = &self.c.cells[ci];
        let corner = &self.c.corners[s.1 as usize];
        let p0 = x[cell[corner[0]] as usize];
        let inv_h = 1.0 / self.c.h[ci];
        let frame = &self.frames[s.0 as usize];
        let mut j = [[0.0; D]; D];
        for k in 0..D {
            let e = sub(x[cell[corner[k + 1]] as usize], p0);
            if self.identity {
                for (r, jr) in j.iter_mut().enumerate() {
                    jr[k] = e[r] * inv_h;
                }
                continue;
            }
            for (r, row) in frame.iter().enumerate() {
                j[r][k] = (row[0] * e[0] + row[1] * e[1] + row[2] * e[2]) * inv_h;
            }
        }
        j
    }

    /// The weighted energy and the determinant of simplex `s`, its
    /// gradient on its `D + 1` vertices written to `g`.
    fn simplex(
        &self,
        s: (u32, u8),
        x: &[[f64; 3]],
        eps: f64,
        theta: f64,
        g: &mut [[f64; 3]; 4],
    ) -> (f64, f64) {
        let ci = self.cells[s.0 as usize] as usize;
        let j = self.jacobian(s, x);
        let (e, de, det) = energy_det::<D>(&j, eps, theta);
        let h = self.c.h[ci];
        let w = h.powi(D as i32);
        let frame = &self.frames[s.0 as usize];
        let mut g0 = [0.0; 3];
        for k in 0..D {
            let mut gk = [0.0; 3];
            if self.identity {
                for (r, g) in gk.iter_mut().enumerate() {
                    *g = de[r][k] * w / h;
                }
            } else {
                for (r, row) in frame.iter().enumerate() {
                    for a in 0..3 {
                        gk[a] += row[a] * de[r][k] * w / h;
                    }
                }
            }
            for a in 0..3 {
                g0[a] -= gk[a];
            }
            g[k + 1] = gk;
        }
        g[0] = g0;
        (e * w, det)
    }

    /// Per cell of the mesh: one of its corner simplices here has a
    /// determinant ≤ 0 at `x` (cells outside the region: `false`).
    fn inverted_cells(&self, x: &[[f64; 3]]) -> Vec<bool> {
        let bad: Vec<bool> = self
            .simplices
            .par_iter()
            .map(|&s| crate::energy::det_cofactor(&self.jacobian(s, x)).0 <= 0.0)
            .collect();
        let mut out = vec![false; self.c.cells.len()];
        for (&(a, _), b) in self.simplices.iter().zip(bad) {
            if b {
                out[self.cells[a as usize] as usize] = true;
            }
        }
        out
    }

    /// Energy, least determinant, and per simplex the gradient on its
    /// `D + 1` vertices.
    fn evaluate(
        &self,
        x: &[[f64; 3]],
        eps: f64,
        theta: f64,
        grads: &mut [[[f64; 3]; 4]],
    ) -> (f64, f64) {
        // per chunk of a fixed size: energy sum, least determinant, inverted
        // count; summed in chunk order (the same bits whatever the threads)
        let per: Vec<(f64, f64, usize)> = self
            .simplices
            .par_chunks(CHUNK)
            .zip(grads.par_chunks_mut(CHUNK))
            .map(|(ss, gs)| {
                let mut acc = (0.0, f64::INFINITY, 0usize);
                for (&s, g) in ss.iter().zip(gs) {
                    let (e, det) = self.simplex(s, x, eps, theta, g);
                    acc.0 += e;
                    acc.1 = acc.1.min(det);
                    acc.2 += usize::from(det <= 0.0);
                }
                acc
            })
            .collect();
        let e = per.iter().map(|p| p.0).sum();
        let d = per.iter().map(|p| p.1).fold(f64::INFINITY, f64::min);
        self.inverted.store(
            per.iter().map(|p| p.2).sum(),
            std::sync::atomic::Ordering::Relaxed,
        );
        (e, d)
    }
}

/// Moves the `movable` vertices of `x` (see the module docs).
pub fn optimize<const D: usize, const K: usize>(
    cells: &Cells<D, K>,
    x: &mut [[f64; 3]],
    movable: &[bool],
    cons: &Constraints,
    r: Option<&Reference>,
    p: Params,
    budget: &mut usize,
) -> Outcome {
    let mut l = Local::new(cells, movable, x.len());
    let n = x.len();
    let mut out = Outcome {
        det_min: f64::INFINITY,
        ..Default::default()
    };
    if l.vars.is_empty() {
        return out;
    }
    let mut grads = vec![[[0.0; 3]; 4]; l.simplices.len()];
    let mean_h = l.cells.iter().map(|&c| cells.h[c as usize]).sum::<f64>() / l.cells.len() as f64;
    let max_step = MAX_STEP * mean_h;
    let (_, mut det_min) = l.evaluate(x, 1.0, p.theta, &mut grads);
    // untangled already: the barrier (ε → 0) keeps it so; else ε starts
    // at the depth of the worst inversion (at most 1, as in the paper,
    // where the map starts fully tangled): a mesh with a few shallow
    // inversions needs no softer start, and each round costs
    // (smoothing, which optimises the whole mesh's shape, starts at 1)
    let mut eps = if det_min > 0.0 {
        1e-10
    } else if p.stop_when_untangled {
        (-det_min).clamp(EPS_MIN_START, 1.0)
    } else {
        1.0
    };
    let fall = if p.stop_when_untangled { EPS_FALL } else { 1.0 };
    let mut best = (usize::MAX, 0);
    let mut bases: Vec<crate::constraint::Basis> = Vec::new();
    // the work of the last round: a smoothing round starts only when the
    // budget covers another like it (a whole-mesh round is costly)
    let mut last_cost = 0usize;
    for round in 0..p.rounds {
        if *budget == 0 || (!p.stop_when_untangled && *budget < last_cost) {
            break;
        }
        let budget_at_start = *budget;
        out.rounds = round + 1;
        if let (Some(reframe), true) = (cells.reframe, round > 0) {
            let x: &[[f64; 3]] = x;
            l.frames = l
                .cells
                .par_iter()
                .map(|&ci| reframe(x, ci as usize))
                .collect();
            // a closest-point query costs about this many evaluations
            *budget = budget.saturating_sub(REFRAME_COST * l.cells.len());
        }
        let mut evaluations = 0usize;
        if bases.is_empty() {
            let x: &[[f64; 3]] = x;
            bases = l
                .vars
                .par_iter()
                .map(|&v| cons.basis(r, v as usize, x[v as usize]))
                .collect();
        }
        let mut offset = vec![0usize; l.vars.len() + 1];
        for (i, b) in bases.iter().enumerate() {
            offset[i + 1] = offset[i] + b.0;
        }
        let x0: Vec<[f64; 3]> = l.vars.iter().map(|&v| x[v as usize]).collect();
        let mut xt = x.to_vec();
        let place = |y: &[f64], xt: &mut [[f64; 3]]| {
            for (i, &v) in l.vars.iter().enumerate() {
                let mut q = x0[i];
                for (k, b) in bases[i].1.iter().take(bases[i].0).enumerate() {
                    for (qa, ba) in q.iter_mut().zip(b) {
                        *qa += y[offset[i] + k] * ba;
                    }
                }
                xt[v as usize] = q;
            }
        };
        let mut y = vec![0.0; offset[l.vars.len()]];
        let (e_prev, _) = l.evaluate(x, eps, p.theta, &mut grads);
        let mut gx = vec![[0.0; 3]; l.vars.len()];
        lbfgs::minimize(
            &mut y,
            |y, gy| {
                evaluations += 1;
                place(y, &mut xt);
                let (e, _) = l.evaluate(&xt, eps, p.theta, &mut grads);
                gx.par_iter_mut().enumerate().for_each(|(i, g)| {
                    *g = [0.0; 3];
                    for &(s, slot) in &l.uses[l.start[i]..l.start[i + 1]] {
                        let gs = grads[s as usize][slot as usize];
                        for a in 0..3 {
                            g[a] += gs[a];
                        }
                    }
                });
                for (i, b) in bases.iter().enumerate() {
                    for k in 0..b.0 {
                        gy[offset[i] + k] = (0..3).map(|a| b.1[k][a] * gx[i][a]).sum();
                    }
                }
                e
            },
            p.iterations,
            1e-9 * mean_h,
            0.05 * mean_h,
            LBFGS_MAX_STEP * mean_h,
            // untangling: once no corner simplex is inverted, the round
            // ends (the projection and the measure come next); the
            // energy's minimum is the smoothing's business
            || p.stop_when_untangled && l.inverted.load(std::sync::atomic::Ordering::Relaxed) == 0,
        );
        place(&y, &mut xt);
        let moved: Vec<([f64; 3], crate::constraint::Basis)> = l
            .vars
            .par_iter()
            .enumerate()
            .map(|(i, &v)| {
                let v = v as usize;
                match r {
                    // a vertex on a set moves at most `max_step` per round,
                    // so that its tangent plane stays a good guide and its
                    // projection stays on its own sheet of the surface
                    Some(_) if cons.kind[v] != crate::constraint::Kind::Free => {
                        let d = sub(xt[v], x0[i]);
                        let len = crate::quality::norm(d);
                        let k = if len > max_step { max_step / len } else { 1.0 };
                        cons.project_basis(r, v, [0, 1, 2].map(|a| x0[i][a] + k * d[a]))
                    }
                    _ => (xt[v], bases[i]),
                }
            })
            .collect();
        for (i, &v) in l.vars.iter().enumerate() {
            x[v as usize] = moved[i].0;
        }
        let next_bases: Vec<crate::constraint::Basis> = moved.into_iter().map(|m| m.1).collect();
        let (e, d) = l.evaluate(x, eps, p.theta, &mut grads);
        det_min = d;
        *budget = budget.saturating_sub((evaluations + 3) * l.simplices.len());
        last_cost = budget_at_start - *budget;
        // ε by the rule of Garanzha et al.
        let sigma = (1.0 - e / e_prev).max(0.1);
        let mu = (1.0 - sigma) * crate::energy::chi(det_min, eps);
        eps = if det_min < mu {
            (2.0 * (mu * (mu - det_min)).sqrt()).min(fall * eps)
        } else {
            1e-10
        };
        bases = next_bases;
        let settled = (e_prev - e).abs() <= SETTLED * e.abs();
        let inverted = l.inverted.load(std::sync::atomic::Ordering::Relaxed);
        if inverted < best.0 {
            best = (inverted, round);
        } else if round >= best.1 + STALL {
            // no fewer inverted corners for a while: stuck
            break;
        }
        if det_min > 0.0 && (p.stop_when_untangled || settled) {
            break;
        }
        if let (Some(region), true) = (cells.region, p.shrink_rings > 0 && inverted > 0) {
            let flagged = l.inverted_cells(x);
            let smaller = region(&flagged, p.shrink_rings);
            if 2 * smaller.iter().filter(|&&m| m).count() <= l.vars.len() {
                l = Local::new(cells, &smaller, n);
                grads = vec![[[0.0; 3]; 4]; l.simplices.len()];
                bases.clear();
            }
        }
    }
    out.det_min = det_min;
    out
}
