//! The grid offset: where the dual grid sits relative to the map's integer
//! grid (both dimensions, one piece of code).
//!
//! Input: a map and its vertex stars (singular flags). Output: the chosen
//! [`GridOffset`] (`Half` or `Zero`) and the counts it was chosen on
//! ([`OffsetChoice`]).
//!
//! The local coordinates of [`crate::local::LocalMap`] are the map shifted
//! by `h` and the dual grid's nodes are their integer points. Both
//! `h = (½, …, ½)` (`Half`, the default of the literature: nodes at
//! half-integers of the map, output vertices at its integer points) and
//! `h = 0` (`Zero`) keep every transition grid-preserving: `h − R·h` is
//! integral for every grid rotation `R`.
//!
//! A singular vertex on a node (a 90° singularity exactly at a cell centre,
//! e.g. every chart of a valid map offset by ½) makes a 3-sided face, and
//! one on an iso makes walks through it inconsistent; sanitization cannot
//! move singular vertices. [`GridOffset::Auto`] therefore counts, for both
//! offsets, the singular vertices on a node (every coordinate within
//! [`ON_GRID`] of an integer after the shift) and those on an iso (some
//! coordinate within [`ON_GRID`] of an integer), and picks the offset with
//! fewer on nodes, then fewer on isos; then fewer boundary facets lying in
//! an iso (a mesh's boundary runs along its edges or faces, which the dual
//! grid's isos must not: a map shifted by ½ has its boundary in isos under
//! `Half`, a map from a real pipeline has it there under `Zero`). Regular
//! interior vertices do not count: where they sit says nothing about which
//! mesh the map carries (MC3D's maps have tet vertices at the hex
//! centres), and sanitization moves them. A full tie keeps `Half`, so
//! that maps that do not care extract exactly as before. A vertex is read
//! at its reference corner (first star entry) in that simplex's chart.

use crate::local::{local_transition, simplex_offsets, LocalMap};
use crate::singular_snap::{singular_corners, snap_singular, Chart, SingularSnap, Snapped};
use dualex_map::topology::NONE;
use dualex_map::{Rot, SimplexMap, Stars, Topology, Transitions};
use rayon::prelude::*;
use std::collections::HashMap;

/// Distance to an integer below which a singular vertex's coordinate counts
/// as on the grid, in map units. Looser than [`crate::grid::EPS`] (which
/// judges local coordinates after snapping) so that a vertex a float's
/// jitter away from a node, as written by another tool, still counts.
pub const ON_GRID: f64 = 1e-6;

/// Where the dual grid's nodes sit (`--grid-offset`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum GridOffset {
    /// Choose `Half` or `Zero` from the singular vertices (module docs).
    #[default]
    Auto,
    /// Map shifted by (½, …, ½): nodes at the map's half-integers.
    Half,
    /// No shift: nodes at the map's integer points.
    Zero,
}

impl GridOffset {
    /// The shift added to every coordinate (`Auto` counts as `Half`).
    pub fn shift(self) -> f64 {
        match self {
            GridOffset::Zero => 0.0,
            GridOffset::Auto | GridOffset::Half => 0.5,
        }
    }

    /// The name used by the CLI and the stats (`auto`, `half`, `zero`).
    pub fn name(self) -> &'static str {
        match self {
            GridOffset::Auto => "auto",
            GridOffset::Half => "half",
            GridOffset::Zero => "zero",
        }
    }

    /// Parses [`Self::name`].
    pub fn parse(s: &str) -> Option<Self> {
        match s {
            "auto" => Some(GridOffset::Auto),
            "half" => Some(GridOffset::Half),
            "zero" => Some(GridOffset::Zero),
            _ => None,
        }
    }
}

/// Vertices on the dual grid under one offset.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OnGrid {
    /// Singular vertices on a node (every coordinate on an iso).
    pub on_node: usize,
    /// Singular vertices on an iso (some coordinate integral), nodes
    /// included.
    pub on_iso: usize,
    /// Boundary facets lying in an iso (all their corners share one
    /// integral coordinate).
    pub boundary_on_iso: usize,
}

/// The offset used and what it was chosen on.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct OffsetChoice {
    /// `Half` or `Zero`, never `Auto`.
    pub offset: GridOffset,
    /// Counts under `Half` (zero unless `Auto`).
    pub half: OnGrid,
    /// Counts under `Zero` (zero unless `Auto`).
    pub zero: OnGrid,
}

/// Whether `x + shift` is within [`ON_GRID`] of an integer (`x − floor(x)`
/// is exact, so large coordinates are judged like small ones).
fn on_iso(x: f64, shift: f64) -> bool {
    let f = x - dualex_util::round::floor(x) + shift;
    (f - dualex_util::round::round(f)).abs() < ON_GRID
}

/// Counts the singular vertices on the grid under both offsets.
pub fn count_on_grid<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    stars: &Stars<D>,
) -> (OnGrid, OnGrid) {
    count_in(|s| map.coords[s], map.coords.len(), 0.0, topo, stars)
}

