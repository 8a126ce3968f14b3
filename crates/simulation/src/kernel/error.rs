//! Simulation failures (codes `vams::sim::*`).

use miette::Diagnostic;
use thiserror::Error;

use crate::analog::AnalogError;
use vams_solver::SolveError;
use vams_syntax::diagnostics::Located;
use vams_syntax::source::Span;

#[derive(Clone, Debug, Error, Diagnostic)]
pub enum SimError {
    /// The analog system could not be built.
    #[error("the analog system is not well formed")]
    #[diagnostic(code(vams::sim::analog))]
    Analog {
        #[related]
        errors: Vec<AnalogError>,
    },

    /// A process did something that has no value at run time, e.g. `a(11)` on a
    /// `bit_vector(0 to 7)`, or `x / 0` on integers.
    #[error("{message} in process `{process}` at t = {} s", seconds(*time))]
    #[diagnostic(code(vams::sim::runtime))]
    Runtime {
        process: String,
        time: f64,
        message: String,
        #[label("here")]
        span: Span,
        #[help]
        help: String,
    },

    /// A file object's declaration names a file that cannot be opened (LRM 4.3.1.4: an
    /// error at elaboration).
    #[error("{message}")]
    #[diagnostic(code(vams::sim::file_open))]
    FileOpen {
        message: String,
        #[label("declared here")]
        span: Span,
        #[help]
        help: String,
    },

    /// `r == sqrt(y)` with `y` gone negative: a quantity is NaN or infinite at an accepted
    /// point (its value would reach the waveforms).
    #[error("quantity `{quantity}` is {value} at t = {} s", seconds(*time))]
    #[diagnostic(code(vams::sim::not_finite))]
    NotFinite {
        quantity: String,
        value: String,
        time: f64,
        #[label("declared here")]
        span: Span,
        #[help]
        help: String,
    },

    /// A simultaneous if without `else`, none of whose conditions holds at an accepted
    /// point: it gives no equations there (LRM 1076.1 12.6.6).
    #[error("no condition of this simultaneous if holds at t = {} s, so it gives no equations", seconds(*time))]
    #[diagnostic(
        code(vams::sim::no_branch),
        help("add an `else` branch, or widen the conditions so that one always holds")
    )]
    NoBranch {
        time: f64,
        #[label("none of its conditions holds")]
        span: Span,
    },

    /// A threshold crossing that flips back whenever the analog solution restarts (a limiter
    /// in a feedback loop switching its equations at the threshold): the analog and digital
    /// parts never settle at `time`.
    #[error("the analog and digital parts did not settle at t = {} s: {limit} restarts, still changing {signals}", seconds(*time))]
    #[diagnostic(
        code(vams::sim::settle_limit),
        help(
            "each restart changes these signals again (often an `'above` whose crossing switches the equations that decide it); give the switch hysteresis or a slope on both sides"
        )
    )]
    SettleLimit {
        time: f64,
        limit: usize,
        signals: String,
    },

    /// The user stopped the run (Ctrl-C); what it computed up to `time` is kept.
    #[error("interrupted at t = {} s", seconds(*time))]
    #[diagnostic(
        code(vams::sim::interrupted),
        help("the run was stopped on request; the waveforms up to this time are kept")
    )]
    Interrupted { time: f64 },

    /// `process begin x := x + 1; end process;` never reaches a wait.
    #[error("process `{process}` ran {limit} instructions at t = {} s without waiting", seconds(*time))]
    #[diagnostic(
        code(vams::sim::runaway),
        help("every path through a process loop must reach a wait statement (LRM 11.3)")
    )]
    Runaway {
        process: String,
        time: f64,
        limit: usize,
        #[label("this process")]
        span: Span,
    },

    /// `a <= not a;` with `b <= a;` zero-delay feedback: time never advances.
    #[error("more than {limit} delta cycles at t = {} s (process `{process}` ran last)", seconds(*time))]
    #[diagnostic(
        code(vams::sim::delta_limit),
        help("a zero-delay loop keeps scheduling events at the same time; add a delay (`after`)")
    )]
    DeltaLimit {
        time: f64,
        limit: usize,
        process: String,
        #[label("last process run")]
        span: Span,
    },

    /// Two processes drive an unresolved signal: `s <= '1';` in one process and `s <= '0';`
    /// in another, with `s : bit`.
    #[error("signal `{signal}` has {count} drivers ({processes}) but no resolution function")]
    #[diagnostic(
        code(vams::sim::multiple_drivers),
        help(
            "drive the signal from one process, or declare it of a resolved type such as \
             std_logic (LRM 14.7.3.2)"
        )
    )]
    MultipleDrivers {
        signal: String,
        count: usize,
        processes: String,
        #[label("declared here")]
        span: Span,
    },

    /// `--probe` with a name the design does not have.
    #[error("no quantity or signal named `{name}`")]
    #[diagnostic(code(vams::sim::unknown_probe))]
    UnknownProbe {
        name: String,
        #[help]
        help: String,
    },

    /// The analog solver gave up, e.g. an equation without a solution past a switch.
    #[error(
        "analog solver failed at t = {} s{}{}",
        seconds(*time),
        names_suffix(unknowns),
        equation_suffix(equation)
    )]
    #[diagnostic(
        code(vams::sim::solve),
        help(
            "the cause is below; check the equations of the unknowns named here, their break \
             values and initial values"
        )
    )]
    Solve {
        time: f64,
        /// Names of the unknowns the failure points at.
        unknowns: Vec<String>,
        #[label("involved here")]
        span: Option<Span>,
        /// The equation the failure points at (largest residual, singular row), described.
        equation: Option<String>,
        #[source]
        #[diagnostic_source]
        cause: SolveError,
    },

    /// `--stop -1` or a NaN tolerance.
    #[error("invalid simulation option: {message}")]
    #[diagnostic(
        code(vams::sim::option),
        help("the stop time must be positive and finite, tolerances positive")
    )]
    BadOption { message: String },

    /// The sink the rows go to stopped taking them (an output file that cannot be written).
    #[error("the waveforms cannot be recorded: {message}")]
    #[diagnostic(
        code(vams::sim::output),
        help("the run stops where its output fails; see the message for the file")
    )]
    Output { message: String },
}

