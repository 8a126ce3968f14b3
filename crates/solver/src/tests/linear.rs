use proptest::prelude::*;

use crate::{LinearOptions, LinearSolver, SolveError};

fn dense() -> LinearOptions {
    LinearOptions {
        dense_max: usize::MAX,
        ..LinearOptions::default()
    }
}

fn sparse() -> LinearOptions {
    LinearOptions {
        dense_max: 0,
        ..LinearOptions::default()
    }
}

/// Solves a 3x3 system on both paths; exact to 1e-14.
#[test]
fn small_system_both_paths() {
    let pattern = [
        (0, 0),
        (0, 1),
        (1, 0),
        (1, 1),
        (1, 2),
        (2, 1),
        (2, 2),
        (2, 2),
    ];
    // The duplicate (2, 2) entries are summed: A[2][2] = 3 + 1.
    let values = [4.0, 1.0, 1.0, 5.0, 2.0, 2.0, 3.0, 1.0];
    let x_true = [1.0, -2.0, 0.5];
    let b = [4.0 - 2.0, 1.0 - 10.0 + 1.0, -4.0 + 2.0];
    for opts in [dense(), sparse()] {
        let mut lin = LinearSolver::new(3, &pattern, opts).expect("valid pattern");
        lin.factor(&values, 0.0).expect("regular");
        let mut x = b;
        lin.solve_in_place(&mut x).expect("factored");
        for (x, t) in x.iter().zip(x_true) {
            assert!(
                (x - t).abs() < 1e-14,
                "{x} vs {t} (dense: {})",
                lin.is_dense()
            );
        }
    }
}

#[test]
fn singular_matrices_are_errors_with_indices() {
    // Rows 0 and 1 are equal: numerically singular.
    let pattern = [(0, 0), (0, 1), (1, 0), (1, 1), (2, 2)];
    let values = [1.0, 1.0, 1.0, 1.0, 1.0];
    for opts in [dense(), sparse()] {
        let mut lin = LinearSolver::new(3, &pattern, opts).expect("valid pattern");
        let err = lin.factor(&values, 0.0).expect_err("singular");
        let SolveError::SingularJacobian {
            row: Some(r),
            column: Some(c),
            structural: false,
            ..
        } = err
        else {
            panic!("expected a singular Jacobian with indices, got {err:?}");
        };
        assert!(r < 2 && c < 2, "row {r}, column {c}");
        let mut x = [1.0; 3];
        assert!(
            lin.solve_in_place(&mut x).is_err(),
            "no solve after a failed factor"
        );
    }
    // Unknown 1 appears in no equation: an empty column names it exactly.
    let pattern = [(0, 0), (1, 0), (2, 2)];
    for opts in [dense(), sparse()] {
        let mut lin = LinearSolver::new(3, &pattern, opts).expect("valid pattern");
        let err = lin.factor(&[1.0, 2.0, 1.0], 0.0).expect_err("singular");
        assert!(matches!(
            err,
            SolveError::SingularJacobian {
                row: None,
                column: Some(1),
                structural: true,
                ..
            }
        ));
    }
    // Equation 2 is empty.
    let pattern = [(0, 0), (1, 1), (0, 2)];
    for opts in [dense(), sparse()] {
        let mut lin = LinearSolver::new(3, &pattern, opts).expect("valid pattern");
        let err = lin.factor(&[1.0, 2.0, 1.0], 0.0).expect_err("singular");
        assert!(matches!(
            err,
            SolveError::SingularJacobian {
                row: Some(2),
                column: None,
                structural: true,
                ..
            }
        ));
    }
}

#[test]
fn bad_inputs_are_errors() {
    assert!(matches!(
        LinearSolver::new(2, &[(0, 0), (2, 1)], dense()),
        Err(SolveError::InvalidSystem { index: 1, .. })
    ));
    let mut lin = LinearSolver::new(2, &[(0, 0), (1, 1)], sparse()).expect("valid");
    assert!(matches!(
        lin.factor(&[1.0, f64::NAN], 0.0),
        Err(SolveError::NonFiniteJacobian {
            row: 1,
            column: 1,
            ..
        })
    ));
    assert!(lin.factor(&[1.0], 0.0).is_err(), "wrong value count");
    let mut empty = LinearSolver::new(0, &[], sparse()).expect("empty is fine");
    empty.factor(&[], 0.0).expect("nothing to factor");
    empty.solve_in_place(&mut []).expect("nothing to solve");
}

