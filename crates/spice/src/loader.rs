//! Where included files come from.
//!
//! Takes a path; gives the file's text. [`Loader`] is what the reader asks for `.include` and
//! `.lib` files, so it never touches the file system itself: the CLI passes [`FsLoader`],
//! tests an in-memory [`MemLoader`]. Paths arrive already resolved against the including
//! file's folder.

use std::io;
use std::path::{Path, PathBuf};

use rustc_hash::FxHashMap;

/// A source of included files.
pub trait Loader {
    /// The text of the file at `path` (invalid UTF-8 replaced, as the deck's own text is).
    fn load(&mut self, path: &Path) -> Result<String, io::Error>;
}

/// Reads the file system.
#[derive(Debug, Default, Clone, Copy)]
pub struct FsLoader;

impl Loader for FsLoader {
    fn load(&mut self, path: &Path) -> Result<String, io::Error> {
        let bytes = std::fs::read(path)?;
        Ok(String::from_utf8_lossy(&bytes).into_owned())
    }
}

/// Files held in memory, by path; any other path is not found.
#[derive(Debug, Default, Clone)]
pub struct MemLoader {
    files: FxHashMap<PathBuf, String>,
}

impl MemLoader {
    pub fn new() -> MemLoader {
        MemLoader::default()
    }

    /// Adds (or replaces) a file; returns `self` for chaining.
    pub fn with(mut self, path: impl Into<PathBuf>, text: impl Into<String>) -> MemLoader {
        self.files.insert(path.into(), text.into());
        self
    }

    pub fn insert(&mut self, path: impl Into<PathBuf>, text: impl Into<String>) {
        self.files.insert(path.into(), text.into());
    }
}

impl Loader for MemLoader {
    fn load(&mut self, path: &Path) -> Result<String, io::Error> {
        self.files
            .get(path)
            .cloned()
            .ok_or_else(|| io::Error::new(io::ErrorKind::NotFound, "no such file"))
    }
}
