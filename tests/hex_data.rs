//! `dualex hex` as a process on HexEx's maps (skipped with a notice when
//! `../shared/data` is absent): the hex counts of HexEx / HexHex, valid
//! meshes (independent checker), clean errors on the broken files.

mod common;
use common::*;

/// Reads a MEDIT `.mesh` written by dualex (vertices + hexahedra only).
fn read_medit(path: &std::path::Path) -> (Vec<[f64; 3]>, Vec<[u32; 8]>) {
    let s = std::fs::read_to_string(path).expect("read .mesh");
    let mut tok = s.split_whitespace();
    let (mut pos, mut hexes) = (Vec::new(), Vec::new());
    while let Some(t) = tok.next() {
        match t {
            "Vertices" => {
                let n: usize = tok.next().and_then(|x| x.parse().ok()).expect("count");
                for _ in 0..n {
                    let p: Vec<f64> = (0..4)
                        .map(|_| tok.next().and_then(|x| x.parse().ok()).expect("num"))
                        .collect();
                    pos.push([p[0], p[1], p[2]]);
                }
            }
            "Hexahedra" => {
                let n: usize = tok.next().and_then(|x| x.parse().ok()).expect("count");
                for _ in 0..n {
                    let h: Vec<u32> = (0..9)
                        .map(|_| tok.next().and_then(|x| x.parse().ok()).expect("idx"))
                        .collect();
                    hexes.push(std::array::from_fn(|k| h[k] - 1));
                }
            }
            _ => {}
        }
    }
    (pos, hexes)
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn hexex_maps_give_the_reference_hex_counts() {
    let Some(root) = shared_data("hexex") else {
        return;
    };
    for (file, hexes) in [
        ("minimal.hexex", 1),
        ("sphere.hexex", 216),
        ("hand_q.hexex", 956),
        ("fancy_ring_q.hexex", 1220),
        ("fancy_ring.hexex", 1220),
        ("rockerarm_q.hexex", 1749),
    ] {
        let dir = Scratch::new(&format!("hex-{file}"));
        let out = dir.arg("h.mesh");
        let r = dualex(&[
            "hex",
            &root.join(file).display().to_string(),
            "-o",
            &out,
            "--stats",
            &dir.arg("s.json"),
        ]);
        assert!(r.status.success(), "{file}: {}", text(&r));
        let (pos, cells) = read_medit(&dir.path("h.mesh"));
        assert_eq!(cells.len(), hexes, "{file}: {}", json(&dir.path("s.json")));
        let rep = dualex_check::check_hex_mesh(pos.len(), &cells, Some(&pos));
        assert!(rep.is_valid(), "{file}: {:?}", rep.errors());
        assert_eq!(rep.components, 1, "{file}");
    }
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn broken_minimal_files_are_refused() {
    let Some(root) = shared_data("hexex") else {
        return;
    };
    for file in [
        "minimal_missing_tets.hexex",
        "minimal_missing_uvw.hexex",
        "minimal_missing_vertices.hexex",
        "minimal_invalid_charts.hexex",
    ] {
        let dir = Scratch::new(&format!("hexbad-{file}"));
        let out = dir.arg("h.mesh");
        let r = dualex(&["hex", &root.join(file).display().to_string(), "-o", &out]);
        let err = String::from_utf8_lossy(&r.stderr);
        assert_eq!(r.status.code(), Some(1), "{file}: {}", text(&r));
        assert_eq!(err.trim_end().lines().count(), 1, "{file}: {err}");
        assert!(err.contains(file), "{file}: {err}");
        assert!(!dir.path("h.mesh").exists(), "{file}");
    }
}
