//! What the simulation cycle needs from the analog side, as a trait: [`AnalogSystem`] is the
//! real implementation; the kernel's tests drive the cycle with small hand-written systems.

use crate::analog::AnalogSystem;
use vams_design::{Design, QuantityId, SignalId};
use vams_solver::{DaeSystem, OpOptions, SolveError};
use vams_syntax::source::Span;

/// The analog system as the kernel drives it (see [`AnalogSystem`] for each method's contract).
pub(crate) trait AnalogModel: DaeSystem {
    fn unknown_names(&self) -> &[String];
    /// Solver index of quantity `q`, `None` when the analog side eliminated it.
    fn quantity_slot(&self, q: QuantityId) -> Option<usize>;
    /// Every quantity's value and `'dot` at the state `(t, x, x')`, by `QuantityId`.
    fn quantity_values(
        &mut self,
        _t: f64,
        x: &[f64],
        xdot: &[f64],
        values: &mut [f64],
        derivatives: &mut [f64],
    ) {
        for (q, (v, d)) in values.iter_mut().zip(derivatives.iter_mut()).enumerate() {
            if let Some(j) = self.quantity_slot(QuantityId(q as u32)) {
                *v = x[j];
                *d = xdot[j];
            }
        }
    }
    fn set_signal(&mut self, s: SignalId, value: f64);
    fn reads_signal(&self, s: SignalId) -> bool;
    /// Times the integrator must step to (the corners of tables of `now`), increasing.
    fn table_times(&self) -> &[f64] {
        &[]
    }
    fn above_signals(&self) -> &[SignalId];
    fn abstol(&self, default: f64) -> Vec<f64>;
    /// What equation `row` is and where it comes from, for failure messages.
    fn equation_site(&self, _design: &Design, _row: usize) -> Option<(String, Span)> {
        None
    }
    /// Records an accepted point for `Q'delayed` (systems without delays ignore it).
    fn record_history(&mut self, _t: f64, _x: &[f64], _xdot: &[f64]) {}
    /// The shortest `Q'delayed` delay, a bound on the step.
    fn shortest_delay(&self) -> Option<f64> {
        None
    }
    /// Index reduction's states chosen again at the initial break values (by `QuantityId`);
    /// may renumber the unknowns, so slots are looked up after it.
    fn choose_states(&mut self, _design: &Design, _point: &[(QuantityId, f64)]) {}
    /// Index reduction's states chosen again at the run's state where the current ones lose
    /// their grip: the rebuilt system's state vector to restart from, `None` to go on.
    fn choose_states_again(
        &mut self,
        _design: &Design,
        _t: f64,
        _x: &[f64],
        _xdot: &[f64],
    ) -> Option<Vec<f64>> {
        None
    }
    #[allow(clippy::too_many_arguments)]
    fn quiescent_point(
        &mut self,
        t: f64,
        guess: &[f64],
        fixed: &[(usize, f64)],
        reltol: f64,
        abstol: &[f64],
        options: &OpOptions,
    ) -> Result<(Vec<f64>, Vec<f64>), SolveError>;
}

impl AnalogModel for AnalogSystem {
    fn unknown_names(&self) -> &[String] {
        AnalogSystem::unknown_names(self)
    }
    fn quantity_slot(&self, q: QuantityId) -> Option<usize> {
        AnalogSystem::quantity_slot(self, q)
    }
    fn quantity_values(
        &mut self,
        t: f64,
        x: &[f64],
        xdot: &[f64],
        values: &mut [f64],
        derivatives: &mut [f64],
    ) {
        AnalogSystem::quantity_values(self, t, x, xdot, values, derivatives)
    }
    fn set_signal(&mut self, s: SignalId, value: f64) {
        AnalogSystem::set_signal(self, s, value)
    }
    fn reads_signal(&self, s: SignalId) -> bool {
        AnalogSystem::reads_signal(self, s)
    }
    fn table_times(&self) -> &[f64] {
        AnalogSystem::table_times(self)
    }
    fn above_signals(&self) -> &[SignalId] {
        AnalogSystem::above_signals(self)
    }
    fn abstol(&self, default: f64) -> Vec<f64> {
        AnalogSystem::abstol(self, default)
    }
    fn equation_site(&self, design: &Design, row: usize) -> Option<(String, Span)> {
        AnalogSystem::equation_site(self, design, row)
    }
    fn choose_states(&mut self, design: &Design, point: &[(QuantityId, f64)]) {
        AnalogSystem::choose_states(self, design, point)
    }
    fn choose_states_again(
        &mut self,
        design: &Design,
        t: f64,
        x: &[f64],
        xdot: &[f64],
    ) -> Option<Vec<f64>> {
        AnalogSystem::choose_states_again(self, design, t, x, xdot)
    }
    fn record_history(&mut self, t: f64, x: &[f64], xdot: &[f64]) {
        AnalogSystem::record_history(self, t, x, xdot)
    }
    fn shortest_delay(&self) -> Option<f64> {
        AnalogSystem::shortest_delay(self)
    }
    fn quiescent_point(
        &mut self,
        t: f64,
        guess: &[f64],
        fixed: &[(usize, f64)],
        reltol: f64,
        abstol: &[f64],
        options: &OpOptions,
    ) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
        AnalogSystem::quiescent_point(self, t, guess, fixed, reltol, abstol, options)
    }
}
