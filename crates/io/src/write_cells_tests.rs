//! Quad / hex writers, read back by the crate's polygon readers or by the
//! small VTK / MEDIT readers below.

use super::*;
use crate::{
    parse_polygon_obj, parse_polygon_ply, write_hex_mesh, write_quad_mesh, OutputErrorKind,
};

/// Awkward but finite coordinates: shortest forms must round-trip.
const AWKWARD: [f64; 8] = [
    0.1,
    -0.0,
    1e-300,
    5e-324,
    1e300,
    std::f64::consts::PI,
    -123456.789,
    2.0 / 3.0,
];

fn positions(n: usize) -> Vec<[f64; 3]> {
    (0..n)
        .map(|i| [AWKWARD[i % 8], AWKWARD[(i + 3) % 8], i as f64 * 0.25])
        .collect()
}

/// A 2×1 strip of quads.
fn strip() -> QuadMesh {
    QuadMesh {
        positions: positions(6),
        cells: vec![[0, 1, 4, 3], [1, 2, 5, 4]],
    }
}

/// Two hexes stacked.
fn tower() -> HexMesh {
    HexMesh {
        positions: positions(12),
        cells: vec![[0, 1, 2, 3, 4, 5, 6, 7], [4, 5, 6, 7, 8, 9, 10, 11]],
    }
}

fn to_bytes(f: impl FnOnce(&mut Vec<u8>) -> io::Result<()>) -> Vec<u8> {
    let mut out = Vec::new();
    f(&mut out).unwrap();
    out
}

/// Reads back a legacy VTK unstructured grid: (points, cells, types).
fn read_vtk(text: &str) -> (Vec<[f64; 3]>, Vec<Vec<u32>>, Vec<u8>) {
    let mut t = text.split_ascii_whitespace();
    while t.next() != Some("POINTS") {}
    let n: usize = t.next().unwrap().parse().unwrap();
    assert_eq!(t.next(), Some("double"));
    let mut num = || t.next().unwrap().parse::<f64>().unwrap();
    let pts: Vec<[f64; 3]> = (0..n).map(|_| [num(), num(), num()]).collect();
    assert_eq!(t.next(), Some("CELLS"));
    let m: usize = t.next().unwrap().parse().unwrap();
    let size: usize = t.next().unwrap().parse().unwrap();
    let mut cells = Vec::new();
    for _ in 0..m {
        let k: usize = t.next().unwrap().parse().unwrap();
        cells.push(
            (0..k)
                .map(|_| t.next().unwrap().parse().unwrap())
                .collect::<Vec<u32>>(),
        );
    }
    assert_eq!(size, cells.iter().map(|c| c.len() + 1).sum::<usize>());
    assert_eq!(t.next(), Some("CELL_TYPES"));
    assert_eq!(t.next().unwrap().parse::<usize>().unwrap(), m);
    let types = (0..m).map(|_| t.next().unwrap().parse().unwrap()).collect();
    assert_eq!(t.next(), None);
    (pts, cells, types)
}

#[test]
fn quad_obj_and_ply_round_trip() {
    let q = strip();
    let obj = parse_polygon_obj(&to_bytes(|w| quad_obj(w, &q))).unwrap();
    assert_eq!(obj.positions, q.positions);
    assert_eq!(obj.faces, vec![vec![0, 1, 4, 3], vec![1, 2, 5, 4]]);
    for format in [
        PlyFormat::Ascii,
        PlyFormat::BinaryLittleEndian,
        PlyFormat::BinaryBigEndian,
    ] {
        let ply = parse_polygon_ply(&to_bytes(|w| quad_ply(w, &q, format))).unwrap();
        assert_eq!(ply.positions, q.positions, "{format:?}");
        assert_eq!(ply.faces, obj.faces, "{format:?}");
    }
}

