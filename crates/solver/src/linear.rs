//! LU factorisation of the Newton matrix, given as values in the system's pattern order.
//!
//! Two paths behind one type. Small systems use a plain in-place LU with partial pivoting
//! (faer's dense LU is blocked and recursive, built for large matrices: about 1 us at n = 8,
//! where this loop takes 0.3 us) that later factorisations replay, with the same pivots, over
//! the structural entries only (`dense`); large ones use faer's simplicial sparse LU (left-looking,
//! partial pivoting, COLAMD column order), which suits circuit matrices: they are very sparse
//! and produce little fill, so supernodes would not pay (the same choice KLU makes). Its pivots
//! and factor patterns then serve refactorisations that search nothing (`sparse`), as KLU's
//! `klu_refactor` does. The column ordering is computed once per pattern.
//! faer's scratch space is a `MemBuffer` sized at construction, so the steady state does not
//! allocate (the factors' `Vec`s keep their capacity between factorisations and only grow if
//! a different pivot sequence produces more fill).

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};

use super::SolveError;
use dense::Dense;
pub use dense::PivotCounts;
pub(super) use sparse::Sparse;

mod dense;
pub(super) mod sparse;

/// Crossover between the dense and the sparse path: systems with at most this many unknowns
/// are factored densely.
///
/// Measured with `cargo bench --bench solver -- crossover` (factor + solve of tridiagonal
/// N-node ladder matrices, release build, 2-core x86-64 box, dense / sparse). With a full
/// pivot search every time the paths crossed near 30 (N = 24: 1.55 / 1.74 us; N = 32: 2.5 /
/// 2.4 us; N = 64: 8.8 / 4.3 us). Refactorisations that reuse the pivots run over the
/// structural entries only, and now the dense path wins everywhere measured (N = 8: 0.16 /
/// 0.66 us; N = 24: 0.53 / 1.79 us; N = 32: 0.72 / 2.3 us; N = 128: 3.0 / 8.7 us). The
/// crossover stays where it was all the same: the dense path's first factorisation (and every
/// new pivot search) is O(N^3), its schedule follows the pivots with no fill-reducing order,
/// and its storage is N^2; a tridiagonal matrix, which produces no fill in any order, does not
/// show what that costs on a meshed circuit.
pub const DEFAULT_DENSE_MAX: usize = 28;

/// Tuning of the linear solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LinearOptions {
    /// Systems with at most this many unknowns use the dense path.
    pub dense_max: usize,
    /// A pivot smaller than `pivot_tol` times the largest magnitude in its column of the
    /// assembled matrix counts as zero (the matrix is reported singular).
    pub pivot_tol: f64,
}

impl Default for LinearOptions {
    fn default() -> Self {
        Self {
            dense_max: DEFAULT_DENSE_MAX,
            pivot_tol: 1e-13,
        }
    }
}

/// A reusable LU solver for one sparsity pattern.
pub struct LinearSolver {
    n: usize,
    pattern: Vec<(usize, usize)>,
    pivot_tol: f64,
    /// Whether the pattern has any entry in each row / column.
    row_used: Vec<bool>,
    col_used: Vec<bool>,
    /// Largest magnitude per row and per column of the last assembled matrix.
    row_max: Vec<f64>,
    col_max: Vec<f64>,
    /// Equilibration of the last factorisation: column `j` is multiplied by `col_scale[j]`
    /// (a power of two near the caller's unit of unknown `j`, 1 without one), then each row
    /// by a power of two near 1 / its largest entry. Right sides are scaled by rows, solutions
    /// by columns.
    row_scale: Vec<f64>,
    col_scale: Vec<f64>,
    /// The scaled values (pattern order) and the scaled diagonal shift of each row.
    scaled: Vec<f64>,
    diag: Vec<f64>,
    factored: bool,
    backend: Backend,
    mem: MemBuffer,
}

enum Backend {
    Dense(Box<Dense>),
    Sparse(Box<Sparse<f64>>),
}

