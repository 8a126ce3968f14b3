//! The paper's estimates (PAPER.md section 3), each read from its capture by regression over
//! a window rather than a two-point slope, with a standard error.
//!
//! Takes the four captures; gives R, L, Ke = Kt, J, D, Tcst_motor and the offset-corrected
//! captures with the landmarks (step, disconnect, stop) that the refinement reuses. Order:
//! offsets, R (blocked), L (inrush start), Ke (constant speed, speed from the ripple
//! spectrum), J (first revolution of the inrush, commutations as ripple events), Tcst_motor
//! and D (coast end and start). It never simulates.

mod coast;

use super::capture::Capture;
use super::error::ExtractError;
use super::signal::{
    dominant_frequency, local_trend, mean, median, moving_average, moving_median, noise_sigma,
    polyfit, sem, upward_crossings,
};
use std::f64::consts::PI;

/// A value with its standard error.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Estimate {
    /// The value, SI units.
    pub value: f64,
    /// Its standard error.
    pub se: f64,
}

impl Estimate {
    pub(super) fn new(value: f64, se: f64) -> Self {
        Estimate {
            value,
            se: se.abs(),
        }
    }
    pub(super) fn rel(&self) -> f64 {
        self.se / self.value.abs().max(1e-300)
    }
}

/// The captures with offsets removed, and where things happen in them.
#[derive(Debug, Clone)]
pub struct Prepared {
    /// Inrush, blocked, speed, coast (offset-corrected).
    pub caps: [Capture; 4],
    /// Index of the voltage step in the inrush capture.
    pub inrush_step: usize,
    /// Index of the voltage step in the blocked capture (0 without pre-trigger).
    pub blocked_step: usize,
    /// First index of the coast proper (after the disconnect and its kick).
    pub coast_start: usize,
    /// Index where the coasting rotor stops.
    pub coast_stop: usize,
    /// Speed from the ripple of the constant-speed capture, rad/s, with its error.
    pub w_cst: Estimate,
    /// Ripple frequency of the constant-speed capture, Hz.
    pub ripple_hz: f64,
    /// Commutation events found in the inrush's first revolution, s.
    pub first_rev_events: Vec<f64>,
}

/// The paper's estimates.
#[derive(Debug, Clone)]
pub struct PaperEstimates {
    /// Armature resistance.
    pub r: Estimate,
    /// Armature inductance.
    pub l: Estimate,
    /// Back-EMF constant.
    pub ke: Estimate,
    /// Torque constant (= Ke).
    pub kt: Estimate,
    /// Inertia.
    pub j: Estimate,
    /// Viscous damping.
    pub d: Estimate,
    /// Constant friction.
    pub tcst_motor: Estimate,
}

pub(super) fn fail(c: &Capture, param: &'static str, what: impl Into<String>) -> ExtractError {
    ExtractError::EstimateFailed {
        role: c.role,
        path: c.path.clone(),
        param,
        what: what.into(),
    }
}

/// Index where the voltage first rises above half its final value (robust to spikes).
fn step_index(c: &Capture) -> Option<usize> {
    let vs = moving_median(&c.v, 2);
    let n = vs.len();
    let vfin = median(&vs[n - n / 5..]);
    let noise = noise_sigma(&c.v).max(1e-12);
    if vfin < 10.0 * noise {
        return None;
    }
    vs.iter().position(|&v| v > 0.5 * vfin)
}

/// Removes the offsets seen before the step (where v = 0 and i = 0).
fn zero_pre_trigger(c: &mut Capture, step: usize) {
    if step < 8 {
        return;
    }
    let end = step - 3;
    // The plain mean: with noise below a step of an 8-bit scope the samples sit on two or
    // three codes, and a trimmed mean leans to the commonest code (a bias of a part of a
    // step, 1 mA on the demo's current, 0.1 % of R).
    let (vo, io) = (mean(&c.v[..end]), mean(&c.i[..end]));
    c.v.iter_mut().for_each(|v| *v -= vo);
    c.i.iter_mut().for_each(|i| *i -= io);
}

