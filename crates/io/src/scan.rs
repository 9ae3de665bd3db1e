//! Shared helpers of the text readers: the "is this text?" check, line
//! numbers of byte offsets, a whitespace token stream that knows its line,
//! and number parsing with messages that quote the offending token.
//!
//! Input: raw bytes. Output: `&str` views into them. Nothing here allocates
//! in proportion to a count read from a file.

use dualex_map::InputError;

/// Checks that `bytes` is text (no NUL byte, valid UTF-8) and returns it as
/// `&str`; the error names the line of the first bad byte and says
/// "not a text {kind} file".
pub(crate) fn as_text<'a>(bytes: &'a [u8], kind: &str) -> Result<&'a str, InputError> {
    if let Some(pos) = bytes.iter().position(|&b| b == 0) {
        return Err(InputError::at_line(
            line_of(bytes, pos),
            format!("not a text {kind} file (NUL byte)"),
        ));
    }
    std::str::from_utf8(bytes).map_err(|e| {
        InputError::at_line(
            line_of(bytes, e.valid_up_to()),
            format!("not a text {kind} file (invalid UTF-8)"),
        )
    })
}

/// 1-based line number of byte offset `pos`.
pub(crate) fn line_of(bytes: &[u8], pos: usize) -> usize {
    let head = bytes.get(..pos).unwrap_or(bytes);
    head.iter().filter(|&&b| b == b'\n').count() + 1
}

/// A token quoted for a message: at most 24 characters, in backquotes.
pub(crate) fn quote(tok: &str) -> String {
    if tok.chars().count() <= 24 {
        format!("`{tok}`")
    } else {
        let head: String = tok.chars().take(20).collect();
        format!("`{head}…`")
    }
}

/// Parses a finite-or-not float; `what` names the value in the message
/// ("vertex coordinate"). Non-finite values are reported separately.
pub(crate) fn parse_finite(tok: &str, what: &str) -> Result<f64, String> {
    match tok.parse::<f64>() {
        Ok(x) if x.is_finite() => Ok(x),
        Ok(_) => Err(format!("{what} is not finite ({})", quote(tok))),
        Err(_) => Err(format!("{what} {} is not a number", quote(tok))),
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
        let e = as_text(b"v 1 2 3\nv 1\0 2 3\n", "OBJ").unwrap_err();
        assert_eq!(e.to_string(), "line 2: not a text OBJ file (NUL byte)");
        let e = as_text(b"a\nb\nc\xff\n", "OBJ").unwrap_err();
        assert_eq!(e.to_string(), "line 3: not a text OBJ file (invalid UTF-8)");
        assert_eq!(as_text(b"ok\n", "OBJ").unwrap(), "ok\n");
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
        assert_eq!(parse_finite("1e-3", "x"), Ok(1e-3));
        assert_eq!(parse_finite(".5", "x"), Ok(0.5));
        assert_eq!(
            parse_finite("nan", "x"),
            Err("x is not finite (`nan`)".into())
        );
        assert_eq!(
            parse_finite("1,5", "x"),
            Err("x `1,5` is not a number".into())
        );
        assert_eq!(quote(&"9".repeat(30)), format!("`{}…`", "9".repeat(20)));
        assert!(fits(3, 2, 5, 1));
        assert!(!fits(3, 2, 4, 1));
        assert!(!fits(u64::MAX, u64::MAX, usize::MAX, 1));
    }
}
