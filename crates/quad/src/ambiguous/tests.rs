use super::*;

fn mesh(cells: Vec<[u32; 4]>, nv: usize) -> QuadMesh {
    QuadMesh {
        positions: (0..nv).map(|i| [i as f64, (i * i) as f64, 0.0]).collect(),
        cells,
    }
}

#[test]
fn nothing_ambiguous_is_the_identity() {
    let m = mesh(vec![[0, 1, 2, 3]], 4);
    let s = split(&m, &[None; 4], &[]);
    assert!(!s.changed());
    assert_eq!(s.polys, vec![vec![0, 1, 2, 3]]);
    assert_eq!(s.intact, vec![true]);
}

#[test]
fn a_hole_side_beside_a_glued_edge_gets_a_point() {
    // cells 0 = [0,1,2,3] and 1 = [1,0,4,5] glued along {0,1} (slots 0 and
    // 4); cell 2 = [5,4,0,1]... its edge 2→3 is (0,1) again, unmatched
    let m = mesh(vec![[0, 1, 2, 3], [1, 0, 4, 5], [6, 7, 0, 1]], 8);
    let mut partner = vec![None; 12];
    partner[0] = Some(4);
    partner[4] = Some(0);
    let holes = [10];
    let s = split(&m, &partner, &holes);
    assert_eq!(s.parallel_edges, 1);
    assert_eq!(s.new_points, vec![[0, 1]]);
    // the glued edge is kept; the unmatched side's cell becomes a pentagon
    assert_eq!(s.polys[0], vec![0, 1, 2, 3]);
    assert_eq!(s.polys[2], vec![6, 7, 0, 8, 1]);
    assert_eq!(s.intact, vec![true, true, false]);
    // the hole edge is split the same way, as the cell traverses it
    assert_eq!(s.hole_edges, vec![(0, 8), (8, 1)]);
    // the point is the edge's midpoint
    assert_eq!(s.positions[8], [0.5, 0.5, 0.0]);
}

#[test]
fn a_folded_cell_is_cut_into_two_with_distinct_corners() {
    // cell 0 = [0,1,0,2] (corner 0 twice), its edges 0 and 2 glued to
    // cells 1 and 2
    let m = mesh(vec![[0, 1, 0, 2], [1, 0, 3, 4], [2, 0, 5, 6]], 7);
    let mut partner = vec![None; 12];
    for (a, b) in [(0usize, 4u32), (2, 8)] {
        partner[a] = Some(b);
        partner[b as usize] = Some(a as u32);
    }
    let s = split(&m, &partner, &[]);
    assert_eq!(s.folded_cells, 1);
    assert_eq!(s.origin, vec![0, 0, 1, 2]);
    for p in &s.polys[..2] {
        let mut d = p.clone();
        d.sort_unstable();
        d.dedup();
        assert_eq!(d.len(), p.len(), "{p:?}");
        assert_eq!(p.len(), 4, "{p:?}");
    }
    // the neighbours got the same points, on the same edges
    let (m1, m2) = (7, 8);
    assert_eq!(s.polys[0], vec![m1, 1, 0, m2]);
    assert_eq!(s.polys[1], vec![m2, 2, 0, m1]);
    assert_eq!(s.polys[2], vec![1, m1, 0, 3, 4]);
    assert_eq!(s.polys[3], vec![2, m2, 0, 5, 6]);
    // every edge of the result is used once in each direction
    let mut uses: HashMap<(u32, u32), i32> = HashMap::new();
    for p in &s.polys {
        for i in 0..p.len() {
            *uses.entry((p[i], p[(i + 1) % p.len()])).or_default() += 1;
        }
    }
    assert!(uses.values().all(|&u| u == 1), "{uses:?}");
}

#[test]
fn a_cell_folded_onto_itself_is_left_as_it_is() {
    // its two cut edges are one edge (glued to each other): not cut
    let m = mesh(vec![[0, 1, 0, 1]], 2);
    let mut partner = vec![None; 4];
    partner[0] = Some(2);
    partner[2] = Some(0);
    let s = split(&m, &partner, &[]);
    assert_eq!(s.folded_cells, 0);
    assert_eq!(s.polys.len(), 1);
}
