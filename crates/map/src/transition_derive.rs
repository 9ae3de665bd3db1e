//! Derivation of [`crate::Transitions`] (to be written).
use crate::{InputError, SimplexMap, Topology, TransitionOptions, TransitionReport, Transitions};

pub(crate) fn derive<const N: usize, const D: usize>(
    _map: &SimplexMap<N, D>,
    _topo: &Topology<N>,
    _opts: &TransitionOptions,
) -> Result<(Transitions<N, D>, TransitionReport), InputError> {
    Err(InputError::new("transitions: not implemented yet"))
}
