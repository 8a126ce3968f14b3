//! Dense output on the last step and root location on it.
//!
//! The interpolant is the cubic Hermite polynomial through `(x, x')` at both ends of the step
//! (fourth-order accurate, above the integration orders 1 and 2, so interpolation adds no
//! visible error); from order 3 on it is the corrector's own polynomial through the history.
//! On the first step after a (re)start the algebraic unknowns' starting slope is unknown; they
//! use the quadratic through both end values and the end slope instead.

use super::step::lagrange;
use super::{HIST, Transient};
use crate::{DaeSystem, SolveError};

/// Hermite basis values and derivatives (per unit `s`) at `s`.
fn hermite(s: f64) -> ([f64; 4], [f64; 4]) {
    let (s2, s3) = (s * s, s * s * s);
    (
        [
            2.0 * s3 - 3.0 * s2 + 1.0,
            s3 - 2.0 * s2 + s,
            -2.0 * s3 + 3.0 * s2,
            s3 - s2,
        ],
        [
            6.0 * s2 - 6.0 * s,
            3.0 * s2 - 4.0 * s + 1.0,
            -6.0 * s2 + 6.0 * s,
            3.0 * s2 - 2.0 * s,
        ],
    )
}

impl Transient {
    /// `x(t)` for `t` inside the last accepted step (or `t` equal to the current time).
    pub fn interpolate(&self, t: f64, out: &mut [f64]) -> Result<(), SolveError> {
        self.interpolate_both(t, out, None)
    }

    /// `x(t)` and `x'(t)` for `t` inside the last accepted step (or `t` equal to the current
    /// time).
    pub fn interpolate_with_derivative(
        &self,
        t: f64,
        out: &mut [f64],
        dout: &mut [f64],
    ) -> Result<(), SolveError> {
        self.interpolate_both(t, out, Some(dout))
    }

    fn interpolate_both(
        &self,
        t: f64,
        out: &mut [f64],
        mut dout: Option<&mut [f64]>,
    ) -> Result<(), SolveError> {
        if out.len() != self.n || dout.as_ref().is_some_and(|d| d.len() != self.n) {
            return Err(SolveError::InvalidSystem {
                reason: "interpolation buffer length differs from the system size",
                index: out.len(),
            });
        }
        if t == self.t || !self.int_valid {
            if t != self.t {
                return Err(SolveError::InvalidTime {
                    t: self.t,
                    requested: t,
                });
            }
            out.copy_from_slice(&self.hist_x[0]);
            if let Some(d) = dout {
                d.copy_from_slice(&self.xdot);
            }
            return Ok(());
        }
        let (t0, t1) = (self.int_t0, self.t);
        let h = t1 - t0;
        if !(t >= t0 - 1e-12 * h && t <= t1 + 1e-12 * h) {
            return Err(SolveError::InvalidTime {
                t: self.t,
                requested: t,
            });
        }
        if self.int_order >= 3 {
            self.interpolate_polynomial(t, out, dout);
            return Ok(());
        }
        let s = (t - t0) / h;
        let (b, db) = hermite(s);
        let (x0, x1) = (&self.hist_x[1], &self.hist_x[0]);
        for i in 0..self.n {
            let (v, dv);
            if self.int_alg_known || self.diff[i] {
                let (d0, d1) = (h * self.xdot_prev[i], h * self.xdot[i]);
                v = b[0] * x0[i] + b[1] * d0 + b[2] * x1[i] + b[3] * d1;
                dv = (db[0] * x0[i] + db[1] * d0 + db[2] * x1[i] + db[3] * d1) / h;
            } else {
                // p(s) = x1 + h x1' (s - 1) + c (s - 1)^2 with p(0) = x0.
                let d1 = h * self.xdot[i];
                let c = x0[i] - x1[i] + d1;
                v = x1[i] + d1 * (s - 1.0) + c * (s - 1.0) * (s - 1.0);
                dv = (d1 + 2.0 * c * (s - 1.0)) / h;
            }
            out[i] = v;
            if let Some(d) = dout.as_deref_mut() {
                d[i] = dv;
            }
        }
        Ok(())
    }

    /// Dense output from order 3 on: the corrector's polynomial through the newest
    /// `int_order + 1` points, of the order in use (the Hermite cubic would cap the
    /// interpolant's accuracy below the step's).
    fn interpolate_polynomial(&self, t: f64, out: &mut [f64], dout: Option<&mut [f64]>) {
        let k = self.int_order;
        let nodes = &self.hist_t[..=k];
        let mut l = [0.0; HIST];
        lagrange(nodes, t, &mut l);
        // As `x_0 + sum_j l_j (x_j - x_0)` (the weights sum to 1): a quantity that holds still
        // reads back exactly, not 1.9999999999999998 for 2.
        let x0 = &self.hist_x[0];
        for (i, o) in out.iter_mut().enumerate() {
            *o = x0[i]
                + (1..=k)
                    .map(|j| l[j] * (self.hist_x[j][i] - x0[i]))
                    .sum::<f64>();
        }
        if let Some(d) = dout {
            // l_j'(t) = l_j(t) sum_{m != j} 1 / (t - t_m), written without the division by
            // l_j's own factors so that it holds at the nodes too.
            let mut dl = [0.0; HIST];
            for (j, dl) in dl.iter_mut().enumerate().take(k + 1) {
                let den: f64 = (0..=k)
                    .filter(|&m| m != j)
                    .map(|m| nodes[j] - nodes[m])
                    .product();
                let num: f64 = (0..=k)
                    .filter(|&m| m != j)
                    .map(|skip| {
                        (0..=k)
                            .filter(|&m| m != j && m != skip)
                            .map(|m| t - nodes[m])
                            .product::<f64>()
                    })
                    .sum();
                *dl = num / den;
            }
            for (i, d) in d.iter_mut().enumerate() {
                *d = (1..=k).map(|j| dl[j] * (self.hist_x[j][i] - x0[i])).sum();
            }
        }
    }