fn equation_suffix(equation: &Option<String>) -> String {
    match equation {
        Some(e) => format!("; worst equation: {e}"),
        None => String::new(),
    }
}

fn names_suffix(names: &[String]) -> String {
    if names.is_empty() {
        String::new()
    } else {
        format!(" (involving {})", names.join(", "))
    }
}

impl Located for SimError {
    fn primary_span(&self) -> Span {
        match self {
            SimError::Runtime { span, .. }
            | SimError::FileOpen { span, .. }
            | SimError::NotFinite { span, .. }
            | SimError::NoBranch { span, .. }
            | SimError::Runaway { span, .. }
            | SimError::DeltaLimit { span, .. }
            | SimError::MultipleDrivers { span, .. } => *span,
            SimError::Solve { span, .. } => span.unwrap_or_default(),
            SimError::Analog { errors } => errors
                .first()
                .map(Located::primary_span)
                .unwrap_or_default(),
            SimError::UnknownProbe { .. }
            | SimError::BadOption { .. }
            | SimError::Interrupted { .. }
            | SimError::Output { .. }
            | SimError::SettleLimit { .. } => Span::default(),
        }
    }
}

/// A time in seconds for a message: plain decimals in the usual range, exponent notation
/// outside it (a step that fell to 1e-323 s would print 323 digits).
fn seconds(t: f64) -> String {
    if t == 0.0 || (1e-4..1e15).contains(&t.abs()) {
        format!("{t}")
    } else {
        format!("{t:e}")
    }
}

#[cfg(test)]
mod tests {
    use super::seconds;

    #[test]
    fn times_print_short_at_any_scale() {
        assert_eq!(seconds(0.0), "0");
        assert_eq!(seconds(0.2915), "0.2915");
        assert_eq!(seconds(5e-324), "5e-324");
        assert_eq!(seconds(3.6e15), "3.6e15");
    }
}
