//! Small-signal (AC) analysis: a DAE `F(x', x, t) = 0` linearised about a point, then
//! `(G + jw C) X = B` solved at each frequency with a complex sparse LU (faer's pivot search,
//! then refactorisations with its pivots).
//!
//! `G = dF/dx` and `C = dF/dx'` come from [`DaeSystem::jacobian_parts`] at the point, with
//! every column read as `x` and then every column read as `x'`: two evaluations of the
//! system's own derivatives, exact where the system differentiates symbolically (no finite
//! differences, and no difference of two `dF/dx + alpha dF/dx'` matrices, which would lose
//! `C`'s digits beside a large `G`). An entry may also carry a pure delay `T` (the system's
//! `Q'delayed(T)`): its value is then multiplied by `e^{-jwT}`; and a sampled-data transfer
//! (`'zoh`, `'ztf`) adds `k H(jw)` to an entry.
//!
//! Knows nothing of VHDL: rows and columns are the system's indices, and the caller builds
//! the right side.

use faer::c64;
use faer::dyn_stack::{MemBuffer, MemStack};
use thiserror::Error;

use super::linear::sparse::Scalar;
use super::linear::{PivotCounts, Sparse, inverse_power_of_two};
use super::{DaeSystem, SolveError};

/// `G` and `C` of a linearised system on its sparsity pattern.
#[derive(Clone, Debug, PartialEq)]
pub struct SmallSignal {
    pub n: usize,
    /// Structural entries `(row, column)`, no duplicates.
    pub pattern: Vec<(usize, usize)>,
    /// `dF/dx` per pattern entry.
    pub g: Vec<f64>,
    /// `dF/dx'` per pattern entry.
    pub c: Vec<f64>,
    /// Pattern entries multiplied by `e^{-jwT}`: `(entry, T)`.
    pub delays: Vec<(usize, f64)>,
    /// Terms `coefficient * H(jw)` added to pattern entries: sampled-data transfers.
    pub sampled: Vec<SampledTerm>,
}

/// A sampled-data transfer's term of a pattern entry: `coefficient * transfer(jw)`.
#[derive(Clone, Debug, PartialEq)]
pub struct SampledTerm {
    pub entry: usize,
    pub coefficient: f64,
    pub transfer: SampledTransfer,
}

/// The frequency response of a sampled-data element of period `T`.
#[derive(Clone, Debug, PartialEq)]
pub enum SampledTransfer {
    /// Sample and hold: `(1 - e^{-jwT}) / (jwT) = e^{-jwT/2} sin(wT/2) / (wT/2)`, 1 at DC.
    Hold { period: f64 },
    /// A z-domain filter over coefficients in ascending powers of `z^-1`, at `z = e^{jwT}`.
    Filter {
        num: Vec<f64>,
        den: Vec<f64>,
        period: f64,
    },
}

impl SampledTransfer {
    /// The response at angular frequency `omega`.
    pub fn at(&self, omega: f64) -> c64 {
        match self {
            SampledTransfer::Hold { period } => {
                let x = omega * period;
                // sin(x/2)/(x/2) without cancellation near DC.
                let sinc = if x.abs() < 1e-4 {
                    1.0 - x * x / 24.0
                } else {
                    (x / 2.0).sin() / (x / 2.0)
                };
                c64::from_polar(sinc, -x / 2.0)
            }
            SampledTransfer::Filter { num, den, period } => {
                let z_inv = c64::from_polar(1.0, -omega * period);
                let poly = |coefficients: &[f64]| {
                    // Horner in z^-1, from the highest power down.
                    (coefficients.iter().rev())
                        .fold(c64::new(0.0, 0.0), |acc, &k| acc * z_inv + c64::new(k, 0.0))
                };
                poly(num) / poly(den)
            }
        }
    }
}

impl SmallSignal {
    /// `G` and `C` of `sys` at `(t, x, x')`.
    pub fn linearise(sys: &mut dyn DaeSystem, t: f64, x: &[f64], xdot: &[f64]) -> SmallSignal {
        let n = sys.len();
        let pattern = sys.pattern().to_vec();
        let mut g = vec![0.0; pattern.len()];
        let mut c = vec![0.0; pattern.len()];
        let mut scratch = vec![0.0; pattern.len()];
        sys.jacobian_parts(t, x, xdot, &vec![false; n], &mut g, &mut scratch);
        sys.jacobian_parts(t, x, xdot, &vec![true; n], &mut c, &mut scratch);
        // A column that is never read as `x'` has no `dF/dx'`: `jacobian_parts` gave its `dF/dx`.
        let mut differential = vec![false; n];
        for (j, &d) in sys.differential().iter().enumerate() {
            differential[j] = d;
        }
        for (cv, &(_, col)) in c.iter_mut().zip(&pattern) {
            if !differential[col] {
                *cv = 0.0;
            }
        }
        SmallSignal {
            n,
            pattern,
            g,
            c,
            delays: Vec::new(),
            sampled: Vec::new(),
        }
    }

