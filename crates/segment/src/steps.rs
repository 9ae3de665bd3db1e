//! Steps 1–7 of both extractions, one function a step, generic over the
//! dimension (`N` corners per simplex, `D` map axes); [`segment`] runs
//! them in order for the drivers (`dualex-quad`, `dualex-hex`), which then
//! untangle (the rest of step 7), run the graph's steps 8–9 and their own
//! repairs (10–11). The numbering is the pipeline's (ARCHITECTURE.md).
//!
//! 1. [`check`], then per pass [`model`]: the map's validity and size
//!    (3D: reflected charts refused, [`InputCheck`]; one walk, which
//!    counts the reverted simplices on the way), its topology,
//!    transitions and vertex stars (`dualex-map`);
//! 2. per pass, in [`prepare`]: the grid offset chosen once and the local
//!    map built with it, its singular vertices snapped
//!    ([`crate::grid_offset::local_map`]);
//! 3. [`prepare`]: the faces that vertices which cannot move span across
//!    the grid split ([`ToSplit`], one `impl` per dimension), steps 1–3
//!    repeated until none is left;
//! 4. [`sanitize`]: the local map's vertices off the dual grid
//!    ([`crate::sanitize`]);
//! 5. [`nodes`]: the integer points inside the simplices
//!    ([`crate::nodes`]);
//! 6. [`trace`]: every node side walked along its iso-line
//!    ([`crate::trace`]);
//! 7. [`link`]: the opposite relation, mutual walks linked into a
//!    [`NodeGraph`] (isolated lost nodes dropped, label-rule violations
//!    counted); its untangling (`NodeGraph::untangle`, in 2D
//!    `untangle_best` with fairing) is the drivers' call.
//!
//! Step 9c's placement, shared too, is in [`crate::place`].
//!
//! Input: a map (not yet validated) and the options. Output: the (split)
//! map, the input simplex of each of its simplices, the sanitized local
//! map, the nodes, the walk ends and the linked graph, with their counts
//! in a [`SegmentStats`] and stage laps (`map`, `sanitize`, `nodes`,
//! `trace`). Invariants: every step is deterministic whatever the number
//! of threads; a pass of step 3 splits at least one face, and the passes
//! stop at [`ToSplit::max_split`] faces.

use crate::diagonal::DiagonalStep;
use crate::grid_offset::{local_map, GridOffset};
use crate::local::LocalMap;
use crate::nodes::Nodes;
use crate::sanitize::Predicates;
use crate::simplex::{Dim, Simplex};
use crate::singular_snap::SingularSnap;
use crate::split::{split_faces_traced, Pass, ToSplit};
use crate::stats::SegmentStats;
use crate::trace::End;
use dualex_graph::NodeGraph;
use dualex_map::corners::VertexCorners;
use dualex_map::{
    InputCounts, InputError, SimplexMap, Stars, Topology, TransitionOptions, Transitions,
};
use dualex_util::timing::Laps;
use std::borrow::Cow;

/// Everything a dimension implements for the generic steps: the input
/// check ([`InputCheck`]), the predicates of the nodes, walks and diagonal
/// walk ([`Simplex`], [`DiagonalStep`]), of sanitization ([`Predicates`])
/// and of the split ([`ToSplit`]).
pub trait Dimension<const N: usize, const D: usize>:
    InputCheck<N, D> + Simplex<N, D> + DiagonalStep<N, D> + Predicates<N, D> + ToSplit<N, D>
{
}

impl<T, const N: usize, const D: usize> Dimension<N, D> for T where
    T: InputCheck<N, D> + Simplex<N, D> + DiagonalStep<N, D> + Predicates<N, D> + ToSplit<N, D>
{
}

/// Step 1's input checks: validity, size and what the dimension refuses,
/// in one walk (`dualex_map::scan`).
pub trait InputCheck<const N: usize, const D: usize> {
    /// The first error, in the order of the checks, or the input's counts.
    fn check(map: &SimplexMap<N, D>) -> Result<InputCounts, InputError>;
}

impl InputCheck<3, 2> for Dim<3, 2> {
    /// D = 2: validity and size (`TriMap::checked`).
    fn check(map: &SimplexMap<3, 2>) -> Result<InputCounts, InputError> {
        map.checked()
    }
}

impl InputCheck<4, 3> for Dim<4, 3> {
    /// D = 3: also charts reflected as a whole (`TetMap::checked`).
    fn check(map: &SimplexMap<4, 3>) -> Result<InputCounts, InputError> {
        map.checked()
    }
}