#[test]
fn vtk_round_trip() {
    let q = strip();
    let (pts, cells, types) = read_vtk(&String::from_utf8(to_bytes(|w| quad_vtk(w, &q))).unwrap());
    assert_eq!(pts, q.positions);
    assert_eq!(cells, vec![vec![0, 1, 4, 3], vec![1, 2, 5, 4]]);
    assert_eq!(types, vec![9, 9]);
    let h = tower();
    let (pts, cells, types) = read_vtk(&String::from_utf8(to_bytes(|w| hex_vtk(w, &h))).unwrap());
    assert_eq!(pts, h.positions);
    assert_eq!(
        cells,
        h.cells.iter().map(|c| c.to_vec()).collect::<Vec<_>>()
    );
    assert_eq!(types, vec![12, 12]);
}

#[test]
fn medit_round_trip() {
    let h = tower();
    let text = String::from_utf8(to_bytes(|w| hex_medit(w, &h))).unwrap();
    let mut t = text.split_ascii_whitespace();
    let head: Vec<&str> = (0..6).map(|_| t.next().unwrap()).collect();
    assert_eq!(
        head,
        [
            "MeshVersionFormatted",
            "2",
            "Dimension",
            "3",
            "Vertices",
            "12"
        ]
    );
    for p in &h.positions {
        let got: Vec<f64> = (0..4).map(|_| t.next().unwrap().parse().unwrap()).collect();
        assert_eq!(got, [p[0], p[1], p[2], 0.0]);
    }
    assert_eq!((t.next(), t.next()), (Some("Hexahedra"), Some("2")));
    for c in &h.cells {
        let got: Vec<u32> = (0..9).map(|_| t.next().unwrap().parse().unwrap()).collect();
        let want: Vec<u32> = c.iter().map(|v| v + 1).chain([0]).collect();
        assert_eq!(got, want);
    }
    assert_eq!((t.next(), t.next()), (Some("End"), None));
}

#[test]
fn file_writers_check_before_writing() {
    let scratch = crate::test_scratch::ScratchDir::new("cells");
    let dir = scratch.path();
    let mut bad = strip();
    bad.cells[1][2] = 6;
    let p = dir.join("bad.obj");
    let e = write_quad_mesh(&p, &bad).unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "{}: cannot write: cell 1 refers to vertex 6, but there are 6 vertices",
            p.display()
        )
    );
    assert!(!p.exists());
    bad = strip();
    bad.positions[2][1] = f64::NAN;
    assert!(matches!(
        write_quad_mesh(&p, &bad).unwrap_err().kind,
        OutputErrorKind::InvalidData(_)
    ));
    let e = write_quad_mesh(&dir.join("q.stl"), &strip()).unwrap_err();
    assert!(
        e.to_string()
            .ends_with("unsupported output format `.stl`; use .obj, .ply, .vtk"),
        "{e}"
    );
    let e = write_hex_mesh(&dir.join("h.obj"), &tower()).unwrap_err();
    assert!(
        e.to_string()
            .ends_with("unsupported output format `.obj`; use .mesh, .vtk, .ovm"),
        "{e}"
    );
    for ext in ["obj", "ply", "vtk"] {
        let p = dir.join(format!("q.{ext}"));
        write_quad_mesh(&p, &strip()).unwrap();
        let back = crate::read_polygon_mesh(&p);
        if ext != "vtk" {
            assert_eq!(back.unwrap().faces.len(), 2, "{ext}");
        }
    }
    for ext in ["mesh", "vtk"] {
        write_hex_mesh(&dir.join(format!("h.{ext}")), &tower()).unwrap();
    }
    let names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    assert!(names.iter().all(|n| !n.ends_with(".tmp")), "{names:?}");
    assert!(names.contains(&"h.mesh".to_string()) && !names.contains(&"bad.obj".to_string()));
}

#[test]
fn check_cells_accepts_a_valid_mesh() {
    assert_eq!(check_cells(&strip()), Ok(()));
    assert_eq!(check_cells(&tower()), Ok(()));
}
