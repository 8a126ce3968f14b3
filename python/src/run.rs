//! `vams.run(...)`: a transient run as `vams run` makes it, the waveforms in memory as NumPy
//! arrays.
//!
//! An assertion of severity failure ends the run but is not an exception: the result comes
//! back with `failed` true, `outcome` "failed" and the failure among `reports` (a testbench
//! that fails is an answer to study). A simulation error (no convergence, a bad option)
//! raises `VamsError`, whose `result` holds the waveforms up to the error (or None when it
//! came before time 0); Ctrl-C raises KeyboardInterrupt.

use std::time::Instant;

use numpy::PyArray1;
use pyo3::exceptions::{PyKeyError, PyKeyboardInterrupt};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use vams::app::compile::unknown_name_help;
use vams::app::error::CliError;
use vams::app::render::{format_report, render_sim_error, severity_name};
use vams::app::stop::stop_time;
use vams::diagnostics::Finding;
use vams::kernel::{self, Outcome, SimError, SimOptions, SimStats, simulate_keeping};
use vams::source::SourceMap;
use vams::waveform::{ColumnKind, Waveforms};

use crate::design::{DesignSpec, time_of};
use crate::diagnostic::{Diagnostic, diagnostics};
use crate::error::{Failure, bad_argument};
use crate::frame::{Columns, data_frame};
use crate::interrupt::on_keyboard_interrupt;

/// A report or assertion of the run: `time` (s), `severity` ("note", "warning", "error",
/// "failure"), `message`, `process`, where (`file`, `line`, `column`; "" and 0 for none) and
/// `text`, the line `vams run` prints.
#[pyclass(frozen, get_all, module = "vams")]
pub struct Report {
    time: f64,
    severity: &'static str,
    message: String,
    process: String,
    file: String,
    line: usize,
    column: usize,
    text: String,
}

impl Report {
    fn new(r: &kernel::Report, sources: &SourceMap) -> Report {
        let (file, line, column) = match (r.span.file.0 as usize) < sources.len() {
            true => {
                let (line, column) = sources.line_col(r.span);
                (sources.file(r.span.file).name.clone(), line, column)
            }
            false => (String::new(), 0, 0),
        };
        Report {
            time: r.time,
            severity: severity_name(r.severity),
            message: r.message.clone(),
            process: r.process.clone(),
            file,
            line,
            column,
            text: format_report(r, sources),
        }
    }
}

#[pymethods]
impl Report {
    fn __repr__(&self) -> String {
        format!("<Report {}>", self.text)
    }

    fn __str__(&self) -> String {
        self.text.clone()
    }
}

/// The result of a run: `time` and each recorded quantity and signal (`result["dut.vout"]`)
/// as float64 NumPy arrays (signals as numbers: booleans and enumerations by position),
/// `columns` (the names), `units`, `reports`, `stats`, `outcome` ("finished", "stopped" by
/// the design, "failed" by an assertion of severity failure), `failed`, `end_time`, `top`,
/// `stop`, and `warnings` (of elaboration).
#[pyclass(frozen, module = "vams")]
pub struct RunResult {
    #[pyo3(get)]
    top: String,
    #[pyo3(get)]
    stop: f64,
    #[pyo3(get)]
    outcome: &'static str,
    #[pyo3(get)]
    end_time: f64,
    time: Py<PyArray1<f64>>,
    columns: Columns<f64>,
    units: Vec<Option<String>>,
    reports: Vec<Py<Report>>,
    stats: SimStats,
    wall_time: f64,
    warnings: Vec<Py<Diagnostic>>,
}

#[pymethods]
impl RunResult {
    #[getter]
    fn time(&self, py: Python<'_>) -> Py<PyArray1<f64>> {
        self.time.clone_ref(py)
    }

    #[getter]
    fn columns(&self) -> Vec<String> {
        self.columns.names.clone()
    }

