//! Damped Newton-Raphson on `G(x) = 0` with a weighted RMS convergence test.
//!
//! Convergence: the update is small in the weighted norm `||dx||_w <= tol` (RMS or max, see
//! [`ErrorNorm`]), where
//! `w_i = 1 / (reltol * |x_i| + abstol_i)` (the IDA/SPICE test `|dx_i| <= reltol*|x_i| + abstol_i`
//! at `tol = 1`), or, when `residual_tol` is set, `max_i |G_i(x)| <= residual_tol` after an update.
//! With `check_residual` (the default) a small update is not enough: the residual at the new
//! point must also be within each equation's tolerance, `|G_i| <= max_j |dG_i/dx_j| / w_j` (what
//! moving any one unknown it reads by its tolerance could change it by: a current for a current
//! balance, a voltage for a voltage equation, whatever the units), the second test SPICE makes.
//! A small update with a large residual (a near-singular or stale Jacobian) iterates on. An
//! affine problem's full step with a fresh factorisation is exact to rounding and skips it.
//! Modified Newton: with `reuse_jacobian` the last factorisation is kept while the contraction
//! rate `||dx_k|| / ||dx_{k-1}||` stays below `max_rate` and, continued over the iterations
//! left, would bring the update within `tol`; otherwise the iteration on a stale matrix
//! refactors before anything else (a junction turning on within the step makes the old matrix
//! contract at 0.4 to 0.7 per iteration: four such iterations fail, a fresh matrix converges). Damping is an Armijo backtracking line search on the
//! residual's 2-norm (halving, at most 6 times).

use super::SolveError;
use super::linear::{LinearOptions, LinearSolver};

/// How per-unknown weighted errors combine into one number that must stay below 1.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum ErrorNorm {
    /// `sqrt(mean((e_i w_i)^2))`, as IDA: smooth, but in a large system one unknown may carry
    /// up to `sqrt(n)` times its tolerance.
    #[default]
    Rms,
    /// `max |e_i w_i|`, as SPICE: every unknown within its own tolerance.
    Max,
    /// The larger of the RMS and `max |e_i w_i| / BOUNDED_MAX_RATIO`: smooth like the RMS
    /// where many unknowns move, and no unknown beyond `BOUNDED_MAX_RATIO` times its
    /// tolerance however many quiet ones surround it.
    Bounded,
}

/// How many of its tolerances one unknown may carry under [`ErrorNorm::Bounded`]. Measured:
/// a diode chain whose wave lives in its first seven of 10 000 stages took it 40 times
/// under the RMS (2.7 % of the swing where ngspice is at 0.6 %); the maximum norm costs the
/// headlight servo 45 % more steps and an RC ladder twice as many, whose RMS let its output
/// carry 2.8 tolerances.
pub const BOUNDED_MAX_RATIO: f64 = 3.0;

/// Per-unknown error weights: `|e_i| <= reltol * |x_i| + abstol_i` is "within tolerance".
#[derive(Debug, Clone, PartialEq)]
pub struct Tolerances {
    pub reltol: f64,
    pub abstol: Vec<f64>,
    pub norm: ErrorNorm,
}

impl Tolerances {
    /// The same absolute tolerance for all `n` unknowns, RMS norm.
    pub fn uniform(n: usize, reltol: f64, abstol: f64) -> Self {
        Self {
            reltol,
            abstol: vec![abstol; n],
            norm: ErrorNorm::Rms,
        }
    }

    /// `w_i = 1 / (reltol * |x_i| + abstol_i)`.
    pub fn weights(&self, x: &[f64], w: &mut [f64]) {
        for ((w, &x), &a) in w.iter_mut().zip(x).zip(&self.abstol) {
            *w = 1.0 / (self.reltol * x.abs() + a);
        }
    }

    /// The weighted norm of `v` (0 for an empty vector).
    pub fn norm(&self, v: &[f64], w: &[f64]) -> f64 {
        match self.norm {
            ErrorNorm::Rms => wrms(v, w),
            ErrorNorm::Max => wmax(v, w),
            ErrorNorm::Bounded => wrms(v, w).max(wmax(v, w) / BOUNDED_MAX_RATIO),
        }
    }
}