/// gmin shift on the diagonal makes a floating unknown solvable.
#[test]
fn diagonal_shift_regularises() {
    for opts in [dense(), sparse()] {
        let mut lin = LinearSolver::new(2, &[(0, 0)], opts).expect("valid");
        lin.factor(&[2.0], 1e-3).expect("shifted");
        let mut x = [2.001, 1e-3];
        lin.solve_in_place(&mut x).expect("factored");
        assert!((x[0] - 1.0).abs() < 1e-14 && (x[1] - 1.0).abs() < 1e-12);
    }
}

/// A random sparse, strictly diagonally dominant matrix as (pattern, values, n).
/// `(n, pattern, values, rhs)`.
type SparseCase = (usize, Vec<(usize, usize)>, Vec<f64>, Vec<f64>);

fn sparse_system() -> impl Strategy<Value = SparseCase> {
    (30usize..90).prop_flat_map(|n| {
        (
            Just(n),
            proptest::collection::vec((0..n, 0..n, -1.0f64..1.0), n..4 * n),
            proptest::collection::vec(-1.0f64..1.0, n),
        )
            .prop_map(|(n, off, b)| {
                let mut pattern = Vec::new();
                let mut values = Vec::new();
                let mut row_sum = vec![0.0f64; n];
                for (r, c, v) in off {
                    pattern.push((r, c));
                    values.push(v);
                    row_sum[r] += v.abs();
                }
                for (i, s) in row_sum.iter().enumerate() {
                    pattern.push((i, i));
                    values.push(s + 1.0);
                }
                (n, pattern, values, b)
            })
    })
}

proptest! {
    /// Dense and sparse LU agree to 1e-10 (relative to the largest component).
    #[test]
    fn sparse_and_dense_agree((n, pattern, values, b) in sparse_system()) {
        let mut xs = b.clone();
        let mut xd = b.clone();
        let mut s = LinearSolver::new(n, &pattern, sparse()).expect("valid");
        let mut d = LinearSolver::new(n, &pattern, dense()).expect("valid");
        prop_assert!(!s.is_dense() && d.is_dense());
        s.factor(&values, 0.0).expect("dominant");
        d.factor(&values, 0.0).expect("dominant");
        s.solve_in_place(&mut xs).expect("factored");
        d.solve_in_place(&mut xd).expect("factored");
        let scale = xd.iter().fold(1e-300f64, |m, v| m.max(v.abs()));
        for (a, b) in xs.iter().zip(&xd) {
            prop_assert!((a - b).abs() <= 1e-10 * scale, "{} vs {}", a, b);
        }
    }
}

/// `(n, pattern, two value sets, rhs)`: a random pattern with its diagonal, and values of
/// either sign whose diagonal may be small, so pivots move between the two sets.
type RefactorCase = (usize, Vec<(usize, usize)>, Vec<f64>, Vec<f64>, Vec<f64>);

fn refactor_case() -> impl Strategy<Value = RefactorCase> {
    (2usize..12).prop_flat_map(|n| {
        proptest::collection::vec((0..n, 0..n), n..3 * n).prop_flat_map(move |off| {
            let mut pattern: Vec<(usize, usize)> = (0..n).map(|i| (i, i)).collect();
            pattern.extend(off);
            let m = pattern.len();
            (
                Just(n),
                Just(pattern),
                proptest::collection::vec(-1.0f64..1.0, m),
                proptest::collection::vec(-1.0f64..1.0, m),
                proptest::collection::vec(-1.0f64..1.0, n),
            )
        })
    })
}

