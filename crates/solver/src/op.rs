//! DC operating point: `F(x' = 0, x, t0) = 0`.
//!
//! Plain damped Newton first; if it fails, gmin stepping (a conductance `gmin` from every
//! unknown to zero, i.e. `+gmin*x_i` in residual `i` and `+gmin` on the diagonal, lowered by an
//! adaptive factor down to zero), then source stepping (ramping `set_source_scale` from 0 to 1
//! with adaptive increments), and last Newton with full steps (no line search, no divergence
//! test, more iterations: the iteration SPICE runs). The line search judges a step by the
//! residual's norm, which an exponential dominates: `r == 10**l` with `l` going from 0 to 6
//! makes every full step look worse, so the damped iteration creeps (3 % of the way per
//! iteration) where two full steps land on the answer. Each stage starts from the caller's
//! initial guess. The quiescent
//! augmentation of the LRM (which equations replace `x' = 0`) is the caller's business.

use super::newton::{Newton, NewtonOptions, NonlinearProblem, Tolerances};
use super::{DaeSystem, LinearOptions, SolveError};

/// How the operating point was found.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OpStrategy {
    Newton,
    GminStepping,
    SourceStepping,
    FullSteps,
}

/// Knobs for [`operating_point`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct OpOptions {
    pub newton: NewtonOptions,
    pub linear: LinearOptions,
    /// First gmin of the gmin-stepping ladder (the last step is always gmin = 0).
    pub gmin_start: f64,
    /// Below this gmin the next step goes straight to 0.
    pub gmin_min: f64,
    /// Smallest source-scale increment before source stepping gives up.
    pub source_step_min: f64,
}

impl Default for OpOptions {
    fn default() -> Self {
        Self {
            newton: NewtonOptions::default(),
            linear: LinearOptions::default(),
            gmin_start: 1e-2,
            gmin_min: 1e-12,
            source_step_min: 1e-4,
        }
    }
}

/// How an operating point was reached and what it cost in total (failed attempts included).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct OpReport {
    pub strategy: OpStrategy,
    pub newton_iterations: usize,
    pub factorizations: usize,
}

struct OpProblem<'a, S: ?Sized> {
    sys: &'a mut S,
    t: f64,
    zeros: Vec<f64>,
    gmin: f64,
}

impl<S: DaeSystem + ?Sized> NonlinearProblem for OpProblem<'_, S> {
    fn residual(&mut self, x: &[f64], out: &mut [f64]) {
        self.sys.residual(self.t, x, &self.zeros, out);
        if self.gmin != 0.0 {
            for (o, x) in out.iter_mut().zip(x) {
                *o += self.gmin * x;
            }
        }
    }
    fn jacobian(&mut self, x: &[f64], out: &mut [f64]) {
        self.sys.jacobian(self.t, x, &self.zeros, 0.0, out);
    }
    fn diagonal_shift(&self) -> f64 {
        self.gmin
    }
    fn residual_scale(&self, out: &mut [f64]) -> bool {
        self.sys.residual_scale(out)
    }
}

/// Solves for the operating point at time `t`, starting from (and returning in) `x`. On error
/// `x` is left as the caller gave it.
pub fn operating_point<S: DaeSystem + ?Sized>(
    sys: &mut S,
    t: f64,
    x: &mut [f64],
    tol: &Tolerances,
    options: &OpOptions,
) -> Result<OpReport, SolveError> {
    let n = sys.len();
    if x.len() != n {
        return Err(SolveError::InvalidSystem {
            reason: "initial guess length differs from the system size",
            index: x.len(),
        });
    }
    let mut newton = Newton::new(n, sys.pattern(), options.linear)?;
    let x0 = x.to_vec();
    let mut report = OpReport {
        strategy: OpStrategy::Newton,
        newton_iterations: 0,
        factorizations: 0,
    };
    let mut p = OpProblem {
        sys,
        t,
        zeros: vec![0.0; n],
        gmin: 0.0,
    };
    // One Newton solve from `x` with the given options (the damped ones but for the last
    // stage), its totals so far in `report`.
    let mut solve = |p: &mut OpProblem<'_, S>,
                     x: &mut [f64],
                     report: &mut OpReport,
                     newton_options: &NewtonOptions| {
        newton.invalidate_jacobian();
        let r = newton.solve(p, x, tol, newton_options, t);
        let totals = newton.totals();
        report.newton_iterations = totals.iterations;
        report.factorizations = totals.factorizations;
        r.map(|_| ())
    };
    let mut attempt = |p: &mut OpProblem<'_, S>, x: &mut [f64], report: &mut OpReport| {
        solve(p, x, report, &options.newton)
    };

    match attempt(&mut p, x, &mut report) {
        Ok(()) => return Ok(report),
        // A structurally singular system will not be rescued by continuation.
        Err(
            e @ SolveError::SingularJacobian {
                structural: true, ..
            },
        )
        | Err(e @ SolveError::InvalidSystem { .. }) => return Err(e),
        Err(_) => {}
    }

    // Gmin stepping.
    x.copy_from_slice(&x0);
    let mut good = x0.clone();
    let (mut gmin, mut good_gmin, mut factor) = (options.gmin_start, f64::NAN, 10.0f64);
    let gmin_ok = loop {
        p.gmin = gmin;
        match attempt(&mut p, x, &mut report) {
            Ok(()) if gmin == 0.0 => break true,
            Ok(()) => {
                good.copy_from_slice(x);
                good_gmin = gmin;
                gmin = if gmin / factor < options.gmin_min {
                    0.0
                } else {
                    gmin / factor
                };
            }
            Err(_) if good_gmin.is_nan() => break false,
            Err(_) => {
                x.copy_from_slice(&good);
                factor = factor.sqrt();
                if factor < 1.05 {
                    break false;
                }
                gmin = good_gmin / factor;
            }
        }
    };
    p.gmin = 0.0;
    if gmin_ok {
        report.strategy = OpStrategy::GminStepping;
        return Ok(report);
    }

    // Source stepping.
    x.copy_from_slice(&x0);
    let (mut s, mut ds) = (0.0f64, 0.1f64);
    p.sys.set_source_scale(0.0);
    let mut last = attempt(&mut p, x, &mut report).err();
    if last.is_none() {
        good.copy_from_slice(x);
        while s < 1.0 {
            let next = (s + ds).min(1.0);
            p.sys.set_source_scale(next);
            match attempt(&mut p, x, &mut report) {
                Ok(()) => {
                    good.copy_from_slice(x);
                    s = next;
                    ds *= 2.0;
                }
                Err(e) => {
                    x.copy_from_slice(&good);
                    ds *= 0.25;
                    if ds < options.source_step_min {
                        last = Some(e);
                        break;
                    }
                }
            }
        }
    }
    p.sys.set_source_scale(1.0);
    let Some(e) = last else {
        report.strategy = OpStrategy::SourceStepping;
        return Ok(report);
    };

    // Full Newton steps.
    x.copy_from_slice(&x0);
    let full = NewtonOptions {
        line_search: false,
        max_rate: f64::INFINITY,
        max_iter: 4 * options.newton.max_iter,
        ..options.newton
    };
    if solve(&mut p, x, &mut report, &full).is_ok() && x.iter().all(|v| v.is_finite()) {
        report.strategy = OpStrategy::FullSteps;
        return Ok(report);
    }
    x.copy_from_slice(&x0);
    Err(SolveError::NoOperatingPoint { last: Box::new(e) })
}
