//! The integrator's options, outcomes and counters.

use crate::{ErrorNorm, LinearOptions};

/// Integrator settings.
#[derive(Debug, Clone, PartialEq)]
pub struct TransientOptions {
    pub reltol: f64,
    /// Absolute tolerance for every unknown, unless `abstol_per_unknown` is non-empty.
    pub abstol: f64,
    pub abstol_per_unknown: Vec<f64>,
    /// How the error test and Newton combine per-unknown errors.
    pub norm: ErrorNorm,
    pub max_step: f64,
    /// Smallest step before giving up (never below 16 ulp of `max(|t|, |t_out|)`).
    pub min_step: f64,
    /// First step; `None` picks one from `x'_0` and the first `t_out`.
    pub initial_step: Option<f64>,
    /// The highest BDF order, 1 to [`super::MAX_ORDER`] (5).
    pub max_order: usize,
    pub linear: LinearOptions,
}

impl Default for TransientOptions {
    fn default() -> Self {
        Self {
            reltol: 1e-4,
            abstol: 1e-9,
            abstol_per_unknown: Vec::new(),
            norm: ErrorNorm::Rms,
            max_step: f64::INFINITY,
            min_step: 0.0,
            initial_step: None,
            max_order: super::MAX_ORDER,
            linear: LinearOptions::default(),
        }
    }
}

/// The local error tolerance for a run whose global relative error should be about
/// `reltol`, up to the default 1e-3 the same, below it `reltol (reltol / 1e-3)^(1/5)`.
///
/// The error test bounds the error made in each step, and a run's error is what the steps
/// leave behind: over a fixed time a method of order `p` takes steps in proportion to
/// `tol^(-1/(p+1))`, so the global error goes like `tol^(p/(p+1))` and its ratio to the
/// tolerance grows as the tolerance tightens (a mass-spring-damper over six periods: 3.9
/// times `reltol` at 1e-3, 19 times at 1e-6). Asking each step for `tol^((p+1)/p)`, with the
/// order of tight runs (5), makes the run's error about proportional to `reltol`, the
/// tolerance proportionality of Hairer and Wanner (IV.8, RADAU5's transformed `RTOL`).
/// Tolerances from 1e-3 up keep their meaning, calibrated there: the default run is
/// unchanged.
pub fn local_reltol(reltol: f64) -> f64 {
    const CALIBRATED: f64 = 1e-3;
    if reltol >= CALIBRATED {
        reltol
    } else {
        reltol * (reltol / CALIBRATED).powf(0.2)
    }
}

/// What one call to [`Transient::advance`] achieved.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Advance {
    /// The integrator stands exactly on the requested `t_out`.
    Reached(f64),
    /// Root function `index` changes sign at `t`; the integrator stands at `t`. `rising` is
    /// true for a crossing from negative to positive.
    Root { t: f64, index: usize, rising: bool },
    /// One step was accepted, ending at this time (before `t_out`).
    StepAccepted(f64),
}

/// Work counters since construction.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq)]
pub struct Stats {
    pub accepted_steps: usize,
    /// Steps rejected by the error test.
    pub rejected_steps: usize,
    /// Steps abandoned because the corrector did not converge.
    pub newton_failures: usize,
    pub newton_iterations: usize,
    pub factorizations: usize,
    /// Factorisations that searched for pivots rather than reusing the last ones.
    pub pivot_searches: usize,
    pub residual_evals: usize,
    pub root_evals: usize,
}
