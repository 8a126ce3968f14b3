//! `--plot DIR`: per capture, each matched column measured with the fitted simulation over
//! it, and the residual (simulated less measured) in the panel below.

use std::path::{Path, PathBuf};

use crate::fit::{Fitted, Series};
use crate::output::plot::{Panel, Trace, plot_panels};

use super::error::FitCliError;
use super::experiment::file_name;

/// Draws every experiment's picture into `dir` (`EXT` is `svg` or `png`); returns the files.
pub fn plots(
    dir: &Path,
    ext: &str,
    f: &Fitted,
    series: &[Series],
    captures: &[String],
) -> Result<Vec<PathBuf>, FitCliError> {
    std::fs::create_dir_all(dir).map_err(|e| FitCliError::Write {
        path: dir.to_path_buf(),
        what: e.to_string(),
    })?;
    let mut written = Vec::new();
    for (e, capture) in captures.iter().enumerate() {
        let mut panels = Vec::new();
        for (s, r) in series
            .iter()
            .zip(&f.series)
            .filter(|(s, _)| s.experiment == e)
        {
            let measured: Vec<(f64, f64)> = s
                .time
                .iter()
                .copied()
                .zip(s.measured.iter().copied())
                .collect();
            let fitted: Vec<(f64, f64)> = s
                .time
                .iter()
                .copied()
                .zip(r.simulated.iter().copied())
                .collect();
            let residual: Vec<(f64, f64)> = s
                .time
                .iter()
                .zip(r.simulated.iter().zip(&s.measured))
                .map(|(t, (v, m))| (*t, v - m))
                .collect();
            panels.push(Panel::new(
                s.simulated.clone(),
                vec![
                    Trace::analog(format!("measured {}", s.label), "", measured),
                    Trace::analog(format!("fitted {}", s.simulated), "", fitted),
                ],
            ));
            panels.push(Panel::new(
                "residual",
                vec![Trace::analog(
                    format!("{} fitted - measured", s.simulated),
                    "",
                    residual,
                )],
            ));
        }
        let stem = Path::new(&file_name(Path::new(capture)))
            .file_stem()
            .map_or_else(
                || format!("capture{e}"),
                |s| s.to_string_lossy().into_owned(),
            );
        let path = dir.join(format!("{stem}.{ext}"));
        plot_panels(&path, &format!("vams fit: {capture}"), &panels).map_err(|err| {
            FitCliError::Write {
                path: path.clone(),
                what: err.to_string(),
            }
        })?;
        written.push(path);
    }
    Ok(written)
}
