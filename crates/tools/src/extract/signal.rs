//! Signal processing for noisy, quantised captures: robust statistics, least-squares
//! polynomial fits with standard errors, a Savitzky-Golay-style local trend, a spectral
//! (Goertzel-scan) ripple-frequency estimate, and hysteresis event detection.
//!
//! Takes plain sample slices; gives numbers with uncertainties. Knows nothing of motors.

use faer::Mat;
use faer::linalg::solvers::DenseSolveCore;

/// Median of a slice (NaN for an empty one).
pub fn median(x: &[f64]) -> f64 {
    if x.is_empty() {
        return f64::NAN;
    }
    let mut v = x.to_vec();
    v.sort_by(f64::total_cmp);
    let n = v.len();
    if n % 2 == 1 {
        v[n / 2]
    } else {
        0.5 * (v[n / 2 - 1] + v[n / 2])
    }
}

/// Mean of the middle 80 % of a slice: robust to spikes, and unlike the median it does
/// not snap to a quantisation level of dithered 8-bit samples.
pub fn trimmed_mean(x: &[f64]) -> f64 {
    let mut v = x.to_vec();
    v.sort_by(f64::total_cmp);
    let cut = v.len() / 10;
    mean(&v[cut..v.len() - cut])
}

/// Mean of a slice.
pub fn mean(x: &[f64]) -> f64 {
    x.iter().sum::<f64>() / x.len().max(1) as f64
}

/// Standard deviation of white noise on `x`, from the median absolute first difference
/// (robust to the signal's slow variation and to outliers).
pub fn noise_sigma(x: &[f64]) -> f64 {
    let d: Vec<f64> = x.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    // For Gaussian noise, median |x_k+1 - x_k| = 0.6745 * sqrt(2) * sigma.
    median(&d) / (0.6745 * std::f64::consts::SQRT_2)
}

/// Standard error of the mean of a slice (sample std / sqrt n).
pub fn sem(x: &[f64]) -> f64 {
    let m = mean(x);
    let var = x.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (x.len().max(2) - 1) as f64;
    (var / x.len().max(1) as f64).sqrt()
}

/// Centred moving median over `2*half+1` samples (shrinking at the ends).
pub fn moving_median(x: &[f64], half: usize) -> Vec<f64> {
    (0..x.len())
        .map(|k| median(&x[k.saturating_sub(half)..(k + half + 1).min(x.len())]))
        .collect()
}

/// Centred moving average over `2*half+1` samples (shrinking at the ends).
pub fn moving_average(x: &[f64], half: usize) -> Vec<f64> {
    let mut prefix = Vec::with_capacity(x.len() + 1);
    prefix.push(0.0);
    for v in x {
        prefix.push(prefix.last().copied().unwrap_or(0.0) + v);
    }
    (0..x.len())
        .map(|k| {
            let a = k.saturating_sub(half);
            let b = (k + half + 1).min(x.len());
            (prefix[b] - prefix[a]) / (b - a) as f64
        })
        .collect()
}

/// A polynomial least-squares fit `y = sum c_k (x - x0)^k` with the coefficients' covariance.
#[derive(Debug, Clone)]
pub struct PolyFit {
    /// The expansion point.
    pub x0: f64,
    /// Coefficients, lowest order first.
    pub coef: Vec<f64>,
    /// Covariance of the coefficients (residual variance times (A^T A)^-1).
    pub cov: Vec<Vec<f64>>,
    /// RMS of the residuals.
    pub rms: f64,
}

impl PolyFit {
    /// Value at `x`.
    pub fn value(&self, x: f64) -> f64 {
        let u = x - self.x0;
        self.coef.iter().rev().fold(0.0, |acc, c| acc * u + c)
    }

    /// Derivative at `x` and its standard error.
    pub fn slope(&self, x: f64) -> (f64, f64) {
        let u = x - self.x0;
        // d/dx = sum k c_k u^(k-1): gradient g_k = k u^(k-1).
        let g: Vec<f64> = (0..self.coef.len())
            .map(|k| {
                if k == 0 {
                    0.0
                } else {
                    k as f64 * u.powi(k as i32 - 1)
                }
            })
            .collect();
        let val = g.iter().zip(&self.coef).map(|(a, b)| a * b).sum();
        let var: f64 = (0..g.len())
            .flat_map(|a| (0..g.len()).map(move |b| (a, b)))
            .map(|(a, b)| g[a] * self.cov[a][b] * g[b])
            .sum();
        (val, var.max(0.0).sqrt())
    }
}

