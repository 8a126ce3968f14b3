//! A measured column as the table of a testbench's input (`vams fit --drive`, and the motor
//! bench's terminal voltage in `vams extract`): the samples reduced to a `vams.tables.pwl`
//! table that keeps every edge and averages the noise and the scope's quantisation away
//! elsewhere.
//!
//! Adaptive block lines: a block of samples is kept as its least-squares line, two points at
//! its first and last sample's times (its mean alone, at its mean time, would stretch an
//! edge next to it over half the block: a step's ramp starting early biased a fitted time
//! constant by 0.1 %), when it is a line within its noise: every
//! sample within 5 sigma plus one quantisation step of the line (an edge fails this), and
//! the mean of each third of the block within 3 standard errors of it (a curve fails this
//! long before single samples show it). Otherwise it is split in two, down to single samples
//! at an edge. A block never spans more than `len / min_points` samples. The table is continuous (its points' times increase), and
//! driving a simulation with it costs one breakpoint per point: a flat stretch of a capture
//! costs a few, where the raw samples would cost thousands.

use super::series::noise;

/// The table `(t0, v0, t1, v1, ...)` of samples `values` at increasing `time`: at least
/// `min_points` points, and more only where the signal is not a line within its noise.
/// Empty input gives an empty table.
pub fn table(time: &[f64], values: &[f64], min_points: usize) -> Vec<f64> {
    let n = time.len().min(values.len());
    if n == 0 {
        return Vec::new();
    }
    let step = quantisation_step(&values[..n]);
    let sigma = noise(&values[..n]).max(trimmed_noise(&values[..n]));
    let longest = n.div_ceil(min_points.max(1)).max(1);
    let mut out = Vec::new();
    let mut stack = vec![(0, n)];
    // Depth first, left half first: the points come out in time order.
    while let Some((a, b)) = stack.pop() {
        let len = b - a;
        // Two samples always lie on their line: a block of fewer than three is kept as its
        // samples (an edge's first sample must not be averaged with the next).
        if len < 3 {
            for k in a..b {
                out.extend([time[k], values[k]]);
            }
        } else if len <= longest
            && let Some((mean_t, mean_v, slope)) = straight(&time[a..b], &values[a..b], sigma, step)
        {
            for t in [time[a], time[b - 1]] {
                out.extend([t, mean_v + slope * (t - mean_t)]);
            }
        } else {
            let mid = a + len / 2;
            stack.push((mid, b));
            stack.push((a, mid));
        }
    }
    out
}

/// The table as a VHDL positional aggregate, the text of a `real_vector` generic.
pub fn literal(flat: &[f64]) -> String {
    let items: Vec<String> = flat
        .iter()
        .map(|v| crate::output::csv::format_number(*v))
        .collect();
    format!("({})", items.join(", "))
}

/// The block's least-squares line (mean time, mean value, slope) when the block is a line
/// within noise `sigma` (see the module documentation).
fn straight(t: &[f64], v: &[f64], sigma: f64, step: f64) -> Option<(f64, f64, f64)> {
    let n = t.len();
    let mean = |x: &[f64]| x.iter().sum::<f64>() / x.len() as f64;
    let (tm, vm) = (mean(t), mean(v));
    let stt: f64 = t.iter().map(|x| (x - tm).powi(2)).sum();
    let stv: f64 = t.iter().zip(v).map(|(x, y)| (x - tm) * (y - vm)).sum();
    let slope = if stt > 0.0 { stv / stt } else { 0.0 };
    let off: Vec<f64> = t
        .iter()
        .zip(v)
        .map(|(x, y)| y - vm - slope * (x - tm))
        .collect();
    if off.iter().any(|d| d.abs() > 5.0 * sigma + step) {
        return None;
    }
    let third = n / 3;
    let se = 3.0 * sigma / (third as f64).sqrt() + 0.5 * step / (third as f64).sqrt();
    let curved = n >= 6
        && [&off[..third], &off[third..n - third], &off[n - third..]]
            .iter()
            .any(|part| mean(part).abs() > se);
    (!curved).then_some((tm, vm, slope))
}