/// Weighted maximum norm `max |v_i w_i|` (NaN if any term is); 0 for empty vectors.
fn wmax(v: &[f64], w: &[f64]) -> f64 {
    v.iter()
        .zip(w)
        .map(|(v, w)| (v * w).abs())
        .fold(0.0, |m, e| if e > m || e.is_nan() { e } else { m })
}

/// Weighted root-mean-square norm `sqrt(mean((v_i w_i)^2))`; 0 for empty vectors.
fn wrms(v: &[f64], w: &[f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    let s: f64 = v.iter().zip(w).map(|(v, w)| (v * w) * (v * w)).sum();
    (s / v.len() as f64).sqrt()
}

/// Index and magnitude of the largest `|v_i|`.
pub(crate) fn worst(v: &[f64]) -> (usize, f64) {
    v.iter()
        .map(|v| v.abs())
        .enumerate()
        .fold((0, 0.0), |a, b| if b.1 > a.1 { b } else { a })
}

/// A square nonlinear system `G(x) = 0` on the pattern given to [`Newton::new`].
pub trait NonlinearProblem {
    /// `out = G(x)`.
    fn residual(&mut self, x: &[f64], out: &mut [f64]);
    /// `dG/dx` at each pattern entry, in pattern order.
    fn jacobian(&mut self, x: &[f64], out: &mut [f64]);
    /// What each residual balances at the last [`NonlinearProblem::residual`] evaluation (see
    /// [`DaeSystem::residual_scale`](crate::DaeSystem::residual_scale)); `false` when
    /// unknown.
    fn residual_scale(&self, _out: &mut [f64]) -> bool {
        false
    }
    /// A conductance added to every diagonal entry of the Jacobian (gmin stepping).
    fn diagonal_shift(&self) -> f64 {
        0.0
    }
    /// The largest fraction of the step `x -> x + dx` worth taking (see
    /// [`DaeSystem::step_limit`](crate::DaeSystem::step_limit)); the damped iteration
    /// starts its backtracking there.
    fn step_limit(&mut self, _x: &[f64], _dx: &[f64]) -> f64 {
        1.0
    }
    /// Rescales `units` (what a significant change of each unknown is, see
    /// [`LinearSolver::factor_scaled`]) for a second factorisation when the first found the
    /// matrix numerically singular; `false` when the problem has no other scaling to offer.
    /// The transient corrector measures its differential unknowns by their derivative
    /// there: its matrix `dF/dx + c0 dF/dx'` tends to `c0 dF/dx'` in those columns as the
    /// step shrinks, and rows that hold both a derivative and an algebraic unknown then
    /// carry the algebraic entry below rounding (a condition of 1e16 at a 1e-15 s step).
    fn rescale_units(&self, _units: &mut [f64]) -> bool {
        false
    }
}

/// Newton's knobs. The defaults suit an operating point; the transient corrector uses
/// `max_iter = 4`, `tol = 0.33`, no line search and Jacobian reuse (as IDA does).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct NewtonOptions {
    pub max_iter: usize,
    /// Bound on `||dx||_w`.
    pub tol: f64,
    /// Optional absolute bound on `max |G_i|` that also counts as converged.
    pub residual_tol: Option<f64>,
    /// Optional bound on `||dx||_w` that also counts as converged once the iteration stops
    /// contracting quadratically (an update at least half the previous one): rounding has
    /// then become the floor, and a tight `tol` would never be met.
    pub stall_tol: Option<f64>,
    pub line_search: bool,
    /// Keep the factorisation across iterations and calls while convergence is fast.
    pub reuse_jacobian: bool,
    /// Contraction rate above which a stale Jacobian is refreshed (and, for a fresh one without
    /// line search, the iteration is declared divergent).
    pub max_rate: f64,
    /// Factor applied to updates computed with a factorisation from an earlier call (the
    /// integrator passes IDA's `2 / (1 + c/c_old)` to make up for a stale `alpha`).
    pub stale_scale: f64,
    /// Converged also needs every residual within its equation's tolerance (see the module
    /// documentation); costs one residual evaluation per solve where the update test alone
    /// would have stopped without one.
    pub check_residual: bool,
    /// The problem is affine (see [`DaeSystem::is_linear`](crate::DaeSystem::is_linear)):
    /// a full step with a Jacobian factored in this call, without diagonal shift, is the
    /// solution, and ends the iteration without a second one to confirm it.
    pub linear: bool,
    /// With [`NewtonOptions::reuse_jacobian`], an update within `tol` computed on a matrix
    /// factored at another point ends the iteration only when the contraction rate is at
    /// most this (1: whenever it contracts); otherwise the matrix is refreshed there first.
    pub stale_rate: f64,
}

