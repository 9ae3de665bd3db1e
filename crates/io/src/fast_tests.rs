//! The parallel fast paths against the sequential readers: on valid files
//! (generated and shared data) they must give the same map; on corrupted
//! files they must give the same map or step aside (`None`), never accept
//! what the sequential reader refuses. Small chunk sizes exercise the
//! joins.

use crate::fast::{hexex_chunked, obj_chunked};
use crate::float_tests::Rng;
use crate::fuzz_tests::mutants;
use crate::hexex::parse_hexex_sequential;
use crate::obj::parse_obj_sequential;
use crate::write_map::{tet_map_hexex, tri_map_obj};

fn obj_bytes(map: &dualex_map::TriMap) -> Vec<u8> {
    let mut out = Vec::new();
    tri_map_obj(&mut out, map).unwrap();
    out
}

fn hexex_bytes(map: &dualex_map::TetMap) -> Vec<u8> {
    let mut out = Vec::new();
    tet_map_hexex(&mut out, map).unwrap();
    out
}

/// Same result as the sequential reader or `None`; `must` asks for `Some`.
/// Returns whether the fast path read the file.
fn agree_obj(bytes: &[u8], chunk: usize, must: bool) -> bool {
    let fast = obj_chunked(bytes, chunk);
    match (fast, parse_obj_sequential(bytes)) {
        (Some(f), Ok(s)) => assert_eq!(f, s),
        (Some(_), Err(e)) => panic!("fast OBJ path accepted a file refused with: {e}"),
        (None, _) => {
            assert!(
                !must,
                "fast OBJ path stepped aside on a valid canonical file"
            );
            return false;
        }
    }
    true
}

fn agree_hexex(bytes: &[u8], chunk: usize, must: bool) -> bool {
    let fast = hexex_chunked(bytes, chunk);
    match (fast, parse_hexex_sequential(bytes)) {
        (Some(f), Ok(s)) => assert_eq!(f, s),
        (Some(_), Err(e)) => panic!("fast hexex path accepted a file refused with: {e}"),
        (None, _) => {
            assert!(
                !must,
                "fast hexex path stepped aside on a valid canonical file"
            );
            return false;
        }
    }
    true
}

#[test]
fn generated_maps_read_the_same_in_chunks() {
    let alt = dualex_gen::Diagonal::Alternating;
    let (tri, _) = dualex_gen::square_noise(12, 0.2, 6.2, 0.3, 7, alt);
    let obj = obj_bytes(&tri);
    let (tet, _) = dualex_gen::block::block_noise(4, 0.2, 2.2, 0.3, 7);
    let hexex = hexex_bytes(&tet);
    for chunk in [1, 7, 64, 1000, 1 << 20] {
        agree_obj(&obj, chunk, true);
        agree_hexex(&hexex, chunk, true);
    }
}

#[test]
fn corrupted_files_never_pass_the_fast_path_alone() {
    let alt = dualex_gen::Diagonal::Alternating;
    let (tri, _) = dualex_gen::square_identity(5, 0.2, 2.7, alt);
    let obj = obj_bytes(&tri);
    let (tet, _) = dualex_gen::block::block(2, 2, 2, 0.2, 1.2);
    let hexex = hexex_bytes(&tet);
    let (bad_obj, bad_hexex) = (mutants(&obj, 3000), mutants(&hexex, 3000));
    for (i, (o, h)) in bad_obj.iter().zip(&bad_hexex).enumerate() {
        let chunk = [5, 50, 1 << 20][i % 3];
        agree_obj(o, chunk, false);
        agree_hexex(h, chunk, false);
    }
    // layouts the fast paths leave to the sequential readers
    let relative = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\nf -3/-3 -2/-2 -1/-1\n";
    agree_obj(relative.as_bytes(), 8, false);
    let one_line = "4 0 0 0 1 0 0 0 1 0 0 0 1 1 0 1 2 3 0 0 0 1 0 0 0 1 0 0 0 1\n";
    agree_hexex(one_line.as_bytes(), 8, false);
}

