//! Variable-step, variable-order (1 to 5) BDF integration of a [`DaeSystem`].
//!
//! **Method.** Variable-coefficient BDF: the corrector's `x'_{n+1}` is the derivative at
//! `t_{n+1}` of the polynomial through the new point and the last `k` accepted points (no
//! interpolation onto a fixed grid, so step changes cost nothing). The predictor extrapolates
//! the last `k + 1` accepted points (or `x_n + h x'_n` right after a (re)start). The local
//! truncation error comes from Milne's device with the exact variable-step constants:
//! `LTE = (P_c/a) / (P_p + P_c/a) * (x_corr - x_pred)`, `P_c = prod_{j<k} (t_{n+1} - t_{n-j})`,
//! `P_p = prod_{j<=k} (t_{n+1} - t_{n-j})`, `a` the corrector's leading coefficient. A step is
//! accepted when `||LTE||_w <= 1` over the unknowns the system does not exempt
//! ([`DaeSystem::error_exempt`]). The corrector's Newton has converged when every unknown's
//! last update is within its own tolerance (the maximum norm, SPICE's test, whatever the error
//! test's norm: a root-mean-square over a thousand quiet unknowns let the few that move carry
//! thirty times theirs; a hundredth of it from order 3 on, see `step`) and every residual is
//! within its equation's tolerance.
//!
//! **Order and step** follow IDA: after a (re)start the order rises by one per step and the
//! step doubles until the error estimate no longer allows it; then orders `k - 1`, `k`, `k + 1`
//! are compared by divided differences of the history (`next_order`), a raise waiting for
//! `k + 1` steps at order `k`. Growth is at most 10x per step at order 1, 2x at order 2 (BDF2
//! stays zero-stable below 2.41x); from order 3 on the step only doubles or shrinks to
//! 0.5-0.9 of itself. An error-test failure above order 2 drops one order, a third failure
//! falls back to order 1.
//! Jacobians are reused across steps while `alpha` stays within 25% (updates scaled by IDA's
//! `2 / (1 + alpha/alpha_old)`); a corrector on a stale matrix refreshes it as soon as its
//! contraction rate could not reach the tolerance in the iterations left, and a failure that
//! began on a stale matrix retries the same step with a fresh one before the step is cut by 4.
//!
//! **Events.** Breakpoints and `t_out` are landed on exactly (the step is stretched or split so
//! no sliver remains). After each accepted step the root functions are evaluated; a sign change
//! is located by the Illinois method on the cubic Hermite interpolant of the step, and the
//! integrator is rewound to the crossing. After a breakpoint or a root, BDF history restarts at
//! order 1. The first step after a restart is IDA's heuristic (`initial_step`), or, in a mode
//! ([`DaeSystem::mode`]) restarted into before, half the step that the first step's error
//! allowed there (at most ten times that step), never more than the step before the restart.
//!
//! **Memory.** Every vector is allocated in [`Transient::new`]; `advance` does not allocate.

mod init;
mod roots;
mod step;
mod types;

use super::newton::{ErrorNorm, Newton, NewtonOptions, Tolerances};
use super::{DaeSystem, SolveError};
pub use types::{Advance, Stats, TransientOptions, local_reltol};

