//! Consistent initial conditions: with the differential unknowns held at their given values,
//! solve `F(x', x, t) = 0` for `x'` of the differential unknowns and `x` of the algebraic ones.
//!
//! The Newton unknown is `z_i = x'_i` (differential `i`) or `z_i = x_i` (algebraic `i`). Its
//! Jacobian column is `dF/dx'_i` or `dF/dx_i`; the system only offers `dF/dx + alpha dF/dx'`, so
//! `dF/dx'` is taken as `J(alpha = 1) - J(alpha = 0)` (exact up to rounding when the model sums
//! the two parts, which is how the interface is defined).
//!
//! **Fallback.** Holding every differential unknown leaves that Jacobian singular when an
//! algebraic constraint ties differential unknowns together: two inductors in series (a KCL row
//! that contains only the two held currents), two inertias coupled by a gear (`v = ratio * w`
//! with `v'` and `w'` both present). Then a tiny implicit-Euler step is taken instead: solve
//! `F((x - x_start) / h, x, t) = 0` for all of `x`, a step that ends at `t` from
//! `x_start = x_held - h x'_before` (the held state taken back along the derivative it had
//! before the restart), and keep `x`: it satisfies every equation at `t`, with the sources at
//! their values at `t` (inconsistent held values are projected onto the constraints; a
//! consistent state moves by `h` times the change of its derivative only). Starting from the
//! held state itself would move a consistent state by `h x'` at every restart, time standing
//! still: a servo whose limiter restarts every few nanoseconds ran its gear 12 times too
//! fast, and the moves kept its limiter chattering. `x'` comes from a second such step from
//! there, to `t + h`, which is not kept.

use super::Transient;
use crate::newton::{Factorization, NewtonOptions, NonlinearProblem, norm2};
use crate::{DaeSystem, SolveError};

/// Newton's bound on the weighted update of the consistent initialisation.
const INIT_TOL: f64 = 0.01 * 0.33;

/// The largest contraction rate at which an update within [`INIT_TOL`] on a matrix from
/// another point ends the iteration (what is left is then about this fraction of the update;
/// a fresh matrix's quadratic convergence leaves less).
const INIT_STALE_RATE: f64 = 1e-3;

/// A mode's last consistent point (Newton's unknowns of the initialisation) and its
/// initialisation's factorisation there.
pub(super) struct Mode {
    key: u64,
    z: Vec<f64>,
    lu: Factorization,
    /// The first step to try after the next restart into this mode (0: none yet): see
    /// [`Transient::remember_first_step`].
    pub(super) first_step: f64,
}

impl Mode {
    pub(super) fn lu_pivot_searches(&self) -> usize {
        self.lu.pivot_searches()
    }
}

/// The first step after a restart into a remembered mode, as a fraction of the step the
/// first step's error allowed at the mode's previous restart. Not the whole of it: that step
/// is of order 1, from a point whose algebraic unknowns sat out its error test, and a PWM
/// bridge that took whole 20-30 us segments in one such step (1 000 points instead of 1 650)
/// drifted 1.5 times as far from ngspice, each step carrying its full tolerance. Half of it
/// splits such a segment into two steps of about equal error.
const FIRST_STEP_FRACTION: f64 = 0.5;

/// The fallback's implicit-Euler step, relative to `max(1, |t|)` seconds.
const FALLBACK_STEP: f64 = 1e-8;

/// Multiples of [`FALLBACK_STEP`] tried in turn when the step's matrix is singular.
const FALLBACK_SCALES: [f64; 3] = [1.0, 30.0, 1000.0];

/// `G(x) = F((x - x_held) / h, x, t_end)` for the differential unknowns (`x' = 0` for the
/// algebraic ones, whose derivative no equation reads); Jacobian `dF/dx + (1/h) dF/dx'`.
struct EulerProblem<'a, S: ?Sized> {
    sys: &'a mut S,
    /// The time the step ends at.
    t_end: f64,
    h: f64,
    diff: &'a [bool],
    held: &'a [f64],
    xdot: &'a mut [f64],
}

impl<S: ?Sized> EulerProblem<'_, S> {
    fn derivative(&mut self, x: &[f64]) {
        for (i, d) in self.xdot.iter_mut().enumerate() {
            *d = if self.diff[i] {
                (x[i] - self.held[i]) / self.h
            } else {
                0.0
            };
        }
    }
}

