//! The sparse path: CSC storage of pattern + diagonal, COLAMD order computed once, faer's
//! simplicial (left-looking, partial pivoting) numeric LU where pivots must be chosen, and a
//! refactorisation with the last pivots (KLU's `klu_refactor`) everywhere else.
//!
//! A Newton matrix keeps its pattern and mostly its pivots from one factorisation to the next.
//! faer's numeric LU searches for pivots and finds the pattern of each column of the factors
//! (a depth-first search) every time: at 200 unknowns of a diode chain, about 20 us a
//! factorisation. After each search the factors are copied into [`Factors`], whose patterns
//! then serve a left-looking refactorisation that searches nothing: each column of A scattered
//! into a dense work vector, the columns of L its U entries name applied in ascending order,
//! the pivot tested against the threshold (as the dense path's [`PIVOT_THRESHOLD`]), and the
//! column of L scaled. A pivot that no longer holds sends the factorisation back to faer. The
//! triangular solves run on the same arrays.
//!
//! Generic over the scalar ([`Scalar`]): `f64` for the Newton matrices, faer's `c64` for the
//! small-signal matrices `G + jwC` of `solver::ac`, refactored frequency after frequency.

use faer::dyn_stack::MemStack;
use faer::sparse::linalg::lu::{
    LuSymbolicParams, SymbolicLu, factorize_symbolic_lu, simplicial, simplicial::SimplicialLu,
};
use faer::sparse::linalg::{LuError, SupernodalThreshold};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::traits::ComplexField;
use faer::{c64, dyn_stack::StackReq};
use std::ops::{Add, AddAssign, Div, Mul, Sub, SubAssign};

use super::dense::{PIVOT_THRESHOLD, PivotCounts};
use super::singular;
use crate::SolveError;

/// A scalar the sparse LU factors: what faer's numeric LU needs, plus arithmetic by value and a
/// magnitude for the pivot tests.
pub(crate) trait Scalar:
    ComplexField
    + Copy
    + PartialEq
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + AddAssign
    + SubAssign
{
    const ZERO: Self;
    const ONE: Self;
    /// The magnitude pivots are compared by (NaN for NaN): `|x|` for a real, `|re| + |im|` for
    /// a complex number, within a factor of `sqrt 2` of `|x|` and without `hypot`, which took a
    /// seventh of a sweep's time. A threshold test needs no more than that.
    fn modulus(self) -> f64;
}

impl Scalar for f64 {
    const ZERO: Self = 0.0;
    const ONE: Self = 1.0;
    fn modulus(self) -> f64 {
        self.abs()
    }
}

impl Scalar for c64 {
    const ZERO: Self = c64::new(0.0, 0.0);
    const ONE: Self = c64::new(1.0, 0.0);
    fn modulus(self) -> f64 {
        self.re.abs() + self.im.abs()
    }
}

/// The factors of the last factorisation in pivot order (`P A Q = L U`), with the patterns a
/// refactorisation reuses. Row indices of L and U are positions in pivot order.
struct Factors<T> {
    /// Column of A eliminated at step `j`.
    col: Vec<usize>,
    /// Row of A at position `i`, and the position of each row of A.
    row_of: Vec<usize>,
    row_pos: Vec<usize>,
    /// L without its unit diagonal, by columns.
    l_ptr: Vec<usize>,
    l_idx: Vec<usize>,
    l_val: Vec<T>,
    /// U without its diagonal, by columns, rows ascending (the order a left-looking column
    /// applies them in).
    u_ptr: Vec<usize>,
    u_idx: Vec<usize>,
    u_val: Vec<T>,
    /// `1 / U[j][j]`.
    inv_diag: Vec<T>,
    /// Dense scratch, all zero between calls.
    work: Vec<T>,
}

/// A sparse LU for one pattern: values assembled into CSC storage, factored with faer's pivot
/// search or with the last pivots, solved (also transposed) in place.
pub(crate) struct Sparse<T: Scalar> {
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<T>,
    /// CSC slot of each pattern entry, in pattern order.
    slot: Vec<usize>,
    /// CSC slot of each diagonal entry (the structure always holds the diagonal, for gmin).
    diag_slot: Vec<usize>,
    symbolic: SymbolicLu<usize>,
    lu: SimplicialLu<usize, T>,
    row_perm: Vec<usize>,
    row_perm_inv: Vec<usize>,
    factors: Factors<T>,
    /// Whether `factors` holds a factorisation whose pivots a refactorisation may reuse.
    reusable: bool,
    pub(crate) counts: PivotCounts,
}

