//! Electrical circuits against closed forms: RC and RL step responses, a diode's operating
//! point, quiescent points with and without break values.

use super::fixture::*;
use vams_design::{BinaryOp, Builtin, Expr};
use vams_solver::{DaeSystem, OpOptions};

/// `vs == v` from `a` to ground and a resistor `r` from `a` to `b`; returns the builder and `b`.
fn source_resistor(v: f64, r: f64) -> (Builder, vams_design::TerminalId) {
    let mut b = Builder::new();
    let el = vams_design::NatureId(0);
    let gnd = b.ground(el);
    let a = b.terminal("a", el);
    let n = b.terminal("b", el);
    let (vs, _) = b.branch("vs", "is", a, gnd);
    b.equation(&format!("vs == {v:?};"), q(vs), c(v));
    let (vr, ir) = b.branch("vr", "ir", a, n);
    b.equation(&format!("vr == {r:?} * ir;"), q(vr), mul(c(r), q(ir)));
    (b, n)
}

#[test]
fn rc_charging_matches_the_exponential() {
    let (r, cap) = (1e3, 1e-6);
    let (mut b, n) = source_resistor(1.0, r);
    let gnd = b.ground(vams_design::NatureId(0));
    let (vc, ic) = b.branch("vc", "ic", n, gnd);
    b.equation("ic == 1.0e-6 * vc'dot;", q(ic), mul(c(cap), dot(vc)));
    let (d, _) = b.finish();
    let mut sys = system(&d);
    let slot = sys.quantity_slot(vc).expect("kept");
    assert!(sys.differential()[slot]);
    let tau = r * cap;
    let times = [0.25e-3, 0.5e-3, 1e-3, 2e-3, 3e-3, 5e-3];
    let states = simulate(&mut sys, &[(slot, 0.0)], 1e-4, &times);
    for (t, x) in times.iter().zip(&states) {
        let exact = 1.0 - (-t / tau).exp();
        let rel = (x[slot] - exact).abs() / exact;
        assert!(
            rel < 1e-3,
            "t = {t}: v = {} vs {exact} (rel {rel:e})",
            x[slot]
        );
    }
}

#[test]
fn rl_current_rises_with_time_constant_l_over_r() {
    let (r, l) = (10.0, 10e-3);
    let (mut b, n) = source_resistor(1.0, r);
    let gnd = b.ground(vams_design::NatureId(0));
    let (vl, il) = b.branch("vl", "il", n, gnd);
    b.equation("vl == 10.0e-3 * il'dot;", q(vl), mul(c(l), dot(il)));
    let (d, _) = b.finish();
    let mut sys = system(&d);
    let slot = sys.quantity_slot(il).expect("kept");
    let tau = l / r;
    let times = [0.3e-3, 1e-3, 2e-3, 4e-3];
    let states = simulate(&mut sys, &[(slot, 0.0)], 1e-4, &times);
    for (t, x) in times.iter().zip(&states) {
        let exact = (1.0 / r) * (1.0 - (-t / tau).exp());
        let rel = (x[slot] - exact).abs() / exact;
        assert!(
            rel < 1e-3,
            "t = {t}: i = {} vs {exact} (rel {rel:e})",
            x[slot]
        );
    }
}

