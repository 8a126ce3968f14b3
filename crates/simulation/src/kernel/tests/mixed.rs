//! The mixed-signal cycle against closed-form solutions. Each scenario runs twice: with the
//! tests' own [`ExprDae`] (runs today) and with the real [`crate::analog::AnalogSystem`]
//! through `simulate` (ignored until the analog module lands).

use super::build::*;
use super::expr_dae::ExprDae;
use crate::kernel::analog_model::AnalogModel;
use crate::kernel::cycle::Simulation;
use crate::kernel::record::Recorder;
use crate::kernel::{Outcome, SimOptions, SimResult, simulate};
use crate::waveform::Waveforms;
use vams_design::{
    BinaryOp::*, BreakReinit, Design, Equation, Expr, Instr, Quantity, QuantityId, QuantityKind,
    SignalId, SignalKind, Type, Value,
};
use vams_syntax::source::Span;

fn quantity(d: &mut Design, name: &str) -> QuantityId {
    d.quantities.push(Quantity {
        name: name.into(),
        kind: QuantityKind::Free,
        tolerance: None,
        subtype: "real".into(),
        unit: None,
        initial_guess: None,
        span: Span::default(),
    });
    QuantityId(d.quantities.len() as u32 - 1)
}

fn equation(d: &mut Design, residual: Expr) {
    d.equations.push(Equation {
        residual,
        span: Span::default(),
        instance: String::new(),
        text: String::new(),
    });
}

fn above(d: &mut Design, q: QuantityId, level: f64) -> SignalId {
    let name = format!("{}'above({level})", d.quantities[q.index()].name);
    let s = signal(d, &name, Type::Boolean, Value::Boolean(false));
    d.signals[s.index()].kind = SignalKind::Above {
        quantity: Expr::Quantity(q),
        level: Expr::real(level),
    };
    s
}

fn brk(reinit: Vec<(QuantityId, Expr)>) -> Instr {
    Instr::Break {
        reinit: reinit
            .into_iter()
            .map(|(q, value)| BreakReinit {
                selector: q,
                quantity: q,
                value,
            })
            .collect(),
        when: None,
        span: Span::default(),
    }
}

fn q(id: QuantityId) -> Expr {
    Expr::Quantity(id)
}

fn dot(id: QuantityId) -> Expr {
    Expr::Dot(id)
}

fn real(x: f64) -> Expr {
    Expr::real(x)
}

fn run_with<A: AnalogModel>(d: &Design, options: &SimOptions, model: A) -> SimResult {
    let mut waveforms = Waveforms::default();
    let recorder =
        Recorder::new(d, &options.probes, options.stop, &mut waveforms).expect("probes exist");
    let end = Simulation::start(d, options, Some(model), &mut |_| {})
        .and_then(|sim| sim.run(recorder, &mut |_| {}))
        .expect("simulation runs");
    SimResult {
        waveforms,
        reports: end.reports,
        outcome: end.outcome,
        stats: end.stats,
    }
}

fn report_times(r: &SimResult, message: &str) -> Vec<f64> {
    r.reports
        .iter()
        .filter(|x| x.message.starts_with(message))
        .map(|x| x.time)
        .collect()
}

// ---- RC low pass driven by a signal step -------------------------------------------------

const TAU: f64 = 1e-3;
const T_STEP: f64 = 1e-3;

/// `tau * v'dot == u - v`, `u` stepping from 0 to 1 at 1 ms; a process reports `v` at 3 ms.
fn rc_design() -> Design {
    let mut d = Design::default();
    let v = quantity(&mut d, "v");
    let u = signal(&mut d, "u", Type::Real, Value::Real(0.0));
    equation(
        &mut d,
        bin(Sub, bin(Mul, real(TAU), dot(v)), bin(Sub, sig(u), q(v))),
    );
    process(
        &mut d,
        "stim",
        vec![],
        vec![wait_for(T_STEP), assign(u, real(1.0), 0.0), Instr::Halt],
    );
    let image = Expr::Image(Type::Real, Box::new(q(v)));
    process(
        &mut d,
        "probe",
        vec![],
        vec![
            wait_for(3e-3),
            assert(None, bin(Concat, text("v="), image), 0),
            Instr::Halt,
        ],
    );
    d
}

fn rc_options() -> SimOptions {
    SimOptions {
        stop: 6e-3,
        reltol: 1e-6,
        ..SimOptions::default()
    }
}

