//! The simulation cycle: the VHDL event kernel synchronised with the analog solver.
//!
//! **Takes** a [`Design`] and [`SimOptions`]; **gives** a [`SimResult`]: the recorded
//! [`Waveforms`], every report and assertion, how the run ended, and statistics. Or, through
//! [`simulate_into`], the rows go to a [`WaveformSink`] as they are accepted (`vams run`
//! streams them to its files) and the run gives a [`SimEnd`].
//!
//! Submodules: `signals` (drivers, projected waveforms, resolution), `process` (the
//! instruction interpreter), `eval`/`ops`/`image` (expressions to values), `fast` (integer expressions without values), `events` (delta
//! cycles), `cycle` (the mixed-signal loop and the quiescent point), `record` (probes and
//! output rows), `analog_model` (what the loop needs from the analog system).
//!
//! May use `design`, `analog`, `solver`, `waveform`, `source`. Never looks at the AST. Designs
//! without quantities never build an analog system.

use crate::analog::{AnalogOptions, AnalogSystem};
use crate::waveform::{WaveformSink, Waveforms};
use vams_design::Design;
use vams_syntax::source::Span;

mod analog_model;
mod call;
mod cancel;
mod coupling;
mod cycle;
mod error;
mod eval;
mod events;
mod fast;
mod image;
mod io;
mod lower;
mod ops;
mod process;
mod progress;
mod record;
mod signals;
mod solve_error;
mod textio;
mod timeouts;

#[cfg(test)]
mod tests;

pub use call::{DEEP_CALL_DEPTH, DEEP_STACK, set_call_depth_limit};
/// The call depth of a thread that did not set one.
pub const DEFAULT_CALL_DEPTH: usize = call::MAX_CALL_DEPTH;
pub use cancel::Cancel;
pub use error::SimError;
pub use progress::ProgressHook;

use cycle::Simulation;
use record::Recorder;

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
    /// Highest order of the BDF integrator, 1 to [`vams_solver::MAX_ORDER`].
    pub max_order: usize,
    /// Names to record (hierarchical, lower case); empty: every quantity and explicit signal.
    pub probes: Vec<String>,
    /// Told the simulated time as the run advances (a progress bar), if given.
    pub progress: Option<ProgressHook>,
    /// Solve for every unknown of the model instead of eliminating those an equation gives
    /// explicitly (slower; for comparisons and for debugging a model).
    pub keep_unknowns: bool,
    /// Stops the run with [`SimError::Interrupted`] when cancelled (Ctrl-C in `vams run`).
    pub cancel: Option<Cancel>,
}

impl Default for SimOptions {
    fn default() -> Self {
        SimOptions {
            stop: 1.0,
            reltol: 1e-3,
            abstol: None,
            max_step: None,
            max_order: vams_solver::MAX_ORDER,
            probes: Vec::new(),
            progress: None,
            keep_unknowns: false,
            cancel: None,
        }
    }
}

