//! What a fit's residual says about the parameters: intervals, correlations, and which
//! parameters the captures do not determine.
//!
//! Two 95 % intervals per parameter, because they answer different questions:
//!
//! * **From the covariance**: `s^2 (J^T J)^-1` with `s^2` the weighted residual's sum of
//!   squares over its degrees of freedom, and Student's t. Right when the residual is white
//!   noise and the model is exact.
//! * **Block bootstrap**: the residual of each series (one measured column of one capture)
//!   resampled in circular blocks as long as its correlation time (so ripple, drift and the
//!   systematic misfit of an imperfect model keep their structure), each replicate solved
//!   for the Gauss-Newton step it causes with the fit's Jacobian (a linearised bootstrap:
//!   2 000 replicates cost a few small solves, not 2 000 fits). Wider than the first when the
//!   residual is correlated, as it is whenever the model misses something. The caller widens
//!   it to hold the first interval and the intervals without each one series
//!   ([`leave_one_out`]): a misfit that the parameters absorb leaves little in the residual
//!   to resample, but shows as captures that disagree.
//!
//! Identifiability from the eigenvalues of the Fisher information `J^T J / s^2` in the
//! optimiser's coordinates (relative changes for log-scaled parameters): a direction whose
//! standard deviation exceeds one (a factor of e for log-scaled ones) is not determined by the
//! captures, and the parameters that make it up are named.

use faer::Mat;
use rand::{RngExt, SeedableRng};
use rand_chacha::ChaCha8Rng;
use statrs::distribution::{ContinuousCDF, StudentsT};

/// The bootstrap's replicates.
pub const REPLICATES: usize = 2000;

/// A direction of the parameters that the captures do not fix.
#[derive(Debug, Clone, PartialEq)]
pub struct Unidentified {
    /// The parameters that make up the direction, with their weights (components of the unit
    /// eigenvector), largest first.
    pub parameters: Vec<(usize, f64)>,
    /// The standard deviation along the direction (optimiser's coordinates).
    pub sd: f64,
}

/// The statistics of a fit.
#[derive(Debug, Clone)]
pub struct Uncertainty {
    /// Residual rows less free parameters.
    pub dof: usize,
    /// The weighted residual's variance per degree of freedom.
    pub s2: f64,
    /// Standard deviation of each coordinate from the covariance (NaN where undetermined or
    /// at a bound).
    pub sd: Vec<f64>,
    /// 95 % half-width multiplier (Student's t).
    pub t95: f64,
    /// The 2.5 % and 97.5 % points of each coordinate's bootstrap distribution.
    pub bootstrap: Vec<Option<(f64, f64)>>,
    /// The correlation matrix (NaN rows for undetermined coordinates).
    pub correlation: Vec<Vec<f64>>,
    /// The directions the captures do not determine.
    pub unidentified: Vec<Unidentified>,
    /// Per series, the bootstrap's block length (samples).
    pub block_lengths: Vec<usize>,
    /// Per coordinate, the reach (below and above the estimate) of the 95 % intervals the fit
    /// would give with one series left out ([`leave_one_out`]); None where no series can be
    /// left out without losing it.
    pub leave_one_out: Vec<Option<(f64, f64)>>,
}

/// Integrated autocorrelation time of a sequence, in samples (1 for white noise): `1 + 2 sum
/// rho_l` up to the first lag where the autocorrelation falls below 0.05.
pub fn correlation_time(r: &[f64]) -> f64 {
    let r0: f64 = r.iter().map(|v| v * v).sum();
    if r0 <= 0.0 || r.len() < 8 {
        return 1.0;
    }
    let mut tau = 1.0;
    for lag in 1..(r.len() / 4).min(2000) {
        let rho = r.iter().zip(&r[lag..]).map(|(a, b)| a * b).sum::<f64>() / r0;
        if rho < 0.05 {
            break;
        }
        tau += 2.0 * rho;
    }
    tau
}

