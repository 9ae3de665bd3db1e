//! Every variant's display names what it is about: the element (kind and
//! index), else the line or the file; and is the exact text the readers
//! and checks wrote before the errors were typed.

use super::*;
use ElementKind::{Cell, Corner, Face, FaceCorner, Hexahedron, Tet, Triangle, Vertex};

/// `error`'s display is `want`, which names `names` (an element, a line
/// or a file).
pub(super) fn says(error: impl Into<InputError>, names: &str, want: &str) {
    let got = error.into().to_string();
    assert_eq!(got, want);
    assert!(got.contains(names), "{got:?} does not name {names:?}");
}

/// `kind` at line `line`.
pub(super) fn at(line: usize, kind: impl Into<InputErrorKind>) -> InputError {
    InputError::at_line(line, kind)
}

/// The token `text`.
pub(super) fn tok(text: &str) -> Token {
    Token::new(text)
}

#[test]
fn the_context_names_the_file_the_location_and_the_elements() {
    let inner = Corner.at(2).error(IndexError::OutOfRange {
        what: Vertex,
        index: 7,
        count: 4,
        counted: Some(Vertex),
    });
    let e = InputError::at_line(7, Tet.at(0).error(inner)).in_file("a.hexex");
    assert_eq!(
        e.to_string(),
        "a.hexex: line 7: tet 0: corner 2: vertex index 7 is out of range (the file has 4 vertices)"
    );
    assert_eq!(e.element(), Some(&Tet.at(0)));
    assert!(matches!(e.cause(), InputErrorKind::Index(_)));
    let e = InputError::at(Location::Byte(96), Face.at(3).error(SyntaxError::EndsEarly));
    assert_eq!(
        e.to_string(),
        "byte 96: face 3: file ends early (truncated file?)"
    );
    let record = ElementKind::from_name("color")
        .at(1)
        .error(SyntaxError::EndsEarly);
    assert_eq!(
        record.to_string(),
        "color 1: file ends early (truncated file?)"
    );
    // one line, whatever a source says
    let source = std::io::Error::other("two\nlines");
    let e = InputError::new(InputErrorKind::from_source(source)).in_file("s.obj");
    assert_eq!(e.to_string(), "s.obj: two lines");
    let read = std::io::Error::from(std::io::ErrorKind::NotFound);
    let e = InputError::new(read).in_file("m.obj");
    assert!(e.to_string().starts_with("m.obj: cannot read: "), "{e}");
    // a token shows at most 24 characters
    assert_eq!(
        tok(&"9".repeat(24)).to_string(),
        format!("`{}`", "9".repeat(24))
    );
    assert_eq!(
        tok(&"9".repeat(99)).to_string(),
        format!("`{}…`", "9".repeat(20))
    );
}