impl SimOptions {
    /// Rejects a stop time or tolerances no run can use.
    pub fn validate(&self) -> Result<(), SimError> {
        let o = self;
        let bad = |message: &str| {
            Err(SimError::BadOption {
                message: message.to_string(),
            })
        };
        if !(o.stop.is_finite() && o.stop >= 0.0) {
            return bad("the stop time must be finite and not negative");
        }
        if !(o.reltol.is_finite() && o.reltol > 0.0) {
            return bad("reltol must be a positive number");
        }
        if o.abstol.is_some_and(|a| !(a.is_finite() && a > 0.0)) {
            return bad("abstol must be a positive number");
        }
        if o.max_step.is_some_and(|h| h.is_nan() || h <= 0.0) {
            return bad("the maximum step must be positive");
        }
        if !(1..=vams_solver::MAX_ORDER).contains(&o.max_order) {
            return bad("the integration order must be 1 to 5");
        }
        Ok(())
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
    /// Steps tried and not taken: by the error test or because Newton did not converge.
    pub rejected_steps: usize,
    /// Of the rejected steps, those whose Newton iteration did not converge.
    pub newton_failures: usize,
    pub newton_iterations: usize,
    pub factorizations: usize,
    /// Factorisations that searched for pivots (the rest reused the last pivot order).
    pub pivot_searches: usize,
    /// Evaluations of the residual F(x', x, t) (Newton's and its line search's).
    pub residual_evaluations: usize,
    pub events: usize,
    pub delta_cycles: usize,
    pub breaks: usize,
}

impl SimStats {
    /// Every counter with its name, in the order `vams run --stats` lists them.
    pub fn named(&self) -> [(&'static str, usize); 10] {
        [
            ("accepted steps", self.accepted_steps),
            ("rejected steps", self.rejected_steps),
            ("Newton failures", self.newton_failures),
            ("Newton iterations", self.newton_iterations),
            ("factorizations", self.factorizations),
            ("pivot searches", self.pivot_searches),
            ("residual evaluations", self.residual_evaluations),
            ("events", self.events),
            ("delta cycles", self.delta_cycles),
            ("breaks", self.breaks),
        ]
    }
}

#[derive(Clone, Debug)]
pub struct SimResult {
    pub waveforms: Waveforms,
    pub reports: Vec<Report>,
    pub outcome: Outcome,
    pub stats: SimStats,
}

/// How a run that recorded into a sink ended: [`SimResult`] without the waveforms, which
/// went to the sink.
#[derive(Clone, Debug)]
pub struct SimEnd {
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
    simulate_keeping(design, options, on_report).map_err(|failed| failed.error)
}

/// A run that stopped with an error, and what it recorded before.
#[derive(Debug)]
pub struct Failed {
    pub error: SimError,
    /// The waveforms up to the error; `None` when it came before time 0 (building the analog
    /// system, the quiescent point).
    pub partial: Option<Waveforms>,
}

/// [`simulate`], keeping the waveforms recorded before an error.
pub fn simulate_keeping(
    design: &Design,
    options: &SimOptions,
    on_report: &mut dyn FnMut(&Report),
) -> Result<SimResult, Box<Failed>> {
    let mut waveforms = Waveforms::default();
    match simulate_into(design, options, &mut waveforms, on_report) {
        Ok(end) => Ok(SimResult {
            waveforms,
            reports: end.reports,
            outcome: end.outcome,
            stats: end.stats,
        }),
        Err(error) => Err(Box::new(Failed {
            error,
            // Rows start at time 0, after the quiescent point.
            partial: (!waveforms.times.is_empty()).then_some(waveforms),
        })),
    }
}

/// Runs the design like [`simulate`], handing every accepted time point to `sink` as it
/// comes instead of keeping it. On an error, the rows before it have reached the sink (none
/// when the error came before time 0: building the analog system, the quiescent point).
pub fn simulate_into(
    design: &Design,
    options: &SimOptions,
    sink: &mut dyn WaveformSink,
    on_report: &mut dyn FnMut(&Report),
) -> Result<SimEnd, SimError> {
    let recorder = Recorder::new(design, &options.probes, options.stop, sink)?;
    let mut analog = analog_system(design, options)?;
    announce_warnings(design, analog.as_ref(), on_report);
    if let Some(a) = analog.as_mut() {
        a.select_quantities(&wanted_quantities(design, &recorder));
    }
    let sim = Simulation::start(design, options, analog, on_report)?;
    sim.run(recorder, on_report)
}

/// The quiescent point after initialisation (processes run to their first wait, breaks
/// applied): `(name, value)` for every quantity, then every explicit signal.
pub fn operating_point(
    design: &Design,
    options: &SimOptions,
) -> Result<Vec<(String, f64)>, SimError> {
    operating_point_and_system(design, options).map(|(point, _)| point)
}

/// A quiescent point by name and the analog system it was found on (see
/// [`operating_point_and_system`]).
pub type PointAndSystem = (Vec<(String, f64)>, Option<AnalogSystem>);

/// [`operating_point`] and the analog system it was found on (`None` without quantities), for
/// a caller that linearises the design next: building the system again would cost about as
/// much as finding the point.
pub fn operating_point_and_system(
    design: &Design,
    options: &SimOptions,
) -> Result<PointAndSystem, SimError> {
    let analog = analog_system(design, options)?;
    let mut sim = Simulation::start(design, options, analog, &mut |_| {})?;
    let point = sim.operating_point();
    Ok((point, sim.into_analog()))
}

/// The quantities a run needs each accepted step: those recorded and those processes read.
fn wanted_quantities(design: &Design, recorder: &Recorder) -> Vec<bool> {
    let mut wanted = vec![false; design.quantities.len()];
    for q in recorder.quantities() {
        wanted[q.index()] = true;
    }
    let mut mark = |e: &vams_design::Expr| {
        e.visit(&mut |e| {
            if let vams_design::Expr::Quantity(q) | vams_design::Expr::Dot(q) = e
                && let Some(w) = wanted.get_mut(q.index())
            {
                *w = true;
            }
        })
    };
    let code = design
        .processes
        .iter()
        .flat_map(|p| &p.code)
        .chain(design.subprograms.iter().flat_map(|s| &s.code));
    for instr in code {
        instr.visit_exprs(&mut mark);
    }
    for l in &design.limits {
        mark(&l.max_step);
    }
    // Checked at every accepted point (`Simulation::check_branch_covers`).
    for cover in &design.branch_covers {
        mark(&cover.condition);
    }
    wanted
}

/// The analog system's warnings, as reports of severity warning at time 0 from no process,
/// so that a run shows them where it shows the model's own reports.
fn announce_warnings(
    design: &Design,
    analog: Option<&AnalogSystem>,
    on_report: &mut dyn FnMut(&Report),
) {
    for w in analog.map(|a| a.warnings(design)).unwrap_or_default() {
        // The message only: `vams check` shows the help.
        on_report(&Report {
            time: 0.0,
            severity: Severity::Warning,
            message: w.to_string(),
            process: String::new(),
            span: vams_syntax::diagnostics::Located::primary_span(&w),
        });
    }
}

/// The analog system, or `None` for a design without quantities.
fn analog_system(design: &Design, options: &SimOptions) -> Result<Option<AnalogSystem>, SimError> {
    if design.quantities.is_empty() {
        return Ok(None);
    }
    let analog = AnalogOptions {
        eliminate: !options.keep_unknowns,
        ..AnalogOptions::default()
    };
    AnalogSystem::with_options(design, &analog)
        .map(Some)
        .map_err(|errors| SimError::Analog { errors })
}