/// The statistics of the least-squares point: `jac` and `residual` are weighted, `series`
/// gives the rows of each measured column (consecutive ranges covering all rows), `held`
/// marks coordinates at a bound (no interval, left out of the covariance). With `weighted`,
/// the weights are each series' own misfit over its effective samples, so the residual's
/// scale is known to be one: a smaller sum of squares (correlated samples, counted as fewer
/// by their weights) does not narrow the intervals.
pub fn analyse(
    jac: &Mat<f64>,
    residual: &[f64],
    series: &[std::ops::Range<usize>],
    held: &[bool],
    seed: u64,
    weighted: bool,
) -> Uncertainty {
    let n = jac.ncols();
    let rows = residual.len();
    let active: Vec<usize> = (0..n).filter(|&k| !held[k]).collect();
    let m = active.len();
    let dof = rows.saturating_sub(m).max(1);
    let s2 = residual.iter().map(|v| v * v).sum::<f64>() / dof as f64;
    let s2 = if weighted { s2.max(1.0) } else { s2 };
    let t95 = StudentsT::new(0.0, 1.0, dof as f64)
        .map(|t| t.inverse_cdf(0.975))
        .unwrap_or(1.96);
    let mut sd = vec![f64::NAN; n];
    let mut correlation = vec![vec![f64::NAN; n]; n];
    let mut bootstrap = vec![None; n];
    let mut unidentified = Vec::new();
    let block_lengths: Vec<usize> = series
        .iter()
        .map(|s| {
            let tau = correlation_time(&residual[s.clone()]);
            ((2.0 * tau).ceil() as usize).clamp(1, (s.len() / 4).max(1))
        })
        .collect();
    // Nothing free, or no eigen-decomposition: no interval for anyone.
    let undetermined = || Uncertainty {
        dof,
        s2,
        sd: vec![f64::NAN; n],
        t95,
        bootstrap: vec![None; n],
        correlation: vec![vec![f64::NAN; n]; n],
        unidentified: Vec::new(),
        block_lengths: block_lengths.clone(),
        leave_one_out: vec![None; n],
    };
    if m == 0 {
        return undetermined();
    }
    let ja = Mat::<f64>::from_fn(rows, m, |i, j| jac[(i, active[j])]);
    let jtj = ja.transpose() * &ja;
    let fisher = Mat::<f64>::from_fn(m, m, |i, j| jtj[(i, j)] / s2.max(f64::MIN_POSITIVE));

    // The eigen-directions of the information; a direction with variance above one is not
    // determined. Those directions are dropped from the inverse (a pseudo-inverse), so the
    // determined parameters still get their intervals.
    let Ok(eig) = fisher.self_adjoint_eigen(faer::Side::Lower) else {
        return undetermined();
    };
    let lambda: Vec<f64> = (0..m).map(|i| eig.S().column_vector()[i]).collect();
    let u = eig.U();
    let weak = weak_directions(&lambda);
    for i in (0..m).filter(|&i| weak[i]) {
        let l = lambda[i];
        let mut parameters: Vec<(usize, f64)> = (0..m)
            .map(|k| (active[k], u[(k, i)]))
            .filter(|(_, w)| w.abs() > 0.2)
            .collect();
        parameters.sort_by(|a, b| b.1.abs().total_cmp(&a.1.abs()));
        unidentified.push(Unidentified {
            parameters,
            sd: if l > 0.0 {
                1.0 / l.sqrt()
            } else {
                f64::INFINITY
            },
        });
    }
    // Coordinates entangled with an undetermined direction get no interval.
    let entangled: Vec<bool> = (0..m).map(|k| entangled_in(u, &weak, k)).collect();
    let cov = Mat::<f64>::from_fn(m, m, |a, b| {
        (0..m)
            .filter(|&i| !weak[i])
            .map(|i| u[(a, i)] * u[(b, i)] / lambda[i])
            .sum()
    });
    for a in 0..m {
        if entangled[a] {
            continue;
        }
        sd[active[a]] = cov[(a, a)].max(0.0).sqrt();
    }
    for a in 0..m {
        for b in 0..m {
            if entangled[a] || entangled[b] {
                continue;
            }
            let d = (cov[(a, a)] * cov[(b, b)]).sqrt();
            correlation[active[a]][active[b]] = if d > 0.0 { cov[(a, b)] / d } else { 0.0 };
        }
    }

    // The linearised block bootstrap: delta* = (J^T J)^+ J^T e*, with e* the residual
    // resampled in circular blocks per series and inflated by sqrt(rows / dof).
    let inflate = (rows as f64 / dof as f64).sqrt();
    let jtj_pinv = Mat::<f64>::from_fn(m, m, |a, b| cov[(a, b)] / s2.max(f64::MIN_POSITIVE));
    // Each series' residual centred: a series whose misfit has a mean (an offset the model
    // lacks) would otherwise shift every replicate the same way, moving the interval off the
    // estimate instead of widening it.
    let centred: Vec<f64> = {
        let mut c = residual.to_vec();
        for range in series {
            let n = range.len().max(1) as f64;
            let mean = residual[range.clone()].iter().sum::<f64>() / n;
            for v in &mut c[range.clone()] {
                *v -= mean;
            }
        }
        c
    };
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut draws: Vec<Vec<f64>> = vec![Vec::with_capacity(REPLICATES); m];
    let mut e = vec![0.0; rows];
    for _ in 0..REPLICATES {
        for (s, range) in series.iter().enumerate() {
            let len = range.len();
            if len == 0 {
                continue;
            }
            let block = block_lengths[s].min(len);
            let mut filled = 0;
            while filled < len {
                let from = rng.random_range(0..len);
                for k in 0..block.min(len - filled) {
                    e[range.start + filled + k] = centred[range.start + (from + k) % len] * inflate;
                }
                filled += block;
            }
        }
        // J^T e* then the step.
        let jte: Vec<f64> = (0..m)
            .map(|j| (0..rows).map(|i| ja[(i, j)] * e[i]).sum())
            .collect();
        for a in 0..m {
            let d: f64 = (0..m).map(|b| jtj_pinv[(a, b)] * jte[b]).sum();
            draws[a].push(d);
        }
    }
    for a in 0..m {
        if entangled[a] {
            continue;
        }
        let d = &mut draws[a];
        d.sort_by(f64::total_cmp);
        let q = |p: f64| d[((p * (d.len() - 1) as f64).round() as usize).min(d.len() - 1)];
        bootstrap[active[a]] = Some((q(0.025), q(0.975)));
    }
    let sd_active: Vec<f64> = active.iter().map(|&k| sd[k]).collect();
    let shifts = leave_one_out(&ja, residual, series, s2, &sd_active, t95);
    let mut loo = vec![None; n];
    for (a, shift) in shifts.into_iter().enumerate() {
        if !entangled[a] {
            loo[active[a]] = shift;
        }
    }
    Uncertainty {
        dof,
        s2,
        sd,
        t95,
        bootstrap,
        correlation,
        unidentified,
        block_lengths,
        leave_one_out: loo,
    }
}

