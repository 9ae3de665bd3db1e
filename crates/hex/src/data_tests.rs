//! Hex extraction on the real maps of `/work/shared/data/hexex` (skipped
//! with a notice when the data is absent). Expected counts are those of
//! HexEx / HexHex listed in the data's README.

use crate::{extract, HexOptions};
use std::path::Path;

const DIR: &str = "../../../shared/data/hexex";

fn run(file: &str) -> Option<(dualex_cells::HexMesh, crate::HexStats)> {
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join(DIR).join(file);
    if !path.exists() {
        eprintln!("skipped: {} is absent", path.display());
        return None;
    }
    let map = dualex_io::read_tet_map(&path).unwrap_or_else(|e| panic!("{e}"));
    let (mesh, st) = extract(&map, &HexOptions::default()).unwrap_or_else(|e| panic!("{e}"));
    eprintln!("{file}: {}", st.to_json());
    Some((mesh, st))
}

/// Extracts `file` and checks the hex count and the mesh's validity.
fn expect(file: &str, hexes: usize) {
    let Some((mesh, st)) = run(file) else { return };
    let rep =
        dualex_check::check_hex_mesh(mesh.positions.len(), &mesh.cells, Some(&mesh.positions));
    let inverted = rep.inverted_cells.as_ref().map_or(0, |c| c.len());
    eprintln!(
        "{file}: {} hexes, checker: {:?}, inverted {inverted}",
        mesh.cells.len(),
        rep.errors()
    );
    assert_eq!(mesh.cells.len(), hexes, "{file}: {}", st.to_json());
    let combinatorial: Vec<String> = rep
        .errors()
        .into_iter()
        .filter(|e| !e.contains("inverted"))
        .collect();
    assert!(combinatorial.is_empty(), "{file}: {combinatorial:?}");
    assert_eq!(st.components, 1, "{file}");
}

#[test]
fn hand_q() {
    expect("hand_q.hexex", 956);
}

#[test]
fn fancy_ring_q() {
    expect("fancy_ring_q.hexex", 1220);
}

#[test]
fn rockerarm_q() {
    expect("rockerarm_q.hexex", 1749);
}

#[test]
fn fancy_ring_noisy() {
    expect("fancy_ring.hexex", 1220);
}

#[test]
fn sphere() {
    expect("sphere.hexex", 216);
}

#[test]
fn minimal() {
    expect("minimal.hexex", 1);
}

#[test]
fn broken_minimal_files_give_one_line_errors() {
    for f in [
        "minimal_missing_tets",
        "minimal_missing_uvw",
        "minimal_missing_vertices",
    ] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join(DIR)
            .join(format!("{f}.hexex"));
        if !path.exists() {
            eprintln!("skipped: {} is absent", path.display());
            continue;
        }
        let err = dualex_io::read_tet_map(&path)
            .and_then(|m| extract(&m, &HexOptions::default()).map(|_| ()))
            .expect_err(f)
            .to_string();
        assert!(!err.contains('\n') && !err.is_empty(), "{f}: {err}");
        eprintln!("{f}: {err}");
    }
}

/// Half of its volume is in a reverted or a flat tet (vertex 1 moved to
/// w = −1 in all its charts): refused as reflected/collapsed charts, with a
/// one-line error naming a tet.
#[test]
fn minimal_invalid_charts_is_refused() {
    let path = Path::new(env!("CARGO_MANIFEST_DIR"))
        .join(DIR)
        .join("minimal_invalid_charts.hexex");
    if !path.exists() {
        eprintln!("skipped: {} is absent", path.display());
        return;
    }
    let map = dualex_io::read_tet_map(&path).unwrap_or_else(|e| panic!("{e}"));
    let err = extract(&map, &HexOptions::default()).expect_err("refused");
    assert!(err.to_string().contains("tet 0"), "{err}");
    assert!(err.to_string().contains("reflected"), "{err}");
}