/// The byte-level line and corner scanning of the OBJ fast path against
/// `str::lines` and `split('/')`: CRLF, a last line without `\n`, tabs,
/// `v/vt/vn`, and corners it must leave to the sequential reader.
#[test]
fn obj_lines_and_corners_read_as_the_sequential_reader() {
    let head = "v 0 0 0\r\nv 1 0 0\nv 0 1 0\t# c\nvt 0 0\nvt 1 0\r\nvt 0 1\n";
    for (face, must) in [
        ("f 1/1 2/2 3/3", true),
        ("f 1/1 2/2 3/3\r\n", true),
        ("f\t1/1/9 2/2/ 3/3//x # t\n\n\r\n", true),
        ("f 1/1 2/2 3/3 \r", true),
        ("f 1//1 2/2 3/3\n", false),
        ("f 1/1 2/2 3\n", false),
        ("f 0/1 2/2 3/3\n", false),
        ("f 1/+1 2/2 3/3\n", false),
        ("f 1/1 2/2 3/4\n", false),
        ("f 1/1 2/2 3/3 1/1\n", false),
        ("f 99999999999/1 2/2 3/3\n", false),
        ("f 0000001/0000001 2/2 03/003\n", true),
        ("f 00000001/1 2/00000002 3/3\n", true),
        ("f 1/1\t2/2\r3/3\n", true),
        ("f 1/0 2/2 3/3\n", false),
        ("f 1/1 2/2 1234567/3\n", false),
        ("f 1/1 2/2: 3/3\n", false),
        ("f 1/1 2/ 3/3\n", false),
        ("f /1 2/2 3/3\n", false),
    ] {
        // at the end of the file, then with lines after it (the corners
        // then read two words at a time)
        let text = format!("{head}{face}");
        assert_eq!(agree_obj(text.as_bytes(), 4, false), must, "{face:?}");
        let text = format!("{head}{face}\n# a comment longer than two words\n");
        assert_eq!(agree_obj(text.as_bytes(), 1 << 20, false), must, "{face:?}");
    }
}

#[test]
fn hexex_lines_read_as_the_sequential_reader() {
    let head = "4\n0 0 0\n1 0 0\r\n0 1 0\t\n0 0 1\n1";
    let tet = "0 1 2 3 0 0 0 1 0 0 0 1 0 0 0 1";
    // vertices not one per line, a blank line before the tet count, the
    // count on a vertex's line or beside the vertex count: left to the
    // sequential reader (which reads them as one token stream)
    for head in [
        "4\n0 0 0\n1 0 0 0\r\n1 0\n0 0 1\n1\n",
        "4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n\n1\n",
        "4\n0 0 0\n1 0 0\n0 1 0\n0 0 1 1\n",
        "4 0 0 0\n1 0 0\n0 1 0\n0 0 1\n1\n",
        "\n 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n1\n",
    ] {
        let text = format!("{head}{tet}\n");
        let must = head.starts_with('\n');
        assert_eq!(agree_hexex(text.as_bytes(), 4, false), must, "{head:?}");
    }
    for (body, must) in [
        (format!("\n{tet}"), true),
        (format!(" \t\r\n{tet}\r\n\n \n"), true),
        (format!("\n\t{tet} \r"), true),
        (format!("\n{tet}\n7\n"), false),
        (format!("\n{tet} 7\n"), false),
        (format!(" 0\n{tet}\n"), false),
        (format!("\n\n{tet}\n"), false),
        (
            format!("\n{}\n", tet.replace(" 1 0 0 0 1", " 1e\x00 0 0 1")),
            false,
        ),
        (format!("\n{}\n", tet.replace("2 3", "2\n3")), false),
        (format!("\n{}\n", tet.replace("0 1 2", "0 +1 2")), false),
        // Unicode whitespace is not a separator for the sequential reader
        (format!("\n{tet}\n\u{a0}\n"), false),
        (format!("\n{tet}\n\x0b\n"), false),
        (format!(" \u{2003}\n{tet}\n"), false),
    ] {
        let text = format!("{head}{body}");
        assert_eq!(agree_hexex(text.as_bytes(), 4, false), must, "{body:?}");
    }
}

