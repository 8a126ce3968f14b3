//! The small-signal model (`analog::small_signal`): `G` and `C` exactly the symbolic
//! derivatives at the linearisation point, nonlinear terms linearised there, the right side
//! from the spectral sources, the noise sources' injections and densities, a sample and hold
//! as its transfer, and the refusal of a signal shaped in time.

use super::fixture::*;
use crate::analog::{AnalogError, AnalogOptions, AnalogSystem};
use faer::c64;
use vams_design::{Builtin, Design, NoiseSource, QuantityId, SignalId, SignalKind, SpectralSource};
use vams_solver::ac::AcSolver;
use vams_solver::noise::{Injection, noise_at};

/// Declares `u` a spectral source of `magnitude` and `phase` (its equation `u == 0.0` is
/// equation `equation`).
fn spectral(d: &mut Design, u: QuantityId, magnitude: f64, phase: f64, equation: usize) {
    d.spectral_sources.push(SpectralSource {
        quantity: u,
        magnitude: c(magnitude),
        phase: c(phase),
        equation,
        span: d.equations[equation].span,
    });
}

/// `X` at `frequency` of the model at its point.
fn response(
    d: &Design,
    quantities: &[f64],
    frequency: f64,
) -> (Vec<c64>, crate::analog::AnalogSystem) {
    let mut sys = system(d);
    let (x, xdot) = sys.point_from_quantities(quantities, &[]).expect("a point");
    let mut model = sys.small_signal(d, &x, &xdot).expect("a model");
    let mut rhs = vec![c64::default(); model.system.n];
    for (row, m, p) in model.excitation(frequency) {
        rhs[row] += c64::from_polar(m, p);
    }
    let mut solver = AcSolver::new(model.system.clone()).expect("a solver");
    (solver.solve(frequency, &rhs).expect("a solution"), sys)
}

#[test]
fn a_nonlinear_equation_is_linearised_at_the_quiescent_point() {
    // x == 1 + u; y == exp(x): Y = e X = e U, with U = 2 e^{j 0.5}.
    let mut b = Builder::new();
    let (u, x, y) = (b.free("u"), b.free("x"), b.free("y"));
    b.equation("u == 0.0;", q(u), c(0.0));
    b.equation("x == 1.0 + u;", q(x), add(c(1.0), q(u)));
    b.equation("y == exp(x);", q(y), call(Builtin::Exp, q(x)));
    let (mut d, _) = b.finish();
    spectral(&mut d, u, 2.0, 0.5, 0);
    // The kernel's point, perturbed: Newton puts `y` back on exp(1).
    let (xs, sys) = response(&d, &[0.0, 1.0, 2.7], 10.0);
    let yy = xs[sys.quantity_slot(y).expect("kept")];
    let expected = c64::from_polar(2.0 * 1f64.exp(), 0.5);
    assert!((yy - expected).norm() < 1e-14 * expected.norm(), "{yy}");
}

#[test]
fn capacitance_beside_a_large_conductance_keeps_every_digit() {
    // 1e9 * v + 1e-12 * v'dot == u: C is exactly 1e-12 (no difference of two matrices that
    // would leave it to the rounding of 1e9), and V = U / (1e9 + jw 1e-12).
    let mut b = Builder::new();
    let (u, v) = (b.free("u"), b.free("v"));
    b.equation("u == 0.0;", q(u), c(0.0));
    b.equation(
        "1.0e9 * v + 1.0e-12 * v'dot == u;",
        add(mul(c(1e9), q(v)), mul(c(1e-12), dot(v))),
        q(u),
    );
    let (mut d, _) = b.finish();
    spectral(&mut d, u, 1.0, 0.0, 0);
    let mut sys = system(&d);
    let (x, xdot) = sys
        .point_from_quantities(&[0.0, 0.0], &[])
        .expect("a point");
    let model = sys.small_signal(&d, &x, &xdot).expect("a model");
    let mut c_values: Vec<f64> = model
        .system
        .c
        .iter()
        .copied()
        .filter(|&c| c != 0.0)
        .collect();
    c_values.sort_by(f64::total_cmp);
    assert_eq!(c_values, vec![1e-12]);
    let f = 1e18;
    let (xs, sys) = response(&d, &[0.0, 0.0], f);
    let vv = xs[sys.quantity_slot(v).expect("kept")];
    let expected = c64::new(1.0, 0.0) / c64::new(1e9, std::f64::consts::TAU * f * 1e-12);
    assert!(
        (vv - expected).norm() < 1e-14 * expected.norm(),
        "{vv} {expected}"
    );
}