#[test]
fn diode_operating_point_matches_a_hand_newton_solution() {
    // 5 V through 1 kOhm into the diode model of models/diode.vhd (rs = 0 here).
    let (is_sat, nvt, vj_lin, r, v) = (1.2e-12, 0.025865, 1.2, 1e3, 5.0);
    let (mut b, n) = source_resistor(v, r);
    let gnd = b.ground(vams_design::NatureId(0));
    let (vd, id) = b.branch("vd", "id", n, gnd);
    let exp = |e: Expr| call(Builtin::Exp, e);
    let div = |a, b| bin(BinaryOp::Div, a, b);
    let above = mul(
        c(is_sat),
        sub(
            mul(
                exp(c(vj_lin / nvt)),
                add(c(1.0), div(sub(q(vd), c(vj_lin)), c(nvt))),
            ),
            c(1.0),
        ),
    );
    let below = mul(c(is_sat), sub(exp(div(q(vd), c(nvt))), c(1.0)));
    let cond = bin(BinaryOp::Gt, q(vd), c(vj_lin));
    b.equation(
        "if vd > vj_lin use id == ... else id == ... end use;",
        q(id),
        Expr::If(Box::new(cond), Box::new(above), Box::new(below)),
    );
    let (d, _) = b.finish();
    let mut sys = system(&d);
    let abstol = sys.abstol(1e-9);
    let n_unk = sys.len();
    let (x, _) = sys
        .quiescent_point(
            0.0,
            &vec![0.0; n_unk],
            &[],
            1e-9,
            &abstol,
            &OpOptions::default(),
        )
        .expect("operating point");

    // Scalar Newton on (v - vd) / r = is (exp(vd / nvt) - 1).
    let mut u = 0.6f64;
    for _ in 0..100 {
        let f = (v - u) / r - is_sat * ((u / nvt).exp() - 1.0);
        let df = -1.0 / r - is_sat / nvt * (u / nvt).exp();
        u -= f / df;
    }
    let got = x[sys.quantity_slot(vd).expect("kept")];
    assert!((got - u).abs() < 1e-9 * u, "vd = {got}, hand Newton {u}");
    let i_got = x[sys.quantity_slot(id).expect("kept")];
    assert!((i_got - (v - u) / r).abs() < 1e-9 * (v - u) / r);
}

#[test]
fn quiescent_point_holds_break_values_and_solves_their_derivatives() {
    let (r, cap) = (1e3, 1e-6);
    let (mut b, n) = source_resistor(1.0, r);
    let gnd = b.ground(vams_design::NatureId(0));
    let (vc, ic) = b.branch("vc", "ic", n, gnd);
    b.equation("ic == 1.0e-6 * vc'dot;", q(ic), mul(c(cap), dot(vc)));
    let (d, _) = b.finish();
    let mut sys = system(&d);
    let (sv, si) = (
        sys.quantity_slot(vc).expect("kept"),
        sys.quantity_slot(ic).expect("kept"),
    );
    let abstol = sys.abstol(1e-9);
    let guess = vec![0.0; sys.len()];
    let opts = OpOptions::default();

    // Without a break value: DC, the capacitor charged to the source.
    let (x, xd) = sys
        .quiescent_point(0.0, &guess, &[], 1e-9, &abstol, &opts)
        .expect("dc");
    assert!((x[sv] - 1.0).abs() < 1e-9 && x[si].abs() < 1e-12 && xd[sv] == 0.0);

    // `break vc => 0.25`: vc held, vc'dot = (1 - 0.25) / (R C).
    let (x, xd) = sys
        .quiescent_point(0.0, &guess, &[(sv, 0.25)], 1e-9, &abstol, &opts)
        .expect("with break");
    assert_eq!(x[sv], 0.25);
    let slope = 0.75 / (r * cap);
    assert!((xd[sv] - slope).abs() < 1e-9 * slope, "vc' = {}", xd[sv]);
    assert!((x[si] - 0.75 / r).abs() < 1e-12);

    // Rows and columns of solver errors map back to the model (solver rows are reordered:
    // row j is the equation matched to unknown j).
    let row = sys
        .row_source()
        .iter()
        .position(|&r| r == 2)
        .expect("assembly row 2");
    let (what, span) = sys.equation_site(&d, row).expect("row 2");
    assert_eq!(what, "`ic == 1.0e-6 * vc'dot`");
    assert_eq!(span, d.equations[2].span);
    assert_eq!(
        sys.unknown_site(&d, sv).map(|s| s.0),
        Some("vc".to_string())
    );
    assert!(sys.equation_site(&d, 99).is_none());
}

#[test]
fn signals_drive_equations_and_are_reported_as_read() {
    let mut b = Builder::new();
    let u = b.signal("u", 2.0);
    let unused = b.signal("unused", 0.0);
    let x = b.free("x");
    b.equation("x == u;", q(x), Expr::Signal(u));
    let (d, _) = b.finish();
    let mut sys = system(&d);
    assert!(sys.reads_signal(u) && !sys.reads_signal(unused));
    let mut out = [0.0];
    sys.residual(0.0, &[0.5], &[0.0], &mut out);
    assert_eq!(out[0], 0.5 - 2.0);
    sys.set_signal(u, 3.0);
    sys.residual(0.0, &[0.5], &[0.0], &mut out);
    assert_eq!(out[0], 0.5 - 3.0);
}

