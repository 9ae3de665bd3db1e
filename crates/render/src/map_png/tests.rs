use super::*;
use crate::canvas::{bbox, white, Fit};
use crate::test_png::{colours, has_colour, read_png, temp_path};
use crate::valence::{V3_RGB, V5_RGB};

/// An `n × n` grid split into triangles, map = position.
fn grid(n: u32) -> TriMap {
    let mut m = TriMap::default();
    for j in 0..=n {
        for i in 0..=n {
            m.positions.push([f64::from(i), f64::from(j), 0.0]);
        }
    }
    for j in 0..n {
        for i in 0..n {
            let v = |a: u32, b: u32| (j + b) * (n + 1) + i + a;
            m.simplices.push([v(0, 0), v(1, 0), v(1, 1)]);
            m.simplices.push([v(0, 0), v(1, 1), v(0, 1)]);
        }
    }
    m.coords = m
        .simplices
        .iter()
        .map(|s| s.map(|v| [m.positions[v as usize][0], m.positions[v as usize][1]]))
        .collect();
    m
}

/// Three unit squares around vertex 0, each in its own chart (a cube
/// corner): vertex 0 has index +1/4.
fn cube_corner() -> TriMap {
    let mut m = TriMap::default();
    m.positions.push([0.0; 3]);
    for k in 0..3 {
        let mut p = [0.0; 3];
        p[k] = 1.0;
        m.positions.push(p);
    }
    for k in 0..3 {
        let mut p = [1.0; 3];
        p[(k + 2) % 3] = 0.0;
        m.positions.push(p);
    }
    for k in 0..3u32 {
        let (a, mid, b) = (1 + k, 4 + k, 1 + (k + 1) % 3);
        m.simplices.push([0, a, mid]);
        m.coords.push([[0.0, 0.0], [1.0, 0.0], [1.0, 1.0]]);
        m.simplices.push([0, mid, b]);
        m.coords.push([[0.0, 0.0], [1.0, 1.0], [0.0, 1.0]]);
    }
    m
}

#[test]
fn cube_corner_is_marked_valence_three() {
    let marks = singular_marks(&cube_corner());
    assert_eq!(
        marks,
        vec![MapMark {
            vertex: 0,
            class: ValenceClass::V3
        }]
    );
    let pix = draw_map(&cube_corner(), &marks, 200).unwrap();
    assert!(has_colour(&pix, V3_RGB));
    assert!(!has_colour(&pix, PURPLE));
}

#[test]
fn folded_grid_shows_purple_and_writes_png() {
    let mut m = grid(4);
    // push the map image of vertex 6 = (1, 1) across its neighbours
    for (s, tri) in m.simplices.iter().enumerate() {
        for (c, &v) in tri.iter().enumerate() {
            if v == 6 {
                m.coords[s][c] = [2.6, 2.4];
            }
        }
    }
    let reverted = (0..m.len()).filter(|&s| m.map_det(s) < 0.0).count();
    assert!(reverted > 0);
    let path = temp_path("folded.png");
    map_png(&m, &path, 256).unwrap();
    let pix = read_png(&path);
    assert_eq!((pix.width(), pix.height()), (256, 256));
    assert!(has_colour(&pix, PURPLE));
    assert!(has_colour(&pix, LIGHT));
    assert!(!has_colour(&pix, V5_RGB));
    assert!(colours(&pix).len() >= 5);
    let _ = std::fs::remove_file(path);
}

#[test]
fn marks_from_turns_when_index_unknown() {
    let s = |turns, q| VertexSingularity {
        vertex: 0,
        turns,
        index_quarters: q,
    };
    assert_eq!(MapMark::of(&s(1, Some(1))).class, ValenceClass::V3);
    assert_eq!(MapMark::of(&s(3, Some(-1))).class, ValenceClass::V5);
    assert_eq!(MapMark::of(&s(1, Some(-3))).class, ValenceClass::Other);
    assert_eq!(MapMark::of(&s(1, None)).class, ValenceClass::V3);
    assert_eq!(MapMark::of(&s(3, None)).class, ValenceClass::V5);
    assert_eq!(MapMark::of(&s(2, None)).class, ValenceClass::Other);
}

