//! Build-time detection of the shared test data: when `../shared/data`
//! (beside the checkout) is absent, sets `cfg(no_shared_data)`, under which
//! the tests that read it (`tests/c_api.rs`) are `#[ignore]`d with the reason, so
//! the test harness lists them as `ignored` instead of passing them
//! silently. The folder (and, when it is absent, its parent) is watched:
//! adding or removing it rebuilds the tests.

use std::path::Path;

fn main() {
    println!("cargo:rustc-check-cfg=cfg(no_shared_data)");
    println!("cargo:rerun-if-changed=build.rs");
    let manifest = std::env::var("CARGO_MANIFEST_DIR").unwrap_or_default();
    let shared = Path::new(&manifest).join("../../../shared");
    let data = shared.join("data");
    if data.is_dir() {
        println!("cargo:rerun-if-changed={}", data.display());
        return;
    }
    println!("cargo:rustc-cfg=no_shared_data");
    // watch only what exists: a missing path would rerun this every build
    if shared.is_dir() {
        println!("cargo:rerun-if-changed={}", shared.display());
    }
}
