//! The event kernel on designs without quantities.

use super::build::*;
use crate::kernel::{Outcome, Severity, SimError, SimOptions, SimResult, simulate};
use vams_design::{BinaryOp::*, DelayMechanism, Design, Expr, Instr, Type, Value};

const NS: f64 = 1e-9;

fn run(design: &Design, stop: f64) -> Result<SimResult, SimError> {
    let options = SimOptions {
        stop,
        ..SimOptions::default()
    };
    simulate(design, &options, &mut |_| {})
}

fn times(result: &SimResult, message: &str) -> Vec<f64> {
    result
        .reports
        .iter()
        .filter(|r| r.message == message)
        .map(|r| r.time)
        .collect()
}

/// `b <= a; c <= b;` and a stimulus checking each delta cycle.
#[test]
fn a_chain_of_assignments_updates_one_delta_apart() {
    let mut d = Design::default();
    let a = signal(&mut d, "a", Type::Integer, Value::Integer(0));
    let b = signal(&mut d, "b", Type::Integer, Value::Integer(0));
    let c = signal(&mut d, "c", Type::Integer, Value::Integer(0));
    for (name, from, to) in [("p_b", a, b), ("p_c", b, c)] {
        process(
            &mut d,
            name,
            vec![],
            vec![
                assign(to, sig(from), 0.0),
                wait_on(vec![from]),
                Instr::Jump(0),
            ],
        );
    }
    let is = |s, v| bin(Eq, sig(s), int(v));
    let all = |x: Vec<Expr>| x.into_iter().reduce(|p, q| bin(And, p, q)).unwrap();
    process(
        &mut d,
        "stim",
        vec![],
        vec![
            assign(a, int(1), 0.0),
            wait_for(0.0),
            assert(Some(all(vec![is(a, 1), is(b, 0), is(c, 0)])), text("d1"), 3),
            wait_for(0.0),
            assert(Some(all(vec![is(b, 1), is(c, 0)])), text("d2"), 3),
            wait_for(0.0),
            assert(Some(is(c, 1)), text("d3"), 3),
            assert(Some(bin(Eq, Expr::Now, time(0.0))), text("time moved"), 3),
            report("done"),
            Instr::Halt,
        ],
    );
    let r = run(&d, 1e-6).unwrap();
    assert_eq!(r.outcome, Outcome::Finished, "{:?}", r.reports);
    assert_eq!(times(&r, "done"), vec![0.0]);
    assert_eq!(r.stats.delta_cycles, 3);
}

/// A clock toggling every 5 ns and a process counting rising edges with `wait until`.
#[test]
fn a_clock_with_wait_for_and_an_edge_counter() {
    let mut d = Design::default();
    let clk = signal(&mut d, "clk", boolean(), Value::Boolean(false));
    process(
        &mut d,
        "clock",
        vec![],
        vec![
            assign(clk, not(sig(clk)), 0.0),
            wait_for(5.0 * NS),
            Instr::Jump(0),
        ],
    );
    let count = bin(Add, var(0), int(1));
    process(
        &mut d,
        "edges",
        vec![("n", Type::Integer, Value::Integer(0))],
        vec![
            wait_until(sig(clk), None),
            Instr::SetVar {
                var: vams_design::VarId(0),
                value: count,
            },
            assert(
                None,
                bin(
                    Concat,
                    text("edge "),
                    Expr::Image(Type::Integer, Box::new(var(0))),
                ),
                0,
            ),
            Instr::Jump(0),
        ],
    );
    let r = run(&d, 42.0 * NS).unwrap();
    let edges: Vec<(f64, String)> = r
        .reports
        .iter()
        .map(|r| (r.time, r.message.clone()))
        .collect();
    assert_eq!(edges.len(), 5, "{edges:?}");
    for (k, (t, m)) in edges.iter().enumerate() {
        assert!((t - 10.0 * NS * k as f64).abs() < 1e-18, "edge {k} at {t}");
        assert_eq!(m, &format!("edge {}", k + 1));
    }
    // Each toggle is recorded as a before/after pair at the same time.
    let w = &r.waveforms;
    assert_eq!(w.value_at("clk", 7.0 * NS), Some(0.0));
    assert_eq!(w.value_at("clk", 12.0 * NS), Some(1.0));
    let at5: Vec<f64> = w
        .times
        .iter()
        .zip(&w.column("clk").unwrap().values)
        .filter(|(t, _)| (**t - 5.0 * NS).abs() < 1e-18)
        .map(|(_, v)| *v)
        .collect();
    assert_eq!(at5, vec![1.0, 0.0]);
}

