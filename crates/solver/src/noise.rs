//! Noise analysis on a linearised system: the output noise power spectral density at one
//! output, `S_y(f) = sum_k |H_k(jw)|^2 S_k(f)`, for uncorrelated sources `k` of densities
//! `S_k` entering the right side at known rows.
//!
//! The transfers `H_k` come from one adjoint solve per frequency: with the output `y = c^T X`
//! and `A X = B`, `y = z^T B` where `A^T z = c`, so `H_k = z[row_k] * coefficient_k` for every
//! source at once (SPICE's `.noise` does the same), on the symbolic factorisation `AcSolver`
//! keeps across frequencies. The band's integral is the trapezoid rule in frequency on the
//! analysis grid.
//!
//! Knows nothing of VHDL: rows, columns and densities are the caller's.

use faer::c64;

use super::ac::{AcSolveError, AcSolver};

/// Where an independent source enters the right side: a unit phasor of it puts
/// `coefficient` in `row`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Injection {
    pub row: usize,
    pub coefficient: f64,
}

/// The noise at the output at one frequency.
#[derive(Clone, Debug, PartialEq)]
pub struct NoisePoint {
    /// Each source's contribution to the output PSD, `|H_k|^2 S_k`.
    pub contributions: Vec<f64>,
    /// Their sum: the output PSD (the sources are uncorrelated, so powers add).
    pub total: f64,
    /// The transfers from the extra injections asked for (e.g. an input, for input-referred
    /// noise), in the order given.
    pub gains: Vec<c64>,
}

/// The output `y = sum_j (a_j + jw b_j) X_j` as the right side of the adjoint system.
fn output_vector(n: usize, output: &[(usize, f64, f64)], omega: f64) -> Vec<c64> {
    let mut c = vec![c64::default(); n];
    for &(j, a, b) in output {
        if let Some(slot) = c.get_mut(j) {
            *slot += c64::new(a, omega * b);
        }
    }
    c
}

/// The output noise at `frequency` (hertz): `output` as `(unknown, dy/dx, dy/dx')`, the
/// sources' injections and their PSDs (same order), and `extra` injections whose transfers
/// to the output are wanted too.
pub fn noise_at(
    solver: &mut AcSolver,
    frequency: f64,
    output: &[(usize, f64, f64)],
    sources: &[Injection],
    densities: &[f64],
    extra: &[Injection],
) -> Result<NoisePoint, AcSolveError> {
    let omega = std::f64::consts::TAU * frequency;
    let c = output_vector(solver.system().n, output, omega);
    let z = solver.solve_transposed(frequency, &c)?;
    let gain = |i: &Injection| z.get(i.row).copied().unwrap_or_default() * i.coefficient;
    let contributions: Vec<f64> = (sources.iter().zip(densities))
        .map(|(i, &s)| gain(i).norm_sqr() * s)
        .collect();
    Ok(NoisePoint {
        total: contributions.iter().sum(),
        contributions,
        gains: extra.iter().map(gain).collect(),
    })
}

/// `integral of psd df` over the grid by the trapezoid rule: `sum (f_{i+1} - f_i) (S_i +
/// S_{i+1}) / 2`. Exact for a PSD linear in frequency between grid points; on a log grid of
/// `n` points per decade a smooth PSD's relative error is of order `(ln 10 / n)^2 / 12`
/// times its curvature in `ln f`.
pub fn integrate(frequencies: &[f64], psd: &[f64]) -> f64 {
    (frequencies.windows(2).zip(psd.windows(2)))
        .map(|(f, s)| (f[1] - f[0]) * (s[0] + s[1]) / 2.0)
        .sum()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::ac::{SmallSignal, Spacing, frequencies};

    /// Unknowns `n` (a noise source, row 0: `n == 0`), `v` (a resistor's node, row 1:
    /// `c v' + (v - n) / r = 0`): thermal noise `n` in series with `r`, loaded by `c`.
    fn noisy_rc(r: f64, c: f64) -> AcSolver {
        AcSolver::new(SmallSignal {
            n: 2,
            pattern: vec![(0, 0), (1, 0), (1, 1)],
            g: vec![1.0, -1.0 / r, 1.0 / r],
            c: vec![0.0, 0.0, c],
            delays: Vec::new(),
            sampled: Vec::new(),
        })
        .expect("a 2x2 pattern")
    }

    #[test]
    fn thermal_noise_of_an_rc_follows_its_transfer() {
        let (r, c) = (1e3, 1e-9);
        let mut solver = noisy_rc(r, c);
        let psd = 4.0 * 1.380649e-23 * 300.0 * r;
        let source = [Injection {
            row: 0,
            coefficient: 1.0,
        }];
        for f in [1.0, 1.591549e5, 1e8] {
            let p = noise_at(&mut solver, f, &[(1, 1.0, 0.0)], &source, &[psd], &source).unwrap();
            let wrc = std::f64::consts::TAU * f * r * c;
            let exact = psd / (1.0 + wrc * wrc);
            assert!((p.total / exact - 1.0).abs() < 1e-12, "{f}: {}", p.total);
            assert_eq!(p.contributions, vec![p.total]);
            assert!((p.gains[0].norm_sqr() * psd / exact - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn an_output_through_its_derivative_reads_jw() {
        // The output `c v'` (the capacitor's current): |H| = w c / |1 + jwrc|.
        let (r, c) = (1e3, 1e-9);
        let mut solver = noisy_rc(r, c);
        let source = [Injection {
            row: 0,
            coefficient: -2.0,
        }];
        let f = 1e5;
        let p = noise_at(&mut solver, f, &[(1, 0.0, c)], &source, &[1.0], &[]).unwrap();
        let w = std::f64::consts::TAU * f;
        let wrc = w * r * c;
        let exact = 4.0 * (w * c).powi(2) / (1.0 + wrc * wrc);
        assert!((p.total / exact - 1.0).abs() < 1e-12, "{}", p.total);
    }

    #[test]
    fn the_trapezoid_integrates_kt_over_c() {
        // The RC's output noise over 0..inf is kT/C; a dense log grid far past the corner
        // gets it to the rule's error.
        let (r, c, kt) = (1e3, 1e-9, 1.380649e-23 * 300.0);
        let mut solver = noisy_rc(r, c);
        let source = [Injection {
            row: 0,
            coefficient: 1.0,
        }];
        let grid = frequencies(1e-2, 1e12, Spacing::PerDecade(200));
        let psd: Vec<f64> = (grid.iter())
            .map(|&f| {
                noise_at(
                    &mut solver,
                    f,
                    &[(1, 1.0, 0.0)],
                    &source,
                    &[4.0 * kt * r],
                    &[],
                )
                .unwrap()
                .total
            })
            .collect();
        let total = integrate(&grid, &psd);
        assert!((total / (kt / c) - 1.0).abs() < 1e-4, "{total}");
        assert_eq!(integrate(&[1.0, 3.0], &[2.0, 4.0]), 6.0);
        assert_eq!(integrate(&[1.0], &[2.0]), 0.0);
    }
}
