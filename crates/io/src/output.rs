//! Output errors and atomic file writing.
//!
//! Every file writer of this crate goes through [`write_atomic`]: the bytes
//! go to a fresh temporary file in the target's directory, which is flushed
//! and then renamed over the target. On any error the temporary file is
//! removed, so a failed write leaves the target untouched (absent or as it
//! was before), and no reader ever sees a half-written file.
//!
//! The temporary file is not `fsync`ed before the rename (as compilers and
//! `cp` write): the rename-on-success guards against a failed or
//! killed process, not against a power cut or a kernel crash in the seconds
//! after the write (ext4 starts writing a file renamed over another at once,
//! `auto_da_alloc`). The sync cost half of the write on an idle disk and up
//! to 95 % of it beside another process writing (the journal commit waits
//! for that process's data): BENCHMARKS.md, "Writing" of issue 25.
//!
//! Only regular files are replaced that way. A symbolic link is written
//! through: its target file is replaced (atomically, beside the target), the
//! link stays; a link whose target does not exist yet has it created
//! there (read from the link, relative to the link's folder; chains of
//! such links followed), as `cat > LINK` would. Devices, pipes and anything under `/dev/` or `/proc/`
//! (`/dev/stdout`, `/dev/null`) are opened and written directly.
//!
//! [`check_writable`] tells before any work whether a path can be written:
//! its folder exists and accepts a new file (probed by creating and
//! removing a temporary file), it is not a folder.

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
    let found = crate::lower_extension(path);
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
    let target = match target(path) {
        Target::Direct => return write_direct(path, body).map_err(err),
        Target::Replace(t) => t,
    };
    let (tmp, file) = create_temp(&target).map_err(err)?;
    let mut w = BufWriter::new(file);
    let result = body(&mut w)
        .and_then(|()| w.into_inner().map_err(|e| e.into_error()))
        .and_then(|file| {
            drop(file);
            fs::rename(&tmp, &target)
        });
    if let Err(e) = result {
        let _ = fs::remove_file(&tmp);
        return Err(err(e));
    }
    Ok(())
}

/// How a path is written.
enum Target {
    /// Opened and written in place (devices, pipes, `/dev/…`, `/proc/…`).
    Direct,
    /// A regular file (or none yet) replaced through a temporary file.
    Replace(PathBuf),
}

/// Most symbolic links followed to a target that does not exist yet (as
/// the kernel's limit, `ELOOP`).
const MAX_LINKS: usize = 40;

/// Where the bytes for `path` go (module docs).
fn target(path: &Path) -> Target {
    target_within(path, MAX_LINKS)
}

/// [`target`], following at most `links` dangling symbolic links.
fn target_within(path: &Path, links: usize) -> Target {
    if path.starts_with("/dev") || path.starts_with("/proc") {
        return Target::Direct;
    }
    let Ok(meta) = fs::symlink_metadata(path) else {
        return Target::Replace(path.to_path_buf());
    };
    if meta.file_type().is_symlink() {
        return match (fs::metadata(path), fs::canonicalize(path)) {
            (Ok(m), Ok(real)) if m.is_file() => Target::Replace(real),
            (Err(e), _) if e.kind() == io::ErrorKind::NotFound && links > 0 => {
                dangling(path, links)
            }
            _ => Target::Direct,
        };
    }
    if meta.is_file() || meta.is_dir() {
        // a folder fails at the rename, naming the path
        Target::Replace(path.to_path_buf())
    } else {
        Target::Direct
    }
}

/// A link whose target does not exist yet: the target (read from the
/// link, relative to the link's folder), created as `cat > LINK` would.
fn dangling(link: &Path, links: usize) -> Target {
    let Ok(to) = fs::read_link(link) else {
        return Target::Direct;
    };
    let to = match link.parent() {
        Some(dir) if to.is_relative() => dir.join(to),
        _ => to,
    };
    target_within(&to, links - 1)
}

fn write_direct(
    path: &Path,
    body: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> io::Result<()> {
    let file = OpenOptions::new()
        .write(true)
        .create(true)
        .truncate(true)
        .open(path)?;
    let mut w = BufWriter::new(file);
    body(&mut w)?;
    w.flush()
}

/// Whether `path` can be written, checked before any work (module docs):
/// the folder exists and takes a new file, and `path` is not a folder.
pub fn check_writable(path: &Path) -> Result<(), OutputError> {
    let err = |e: io::Error| OutputError::new(path, OutputErrorKind::Io(e));
    let target = match target(path) {
        Target::Direct => {
            OpenOptions::new().write(true).open(path).map_err(err)?;
            return Ok(());
        }
        Target::Replace(t) => t,
    };
    if target.is_dir() {
        return Err(err(io::Error::new(
            io::ErrorKind::IsADirectory,
            "is a directory",
        )));
    }
    let (tmp, file) = create_temp(&target).map_err(|e| match e.kind() {
        io::ErrorKind::NotFound => err(io::Error::new(
            io::ErrorKind::NotFound,
            "the folder does not exist",
        )),
        _ => err(e),
    })?;
    drop(file);
    fs::remove_file(&tmp).map_err(err)
}

/// Whether `path` has one of the `allowed` extensions (lower-cased), and
/// can be written ([`check_writable`]).
pub fn check_output(path: &Path, allowed: &'static [&'static str]) -> Result<(), OutputError> {
    extension(path, allowed)?;
    check_writable(path)
}

/// Writes raw bytes (a PNG, …) like every other writer (module docs).
pub fn write_bytes(path: &Path, bytes: &[u8]) -> Result<(), OutputError> {
    write_atomic(path, |w| w.write_all(bytes))
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

    #[cfg(unix)]
    #[test]
    fn symlinks_and_devices_are_written_through() {
        use std::os::unix::fs::FileTypeExt;
        let p = scratch("real.txt");
        write_text(&p, "old").unwrap();
        let link = p.with_file_name("link.txt");
        let _ = fs::remove_file(&link);
        std::os::unix::fs::symlink(&p, &link).unwrap();
        write_text(&link, "new").unwrap();
        assert!(fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(fs::read_to_string(&p).unwrap(), "new");
        write_text(Path::new("/dev/null"), "x").unwrap();
        assert!(fs::metadata("/dev/null")
            .unwrap()
            .file_type()
            .is_char_device());
        assert_eq!(leftovers(p.parent().unwrap()), 0);
    }

    #[cfg(unix)]
    #[test]
    fn dangling_symlinks_create_their_targets() {
        let p = scratch("made.txt");
        let link = p.with_file_name("link.txt");
        std::os::unix::fs::symlink("made.txt", &link).unwrap();
        check_writable(&link).unwrap();
        assert!(!p.exists(), "the check writes nothing");
        write_text(&link, "new").unwrap();
        assert_eq!(fs::read_to_string(&p).unwrap(), "new");
        assert!(fs::symlink_metadata(&link)
            .unwrap()
            .file_type()
            .is_symlink());
        assert_eq!(leftovers(p.parent().unwrap()), 0);
    }

    #[test]
    fn writability_is_checked_up_front() {
        let p = scratch("probe.obj");
        check_output(&p, &["obj"]).unwrap();
        assert!(!p.exists());
        assert_eq!(leftovers(p.parent().unwrap()), 0);
        let e = check_writable(&p.with_file_name("nodir/x.obj")).unwrap_err();
        assert!(
            e.to_string()
                .ends_with("nodir/x.obj: cannot write: the folder does not exist"),
            "{e}"
        );
        assert!(check_writable(p.parent().unwrap()).is_err());
        assert!(check_output(&p.with_extension("stl"), &["obj"]).is_err());
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
