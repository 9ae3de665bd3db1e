//! [`trace_all`] (the sides of positive direction walked, the sides they
//! reached written as the reverse when [`trace`] says it is) against the
//! former form, every side walked ([`dualex_graph::walk::walk_all`]), the
//! oracle: the same ends and report on every generated map, sanitized
//! and not (nodes near facets, vertices on isos), and with the local
//! coordinates rounded onto a coarse lattice, which breaks the charts'
//! agreement (walks that do not come back, corner crossings on one side
//! only, nodes on the crossings).

use super::*;
use crate::stats::SegmentStats;
use crate::steps::{prepare, sanitize, Dimension, Options, Prepared};
use dualex_map::{SimplexMap, TransitionOptions};
use dualex_util::rng::SplitMix;
use dualex_util::timing::Laps;

/// Both forms on `local`; returns the walks the paired form derived.
fn compare<const N: usize, const D: usize>(
    local: &LocalMap<N, D>,
    topo: &Topology<N>,
    what: &str,
) -> usize
where
    Dim<N, D>: Simplex<N, D>,
{
    let nodes = Nodes::find(local);
    let max_steps = N * local.coords.len() + N;
    let walk = |n, d| trace(local, topo, &nodes, n, d, max_steps);
    let (want, want_rep) = dualex_graph::walk::walk_all(nodes.len(), |n, d| {
        let t = walk(n, d);
        (t.end, t.steps)
    });
    let (got, got_rep) = trace_all(local, topo, &nodes);
    assert_eq!(got_rep, want_rep, "{what}");
    for (s, (g, w)) in got.iter().zip(&want).enumerate() {
        assert_eq!(g, w, "{what}: side {s}");
    }
    // the walks the paired form derives: odd sides reached by even ones
    (0..nodes.len() * 2 * D)
        .step_by(2)
        .filter(|&s| {
            let t = walk(s / (2 * D), s % (2 * D));
            matches!(t.end, End::Node { side, .. } if side % 2 == 1) && t.back
        })
        .count()
}

/// Steps 1–3 of `map`.
fn prepared<'a, const N: usize, const D: usize>(
    map: &'a SimplexMap<N, D>,
    opts: &TransitionOptions,
) -> Option<Prepared<'a, N, D>>
where
    Dim<N, D>: Dimension<N, D>,
{
    let o = Options::new(opts, Default::default(), 7);
    prepare(map, &o, &mut SegmentStats::default(), |_, _, _| {}).ok()
}

/// Every local coordinate rounded to a multiple of `1 / k`.
fn coarse<const N: usize, const D: usize>(local: &mut LocalMap<N, D>, k: f64) {
    for c in local.coords.iter_mut().flatten().flatten() {
        *c = (*c * k).round() / k;
    }
}

/// Each corner on its own (the charts of a vertex then disagree): one in
/// five gets a coordinate moved onto its nearest integer (an iso), one in
/// five a few ulps beside it, one in five a coordinate moved by a few ulps.
fn jolt<const N: usize, const D: usize>(local: &mut LocalMap<N, D>, seed: u64) {
    let mut rng = SplitMix::new(seed);
    for c in local.coords.iter_mut().flatten() {
        let (u, axis) = (rng.unit(), (rng.unit() * D as f64) as usize % D);
        let ulps = |x: f64, k: f64| x + x.abs().max(1.0) * f64::EPSILON * k;
        if u < 0.2 {
            c[axis] = c[axis].round();
        } else if u < 0.4 {
            // an integer's neighbourhood: nodes a few ulps off the facets
            c[axis] = ulps(c[axis].round(), (u - 0.3) * 40.0);
        } else if u < 0.6 {
            c[axis] = ulps(c[axis], (u - 0.5) * 40.0);
        }
    }
}

/// `map` before and after sanitization, rounded and jolted; the walks
/// derived.
fn check_map<const N: usize, const D: usize>(map: &SimplexMap<N, D>, what: &str) -> usize
where
    Dim<N, D>: Dimension<N, D>,
{
    let opts = TransitionOptions::default();
    let Some(p) = prepared(map, &opts) else {
        return 0;
    };
    let mut derived = compare(&p.local, &p.topo, &format!("{what}, not sanitized"));
    let s = sanitize(p, 7, &mut SegmentStats::default(), &mut Laps::start());
    derived += compare(&s.local, &s.topo, &format!("{what}, sanitized"));
    for k in [1.0, 2.0, 4.0] {
        let mut local = s.local.clone();
        coarse(&mut local, k);
        derived += compare(&local, &s.topo, &format!("{what}, rounded to 1/{k}"));
    }
    for seed in 1..=4 {
        let mut local = s.local.clone();
        jolt(&mut local, seed);
        derived += compare(&local, &s.topo, &format!("{what}, jolted {seed}"));
    }
    derived
}

#[test]
fn paired_walks_equal_every_side_walked_in_2d() {
    let mut derived = 0;
    for name in dualex_gen::registry::names() {
        for seed in [1, 2] {
            let Some((map, _)) = dualex_gen::registry::by_name(&name, seed) else {
                continue;
            };
            derived += check_map(&map, &format!("{name} {seed}"));
        }
    }
    assert!(derived > 10_000, "{derived} walks derived");
}

#[test]
fn paired_walks_equal_every_side_walked_in_3d() {
    let mut derived = 0;
    for name in dualex_gen::registry::names_3d() {
        for seed in [1, 2] {
            let Some((map, _)) = dualex_gen::registry::by_name_3d(&name, seed) else {
                continue;
            };
            derived += check_map(&map, &format!("{name} {seed}"));
        }
    }
    assert!(derived > 4_000, "{derived} walks derived");
}