/// Solves with a fresh dense solver, or `None` where it finds the matrix singular.
fn fresh_solve(
    n: usize,
    pattern: &[(usize, usize)],
    values: &[f64],
    b: &[f64],
) -> Option<Vec<f64>> {
    let mut lin = LinearSolver::new(n, pattern, dense()).expect("valid");
    lin.factor(values, 0.0).ok()?;
    let mut x = b.to_vec();
    lin.solve_in_place(&mut x).expect("factored");
    Some(x)
}

proptest! {
    /// A refactorisation (pivots reused from the first value set, or searched anew when they
    /// no longer hold) solves the second system as a fresh factorisation does, to 1e-9 of the
    /// residual scale, on well-conditioned cases; on both paths.
    #[test]
    fn refactorisation_matches_a_fresh_factorisation((n, pattern, v1, v2, b) in refactor_case()) {
        for opts in [dense(), sparse()] {
            refactor_and_check(n, &pattern, &v1, &v2, &b, opts)?;
        }
    }
}

fn refactor_and_check(
    n: usize,
    pattern: &[(usize, usize)],
    v1: &[f64],
    v2: &[f64],
    b: &[f64],
    opts: LinearOptions,
) -> Result<(), TestCaseError> {
    let mut lin = LinearSolver::new(n, pattern, opts).expect("valid");
    // Singular or not, the first factorisation leaves a state the second must not trust.
    let _ = lin.factor(v1, 0.0);
    let Some(expected) = fresh_solve(n, pattern, v2, b) else {
        if lin.is_dense() {
            prop_assert!(
                lin.factor(v2, 0.0).is_err(),
                "a fresh solver finds it singular"
            );
        }
        // The sparse path's column order differs: its verdict on a matrix the dense path
        // calls singular may too.
        return Ok(());
    };
    // Residual check of the reference: skip ill-conditioned draws.
    let mut a = vec![0.0; n * n];
    for (&(r, c), &v) in pattern.iter().zip(v2) {
        a[r * n + c] += v;
    }
    let scale = expected.iter().fold(0.0f64, |m, v| m.max(v.abs()));
    prop_assume!(scale < 1e6);
    // Twice: the second reuses the pivots of the first whenever they still hold.
    for _ in 0..2 {
        lin.factor(v2, 0.0).expect("a fresh solver factors it");
        let mut x = b.to_vec();
        lin.solve_in_place(&mut x).expect("factored");
        for r in 0..n {
            let ax: f64 = (0..n).map(|c| a[r * n + c] * x[c]).sum();
            prop_assert!(
                (ax - b[r]).abs() <= 1e-9 * scale.max(1.0),
                "row {}: {} vs {} (dense: {})",
                r,
                ax,
                b[r],
                lin.is_dense()
            );
        }
    }
    let counts = lin.pivot_counts();
    // Every factorisation counted (the pattern holds the diagonal: no empty row).
    prop_assert_eq!(counts.searched + counts.reused, 3);
    prop_assert!(
        counts.reused >= 1,
        "the third factorisation reuses the second's pivots"
    );
    Ok(())
}