/// A simplex with a repeated vertex: the fast paths check it as they read
/// (they validate nothing afterwards), so they step aside and the
/// sequential readers refuse the file, naming the simplex.
#[test]
fn repeated_corners_are_left_to_the_sequential_readers() {
    let head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";
    for face in ["f 1/1 1/2 3/3\n", "f 1/1 2/2 2/3\n", "f 3/1 2/2 3/3\n"] {
        let text = format!("{head}f 1/1 2/2 3/3\n{face}");
        assert!(!agree_obj(text.as_bytes(), 1 << 20, false), "{face:?}");
        let e = parse_obj_sequential(text.as_bytes()).unwrap_err();
        assert!(e.to_string().contains("triangle 1"), "{face:?}: {e}");
    }
    let head = "4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n2\n0 1 2 3 0 0 0 1 0 0 0 1 0 0 0 1\n";
    for tet in [
        "0 0 2 3", "0 1 2 0", "0 1 3 3", "1 2 1 3", "0 2 1 2", "3 1 2 3",
    ] {
        let text = format!("{head}{tet} 0 0 0 1 0 0 0 1 0 0 0 1\n");
        assert!(!agree_hexex(text.as_bytes(), 1 << 20, false), "{tet:?}");
        let e = parse_hexex_sequential(text.as_bytes()).unwrap_err();
        assert!(e.to_string().contains("tet 1"), "{tet:?}: {e}");
    }
}

#[test]
#[cfg_attr(
    no_shared_data,
    ignore = "../shared/data is absent (real maps from libQEx, Directional, MC3D, libHexEx: see README, Tests)"
)]
fn shared_data_reads_the_same() {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("../../../shared/data");
    let Ok(walk) = std::fs::read_dir(&dir) else {
        eprintln!("SKIPPED: {} is absent", dir.display());
        return;
    };
    let mut stack: Vec<std::path::PathBuf> = walk.flatten().map(|e| e.path()).collect();
    let (mut seen, mut fast) = (0, 0);
    while let Some(p) = stack.pop() {
        if p.is_dir() {
            stack.extend(
                std::fs::read_dir(&p)
                    .into_iter()
                    .flatten()
                    .flatten()
                    .map(|e| e.path()),
            );
            continue;
        }
        let ext = p.extension().and_then(|e| e.to_str()).unwrap_or("");
        let Ok(bytes) = std::fs::read(&p) else {
            continue;
        };
        fast += usize::from(match ext {
            "obj" => agree_obj(&bytes, 1 << 16, false),
            "hexex" => agree_hexex(&bytes, 1 << 16, false),
            _ => continue,
        });
        seen += 1;
    }
    eprintln!("{fast} of {seen} shared .obj/.hexex files read by the fast paths");
    assert!(seen > 0, "no .obj/.hexex under {}", dir.display());
    // the shared data's valid maps use the canonical layouts
    assert!(fast * 2 > seen, "{fast} of {seen}");
}

/// `text_lines` against its definition (`str::from_utf8`, no NUL, then
/// `count_lines` as `str::lines` counts): ASCII, multi-byte and invalid
/// UTF-8, NUL bytes, CR, a last line with or without `\n`, blocks longer
/// than the 224 bytes its loop sums at a time.
#[test]
fn text_lines_is_utf8_without_nul_and_the_line_count() {
    use crate::cursor::{count_lines, text_lines};
    // xorshift, as `mutants`
    let mut s = 0x2545_f491_4f6c_dd1du64;
    let mut next = move |m: usize| {
        s ^= s << 13;
        s ^= s >> 7;
        s ^= s << 17;
        (s % m as u64) as usize
    };
    let alphabet: [&[u8]; 9] = [
        b"v 1.5 2",
        b"\n",
        b"\r\n",
        b"\xc3\xa9",
        b"\xe2\x82\xac",
        b"\xff",
        b"\x00",
        b"\xc3",
        b" ",
    ];
    for case in 0..3000 {
        let mut bytes = Vec::new();
        let len = [3, 40, 300, 2000, 223, 224, 225, 449][case % 8];
        // most cases from the harmless symbols only
        let kinds = if case % 3 == 0 { alphabet.len() } else { 5 };
        while bytes.len() < len {
            bytes.extend_from_slice(alphabet[next(kinds)]);
        }
        let want = std::str::from_utf8(&bytes)
            .ok()
            .filter(|t| !t.contains('\0'))
            .map(|t| {
                assert_eq!(count_lines(&bytes), t.lines().count());
                t.lines().count()
            });
        assert_eq!(
            text_lines(&bytes),
            want,
            "{:?}",
            String::from_utf8_lossy(&bytes)
        );
    }
    assert_eq!(text_lines(b""), Some(0));
}