fn check_rc(r: &SimResult) {
    assert_eq!(r.outcome, Outcome::Finished);
    let w = &r.waveforms;
    let v = &w.column("v").expect("v recorded").values;
    let exact = |t: f64| {
        if t <= T_STEP {
            0.0
        } else {
            1.0 - (-(t - T_STEP) / TAU).exp()
        }
    };
    let mut after = 0;
    for (&t, &x) in w.times.iter().zip(v) {
        let e = exact(t);
        // 1e-3 relative once the response has risen a little; absolute 1e-5 V before.
        let tol = if t - T_STEP > 0.1 * TAU {
            1e-3 * e
        } else {
            1e-5
        };
        assert!((x - e).abs() <= tol, "t = {t}: v = {x}, exact {e}");
        after += usize::from(t > T_STEP);
    }
    assert!(after > 10, "only {after} points after the step");
    // The step is recorded as two rows at 1 ms: u = 0, then u = 1.
    let u = &w.column("u").expect("u recorded").values;
    let at_step: Vec<f64> = w
        .times
        .iter()
        .zip(u)
        .filter(|(t, _)| **t == T_STEP)
        .map(|(_, u)| *u)
        .collect();
    assert_eq!(at_step, vec![0.0, 1.0]);
    // The process read the analog solution at 3 ms.
    let probe = r
        .reports
        .iter()
        .find(|x| x.message.starts_with("v="))
        .expect("probe ran");
    let read: f64 = probe.message[2..].parse().expect("a number");
    assert!(
        (read - exact(3e-3)).abs() < 1e-3 * exact(3e-3),
        "read {read}"
    );
    assert!(r.stats.accepted_steps > 0 && r.stats.newton_iterations > 0);
}

#[test]
fn rc_low_pass_follows_the_exponential() {
    let d = rc_design();
    check_rc(&run_with(&d, &rc_options(), ExprDae::new(&d)));
}

#[test]
fn rc_low_pass_follows_the_exponential_with_the_analog_system() {
    let d = rc_design();
    check_rc(&simulate(&d, &rc_options(), &mut |_| {}).expect("runs"));
}

/// With a zero interval the progress hook sees every accepted step: times rise to the stop
/// time, and the results are those of a run without a hook.
#[test]
fn progress_hook_follows_the_simulated_time() {
    use crate::kernel::ProgressHook;
    use std::sync::{Arc, Mutex};
    let d = rc_design();
    let seen = Arc::new(Mutex::new(Vec::new()));
    let sink = seen.clone();
    let options = SimOptions {
        progress: Some(ProgressHook::every(std::time::Duration::ZERO, move |t| {
            sink.lock().expect("one writer").push(t)
        })),
        ..rc_options()
    };
    let r = simulate(&d, &options, &mut |_| {}).expect("runs");
    check_rc(&r);
    let times = seen.lock().expect("run finished").clone();
    assert!(times.len() > 10, "{} calls", times.len());
    assert!(times.windows(2).all(|w| w[0] <= w[1]), "{times:?}");
    assert_eq!(times.last().copied(), Some(rc_options().stop));
}

// ---- Bouncing ball -------------------------------------------------------------------------

const H0: f64 = 1.0;
const G: f64 = 9.81;
const E: f64 = 0.8;

/// `y'dot == v; v'dot == -g`, `break y => h0, v => 0`, and on `not y'above(0)`:
/// `report "impact"; break v => -e * v`.
fn ball_design() -> Design {
    let mut d = Design::default();
    let y = quantity(&mut d, "y");
    let v = quantity(&mut d, "v");
    equation(&mut d, bin(Sub, dot(y), q(v)));
    equation(&mut d, bin(Add, dot(v), real(G)));
    let grounded = above(&mut d, y, 0.0);
    process(
        &mut d,
        "initial",
        vec![],
        vec![brk(vec![(y, real(H0)), (v, real(0.0))]), Instr::Halt],
    );
    process(
        &mut d,
        "bounce",
        vec![],
        vec![
            wait_until(not(sig(grounded)), None),
            report("impact"),
            brk(vec![(v, bin(Mul, real(-E), q(v)))]),
            Instr::Jump(0),
        ],
    );
    d
}

fn ball_options() -> SimOptions {
    SimOptions {
        stop: 2.5,
        reltol: 1e-7,
        ..SimOptions::default()
    }
}

