//! Solver failures mapped back to the model: the indices a [`SolveError`] carries become
//! unknown names and the span of the quantity involved.

use crate::design::Design;
use crate::solver::SolveError;

use super::error::SimError;

/// Maps a solver failure's indices to names (and the first named quantity's span).
pub(crate) fn solve_error(
    cause: SolveError,
    now: f64,
    names: &[String],
    slots: &[usize],
    design: &Design,
) -> SimError {
    let (time, unknown) = indices(&cause);
    let unknowns: Vec<String> = unknown
        .iter()
        .filter_map(|&i| names.get(i).cloned())
        .collect();
    let span = unknown.and_then(|i| {
        slots
            .iter()
            .position(|&s| s == i)
            .map(|q| design.quantities[q].span)
    });
    SimError::Solve {
        time: time.unwrap_or(now),
        unknowns,
        span,
        cause,
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
