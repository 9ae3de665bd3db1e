//! The fast paths' float parser ([`crate::decimal`], used by
//! [`crate::scan::finite`] and [`crate::cursor::Cursor::float`])
//! against the standard library's `str::parse::<f64>`, the reference of the
//! sequential readers: over millions of random decimal strings (1–25
//! digits on either side of the point, signs, exponents, leading and
//! trailing zeros, `.5`, `5.`, `inf` / `nan` forms, mutations) and every
//! `f64` printed in several ways, the parser must give the same bits as
//! `str::parse` whenever it accepts, and must accept whenever `str::parse`
//! gives a finite value (so no file leaves the fast path because of it).

use crate::cursor::Cursor;
use crate::decimal::parse_field;
use crate::scan::finite;

/// Xorshift64: deterministic, no dependency.
pub(crate) struct Rng(pub(crate) u64);

impl Rng {
    pub(crate) fn next(&mut self) -> u64 {
        self.0 ^= self.0 << 13;
        self.0 ^= self.0 >> 7;
        self.0 ^= self.0 << 17;
        self.0
    }

    pub(crate) fn below(&mut self, n: usize) -> usize {
        (self.next() % n.max(1) as u64) as usize
    }

    pub(crate) fn pick<'a>(&mut self, items: &[&'a str]) -> &'a str {
        items[self.below(items.len())]
    }

    /// `n` decimal digits, often with runs of zeros or nines.
    fn digits(&mut self, n: usize, out: &mut String) {
        let style = self.below(4);
        for _ in 0..n {
            let d = match style {
                0 if self.below(3) > 0 => 0,
                1 if self.below(3) > 0 => 9,
                _ => self.below(10) as u8,
            };
            out.push(char::from(b'0' + d));
        }
    }
}

/// A random decimal string: `[sign] [int] [. [frac]] [e [sign] exp]`,
/// or one of the special forms, possibly mutated.
pub(crate) fn random_token(r: &mut Rng) -> String {
    let mut s = String::new();
    if r.below(40) == 0 {
        let special = [
            "inf", "INF", "Infinity", "infinity", "infinit", "nan", "NaN", "NAN", "nan(1)", "in",
            "", ".", "-", "+", "e", "e5", "-.", "+.e1", "1e", "1e+", "1e-", "1.e", "..1", "1..",
            "0x10", "1_0", " 1", "1 ", "١", "1e5.5", "--1", "+-1", "1f", "1d", "0.0.0",
        ];
        s.push_str(r.pick(&["", "+", "-"]));
        s.push_str(r.pick(&special));
        return s;
    }
    s.push_str(r.pick(&["", "", "", "-", "+"]));
    let int = r.below(26);
    let lead = if r.below(4) == 0 { r.below(6) } else { 0 };
    s.push_str(&"0".repeat(lead));
    r.digits(int, &mut s);
    if r.below(3) > 0 {
        s.push('.');
        let frac = r.below(26);
        r.digits(frac, &mut s);
        if r.below(4) == 0 {
            s.push_str(&"0".repeat(r.below(8)));
        }
    }
    if r.below(3) == 0 {
        s.push_str(r.pick(&["e", "E"]));
        s.push_str(r.pick(&["", "-", "+"]));
        let n = match r.below(10) {
            0 => 0,
            1 => 4 + r.below(20),
            _ => 1 + r.below(3),
        };
        r.digits(n, &mut s);
    }
    if r.below(20) == 0 && !s.is_empty() {
        let at = r.below(s.len() + 1);
        let c = r.pick(&["0", "9", ".", "e", "-", "+", "_", " ", "x", "n", "ü"]);
        if s.is_char_boundary(at) {
            s.insert_str(at, c);
        }
    }
    s
}

