//! The sparse path: CSC storage of pattern + diagonal, COLAMD order computed once, faer's
//! simplicial (left-looking, partial pivoting) numeric LU on every refactorisation.

use faer::dyn_stack::MemStack;
use faer::perm::PermRef;
use faer::sparse::linalg::lu::{
    LuSymbolicParams, SymbolicLu, factorize_symbolic_lu, simplicial, simplicial::SimplicialLu,
};
use faer::sparse::linalg::{LuError, SupernodalThreshold};
use faer::sparse::{SparseColMatRef, SymbolicSparseColMatRef};
use faer::{Conj, MatMut, Par};

use super::singular;
use crate::solver::SolveError;

pub(super) struct Sparse {
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
    values: Vec<f64>,
    /// CSC slot of each pattern entry, in pattern order.
    slot: Vec<usize>,
    /// CSC slot of each diagonal entry (the structure always holds the diagonal, for gmin).
    diag_slot: Vec<usize>,
    symbolic: SymbolicLu<usize>,
    lu: SimplicialLu<usize, f64>,
    row_perm: Vec<usize>,
    row_perm_inv: Vec<usize>,
}

impl Sparse {
    pub(super) fn new(n: usize, pattern: &[(usize, usize)]) -> Result<Self, SolveError> {
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
            values: vec![0.0; row_idx.len()],
            col_ptr,
            row_idx,
            slot,
            diag_slot,
            symbolic,
            lu: SimplicialLu::new(),
            row_perm: vec![0; n],
            row_perm_inv: vec![0; n],
        })
    }

    pub(super) fn assemble(
        &mut self,
        values: &[f64],
        diag: Option<&[f64]>,
        row_max: &mut [f64],
        col_max: &mut [f64],
    ) {
        self.values.fill(0.0);
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
                let (r, v) = (self.row_idx[k], self.values[k].abs());
                row_max[r] = row_max[r].max(v);
                *cm = cm.max(v);
            }
        }
    }

    pub(super) fn factor(
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
                .map_or(0.0, |(_, v)| v.abs());
            if pivot.is_nan() || pivot <= pivot_tol * col_max[c] {
                return Err(singular(self.row_perm[j], c));
            }
        }
        Ok(())
    }

    /// Solves in place with the last factorisation (the caller checks it is valid).
    pub(super) fn solve(&self, x: MatMut<'_, f64>, stack: &mut MemStack) {
        let n = self.row_perm.len();
        let row_perm = PermRef::new_checked(&self.row_perm, &self.row_perm_inv, n);
        let col_perm = self.symbolic.col_perm();
        self.lu
            .solve_in_place_with_conj(row_perm, col_perm, Conj::No, x, Par::Seq, stack);
    }
}
