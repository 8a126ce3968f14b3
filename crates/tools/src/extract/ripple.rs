//! The commutation ripple of a motor's current, as the joint fit accounts for it.
//!
//! A brushed motor's current carries a ripple at the commutation frequency that its model
//! (`dc_motor`) does not have: as the rotor turns, the brushes short one coil after the other.
//! Where the rotor starts from rest (the inrush), the first commutation period is a slow
//! swell of the current, not an oscillation the fit can see as noise: fitted without it, the
//! swell reads as a lower armature resistance (0.4 % on the demo motor, with a covariance
//! interval a fifth of that). The ripple is a periodic function of the rotor's angle, so it is
//! modelled as one: a relative modulation of the simulated current, a Fourier series in the
//! simulated angle at the commutation harmonics and their sidebands of one revolution (a
//! ripple whose depth varies around the revolution), `i (1 + sum a_k cos(k theta) + b_k sin(k
//! theta))`. Its coefficients are linear, and are solved for at each simulation (variable
//! projection): the optimiser sees the residual left by the best ripple, and the parameters'
//! sensitivities include the ripple's adjustment to them.

use faer::Mat;
use faer::linalg::solvers::DenseSolveCore;

/// The harmonics of the rotor's angle that make up the ripple.
#[derive(Debug, Clone)]
pub struct RippleModel {
    harmonics: Vec<f64>,
}

impl RippleModel {
    /// The ripple of a motor with `commutations` per revolution: the first two commutation
    /// harmonics, each with the sidebands of one revolution.
    pub fn commutation(commutations: u32) -> RippleModel {
        let n = commutations.max(1);
        let mut harmonics: Vec<u32> = [n, 2 * n]
            .iter()
            .flat_map(|&h| [h - 1, h, h + 1])
            .filter(|&h| h > 0)
            .collect();
        harmonics.sort_unstable();
        harmonics.dedup();
        RippleModel {
            harmonics: harmonics.into_iter().map(f64::from).collect(),
        }
    }

    /// The simulated series with the ripple that best explains the measured one added: the
    /// coefficients by least squares over the points compared (`simulated` not `None`, every
    /// value finite), with a constant beside them that is not applied (a probe's offset,
    /// which the fit estimates itself, must not lean on the ripple). The series unchanged
    /// where the points do not determine the coefficients.
    pub fn apply(
        &self,
        simulated: &[Option<f64>],
        angle: &[Option<f64>],
        measured: &[f64],
    ) -> Vec<Option<f64>> {
        let columns = 2 * self.harmonics.len() + 1;
        let rows: Vec<(f64, f64, f64)> = simulated
            .iter()
            .zip(angle)
            .zip(measured)
            .filter_map(|((s, a), m)| Some(((*s)?, (*a)?, *m)))
            .filter(|(s, a, m)| s.is_finite() && a.is_finite() && m.is_finite())
            .collect();
        let Some(coefficients) = (rows.len() > 4 * columns)
            .then(|| self.solve(&rows, columns))
            .flatten()
        else {
            return simulated.to_vec();
        };
        simulated
            .iter()
            .zip(angle)
            .map(|(s, a)| {
                let (s, a) = ((*s)?, a.unwrap_or(0.0));
                let mut basis = vec![0.0; columns];
                self.basis(s, a, &mut basis);
                // The constant (last) is the offset's, not the ripple's.
                let ripple: f64 = basis[..columns - 1]
                    .iter()
                    .zip(&coefficients)
                    .map(|(b, c)| b * c)
                    .sum();
                Some(s + ripple)
            })
            .collect()
    }

    /// The row of the least-squares problem at a point: the simulated value times each
    /// harmonic's cosine and sine, then the constant.
    fn basis(&self, simulated: f64, angle: f64, row: &mut [f64]) {
        for (k, h) in self.harmonics.iter().enumerate() {
            let (sin, cos) = (h * angle).sin_cos();
            row[2 * k] = simulated * cos;
            row[2 * k + 1] = simulated * sin;
        }
        row[row.len() - 1] = 1.0;
    }

    /// The coefficients of `measured - simulated` on the basis (normal equations with the
    /// columns scaled to unit norm; None where singular).
    fn solve(&self, rows: &[(f64, f64, f64)], columns: usize) -> Option<Vec<f64>> {
        let mut ata = Mat::<f64>::zeros(columns, columns);
        let mut atb = vec![0.0; columns];
        let mut row = vec![0.0; columns];
        for &(s, a, m) in rows {
            self.basis(s, a, &mut row);
            for i in 0..columns {
                atb[i] += row[i] * (m - s);
                for j in 0..=i {
                    ata[(i, j)] += row[i] * row[j];
                }
            }
        }
        let scale: Vec<f64> = (0..columns)
            .map(|i| {
                let d = ata[(i, i)].sqrt();
                if d > 0.0 { 1.0 / d } else { 0.0 }
            })
            .collect();
        if scale.contains(&0.0) {
            return None;
        }
        for i in 0..columns {
            for j in 0..=i {
                let v = ata[(i, j)] * scale[i] * scale[j];
                ata[(i, j)] = v;
                ata[(j, i)] = v;
            }
        }
        let inverse = ata.llt(faer::Side::Lower).ok()?.inverse();
        let c: Vec<f64> = (0..columns)
            .map(|i| {
                scale[i]
                    * (0..columns)
                        .map(|j| inverse[(i, j)] * atb[j] * scale[j])
                        .sum::<f64>()
            })
            .collect();
        c.iter().all(|v| v.is_finite()).then_some(c)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_ripple_of_the_commutation_harmonics_is_taken_out_exactly() {
        // A decaying current with a 4-commutation ripple whose depth varies around the
        // revolution, read 0.05 high by its probe.
        let model = RippleModel::commutation(4);
        let n = 4000;
        let angle: Vec<Option<f64>> = (0..n).map(|k| Some(0.01 * k as f64)).collect();
        let simulated: Vec<Option<f64>> = (0..n)
            .map(|k| Some(2.0 * (-(k as f64) / 1500.0).exp() + 0.3))
            .collect();
        let measured: Vec<f64> = simulated
            .iter()
            .zip(&angle)
            .map(|(s, a)| {
                let (s, a) = (s.unwrap(), a.unwrap());
                let depth = 0.08 * (1.0 + 0.25 * a.cos());
                s * (1.0 + depth * ((4.0 * a).sin() + 0.3 * (8.0 * a).sin())) + 0.05
            })
            .collect();
        let fitted = model.apply(&simulated, &angle, &measured);
        for (f, m) in fitted.iter().zip(&measured) {
            // What is left is the offset alone.
            assert!((m - f.unwrap() - 0.05).abs() < 1e-9, "{f:?} {m}");
        }
    }

    #[test]
    fn too_few_points_leave_the_series_alone() {
        let model = RippleModel::commutation(4);
        let simulated = vec![Some(1.0), None, Some(1.0)];
        let angle = vec![Some(0.0), Some(1.0), Some(2.0)];
        let fitted = model.apply(&simulated, &angle, &[1.1, 1.0, 0.9]);
        assert_eq!(fitted, simulated);
    }
}
