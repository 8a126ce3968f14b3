//! One BDF step: predictor, corrector, error test; and the bookkeeping after acceptance.

use super::Transient;
use crate::solver::newton::NonlinearProblem;
use crate::solver::{DaeSystem, SolveError};

pub(super) enum Attempt {
    Accepted {
        err: f64,
    },
    ErrorTest {
        err: f64,
        worst: usize,
    },
    /// `stale`: the corrector ran on a factorisation from an earlier step, so a retry with a
    /// fresh Jacobian at the same step size comes before shrinking the step.
    NewtonFailed {
        err: SolveError,
        stale: bool,
    },
}

/// `G(x) = F(t, x, c0 x + beta)`, Jacobian `dF/dx + c0 dF/dx'`.
struct Corrector<'a, S: ?Sized> {
    sys: &'a mut S,
    diff: &'a [bool],
    t: f64,
    c0: f64,
    beta: &'a [f64],
    xdot: &'a mut [f64],
}

impl<S: ?Sized> Corrector<'_, S> {
    fn derivative(&mut self, x: &[f64]) {
        for ((d, &x), &b) in self.xdot.iter_mut().zip(x).zip(self.beta) {
            *d = self.c0 * x + b;
        }
    }
}

impl<S: DaeSystem + ?Sized> NonlinearProblem for Corrector<'_, S> {
    fn residual(&mut self, x: &[f64], out: &mut [f64]) {
        self.derivative(x);
        self.sys.residual(self.t, x, self.xdot, out);
    }
    fn jacobian(&mut self, x: &[f64], out: &mut [f64]) {
        self.derivative(x);
        self.sys.jacobian(self.t, x, self.xdot, self.c0, out);
    }
    fn step_limit(&mut self, x: &[f64], dx: &[f64]) -> f64 {
        self.derivative(x);
        self.sys.step_limit(self.t, x, self.xdot, dx)
    }
    fn residual_scale(&self, out: &mut [f64]) -> bool {
        self.sys.residual_scale(out)
    }
    /// A differential unknown's change measured as the change of its derivative, `c0` times
    /// larger: the columns then tend to `dF/dx'` as the step shrinks, which an index-1
    /// system keeps regular however small the step.
    fn rescale_units(&self, units: &mut [f64]) -> bool {
        if self.c0 <= 1.0 {
            return false;
        }
        for (u, &d) in units.iter_mut().zip(self.diff) {
            if d {
                *u /= self.c0;
            }
        }
        true
    }
}

/// Lagrange weights at `t` for nodes `tau` (`l_j(t)`), written into `out[..tau.len()]`.
fn lagrange(tau: &[f64], t: f64, out: &mut [f64; 4]) {
    for j in 0..tau.len() {
        let mut l = 1.0;
        for m in 0..tau.len() {
            if m != j {
                l *= (t - tau[m]) / (tau[j] - tau[m]);
            }
        }
        out[j] = l;
    }
}

/// Derivative weights at `tau[0]` of the Lagrange basis on `tau` (`l_j'(tau_0)`).
fn derivative_weights(tau: &[f64], out: &mut [f64; 4]) {
    let t0 = tau[0];
    out[0] = tau[1..].iter().map(|&tm| 1.0 / (t0 - tm)).sum();
    for j in 1..tau.len() {
        let mut num = 1.0;
        let mut den = 1.0;
        for m in 0..tau.len() {
            if m != j {
                den *= tau[j] - tau[m];
                if m != 0 {
                    num *= t0 - tau[m];
                }
            }
        }
        out[j] = num / den;
    }
}