/// Runs the paper's method on the four captures (inrush, blocked, speed, coast).
pub fn estimate(
    caps: &[Capture; 4],
    commutations: u32,
) -> Result<(PaperEstimates, Prepared), ExtractError> {
    let [inrush, blocked, speed, coast] = caps.clone();
    let n_c = commutations.max(1) as f64;

    // Offsets and landmarks.
    let mut inrush = inrush;
    let inrush_step = match step_index(&inrush) {
        Some(k) if k >= 8 => k,
        Some(_) => {
            return Err(ExtractError::NoStep {
                role: "inrush",
                path: inrush.path.clone(),
                what:
                    "the record starts with the voltage already on; expected a pre-trigger at 0 V"
                        .into(),
            });
        }
        None => {
            return Err(ExtractError::NoStep {
                role: "inrush",
                path: inrush.path.clone(),
                what: "the voltage never rises clearly above its noise".into(),
            });
        }
    };
    zero_pre_trigger(&mut inrush, inrush_step);
    let mut blocked = blocked;
    let blocked_step = match step_index(&blocked) {
        Some(k) => k,
        None => {
            return Err(ExtractError::NoStep {
                role: "blocked",
                path: blocked.path.clone(),
                what: "the voltage across the blocked motor stays near 0 V".into(),
            });
        }
    };
    zero_pre_trigger(&mut blocked, blocked_step);
    let mut coast = coast;
    let (coast_start, coast_stop, v_off, i_off) = coast::landmarks(&mut coast)?;
    let mut speed = speed;
    // The constant-speed capture has no zero reference: take the probes' offsets from the
    // coast's standstill (same probes in the bench procedure).
    speed.v.iter_mut().for_each(|v| *v -= v_off);
    speed.i.iter_mut().for_each(|i| *i -= i_off);

    // b. R = U/I at the blocked steady state (second half after the step).
    let a = blocked_step + (blocked.len() - blocked_step) / 2;
    let (u, i) = (&blocked.v[a..], &blocked.i[a..]);
    let (um, im) = (mean(u), mean(i));
    if im <= 5.0 * sem(i).max(1e-9) || um <= 0.0 {
        return Err(fail(
            &blocked,
            "R",
            format!(
                "the steady current is {im:.3e} A at {um:.3} V; expected a clearly positive current"
            ),
        ));
    }
    let r = Estimate::new(
        um / im,
        um / im * ((sem(u) / um).powi(2) + (sem(i) / im).powi(2)).sqrt(),
    );

    // The inrush current cannot exceed the stall current U/R by much (the back-EMF only
    // lowers it): a blocked current far below the inrush peak means the rotor turned.
    let inrush_peak = moving_average(&inrush.i, 2)
        .into_iter()
        .fold(f64::MIN, f64::max);
    let inrush_u = median(&inrush.v[inrush_step..]);
    if inrush_peak > 1.5 * inrush_u / r.value {
        return Err(fail(
            &blocked,
            "R",
            format!(
                "the blocked current ({im:.3e} A at {um:.3} V) is far below the inrush peak ({inrush_peak:.3e} A at {inrush_u:.3} V); expected the stall current, with the rotor held"
            ),
        ));
    }

    // a. L from the start of the inrush: integral of (v - R i) = L (i - i0), regressed.
    let l = inductance(&inrush, inrush_step, r.value)?;
    let l_shift = inductance(&inrush, inrush_step, r.value + r.se)?;
    let l = Estimate::new(l.value, l.se.hypot(l_shift.value - l.value));

    // c. Ke from the constant speed, w from the ripple frequency.
    let dt = speed.dt();
    let peak =
        dominant_frequency(&speed.i, dt, 2.0, 0.45 / dt).ok_or_else(|| ExtractError::NoRipple {
            role: "speed",
            path: speed.path.clone(),
            what: "the record is too short for a spectral estimate".into(),
        })?;
    if peak.prominence < 30.0 {
        return Err(ExtractError::NoRipple {
            role: "speed",
            path: speed.path.clone(),
            what: format!(
                "the strongest line of the current's spectrum ({:.1} Hz) is only {:.1} times the median power; expected a clear commutation line",
                peak.freq, peak.prominence
            ),
        });
    }
    let w_cst = Estimate::new(2.0 * PI * peak.freq / n_c, 2.0 * PI * peak.se / n_c);
    let (us, is) = (mean(&speed.v), mean(&speed.i));
    let emf = us - r.value * is;
    if emf <= 0.0 {
        return Err(fail(
            &speed,
            "Ke",
            format!("U - R*I = {emf:.3} V is not positive"),
        ));
    }
    let ke_v = emf / w_cst.value;
    let ke_se = ((sem(&speed.v) / w_cst.value).powi(2)
        + (is * r.se / w_cst.value).powi(2)
        + (r.value * sem(&speed.i) / w_cst.value).powi(2)
        + (ke_v * w_cst.rel()).powi(2))
    .sqrt();
    let ke = Estimate::new(ke_v, ke_se);
    let kt = ke;

    // a. again: J from the first revolution of the inrush.
    let (j, events) = inertia(&inrush, inrush_step, &r, &l, &ke, &w_cst, n_c)?;

    // d. Coast: slopes at the end (w = 0) and the start (w = w_cst).
    let (tcst, d) = coast::friction(&coast, coast_start, coast_stop, &ke, &j)?;

    let est = PaperEstimates {
        r,
        l,
        ke,
        kt,
        j,
        d,
        tcst_motor: tcst,
    };
    let prep = Prepared {
        caps: [inrush, blocked, speed, coast],
        inrush_step,
        blocked_step,
        coast_start,
        coast_stop,
        w_cst,
        ripple_hz: peak.freq,
        first_rev_events: events,
    };
    Ok((est, prep))
}

