//! `vams.Diagnostic`: one diagnostic of `vams check` (or of a failed compile) as an object.

use pyo3::prelude::*;
use vams::diagnostics::Finding;

/// A diagnostic: where (`file`, `line` and `column` from 1; `""` and 0 for none), how serious
/// (`severity`: "error" or "warning"), what (`code`, `message`, `label`, `help`), and `text`,
/// the rendered diagnostic as `vams check` prints it.
#[pyclass(frozen, get_all, module = "vams")]
pub struct Diagnostic {
    file: String,
    line: usize,
    column: usize,
    severity: &'static str,
    code: Option<String>,
    message: String,
    label: Option<String>,
    help: Option<String>,
    text: String,
}

impl From<&Finding> for Diagnostic {
    fn from(f: &Finding) -> Diagnostic {
        Diagnostic {
            file: f.file.clone(),
            line: f.line,
            column: f.column,
            severity: f.level.name(),
            code: f.code.clone(),
            message: f.message.clone(),
            label: f.label.clone(),
            help: f.help.clone(),
            text: f.render_plain(),
        }
    }
}

#[pymethods]
impl Diagnostic {
    fn __repr__(&self) -> String {
        format!(
            "<Diagnostic {} {}:{}:{}: {}>",
            self.severity, self.file, self.line, self.column, self.message
        )
    }

    fn __str__(&self) -> String {
        self.text.clone()
    }
}

/// Each finding as a `Diagnostic` object.
pub fn diagnostics(py: Python<'_>, findings: &[Finding]) -> PyResult<Vec<Py<Diagnostic>>> {
    findings
        .iter()
        .map(|f| Py::new(py, Diagnostic::from(f)))
        .collect()
}