impl<T: Scalar> Sparse<T> {
    /// Scratch space faer's numeric LU needs at `n` unknowns.
    pub(crate) fn scratch(n: usize) -> StackReq {
        simplicial::factorize_simplicial_numeric_lu_scratch::<usize, T>(n, n)
    }

    /// The structure of `pattern` plus the diagonal (duplicates summed) and its fill-reducing
    /// column order.
    pub(crate) fn new(n: usize, pattern: &[(usize, usize)]) -> Result<Self, SolveError> {
        // Column-major order of the distinct entries of pattern + diagonal.
        let mut entries: Vec<(usize, usize)> = pattern
            .iter()
            .map(|&(r, c)| (c, r))
            .chain((0..n).map(|i| (i, i)))
            .collect();
        entries.sort_unstable();
        entries.dedup();
        let mut col_ptr = vec![0usize; n + 1];
        for &(c, _) in &entries {
            col_ptr[c + 1] += 1;
        }
        for c in 0..n {
            col_ptr[c + 1] += col_ptr[c];
        }
        let row_idx: Vec<usize> = entries.iter().map(|&(_, r)| r).collect();
        let find = |r: usize, c: usize| -> usize {
            // Present by construction: every pattern entry and diagonal went into `entries`.
            let col = &row_idx[col_ptr[c]..col_ptr[c + 1]];
            col_ptr[c] + col.binary_search(&r).unwrap_or(0)
        };
        let slot = pattern.iter().map(|&(r, c)| find(r, c)).collect();
        let diag_slot = (0..n).map(|i| find(i, i)).collect();
        let symbolic_a = SymbolicSparseColMatRef::new_checked(n, n, &col_ptr, None, &row_idx);
        let params = LuSymbolicParams {
            supernodal_flop_ratio_threshold: SupernodalThreshold::FORCE_SIMPLICIAL,
            ..Default::default()
        };
        let symbolic =
            factorize_symbolic_lu(symbolic_a, params).map_err(|_| SolveError::InvalidSystem {
                reason: "sparse symbolic analysis failed (out of memory)",
                index: n,
            })?;
        Ok(Self {
            values: vec![T::ZERO; row_idx.len()],
            col_ptr,
            row_idx,
            slot,
            diag_slot,
            symbolic,
            lu: SimplicialLu::new(),
            row_perm: vec![0; n],
            row_perm_inv: vec![0; n],
            factors: Factors {
                col: Vec::new(),
                row_of: Vec::new(),
                row_pos: Vec::new(),
                l_ptr: Vec::new(),
                l_idx: Vec::new(),
                l_val: Vec::new(),
                u_ptr: Vec::new(),
                u_idx: Vec::new(),
                u_val: Vec::new(),
                inv_diag: Vec::new(),
                work: vec![T::ZERO; n],
            },
            reusable: false,
            counts: PivotCounts::default(),
        })
    }

    /// Sums `values` (pattern order) and `diag` into the CSC storage, raising `row_max` and
    /// `col_max` to the magnitudes of the summed entries.
    pub(crate) fn assemble(
        &mut self,
        values: &[T],
        diag: Option<&[T]>,
        row_max: &mut [f64],
        col_max: &mut [f64],
    ) {
        self.values.fill(T::ZERO);
        for (&k, &v) in self.slot.iter().zip(values) {
            self.values[k] += v;
        }
        if let Some(diag) = diag {
            for (&k, &d) in self.diag_slot.iter().zip(diag) {
                self.values[k] += d;
            }
        }
        for (c, cm) in col_max.iter_mut().enumerate() {
            for k in self.col_ptr[c]..self.col_ptr[c + 1] {
                let (r, v) = (self.row_idx[k], self.values[k].modulus());
                row_max[r] = row_max[r].max(v);
                *cm = cm.max(v);
            }
        }
    }

