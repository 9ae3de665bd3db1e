//! Crate-level tests: generic over D, run for D = 2 and D = 3.

mod fair_order_tests;
mod fair_tests;
mod glue_par_tests;
mod glue_tests;
mod ops_tests;
pub(crate) mod support;
mod untangle_tests;
