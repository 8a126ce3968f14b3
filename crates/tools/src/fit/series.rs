//! A measured series: one column of one capture, as the fit compares it with a simulation.

/// One measured column of one capture, at the times the simulation is compared.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// The experiment (capture) it belongs to.
    pub experiment: usize,
    /// What the simulation records for it (a quantity or signal name).
    pub simulated: String,
    /// How it is named to people (`coast.csv: voltage`).
    pub label: String,
    /// Sample times in the simulation's time (s).
    pub time: Vec<f64>,
    /// Measured values.
    pub measured: Vec<f64>,
    /// Where each measured value is the mean of a block of samples (a reduced capture), the
    /// block's duration: the simulation is then averaged over the same interval, so that the
    /// curvature of a fast edge inside a block does not bias the fit. Empty: point samples.
    pub width: Vec<f64>,
    /// The interval of the samples the blocks were made of (0: unknown): a point or block
    /// within one such interval of a jump of the simulation (a switch) is not compared
    /// ([`near_jump`]).
    pub sample_interval: f64,
    /// The measurement's standard deviation where it is known (a value derived from another
    /// measurement, with its standard error): the series then weighs by it throughout,
    /// instead of by its estimated noise and misfit.
    pub sigma: Option<f64>,
    /// The measuring channel's additive offset (a probe's zero), fitted with the parameters:
    /// the measured value is the simulated one plus offset number `k`, shared by every series
    /// that names `k` (one probe in several captures). `None`: the channel reads true. An
    /// offset estimated beforehand and subtracted is exact to the fit, and its error, common
    /// to every sample of a capture, then escapes the intervals: fitted, it is counted.
    pub offset: Option<usize>,
}

impl Series {
    /// The series' noise, estimated robustly from its first differences (`1.4826 MAD /
    /// sqrt 2`, which a smooth signal sampled densely hardly affects), floored at a
    /// millionth of its range so a noise-free series weighs finitely.
    pub fn noise(&self) -> f64 {
        match self.sigma {
            Some(sigma) => sigma,
            None => noise(&self.measured),
        }
    }
}

/// The noise of samples `values`, estimated robustly from their first differences (`1.4826
/// MAD / sqrt 2`), floored at a millionth of their range (1 for fewer than three samples).
pub fn noise(values: &[f64]) -> f64 {
    let mut d: Vec<f64> = values.windows(2).map(|w| w[1] - w[0]).collect();
    let range = values
        .iter()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(*v), hi.max(*v))
        });
    let floor = ((range.1 - range.0).abs() * 1e-6).max(1e-300);
    if d.len() < 2 {
        return floor.max(1.0);
    }
    let m = median(&mut d);
    let mut dev: Vec<f64> = d.iter().map(|v| (v - m).abs()).collect();
    let mad = median(&mut dev);
    (1.4826 * mad / std::f64::consts::SQRT_2).max(floor)
}

