//! Shared helpers of the text readers: the "is this text?" check, line
//! numbers of byte offsets, a whitespace token stream that knows its line,
//! and number parsing with errors that quote the offending token.
//!
//! Input: raw bytes. Output: `&str` views into them. Nothing here allocates
//! in proportion to a count read from a file.

use dualex_map::error::{Format, FormatError, NotTextReason, Subject, SyntaxError, Token};
use dualex_map::{InputError, InputErrorKind};

/// Checks that `bytes` is text (no NUL byte, valid UTF-8) and returns it as
/// `&str`; the error names the line of the first bad byte and says
/// "not a text {format} file".
pub(crate) fn as_text(bytes: &[u8], format: Format) -> Result<&str, InputError> {
    let not_text = |pos: usize, reason| {
        let reason = Some(reason);
        InputError::at_line(line_of(bytes, pos), FormatError::NotText { format, reason })
    };
    if let Some(pos) = bytes.iter().position(|&b| b == 0) {
        return Err(not_text(pos, NotTextReason::NulByte));
    }
    std::str::from_utf8(bytes).map_err(|e| not_text(e.valid_up_to(), NotTextReason::InvalidUtf8))
}

/// 1-based line number of byte offset `pos`.
pub(crate) fn line_of(bytes: &[u8], pos: usize) -> usize {
    let head = bytes.get(..pos).unwrap_or(bytes);
    head.iter().filter(|&&b| b == b'\n').count() + 1
}

/// A finite float, or `None` (the fast paths, which only need to know):
/// the value and decision of `str::parse::<f64>` ([`crate::decimal`]).
#[inline]
pub(crate) fn finite(tok: &str) -> Option<f64> {
    let b = tok.as_bytes();
    crate::decimal::finite_field(b)
        .filter(|&(_, n)| n == b.len())
        .map(|(x, _)| x)
}

/// Parses a finite float; `what` names the value in the error ("vertex
/// coordinate"). Non-finite values are reported separately.
pub(crate) fn parse_finite(tok: &str, what: Subject) -> Result<f64, InputErrorKind> {
    match tok.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err(InputErrorKind::NonFinite {
            what,
            token: Some(Token::new(tok)),
        }),
        Err(_) => Err(SyntaxError::NotANumber {
            what: Some(what),
            token: Token::new(tok),
        }
        .into()),
    }
}

/// A stream of whitespace-separated tokens that tracks the line number.
pub(crate) struct Tokens<'a> {
    text: &'a str,
    pos: usize,
    line: usize,
    last: usize,
}

impl<'a> Tokens<'a> {
    /// Tokens of `text`, whose first line is line `first_line`.
    pub(crate) fn new(text: &'a str, first_line: usize) -> Self {
        Tokens {
            text,
            pos: 0,
            line: first_line,
            last: first_line,
        }
    }

    /// The line of the last token returned (the first line before any):
    /// where "the file ends early" is reported.
    pub(crate) fn last_line(&self) -> usize {
        self.last
    }

    /// Bytes not yet consumed.
    pub(crate) fn remaining(&self) -> usize {
        self.text.len().saturating_sub(self.pos)
    }

    /// The next token and its line.
    pub(crate) fn next_token(&mut self) -> Option<(&'a str, usize)> {
        let bytes = self.text.as_bytes();
        while let Some(&b) = bytes.get(self.pos) {
            if !b.is_ascii_whitespace() {
                break;
            }
            if b == b'\n' {
                self.line += 1;
            }
            self.pos += 1;
        }
        let start = self.pos;
        while bytes
            .get(self.pos)
            .is_some_and(|b| !b.is_ascii_whitespace())
        {
            self.pos += 1;
        }
        // ASCII whitespace never splits a UTF-8 sequence, so `get` succeeds.
        let tok = self.text.get(start..self.pos).filter(|t| !t.is_empty())?;
        self.last = self.line;
        Some((tok, self.line))
    }
}

/// Whether `count` records of at least `min_bytes` bytes each fit in
/// `remaining` bytes (`slack` extra bytes allowed, e.g. a missing final
/// separator). Never overflows.
pub(crate) fn fits(count: u64, min_bytes: u64, remaining: usize, slack: u64) -> bool {
    let need = (count as u128) * (min_bytes as u128);
    need <= remaining as u128 + slack as u128
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn text_check_names_the_line_of_the_bad_byte() {
        let e = as_text(b"v 1 2 3\nv 1\0 2 3\n", Format::Obj).unwrap_err();
        assert_eq!(e.to_string(), "line 2: not a text OBJ file (NUL byte)");
        let e = as_text(b"a\nb\nc\xff\n", Format::Obj).unwrap_err();
        assert_eq!(e.to_string(), "line 3: not a text OBJ file (invalid UTF-8)");
        assert_eq!(as_text(b"ok\n", Format::Obj).unwrap(), "ok\n");
    }

    #[test]
    fn tokens_track_lines() {
        let mut t = Tokens::new("  a b\r\n\n c\n", 1);
        assert_eq!(t.next_token(), Some(("a", 1)));
        assert_eq!(t.next_token(), Some(("b", 1)));
        assert_eq!(t.next_token(), Some(("c", 3)));
        assert_eq!(t.next_token(), None);
        assert_eq!(t.last_line(), 3);
        assert_eq!(t.remaining(), 0);
    }

    #[test]
    fn numbers_and_quotes() {
        let parse = |t: &str| parse_finite(t, Subject::Value).map_err(|e| e.to_string());
        assert_eq!(parse("1e-3"), Ok(1e-3));
        assert_eq!(parse(".5"), Ok(0.5));
        assert_eq!(parse("nan"), Err("value is not finite (`nan`)".into()));
        assert_eq!(parse("1,5"), Err("value `1,5` is not a number".into()));
        let long = Token::new(&"9".repeat(30)).to_string();
        assert_eq!(long, format!("`{}…`", "9".repeat(20)));
        assert!(fits(3, 2, 5, 1));
        assert!(!fits(3, 2, 4, 1));
        assert!(!fits(u64::MAX, u64::MAX, usize::MAX, 1));
    }
}
