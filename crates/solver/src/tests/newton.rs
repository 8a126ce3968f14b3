use proptest::prelude::*;

use crate::{LinearOptions, Newton, NewtonOptions, NonlinearProblem, SolveError, Tolerances};

struct Linear {
    a: Vec<Vec<f64>>,
    b: Vec<f64>,
    pattern: Vec<(usize, usize)>,
}

impl NonlinearProblem for Linear {
    fn residual(&mut self, x: &[f64], out: &mut [f64]) {
        for (i, o) in out.iter_mut().enumerate() {
            *o = self.a[i].iter().zip(x).map(|(a, x)| a * x).sum::<f64>() - self.b[i];
        }
    }
    fn jacobian(&mut self, _x: &[f64], out: &mut [f64]) {
        for (o, &(i, j)) in out.iter_mut().zip(&self.pattern) {
            *o = self.a[i][j];
        }
    }
}

fn well_conditioned() -> impl Strategy<Value = (Vec<Vec<f64>>, Vec<f64>, Vec<f64>)> {
    (1usize..12).prop_flat_map(|n| {
        (
            proptest::collection::vec(proptest::collection::vec(-1.0f64..1.0, n), n),
            proptest::collection::vec(-10.0f64..10.0, n),
            proptest::collection::vec(-10.0f64..10.0, n),
        )
            .prop_map(move |(mut a, b, x0)| {
                for (i, row) in a.iter_mut().enumerate() {
                    row[i] = row.iter().map(|v| v.abs()).sum::<f64>() + 1.0;
                }
                (a, b, x0)
            })
    })
}

proptest! {
    /// On a linear system Newton converges in exactly one iteration, and the residual on
    /// return is below the requested 1e-10 (the matrix is diagonally dominant, so its
    /// condition number is at most about 2n + 1).
    #[test]
    fn linear_system_converges_in_one_iteration((a, b, x0) in well_conditioned()) {
        let n = b.len();
        let pattern: Vec<_> = (0..n).flat_map(|i| (0..n).map(move |j| (i, j))).collect();
        let mut p = Linear { a, b, pattern };
        let mut newton = Newton::new(n, &p.pattern, LinearOptions::default()).expect("valid");
        let opts = NewtonOptions { residual_tol: Some(1e-10), ..NewtonOptions::default() };
        let tol = Tolerances::uniform(n, 1e-6, 1e-9);
        let mut x = x0;
        let rep = newton.solve(&mut p, &mut x, &tol, &opts, 0.0).expect("converges");
        prop_assert_eq!(rep.iterations, 1);
        let mut r = vec![0.0; n];
        p.residual(&x, &mut r);
        prop_assert!(r.iter().all(|r| r.abs() <= 1e-10), "residual {:?}", r);
    }
}

struct Scalar<F: Fn(f64) -> (f64, f64)>(F);

impl<F: Fn(f64) -> (f64, f64)> NonlinearProblem for Scalar<F> {
    fn residual(&mut self, x: &[f64], out: &mut [f64]) {
        out[0] = (self.0)(x[0]).0;
    }
    fn jacobian(&mut self, x: &[f64], out: &mut [f64]) {
        out[0] = (self.0)(x[0]).1;
    }
}

/// `x^2 + 1 = 0` has no real root: a typed error with iteration count and worst equation.
#[test]
fn no_real_root_is_reported() {
    let mut p = Scalar(|x| (x * x + 1.0, 2.0 * x));
    let mut newton = Newton::new(1, &[(0, 0)], LinearOptions::default()).expect("valid");
    let tol = Tolerances::uniform(1, 1e-6, 1e-9);
    let opts = NewtonOptions {
        max_iter: 20,
        ..NewtonOptions::default()
    };
    let err = newton
        .solve(&mut p, &mut [0.5], &tol, &opts, 2.5)
        .expect_err("no root");
    match err {
        SolveError::NewtonDiverged {
            t,
            iterations,
            worst_equation,
            residual,
        } => {
            assert_eq!((t, iterations, worst_equation), (2.5, 20, 0));
            assert!(residual >= 1.0);
        }
        // Landing exactly on x = 0 makes the Jacobian singular; also a proper report.
        SolveError::SingularJacobian { t, .. } => assert_eq!(t, 2.5),
        other => panic!("unexpected {other:?}"),
    }
}

