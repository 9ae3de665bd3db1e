//! `inspect`: the whole map analysis in one report.
//!
//! Input: a [`TriMap`] or [`TetMap`] and [`InspectOptions`]. Steps:
//! 1. validate; 2. weld coincident boundary vertices (optional);
//! 3. topology (manifold, oriented); 4. transitions (optionally rounded);
//! 5. stars; 6. singularities; 7. reverted and degenerate simplices.
//!
//! Output: a [`MapReport`] (its JSON form is the facade's
//! `dualex::map_report_json`: this crate has no JSON dependency) and a
//! human-readable [`Display`](std::fmt::Display), or the first
//! [`InputError`]. Singularity indices are reduced fractions of quarters
//! ("1/4", "-1/2", "1", "-5/4"); vertices whose integer part is unknown
//! (folded ring) are keyed by their index modulo 1 ("1/4", "1/2", "3/4").

use std::collections::BTreeMap;
use std::fmt;

use crate::corners::VertexCorners;
use crate::singularity::{edge_singularities, quality, vertex_singularities_with};
use crate::weld::weld;
use crate::{
    InputError, SimplexMap, Stars, TetMap, Topology, TransitionOptions, Transitions, TriMap,
};

/// Options of [`inspect`].
#[derive(Clone, Copy, Debug)]
pub struct InspectOptions {
    /// Weld coincident boundary vertices first (cut meshes).
    pub weld: bool,
    /// Snap non-integral translations instead of failing.
    pub round: bool,
    /// Accepted translation residual (see [`TransitionOptions`]).
    pub tolerance: f64,
}

impl Default for InspectOptions {
    fn default() -> Self {
        InspectOptions {
            weld: true,
            round: false,
            tolerance: TransitionOptions::default().tolerance,
        }
    }
}

/// What [`inspect`] found.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct MapReport {
    /// Map dimension (2 or 3).
    pub dimension: usize,
    /// Triangles or tets.
    pub simplices: usize,
    /// Vertices (after welding).
    pub vertices: usize,
    /// Facets without a neighbour.
    pub boundary_facets: usize,
    /// Boundary loops (2D only).
    pub boundary_loops: Option<usize>,
    /// Connected components.
    pub components: usize,
    /// Simplices with `det < 0`.
    pub reverted: usize,
    /// Degenerate simplices (see [`crate::singularity`]).
    pub degenerate: usize,
    /// Largest translation residual before rounding.
    pub max_transition_residual: f64,
    /// Translations snapped (with `round`).
    pub snapped_transitions: usize,
    /// Facets whose rotation was not determined by the map.
    pub ambiguous_facets: usize,
    /// Interior facets with a non-identity rotation.
    pub non_identity_transitions: usize,
    /// Vertices whose star is inconsistent (2D: singular; 3D: on a singular edge).
    pub singular_vertices: usize,
    /// 2D: interior singularities by index → count.
    pub singularities: BTreeMap<String, usize>,
    /// 2D: singular vertices with unknown integer part, by index mod 1 → count.
    pub singularities_integer_part_unknown: BTreeMap<String, usize>,
    /// 3D: singular edges by angle → count.
    pub singular_edges: BTreeMap<String, usize>,
    /// Vertices merged by welding.
    pub welded_vertices: usize,
}

/// Maps that [`inspect`] accepts: [`TriMap`] and [`TetMap`].
pub trait Inspect {
    /// Runs the analysis (see [`inspect`]).
    fn inspect_map(&self, opts: &InspectOptions) -> Result<MapReport, InputError>;
}

/// Analyses a map (see the module docs).
pub fn inspect<M: Inspect>(map: &M, opts: &InspectOptions) -> Result<MapReport, InputError> {
    map.inspect_map(opts)
}

/// A map after steps 1–5, with the report filled so far.
struct Analysed<const N: usize, const D: usize> {
    map: SimplexMap<N, D>,
    topo: Topology<N>,
    trans: Transitions<N, D>,
    report: MapReport,
}

fn analyse<const N: usize, const D: usize>(
    input: &SimplexMap<N, D>,
    opts: &InspectOptions,
) -> Result<Analysed<N, D>, InputError> {
    input.validate()?;
    let mut report = MapReport {
        dimension: D,
        ..Default::default()
    };
    let map = if opts.weld {
        let (m, w) = weld(input);
        report.welded_vertices = w.welded_vertices;
        m
    } else {
        input.clone()
    };
    let topo = Topology::build(&map)?;
    let topts = TransitionOptions {
        tolerance: opts.tolerance,
        round: opts.round,
        ..Default::default()
    };
    let (trans, trep) = Transitions::derive(&map, &topo, &topts)?;
    let stars = Stars::build(&map, &topo, &trans);
    let (reverted, degenerate) = quality(&map);
    report.simplices = map.len();
    report.vertices = map.positions.len();
    report.boundary_facets = topo.boundary_facets;
    report.components = topo.components();
    report.reverted = reverted;
    report.degenerate = degenerate;
    report.max_transition_residual = trep.max_residual;
    report.snapped_transitions = trep.snapped;
    report.ambiguous_facets = trep.ambiguous_facets;
    report.non_identity_transitions = trep.non_identity;
    report.singular_vertices = stars.singular.iter().filter(|&&s| s).count();
    Ok(Analysed {
        map,
        topo,
        trans,
        report,
    })
}