/// The eigen-directions of a Fisher information (eigenvalues `lambda`, each the inverse of
/// the variance along its direction) that the data do not determine: a standard deviation
/// above one, or an eigenvalue that is rounding beside the largest.
fn weak_directions(lambda: &[f64]) -> Vec<bool> {
    let largest = lambda.iter().copied().fold(0.0f64, f64::max);
    lambda
        .iter()
        .map(|&l| l < 1.0 || l <= largest * 1e-13)
        .collect()
}

/// Whether coordinate `k` takes part in a weak direction (a component above 0.2 of its unit
/// eigenvector `u`'s column).
fn entangled_in(u: faer::MatRef<'_, f64>, weak: &[bool], k: usize) -> bool {
    (0..weak.len()).any(|i| weak[i] && u[(k, i)].abs() > 0.2)
}

/// The intervals the fit would give with one series left out, as reaches below and above the
/// estimate: the estimate moves by one Gauss-Newton step from the least-squares point without
/// that series' rows, `(H - H_s)^-1 J_s^T r_s` with `H = J^T J` (exact for a linear model),
/// and its interval is `t95` standard deviations of `(H - H_s)^-1` either side. Captures that
/// agree within their noise move the estimate by about a standard deviation; a model that
/// misses something one capture shows (a commutation ripple the model lacks) moves it further,
/// and an interval that does not hold what the fit without that capture says hides the
/// disagreement. A series without which a coordinate's standard deviation would grow more
/// than threefold is the one that determines it: its removal says nothing about agreement,
/// and is not counted for that coordinate. `sd` is each coordinate's standard deviation with
/// every series (NaN: none).
pub fn leave_one_out(
    jac: &Mat<f64>,
    residual: &[f64],
    series: &[std::ops::Range<usize>],
    s2: f64,
    sd: &[f64],
    t95: f64,
) -> Vec<Option<(f64, f64)>> {
    let m = jac.ncols();
    let mut out: Vec<Option<(f64, f64)>> = vec![None; m];
    let h = jac.transpose() * jac;
    let s2 = s2.max(f64::MIN_POSITIVE);
    for range in series {
        if range.is_empty() {
            continue;
        }
        let rows = range.len();
        let js = jac.subrows(range.start, rows);
        let hs = js.transpose() * js;
        // The Fisher information of the other series.
        let rest = Mat::<f64>::from_fn(m, m, |a, b| (h[(a, b)] - hs[(a, b)]) / s2);
        let Ok(eig) = rest.self_adjoint_eigen(faer::Side::Lower) else {
            continue;
        };
        let lambda: Vec<f64> = (0..m).map(|i| eig.S().column_vector()[i]).collect();
        let u = eig.U();
        // Directions the remaining series leave undetermined are dropped, and every
        // coordinate entangled with them skipped, as for the intervals.
        let weak = weak_directions(&lambda);
        let g: Vec<f64> = (0..m)
            .map(|a| {
                (0..rows)
                    .map(|i| js[(i, a)] * residual[range.start + i])
                    .sum()
            })
            .collect();
        for a in 0..m {
            if entangled_in(u, &weak, a) || !sd[a].is_finite() {
                continue;
            }
            // (H - H_s)^-1 = F^-1 / s2 with F the information of the other series.
            let (mut var, mut step) = (0.0, 0.0);
            for i in (0..m).filter(|&i| !weak[i]) {
                let ua = u[(a, i)];
                var += ua * ua / lambda[i];
                step += ua * (0..m).map(|b| u[(b, i)] * g[b]).sum::<f64>() / lambda[i] / s2;
            }
            let sd_without = var.sqrt();
            if sd_without > 3.0 * sd[a] {
                continue;
            }
            let reach = (step - t95 * sd_without, step + t95 * sd_without);
            out[a] = Some(match out[a] {
                Some((lo, hi)) => (lo.min(reach.0), hi.max(reach.1)),
                None => reach,
            });
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;
    use faer::linalg::solvers::Solve;
    use rand_distr_free::normal;

    /// Gaussian draws without another crate: Box-Muller on the seeded stream.
    mod rand_distr_free {
        use rand::RngExt;
        pub fn normal(rng: &mut impl RngExt) -> f64 {
            let u1: f64 = rng.random_range(f64::EPSILON..1.0);
            let u2: f64 = rng.random_range(0.0..1.0);
            (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
        }
    }

    /// A straight line `y = a + b t` fitted to white noise of sd 0.1: the covariance gives
    /// the textbook standard errors.
    #[test]
    fn straight_line_standard_errors() {
        let n = 400;
        let t: Vec<f64> = (0..n).map(|k| k as f64 / n as f64).collect();
        let jac = Mat::<f64>::from_fn(n, 2, |i, j| if j == 0 { 1.0 } else { t[i] });
        let mut rng = ChaCha8Rng::seed_from_u64(3);
        let noise: Vec<f64> = (0..n).map(|_| 0.1 * normal(&mut rng)).collect();
        // The residual of the least-squares line: noise less its projection.
        let jtj = jac.transpose() * &jac;
        let y = Mat::<f64>::from_fn(n, 1, |i, _| noise[i]);
        let coef = jtj
            .llt(faer::Side::Lower)
            .unwrap()
            .solve(jac.transpose() * &y);
        let resid: Vec<f64> = (0..n)
            .map(|i| noise[i] - coef[(0, 0)] - coef[(1, 0)] * t[i])
            .collect();
        let u = analyse(
            &jac,
            &resid,
            std::slice::from_ref(&(0..n)),
            &[false, false],
            1,
            false,
        );
        let sxx: f64 = t.iter().map(|v| (v - 0.49875).powi(2)).sum();
        let se_b = 0.1 / sxx.sqrt();
        assert!((u.sd[1] / se_b - 1.0).abs() < 0.1, "{} vs {se_b}", u.sd[1]);
        assert!(u.unidentified.is_empty());
        // White residual: the bootstrap agrees with the covariance within sampling error.
        let (lo, hi) = u.bootstrap[1].unwrap();
        let half = (hi - lo) / 2.0;
        assert!(
            (half / (1.96 * u.sd[1]) - 1.0).abs() < 0.15,
            "{half} vs {}",
            u.sd[1]
        );
        assert!(u.correlation[0][1] < -0.8);
    }

    /// Two parameters with proportional effects cannot be told apart.
    #[test]
    fn proportional_columns_are_unidentified() {
        let n = 100;
        let jac = Mat::<f64>::from_fn(n, 3, |i, j| match j {
            0 => (i as f64).sin(),
            1 => 2.0 * (i as f64).cos(),
            _ => 4.0 * (i as f64).cos(),
        });
        let resid: Vec<f64> = (0..n)
            .map(|i| 0.01 * ((i * 7919) % 13) as f64 - 0.06)
            .collect();
        let u = analyse(
            &jac,
            &resid,
            std::slice::from_ref(&(0..n)),
            &[false; 3],
            1,
            false,
        );
        assert_eq!(u.unidentified.len(), 1, "{:?}", u.unidentified);
        let names: Vec<usize> = u.unidentified[0].parameters.iter().map(|p| p.0).collect();
        assert!(names.contains(&1) && names.contains(&2) && !names.contains(&0));
        assert!(u.sd[0].is_finite() && u.sd[1].is_nan() && u.sd[2].is_nan());
    }

    /// A correlated residual (a slow sine, as a model error leaves) widens the bootstrap's
    /// interval beyond the covariance's.
    #[test]
    fn correlated_residual_widens_the_bootstrap() {
        let n = 2000;
        let jac = Mat::<f64>::from_fn(n, 1, |_, _| 1.0);
        let resid: Vec<f64> = (0..n)
            .map(|i| 0.1 * (i as f64 * std::f64::consts::TAU / 400.0).sin())
            .collect();
        let u = analyse(
            &jac,
            &resid,
            std::slice::from_ref(&(0..n)),
            &[false],
            1,
            false,
        );
        let (lo, hi) = u.bootstrap[0].unwrap();
        assert!(
            (hi - lo) / 2.0 > 3.0 * 1.96 * u.sd[0],
            "{lo} {hi} {}",
            u.sd[0]
        );
        assert!(u.block_lengths[0] > 50);
    }

    #[test]
    fn leaving_out_a_disagreeing_series_moves_the_estimate_to_the_others() {
        // A constant `a` measured by three series of 100 rows each, unit weights: two read 1.0,
        // one reads 1.3 (a model that misses something that series shows). Least squares
        // gives 1.1; without the odd series 1.0, without one of the others 1.15.
        let rows = 300;
        let jac = Mat::<f64>::from_fn(rows, 1, |_, _| 1.0);
        let a = 1.1;
        let measured = |i: usize| if i >= 200 { 1.3 } else { 1.0 };
        let residual: Vec<f64> = (0..rows).map(|i| a - measured(i)).collect();
        let series = [0..100, 100..200, 200..300];
        let sd = [0.1 / (rows as f64).sqrt()];
        // Without a series the estimate rests on 200 rows: its sd is sqrt(s2 / 200), with s2
        // the residual's variance (6 / 299), and the interval 2 sd either side.
        let sd200 = (6.0 / 299.0 / 200.0f64).sqrt();
        // s2 as the fit computes it: the residual's sum of squares over its degrees of freedom.
        let s2 = 6.0 / 299.0;
        let shifts = leave_one_out(&jac, &residual, &series, s2, &sd, 2.0);
        let (lo, hi) = shifts[0].unwrap();
        assert!((lo - (-0.1 - 2.0 * sd200)).abs() < 1e-12, "{lo}");
        assert!((hi - (0.05 + 2.0 * sd200)).abs() < 1e-12, "{hi}");
        // A series that alone determines the coordinate is not left out: with one series,
        // nothing remains.
        let whole = std::iter::once(0..rows).collect::<Vec<_>>();
        let one = leave_one_out(&jac, &residual, &whole, s2, &sd, 2.0);
        assert_eq!(one[0], None);
    }
}
