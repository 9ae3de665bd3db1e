//! The perturbation rounds' moves ([`super::sanitize`]): which vertices
//! of a round's bad list move, by which random step, in which order.
//!
//! Input: the bad vertices of a round (increasing), its amplitude, the
//! clusters ([`Clusters`]) and the singular vertices' free axes. Output:
//! the moved vertices (`touched`, in order) and their moves in their
//! reference charts (`deltas`), applied by [`super::move_all`].
//!
//! Invariant: the random steps are drawn as one sequence in `todo`'s order
//! (a cluster's step once, at its first member met; a singular vertex's
//! sign draw at its place), whatever the thread count: each step is drawn
//! from its place in the sequence ([`SplitMix::ahead`]). Without a
//! non-trivial cluster and without a free axis among the round's vertices
//! (every benchmark map), vertex `i` of `todo` moves alone by the step at
//! place `i`: [`Mover::round`] then draws the steps without planning them
//! one by one ([`Mover::round_lone`]; the planned form,
//! [`Mover::round_planned`], is its test's oracle).

use super::{Dim, Predicates};
use crate::cluster::Clusters;
use dualex_map::{Rot, Stars};
use dualex_util::rng::SplitMix;
use rayon::prelude::*;
use std::collections::{BTreeSet, HashSet};

/// The state of the perturbation rounds.
pub(super) struct Mover<'a, const D: usize> {
    stars: &'a Stars<D>,
    clusters: &'a Clusters<D>,
    /// Per vertex: the only axis a singular vertex may move along.
    free_axis: &'a [Option<usize>],
    pub(super) rng: SplitMix,
    pub(super) moved: Vec<bool>,
    pub(super) moved_singular: HashSet<u32>,
    /// Vertices moved in the current round, in order.
    pub(super) touched: Vec<u32>,
    /// Their moves, in their reference charts (applied by [`move_all`]).
    pub(super) deltas: Vec<[f64; D]>,
    /// Their moves before the steps are drawn (one per `touched`).
    plan: Vec<Move<D>>,
    /// Per cluster root: the last round (epoch) in which it moved.
    done_epoch: Vec<u32>,
    pub(super) epoch: u32,
    /// Roots of the clusters that could not move as one.
    pub(super) stuck: BTreeSet<u32>,
    /// Roots of the stuck clusters whose members moved one by one.
    pub(super) apart: BTreeSet<u32>,
}

impl<'a, const D: usize> Mover<'a, D> {
    /// A mover before its first round: nothing moved, the generator at
    /// `seed`.
    pub(super) fn new(
        stars: &'a Stars<D>,
        clusters: &'a Clusters<D>,
        free_axis: &'a [Option<usize>],
        seed: u64,
    ) -> Self {
        let nv = stars.singular.len();
        Mover {
            stars,
            clusters,
            free_axis,
            rng: SplitMix::new(seed),
            moved: vec![false; nv],
            moved_singular: HashSet::new(),
            touched: Vec::new(),
            deltas: Vec::new(),
            plan: Vec::new(),
            done_epoch: vec![0; nv],
            epoch: 0,
            stuck: BTreeSet::new(),
            apart: BTreeSet::new(),
        }
    }

    fn free(&self, v: u32) -> Option<usize> {
        self.free_axis.get(v as usize).copied().flatten()
    }

    /// The vertices of `bad` that may move: the non-singular ones, and in
    /// the ordinary rounds the singular ones with a free axis (the extra
    /// rounds are for non-singular vertices only: a singular vertex still
    /// on the grid after the ordinary rounds is on an iso its free axis
    /// does not cross).
    pub(super) fn movable(&self, bad: &[u32], last_resort: bool) -> Vec<u32> {
        let movable = |v: &&u32| {
            !self.stars.singular[**v as usize] || (!last_resort && self.free(**v).is_some())
        };
        bad.par_iter()
            .with_min_len(STEP_TASK)
            .filter(movable)
            .copied()
            .collect()
    }

    /// Moves every vertex of `todo` (its whole cluster, once) by a random
    /// vector of length `amp` (into `touched` and `deltas`). With
    /// `last_resort` (the extra rounds), the members of a stuck cluster
    /// move one by one (each is non-singular: consistent in its own
    /// charts).
    ///
    /// The moves and their places in the random sequence are chosen in
    /// `todo`'s order; the steps, which draw a fixed number of values
    /// each, are then drawn in parallel, each from its own place
    /// ([`SplitMix::ahead`]): the same numbers as drawn one after the
    /// other.
    pub(super) fn round<const N: usize>(&mut self, todo: &[u32], amp: f64, last_resort: bool)
    where
        Dim<N, D>: Predicates<N, D>,
    {
        let lone = self.clusters.count_nontrivial() == 0
            && !todo
                .par_iter()
                .with_min_len(STEP_TASK)
                .any(|&v| self.free(v).is_some());
        if lone {
            self.round_lone::<N>(todo, amp);
        } else {
            self.round_planned::<N>(todo, amp, last_resort);
        }
    }

