//! Tests of the PLY reader (round trips through the writer are in
//! `roundtrip_tests.rs`).

use super::*;

/// An ascii map with extra elements and properties to skip, int positions.
const ASCII: &str = "ply\nformat ascii 1.0\ncomment c\n\
element material 1\nproperty list uchar float rgb\nproperty int id\n\
element vertex 4\nproperty int x\nproperty float y\nproperty uchar red\nproperty double z\n\
property list uchar int junk\n\
element face 2\nproperty uchar flags\nproperty list uchar uint vertex_index\n\
property list int float texcoord\n\
end_header\n\
3 0.5 0.5 0.5 7\n\
0 0 9 0 0\n1 0 9 0 2 5 6\n1 1 9 0 0\n0 1 9 -1.5 1 4\n\
0 3 0 1 2 6 0 0 1 0 1 1\n1 3 0 2 3 6 0 0 1 1 0 1\n";

fn err(text: &[u8]) -> String {
    parse_ply(text).unwrap_err().to_string()
}

#[test]
fn ascii_skips_what_it_does_not_need() {
    let m = parse_ply(ASCII.as_bytes()).unwrap();
    assert_eq!(
        m.positions,
        vec![
            [0.0, 0.0, 0.0],
            [1.0, 0.0, 0.0],
            [1.0, 1.0, 0.0],
            [0.0, 1.0, -1.5]
        ]
    );
    assert_eq!(m.simplices, vec![[0, 1, 2], [0, 2, 3]]);
    assert_eq!(m.coords[1], [[0.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    let p = parse_polygon_ply(ASCII.as_bytes()).unwrap();
    assert_eq!(p.faces, vec![vec![0, 1, 2], vec![0, 2, 3]]);
}

#[test]
fn face_errors_name_the_record_and_line() {
    let quad = ASCII.replace("0 3 0 1 2 6", "0 4 0 1 2 3 6");
    assert_eq!(
        err(quad.as_bytes()),
        "line 23: face 0 has 4 vertices; only triangles are supported (triangulate the mesh first)"
    );
    let short = ASCII.replace("0 3 0 1 2 6 0 0 1 0 1 1", "0 3 0 1 2 4 0 0 1 0");
    assert_eq!(
        err(short.as_bytes()),
        "line 23: face 0: texcoord list has 4 values; expected 6 (u0 v0 u1 v1 u2 v2)"
    );
    let bad = ASCII.replace("1 3 0 2 3", "1 3 0 2.5 3");
    assert_eq!(
        err(bad.as_bytes()),
        "line 24: face 1: `2.5` is not an integer"
    );
    let nan = ASCII.replace("1 3 0 2 3 6 0 0 1 1 0 1", "1 3 0 2 3 6 0 0 1 nan 0 1");
    assert_eq!(
        err(nan.as_bytes()),
        "line 24: face 1: texcoord is not finite"
    );
    let range = ASCII.replace("1 3 0 2 3", "1 3 0 2 9");
    assert_eq!(
        err(range.as_bytes()),
        "triangle 1: corner 2 refers to vertex 9, but there are 4 vertices"
    );
}

#[test]
fn structural_errors() {
    let no_tc = ASCII.replace("property list int float texcoord\n", "");
    assert_eq!(
        err(no_tc.as_bytes()),
        "line 13: element `face` has no `texcoord` list property (per-corner u0 v0 u1 v1 u2 v2), \
         and element `vertex` no `u v`, `s t` or `texture_u texture_v` pair"
    );
    // without texcoord values it is still a polygon mesh
    let no_tc_data = no_tc
        .replace(" 6 0 0 1 0 1 1", "")
        .replace(" 6 0 0 1 1 0 1", "");
    assert_eq!(
        parse_polygon_ply(no_tc_data.as_bytes())
            .unwrap()
            .faces
            .len(),
        2
    );
    assert!(err(no_tc_data.as_bytes()).starts_with("line 13: element `face` has no `texcoord`"));
    let no_z = ASCII.replace("property double z\n", "");
    assert_eq!(
        err(no_z.as_bytes()),
        "line 7: element `vertex` has no scalar property `z`"
    );
    let no_face = "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\nend_header\n0 0 0\n";
    assert_eq!(err(no_face.as_bytes()), "PLY file has no `face` element");
    let cut = &ASCII[..ASCII.len() - 12];
    assert_eq!(err(cut.as_bytes()), "line 24: face 1: list `texcoord` claims 6 items but the file ends before (truncated file?)");
}

#[test]
fn absurd_counts_fail_fast() {
    let huge = ASCII.replace("element vertex 4", "element vertex 100000000000000");
    let e = err(huge.as_bytes());
    assert!(
        e.starts_with("line 7: element `vertex` claims 100000000000000 records, but only"),
        "{e}"
    );
    let mut bin = b"ply\nformat binary_little_endian 1.0\nelement vertex 100000000000000\n\
        property float x\nproperty float y\nproperty float z\nelement face 0\n\
        property list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n"
        .to_vec();
    bin.extend_from_slice(&[0u8; 36]);
    assert_eq!(
        err(&bin),
        "line 3: element `vertex` claims 100000000000000 records, but only 36 bytes follow (truncated or corrupt file)"
    );
    // a list claiming 2^32-1 items in a small binary file
    let mut list = b"ply\nformat binary_big_endian 1.0\nelement vertex 0\nproperty float x\n\
        property float y\nproperty float z\nelement face 1\nproperty list uint int vertex_indices\n\
        property list uchar float texcoord\nend_header\n"
        .to_vec();
    list.extend_from_slice(&[0xff, 0xff, 0xff, 0xff, 0, 0, 0, 1]);
    let e = err(&list);
    assert!(e.starts_with("byte "), "{e}");
    assert!(e.ends_with("face 0: list `vertex_indices` claims 4294967295 items but the file ends before (truncated file?)"), "{e}");
}

#[test]
fn non_text_ascii_body_is_rejected() {
    let mut b = ASCII.as_bytes().to_vec();
    let n = b.len();
    b[n - 3] = 0;
    assert_eq!(err(&b), "line 24: not a text PLY file (NUL byte)");
}
