//! Small constructors for hand-built designs.

use vams_design::{
    BinaryOp, DelayMechanism, Design, Expr, Instr, Process, Signal, SignalId, SignalKind, Type,
    Value, VarId, Variable,
};
use vams_syntax::source::Span;

pub fn boolean() -> Type {
    Type::Boolean
}

pub fn std_logic() -> Type {
    Type::Enum {
        name: "std_ulogic".into(),
        literals: [
            "'U'", "'X'", "'0'", "'1'", "'Z'", "'W'", "'L'", "'H'", "'-'",
        ]
        .iter()
        .map(|s| s.to_string())
        .collect(),
    }
}

/// Adds an explicit signal and returns its id.
pub fn signal(d: &mut Design, name: &str, ty: Type, init: Value) -> SignalId {
    d.signals.push(Signal {
        range: None,
        name: name.into(),
        ty,
        init,
        kind: SignalKind::Explicit,
        span: Span::default(),
        resolution: None,
        guarded: None,
    });
    SignalId(d.signals.len() as u32 - 1)
}

pub fn process(d: &mut Design, name: &str, vars: Vec<(&str, Type, Value)>, code: Vec<Instr>) {
    d.processes.push(Process {
        spans: Vec::new(),
        name: name.into(),
        vars: vars
            .into_iter()
            .map(|(n, ty, init)| Variable {
                range: None,
                name: n.into(),
                ty,
                init,
            })
            .collect(),
        code,
        span: Span::default(),
        driver_inits: Vec::new(),
    });
}

pub fn sig(s: SignalId) -> Expr {
    Expr::Signal(s)
}

pub fn var(v: u32) -> Expr {
    Expr::Var(VarId(v))
}

pub fn int(i: i64) -> Expr {
    Expr::Const(Value::Integer(i))
}

pub fn boolc(b: bool) -> Expr {
    Expr::Const(Value::Boolean(b))
}

pub fn time(t: f64) -> Expr {
    Expr::Const(Value::Time(t))
}

pub fn text(s: &str) -> Expr {
    Expr::Const(Value::String(s.into()))
}

pub fn bin(op: BinaryOp, a: Expr, b: Expr) -> Expr {
    Expr::Binary(op, Box::new(a), Box::new(b))
}

pub fn not(a: Expr) -> Expr {
    Expr::Unary(vams_design::UnaryOp::Not, Box::new(a))
}

/// `target <= value after delay` (inertial, the delay as the rejection limit).
pub fn assign(target: SignalId, value: Expr, delay: f64) -> Instr {
    Instr::Assign {
        index: None,
        target,
        waveform: vec![(Some(value), time(delay))],
        mechanism: DelayMechanism::Inertial { reject: None },
    }
}

pub fn transport(target: SignalId, value: Expr, delay: f64) -> Instr {
    Instr::Assign {
        index: None,
        target,
        waveform: vec![(Some(value), time(delay))],
        mechanism: DelayMechanism::Transport,
    }
}

pub fn wait_for(t: f64) -> Instr {
    Instr::Wait {
        on: vec![],
        until: None,
        timeout: Some(time(t)),
    }
}

pub fn wait_on(on: Vec<SignalId>) -> Instr {
    Instr::Wait {
        on,
        until: None,
        timeout: None,
    }
}

pub fn wait_until(cond: Expr, timeout: Option<f64>) -> Instr {
    Instr::Wait {
        on: vec![],
        until: Some(cond),
        timeout: timeout.map(time),
    }
}

/// `assert cond report msg severity sev` (`cond` `None`: a plain report).
pub fn assert(cond: Option<Expr>, msg: Expr, severity: u32) -> Instr {
    Instr::Assert {
        cond,
        report: Some(msg),
        severity: Expr::Const(Value::Enum(severity)),
        span: Span::default(),
    }
}

pub fn report(msg: &str) -> Instr {
    assert(None, text(msg), 0)
}
