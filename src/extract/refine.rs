//! The refinement beyond the paper: the four experiments simulated with the motor equations
//! and all parameters fitted jointly to the four captures by Levenberg-Marquardt.
//!
//! Takes the prepared captures and a starting point (the paper's estimates); gives the
//! fitted parameters with standard errors from the Gauss-Newton covariance, and the RMS
//! residual of each capture. Parameters are fitted as logarithms (all are positive);
//! `Kt = Ke` (SI units: Kt alone is not identifiable, scaling Kt, J, D, Tcst together leaves
//! every capture unchanged). The coast's initial speed is a nuisance parameter. Each capture
//! weighs the same: its residuals are divided by its signal scale and sqrt(samples).

use super::model::{MotorParams, simulate_coast, simulate_driven};
use super::paper::{Estimate, Prepared};
use super::signal::{mean, median, moving_median};
use faer::Mat;
use faer::linalg::solvers::{DenseSolveCore, Solve};

/// The number of motor parameters fitted (R, L, Ke, J, D, Tcst_motor).
const NP: usize = 6;

/// The result of the joint fit.
#[derive(Debug, Clone)]
pub struct Refined {
    /// Fitted parameters.
    pub params: MotorParams,
    /// Standard errors in the order of [`MotorParams::NAMES`].
    pub se: [f64; 7],
    /// RMS residual of each capture (A, A, A, V) with the starting parameters.
    pub rms_start: [f64; 4],
    /// RMS residual of each capture (A, A, A, V) with the fitted parameters.
    pub rms: [f64; 4],
    /// Levenberg-Marquardt iterations taken.
    pub iterations: usize,
    /// The simulated traces with the fitted parameters: (time, simulated) per capture.
    pub sim: [Vec<(f64, f64)>; 4],
}

fn to_params(x: &[f64]) -> MotorParams {
    let e: Vec<f64> = x.iter().map(|v| v.exp()).collect();
    MotorParams {
        r: e[0],
        l: e[1],
        ke: e[2],
        kt: e[2],
        j: e[3],
        d: e[4],
        tcst_motor: e[5],
    }
}

/// Simulations of the four captures: per capture (first index, simulated values).
fn simulate(p: &MotorParams, w_coast: f64, prep: &Prepared) -> [(usize, Vec<f64>); 4] {
    let [inrush, blocked, speed, coast] = &prep.caps;
    let a = prep.inrush_step.saturating_sub(2);
    let (ii, _) = simulate_driven(p, &inrush.t[a..], &inrush.v[a..], 0.0, 0.0, false);
    let b = prep.blocked_step.saturating_sub(2);
    let i0 = if prep.blocked_step < 8 {
        blocked.i[0]
    } else {
        0.0
    };
    let (ib, _) = simulate_driven(p, &blocked.t[b..], &blocked.v[b..], i0, 0.0, true);
    let (w0, is0) = p.steady_state(mean(&speed.v));
    let (is, _) = simulate_driven(p, &speed.t, &speed.v, is0, w0, false);
    let c = prep.coast_start;
    let wc = simulate_coast(p, &coast.t[c..], w_coast);
    let vc = wc.iter().map(|w| p.ke * w).collect();
    [(a, ii), (b, ib), (0, is), (c, vc)]
}

fn measured(prep: &Prepared, k: usize) -> &[f64] {
    if k == 3 {
        &prep.caps[3].v
    } else {
        &prep.caps[k].i
    }
}

/// Weighted residuals and the RMS per capture (physical units).
fn residuals(x: &[f64], prep: &Prepared, scales: &[f64; 4]) -> (Vec<f64>, [f64; 4]) {
    let p = to_params(x);
    let sims = simulate(&p, x[NP].exp(), prep);
    let mut out = Vec::new();
    let mut rms = [0.0; 4];
    for (k, (first, sim)) in sims.iter().enumerate() {
        let meas = &measured(prep, k)[*first..];
        let n = sim.len().min(meas.len()).max(1);
        let w = 1.0 / (scales[k] * (n as f64).sqrt());
        let mut ss = 0.0;
        for (s, m) in sim.iter().zip(meas) {
            let r = s - m;
            ss += r * r;
            out.push(r * w);
        }
        rms[k] = (ss / n as f64).sqrt();
    }
    // The speed read from the ripple, as one measurement with its standard error.
    let (w_sim, _) = p.steady_state(mean(&prep.caps[2].v));
    out.push((w_sim - prep.w_cst.value) / prep.w_cst.se.max(1e-9 * prep.w_cst.value));
    (out, rms)
}

