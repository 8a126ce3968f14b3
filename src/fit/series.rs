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
}

impl Series {
    /// The series' noise, estimated robustly from its first differences (`1.4826 MAD /
    /// sqrt 2`, which a smooth signal sampled densely hardly affects), floored at a
    /// millionth of its range so a noise-free series weighs finitely.
    pub fn noise(&self) -> f64 {
        let mut d: Vec<f64> = self.measured.windows(2).map(|w| w[1] - w[0]).collect();
        let range = self
            .measured
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
        return values[0];
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
    // Points k and k+1 bracket t. Several points at one time (an event's delta cycles):
    // the last value at that time holds until the next point.
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
    // Where the trace has a corner (an event, a switch), the parabola overshoots; stay
    // within the bracketing values then.
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
        };
        // The MAD is Gaussian-calibrated: uniform noise reads within 20 % of its sd.
        let sigma = s.noise();
        assert!(sigma > 0.008 && sigma < 0.012, "{sigma}");
    }
}
