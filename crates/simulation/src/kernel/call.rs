//! Calls of user-defined subprograms: the frame of a call and the function interpreter.
//!
//! A function runs to its `Return` inside the evaluation of the expression that calls it (it
//! never waits), in a fresh frame of its own; nested calls go one level deeper, and a chain of
//! more than [`MAX_CALL_DEPTH`] calls is a run-time error, not a stack overflow. Procedures run
//! in the process interpreter, which keeps their frames on the process's call stack so that a
//! `wait` inside one suspends them all (`kernel::process`).

use vams_design::{Expr, Instr, Subprogram, SubprogramId, Value};

use super::Severity;
use super::eval::{Env, EvalError, eval, integer, set_element, truth};
use super::io::FunctionReport;
use super::process::INSTRUCTION_LIMIT;

/// The deepest chain of subprogram calls (function calls nested in expressions plus procedure
/// frames of one process) on a thread that did not set its own limit. A nested function call
/// recurses in the interpreter: measured about 1.7 KB of stack per level in a release build
/// and 15 KB in a debug build (`return f(n + 1) + 1;`), so 100 levels stay inside the 2 MiB
/// of an ordinary thread either way.
pub(crate) const MAX_CALL_DEPTH: usize = 100;

/// The deepest chain on a thread with [`DEEP_STACK`] bytes of stack, as the command line's
/// threads have: ordinary recursion (a factorial of 1000, a walk down a long list) fits, at
/// 150 MB of stack in a debug build.
pub const DEEP_CALL_DEPTH: usize = 10_000;

/// The stack of a thread that runs simulations with [`DEEP_CALL_DEPTH`] (address space only:
/// the pages a run does not touch cost nothing).
pub const DEEP_STACK: usize = 1 << 30;

thread_local! {
    static CALL_DEPTH: std::cell::Cell<usize> = const { std::cell::Cell::new(MAX_CALL_DEPTH) };
}

/// Lets simulations on this thread nest `depth` calls; the thread's stack must hold them (see
/// [`DEEP_STACK`]).
pub fn set_call_depth_limit(depth: usize) {
    CALL_DEPTH.with(|c| c.set(depth));
}

/// The call depth allowed on this thread.
pub(crate) fn call_depth_limit() -> usize {
    CALL_DEPTH.with(|c| c.get())
}

/// The error for a call one level too deep.
pub(crate) fn too_deep(name: &str) -> EvalError {
    let limit = call_depth_limit();
    EvalError::new(
        format!("more than {limit} nested subprogram calls (calling `{name}`)"),
        "a recursive subprogram must reach a case that does not call itself (the command line \
         allows 10 000 nested calls, a program calling the library 100 unless its thread sets \
         more)",
    )
}

/// The initial frame of a call of `sub`: the argument values, then the locals' initial values.
pub(crate) fn frame(sub: &Subprogram, args: Vec<Value>) -> Vec<Value> {
    let mut vars = args;
    vars.extend(sub.vars[vars.len()..].iter().map(|v| v.init.clone()));
    vars
}

