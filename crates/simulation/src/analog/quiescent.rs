//! The quiescent point (LRM 1076.1 12.6.4): the operating point with the augmentation set
//! `x'_i = 0` for every differential unknown, except those a break statement fixes, which are
//! held at their value while `x'_i` takes their place as the Newton unknown.
//!
//! A differential unknown that `x' = 0` leaves undetermined is held at its initial value too,
//! as if a break statement fixed it: one that appears nowhere undifferentiated (an integrator
//! whose output feeds nothing algebraic), or one whose derivative an equation sets without
//! any undifferentiated unknown (`phi'dot == wc`, a free-running oscillator's phase, where
//! `x' = 0` contradicts the equation). Without this such models have no quiescent point
//! (a singular Jacobian at t = 0); with it they start from their initial values, as a
//! `break phi => 0.0;` the model does not write would make them.
//!
//! Break values can hold more than the equations allow: `break w1 => 0.0, w2 => 0.0;` on two
//! inertias joined by a rigid gear (`w1 == 3.0 * w2`, an index-2 system) leaves the gear's
//! equation with no unknown at all, and the Jacobian singular. Such an equation is structurally
//! unmatched; one held unknown it reads is released (solved from it, `w1 = 3 w2`, projecting
//! inconsistent values onto the constraint), until every equation is matched. The transient
//! integrator's initialisation then finds the consistent derivatives (`w1' = 3 w2'`).
//!
//! An adapter [`DaeSystem`] presents the augmented problem to [`operating_point`] (which adds
//! gmin and source stepping): its unknown `z_i` is `x'_i` for a fixed differential unknown and
//! `x_i` otherwise, and its Jacobian column `i` is `dF/dx'_i` or `dF/dx_i` accordingly.

use super::AnalogSystem;
use vams_solver::{DaeSystem, ErrorNorm, OpOptions, SolveError, Tolerances, operating_point};

struct Quiescent<'a> {
    sys: &'a mut AnalogSystem,
    /// Per unknown: true when `z_i` is `x'_i` (a fixed differential unknown).
    held: Vec<bool>,
    algebraic: Vec<bool>,
    x: Vec<f64>,
    xdot: Vec<f64>,
}

impl Quiescent<'_> {
    fn assemble(&mut self, z: &[f64]) {
        for (i, &zi) in z.iter().enumerate() {
            if self.held[i] {
                self.xdot[i] = zi;
            } else {
                self.x[i] = zi;
            }
        }
    }
}

impl DaeSystem for Quiescent<'_> {
    fn len(&self) -> usize {
        self.held.len()
    }
    fn differential(&self) -> &[bool] {
        // Every Newton unknown of the augmented problem is algebraic.
        &self.algebraic
    }
    fn pattern(&self) -> &[(usize, usize)] {
        self.sys.pattern()
    }
    fn residual(&mut self, t: f64, z: &[f64], _zdot: &[f64], out: &mut [f64]) {
        self.assemble(z);
        self.sys.residual(t, &self.x, &self.xdot, out);
    }
    fn jacobian(&mut self, t: f64, z: &[f64], _zdot: &[f64], _alpha: f64, out: &mut [f64]) {
        self.assemble(z);
        self.sys
            .jacobian_columns(t, &self.x, &self.xdot, &self.held, out);
    }
    fn set_source_scale(&mut self, s: f64) {
        self.sys.set_source_scale(s);
    }
}

/// Marks in `held` the differential unknowns that `x' = 0` leaves undetermined (see the
/// module comment), from the structure of the Jacobian: an unknown that no equation reads
/// undifferentiated, and the unknowns of an equation that reads no unknown undifferentiated
/// (every branch of its simultaneous `if` included). Structure, not values: a value that is
/// zero at the guess (a flat table segment, `x**2` at 0) does not make an unknown free.
fn hold_undetermined(sys: &AnalogSystem, held: &mut [bool]) {
    let n = held.len();
    let differential = sys.differential();
    let (mut row_x, mut col_x) = (vec![false; n], vec![false; n]);
    for ((r, c), reads_x, _) in sys.jacobian_structure() {
        if reads_x && !held[c] {
            row_x[r] = true;
            col_x[c] = true;
        }
    }
    let mut hold = vec![false; n];
    for ((r, c), _, reads_dot) in sys.jacobian_structure() {
        if differential[c] && reads_dot && (!row_x[r] || !col_x[c]) {
            hold[c] = true;
        }
    }
    for (h, new) in held.iter_mut().zip(hold) {
        *h |= new;
    }
}

/// Releases held unknowns (see the module comment) until a maximum matching of the augmented
/// problem's structure (column `c` is `x'_c` where held, `x_c` otherwise) matches every
/// equation, or no unmatched equation reads a held unknown. One at a time: releasing one can
/// match several equations.
fn release_overheld(sys: &AnalogSystem, held: &mut [bool]) {
    let n = held.len();
    let structure: Vec<((usize, usize), bool, bool)> = sys.jacobian_structure().collect();
    for _ in 0..n {
        let pattern: Vec<(usize, usize)> = (structure.iter())
            .filter(|&&((_, c), reads_x, reads_dot)| if held[c] { reads_dot } else { reads_x })
            .map(|&(rc, _, _)| rc)
            .collect();
        let m =
            super::structure::maximum_matching(&super::structure::Incidence::new(n, n, &pattern));
        // The last held unknown that an unmatched equation reads undifferentiated.
        let release = (structure.iter().rev())
            .find(|&&((r, c), reads_x, _)| m.row_match[r].is_none() && reads_x && held[c])
            .map(|&((_, c), _, _)| c);
        match release {
            Some(c) => held[c] = false,
            None => return,
        }
    }
}

/// See [`AnalogSystem::quiescent_point`]. A fixed value for an unknown that appears nowhere
/// differentiated has no `x' = 0` equation to replace: it only serves as the starting guess.
pub fn solve(
    sys: &mut AnalogSystem,
    t: f64,
    guess: &[f64],
    fixed: &[(usize, f64)],
    reltol: f64,
    abstol: &[f64],
    options: &OpOptions,
) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
    let n = sys.len();
    let invalid = |reason, index| Err(SolveError::InvalidSystem { reason, index });
    if guess.len() != n {
        return invalid(
            "initial guess length differs from the system size",
            guess.len(),
        );
    }
    if abstol.len() != n {
        return invalid("abstol length differs from the system size", abstol.len());
    }
    let mut x = guess.to_vec();
    let mut held = vec![false; n];
    for &(i, v) in fixed {
        if i >= n {
            return invalid("fixed unknown index out of range", i);
        }
        x[i] = v;
        held[i] = sys.differential()[i];
    }
    hold_undetermined(sys, &mut held);
    if fixed
        .iter()
        .any(|&(i, _)| held.get(i).copied().unwrap_or(false))
    {
        release_overheld(sys, &mut held);
    }
    let mut z: Vec<f64> = (0..n).map(|i| if held[i] { 0.0 } else { x[i] }).collect();
    let mut p = Quiescent {
        sys,
        held,
        algebraic: vec![false; n],
        x,
        xdot: vec![0.0; n],
    };
    let tol = Tolerances {
        reltol,
        abstol: abstol.to_vec(),
        norm: ErrorNorm::Rms,
    };
    operating_point(&mut p, t, &mut z, &tol, options)?;
    p.assemble(&z);
    Ok((p.x, p.xdot))
}
