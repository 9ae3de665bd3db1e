//! Build-time detection of the shared test data for `tests/c_api.rs` and
//! `tests/ovm_maps.rs` (the one script of the workspace,
//! `tools/build/shared_data_cfg.rs`).

include!("../../tools/build/shared_data_cfg.rs");
