//! One BDF step: predictor, corrector, error test; and the bookkeeping after acceptance.

use super::{HIST, Transient};
use crate::newton::NonlinearProblem;
use crate::{DaeSystem, SolveError};

/// The corrector's Newton tolerance (in units of each unknown's error tolerance, maximum
/// norm) at orders 3 to 5; orders 1 and 2 use 1 (SPICE's test).
const HIGH_ORDER_NEWTON_TOL: f64 = 0.01;

/// The highest order the start-up phase raises to while it doubles the step at every step.
/// Variable-step BDF is zero-stable under a step ratio repeated at every step only up to
/// `1 + sqrt(2)` at order 2, about 1.6 at order 3 and 1.1 at order 5 (Grigorieff): doubling
/// at orders 4 and 5 grew rounding into the state (a bouncing ball's velocity, restarted at
/// an impact in steps of 1e-9 s, came out 4e-4 m/s off and its fourth impact 0.2 ms late).
/// Higher orders come from the settled estimates, where the step stays put between changes.
const STARTUP_ORDER: usize = 2;

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
pub(super) fn lagrange(tau: &[f64], t: f64, out: &mut [f64; HIST]) {
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
fn derivative_weights(tau: &[f64], out: &mut [f64; HIST]) {
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
        let k = self.step_order();
        let h = t_new - self.t;
        // Predictor.
        let p_pred;
        if self.nhist > k {
            let mut l = [0.0; HIST];
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
        let mut tau = [t_new; HIST];
        tau[1..=k].copy_from_slice(&self.hist_t[..k]);
        let mut d = [0.0; HIST];
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
        // From order 3 on the corrector is solved tighter: what Newton leaves (up to its
        // update's tolerance on a reused matrix) is noise to the divided differences that
        // choose the order, and a difference of order 6 multiplies it by about 64: at order 5
        // an exponential decay at reltol 1e-7 read its noise as growing derivatives, fell
        // back to order 1 and failed its error test there by a factor of 100.
        self.newton_opts.tol = if k >= 3 { HIGH_ORDER_NEWTON_TOL } else { 1.0 };
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
        let k = self.step_order();
        self.stats.accepted_steps += 1;
        if self.first_slot.is_some() {
            self.remember_first_step(h, err);
        }
        // Vectors move by rotating rather than copying: the oldest history vector and the old
        // `xdot_prev` become the scratch `x_new` and `xdot_new`.
        self.hist_x.rotate_right(1);
        std::mem::swap(&mut self.hist_x[0], &mut self.x_new);
        self.hist_t.rotate_right(1);
        self.hist_t[0] = t_new;
        self.nhist = (self.nhist + 1).min(HIST);
        std::mem::swap(&mut self.xdot_prev, &mut self.xdot);
        std::mem::swap(&mut self.xdot, &mut self.xdot_new);
        self.int_t0 = self.t;
        self.int_valid = true;
        self.int_alg_known = self.xdot_alg_known;
        self.int_order = k;
        self.t = t_new;
        self.steps_at_order = if k == self.order {
            self.steps_at_order + 1
        } else {
            0
        };

        let (order, factor) = self.next_order(k, err.max(1e-12));
        let mut h_next = h * factor;
        // Growth limits. Start-up: 2x per step while the order rises (IDA). Order 1 is
        // A-stable for any ratio (10x keeps the estimate meaningful); variable-step BDF2 is
        // zero-stable for ratios below 1 + sqrt(2), so 2x. From order 3 on the step changes
        // only when it must shrink (to 0.5-0.9 of itself) or can double (IDA's rule): the
        // variable-coefficient formulas of orders 3 to 5 are zero-stable for steps that stay
        // put between changes, not for a ratio drifting at every step. No growth right after a
        // failure.
        let grows = h_next > h;
        h_next = match (after_failure, self.startup, order) {
            (true, _, _) if grows => h,
            (false, true, _) if order > 1 => h_next.min(2.0 * h),
            (false, _, 1) => h_next.min(10.0 * h),
            (false, _, 2) => h_next.min(2.0 * h),
            (_, _, _) if factor >= 2.0 => 2.0 * h,
            (_, _, _) if factor >= 1.0 => h,
            (_, _, _) => h * factor.clamp(0.5, 0.9),
        };
        self.order = order;
        self.h = h_next;
        // From now on x' of every unknown comes from the BDF formula.
        self.xdot_alg_known = true;
    }

    /// The order for the next step and the step's factor over `h`, after a step of order `k`
    /// and size `h` with error norm `err`.
    ///
    /// Each order `q` near `k` is judged by `T_q`, an estimate of `||h^(q+1) x^(q+1)||`: from
    /// the divided difference of the newest `q + 2` points, `x^(q+1) = (q+1)! x[t_0..t_q+1]`.
    /// IDA's rules: in the start-up phase raise at every step; otherwise lower when the lower
    /// orders' terms are no larger (`T_1 <= T_2 / 2` at order 2, `max(T_(k-1), T_(k-2)) <=
    /// T_k` above: the higher derivatives are noise, or growing, and a lower order does as
    /// well), or after `k + 1` steps at order `k`, raise when `T_(k+1) < T_k` (`< T_k / 2`
    /// at order 1) unless `T_(k-1)` is below both. The new order's error is `C_q T_q`, with
    /// BDF's error constant `C_q`, the quantity the step's own error test measured for `q = k`
    /// (whose `err` is used as it is).
    fn next_order(&mut self, k: usize, err: f64) -> (usize, f64) {
        let max = self.opts.max_order;
        let step_factor = |q: usize, e: f64| 0.8 * e.max(1e-12).powf(-1.0 / (q as f64 + 1.0));
        if k < self.order {
            // The history is still too short for the order chosen: keep it.
            let factor = step_factor(k, err);
            self.startup &= factor >= 2.0;
            return (self.order, factor);
        }
        // Only over a history of steps at this order: a term that spans the lower orders'
        // steps of a start-up measures their larger errors, not the solution (a start-up that
        // reached order 2 fell straight back to 1 and took 4 s steps at it). Until then the
        // terms are not computed at all.
        let settled = self.steps_at_order > k;
        let (order, e) = if self.startup && k < max.min(STARTUP_ORDER) {
            // Raised without an estimate (the history spans the start-up's rising orders):
            // the step stays what the current order allows.
            (k + 1, err)
        } else if !settled {
            (k, err)
        } else {
            // After a step of order k there are at least k + 2 points.
            let t_k = self.derivative_term(k);
            let t_km1 = (k > 1).then(|| self.derivative_term(k - 1));
            let t_km2 = (k > 2).then(|| self.derivative_term(k - 2));
            let lower = match (t_km1, t_km2) {
                (Some(t1), None) => t1 <= 0.5 * t_k,
                (Some(t1), Some(t2)) => t1.max(t2) <= t_k,
                _ => false,
            };
            if lower {
                (k - 1, error_constant(k - 1) * t_km1.unwrap_or(t_k))
            } else if k >= max || self.nhist < k + 3 {
                (k, err)
            } else {
                let t_kp1 = self.derivative_term(k + 1);
                match t_km1 {
                    Some(t1) if t1 <= t_k.min(t_kp1) => (k - 1, error_constant(k - 1) * t1),
                    None if t_kp1 < 0.5 * t_k => (k + 1, error_constant(k + 1) * t_kp1),
                    Some(_) if t_kp1 < t_k => (k + 1, error_constant(k + 1) * t_kp1),
                    _ => (k, err),
                }
            }
        };
        let factor = step_factor(order, e);
        if self.startup && (factor < 2.0 || order == max) {
            self.startup = false;
        }
        if order != k {
            self.steps_at_order = 0;
        }
        (order, factor)
    }

    /// `T_q = ||h^(q+1) x^(q+1)||_w` from the newest `q + 2` points (see `next_order`), with
    /// `h` the step just taken. (Scaled by the points' own spread instead, IDA's modified
    /// divided difference, the terms after a run of doubling steps came out smaller than the
    /// next step's error and the exponential decay's error grew twofold.)
    fn derivative_term(&mut self, q: usize) -> f64 {
        let h = self.hist_t[0] - self.hist_t[1];
        let factorial: f64 = (1..=q + 1).map(|j| j as f64).product();
        factorial * h.powi(q as i32 + 1) * self.divided_difference_norm(q + 1)
    }

    /// `||x[t_0, ..., t_m]||_w`, the m-th divided difference of the newest `m + 1` points
    /// (about `x^(m) / m!`), with the weights of the newest point (which the error test of
    /// the step just accepted left in `w`).
    fn divided_difference_norm(&mut self, m: usize) -> f64 {
        // x[t_0..t_m] = sum_j x_j / prod_{l != j} (t_j - t_l): the weights depend on the times
        // only, so per unknown it is m + 1 multiply-adds.
        let t = &self.hist_t;
        let mut c = [0.0; HIST];
        for (j, c) in c.iter_mut().enumerate().take(m + 1) {
            let mut p = 1.0;
            for (l, &tl) in t.iter().enumerate().take(m + 1) {
                if l != j {
                    p *= t[j] - tl;
                }
            }
            *c = 1.0 / p;
        }
        self.scratch.fill(0.0);
        for (x, &c) in self.hist_x.iter().zip(&c).take(m + 1) {
            for (s, &x) in self.scratch.iter_mut().zip(x) {
                *s += c * x;
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

/// BDF's error constant at order `q` (fixed step): `1 / ((q + 1) (1 + 1/2 + ... + 1/q))`,
/// so that the local error is `C_q h^(q+1) x^(q+1)` (1/2, 2/9, 3/22, 12/125, 10/137).
fn error_constant(q: usize) -> f64 {
    let harmonic: f64 = (1..=q).map(|j| 1.0 / j as f64).sum();
    1.0 / ((q as f64 + 1.0) * harmonic)
}
