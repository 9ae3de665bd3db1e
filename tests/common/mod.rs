//! Helpers shared by the end-to-end tests: run the real `dualex` binary,
//! scratch directories, the shared data folder.
#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// Runs `dualex` with `args`.
pub fn dualex(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_dualex"))
        .args(args)
        .output()
        .expect("run the dualex binary")
}

/// One quieted `dualex remesh` run with its stats written.
pub struct Remesh<'a> {
    /// The surface.
    pub input: &'a str,
    /// The quad mesh written.
    pub output: &'a str,
    /// `--quads`.
    pub quads: usize,
    /// `--rounding`.
    pub rounding: &'a str,
    /// `--seed`.
    pub seed: u64,
    /// `--stats`.
    pub stats: &'a str,
}

impl Remesh<'_> {
    /// Runs it.
    pub fn run(&self) -> Output {
        dualex(&[
            "remesh",
            self.input,
            "-o",
            self.output,
            "--quads",
            &self.quads.to_string(),
            "--rounding",
            self.rounding,
            "--seed",
            &self.seed.to_string(),
            "--stats",
            self.stats,
            "-q",
        ])
    }
}

/// stdout and stderr of a run, for assertion messages.
pub fn text(out: &Output) -> String {
    format!(
        "exit {:?}\nstdout: {}\nstderr: {}",
        out.status.code(),
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    )
}

/// A fresh scratch directory for one test, removed on drop.
pub struct Scratch(pub PathBuf);

impl Scratch {
    /// A new, empty directory named after the test.
    pub fn new(name: &str) -> Self {
        // unique within the process too: tests run in parallel threads
        static NEXT: std::sync::atomic::AtomicUsize = std::sync::atomic::AtomicUsize::new(0);
        let k = NEXT.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
        let dir =
            std::env::temp_dir().join(format!("dualex-test-{}-{k}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create scratch dir");
        Scratch(dir)
    }

    /// A path inside the directory.
    pub fn path(&self, file: &str) -> PathBuf {
        self.0.join(file)
    }

    /// The same, as a string for command lines.
    pub fn arg(&self, file: &str) -> String {
        self.path(file).display().to_string()
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// `../shared/data/SUB` beside the checkout, or `None` with a printed notice.
pub fn shared_data(sub: &str) -> Option<PathBuf> {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("../../../shared/data")
        .join(sub);
    if root.is_dir() {
        Some(root)
    } else {
        eprintln!(
            "NOTICE: {} is absent: skipping the tests on shared data",
            root.display()
        );
        None
    }
}

/// Reads a JSON file.
pub fn json(path: &Path) -> serde_json::Value {
    let s = std::fs::read_to_string(path).expect("read json");
    serde_json::from_str(&s).expect("parse json")
}

/// Reads a quad mesh written by `dualex quad` and checks it with the
/// independent checker; panics naming `what` if it is invalid.
pub fn read_valid_quads(
    path: &Path,
    what: &str,
) -> (dualex_io::PolyMesh, dualex_check::QuadReport) {
    let mesh = dualex_io::read_polygon_mesh(path).unwrap_or_else(|e| panic!("{what}: {e}"));
    let quads: Vec<[u32; 4]> = mesh
        .faces
        .iter()
        .map(|f| {
            assert_eq!(f.len(), 4, "{what}: a face with {} vertices", f.len());
            [f[0], f[1], f[2], f[3]]
        })
        .collect();
    let rep = dualex_check::check_quad_mesh(mesh.positions.len(), &quads);
    assert!(
        rep.is_valid(),
        "{what}: invalid quad mesh: {:?}",
        rep.errors()
    );
    (mesh, rep)
}
