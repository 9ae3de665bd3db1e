//! Output errors and atomic file writing.
//!
//! Every file writer of this crate goes through [`write_atomic`]: the bytes
//! go to a fresh temporary file in the target's directory, which is flushed,
//! synced and then renamed over the target. On any error the temporary file
//! is removed, so a failed write leaves the target untouched (absent or as it
//! was before).

use std::fmt;
use std::fs::{self, File, OpenOptions};
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// Why a file could not be written.
#[derive(Debug)]
pub enum OutputErrorKind {
    /// The extension does not name a format this writer supports.
    UnsupportedExtension {
        /// The extension found (without dot; empty if none).
        found: String,
        /// The supported extensions (without dot).
        allowed: &'static [&'static str],
    },
    /// The data to write breaks the format's rules (e.g. an index out of
    /// range, a non-finite coordinate); checked before anything is written.
    InvalidData(String),
    /// The operating system refused.
    Io(io::Error),
}

/// An error while writing `path`; displayed as one line `PATH: what`.
#[derive(Debug)]
pub struct OutputError {
    /// The file that was to be written.
    pub path: PathBuf,
    /// What went wrong.
    pub kind: OutputErrorKind,
}

impl OutputError {
    pub(crate) fn new(path: &Path, kind: OutputErrorKind) -> Self {
        OutputError {
            path: path.to_path_buf(),
            kind,
        }
    }
}

impl fmt::Display for OutputError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}: ", self.path.display())?;
        match &self.kind {
            OutputErrorKind::UnsupportedExtension { found, allowed } => {
                let list: Vec<String> = allowed.iter().map(|e| format!(".{e}")).collect();
                if found.is_empty() {
                    write!(
                        f,
                        "no file extension to choose the output format; use {}",
                        list.join(", ")
                    )
                } else {
                    write!(
                        f,
                        "unsupported output format `.{found}`; use {}",
                        list.join(", ")
                    )
                }
            }
            OutputErrorKind::InvalidData(m) => write!(f, "cannot write: {}", m.replace('\n', " ")),
            OutputErrorKind::Io(e) => {
                write!(f, "cannot write: {}", e.to_string().replace('\n', " "))
            }
        }
    }
}

impl std::error::Error for OutputError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match &self.kind {
            OutputErrorKind::Io(e) => Some(e),
            _ => None,
        }
    }
}

/// The lower-case extension of `path` if it is one of `allowed`.
pub(crate) fn extension(
    path: &Path,
    allowed: &'static [&'static str],
) -> Result<String, OutputError> {
    let found = path
        .extension()
        .and_then(|e| e.to_str())
        .unwrap_or("")
        .to_ascii_lowercase();
    if allowed.contains(&found.as_str()) {
        Ok(found)
    } else {
        Err(OutputError::new(
            path,
            OutputErrorKind::UnsupportedExtension { found, allowed },
        ))
    }
}

/// Writes `path` atomically with `body` (see the module docs).
pub(crate) fn write_atomic(
    path: &Path,
    body: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> Result<(), OutputError> {
    let err = |e: io::Error| OutputError::new(path, OutputErrorKind::Io(e));
    let (tmp, file) = create_temp(path).map_err(err)?;
    let mut w = BufWriter::new(file);
    let result = body(&mut w)
        .and_then(|()| w.into_inner().map_err(|e| e.into_error()))
        .and_then(|file| file.sync_all())
        .and_then(|()| fs::rename(&tmp, path));
    if let Err(e) = result {
        let _ = fs::remove_file(&tmp);
        return Err(err(e));
    }
    Ok(())
}

/// A new file `.NAME.PID.K.tmp` beside `path` (never an existing one).
fn create_temp(path: &Path) -> io::Result<(PathBuf, File)> {
    let name = path
        .file_name()
        .ok_or_else(|| io::Error::new(io::ErrorKind::InvalidInput, "the path has no file name"))?;
    let dir = match path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d.to_path_buf(),
        _ => PathBuf::from("."),
    };
    let mut last = None;
    for k in 0..100 {
        let mut tmp_name = std::ffi::OsString::from(".");
        tmp_name.push(name);
        tmp_name.push(format!(".{}.{k}.tmp", std::process::id()));
        let tmp = dir.join(tmp_name);
        match OpenOptions::new().write(true).create_new(true).open(&tmp) {
            Ok(f) => return Ok((tmp, f)),
            Err(e) if e.kind() == io::ErrorKind::AlreadyExists => last = Some(e),
            Err(e) => return Err(e),
        }
    }
    Err(last.unwrap_or_else(|| io::Error::other("no free temporary file name")))
}

/// Writes a text file atomically (any extension).
pub fn write_text(path: &Path, text: &str) -> Result<(), OutputError> {
    write_atomic(path, |w| w.write_all(text.as_bytes()))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `name` in a directory of its own (tests run in parallel); the
    /// directory is removed when the returned path is dropped.
    pub(crate) fn scratch(name: &str) -> crate::test_scratch::ScratchFile {
        crate::test_scratch::ScratchFile::new(name)
    }

    fn leftovers(dir: &Path) -> usize {
        fs::read_dir(dir)
            .unwrap()
            .filter(|e| {
                e.as_ref()
                    .unwrap()
                    .file_name()
                    .to_string_lossy()
                    .ends_with(".tmp")
            })
            .count()
    }

    #[test]
    fn failure_keeps_the_old_file_and_removes_the_temp() {
        let p = scratch("atomic.txt");
        write_text(&p, "old").unwrap();
        let e = write_atomic(&p, |w| {
            w.write_all(b"half")?;
            Err(io::Error::other("disk on fire"))
        })
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            format!("{}: cannot write: disk on fire", p.display())
        );
        assert_eq!(fs::read_to_string(&p).unwrap(), "old");
        assert_eq!(leftovers(p.parent().unwrap()), 0);
        write_text(&p, "new").unwrap();
        assert_eq!(fs::read_to_string(&p).unwrap(), "new");
    }

    #[test]
    fn rename_over_a_directory_fails_cleanly() {
        let p = scratch("is_a_dir.obj");
        fs::create_dir_all(&p).unwrap();
        assert!(matches!(
            write_text(&p, "x").unwrap_err().kind,
            OutputErrorKind::Io(_)
        ));
        assert_eq!(leftovers(p.parent().unwrap()), 0);
        let missing = p.join("no/such/dir.obj");
        assert!(write_text(&missing, "x").is_err());
    }

    #[test]
    fn extensions_are_checked() {
        let allowed: &'static [&'static str] = &["obj", "vtk"];
        assert_eq!(extension(Path::new("a/B.OBJ"), allowed).unwrap(), "obj");
        let e = extension(Path::new("out.stl"), allowed).unwrap_err();
        assert_eq!(
            e.to_string(),
            "out.stl: unsupported output format `.stl`; use .obj, .vtk"
        );
        let e = extension(Path::new("out"), allowed).unwrap_err();
        assert_eq!(
            e.to_string(),
            "out: no file extension to choose the output format; use .obj, .vtk"
        );
    }
}
