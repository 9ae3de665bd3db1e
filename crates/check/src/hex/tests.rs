use super::*;

/// An `nx × ny × nz` block of unit hexes with positions.
fn block(nx: u32, ny: u32, nz: u32) -> (Vec<[f64; 3]>, Vec<[u32; 8]>) {
    let id = |i: u32, j: u32, k: u32| (k * (ny + 1) + j) * (nx + 1) + i;
    let mut p = Vec::new();
    for k in 0..=nz {
        for j in 0..=ny {
            for i in 0..=nx {
                p.push([i, j, k].map(f64::from));
            }
        }
    }
    let mut h = Vec::new();
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let c = |x: u32, y: u32, z: u32| id(i + x, j + y, k + z);
                h.push([
                    c(0, 0, 0),
                    c(1, 0, 0),
                    c(1, 1, 0),
                    c(0, 1, 0),
                    c(0, 0, 1),
                    c(1, 0, 1),
                    c(1, 1, 1),
                    c(0, 1, 1),
                ]);
            }
        }
    }
    (p, h)
}

fn hist(pairs: &[(u32, usize)]) -> BTreeMap<u32, usize> {
    pairs.iter().copied().collect()
}

#[test]
fn block_counts() {
    let (p, h) = block(2, 2, 2);
    let r = check_hex_mesh(p.len(), &h, Some(&p));
    assert!(r.is_valid(), "{:?}", r.errors());
    assert_eq!(
        (r.cells, r.vertices_used, r.edges, r.faces),
        (8, 27, 54, 36)
    );
    assert_eq!((r.boundary_faces, r.components, r.euler), (24, 1, 1));
    assert_eq!(r.interior_edge_valence, hist(&[(4, 6)]));
    assert_eq!((r.boundary.euler, r.boundary.components), (2, 1));
    assert_eq!(r.boundary.interior_valence, hist(&[(3, 8), (4, 18)]));
    assert_eq!(r.inverted_cells, Some(vec![]));
}

#[test]
fn without_positions_orientation_is_unknown() {
    let (p, h) = block(1, 1, 1);
    let r = check_hex_mesh(p.len(), &h, None);
    assert!(r.is_valid());
    assert_eq!(r.inverted_cells, None);
    assert!(r.interior_edge_valence.is_empty());
}

#[test]
fn flipped_hex_is_inverted_and_misoriented() {
    let (p, mut h) = block(3, 1, 1);
    let c = h[1];
    h[1] = [c[4], c[5], c[6], c[7], c[0], c[1], c[2], c[3]];
    let r = check_hex_mesh(p.len(), &h, Some(&p));
    assert_eq!(r.inverted_cells, Some(vec![1]));
    assert_eq!(r.misoriented_faces.len(), 2);
    assert!(!r.is_valid());
}

#[test]
fn missing_hex_is_a_cavity() {
    let (p, mut h) = block(3, 3, 3);
    h.remove(13); // the centre
    let r = check_hex_mesh(p.len(), &h, Some(&p));
    assert!(r.is_valid(), "a cavity is a valid mesh: {:?}", r.errors());
    assert_eq!((r.boundary.components, r.boundary.euler), (2, 4));
    assert_eq!(r.boundary_faces, 54 + 6);
    // V − E + F − C of a ball with a cavity: 1 + 1
    assert_eq!(r.euler, 2);
}

#[test]
fn third_hex_on_a_face_is_non_manifold() {
    let (mut p, mut h) = block(1, 1, 2);
    // a third hex on the middle face 4-5-6-7, below it, with new vertices
    let n = p.len() as u32;
    p.extend([
        [0.0, 0.0, 0.5],
        [1.0, 0.0, 0.5],
        [1.0, 1.0, 0.5],
        [0.0, 1.0, 0.5],
    ]);
    h.push([n, n + 1, n + 2, n + 3, 4, 5, 6, 7]);
    let r = check_hex_mesh(p.len(), &h, Some(&p));
    assert_eq!(r.non_manifold_faces, vec![[4, 5, 6, 7]]);
    assert!(!r.is_valid());
}

#[test]
fn hexes_sharing_only_a_vertex_or_an_edge() {
    let (p, h) = block(2, 2, 1);
    // cells 0 and 3 share the edge of vertices 4 and 13 only
    let r = check_hex_mesh(p.len(), &[h[0], h[3]], Some(&p));
    assert_eq!(r.boundary.non_manifold_edges, vec![[4, 13]]);
    assert!(!r.is_valid());
    let (p, h) = block(2, 2, 2);
    // cells 0 and 7 share vertex 13 (the centre) only
    let r = check_hex_mesh(p.len(), &[h[0], h[7]], Some(&p));
    assert_eq!(r.boundary.non_manifold_vertices, vec![13]);
    assert!(r.boundary.non_manifold_edges.is_empty());
    assert!(!r.is_valid());
}

