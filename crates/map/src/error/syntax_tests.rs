//! The syntax and count errors' displays: each names the line, the element
//! or the element kind counted, in the readers' own words.

use super::tests::{at, says, tok};
use super::*;
use ElementKind::{Cell, Edge, Face, FaceCorner, Halfface, Hexahedron, Tet, Triangle, Vertex};

#[test]
fn value_syntax_errors_name_the_value_and_its_element() {
    let number = |what| SyntaxError::NotANumber {
        what,
        token: tok("0x1"),
    };
    says(
        InputError::at_line(2, number(Some(Subject::VertexCoordinate))),
        "line 2",
        "line 2: vertex coordinate `0x1` is not a number",
    );
    says(
        Vertex.at(1).error(number(Some(Subject::Value))),
        "vertex 1",
        "vertex 1: value `0x1` is not a number",
    );
    says(
        number(Some(Subject::Element(Halfface.at(3)))),
        "halfface 3",
        "halfface 3 `0x1` is not a number",
    );
    says(
        Vertex.at(2).error(number(None)),
        "vertex 2",
        "vertex 2: `0x1` is not a number",
    );
    let int = SyntaxError::NotAnInteger {
        what: Some(Subject::Index(Vertex)),
        token: tok("2.5"),
    };
    says(
        FaceCorner.at(2).error(int),
        "face corner 2",
        "face corner 2: vertex index `2.5` is not an integer",
    );
    let count = SyntaxError::NotANonNegativeInteger {
        what: Subject::Count(Tet),
        token: tok("-1"),
        hint: false,
    };
    says(
        InputError::at_line(6, count),
        "tet count",
        "line 6: tet count `-1` is not a non-negative integer",
    );
    let index = SyntaxError::NotANonNegativeInteger {
        what: Subject::Index(Vertex),
        token: tok("2.0"),
        hint: true,
    };
    says(Tet.at(0).error(index), "tet 0", "tet 0: vertex index `2.0` is not a non-negative integer (a number is missing or extra earlier in the file, or a count is wrong)");
    let element = SyntaxError::NotANonNegativeInteger {
        what: Subject::ElementCount,
        token: tok("-3"),
        hint: false,
    };
    says(
        InputError::at_line(3, element),
        "element count",
        "line 3: element count `-3` is not a non-negative integer",
    );
    let medit = |what| SyntaxError::NotAValidNumber {
        what,
        token: "x".into(),
    };
    says(
        medit(Subject::Element(Hexahedron.at(4))),
        "hexahedron 4",
        "hexahedron 4: `x` is not a valid number",
    );
    says(
        medit(Subject::Reference(Vertex.at(5))),
        "vertex 5",
        "vertex 5 reference: `x` is not a valid number",
    );
    says(
        medit(Subject::Keyword("Dimension".into())),
        "Dimension",
        "Dimension: `x` is not a valid number",
    );
    says(
        medit(Subject::Count(Hexahedron)),
        "hexahedron count",
        "hexahedron count: `x` is not a valid number",
    );
    let length = SyntaxError::BadListLength {
        list: "texcoord".into(),
        length: -2.0,
    };
    says(
        Face.at(1).error(length),
        "face 1",
        "face 1: list `texcoord` length -2 is not a non-negative integer",
    );
    let items = SyntaxError::ListTruncated {
        list: "vertex_indices".into(),
        items: 9.0,
    };
    says(
        Face.at(2).error(items),
        "face 2",
        "face 2: list `vertex_indices` claims 9 items but the file ends before (truncated file?)",
    );
}

