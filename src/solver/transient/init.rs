//! Consistent initial conditions: with the differential unknowns held at their given values,
//! solve `F(x', x, t) = 0` for `x'` of the differential unknowns and `x` of the algebraic ones.
//!
//! The Newton unknown is `z_i = x'_i` (differential `i`) or `z_i = x_i` (algebraic `i`). Its
//! Jacobian column is `dF/dx'_i` or `dF/dx_i`; the system only offers `dF/dx + alpha dF/dx'`, so
//! `dF/dx'` is taken as `J(alpha = 1) - J(alpha = 0)` (exact up to rounding when the model sums
//! the two parts, which is how the interface is defined).

use crate::solver::DaeSystem;
use crate::solver::newton::NonlinearProblem;

pub(super) struct InitProblem<'a, S: ?Sized> {
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
    pub fn z_from(&self, z: &mut [f64]) {
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
