//! Vertex stars: the simplices around each vertex, with the rotation from the
//! vertex's reference chart (that of its first simplex) to each simplex's
//! chart, accumulated across the facets that contain the vertex.
//!
//! A vertex is **singular** (in 2D: the rotation around it is not the
//! identity; in 3D: it lies on a singular edge) when two walks around it
//! reach the same simplex with different rotations. Its corners cannot be
//! moved together consistently: sanitization must not perturb it.
//!
//! Layout (CSR): the entries of vertex `v` are
//! `entries[offsets[v]..offsets[v+1]]`, first entry = reference chart
//! (identity rotation).

use crate::corners::VertexCorners;
use crate::{topology::Topology, transition::Transitions, InputError, Rot, SimplexMap};

/// One corner around a vertex.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct StarEntry<const D: usize> {
    /// The simplex.
    pub simplex: u32,
    /// Which of its corners is the vertex.
    pub corner: u8,
    /// Rotation from the vertex's reference chart to this simplex's chart.
    pub rot: Rot<D>,
}

/// The stars of all vertices.
#[derive(Clone, Debug, Default)]
pub struct Stars<const D: usize> {
    /// CSR offsets, one more than the vertex count.
    pub offsets: Vec<u32>,
    /// Star entries.
    pub entries: Vec<StarEntry<D>>,
    /// Per vertex: the rotations around it are inconsistent (singular).
    pub singular: Vec<bool>,
    /// Per vertex: it lies on the boundary.
    pub boundary: Vec<bool>,
}

impl<const D: usize> Stars<D> {
    /// Builds the stars of every vertex.
    pub fn build<const N: usize>(
        map: &SimplexMap<N, D>,
        topo: &Topology<N>,
        trans: &Transitions<N, D>,
    ) -> Self {
        crate::star_build::build(map, topo, trans)
    }

    /// [`Self::build`] with the map's corner lists, built `indexed`
    /// ([`VertexCorners::build`]; shared with [`Topology::build_with`]).
    pub fn build_with<const N: usize>(
        map: &SimplexMap<N, D>,
        topo: &Topology<N>,
        trans: &Transitions<N, D>,
        corners: &VertexCorners,
    ) -> Self {
        crate::star_build::build_with(map, topo, trans, corners)
    }

    /// [`Self::build_with`] on a topology built without its vertex check
    /// ([`Topology::glue_with`]), which the walk makes: the error of
    /// [`Topology::build`] for the first vertex whose simplices are not
    /// connected through its facets.
    pub fn build_checked<const N: usize>(
        map: &SimplexMap<N, D>,
        topo: &Topology<N>,
        trans: &Transitions<N, D>,
        corners: &VertexCorners,
    ) -> Result<Self, InputError> {
        crate::star_build::build_checked(map, topo, trans, corners)
    }

    /// The star of vertex `v`.
    pub fn of(&self, v: usize) -> &[StarEntry<D>] {
        &self.entries[self.offsets[v] as usize..self.offsets[v + 1] as usize]
    }
}
