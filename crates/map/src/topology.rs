//! Facet adjacency of a simplicial mesh, boundary, manifoldness and
//! orientation checks.
//!
//! Input: a validated [`SimplexMap`]. Output: [`Topology`], or an
//! [`InputError`] naming the first non-manifold facet / vertex or the first
//! pair of inconsistently oriented simplices.
//!
//! Invariants: `adj` is an involution on interior facets
//! (`adj[adj[s][f]][adj_facet[s][f]] == s`); facet `f` is the one opposite
//! corner `f` (see [`crate::mesh`]).

use crate::corners::VertexCorners;
use crate::{InputError, SimplexMap};

/// Marks "no neighbour" (boundary facet) in [`Topology::adj`].
pub const NONE: u32 = u32::MAX;

/// Facet adjacency.
#[derive(Clone, Debug, Default)]
pub struct Topology<const N: usize> {
    /// Neighbouring simplex across each facet, or [`NONE`] on the boundary.
    pub adj: Vec<[u32; N]>,
    /// Index of the shared facet in the neighbour.
    pub adj_facet: Vec<[u8; N]>,
    /// `nbr_corner[s][f][c]`: the corner of the neighbour across facet `f`
    /// that holds the same vertex as corner `c` of `s` (`c != f`); entry `f`
    /// holds the neighbour's opposite corner `adj_facet[s][f]`.
    pub nbr_corner: Vec<[[u8; N]; N]>,
    /// Number of boundary facets.
    pub boundary_facets: usize,
}

impl<const N: usize> Topology<N> {
    /// Builds the adjacency and checks manifoldness and orientation.
    pub fn build<const D: usize>(map: &SimplexMap<N, D>) -> Result<Self, InputError> {
        crate::topology_build::build(map)
    }

    /// [`Self::build`] with the map's corner lists, built `indexed`
    /// ([`VertexCorners::build`]; shared with [`crate::Stars::build_with`]).
    pub fn build_with<const D: usize>(
        map: &SimplexMap<N, D>,
        corners: &VertexCorners,
    ) -> Result<Self, InputError> {
        crate::topology_build::build_with(map, corners)
    }

    /// [`Self::build_with`] without the check of the vertices (that the
    /// simplices around each are connected through its facets): for a
    /// caller that makes it otherwise, as [`crate::Stars::build_checked`]
    /// does in its walk, or with [`Self::check_vertices`].
    pub fn glue_with<const D: usize>(
        map: &SimplexMap<N, D>,
        corners: &VertexCorners,
    ) -> Result<Self, InputError> {
        crate::topology_build::glue_with(map, corners)
    }

    /// The check of the vertices that [`Self::glue_with`] leaves out: the
    /// error of [`Self::build`] for the first vertex that fails it.
    pub fn check_vertices<const D: usize>(
        &self,
        map: &SimplexMap<N, D>,
        corners: &VertexCorners,
    ) -> Result<(), InputError> {
        crate::topology_build::check_vertices(map, self, corners)
    }

    /// Neighbour across facet `f` of `s`, if any.
    #[inline]
    pub fn neighbour(&self, s: usize, f: usize) -> Option<(usize, usize)> {
        let n = self.adj[s][f];
        (n != NONE).then(|| (n as usize, self.adj_facet[s][f] as usize))
    }
}