    /// Factors the assembled values: a refactorisation with the last pivots when they hold,
    /// faer's pivot search otherwise.
    pub(crate) fn factor(
        &mut self,
        stack: &mut MemStack,
        pivot_tol: f64,
        col_max: &[f64],
    ) -> Result<(), SolveError> {
        if self.reusable && self.refactor(pivot_tol, col_max) {
            self.counts.reused += 1;
            return Ok(());
        }
        self.reusable = false;
        self.counts.searched += 1;
        self.search(stack, pivot_tol, col_max)?;
        self.compile();
        self.reusable = true;
        Ok(())
    }

    /// faer's numeric LU, which chooses the pivots.
    fn search(
        &mut self,
        stack: &mut MemStack,
        pivot_tol: f64,
        col_max: &[f64],
    ) -> Result<(), SolveError> {
        let n = self.row_perm.len();
        let sym = SymbolicSparseColMatRef::new_checked(n, n, &self.col_ptr, None, &self.row_idx);
        let a = SparseColMatRef::new(sym, &self.values);
        let col_perm = self.symbolic.col_perm();
        let (col_fwd, _) = col_perm.arrays();
        let result = simplicial::factorize_simplicial_numeric_lu(
            &mut self.row_perm,
            &mut self.row_perm_inv,
            &mut self.lu,
            a,
            col_perm,
            stack,
        );
        match result {
            Ok(()) => {}
            Err(LuError::SymbolicSingular { index }) => {
                return Err(SolveError::SingularJacobian {
                    t: 0.0,
                    row: None,
                    column: col_fwd.get(index).copied(),
                    structural: true,
                });
            }
            Err(LuError::Generic(_)) => {
                return Err(SolveError::InvalidSystem {
                    reason: "sparse LU failed (out of memory)",
                    index: n,
                });
            }
        }
        // The pivot of step j is the last entry of U's column j (row index j).
        let u = self.lu.u_factor_unsorted();
        for (j, &c) in col_fwd.iter().enumerate() {
            let rows = u.row_idx_of_col_raw(j);
            let vals = u.val_of_col(j);
            let pivot = rows
                .iter()
                .zip(vals)
                .find(|&(&r, _)| r == j)
                .map_or(0.0, |(_, v)| v.modulus());
            if pivot.is_nan() || pivot <= pivot_tol * col_max[c] {
                return Err(singular(self.row_perm[j], c));
            }
        }
        Ok(())
    }

    /// Copies faer's factors (after a successful [`Sparse::search`]) into `factors`. Vectors
    /// keep their capacity, so the steady state does not allocate.
    fn compile(&mut self) {
        let f = &mut self.factors;
        let n = self.row_perm.len();
        let (col_fwd, _) = self.symbolic.col_perm().arrays();
        f.col.clear();
        f.col.extend_from_slice(col_fwd);
        f.row_of.clear();
        f.row_of.extend_from_slice(&self.row_perm);
        f.row_pos.clear();
        f.row_pos.extend_from_slice(&self.row_perm_inv);
        let (l, u) = (self.lu.l_factor_unsorted(), self.lu.u_factor_unsorted());
        f.l_ptr.clear();
        f.l_idx.clear();
        f.l_val.clear();
        f.u_ptr.clear();
        f.u_idx.clear();
        f.u_val.clear();
        f.inv_diag.clear();
        f.l_ptr.push(0);
        f.u_ptr.push(0);
        for j in 0..n {
            for (&r, &v) in l.row_idx_of_col_raw(j).iter().zip(l.val_of_col(j)) {
                if r != j {
                    f.l_idx.push(r);
                    f.l_val.push(v);
                }
            }
            f.l_ptr.push(f.l_idx.len());
            let start = f.u_idx.len();
            let mut diag = T::ZERO;
            for (&r, &v) in u.row_idx_of_col_raw(j).iter().zip(u.val_of_col(j)) {
                if r == j {
                    diag = v;
                } else {
                    f.u_idx.push(r);
                    f.u_val.push(v);
                }
            }
            // Ascending rows: insertion sort of a short column, values alongside.
            for a in start + 1..f.u_idx.len() {
                let mut b = a;
                while b > start && f.u_idx[b - 1] > f.u_idx[b] {
                    f.u_idx.swap(b - 1, b);
                    f.u_val.swap(b - 1, b);
                    b -= 1;
                }
            }
            f.u_ptr.push(f.u_idx.len());
            // `search` checked every pivot against the singularity threshold.
            f.inv_diag.push(T::ONE / diag);
        }
    }

