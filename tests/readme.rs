//! The README's two commands stay runnable: the main job's `cargo run -p
//! dualex-cli` must pick the `dualex` binary although the package has two
//! (`default-run`) and write only into a folder it creates and git
//! ignores; the test command is `bash .ci/run`, which installs what the
//! tests need and runs the whole workspace's tests. The "Use from Rust"
//! snippet is the compiled example `crates/dualex/examples/quad.rs`.

use std::path::Path;

fn read(rel: &str) -> String {
    let p = Path::new(env!("CARGO_MANIFEST_DIR")).join(rel);
    std::fs::read_to_string(&p).unwrap_or_else(|e| panic!("{}: {e}", p.display()))
}

/// The README's main command line.
fn main_command(readme: &str) -> &str {
    readme
        .lines()
        .find(|l| l.contains("cargo run") && l.contains("-p dualex-cli"))
        .unwrap_or_else(|| panic!("README has no `cargo run -p dualex-cli` line"))
}

#[test]
fn the_main_command_names_a_runnable_binary() {
    let readme = read("../../README.md");
    let main = main_command(&readme);
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
fn the_main_command_writes_into_a_created_ignored_folder() {
    let readme = read("../../README.md");
    let main = main_command(&readme);
    assert!(
        main.starts_with("mkdir -p out && cargo run"),
        "`{main}` must create out/ first"
    );
    let args: Vec<&str> = main.split_whitespace().collect();
    for flag in ["-o", "--stats"] {
        let k = args.iter().position(|a| *a == flag);
        let file = k.and_then(|k| args.get(k + 1));
        assert!(
            file.is_some_and(|f| f.starts_with("out/")),
            "`{main}`: {flag} must write into out/"
        );
    }
    let ignore = read("../../.gitignore");
    assert!(
        ignore
            .lines()
            .any(|l| l.trim() == "/out" || l.trim() == "out/"),
        ".gitignore does not ignore out/"
    );
}

#[test]
fn the_test_command_is_ci_run_which_tests_the_workspace() {
    let readme = read("../../README.md");
    assert!(
        readme.lines().any(|l| l.trim() == "bash .ci/run"),
        "README's test command is not `bash .ci/run`"
    );
    assert!(
        readme.contains("Run all tests: `bash .ci/run`"),
        "README does not say \"Run all tests: `bash .ci/run`\""
    );
    let ci = read("../../.ci/run");
    assert!(
        ci.lines()
            .any(|l| l.trim() == "cargo test --workspace --profile ci"),
        "`.ci/run` does not run `cargo test --workspace --profile ci`"
    );
    assert!(
        ci.contains("apt-get install") && ci.contains("tetgen"),
        "`.ci/run` no longer installs TetGen"
    );
}

#[test]
fn the_rust_snippet_is_the_compiled_example() {
    let readme = read("../../README.md");
    let example = read("../dualex/examples/quad.rs");
    let section = readme
        .split("## Use from Rust")
        .nth(1)
        .unwrap_or_else(|| panic!("README has no \"Use from Rust\" section"));
    let snippet = section
        .split("```rust\n")
        .nth(1)
        .and_then(|s| s.split("```").next())
        .unwrap_or_else(|| panic!("\"Use from Rust\" has no ```rust block"));
    assert_eq!(
        snippet, example,
        "README's Rust snippet differs from crates/dualex/examples/quad.rs"
    );
}
