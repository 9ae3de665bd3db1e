//! Determinism across thread counts (issue 6): the same input gives
//! byte-identical output files and stats (timings aside) with 1, 2 and 3
//! worker threads. The inputs are large enough to be cut into several
//! parallel chunks by every parallel stage (reader chunks of 1 MiB, node
//! chunks of 4096 triangles / 2048 tets, walks and vertices by 1024), and
//! messy (a fold; noise) so that untangling runs.

mod common;
use common::{dualex, text, Scratch};

/// Runs `args` + `-j N --stats` for N = 1, 2, 3 and checks that `out_ext`
/// outputs and stats agree byte for byte.
fn same_for_every_thread_count(dir: &Scratch, cmd: &str, input: &str, out_ext: &str) {
    let mut outputs: Vec<(Vec<u8>, serde_json::Value)> = Vec::new();
    for j in ["1", "2", "3"] {
        let out = dir.arg(&format!("out{j}.{out_ext}"));
        let stats = dir.arg(&format!("stats{j}.json"));
        let run = dualex(&[cmd, input, "-o", &out, "--stats", &stats, "-j", j, "-q"]);
        assert!(run.status.success(), "{}", text(&run));
        let mut json: serde_json::Value =
            serde_json::from_slice(&std::fs::read(&stats).expect("stats")).expect("json");
        let timings = json.as_object_mut().and_then(|o| o.remove("time_ms"));
        assert!(timings.is_some(), "stats have time_ms");
        outputs.push((std::fs::read(&out).expect("output"), json));
    }
    for (j, o) in outputs.iter().enumerate().skip(1) {
        assert!(
            o.0 == outputs[0].0,
            "{cmd}: output with {} threads differs from 1 thread",
            j + 1
        );
        assert_eq!(o.1, outputs[0].1, "{cmd}: stats with {} threads", j + 1);
    }
    assert!(outputs[0].0.len() > 1000, "{cmd}: output is not trivial");
}

#[test]
fn quads_do_not_depend_on_the_thread_count() {
    let dir = Scratch::new("determinism-quad");
    // a folded torus of 300 × 150 × 2 = 90 000 triangles (~7 MB of OBJ)
    let fold = dualex_gen::Perturb::Fold { strength: 1.5 };
    let (map, _) = dualex_gen::torus(150, 75, 300, 150, fold, dualex_gen::Diagonal::Alternating);
    assert!(map.len() > 50_000);
    let input = dir.arg("torus_fold.obj");
    dualex_io::write_tri_map(std::path::Path::new(&input), &map).expect("write");
    assert!(std::fs::metadata(&input).expect("input").len() > 3 << 20);
    same_for_every_thread_count(&dir, "quad", &input, "obj");
}

#[test]
fn hexes_do_not_depend_on_the_thread_count() {
    let dir = Scratch::new("determinism-hex");
    // 6 · 14³ = 16 464 noisy tets (~4 MB of .hexex)
    let (map, _) = dualex_gen::block::block_noise(14, 0.2, 7.2, 0.3, 7);
    let input = dir.arg("block_noise.hexex");
    dualex_io::write_tet_map(std::path::Path::new(&input), &map).expect("write");
    assert!(std::fs::metadata(&input).expect("input").len() > 2 << 20);
    same_for_every_thread_count(&dir, "hex", &input, "mesh");
}
