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

    /// `dualex generate NAME` into `NAME.obj` here (panics on failure).
    pub fn generate(&self, name: &str) {
        let g = dualex(&[
            "generate",
            name,
            "-o",
            &self.arg(&format!("{name}.obj")),
            "-q",
        ]);
        assert!(g.status.success(), "{}", text(&g));
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

/// What a valid `dualex remesh` output breaks, from its checker report
/// and its stats: `shape` (components, Euler characteristic, boundary
/// loops) not the input's, interior vertices of valence ≤ 2 beyond
/// [`low_valence`]'s allowance, inverted quads left (issue 21: the
/// geometric stage's count, against the input triangle nearest each
/// quad's centre).
pub fn remesh_problems(
    rep: &dualex_check::QuadReport,
    stats: &serde_json::Value,
    shape: (usize, i64, usize),
) -> Vec<String> {
    let mut problems = Vec::new();
    let topo = (rep.components, rep.euler, rep.boundary_loops);
    if topo != shape {
        problems.push(format!(
            "components/Euler/boundary loops {topo:?}, surface {shape:?}"
        ));
    }
    let (low, allowed) = low_valence(stats);
    if low > allowed {
        problems.push(format!(
            "{low} interior vertices of valence ≤ 2 (allowed {allowed})"
        ));
    }
    let inverted = stats["geometry"]["after"]["inverted"].as_u64();
    if inverted != Some(0) {
        problems.push(format!("{inverted:?} inverted quads"));
    }
    problems
}

/// From `dualex remesh`'s stats: the output's interior vertices of
/// valence ≤ 2, and how many its singularities allow (one per
/// singularity of index ≥ +½: such a vertex is its quad-mesh image).
pub fn low_valence(stats: &serde_json::Value) -> (u64, u64) {
    let sum = |h: &serde_json::Value, keep: &dyn Fn(&str) -> bool| -> u64 {
        h.as_object()
            .map(|h| {
                h.iter()
                    .filter(|(k, _)| keep(k))
                    .filter_map(|(_, v)| v.as_u64())
                    .sum()
            })
            .unwrap_or(0)
    };
    let low = sum(&stats["output"]["valence_interior"], &|k| {
        k.parse::<u32>().is_ok_and(|v| v <= 2)
    });
    let allowed = sum(&stats["remesh"]["singularity_index"], &|k| {
        k.trim_end_matches("/4")
            .parse::<i32>()
            .is_ok_and(|q| q >= 2)
    });
    (low, allowed)
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

/// A 3 × 3 grid of unit quads in the plane z = 0, counter-clockwise seen
/// from +z, except the middle one when `flip_middle` (listed clockwise:
/// scaled Jacobian −1 against +z). Positions and quads (0-based).
pub fn quad_grid(flip_middle: bool) -> (Vec<[f64; 3]>, Vec<[u32; 4]>) {
    let positions = (0..16)
        .map(|k| [f64::from(k % 4), f64::from(k / 4), 0.0])
        .collect();
    let mut quads = Vec::new();
    for j in 0..3 {
        for i in 0..3 {
            let v = j * 4 + i;
            let q = [v, v + 1, v + 5, v + 4];
            quads.push(if flip_middle && (i, j) == (1, 1) {
                [q[0], q[3], q[2], q[1]]
            } else {
                q
            });
        }
    }
    (positions, quads)
}

/// Writes positions and faces (0-based) as OBJ.
pub fn write_obj(path: &Path, positions: &[[f64; 3]], faces: &[Vec<u32>]) {
    let mut s = String::new();
    for p in positions {
        s += &format!("v {} {} {}\n", p[0], p[1], p[2]);
    }
    for f in faces {
        let ids: Vec<String> = f.iter().map(|v| (v + 1).to_string()).collect();
        s += &format!("f {}\n", ids.join(" "));
    }
    std::fs::write(path, s).expect("write obj");
}

/// Writes cells of `K` vertices as legacy ASCII VTK (`ty`: 9 quads, 12 hexes).
pub fn write_vtk<const K: usize>(path: &Path, positions: &[[f64; 3]], cells: &[[u32; K]], ty: u8) {
    let mut s = format!(
        "# vtk DataFile Version 3.0\ntest\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS {} double\n",
        positions.len()
    );
    for p in positions {
        s += &format!("{} {} {}\n", p[0], p[1], p[2]);
    }
    s += &format!("CELLS {} {}\n", cells.len(), cells.len() * (K + 1));
    for c in cells {
        let ids: Vec<String> = c.iter().map(|v| v.to_string()).collect();
        s += &format!("{K} {}\n", ids.join(" "));
    }
    s += &format!("CELL_TYPES {}\n", cells.len());
    for _ in cells {
        s += &format!("{ty}\n");
    }
    std::fs::write(path, s).expect("write vtk");
}

/// Three separate hexes side by side along x (VTK order): a unit cube, the
/// same with bottom and top swapped (inverted, scaled Jacobian −1) when
/// `inverted`, and one whose vertex 1 sits on vertex 0 (degenerate:
/// value 0) when `degenerate`.
pub fn hex_trio(inverted: bool, degenerate: bool) -> (Vec<[f64; 3]>, Vec<[u32; 8]>) {
    let square = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0]];
    let mut positions = Vec::new();
    let mut hexes = Vec::new();
    for h in 0..3u32 {
        let x0 = 2.0 * f64::from(h);
        for z in [0.0, 1.0] {
            for [x, y] in square {
                positions.push([x0 + x, y, z]);
            }
        }
        let b = 8 * h;
        let mut cell: [u32; 8] = std::array::from_fn(|k| b + k as u32);
        if h == 1 && inverted {
            cell = [b + 4, b + 5, b + 6, b + 7, b, b + 1, b + 2, b + 3];
        }
        if h == 2 && degenerate {
            positions[(b + 1) as usize] = positions[b as usize];
        }
        hexes.push(cell);
    }
    (positions, hexes)
}

/// Writes hexes (0-based, VTK order) as MEDIT `.mesh`.
pub fn write_medit(path: &Path, positions: &[[f64; 3]], hexes: &[[u32; 8]]) {
    let mut s = format!(
        "MeshVersionFormatted 1\nDimension 3\nVertices\n{}\n",
        positions.len()
    );
    for p in positions {
        s += &format!("{} {} {} 0\n", p[0], p[1], p[2]);
    }
    s += &format!("Hexahedra\n{}\n", hexes.len());
    for h in hexes {
        let ids: Vec<String> = h.iter().map(|v| (v + 1).to_string()).collect();
        s += &format!("{} 0\n", ids.join(" "));
    }
    s += "End\n";
    std::fs::write(path, s).expect("write mesh");
}

/// The square [0, 3]² as 2 triangles, facing +z (`up`) or −z.
pub fn square_surface(path: &Path, up: bool) {
    let p = [
        [0.0, 0.0, 0.0],
        [3.0, 0.0, 0.0],
        [3.0, 3.0, 0.0],
        [0.0, 3.0, 0.0],
    ];
    let faces = if up {
        vec![vec![0, 1, 2], vec![0, 2, 3]]
    } else {
        vec![vec![0, 2, 1], vec![0, 3, 2]]
    };
    write_obj(path, &p, &faces);
}
