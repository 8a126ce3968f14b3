//! Whole-or-nothing file writes: the content goes to a temporary file in the target's own
//! directory (so the final rename stays on one file system), which is renamed over the target
//! only when complete. A failed write never leaves a half-written file nor destroys the
//! previous one.

use std::fs::File;
use std::io::{self, BufWriter, Write};
use std::path::{Path, PathBuf};

/// A temporary name beside `path`, keeping its extension (plot backends choose the format by
/// it): `dir/.name.vams-tmp-<pid>.ext`.
pub fn temp_path(path: &Path) -> PathBuf {
    let stem = path
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = path
        .extension()
        .map(|e| format!(".{}", e.to_string_lossy()))
        .unwrap_or_default();
    path.with_file_name(format!(".{stem}.vams-tmp-{}{ext}", std::process::id()))
}

/// Moves a finished temporary file over `path`; removes it when that fails.
pub fn commit(temp: &Path, path: &Path) -> io::Result<()> {
    std::fs::rename(temp, path).inspect_err(|_| {
        let _ = std::fs::remove_file(temp);
    })
}

/// Writes `path` through `fill`, atomically.
pub fn write_atomically(
    path: &Path,
    fill: impl FnOnce(&mut BufWriter<File>) -> io::Result<()>,
) -> io::Result<()> {
    let temp = temp_path(path);
    let written = File::create(&temp).and_then(|file| {
        let mut out = BufWriter::new(file);
        fill(&mut out)?;
        out.flush()?;
        out.get_ref().sync_all()
    });
    match written {
        Ok(()) => commit(&temp, path),
        Err(e) => {
            let _ = std::fs::remove_file(&temp);
            Err(e)
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn failed_write_keeps_the_previous_file_and_leaves_no_temporary() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("out.csv");
        write_atomically(&path, |w| w.write_all(b"first\n")).unwrap();
        let failed = write_atomically(&path, |w| {
            w.write_all(b"partial")?;
            Err(io::Error::other("simulated failure"))
        });
        assert!(failed.is_err());
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "first\n");
        let names: Vec<_> = std::fs::read_dir(dir.path()).unwrap().collect();
        assert_eq!(names.len(), 1, "temporary left behind");
        write_atomically(&path, |w| w.write_all(b"second\n")).unwrap();
        assert_eq!(std::fs::read_to_string(&path).unwrap(), "second\n");
    }

    #[test]
    fn temporary_keeps_directory_and_extension() {
        let t = temp_path(Path::new("plots/run.svg"));
        assert_eq!(t.parent(), Some(Path::new("plots")));
        assert_eq!(t.extension().unwrap(), "svg");
        assert!(
            t.file_name()
                .unwrap()
                .to_string_lossy()
                .starts_with(".run.")
        );
    }

    #[test]
    fn missing_directory_is_an_error() {
        let dir = tempfile::tempdir().unwrap();
        let path = dir.path().join("no/such/dir/out.csv");
        assert!(write_atomically(&path, |w| w.write_all(b"x")).is_err());
        assert!(!path.exists());
    }
}