impl LinearSolver {
    /// Prepares a solver for `n` unknowns and the given structural nonzeros (duplicates are
    /// summed; the diagonal is always part of the structure).
    pub fn new(
        n: usize,
        pattern: &[(usize, usize)],
        options: LinearOptions,
    ) -> Result<Self, SolveError> {
        if let Some(k) = pattern.iter().position(|&(r, c)| r >= n || c >= n) {
            return Err(SolveError::InvalidSystem {
                reason: "pattern entry out of range",
                index: k,
            });
        }
        let (backend, req) = if n <= options.dense_max {
            (
                Backend::Dense(Box::new(Dense::new(n, pattern))),
                StackReq::EMPTY,
            )
        } else {
            let sparse = Sparse::new(n, pattern)?;
            let req = Sparse::<f64>::scratch(n);
            (Backend::Sparse(Box::new(sparse)), req)
        };
        let mem = MemBuffer::try_new(req).map_err(|_| SolveError::InvalidSystem {
            reason: "out of memory for the linear solver's scratch space",
            index: n,
        })?;
        let (mut row_used, mut col_used) = (vec![false; n], vec![false; n]);
        for &(r, c) in pattern {
            row_used[r] = true;
            col_used[c] = true;
        }
        Ok(Self {
            n,
            row_used,
            col_used,
            pattern: pattern.to_vec(),
            pivot_tol: options.pivot_tol,
            row_max: vec![0.0; n],
            col_max: vec![0.0; n],
            row_scale: vec![1.0; n],
            col_scale: vec![1.0; n],
            scaled: vec![0.0; pattern.len()],
            diag: vec![0.0; n],
            factored: false,
            backend,
            mem,
        })
    }

    /// Number of unknowns.
    pub fn len(&self) -> usize {
        self.n
    }

    /// True for a system without unknowns.
    pub fn is_empty(&self) -> bool {
        self.n == 0
    }

    /// How often the factorisations searched for pivots and how often they reused the last
    /// ones.
    pub fn pivot_counts(&self) -> PivotCounts {
        match &self.backend {
            Backend::Dense(d) => d.counts,
            Backend::Sparse(s) => s.counts,
        }
    }

    /// True when this solver uses the dense path.
    pub fn is_dense(&self) -> bool {
        matches!(self.backend, Backend::Dense(_))
    }

    /// Factors the matrix whose entries are `values` (pattern order) plus `diag_shift` on the
    /// diagonal. Errors carry `t = 0`; callers restamp them with [`SolveError::at`].
    pub fn factor(&mut self, values: &[f64], diag_shift: f64) -> Result<(), SolveError> {
        self.factor_scaled(values, diag_shift, None)
    }

    /// [`LinearSolver::factor`] with the unknowns measured in `units` (positive; what a
    /// significant change of each unknown is, e.g. its error tolerance), so that pivots and
    /// the singularity test compare entries in those units rather than in the model's.
    ///
    /// The matrix is equilibrated: columns by `units`, then rows by their largest entry. A
    /// circuit's rows and columns differ by many orders of magnitude (a forward-biased
    /// junction's conductance of 1e24 beside a source row of 1, its current of 1e22 A beside
    /// millivolts), and partial pivoting on the raw matrix then takes the junction's row as
    /// the pivot of a column the source row needed, leaving the source's current a column of
    /// rounding, reported singular. Powers of two scale exactly, so a well-scaled matrix
    /// factors to the same numbers.
    pub fn factor_scaled(
        &mut self,
        values: &[f64],
        diag_shift: f64,
        units: Option<&[f64]>,
    ) -> Result<(), SolveError> {
        self.factored = false;
        if values.len() != self.pattern.len() {
            return Err(SolveError::InvalidSystem {
                reason: "Jacobian value count differs from the pattern length",
                index: values.len(),
            });
        }
        if self.n == 0 {
            // Nothing to factor (and row chunks of width 0 do not exist).
            self.factored = true;
            return Ok(());
        }
        if !self.equilibrate(values, diag_shift, units) {
            // Only now look for the culprit: the test rides along the scaling pass.
            let k = values.iter().position(|v| !v.is_finite()).unwrap_or(0);
            let (row, column) = self.pattern.get(k).copied().unwrap_or((0, 0));
            return Err(SolveError::NonFiniteJacobian {
                t: 0.0,
                row,
                column,
            });
        }
        let (values, diag) = (
            &self.scaled[..],
            (diag_shift != 0.0).then_some(&self.diag[..]),
        );
        self.row_max.fill(0.0);
        self.col_max.fill(0.0);
        let stack = MemStack::new(&mut self.mem);
        match &mut self.backend {
            Backend::Dense(d) => {
                let (row_used, col_used) = (&self.row_used, &self.col_used);
                let factored = d.factor(
                    &self.pattern,
                    values,
                    diag,
                    self.pivot_tol,
                    (&mut self.row_max, &mut self.col_max),
                    |row_max, col_max| check_empty(row_max, col_max, row_used, col_used),
                )?;
                if let Err(j) = factored {
                    return Err(singular(d.perm[j], j));
                }
            }
            Backend::Sparse(s) => {
                s.assemble(values, diag, &mut self.row_max, &mut self.col_max);
                check_empty(&self.row_max, &self.col_max, &self.row_used, &self.col_used)?;
                s.factor(stack, self.pivot_tol, &self.col_max)?;
            }
        }
        self.factored = true;
        Ok(())
    }

