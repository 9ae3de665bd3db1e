//! Shared by the mesh round-trip tests: extract a map made by
//! `dualex_gen::from_mesh` and compare the result with the expectation built
//! from the input mesh (never from the code under test).
#![allow(dead_code)]

use dualex_gen::from_mesh::{self, meshes, FromMeshOptions};

/// The outcome of one case: `Ok` or what went wrong.
pub type Outcome = Result<(), String>;

fn diff<T: std::fmt::Debug + PartialEq>(out: &mut Vec<String>, what: &str, got: T, want: T) {
    if got != want {
        out.push(format!("{what}: got {got:?}, expected {want:?}"));
    }
}

pub fn catch(f: impl FnOnce() -> Outcome) -> Outcome {
    std::panic::catch_unwind(std::panic::AssertUnwindSafe(f)).unwrap_or_else(|p| {
        let msg = p
            .downcast_ref::<String>()
            .cloned()
            .or_else(|| p.downcast_ref::<&str>().map(|s| s.to_string()))
            .unwrap_or_default();
        Err(format!("panic: {msg}"))
    })
}

/// Runs `mesh` (built-in) with `o` through `dualex_quad::extract`.
pub fn quad_case(name: &str, o: &FromMeshOptions) -> Outcome {
    let mesh = meshes::quad_mesh_by_name(name).ok_or("unknown mesh")?;
    let g = from_mesh::from_quads(&mesh, o).map_err(|e| format!("generate: {e}"))?;
    check_quads(&g, o)
}

/// Extracts `g.map` and compares with its expectation.
pub fn check_quads(g: &from_mesh::FromQuads, o: &FromMeshOptions) -> Outcome {
    let (out, _) =
        dualex_quad::extract(&g.map, &Default::default()).map_err(|e| format!("refused: {e}"))?;
    compare_quads(g, o, &out)
}

/// Compares an extracted quad mesh with `g`'s expectation.
pub fn compare_quads(
    g: &from_mesh::FromQuads,
    o: &FromMeshOptions,
    out: &dualex_cells::QuadMesh,
) -> Outcome {
    let got = dualex_check::check_quad_mesh(out.positions.len(), &out.cells);
    let mut bad = Vec::new();
    if !got.is_valid() {
        bad.push(format!("invalid: {:?}", got.errors()));
    }
    if o.half_shift {
        let e = &g.expected;
        diff(&mut bad, "quads", Some(got.faces), e.quads);
        diff(
            &mut bad,
            "interior valence",
            Some(&got.interior_valence),
            e.interior_valence.as_ref(),
        );
        diff(&mut bad, "euler", Some(got.euler), e.euler);
        diff(
            &mut bad,
            "boundary loops",
            Some(got.boundary_loops),
            e.boundary_loops,
        );
    } else {
        let want = dualex_check::check_quad_mesh(g.refined.positions.len(), &g.refined.cells);
        diff(&mut bad, "quads", got.faces, want.faces);
        diff(
            &mut bad,
            "interior valence",
            &got.interior_valence,
            &want.interior_valence,
        );
        diff(
            &mut bad,
            "boundary valence",
            &got.boundary_valence,
            &want.boundary_valence,
        );
        diff(&mut bad, "euler", got.euler, want.euler);
        diff(
            &mut bad,
            "boundary loops",
            got.boundary_loops,
            want.boundary_loops,
        );
        diff(&mut bad, "components", got.components, want.components);
    }
    if bad.is_empty() {
        Ok(())
    } else {
        Err(bad.join("; "))
    }
}

/// Runs `mesh` (built-in) with `o` through `dualex_hex::extract`.
pub fn hex_case(name: &str, o: &FromMeshOptions) -> Outcome {
    let mesh = meshes::hex_mesh_by_name(name).ok_or("unknown mesh")?;
    let g = from_mesh::from_hexes(&mesh, o).map_err(|e| format!("generate: {e}"))?;
    check_hexes(&g)
}

/// Extracts `g.map` and compares with the refined mesh's counts.
pub fn check_hexes(g: &from_mesh::FromHexes) -> Outcome {
    check_hexes_stats(g).0
}

/// [`check_hexes`], with the extraction's stats (`HexStats::to_json`) when
/// it ran.
pub fn check_hexes_stats(g: &from_mesh::FromHexes) -> (Outcome, Option<serde_json::Value>) {
    match dualex_hex::extract(&g.map, &Default::default()) {
        Err(e) => (Err(format!("refused: {e}")), None),
        Ok((out, st)) => (compare_hexes(g, &out), Some(st.to_json())),
    }
}

/// Compares an extracted hex mesh with the refined mesh's counts.
pub fn compare_hexes(g: &from_mesh::FromHexes, out: &dualex_cells::HexMesh) -> Outcome {
    let got = dualex_check::check_hex_mesh(out.positions.len(), &out.cells, None);
    let want = dualex_check::check_hex_mesh(g.refined.positions.len(), &g.refined.cells, None);
    let mut bad = Vec::new();
    if !got.is_valid() {
        bad.push(format!("invalid: {:?}", got.errors()));
    }
    diff(&mut bad, "hexes", got.cells, want.cells);
    diff(
        &mut bad,
        "interior edge valence",
        &got.interior_edge_valence,
        &want.interior_edge_valence,
    );
    diff(&mut bad, "euler", got.euler, want.euler);
    diff(&mut bad, "components", got.components, want.components);
    diff(
        &mut bad,
        "boundary quads",
        got.boundary.faces,
        want.boundary.faces,
    );
    diff(
        &mut bad,
        "boundary components",
        got.boundary.components,
        want.boundary.components,
    );
    diff(
        &mut bad,
        "boundary euler",
        got.boundary.euler,
        want.boundary.euler,
    );
    diff(
        &mut bad,
        "boundary valence",
        &got.boundary.interior_valence,
        &want.boundary.interior_valence,
    );
    if bad.is_empty() {
        Ok(())
    } else {
        Err(bad.join("; "))
    }
}
