//! The untangling and gluing used by the quad (D = 2) and hex (D = 3) paths
//! are the same generic code of `dualex-graph`: neither path nor their
//! shared steps (`dualex-segment`) defines its own pleat removal, OP1/OP2
//! or union–find gluing (checked on the sources), and both suites exercise
//! it (pleats removed on messy maps, via the CLI).

mod common;
use common::*;
use std::path::Path;

fn sources(dir: &Path) -> Vec<(String, String)> {
    let mut out = Vec::new();
    for e in std::fs::read_dir(dir).expect("read src").flatten() {
        let p = e.path();
        if p.is_dir() {
            out.extend(sources(&p));
        } else if p.extension().is_some_and(|x| x == "rs") {
            out.push((
                p.display().to_string(),
                std::fs::read_to_string(&p).expect("read"),
            ));
        }
    }
    out
}

#[test]
fn quad_and_hex_define_no_graph_operation_of_their_own() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR")).join("../..");
    let shared = sources(&root.join("crates/segment/src"));
    for krate in ["quad", "hex"] {
        let src = sources(&root.join("crates").join(krate).join("src"));
        assert!(!src.is_empty());
        for (file, text) in src.iter().chain(&shared) {
            for def in [
                "fn untangle",
                "fn remove_pleat",
                "fn op1",
                "fn op2",
                "fn glue(",
            ] {
                assert!(
                    !text.contains(def),
                    "{file} defines `{def}`: it must use dualex-graph"
                );
            }
        }
        // the driver and the steps both call (`dualex_segment::steps`)
        let all: String = src.iter().chain(&shared).map(|(_, t)| t.as_str()).collect();
        // `.untangle()` or `.untangle_best(` (other orders, quads)
        for call in [".untangle", ".glue()", "NodeGraph::<"] {
            assert!(
                all.contains(call),
                "crates/{krate} does not call `{call}` of dualex-graph"
            );
        }
    }
}

#[test]
fn both_dimensions_remove_pleats_with_the_core() {
    let dir = Scratch::new("core");
    for (name, file, cmd, out) in [
        ("square_noise", "m.obj", "quad", "q.obj"),
        ("block_noise", "m.hexex", "hex", "h.mesh"),
    ] {
        let m = dir.arg(file);
        assert!(dualex(&["generate", name, "-o", &m]).status.success());
        let r = dualex(&[cmd, &m, "-o", &dir.arg(out), "--stats", &dir.arg("s.json")]);
        assert!(r.status.success(), "{name}: {}", text(&r));
        let st = json(&dir.path("s.json"));
        assert!(
            st["untangle"]["pleats_removed"].as_u64().unwrap_or(0) > 0,
            "{name}: {st}"
        );
        assert_eq!(st["untangle"]["pleats_left"], 0, "{name}: {st}");
    }
}