fn check_ball(r: &SimResult) {
    let v1 = (2.0 * G * H0).sqrt();
    let mut expected = vec![(2.0 * H0 / G).sqrt()];
    for k in 1..6 {
        let last = expected[k - 1];
        expected.push(last + 2.0 * E.powi(k as i32) * v1 / G);
    }
    expected.retain(|&t| t < 2.5);
    let impacts = report_times(r, "impact");
    assert_eq!(impacts.len(), expected.len(), "{impacts:?} vs {expected:?}");
    for (t, x) in impacts.iter().zip(&expected) {
        assert!((t - x).abs() < 1e-6, "impact at {t}, analytic {x}");
    }
    assert_eq!(r.stats.breaks, 1 + expected.len());
}

#[test]
fn bouncing_ball_impacts_at_the_analytic_times() {
    let d = ball_design();
    check_ball(&run_with(&d, &ball_options(), ExprDae::new(&d)));
}

#[test]
fn bouncing_ball_impacts_at_the_analytic_times_with_the_analog_system() {
    let d = ball_design();
    check_ball(&simulate(&d, &ball_options(), &mut |_| {}).expect("runs"));
}

// ---- Thermostat with hysteresis --------------------------------------------------------------

const TAU_ROOM: f64 = 100.0;
const T_ON: f64 = 30.0;
const T_OFF: f64 = 10.0;
const T_LOW: f64 = 19.0;
const T_HIGH: f64 = 21.0;
const T0: f64 = 15.0;

/// `if heater use temp'dot == (t_on - temp)/tau else temp'dot == (t_off - temp)/tau`, with a
/// control process on `temp'above(t_high)` and `temp'above(t_low)`.
fn thermostat_design() -> Design {
    let mut d = Design::default();
    let temp = quantity(&mut d, "temp");
    let heater = signal(&mut d, "heater", Type::Boolean, Value::Boolean(true));
    let towards = |target: f64| {
        bin(
            Sub,
            dot(temp),
            bin(Div, bin(Sub, real(target), q(temp)), real(TAU_ROOM)),
        )
    };
    equation(
        &mut d,
        Expr::If(
            Box::new(sig(heater)),
            Box::new(towards(T_ON)),
            Box::new(towards(T_OFF)),
        ),
    );
    let high = above(&mut d, temp, T_HIGH);
    let low = above(&mut d, temp, T_LOW);
    process(
        &mut d,
        "initial",
        vec![],
        vec![brk(vec![(temp, real(T0))]), Instr::Halt],
    );
    process(
        &mut d,
        "break_on_heater",
        vec![],
        vec![brk(vec![]), wait_on(vec![heater]), Instr::Jump(0)],
    );
    process(
        &mut d,
        "control",
        vec![],
        vec![
            Instr::JumpIfNot {
                cond: bin(And, sig(high), sig(heater)),
                target: 4,
            },
            assign(heater, boolc(false), 0.0),
            report("off"),
            Instr::Jump(7),
            Instr::JumpIfNot {
                cond: bin(And, not(sig(low)), not(sig(heater))),
                target: 7,
            },
            assign(heater, boolc(true), 0.0),
            report("on"),
            wait_on(vec![high, low]),
            Instr::Jump(0),
        ],
    );
    d
}

/// reltol 1e-8: the integrator controls the error per step, and over the 51 s before the
/// first switch (about 100 steps at reltol 1e-7) the temperature drifts by 8e-5 K, which moves
/// the switch by 1.7e-5 relative; at 1e-8 the drift stays well inside the 1e-5 asked for.
fn thermostat_options() -> SimOptions {
    SimOptions {
        stop: 400.0,
        reltol: 1e-8,
        ..SimOptions::default()
    }
}