    /// The pattern entry at `(row, column)`, made (with `G = C = 0`) if the system has none.
    pub fn entry(&mut self, row: usize, column: usize) -> usize {
        if let Some(k) = self.pattern.iter().position(|&rc| rc == (row, column)) {
            return k;
        }
        self.pattern.push((row, column));
        self.g.push(0.0);
        self.c.push(0.0);
        self.pattern.len() - 1
    }

    /// The value of `G + jw C` (delays applied) at each pattern entry.
    pub fn matrix_values(&self, omega: f64) -> Vec<c64> {
        let mut values = Vec::with_capacity(self.pattern.len());
        self.matrix_values_into(omega, &mut values);
        values
    }

    /// [`SmallSignal::matrix_values`] into `values`, whose capacity is kept.
    pub fn matrix_values_into(&self, omega: f64, values: &mut Vec<c64>) {
        values.clear();
        values.extend((self.g.iter().zip(&self.c)).map(|(&g, &c)| c64::new(g, omega * c)));
        for &(k, delay) in &self.delays {
            values[k] *= c64::from_polar(1.0, -omega * delay);
        }
        for term in &self.sampled {
            values[term.entry] += term.transfer.at(omega) * term.coefficient;
        }
    }
}

/// Why a frequency point has no solution.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum AcSolveError {
    /// The matrix is singular (structurally, or a pivot vanished) at this frequency.
    #[error("the linearised system is singular at {frequency} Hz")]
    Singular { frequency: f64 },
    /// faer could not allocate or build the matrix.
    #[error("the sparse solver failed: {0}")]
    Solver(String),
}

/// Solves `(G + jw C) X = B` frequency after frequency on one symbolic factorisation (the
/// pattern and its fill-reducing order do not change with the frequency).
///
/// The first frequency is factored with faer's pivot search; the next ones refactor with its
/// pivots (the sparse LU of `solver::linear`, generic over the scalar), which skips the search
/// and the pattern's depth-first walks. The matrix moves with the frequency far more than a
/// Newton matrix moves between iterations (`G` rules at low frequencies, `C` at high ones), so
/// the threshold test matters: a pivot that falls below it sends that frequency back to the
/// search, whose pivots then serve the frequencies after it. Buffers are kept, so the steady
/// state allocates only the returned solution.
pub struct AcSolver {
    system: SmallSignal,
    lu: Sparse<c64>,
    mem: MemBuffer,
    /// `G + jw C` at the current frequency, rows equilibrated (pattern order).
    values: Vec<c64>,
    row_max: Vec<f64>,
    col_max: Vec<f64>,
    row_scale: Vec<f64>,
}

impl AcSolver {
    pub fn new(system: SmallSignal) -> Result<AcSolver, AcSolveError> {
        let n = system.n;
        if let Some(&(r, c)) = system.pattern.iter().find(|&&(r, c)| r >= n || c >= n) {
            return Err(AcSolveError::Solver(format!(
                "pattern entry ({r}, {c}) out of range of {n} unknowns"
            )));
        }
        let lu =
            Sparse::new(n, &system.pattern).map_err(|e| AcSolveError::Solver(e.to_string()))?;
        let mem = MemBuffer::try_new(Sparse::<c64>::scratch(n))
            .map_err(|_| AcSolveError::Solver("out of memory for the LU's scratch".into()))?;
        Ok(AcSolver {
            values: Vec::with_capacity(system.pattern.len()),
            row_max: vec![0.0; n],
            col_max: vec![0.0; n],
            row_scale: vec![1.0; n],
            system,
            lu,
            mem,
        })
    }

    pub fn system(&self) -> &SmallSignal {
        &self.system
    }

    /// How often the frequencies searched for pivots and how often they reused the last ones.
    pub fn pivot_counts(&self) -> PivotCounts {
        self.lu.counts
    }

