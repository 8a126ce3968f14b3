//! The simulation cycle: the VHDL event kernel synchronised with the analog solver.
//!
//! **Takes** a [`Design`] and [`SimOptions`]; **gives** a [`SimResult`]: the recorded
//! [`Waveforms`], every report and assertion, how the run ended, and statistics.
//!
//! May use `design`, `analog`, `solver`, `waveform`, `source`. Never looks at the AST.

use crate::design::Design;
use crate::source::Span;
use crate::waveform::Waveforms;

mod error;

pub use error::SimError;

/// How to run.
#[derive(Clone, Debug)]
pub struct SimOptions {
    /// End time in seconds.
    pub stop: f64,
    pub reltol: f64,
    /// Overrides every tolerance group's absolute tolerance when given.
    pub abstol: Option<f64>,
    /// Largest time step in seconds.
    pub max_step: Option<f64>,
    /// Names to record (hierarchical, lower case); empty: every quantity and explicit signal.
    pub probes: Vec<String>,
}

impl Default for SimOptions {
    fn default() -> Self {
        SimOptions {
            stop: 1.0,
            reltol: 1e-3,
            abstol: None,
            max_step: None,
            probes: Vec::new(),
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
pub enum Severity {
    Note,
    Warning,
    Error,
    Failure,
}

/// One report or failed assertion.
#[derive(Clone, Debug)]
pub struct Report {
    pub time: f64,
    pub severity: Severity,
    pub message: String,
    /// The process it came from (`dut.u_ic.direction`).
    pub process: String,
    pub span: Span,
}

/// How a run ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Outcome {
    /// Reached the stop time.
    Finished,
    /// `std.env.stop` or `finish` at the given time.
    Stopped { time: f64 },
    /// An assertion of severity failure at the given time.
    Failed { time: f64 },
}

/// Counters for the closing figures and `--stats`.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct SimStats {
    pub accepted_steps: usize,
    pub rejected_steps: usize,
    pub newton_iterations: usize,
    pub factorizations: usize,
    pub events: usize,
    pub delta_cycles: usize,
    pub breaks: usize,
}

#[derive(Clone, Debug)]
pub struct SimResult {
    pub waveforms: Waveforms,
    pub reports: Vec<Report>,
    pub outcome: Outcome,
    pub stats: SimStats,
}

/// Runs the design from its quiescent point to `options.stop`; `on_report` sees each report
/// as it happens (for live printing).
pub fn simulate(
    design: &Design,
    options: &SimOptions,
    on_report: &mut dyn FnMut(&Report),
) -> Result<SimResult, SimError> {
    let _ = (design, options, on_report);
    todo!("simulate")
}

/// The quiescent point after initialisation (processes run to their first wait, breaks
/// applied): `(name, value)` for every quantity, then every explicit signal.
pub fn operating_point(
    design: &Design,
    options: &SimOptions,
) -> Result<Vec<(String, f64)>, SimError> {
    let _ = (design, options);
    todo!("operating_point")
}