fn check_thermostat(r: &SimResult) {
    let first = TAU_ROOM * ((T_ON - T0) / (T_ON - T_HIGH)).ln();
    let cool = TAU_ROOM * ((T_HIGH - T_OFF) / (T_LOW - T_OFF)).ln();
    let heat = TAU_ROOM * ((T_ON - T_LOW) / (T_ON - T_HIGH)).ln();
    let (mut offs, mut ons) = (vec![first], Vec::new());
    loop {
        let on = offs.last().unwrap() + cool;
        let off = on + heat;
        if on < 400.0 {
            ons.push(on);
        }
        if off >= 400.0 {
            break;
        }
        offs.push(off);
    }
    for (message, expected) in [("off", &offs), ("on", &ons)] {
        let got = report_times(r, message);
        assert_eq!(
            got.len(),
            expected.len(),
            "{message}: {got:?} vs {expected:?}"
        );
        for (t, x) in got.iter().zip(expected.iter()) {
            assert!((t - x).abs() < 1e-5 * x, "{message} at {t}, analytic {x}");
        }
    }
    // Between switches the temperature stays inside the hysteresis band (to the tolerance).
    let w = &r.waveforms;
    let temp = &w.column("temp").expect("temp recorded").values;
    for (&t, &x) in w.times.iter().zip(temp) {
        if t > first {
            assert!(
                (T_LOW - 1e-3..=T_HIGH + 1e-3).contains(&x),
                "temp {x} at {t}"
            );
        }
    }
}

#[test]
fn thermostat_switches_at_the_analytic_times() {
    let d = thermostat_design();
    check_thermostat(&run_with(&d, &thermostat_options(), ExprDae::new(&d)));
}

#[test]
fn thermostat_switches_at_the_analytic_times_with_the_analog_system() {
    let d = thermostat_design();
    check_thermostat(&simulate(&d, &thermostat_options(), &mut |_| {}).expect("runs"));
}

// ---- Operating point and failures -----------------------------------------------------------

#[test]
fn the_operating_point_holds_the_initial_breaks() {
    let d = thermostat_design();
    let mut sim = Simulation::start(
        &d,
        &thermostat_options(),
        Some(ExprDae::new(&d)),
        &mut |_| {},
    )
    .expect("initialises");
    assert_eq!(
        sim.operating_point(),
        vec![("temp".to_string(), T0), ("heater".to_string(), 1.0)]
    );
}

/// `y'dot == y * y` from `y = 1` blows up at `t = 1`: the solver's failure names `y`.
#[test]
fn a_solver_failure_names_the_unknown_and_the_time() {
    let mut d = Design::default();
    let y = quantity(&mut d, "y");
    equation(&mut d, bin(Sub, dot(y), bin(Mul, q(y), q(y))));
    process(
        &mut d,
        "initial",
        vec![],
        vec![brk(vec![(y, real(1.0))]), Instr::Halt],
    );
    let options = SimOptions {
        stop: 2.0,
        ..SimOptions::default()
    };
    let mut waveforms = Waveforms::default();
    let recorder = Recorder::new(&d, &[], options.stop, &mut waveforms).expect("probes");
    let result = Simulation::start(&d, &options, Some(ExprDae::new(&d)), &mut |_| {})
        .and_then(|sim| sim.run(recorder, &mut |_| {}));
    match result {
        Err(crate::kernel::SimError::Solve { time, unknowns, .. }) => {
            assert!((0.9..=1.0).contains(&time), "failed at {time}");
            assert_eq!(unknowns, vec!["y".to_string()]);
        }
        other => panic!(
            "expected a solver failure, got {:?}",
            other.map(|r| r.outcome)
        ),
    }
}

/// A break that moves a quantity across a threshold is a crossing the integrator cannot see:
/// the `'above` signal must still change, at the break's time.
#[test]
fn a_break_across_a_threshold_changes_the_above_signal() {
    let mut d = Design::default();
    let x = quantity(&mut d, "x");
    equation(&mut d, bin(Sub, dot(x), real(1.0)));
    let over = above(&mut d, x, 3.0);
    process(
        &mut d,
        "initial",
        vec![],
        vec![brk(vec![(x, real(0.0))]), Instr::Halt],
    );
    process(
        &mut d,
        "jump",
        vec![],
        vec![wait_for(1.0), brk(vec![(x, real(5.0))]), Instr::Halt],
    );
    process(
        &mut d,
        "watch",
        vec![],
        vec![
            wait_until(sig(over), None),
            report("over"),
            wait_until(not(sig(over)), None),
            report("under"),
            Instr::Halt,
        ],
    );
    let options = SimOptions {
        stop: 2.0,
        ..SimOptions::default()
    };
    let r = run_with(&d, &options, ExprDae::new(&d));
    assert_eq!(report_times(&r, "over"), vec![1.0]);
    assert!(report_times(&r, "under").is_empty());
    let x_end = r.waveforms.value_at("x", 2.0).expect("x recorded");
    assert!((x_end - 6.0).abs() < 1e-9, "x(2) = {x_end}");
}