#[test]
fn math_domain_errors_give_nan_not_panics() {
    let mut b = Builder::new();
    let x = b.free("x");
    b.equation(
        "log(x) == 1.0 / x;",
        call(Builtin::Log, q(x)),
        bin(BinaryOp::Div, c(1.0), q(x)),
    );
    let (d, _) = b.finish();
    let mut sys = system(&d);
    let mut out = [0.0];
    sys.residual(0.0, &[-1.0], &[0.0], &mut out);
    assert!(out[0].is_nan());
    let mut jac = vec![0.0; sys.pattern().len()];
    sys.jacobian(0.0, &[0.0], &[0.0], 1.0, &mut jac);
    assert!(!jac[0].is_finite());
}

#[test]
fn source_scale_multiplies_the_independent_terms_only() {
    let (mut b, n) = source_resistor(2.0, 1e3);
    let gnd = b.ground(vams_design::NatureId(0));
    let (vl, _) = b.branch("vl", "il", n, gnd);
    b.equation("vl == 0.5;", q(vl), c(0.5));
    let (d, _) = b.finish();
    let mut sys = system(&d);
    let n = sys.len();
    let mut out = vec![0.0; n];
    sys.set_source_scale(0.25);
    sys.residual(0.0, &vec![0.0; n], &vec![0.0; n], &mut out);
    // Assembly row 0 is `vs - 2.0`, row 1 `vr - 1000 ir` (no source term), row 2 `vl - 0.5`.
    let rows: Vec<usize> = (0..3)
        .map(|r| sys.row_source().iter().position(|&s| s == r).unwrap())
        .collect();
    let pick = |out: &[f64]| rows.iter().map(|&r| out[r]).collect::<Vec<f64>>();
    assert_eq!(pick(&out), [-0.5, 0.0, -0.125]);
    sys.set_source_scale(1.0);
    sys.residual(0.0, &vec![0.0; n], &vec![0.0; n], &mut out);
    assert_eq!(pick(&out), [-2.0, 0.0, -0.5]);
}

#[test]
fn above_signals_are_root_functions() {
    use vams_design::{Signal, SignalKind, Type, Value};
    use vams_solver::{Advance, Transient, TransientOptions};
    let mut b = Builder::new();
    let x = b.free("x");
    b.equation("x'dot == 2.0;", dot(x), c(2.0));
    let (mut d, _) = b.finish();
    d.signals.push(Signal {
        range: None,
        resolution: None,
        guarded: None,
        name: "x'above(0.5)".into(),
        ty: Type::Boolean,
        init: Value::Boolean(false),
        kind: SignalKind::Above {
            quantity: q(x),
            level: c(0.5),
        },
        span: Default::default(),
    });
    let mut sys = system(&d);
    assert_eq!(sys.above_signals(), &[vams_design::SignalId(0)]);
    assert_eq!(sys.root_count(), 1);
    let mut tr = Transient::new(&mut sys, 0.0, &[0.0], TransientOptions::default()).expect("init");
    let root = loop {
        match tr.advance(&mut sys, 1.0).expect("step") {
            Advance::Root { t, index, rising } => break (t, index, rising),
            Advance::Reached(_) => panic!("no root found"),
            Advance::StepAccepted(_) => {}
        }
    };
    assert_eq!((root.1, root.2), (0, true));
    assert!((root.0 - 0.25).abs() < 1e-9, "crossing at {}", root.0);
}

#[test]
fn abstol_follows_tolerance_groups() {
    let mut b = Builder::new();
    let rot = b.nature("rotational_v", "DEFAULT_ANGULAR_VELOCITY", "DEFAULT_TORQUE");
    let gnd = b.ground(rot);
    let shaft = b.terminal("shaft", rot);
    let (w, t) = b.branch("w", "t", shaft, gnd);
    let f = b.free("f");
    b.equation("w == 1.0;", q(w), c(1.0));
    b.equation("f == t;", q(f), q(t));
    let (d, _) = b.finish();
    let sys = system(&d);
    // v(shaft), w, t, f.
    assert_eq!(sys.abstol(0.5), vec![1e-4, 1e-4, 1e-9, 0.5]);
}
