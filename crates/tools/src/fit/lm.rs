//! Levenberg-Marquardt with bounds, on a residual that a simulator computes.
//!
//! Takes a [`Residuals`] (weighted residual rows at a point in the optimiser's coordinates,
//! several points at once so that the caller can simulate them in parallel) and a start
//! inside the bounds; gives the point of least squares, the Jacobian there and how the
//! iteration ended. The Jacobian is by forward differences (one batch of simulations per
//! iteration, run in parallel by the caller): the simulator's own sensitivity equations would
//! be exact, but a difference of two simulations at a tight tolerance is accurate to about
//! `reltol / step` (1e-3 at the defaults), which moves a Gauss-Newton step by far less than the
//! noise of any capture, and it works for every model the simulator runs, events and `break`
//! included. Bounds are kept by projection: a parameter at a bound whose gradient pushes
//! outward is held for that step (an active set), the others solve the damped normal
//! equations, and the step is clipped to the box.

use faer::Mat;
use faer::linalg::solvers::Solve;

/// The residual of a fit: the caller simulates.
pub trait Residuals: Sync {
    /// Why a point could not be evaluated (a simulation that failed).
    type Error: Clone + std::fmt::Display + Send;
    /// The weighted residual rows at each point (coordinates of the optimiser), in order.
    fn evaluate(&self, points: &[Vec<f64>]) -> Vec<Result<Vec<f64>, Self::Error>>;
}

/// The iteration's settings.
#[derive(Debug, Clone)]
pub struct Settings {
    /// The most iterations (Jacobians).
    pub max_iterations: usize,
    /// Stop when an accepted step lowers the cost by less than this fraction...
    pub cost_tolerance: f64,
    /// ... and moves no coordinate by more than this.
    pub step_tolerance: f64,
    /// The forward-difference step in the optimiser's coordinates (a relative change of
    /// a log-scaled parameter).
    pub difference_step: f64,
    /// The largest change of one coordinate in one step (2 in log space: a factor of 7.4).
    pub max_step: f64,
}

impl Default for Settings {
    fn default() -> Self {
        Settings {
            max_iterations: 100,
            cost_tolerance: 1e-9,
            step_tolerance: 1e-6,
            difference_step: 1e-3,
            max_step: 2.0,
        }
    }
}

/// How the iteration ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ending {
    /// The cost and the step became small.
    Converged,
    /// No damping found a step that lowers the cost: a minimum to the precision of the
    /// simulations.
    NoBetterStep,
    /// The iteration limit.
    IterationLimit,
}

/// The least-squares point.
#[derive(Debug, Clone)]
pub struct Solution {
    /// The coordinates.
    pub x: Vec<f64>,
    /// The weighted residual there.
    pub residual: Vec<f64>,
    /// Its sum of squares.
    pub cost: f64,
    /// The Jacobian of the residual at `x` (rows by coordinates).
    pub jacobian: Mat<f64>,
    /// The weighted residual at the start, and its sum of squares.
    pub start_residual: Vec<f64>,
    pub start_cost: f64,
    /// Jacobians computed.
    pub iterations: usize,
    /// Points evaluated.
    pub evaluations: usize,
    /// Which coordinates ended at a bound.
    pub at_bound: Vec<bool>,
    /// How it ended.
    pub ending: Ending,
}

/// The failure of a fit.
#[derive(Debug, Clone)]
pub enum LmError<E> {
    /// The start could not be evaluated.
    Start(E),
    /// The residual at the start is not finite.
    NotFinite,
    /// A Jacobian column could not be evaluated on either side of the point.
    Jacobian { coordinate: usize, error: E },
}

