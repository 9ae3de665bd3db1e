//! The driver's tests: seeds, the extraction's count in the loop.

use super::*;

/// Seeds move the grid: two seeds give two maps of the sphere, each
/// with the sphere's 8 singularities of index ¼, no flipped triangle,
/// and a translation-free difference only up to the rounding.
#[test]
fn seeds_give_different_maps_of_one_surface() {
    let s = crate::shapes::icosphere(3);
    let run = |seed| {
        let opts = RemeshOptions {
            target: Target::Quads(300),
            seed,
            ..RemeshOptions::default()
        };
        remesh(&s, &opts).expect("the sphere's map")
    };
    let (a, b) = (run(1), run(2));
    for r in [&a, &b] {
        assert_eq!(r.stats.singularity_index.get(&1), Some(&8));
        assert_eq!(r.stats.singularities, 8);
        assert_eq!((r.stats.flipped, r.stats.degenerate), (0, 0));
        assert_eq!(r.stats.off_grid, 0);
    }
    assert_ne!(
        a.map.coords, b.map.coords,
        "seed 2 gives the same map as seed 1"
    );
    assert_eq!(run(1).map.coords, a.map.coords, "a seed gives one map");
}

/// The map's signed area (map units²).
fn area(map: &TriMap) -> f64 {
    map.coords
        .iter()
        .map(|[a, b, d]| 0.5 * ((b[0] - a[0]) * (d[1] - a[1]) - (b[1] - a[1]) * (d[0] - a[0])))
        .sum()
}

/// An extraction that makes 30 % more quads than cells: the map is
/// made again for a smaller area and that one is kept; one that
/// refuses the second map keeps the first; no count, one map.
#[test]
fn the_extractions_count_retargets_the_map_once() {
    let s = crate::shapes::icosphere(3);
    let opts = RemeshOptions {
        target: Target::Quads(300),
        ..RemeshOptions::default()
    };
    let plain = remesh(&s, &opts).expect("the sphere's map");
    assert!(plain.stats.counted.is_empty(), "no count, no entry");
    assert_eq!(plain.stats.kept, None);
    let mut calls = 0;
    let mut more = |m: &TriMap| {
        calls += 1;
        Some((1.3 * area(m)).round() as usize)
    };
    let r = remesh_counted(&s, &opts, &mut more).expect("the sphere's map");
    assert_eq!(calls, 2);
    let [Some(q1), Some(q2)] = r.stats.counted[..] else {
        panic!("two counts: {:?}", r.stats.counted);
    };
    assert!(q1.abs_diff(300) > 15, "{q1}: no recount needed");
    assert!(q2.abs_diff(300) <= 15, "{q2} for 300");
    assert_eq!(
        (1.3 * area(&r.map)).round() as usize,
        q2,
        "the second map kept"
    );
    assert_eq!(r.stats.kept, Some(1));
    // the second map refused: the first kept
    let mut first_only = |m: &TriMap| (area(m) > 260.0).then(|| (1.3 * area(m)).round() as usize);
    let r = remesh_counted(&s, &opts, &mut first_only).expect("the sphere's map");
    assert_eq!(r.stats.counted, vec![Some(q1), None]);
    assert_eq!(r.stats.kept, Some(0));
    assert_eq!(r.map.coords, plain.map.coords);
    // a count within the tolerance: one map, the plain one
    let mut exact = |m: &TriMap| Some(area(m).round() as usize);
    let r = remesh_counted(&s, &opts, &mut exact).expect("the sphere's map");
    assert_eq!(r.stats.counted.len(), 1);
    assert_eq!(r.map.coords, plain.map.coords);
    // the first map refused: made again with the grid moved, kept
    let mut calls = 0;
    let mut refuse_first = |m: &TriMap| {
        calls += 1;
        (calls > 1).then(|| area(m).round() as usize)
    };
    let r = remesh_counted(&s, &opts, &mut refuse_first).expect("the sphere's map");
    assert_eq!(r.stats.counted.len(), 2);
    assert_eq!(r.stats.kept, Some(1), "the map the grid move made");
    assert_eq!(r.stats.counted[0], None);
    assert!(r.stats.counted[1].is_some());
    assert_ne!(r.map.coords, plain.map.coords, "the grid moved");
    // every map refused: all the moves tried, the first map returned
    let mut never = |_: &TriMap| None;
    let r = remesh_counted(&s, &opts, &mut never).expect("the sphere's map");
    assert_eq!(r.stats.counted, vec![None; 1 + crate::recount::MOVES.len()]);
    assert_eq!(r.stats.kept, Some(0), "all refused: the first map");
    assert_eq!(r.map.coords, plain.map.coords);
}