/// `count_lines` and `text_lines` on runs of newlines (every byte of a
/// block a newline: the per-lane byte counts at their largest) and of
/// other bytes, of every length up to four blocks and then some, with and
/// without a last byte that is not a newline.
#[test]
fn line_counts_of_newline_runs() {
    use crate::cursor::{count_lines, text_lines};
    for len in 0..1000 {
        for last in [None, Some(b'x')] {
            let mut bytes = vec![b'\n'; len];
            bytes.extend(last);
            let want = len + usize::from(last.is_some());
            assert_eq!(count_lines(&bytes), want, "{len} {last:?}");
            assert_eq!(text_lines(&bytes), Some(want), "{len} {last:?}");
            // newlines every third byte
            let spaced: Vec<u8> = (0..len)
                .map(|i| if i % 3 == 2 { b'\n' } else { b'7' })
                .collect();
            let want = len / 3 + usize::from(len % 3 != 0);
            assert_eq!(count_lines(&spaced), want, "{len}");
            assert_eq!(text_lines(&spaced), Some(want), "{len}");
        }
    }
}

/// Random OBJ texts of three vertices, three `vt` and a few faces, each
/// line's start and end taken from a list: the keywords `v`, `vt`, `f`
/// with one space, two, a tab, a blank before, glued to more letters, or
/// other keywords; the line ends `\n` right after the last field, blanks
/// first, `\r\n`, a comment, or the end of the file. The fast path reads
/// the keyword and the common line end without the field loop; it must
/// read each text as the sequential reader does or step aside.
#[test]
fn obj_line_starts_and_ends_read_as_the_sequential_reader() {
    let mut r = Rng(0x51_7cc1_b727_220a);
    let starts = ["", "", "", "", " ", "  ", "\t", "\x0c", ""];
    let seps = [" ", " ", " ", " ", "  ", "\t", " \t"];
    let ends = [
        " \n", "\r\n", "\t\n", " # c\n", "#c\n", " 7\n", " x\n", "  x\n",
    ];
    let (mut fast, mut seen) = (0, 0);
    for case in 0..20_000 {
        let mut text = String::new();
        let mut line = |r: &mut Rng, kw: &str, fields: &[&str], last: bool| {
            text.push_str(r.pick(&starts));
            text.push_str(kw);
            for f in fields {
                text.push_str(r.pick(&seps));
                text.push_str(f);
            }
            if !last || r.below(2) == 0 {
                text.push_str(if r.below(6) == 0 { r.pick(&ends) } else { "\n" });
            }
        };
        let kinds = ["v", "vt", "f", "vn", "vtx", "fv", "g", "#", "", "v1"];
        let kw = |r: &mut Rng, own: &'static str| {
            if r.below(24) == 0 {
                r.pick(&kinds)
            } else {
                own
            }
        };
        for p in ["0 0 0", "1 0 0.5", "-0.0 1 0"] {
            let k = kw(&mut r, "v");
            line(&mut r, k, &p.split(' ').collect::<Vec<_>>(), false);
        }
        for p in ["0 0", "1 0.25", "0 1"] {
            let k = kw(&mut r, "vt");
            line(&mut r, k, &p.split(' ').collect::<Vec<_>>(), false);
        }
        let faces = 1 + r.below(3);
        for n in 0..faces {
            let k = kw(&mut r, "f");
            let f = r.pick(&[
                "1/1 2/2 3/3",
                "3/3 2/2 1/1",
                "1/1/1 2/2/2 3/3/3",
                "2/2 3/3 1/1",
            ]);
            line(&mut r, k, &f.split(' ').collect::<Vec<_>>(), n + 1 == faces);
        }
        seen += 1;
        fast += usize::from(agree_obj(
            text.as_bytes(),
            [7, 64, 1 << 20][case % 3],
            false,
        ));
    }
    // most texts are of the common form
    assert!(fast * 4 > seen, "{fast} of {seen} read by the fast path");
}