/// The options of steps 1–4.
#[derive(Clone, Copy, Debug)]
pub struct Options<'a> {
    /// Transition derivation options (step 1).
    pub transitions: &'a TransitionOptions,
    /// Where the dual grid sits (step 2).
    pub grid_offset: GridOffset,
    /// Seed of the sanitization perturbations (step 4).
    pub seed: u64,
}

impl<'a> Options<'a> {
    /// The options of steps 1–4 (module docs).
    pub fn new(transitions: &'a TransitionOptions, grid_offset: GridOffset, seed: u64) -> Self {
        Options {
            transitions,
            grid_offset,
            seed,
        }
    }
}

/// What steps 1–7 leave: the sanitized map, its nodes, the end of every
/// node side's walk and the linked graph (not yet untangled).
pub struct Segmented<'a, const N: usize, const D: usize> {
    /// The sanitized (split) map.
    pub sanitized: Sanitized<'a, N, D>,
    /// Its nodes.
    pub nodes: Nodes<N, D>,
    /// Per side (`node·2D + dir`), how its walk ended.
    pub ends: Vec<End<D>>,
    /// The nodes with every mutual pair of walks linked.
    pub graph: NodeGraph<D>,
}

/// Steps 1–7 in order (module docs), `first_pass` as in [`prepare`],
/// also given the input's counts from [`check`].
pub fn segment<'a, const N: usize, const D: usize>(
    map: &'a SimplexMap<N, D>,
    opts: &Options<'_>,
    st: &mut SegmentStats,
    laps: &mut Laps,
    first_pass: impl FnOnce(
        &SimplexMap<N, D>,
        &Model<N, D>,
        &<Dim<N, D> as ToSplit<N, D>>::Singular,
        &InputCounts,
    ),
) -> Result<Segmented<'a, N, D>, InputError>
where
    Dim<N, D>: Dimension<N, D>,
{
    let counts = check(map)?;
    let read = |m: &_, model: &_, singular: &_| first_pass(m, model, singular, &counts);
    let prepared = prepare(map, opts, st, read)?;
    laps.lap("map");
    Ok(segment_prepared(prepared, opts.seed, st, laps))
}

/// Steps 4–7 in order on what steps 1–3 left (for [`segment`], and for
/// the drivers' retry on a relaxed local map: `crate::relax::retry`).
pub fn segment_prepared<'a, const N: usize, const D: usize>(
    prepared: Prepared<'a, N, D>,
    seed: u64,
    st: &mut SegmentStats,
    laps: &mut Laps,
) -> Segmented<'a, N, D>
where
    Dim<N, D>: Dimension<N, D>,
{
    let sanitized = sanitize(prepared, seed, st, laps);
    let nodes = nodes(&sanitized.local, st, laps);
    let ends = trace(&sanitized, &nodes, st);
    let graph = link(&nodes, &ends, st, laps);
    Segmented {
        sanitized,
        nodes,
        ends,
        graph,
    }
}

/// Step 1's model of one pass.
pub struct Model<const N: usize, const D: usize> {
    /// Adjacency.
    pub topo: Topology<N>,
    /// Transitions across the facets.
    pub trans: Transitions<N, D>,
    /// Vertex stars, singular flags.
    pub stars: Stars<D>,
    /// The corner lists the model was built from, without their
    /// positions (read by a first pass: the 2D singularity statistics;
    /// dropped before the local map).
    pub corners: VertexCorners,
}

/// What steps 1–3 leave: the map the rest runs on and its local map.
pub struct Prepared<'a, const N: usize, const D: usize> {
    /// The input, or its split (step 3).
    pub map: Cow<'a, SimplexMap<N, D>>,
    /// Per simplex of `map`, the input simplex it is (a piece of).
    pub parent: Vec<u32>,
    /// Adjacency of `map`.
    pub topo: Topology<N>,
    /// Vertex stars of `map` (read by sanitization, then dropped).
    pub stars: Stars<D>,
    /// The local map, singular vertices snapped.
    pub local: LocalMap<N, D>,
    /// The free axes of the singular vertices ([`ToSplit::free_axes`]).
    pub free: Vec<Option<usize>>,
    /// What snapping the singular vertices did.
    pub snap: SingularSnap,
}