/// A 2 ns pulse on `a`, delayed by 5 ns three ways.
fn pulse_design() -> Design {
    let mut d = Design::default();
    let a = signal(&mut d, "a", boolean(), Value::Boolean(false));
    let inertial = signal(&mut d, "inertial", boolean(), Value::Boolean(false));
    let transported = signal(&mut d, "transported", boolean(), Value::Boolean(false));
    let reject1 = signal(&mut d, "reject1", boolean(), Value::Boolean(false));
    process(
        &mut d,
        "stim",
        vec![],
        vec![
            wait_for(10.0 * NS),
            assign(a, boolc(true), 0.0),
            wait_for(2.0 * NS),
            assign(a, boolc(false), 0.0),
            Instr::Halt,
        ],
    );
    process(
        &mut d,
        "p_inertial",
        vec![],
        vec![
            assign(inertial, sig(a), 5.0 * NS),
            wait_on(vec![a]),
            Instr::Jump(0),
        ],
    );
    process(
        &mut d,
        "p_transport",
        vec![],
        vec![
            transport(transported, sig(a), 5.0 * NS),
            wait_on(vec![a]),
            Instr::Jump(0),
        ],
    );
    process(
        &mut d,
        "p_reject",
        vec![],
        vec![
            Instr::Assign {
                index: None,
                target: reject1,
                waveform: vec![(Some(sig(a)), time(5.0 * NS))],
                mechanism: DelayMechanism::Inertial {
                    reject: Some(time(1.0 * NS)),
                },
            },
            wait_on(vec![a]),
            Instr::Jump(0),
        ],
    );
    d
}

#[test]
fn inertial_delay_swallows_a_short_pulse_and_transport_keeps_it() {
    let r = run(&pulse_design(), 30.0 * NS).unwrap();
    let w = &r.waveforms;
    let high = |name: &str| {
        let col = w.column(name).unwrap();
        let ts: Vec<f64> = w
            .times
            .iter()
            .zip(&col.values)
            .filter(|(_, v)| **v == 1.0)
            .map(|(t, _)| *t)
            .collect();
        ts
    };
    assert!(high("inertial").is_empty(), "{:?}", high("inertial"));
    for name in ["transported", "reject1"] {
        let h = high(name);
        assert!(!h.is_empty(), "{name} never went high");
        assert!((h[0] - 15.0 * NS).abs() < 1e-18, "{name} rose at {}", h[0]);
        assert!(
            (h.last().unwrap() - 17.0 * NS).abs() < 1e-18,
            "{name} fell after {h:?}"
        );
    }
    assert_eq!(w.value_at("transported", 20.0 * NS), Some(0.0));
}