#[test]
fn format_errors_name_the_format_and_the_element() {
    let e = FormatError::UnsupportedExtension {
        extension: "stl".into(),
        allowed: &["obj", "ply"],
    };
    says(
        InputError::new(e).in_file("m.stl"),
        "m.stl",
        "m.stl: unsupported input format `.stl`; use .obj, .ply",
    );
    let nul = FormatError::NotText {
        format: Format::Obj,
        reason: Some(NotTextReason::NulByte),
    };
    says(
        at(2, nul),
        "line 2",
        "line 2: not a text OBJ file (NUL byte)",
    );
    let utf8 = FormatError::NotText {
        format: Format::Ply,
        reason: Some(NotTextReason::InvalidUtf8),
    };
    says(
        at(3, utf8),
        "line 3",
        "line 3: not a text PLY file (invalid UTF-8)",
    );
    let vtk = FormatError::NotText {
        format: Format::Vtk,
        reason: None,
    };
    says(
        InputError::new(vtk).in_file("m.vtk"),
        "m.vtk",
        "m.vtk: not a text file (legacy ASCII VTK expected)",
    );
    let medit = FormatError::NotText {
        format: Format::Medit,
        reason: None,
    };
    says(
        InputError::new(medit).in_file("m.mesh"),
        "m.mesh",
        "m.mesh: not a text MEDIT file",
    );
    says(
        at(1, FormatError::NotFormat(Format::Ply)),
        "line 1",
        "line 1: not a PLY file (it does not start with `ply`)",
    );
    says(
        at(1, FormatError::NotFormat(Format::Vtk)),
        "line 1",
        "line 1: not a VTK file (no `# vtk DataFile` header)",
    );
    says(
        at(3, FormatError::Binary(Format::Vtk)),
        "line 3",
        "line 3: binary VTK is not supported",
    );
    says(
        at(1, FormatError::Binary(Format::Ovm)),
        "line 1",
        "line 1: binary .ovm files are not supported; write it as ASCII",
    );
    says(
        at(5, FormatError::MeditSection("Tetrahedra".into())),
        "line 5",
        "line 5: unsupported MEDIT section `Tetrahedra` (only Vertices and Hexahedra)",
    );
    says(at(2, FormatError::PlyFormat(tok("text"))), "line 2", "line 2: unknown PLY format `text` (expected ascii, binary_little_endian or binary_big_endian)");
    says(
        at(4, FormatError::PlyType(tok("quad"))),
        "line 4",
        "line 4: unknown PLY type `quad`",
    );
    says(
        Cell.at(0).error(FormatError::CellType(5)),
        "cell 0",
        "cell 0: type 5; only quads (9) and hexes (12) are read",
    );
    let mixed = FormatError::MixedCells {
        vertices: 8,
        cell_type: 12,
    };
    says(
        Cell.at(1).error(mixed),
        "cell 1",
        "cell 1: 8 vertices of type 12; all cells must be quads or all hexes",
    );
    for (why, want) in [
        (
            NotATet::Halffaces(6),
            "6 halffaces; only tets (4) are supported",
        ),
        (NotATet::NonTriangleFace, "a face that is not a triangle"),
        (NotATet::ThreeVertices, "all faces on three vertices"),
        (
            NotATet::NotOpposite { vertex: 4 },
            "not a tet: vertex 4 is not opposite exactly one face",
        ),
        (
            NotATet::MoreThanFourVertices,
            "not a tet: its faces span more than 4 vertices",
        ),
    ] {
        says(
            at(9, Cell.at(2).error(FormatError::NotATet(why))),
            "cell 2",
            &format!("line 9: cell 2: {want}"),
        );
    }
    says(
        FormatError::MissingElement("face"),
        "face",
        "PLY file has no `face` element",
    );
    let x = FormatError::MissingScalarProperty {
        element: "vertex",
        property: "x",
    };
    says(
        at(3, x),
        "vertex",
        "line 3: element `vertex` has no scalar property `x`",
    );
    let list = FormatError::MissingListProperty {
        element: "face",
        property: "vertex_indices",
    };
    says(
        at(6, list),
        "face",
        "line 6: element `face` has no `vertex_indices` list property",
    );
    let pair = FormatError::UnpairedTextureCoordinate {
        has: "u",
        lacks: "v",
    };
    says(at(3, pair), "vertex", "line 3: element `vertex` has property `u` but no `v` (per-vertex texture coordinates need both)");
    says(at(7, FormatError::NoPlyMapCoordinates), "face", "line 7: element `face` has no `texcoord` list property (per-corner u0 v0 u1 v1 u2 v2), and element `vertex` no `u v`, `s t` or `texture_u texture_v` pair");
    let ty = FormatError::PropertyType {
        property: "HexHex::Parametrization",
        found: "int".into(),
    };
    says(
        at(20, ty),
        "line 20",
        "line 20: property \"HexHex::Parametrization\" has type `int`, expected `vec3d`",
    );
    says(
        FormatError::NoHalffaceProperty("HexHex::Parametrization"),
        "halfface",
        "no halfface property \"HexHex::Parametrization\" (vec3d): not a HexHex map",
    );
}

