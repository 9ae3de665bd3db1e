//! The README's two commands stay runnable: the main job's `cargo run -p
//! dualex-cli` must pick the `dualex` binary although the package has two
//! (`default-run`), and the test command must be the one `.ci/run` runs.

use std::path::Path;

fn read(rel: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

#[test]
fn the_main_command_names_a_runnable_binary() {
    let readme = read("../../README.md");
    let main = readme
        .lines()
        .find(|l| l.starts_with("cargo run") && l.contains("-p dualex-cli"))
        .unwrap_or_else(|| panic!("README has no `cargo run -p dualex-cli` line"));
    let manifest = read("Cargo.toml");
    let bins = manifest.matches("[[bin]]").count();
    if bins > 1 && !main.contains("--bin") {
        assert!(
            manifest.contains("default-run = \"dualex\""),
            "{bins} binaries and no default-run: `{main}` would not know which to run"
        );
    }
}

#[test]
fn the_test_command_is_the_one_ci_runs() {
    let readme = read("../../README.md");
    let ci = read("../../.ci/run");
    let test = readme
        .lines()
        .find(|l| l.starts_with("cargo test"))
        .unwrap_or_else(|| panic!("README has no `cargo test` line"));
    assert!(
        ci.lines().any(|l| l.trim() == test.trim()),
        "`.ci/run` does not run the README's test command `{test}`"
    );
}