/// Fits a polynomial of `degree` to the points, expanded about `x0`. None when there are
/// too few points or the normal equations are singular.
pub fn polyfit(x: &[f64], y: &[f64], degree: usize, x0: f64) -> Option<PolyFit> {
    let n = x.len().min(y.len());
    let m = degree + 1;
    if n <= m {
        return None;
    }
    // Scale the abscissa to [-1, 1] for conditioning.
    let span = x
        .iter()
        .map(|v| (v - x0).abs())
        .fold(0.0, f64::max)
        .max(1e-300);
    let mut ata = Mat::<f64>::zeros(m, m);
    let mut aty = vec![0.0; m];
    for k in 0..n {
        let u = (x[k] - x0) / span;
        let mut pa = 1.0;
        for a in 0..m {
            aty[a] += pa * y[k];
            let mut pb = 1.0;
            for b in 0..m {
                ata[(a, b)] += pa * pb;
                pb *= u;
            }
            pa *= u;
        }
    }
    let llt = ata.llt(faer::Side::Lower).ok()?;
    let inv = llt.inverse();
    let c: Vec<f64> = (0..m)
        .map(|a| (0..m).map(|b| inv[(a, b)] * aty[b]).sum())
        .collect();
    let mut ss = 0.0;
    for k in 0..n {
        let u = (x[k] - x0) / span;
        let fit = c.iter().rev().fold(0.0, |acc, v| acc * u + v);
        ss += (y[k] - fit).powi(2);
    }
    let var = ss / (n - m) as f64;
    let coef: Vec<f64> = (0..m).map(|a| c[a] / span.powi(a as i32)).collect();
    let cov = (0..m)
        .map(|a| {
            (0..m)
                .map(|b| var * inv[(a, b)] / span.powi(a as i32) / span.powi(b as i32))
                .collect()
        })
        .collect();
    Some(PolyFit {
        x0,
        coef,
        cov,
        rms: (ss / n as f64).sqrt(),
    })
}

/// Local trend by a centred quadratic fit over `2*half(k)+1` samples at each sample (a
/// Savitzky-Golay smoother whose window may vary along the record). A wide window is
/// subsampled to at most 96 points, which keeps the cost linear in the record's length.
pub fn local_trend(y: &[f64], half: impl Fn(usize) -> usize) -> Vec<f64> {
    let n = y.len();
    (0..n)
        .map(|k| {
            let h = half(k).max(2);
            let a = k.saturating_sub(h);
            let b = (k + h + 1).min(n);
            let stride = ((b - a) / 96).max(1);
            quadratic_at_centre(y, a, b, stride, k).unwrap_or(y[k])
        })
        .collect()
}

/// Value at `k` of the quadratic fitted to `y[a..b]` (every `stride`-th sample).
fn quadratic_at_centre(y: &[f64], a: usize, b: usize, stride: usize, k: usize) -> Option<f64> {
    let scale = (b - a).max(1) as f64;
    let (mut s, mut t) = ([0.0f64; 5], [0.0f64; 3]);
    for j in (a..b).step_by(stride) {
        let u = (j as f64 - k as f64) / scale;
        let mut p = 1.0;
        for (e, acc) in s.iter_mut().enumerate() {
            *acc += p;
            if e < 3 {
                t[e] += p * y[j];
            }
            p *= u;
        }
    }
    // Normal equations [s0 s1 s2; s1 s2 s3; s2 s3 s4] c = t, solved for c0 by Cramer's rule.
    let det3 = |m: [[f64; 3]; 3]| {
        m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1])
            - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0])
            + m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0])
    };
    let m = [[s[0], s[1], s[2]], [s[1], s[2], s[3]], [s[2], s[3], s[4]]];
    let det = det3(m);
    if det.abs() < 1e-300 || s[0] < 4.0 {
        return None;
    }
    let m0 = [[t[0], s[1], s[2]], [t[1], s[2], s[3]], [t[2], s[3], s[4]]];
    Some(det3(m0) / det)
}