    /// Fills `col_scale`, `row_scale`, `scaled` and `diag` for `values` plus `diag_shift`. A
    /// row's largest entry is taken over its contributions before duplicates are summed:
    /// cheaper, and any power of two is an exact scaling, so an estimate costs nothing in
    /// accuracy. False when some value is not finite.
    fn equilibrate(&mut self, values: &[f64], diag_shift: f64, units: Option<&[f64]>) -> bool {
        match units {
            Some(units) if units.len() == self.n => {
                for (c, &u) in self.col_scale.iter_mut().zip(units) {
                    *c = 1.0 / inverse_power_of_two(u);
                }
            }
            _ => self.col_scale.fill(1.0),
        }
        let (col, row) = (&self.col_scale, &mut self.row_scale);
        for (r, &c) in row.iter_mut().zip(col) {
            *r = (diag_shift * c).abs();
        }
        let mut finite = true;
        for (x, (&(r, c), &v)) in self.scaled.iter_mut().zip(self.pattern.iter().zip(values)) {
            finite &= v.is_finite();
            *x = v * col[c];
            row[r] = row[r].max(x.abs());
        }
        for s in row.iter_mut() {
            *s = inverse_power_of_two(*s);
        }
        for (x, &(r, _)) in self.scaled.iter_mut().zip(&self.pattern) {
            *x *= row[r];
        }
        for ((d, &s), &c) in self.diag.iter_mut().zip(row.iter()).zip(col) {
            *d = diag_shift * s * c;
        }
        finite
    }

    /// Solves `A x = rhs` in place with the last factorisation.
    pub fn solve_in_place(&mut self, rhs: &mut [f64]) -> Result<(), SolveError> {
        if !self.factored || rhs.len() != self.n {
            return Err(SolveError::InvalidSystem {
                reason: "solve without a valid factorisation or with a wrong-sized right side",
                index: rhs.len(),
            });
        }
        let n = self.n;
        for (x, &s) in rhs.iter_mut().zip(&self.row_scale) {
            *x *= s;
        }
        match &mut self.backend {
            _ if n == 0 => {}
            Backend::Dense(d) => d.solve(rhs),
            Backend::Sparse(s) => s.solve(rhs),
        }
        for (x, &c) in rhs.iter_mut().zip(&self.col_scale) {
            *x *= c;
        }
        Ok(())
    }
}

/// A power of two within a factor of two of `1 / m` for a positive finite `m` (exponent
/// clamped so that it and its inverse stay normal), 1 for zero: an empty row stays empty and
/// is reported as such.
pub(super) fn inverse_power_of_two(m: f64) -> f64 {
    if m == 0.0 || !m.is_finite() {
        return 1.0;
    }
    // Biased exponent of m; subnormals (field 0) count as 2^-1022.
    let exponent = (((m.to_bits() >> 52) & 0x7ff) as i64 - 1023).clamp(-1000, 1000);
    f64::from_bits(((1023 - exponent) as u64) << 52)
}

pub(super) fn singular(row: usize, column: usize) -> SolveError {
    SolveError::SingularJacobian {
        t: 0.0,
        row: Some(row),
        column: Some(column),
        structural: false,
    }
}

/// An all-zero row or column names the culprit exactly; report it before elimination blurs
/// it. `*_used` tell a structural hole (nothing in the pattern) from a numerical zero.
fn check_empty(
    row_max: &[f64],
    col_max: &[f64],
    row_used: &[bool],
    col_used: &[bool],
) -> Result<(), SolveError> {
    if let Some(r) = row_max.iter().position(|&v| v == 0.0) {
        return Err(SolveError::SingularJacobian {
            t: 0.0,
            row: Some(r),
            column: None,
            structural: !row_used[r],
        });
    }
    if let Some(c) = col_max.iter().position(|&v| v == 0.0) {
        return Err(SolveError::SingularJacobian {
            t: 0.0,
            row: None,
            column: Some(c),
            structural: !col_used[c],
        });
    }
    Ok(())
}
