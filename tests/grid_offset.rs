//! `--grid-offset`: a valid map whose singularities all sit at cell centres
//! (every chart of an exact generated map offset by ½) extracts under
//! `auto` like the unshifted map does (same counts and valences) by picking
//! the offset 0, and the unshifted map keeps the offset ½ and today's
//! output, bit for bit.

mod common;
use common::*;
use dualex_segment::grid_offset::GridOffset;

/// Adds ½ to every corner coordinate: transitions stay grid-preserving
/// (`h − R·h` is integral for `h = (½, …, ½)`).
fn offset_by_half<const N: usize, const D: usize>(map: &mut dualex_map::SimplexMap<N, D>) {
    for x in map.coords.iter_mut().flatten().flatten() {
        *x += 0.5;
    }
}

fn quads(
    map: &dualex_map::TriMap,
    grid: GridOffset,
) -> (dualex_cells::QuadMesh, serde_json::Value) {
    let opts = dualex_quad::QuadOptions {
        grid_offset: grid,
        ..Default::default()
    };
    let (mesh, st) = dualex_quad::extract(map, &opts).unwrap_or_else(|e| panic!("{e}"));
    (mesh, st.to_json())
}

fn hexes(map: &dualex_map::TetMap, grid: GridOffset) -> (dualex_cells::HexMesh, serde_json::Value) {
    let opts = dualex_hex::HexOptions {
        grid_offset: grid,
        ..Default::default()
    };
    let (mesh, st) = dualex_hex::extract(map, &opts).unwrap_or_else(|e| panic!("{e}"));
    (mesh, st.to_json())
}

#[test]
fn cube_surface_offset_by_half_picks_zero() {
    for name in ["cube", "cube_fold"] {
        let (map, exp) = dualex_gen::by_name(name, 1).expect("generator");
        let (plain, st) = quads(&map, GridOffset::Auto);
        assert_eq!(st["grid_offset"], "half", "{name}: {st}");
        let (half, _) = quads(&map, GridOffset::Half);
        assert_eq!(
            plain, half,
            "{name}: auto must be today's output (offset ½)"
        );
        let want = dualex_check::check_quad_mesh(plain.positions.len(), &plain.cells);
        assert_eq!(Some(want.faces), exp.quads, "{name}");

        let mut shifted = map.clone();
        offset_by_half(&mut shifted);
        let (mesh, st) = quads(&shifted, GridOffset::Auto);
        assert_eq!(st["grid_offset"], "zero", "{name}: {st}");
        assert_eq!(
            st["grid_offset_choice"]["half"]["on_node"], 8,
            "{name}: {st}"
        );
        assert_eq!(
            st["grid_offset_choice"]["zero"]["on_iso"], 0,
            "{name}: {st}"
        );
        let got = dualex_check::check_quad_mesh(mesh.positions.len(), &mesh.cells);
        assert!(got.is_valid(), "{name}: {:?}", got.errors());
        assert_eq!(got.faces, want.faces, "{name}: {st}");
        assert_eq!(got.vertices_used, want.vertices_used, "{name}");
        assert_eq!(got.interior_valence, want.interior_valence, "{name}");
        assert_eq!(got.euler, want.euler, "{name}");
        assert_eq!(st["repair"]["subdivided"], false, "{name}: {st}");

        // forcing ½ on the shifted map puts the 8 corners on nodes: 8
        // triangles, paired by the local repair (4 paths), no subdivision;
        // the 8 valence-3 vertices and the sphere's Euler characteristic
        // stay
        let (mesh, st) = quads(&shifted, GridOffset::Half);
        assert_eq!(st["grid_offset"], "half");
        assert_eq!(st["repair"]["subdivided"], false, "{name}: {st}");
        assert_eq!(st["repair"]["local_paths"], 4, "{name}: {st}");
        let got = dualex_check::check_quad_mesh(mesh.positions.len(), &mesh.cells);
        assert!(got.is_valid(), "{name}: {:?}", got.errors());
        assert_eq!(got.euler, 2, "{name}");
        assert_eq!(got.interior_valence.get(&3), Some(&8), "{name}: {st}");
        if name == "cube" {
            // 54 quads, the 8 triangles made quads, and the quads the 4
            // paths add (the cheapest pairing, whatever the face order)
            assert_eq!(got.faces, 64, "{name}: {st}");
        }
    }
}