/// `wait until s for 10 ns` resumes on the condition, or at the timeout.
#[test]
fn wait_until_with_a_timeout() {
    let mut d = Design::default();
    let s = signal(&mut d, "s", boolean(), Value::Boolean(false));
    let never = signal(&mut d, "never", boolean(), Value::Boolean(false));
    process(
        &mut d,
        "stim",
        vec![],
        vec![assign(s, boolc(true), 3.0 * NS), Instr::Halt],
    );
    process(
        &mut d,
        "waiter",
        vec![],
        vec![
            wait_until(sig(s), Some(10.0 * NS)),
            report("first"),
            wait_until(sig(never), Some(10.0 * NS)),
            report("second"),
            Instr::Halt,
        ],
    );
    // `never` has a driver that never changes it, so its process must not be mistaken for one.
    process(
        &mut d,
        "idle",
        vec![],
        vec![assign(never, boolc(false), 0.0), Instr::Halt],
    );
    let r = run(&d, 100.0 * NS).unwrap();
    let first = times(&r, "first");
    let second = times(&r, "second");
    assert_eq!(first.len(), 1);
    assert!((first[0] - 3.0 * NS).abs() < 1e-18);
    assert_eq!(second.len(), 1);
    assert!((second[0] - 13.0 * NS).abs() < 1e-18);
}

#[test]
fn two_drivers_of_a_std_logic_signal_are_resolved() {
    let (zero, one, z, x) = (2, 3, 4, 1);
    let mut d = Design::default();
    let bus = signal(&mut d, "bus", std_logic(), Value::Enum(0));
    let e = |p| Expr::Const(Value::Enum(p));
    process(
        &mut d,
        "drive_low",
        vec![],
        vec![
            assign(bus, e(zero), 0.0),
            wait_for(5.0 * NS),
            assign(bus, e(z), 0.0),
            Instr::Halt,
        ],
    );
    process(
        &mut d,
        "drive_high",
        vec![],
        vec![assign(bus, e(one), 0.0), Instr::Halt],
    );
    let r = run(&d, 10.0 * NS).unwrap();
    assert_eq!(r.waveforms.value_at("bus", 1.0 * NS), Some(x as f64));
    assert_eq!(r.waveforms.value_at("bus", 6.0 * NS), Some(one as f64));
}

#[test]
fn two_drivers_of_an_unresolved_signal_are_an_error() {
    let mut d = Design::default();
    let n = signal(&mut d, "n", Type::Integer, Value::Integer(0));
    process(
        &mut d,
        "p1",
        vec![],
        vec![assign(n, int(1), 0.0), Instr::Halt],
    );
    process(
        &mut d,
        "p2",
        vec![],
        vec![assign(n, int(2), 0.0), Instr::Halt],
    );
    match run(&d, 1.0) {
        Err(SimError::MultipleDrivers {
            signal,
            count,
            processes,
            ..
        }) => {
            assert_eq!((signal.as_str(), count), ("n", 2));
            assert_eq!(processes, "p1, p2");
        }
        other => panic!("expected a multiple-driver error, got {other:?}"),
    }
}

#[test]
fn severities_are_kept_and_failure_ends_the_run() {
    let mut d = Design::default();
    process(
        &mut d,
        "checks",
        vec![],
        vec![
            assert(Some(boolc(false)), text("a note"), 0),
            assert(Some(boolc(true)), text("not reported"), 3),
            wait_for(1e-3),
            assert(Some(boolc(false)), text("a warning"), 1),
            assert(Some(boolc(false)), text("an error"), 2),
            wait_for(1e-3),
            assert(Some(boolc(false)), text("the end"), 3),
            report("after the end"),
            Instr::Halt,
        ],
    );
    let mut live = Vec::new();
    let r = simulate(&d, &SimOptions::default(), &mut |r| {
        live.push(r.message.clone())
    })
    .unwrap();
    let got: Vec<(Severity, &str, f64)> = r
        .reports
        .iter()
        .map(|r| (r.severity, r.message.as_str(), r.time))
        .collect();
    assert_eq!(
        got,
        vec![
            (Severity::Note, "a note", 0.0),
            (Severity::Warning, "a warning", 1e-3),
            (Severity::Error, "an error", 1e-3),
            (Severity::Failure, "the end", 2e-3),
        ]
    );
    assert_eq!(live.len(), 4);
    assert_eq!(r.outcome, Outcome::Failed { time: 2e-3 });
    assert_eq!(r.reports[0].process, "checks");
}

