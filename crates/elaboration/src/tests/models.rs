//! The headlight models of `models/`: elaborated whole, with concrete facts checked.

use std::path::Path;

use crate::{ElabOptions, elaborate, find_tops};
use vams_design::{BinaryOp, Design, Expr, Instr, QuantityKind, SignalKind, Value};
use vams_syntax::diagnostics::render_plain;

use super::parse_all;

fn models() -> Vec<(String, String)> {
    let dir = Path::new(env!("CARGO_MANIFEST_DIR")).join("../../models");
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .expect("models directory")
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|e| e == "vhd"))
        .map(|p| {
            (
                p.display().to_string(),
                std::fs::read_to_string(&p).expect("model text"),
            )
        })
        .collect();
    out.sort();
    out
}

fn elab(top: &str, generics: &[(&str, &str)]) -> Design {
    let m = models();
    let user: Vec<(&str, &str)> = m.iter().map(|(a, b)| (a.as_str(), b.as_str())).collect();
    let (sources, files) = parse_all(&user);
    let options = ElabOptions {
        top: top.into(),
        generics: generics
            .iter()
            .map(|(a, b)| (a.to_string(), b.to_string()))
            .collect(),
    };
    match elaborate(&sources, &files, &options) {
        Ok(d) => d,
        Err(errors) => {
            let text: Vec<String> = errors.iter().map(|e| render_plain(e, &sources)).collect();
            panic!("elaboration of {top} failed:\n{}", text.join("\n"));
        }
    }
}

fn quantity(d: &Design, name: &str) -> usize {
    d.quantities
        .iter()
        .position(|q| q.name == name)
        .unwrap_or_else(|| {
            let names: Vec<&str> = d.quantities.iter().map(|q| q.name.as_str()).collect();
            panic!("no quantity {name}; have {names:?}")
        })
}

#[test]
fn tracking_bench_elaborates() {
    let d = elab("tb_tracking", &[]);
    assert_eq!(d.top, "tb_tracking");
    for q in [
        "vref",
        "vfb",
        "v_motor",
        "i_motor",
        "dut.u_motor.w",
        "dut.u_motor.i",
        "dut.u_ic.e",
    ] {
        quantity(&d, q);
    }
    // i_motor is a quantity port of headlight_system: an alias, not a copy.
    assert!(!d.quantities.iter().any(|q| q.name == "dut.i_motor"));
    let i = &d.quantities[quantity(&d, "dut.u_motor.i")];
    assert_eq!(&*i.subtype, "current");
    assert_eq!(i.unit.as_deref(), Some("A"));
    assert_eq!(i.tolerance.as_deref(), Some("DEFAULT_CURRENT"));
    assert!(matches!(i.kind, QuantityKind::Through { .. }));
    let w = &d.quantities[quantity(&d, "dut.u_motor.w")];
    assert_eq!(w.unit.as_deref(), Some("rad/s"));
    assert!(d.signals.iter().any(|s| s.name == "ov"));
}

#[test]
fn overvoltage_bench_elaborates() {
    let d = elab("tb_overvoltage", &[]);
    quantity(&d, "v_supply");
    let battery = d
        .processes
        .iter()
        .find(|p| p.name == "dut.u_battery.profile")
        .expect("battery profile process");
    assert!(battery.vars.iter().any(|v| v.name == "v_prev"));
}

/// The equation of `instance` whose text starts with `text`.
fn equation<'d>(d: &'d Design, instance: &str, text: &str) -> &'d Expr {
    &d.equations
        .iter()
        .find(|e| e.instance == instance && e.text.starts_with(text))
        .unwrap_or_else(|| panic!("no equation `{text}` in {instance}"))
        .residual
}

/// The constant factor of `r * i` in the motor's voltage equation
/// `v - ((ke * w + r * i) + l * i'dot)`.
fn motor_r(d: &Design) -> f64 {
    let i = quantity(d, "dut.u_motor.i");
    let mut found = None;
    equation(d, "dut.u_motor", "v == ke * w").visit(&mut |e| {
        if let Expr::Binary(BinaryOp::Mul, a, b) = e {
            if let (Expr::Const(Value::Real(r)), Expr::Quantity(q)) = (&**a, &**b) {
                if q.index() == i {
                    found = Some(*r);
                }
            }
        }
    });
    found.expect("r * i in the motor equation")
}

#[test]
fn equations_balance_the_unknowns() {
    for top in ["tb_tracking", "tb_overvoltage"] {
        let d = elab(top, &[]);
        // Across quantities are fixed by terminal potentials; every through and free quantity
        // needs one simultaneous equation.
        let unknowns = d
            .quantities
            .iter()
            .filter(|q| !matches!(q.kind, QuantityKind::Across { .. }))
            .count();
        assert_eq!(d.equations.len(), unknowns, "{top}");
        assert_eq!(d.equations.len(), 35, "{top}");
        assert!(d.equations.iter().all(|e| e.residual.is_analog()));
    }
}