/// The noise from the RMS of the first differences without their largest 2 % (the edges):
/// where the noise is below a scope's quantisation step most differences are 0, and the
/// median of their deviations (which [`noise`] takes) is 0 too.
fn trimmed_noise(values: &[f64]) -> f64 {
    let mut d: Vec<f64> = values.windows(2).map(|w| (w[1] - w[0]).abs()).collect();
    d.sort_by(f64::total_cmp);
    let keep = d.len() - d.len() / 50;
    if keep == 0 {
        return 0.0;
    }
    let ms = d[..keep].iter().map(|x| x * x).sum::<f64>() / keep as f64;
    (ms / 2.0).sqrt()
}

/// The smallest nonzero difference between two of the values (a scope's quantisation
/// step; 0 for a continuous-valued column, where it is tiny anyway).
fn quantisation_step(values: &[f64]) -> f64 {
    let mut sorted: Vec<f64> = values.iter().copied().filter(|v| v.is_finite()).collect();
    sorted.sort_by(f64::total_cmp);
    let step = sorted
        .windows(2)
        .map(|w| w[1] - w[0])
        .filter(|d| *d > 0.0)
        .fold(f64::INFINITY, f64::min);
    if step.is_finite() { step } else { 0.0 }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A step from 0 to 12 V at 1 ms with a sag that decays, sampled at 10 us with noise and
    /// 8-bit quantisation.
    fn captured() -> (Vec<f64>, Vec<f64>, Vec<f64>) {
        let lsb = 16.0 / 256.0;
        let mut state = 7u64;
        let mut gauss = || {
            // A sum of uniforms: close enough to Gaussian for a test of the reduction.
            (0..12)
                .map(|_| {
                    state = state
                        .wrapping_mul(6364136223846793005)
                        .wrapping_add(1442695040888963407);
                    (state >> 11) as f64 / (1u64 << 53) as f64
                })
                .sum::<f64>()
                - 6.0
        };
        let t: Vec<f64> = (0..5000).map(|k| k as f64 * 1e-5).collect();
        let truth: Vec<f64> = t
            .iter()
            .map(|&t| {
                if t < 1e-3 {
                    0.0
                } else {
                    12.0 - 0.5 * (-(t - 1e-3) / 2e-3).exp()
                }
            })
            .collect();
        let measured = truth
            .iter()
            .map(|v| ((v + 0.5 * lsb * gauss()) / lsb).round() * lsb)
            .collect();
        (t, truth, measured)
    }

    #[test]
    fn keeps_the_edge_and_averages_the_flat_parts() {
        let (t, truth, measured) = captured();
        let flat = table(&t, &measured, 50);
        let points = flat.len() / 2;
        assert!((50..200).contains(&points), "{points} points");
        // The table's times increase (a valid pwl table).
        vams_design::pwl::Table::new(&flat).expect("a valid table");
        // The edge: a point on each side of it, one sample apart, at 0 V and near 12 V.
        let xs: Vec<f64> = flat.iter().step_by(2).copied().collect();
        let at = |x: f64| xs.iter().position(|&p| (p - x).abs() < 1e-9);
        let before = at(0.99e-3).expect("a point at the last sample before the edge");
        let after = at(1.0e-3).expect("a point at the first sample after the edge");
        assert_eq!(after, before + 1);
        assert!(flat[2 * before + 1].abs() < 0.05 && flat[2 * after + 1] > 11.0);
        // Away from the edge, the table follows the truth far closer than one sample does.
        let table = vams_design::pwl::Table::new(&flat).unwrap();
        let (mut worst, mut raw) = (0.0f64, 0.0f64);
        for k in (120..5000).step_by(7) {
            worst = worst.max((table.value(t[k]) - truth[k]).abs());
            raw = raw.max((measured[k] - truth[k]).abs());
        }
        assert!(worst < 0.4 * raw, "table {worst} V, samples {raw} V");
    }

    #[test]
    fn the_literal_is_a_vhdl_aggregate() {
        assert_eq!(literal(&[0.0, 1.5, 1e-3, -2.0]), "(0, 1.5, 0.001, -2)");
        assert!(table(&[], &[], 10).is_empty());
    }
}
