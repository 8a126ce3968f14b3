//! `vams.sweep(...)`: design-space runs as `vams sweep SPEC.toml` makes them (the same
//! function), then its result table read back as columns.

use std::path::PathBuf;
use std::time::Duration;

use numpy::PyArray1;
use pyo3::IntoPyObjectExt;
use pyo3::exceptions::{PyKeyError, PyKeyboardInterrupt};
use pyo3::prelude::*;
use vams::app::study::table::read_table;
use vams::app::notes::Notes;
use vams::app::study::{StudyOptions, StudyError, StudyOutcome, run_study};
use vams::kernel::Cancel;

use crate::error::{Failure, bad_argument};
use crate::frame::data_frame;

/// The result table of a sweep (`DIR/results.csv`): `dir` (the output folder, with the
/// table and the plots), `summary` (the text `vams sweep` prints at the end), `columns`
/// (the table's header in order), each column by name (`result["settle"]`: float64 for the
/// run number, numeric parameters and the metrics, a metric that could not be evaluated
/// NaN; a list of str for `case`, `pass`, `status`, `message` and literal parameters),
/// `len(result)` (the runs), `to_pandas()`.
#[pyclass(frozen, module = "vams")]
pub struct SweepResult {
    #[pyo3(get)]
    dir: PathBuf,
    #[pyo3(get)]
    summary: String,
    names: Vec<String>,
    /// A float64 array or a list of str per column.
    values: Vec<Py<PyAny>>,
    rows: usize,
}

#[pymethods]
impl SweepResult {
    #[getter]
    fn columns(&self) -> Vec<String> {
        self.names.clone()
    }

    fn __len__(&self) -> usize {
        self.rows
    }

    /// The column `name` (exactly as in the header, else case-insensitively).
    fn __getitem__(&self, py: Python<'_>, name: &str) -> PyResult<Py<PyAny>> {
        let k = (self.names.iter().position(|n| n == name))
            .or_else(|| (self.names.iter()).position(|n| n.eq_ignore_ascii_case(name.trim())));
        match k {
            Some(k) => Ok(self.values[k].clone_ref(py)),
            None => Err(PyKeyError::new_err(format!(
                "`{name}` is not a column of the result table"
            ))),
        }
    }

    fn __repr__(&self) -> String {
        format!(
            "<vams.SweepResult: {} runs, {} columns in {}>",
            self.rows,
            self.names.len(),
            self.dir.display()
        )
    }

    /// A pandas DataFrame of the table, its columns in order.
    fn to_pandas<'py>(&self, py: Python<'py>) -> PyResult<Bound<'py, PyAny>> {
        let run = self.values[0]
            .bind(py)
            .cast::<PyArray1<f64>>()?
            .clone()
            .unbind();
        data_frame(py, (&self.names[0], &run), |d| {
            for (name, column) in self.names.iter().zip(&self.values).skip(1) {
                d.set_item(name, column.clone_ref(py))?;
            }
            Ok(())
        })
    }
}

