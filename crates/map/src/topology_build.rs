//! Construction of [`crate::Topology`] (to be written).
use crate::{InputError, SimplexMap, Topology};

pub(crate) fn build<const N: usize, const D: usize>(
    _map: &SimplexMap<N, D>,
) -> Result<Topology<N>, InputError> {
    Err(InputError::new("topology: not implemented yet"))
}