fn inductance(c: &Capture, step: usize, r: f64) -> Result<Estimate, ExtractError> {
    let ismooth = moving_average(&c.i, 2);
    let ipk = ismooth[step..].iter().copied().fold(f64::MIN, f64::max);
    let start = step.saturating_sub(2);
    // Up to 40 % of the peak (back-EMF still negligible), stretched to 8 samples after the
    // step for slow sample rates as long as the current stays under 80 % of the peak.
    let reach = |frac: f64| {
        (step..c.len())
            .find(|&k| ismooth[k] > frac * ipk)
            .unwrap_or(c.len())
    };
    let end = reach(0.4).max((step + 8).min(reach(0.8)));
    if end < step + 6 {
        return Err(fail(
            c,
            "L",
            format!(
                "the current reaches 80 % of its peak within {} samples of the step; expected a sample rate fast enough to see the rise (at least 6 samples)",
                end - step
            ),
        ));
    }
    let (mut x, mut y) = (Vec::new(), Vec::new());
    let mut integral = 0.0;
    for k in start..end {
        if k > start {
            let dt = c.t[k] - c.t[k - 1];
            integral += 0.5 * dt * ((c.v[k] - r * c.i[k]) + (c.v[k - 1] - r * c.i[k - 1]));
        }
        // Points from the sample after the step on: where the step falls between two samples
        // is unknown, which shifts every later integral by the same constant (the intercept).
        if k > step {
            x.push(c.i[k] - c.i[start]);
            y.push(integral);
        }
    }
    let fit = polyfit(&x, &y, 1, 0.0)
        .ok_or_else(|| fail(c, "L", "the rising current gives no regression"))?;
    let (value, se) = (fit.coef[1], fit.cov[1][1].sqrt());
    if value <= 0.0 {
        return Err(fail(
            c,
            "L",
            format!("the start of the inrush gives L = {value:.3e} H"),
        ));
    }
    Ok(Estimate::new(value, se))
}