/// Quadratic convergence to sqrt(2) from 1 within reltol 1e-12; the line search tames
/// `atan`, where undamped Newton from x0 = 3 diverges.
#[test]
fn converges_on_nonlinear_scalars() {
    let tol = Tolerances::uniform(1, 1e-12, 1e-14);
    let mut newton = Newton::new(1, &[(0, 0)], LinearOptions::default()).expect("valid");
    let opts = NewtonOptions::default();
    let mut x = [1.0];
    let rep = newton
        .solve(
            &mut Scalar(|x| (x * x - 2.0, 2.0 * x)),
            &mut x,
            &tol,
            &opts,
            0.0,
        )
        .expect("converges");
    assert!(
        (x[0] - 2f64.sqrt()).abs() < 1e-12 && rep.iterations <= 7,
        "{rep:?}"
    );
    let mut x = [3.0];
    newton
        .solve(
            &mut Scalar(|x| (x.atan(), 1.0 / (1.0 + x * x))),
            &mut x,
            &tol,
            &opts,
            0.0,
        )
        .expect("damped Newton converges");
    assert!(x[0].abs() < 1e-12);
}

/// A NaN in the residual is an error naming the equation, not a panic or a loop.
#[test]
fn non_finite_residual_is_reported() {
    let mut p = Scalar(|x| (x.ln(), 1.0 / x));
    let mut newton = Newton::new(1, &[(0, 0)], LinearOptions::default()).expect("valid");
    let tol = Tolerances::uniform(1, 1e-6, 1e-9);
    let err = newton.solve(&mut p, &mut [-1.0], &tol, &NewtonOptions::default(), 0.0);
    assert!(
        matches!(err, Err(SolveError::NonFiniteResidual { equation: 0, .. })),
        "{err:?}"
    );
}

/// With a bound no update can meet (the residual carries a rapid ripple of 1e-10, as
/// rounding would), the iteration ends once it stops contracting within `stall_tol`, at the
/// root to the ripple's size; without the stall test it fails.
#[test]
fn a_stalled_iteration_within_its_bound_converges() {
    use crate::LinearOptions;
    use crate::newton::{Newton, NewtonOptions, NonlinearProblem, Tolerances};
    struct RippledCube;
    impl NonlinearProblem for RippledCube {
        fn residual(&mut self, x: &[f64], out: &mut [f64]) {
            out[0] = x[0] * x[0] * x[0] - 2.0 + 1e-10 * (1e13 * x[0]).sin();
        }
        fn jacobian(&mut self, x: &[f64], out: &mut [f64]) {
            out[0] = 3.0 * x[0] * x[0];
        }
    }
    let root = 2.0_f64.cbrt();
    let tol = Tolerances::uniform(1, 0.0, 1e-14);
    for stall_tol in [None, Some(1e6)] {
        let mut newton = Newton::new(1, &[(0, 0)], LinearOptions::default()).expect("valid");
        let opts = NewtonOptions {
            tol: 1e-3,
            stall_tol,
            ..NewtonOptions::default()
        };
        let mut x = [3.0];
        let solved = newton.solve(&mut RippledCube, &mut x, &tol, &opts, 0.0);
        match stall_tol {
            None => assert!(solved.is_err(), "{x:?} {solved:?}"),
            Some(_) => {
                let report = solved.expect("stalls at the root");
                assert!(
                    (x[0] - root).abs() < 1e-9 && report.iterations < 20,
                    "{x:?} {report:?}"
                );
            }
        }
    }
}

/// One unknown at three times its tolerance among 999 quiet ones: the RMS calls that 0.09
/// (well within), the bounded norm exactly at its limit, the maximum three.
#[test]
fn the_bounded_norm_does_not_dilute_in_large_systems() {
    use crate::{ErrorNorm, Tolerances};
    let mut e = vec![0.0; 1000];
    e[17] = 3.0e-6;
    let w = vec![1e6; 1000];
    let norm = |norm| {
        Tolerances {
            reltol: 0.0,
            abstol: vec![1e-6; 1000],
            norm,
        }
        .norm(&e, &w)
    };
    assert!((norm(ErrorNorm::Rms) - 3.0 / 1000f64.sqrt()).abs() < 1e-12);
    assert!((norm(ErrorNorm::Bounded) - 1.0).abs() < 1e-12);
    assert!((norm(ErrorNorm::Max) - 3.0).abs() < 1e-12);
    // Where every unknown moves alike the bounded norm is the RMS.
    let even = vec![0.5e-6; 1000];
    let t = Tolerances::uniform(1000, 0.0, 1e-6);
    let bounded = Tolerances {
        norm: ErrorNorm::Bounded,
        ..t.clone()
    };
    assert_eq!(bounded.norm(&even, &w), t.norm(&even, &w));
}
