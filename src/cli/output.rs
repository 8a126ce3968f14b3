//! Where a command's text goes: a file written atomically, or standard output.

use std::io::Write;

use crate::app::error::CliError;
use crate::output::atomic::write_atomically;

/// Writes `text` to `path` atomically, or to standard output when there is none; the
/// path written, if any.
pub fn write_text(path: Option<&std::path::Path>, text: &str) -> Result<Option<String>, CliError> {
    let write_error = |path: &std::path::Path, e: &dyn std::fmt::Display| CliError::Write {
        path: path.display().to_string(),
        reason: e.to_string(),
    };
    match path {
        Some(path) => {
            write_atomically(path, |w| w.write_all(text.as_bytes()))
                .map_err(|e| write_error(path, &e))?;
            Ok(Some(path.display().to_string()))
        }
        None => {
            let mut stdout = std::io::stdout().lock();
            stdout
                .write_all(text.as_bytes())
                .and_then(|()| stdout.flush())
                .map_err(|e| write_error(std::path::Path::new("<stdout>"), &e))?;
            Ok(None)
        }
    }
}