    /// [`Self::round`] when every vertex of `todo` moves alone (no
    /// non-trivial cluster, no free axis): vertex `i` by the step at place
    /// `i` of the round's sequence, the steps drawn in parallel. What
    /// [`Self::round_planned`] does there: each vertex is its own root,
    /// movable, met once (`todo` has no repeats), and carried by the
    /// identity.
    fn round_lone<const N: usize>(&mut self, todo: &[u32], amp: f64)
    where
        Dim<N, D>: Predicates<N, D>,
    {
        let step = <Dim<N, D>>::step;
        let per_step = self.per_step::<N>(amp);
        self.epoch += 1;
        let start = self.rng.clone();
        for &v in todo {
            self.moved[v as usize] = true;
        }
        self.touched.extend_from_slice(todo);
        let draw = |i: usize| step(&mut start.ahead(i as u64 * per_step), amp);
        self.deltas.par_extend(
            (0..todo.len())
                .into_par_iter()
                .with_min_len(STEP_TASK)
                .map(draw),
        );
        self.rng = start.ahead(todo.len() as u64 * per_step);
    }

    /// The draws of one step of length `amp`.
    fn per_step<const N: usize>(&self, amp: f64) -> u64
    where
        Dim<N, D>: Predicates<N, D>,
    {
        let step = <Dim<N, D>>::step;
        self.rng
            .draws_of(STEP_DRAWS, |r| {
                step(r, amp);
            })
            .expect("a step draws a fixed number of values, at most STEP_DRAWS")
    }

    /// [`Self::round`] planned vertex by vertex in `todo`'s order (any
    /// clusters and free axes).
    pub(super) fn round_planned<const N: usize>(
        &mut self,
        todo: &[u32],
        amp: f64,
        last_resort: bool,
    ) where
        Dim<N, D>: Predicates<N, D>,
    {
        let per_step = self.per_step::<N>(amp);
        self.epoch += 1;
        let mut draws = Draws {
            start: self.rng.clone(),
            used: 0,
            per_step,
        };
        self.plan.clear();
        for block in todo.chunks(PLAN_BLOCK) {
            for &v in block {
                self.plan_move(v, &mut draws, amp, last_resort);
            }
            // this block's moves, drawn in parallel (the plan stays small)
            self.draw_deltas::<N>(&draws.start, amp);
        }
        self.rng = draws.start.ahead(draws.used);
    }

    /// Plans the move of `v` (its whole cluster, once per round) in
    /// [`Self::round`]: into `touched` and `plan`, its step at the next
    /// place of `draws`.
    fn plan_move(&mut self, v: u32, draws: &mut Draws, amp: f64, last_resort: bool) {
        if let Some(axis) = self.free(v) {
            let mut d = [0.0; D];
            d[axis] = if draws.start.ahead(draws.used).unit() < 0.5 {
                amp
            } else {
                -amp
            };
            draws.used += 1;
            self.touched.push(v);
            self.plan.push(Move::Fixed(d));
            self.moved_singular.insert(v);
            return;
        }
        let root = self.clusters.root(v);
        let movable = self.clusters.movable(root);
        if !movable && last_resort {
            self.apart.insert(root);
            self.moved[v as usize] = true;
            self.touched.push(v);
            self.plan.push(Move::Step(draws.next_step(), Rot::IDENTITY));
            return;
        }
        if self.done_epoch[root as usize] == self.epoch {
            return;
        }
        self.done_epoch[root as usize] = self.epoch;
        let at = draws.next_step();
        if !movable {
            self.stuck.insert(root);
            return;
        }
        let (moved, touched, plan) = (&mut self.moved, &mut self.touched, &mut self.plan);
        self.clusters.for_each_member(root, |w, r| {
            moved[w as usize] = true;
            touched.push(w);
            plan.push(Move::Step(at, r));
        });
    }

    /// The moves of the `plan` into `deltas`, in parallel: each step drawn
    /// from `rng` (the round's start) at its place, of length `amp`; the
    /// plan emptied.
    fn draw_deltas<const N: usize>(&mut self, rng: &SplitMix, amp: f64)
    where
        Dim<N, D>: Predicates<N, D>,
    {
        let delta = |m: &Move<D>| match *m {
            Move::Fixed(d) => d,
            Move::Step(at, r) => r.apply(&<Dim<N, D>>::step(&mut rng.ahead(at), amp)),
        };
        self.deltas
            .par_extend(self.plan.par_iter().with_min_len(STEP_TASK).map(delta));
        self.plan.clear();
    }
}

/// Where a round's random values come from: the generator at the round's
/// start, the draws taken so far, the draws of one step.
struct Draws {
    start: SplitMix,
    used: u64,
    per_step: u64,
}

impl Draws {
    /// The place of the next step; its draws taken.
    fn next_step(&mut self) -> u64 {
        let at = self.used;
        self.used += self.per_step;
        at
    }
}

/// The most values one [`Predicates::step`] may draw.
pub(crate) const STEP_DRAWS: u64 = 8;

/// Steps per parallel task of [`Mover::round`].
const STEP_TASK: usize = 4096;

/// Vertices of `todo` planned before their steps are drawn, in
/// [`Mover::round`] (the plan's memory stays below 1 MB).
const PLAN_BLOCK: usize = 4 * STEP_TASK;

/// One vertex's move in a round: a fixed vector, or the random step drawn
/// at a place of the sequence (draws from the round's start) carried by a
/// rotation (from the cluster root's chart).
#[derive(Clone, Copy)]
enum Move<const D: usize> {
    Fixed([f64; D]),
    Step(u64, Rot<D>),
}
