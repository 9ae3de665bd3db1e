//! A byte cursor over whitespace-separated numeric fields, for the fast
//! paths: numbers are parsed where they lie, without first cutting the
//! text into lines and tokens, and without checking it is UTF-8.
//!
//! Input: raw bytes. Output: numbers, or `None` as soon as a field is not
//! what is asked. Invariant: a field is a maximal run of non-whitespace
//! bytes (ASCII whitespace, as `split_ascii_whitespace`), and a field is
//! accepted exactly when the token-based fast paths would accept the same
//! token ([`crate::scan::finite`], digits-only indices). Every accepted
//! field is ASCII, so a file whose every non-blank byte lies in an accepted
//! field is ASCII text without a NUL byte: the fast paths need no separate
//! text check (a bad byte makes them refuse, and the sequential reader
//! reports it).

/// A position in `bytes`.
pub(crate) struct Cursor<'a> {
    bytes: &'a [u8],
    pos: usize,
}

/// ASCII whitespace other than the line end (`\r` included: `str::lines`
/// drops it only at the end of a line, and `split_ascii_whitespace` drops
/// it anywhere).
#[inline]
fn blank(b: u8) -> bool {
    b.is_ascii_whitespace() && b != b'\n'
}

impl<'a> Cursor<'a> {
    /// A cursor at the start of `bytes`.
    pub(crate) fn new(bytes: &'a [u8]) -> Self {
        Cursor { bytes, pos: 0 }
    }