#[test]
fn non_finite_values_name_the_value_and_its_element() {
    let nan = |what| InputErrorKind::NonFinite {
        what,
        token: Some(tok("nan")),
    };
    says(
        InputError::at_line(2, nan(Subject::VertexCoordinate)),
        "line 2",
        "line 2: vertex coordinate is not finite (`nan`)",
    );
    says(
        nan(Subject::Element(Vertex.at(3))),
        "vertex 3",
        "vertex 3 is not finite (`nan`)",
    );
    says(
        Tet.at(0).error(nan(Subject::Value)),
        "tet 0",
        "tet 0: value is not finite (`nan`)",
    );
    let plain = |what| InputErrorKind::NonFinite { what, token: None };
    says(
        Vertex.at(4).error(plain(Subject::Coordinate)),
        "vertex 4",
        "vertex 4: coordinate is not finite",
    );
    says(
        Vertex
            .at(5)
            .error(plain(Subject::NamedTextureCoordinate("s".into()))),
        "vertex 5",
        "vertex 5: texture coordinate `s` is not finite",
    );
    says(
        Face.at(6).error(plain(Subject::Texcoord)),
        "face 6",
        "face 6: texcoord is not finite",
    );
}

#[test]
fn extrusion_errors_name_the_vertex_or_the_option() {
    says(
        Extrusion::NoLayers,
        "--layers",
        "--layers must be at least 1",
    );
    says(
        Extrusion::Thickness(-0.5),
        "thickness",
        "thickness -0.5 is not positive",
    );
    says(
        Vertex.at(8).error(Extrusion::VanishingNormal),
        "vertex 8",
        "vertex 8: its area-weighted normal vanishes: cannot offset the surface there",
    );
}

#[test]
fn index_errors_name_the_element_indexed() {
    let at = |e: IndexError| FaceCorner.at(2).error(e);
    says(
        at(IndexError::Zero { what: Vertex }),
        "face corner 2",
        "face corner 2: vertex index 0 is invalid (OBJ indices start at 1)",
    );
    let before = IndexError::BeforeFirst {
        what: Vertex,
        index: -7,
        defined: 4,
    };
    says(
        at(before),
        "face corner 2",
        "face corner 2: vertex index -7 points before the first vertex (4 defined so far)",
    );
    let large = IndexError::TooLarge {
        what: ElementKind::TextureCoordinate,
        index: 1 << 40,
    };
    says(
        at(large),
        "face corner 2",
        "face corner 2: texture coordinate index 1099511627776 is too large",
    );
    let range = IndexError::OutOfRange {
        what: Vertex,
        index: 9,
        count: 4,
        counted: None,
    };
    says(
        at(range),
        "face corner 2",
        "face corner 2: vertex index 9 is out of range (the file has 4)",
    );
    let points = IndexError::VertexOutOfRange {
        vertex: 9,
        count: 1,
        style: RangeStyle::Points,
    };
    says(
        Cell.at(0).error(points),
        "cell 0",
        "cell 0: vertex 9 out of range (1 points)",
    );
    let one = IndexError::VertexOutOfRange {
        vertex: 9,
        count: 8,
        style: RangeStyle::OneBased,
    };
    says(
        Hexahedron.at(0).error(one),
        "hexahedron 0",
        "hexahedron 0: vertex 9 out of range 1..=8",
    );
    let refers = IndexError::RefersToVertex {
        owner: Face.at(1),
        corner: None,
        vertex: 5,
        count: 3,
    };
    says(
        refers,
        "face 1",
        "face 1 refers to vertex 5, but there are 3 vertices",
    );
    let corner = IndexError::RefersToVertex {
        owner: Tet.at(2),
        corner: Some(3),
        vertex: 5,
        count: 3,
    };
    says(
        corner,
        "tet 2",
        "tet 2: corner 3 refers to vertex 5, but there are 3 vertices",
    );
    says(
        Face.at(0).error(IndexError::NotValid { value: -1.0 }),
        "face 0",
        "face 0: vertex index -1 is not a valid index",
    );
    let list = IndexError::ListOutOfRange {
        index: 12,
        bound: 10,
    };
    says(
        Cell.at(4).error(list),
        "cell 4",
        "cell 4: index 12 out of range (there are 10)",
    );
}