impl Default for NewtonOptions {
    fn default() -> Self {
        Self {
            max_iter: 50,
            tol: 1.0,
            residual_tol: None,
            stall_tol: None,
            line_search: true,
            reuse_jacobian: false,
            max_rate: 0.9,
            stale_scale: 1.0,
            check_residual: true,
            linear: false,
            stale_rate: 1.0,
        }
    }
}

/// What one successful [`Newton::solve`] cost.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct NewtonReport {
    pub iterations: usize,
    pub factorizations: usize,
    pub residual_evals: usize,
}

/// A factorisation set aside, with the Jacobian it was computed from: see
/// [`Newton::exchange`].
pub struct Factorization {
    lin: LinearSolver,
    jac: Vec<f64>,
    valid: bool,
}

/// Newton's workspace: the linear solver and every vector it needs, allocated once.
pub struct Newton {
    lin: LinearSolver,
    linear_options: LinearOptions,
    /// The pattern: row and column of each Jacobian entry.
    pattern: Vec<(usize, usize)>,
    jac: Vec<f64>,
    /// Per equation, the residual within tolerance (see [`Newton::residual_within_tolerance`]).
    row_tol: Vec<f64>,
    r: Vec<f64>,
    dx: Vec<f64>,
    x_trial: Vec<f64>,
    r_trial: Vec<f64>,
    w: Vec<f64>,
    /// What a significant change of each unknown is when the Jacobian was factored.
    units: Vec<f64>,
    jac_valid: bool,
    totals: NewtonReport,
}

impl Newton {
    pub fn new(
        n: usize,
        pattern: &[(usize, usize)],
        linear: LinearOptions,
    ) -> Result<Self, SolveError> {
        Ok(Self {
            lin: LinearSolver::new(n, pattern, linear)?,
            linear_options: linear,
            pattern: pattern.to_vec(),
            jac: vec![0.0; pattern.len()],
            row_tol: vec![0.0; n],
            r: vec![0.0; n],
            dx: vec![0.0; n],
            x_trial: vec![0.0; n],
            r_trial: vec![0.0; n],
            w: vec![0.0; n],
            units: vec![0.0; n],
            jac_valid: false,
            totals: NewtonReport::default(),
        })
    }

    /// Forces a fresh Jacobian at the next iteration.
    pub fn invalidate_jacobian(&mut self) {
        self.jac_valid = false;
    }
}

impl Factorization {
    /// Forgets the factorisation (the slot keeps its solver and pivot orders).
    pub fn invalidate(&mut self) {
        self.valid = false;
    }

    /// Pivot searches of factorisations made while this slot was Newton's.
    pub fn pivot_searches(&self) -> usize {
        self.lin.pivot_counts().searched
    }
}

impl Newton {
    /// A factorisation slot for [`Newton::exchange`], holding none yet.
    pub fn spare(&self) -> Result<Factorization, SolveError> {
        Ok(Factorization {
            lin: LinearSolver::new(self.r.len(), &self.pattern, self.linear_options)?,
            jac: vec![0.0; self.pattern.len()],
            valid: false,
        })
    }

    /// Exchanges the current factorisation (and the Jacobian it came from) with `other`: a
    /// problem that comes back to a few matrices in turn (the consistent initialisations of
    /// a switching circuit's modes) keeps one per matrix, and the solver it swaps out keeps
    /// its own factorisation and pivot orders for when it comes back.
    pub fn exchange(&mut self, other: &mut Factorization) {
        std::mem::swap(&mut self.lin, &mut other.lin);
        std::mem::swap(&mut self.jac, &mut other.jac);
        std::mem::swap(&mut self.jac_valid, &mut other.valid);
    }

    /// The residual at the last point Newton evaluated.
    pub fn last_residual(&self) -> &[f64] {
        &self.r
    }

