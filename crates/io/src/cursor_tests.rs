//! The cursor's field reads ([`Cursor::float`], [`Cursor::integer`],
//! [`Cursor::slash_pair`], [`Cursor::field`], [`Cursor::end_line`])
//! against a model of the token-based readers: the text cut into lines at
//! `\n`, each line into fields by `split_ascii_whitespace`, a float field
//! read by `str::parse::<f64>` (finite values only), an integer field
//! digits only. Random lines of random fields (numbers of every form,
//! integers, corners, bad fields) with random separators (one space, many,
//! tabs, `\r`, `\x0b` — not whitespace —, `\x0c`), `\n` or `\r\n` line ends,
//! the last line with or without one: every read must give the model's
//! answer, the cursor must stay on the model's field until the first
//! refusal.

use crate::cursor::Cursor;
use crate::float_tests::{random_token, Rng};

/// What the test asks the cursor for next.
#[derive(Clone, Copy, Debug)]
enum Ask {
    Float,
    Integer(usize),
    Pair,
    Field,
}

/// The model's answer for `ask` on the field `tok` (`None`: refused).
fn model(ask: Ask, tok: &str) -> Option<String> {
    let digits = |s: &str| !s.is_empty() && s.bytes().all(|b| b.is_ascii_digit());
    match ask {
        Ask::Float => {
            let x = tok.parse::<f64>().ok().filter(|x| x.is_finite())?;
            Some(format!("{:x}", x.to_bits()))
        }
        Ask::Integer(max) => (digits(tok) && tok.len() <= max)
            .then(|| format!("{}", tok.parse::<u64>().unwrap_or(0))),
        Ask::Pair => {
            // what `slash_pair` reads, or `None` (then the caller reads
            // the field as a whole)
            let (a, b) = tok.split_once('/')?;
            let ok = digits(a) && digits(b) && a.len() < 8 && b.len() < 8;
            ok.then(|| {
                format!(
                    "{}/{}",
                    a.parse::<u64>().unwrap_or(0),
                    b.parse::<u64>().unwrap_or(0)
                )
            })
        }
        Ask::Field => Some(tok.to_string()),
    }
}

/// The cursor's answer for `ask` (`slash_pair` refusing leaves the field
/// to `field`, as the OBJ reader does).
fn read(c: &mut Cursor<'_>, ask: Ask) -> Option<String> {
    match ask {
        Ask::Float => c.float().map(|x| format!("{:x}", x.to_bits())),
        Ask::Integer(max) => c.integer(max).map(|i| format!("{i}")),
        Ask::Pair => c.slash_pair().map(|(a, b)| format!("{a}/{b}")),
        Ask::Field => Some(String::from_utf8_lossy(c.field()).into_owned()),
    }
}

/// A random field: a number, an integer, a corner or a bad field.
fn random_field(r: &mut Rng) -> String {
    match r.below(24) {
        0..=13 => random_token(r).replace(|c: char| c.is_ascii_whitespace(), ""),
        14..=16 => format!("{}", r.next() >> r.below(64)),
        17..=19 => format!(
            "{}/{}",
            r.next() >> (40 + r.below(24)),
            r.next() >> (40 + r.below(24))
        ),
        20..=22 => r
            .pick(&[
                "0.19999999995343387",
                "16.199999999953434",
                "-0.6999999999534339",
                "0.0",
                "1",
                "00000001",
                "1/1/1",
                "1//2",
                "#",
            ])
            .to_string(),
        _ => r
            .pick(&[
                "1.5.5", "-", "1e", "nan", "inf", "0x1", "x", "1\x0b2", "\u{a0}", "+1",
            ])
            .to_string(),
    }
}

/// The ask a field meets in the readers' layouts (one the model accepts,
/// if any), or now and then any.
fn random_ask(r: &mut Rng, tok: &str) -> Ask {
    let any = [
        Ask::Float,
        Ask::Integer(10),
        Ask::Integer(19),
        Ask::Integer(3),
        Ask::Pair,
        Ask::Field,
    ];
    if r.below(40) == 0 {
        return any[r.below(any.len())];
    }
    [Ask::Pair, Ask::Integer(10), Ask::Float]
        .into_iter()
        .find(|&ask| model(ask, tok).is_some())
        .unwrap_or(Ask::Float)
}