#[test]
fn bad_inputs_are_errors_not_panics() {
    let m = grid(2);
    let bad_mark = [MapMark {
        vertex: 99,
        class: ValenceClass::V3,
    }];
    assert!(draw_map(&m, &bad_mark, 100).is_err());
    assert!(draw_map(&TriMap::default(), &[], 100).is_err());
    let mut far = grid(2);
    far.coords.iter_mut().flatten().for_each(|p| p[0] += 1e17);
    assert!(draw_map(&far, &[], 100).is_ok());
}

/// Whether some pixel of the rectangle `r` has exactly colour `rgb`.
fn has_colour_in(pix: &Pixmap, r: tiny_skia::Rect, rgb: [u8; 3]) -> bool {
    let w = pix.width();
    pix.pixels().iter().enumerate().any(|(i, p)| {
        let (x, y) = ((i as u32 % w) as f32, (i as u32 / w) as f32);
        let c = p.demultiply();
        let (cx, cy) = (x + 0.5, y + 0.5);
        (r.left()..r.right()).contains(&cx)
            && (r.top()..r.bottom()).contains(&cy)
            && [c.red(), c.green(), c.blue()] == rgb
            && c.alpha() == 255
    })
}

#[test]
fn reverted_singular_disk_has_a_legend_and_scaled_marks() {
    let (map, _) = dualex_gen::singular_disk(1, true, 6, 16, 4.0).unwrap();
    let reverted = (0..map.len()).filter(|&s| map.map_det(s) < 0.0).count();
    assert!(reverted > 0);
    let (welded, _) = weld(&map);
    let marks = singular_marks(&welded);
    assert!(
        marks.iter().any(|m| m.class == ValenceClass::V3),
        "{marks:?}"
    );
    for size in [256, 1200] {
        let mut pix = white(size).unwrap();
        let lo_hi = bbox(welded.coords.iter().flatten().copied()).unwrap();
        draw_triangles(&mut pix, &welded, &Fit::new(lo_hi.0, lo_hi.1, size));
        let rect = legend::draw_legend(&mut pix, reverted, &marks).expect("no legend");
        // small: a corner box, not a band across the picture
        let s = size as f32;
        assert!(
            rect.width() < 0.4 * s && rect.height() < 0.2 * s,
            "{rect:?}"
        );
        assert!(rect.left() < 0.1 * s || rect.right() > 0.9 * s);
        assert!(rect.top() < 0.1 * s || rect.bottom() > 0.9 * s);
        assert!(has_colour_in(&pix, rect, PURPLE), "no reverted swatch");
        assert!(has_colour_in(&pix, rect, V3_RGB), "no +1/4 swatch");
        assert!(has_colour_in(&pix, rect, legend::INK), "no text");
        assert!(!has_colour_in(&pix, rect, V5_RGB));
    }
    // the whole picture: marks as large as 0.7 % of it, legend included
    let bytes = map_png_bytes(&map, 1200).unwrap();
    let pix = Pixmap::decode_png(&bytes).unwrap();
    let blue = colours(&pix)
        .iter()
        .find(|(c, _)| *c == V3_RGB)
        .map_or(0, |&(_, n)| n);
    let r = mark_radius(1200);
    assert!(r > 8.0);
    assert!(blue as f32 > 3.0 * r * r, "marks cover {blue} px only");
    assert!(has_colour(&pix, legend::INK));
    if let Some(dir) = std::env::var_os("DUALEX_KEEP_PNG") {
        std::fs::write(std::path::Path::new(&dir).join("legend.png"), &bytes).unwrap();
    }
}

#[test]
fn no_legend_when_nothing_to_explain() {
    let mut pix = white(100).unwrap();
    assert!(legend::draw_legend(&mut pix, 0, &[]).is_none());
    assert_eq!(colours(&pix).len(), 1);
}
