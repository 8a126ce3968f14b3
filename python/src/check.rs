//! `vams.check(paths)`: every diagnostic of `vams check` as `vams.Diagnostic` objects.

use pyo3::prelude::*;
use pyo3::types::PyDict;
use vams::app::check::diagnose;

use crate::design::DesignSpec;
use crate::diagnostic::{Diagnostic, diagnostics};
use crate::error::Failure;

/// check(paths, libraries=None) -> list[Diagnostic]
///
/// Checks the sources under `paths` (a path or a list; directories are searched for .vhd,
/// .vhdl and .ams files) as `vams check` does: syntax, analysis, elaboration of every top
/// candidate and its analog system. Returns every error and warning, each once; an empty
/// list for clean sources. Raises VamsError only when a path cannot be read.
#[pyfunction]
#[pyo3(signature = (paths, libraries=None))]
pub fn check(
    py: Python<'_>,
    paths: &Bound<'_, PyAny>,
    libraries: Option<&Bound<'_, PyDict>>,
) -> PyResult<Vec<Py<Diagnostic>>> {
    let spec = DesignSpec::new(paths, None, None, libraries)?;
    let checked = py
        .detach(|| diagnose(&spec.paths, &spec.libraries, None))
        .map_err(|e| Failure::from(e).into_pyerr(py, None))?;
    diagnostics(py, &checked.findings)
}