    /// `X` at `frequency` (hertz) for the right side `rhs`: `(G + jw C) X = rhs`.
    pub fn solve(&mut self, frequency: f64, rhs: &[c64]) -> Result<Vec<c64>, AcSolveError> {
        self.solve_with(frequency, rhs, false)
    }

    /// `Z` at `frequency` (hertz) with `(G + jw C)^T Z = rhs` (transposed, not conjugated):
    /// the adjoint system. For an output `y = c^T X`, the solution of `A^T z = c` gives the
    /// transfer from every right side at once, `y = z^T B`, so a noise analysis needs one
    /// solve per frequency however many sources it has (as SPICE's `.noise` does).
    pub fn solve_transposed(
        &mut self,
        frequency: f64,
        rhs: &[c64],
    ) -> Result<Vec<c64>, AcSolveError> {
        self.solve_with(frequency, rhs, true)
    }

    fn solve_with(
        &mut self,
        frequency: f64,
        rhs: &[c64],
        transposed: bool,
    ) -> Result<Vec<c64>, AcSolveError> {
        let n = self.system.n;
        if n == 0 {
            return Ok(Vec::new());
        }
        let omega = std::f64::consts::TAU * frequency;
        self.system.matrix_values_into(omega, &mut self.values);
        // Rows equilibrated to a largest entry of 1 (a power of two, so exactly): a force
        // balance beside a displacement definition spans many decades, and partial pivoting
        // compares rows' entries as they stand.
        self.row_max.fill(0.0);
        for (v, &(row, _)) in self.values.iter().zip(&self.system.pattern) {
            self.row_max[row] = self.row_max[row].max(v.modulus());
        }
        for (s, &m) in self.row_scale.iter_mut().zip(&self.row_max) {
            *s = inverse_power_of_two(m);
        }
        for (v, &(row, _)) in self.values.iter_mut().zip(&self.system.pattern) {
            *v *= self.row_scale[row];
        }
        self.row_max.fill(0.0);
        self.col_max.fill(0.0);
        self.lu
            .assemble(&self.values, None, &mut self.row_max, &mut self.col_max);
        // A pivot tolerance of 0: only an exactly vanished (or undefined) pivot is singular, as
        // with faer's own LU; a tiny one shows in the solution.
        match self
            .lu
            .factor(MemStack::new(&mut self.mem), 0.0, &self.col_max)
        {
            Ok(()) => {}
            Err(SolveError::InvalidSystem { reason, .. }) => {
                return Err(AcSolveError::Solver(reason.to_string()));
            }
            Err(_) => return Err(AcSolveError::Singular { frequency }),
        }
        // The factors are of `D A` (`D` the row scales). `D A X = D b` for `X`; for the
        // adjoint, `(D A)^T W = A^T D W = c`, so `Z = D W`.
        let x: Vec<c64> = if transposed {
            let mut w: Vec<c64> = (0..n)
                .map(|i| rhs.get(i).copied().unwrap_or_default())
                .collect();
            self.lu.solve_transposed(&mut w);
            for (w, &s) in w.iter_mut().zip(&self.row_scale) {
                *w *= s;
            }
            w
        } else {
            let mut x: Vec<c64> = (0..n)
                .map(|i| rhs.get(i).copied().unwrap_or_default() * self.row_scale[i])
                .collect();
            self.lu.solve(&mut x);
            x
        };
        // A vanished pivot shows as an infinite or undefined solution.
        if x.iter().any(|v| !(v.re.is_finite() && v.im.is_finite())) {
            return Err(AcSolveError::Singular { frequency });
        }
        Ok(x)
    }
}

/// How the analysis frequencies are spaced.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Spacing {
    /// This many points per decade, logarithmically spaced (both ends included).
    PerDecade(usize),
    /// This many points, evenly spaced (both ends included).
    Linear(usize),
}

/// The frequencies from `from` to `to` (hertz, `0 < from <= to`). A decade sweep's points
/// are `from * 10^(k / per_decade)` (computed from the index, not accumulated, so whole
/// decades of `from` are exact) and it ends at `to` itself.
pub fn frequencies(from: f64, to: f64, spacing: Spacing) -> Vec<f64> {
    if from >= to {
        return vec![from];
    }
    match spacing {
        Spacing::Linear(points) => {
            let points = points.max(2);
            let step = (to - from) / (points - 1) as f64;
            (0..points)
                .map(|k| {
                    if k + 1 == points {
                        to
                    } else {
                        from + step * k as f64
                    }
                })
                .collect()
        }
        Spacing::PerDecade(per_decade) => {
            let per_decade = per_decade.max(1) as f64;
            let (start, end) = (from.log10(), to.log10());
            // Points at `start + k / per_decade` decades; the last below `to` (by more than
            // rounding) is followed by `to`.
            let count = ((end - start) * per_decade * (1.0 + 1e-12)).floor() as usize;
            let mut out: Vec<f64> = (0..=count)
                .map(|k| from * 10f64.powf(k as f64 / per_decade))
                .collect();
            if let Some(last) = out.last_mut()
                && (*last / to - 1.0).abs() < 1e-9
            {
                *last = to;
            } else {
                out.push(to);
            }
            out
        }
    }
}

