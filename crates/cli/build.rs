//! Sets `cfg(no_shared_data)` when `../shared/data` is absent, so that
//! the end-to-end tests in tests/ are listed as ignored, with the reason (the one
//! script of the workspace, `tools/build/shared_data_cfg.rs`).

include!("../../tools/build/shared_data_cfg.rs");