    /// Bytes not yet consumed.
    pub(crate) fn rest(&self) -> &'a [u8] {
        self.bytes.get(self.pos..).unwrap_or_default()
    }

    /// Skips ASCII whitespace, line ends included.
    #[inline]
    pub(crate) fn skip_space(&mut self) {
        while self
            .bytes
            .get(self.pos)
            .is_some_and(u8::is_ascii_whitespace)
        {
            self.pos += 1;
        }
    }

    /// Skips ASCII whitespace up to the line end.
    #[inline]
    fn skip_blank(&mut self) {
        let mut pos = self.pos;
        while self.bytes.get(pos).is_some_and(|&b| blank(b)) {
            pos += 1;
        }
        self.pos = pos;
    }

    /// Whether the cursor stands at the end of a field.
    #[inline]
    fn at_field_end(&self) -> bool {
        self.bytes.get(self.pos).is_none_or(u8::is_ascii_whitespace)
    }

    /// The next field on this line (empty at the line end); one space
    /// after it is consumed too.
    #[inline]
    pub(crate) fn field(&mut self) -> &'a [u8] {
        self.skip_blank();
        let start = self.pos;
        while self
            .bytes
            .get(self.pos)
            .is_some_and(|b| !b.is_ascii_whitespace())
        {
            self.pos += 1;
        }
        let field = self.bytes.get(start..self.pos).unwrap_or_default();
        self.skip_space_once();
        field
    }

    /// Consumes `prefix` if the bytes at the cursor start with it.
    #[inline(always)]
    pub(crate) fn eat(&mut self, prefix: &[u8]) -> bool {
        let found = self.rest().starts_with(prefix);
        if found {
            self.pos += prefix.len();
        }
        found
    }

    /// Consumes one space if the cursor stands at one.
    #[inline(always)]
    fn skip_space_once(&mut self) {
        self.pos += usize::from(self.bytes.get(self.pos) == Some(&b' '));
    }

    /// Consumes the rest of the line and its `\n`, whatever they hold.
    #[inline]
    pub(crate) fn skip_line(&mut self) {
        let rest = self.rest();
        self.pos += rest
            .iter()
            .position(|&b| b == b'\n')
            .map_or(rest.len(), |i| i + 1);
    }

    /// The next field on this line as a finite float (the same value and
    /// decision as [`crate::scan::finite`] on the field; `finite_field_spaced`
    /// reads the field whole, up to whitespace or the end), and one space
    /// after it. Inlined: the callers' loops keep the parser's constants in
    /// registers (fewer instructions per field, BENCHMARKS.md).
    ///
    /// The field is first read where the cursor stands, without a look for
    /// blanks: a field that starts with a blank (or the line end) is
    /// refused there, and only then are the blanks skipped
    /// ([`float_after_blanks`]); a field that does not start with
    /// one is read the same either way.
    #[inline(always)]
    pub(crate) fn float(&mut self) -> Option<f64> {
        let (x, n) = match crate::decimal::finite_field_spaced(self.bytes.get(self.pos..)?) {
            Some(found) => found,
            None => float_after_blanks(self.bytes, self.pos)?,
        };
        self.pos += n;
        Some(x)
    }

    /// The next field on this line as a decimal integer of at most
    /// `max_digits` digits (digits only, no sign), and one space after it.
    /// A field of 1 to 7 digits with 8 bytes left, where the cursor
    /// stands, is read in one word; anything else (blanks first, longer
    /// fields, the end of the bytes) by [`integer_after_blanks`].
    #[inline]
    pub(crate) fn integer(&mut self, max_digits: usize) -> Option<u64> {
        // one bounds check: `pos + 8` cannot wrap (`pos ≤ len`)
        let word = self.bytes.get(self.pos..self.pos + 8);
        if let Some(w) = word.and_then(<[u8]>::first_chunk) {
            let w = u64::from_le_bytes(*w);
            let mut i = 0;
            let n = crate::decimal::part_word(w, &mut i);
            if (1..8).contains(&n) && n <= max_digits {
                if let Some(gap) = gap_after((w >> (8 * n)) as u8) {
                    self.pos += n + gap;
                    return Some(i);
                }
            }
        }
        let (i, n) = integer_after_blanks(self.bytes, self.pos, max_digits)?;
        self.pos += n;
        Some(i)
    }

    /// The field where the cursor stands, when it is `digits/digits`, 1
    /// to 7 digits each, read in two words (the OBJ corner `v/vt`), and one
    /// space after it; `None`, the cursor unmoved, when it is anything else
    /// (blanks first included) or fewer than 16 bytes are left.
    #[inline]
    pub(crate) fn slash_pair(&mut self) -> Option<(u64, u64)> {
        let b: &[u8; 16] = self.bytes.get(self.pos..)?.first_chunk()?;
        let word = |at: usize| crate::decimal::word_at(b, at);
        let (mut v, mut vt) = (0, 0);
        let w = word(0);
        let k = crate::decimal::part_word(w, &mut v);
        if !(1..8).contains(&k) || (w >> (8 * k)) as u8 != b'/' {
            return None;
        }
        let w = word(k + 1);
        let l = crate::decimal::part_word(w, &mut vt);
        if !(1..8).contains(&l) {
            return None;
        }
        let gap = gap_after((w >> (8 * l)) as u8)?;
        self.pos += k + 1 + l + gap;
        Some((v, vt))
    }

    /// Consumes the rest of the line, which must be blank, and its `\n`
    /// (or the end of the bytes).
    #[inline]
    pub(crate) fn end_line(&mut self) -> Option<()> {
        // the common case first: the `\n` right where the cursor stands
        if self.eat(b"\n") {
            return Some(());
        }
        self.skip_blank();
        match self.bytes.get(self.pos) {
            None => Some(()),
            Some(b'\n') => {
                self.pos += 1;
                Some(())
            }
            Some(_) => None,
        }
    }
}

/// The bytes a word-read field's end takes when `byte` follows its
/// digits: 1 for a space (consumed with the field), 0 for other
/// whitespace (left for the line's end), `None` for anything else (the
/// field goes on: not one of the fast reads').
#[inline(always)]
fn gap_after(byte: u8) -> Option<usize> {
    match byte {
        b' ' => Some(1),
        c if c.is_ascii_whitespace() => Some(0),
        _ => None,
    }
}

/// [`Cursor::float`] at `pos` of `bytes` after the blanks there (out of
/// line, the cursor's fields passed by value so that the callers keep
/// them in registers: more than one blank, a tab, or a bad field): the
/// value and the bytes to move on by (blanks, field, one space).
#[cold]
#[inline(never)]
fn float_after_blanks(bytes: &[u8], pos: usize) -> Option<(f64, usize)> {
    let mut c = Cursor { bytes, pos };
    c.skip_blank();
    let (x, n) = crate::decimal::finite_field_spaced(c.rest())?;
    Some((x, c.pos + n - pos))
}