    /// Evaluates the roots at the new point; on a sign change locates the earliest crossing,
    /// rewinds the integrator to it and returns the first root to report (queueing the rest).
    pub(super) fn locate_roots<S: DaeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
    ) -> Option<(usize, bool)> {
        let m = self.g_prev.len();
        if m == 0 {
            return None;
        }
        let at = (self.t, self.hist_x[0].as_slice(), self.xdot.as_slice());
        Self::eval_roots(sys, &self.root_offsets, at, &mut self.g_new);
        self.stats.root_evals += 1;
        let crossed =
            |a: f64, b: f64| a != 0.0 && (b == 0.0 || a.signum() != b.signum() || b.is_nan());
        let (t0, t1) = (self.int_t0, self.t);
        let tol = (1e-9 * (t1 - t0)).max(4.0 * f64::EPSILON * t1.abs());
        let mut t_root = f64::INFINITY;
        for i in 0..m {
            if crossed(self.g_prev[i], self.g_new[i]) && self.g_new[i].is_finite() {
                let tr = self.illinois(sys, i, t0, self.g_prev[i], t1, self.g_new[i], tol);
                t_root = t_root.min(tr);
            }
        }
        if !t_root.is_finite() {
            self.g_prev.copy_from_slice(&self.g_new);
            return None;
        }
        if t_root < t1 {
            // Rewind: the crossing becomes the current point; the step's interpolant restricted
            // to [t0, t_root] is the same polynomial, so dense output stays valid.
            let mut x = std::mem::take(&mut self.x_new);
            let mut xd = std::mem::take(&mut self.xdot_new);
            // The interval check passes: t0 < t_root < t1 by construction.
            let ok = self.interpolate_both(t_root, &mut x, Some(&mut xd)).is_ok();
            if ok {
                self.hist_x[0].copy_from_slice(&x);
                self.xdot.copy_from_slice(&xd);
                self.hist_t[0] = t_root;
                self.t = t_root;
            }
            self.x_new = x;
            self.xdot_new = xd;
            let at = (self.t, self.hist_x[0].as_slice(), self.xdot.as_slice());
            Self::eval_roots(sys, &self.root_offsets, at, &mut self.g_new);
            self.stats.root_evals += 1;
        }
        // Report every function that has crossed by t_root, lowest index first.
        self.pending.clear();
        for i in (0..m).rev() {
            if crossed(self.g_prev[i], self.g_new[i]) {
                self.pending.push((i, self.g_prev[i] < 0.0));
            }
        }
        self.g_prev.copy_from_slice(&self.g_new);
        // The history stays: the rewound point lies on the step's interpolant, which is the
        // corrector's polynomial through the history from order 3 on (and within the order's
        // error of it below), so the next step goes on at the order in use. A crossing that
        // changes the equations restarts the integrator anyway (`restart`); one that only
        // wakes a process no longer costs a climb from order 1, whose first long steps each
        // spent the whole tolerance (a thermostat's temperature drifted 0.4 % that way).
        // The rewound point is an interpolant, not a solution: an algebraic unknown there is
        // off its equations by the interpolation error (an opamp's output, 1e5 times its
        // state), which the next step's error test would measure at every step size (err 1.54
        // as h fell from 1e-10 to 5e-14 s, until the matrix turned singular). As after a
        // restart, algebraic unknowns sit the first step's error test out.
        self.xdot_alg_known = false;
        self.pending.pop()
    }

    /// Illinois (modified regula falsi) for root function `i` on `[a, b]`; returns a time at or
    /// just past the crossing (within `tol`).
    #[allow(clippy::too_many_arguments)]
    fn illinois<S: DaeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
        i: usize,
        mut a: f64,
        mut fa: f64,
        mut b: f64,
        mut fb: f64,
        tol: f64,
    ) -> f64 {
        let mut x = std::mem::take(&mut self.scratch);
        let mut xd = std::mem::take(&mut self.xdot_tmp);
        let mut side = 0i8;
        for _ in 0..200 {
            if fb == 0.0 || b - a <= tol {
                break;
            }
            let mut c = b - fb * (b - a) / (fb - fa);
            if !(c > a && c < b) {
                c = 0.5 * (a + b);
            }
            if self.interpolate_both(c, &mut x, Some(&mut xd)).is_err() {
                break;
            }
            Self::eval_roots(sys, &self.root_offsets, (c, &x, &xd), &mut self.g_tmp);
            self.stats.root_evals += 1;
            let fc = self.g_tmp[i];
            if fc == 0.0 {
                b = c;
                break;
            }
            if fc.signum() == fb.signum() {
                b = c;
                fb = fc;
                if side == -1 {
                    fa *= 0.5;
                }
                side = -1;
            } else {
                a = c;
                fa = fc;
                if side == 1 {
                    fb *= 0.5;
                }
                side = 1;
            }
        }
        self.scratch = x;
        self.xdot_tmp = xd;
        b
    }
}
