//! One run of a sweep: elaborate the analysed design with the run's generics (the sources
//! are parsed and analysed once for the whole sweep), simulate it keeping only the columns
//! the metrics and the envelope read, evaluate the metrics, and make the run's row. A run
//! that fails (elaboration, solver, run-time error, assertion of severity failure) is a row
//! with its message, never a stopped sweep.

use crate::app::compile::Prepared;
use crate::app::render::{located_line, sim_error_line};
use crate::kernel::{Cancel, Outcome, Severity, SimError, SimOptions, simulate_into};
use crate::waveform::{ColumnKind, Header, SinkError, WaveformSink, Waveforms};

use super::metric::Metric;
use super::plan::{ParamValue, Run};
use super::table::{Row, Status};

/// What every run shares.
pub struct Job<'a> {
    pub prepared: &'a Prepared,
    pub parameters: Vec<String>,
    pub metrics: &'a [Metric],
    /// The columns drawn as envelopes.
    pub envelope: &'a [String],
    pub stop: f64,
    pub reltol: f64,
    pub abstol: Option<f64>,
    pub max_step: Option<f64>,
    pub cancel: Cancel,
}

/// The sink of a run whose metrics read no column (only its reports): no row is built.
struct NoRows;

impl WaveformSink for NoRows {
    fn start(&mut self, _: &Header) -> Result<(), SinkError> {
        Ok(())
    }

    fn row(&mut self, _: f64, _: &[f64]) -> Result<(), SinkError> {
        Ok(())
    }

    fn wants_rows(&self) -> bool {
        false
    }
}

/// A run's envelope column: times, values, and whether it holds between samples.
pub type Trace = (Vec<f64>, Vec<f64>, bool);

/// A finished run.
pub struct Done {
    pub row: Row,
    /// Per envelope column, its trace (`None` where the run has no such column).
    pub traces: Vec<Option<Trace>>,
}

impl Job<'_> {
    /// The columns a run records: what the metrics and the envelope read.
    fn probes(&self) -> Vec<String> {
        let mut probes: Vec<String> = Vec::new();
        for name in self
            .metrics
            .iter()
            .flat_map(Metric::probes)
            .chain(self.envelope.iter().cloned())
        {
            if !probes.contains(&name) {
                probes.push(name);
            }
        }
        probes
    }

    /// Run `run` failed with `message`: no metric, the limits failed where there are some.
    pub fn failure(&self, run: &Run, message: String) -> Done {
        Done {
            row: Row {
                index: run.index,
                case: run.case.clone(),
                values: run.values.iter().map(ParamValue::literal).collect(),
                metrics: vec![None; self.metrics.len()],
                pass: self.has_limits().then_some(false),
                status: Status::Failed,
                message,
            },
            traces: vec![None; self.envelope.len()],
        }
    }

    /// Runs `run`; `None` when the sweep was interrupted during it (nothing to record: a
    /// resumed sweep runs it again).
    pub fn run(&self, run: &Run) -> Option<Done> {
        if self.cancel.is_cancelled() {
            return None;
        }
        let failed = |message: String| self.failure(run, message);
        let loaded = &self.prepared.loaded;
        // The spec's `[design] generics` are the prepared design's; the run's values win.
        let design = match self.prepared.try_elaborate(&run.generics(&self.parameters)) {
            Ok(d) => d,
            Err(errors) => {
                let first = errors
                    .first()
                    .map(|e| located_line(e, &loaded.sources))
                    .unwrap_or_default();
                return Some(failed(format!("elaboration: {first}")));
            }
        };
        let sim = SimOptions {
            stop: self.stop,
            reltol: self.reltol,
            abstol: self.abstol,
            max_step: self.max_step,
            max_order: 5,
            probes: self.probes(),
            progress: None,
            keep_unknowns: false,
            cancel: Some(self.cancel.clone()),
        };
        let mut waves = Waveforms::default();
        let mut reports = Vec::new();
        let mut on_report = |r: &crate::kernel::Report| reports.push(r.clone());
        // No probes would mean "record everything": with nothing to read, record nothing.
        let result = if sim.probes.is_empty() {
            simulate_into(&design, &sim, &mut NoRows, &mut on_report)
        } else {
            simulate_into(&design, &sim, &mut waves, &mut on_report)
        };
        let end = match result {
            Ok(end) => end,
            Err(SimError::Interrupted { .. }) => return None,
            Err(e) => {
                let message = sim_error_line(&e, waves.times.last().copied(), &loaded.sources);
                return Some(failed(message));
            }
        };
        if let Outcome::Failed { time } = end.outcome {
            let why = reports
                .iter()
                .rev()
                .find(|r| r.severity == Severity::Failure)
                .map_or("assertion of severity failure".to_string(), |r| {
                    r.message.clone()
                });
            return Some(failed(format!(
                "failure at t = {}: {why}",
                crate::app::time::format_time(time)
            )));
        }
        let mut problems = Vec::new();
        let mut pass = self.has_limits().then_some(true);
        let metrics = self
            .metrics
            .iter()
            .map(|m| match m.evaluate(&waves, &end.reports) {
                Ok(v) => {
                    if m.check(v) == Some(false) {
                        pass = Some(false);
                    }
                    Some(v)
                }
                Err(e) => {
                    // The error names its metric.
                    problems.push(e.to_string());
                    if pass.is_some() {
                        pass = Some(false);
                    }
                    None
                }
            })
            .collect();
        let traces = self
            .envelope
            .iter()
            .map(|name| {
                waves.column(name).map(|c| {
                    (
                        waves.times.clone(),
                        c.values.clone(),
                        matches!(c.kind, ColumnKind::Signal { .. }),
                    )
                })
            })
            .collect();
        Some(Done {
            row: Row {
                index: run.index,
                case: run.case.clone(),
                values: run.values.iter().map(ParamValue::literal).collect(),
                metrics,
                pass,
                status: Status::Ok,
                message: problems.join("; "),
            },
            traces,
        })
    }

    fn has_limits(&self) -> bool {
        self.metrics
            .iter()
            .any(|m| m.limit.min.is_some() || m.limit.max.is_some())
    }
}
