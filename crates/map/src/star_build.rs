//! Construction of [`crate::Stars`] (to be written).
use crate::{SimplexMap, Stars, Topology, Transitions};

pub(crate) fn build<const N: usize, const D: usize>(
    _map: &SimplexMap<N, D>,
    _topo: &Topology<N>,
    _trans: &Transitions<N, D>,
) -> Stars<D> {
    Stars::default()
}