/// The BDF integrator's state. See the module documentation for the method.
pub struct Transient {
    n: usize,
    tol: Tolerances,
    /// The same tolerances under the maximum norm, for Newton's convergence test: every
    /// unknown's update within its own tolerance (the error test keeps `tol`'s norm).
    newton_tol: Tolerances,
    opts: TransientOptions,
    newton_opts: NewtonOptions,
    newton: Newton,
    diff: Vec<bool>,
    /// Unknowns the error test and the order selection count (all but the system's
    /// [`DaeSystem::error_exempt`] ones).
    tested: Vec<bool>,
    t: f64,
    /// Step to try next; 0 until the first `advance` picks one.
    h: f64,
    /// The order to use; a step uses less while the history is too short for it.
    order: usize,
    /// Accepted steps in a row taken at the order the last one used (raising the order waits
    /// for `k + 1` of them, as IDA does, so the estimates behind it span steps of order `k`).
    steps_at_order: usize,
    /// Since the last (re)start and until the first failed step or the first step the error
    /// estimate does not let double: the order rises by one per step and the step may double
    /// (IDA's start-up phase), so the low-order steps of a restart stay few and short.
    startup: bool,
    /// Accepted points, newest first; `hist_x[0]` is the current state.
    hist_t: [f64; HIST],
    hist_x: [Vec<f64>; HIST],
    nhist: usize,
    /// The order of the last accepted step: dense output on it is the corrector's polynomial
    /// through the newest `int_order + 1` points (above order 2).
    int_order: usize,
    /// `x'` at `t` and at the start of the last step.
    xdot: Vec<f64>,
    xdot_prev: Vec<f64>,
    /// The last step `[int_t0, t]` for dense output; `x(int_t0) = hist_x[1]`.
    int_t0: f64,
    int_valid: bool,
    /// False when algebraic `x'` at `int_t0` is unknown (first step after a (re)start).
    xdot_alg_known: bool,
    /// `xdot_alg_known` as it was at the start of the last step.
    int_alg_known: bool,
    /// Upper bound for the first step after a restart (the last step taken).
    h_cap: f64,
    /// The first step after this restart, from the mode's memory (0: none; see
    /// `init::Mode::first_step`).
    h_first: f64,
    /// The slot in `modes` of the mode the last consistent initialisation was made in, while
    /// the first step after it is still to be accepted.
    first_slot: Option<usize>,
    c0_factored: f64,
    x_pred: Vec<f64>,
    x_new: Vec<f64>,
    xdot_new: Vec<f64>,
    beta: Vec<f64>,
    w: Vec<f64>,
    scratch: Vec<f64>,
    jac0: Vec<f64>,
    g_prev: Vec<f64>,
    g_new: Vec<f64>,
    g_tmp: Vec<f64>,
    /// Per root function, a constant added to the system's value before any sign test: the
    /// caller's hysteresis (see [`Transient::set_root_offset`]).
    root_offsets: Vec<f64>,
    /// Scratch: `x'` of the dense output where root functions are evaluated.
    xdot_tmp: Vec<f64>,
    /// `x'` just before a restart, where the implicit-Euler fallback of the consistent
    /// initialisation starts its step (see `init`).
    xdot_held: Vec<f64>,
    /// Roots found at `t` still to be reported, last to report first.
    pending: Vec<(usize, bool)>,
    /// Breakpoints ahead, sorted descending (the next one is last).
    breakpoints: Vec<f64>,
    /// The last consistent point of each of the last few modes ([`DaeSystem::mode`]) and
    /// the factorisation there, replaced round-robin from `mode_next`.
    modes: Vec<init::Mode>,
    mode_next: usize,
    /// Scratch: residuals of the two starting points a restart compares.
    r_start: Vec<f64>,
    stats: Stats,
}

/// The highest BDF order (IDA's and DASSL's too: BDF6 and above are not zero-stable).
pub const MAX_ORDER: usize = 5;

/// Accepted points kept: order `k` needs `k + 1` for its predictor, and the estimate that
/// decides a raise from `MAX_ORDER - 1` a divided difference over `MAX_ORDER + 2`.
const HIST: usize = MAX_ORDER + 2;

/// Newton failures (fresh Jacobian) in one step after which the step's Newton is damped.
const RESCUE_AFTER: usize = 3;

