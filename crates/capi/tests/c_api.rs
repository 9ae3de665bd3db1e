//! The C API from C: compiles `tests/c/test_quad_hex.c` with `cc` (gcc)
//! against `include/dualex.h` and the library cargo built for this test
//! (static and shared), runs it on small maps it builds itself and on the
//! shared maps of `../shared/data` (dumped here as plain text; listed as
//! ignored with the reason when the folder is absent, see `build.rs`), and
//! checks that the header's struct layout is the Rust one, field by field;
//! on noisy generated maps it checks the geometric stage's quality fields.

use dualex_capi::{DualexHexMesh, DualexOptions, DualexQuadMesh};
use std::mem::{offset_of, size_of};
use std::path::{Path, PathBuf};
use std::process::Command;

/// The folder holding the library cargo built for this test: this test
/// runs from `target/<profile>/deps`, where `cargo test` puts the
/// library's static and shared forms (`cargo build` copies them up to
/// `target/<profile>`, which `cargo test` does not refresh).
fn lib_dir() -> PathBuf {
    let exe = std::env::current_exe().expect("the test's path");
    let deps = exe.parent().expect("the deps folder");
    if deps.join("libdualex_capi.a").is_file() {
        return deps.to_path_buf();
    }
    deps.parent().expect("the profile folder").to_path_buf()
}

fn manifest() -> &'static Path {
    Path::new(env!("CARGO_MANIFEST_DIR"))
}

/// A fresh scratch folder for one test, removed on drop.
struct Scratch(PathBuf);

