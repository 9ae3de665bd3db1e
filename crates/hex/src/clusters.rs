//! Collapsed clusters (vertices joined by zero-length map edges, moved as
//! one): the dimension-generic [`dualex_segment::cluster::Clusters`] at D = 3.

/// The collapsed clusters of a tet map.
pub type Clusters = dualex_segment::cluster::Clusters<3>;