/// What step 4 leaves: [`Prepared`] without the stars, sanitized.
pub struct Sanitized<'a, const N: usize, const D: usize> {
    /// The input, or its split (step 3).
    pub map: Cow<'a, SimplexMap<N, D>>,
    /// Per simplex of `map`, the input simplex it is (a piece of).
    pub parent: Vec<u32>,
    /// Adjacency of `map`.
    pub topo: Topology<N>,
    /// The sanitized local map.
    pub local: LocalMap<N, D>,
}

/// Step 1, once: refuses an invalid map, one whose images span absurdly
/// many grid points (before any allocation, `crate::nodes::check_size`),
/// and what the dimension refuses, in one walk ([`InputCheck`]); counts
/// the input's reverted (3D: and degenerate) simplices.
pub fn check<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
) -> Result<InputCounts, InputError>
where
    Dim<N, D>: Dimension<N, D>,
{
    Dim::<N, D>::check(map)
}

/// Step 1, per pass: topology, transitions (their residual and roundings
/// counted) and vertex stars (singular vertices counted).
pub fn model<const N: usize, const D: usize>(
    map: &SimplexMap<N, D>,
    opts: &TransitionOptions,
    st: &mut SegmentStats,
) -> Result<Model<N, D>, InputError> {
    // the corner lists, built once for the topology and the stars; each
    // corner's place in its list only in 3D (the 2D stars' fans find
    // their way without it, a vertex of several fans by a search)
    let corners = VertexCorners::build(&map.simplices, map.positions.len(), D == 3);
    // the topology's vertex check is made by the stars' walk (no walk of
    // its own); errors keep their order: a transition's error comes after
    // a vertex's
    // (each transition fitted where the topology glues its pair)
    let (topo, derived) = Transitions::glue_derive(map, &corners, opts)?;
    let (trans, trep) = match derived {
        Ok(derived) => derived,
        Err(e) => {
            // the vertex check's walk needs the places (an error's path)
            let indexed;
            let corners = if corners.position.is_empty() {
                indexed = VertexCorners::build(&map.simplices, map.positions.len(), true);
                &indexed
            } else {
                &corners
            };
            topo.check_vertices(map, corners)?;
            return Err(e);
        }
    };
    st.max_transition_residual = trep.max_residual;
    st.snapped_transitions = trep.snapped;
    let stars = Stars::build_checked(map, &topo, &trans, &corners)?;
    st.singular_vertices = stars.singular.iter().filter(|&&s| s).count();
    // the positions were for the walks only
    let corners = VertexCorners {
        position: Vec::new(),
        ..corners
    };
    Ok(Model {
        topo,
        trans,
        stars,
        corners,
    })
}

/// Steps 1–3, repeated until nothing is left to split: the model, the
/// local map with the grid offset chosen on the first pass (splits add no
/// singular vertex), the faces to split. `first_pass` reads the input's
/// own model once (a dimension's input counts).
pub fn prepare<'a, const N: usize, const D: usize>(
    map: &'a SimplexMap<N, D>,
    opts: &Options<'_>,
    st: &mut SegmentStats,
    first_pass: impl FnOnce(&SimplexMap<N, D>, &Model<N, D>, &<Dim<N, D> as ToSplit<N, D>>::Singular),
) -> Result<Prepared<'a, N, D>, InputError>
where
    Dim<N, D>: Dimension<N, D>,
{
    let input = map.len();
    let mut map = Cow::Borrowed(map);
    // the identity, written on the pool (its pages' first touch: ~1.4 ms
    // on one thread for 1M tets)
    let mut parent: Vec<u32> = {
        use rayon::prelude::*;
        (0..input as u32)
            .into_par_iter()
            .with_min_len(1 << 16)
            .collect()
    };
    let mut first_pass = Some(first_pass);
    let mut chosen = None;
    loop {
        let m = model(&map, opts.transitions, st)?;
        let singular = Dim::<N, D>::singular(&map, &m.topo, &m.trans, &m.stars);
        if let Some(read) = first_pass.take() {
            read(&map, &m, &singular);
        }
        let Model {
            topo,
            trans,
            stars,
            corners,
        } = m;
        drop(corners);
        // step 2: the local map takes the transitions over (no copy)
        let (local, snap, choice) = local_map(&map, &topo, trans, &stars, opts.grid_offset, chosen);
        chosen = Some(choice);
        st.grid_offset = choice;
        // step 3
        let free = Dim::<N, D>::free_axes(&topo, &stars, &local);
        let pass = Pass {
            map: &map,
            topo: &topo,
            stars: &stars,
            local: &local,
            free: &free,
        };
        let faces = Dim::<N, D>::faces(&pass, &singular);
        if faces.is_empty() || st.split >= Dim::<N, D>::max_split(input, map.len()) {
            return Ok(Prepared {
                map,
                parent,
                topo,
                stars,
                local,
                free,
                snap,
            });
        }
        let (next, applied, pieces) = split_faces_traced(&map, &faces);
        parent = pieces.iter().map(|&p| parent[p as usize]).collect();
        st.split += applied;
        map = Cow::Owned(next);
    }
}