/// `u == 0` (the spectral source) and `y == 3 * S`, where `S` is an implicit signal that a
/// generated process drives (as behind `u'zoh` or `u'slew`).
fn sampled_design(name: &str) -> (Design, QuantityId, QuantityId, SignalId) {
    let mut b = Builder::new();
    let (u, y) = (b.free("u"), b.free("y"));
    let s = b.signal(name, 0.0);
    b.equation("u == 0.0;", q(u), c(0.0));
    b.equation(
        "y == 3.0 * u'zoh(1.0e-3);",
        q(y),
        mul(c(3.0), vams_design::Expr::Signal(s)),
    );
    let (mut d, _) = b.finish();
    d.signals[s.index()].kind = SignalKind::Implicit;
    spectral(&mut d, u, 1.0, 0.0, 0);
    (d, u, y, s)
}

#[test]
fn a_signal_shaped_in_time_is_refused_with_its_span() {
    let (d, _, _, s) = sampled_design("u'slew");
    let mut sys = system(&d);
    let (x, xdot) = sys
        .point_from_quantities(&[0.0, 0.0], &[])
        .expect("a point");
    let errors = sys.small_signal(&d, &x, &xdot).err().expect("refused");
    assert!(
        matches!(&errors[..], [AnalogError::FrequencyDomain { span, what, .. }]
            if *span == d.signals[s.index()].span && what == "`u'slew`"),
        "{errors:?}"
    );
}

#[test]
fn a_sample_and_hold_is_its_transfer_from_its_input() {
    let (mut d, u, y, s) = sampled_design("u'zoh");
    d.sampled.push(vams_design::Sampled {
        signal: s,
        input: u,
        period: 1e-3,
        filter: None,
        span: d.signals[s.index()].span,
    });
    let options = AnalogOptions {
        eliminate: false,
        ..AnalogOptions::default()
    };
    let mut sys = AnalogSystem::with_options(&d, &options).expect("a system");
    let (x, xdot) = sys
        .point_from_quantities(&[0.0, 0.0], &[])
        .expect("a point");
    let mut model = sys.small_signal(&d, &x, &xdot).expect("a model");
    assert_eq!(model.system.sampled.len(), 1, "one transfer term");
    let mut solver = AcSolver::new(model.system.clone()).expect("a solver");
    let mut rhs = vec![c64::default(); model.system.n];
    for (row, m, p) in model.excitation(250.0) {
        rhs[row] += c64::from_polar(m, p);
    }
    let xs = solver.solve(250.0, &rhs).expect("a solution");
    let yy = xs[sys.quantity_slot(y).expect("kept")];
    // 3 (1 - e^{-jwT}) / (jwT) at wT = pi / 2.
    let x = std::f64::consts::FRAC_PI_2;
    let expected = c64::from_polar(3.0 * (x / 2.0).sin() / (x / 2.0), -x / 2.0);
    assert!((yy - expected).norm() < 1e-14, "{yy} {expected}");
}