#[test]
fn stop_ends_the_run_cleanly() {
    let mut d = Design::default();
    let n = signal(&mut d, "n", Type::Integer, Value::Integer(0));
    process(
        &mut d,
        "count",
        vec![],
        vec![
            assign(n, bin(Add, sig(n), int(1)), 0.0),
            wait_for(1e-3),
            Instr::JumpIfNot {
                cond: bin(Ge, sig(n), int(3)),
                target: 0,
            },
            Instr::Stop,
        ],
    );
    let r = run(&d, 1.0).unwrap();
    assert_eq!(r.outcome, Outcome::Stopped { time: 3e-3 });
    assert_eq!(r.waveforms.times.last(), Some(&3e-3));
    assert_eq!(r.waveforms.value_at("n", 1.0), Some(3.0));
}

#[test]
fn zero_delay_oscillation_hits_the_delta_limit() {
    let mut d = Design::default();
    let a = signal(&mut d, "a", boolean(), Value::Boolean(false));
    process(
        &mut d,
        "osc",
        vec![],
        vec![
            assign(a, not(sig(a)), 0.0),
            wait_on(vec![a]),
            Instr::Jump(0),
        ],
    );
    match run(&d, 1.0) {
        Err(SimError::DeltaLimit { process, time, .. }) => {
            assert_eq!(process, "osc");
            assert_eq!(time, 0.0);
        }
        other => panic!("expected the delta limit, got {other:?}"),
    }
}

#[test]
fn an_index_out_of_bounds_names_the_process() {
    let mut d = Design::default();
    let ty = Type::Array {
        element: Box::new(Type::Integer),
        left: 0,
        right: 3,
        ascending: true,
    };
    let array = Value::Array(vec![Value::Integer(0); 4]);
    process(
        &mut d,
        "indexer",
        vec![("a", ty, array)],
        vec![
            wait_for(1e-3),
            Instr::SetVarElement {
                var: vams_design::VarId(0),
                index: int(4),
                value: int(1),
            },
            Instr::Halt,
        ],
    );
    match run(&d, 1.0) {
        Err(SimError::Runtime {
            process,
            time,
            message,
            ..
        }) => {
            assert_eq!(process, "indexer");
            assert_eq!(time, 1e-3);
            assert!(message.contains("index 4"), "{message}");
        }
        other => panic!("expected a run-time error, got {other:?}"),
    }
}

#[test]
fn unknown_probes_suggest_a_near_name() {
    let mut d = Design::default();
    signal(&mut d, "speed", Type::Real, Value::Real(0.0));
    let options = SimOptions {
        probes: vec!["sped".into()],
        ..SimOptions::default()
    };
    match simulate(&d, &options, &mut |_| {}) {
        Err(SimError::UnknownProbe { name, help }) => {
            assert_eq!(name, "sped");
            assert_eq!(help, "did you mean `speed`?");
        }
        other => panic!("expected an unknown probe, got {other:?}"),
    }
}

#[test]
fn a_process_that_never_waits_is_stopped() {
    let mut d = Design::default();
    process(&mut d, "spin", vec![], vec![Instr::Jump(0)]);
    match run(&d, 1.0) {
        Err(SimError::Runaway { process, .. }) => assert_eq!(process, "spin"),
        other => panic!("expected a runaway process, got {other:?}"),
    }
}

#[test]
fn unusable_options_are_rejected() {
    let d = Design::default();
    for options in [
        SimOptions {
            stop: f64::NAN,
            ..SimOptions::default()
        },
        SimOptions {
            reltol: 0.0,
            ..SimOptions::default()
        },
        SimOptions {
            abstol: Some(-1.0),
            ..SimOptions::default()
        },
        SimOptions {
            max_step: Some(0.0),
            ..SimOptions::default()
        },
    ] {
        let r = simulate(&d, &options, &mut |_| {});
        assert!(matches!(r, Err(SimError::BadOption { .. })), "{options:?}");
    }
}