#[test]
fn map_errors_name_the_simplex_facet_or_vertex() {
    let position = MapError::NonFinitePosition([1.0, f64::NAN, 0.0]);
    says(
        Vertex.at(3).error(position),
        "vertex 3",
        "vertex 3: position is not finite (1 NaN 0)",
    );
    says(
        Triangle.at(0).error(MapError::RepeatedVertex { vertex: 1 }),
        "triangle 0",
        "triangle 0: vertex 1 appears twice",
    );
    let coordinate = MapError::NonFiniteMapCoordinate { corner: 2 };
    says(
        Tet.at(4).error(coordinate),
        "tet 4",
        "tet 4: corner 2 has a non-finite map coordinate",
    );
    let large = MapError::TooLarge {
        points: 1e18,
        total: 1e18,
    };
    says(Triangle.at(1).error(large), "triangle 1", "triangle 1: map too large: its image spans 1.000e18 grid points, the whole map 1.000e18 (limit 2.684e8); scale the map down");
    says(Tet.at(5).error(MapError::Reflected { percent: 62.4 }), "tet 5", "tet 5: reverted or degenerate tets make up 62% of the volume: the charts are reflected or collapsed, not a map of this volume");
    let facet = MapError::NonManifoldFacet {
        simplex: Triangle,
        vertices: vec![1, 4],
        simplices: vec![0, 2, 7],
    };
    says(
        facet,
        "edge 1-4",
        "edge 1-4 is shared by 3 triangles (0, 2, 7): non-manifold",
    );
    let face = MapError::NonManifoldFacet {
        simplex: Tet,
        vertices: vec![1, 2, 3],
        simplices: vec![0, 1, 2],
    };
    says(
        face,
        "face 1-2-3",
        "face 1-2-3 is shared by 3 tets (0, 1, 2): non-manifold",
    );
    let opposite = MapError::OppositeOrientations {
        simplex: Tet,
        simplices: [3, 8],
        vertices: vec![0, 2, 5],
    };
    says(
        opposite,
        "tets 3 and 8",
        "tets 3 and 8 have opposite orientations across face 0-2-5",
    );
    let fan = MapError::NonManifoldVertex {
        vertex: 6,
        simplex: Triangle,
    };
    says(
        fan,
        "vertex 6",
        "vertex 6 is non-manifold: its triangles form more than one fan",
    );
    let star = MapError::NonManifoldVertex {
        vertex: 6,
        simplex: Tet,
    };
    says(
        star,
        "vertex 6",
        "vertex 6 is non-manifold: its tets are not connected through the faces around it",
    );
    let reflected = |round_hint| MapError::ReflectedTransition {
        simplex: Triangle.at(3),
        facet: 1,
        neighbour: 9,
        mismatch: 0.2,
        round_hint,
    };
    says(reflected(false), "triangle 3 edge 1", "triangle 3 edge 1: the charts of triangles 3 and 9 differ by a reflection or a non-grid rotation (mismatch 0.2)");
    says(reflected(true), "triangles 3 and 9", "triangle 3 edge 1: the charts of triangles 3 and 9 differ by a reflection or a non-grid rotation (mismatch 0.2); if the charts are only noisy, --round-transitions would accept it");
    let integral = MapError::NonIntegralTransition {
        simplex: Tet.at(2),
        facet: 0,
        neighbour: 5,
        residual: 0.3,
        tolerance: 0.001,
        round_limit: 0.1,
    };
    says(integral, "tet 2 face 0", "tet 2 face 0: the transition to tet 5 is not integral (residual 0.3 > tolerance 0.001, and above 0.1, the largest rounded by default); --round-transitions would round it");
}
