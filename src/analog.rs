//! The analog side of an elaborated design as a DAE the solver integrates.
//!
//! **Takes** a [`Design`]; **gives** an [`AnalogSystem`] implementing [`DaeSystem`]: unknowns
//! (terminal potentials, then quantities), the conservation laws generated from the terminal
//! graph, the user's equations compiled to a flat tape with symbolic Jacobians, structural
//! analysis before any number is computed, and the quiescent (and break) initial conditions.
//!
//! May use `design`, `solver`, `source`, `diagnostics`. Knows nothing of processes or time
//! stepping policy: the kernel drives it.

use crate::design::{Design, QuantityId, SignalId};
use crate::solver::{DaeSystem, OpOptions, SolveError};

mod error;

pub use error::AnalogError;

/// The compiled DAE of a design.
pub struct AnalogSystem {}

impl AnalogSystem {
    /// Builds unknowns and equations, checks the structure, compiles residuals and Jacobians.
    pub fn new(design: &Design) -> Result<AnalogSystem, Vec<AnalogError>> {
        let _ = design;
        todo!("AnalogSystem::new")
    }

    /// Names of the unknowns in solver order (quantity names; `potential(t)` for terminals).
    pub fn unknown_names(&self) -> &[String] {
        todo!()
    }

    /// Index of quantity `q` in the unknown vector.
    pub fn quantity_slot(&self, q: QuantityId) -> usize {
        let _ = q;
        todo!()
    }

    /// Sets the value that equations read for signal `s` (booleans and enums as positions).
    pub fn set_signal(&mut self, s: SignalId, value: f64) {
        let _ = (s, value);
        todo!()
    }

    /// True when some equation reads signal `s` (a change is then a discontinuity).
    pub fn reads_signal(&self, s: SignalId) -> bool {
        let _ = s;
        todo!()
    }

    /// The `'above` signals; root function `i` of [`DaeSystem::roots`] is
    /// `quantity - level` of `above_signals()[i]`.
    pub fn above_signals(&self) -> &[SignalId] {
        todo!()
    }

    /// Absolute tolerance per unknown: from the quantity's tolerance group, else `default`.
    pub fn abstol(&self, default: f64) -> Vec<f64> {
        let _ = default;
        todo!()
    }

    /// Quiescent point at time `t`: solves `F(x', x, t) = 0` with `x'_i = 0` for every
    /// differential unknown except those in `fixed`, which are held at the given value with
    /// `x'_i` solved for instead (the LRM's augmentation set with break values). Starts from
    /// `guess`; returns `(x, x')`.
    pub fn quiescent_point(
        &mut self,
        t: f64,
        guess: &[f64],
        fixed: &[(usize, f64)],
        reltol: f64,
        abstol: &[f64],
        options: &OpOptions,
    ) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
        let _ = (t, guess, fixed, reltol, abstol, options);
        todo!()
    }

    /// The equation system as text for `vams dae`: unknowns, then each equation with its
    /// source location (`file:line`) and text.
    pub fn listing(&self, design: &Design, sources: &crate::source::SourceMap) -> String {
        let _ = (design, sources);
        todo!()
    }
}

impl DaeSystem for AnalogSystem {
    fn len(&self) -> usize {
        todo!()
    }
    fn differential(&self) -> &[bool] {
        todo!()
    }
    fn pattern(&self) -> &[(usize, usize)] {
        todo!()
    }
    fn residual(&mut self, t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        let _ = (t, x, xdot, out);
        todo!()
    }
    fn jacobian(&mut self, t: f64, x: &[f64], xdot: &[f64], alpha: f64, out: &mut [f64]) {
        let _ = (t, x, xdot, alpha, out);
        todo!()
    }
}