#[test]
fn an_eliminated_quantity_is_the_linearisation_of_its_formula() {
    // v + 1e-3 v'dot == 3 + u; i == 2 v'dot + v * v, eliminated: I = (2 v0 + 2 jw) V at v0 = 3.
    let mut b = Builder::new();
    let (u, v, i) = (b.free("u"), b.free("v"), b.free("i"));
    b.equation("u == 0.0;", q(u), c(0.0));
    b.equation(
        "v + 1.0e-3 * v'dot == 3.0 + u;",
        add(q(v), mul(c(1e-3), dot(v))),
        add(c(3.0), q(u)),
    );
    b.equation(
        "i == 2.0 * v'dot + v * v;",
        q(i),
        add(mul(c(2.0), dot(v)), mul(q(v), q(v))),
    );
    let (mut d, _) = b.finish();
    spectral(&mut d, u, 1.0, 0.0, 0);
    let mut sys = crate::analog::AnalogSystem::new(&d).expect("a system");
    assert!(sys.quantity_slot(i).is_none(), "i is eliminated");
    let (x, xdot) = sys
        .point_from_quantities(&[0.0, 3.0, 9.0], &[])
        .expect("a point");
    sys.small_signal(&d, &x, &xdot).expect("a model");
    let slot = sys.quantity_slot(v).expect("v survives");
    assert_eq!(
        sys.linear_output(i, &x, &xdot),
        Some(vec![(slot, 6.0, 2.0)])
    );
    assert_eq!(
        sys.linear_output(v, &x, &xdot),
        Some(vec![(slot, 1.0, 0.0)])
    );
}

#[test]
fn a_noise_source_enters_at_its_row_with_a_density_that_reads_frequency() {
    // 0 == 2 n (the residual's sign and scale are the writer's); y == 3 + n; the density
    // is 1e-16 / frequency: at 100 Hz, |H|^2 S = 1e-18 whatever the row's coefficient.
    let mut b = Builder::new();
    let (n, y) = (b.free("n"), b.free("y"));
    let f = b.signal("frequency", 0.0);
    b.equation("0.0 == 2.0 * n;", c(0.0), mul(c(2.0), q(n)));
    b.equation("y == 3.0 + n;", q(y), add(c(3.0), q(n)));
    let (mut d, _) = b.finish();
    d.signals[f.index()].kind = SignalKind::Implicit;
    d.frequency_signal = Some(f);
    let density = bin(
        vams_design::BinaryOp::Div,
        c(1e-16),
        vams_design::Expr::Signal(f),
    );
    d.noise_sources.push(NoiseSource {
        quantity: n,
        density: sub(density, c(1e-19)),
        equation: 0,
        span: d.equations[0].span,
    });
    let mut sys = system(&d);
    let (x, xdot) = sys
        .point_from_quantities(&[0.0, 3.0], &[])
        .expect("a point");
    let mut model = sys.small_signal(&d, &x, &xdot).expect("a model");
    let injections: Vec<Injection> = (model.noise_injections().into_iter())
        .map(|(row, coefficient)| Injection { row, coefficient })
        .collect();
    assert_eq!(injections.len(), 1);
    assert_eq!(injections[0].coefficient.abs(), 2.0);
    let densities = model.noise_densities(100.0).expect("a density");
    assert!(
        (densities[0] / (1e-18 - 1e-19) - 1.0).abs() < 1e-14,
        "{densities:?}"
    );
    let output = sys
        .linear_output(y, &x, &xdot)
        .expect("y has an expression");
    let mut solver = AcSolver::new(model.system.clone()).expect("a solver");
    let point =
        noise_at(&mut solver, 100.0, &output, &injections, &densities, &[]).expect("solved");
    assert!(
        (point.total / densities[0] - 1.0).abs() < 1e-14,
        "{point:?}"
    );
    // Above 1 kHz the density is negative: an error naming the source, with its span.
    let error = model.noise_densities(2e3).expect_err("refused");
    assert!(
        matches!(&error, AnalogError::NoiseDensity { name, frequency, value, span }
            if name == "n" && *frequency == 2e3 && *value < 0.0 && *span == d.equations[0].span),
        "{error:?}"
    );
}