#[test]
fn line_syntax_errors_name_the_line_or_the_element() {
    says(
        at(2, SyntaxError::UnknownStatement(tok("3"))),
        "line 2",
        "line 2: unknown statement `3`",
    );
    says(
        at(6, SyntaxError::NoTextureCoordinate { corner: 2 }),
        "face corner 2",
        "line 6: face corner 2 has no texture coordinate (expected f v/vt)",
    );
    says(
        at(5, SyntaxError::UnexpectedHeaderLine(tok("foo bar"))),
        "line 5",
        "line 5: unexpected PLY header line `foo bar`",
    );
    says(
        at(4, SyntaxError::MalformedProperty("float".into())),
        "line 4",
        "line 4: malformed property line `property float`",
    );
    says(
        at(3, SyntaxError::PropertyBeforeElement),
        "element",
        "line 3: property before any element",
    );
    says(
        at(2, SyntaxError::HeaderLineNotText),
        "line 2",
        "line 2: PLY header line is not text",
    );
    says(
        at(3, SyntaxError::NoFormatLine),
        "line 3",
        "line 3: PLY header has no `format` line",
    );
    says(
        at(4, SyntaxError::NoEndHeader),
        "line 4",
        "line 4: PLY header has no `end_header` line (truncated file?)",
    );
    says(
        at(4, SyntaxError::ListCountNotInteger(tok("x"))),
        "line 4",
        "line 4: list count type of `x` is not an integer type",
    );
    let keyword = SyntaxError::ExpectedKeyword {
        keyword: "Edges",
        found: tok("Faces"),
    };
    says(
        at(8, keyword),
        "Edges",
        "line 8: expected `Edges`, found `Faces`",
    );
    says(
        at(30, SyntaxError::ExpectedPropertyHeader(tok("1 2 3"))),
        "line 30",
        "line 30: expected a property header (`HFProp vec3d \"name\"`), found `1 2 3`",
    );
    let value = SyntaxError::ExpectedValue {
        what: "cell count",
        found: "x".into(),
    };
    says(
        at(7, value),
        "cell count",
        "line 7: expected cell count, found \"x\"",
    );
    says(
        at(9, Face.at(0).error(SyntaxError::BadValence(tok("-1 2")))),
        "face 0",
        "line 9: face 0: bad valence in `-1 2`",
    );
    says(
        at(9, Cell.at(1).error(SyntaxError::BadIndex(tok("z")))),
        "cell 1",
        "line 9: cell 1: bad index `z`",
    );
    says(
        at(
            9,
            Edge.at(2).error(SyntaxError::BadVertexIndexIn(tok("0 9"))),
        ),
        "edge 2",
        "line 9: edge 2: bad vertex index in `0 9`",
    );
    let count = SyntaxError::BadSectionCount {
        section: "Vertices",
        token: tok("many"),
    };
    says(
        at(3, count),
        "Vertices",
        "line 3: bad Vertices count `many`",
    );
    let trailing = SyntaxError::TrailingToken {
        token: tok("7"),
        declared: 1,
    };
    says(
        at(9, trailing),
        "tet",
        "line 9: unexpected `7` after the last tet (the file declares 1 tets)",
    );
}

#[test]
fn truncations_name_what_was_awaited() {
    let before = |a| SyntaxError::EndsBefore(a);
    says(
        at(5, before(Awaited::Count(Tet))),
        "tet count",
        "line 5: file ends before the tet count",
    );
    says(
        at(2, before(Awaited::Section("Edges"))),
        "Edges",
        "line 2: file ends before the Edges section",
    );
    says(
        at(2, before(Awaited::SectionCount("Faces"))),
        "Faces",
        "line 2: file ends before the Faces count",
    );
    says(
        at(2, before(Awaited::Record(Edge))),
        "an edge",
        "line 2: file ends before an edge",
    );
    says(
        at(2, before(Awaited::Record(Vertex))),
        "a vertex",
        "line 2: file ends before a vertex",
    );
    says(
        at(2, before(Awaited::Parameter)),
        "parameter",
        "line 2: file ends before a parameter",
    );
    for (owner, values, want) in [
        (
            Tet.at(0),
            Values::MapCoordinates,
            "12 map coordinates, found 9",
        ),
        (Vertex.at(1), Values::Coordinates, "12 coordinates, found 9"),
        (
            Tet.at(2),
            Values::VertexIndices,
            "12 vertex indices, found 9",
        ),
    ] {
        let name = owner.to_string();
        let e = SyntaxError::EndsIn {
            owner,
            expected: 12,
            values,
            found: 9,
        };
        says(
            at(7, e),
            &name,
            &format!("line 7: file ends in {name}: expected {want}"),
        );
    }
    says(
        Face.at(3).error(SyntaxError::EndsEarly),
        "face 3",
        "face 3: file ends early (truncated file?)",
    );
    let reading = SyntaxError::EndsWhileReading(Subject::Element(Vertex.at(0)));
    says(reading, "vertex 0", "file ends while reading vertex 0");
    says(
        at(4, SyntaxError::Truncated { expected: "x" }),
        "line 4",
        "line 4: truncated: expected x",
    );
}