/// sweep(spec, out=None, *, jobs=None, resume=False, overwrite=False) -> SweepResult
///
/// Runs the design-space sweep of the TOML file `spec` as `vams sweep SPEC [--out DIR]
/// [--jobs N] [--resume] [--overwrite]`: the table, plots and summary go to `out` (default:
/// `SPEC-NAME.sweep` in the current folder), `jobs` runs at once (default: one per core).
/// The progress and summary are printed to the process's stderr as the CLI prints them (not
/// to a notebook's output); the summary is also `result.summary`. A bad spec or design
/// raises VamsError; Ctrl-C stops the sweep and raises KeyboardInterrupt, the finished runs
/// kept in the table for `resume=True`.
#[pyfunction]
#[pyo3(signature = (spec, out=None, *, jobs=None, resume=false, overwrite=false))]
pub fn sweep(
    py: Python<'_>,
    spec: PathBuf,
    out: Option<PathBuf>,
    jobs: Option<u32>,
    resume: bool,
    overwrite: bool,
) -> PyResult<SweepResult> {
    if jobs == Some(0) {
        return Err(bad_argument("jobs is at least 1"));
    }
    if resume && overwrite {
        return Err(bad_argument("resume and overwrite exclude each other"));
    }
    let args = StudyOptions {
        spec,
        out,
        jobs,
        resume,
        overwrite,
        yes: false,
        shard: None,
        slurm: false,
        array_size: None,
        partition: None,
        time: None,
        dry_run: false,
        wait: false,
    };
    let (swept, interrupted) = py.detach(|| sweep_watching_signals(&args));
    let swept = match swept {
        Ok(Some(swept)) if !interrupted => swept,
        Ok(_) if interrupted => {
            return Err(PyKeyboardInterrupt::new_err("the sweep was interrupted"));
        }
        Err(e) if interrupted => {
            return Err(PyKeyboardInterrupt::new_err(format!(
                "{e}; resume=True continues it"
            )));
        }
        Ok(_) => unreachable!("a local sweep gives back its folder"),
        Err(e) => return Err(Failure::summary(e).into_pyerr(py, None)),
    };
    let table = (read_table(&swept.table))
        .map_err(|e| Failure::summary(StudyError::from(e)).into_pyerr(py, None))?;
    let (names, rows) = (table.header, table.rows);
    // `run,case,` parameters and metrics `,pass,status,message`.
    let middle = names.len() - 5;
    let strings = |cell: &dyn Fn(&vams::app::study::table::Row) -> String| {
        rows.iter()
            .map(cell)
            .collect::<Vec<String>>()
            .into_py_any(py)
    };
    let mut values = Vec::with_capacity(names.len());
    let run: Vec<f64> = rows.iter().map(|r| r.index as f64).collect();
    values.push(PyArray1::from_vec(py, run).into_any().unbind());
    values.push(strings(&|r| r.case.clone())?);
    for p in 0..middle {
        // A number or empty (a metric that could not be evaluated: NaN) in every row makes
        // a float64 column; a literal (an enumeration's value) a column of str.
        let numbers: Option<Vec<f64>> = (rows.iter())
            .map(|r| match r.values[p].trim() {
                "" => Some(f64::NAN),
                cell => cell.parse().ok(),
            })
            .collect();
        values.push(match numbers {
            Some(numbers) => PyArray1::from_vec(py, numbers).into_any().unbind(),
            None => strings(&|r| r.values[p].clone())?,
        });
    }
    values.push(strings(&|r| {
        match r.pass {
            Some(true) => "pass",
            Some(false) => "fail",
            None => "",
        }
        .to_string()
    })?);
    values.push(strings(&|r| r.status.name().to_string())?);
    values.push(strings(&|r| r.message.clone())?);
    let StudyOutcome { dir, summary, .. } = swept;
    Ok(SweepResult {
        dir,
        summary,
        names,
        values,
        rows: rows.len(),
    })
}

/// Runs the sweep on a thread of its own while this (the main) thread asks Python for
/// pending signals every 50 ms; a KeyboardInterrupt cancels the runs. Also whether it was
/// interrupted.
fn sweep_watching_signals(args: &StudyOptions) -> (miette::Result<Option<StudyOutcome>>, bool) {
    let cancel = Cancel::new();
    let mut interrupted = false;
    let swept = std::thread::scope(|scope| {
        let flag = cancel.clone();
        // The spec's sources are parsed on this thread: a main thread's stack.
        let worker = std::thread::Builder::new()
            .stack_size(64 << 20)
            .spawn_scoped(scope, move || run_study(args, flag, &StderrNotes));
        let worker = match worker {
            Ok(worker) => worker,
            Err(e) => return Err(miette::miette!("cannot start the sweep: {e}")),
        };
        while !worker.is_finished() {
            std::thread::sleep(Duration::from_millis(50));
            if !interrupted && Python::attach(|py| py.check_signals()).is_err() {
                interrupted = true;
                cancel.cancel();
            }
        }
        worker
            .join()
            .unwrap_or_else(|_| Err(miette::miette!("internal error: the sweep panicked")))
    });
    (swept, interrupted)
}

/// The sweep's progress lines and diagnostics on the process's stderr, where a script or a
/// notebook's log shows them (as `vams sweep` prints them); no progress bar.
struct StderrNotes;

impl Notes for StderrNotes {
    fn note(&self, text: &str) {
        eprint!("{text}");
    }

    fn output(&self, text: &str) {
        print!("{text}");
    }
}