/// `q/4` as a reduced fraction: "1/4", "-1/2", "1", "-5/4".
pub fn quarters(q: i64) -> String {
    match q.rem_euclid(4) {
        0 => format!("{}", q / 4),
        2 => format!("{}/2", q / 2),
        _ => format!("{q}/4"),
    }
}

/// Singular vertices of a 2D map by index (`"1/4"` → count), and those
/// whose integer part is unknown by index modulo 1 (module docs).
pub fn singularity_histogram(
    map: &TriMap,
    topo: &Topology<3>,
    trans: &Transitions<3, 2>,
) -> (BTreeMap<String, usize>, BTreeMap<String, usize>) {
    let lists = VertexCorners::build(&map.simplices, map.positions.len(), false);
    singularity_histogram_with(map, topo, trans, &lists)
}

/// [`singularity_histogram`] with the map's corner lists
/// ([`crate::singularity::vertex_singularities_with`]).
pub fn singularity_histogram_with(
    map: &TriMap,
    topo: &Topology<3>,
    trans: &Transitions<3, 2>,
    lists: &VertexCorners,
) -> (BTreeMap<String, usize>, BTreeMap<String, usize>) {
    let (mut known, mut unknown) = (BTreeMap::new(), BTreeMap::new());
    for s in vertex_singularities_with(map, topo, trans, lists) {
        match s.index_quarters {
            Some(q) => *known.entry(quarters(q)).or_default() += 1,
            None => *unknown.entry(quarters(s.turns)).or_default() += 1,
        }
    }
    (known, unknown)
}

/// Singular edges of a 3D map by angle label (`"+90°"` → count).
pub fn singular_edge_histogram<'a>(
    edges: impl IntoIterator<Item = &'a crate::singularity::EdgeSingularity>,
) -> BTreeMap<String, usize> {
    let mut h = BTreeMap::new();
    for e in edges {
        *h.entry(e.angle.label().to_string()).or_default() += 1;
    }
    h
}

impl Inspect for TriMap {
    fn inspect_map(&self, opts: &InspectOptions) -> Result<MapReport, InputError> {
        let a = analyse(self, opts)?;
        let mut report = a.report;
        report.boundary_loops = Some(a.topo.boundary_loops(&a.map));
        (
            report.singularities,
            report.singularities_integer_part_unknown,
        ) = singularity_histogram(&a.map, &a.topo, &a.trans);
        Ok(report)
    }
}

impl Inspect for TetMap {
    fn inspect_map(&self, opts: &InspectOptions) -> Result<MapReport, InputError> {
        self.validate()?;
        self.check_not_reflected()?;
        let a = analyse(self, opts)?;
        let mut report = a.report;
        report.singular_edges =
            singular_edge_histogram(&edge_singularities(&a.map, &a.topo, &a.trans));
        Ok(report)
    }
}

fn histogram(m: &BTreeMap<String, usize>) -> String {
    if m.is_empty() {
        return "none".into();
    }
    let parts: Vec<String> = m.iter().map(|(k, v)| format!("{k}: {v}")).collect();
    parts.join(", ")
}

impl fmt::Display for MapReport {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let (w, fw) = if self.dimension == 2 {
            ("triangles", "edges")
        } else {
            ("tets", "faces")
        };
        writeln!(
            f,
            "{} {w}, {} vertices ({} welded)",
            self.simplices, self.vertices, self.welded_vertices
        )?;
        write!(
            f,
            "components: {}, boundary {fw}: {}",
            self.components, self.boundary_facets
        )?;
        if let Some(l) = self.boundary_loops {
            write!(f, ", boundary loops: {l}")?;
        }
        writeln!(f)?;
        writeln!(
            f,
            "reverted {w}: {}, degenerate: {}",
            self.reverted, self.degenerate
        )?;
        writeln!(
            f,
            "transitions: max residual {:e}, {} non-identity, {} snapped, {} ambiguous {fw}",
            self.max_transition_residual,
            self.non_identity_transitions,
            self.snapped_transitions,
            self.ambiguous_facets
        )?;
        if self.dimension == 2 {
            writeln!(
                f,
                "singularities (index: count): {}",
                histogram(&self.singularities)
            )?;
            write!(
                f,
                "singular, integer part unknown (index mod 1: count): {}",
                histogram(&self.singularities_integer_part_unknown)
            )
        } else {
            writeln!(f, "vertices on singular edges: {}", self.singular_vertices)?;
            write!(
                f,
                "singular edges (angle: count): {}",
                histogram(&self.singular_edges)
            )
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fractions() {
        let got: Vec<String> = [1, -2, 4, -5, 2, 3, 6, -4, 0].map(quarters).to_vec();
        assert_eq!(
            got,
            ["1/4", "-1/2", "1", "-5/4", "1/2", "3/4", "3/2", "-1", "0"]
        );
    }
}