/// Power of the uniformly sampled `y` (spacing `dt`) at frequency `f`, by Goertzel.
fn goertzel_power(y: &[f64], dt: f64, f: f64) -> f64 {
    let w = 2.0 * std::f64::consts::PI * f * dt;
    let coeff = 2.0 * w.cos();
    let (mut s1, mut s2) = (0.0, 0.0);
    for &v in y {
        let s0 = v + coeff * s1 - s2;
        s2 = s1;
        s1 = s0;
    }
    s1 * s1 + s2 * s2 - coeff * s1 * s2
}

/// A spectral peak: frequency, its standard error, and peak-to-median power ratio.
#[derive(Debug, Clone, Copy)]
pub struct Peak {
    /// Frequency, Hz.
    pub freq: f64,
    /// Standard error of the frequency, Hz.
    pub se: f64,
    /// Peak power over the median power of the scanned band.
    pub prominence: f64,
}

fn windowed(y: &[f64]) -> Vec<f64> {
    let n = y.len();
    let xs: Vec<f64> = (0..n).map(|k| k as f64).collect();
    let trend = polyfit(&xs, y, 1, 0.0);
    (0..n)
        .map(|k| {
            let hann = 0.5 - 0.5 * (2.0 * std::f64::consts::PI * k as f64 / (n - 1) as f64).cos();
            let d = trend.as_ref().map_or(y[k], |t| y[k] - t.value(k as f64));
            d * hann
        })
        .collect()
}

fn peak_in(y: &[f64], dt: f64, fmin: f64, fmax: f64) -> Option<(f64, f64)> {
    let n = y.len();
    let span = n as f64 * dt;
    let yw = windowed(y);
    let df = 0.5 / span;
    let steps = ((fmax - fmin) / df).ceil() as usize;
    if steps < 8 {
        return None;
    }
    let powers: Vec<(f64, f64)> = (0..=steps)
        .map(|s| {
            let f = fmin + s as f64 * df;
            (f, goertzel_power(&yw, dt, f))
        })
        .collect();
    let best = powers.iter().copied().max_by(|a, b| a.1.total_cmp(&b.1))?;
    let med = median(&powers.iter().map(|p| p.1).collect::<Vec<_>>());
    // Refine by golden-section search on the continuous spectrum around the grid maximum.
    let (mut a, mut b) = (best.0 - df, best.0 + df);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..40 {
        let c = b - g * (b - a);
        let d = a + g * (b - a);
        if goertzel_power(&yw, dt, c) > goertzel_power(&yw, dt, d) {
            b = d;
        } else {
            a = c;
        }
    }
    Some((0.5 * (a + b), best.1 / med.max(1e-300)))
}

/// The dominant frequency of `y` (uniform spacing `dt`) in `[fmin, fmax]` after removing a
/// linear trend. The standard error comes from the spread of the estimates over four
/// quarters of the record. None when the band is too narrow for the record.
pub fn dominant_frequency(y: &[f64], dt: f64, fmin: f64, fmax: f64) -> Option<Peak> {
    // The search costs the record's length times the number of frequencies, which grows with
    // it: a long record (a scope's 100 000 points) is first reduced to block means of at most
    // 8 192 points, whose band still reaches far above any commutation line.
    const MOST: usize = 8192;
    if y.len() > MOST {
        let m = y.len().div_ceil(MOST);
        let reduced: Vec<f64> = y.chunks_exact(m).map(mean).collect();
        return dominant_frequency(&reduced, dt * m as f64, fmin, fmax);
    }
    let n = y.len();
    let span = n as f64 * dt;
    let fmin = fmin.max(4.0 / span);
    let fmax = fmax.min(0.45 / dt);
    let (freq, prominence) = peak_in(y, dt, fmin, fmax)?;
    let q = n / 4;
    let quarter: Vec<f64> = (0..4)
        .filter_map(|k| {
            let lo = (freq * 0.8).max(4.0 / (q as f64 * dt));
            peak_in(&y[k * q..(k + 1) * q], dt, lo, freq * 1.2).map(|p| p.0)
        })
        .collect();
    let se = if quarter.len() >= 2 {
        let m = mean(&quarter);
        let var = quarter.iter().map(|f| (f - m).powi(2)).sum::<f64>() / (quarter.len() - 1) as f64;
        // The full record has about twice the resolution of a quarter in each direction.
        (var / quarter.len() as f64).sqrt()
    } else {
        freq / (n as f64)
    };
    Some(Peak {
        freq,
        se: se.max(0.05 / span),
        prominence,
    })
}