    fn refactor<P: NonlinearProblem>(
        &mut self,
        p: &mut P,
        x: &[f64],
        tol: &Tolerances,
        t: f64,
        rep: &mut NewtonReport,
    ) -> Result<(), SolveError> {
        self.jac_valid = false;
        p.jacobian(x, &mut self.jac);
        // Unknowns in units of their tolerance: a current of 1e22 A and a node voltage then
        // compare as the convergence test compares them.
        for ((u, &x), &a) in self.units.iter_mut().zip(x).zip(&tol.abstol) {
            *u = tol.reltol * x.abs() + a;
        }
        let factored = self
            .lin
            .factor_scaled(&self.jac, p.diagonal_shift(), Some(&self.units));
        match factored {
            Err(SolveError::SingularJacobian {
                structural: false, ..
            }) if p.rescale_units(&mut self.units) => self
                .lin
                .factor_scaled(&self.jac, p.diagonal_shift(), Some(&self.units))
                .map_err(|e| e.at(t))?,
            other => other.map_err(|e| e.at(t))?,
        }
        rep.factorizations += 1;
        self.jac_valid = true;
        Ok(())
    }

    /// `dx = -scale J^{-1} r`, returning `||dx||_w` at `x`.
    fn step(&mut self, x: &[f64], tol: &Tolerances, t: f64, scale: f64) -> Result<f64, SolveError> {
        for (d, r) in self.dx.iter_mut().zip(&self.r) {
            *d = -scale * r;
        }
        self.lin.solve_in_place(&mut self.dx).map_err(|e| e.at(t))?;
        tol.weights(x, &mut self.w);
        Ok(tol.norm(&self.dx, &self.w))
    }

    fn eval<P: NonlinearProblem>(
        p: &mut P,
        x: &[f64],
        out: &mut [f64],
        t: f64,
        rep: &mut NewtonReport,
    ) -> Result<(), SolveError> {
        p.residual(x, out);
        rep.residual_evals += 1;
        match out.iter().position(|v| !v.is_finite()) {
            Some(equation) => Err(SolveError::NonFiniteResidual { t, equation }),
            None => Ok(()),
        }
    }

    /// True when every `|r_i|` at `x` is within its equation's tolerance: `reltol` times what
    /// the equation balances (its largest term, when the problem knows it) plus
    /// `max_j |J_ij| abstol_j`; without the terms, `max_j |J_ij| (reltol |x_j| + abstol_j)`.
    /// The Jacobian is the one last factored (a scale, so a stale one serves). `r` must be the
    /// residual at `x`, the problem's last evaluation.
    ///
    /// The terms matter on a junction: `|J_ij| |x_j|` of a diode's current is `I v / vt`, 27
    /// times the current at 0.7 V, so the Jacobian's scale let a current balance be off by a
    /// quarter of its current at `reltol` 1e-2, and the junction ran away from one accepted
    /// point to the next (the diode chain at `--reltol 1e-2`).
    fn residual_within_tolerance<P: NonlinearProblem>(
        &mut self,
        p: &P,
        x: &[f64],
        tol: &Tolerances,
    ) -> bool {
        // What each unknown's change is measured in through the Jacobian: its abstol beside
        // the terms, its whole tolerance (the inverse of its weight) without them.
        if p.residual_scale(&mut self.row_tol) {
            for t in self.row_tol.iter_mut() {
                *t *= tol.reltol;
            }
            for (u, &a) in self.w.iter_mut().zip(&tol.abstol) {
                *u = a;
            }
        } else {
            self.row_tol.fill(0.0);
            for ((u, &x), &a) in self.w.iter_mut().zip(x).zip(&tol.abstol) {
                *u = tol.reltol * x.abs() + a;
            }
        }
        for (&(i, j), &a) in self.pattern.iter().zip(&self.jac) {
            let scaled = a.abs() * self.w[j];
            if scaled > self.row_tol[i] {
                self.row_tol[i] = scaled;
            }
        }
        self.r.iter().zip(&self.row_tol).all(|(r, t)| r.abs() <= *t)
    }

    /// Whether the residual (already evaluated at `x`) agrees with a small update, when the
    /// options ask for that check.
    fn residual_agrees<P: NonlinearProblem>(
        &mut self,
        p: &P,
        x: &[f64],
        tol: &Tolerances,
        opts: &NewtonOptions,
    ) -> bool {
        !opts.check_residual || self.residual_within_tolerance(p, x, tol)
    }

