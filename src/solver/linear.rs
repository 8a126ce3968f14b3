//! LU factorisation of the Newton matrix, given as values in the system's pattern order.
//!
//! Two paths behind one type. Small systems use a plain in-place LU with partial pivoting
//! (faer's dense LU is blocked and recursive, built for large matrices: about 1 us at n = 8,
//! where this loop takes 0.4 us); large ones use faer's simplicial sparse LU (left-looking,
//! partial pivoting, COLAMD column order), which suits circuit matrices: they are very sparse
//! and produce little fill, so supernodes would not pay (the same choice KLU makes). The column
//! ordering is computed once per pattern; each `factor` scatters the values into preallocated
//! CSC storage and refactors numerically.
//! Scratch space for factor and solve is a `MemBuffer` sized at construction, so the steady state
//! does not allocate (the simplicial factor's `Vec`s keep their capacity between refactorisations
//! and only grow if a different pivot sequence produces more fill).

use faer::dyn_stack::{MemBuffer, MemStack, StackReq};
use faer::sparse::linalg::lu::simplicial;
use faer::{MatMut, Par};

use super::SolveError;
use sparse::Sparse;

mod sparse;

/// Crossover between the dense and the sparse path: systems with at most this many unknowns
/// are factored densely.
///
/// Measured with `cargo bench --bench solver -- crossover` (factor + solve of tridiagonal
/// N-node ladder matrices, release build, 2-core x86-64 box, dense / sparse): N = 4: 0.14 /
/// 0.44 us; N = 8: 0.40 / 0.89 us; N = 12: 0.82 / 0.93 us; N = 16: 1.38 / 1.26 us; N = 24:
/// 3.2 / 1.7 us; N = 32: 5.6 / 2.5 us; N = 128: 99 / 8.9 us. The paths cross near 16 on a
/// tridiagonal matrix, the sparse path's best case; denser circuit matrices favour the dense
/// path a little longer.
pub const DEFAULT_DENSE_MAX: usize = 16;

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
    factored: bool,
    backend: Backend,
    mem: MemBuffer,
}

enum Backend {
    Dense(Dense),
    Sparse(Box<Sparse>),
}

/// Row-major `n x n` LU with partial pivoting, in place: `a` holds `L` (unit diagonal, below)
/// and `U`; row `k` of the factors is row `perm[k]` of the assembled matrix.
struct Dense {
    a: Vec<f64>,
    perm: Vec<usize>,
    scratch: Vec<f64>,
}

impl Dense {
    /// Factors `a` in place. Returns the pivot step `j` whose pivot is not above `tol *
    /// col_max[j]` (the matrix counts as singular there), if any.
    fn factor(&mut self, n: usize, pivot_tol: f64, col_max: &[f64]) -> Result<(), usize> {
        let a = &mut self.a;
        for (k, p) in self.perm.iter_mut().enumerate() {
            *p = k;
        }
        for j in 0..n {
            let mut p = j;
            let mut best = a[j * n + j].abs();
            for r in j + 1..n {
                let v = a[r * n + j].abs();
                if v > best {
                    best = v;
                    p = r;
                }
            }
            if best.is_nan() || best <= pivot_tol * col_max[j] {
                return Err(j);
            }
            if p != j {
                for c in 0..n {
                    a.swap(j * n + c, p * n + c);
                }
                self.perm.swap(j, p);
            }
            let pivot = a[j * n + j];
            for r in j + 1..n {
                let l = a[r * n + j] / pivot;
                a[r * n + j] = l;
                if l != 0.0 {
                    for c in j + 1..n {
                        a[r * n + c] -= l * a[j * n + c];
                    }
                }
            }
        }
        Ok(())
    }

    fn solve(&mut self, n: usize, rhs: &mut [f64]) {
        let a = &self.a;
        for (k, &p) in self.perm.iter().enumerate() {
            self.scratch[k] = rhs[p];
        }
        let y = &mut self.scratch;
        for r in 1..n {
            let mut sum = y[r];
            for c in 0..r {
                sum -= a[r * n + c] * y[c];
            }
            y[r] = sum;
        }
        for r in (0..n).rev() {
            let mut sum = y[r];
            for c in r + 1..n {
                sum -= a[r * n + c] * y[c];
            }
            y[r] = sum / a[r * n + r];
        }
        rhs.copy_from_slice(y);
    }
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
        let par = Par::Seq;
        let (backend, req) = if n <= options.dense_max {
            let dense = Dense {
                a: vec![0.0; n * n],
                perm: vec![0; n],
                scratch: vec![0.0; n],
            };
            (Backend::Dense(dense), StackReq::EMPTY)
        } else {
            let sparse = Sparse::new(n, pattern)?;
            let req = StackReq::any_of(&[
                simplicial::factorize_simplicial_numeric_lu_scratch::<usize, f64>(n, n),
                simplicial::solve_in_place_scratch::<usize, f64>(n, 1, par),
            ]);
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

    /// True when this solver uses the dense path.
    pub fn is_dense(&self) -> bool {
        matches!(self.backend, Backend::Dense(_))
    }

    /// Factors the matrix whose entries are `values` (pattern order) plus `diag_shift` on the
    /// diagonal. Errors carry `t = 0`; callers restamp them with [`SolveError::at`].
    pub fn factor(&mut self, values: &[f64], diag_shift: f64) -> Result<(), SolveError> {
        self.factored = false;
        if values.len() != self.pattern.len() {
            return Err(SolveError::InvalidSystem {
                reason: "Jacobian value count differs from the pattern length",
                index: values.len(),
            });
        }
        if let Some(k) = values.iter().position(|v| !v.is_finite()) {
            let (row, column) = self.pattern[k];
            return Err(SolveError::NonFiniteJacobian {
                t: 0.0,
                row,
                column,
            });
        }
        self.row_max.fill(0.0);
        self.col_max.fill(0.0);
        let stack = MemStack::new(&mut self.mem);
        match &mut self.backend {
            Backend::Dense(d) => {
                let n = self.n;
                d.a.fill(0.0);
                for (&(r, c), &v) in self.pattern.iter().zip(values) {
                    d.a[r * n + c] += v;
                }
                for i in 0..n {
                    d.a[i * n + i] += diag_shift;
                }
                for r in 0..n {
                    for c in 0..n {
                        let v = d.a[r * n + c].abs();
                        self.row_max[r] = self.row_max[r].max(v);
                        self.col_max[c] = self.col_max[c].max(v);
                    }
                }
                check_empty(&self.row_max, &self.col_max, &self.row_used, &self.col_used)?;
                if let Err(j) = d.factor(n, self.pivot_tol, &self.col_max) {
                    return Err(singular(d.perm[j], j));
                }
            }
            Backend::Sparse(s) => {
                s.assemble(values, diag_shift, &mut self.row_max, &mut self.col_max);
                check_empty(&self.row_max, &self.col_max, &self.row_used, &self.col_used)?;
                s.factor(stack, self.pivot_tol, &self.col_max)?;
            }
        }
        self.factored = true;
        Ok(())
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
        match &mut self.backend {
            Backend::Dense(d) => d.solve(n, rhs),
            Backend::Sparse(s) => {
                let stack = MemStack::new(&mut self.mem);
                s.solve(MatMut::from_column_major_slice_mut(rhs, n, 1), stack);
            }
        }
        Ok(())
    }
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
