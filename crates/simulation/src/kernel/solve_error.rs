//! Solver failures mapped back to the model: the indices a [`SolveError`] carries become
//! unknown names, the equation involved (what it is and its source span), and the span to
//! point at: the equation's, else the first quantity's.

use vams_design::Design;
use vams_solver::SolveError;

use super::analog_model::AnalogModel;
use super::error::SimError;

/// Maps a solver failure's indices to names (and the first named quantity's span).
/// Names and sites come from `sys` only now, on failure: building them for every equation up
/// front cost as much as the analysis on large circuits.
pub(crate) fn solve_error<A: AnalogModel + ?Sized>(
    cause: SolveError,
    now: f64,
    sys: &A,
    slots: &[Option<usize>],
    design: &Design,
) -> SimError {
    let names = sys.unknown_names();
    let (time, unknown) = indices(&cause);
    let equation = equation_of(&cause).and_then(|r| sys.equation_site(design, r));
    let unknowns: Vec<String> = unknown
        .iter()
        .filter_map(|&i| names.get(i).cloned())
        .collect();
    let span = unknown.and_then(|i| {
        slots
            .iter()
            .position(|&s| s == Some(i))
            .map(|q| design.quantities[q].span)
    });
    SimError::Solve {
        time: time.unwrap_or(now),
        unknowns,
        span: equation.as_ref().map(|(_, s)| *s).or(span),
        equation: equation.map(|(what, _)| what),
        cause,
    }
}

/// The equation (row) a solver error points at, if it says.
fn equation_of(e: &SolveError) -> Option<usize> {
    match e {
        SolveError::NewtonDiverged { worst_equation, .. } => Some(*worst_equation),
        SolveError::SingularJacobian { row, .. } => *row,
        SolveError::NonFiniteResidual { equation, .. } => Some(*equation),
        SolveError::NonFiniteJacobian { row, .. } => Some(*row),
        SolveError::NoOperatingPoint { last } => equation_of(last),
        _ => None,
    }
}

/// The time and the unknown a solver error points at, if it says.
fn indices(e: &SolveError) -> (Option<f64>, Option<usize>) {
    match e {
        SolveError::StepTooSmall {
            t, worst_unknown, ..
        } => (Some(*t), Some(*worst_unknown)),
        SolveError::SingularJacobian { t, column, .. } => (Some(*t), *column),
        SolveError::NonFiniteJacobian { t, column, .. } => (Some(*t), Some(*column)),
        SolveError::NewtonDiverged { t, .. }
        | SolveError::NonFiniteResidual { t, .. }
        | SolveError::InvalidTime { t, .. } => (Some(*t), None),
        SolveError::NoOperatingPoint { last } => indices(last),
        SolveError::InvalidSystem { .. } => (None, None),
    }
}