/// Times where `y` crosses zero upwards, with hysteresis `h`: a crossing counts only after
/// `y` went below `-h`, and is placed where `y` passes 0 (linear interpolation).
pub fn upward_crossings(t: &[f64], y: &[f64], h: f64) -> Vec<f64> {
    let mut out = Vec::new();
    let mut armed = false;
    for k in 1..y.len().min(t.len()) {
        if y[k] < -h {
            armed = true;
        }
        if armed && y[k] > h {
            // Walk back to the sample where y crossed 0.
            let mut j = k;
            while j > 0 && y[j - 1] > 0.0 {
                j -= 1;
            }
            if j > 0 {
                let (y0, y1) = (y[j - 1], y[j]);
                let frac = if y1 != y0 { -y0 / (y1 - y0) } else { 0.5 };
                out.push(t[j - 1] + frac * (t[j] - t[j - 1]));
            }
            armed = false;
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn polyfit_recovers_a_quadratic_and_its_slope() {
        let x: Vec<f64> = (0..50).map(|k| k as f64 * 0.1).collect();
        let y: Vec<f64> = x.iter().map(|v| 1.0 + 2.0 * v - 0.5 * v * v).collect();
        let f = polyfit(&x, &y, 2, 1.0).unwrap();
        let (s, se) = f.slope(2.0);
        assert!((s - (2.0 - 2.0)).abs() < 1e-9 && se < 1e-6);
        assert!((f.value(3.0) - (1.0 + 6.0 - 4.5)).abs() < 1e-9);
    }

    #[test]
    fn dominant_frequency_of_a_noisy_tone() {
        let dt = 1e-4;
        let mut state = 1u64;
        let y: Vec<f64> = (0..5000)
            .map(|k| {
                state = state
                    .wrapping_mul(6364136223846793005)
                    .wrapping_add(1442695040888963407);
                let noise = ((state >> 33) as f64 / (1u64 << 31) as f64) - 0.5;
                (2.0 * std::f64::consts::PI * 437.3 * k as f64 * dt).sin()
                    + 0.5 * noise
                    + 0.001 * k as f64
            })
            .collect();
        let p = dominant_frequency(&y, dt, 10.0, 4000.0).unwrap();
        assert!((p.freq - 437.3).abs() < 0.2, "{p:?}");
        assert!(p.prominence > 100.0);
        assert!(p.se < 1.0);
    }

    #[test]
    fn local_trend_follows_a_parabola_and_smooths_a_tone() {
        let y: Vec<f64> = (0..2000)
            .map(|k| {
                1e-6 * (k as f64).powi(2) + (2.0 * std::f64::consts::PI * k as f64 / 200.0).sin()
            })
            .collect();
        let tr = local_trend(&y, |_| 400);
        for k in [500, 1000, 1500] {
            assert!(
                (tr[k] - 1e-6 * (k as f64).powi(2)).abs() < 0.1,
                "{k}: {}",
                tr[k]
            );
        }
    }

    #[test]
    fn crossings_ignore_noise_below_the_hysteresis() {
        let t: Vec<f64> = (0..1000).map(|k| k as f64 * 1e-3).collect();
        let y: Vec<f64> = t
            .iter()
            .enumerate()
            .map(|(k, v)| {
                (2.0 * std::f64::consts::PI * 5.0 * v).sin() + if k % 2 == 0 { 0.05 } else { -0.05 }
            })
            .collect();
        let c = upward_crossings(&t, &y, 0.3);
        assert_eq!(c.len(), 4, "{c:?}");
        assert!((c[0] - 0.2).abs() < 2e-3);
    }
}