    /// The equation whose residual is the most tolerances off (after a failed
    /// [`Newton::residual_within_tolerance`] the tolerances are current) and its residual.
    fn worst_scaled(&self) -> (usize, f64) {
        let mut worst = (0, -1.0);
        for (i, (r, t)) in self.r.iter().zip(&self.row_tol).enumerate() {
            let ratio = if *t > 0.0 { r.abs() / t } else { f64::INFINITY };
            if ratio > worst.1 {
                worst = (i, ratio);
            }
        }
        (worst.0, self.r[worst.0])
    }

    /// Factorisations that searched for pivots (both paths reuse the last pivots while they
    /// hold), failed solves included.
    pub fn pivot_searches(&self) -> usize {
        self.lin.pivot_counts().searched
    }

    /// Work done by every `solve` since construction, failed ones included.
    pub fn totals(&self) -> NewtonReport {
        self.totals
    }

    /// Solves `p(x) = 0` starting from `x`; on success `x` holds the solution. On failure `x`
    /// holds the last iterate. `t` only stamps errors.
    pub fn solve<P: NonlinearProblem>(
        &mut self,
        p: &mut P,
        x: &mut [f64],
        tol: &Tolerances,
        opts: &NewtonOptions,
        t: f64,
    ) -> Result<NewtonReport, SolveError> {
        let mut rep = NewtonReport::default();
        let result = self.solve_counted(p, x, tol, opts, t, &mut rep);
        self.totals.iterations += rep.iterations;
        self.totals.factorizations += rep.factorizations;
        self.totals.residual_evals += rep.residual_evals;
        result.map(|()| rep)
    }