    /// Refactors the assembled values with the pivots and patterns of the last search; false
    /// when a pivot falls below [`PIVOT_THRESHOLD`] of its column (or the singularity test),
    /// leaving the factors unusable until a search.
    fn refactor(&mut self, pivot_tol: f64, col_max: &[f64]) -> bool {
        let f = &mut self.factors;
        let work = &mut f.work;
        for j in 0..f.col.len() {
            let c = f.col[j];
            for k in self.col_ptr[c]..self.col_ptr[c + 1] {
                work[f.row_pos[self.row_idx[k]]] = self.values[k];
            }
            for p in f.u_ptr[j]..f.u_ptr[j + 1] {
                let k = f.u_idx[p];
                let ukj = work[k];
                work[k] = T::ZERO;
                f.u_val[p] = ukj;
                if ukj != T::ZERO {
                    for q in f.l_ptr[k]..f.l_ptr[k + 1] {
                        let i = f.l_idx[q];
                        work[i] -= f.l_val[q] * ukj;
                    }
                }
            }
            let pivot = work[j];
            work[j] = T::ZERO;
            let (lo, hi) = (f.l_ptr[j], f.l_ptr[j + 1]);
            let largest = f.l_idx[lo..hi]
                .iter()
                .fold(0.0_f64, |m, &i| m.max(work[i].modulus()));
            let size = pivot.modulus();
            let holds = size > pivot_tol * col_max[c]
                && size >= PIVOT_THRESHOLD * largest
                && size.is_finite();
            if !holds {
                for &i in &f.l_idx[lo..hi] {
                    work[i] = T::ZERO;
                }
                return false;
            }
            let inv = T::ONE / pivot;
            f.inv_diag[j] = inv;
            for q in lo..hi {
                let i = f.l_idx[q];
                f.l_val[q] = work[i] * inv;
                work[i] = T::ZERO;
            }
        }
        true
    }

    /// Solves `A x = rhs` in place with the last factorisation (the caller checks it is
    /// valid): `rhs` permuted by rows, `L` forward, `U` backward, unpermuted by columns.
    pub(crate) fn solve(&mut self, rhs: &mut [T]) {
        let f = &mut self.factors;
        let y = &mut f.work;
        for (y, &r) in y.iter_mut().zip(&f.row_of) {
            *y = rhs[r];
        }
        for j in 0..y.len() {
            let yj = y[j];
            if yj != T::ZERO {
                for q in f.l_ptr[j]..f.l_ptr[j + 1] {
                    let i = f.l_idx[q];
                    y[i] -= f.l_val[q] * yj;
                }
            }
        }
        for j in (0..y.len()).rev() {
            let yj = y[j] * f.inv_diag[j];
            y[j] = T::ZERO;
            rhs[f.col[j]] = yj;
            if yj != T::ZERO {
                for p in f.u_ptr[j]..f.u_ptr[j + 1] {
                    let i = f.u_idx[p];
                    y[i] -= f.u_val[p] * yj;
                }
            }
        }
    }

    /// Solves `A^T z = rhs` (transposed, not conjugated) in place with the last factorisation.
    /// With `P A Q = L U`, `A^T = Q U^T L^T P`: `rhs` permuted by columns, `U^T` forward and
    /// `L^T` backward (each a dot product with a stored column), unpermuted by rows.
    pub(crate) fn solve_transposed(&mut self, rhs: &mut [T]) {
        let f = &mut self.factors;
        let y = &mut f.work;
        for (y, &c) in y.iter_mut().zip(&f.col) {
            *y = rhs[c];
        }
        for j in 0..y.len() {
            let mut s = y[j];
            for p in f.u_ptr[j]..f.u_ptr[j + 1] {
                s -= f.u_val[p] * y[f.u_idx[p]];
            }
            y[j] = s * f.inv_diag[j];
        }
        for j in (0..y.len()).rev() {
            let mut s = y[j];
            for q in f.l_ptr[j]..f.l_ptr[j + 1] {
                s -= f.l_val[q] * y[f.l_idx[q]];
            }
            y[j] = s;
        }
        for (y, &r) in y.iter_mut().zip(&f.row_of) {
            rhs[r] = *y;
            *y = T::ZERO;
        }
    }
}