/// `finite(tok)` agrees with `str::parse` (see the module docs).
fn check(tok: &str) {
    let std = tok.parse::<f64>().ok().filter(|x| x.is_finite());
    let fast = finite(tok);
    assert_eq!(
        fast.map(f64::to_bits),
        std.map(f64::to_bits),
        "token {tok:?}: fast {fast:?}, std {std:?}"
    );
    // the cursor, parsing in place, decides as on the field alone, and
    // stops at its end whatever follows
    // (the long tail: every field has the bytes of the one-word paths)
    for tail in [
        "",
        " 1",
        "\t9e9",
        "\r\n5",
        "\n",
        " x",
        " 0.25 1.5 -2.75 1e3 4.125 8",
    ] {
        let text = format!("{tok}{tail}");
        let mut c = Cursor::new(text.as_bytes());
        let whole = !tok.is_empty() && !tok.contains(|c: char| c.is_ascii_whitespace());
        let got = c.float();
        if whole {
            assert_eq!(got.map(f64::to_bits), std.map(f64::to_bits), "{text:?}");
            if got.is_some() {
                // (one space after the field is read with it)
                let after = tail.strip_prefix(' ').unwrap_or(tail);
                assert_eq!(c.rest(), after.as_bytes(), "{text:?}");
            }
        } else if let Some(x) = got {
            // the first field of the line
            let line = text.split('\n').next().unwrap_or("");
            let field = line.split_ascii_whitespace().next().unwrap_or("");
            assert_eq!(
                Some(x.to_bits()),
                finite(field).map(f64::to_bits),
                "{text:?}"
            );
        }
    }
    // and the whole field, non-finite values included
    if !tok.is_empty() && !tok.contains(|c: char| c.is_ascii_whitespace()) {
        let mine = parse_field(tok.as_bytes());
        let s = tok.parse::<f64>().ok();
        let same = match (mine, s) {
            (Some((x, n)), Some(y)) => {
                n == tok.len() && (x.to_bits() == y.to_bits() || x.is_nan() && y.is_nan())
            }
            (None, None) => true,
            _ => false,
        };
        assert!(same, "token {tok:?}: parse_field {mine:?}, std {s:?}");
        // the same with bytes after it (the one-word paths read ahead)
        let ahead = format!("{tok}\t0.123456789012345678901234");
        let mine_ahead = parse_field(ahead.as_bytes());
        assert_eq!(
            mine_ahead.map(|(x, n)| (x.to_bits(), n)),
            mine.map(|(x, n)| (x.to_bits(), n)),
            "token {tok:?} read ahead"
        );
    }
}

#[test]
fn every_digit_count_parses_as_std_does() {
    // 0–25 digits either side of the point (the point at every place of
    // the first words, fields longer than 19 digits), with leading and
    // trailing zeros, signs, exponents, bad tails; no point
    for int in 0..=25 {
        for frac in 0..=25 {
            let digits: String = (0..int + frac)
                .map(|i| char::from(b'1' + (i * 7 % 9) as u8))
                .collect();
            let (a, b) = digits.split_at(int);
            for sign in ["", "-", "+"] {
                for exp in ["", "e5", "E-17", "e+300", "e-330", "e", "x"] {
                    check(&format!("{sign}{a}.{b}{exp}"));
                    check(&format!("{sign}0{a}.{b}0{exp}"));
                }
            }
            check(&format!("{a}{b}"));
        }
    }
}

#[test]
fn random_decimal_strings_parse_as_std_does() {
    let mut r = Rng(0x2545_f491_4f6c_dd1d);
    for _ in 0..3_000_000 {
        check(&random_token(&mut r));
    }
}

#[test]
fn every_exact_conversion_parses_as_std_does() {
    // up to 19 digits and exponents around the boundaries of the exact
    // conversions (2^53, 10^22, 19 digits)
    let mut r = Rng(0x1234_5678_9abc_def1);
    for _ in 0..2_000_000 {
        let digits = 1 + r.below(19) as u32;
        let m = r.next() % 10u64.pow(digits);
        let e = r.below(61) as i64 - 30;
        check(&format!("{m}e{e}"));
        let t = m.to_string();
        let point = r.below(t.len() + 1);
        check(&format!(
            "{}.{}E{}",
            &t[..point],
            &t[point..],
            -(r.below(25) as i64)
        ));
    }
}

#[test]
fn every_kind_of_printed_f64_parses_as_std_does() {
    let mut r = Rng(0x9e37_79b9_7f4a_7c15);
    for i in 0..400_000u64 {
        let x = match i % 4 {
            0 => f64::from_bits(r.next()),
            1 => (r.next() as f64) / (r.next() as f64),
            2 => f64::from_bits(r.next() >> 12), // subnormal
            _ => (r.below(2000) as f64 - 1000.0) / 40.0,
        };
        for tok in [
            format!("{x}"),
            format!("{x:e}"),
            format!("{x:.17}"),
            format!("{x:.25e}"),
            format!("{x:.3e}"),
            ryu::Buffer::new().format(x).to_string(),
        ] {
            check(&tok);
        }
    }
}

