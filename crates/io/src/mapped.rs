//! The map readers' input file, mapped into memory instead of copied into
//! a `Vec`.
//!
//! Input: a path. Output: its bytes, as a read-only mapping of a regular,
//! non-empty file, or else read by `std::fs::read` (pipes, empty files, any
//! mapping failure: then also the error, as before). Why: copying a 96 MB
//! file into fresh memory costs a page fault per 4 KiB page on one thread;
//! a mapping of the page cache faults around 16 pages at a time, and the
//! faults fall in the parallel parse (BENCHMARKS.md, "Reading, second
//! pass"). Invariant: the bytes are the file's; a file truncated by another
//! process while it is mapped ends the process with SIGBUS where a read
//! would have seen a shorter file — the price of the mapping.

use crate::read_bytes;
use dualex_map::InputError;
use std::path::Path;

/// A file's bytes, mapped or read.
pub(crate) enum Input {
    /// A read-only mapping of the whole file.
    Mapped(memmap2::Mmap),
    /// The file read into memory.
    Read(Vec<u8>),
}

impl std::ops::Deref for Input {
    type Target = [u8];

    fn deref(&self) -> &[u8] {
        match self {
            Input::Mapped(m) => m,
            Input::Read(v) => v,
        }
    }
}

/// The bytes of `path`, mapped when it is a regular non-empty file.
pub(crate) fn map_or_read(path: &Path) -> Result<Input, InputError> {
    match map(path) {
        Some(m) => Ok(Input::Mapped(m)),
        None => read_bytes(path).map(Input::Read),
    }
}

#[allow(unsafe_code)]
fn map(path: &Path) -> Option<memmap2::Mmap> {
    let file = std::fs::File::open(path).ok()?;
    let meta = file.metadata().ok()?;
    if !meta.is_file() || meta.len() == 0 {
        return None;
    }
    // SAFETY: the mapping is read-only and lives as long as the returned
    // value; the bytes only change if another process writes the file
    // meanwhile (see the module docs).
    unsafe { memmap2::Mmap::map(&file) }.ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::test_scratch::ScratchDir;

    #[test]
    fn mapped_or_read_bytes_and_errors_are_those_of_a_read() {
        let dir = ScratchDir::new("mapped");
        let (full, empty) = (dir.join("a.obj"), dir.join("e.obj"));
        std::fs::write(&full, b"v 1 2 3\n").unwrap();
        std::fs::write(&empty, b"").unwrap();
        let a = map_or_read(&full).unwrap();
        assert!(matches!(a, Input::Mapped(_)));
        assert_eq!(&*a, b"v 1 2 3\n");
        let e = map_or_read(&empty).unwrap();
        assert!(matches!(e, Input::Read(_)) && e.is_empty());
        for missing in [dir.join("none.obj"), dir.path().to_path_buf()] {
            let got = map_or_read(&missing).err().map(|e| e.to_string());
            let want = read_bytes(&missing).err().map(|e| e.to_string());
            assert!(got.is_some());
            assert_eq!(got, want);
        }
    }
}