fn cost(r: &[f64]) -> f64 {
    r.iter().map(|v| v * v).sum()
}

/// Fits all parameters jointly, starting from `start`: a first pass weighs each capture by
/// its RMS residual at the start, a second by its RMS residual after the first pass (each
/// capture's noise, ripple included, estimated from its own fit).
pub fn refine(prep: &Prepared, start: &MotorParams) -> Refined {
    let driven = drive_inputs(prep);
    let prep = &driven;
    let coast = &prep.caps[3];
    let w_coast = (median(&coast.v[prep.coast_start..(prep.coast_start + 20).min(coast.len())])
        / start.ke)
        .max(1e-6);
    let x: Vec<f64> = [
        start.r,
        start.l,
        start.ke,
        start.j,
        start.d,
        start.tcst_motor,
        w_coast,
    ]
    .iter()
    .map(|v| v.max(1e-30).ln())
    .collect();
    let (_, rms_start) = residuals(&x, prep, &[1.0; 4]);
    let floor = |rms: [f64; 4]| rms.map(|v| v.max(1e-9));
    let first = lm(prep, x, &floor(rms_start));
    let (_, rms_first) = residuals(&first.0, prep, &[1.0; 4]);
    let (x, jac, _, _, iterations) = lm(prep, first.0, &floor(rms_first));
    let params = to_params(&x);
    let (r, _) = residuals(&x, prep, &floor(rms_first));
    let fisher = fisher(&jac, &r, &block_lengths(prep));
    let vals = [
        params.r,
        params.l,
        params.ke,
        params.j,
        params.d,
        params.tcst_motor,
    ];
    let mut se_fit = [f64::NAN; NP];
    if let Ok(llt) = fisher.llt(faer::Side::Lower) {
        let inv = llt.inverse();
        for d in 0..NP {
            se_fit[d] = vals[d] * inv[(d, d)].max(0.0).sqrt();
        }
    }
    let (_, rms) = residuals(&x, prep, &[1.0; 4]);
    let sims = simulate(&params, x[NP].exp(), prep);
    let sim = std::array::from_fn(|k| {
        let (first, s) = &sims[k];
        prep.caps[k].t[*first..]
            .iter()
            .copied()
            .zip(s.iter().copied())
            .collect()
    });
    Refined {
        params,
        se: [
            se_fit[0], se_fit[1], se_fit[2], se_fit[2], se_fit[3], se_fit[4], se_fit[5],
        ],
        rms_start,
        rms,
        iterations: first.4 + iterations,
        sim,
    }
}

/// The captures as simulation inputs: the driving voltages of the inrush and blocked
/// captures through a 5-sample moving median (it keeps the step, drops the 8-bit chatter
/// that would otherwise drive the simulated current), the constant-speed capture's voltage
/// replaced by its mean (steady by definition). Currents and the coast stay as measured.
fn drive_inputs(prep: &Prepared) -> Prepared {
    let mut out = prep.clone();
    for k in 0..2 {
        out.caps[k].v = moving_median(&prep.caps[k].v, 2);
    }
    let m = mean(&prep.caps[2].v);
    out.caps[2].v.iter_mut().for_each(|v| *v = m);
    out
}

/// The number of residual rows of each capture.
fn block_lengths(prep: &Prepared) -> [usize; 4] {
    let firsts = [
        prep.inrush_step.saturating_sub(2),
        prep.blocked_step.saturating_sub(2),
        0,
        prep.coast_start,
    ];
    std::array::from_fn(|k| prep.caps[k].len() - firsts[k])
}

