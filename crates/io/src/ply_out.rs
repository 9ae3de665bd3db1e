//! A minimal PLY record writer shared by the quad-mesh and tri-map writers.
//!
//! The caller writes the header lines (without `ply`, `format` and
//! `end_header`, added here), then each record's values in header order and
//! [`PlyWriter::end_record`]. Lists have a `uchar` length; indices are
//! `int`; reals are `double` (exact round trip). Ascii reals use Rust's
//! shortest round-trip form.

use crate::PlyFormat;
use std::io::{self, Write};

/// Writes PLY values in one of the three encodings.
pub(crate) struct PlyWriter<'w, W: Write> {
    w: &'w mut W,
    format: PlyFormat,
    first: bool,
}

impl<'w, W: Write> PlyWriter<'w, W> {
    pub(crate) fn new(w: &'w mut W, format: PlyFormat) -> Self {
        PlyWriter {
            w,
            format,
            first: true,
        }
    }

    /// `ply`, the format line, `lines`, `end_header`.
    pub(crate) fn header(&mut self, lines: &[&str]) -> io::Result<()> {
        let f = match self.format {
            PlyFormat::Ascii => "ascii",
            PlyFormat::BinaryLittleEndian => "binary_little_endian",
            PlyFormat::BinaryBigEndian => "binary_big_endian",
        };
        writeln!(self.w, "ply\nformat {f} 1.0\ncomment written by dualex")?;
        for l in lines {
            writeln!(self.w, "{l}")?;
        }
        writeln!(self.w, "end_header")
    }

    fn sep(&mut self) -> io::Result<()> {
        if !self.first {
            self.w.write_all(b" ")?;
        }
        self.first = false;
        Ok(())
    }

    /// Real values as `double`.
    pub(crate) fn doubles(&mut self, xs: &[f64]) -> io::Result<()> {
        for &x in xs {
            match self.format {
                PlyFormat::Ascii => {
                    self.sep()?;
                    write!(self.w, "{x:?}")?;
                }
                PlyFormat::BinaryLittleEndian => self.w.write_all(&x.to_le_bytes())?,
                PlyFormat::BinaryBigEndian => self.w.write_all(&x.to_be_bytes())?,
            }
        }
        Ok(())
    }

    /// A list with a `uchar` length and `int` items.
    pub(crate) fn index_list(&mut self, items: &[u32]) -> io::Result<()> {
        let n = u8::try_from(items.len())
            .map_err(|_| io::Error::other("bug: PLY list longer than 255 items"))?;
        self.uchar(n)?;
        for &v in items {
            let v = i32::try_from(v).map_err(|_| {
                io::Error::other(format!("vertex index {v} does not fit a PLY int"))
            })?;
            match self.format {
                PlyFormat::Ascii => {
                    self.sep()?;
                    write!(self.w, "{v}")?;
                }
                PlyFormat::BinaryLittleEndian => self.w.write_all(&v.to_le_bytes())?,
                PlyFormat::BinaryBigEndian => self.w.write_all(&v.to_be_bytes())?,
            }
        }
        Ok(())
    }

    /// A list with a `uchar` length and `double` items.
    pub(crate) fn double_list(&mut self, items: &[f64]) -> io::Result<()> {
        let n = u8::try_from(items.len())
            .map_err(|_| io::Error::other("bug: PLY list longer than 255 items"))?;
        self.uchar(n)?;
        self.doubles(items)
    }

    fn uchar(&mut self, n: u8) -> io::Result<()> {
        match self.format {
            PlyFormat::Ascii => {
                self.sep()?;
                write!(self.w, "{n}")
            }
            _ => self.w.write_all(&[n]),
        }
    }

    /// Ends a record (a newline in ascii).
    pub(crate) fn end_record(&mut self) -> io::Result<()> {
        self.first = true;
        if self.format == PlyFormat::Ascii {
            self.w.write_all(b"\n")?;
        }
        Ok(())
    }
}
