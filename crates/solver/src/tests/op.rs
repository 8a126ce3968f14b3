use super::systems::{Algebraic, DiodeCircuit, LinearDae};
use crate::{OpOptions, OpStrategy, SolveError, Tolerances, operating_point};

/// Diode voltage by bisection on the Shockley equation (independent of Newton).
fn bisect_diode(d: &DiodeCircuit) -> f64 {
    let f = |v: f64| (v - d.vs) / d.r + d.is * ((v / d.vt).exp() - 1.0);
    let (mut lo, mut hi) = (0.0, d.vs);
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if f(mid) > 0.0 { hi = mid } else { lo = mid }
    }
    0.5 * (lo + hi)
}

fn diode() -> DiodeCircuit {
    DiodeCircuit {
        vs: 5.0,
        r: 1e3,
        is: 1e-14,
        vt: 0.025852,
        scale: 1.0,
    }
}

/// Diode + resistor operating point agrees with bisection to 1e-9 V.
#[test]
fn diode_resistor_operating_point() {
    let mut d = diode();
    let expected = bisect_diode(&d);
    let tol = Tolerances::uniform(2, 1e-9, 1e-12);
    let mut x = [0.0, 0.0];
    let rep = operating_point(&mut d, 0.0, &mut x, &tol, &OpOptions::default()).expect("op");
    assert!((x[1] - expected).abs() < 1e-9, "{} vs {expected}", x[1]);
    assert_eq!(x[0], 5.0);
    assert_eq!(rep.strategy, OpStrategy::Newton);
}

/// With Newton starved of iterations (4), plain Newton and gmin stepping fail from a cold
/// start; source stepping lands on the bisection answer (1e-9 V) and leaves the scale at 1.
#[test]
fn fallbacks_rescue_a_hard_start() {
    let mut d = diode();
    let expected = bisect_diode(&d);
    let tol = Tolerances::uniform(2, 1e-9, 1e-12);
    let mut opts = OpOptions::default();
    opts.newton.max_iter = 4;
    let mut x = [0.0, 0.0];
    let rep = operating_point(&mut d, 0.0, &mut x, &tol, &opts).expect("rescued");
    assert_eq!(rep.strategy, OpStrategy::SourceStepping);
    assert!((x[1] - expected).abs() < 1e-9, "{} vs {expected}", x[1]);
    assert_eq!(d.scale, 1.0);
}

/// The operating point of the RLC has x' = 0: no current, v_c = v_b = V.
#[test]
fn linear_dae_operating_point() {
    let mut s = LinearDae::rlc(10.0, 1e-3, 1e-6, 2.0);
    let tol = Tolerances::uniform(3, 1e-9, 1e-12);
    let mut x = [0.0; 3];
    operating_point(&mut s, 0.0, &mut x, &tol, &OpOptions::default()).expect("op");
    assert!(x[0].abs() < 1e-12 && (x[1] - 2.0).abs() < 1e-12 && (x[2] - 2.0).abs() < 1e-12);
}

/// `x^2 + 1 = 0`: every strategy fails; the error says so and keeps the last cause.
#[test]
fn no_operating_point_is_reported() {
    let mut s = Algebraic {
        n: 1,
        pattern: vec![(0, 0)],
        diff: vec![false],
        f: |x: &[f64], out: &mut [f64]| out[0] = x[0] * x[0] + 1.0,
        j: |x: &[f64], out: &mut [f64]| out[0] = 2.0 * x[0],
    };
    let tol = Tolerances::uniform(1, 1e-6, 1e-9);
    let mut x = [0.3];
    let err = operating_point(&mut s, 0.0, &mut x, &tol, &OpOptions::default()).expect_err("none");
    assert!(
        matches!(err, SolveError::NoOperatingPoint { .. }),
        "{err:?}"
    );
    assert_eq!(x, [0.3], "the caller's guess is left untouched");
}

/// Two copies of the same equation: singular, reported with indices, no panic.
#[test]
fn singular_system_is_reported() {
    let mut s = Algebraic {
        n: 2,
        pattern: vec![(0, 0), (0, 1), (1, 0), (1, 1)],
        diff: vec![false, false],
        f: |x: &[f64], out: &mut [f64]| {
            out[0] = x[0] + x[1] - 1.0;
            out[1] = x[0] + x[1] - 2.0;
        },
        j: |_x: &[f64], out: &mut [f64]| out.fill(1.0),
    };
    let tol = Tolerances::uniform(2, 1e-6, 1e-9);
    let err = operating_point(&mut s, 0.0, &mut [0.0, 0.0], &tol, &OpOptions::default());
    let Err(SolveError::NoOperatingPoint { last }) = err else {
        panic!("expected no operating point, got {err:?}");
    };
    assert!(matches!(
        *last,
        SolveError::SingularJacobian {
            row: Some(_),
            column: Some(_),
            ..
        }
    ));
}

/// `x^3 = 1` from x = 0: the Jacobian is singular at the start, so plain Newton fails; the
/// gmin conductance makes it regular and gmin stepping walks to x = 1 (to 1e-12).
#[test]
fn gmin_stepping_rescues_a_singular_start() {
    let mut s = Algebraic {
        n: 1,
        pattern: vec![(0, 0)],
        diff: vec![false],
        f: |x: &[f64], out: &mut [f64]| out[0] = x[0] * x[0] * x[0] - 1.0,
        j: |x: &[f64], out: &mut [f64]| out[0] = 3.0 * x[0] * x[0],
    };
    let tol = Tolerances::uniform(1, 1e-12, 1e-14);
    let mut x = [0.0];
    let rep = operating_point(&mut s, 0.0, &mut x, &tol, &OpOptions::default()).expect("op");
    assert_eq!(rep.strategy, OpStrategy::GminStepping);
    assert!((x[0] - 1.0).abs() < 1e-12, "{}", x[0]);
}

/// `l = 6`, `r = 10^l` from zero (a switch's resistance interpolated in decades): every full
/// step makes the residual's norm larger until the last (r goes 0, 14.8, 1e6), so the line
/// search creeps 3 % of the way per iteration and the damped strategies run out of
/// iterations; full Newton steps land on r = 1e6 in a few.
#[test]
fn full_steps_rescue_an_exponential_the_line_search_creeps_along() {
    let mut s = Algebraic {
        n: 2,
        pattern: vec![(0, 0), (1, 0), (1, 1)],
        diff: vec![false, false],
        f: |x: &[f64], out: &mut [f64]| {
            out[0] = x[0] - 6.0;
            out[1] = x[1] - 10f64.powf(x[0]);
        },
        j: |x: &[f64], out: &mut [f64]| {
            out[0] = 1.0;
            out[1] = -std::f64::consts::LN_10 * 10f64.powf(x[0]);
            out[2] = 1.0;
        },
    };
    let tol = Tolerances::uniform(2, 1e-9, 1e-12);
    let mut x = [0.0, 0.0];
    let rep = operating_point(&mut s, 0.0, &mut x, &tol, &OpOptions::default()).expect("op");
    assert_eq!(rep.strategy, OpStrategy::FullSteps);
    assert!(
        (x[0] - 6.0).abs() < 1e-12 && (x[1] - 1e6).abs() < 1e-6,
        "{x:?}"
    );
}