#[test]
fn fields_read_as_the_token_readers_do() {
    let mut r = Rng(0x9e37_79b9_7f4a_7c15);
    let seps = [
        " ", " ", " ", " ", "  ", "\t", " \t ", "\r", " \r ", "\x0c", "   ",
    ];
    let (mut read_ok, mut refused) = (0, 0);
    for _ in 0..100_000 {
        // the text: 1 to 4 lines of 0 to 17 fields
        let mut lines: Vec<Vec<String>> = Vec::new();
        let mut text = String::new();
        if r.below(4) == 0 {
            text.push_str(r.pick(&seps));
        }
        let nl = 1 + r.below(4);
        for l in 0..nl {
            let fields: Vec<String> = (0..r.below(18)).map(|_| random_field(&mut r)).collect();
            for (i, f) in fields.iter().enumerate() {
                if i > 0 {
                    text.push_str(r.pick(&seps));
                }
                text.push_str(f);
            }
            if r.below(4) == 0 {
                text.push_str(r.pick(&seps));
            }
            if l + 1 < nl || r.below(2) == 0 {
                text.push_str(r.pick(&["\n", "\n", "\r\n", " \n"]));
            }
            lines.push(fields);
        }
        // the model's fields, line by line (the text as the readers cut it)
        let model_lines: Vec<Vec<&str>> = text
            .split('\n')
            .map(|l| l.split_ascii_whitespace().collect())
            .collect();
        let mut c = Cursor::new(text.as_bytes());
        let mut whole = true;
        'lines: for fields in &model_lines {
            for &tok in fields {
                let ask = random_ask(&mut r, tok);
                let want = model(ask, tok);
                // whether the cursor stands at the field (not at blanks
                // before it), and the bytes from there on
                let (at_field, ahead) = (blanks(c.rest()) == 0, c.rest().len());
                match (read(&mut c, ask), want) {
                    (Some(got), Some(want)) => {
                        assert_eq!(got, want, "{ask:?} on {tok:?} in {text:?}");
                        read_ok += 1;
                    }
                    (None, want) if matches!(ask, Ask::Pair) => {
                        // refused only when it is no pair, blanks come
                        // first or it is too near the end; the OBJ reader
                        // then reads the field whole
                        let may = want.is_none() || !at_field || ahead < 16;
                        assert!(may, "{tok:?} in {text:?}");
                        assert_eq!(c.field(), tok.as_bytes(), "{text:?}");
                        refused += 1;
                    }
                    (None, None) => {
                        refused += 1;
                        whole = false;
                        break 'lines;
                    }
                    (got, want) => {
                        panic!("{ask:?} on {tok:?} in {text:?}: {got:?}, model {want:?}")
                    }
                }
            }
            // the line end: every field read
            assert!(c.end_line().is_some(), "line end in {text:?}");
        }
        // past the last line: nothing left
        assert!(!whole || c.rest().is_empty(), "{text:?}");
    }
    assert!(
        read_ok > 300_000 && refused > 50_000,
        "{read_ok} read, {refused} refused"
    );
}

/// How many blanks (whitespace but `\n`) begin `b`.
fn blanks(b: &[u8]) -> usize {
    b.iter()
        .take_while(|&&x| x.is_ascii_whitespace() && x != b'\n')
        .count()
}

#[test]
fn a_field_at_the_end_of_the_bytes_reads_whole() {
    for tok in ["0.19999999995343387", "7", "12/34", "1e5", "-0.5"] {
        for sep in ["", " ", "\t", "  "] {
            let text = format!("{sep}{tok}");
            for ask in [Ask::Float, Ask::Integer(19), Ask::Field] {
                let mut c = Cursor::new(text.as_bytes());
                let got = read(&mut c, ask);
                let want = model(ask, tok);
                assert_eq!(got, want, "{ask:?} on {text:?}");
                if got.is_some() {
                    assert!(c.rest().is_empty(), "{ask:?} on {text:?}");
                }
            }
        }
    }
}