impl<S: DaeSystem + ?Sized> NonlinearProblem for EulerProblem<'_, S> {
    fn residual(&mut self, x: &[f64], out: &mut [f64]) {
        self.derivative(x);
        self.sys.residual(self.t_end, x, self.xdot, out);
    }

    fn step_limit(&mut self, x: &[f64], dx: &[f64]) -> f64 {
        self.derivative(x);
        self.sys.step_limit(self.t_end, x, self.xdot, dx)
    }

    fn jacobian(&mut self, x: &[f64], out: &mut [f64]) {
        self.derivative(x);
        self.sys
            .jacobian(self.t_end, x, self.xdot, 1.0 / self.h, out);
    }

    fn residual_scale(&self, out: &mut [f64]) -> bool {
        self.sys.residual_scale(out)
    }
}

struct InitProblem<'a, S: ?Sized> {
    pub sys: &'a mut S,
    pub t: f64,
    pub diff: &'a [bool],
    /// Held values (differential unknowns) and scratch for the assembled state.
    pub x: &'a mut [f64],
    pub xdot: &'a mut [f64],
    pub jac0: &'a mut [f64],
    /// Scratch: the `x` part of a Newton step.
    pub dx: &'a mut [f64],
}

impl<S: DaeSystem + ?Sized> InitProblem<'_, S> {
    /// Spreads `z` into `x` and `xdot`.
    fn assemble(&mut self, z: &[f64]) {
        for (i, &zi) in z.iter().enumerate() {
            if self.diff[i] {
                self.xdot[i] = zi;
            } else {
                self.x[i] = zi;
                self.xdot[i] = 0.0;
            }
        }
    }

    /// The starting `z` for the given state.
    fn z_from(&self, z: &mut [f64]) {
        for (i, zi) in z.iter_mut().enumerate() {
            *zi = if self.diff[i] {
                self.xdot[i]
            } else {
                self.x[i]
            };
        }
    }
}

impl<S: DaeSystem + ?Sized> NonlinearProblem for InitProblem<'_, S> {
    fn residual(&mut self, z: &[f64], out: &mut [f64]) {
        self.assemble(z);
        self.sys.residual(self.t, self.x, self.xdot, out);
    }

    fn step_limit(&mut self, z: &[f64], dz: &[f64]) -> f64 {
        self.assemble(z);
        for ((d, &dzi), &diff) in self.dx.iter_mut().zip(dz).zip(self.diff) {
            // Differential unknowns are held: only the algebraic ones move.
            *d = if diff { 0.0 } else { dzi };
        }
        self.sys.step_limit(self.t, self.x, self.xdot, self.dx)
    }

    fn jacobian(&mut self, z: &[f64], out: &mut [f64]) {
        self.assemble(z);
        self.sys
            .jacobian_parts(self.t, self.x, self.xdot, self.diff, out, self.jac0);
    }

    fn residual_scale(&self, out: &mut [f64]) -> bool {
        self.sys.residual_scale(out)
    }
}

