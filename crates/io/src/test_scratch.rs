//! Scratch directories for the unit tests, removed when dropped (even when
//! the test fails), so that test runs leave nothing in the temp folder.

use std::path::{Path, PathBuf};

/// `$TMP/dualex-io-<pid>-<name>`, created empty, removed on drop.
pub(crate) struct ScratchDir(PathBuf);

impl ScratchDir {
    /// A fresh directory for one test (tests run in parallel: one name each).
    pub(crate) fn new(name: &str) -> Self {
        let dir = std::env::temp_dir().join(format!("dualex-io-{}-{name}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("create scratch dir");
        ScratchDir(dir)
    }

    /// The directory.
    pub(crate) fn path(&self) -> &Path {
        &self.0
    }

    /// A path inside the directory.
    pub(crate) fn join(&self, file: &str) -> PathBuf {
        self.0.join(file)
    }
}

impl Drop for ScratchDir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// A file path `$TMP/dualex-io-<pid>-<name>/<name>` used as a `&Path`;
/// its directory is removed on drop.
pub(crate) struct ScratchFile {
    file: PathBuf,
    _dir: ScratchDir,
}

impl ScratchFile {
    /// A fresh directory named after `name`, and `name` inside it.
    pub(crate) fn new(name: &str) -> Self {
        let dir = ScratchDir::new(name);
        ScratchFile {
            file: dir.join(name),
            _dir: dir,
        }
    }
}

impl std::ops::Deref for ScratchFile {
    type Target = Path;
    fn deref(&self) -> &Path {
        &self.file
    }
}

impl AsRef<Path> for ScratchFile {
    fn as_ref(&self) -> &Path {
        &self.file
    }
}