fn cost(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

fn finite(r: &[f64]) -> bool {
    r.iter().all(|v| v.is_finite())
}

/// The forward-difference Jacobian at `x` (backward where the forward point leaves the box).
fn jacobian<R: Residuals>(
    res: &R,
    x: &[f64],
    r: &[f64],
    bounds: &[(f64, f64)],
    h: f64,
    evaluations: &mut usize,
) -> Result<Mat<f64>, LmError<R::Error>> {
    let steps: Vec<f64> = (0..x.len())
        .map(|k| if x[k] + h > bounds[k].1 { -h } else { h })
        .collect();
    let points: Vec<Vec<f64>> = (0..x.len())
        .map(|k| {
            let mut p = x.to_vec();
            p[k] += steps[k];
            p
        })
        .collect();
    *evaluations += points.len();
    let results = res.evaluate(&points);
    let mut jac = Mat::<f64>::zeros(r.len(), x.len());
    for (k, result) in results.into_iter().enumerate() {
        let rk = match result {
            Ok(rk) if rk.len() == r.len() && finite(&rk) => rk,
            Ok(_) => {
                // A perturbed simulation that gives another number of rows or a non-finite
                // value: that coordinate has no usable sensitivity here; zero keeps it still.
                continue;
            }
            Err(error) => {
                return Err(LmError::Jacobian {
                    coordinate: k,
                    error,
                });
            }
        };
        for (row, (a, b)) in rk.iter().zip(r).enumerate() {
            jac[(row, k)] = (a - b) / steps[k];
        }
    }
    Ok(jac)
}

/// Minimises the sum of squares of `res` from `start` within `bounds` (per coordinate,
/// infinite where unbounded).
pub fn minimise<R: Residuals>(
    res: &R,
    start: &[f64],
    bounds: &[(f64, f64)],
    settings: &Settings,
) -> Result<Solution, LmError<R::Error>> {
    let n = start.len();
    let mut x: Vec<f64> = (0..n)
        .map(|k| start[k].clamp(bounds[k].0, bounds[k].1))
        .collect();
    let mut evaluations = 1;
    let mut r = res
        .evaluate(std::slice::from_ref(&x))
        .into_iter()
        .next()
        .expect("evaluate returns one result per point")
        .map_err(LmError::Start)?;
    if !finite(&r) {
        return Err(LmError::NotFinite);
    }
    let mut c = cost(&r);
    let (start_residual, start_cost) = (r.clone(), c);
    let mut lambda = 1e-3;
    let mut iterations = 0;
    let mut ending = Ending::IterationLimit;
    let h = settings.difference_step;
    let mut jac = jacobian(res, &x, &r, bounds, h, &mut evaluations)?;
    iterations += 1;
    let mut fresh = true; // `jac` is at the current `x`
    while iterations <= settings.max_iterations {
        if !fresh {
            jac = jacobian(res, &x, &r, bounds, h, &mut evaluations)?;
            iterations += 1;
            fresh = true;
        }
        let jtj = jac.transpose() * &jac;
        let rc = Mat::<f64>::from_fn(r.len(), 1, |i, _| r[i]);
        let g = jac.transpose() * &rc;
        // The active set: coordinates at a bound that the descent direction pushes out.
        let free: Vec<usize> = (0..n)
            .filter(|&k| {
                let at_lo = x[k] <= bounds[k].0 && g[(k, 0)] > 0.0;
                let at_hi = x[k] >= bounds[k].1 && g[(k, 0)] < 0.0;
                !(at_lo || at_hi)
            })
            .collect();
        if free.is_empty() {
            ending = Ending::Converged;
            break;
        }
        let m = free.len();
        let mut accepted = None;
        while lambda < 1e12 {
            let a = Mat::<f64>::from_fn(m, m, |i, j| {
                let v = jtj[(free[i], free[j])];
                if i == j {
                    v + lambda * v.max(1e-12 * (1.0 + v.abs()))
                } else {
                    v
                }
            });
            let b = Mat::<f64>::from_fn(m, 1, |i, _| -g[(free[i], 0)]);
            let Ok(llt) = a.llt(faer::Side::Lower) else {
                lambda *= 10.0;
                continue;
            };
            let step = llt.solve(&b);
            let mut xn = x.clone();
            let mut moved: f64 = 0.0;
            for (i, &k) in free.iter().enumerate() {
                let d = step[(i, 0)].clamp(-settings.max_step, settings.max_step);
                xn[k] = (x[k] + d).clamp(bounds[k].0, bounds[k].1);
                moved = moved.max((xn[k] - x[k]).abs());
            }
            evaluations += 1;
            let trial = res.evaluate(std::slice::from_ref(&xn)).into_iter().next();
            match trial {
                Some(Ok(rn)) if rn.len() == r.len() && finite(&rn) && cost(&rn) < c => {
                    accepted = Some((xn, rn, moved));
                    break;
                }
                // A failed simulation or a worse cost: a shorter, more gradient-like step.
                _ => lambda *= 4.0,
            }
            if moved < 1e-14 {
                break;
            }
        }
        let Some((xn, rn, moved)) = accepted else {
            ending = Ending::NoBetterStep;
            break;
        };
        let cn = cost(&rn);
        let gain = (c - cn) / c.max(f64::MIN_POSITIVE);
        x = xn;
        r = rn;
        c = cn;
        fresh = false;
        lambda = (lambda / 3.0).max(1e-9);
        if gain < settings.cost_tolerance && moved < settings.step_tolerance.max(h * 1e-2) {
            ending = Ending::Converged;
            break;
        }
        if gain < settings.cost_tolerance * 1e-3 {
            // Progress below what the simulations resolve.
            ending = Ending::Converged;
            break;
        }
    }
    if !fresh {
        jac = jacobian(res, &x, &r, bounds, h, &mut evaluations)?;
    }
    let at_bound = (0..n)
        .map(|k| x[k] <= bounds[k].0 || x[k] >= bounds[k].1)
        .collect();
    Ok(Solution {
        x,
        residual: r,
        cost: c,
        jacobian: jac,
        start_residual,
        start_cost,
        iterations,
        evaluations,
        at_bound,
        ending,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    /// An exponential decay `a exp(-t/tau) + c` sampled at 200 points.
    struct Decay {
        t: Vec<f64>,
        y: Vec<f64>,
    }

    impl Decay {
        fn new(a: f64, tau: f64, c: f64) -> Self {
            let t: Vec<f64> = (0..200).map(|k| k as f64 * 0.01).collect();
            let y = t.iter().map(|t| a * (-t / tau).exp() + c).collect();
            Decay { t, y }
        }
    }

    impl Residuals for Decay {
        type Error = String;
        fn evaluate(&self, points: &[Vec<f64>]) -> Vec<Result<Vec<f64>, String>> {
            points
                .iter()
                .map(|x| {
                    // a and tau in log space, c linear.
                    let (a, tau, c) = (x[0].exp(), x[1].exp(), x[2]);
                    Ok(self
                        .t
                        .iter()
                        .zip(&self.y)
                        .map(|(t, y)| a * (-t / tau).exp() + c - y)
                        .collect())
                })
                .collect()
        }
    }

    #[test]
    fn finds_an_exponential_from_far_away() {
        let d = Decay::new(2.0, 0.3, 0.5);
        let inf = (f64::NEG_INFINITY, f64::INFINITY);
        let s = minimise(
            &d,
            &[0.0, (0.02f64).ln(), 0.0],
            &[inf; 3],
            &Settings::default(),
        )
        .unwrap();
        assert!((s.x[0].exp() - 2.0).abs() < 1e-5, "{:?}", s.x);
        assert!((s.x[1].exp() - 0.3).abs() < 1e-5, "{:?}", s.x);
        assert!((s.x[2] - 0.5).abs() < 1e-5, "{:?}", s.x);
        assert!(s.cost < 1e-12 && s.start_cost > 1.0);
    }

    #[test]
    fn respects_bounds() {
        let d = Decay::new(2.0, 0.3, 0.5);
        let inf = (f64::NEG_INFINITY, f64::INFINITY);
        // tau may not exceed 0.2: the fit ends at the bound and says so.
        let bounds = [inf, (f64::NEG_INFINITY, 0.2f64.ln()), (0.0, 1.0)];
        let s = minimise(
            &d,
            &[0.0, (0.1f64).ln(), 0.9],
            &bounds,
            &Settings::default(),
        )
        .unwrap();
        assert!(s.x[1] <= 0.2f64.ln() + 1e-15);
        assert!(s.at_bound[1] && !s.at_bound[0]);
        assert!(s.x[2] >= 0.0 && s.x[2] <= 1.0);
    }
}