impl Transient {
    /// Restarts after a discontinuity at `t` with state `x` (differential unknowns are held,
    /// the rest recomputed): order 1, a fresh small step, history forgotten.
    pub fn restart<S: DaeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
        t: f64,
        x: &[f64],
    ) -> Result<(), SolveError> {
        if x.len() != self.n {
            return Err(SolveError::InvalidSystem {
                reason: "restart state length differs from the system size",
                index: x.len(),
            });
        }
        if !t.is_finite() {
            return Err(SolveError::InvalidTime {
                t: self.t,
                requested: t,
            });
        }
        self.t = t;
        self.hist_t = [t; super::HIST];
        self.hist_x[0].copy_from_slice(x);
        self.pending.clear();
        self.consistent(sys)?;
        // A small step: the heuristic again, or what the mode's last restart found its first
        // step could be (`remember_first_step`), never more than the last step taken. The
        // heuristic's 1e-3 of the distance to the next event alone had a PWM bridge ramp
        // through steps of 30 ns, 300 ns and 3 us in each of its 20-30 us segments.
        if self.h > 0.0 {
            self.h_cap = self.h;
        }
        self.h = 0.0;
        Ok(())
    }

    pub(super) fn consistent<S: DaeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
    ) -> Result<(), SolveError> {
        let t = self.t;
        self.xdot_held.copy_from_slice(&self.xdot);
        self.xdot.fill(0.0);
        let mode = sys.mode();
        // Unknowns appearing nowhere differentiated keep x' = 0.
        let mut p = InitProblem {
            sys,
            t,
            diff: &self.diff,
            x: &mut self.hist_x[0],
            xdot: &mut self.xdot,
            jac0: &mut self.jac0,
            dx: &mut self.x_new,
        };
        p.z_from(&mut self.scratch);
        // A switching model comes back to the same mode again and again (a PWM period
        // later): that mode's last consistent point is usually much nearer than the held
        // state, whose algebraic unknowns belong to the mode just left (a diode that must
        // now conduct starts from reverse bias). Start from whichever fits better.
        let cached = mode.and_then(|m| self.modes.iter().position(|s| s.key == m));
        self.h_first = cached.map_or(0.0, |k| self.modes[k].first_step);
        self.first_slot = None;
        if let Some(k) = cached {
            p.residual(&self.scratch, &mut self.r_start);
            let held = norm2(&self.r_start);
            let z = &self.modes[k].z;
            p.residual(z, &mut self.r_start);
            let remembered = norm2(&self.r_start);
            self.stats.residual_evals += 2;
            if remembered < held {
                self.scratch.copy_from_slice(z);
            }
        }
        // No error test follows to catch an inexact start, so the update must be far inside
        // the tolerance: IDA's initial-condition test, 0.01 times the corrector's 0.33. An
        // absolute residual test would stop early on equations of tiny currents (a reverse
        // diode's 1e-8 A, whose tolerance is 1e-11): the restart point's error then feeds
        // the divided differences of the first steps, whose points are nanoseconds apart.
        // Where rounding keeps the update above the bound (`x'` of a quantity at rest beside
        // volts), the iteration stops when it stops contracting.
        //
        // A mode seen before also left its matrix, factored at its last consistent point:
        // Newton starts on it and refreshes it only where it converges too slowly, or
        // converges at a rate that leaves more than a thousandth of the update as error (a
        // PWM bridge's restarts then factor once where they factored twice, or not at all).
        let opts = NewtonOptions {
            tol: INIT_TOL,
            stall_tol: Some(1.0),
            reuse_jacobian: true,
            stale_rate: INIT_STALE_RATE,
            linear: self.newton_opts.linear,
            ..NewtonOptions::default()
        };
        match cached {
            Some(k) => self.newton.exchange(&mut self.modes[k].lu),
            None => self.newton.invalidate_jacobian(),
        }
        let solved = self
            .newton
            .solve(&mut p, &mut self.scratch, &self.newton_tol, &opts, t);
        if let Some(k) = cached {
            // The integrator's own factorisation back; the mode's stays with the mode. One
            // that took more than two iterations without a refresh has drifted from where
            // the mode's restarts now land (a motor speeding up): the next one refactors.
            self.newton.exchange(&mut self.modes[k].lu);
            if solved
                .as_ref()
                .is_ok_and(|r| r.factorizations == 0 && r.iterations > 2)
            {
                self.modes[k].lu.invalidate();
            }
        }
        match solved {
            Ok(_) => {
                if let Some(m) = mode {
                    self.first_slot = Some(self.remember_mode(m)?);
                }
                // Spread the converged z (the last residual may have been at an earlier
                // iterate).
                for i in 0..self.n {
                    if self.diff[i] {
                        self.xdot[i] = self.scratch[i];
                    } else {
                        self.hist_x[0][i] = self.scratch[i];
                        self.xdot[i] = 0.0;
                    }
                }
            }
            // Holding the state left the matrix singular, or Newton on `x'` diverged (a
            // switched diode whose current must jump: the held state is far from consistent).
            Err(SolveError::SingularJacobian { .. } | SolveError::NewtonDiverged { .. }) => {
                // The tiny step is badly conditioned (entries of 1/h beside O(1) ones); if its
                // Newton stalls in rounding, start from the held state with `x' = 0`: `x'` only
                // feeds the first predictor, and the first BDF1 step, of a size the error test
                // chooses, makes the state consistent.
                match self.euler_fallback(sys) {
                    Ok(()) => {}
                    // A singular Euler matrix is a structural defect: report it.
                    Err(e @ SolveError::SingularJacobian { .. }) => return Err(e),
                    Err(_) => {
                        // `x_pred` holds the start of the step that failed: the held state, or
                        // its projection when only the second step failed.
                        self.hist_x[0].copy_from_slice(&self.x_pred);
                        self.xdot.fill(0.0);
                    }
                }
            }
            Err(e) => return Err(e),
        }
        if let (Some(k), false) = (cached, solved.is_ok()) {
            self.modes[k].lu.invalidate();
        }
        self.newton.invalidate_jacobian();
        self.c0_factored = 0.0;
        self.forget_history();
        self.int_valid = false;
        self.xdot_alg_known = false;
        if !self.g_prev.is_empty() {
            let at = (t, self.hist_x[0].as_slice(), self.xdot.as_slice());
            Self::eval_roots(sys, &self.root_offsets, at, &mut self.g_prev);
            self.stats.root_evals += 1;
        }
        Ok(())
    }

    /// Keeps the consistent point in `scratch` as mode `m`'s (a few modes, round-robin; a
    /// slot's vectors and solver are allocated once). A new mode's slot has no factorisation
    /// yet: its next initialisation makes one in the slot's solver, so the integrator's
    /// solver, with the pivot orders it compiled for the corrector's matrices, stays the
    /// integrator's (handing it to the slot cost the headlight tracking run 4 %).
    fn remember_mode(&mut self, m: u64) -> Result<usize, SolveError> {
        const MODES: usize = 8;
        let k = match self.modes.iter().position(|s| s.key == m) {
            Some(k) => k,
            None if self.modes.len() < MODES => {
                self.modes.push(Mode {
                    key: m,
                    z: self.scratch.clone(),
                    lu: self.newton.spare()?,
                    first_step: 0.0,
                });
                self.modes.len() - 1
            }
            None => {
                let k = self.mode_next;
                self.modes[k].key = m;
                self.modes[k].lu.invalidate();
                self.modes[k].first_step = 0.0;
                self.mode_next = (self.mode_next + 1) % MODES;
                k
            }
        };
        self.modes[k].z.copy_from_slice(&self.scratch);
        Ok(k)
    }

    /// After the first step since a restart into a remembered mode was accepted (step `h`,
    /// error norm `err` at order 1): the next restart into the mode starts at
    /// [`FIRST_STEP_FRACTION`] of the step that error allows, but at most ten times this
    /// one (the order-1 growth limit).
    pub(super) fn remember_first_step(&mut self, h: f64, err: f64) {
        if let Some(k) = self.first_slot.take() {
            let allowed = h * 0.8 / err.max(1e-12).sqrt();
            self.modes[k].first_step = (FIRST_STEP_FRACTION * allowed).min(10.0 * h);
        }
    }

    /// The implicit-Euler fallback of the module documentation, in two steps: the first
    /// projects the held state onto the constraints (an inconsistent state jumps, and its
    /// difference quotient is an impulse, not a derivative); the second, from the projected
    /// state, gives `x'`. `x_pred` keeps the step's start and `x_new` is the iterate (both
    /// free during initialisation).
    fn euler_fallback<S: DaeSystem + ?Sized>(&mut self, sys: &mut S) -> Result<(), SolveError> {
        // The smallest step conditions worst (entries of m/h beside entries of 1, as with a
        // reflector mass behind a 60:1 gear): when its matrix is numerically singular, a
        // larger step usually is not; a structural defect stays singular at every step.
        let held = self.hist_x[0].clone();
        let mut result = Ok(());
        for scale in FALLBACK_SCALES {
            self.hist_x[0].copy_from_slice(&held);
            result = self.euler_fallback_with(sys, FALLBACK_STEP * scale);
            if !matches!(result, Err(SolveError::SingularJacobian { .. })) {
                break;
            }
        }
        if result.is_err() {
            self.hist_x[0].copy_from_slice(&held);
            self.x_pred.copy_from_slice(&held);
        }
        result
    }

    fn euler_fallback_with<S: DaeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
        h_rel: f64,
    ) -> Result<(), SolveError> {
        let t = self.t;
        let h = h_rel * t.abs().max(1.0);
        // `x' = dx / h`: the update must be far inside the usual tolerance for `x'` to be
        // accurate, which full Newton steps reach at once on the (locally) linear problems here.
        let opts = NewtonOptions {
            tol: 1e-3,
            linear: self.newton_opts.linear,
            ..NewtonOptions::default()
        };
        for step in 0..2 {
            self.x_pred.copy_from_slice(&self.hist_x[0]);
            self.x_new.copy_from_slice(&self.hist_x[0]);
            if step == 0 {
                for ((start, &d), &diff) in
                    self.x_pred.iter_mut().zip(&self.xdot_held).zip(&self.diff)
                {
                    if diff {
                        *start -= h * d;
                    }
                }
            }
            // The first step ends at `t` (its result is the state kept), the second at `t + h`.
            let mut p = EulerProblem {
                sys: &mut *sys,
                t_end: if step == 0 { t } else { t + h },
                h,
                diff: &self.diff,
                held: &self.x_pred,
                xdot: &mut self.xdot,
            };
            self.newton.invalidate_jacobian();
            self.newton
                .solve(&mut p, &mut self.x_new, &self.newton_tol, &opts, t)?;
            if step == 0 {
                self.hist_x[0].copy_from_slice(&self.x_new);
            }
        }
        for i in 0..self.n {
            self.xdot[i] = if self.diff[i] {
                (self.x_new[i] - self.x_pred[i]) / h
            } else {
                0.0
            };
        }
        Ok(())
    }
}