    /// Each column's unit symbol (None for signals and quantities without one).
    #[getter]
    fn units<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (name, unit) in self.columns.names.iter().zip(&self.units) {
            dict.set_item(name, unit)?;
        }
        Ok(dict)
    }

    #[getter]
    fn reports(&self, py: Python<'_>) -> Vec<Py<Report>> {
        self.reports.iter().map(|r| r.clone_ref(py)).collect()
    }

    #[getter]
    fn warnings(&self, py: Python<'_>) -> Vec<Py<Diagnostic>> {
        self.warnings.iter().map(|w| w.clone_ref(py)).collect()
    }

    /// The solver's and the kernel's counters (`accepted_steps`, `newton_iterations`, ...,
    /// as `vams run --stats` lists them) and `wall_time` in seconds.
    #[getter]
    fn stats<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyDict>> {
        let dict = PyDict::new(py);
        for (name, n) in self.stats.named() {
            dict.set_item(name.to_ascii_lowercase().replace(' ', "_"), n)?;
        }
        dict.set_item("wall_time", self.wall_time)?;
        Ok(dict)
    }

    #[getter]
    fn failed(&self) -> bool {
        self.outcome == "failed"
    }

    fn __getitem__(&self, py: Python<'_>, name: &str) -> PyResult<Py<PyArray1<f64>>> {
        self.columns.get(py, name).ok_or_else(|| {
            let names = self.columns.names.iter().map(String::as_str);
            let help = unknown_name_help(names, &name.trim().to_ascii_lowercase());
            PyKeyError::new_err(format!(
                "no column `{name}` was recorded; {}",
                help.unwrap_or_default()
            ))
        })
    }

    fn __contains__(&self, name: &str) -> bool {
        let wanted = name.trim().to_ascii_lowercase();
        self.columns.names.contains(&wanted)
    }

    fn __len__(&self) -> usize {
        self.columns.names.len()
    }

    /// A pandas DataFrame: a `time` column, then one column per recorded name.
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        data_frame(py, ("time", &self.time), |d| self.columns.add_to(py, d))
    }

    fn __repr__(&self, py: Python<'_>) -> String {
        let rows = numpy::PyUntypedArrayMethods::len(self.time.bind(py));
        format!(
            "<RunResult {}: {} to {} s, {} rows x {} columns>",
            self.top,
            self.outcome,
            self.end_time,
            rows,
            self.columns.names.len()
        )
    }
}

/// What a run gives before it becomes Python objects (built with the GIL released).
struct Ran {
    top: String,
    stop: f64,
    waveforms: Waveforms,
    reports: Vec<Report>,
    outcome: Option<Outcome>,
    stats: SimStats,
    wall_time: f64,
    warnings: Vec<Finding>,
}

impl Ran {
    fn into_result(self, py: Python<'_>) -> PyResult<RunResult> {
        let (outcome, end_time) = match self.outcome {
            Some(Outcome::Finished) => ("finished", self.stop),
            Some(Outcome::Stopped { time }) => ("stopped", time),
            Some(Outcome::Failed { time }) => ("failed", time),
            // An error: the run ended at the last row.
            None => ("error", self.waveforms.times.last().copied().unwrap_or(0.0)),
        };
        let units = (self.waveforms.columns.iter())
            .map(|c| match &c.kind {
                ColumnKind::Quantity { unit } => unit.clone(),
                ColumnKind::Signal { .. } => None,
            })
            .collect();
        let columns = (self.waveforms.columns.into_iter())
            .map(|c| (c.name, c.values))
            .collect();
        Ok(RunResult {
            top: self.top,
            stop: self.stop,
            outcome,
            end_time,
            time: PyArray1::from_vec(py, self.waveforms.times).unbind(),
            columns: Columns::new(py, columns),
            units,
            reports: (self.reports.into_iter())
                .map(|r| Py::new(py, r))
                .collect::<PyResult<_>>()?,
            stats: self.stats,
            wall_time: self.wall_time,
            warnings: diagnostics(py, &self.warnings)?,
        })
    }
}

/// A run that stopped with an error: why, and what it computed before.
struct Stopped {
    failure: Failure,
    interrupted: bool,
    partial: Option<Ran>,
}

/// The solver options of `vams run`.
struct RunOptions {
    stop: Option<f64>,
    reltol: f64,
    abstol: Option<f64>,
    max_step: Option<f64>,
    max_order: usize,
    probes: Vec<String>,
    keep_unknowns: bool,
}