#[test]
fn degenerate_and_out_of_range_cells() {
    let (p, mut h) = block(1, 1, 1);
    let mut d = h[0];
    d[7] = d[6];
    h.push(d);
    h.push([0, 1, 2, 3, 4, 5, 6, 100]);
    let r = check_hex_mesh(p.len(), &h, Some(&p));
    assert_eq!(r.degenerate_cells, vec![1]);
    assert_eq!(r.out_of_range_cells, vec![2]);
    assert_eq!(r.inverted_cells, Some(vec![]));
    assert_eq!(r.errors().len(), 2);
}

#[test]
fn missing_positions_are_reported() {
    let (p, h) = block(1, 1, 1);
    let r = check_hex_mesh(p.len(), &h, Some(&p[..4]));
    assert!(r.missing_positions);
    assert_eq!(r.inverted_cells, Some(vec![0]));
}

/// The bucketed faces of one hex equal a hash map's count (the geometric
/// stage's former code): a block, and random cells with repeated
/// vertices and shared faces.
#[test]
fn lone_hex_faces_equal_a_hash_count() {
    fn reference(hexes: &[[u32; 8]]) -> Vec<(usize, usize)> {
        let mut count = std::collections::HashMap::new();
        for (h, cell) in hexes.iter().enumerate() {
            for (f, face) in HEX_FACES.iter().enumerate() {
                count.entry(face_key(cell, face)).or_insert((0, h, f)).0 += 1;
            }
        }
        let mut out: Vec<_> = count
            .into_values()
            .filter(|c| c.0 == 1)
            .map(|c| (c.1, c.2))
            .collect();
        out.sort_unstable();
        out
    }
    let (_, h) = block(3, 2, 2);
    assert_eq!(lone_hex_faces(&h).len(), 2 * (6 + 6 + 4));
    assert_eq!(lone_hex_faces(&h), reference(&h));
    let mut z = 11u32;
    let mut next = |m: u32| {
        z = z.wrapping_mul(1_103_515_245).wrapping_add(12_345);
        (z >> 8) % m
    };
    for case in 0..200u32 {
        let n = 4 + case % 13;
        let cells: Vec<[u32; 8]> = (0..case % 30).map(|_| [0; 8].map(|_| next(n))).collect();
        assert_eq!(lone_hex_faces(&cells), reference(&cells), "{cells:?}");
    }
}

/// The faces' lists and the components, read in parallel tasks, against
/// a map of the faces and a serial union–find, on a block large enough
/// for many tasks: cells flipped (misoriented faces), removed (cavities),
/// a third cell on some faces (non-manifold), and a second block apart.
#[test]
fn face_lists_and_components_match_a_serial_count() {
    use dualex_util::union_find::UnionFind;
    let (mut p, mut h) = block(24, 24, 24);
    for c in (5..h.len()).step_by(997) {
        let x = h[c];
        h[c] = [x[4], x[5], x[6], x[7], x[0], x[1], x[2], x[3]];
    }
    for c in (300..h.len()).step_by(1409).rev() {
        h.remove(c);
    }
    for c in (40..h.len()).step_by(2003) {
        let x = h[c];
        let n = p.len() as u32;
        p.extend([[0.0; 3]; 4]);
        h.push([n, n + 1, n + 2, n + 3, x[4], x[5], x[6], x[7]]);
    }
    let (p2, h2) = block(3, 2, 2);
    let base = p.len() as u32;
    p.extend(p2);
    h.extend(h2.iter().map(|c| c.map(|v| v + base)));
    let r = check_hex_mesh(p.len(), &h, None);
    // the reference: every face's uses in a map
    let mut uses: BTreeMap<[u32; 4], Vec<[u32; 4]>> = BTreeMap::new();
    for c in &h {
        for f in &HEX_FACES {
            uses.entry(face_key(c, f))
                .or_default()
                .push(f.map(|i| c[i]));
        }
    }
    let (mut boundary, mut mis, mut non) = (Vec::new(), Vec::new(), Vec::new());
    for (key, u) in &uses {
        match u[..] {
            [one] => boundary.push(one),
            [a, b] if !opposite(&a, &b) => mis.push(*key),
            [_, _] => {}
            _ => non.push(*key),
        }
    }
    boundary.sort_unstable();
    assert_eq!(r.faces, uses.len());
    assert_eq!(
        (r.misoriented_faces.clone(), r.non_manifold_faces.clone()),
        (mis, non)
    );
    assert!(!r.misoriented_faces.is_empty() && !r.non_manifold_faces.is_empty());
    assert_eq!(r.boundary_faces, boundary.len());
    let mut uf = UnionFind::new(p.len());
    let mut used = vec![false; p.len()];
    for c in &h {
        for &v in c {
            used[v as usize] = true;
            uf.union(c[0] as usize, v as usize);
        }
    }
    let n_used = used.iter().filter(|&&u| u).count();
    let components = uf.count_sets((0..p.len()).filter(|&v| used[v]));
    assert_eq!((r.vertices_used, r.components), (n_used, components));
    assert_eq!(components, 2);
}
