//! A map folded around singular vertices that the untangling cannot
//! resolve (issue 22: ball_hole69 refined twice, 8 folds, seed 1) comes
//! out exact through the relaxed retry, and says so on stderr under `-q`
//! and in the stats (`relax`), never silently.

use super::stderr;
use crate::common::*;

#[test]
fn a_relaxed_map_is_said_and_comes_out_exact() {
    let dir = Scratch::new("relax");
    let map = dir.arg("m.hexex");
    let out = dualex(&[
        "generate",
        "ball_hole69",
        "--scale",
        "2",
        "--folds-at-singular",
        "8",
        "--seed",
        "1",
        "-o",
        &map,
        "-q",
    ]);
    assert!(out.status.success(), "{}", text(&out));
    let want = json(&dir.path("m.expected.json"));
    let st = dir.arg("s.json");
    let out = dualex(&["hex", &map, "-o", &dir.arg("h.mesh"), "--stats", &st, "-q"]);
    assert!(out.status.success(), "{}", text(&out));
    let st = json(&dir.path("s.json"));
    let relax = &st["relax"];
    assert!(relax["reverted_before"].as_u64().unwrap_or(0) > 0, "{st}");
    assert_eq!(relax["reverted_after"], 0, "{st}");
    assert!(relax["relaxed_vertices"].as_u64().unwrap_or(0) > 0, "{st}");
    assert_eq!(st["output"]["hexes"], want["hexes"], "{st}");
    assert_eq!(
        st["output"]["boundary_surfaces"], want["boundary_components"],
        "{st}"
    );
    assert_eq!(st["topology_matches_input"], true, "{st}");
    let err = stderr(&out);
    assert!(
        err.contains("reverted simplices that the untangling could not resolve")
            && err.contains("moved in map space"),
        "{}",
        text(&out)
    );
}