#[test]
fn long_mantissas_parse_as_std_does() {
    // the benchmark maps' shape ("0.19999999995343387"): 1–3 integer
    // digits, 12–20 fraction digits, often runs of 9s or 0s; then the
    // 19/20-digit limit with leading zeros, signs and exponents
    let mut r = Rng(0x0dd1_7e57_5eed_1234);
    for _ in 0..1_000_000 {
        let mut s = String::from(r.pick(&["", "", "-", "+"]));
        let int = 1 + r.below(3);
        r.digits(int, &mut s);
        s.push('.');
        s.push_str(&"0".repeat(if r.below(4) == 0 { r.below(6) } else { 0 }));
        let frac = 12 + r.below(9);
        r.digits(frac, &mut s);
        if r.below(4) == 0 {
            s.push_str(r.pick(&["e", "E"]));
            s.push_str(r.pick(&["", "-", "+"]));
            s.push_str(&(r.below(330)).to_string());
        }
        check(&s);
    }
}

#[test]
fn halfway_cases_parse_as_std_does() {
    // m·2^e with m odd of 54 bits lies halfway between two f64: written as
    // an integer (e ≥ 0) or as m·5^k · 10^-k (e = -k), then one unit of
    // the last digit below and above
    let mut r = Rng(0x4a1f_3a1f_0123_4567);
    for _ in 0..200_000 {
        let m = u128::from((r.next() >> 10) | 1 << 53 | 1);
        let (digits, exp) = match r.below(2) {
            0 => (m << r.below(12), 0),
            _ => {
                let k = r.below(6) as u32;
                (m * 5u128.pow(k), -(k as i64))
            }
        };
        for d in [digits - 1, digits, digits + 1] {
            check(&format!("{d}e{exp}"));
            let t = d.to_string();
            let point = r.below(t.len() + 1);
            let shift = (t.len() - point) as i64;
            check(&format!("{}.{}e{}", &t[..point], &t[point..], exp + shift));
        }
    }
}

#[test]
fn hard_cases_parse_as_std_does() {
    let cases = [
        "9007199254740993",
        "9007199254740992.5",
        "9007199254740993.0000000000000000001",
        "2.2250738585072011e-308",
        "2.2250738585072012e-308",
        "4.9406564584124654e-324",
        "2.4703282292062327e-324",
        "2.4703282292062328e-324",
        "1.7976931348623157e308",
        "1.7976931348623158e308",
        "1.7976931348623159e308",
        "0.1",
        "0.19999999995343387",
        "0.6999999999534339",
        "1e22",
        "1e23",
        "123456789012345678901234567890e-30",
        "0.000000000000000000000000000000000000000000000000001e51",
        "1e99999999999999999999",
        "0e99999999999999999999",
        "1e-99999999999999999999",
        "-0",
        "-0.0e5",
        "5.",
        ".5",
        "+.5e-0",
        "1e-342",
        "9999999999999999999e-362",
        "1e308",
        "9999999999999999999e289",
        "0.0000000000000000000000000000001",
        "1234567890123456789",
        "12345678901234567890",
        "0.1234567890123456789",
        "0.01234567890123456789",
        "00000000000000000000000000001.5",
        "1.5e0000",
        "1.5e00001",
        "-.0e-0",
        "7.",
        // the point at every place of the first word, and after it
        "1234567.8",
        "12345678.9",
        "1234567.",
        ".12345678",
        "0.1234567",
        "0.12345678",
        "0.123456789",
        "9999999.999999999999",
        "9999999.9999999999999",
        "0.99999999999999999999",
        "0.1999999999999999999",
        "1.2345678901234567890",
        "0.0000000000000000001",
        "0.00000000000000000001",
        "-0.0",
        "-0.",
        "0.",
        "1.e5",
        "1.5e",
        "1.5x",
        "1.5.5",
        "1.2345678/",
        "1.234567:",
        "1.23456789012345:",
        "1e-400",
        "1e309",
        "1.7976931348623157e308",
        "0.000000000000000000000000000000000000000000000000000000000001e-300",
    ];
    for tok in cases {
        check(tok);
    }
}