    fn solve_counted<P: NonlinearProblem>(
        &mut self,
        p: &mut P,
        x: &mut [f64],
        tol: &Tolerances,
        opts: &NewtonOptions,
        t: f64,
        rep: &mut NewtonReport,
    ) -> Result<(), SolveError> {
        let n = self.r.len();
        if x.len() != n || tol.abstol.len() != n {
            return Err(SolveError::InvalidSystem {
                reason: "state or tolerance vector length differs from the system size",
                index: x.len(),
            });
        }
        Self::eval(p, x, &mut self.r, t, rep)?;
        let mut prev_norm = f64::INFINITY;
        // The iteration whose iterate the factorisation was computed at (0: an earlier call's).
        let mut factored_at = 0;
        for iter in 1..=opts.max_iter {
            if !self.jac_valid || !opts.reuse_jacobian {
                self.refactor(p, x, tol, t, rep)?;
                factored_at = iter;
            }
            let stale = rep.factorizations == 0;
            let scale = if stale { opts.stale_scale } else { 1.0 };
            let mut norm = self.step(x, tol, t, scale)?;
            // A matrix factored at another point (an earlier call's, or an earlier iterate of
            // this one) contracts linearly: at this rate, the iterations left would not bring
            // the update within tolerance, or it does not contract at all. Refresh before
            // judging the iteration, rather than fail the step and redo it (or, damped, walk
            // thirty iterations around a junction's knee on the slope of the first one). An
            // affine problem's matrix is the same everywhere.
            let rate = norm / prev_norm;
            let short = norm * rate.powi((opts.max_iter - iter) as i32) > opts.tol;
            let moved = stale || (factored_at != iter && !opts.linear);
            // An update that stops halving looks like the rounding floor (`stall_tol` below),
            // but on a matrix from another point it is only linear convergence: judge the
            // floor with a fresh matrix.
            let slow = opts
                .stall_tol
                .is_some_and(|bound| norm <= bound && norm > 0.5 * prev_norm);
            // Within tolerance on a matrix from another point, the error left is about
            // `rate / (1 - rate)` times the update: more than `stale_rate` (or unknown, in
            // the first iteration) and the update is redone on a fresh matrix.
            let known_rate = if prev_norm.is_finite() { rate } else { 1.0 };
            let loose = norm <= opts.tol && known_rate > opts.stale_rate;
            if moved && (rate > opts.max_rate || short || slow || loose) {
                self.refactor(p, x, tol, t, rep)?;
                factored_at = iter;
                norm = self.step(x, tol, t, 1.0)?;
            }
            rep.iterations = iter;
            // On an affine problem a full step with this call's (exact) Jacobian is the answer.
            let exact = opts.linear && !stale && p.diagonal_shift() == 0.0 && norm.is_finite();
            let stalled = opts
                .stall_tol
                .is_some_and(|bound| norm <= bound && norm > 0.5 * prev_norm);
            // Without damping, a fresh Jacobian that does not contract means divergence: give
            // up early so the integrator can shrink the step (IDA's rate test).
            let diverging = !opts.line_search && norm > opts.max_rate * prev_norm && !stalled;
            if !norm.is_finite() || diverging {
                break;
            }
            // A step already within tolerance needs no damping (and rounding would defeat the
            // sufficient-decrease test there).
            // `ends`: the iteration would stop here if the residual agrees.
            // `damped`: the line search shortened the step and the residual fell, so the
            // iteration is still on its way (slow, not at the rounding floor).
            let before = norm2(&self.r);
            let (ends, damped) = if opts.line_search && norm > opts.tol && !stalled {
                // Backtracking starts where exponentials stop overshooting.
                let mut lambda = p.step_limit(x, &self.dx).clamp(1e-9, 1.0);
                let f0 = before;
                let mut decreased;
                loop {
                    for ((xt, &x), &d) in self.x_trial.iter_mut().zip(x.iter()).zip(&self.dx) {
                        *xt = x + lambda * d;
                    }
                    p.residual(&self.x_trial, &mut self.r_trial);
                    rep.residual_evals += 1;
                    let f1 = norm2(&self.r_trial);
                    decreased = f1.is_finite() && f1 <= (1.0 - 1e-4 * lambda) * f0;
                    if decreased || lambda < 0.03 {
                        break;
                    }
                    lambda *= 0.5;
                }
                x.copy_from_slice(&self.x_trial);
                std::mem::swap(&mut self.r, &mut self.r_trial);
                if let Some(equation) = self.r.iter().position(|v| !v.is_finite()) {
                    return Err(SolveError::NonFiniteResidual { t, equation });
                }
                (exact && lambda == 1.0, decreased && lambda < 1.0)
            } else {
                for (x, d) in x.iter_mut().zip(&self.dx) {
                    *x += d;
                }
                // Stalled within its bound, the residual is rounding: no test could pass it.
                // An affine problem's full step with a fresh exact factorisation leaves only
                // the rounding of the solve, so it needs no residual to confirm it (that
                // evaluation would cost an RC ladder a third of its time).
                let small = norm <= opts.tol;
                if stalled || exact || (small && !opts.check_residual) {
                    return Ok(());
                }
                Self::eval(p, x, &mut self.r, t, rep)?;
                (small, false)
            };
            // At the rounding floor (neither the updates nor the residual contract any more), a
            // residual within every equation's tolerance is the answer whatever the update's
            // size: `x'` of a consistent initialisation, weighed on the scale of `x`, can wander
            // by more than that scale in the last bits of an ill-conditioned row. An iteration
            // still on its way is not there, though its updates may not contract either (full
            // steps walk down a junction's exponential by about `vt` each while the residual
            // falls by `e`; a damped step contracts slowly): its residual can be within those
            // tolerances (a large conductance makes a loose one) with a node hundreds of
            // tolerances from the solution.
            let floor = opts.check_residual
                && opts.stall_tol.is_some()
                && !damped
                && norm > 0.5 * prev_norm
                && norm2(&self.r) > 0.5 * before;
            if ends || floor {
                if self.residual_agrees(p, x, tol, opts) {
                    return Ok(());
                }
                // The update is within tolerance and the residual is not: a matrix from
                // another point walks the rest of the way linearly (a junction's current must
                // meet reltol of itself, its voltage only reltol of the voltage, about 25
                // times looser at 0.7 V); a fresh one gets there in one step.
                if opts.reuse_jacobian && !opts.linear && factored_at != iter {
                    self.jac_valid = false;
                }
            }
            if let Some(rt) = opts.residual_tol
                && worst(&self.r).1 <= rt
            {
                return Ok(());
            }
            prev_norm = norm;
        }
        let (worst_equation, residual) = if opts.check_residual {
            self.residual_within_tolerance(p, x, tol);
            self.worst_scaled()
        } else {
            worst(&self.r)
        };
        Err(SolveError::NewtonDiverged {
            t,
            iterations: rep.iterations,
            worst_equation,
            residual,
        })
    }
}

pub(crate) fn norm2(v: &[f64]) -> f64 {
    v.iter().map(|v| v * v).sum::<f64>().sqrt()
}