impl Transient {
    /// Predicts, corrects and tests one step from `self.t` to `t_new` at `self.order`.
    pub(super) fn try_step<S: DaeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
        t_new: f64,
    ) -> Result<Attempt, SolveError> {
        let k = if self.nhist > self.order {
            self.order
        } else {
            1
        };
        let h = t_new - self.t;
        // Predictor.
        let p_pred;
        if self.nhist > k {
            let mut l = [0.0; 4];
            lagrange(&self.hist_t[..=k], t_new, &mut l);
            for i in 0..self.n {
                self.x_pred[i] = (0..=k).map(|j| l[j] * self.hist_x[j][i]).sum();
            }
            p_pred = self.hist_t[..=k]
                .iter()
                .map(|&tj| t_new - tj)
                .product::<f64>();
        } else {
            for i in 0..self.n {
                self.x_pred[i] = self.hist_x[0][i] + h * self.xdot[i];
            }
            p_pred = h * h;
        }
        // Corrector coefficients on nodes (t_new, t_n, ..., t_{n-k+1}).
        let mut tau = [t_new; 4];
        tau[1..=k].copy_from_slice(&self.hist_t[..k]);
        let mut d = [0.0; 4];
        derivative_weights(&tau[..=k], &mut d);
        let c0 = d[0];
        for i in 0..self.n {
            self.beta[i] = (1..=k).map(|j| d[j] * self.hist_x[j - 1][i]).sum();
        }
        let p_corr = self.hist_t[..k]
            .iter()
            .map(|&tj| t_new - tj)
            .product::<f64>()
            / c0;
        let ratio = p_corr / (p_pred + p_corr);

        if self.c0_factored == 0.0 || (c0 / self.c0_factored - 1.0).abs() > 0.25 {
            self.newton.invalidate_jacobian();
            self.c0_factored = 0.0;
        }
        self.newton_opts.stale_scale = if self.c0_factored > 0.0 {
            2.0 / (1.0 + c0 / self.c0_factored)
        } else {
            1.0
        };
        self.x_new.copy_from_slice(&self.x_pred);
        let mut corr = Corrector {
            sys,
            diff: &self.diff,
            t: t_new,
            c0,
            beta: &self.beta,
            xdot: &mut self.xdot_new,
        };
        let solved = self.newton.solve(
            &mut corr,
            &mut self.x_new,
            &self.newton_tol,
            &self.newton_opts,
            t_new,
        );
        let rep = match solved {
            Ok(rep) => rep,
            Err(e @ SolveError::InvalidSystem { .. }) => return Err(e),
            Err(err) => {
                // A solve that began on a reused Jacobian is retried at the same step with a
                // fresh one before the step is cut (IDA's rule), even if it refreshed the
                // matrix midway: four iterations split between two matrices are not a fair
                // trial of the step.
                let stale = self.c0_factored != 0.0;
                return Ok(Attempt::NewtonFailed { err, stale });
            }
        };
        corr.derivative(&self.x_new);
        if rep.factorizations > 0 {
            self.c0_factored = c0;
        }

        // Error test; algebraic unknowns sit it out on the first step after a (re)start, where
        // their predictor (constant) is only first-order.
        self.tol.weights(&self.x_new, &mut self.w);
        let skip_alg = !self.xdot_alg_known;
        for i in 0..self.n {
            let e = ratio * (self.x_new[i] - self.x_pred[i]);
            let tested = self.tested[i] && (self.diff[i] || !skip_alg);
            self.scratch[i] = if tested { e } else { 0.0 };
        }
        let err = self.tol.norm(&self.scratch, &self.w);
        if err <= 1.0 {
            return Ok(Attempt::Accepted { err });
        }
        let worst = (0..self.n)
            .map(|i| (self.scratch[i] * self.w[i]).abs())
            .enumerate()
            .fold((0, -1.0), |a, b| if b.1 > a.1 { b } else { a })
            .0;
        // A NaN error norm must not pass as "not greater than 1".
        Ok(Attempt::ErrorTest {
            err: if err.is_nan() { 1e10 } else { err },
            worst,
        })
    }

    /// Commits the step to `t_new` and picks the next step size and order.
    pub(super) fn accept<S: DaeSystem + ?Sized>(
        &mut self,
        _sys: &mut S,
        t_new: f64,
        h: f64,
        err: f64,
        after_failure: bool,
    ) {
        let k = if self.nhist > self.order {
            self.order
        } else {
            1
        };
        self.stats.accepted_steps += 1;
        if self.first_slot.is_some() {
            self.remember_first_step(h, err);
        }
        // Vectors move by swapping rather than copying: the oldest history vector and the old
        // `xdot_prev` become the scratch `x_new` and `xdot_new`.
        self.hist_x.swap(2, 3);
        self.hist_x.swap(1, 2);
        self.hist_x.swap(0, 1);
        std::mem::swap(&mut self.hist_x[0], &mut self.x_new);
        self.hist_t.rotate_right(1);
        self.hist_t[0] = t_new;
        self.nhist = (self.nhist + 1).min(4);
        std::mem::swap(&mut self.xdot_prev, &mut self.xdot);
        std::mem::swap(&mut self.xdot, &mut self.xdot_new);
        self.int_t0 = self.t;
        self.int_valid = true;
        self.int_alg_known = self.xdot_alg_known;
        self.t = t_new;

        // Candidate steps per order, uncapped: from the error estimate for the order used, from
        // divided differences for the other one. Switching needs a 20% gain.
        // err^(-1/(k+1)) by sqrt and cbrt: `powf` costs several times more.
        let err = err.max(1e-12);
        let shrink = if k == 1 { err.sqrt() } else { err.cbrt() };
        let mut h_next = h * 0.8 / shrink;
        let mut order = k;
        if k == 1 && self.opts.max_order >= 2 && self.nhist >= 4 {
            let d3 = self.divided_difference_norm(3);
            let h2 = 0.8 * (0.75 / d3.max(1e-300)).cbrt();
            if h2 > 1.2 * h_next {
                order = 2;
                h_next = h2;
            }
        } else if k == 2 {
            let d2 = self.divided_difference_norm(2);
            let h1 = 0.8 / d2.max(1e-300).sqrt();
            if h1 > 1.2 * h_next {
                order = 1;
                h_next = h1;
            }
        }
        // Growth limits: BDF1 is A-stable for any ratio (10x keeps the estimate meaningful);
        // variable-step BDF2 is zero-stable for ratios below 1 + sqrt(2), so 2x. No growth
        // right after a failure.
        let growth = match (after_failure, order) {
            (true, _) => 1.0,
            (false, 1) => 10.0,
            (false, _) => 2.0,
        };
        h_next = h_next.min(growth * h);
        self.order = order;
        self.h = h_next;
        // From now on x' of every unknown comes from the BDF formula.
        self.xdot_alg_known = true;
    }

    /// `||x[t_0, ..., t_m]||_w`, the m-th divided difference of the newest `m + 1` points
    /// (about `x^(m) / m!`), with the weights of the newest point (which the error test of
    /// the step just accepted left in `w`).
    fn divided_difference_norm(&mut self, m: usize) -> f64 {
        // x[t_0..t_m] = sum_j x_j / prod_{l != j} (t_j - t_l): the weights depend on the times
        // only, so per unknown it is m + 1 multiply-adds.
        let t = &self.hist_t;
        let mut c = [0.0; 4];
        for (j, c) in c.iter_mut().enumerate().take(m + 1) {
            let mut p = 1.0;
            for (l, &tl) in t.iter().enumerate().take(m + 1) {
                if l != j {
                    p *= t[j] - tl;
                }
            }
            *c = 1.0 / p;
        }
        let [x0, x1, x2, x3] = &self.hist_x;
        let (x0, x1, x2, x3) = (&x0[..self.n], &x1[..self.n], &x2[..self.n], &x3[..self.n]);
        if m == 2 {
            for (i, s) in self.scratch.iter_mut().enumerate() {
                *s = c[0] * x0[i] + c[1] * x1[i] + c[2] * x2[i];
            }
        } else {
            for (i, s) in self.scratch.iter_mut().enumerate() {
                *s = c[0] * x0[i] + c[1] * x1[i] + c[2] * x2[i] + c[3] * x3[i];
            }
        }
        for (s, &tested) in self.scratch.iter_mut().zip(&self.tested) {
            *s = if tested { *s } else { 0.0 };
        }
        debug_assert!({
            let mut w = self.w.clone();
            self.tol.weights(&self.hist_x[0], &mut w);
            w == self.w
        });
        self.tol.norm(&self.scratch, &self.w)
    }
}
