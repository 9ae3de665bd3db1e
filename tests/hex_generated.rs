//! `dualex generate` + `dualex hex` as processes on every generated tet map:
//! valid hex meshes (independent checker) equal to the expected block
//! (hex count, boundary surface, Euler characteristic) wherever the
//! generator knows it, and interior edges of valence 4 on valid blocks.

mod common;
use common::*;

/// Reads a MEDIT `.mesh` written by dualex (vertices + hexahedra).
fn read_medit(path: &std::path::Path) -> (Vec<[f64; 3]>, Vec<[u32; 8]>) {
    let s = std::fs::read_to_string(path).expect("read .mesh");
    let mut tok = s.split_whitespace();
    let num = |t: &mut std::str::SplitWhitespace| {
        t.next()
            .and_then(|x| x.parse::<f64>().ok())
            .expect("number")
    };
    let (mut pos, mut hexes) = (Vec::new(), Vec::new());
    while let Some(t) = tok.next() {
        match t {
            "Vertices" => {
                let n = num(&mut tok) as usize;
                for _ in 0..n {
                    let p = [num(&mut tok), num(&mut tok), num(&mut tok)];
                    num(&mut tok);
                    pos.push(p);
                }
            }
            "Hexahedra" => {
                let n = num(&mut tok) as usize;
                for _ in 0..n {
                    let h: [u32; 8] = std::array::from_fn(|_| num(&mut tok) as u32 - 1);
                    num(&mut tok);
                    hexes.push(h);
                }
            }
            _ => {}
        }
    }
    (pos, hexes)
}

#[test]
fn every_generated_tet_map_gives_its_expected_block() {
    for name in dualex_gen::names_3d() {
        let dir = Scratch::new(&format!("hexgen-{name}"));
        let map = dir.arg("m.hexex");
        let out = dualex(&["generate", &name, "-o", &map]);
        assert!(out.status.success(), "generate {name}: {}", text(&out));
        let mesh = dir.arg("h.mesh");
        let out = dualex(&["hex", &map, "-o", &mesh, "--stats", &dir.arg("s.json")]);
        assert!(out.status.success(), "hex {name}: {}", text(&out));
        let st = json(&dir.path("s.json"));
        let (pos, cells) = read_medit(&dir.path("h.mesh"));
        let rep = dualex_check::check_hex_mesh(pos.len(), &cells, Some(&pos));
        // messy maps: vertices sit on noisy preimages, so hexes may be
        // geometrically inverted; the combinatorics must be valid
        let errors: Vec<String> = rep
            .errors()
            .into_iter()
            .filter(|e| !e.contains("inverted"))
            .collect();
        assert!(errors.is_empty(), "{name}: {errors:?}; {st}");
        assert_eq!(rep.components, 1, "{name}");
        let (_, exp) = dualex_gen::by_name_3d(&name, 1).expect("known");
        if let Some(h) = exp.hexes {
            assert_eq!(cells.len(), h, "{name}: {st}");
        }
        if let Some(b) = exp.boundary_components {
            assert_eq!(rep.boundary.components, b, "{name}: boundary surfaces");
        }
        if let Some(e) = exp.boundary_euler {
            assert_eq!(
                rep.boundary.euler, e,
                "{name}: boundary Euler characteristic"
            );
        }
        if name == "block" {
            assert!(rep.is_valid(), "{name}: {:?}", rep.errors());
            assert_eq!(
                rep.interior_edge_valence
                    .keys()
                    .copied()
                    .collect::<Vec<_>>(),
                vec![4],
                "{name}"
            );
            assert_eq!(rep.euler, 1, "{name}: V − E + F − C of a ball");
        }
        if name.contains("noise") || name.contains("rotated") || name.contains("fold") {
            eprintln!(
                "{name}: reverted nodes {}, pleats removed {}",
                st["reverted_nodes"], st["untangle"]["pleats_removed"]
            );
        }
    }
}