/// [`count_on_grid`] on the per-corner coordinates `coords_of(s)` of the
/// `len` simplices, which carry the shift `base` already (`0.5`: the ½
/// chart). Reads the simplices with a boundary facet and the reference
/// corners of the singular vertices only.
fn count_in<const N: usize, const D: usize>(
    coords_of: impl Fn(usize) -> [[f64; D]; N] + Sync,
    len: usize,
    base: f64,
    topo: &Topology<N>,
    stars: &Stars<D>,
) -> (OnGrid, OnGrid) {
    let (mut half, mut zero) = (OnGrid::default(), OnGrid::default());
    let shifts = [(0.5 - base), (0.0 - base)];
    // the simplices in parallel: counts, the same for every split
    let flat = |s: usize| boundary_on_iso(&coords_of(s), s, topo, shifts);
    [half.boundary_on_iso, zero.boundary_on_iso] = (0..len)
        .into_par_iter()
        .with_min_len(4096)
        .filter(|&s| topo.adj[s].contains(&NONE))
        .map(flat)
        .reduce(|| [0, 0], |a, b| [a[0] + b[0], a[1] + b[1]]);
    for v in (0..stars.singular.len()).filter(|&v| stars.singular[v]) {
        let Some(e) = stars.of(v).first() else {
            continue;
        };
        if e.simplex as usize >= len || e.corner as usize >= N {
            continue;
        }
        let p = coords_of(e.simplex as usize)[e.corner as usize];
        for (count, shift) in [(&mut half, shifts[0]), (&mut zero, shifts[1])] {
            let on = p.iter().filter(|&&x| on_iso(x, shift)).count();
            count.on_node += usize::from(on == D);
            count.on_iso += usize::from(on > 0);
        }
    }
    (half, zero)
}

/// The boundary facets of simplex `s` (its corners `c`) that lie in an
/// iso under each of the two `shifts` (all their corners share one
/// coordinate within [`ON_GRID`] of the grid).
fn boundary_on_iso<const N: usize, const D: usize>(
    c: &[[f64; D]; N],
    s: usize,
    topo: &Topology<N>,
    shifts: [f64; 2],
) -> [usize; 2] {
    let mut counts = [0; 2];
    for f in (0..N).filter(|&f| topo.neighbour(s, f).is_none()) {
        let mut corners = (0..N).filter(|&k| k != f).map(|k| &c[k]);
        let Some(first) = corners.next() else {
            continue;
        };
        let rest: Vec<&[f64; D]> = corners.collect();
        for (count, shift) in counts.iter_mut().zip(shifts) {
            let flat = (0..D).any(|k| {
                on_iso(first[k], shift) && rest.iter().all(|p| (p[k] - first[k]).abs() < ON_GRID)
            });
            *count += usize::from(flat);
        }
    }
    counts
}

/// Resolves `opt`: `Half` and `Zero` as given, `Auto` by the counts.
pub fn choose<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    stars: &Stars<D>,
    opt: GridOffset,
) -> OffsetChoice {
    if opt != GridOffset::Auto {
        return given(opt);
    }
    decide(count_on_grid(map, topo, stars))
}

/// The choice of an offset given (`Half` or `Zero`): no counts.
fn given(offset: GridOffset) -> OffsetChoice {
    OffsetChoice {
        offset,
        ..Default::default()
    }
}

/// Step 2 of both extractions, the one place the grid offset is decided:
/// the offset chosen, then the local map built once with it, its singular
/// vertices snapped ([`crate::singular_snap`]). `chosen`: the choice of an
/// earlier pass on the same input (the drivers split the map and build
/// again; splits add no singular vertex), kept as it is.
///
/// `Auto` is decided on the singular vertices snapped in the chart `Half`
/// (a vertex a float's jitter away from a node is exactly on it then), read
/// on demand around them and on the boundary ([`choose_snapped`]); the
/// local map is then built with the chosen offset, its coordinates rounded
/// in that chart ([`LocalMap::with_grid_in`]: for `Zero`, `(x + ½) − ½`,
/// not `x`, so that every output is as when the choice was made on a map
/// built with `Half` and shifted back), and the snapped corners written
/// into it less the offsets' difference (exact).
pub fn local_map<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    trans: Transitions<N, D>,
    stars: &Stars<D>,
    opt: GridOffset,
    chosen: Option<OffsetChoice>,
) -> (LocalMap<N, D>, SingularSnap, OffsetChoice) {
    let offset = simplex_offsets(map);
    let (choice, chart, snapped) = match (chosen, opt) {
        (Some(c), _) => (c, c.offset, None),
        (None, GridOffset::Auto) => {
            let chart = HalfChart {
                map,
                topo,
                trans: &trans,
                offset: &offset,
            };
            let (c, snapped) = choose_in_half(&chart, map.coords.len(), topo, stars);
            (c, GridOffset::Half, Some(snapped))
        }
        (None, given_offset) => (given(given_offset), given_offset, None),
    };
    let mut local = LocalMap::with_grid_in(map, topo, trans, offset, choice.offset, chart);
    let snap = match snapped {
        Some((rep, corners)) => {
            let back = chart.shift() - choice.offset.shift();
            for (v, xs) in corners {
                for (e, x) in stars.of(v as usize).iter().zip(xs) {
                    let x = if back == 0.0 { x } else { x.map(|y| y - back) };
                    local.coords[e.simplex as usize][e.corner as usize] = x;
                }
            }
            rep
        }
        None => snap_singular(&mut local, topo, stars),
    };
    (local, snap, choice)
}

