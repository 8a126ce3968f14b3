//! `vams.VamsError` and what raises it: every way a compile, a run or an analysis fails, with
//! the diagnostics' text as the message (file:line:col of each, as `vams` prints them).

use miette::Report;
use pyo3::create_exception;
use pyo3::exceptions::PyException;
use pyo3::prelude::*;
use vams::app::ac::NotLinearised;
use vams::app::compile::NotCompiled;
use vams::app::error::CliError;
use vams::app::load::InputError;
use vams::diagnostics::{Finding, Level};

use crate::diagnostic::diagnostics;

create_exception!(
    vams,
    VamsError,
    PyException,
    "A model that does not compile, a run or an analysis that fails. The message is the \
     diagnostics' text; `diagnostics` lists them as `vams.Diagnostic` objects and `result` \
     holds what a failed run computed before the error (or None)."
);

/// Why a call failed, before it becomes a `VamsError`.
#[derive(Debug)]
pub struct Failure {
    /// The located diagnostics.
    pub findings: Vec<Finding>,
    /// Diagnostics rendered already (the simulator's and the small-signal analysis's).
    pub rendered: String,
    /// The summary: what failed.
    pub summary: Report,
}

impl Failure {
    /// A failure with only a summary.
    pub fn summary(summary: impl Into<Report>) -> Failure {
        Failure {
            findings: Vec::new(),
            rendered: String::new(),
            summary: summary.into(),
        }
    }

    /// The `VamsError`: the message is every diagnostic, then the summary; the attributes
    /// `diagnostics` and `result` (`partial`).
    pub fn into_pyerr(self, py: Python<'_>, partial: Option<Py<PyAny>>) -> PyErr {
        let Failure {
            findings,
            rendered,
            summary,
        } = self;
        let mut message: String = findings.iter().map(Finding::render_plain).collect();
        message.push_str(&rendered);
        message.push_str(&Finding::unlocated(summary, Level::Error).render_plain());
        let error = VamsError::new_err(message);
        let attributes = || -> PyResult<()> {
            let value = error.value(py);
            value.setattr("diagnostics", diagnostics(py, &findings)?)?;
            value.setattr("result", partial)?;
            Ok(())
        };
        match attributes() {
            Ok(()) => error,
            Err(e) => e,
        }
    }
}

impl From<NotCompiled> for Failure {
    fn from(n: NotCompiled) -> Failure {
        Failure {
            findings: n.findings,
            rendered: String::new(),
            summary: n.error,
        }
    }
}

impl From<NotLinearised> for Failure {
    fn from(n: NotLinearised) -> Failure {
        Failure {
            findings: Vec::new(),
            rendered: n.diagnostics,
            summary: n.error.into(),
        }
    }
}

impl From<InputError> for Failure {
    fn from(e: InputError) -> Failure {
        Failure::summary(e)
    }
}

impl From<CliError> for Failure {
    fn from(e: CliError) -> Failure {
        Failure::summary(e)
    }
}

/// A `ValueError` for an argument that does not read.
pub fn bad_argument(message: impl Into<String>) -> PyErr {
    pyo3::exceptions::PyValueError::new_err(message.into())
}