impl Scratch {
    fn new(name: &str) -> Self {
        let d = std::env::temp_dir().join(format!("dualex-capi-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).expect("create the scratch folder");
        Scratch(d)
    }
}

impl Drop for Scratch {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// Compiles the C test into `dir` against the static (or shared) library.
fn c_program(dir: &Scratch, shared: bool) -> PathBuf {
    let exe = dir.0.join("test_quad_hex");
    let lib = lib_dir();
    let mut cc = Command::new("cc");
    cc.args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-pedantic"])
        .arg("-I")
        .arg(manifest().join("include"))
        .arg(manifest().join("tests/c/test_quad_hex.c"))
        .arg("-o")
        .arg(&exe);
    if shared {
        cc.arg("-L").arg(&lib).arg("-ldualex_capi");
        cc.arg(format!("-Wl,-rpath,{}", lib.display()));
    } else {
        cc.arg(lib.join("libdualex_capi.a"));
        // rustc --print native-static-libs on Linux
        cc.args([
            "-lgcc_s",
            "-lutil",
            "-lrt",
            "-lpthread",
            "-lm",
            "-ldl",
            "-lc",
        ]);
    }
    let out = cc.output().expect("run cc (gcc)");
    assert!(
        out.status.success(),
        "cc failed:\n{}",
        String::from_utf8_lossy(&out.stderr)
    );
    exe
}

/// Runs a compiled C program; its stdout.
fn run(exe: &Path, args: &[&str]) -> String {
    let out = Command::new(exe)
        .args(args)
        .output()
        .expect("run the C test");
    let text = format!(
        "stdout: {}\nstderr: {}",
        String::from_utf8_lossy(&out.stdout),
        String::from_utf8_lossy(&out.stderr)
    );
    assert!(
        out.status.success(),
        "{} {args:?} failed: {text}",
        exe.display()
    );
    String::from_utf8_lossy(&out.stdout).into_owned()
}

#[test]
fn c_program_extracts_small_maps_and_reports_errors_static() {
    let dir = Scratch::new("static");
    let out = run(&c_program(&dir, false), &[]);
    assert!(out.contains("all checks passed"), "{out}");
}

#[test]
fn c_program_links_the_shared_library() {
    let dir = Scratch::new("shared");
    let out = run(&c_program(&dir, true), &[]);
    assert!(out.contains("all checks passed"), "{out}");
}

#[test]
fn header_compiles_as_cpp() {
    let out = Command::new("c++")
        .args([
            "-x",
            "c++",
            "-std=c++11",
            "-Wall",
            "-Werror",
            "-fsyntax-only",
            "-I",
        ])
        .arg(manifest().join("include"))
        .arg(manifest().join("include/dualex.h"))
        .output();
    match out {
        Ok(o) => assert!(o.status.success(), "{}", String::from_utf8_lossy(&o.stderr)),
        Err(e) => eprintln!("NOTICE: no C++ compiler ({e}): the header's C++ check is skipped"),
    }
}

/// The header's layout as the C compiler sees it equals Rust's.
#[test]
fn header_layout_matches_the_rust_structs() {
    let dir = Scratch::new("layout");
    let out = run(&c_program(&dir, false), &["--layout"]);
    // `rust_field as c_field` where the one Rust struct of both
    // dimensions names a field for both (`n_singular`)
    macro_rules! rust_layout {
        ($t:ident: $($f:ident $(as $c:ident)?),*) => {{
            let mut s = format!("{} {}\n", stringify!($t), size_of::<$t>());
            $(s += &format!(
                "{}.{} {} {}\n",
                stringify!($t),
                rust_layout!(@name $f $($c)?),
                offset_of!($t, $f),
                size_of_field(|x: &$t| &x.$f)
            );)*
            s
        }};
        (@name $f:ident) => { stringify!($f) };
        (@name $f:ident $c:ident) => { stringify!($c) };
    }
    let expected = rust_layout!(DualexOptions: weld, fairing, round_transitions, grid_offset, strict, seed,
            untangle, smooth_rounds)
        + &rust_layout!(DualexQuadMesh: n_vertices, positions, n_cells, cells, sources, n_components,
            n_boundary_components as n_boundary_loops, euler, n_singular as n_singular_vertices, n_welded_vertices, topology_matches,
            sj_min_before, sj_min_after, sj_p5_before, sj_p5_after, inverted_before, inverted_after,
            moved_vertices)
        + &rust_layout!(DualexHexMesh: n_vertices, positions, n_cells, cells, sources, n_components,
            n_boundary_components as n_boundary_surfaces, euler, n_singular as n_singular_edges, n_welded_vertices, topology_matches,
            sj_min_before, sj_min_after, sj_p5_before, sj_p5_after, inverted_before, inverted_after,
            moved_vertices);
    assert_eq!(out, expected);
}

fn size_of_field<T, F>(_: impl Fn(&T) -> &F) -> usize {
    size_of::<F>()
}

/// Writes a map as the C test's plain text: kind, vertices, simplices
/// with their corners' map coordinates.
fn dump<const N: usize, const D: usize>(
    kind: &str,
    positions: &[[f64; 3]],
    simplices: &[[u32; N]],
    coords: &[[[f64; D]; N]],
    path: &Path,
) -> std::io::Result<()> {
    use std::fmt::Write;
    let mut s = format!("{kind} {}\n", positions.len());
    for p in positions {
        let _ = writeln!(s, "{} {} {}", p[0], p[1], p[2]);
    }
    let _ = writeln!(s, "{}", simplices.len());
    for (t, c) in simplices.iter().zip(coords) {
        for v in t {
            let _ = write!(s, "{v} ");
        }
        for x in c.iter().flatten() {
            let _ = write!(s, "{x} ");
        }
        s.push('\n');
    }
    std::fs::write(path, s)
}

/// `map` written for the C test as `kind` (`"tri"`, `"tet"`) to `path`;
/// the path, as the C test's argument.
fn dumped<const N: usize, const D: usize>(
    kind: &str,
    map: &dualex::map::SimplexMap<N, D>,
    path: PathBuf,
) -> String {
    dump(kind, &map.positions, &map.simplices, &map.coords, &path).expect("write the dump");
    path.to_str().unwrap_or_default().to_string()
}

/// Noisy maps of `dualex_gen` meshes (noise 0.6, folds) whose extraction
/// places some elements inverted (checked by the facade's tests too): the
/// C program finds them untangled by default (`inverted_after == 0`),
/// kept with `untangle = 0`, refused with `strict` then.
#[test]
fn c_program_reads_the_quality_of_messy_maps() {
    use dualex_gen::from_mesh::{self, meshes, FromMeshOptions};
    let noisy = |scale, seed| FromMeshOptions {
        scale,
        noise: 0.6,
        folds: true,
        seed,
        ..Default::default()
    };
    let dir = Scratch::new("messy");
    let exe = c_program(&dir, false);
    let disk = meshes::quad_mesh_by_name("ngon4").expect("ngon4");
    let disk = from_mesh::from_quads(&disk, &noisy(3, 2)).expect("a map");
    let cylinder = meshes::hex_mesh_by_name("cylinder6").expect("cylinder6");
    let cylinder = from_mesh::from_hexes(&cylinder, &noisy(2, 1)).expect("a map");
    let runs = [
        ("36 cells", dumped("tri", &disk.map, dir.0.join("disk.txt"))),
        (
            "96 cells",
            dumped("tet", &cylinder.map, dir.0.join("cylinder.txt")),
        ),
    ];
    for (cells, path) in runs {
        let out = run(&exe, &["--messy", &path]);
        assert!(out.contains(cells) && out.contains(", 0 after"), "{out}");
        assert!(out.contains("all checks passed"), "{out}");
    }
}

fn data(rel: &str) -> PathBuf {
    manifest().join("../../../shared/data").join(rel)
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn c_program_gets_the_reference_counts_on_shared_maps() {
    let fandisk = dualex::read_tri_map(data("qex/fandisk_param.obj")).expect("read fandisk");
    let dir = Scratch::new("shared-maps");
    let exe = c_program(&dir, false);
    let path = dumped("tri", &fandisk, dir.0.join("fandisk.txt"));
    let out = run(&exe, &[&path, "897"]);
    assert!(out.contains("897 quads"), "{out}");

    let hand = dualex::read_tet_map(data("hexex/hand_q.hexex")).expect("read hand_q");
    let path = dumped("tet", &hand, dir.0.join("hand_q.txt"));
    let out = run(&exe, &[&path, "956"]);
    assert!(out.contains("956 hexes"), "{out}");
}

/// Installs the header and both libraries into `dir/prefix` as the README
/// says (`include/dualex.h`, `lib/libdualex_capi.{so,a}`); returns the prefix.
fn install_prefix(dir: &Scratch) -> PathBuf {
    let prefix = dir.0.join("prefix");
    let (inc, lib) = (prefix.join("include"), prefix.join("lib"));
    for d in [&inc, &lib] {
        std::fs::create_dir_all(d).expect("create the prefix");
    }
    let copy = |from: &Path, to: &Path| std::fs::copy(from, to).expect("install a file");
    copy(&manifest().join("include/dualex.h"), &inc.join("dualex.h"));
    for name in ["libdualex_capi.so", "libdualex_capi.a"] {
        copy(&lib_dir().join(name), &lib.join(name));
    }
    prefix
}

/// `cmake/dualex-config.cmake`, installed into a scratch prefix, lets a
/// CMake project (`find_package(dualex)`, `dualex::dualex`) build and run
/// the C test, against the shared and (`DUALEX_STATIC=ON`) the static
/// library.
#[test]
fn cmake_package_builds_the_c_test() {
    let dir = Scratch::new("cmake");
    let prefix = install_prefix(&dir);
    let config = prefix.join("lib/cmake/dualex");
    std::fs::create_dir_all(&config).expect("create lib/cmake/dualex");
    std::fs::copy(
        manifest().join("cmake/dualex-config.cmake"),
        config.join("dualex-config.cmake"),
    )
    .expect("install dualex-config.cmake");
    let project = dir.0.join("app");
    std::fs::create_dir_all(&project).expect("create the project");
    std::fs::copy(
        manifest().join("tests/c/test_quad_hex.c"),
        project.join("app.c"),
    )
    .expect("copy the C test");
    std::fs::write(
        project.join("CMakeLists.txt"),
        "cmake_minimum_required(VERSION 3.10)\nproject(app C)\n\
         find_package(dualex REQUIRED)\nadd_executable(app app.c)\n\
         target_link_libraries(app PRIVATE dualex::dualex)\n",
    )
    .expect("write CMakeLists.txt");
    for stat in [false, true] {
        let build = dir
            .0
            .join(if stat { "build-static" } else { "build-shared" });
        let cmake = |args: &[&std::ffi::OsStr]| {
            let out = match Command::new("cmake").args(args).output() {
                Ok(o) => o,
                Err(e) => panic!("cmake could not run ({e}): install it (`bash .ci/run` does)"),
            };
            assert!(
                out.status.success(),
                "cmake {args:?}: {}{}",
                String::from_utf8_lossy(&out.stdout),
                String::from_utf8_lossy(&out.stderr)
            );
        };
        let dualex_dir = format!("-Ddualex_DIR={}", config.display());
        let kind = format!("-DDUALEX_STATIC={}", if stat { "ON" } else { "OFF" });
        cmake(&[
            "-S".as_ref(),
            project.as_os_str(),
            "-B".as_ref(),
            build.as_os_str(),
            dualex_dir.as_ref(),
            kind.as_ref(),
        ]);
        cmake(&["--build".as_ref(), build.as_os_str()]);
        let run = Command::new(build.join("app"))
            .env("LD_LIBRARY_PATH", prefix.join("lib"))
            .output()
            .expect("run the CMake-built program");
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
        let text = String::from_utf8_lossy(&run.stdout);
        assert!(text.contains("all checks passed"), "{text}");
    }
}

/// `dualex.pc.in`, installed into a scratch prefix, gives the flags that
/// compile and link the C test (shared and, with `--static`, static).
#[test]
fn pkg_config_file_links_the_c_test() {
    let dir = Scratch::new("pkg-config");
    let prefix = install_prefix(&dir);
    let (lib, pc) = (prefix.join("lib"), prefix.join("lib/pkgconfig"));
    std::fs::create_dir_all(&pc).expect("create lib/pkgconfig");
    let template =
        std::fs::read_to_string(manifest().join("dualex.pc.in")).expect("read dualex.pc.in");
    let text = template
        .replace("@PREFIX@", &prefix.display().to_string())
        .replace("@VERSION@", env!("CARGO_PKG_VERSION"));
    std::fs::write(pc.join("dualex.pc"), text).expect("write dualex.pc");
    for stat in [false, true] {
        let mut args = vec!["--cflags", "--libs", "dualex"];
        if stat {
            args.insert(0, "--static");
        }
        let flags = match Command::new("pkg-config")
            .args(&args)
            .env("PKG_CONFIG_PATH", &pc)
            .output()
        {
            Ok(o) if o.status.success() => String::from_utf8_lossy(&o.stdout).into_owned(),
            Ok(o) => panic!("pkg-config failed: {}", String::from_utf8_lossy(&o.stderr)),
            Err(e) => panic!("pkg-config could not run ({e}): install it (`bash .ci/run` does)"),
        };
        let exe = dir.0.join(if stat { "static" } else { "shared" });
        let mut cc = Command::new("cc");
        cc.arg(manifest().join("tests/c/test_quad_hex.c"))
            .arg("-o")
            .arg(&exe);
        if stat {
            // the static library ahead of -ldualex_capi resolves every symbol
            cc.arg(lib.join("libdualex_capi.a"));
        }
        cc.args(flags.split_whitespace());
        let out = cc.output().expect("run cc");
        assert!(
            out.status.success(),
            "cc {flags}: {}",
            String::from_utf8_lossy(&out.stderr)
        );
        let run = Command::new(&exe)
            .env("LD_LIBRARY_PATH", &lib)
            .output()
            .expect("run");
        assert!(
            run.status.success(),
            "{}",
            String::from_utf8_lossy(&run.stderr)
        );
    }
}

/// The README's C snippet ("Use from C/C++") compiles and runs.
#[test]
fn the_readme_c_snippet_runs() {
    let readme = std::fs::read_to_string(manifest().join("../../README.md")).expect("read README");
    let section = readme
        .split("## Use from C/C++")
        .nth(1)
        .expect("README has a \"Use from C/C++\" section");
    let code = section
        .split("```c\n")
        .nth(1)
        .and_then(|s| s.split("```").next())
        .expect("the section has a ```c block");
    let dir = Scratch::new("readme");
    let src = dir.0.join("readme.c");
    std::fs::write(&src, code).expect("write readme.c");
    let exe = dir.0.join("readme");
    let lib = lib_dir();
    let out = Command::new("cc")
        .args(["-std=c99", "-Wall", "-Wextra", "-Werror", "-I"])
        .arg(manifest().join("include"))
        .arg(&src)
        .arg("-o")
        .arg(&exe)
        .arg("-L")
        .arg(&lib)
        .arg("-ldualex_capi")
        .arg(format!("-Wl,-rpath,{}", lib.display()))
        .output()
        .expect("run cc");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    assert_eq!(run(&exe, &[]), "16 quads, 25 vertices\n");
}