/// Resolves `opt` as [`local_map`] does, without building the local map
/// (`dualex-extrude` asks which offset `dualex quad` takes).
pub fn choose_snapped<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    topo: &Topology<N>,
    trans: &Transitions<N, D>,
    stars: &Stars<D>,
    opt: GridOffset,
) -> OffsetChoice {
    if opt != GridOffset::Auto {
        return given(opt);
    }
    let offset = simplex_offsets(map);
    let chart = HalfChart {
        map,
        topo,
        trans,
        offset: &offset,
    };
    choose_in_half(&chart, map.coords.len(), topo, stars).0
}

/// `Auto` decided on the chart `Half` ([`HalfChart`]) with the singular
/// vertices snapped; also returns the snapped corners.
fn choose_in_half<const N: usize, const D: usize>(
    chart: &HalfChart<'_, N, D>,
    len: usize,
    topo: &Topology<N>,
    stars: &Stars<D>,
) -> (OffsetChoice, Snapped<D>) {
    let (rep, corners) = singular_corners(chart, topo, stars);
    // the snapped corners, by (simplex, corner)
    let mut at: HashMap<(u32, u8), [f64; D]> = HashMap::new();
    for (v, xs) in &corners {
        for (e, x) in stars.of(*v as usize).iter().zip(xs) {
            at.insert((e.simplex, e.corner), *x);
        }
    }
    let coords_of = |s: usize| -> [[f64; D]; N] {
        std::array::from_fn(|c| match at.get(&(s as u32, c as u8)) {
            Some(x) => *x,
            None => chart.corner(s, c),
        })
    };
    let counts = count_in(coords_of, len, 0.5, topo, stars);
    (decide(counts), (rep, corners))
}

/// The local coordinates and transitions of the chart `Half`
/// ([`LocalMap::with_grid`] at `Half`, bit for bit), computed on demand
/// for the simplices asked for.
struct HalfChart<'a, const N: usize, const D: usize> {
    map: &'a SimplexMap<N, D>,
    topo: &'a Topology<N>,
    trans: &'a Transitions<N, D>,
    /// [`crate::local::simplex_offset`] of every simplex.
    offset: &'a [[i64; D]],
}

impl<const N: usize, const D: usize> Chart<N, D> for HalfChart<'_, N, D> {
    fn corner(&self, s: usize, c: usize) -> [f64; D] {
        let o = self.offset[s];
        let p = self.map.coords[s][c];
        std::array::from_fn(|k| (p[k] - o[k] as f64) + 0.5)
    }

    fn transition(&self, s: usize, f: usize) -> (Rot<D>, [i64; D]) {
        let (r, t) = (self.trans.rot[s][f], self.trans.trans[s][f]);
        let Some((n, _)) = self.topo.neighbour(s, f) else {
            return (r, t);
        };
        (
            r,
            local_transition(&r, &t, &self.offset[s], &self.offset[n], 0.5),
        )
    }
}

/// The offset with fewer singular vertices on nodes, then on isos, then
/// fewer boundary facets in isos; `Half` on a tie.
fn decide((half, zero): (OnGrid, OnGrid)) -> OffsetChoice {
    let key = |c: OnGrid| (c.on_node, c.on_iso, c.boundary_on_iso);
    OffsetChoice {
        offset: if key(zero) < key(half) {
            GridOffset::Zero
        } else {
            GridOffset::Half
        },
        half,
        zero,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn names_round_trip() {
        for g in [GridOffset::Auto, GridOffset::Half, GridOffset::Zero] {
            assert_eq!(GridOffset::parse(g.name()), Some(g));
        }
        assert_eq!(GridOffset::parse("quarter"), None);
    }

    #[test]
    fn on_iso_judges_the_fraction() {
        assert!(on_iso(3.0, 0.0) && on_iso(-2.5, 0.5) && on_iso(2.5 + 1e-9, 0.5));
        assert!(!on_iso(3.0, 0.5) && !on_iso(2.5, 0.0) && !on_iso(0.25, 0.5));
        let big = (1u64 << 40) as f64;
        assert!(on_iso(big + 0.5, 0.5) && !on_iso(big + 0.5, 0.0));
    }
}
