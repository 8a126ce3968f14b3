//! Consistent initial conditions: with the differential unknowns held at their given values,
//! solve `F(x', x, t) = 0` for `x'` of the differential unknowns and `x` of the algebraic ones.
//!
//! The Newton unknown is `z_i = x'_i` (differential `i`) or `z_i = x_i` (algebraic `i`). Its
//! Jacobian column is `dF/dx'_i` or `dF/dx_i`; the system only offers `dF/dx + alpha dF/dx'`, so
//! `dF/dx'` is taken as `J(alpha = 1) - J(alpha = 0)` (exact up to rounding when the model sums
//! the two parts, which is how the interface is defined).

use super::Transient;
use crate::solver::newton::{NewtonOptions, NonlinearProblem};
use crate::solver::{DaeSystem, SolveError};

struct InitProblem<'a, S: ?Sized> {
    pub sys: &'a mut S,
    pub t: f64,
    pub diff: &'a [bool],
    /// Held values (differential unknowns) and scratch for the assembled state.
    pub x: &'a mut [f64],
    pub xdot: &'a mut [f64],
    /// Column of each pattern entry.
    pub cols: &'a [usize],
    pub jac0: &'a mut [f64],
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

    fn jacobian(&mut self, z: &[f64], out: &mut [f64]) {
        self.assemble(z);
        self.sys.jacobian(self.t, self.x, self.xdot, 0.0, self.jac0);
        self.sys.jacobian(self.t, self.x, self.xdot, 1.0, out);
        for ((o, &j0), &c) in out.iter_mut().zip(self.jac0.iter()).zip(self.cols) {
            if !self.diff[c] {
                *o = j0;
            } else {
                *o -= j0;
            }
        }
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
        self.hist_t = [t; 4];
        self.hist_x[0].copy_from_slice(x);
        self.pending.clear();
        self.consistent(sys)?;
        // A small step: the heuristic again, never more than the last step taken.
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
        self.xdot.fill(0.0);
        // Unknowns appearing nowhere differentiated keep x' = 0.
        let mut p = InitProblem {
            sys,
            t,
            diff: &self.diff,
            x: &mut self.hist_x[0],
            xdot: &mut self.xdot,
            cols: &self.cols,
            jac0: &mut self.jac0,
        };
        p.z_from(&mut self.scratch);
        let opts = NewtonOptions {
            residual_tol: Some(1e-12),
            ..NewtonOptions::default()
        };
        self.newton.invalidate_jacobian();
        self.newton
            .solve(&mut p, &mut self.scratch, &self.tol, &opts, t)?;
        // Spread the converged z (the last residual may have been at an earlier iterate).
        for i in 0..self.n {
            if self.diff[i] {
                self.xdot[i] = self.scratch[i];
            } else {
                self.hist_x[0][i] = self.scratch[i];
                self.xdot[i] = 0.0;
            }
        }
        self.newton.invalidate_jacobian();
        self.c0_factored = 0.0;
        self.order = 1;
        self.nhist = 1;
        self.int_valid = false;
        self.xdot_alg_known = false;
        if !self.g_prev.is_empty() {
            sys.roots(t, &self.hist_x[0], &mut self.g_prev);
            self.stats.root_evals += 1;
        }
        Ok(())
    }
}
