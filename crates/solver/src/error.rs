//! The solver's error type: indices only, never names or spans.
//!
//! Every variant carries the simulation time and the equation (row) or unknown (column) index
//! that the failure points at. The simulator maps those indices back to the DAE's equations and
//! their source spans; the solver never sees either.

use miette::Diagnostic;
use thiserror::Error;

/// Why the numerical core gave up. Codes `E4xx` are the solve stage's range.
#[derive(Debug, Clone, PartialEq, Error, Diagnostic)]
pub enum SolveError {
    /// Newton-Raphson did not meet its tolerance within the iteration limit.
    ///
    /// Example: `F(x) = x^2 + 1` has no real root; every iteration leaves `|F| >= 1`.
    #[error(
        "Newton iteration did not converge at t = {t:e} after {iterations} iterations; \
         row {worst_equation} of the solver's system has the largest residual ({residual:e})"
    )]
    #[diagnostic(
        code(vams::solve::E401),
        help(
            "check that the equation can be satisfied near the starting values; give a better \
             initial value (LRM 1076.1 12.6.4: quantities start from their initial values), or \
             relax the tolerances"
        )
    )]
    NewtonDiverged {
        t: f64,
        iterations: usize,
        worst_equation: usize,
        residual: f64,
    },

    /// The integrator had to shrink the step below its minimum to meet the error tolerance.
    ///
    /// Example: a discontinuous right-hand side `x' = if x > 0 then -1 else 1` chatters at 0.
    #[error(
        "time step fell to {step:e} at t = {t:e} (below the minimum); unknown {worst_unknown} \
         has the largest error"
    )]
    #[diagnostic(
        code(vams::solve::E402),
        help(
            "a discontinuity the model does not announce can cause this: use 'above and \
             break (LRM 1076.1 8.14) so the solver restarts there, or relax the tolerances"
        )
    )]
    StepTooSmall {
        t: f64,
        step: f64,
        worst_unknown: usize,
    },

    /// The Jacobian is singular. `row` is the equation and `column` the unknown at which
    /// elimination broke down, when they can be told. `structural` is true when the pattern
    /// itself is deficient (an equation with no entries, an unknown in no equation): no value
    /// of the unknowns can fix that.
    ///
    /// Example: two equations that both say `v = 1` leave one unknown undetermined.
    #[error(
        "singular Jacobian at t = {t:e}{}{}",
        pivot_site(*row, *column),
        if *structural { ", structurally" } else { "" }
    )]
    #[diagnostic(
        code(vams::solve::E403),
        help(
            "the system is structurally or numerically under-determined: an equation is \
             missing or redundant, or a quantity is not referenced by any equation (LRM 1076.1 \
             12.6.6: the number of simultaneous statements must match the quantities)"
        )
    )]
    SingularJacobian {
        t: f64,
        row: Option<usize>,
        column: Option<usize>,
        structural: bool,
    },

    /// The model returned NaN or infinity in its residual.
    #[error("residual of equation {equation} is not finite at t = {t:e}")]
    #[diagnostic(
        code(vams::solve::E404),
        help("look for a division by zero, a log of a non-positive value or an overflowing exp")
    )]
    NonFiniteResidual { t: f64, equation: usize },

    /// The model returned NaN or infinity in its Jacobian.
    #[error("Jacobian entry (equation {row}, unknown {column}) is not finite at t = {t:e}")]
    #[diagnostic(
        code(vams::solve::E405),
        help("look for a division by zero or an overflowing derivative in that equation")
    )]
    NonFiniteJacobian { t: f64, row: usize, column: usize },

    /// The system description itself is inconsistent (caller bug, not a numerical failure).
    #[error("invalid system: {reason}")]
    #[diagnostic(code(vams::solve::E406))]
    InvalidSystem { reason: &'static str, index: usize },

    /// A time argument lies behind the integrator or is not finite.
    #[error("requested time {requested:e} is not ahead of the current time {t:e}")]
    #[diagnostic(code(vams::solve::E407))]
    InvalidTime { t: f64, requested: f64 },

    /// Operating point: Newton, gmin stepping and source stepping all failed. `last` is the
    /// error of the last attempt (source stepping).
    #[error("no operating point found: Newton, gmin stepping and source stepping failed")]
    #[diagnostic(
        code(vams::solve::E408),
        help(
            "give initial values close to the expected operating point, or check for \
             equations without a DC solution (a floating capacitor node, an ideal source loop)"
        )
    )]
    NoOperatingPoint {
        #[source]
        last: Box<SolveError>,
    },
}

impl SolveError {
    /// The same error with its time stamp replaced (the linear solver does not know `t`).
    pub(crate) fn at(mut self, time: f64) -> Self {
        match &mut self {
            Self::NewtonDiverged { t, .. }
            | Self::StepTooSmall { t, .. }
            | Self::SingularJacobian { t, .. }
            | Self::NonFiniteResidual { t, .. }
            | Self::NonFiniteJacobian { t, .. }
            | Self::InvalidTime { t, .. } => *t = time,
            Self::InvalidSystem { .. } | Self::NoOperatingPoint { .. } => {}
        }
        self
    }
}

/// Where an elimination broke down, in the solver's numbering (the caller names the equation
/// and unknowns): empty when it cannot be told.
fn pivot_site(row: Option<usize>, column: Option<usize>) -> String {
    match (row, column) {
        (Some(r), Some(c)) => format!(" (at row {r}, column {c} of the solver's system)"),
        (Some(r), None) => format!(" (at row {r} of the solver's system)"),
        (None, Some(c)) => format!(" (at column {c} of the solver's system)"),
        (None, None) => String::new(),
    }
}