/// Step 4: sanitization with the seed of its perturbations; the stars are
/// dropped after it. Laps `sanitize`.
pub fn sanitize<'a, const N: usize, const D: usize>(
    p: Prepared<'a, N, D>,
    seed: u64,
    st: &mut SegmentStats,
    laps: &mut Laps,
) -> Sanitized<'a, N, D>
where
    Dim<N, D>: Dimension<N, D>,
{
    let Prepared {
        map,
        parent,
        topo,
        stars,
        mut local,
        free,
        snap,
    } = p;
    st.sanitize = crate::sanitize::sanitize(&map, &topo, &stars, &free, &mut local, seed);
    st.sanitize.singular_snap = snap;
    drop(stars);
    laps.lap("sanitize");
    Sanitized {
        map,
        parent,
        topo,
        local,
    }
}

/// Step 5: the nodes, counted (and those in reverted simplices). Laps
/// `nodes`.
pub fn nodes<const N: usize, const D: usize>(
    local: &LocalMap<N, D>,
    st: &mut SegmentStats,
    laps: &mut Laps,
) -> Nodes<N, D>
where
    Dim<N, D>: Dimension<N, D>,
{
    let nodes = Nodes::find(local);
    st.nodes = nodes.len();
    st.reverted_nodes = nodes.reverted.iter().filter(|&&r| r).count();
    laps.lap("nodes");
    nodes
}

/// Step 6: the end of every node side's walk, the outcomes counted.
pub fn trace<const N: usize, const D: usize>(
    s: &Sanitized<'_, N, D>,
    nodes: &Nodes<N, D>,
    st: &mut SegmentStats,
) -> Vec<End<D>>
where
    Dim<N, D>: Dimension<N, D>,
{
    let (ends, rep) = crate::trace::trace_all(&s.local, &s.topo, nodes);
    st.trace = rep;
    ends
}

/// Step 7's opposite relation: the graph of the nodes with every mutual
/// pair of walks linked, isolated nodes whose walks were all lost dropped,
/// label-rule violations counted. Laps `trace` (steps 6 and 7).
pub fn link<const N: usize, const D: usize>(
    nodes: &Nodes<N, D>,
    ends: &[End<D>],
    st: &mut SegmentStats,
    laps: &mut Laps,
) -> NodeGraph<D> {
    let mut graph = NodeGraph::<D>::new(nodes.reverted.clone());
    st.links = graph.link_mutual(ends);
    st.isolated_dropped = graph.drop_isolated_lost(ends);
    st.label_violations = graph.label_violations();
    laps.lap("trace");
    graph
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The vertex check made by the stars' walk keeps the errors' order:
    /// a pinched vertex is named before a transition's error, as by
    /// [`Topology::build`].
    #[test]
    fn a_pinched_vertex_comes_before_a_reflection() {
        // triangles 0 and 1 differ by a reflection; triangle 2 touches
        // them at vertex 0 only
        let map = SimplexMap::<3, 2> {
            positions: vec![[0.0; 3]; 6],
            simplices: vec![[0, 1, 2], [2, 1, 3], [0, 4, 5]],
            coords: vec![
                [[0.0, 0.0], [2.0, 0.0], [0.0, 1.0]],
                [[1.0, 0.0], [0.0, 2.0], [2.0, 1.0]],
                [[5.0, 5.0], [6.0, 5.0], [5.0, 6.0]],
            ],
        };
        let want = Topology::build(&map).expect_err("pinched").to_string();
        assert!(want.contains("vertex 0 is non-manifold"), "{want}");
        let opts = TransitionOptions::default();
        let got = model(&map, &opts, &mut SegmentStats::default());
        assert_eq!(got.err().map(|e| e.to_string()), Some(want));
        // without the pinch, the reflection
        let mut map = map;
        map.simplices[2] = [6, 4, 5];
        map.positions.push([0.0; 3]);
        let got = model(&map, &opts, &mut SegmentStats::default());
        let e = got.err().map(|e| e.to_string()).unwrap_or_default();
        assert!(e.contains("reflection"), "{e}");
    }
}
