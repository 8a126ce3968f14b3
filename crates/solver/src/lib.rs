//! The numerical core: linear algebra, Newton, operating point and BDF transient integration.
//!
//! **Takes** a DAE `F(x', x, t) = 0` through the [`DaeSystem`] trait: residuals, a Jacobian
//! `dF/dx + alpha * dF/dx'` on a fixed sparsity pattern, and optional root functions.
//!
//! **Gives** an operating point ([`operating_point`]), a variable-step variable-order BDF
//! integrator ([`Transient`]) that lands on breakpoints and locates roots, and the building
//! blocks under them ([`Newton`], [`LinearSolver`]).
//!
//! **Never** knows about VHDL, names or source spans: failures are [`SolveError`]s carrying
//! equation and unknown indices, which the caller maps back to the model. It never invents a
//! value on failure, never panics on any input, and never allocates inside the time-step loop.

pub mod ac;
mod error;
mod linear;
mod newton;
pub mod noise;
mod op;
pub mod poles;
mod transient;

#[cfg(test)]
mod tests;

pub use error::SolveError;
pub use linear::{DEFAULT_DENSE_MAX, LinearOptions, LinearSolver, PivotCounts};
pub use newton::{ErrorNorm, Newton, NewtonOptions, NewtonReport, NonlinearProblem, Tolerances};
pub use op::{OpOptions, OpReport, OpStrategy, operating_point};
pub use transient::{Advance, MAX_ORDER, Stats, Transient, TransientOptions, local_reltol};

/// A DAE `F(x', x, t) = 0` as the solver sees it. Unknown `i` is "differential" when `x'_i`
/// appears in some equation.
pub trait DaeSystem {
    /// Number of unknowns (and of equations).
    fn len(&self) -> usize;
    /// True for a system without unknowns.
    fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// Which unknowns appear differentiated (the rest are algebraic).
    fn differential(&self) -> &[bool];
    /// Unknowns the local error test leaves out (empty: none): algebraic unknowns that the
    /// equations give only through a derivative of a constrained unknown, which BDF computes
    /// to first order whatever its order. Their accuracy follows from the others'.
    fn error_exempt(&self) -> &[bool] {
        &[]
    }
    /// Structural nonzeros of `dF/dx + dF/dx'` as `(row, col)`, fixed for the system's lifetime.
    fn pattern(&self) -> &[(usize, usize)];
    /// `out = F(xdot, x, t)`.
    fn residual(&mut self, t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]);
    /// Values of `dF/dx + alpha * dF/dx'` at each pattern entry, in pattern order.
    fn jacobian(&mut self, t: f64, x: &[f64], xdot: &[f64], alpha: f64, out: &mut [f64]);
    /// Values of `dF/dx'` in the columns flagged in `dot_columns` and of `dF/dx` in the others,
    /// at each pattern entry (what consistent initialisation solves with). The default takes
    /// the difference of two [`DaeSystem::jacobian`] calls; systems that keep the parts apart
    /// answer in one evaluation.
    fn jacobian_parts(
        &mut self,
        t: f64,
        x: &[f64],
        xdot: &[f64],
        dot_columns: &[bool],
        out: &mut [f64],
        scratch: &mut [f64],
    ) {
        self.jacobian(t, x, xdot, 0.0, scratch);
        self.jacobian(t, x, xdot, 1.0, out);
        let columns = self.pattern().iter().map(|&(_, c)| c);
        for ((o, &j0), c) in out.iter_mut().zip(scratch.iter()).zip(columns) {
            *o = if dot_columns[c] { *o - j0 } else { j0 };
        }
    }
    /// Root functions `g(t, x, x')` whose sign changes the integrator must locate.
    fn root_count(&self) -> usize {
        0
    }
    /// `out = g(t, x, x')`, `root_count()` values.
    fn roots(&mut self, _t: f64, _x: &[f64], _xdot: &[f64], _out: &mut [f64]) {}
    /// The fraction of the Newton step `x -> x + dx` (at `t`, with derivative `xdot`) that
    /// keeps exponentials from overshooting (a diode switching on from far away), in `(0, 1]`.
    fn step_limit(&mut self, _t: f64, _x: &[f64], _xdot: &[f64], _dx: &[f64]) -> f64 {
        1.0
    }
    /// True when `F` is affine in `x` and `x'` (for any signals and `t`): a Newton step with
    /// the exact Jacobian then lands on the solution, and needs no second iteration to confirm
    /// it. Systems that do not know say `false`.
    fn is_linear(&self) -> bool {
        false
    }

    /// What each residual balances, at the last [`DaeSystem::residual`] evaluation: the
    /// largest magnitude among its terms (the summands of its top-level sum; a current
    /// balance's largest current). Newton judges a residual against `reltol` times this, as
    /// SPICE judges a device's current against its own magnitude. `false`: the system does
    /// not know, and the scale comes from the Jacobian instead.
    fn residual_scale(&self, _out: &mut [f64]) -> bool {
        false
    }

    /// Source scaling in `[0, 1]` for source stepping (independent sources multiply by it).
    fn set_source_scale(&mut self, _s: f64) {}

    /// An identifier of the discrete state the equations are in (for a model, the values of
    /// the signals they read), for systems that switch between modes: a restart in a mode seen
    /// before may start Newton from that mode's last consistent point. `None`: no modes.
    fn mode(&self) -> Option<u64> {
        None
    }
}