/// Runs function `id` on `args` (evaluated in `env`) and returns its result.
pub(crate) fn call_function(
    id: SubprogramId,
    args: &[Expr],
    env: &Env,
) -> Result<Value, EvalError> {
    let Some(sub) = env.subprograms.get(id.index()) else {
        return Err(EvalError::new(
            "a call of a subprogram the design does not have",
            "this is a bug in elaboration",
        ));
    };
    if env.depth >= call_depth_limit() {
        return Err(too_deep(&sub.name));
    }
    let values = args
        .iter()
        .map(|a| eval(a, env))
        .collect::<Result<Vec<_>, _>>()?;
    let mut vars = frame(sub, values);
    let mut pc = 0;
    for step in 0..INSTRUCTION_LIMIT {
        env.io.check_cancel(step)?;
        let inner = Env {
            vars: &vars,
            depth: env.depth + 1,
            ..*env
        };
        let Some(instr) = sub.code.get(pc) else {
            return Err(no_return(sub));
        };
        pc += 1;
        match instr {
            Instr::SetVar { var, value } => {
                let v = super::fast::value(value, &inner)?;
                vars[var.index()] = v;
            }
            Instr::SetVarElement { var, index, value } => {
                let i = integer(&eval(index, &inner)?)?;
                let v = eval(value, &inner)?;
                let ty = &sub.vars[var.index()].ty;
                set_element(&mut vars[var.index()], ty, i, v)?;
            }
            Instr::SetHeap { pointer, value } => super::textio::set_heap(pointer, value, &inner)?,
            Instr::Native {
                op,
                args,
                copy_back,
                ..
            } => {
                for (var, v) in super::textio::call(op, args, copy_back, &inner)? {
                    vars[var.index()] = v;
                }
            }
            Instr::Jump(target) => pc = *target,
            Instr::JumpIfNot { cond, target } => {
                if !super::fast::condition(cond, &inner)? {
                    pc = *target;
                }
            }
            Instr::Return(Some(e)) => return super::fast::value(e, &inner),
            Instr::Return(None) => return Err(no_return(sub)),
            Instr::Assert {
                cond,
                report,
                severity,
                span,
            } => {
                if let Some(c) = cond {
                    if truth(&eval(c, &inner)?)? {
                        continue;
                    }
                }
                function_report(sub, report.as_ref(), severity, *span, &inner)?;
            }
            Instr::Call { .. }
            | Instr::Assign { .. }
            | Instr::Wait { .. }
            | Instr::Break { .. }
            | Instr::Stop
            | Instr::Halt => {
                return Err(EvalError::new(
                    format!(
                        "function `{}` executed a statement functions cannot have",
                        sub.name
                    ),
                    "functions cannot wait, assign signals or call procedures (LRM 4.2)",
                ));
            }
        }
    }
    Err(EvalError::new(
        format!(
            "function `{}` ran {INSTRUCTION_LIMIT} instructions without returning",
            sub.name
        ),
        "check the function's loops: every path must reach a return",
    ))
}

/// A report (or failed assertion) of `sub`: queued for the calling process to tell, or an
/// error for severity failure. Kept out of `call_function`, whose frame every nested call
/// adds to the stack (a debug build's frames must stay under 20 KB per level).
#[inline(never)]
fn function_report(
    sub: &Subprogram,
    report: Option<&Expr>,
    severity: &Expr,
    span: vams_syntax::source::Span,
    env: &Env,
) -> Result<(), EvalError> {
    let (message, severity) = assertion_report(report, severity, env)?;
    if severity == Severity::Failure {
        return Err(EvalError::new(
            format!("failure reported in function `{}`: {message}", sub.name),
            "an assertion of severity failure stops the simulation",
        ));
    }
    // Told by the process that evaluated the call, in order with its own reports.
    (env.io.function_reports.borrow_mut()).push(FunctionReport {
        severity,
        message,
        span,
    });
    Ok(())
}

/// The message and severity of a failed assertion or a `report` (`Assertion violation.`
/// without a message; positions of `severity_level` from note), in a process or a function.
pub(crate) fn assertion_report(
    report: Option<&Expr>,
    severity: &Expr,
    env: &Env,
) -> Result<(String, Severity), EvalError> {
    let message = match report {
        Some(r) => match eval(r, env)? {
            Value::String(s) => s,
            other => format!("{other:?}"),
        },
        None => "Assertion violation.".to_string(),
    };
    let severity = match eval(severity, env)? {
        Value::Enum(0) => Severity::Note,
        Value::Enum(1) => Severity::Warning,
        Value::Enum(2) => Severity::Error,
        _ => Severity::Failure,
    };
    Ok((message, severity))
}

fn no_return(sub: &Subprogram) -> EvalError {
    EvalError::new(
        format!("function `{}` ended without a return statement", sub.name),
        "every path through a function must end in `return value;` (LRM 10.13)",
    )
}