#[test]
fn singular_wedge_offset_by_half_picks_zero() {
    for name in ["wedge_p1", "wedge_m1"] {
        let (map, exp) = dualex_gen::by_name_3d(name, 1).expect("generator");
        let (plain, st) = hexes(&map, GridOffset::Auto);
        assert_eq!(st["grid_offset"], "half", "{name}: {st}");
        let (half, _) = hexes(&map, GridOffset::Half);
        assert_eq!(
            plain, half,
            "{name}: auto must be today's output (offset ½)"
        );
        let want = dualex_check::check_hex_mesh(plain.positions.len(), &plain.cells, None);
        assert_eq!(Some(want.cells), exp.hexes, "{name}");

        let mut shifted = map.clone();
        offset_by_half(&mut shifted);
        let (mesh, st) = hexes(&shifted, GridOffset::Auto);
        assert_eq!(st["grid_offset"], "zero", "{name}: {st}");
        let got = dualex_check::check_hex_mesh(mesh.positions.len(), &mesh.cells, None);
        assert!(got.is_valid(), "{name}: {:?}", got.errors());
        assert_eq!(got.cells, want.cells, "{name}: {st}");
        assert_eq!(got.vertices_used, want.vertices_used, "{name}");
        assert_eq!(got.boundary_faces, want.boundary_faces, "{name}");
        assert_eq!(
            got.interior_edge_valence, want.interior_edge_valence,
            "{name}"
        );
        assert_eq!(got.euler, want.euler, "{name}");
    }
}

#[test]
fn cli_option_and_bad_value() {
    let dir = Scratch::new("grid-offset-cli");
    let map = dir.arg("cube.obj");
    let out = dualex(&["generate", "cube", "-o", &map]);
    assert!(out.status.success(), "{}", text(&out));
    for (value, want) in [("auto", "half"), ("half", "half"), ("zero", "zero")] {
        let stats = dir.arg(&format!("{value}.json"));
        let q = dir.arg(&format!("{value}.obj"));
        let out = dualex(&[
            "quad",
            &map,
            "-o",
            &q,
            "--stats",
            &stats,
            "--grid-offset",
            value,
        ]);
        assert!(out.status.success(), "{value}: {}", text(&out));
        assert_eq!(
            json(&dir.path(&format!("{value}.json")))["grid_offset"],
            want
        );
    }
    let out = dualex(&[
        "quad",
        &map,
        "-o",
        &dir.arg("x.obj"),
        "--grid-offset",
        "third",
    ]);
    assert_eq!(out.status.code(), Some(2), "{}", text(&out));
    let err = String::from_utf8_lossy(&out.stderr);
    // clap's usage error: the first line names the option and the values
    let first = err.lines().next().unwrap_or("");
    assert!(
        first.contains("--grid-offset") && first.contains("auto, half or zero"),
        "{err}"
    );
}

/// `dualex extrude` keeps the 2D grid: the cube surface offset by ½ (which
/// `dualex quad` extracts with the offset 0) has its charts shifted by ½
/// before extruding, so `dualex hex` (offset ½ on extruded maps) gives L
/// layers of the same quads; the unshifted cube is extruded as it is.
#[test]
fn extrusion_keeps_the_2d_grid_offset() {
    let Some((cube, _)) = dualex_gen::by_name("cube", 1) else {
        panic!("generator");
    };
    let mut shifted = cube.clone();
    offset_by_half(&mut shifted);
    for (map, want_shift) in [(cube, false), (shifted, true)] {
        let opts = dualex_extrude::ExtrudeOptions {
            layers: 2,
            program: "dualex-test-no-tetgen".into(),
            fallback: true,
            ..Default::default()
        };
        let (tets, rep) = dualex_extrude::extrude(&map, &opts).unwrap_or_else(|e| panic!("{e}"));
        assert_eq!(rep.uv_shifted, want_shift);
        let (q, _) = quads(&map, GridOffset::Auto);
        let (h, st) = hexes(&tets, GridOffset::Auto);
        assert_eq!(st["grid_offset"], "half", "{st}");
        assert_eq!(h.cells.len(), 2 * q.cells.len(), "{st}");
        assert_eq!(h.positions.len(), 3 * q.positions.len(), "{st}");
    }
}