/// [`Cursor::integer`] at `pos` of `bytes` after the blanks there, any
/// length (out of line, as [`float_after_blanks`]): the value and the
/// bytes to move on by (blanks, field, one space).
#[cold]
#[inline(never)]
fn integer_after_blanks(bytes: &[u8], pos: usize, max_digits: usize) -> Option<(u64, usize)> {
    let mut c = Cursor { bytes, pos };
    c.skip_blank();
    let (i, n) = leading_digits(c.rest());
    c.pos += n;
    if n == 0 || n > max_digits || !c.at_field_end() {
        return None;
    }
    c.skip_space_once();
    Some((i, c.pos - pos))
}

/// The value of the decimal digits at the start of `b` (wrapping past 19
/// digits: the callers refuse more) and how many there are.
#[inline]
pub(crate) fn leading_digits(b: &[u8]) -> (u64, usize) {
    let mut i = 0u64;
    let mut n = 0;
    while let Some(&d) = b.get(n).filter(|d| d.is_ascii_digit()) {
        i = i.wrapping_mul(10).wrapping_add(u64::from(d - b'0'));
        n += 1;
    }
    (i, n)
}

/// Bytes per block of the counting loops: a multiple of 32, so that a
/// block is whole vector steps with no tail loop of its own, and below
/// 256, so that a count per byte lane cannot overflow.
const BLOCK: usize = 224;

/// The number of lines of `bytes` as `str::lines` counts them: one per
/// `\n`, plus a last line without one.
pub(crate) fn count_lines(bytes: &[u8]) -> usize {
    // whole blocks summed in u8: the loop vectorizes and unrolls
    let blocks = bytes.chunks_exact(BLOCK);
    let tail = blocks.remainder();
    let newlines: usize = blocks
        .map(|c| usize::from(c.iter().fold(0u8, |n, &b| n + u8::from(b == b'\n'))))
        .sum();
    let tail_newlines = tail.iter().filter(|&&b| b == b'\n').count();
    newlines + tail_newlines + usize::from(bytes.last().is_some_and(|&b| b != b'\n'))
}

/// [`count_lines`] of `bytes` if they are text (valid UTF-8 without a NUL
/// byte), in one pass: per block of [`BLOCK`] bytes the newlines are
/// counted and the bytes or-ed and min-ed (the loop vectorizes); only
/// bytes with a non-ASCII one are checked as UTF-8 again
/// (`str::from_utf8`).
pub(crate) fn text_lines(bytes: &[u8]) -> Option<usize> {
    let (mut newlines, mut any, mut least) = (0usize, 0u8, u8::MAX);
    let blocks = bytes.chunks_exact(BLOCK);
    let tail = blocks.remainder();
    for c in blocks.chain(std::iter::once(tail)) {
        let (mut n, mut or, mut min) = (0u8, 0u8, u8::MAX);
        for &b in c {
            n += u8::from(b == b'\n');
            or |= b;
            min = min.min(b);
        }
        newlines += usize::from(n);
        any |= or;
        least = least.min(min);
    }
    if least == 0 || (!any.is_ascii() && std::str::from_utf8(bytes).is_err()) {
        return None;
    }
    Some(newlines + usize::from(bytes.last().is_some_and(|&b| b != b'\n')))
}

/// `bytes` cut after a `\n` every ~`chunk` bytes (the last piece may end
/// without one).
pub(crate) fn line_chunks(bytes: &[u8], chunk: usize) -> Vec<&[u8]> {
    let chunk = chunk.max(1);
    let mut out = Vec::with_capacity(bytes.len() / chunk + 1);
    let mut rest = bytes;
    while rest.len() > chunk {
        let cut = rest[chunk..]
            .iter()
            .position(|&b| b == b'\n')
            .map_or(rest.len(), |i| chunk + i + 1);
        let (head, tail) = rest.split_at(cut);
        out.push(head);
        rest = tail;
    }
    if !rest.is_empty() {
        out.push(rest);
    }
    out
}