/// Integrated autocorrelation time of a residual sequence, in samples (1 for white noise):
/// `1 + 2 sum rho_l` up to the first lag where the autocorrelation falls below 0.05.
fn correlation_time(r: &[f64]) -> f64 {
    let r0: f64 = r.iter().map(|v| v * v).sum();
    if r0 <= 0.0 {
        return 1.0;
    }
    let mut tau = 1.0;
    for lag in 1..(r.len() / 4).min(4000) {
        let rho = r.iter().zip(&r[lag..]).map(|(a, b)| a * b).sum::<f64>() / r0;
        if rho < 0.05 {
            break;
        }
        tau += 2.0 * rho;
    }
    tau
}

/// The Fisher information of the log-parameters. The rows of capture k were weighted by
/// 1/(sigma_k sqrt(n_k)); a capture's information is `J_k^T J_k / sigma_k^2` over its
/// effective (uncorrelated) samples, `n_k / tau_k`, so its block is scaled by `n_k / tau_k`.
fn fisher(jac: &Mat<f64>, r: &[f64], lengths: &[usize; 4]) -> Mat<f64> {
    let m = jac.ncols();
    let mut f = Mat::<f64>::zeros(m, m);
    let mut start = 0;
    let mut blocks: Vec<(usize, usize, f64)> = Vec::new();
    for &n in lengths {
        let end = (start + n).min(r.len());
        let tau = correlation_time(&r[start..end]);
        blocks.push((start, end, n as f64 / tau));
        start = end;
    }
    // The ripple-speed row carries its own standard error.
    blocks.push((start, r.len(), 1.0));
    for (a, b, scale) in blocks {
        for row in a..b {
            for i in 0..m {
                for j in 0..m {
                    f[(i, j)] += scale * jac[(row, i)] * jac[(row, j)];
                }
            }
        }
    }
    f
}

/// Levenberg-Marquardt from `x`; returns the solution, the last Jacobian, the cost, the
/// number of residual rows and the iterations taken.
fn lm(
    prep: &Prepared,
    mut x: Vec<f64>,
    scales: &[f64; 4],
) -> (Vec<f64>, Mat<f64>, f64, usize, usize) {
    let m = x.len();
    let (mut r, _) = residuals(&x, prep, scales);
    let mut c = cost(&r);
    let mut lambda = 1e-3;
    let mut iterations = 0;
    let mut jac = Mat::<f64>::zeros(r.len(), m);
    for it in 0..60 {
        iterations = it + 1;
        // Forward-difference Jacobian in log space.
        for p in 0..m {
            let mut xp = x.clone();
            let h = 1e-5;
            xp[p] += h;
            let (rp, _) = residuals(&xp, prep, scales);
            for (row, (a, b)) in rp.iter().zip(&r).enumerate() {
                jac[(row, p)] = (a - b) / h;
            }
        }
        let jtj = jac.transpose() * &jac;
        let rc = Mat::<f64>::from_fn(r.len(), 1, |i, _| r[i]);
        let jtr = jac.transpose() * &rc;
        let mut improved = false;
        for _ in 0..12 {
            let mut a = jtj.clone();
            for d in 0..m {
                a[(d, d)] += lambda * jtj[(d, d)].max(1e-12);
            }
            let Ok(llt) = a.llt(faer::Side::Lower) else {
                lambda *= 10.0;
                continue;
            };
            let step = llt.solve(&jtr);
            let xn: Vec<f64> = (0..m)
                .map(|d| x[d] - step[(d, 0)].clamp(-1.0, 1.0))
                .collect();
            let (rn, _) = residuals(&xn, prep, scales);
            let cn = cost(&rn);
            if cn.is_finite() && cn < c {
                let gain = (c - cn) / c.max(1e-300);
                x = xn;
                r = rn;
                c = cn;
                lambda = (lambda / 3.0).max(1e-9);
                improved = gain > 1e-9;
                break;
            }
            lambda *= 10.0;
        }
        if !improved {
            break;
        }
    }
    let rows = r.len();
    (x, jac, c, rows, iterations)
}

/// The paper's estimates as motor parameters.
pub fn start_params(e: &super::paper::PaperEstimates) -> MotorParams {
    let v = |x: &Estimate| x.value;
    MotorParams {
        r: v(&e.r),
        l: v(&e.l),
        ke: v(&e.ke),
        kt: v(&e.kt),
        j: v(&e.j),
        d: v(&e.d),
        tcst_motor: v(&e.tcst_motor),
    }
}
