//! The coast capture (d): where the supply is disconnected and where the rotor stops, the
//! probes' offsets at standstill, and the paper's Tcst_motor and D from the slopes of the
//! back-EMF at the end and the start of the coast.

use super::{Estimate, fail};
use crate::extract::capture::Capture;
use crate::extract::error::ExtractError;
use crate::extract::signal::{mean, median, moving_average, moving_median, noise_sigma, polyfit};

/// Finds disconnect, start and stop of the coast, removes the offsets; returns
/// (start, stop, voltage offset, current offset).
pub(super) fn landmarks(c: &mut Capture) -> Result<(usize, usize, f64, f64), ExtractError> {
    let n = c.len();
    let im = moving_median(&c.i, 2);
    let i_pre = median(&im[..(n / 50).max(3)]);
    // Plain means for the offsets (see `zero_pre_trigger`).
    let i_post = mean(&c.i[n / 2..]);
    let si = noise_sigma(&c.i);
    let kd = if i_pre - i_post > 5.0 * si.max(1e-9) {
        im.iter()
            .position(|&v| v < 0.5 * (i_pre + i_post))
            .unwrap_or(0)
    } else {
        0
    };
    let guard = (n / 500).max(5);
    let k_s = (kd + guard).min(n - 1);
    let v_start = median(&c.v[k_s..(k_s + 20).min(n)]);
    let tail = mean(&c.v[n - n / 20..]);
    if v_start <= 0.0 || tail > 0.05 * v_start {
        return Err(ExtractError::CoastNeverStops {
            path: c.path.clone(),
            what: format!(
                "the voltage is still {tail:.3} V at the end of the record (it started at {v_start:.3} V); expected it to fall to about 0 V"
            ),
        });
    }
    c.v.iter_mut().for_each(|v| *v -= tail);
    c.i.iter_mut().for_each(|i| *i -= i_post);
    let vs = moving_average(&c.v, (n / 400).max(1));
    let thr = (4.0 * noise_sigma(&c.v)).max(0.02 * (v_start - tail));
    let stop = (k_s..n).find(|&k| vs[k] < thr).unwrap_or(n - 1);
    if stop + n / 50 >= n {
        return Err(ExtractError::CoastNeverStops {
            path: c.path.clone(),
            what: "the rotor comes to rest only at the very end of the record; expected some samples at standstill".into(),
        });
    }
    Ok((k_s, stop, tail, i_post))
}

pub(super) fn friction(
    c: &Capture,
    start: usize,
    stop: usize,
    ke: &Estimate,
    j: &Estimate,
) -> Result<(Estimate, Estimate), ExtractError> {
    let v0 = median(&c.v[start..(start + 20).min(stop)]);
    // End: quadratic over the last stretch (from 30 % of the start voltage down to the stop),
    // slope where the fit reaches 0 V.
    let ka = (start..stop).find(|&k| c.v[k] < 0.3 * v0).unwrap_or(start);
    if stop < ka + 10 {
        return Err(fail(
            c,
            "Tcst_motor",
            "too few samples between 30 % of the start voltage and the stop",
        ));
    }
    let t_stop = c.t[stop];
    let end_fit = polyfit(&c.t[ka..stop], &c.v[ka..stop], 2, t_stop)
        .ok_or_else(|| fail(c, "Tcst_motor", "the end of the coast gives no regression"))?;
    // Root of c0 + c1 u + c2 u^2 nearest u = 0.
    let [c0, c1, c2] = [end_fit.coef[0], end_fit.coef[1], end_fit.coef[2]];
    let u_root = if c2.abs() > 1e-300 {
        let disc = c1 * c1 - 4.0 * c2 * c0;
        if disc >= 0.0 {
            let s = disc.sqrt();
            let r1 = (-c1 + s) / (2.0 * c2);
            let r2 = (-c1 - s) / (2.0 * c2);
            if r1.abs() < r2.abs() { r1 } else { r2 }
        } else {
            -c0 / c1
        }
    } else {
        -c0 / c1
    };
    let (slope_end, slope_end_se) = end_fit.slope(t_stop + u_root);
    if slope_end >= 0.0 {
        return Err(fail(
            c,
            "Tcst_motor",
            "the voltage does not fall at the end of the coast",
        ));
    }
    let tcst_v = -j.value * slope_end / ke.value;
    let tcst = Estimate::new(
        tcst_v,
        tcst_v * (j.rel().powi(2) + ke.rel().powi(2) + (slope_end_se / slope_end).powi(2)).sqrt(),
    );
    // Start: quadratic over the first 15 % of the coast, slope at its start.
    let kb = start + ((stop - start) * 15 / 100).max(10);
    let t_s = c.t[start];
    let start_fit = polyfit(&c.t[start..kb], &c.v[start..kb], 2, t_s)
        .ok_or_else(|| fail(c, "D", "the start of the coast gives no regression"))?;
    let (slope_s, slope_s_se) = start_fit.slope(t_s);
    let w_s = start_fit.coef[0] / ke.value;
    let torque = -j.value * slope_s / ke.value;
    let d_v = ((torque - tcst.value) / w_s).max(1e-3 * tcst.value / w_s);
    let torque_se =
        torque * (j.rel().powi(2) + ke.rel().powi(2) + (slope_s_se / slope_s).powi(2)).sqrt();
    let d = Estimate::new(d_v, torque_se.hypot(tcst.se) / w_s);
    Ok((tcst, d))
}