/// A Newton matrix whose values drift a little keeps its pivots: one search, then
/// refactorisations over the schedule; a value change that makes a kept pivot tiny next to
/// its column sends the factorisation back to a search, which still solves exactly.
#[test]
fn pivots_are_reused_while_they_hold() {
    // [[1e-3, 1, 0], [1, 1, 1], [0, 1, 4]] pivots on row 1 first.
    let pattern = [(0, 0), (0, 1), (1, 0), (1, 1), (1, 2), (2, 1), (2, 2)];
    let base = [1e-3, 1.0, 1.0, 1.0, 1.0, 1.0, 4.0];
    let solve = |lin: &mut LinearSolver, values: &[f64]| {
        lin.factor(values, 0.0).expect("regular");
        let mut x = [1.0, 2.0, 3.0];
        lin.solve_in_place(&mut x).expect("factored");
        let a = |r: usize, c: usize| {
            pattern
                .iter()
                .zip(values)
                .filter(|(p, _)| **p == (r, c))
                .map(|(_, v)| v)
                .sum::<f64>()
        };
        for (r, b) in [1.0, 2.0, 3.0].iter().enumerate() {
            let ax: f64 = (0..3).map(|c| a(r, c) * x[c]).sum();
            assert!((ax - b).abs() < 1e-12, "row {r}: {ax} vs {b}");
        }
    };
    let mut lin = LinearSolver::new(3, &pattern, dense()).expect("valid");
    for k in 0..10 {
        let drift: Vec<f64> = base.iter().map(|v| v * (1.0 + 0.01 * k as f64)).collect();
        solve(&mut lin, &drift);
    }
    let counts = lin.pivot_counts();
    assert_eq!((counts.searched, counts.reused), (1, 9));
    // Row 1's pivot in column 0 becomes 1e-6 next to row 0's 1: below the threshold.
    let mut swapped = base;
    swapped[0] = 1.0;
    swapped[2] = 1e-6;
    solve(&mut lin, &swapped);
    let counts = lin.pivot_counts();
    assert_eq!((counts.searched, counts.reused), (2, 9));
    // A switching circuit alternates between the two: each state's order is kept and tried,
    // so no further search.
    for _ in 0..5 {
        solve(&mut lin, &base);
        solve(&mut lin, &swapped);
    }
    let counts = lin.pivot_counts();
    assert_eq!((counts.searched, counts.reused), (2, 19));
}

/// A diode straight across a voltage source, every unknown kept: source row `v1 = 2.19`, the
/// current balance `is + id + 1e-8 v1 = 0`, the across definition `vd + v1 = 0`, and the
/// linearised junction `id - g vd = c` with g = 2.3e24 S and id about 5e22 A. Rows differ by
/// 24 orders of magnitude, columns too; in units of the unknowns' tolerances the matrix is
/// benign, and both paths solve it to rounding (row scaling alone reported it singular).
#[test]
fn badly_scaled_junction_solves_in_tolerance_units() {
    let pattern = [
        (0, 0),
        (1, 0),
        (1, 1),
        (1, 2),
        (2, 0),
        (2, 3),
        (3, 2),
        (3, 3),
    ];
    let g = 2.3e24;
    let values = [1.0, 1e-8, 1.0, 1.0, 1.0, 1.0, 1.0, -g];
    let (v1, id) = (2.19, 5.0e22);
    let x_true: [f64; 4] = [v1, -id - 1e-8 * v1, id, -v1];
    let b = [v1, 0.0, 0.0, id + g * v1];
    let units: Vec<f64> = x_true.iter().map(|x| 1e-3 * x.abs() + 1e-9).collect();
    for opts in [dense(), sparse()] {
        let mut lin = LinearSolver::new(4, &pattern, opts).expect("valid pattern");
        lin.factor_scaled(&values, 0.0, Some(&units))
            .expect("regular in tolerance units");
        let mut x = b;
        lin.solve_in_place(&mut x).expect("factored");
        for (x, t) in x.iter().zip(x_true) {
            assert!(
                (x - t).abs() <= 1e-12 * t.abs(),
                "{x} vs {t} (dense: {})",
                lin.is_dense()
            );
        }
    }
}

/// Powers of two scale exactly: equilibration leaves a well-scaled system's solution bit for
/// bit what the unscaled elimination gives, whatever units are passed.
#[test]
fn equilibration_does_not_change_a_well_scaled_solution() {
    let pattern = [(0, 0), (0, 1), (1, 0), (1, 1)];
    let values: [f64; 4] = [3.0, 1.0, 1.0, 2.0];
    let b = [5.0, 5.0];
    let mut reference = b;
    let mut lin = LinearSolver::new(2, &pattern, dense()).expect("valid pattern");
    lin.factor(&values, 0.0).expect("regular");
    lin.solve_in_place(&mut reference).expect("factored");
    assert_eq!(reference, [1.0, 2.0]);
    let mut x = b;
    lin.factor_scaled(&values, 0.0, Some(&[4.0, 0.25]))
        .expect("regular");
    lin.solve_in_place(&mut x).expect("factored");
    assert_eq!(x, reference);
}