/// Magnitude in decibels (`20 log10 |z|`).
pub fn db(z: c64) -> f64 {
    20.0 * z.norm().log10()
}

/// Phase in degrees, in `(-180, 180]`.
pub fn degrees(z: c64) -> f64 {
    z.arg().to_degrees()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn decade_sweep_lands_on_decades_and_ends() {
        let f = frequencies(1.0, 1e6, Spacing::PerDecade(20));
        assert_eq!(f.len(), 121);
        assert_eq!(f[0], 1.0);
        assert_eq!(f[120], 1e6);
        assert!((f[20] / 10.0 - 1.0).abs() < 1e-14);
        let f = frequencies(2.0, 30.0, Spacing::PerDecade(1));
        assert_eq!(f, vec![2.0, 20.0, 30.0]);
        let f = frequencies(10.0, 20.0, Spacing::Linear(3));
        assert_eq!(f, vec![10.0, 15.0, 20.0]);
        assert_eq!(frequencies(5.0, 5.0, Spacing::Linear(10)), vec![5.0]);
    }

    /// `x0 - b = 0` (a source) and `c x1' + (x1 - x0) / r = 0`: an RC low-pass.
    fn rc(r: f64, c: f64) -> SmallSignal {
        SmallSignal {
            n: 2,
            pattern: vec![(0, 0), (1, 0), (1, 1)],
            g: vec![1.0, -1.0 / r, 1.0 / r],
            c: vec![0.0, 0.0, c],
            delays: Vec::new(),
            sampled: Vec::new(),
        }
    }

    #[test]
    fn sampled_transfers_at_dc_and_at_the_sampling_frequencies() {
        let period = 1e-3;
        let hold = SampledTransfer::Hold { period };
        let w = |f: f64| std::f64::consts::TAU * f;
        assert!((hold.at(0.0) - c64::new(1.0, 0.0)).norm() < 1e-15);
        // Half the sampling frequency: |H| = 2/pi, a quarter-turn late.
        let half = hold.at(w(500.0));
        assert!((half.norm() - 2.0 / std::f64::consts::PI).abs() < 1e-15);
        assert!((half.arg() + std::f64::consts::FRAC_PI_2).abs() < 1e-15);
        assert!(hold.at(w(2e3)).norm() < 1e-15);
        // Near DC the series and the formula meet.
        let near = |x: f64| hold.at(x / period);
        for x in [0.99e-4, 1.01e-4] {
            assert!((near(x).norm() - (1.0 - x * x / 24.0)).abs() < 1e-15);
        }
        let filter = SampledTransfer::Filter {
            num: vec![0.2],
            den: vec![1.0, -0.8],
            period,
        };
        assert!((filter.at(0.0) - c64::new(1.0, 0.0)).norm() < 1e-15);
        // Half the sampling frequency: z^-1 = -1.
        assert!((filter.at(w(500.0)) - c64::new(0.2 / 1.8, 0.0)).norm() < 1e-15);
    }

    #[test]
    fn rc_low_pass_matches_its_closed_form() {
        let (r, c) = (1e3, 1e-7);
        let mut solver = AcSolver::new(rc(r, c)).unwrap();
        for f in [1.0, 100.0, 1591.5494309189535, 1e5] {
            let x = solver
                .solve(f, &[c64::new(1.0, 0.0), c64::new(0.0, 0.0)])
                .unwrap();
            let wrc = std::f64::consts::TAU * f * r * c;
            let h = x[1];
            let expected = 1.0 / (1.0 + wrc * wrc).sqrt();
            assert!((h.norm() / expected - 1.0).abs() < 1e-12, "{f}: {h}");
            assert!((h.arg() + wrc.atan()).abs() < 1e-12);
        }
    }

    #[test]
    fn the_adjoint_solve_gives_every_transfer_at_once() {
        // A 3x3 system with a delay and unequal row scales: z^T b must equal c^T x for
        // every right side b, with x from the direct solve.
        let sys = SmallSignal {
            n: 3,
            pattern: vec![(0, 0), (0, 1), (1, 0), (1, 1), (1, 2), (2, 1), (2, 2)],
            g: vec![2.0, -1.0, -1e-3, 3e-3, -1e-3, -5.0, 1e4],
            c: vec![1e-6, 0.0, 0.0, 2e-9, 0.0, 0.0, 3e-2],
            delays: vec![(5, 1e-4)],
            // And a sampled-data term: the transposed solve sees the same matrix.
            sampled: vec![SampledTerm {
                entry: 2,
                coefficient: 0.5,
                transfer: SampledTransfer::Hold { period: 1e-4 },
            }],
        };
        let mut solver = AcSolver::new(sys).unwrap();
        let c = [
            c64::new(0.5, 0.0),
            c64::new(-1.0, 2.0),
            c64::new(3.0, -0.25),
        ];
        for f in [0.1, 1e3, 1e6] {
            let z = solver.solve_transposed(f, &c).unwrap();
            for k in 0..3 {
                let mut b = vec![c64::default(); 3];
                b[k] = c64::new(1.0, 0.0);
                let x = solver.solve(f, &b).unwrap();
                let direct: c64 = (0..3).map(|j| c[j] * x[j]).sum();
                assert!((direct - z[k]).norm() <= 1e-12 * direct.norm(), "{f} {k}");
            }
        }
    }

    #[test]
    fn a_pivot_that_fades_with_the_frequency_is_searched_again() {
        // [[1.4, jw], [1, 1]]: at low frequencies row 0 pivots column 0; at high ones its
        // equilibrated entry there falls to 1.4 / w and row 1 must take over.
        let sys = SmallSignal {
            n: 2,
            pattern: vec![(0, 0), (0, 1), (1, 0), (1, 1)],
            g: vec![1.4, 0.0, 1.0, 1.0],
            c: vec![0.0, 1.0, 0.0, 0.0],
            delays: Vec::new(),
            sampled: Vec::new(),
        };
        let mut solver = AcSolver::new(sys).unwrap();
        let b = [c64::new(1.0, 0.0), c64::default()];
        for (k, f) in [1e-3, 2e-3, 1e5, 2e5].into_iter().enumerate() {
            let x = solver.solve(f, &b).unwrap();
            let det = c64::new(1.4, -std::f64::consts::TAU * f);
            let expected = [c64::new(1.0, 0.0) / det, c64::new(-1.0, 0.0) / det];
            for (x, e) in x.iter().zip(expected) {
                assert!((x - e).norm() <= 1e-14 * e.norm(), "{f}: {x} against {e}");
            }
            let z = solver.solve_transposed(f, &b).unwrap();
            // A^T z = b: z = [1, -jw] / det.
            let expected = [
                c64::new(1.0, 0.0) / det,
                c64::new(0.0, -std::f64::consts::TAU * f) / det,
            ];
            for (z, e) in z.iter().zip(expected) {
                assert!((z - e).norm() <= 1e-14 * e.norm(), "{f}: {z} against {e}");
            }
            // One search at the first frequency and one where the pivot fades; the rest reuse.
            let searched = if k < 2 { 1 } else { 2 };
            assert_eq!(solver.pivot_counts().searched, searched, "{f}");
        }
    }

    #[test]
    fn a_delay_turns_the_phase() {
        let mut sys = SmallSignal {
            n: 2,
            pattern: vec![(0, 0), (1, 0), (1, 1)],
            g: vec![1.0, -1.0, 1.0],
            c: vec![0.0; 3],
            delays: vec![(1, 1e-3)],
            sampled: Vec::new(),
        };
        let mut solver = AcSolver::new(sys.clone()).unwrap();
        let x = solver
            .solve(125.0, &[c64::new(1.0, 0.0), c64::default()])
            .unwrap();
        // e^{-j 2 pi 125 1e-3} = e^{-j pi/4}.
        assert!((x[1].norm() - 1.0).abs() < 1e-14);
        assert!((degrees(x[1]) + 45.0).abs() < 1e-12);
        sys.g = vec![0.0, -1.0, 1.0];
        let singular = AcSolver::new(sys)
            .unwrap()
            .solve(1.0, &[c64::new(1.0, 0.0), c64::default()]);
        assert!(
            matches!(singular, Err(AcSolveError::Singular { .. })),
            "{singular:?}"
        );
    }
}
