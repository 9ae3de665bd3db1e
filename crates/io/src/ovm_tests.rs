//! `.ovm` tet maps: HexHex's convention on a file written by hand as
//! OpenVolumeMesh's `FileManager` writes it, the writer reproducing that
//! file, round trips, and bad files as one-line errors.

use crate::{parse_ovm_tet_map, tet_map_ovm};
use dualex_map::TetMap;

/// One tet `0 1 2 3` as HexHex's `.hexex` reader builds it (halffaces
/// `(0 1 2)`, `(0 2 3)`, `(0 3 1)`, `(1 3 2)`), corner `k` mapped to `p_k`
/// = 0, 2x, 2y, 2z: each halfface holds the value of the vertex opposite.
const ONE_TET: &str = "OVM ASCII
Vertices
4
0.0 0.0 0.0
1.0 0.0 0.0
0.0 1.0 0.0
0.0 0.0 1.0
Edges
6
0 1
1 2
2 0
2 3
3 0
3 1
Faces
4
3 0 2 4
3 5 6 8
3 9 10 1
3 11 7 3
Polyhedra
1
4 0 2 4 6
HFProp vec3d \"HexHex::Parametrization\"
0.0 0.0 2.0
0.0 0.0 0.0
2.0 0.0 0.0
0.0 0.0 0.0
0.0 2.0 0.0
0.0 0.0 0.0
0.0 0.0 0.0
0.0 0.0 0.0
";

fn one_tet() -> TetMap {
    TetMap {
        positions: vec![[0.0; 3], [1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.0, 1.0]],
        simplices: vec![[0, 1, 2, 3]],
        coords: vec![[[0.0; 3], [2.0, 0.0, 0.0], [0.0, 2.0, 0.0], [0.0, 0.0, 2.0]]],
    }
}

fn written(map: &TetMap) -> String {
    let mut out = Vec::new();
    tet_map_ovm(&mut out, map).unwrap_or_else(|e| panic!("write: {e}"));
    String::from_utf8(out).unwrap_or_default()
}

fn parsed(text: &str) -> TetMap {
    parse_ovm_tet_map(text.as_bytes()).unwrap_or_else(|e| panic!("{e}"))
}

#[test]
fn each_halfface_holds_the_parameter_of_the_opposite_vertex() {
    assert_eq!(parsed(ONE_TET), one_tet());
}

#[test]
fn the_writer_writes_what_openvolumemesh_writes() {
    assert_eq!(written(&one_tet()), ONE_TET);
}

#[test]
fn other_properties_comments_and_old_style_names_are_skipped() {
    let text = ONE_TET.replace(
        "HFProp",
        "# a comment\nVProp int \"tag\"\n1\n2\n3\n4\n\nCProp double \"q\"\n\"q\"\n0.5\nHFProp",
    ) + "MProp string \"note\"\nhello\n";
    assert_eq!(parsed(&text), one_tet());
}

#[test]
fn tet_maps_round_trip_with_shared_faces() {
    // the unit cube of 6 tets around the diagonal 0–7, mapped onto [0, 2]³
    let positions: Vec<[f64; 3]> = (0..8)
        .map(|i| [(i & 1) as f64, (i >> 1 & 1) as f64, (i >> 2 & 1) as f64])
        .collect();
    let simplices = vec![
        [0, 1, 3, 7],
        [0, 3, 2, 7],
        [0, 2, 6, 7],
        [0, 6, 4, 7],
        [0, 4, 5, 7],
        [0, 5, 1, 7],
    ];
    let coords = simplices
        .iter()
        .map(|t: &[u32; 4]| t.map(|v| positions[v as usize].map(|x| 2.0 * x + 0.1)))
        .collect();
    let map = TetMap {
        positions,
        simplices,
        coords,
    };
    let text = written(&map);
    // 12 boundary triangles + 6 inner ones, each written once
    assert!(text.contains("Faces\n18\n"), "{text}");
    assert_eq!(parsed(&text), map);
}

#[test]
fn bad_files_are_one_line_errors() {
    let msg = |text: &str| {
        parse_ovm_tet_map(text.as_bytes())
            .err()
            .map(|e| e.to_string())
            .unwrap_or_default()
    };
    let no_param = ONE_TET.split("HFProp").next().unwrap_or_default();
    assert_eq!(
        msg(no_param),
        "no halfface property \"HexHex::Parametrization\" (vec3d): not a HexHex map"
    );
    assert_eq!(
        msg("OVM BINARY\n"),
        "line 1: binary .ovm files are not supported; write it as ASCII"
    );
    assert_eq!(
        msg(&ONE_TET.replace("3 11 7 3", "3 11 7 99")),
        "line 21: face 3: index 99 out of range (there are 12)"
    );
    assert_eq!(
        msg(&ONE_TET.replace("Polyhedra\n1\n", "Polyhedra\n99\n")),
        "line 23: 99 Polyhedra declared but only 10 lines follow"
    );
    assert_eq!(
        msg(&ONE_TET.replace("4 0 2 4 6", "3 0 2 4")),
        "line 24: cell 0: 3 halffaces; only tets (4) are supported"
    );
    assert_eq!(
        msg(&ONE_TET.replace("Edges", "Edgez")),
        "line 8: expected `Edges`, found `Edgez`"
    );
    assert!(msg(&ONE_TET.replace(
        "2.0 0.0 0.0\n0.0 0.0 0.0\n0.0 2.0",
        "nan 0.0 0.0\n0.0 0.0 0.0\n0.0 2.0"
    ))
    .starts_with("line 28: halfface 2"));
}