/// J = Kt*I_avg/(dw/dt) over the first revolution; the commutations are upward zero
/// crossings of the current's relative ripple about a local quadratic trend, whose window is
/// sized from the speed that the back-EMF indicates (1.5 local ripple periods).
fn inertia(
    c: &Capture,
    step: usize,
    r: &Estimate,
    l: &Estimate,
    ke: &Estimate,
    w_cst: &Estimate,
    n_c: f64,
) -> Result<(Estimate, Vec<f64>), ExtractError> {
    let dt = c.dt();
    let t0 = c.t[step];
    let ks = step + ((5.0 * l.value / r.value) / dt).ceil() as usize;
    if ks + 64 >= c.len() {
        return Err(fail(
            c,
            "J",
            "the record ends within five electrical time constants of the step",
        ));
    }
    // Speed from the back-EMF, smoothed, only to size the trend window.
    let ism = moving_average(&c.i, 4);
    let didt: Vec<f64> = (0..c.len())
        .map(|k| {
            let (a, b) = (k.saturating_sub(1), (k + 1).min(c.len() - 1));
            (ism[b] - ism[a]) / (c.t[b] - c.t[a]).max(1e-300)
        })
        .collect();
    let w_emf: Vec<f64> = (0..c.len())
        .map(|k| (c.v[k] - r.value * c.i[k] - l.value * didt[k]) / ke.value)
        .collect();
    let t_min = 2.0 * PI / (n_c * w_cst.value);
    let w_emf = moving_average(&w_emf, ((0.5 * t_min / dt) as usize).max(2));
    let seg_i = &c.i[ks..];
    let seg_t = &c.t[ks..];
    let local_period = |k: usize| 2.0 * PI / (n_c * w_emf[ks + k].max(0.05 * w_cst.value));
    let trend = local_trend(seg_i, |k| {
        ((0.75 * local_period(k) / dt) as usize).min(seg_i.len() / 2)
    });
    let rel: Vec<f64> = seg_i
        .iter()
        .zip(&trend)
        .map(|(i, tr)| if tr.abs() > 1e-12 { i / tr - 1.0 } else { 0.0 })
        .collect();
    let rel = moving_average(&rel, ((t_min / 16.0 / dt) as usize).max(1));
    let mad = median(&rel.iter().map(|v| v.abs()).collect::<Vec<_>>());
    let raw = upward_crossings(seg_t, &rel, 0.5 * mad);
    // Outlier-robust: drop an event closer to its predecessor than 40 % of the local period
    // that the back-EMF indicates (a double crossing on noise).
    // Also drop an event before the rotor has turned half a commutation (the ripple's first
    // lobe against the trend's edge).
    let mut theta = vec![0.0; seg_i.len()];
    for k in 1..seg_i.len() {
        theta[k] = theta[k - 1] + w_emf[ks + k].max(0.0) * dt;
    }
    let theta_before = 0.5 * (w_emf[ks].max(0.0)) * (seg_t[0] - t0);
    let mut events: Vec<f64> = Vec::new();
    for &e in &raw {
        let k = (((e - seg_t[0]) / dt) as usize).min(seg_i.len() - 1);
        if theta_before + theta[k] < PI / n_c {
            continue;
        }
        match events.last() {
            Some(&p) if e - p < 0.4 * local_period(k) => {}
            _ => events.push(e),
        }
    }
    let first: Vec<f64> = events.iter().copied().take(n_c as usize).collect();
    if first.len() < 3 {
        return Err(ExtractError::NoRipple {
            role: "inrush",
            path: c.path.clone(),
            what: format!(
                "{} commutation(s) found in the run-up where the first revolution needs {}",
                first.len(),
                n_c
            ),
        });
    }
    // theta_k = c + alpha/2 (t_k - t0)^2 with theta_k = 2 pi k / N.
    let u: Vec<f64> = first.iter().map(|t| 0.5 * (t - t0).powi(2)).collect();
    let th: Vec<f64> = (1..=first.len())
        .map(|k| 2.0 * PI * k as f64 / n_c)
        .collect();
    let fit = polyfit(&u, &th, 1, 0.0)
        .ok_or_else(|| fail(c, "J", "the commutation times give no regression"))?;
    let (alpha, alpha_se) = (fit.coef[1], fit.cov[1][1].sqrt());
    if alpha <= 0.0 {
        return Err(fail(c, "J", "the commutations do not accelerate"));
    }
    let t_end = *first.last().unwrap_or(&t0);
    let k_end = c.t.iter().position(|&t| t >= t_end).unwrap_or(c.len());
    let i_avg = mean(&c.i[step..k_end.max(step + 1)]);
    if i_avg.is_nan() || i_avg <= 0.0 {
        return Err(fail(
            c,
            "J",
            format!(
                "the mean current over the first revolution is {i_avg:.3e} A; expected a positive inrush current"
            ),
        ));
    }
    let j = ke.value * i_avg / alpha;
    let se = j * ((alpha_se / alpha).powi(2) + ke.rel().powi(2)).sqrt();
    Ok((Estimate::new(j, se), first))
}