#[test]
fn generics_propagate_and_can_be_overridden() {
    let d = elab("tb_tracking", &[]);
    assert_eq!(motor_r(&d), 4.0);
    let d = elab("tb_tracking", &[("r", "5.0")]);
    assert_eq!(motor_r(&d), 5.0);
    // tcst = tcst_motor + tcst_system folds to one constant in the friction equation.
    let d = elab("tb_tracking", &[("tcst_motor", "1.0e-3")]);
    let friction = equation(&d, "dut.u_friction", "t == tcst");
    let mut consts = Vec::new();
    friction.visit(&mut |e| {
        if let Expr::Const(Value::Real(x)) = e {
            consts.push(*x);
        }
    });
    assert!(consts.contains(&(1.0e-3 + 2.0e-3)), "{consts:?}");
}

#[test]
fn the_ic_has_its_above_signals_and_processes() {
    let d = elab("tb_tracking", &[]);
    let above: Vec<&str> = d
        .signals
        .iter()
        .filter(|s| matches!(s.kind, SignalKind::Above { .. }))
        .map(|s| s.name.as_str())
        .collect();
    assert_eq!(
        above,
        [
            "dut.u_ic.e'above(0.15)",
            "dut.u_ic.e'above(0.1)",
            "dut.u_ic.e'above(-0.1)",
            "dut.u_ic.e'above(-0.15)",
            "dut.u_ic.v_s'above(18.1)",
            "dut.u_ic.v_s'above(17.5)",
        ]
    );
    let direction = d
        .processes
        .iter()
        .find(|p| p.name == "dut.u_ic.direction")
        .expect("direction process");
    match &direction.code[direction.code.len() - 2] {
        Instr::Wait { on, .. } => assert_eq!(on.len(), 4),
        other => panic!("expected the sensitivity wait, found {other:?}"),
    }
    // `ov <= ov_state;` drives the testbench's signal through the port: the same SignalId.
    let ov = d.signals.iter().position(|s| s.name == "ov").expect("ov");
    let assigns_ov = d.processes.iter().any(|p| {
        p.name.starts_with("dut.u_ic._p")
            && p.code
                .iter()
                .any(|i| matches!(i, Instr::Assign { target, .. } if target.index() == ov))
    });
    assert!(assigns_ov);
}

#[test]
fn processes_keep_exact_times_and_jump_targets() {
    let d = elab("tb_tracking", &[]);
    let check = d
        .processes
        .iter()
        .find(|p| p.name == "check")
        .expect("check process");
    assert!(
        matches!(&check.code[1], Instr::Wait { timeout: Some(Expr::Const(Value::Time(t))), .. } if *t == 0.6)
    );
    for p in &d.processes {
        for i in &p.code {
            if let Instr::Jump(t) | Instr::JumpIfNot { target: t, .. } = i {
                assert!(*t < p.code.len(), "{}: jump to {t}", p.name);
            }
        }
        assert!(
            matches!(p.code.last(), Some(Instr::Jump(0) | Instr::Halt)),
            "{}",
            p.name
        );
    }
}

#[test]
fn overvoltage_monitors_wait_on_above_signals() {
    let d = elab("tb_overvoltage", &[]);
    let monitor = d
        .processes
        .iter()
        .find(|p| p.name == "monitor_high")
        .expect("monitor_high");
    let Instr::Wait {
        on, until: Some(_), ..
    } = &monitor.code[0]
    else {
        panic!("expected wait until, found {:?}", monitor.code[0]);
    };
    assert_eq!(d.signals[on[0].index()].name, "v_supply'above(18.15)");
}

#[test]
fn tops_are_the_testbenches() {
    let m = models();
    let user: Vec<(&str, &str)> = m.iter().map(|(a, b)| (a.as_str(), b.as_str())).collect();
    let (sources, files) = parse_all(&user);
    assert_eq!(
        find_tops(&vams_semantics::analysis::analyse(&sources, &files), &files),
        ["tb_overvoltage", "tb_position_loop", "tb_tracking"]
    );
}

#[test]
fn elaboration_is_fast() {
    let m = models();
    let user: Vec<(&str, &str)> = m.iter().map(|(a, b)| (a.as_str(), b.as_str())).collect();
    let (sources, files) = parse_all(&user);
    let options = ElabOptions {
        top: "tb_tracking".into(),
        generics: Vec::new(),
    };
    let start = std::time::Instant::now();
    for _ in 0..5 {
        assert!(elaborate(&sources, &files, &options).is_ok());
    }
    // A few milliseconds each in release; generous for unoptimised test builds.
    assert!(
        start.elapsed().as_secs_f64() / 5.0 < 0.5,
        "{:?}",
        start.elapsed()
    );
}