/// run(paths, top=None, stop=None, *, generics=None, libraries=None, reltol=1e-3,
///     abstol=None, max_step=None, max_order=5, probes=None, keep_unknowns=False) -> RunResult
///
/// Simulates the top entity `top` (default: the only entity nothing instantiates) of the
/// sources under `paths` from its quiescent point to `stop` (seconds, or text such as
/// "6 s"; default: the `-- vams: stop` comment of the file declaring the top), as `vams run`.
/// `generics` overrides generics of the top ({"r": 8.0, "t_step": "10 ms"}, or an
/// instance's by path: {"dut.u_motor.r": 4.0}). `probes` limits the recorded names
/// (default: every quantity and explicit signal). The GIL is released during the run.
#[pyfunction]
#[pyo3(signature = (paths, top=None, stop=None, *, generics=None, libraries=None, reltol=1e-3,
                    abstol=None, max_step=None, max_order=5, probes=None, keep_unknowns=false))]
#[allow(clippy::too_many_arguments)] // Python's keyword arguments, as `vams run`'s options.
pub fn run(
    py: Python<'_>,
    paths: &Bound<'_, PyAny>,
    top: Option<String>,
    stop: Option<&Bound<'_, PyAny>>,
    generics: Option<&Bound<'_, PyDict>>,
    libraries: Option<&Bound<'_, PyDict>>,
    reltol: f64,
    abstol: Option<f64>,
    max_step: Option<&Bound<'_, PyAny>>,
    max_order: usize,
    probes: Option<Vec<String>>,
    keep_unknowns: bool,
) -> PyResult<RunResult> {
    let spec = DesignSpec::new(paths, top, generics, libraries)?;
    let options = RunOptions {
        stop: stop.map(time_of).transpose()?,
        reltol,
        abstol,
        max_step: max_step.map(time_of).transpose()?,
        max_order,
        probes: (probes.unwrap_or_default().iter())
            .map(|p| p.trim().to_ascii_lowercase())
            .collect(),
        keep_unknowns,
    };
    if !(1..=5).contains(&max_order) {
        return Err(bad_argument("max_order is 1 (backward Euler) to 5"));
    }
    match py.detach(|| simulate(&spec, options)) {
        Ok(ran) => ran.into_result(py),
        Err(stopped) if stopped.interrupted => Err(PyKeyboardInterrupt::new_err(
            "the run was interrupted (its waveforms so far are lost)",
        )),
        Err(stopped) => {
            let partial = match stopped.partial {
                Some(ran) => Some(Py::new(py, ran.into_result(py)?)?.into_any()),
                None => None,
            };
            Err(stopped.failure.into_pyerr(py, partial))
        }
    }
}

/// Compiles and runs (without the GIL).
fn simulate(spec: &DesignSpec, run: RunOptions) -> Result<Ran, Box<Stopped>> {
    let started = Instant::now();
    let stopped = |failure: Failure| {
        Box::new(Stopped {
            failure,
            interrupted: false,
            partial: None,
        })
    };
    let (compiled, warnings) = spec.compile().map_err(stopped)?;
    let (loaded, design) = (&compiled.loaded, &compiled.design);
    let stop = stop_time(loaded, &design.top, run.stop).map_err(|n| stopped(n.into()))?;
    let (cancel, hook) = on_keyboard_interrupt();
    let options = SimOptions {
        stop,
        reltol: run.reltol,
        abstol: run.abstol,
        max_step: run.max_step,
        max_order: run.max_order,
        probes: run.probes,
        progress: Some(hook),
        keep_unknowns: run.keep_unknowns,
        cancel: Some(cancel),
    };
    let mut reports = Vec::new();
    let result = simulate_keeping(design, &options, &mut |r| {
        reports.push(Report::new(r, &loaded.sources));
    });
    let mut ran = Ran {
        top: design.top.clone(),
        stop,
        waveforms: Waveforms::default(),
        reports,
        outcome: None,
        stats: SimStats::default(),
        wall_time: 0.0,
        warnings,
    };
    match result {
        Ok(end) => {
            ran.waveforms = end.waveforms;
            ran.outcome = Some(end.outcome);
            ran.stats = end.stats;
            ran.wall_time = started.elapsed().as_secs_f64();
            Ok(ran)
        }
        Err(failed) => {
            let interrupted = matches!(failed.error, SimError::Interrupted { .. });
            let failure = Failure {
                findings: Vec::new(),
                rendered: render_sim_error(&failed.error, &loaded.sources),
                summary: CliError::Simulation {
                    top: design.top.clone(),
                }
                .into(),
            };
            ran.wall_time = started.elapsed().as_secs_f64();
            let partial = failed.partial.map(|waveforms| Ran { waveforms, ..ran });
            Err(Box::new(Stopped {
                failure,
                interrupted,
                partial,
            }))
        }
    }
}