fn median(v: &mut [f64]) -> f64 {
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// The durations of the blocks that [`crate::capture::Capture::decimated`] averages `time`
/// into for `max_points` (empty when it keeps every sample): each block's first to last
/// sample plus one sample interval.
pub fn block_widths(time: &[f64], max_points: usize) -> Vec<f64> {
    let n = time.len();
    if max_points == 0 || n <= max_points || n < 2 {
        return Vec::new();
    }
    let dt = (time[n - 1] - time[0]) / (n - 1) as f64;
    time.chunks(n.div_ceil(max_points))
        .map(|b| b[b.len() - 1] - b[0] + dt)
        .collect()
}

/// The mean interval of `time` (0 for fewer than two samples).
pub fn sample_interval(time: &[f64]) -> f64 {
    match time {
        [first, .., last] => (last - first) / (time.len() - 1) as f64,
        _ => 0.0,
    }
}

/// Whether the trace jumps (two points at one time with different values: a switch, a
/// `break`) within `[t - width/2 - dt, t + width/2 + dt]`: a block, or a point sample, within
/// a sample interval `dt` of a jump. Such a point is not compared (see
/// [`crate::fit::Simulated`]); the margin of a whole sample keeps a point out while a
/// switching time moves by less than a sample around it, so that a difference step never
/// moves the jump across a compared sample.
pub fn near_jump(times: &[f64], values: &[f64], t: f64, width: f64, dt: f64) -> bool {
    let reach = 0.5 * width.max(0.0) + dt.max(0.0);
    let (a, b) = (t - reach, t + reach);
    let from = times.partition_point(|x| *x < a).max(1);
    let to = times.partition_point(|x| *x <= b).min(times.len());
    (from..to).any(|k| {
        times[k] == times[k - 1] && {
            let (u, v) = (values[k - 1], values[k]);
            (u - v).abs() > 1e-9 * u.abs().max(v.abs())
        }
    })
}

/// The mean of a trace over `[t - width/2, t + width/2]`: the exact integral of its
/// piecewise-linear interpolant (the simulator's points are dense where the response curves,
/// and an edge, two points at one time, is integrated as the step it is), or its value at `t`
/// for a zero width. `hint` as for [`interpolate`].
pub fn block_mean(times: &[f64], values: &[f64], t: f64, width: f64, hint: &mut usize) -> f64 {
    if width <= 0.0 || times.len() < 2 {
        return interpolate(times, values, t, hint);
    }
    let (a, b) = (t - 0.5 * width, t + 0.5 * width);
    let n = times.len();
    // Before the first point and after the last, the trace holds its end values.
    let mut area = 0.0;
    if a < times[0] {
        let k = times.partition_point(|x| *x <= times[0]).saturating_sub(1);
        area += values[k] * (b.min(times[0]) - a);
    }
    if b > times[n - 1] {
        area += values[n - 1] * (b - a.max(times[n - 1]));
    }
    // The segments that overlap [a, b], each by Simpson's rule on its own interpolant (exact
    // for the quadratic through it; an edge, a segment of zero length, adds nothing).
    let mut k = (*hint).min(n - 2);
    if times[k] > a {
        k = times.partition_point(|x| *x <= a).saturating_sub(1);
    }
    while k + 1 < n && times[k + 1] <= a {
        k += 1;
    }
    let start = k;
    while k + 1 < n && times[k] < b {
        let (lo, hi) = (times[k].max(a), times[k + 1].min(b));
        if hi > lo {
            let f = |x: f64| in_segment(times, values, k, x);
            area += (hi - lo) * (f(lo) + 4.0 * f(0.5 * (lo + hi)) + f(hi)) / 6.0;
        }
        k += 1;
    }
    *hint = start;
    area / width
}

/// The value of a piecewise trace `(times, values)` at `t` by quadratic interpolation through
/// the three nearest points (the simulator's accepted points are far apart where the solution
/// is smooth: a straight line between them would be the largest error of the comparison).
/// `hint` is the index to start searching from (times are visited in order).
pub fn interpolate(times: &[f64], values: &[f64], t: f64, hint: &mut usize) -> f64 {
    let n = times.len();
    if n == 0 {
        return f64::NAN;
    }
    if n == 1 || t <= times[0] {
        // The last value at the first time: a run starts with its quiescent point, then the
        // rows its initial delta cycles and `break`s give at the same time.
        let k = times.partition_point(|x| *x <= times[0]);
        return values[k.saturating_sub(1)];
    }
    if t >= times[n - 1] {
        return values[n - 1];
    }
    let mut k = (*hint).min(n - 2);
    if times[k] > t {
        k = times.partition_point(|x| *x <= t).saturating_sub(1);
    }
    while k + 1 < n && times[k + 1] <= t {
        k += 1;
    }
    *hint = k;
    in_segment(times, values, k, t)
}

/// The trace's value at `t` in its segment `k` (`times[k] <= t <= times[k + 1]`): the
/// quadratic through the segment and a third point on the nearer side, or the straight line
/// where that parabola would overshoot (a corner: an event, a switch).
fn in_segment(times: &[f64], values: &[f64], k: usize, t: f64) -> f64 {
    let n = times.len();
    // Several points at one time (an event's delta cycles): the last value at that time
    // holds until the next point.
    let (t0, t1) = (times[k], times[k + 1]);
    if t1 <= t0 {
        return values[k + 1];
    }
    // A third point on the nearer side, when it is a distinct time.
    let third = if k > 0 && (t - t0) < (t1 - t) && times[k - 1] < t0 {
        Some(k - 1)
    } else if k + 2 < n && times[k + 2] > t1 {
        Some(k + 2)
    } else if k > 0 && times[k - 1] < t0 {
        Some(k - 1)
    } else {
        None
    };
    let linear = values[k] + (values[k + 1] - values[k]) * (t - t0) / (t1 - t0);
    let Some(j) = third else {
        return linear;
    };
    let (a, b, c) = (t0, t1, times[j]);
    let (ya, yb, yc) = (values[k], values[k + 1], values[j]);
    let q = ya * (t - b) * (t - c) / ((a - b) * (a - c))
        + yb * (t - a) * (t - c) / ((b - a) * (b - c))
        + yc * (t - a) * (t - b) / ((c - a) * (c - b));
    let (lo, hi) = if ya < yb { (ya, yb) } else { (yb, ya) };
    if q.is_finite() && q >= lo - (hi - lo) && q <= hi + (hi - lo) {
        q
    } else {
        linear
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn quadratic_interpolation_is_exact_on_parabolas() {
        let t: Vec<f64> = vec![0.0, 0.3, 1.0, 1.1, 2.5];
        let y: Vec<f64> = t.iter().map(|t| 1.0 + 2.0 * t - 0.5 * t * t).collect();
        let mut hint = 0;
        for k in 0..=25 {
            let x = k as f64 * 0.1;
            let v = interpolate(&t, &y, x, &mut hint);
            assert!(
                (v - (1.0 + 2.0 * x - 0.5 * x * x)).abs() < 1e-12,
                "{x}: {v}"
            );
        }
    }

    #[test]
    fn block_means_integrate_edges_and_curves_exactly() {
        // A step from 0 to 1 at t = 1 (two points at one time), flat after it.
        let t = [0.0, 1.0, 1.0, 2.0, 3.0, 4.0];
        let y = [0.0, 0.0, 1.0, 1.0, 1.0, 1.0];
        let mut hint = 0;
        // [0.5, 1.5]: half at 0, half at 1.
        assert!((block_mean(&t, &y, 1.0, 1.0, &mut hint) - 0.5).abs() < 1e-15);
        // Beyond the end the last value holds.
        assert!((block_mean(&t, &y, 4.0, 1.0, &mut hint) - 1.0).abs() < 1e-15);
        // A parabola sampled at whole seconds: its mean over [1.5, 2.5] exactly.
        let t = [0.0, 1.0, 2.0, 3.0, 4.0];
        let y = t.map(|t| t * t);
        let mut hint = 0;
        let exact = (2.5f64.powi(3) - 1.5f64.powi(3)) / 3.0;
        assert!((block_mean(&t, &y, 2.0, 1.0, &mut hint) - exact).abs() < 1e-12);
        // A zero width is the value at the point.
        assert!((block_mean(&t, &y, 2.5, 0.0, &mut hint) - 6.25).abs() < 1e-12);
    }

    #[test]
    fn points_within_a_sample_of_a_jump_are_near_it() {
        // A jump at 1.1 (two points at one time), and a continuous kink at 3 (two points at
        // one time with one value: a break that changes nothing of this trace).
        let t = [0.0, 1.1, 1.1, 2.0, 3.0, 3.0, 4.0];
        let y = [0.0, 0.0, 1.0, 1.0, 1.0, 1.0, 0.0];
        // Points 0.5 apart: 1.0 and 1.5 are within a sample of the jump, 0.5 and 2.0 are not.
        for (t0, near) in [(0.5, false), (1.0, true), (1.5, true), (2.0, false)] {
            assert_eq!(near_jump(&t, &y, t0, 0.0, 0.5), near, "{t0}");
        }
        // The kink is no jump.
        assert!(!near_jump(&t, &y, 3.0, 0.0, 0.5));
        // A block [0, 0.8] reaches the jump with its margin of 0.5; [-0.5, 0.1] does not.
        assert!(near_jump(&t, &y, 0.4, 0.8, 0.5));
        assert!(!near_jump(&t, &y, -0.2, 0.6, 0.5));
    }

    #[test]
    fn noise_of_a_smooth_signal_is_its_noise() {
        let n = 5000;
        // Uniform noise of sd 0.01 from a linear congruential stream.
        let mut state = 12345u64;
        let measured: Vec<f64> = (0..n)
            .map(|k| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let u = (state >> 11) as f64 / (1u64 << 53) as f64;
                let t = k as f64 / n as f64;
                (1.0 - (-5.0 * t).exp()) + 0.01 * 3f64.sqrt() * (2.0 * u - 1.0)
            })
            .collect();
        let s = Series {
            experiment: 0,
            simulated: "v".into(),
            label: "v".into(),
            time: (0..n).map(|k| k as f64).collect(),
            measured,
            width: Vec::new(),
            sample_interval: 0.0,
            sigma: None,
            offset: None,
        };
        // The MAD is Gaussian-calibrated: uniform noise reads within 20 % of its sd.
        let sigma = s.noise();
        assert!(sigma > 0.008 && sigma < 0.012, "{sigma}");
    }
}