#[test]
fn count_errors_name_the_element_kind_counted() {
    let bytes = CountError::ExceedsBytes {
        what: Tet,
        count: 1,
        bytes: 5,
        numbers_each: 16,
    };
    says(at(6, bytes), "tets", "line 6: the file declares 1 tets, but only 5 bytes follow (each tet needs 16 numbers): truncated file or wrong count");
    says(
        at(
            1,
            CountError::TooLarge {
                what: Vertex,
                count: 1 << 40,
            },
        ),
        "vertex count",
        "line 1: vertex count 1099511627776 is too large",
    );
    let lines = CountError::SectionExceedsLines {
        section: "Edges",
        count: 9,
        lines: 2,
    };
    says(
        at(4, lines),
        "Edges",
        "line 4: 9 Edges declared but only 2 lines follow",
    );
    let property = CountError::PropertyExceedsLines {
        property: "p".into(),
        count: 9,
        lines: 2,
    };
    says(
        at(4, property),
        "\"p\"",
        "line 4: property \"p\": 9 values expected but only 2 lines follow",
    );
    says(
        at(
            5,
            CountError::ExceedsFile {
                what: "point count",
                count: 99,
            },
        ),
        "point count",
        "line 5: point count 99 is more than the file holds",
    );
    says(
        at(
            1,
            CountError::DoNotFit {
                what: Hexahedron,
                count: 9,
            },
        ),
        "hexahedra",
        "line 1: 9 hexahedra do not fit in the file",
    );
    let element = CountError::ElementExceedsBytes {
        element: "vertex".into(),
        count: 9,
        bytes: 3,
    };
    says(at(3, element), "vertex", "line 3: element `vertex` claims 9 records, but only 3 bytes follow (truncated or corrupt file)");
    says(
        CountError::CellTypes { cells: 2, types: 1 },
        "cells",
        "2 cells but 1 cell types",
    );
    let sets = CountError::MapCoordinates {
        simplex: Triangle,
        simplices: 2,
        coords: 1,
    };
    says(
        sets,
        "triangles",
        "2 triangles but 1 sets of map coordinates",
    );
    says(
        Cell.at(1).error(CountError::Indices {
            declared: 4,
            given: 3,
        }),
        "cell 1",
        "cell 1: 4 indices declared, 3 given",
    );
    says(
        Vertex.at(2).error(CountError::FewerValues { expected: 3 }),
        "vertex 2",
        "vertex 2: fewer than 3 values",
    );
    says(
        at(1, CountError::VertexCoordinates { found: 2 }),
        "vertex",
        "line 1: vertex has 2 coordinates; expected `v x y z`",
    );
    says(
        at(1, CountError::TextureValues { found: 1 }),
        "texture coordinate",
        "line 1: texture coordinate has 1 values; expected `vt u v`",
    );
    says(
        Face.at(0).error(CountError::Texcoords { values: 4 }),
        "face 0",
        "face 0: texcoord list has 4 values; expected 6 (u0 v0 u1 v1 u2 v2)",
    );
    for (face, need, want) in [
        (
            None,
            FaceNeed::Triangle,
            "face has 2 vertices; a triangle needs 3",
        ),
        (
            None,
            FaceNeed::AtLeastThree,
            "face has 2 vertices; a face needs at least 3",
        ),
        (
            Some(4),
            FaceNeed::OnlyTriangles,
            "face 4 has 2 vertices; only triangles are supported (triangulate the mesh first)",
        ),
        (Some(4), FaceNeed::Unstated, "face 4 has 2 vertices"),
    ] {
        says(
            CountError::FaceSize {
                face,
                vertices: 2,
                need,
            },
            "face",
            want,
        );
    }
    for (what, reason, want) in [
        (
            Triangle,
            Some(EmptyReason::NoFaceLine),
            "no triangles (the file has no `f` line)",
        ),
        (
            Cell,
            Some(EmptyReason::ZeroCount("Polyhedra")),
            "no cells (the Polyhedra count is 0)",
        ),
        (
            Triangle,
            Some(EmptyReason::EmptyElement("face")),
            "no triangles (the `face` element is empty)",
        ),
        (Hexahedron, None, "no hexahedra"),
        (Tet, None, "no tets"),
    ] {
        let name = what.plural();
        says(CountError::Empty { what, reason }, &name, want);
    }
    says(
        CountError::TooManyVertices(5_000_000_000),
        "vertices",
        "5000000000 vertices: more than u32 indices can address",
    );
}
