//! Subprogram calls in the kernel: function frames, recursion, procedure frames that survive a
//! wait, `out` copy-back, drivers of signals assigned in procedures, and the depth limit.

use super::build::*;
use crate::kernel::{Outcome, SimError, SimOptions, SimResult, simulate};
use vams_design::{
    BinaryOp::*, Design, Expr, Instr, ParamMode, Subprogram, SubprogramId, SubprogramKind, Type,
    Value, VarId, Variable,
};
use vams_syntax::source::Span;

const MS: f64 = 1e-3;

fn run(design: &Design, stop: f64) -> Result<SimResult, SimError> {
    let options = SimOptions {
        stop,
        ..SimOptions::default()
    };
    simulate(design, &options, &mut |_| {})
}

fn int_var(name: &str) -> Variable {
    Variable {
        range: None,
        name: name.into(),
        ty: Type::Integer,
        init: Value::Integer(0),
    }
}

fn subprogram(
    d: &mut Design,
    kind: SubprogramKind,
    params: Vec<ParamMode>,
    code: Vec<Instr>,
) -> SubprogramId {
    let vars = (0..params.len().max(1))
        .map(|k| int_var(&format!("v{k}")))
        .collect();
    d.subprograms.push(Subprogram {
        spans: Vec::new(),
        name: format!("sub{}", d.subprograms.len()),
        kind,
        params,
        vars,
        code,
        span: Span::default(),
        intrinsic: None,
    });
    SubprogramId(d.subprograms.len() as u32 - 1)
}

fn call(sub: SubprogramId, args: Vec<Expr>) -> Expr {
    Expr::FnCall {
        sub,
        args,
        signals: vec![],
    }
}

/// `fact(n) = if n <= 1 then 1 else n * fact(n - 1)`.
fn factorial(d: &mut Design) -> SubprogramId {
    let id = SubprogramId(d.subprograms.len() as u32);
    subprogram(
        d,
        SubprogramKind::Function,
        vec![ParamMode::In],
        vec![
            Instr::JumpIfNot {
                cond: bin(Le, var(0), int(1)),
                target: 2,
            },
            Instr::Return(Some(int(1))),
            Instr::Return(Some(bin(
                Mul,
                var(0),
                call(id, vec![bin(Sub, var(0), int(1))]),
            ))),
        ],
    )
}

#[test]
fn a_recursive_function_computes_factorials() {
    let mut d = Design::default();
    let fact = factorial(&mut d);
    process(
        &mut d,
        "p",
        vec![("x", Type::Integer, Value::Integer(0))],
        vec![
            Instr::SetVar {
                var: VarId(0),
                value: call(fact, vec![int(12)]),
            },
            assert(Some(bin(Eq, var(0), int(479_001_600))), text("wrong"), 3),
            report("ok"),
            Instr::Halt,
        ],
    );
    let r = run(&d, 1.0).unwrap();
    assert_eq!(r.outcome, Outcome::Finished, "{:?}", r.reports);
    assert_eq!(r.reports.len(), 1, "{:?}", r.reports);
}

/// A procedure `(x : inout; y : out)` that waits 1 ms between `y := 2 * x` and `x := x + 1`:
/// the caller's variables change only when it returns.
#[test]
fn a_procedure_waits_and_copies_back_out_parameters() {
    let mut d = Design::default();
    let done = signal(&mut d, "done", Type::Boolean, Value::Boolean(false));
    let proc_id = subprogram(
        &mut d,
        SubprogramKind::Procedure,
        vec![ParamMode::InOut, ParamMode::Out],
        vec![
            Instr::SetVar {
                var: VarId(1),
                value: bin(Mul, int(2), var(0)),
            },
            assign(done, boolc(true), 0.0),
            wait_for(MS),
            Instr::SetVar {
                var: VarId(0),
                value: bin(Add, var(0), int(1)),
            },
            Instr::Return(None),
        ],
    );
    let caller_sees = |x: i64, y: i64| bin(And, bin(Eq, var(0), int(x)), bin(Eq, var(1), int(y)));
    process(
        &mut d,
        "caller",
        vec![
            ("x", Type::Integer, Value::Integer(5)),
            ("y", Type::Integer, Value::Integer(-1)),
        ],
        vec![
            Instr::Call {
                sub: proc_id,
                args: vec![var(0), int(0)],
                copy_back: vec![(VarId(0), VarId(0)), (VarId(1), VarId(1))],
                signals: vec![],
                span: Span::default(),
            },
            assert(Some(caller_sees(6, 10)), text("copy-back wrong"), 3),
            assert(Some(bin(Eq, Expr::Now, time(MS))), text("did not wait"), 3),
            assert(Some(sig(done)), text("no driver"), 3),
            report("ok"),
            Instr::Halt,
        ],
    );
    let r = run(&d, 1.0).unwrap();
    assert_eq!(r.outcome, Outcome::Finished, "{:?}", r.reports);
    assert_eq!(r.reports.len(), 1, "{:?}", r.reports);
    assert!((r.reports[0].time - MS).abs() < 1e-15);
}

#[test]
fn endless_recursion_stops_at_the_depth_limit() {
    let mut d = Design::default();
    // f(n) = f(n + 1) + 1
    let id = SubprogramId(0);
    subprogram(
        &mut d,
        SubprogramKind::Function,
        vec![ParamMode::In],
        vec![Instr::Return(Some(bin(
            Add,
            call(id, vec![bin(Add, var(0), int(1))]),
            int(1),
        )))],
    );
    process(
        &mut d,
        "deep",
        vec![("x", Type::Integer, Value::Integer(0))],
        vec![
            Instr::SetVar {
                var: VarId(0),
                value: call(id, vec![int(0)]),
            },
            Instr::Halt,
        ],
    );
    // Inside a 2 MiB thread, like a test or `vams test` worker: an error, not an overflow.
    let err = std::thread::Builder::new()
        .stack_size(2 << 20)
        .spawn(move || run(&d, 1.0).err())
        .unwrap()
        .join()
        .unwrap()
        .expect("the run fails");
    let text = err.to_string();
    assert!(text.contains("process `deep`"), "{text}");
    assert!(
        text.contains("more than 100 nested subprogram calls"),
        "{text}"
    );
}