impl Transient {
    /// Sets up the integrator at `(t0, x0)` and computes consistent initial values: algebraic
    /// unknowns and `x'` of the differential ones, with the differential unknowns held.
    pub fn new<S: DaeSystem + ?Sized>(
        sys: &mut S,
        t0: f64,
        x0: &[f64],
        options: TransientOptions,
    ) -> Result<Self, SolveError> {
        let n = sys.len();
        let check = |ok: bool, reason: &'static str, index: usize| {
            if ok {
                Ok(())
            } else {
                Err(SolveError::InvalidSystem { reason, index })
            }
        };
        check(
            x0.len() == n,
            "initial state length differs from the system size",
            x0.len(),
        )?;
        check(
            sys.differential().len() == n,
            "differential flags length differs",
            n,
        )?;
        check(t0.is_finite(), "initial time is not finite", 0)?;
        let per = &options.abstol_per_unknown;
        check(
            per.is_empty() || per.len() == n,
            "abstol_per_unknown length differs",
            n,
        )?;
        check(
            (1..=MAX_ORDER).contains(&options.max_order),
            "max_order must be between 1 and 5",
            options.max_order,
        )?;
        check(
            options.reltol >= 0.0 && (options.abstol > 0.0 || !per.is_empty()),
            "tolerances must be positive",
            0,
        )?;
        let tol = Tolerances {
            reltol: options.reltol,
            abstol: if per.is_empty() {
                vec![options.abstol; n]
            } else {
                per.clone()
            },
            norm: options.norm,
        };
        let pattern = sys.pattern();
        let newton = Newton::new(n, pattern, options.linear)?;
        let jac0 = vec![0.0; pattern.len()];
        let m = sys.root_count();
        let v = || vec![0.0; n];
        let newton_tol = Tolerances {
            norm: ErrorNorm::Max,
            ..tol.clone()
        };
        let mut this = Self {
            n,
            tol,
            newton_tol,
            newton_opts: NewtonOptions {
                max_iter: 4,
                tol: 1.0,
                residual_tol: None,
                stall_tol: None,
                line_search: false,
                reuse_jacobian: true,
                max_rate: 0.9,
                stale_scale: 1.0,
                check_residual: true,
                linear: sys.is_linear(),
                stale_rate: 1.0,
            },
            newton,
            diff: sys.differential().to_vec(),
            tested: (0..n)
                .map(|i| !sys.error_exempt().get(i).copied().unwrap_or(false))
                .collect(),
            t: t0,
            h: 0.0,
            order: 1,
            steps_at_order: 0,
            startup: true,
            hist_t: [t0; HIST],
            hist_x: std::array::from_fn(|j| if j == 0 { x0.to_vec() } else { v() }),
            nhist: 1,
            int_order: 1,
            xdot: v(),
            xdot_prev: v(),
            int_t0: t0,
            int_valid: false,
            xdot_alg_known: false,
            int_alg_known: false,
            h_cap: f64::INFINITY,
            h_first: 0.0,
            first_slot: None,
            c0_factored: 0.0,
            x_pred: v(),
            x_new: v(),
            xdot_new: v(),
            beta: v(),
            w: v(),
            scratch: v(),
            jac0,
            g_prev: vec![0.0; m],
            g_new: vec![0.0; m],
            g_tmp: vec![0.0; m],
            root_offsets: vec![0.0; m],
            xdot_tmp: vec![0.0; n],
            xdot_held: vec![0.0; n],
            pending: Vec::with_capacity(m),
            breakpoints: Vec::new(),
            modes: Vec::new(),
            mode_next: 0,
            r_start: v(),
            stats: Stats::default(),
            opts: options,
        };
        this.consistent(sys)?;
        Ok(this)
    }

    /// Demands that a step end exactly at `t` (ignored if `t` is not ahead).
    pub fn add_breakpoint(&mut self, t: f64) {
        if t.is_finite() && t > self.t && !self.breakpoints.contains(&t) {
            let at = self.breakpoints.partition_point(|&b| b > t);
            self.breakpoints.insert(at, t);
        }
    }

    /// Demands that steps end exactly at each of `times` (increasing) that lies ahead.
    pub fn add_breakpoints(&mut self, times: &[f64]) {
        let ahead = times
            .iter()
            .copied()
            .filter(|t| t.is_finite() && *t > self.t);
        self.breakpoints.extend(ahead);
        // Kept in decreasing order: the next one is the last.
        self.breakpoints.sort_by(|a, b| b.total_cmp(a));
        self.breakpoints.dedup();
    }

    pub fn time(&self) -> f64 {
        self.t
    }

    /// Adds `offset` to root function `i` from now on (replacing the previous one): the
    /// integrator then locates the zeros of `g_i + offset`. A caller that reports a crossing
    /// only once its function is a band past zero, on the side away from the current state,
    /// gets hysteresis (see `kernel::cycle`).
    pub fn set_root_offset(&mut self, i: usize, offset: f64) {
        if let (Some(o), Some(g)) = (self.root_offsets.get_mut(i), self.g_prev.get_mut(i)) {
            *g += offset - *o;
            *o = offset;
        }
    }

    /// The offset of root function `i` ([`Transient::set_root_offset`]), 0 by default.
    pub fn root_offset(&self, i: usize) -> f64 {
        self.root_offsets.get(i).copied().unwrap_or(0.0)
    }

    /// The system's root functions at `(t, x, x')` with their offsets, into `out`.
    pub(super) fn eval_roots<S: DaeSystem + ?Sized>(
        sys: &mut S,
        offsets: &[f64],
        (t, x, xdot): (f64, &[f64], &[f64]),
        out: &mut [f64],
    ) {
        sys.roots(t, x, xdot, out);
        for (g, o) in out.iter_mut().zip(offsets) {
            *g += o;
        }
    }

    /// The state `x` at [`Self::time`].
    pub fn state(&self) -> &[f64] {
        &self.hist_x[0]
    }

    /// `x'` at [`Self::time`] (zero for algebraic unknowns right after a (re)start).
    pub fn derivative(&self) -> &[f64] {
        &self.xdot
    }

    /// Where the last accepted step began, while dense output covers it (`None` right after
    /// a start or restart).
    pub fn last_step_start(&self) -> Option<f64> {
        self.int_valid.then_some(self.int_t0)
    }

    /// The step the integrator will try next (0 before the first `advance`).
    pub fn step_size(&self) -> f64 {
        self.h
    }

    pub fn order(&self) -> usize {
        self.order
    }

    /// Work counters; the Newton figures include failed corrector attempts.
    pub fn stats(&self) -> Stats {
        let newton = self.newton.totals();
        Stats {
            newton_iterations: newton.iterations,
            factorizations: newton.factorizations,
            pivot_searches: self.newton.pivot_searches()
                + self
                    .modes
                    .iter()
                    .map(|m| m.lu_pivot_searches())
                    .sum::<usize>(),
            residual_evals: newton.residual_evals + self.stats.residual_evals,
            ..self.stats
        }
    }

    /// Starts the BDF history afresh at the current point: order 1, start-up phase.
    fn forget_history(&mut self) {
        self.order = 1;
        self.nhist = 1;
        self.steps_at_order = 0;
        self.startup = true;
    }

    /// The order the next step uses: `self.order`, unless the history is too short (order
    /// `k` extrapolates `k + 1` accepted points).
    fn step_order(&self) -> usize {
        self.order.min(self.nhist.saturating_sub(1)).max(1)
    }

    /// First step: `0.001 * (t_out - t)`, shrunk so that `||h x'||_w <= 0.5` (IDA's heuristic).
    fn initial_step(&mut self, t_out: f64) -> f64 {
        if let Some(h) = self.opts.initial_step {
            return h;
        }
        let mut h = 1e-3 * (t_out - self.t);
        self.tol.weights(&self.hist_x[0], &mut self.w);
        let nd = self.tol.norm(&self.xdot, &self.w);
        if h * nd > 0.5 {
            h = 0.5 / nd;
        }
        // Never below what the time axis resolves where the run stands. The stop time plays
        // no part beyond the 1e-3 above: a step floor scaled by it (`--stop 1e30s`) jumped
        // over everything the model does in its first seconds.
        h.max(64.0 * self.min_step())
    }

    /// The step floor: the option, but never below 16 ulp of the current time.
    fn min_step(&self) -> f64 {
        self.opts.min_step.max(16.0 * f64::EPSILON * self.t.abs())
    }

    /// Takes at most one step towards `t_out` (landing on it exactly) and reports the outcome.
    pub fn advance<S: DaeSystem + ?Sized>(
        &mut self,
        sys: &mut S,
        t_out: f64,
    ) -> Result<Advance, SolveError> {
        if let Some((index, rising)) = self.pending.pop() {
            return Ok(Advance::Root {
                t: self.t,
                index,
                rising,
            });
        }
        if t_out.is_nan() || t_out < self.t {
            return Err(SolveError::InvalidTime {
                t: self.t,
                requested: t_out,
            });
        }
        // Targets a few hundred ulp away cannot be stepped to (the step's time differences
        // would carry percent-level rounding, and the error test fails at every size): they
        // count as reached. Event times that accumulate rounding land that close to a round
        // stop time (a 20 kHz PWM ends 2.4e-16 s short of 20 ms).
        let ulps = 16.0 * f64::EPSILON * self.t.abs().max(t_out.abs());
        if t_out - self.t <= (64.0 * ulps).max(self.min_step()) {
            self.t = t_out;
            self.hist_t[0] = t_out;
            return Ok(Advance::Reached(self.t));
        }
        while self.breakpoints.last().is_some_and(|&b| b <= self.t + ulps) {
            self.breakpoints.pop();
        }
        if self.h.is_nan() || self.h <= 0.0 {
            let h0 = self.initial_step(t_out).max(self.h_first);
            self.h = h0.min(self.opts.max_step).min(self.h_cap);
        }
        let mut last_err: Option<SolveError> = None;
        let mut failures = 0usize;
        let mut newton_failures = 0usize;
        loop {
            let bp = self.breakpoints.last().copied().unwrap_or(f64::INFINITY);
            let stop = t_out.min(bp);
            let mut h = self.h.min(self.opts.max_step);
            let t_new = if self.t + h >= stop {
                h = stop - self.t;
                stop
            } else if self.t + 1.5 * h > stop {
                h = 0.5 * (stop - self.t);
                self.t + h
            } else {
                self.t + h
            };
            if h.is_nan() || h < self.min_step() || t_new <= self.t {
                return Err(last_err.unwrap_or(SolveError::StepTooSmall {
                    t: self.t,
                    step: h,
                    worst_unknown: 0,
                }));
            }
            // After repeated Newton failures (a diode switching on from far away, where
            // undamped Newton overshoots on the exponential however small the step), damp
            // the iteration and give it more room; the fast undamped mode resumes afterwards.
            let rescue = newton_failures >= RESCUE_AFTER;
            self.newton_opts.line_search = rescue;
            self.newton_opts.max_iter = if rescue { 30 } else { 4 };
            match self.try_step(sys, t_new)? {
                step::Attempt::Accepted { err } => {
                    self.newton_opts.line_search = false;
                    self.newton_opts.max_iter = 4;
                    self.accept(sys, t_new, h, err, failures > 0);
                    break;
                }
                step::Attempt::ErrorTest { err, worst } => {
                    self.stats.rejected_steps += 1;
                    failures += 1;
                    self.startup = false;
                    let k = self.step_order() as f64;
                    let mut fac = (0.8 * err.powf(-1.0 / (k + 1.0))).clamp(0.1, 0.9);
                    if failures >= 2 {
                        fac = fac.min(0.25);
                    }
                    self.h = h * fac;
                    // Above order 2, a failed step drops one order (its estimate of the next
                    // derivative up is the first to go wrong where the solution turns), and
                    // only a third failure falls back to order 1 (IDA's rules): a fall from
                    // order 5 to 1 at the step that order 5 could nearly take cost a
                    // sine's waveform 1e3 times its tolerance.
                    if self.order > 2 {
                        self.order -= 1;
                        self.steps_at_order = 0;
                    }
                    last_err = Some(SolveError::StepTooSmall {
                        t: self.t,
                        step: self.h,
                        worst_unknown: worst,
                    });
                }
                step::Attempt::NewtonFailed { err, stale } => {
                    self.stats.newton_failures += 1;
                    self.newton.invalidate_jacobian();
                    self.c0_factored = 0.0;
                    if !stale {
                        self.startup = false;
                        failures += 1;
                        newton_failures += 1;
                        self.h = 0.25 * h;
                    }
                    last_err = Some(err);
                }
            }
            if failures >= 3 || (failures >= 2 && self.order <= 2) {
                self.order = 1;
                self.steps_at_order = 0;
            }
        }
        if let Some((index, rising)) = self.locate_roots(sys) {
            return Ok(Advance::Root {
                t: self.t,
                index,
                rising,
            });
        }
        if self.breakpoints.last() == Some(&self.t) {
            self.breakpoints.pop();
            self.forget_history();
        }
        if self.t == t_out {
            Ok(Advance::Reached(self.t))
        } else {
            Ok(Advance::StepAccepted(self.t))
        }
    }
}
