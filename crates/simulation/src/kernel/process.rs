//! The process interpreter: runs a lowered [`Process`] from its resume point to the next wait.

use vams_design::{
    DelayMechanism, Expr, Instr, Process, QuantityId, SignalId, Subprogram, SubprogramId, Value,
    Variable,
};
use vams_syntax::source::Span;

use super::call::{assertion_report, call_depth_limit, frame, too_deep};
use super::error::SimError;
use super::eval::{Env, EvalError, eval, integer, offset, set_element, truth};
use super::lower::{Flow, Op};
use super::signals::{Delay, Signals};
use super::{Report, Severity};

/// Instructions one activation may execute before it counts as a loop without a wait.
pub(crate) const INSTRUCTION_LIMIT: usize = 10_000_000;

/// How an activation ended.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Suspend {
    /// At a `Wait`; the process state says on what.
    Wait,
    /// `wait;` or `Halt`: never again.
    Halt,
    /// `std.env.stop`.
    Stop,
    /// An assertion of severity failure.
    Failure,
}

/// A process's run-time state.
pub(crate) struct ProcState {
    /// Next instruction of the running code.
    pub pc: usize,
    /// Variables of the running code (the process's, or the running procedure's frame).
    pub vars: Vec<Value>,
    /// The running code: `None` for the process's own, else a procedure.
    pub running: Option<SubprogramId>,
    /// The suspended callers of the running procedure, innermost last.
    stack: Vec<Frame>,
    /// Signals the wait at each instruction index of the process is sensitive to (empty
    /// elsewhere).
    sensitivity: Vec<Vec<SignalId>>,
    /// The driver of the whole-signal assignment at each instruction index of the process,
    /// once its first execution has found it (a process's drivers never change).
    driver_at: Vec<Option<usize>>,
    /// Signals a wait inside a procedure is sensitive to (filled when it suspends).
    procedure_sensitivity: Vec<SignalId>,
    /// Index in the running code of the `Wait` the process is suspended at.
    pub waiting_at: Option<usize>,
    /// Absolute time at which the current wait times out.
    pub timeout_at: Option<f64>,
    pub halted: bool,
}

impl ProcState {
    pub fn new(process: &Process) -> ProcState {
        let sensitivity = process
            .code
            .iter()
            .map(|instr| match instr {
                // `wait until c` without `on` is sensitive to the signals `c` reads (LRM 10.2).
                Instr::Wait { on, until, .. } if on.is_empty() => {
                    let mut s = until.as_ref().map(Expr::signals).unwrap_or_default();
                    s.sort_unstable();
                    s.dedup();
                    s
                }
                Instr::Wait { on, .. } => on.clone(),
                _ => Vec::new(),
            })
            .collect();
        ProcState {
            pc: 0,
            vars: process.vars.iter().map(|v| v.init.clone()).collect(),
            running: None,
            stack: Vec::new(),
            driver_at: vec![None; process.code.len()],
            sensitivity,
            procedure_sensitivity: Vec::new(),
            waiting_at: None,
            timeout_at: None,
            halted: false,
        }
    }

    /// The condition of the current wait, if it has one.
    pub fn until<'p>(&self, process: &'p Process, subs: &'p [Subprogram]) -> Option<&'p Expr> {
        match code_of(process, subs, self.running)
            .0
            .get(self.waiting_at?)?
        {
            Instr::Wait { until, .. } => until.as_ref(),
            _ => None,
        }
    }

    /// Every signal a wait of the process's own code is sensitive to (with repeats).
    pub fn own_sensitivity(&self) -> impl Iterator<Item = SignalId> + '_ {
        self.sensitivity.iter().flatten().copied()
    }

    /// The signals the current wait is sensitive to.
    pub fn sensitivity(&self) -> &[SignalId] {
        match self.waiting_at {
            Some(_) if self.running.is_some() => &self.procedure_sensitivity,
            Some(at) => &self.sensitivity[at],
            None => &[],
        }
    }
}

/// A suspended caller: where to continue and its variables.
struct Frame {
    running: Option<SubprogramId>,
    pc: usize,
    vars: Vec<Value>,
}

/// The code and variable declarations of the process or of procedure `running`.
fn code_of<'p>(
    process: &'p Process,
    subs: &'p [Subprogram],
    running: Option<SubprogramId>,
) -> (&'p [Instr], &'p [Variable], &'p [Span]) {
    match running.and_then(|id| subs.get(id.index())) {
        Some(sub) => (&sub.code, &sub.vars, &sub.spans),
        None => (&process.code, &process.vars, &process.spans),
    }
}

/// Everything an activation reads and writes outside its own state.
pub(crate) struct Context<'a> {
    pub signals: &'a mut Signals,
    pub quantities: &'a [f64],
    pub derivatives: &'a [f64],
    pub now: f64,
    /// Reinitialisation values of the breaks executed, in order.
    pub breaks: &'a mut Vec<(QuantityId, f64)>,
    /// Number of break statements executed (with or without values).
    pub break_count: &'a mut usize,
    pub reports: &'a mut Vec<Report>,
    pub on_report: &'a mut dyn FnMut(&Report),
    /// Reused buffer for a waveform being assigned.
    pub waveform: &'a mut Vec<(Option<Value>, f64)>,
    /// The design's subprograms.
    pub subprograms: &'a [Subprogram],
    /// The design's signals (their names and integer ranges, for range checks).
    pub design_signals: &'a [vams_design::Signal],
    /// The heap and the files.
    pub io: &'a super::io::Io,
}

/// `v` within `range` (an integer subtype's bounds), or the run-time error VHDL requires for
/// an assignment of a value outside them (LRM 8.4, 8.5).
fn in_range(v: &Value, range: Option<(i64, i64)>, what: &str, name: &str) -> Result<(), EvalError> {
    match (v, range) {
        (Value::Integer(i), Some((lo, hi))) if *i < lo || *i > hi => Err(EvalError::new(
            format!("{what} `{name}` assigned {i}, outside its range {lo} to {hi}"),
            "an integer object must stay within its subtype's range (bound check, LRM 8.4 and              8.5); widen the subtype, or keep the value in range",
        )),
        _ => Ok(()),
    }
}

/// `d` seconds after `now`, on the femtosecond grid VHDL's time lives on (LRM 3.1.3.1: time
/// is an integer number of its resolution limit), never before `now` (which an analog
/// threshold crossing puts between grid points). Sums of delays in seconds drift off the
/// grid (13 000 clock periods of 25 us end 16 fs before 0.324975 s), and two processes
/// reaching the same instant by different sums would schedule two time points 16 fs apart,
/// a step no integrator can take; on the grid they are one. `d = 0` is the next delta cycle
/// at `now` itself. Beyond 2^53 fs (about 9000 s) the nearest double is kept.
pub(crate) fn later(now: f64, d: f64) -> f64 {
    const FS: f64 = 1e15;
    if d == 0.0 {
        return now;
    }
    let t = now + d;
    let x = t * FS;
    if x.abs() < 9.0e15 {
        // Not `f64::max`, whose NaN handling puts five more instructions on the path from
        // one time point's time to the next's: neither is NaN.
        let r = round(x) / FS;
        if r < now { now } else { r }
    } else {
        t
    }
}

/// `x.round()` (half away from zero) for `|x| < 2^53`, without the library call that the
/// baseline x86-64 target makes of `f64::round` (it has no rounding instruction): `x` less
/// its truncation is exact at these magnitudes.
#[inline(always)]
fn round(x: f64) -> f64 {
    // 2^52: from there on every double is an integer.
    const BIG: f64 = 4_503_599_627_370_496.0;
    if (0.0..BIG).contains(&x) {
        // Times: rounded to the nearest integer (ties to even) by the addition's own
        // rounding, the sum's unit in the last place being 1, and a tie that went down to
        // even taken up (`r - x` is exact). Two additions instead of two conversions on
        // the path from one time point's time to the next's.
        let r = (x + BIG) - BIG;
        return if r - x == -0.5 { r + 1.0 } else { r };
    }
    let n = x as i64;
    let f = x - n as f64;
    let n = if f >= 0.5 {
        n + 1
    } else if f <= -0.5 {
        n - 1
    } else {
        n
    };
    n as f64
}

/// Tells the reports that functions made while `process` evaluated their calls.
#[inline]
pub(crate) fn emit_function_reports(cx: &mut Context, process: &str) {
    // Checked before every instruction: the common case stays inline and cheap.
    if !cx.io.function_reports.borrow().is_empty() {
        emit_pending_reports(cx, process);
    }
}

#[inline(never)]
fn emit_pending_reports(cx: &mut Context, process: &str) {
    for r in cx.io.function_reports.take() {
        let report = Report {
            time: cx.now,
            severity: r.severity,
            message: r.message,
            process: process.to_string(),
            span: r.span,
        };
        (cx.on_report)(&report);
        cx.reports.push(report);
    }
}

/// The `Env` a process's expressions read: built where an instruction evaluates, since
/// assignments change the signals and variables it borrows.
macro_rules! process_env {
    ($cx:expr, $state:expr, $subs:expr, $index:expr) => {
        Env {
            signals: &$cx.signals.states,
            vars: &$state.vars,
            quantities: $cx.quantities,
            derivatives: $cx.derivatives,
            now: $cx.now,
            subprograms: $subs,
            depth: $state.stack.len(),
            io: $cx.io,
            drivers: Some((&*$cx.signals, $index)),
        }
    };
}

/// Runs process `index` until it suspends; `lowered` is its code lowered
/// ([`super::lower`]), instruction by instruction, and `first_step` the number of
/// instructions [`super::lower::run`] ran before it declined (0 without it).
pub(crate) fn run(
    index: usize,
    process: &Process,
    lowered: &[Op],
    state: &mut ProcState,
    cx: &mut Context,
    first_step: usize,
) -> Result<Suspend, SimError> {
    let now = cx.now;
    let fail = |e: EvalError, span: Span| runtime_error(process, now, e, span);
    state.waiting_at = None;
    state.timeout_at = None;
    let subs = cx.subprograms;
    // The running code changes only at `Call` and `Return`, which look it up again.
    let (mut code, mut decls, mut spans) = code_of(process, subs, state.running);
    // The lowered instructions of the running code: none in a procedure.
    let mut ops = match state.running {
        None => lowered,
        Some(_) => &[],
    };
    // What an instruction's expressions read; built where used, since assignments change
    // the signals and variables it borrows.
    macro_rules! env {
        () => {
            process_env!(cx, state, subs, index)
        };
    }
    for step in first_step..INSTRUCTION_LIMIT {
        cx.io
            .check_cancel(step)
            .map_err(|e| fail(e, process.span))?;
        let pc = state.pc;
        // A lowered instruction, unless it declines (then the interpreter runs it below).
        if let Some(op) = ops.get(pc) {
            // One instruction at a time: the count of the loop is the instructions'.
            match super::lower::step::<false>(op, state, cx.signals, now) {
                Some(Flow::Next(_)) => continue,
                Some(Flow::Suspend(s)) => return Ok(s),
                None => {}
            }
        }
        // What functions reported during the previous instructions (lowered instructions
        // call none).
        emit_function_reports(cx, &process.name);
        let Some(instr) = code.get(pc) else {
            // Elaboration guarantees every path ends in a wait; stop here rather than panic.
            return Err(fail(
                EvalError::new(
                    "the process ran past its last instruction",
                    "this is a bug in elaboration: every process must end in a loop",
                ),
                process.span,
            ));
        };
        // An error points at the statement the instruction comes from, else the process.
        let at = |e: EvalError| fail(e, spans.get(pc).copied().unwrap_or(process.span));
        state.pc += 1;
        match instr {
            Instr::SetVar { var, value } => {
                let env = env!();
                let v = super::fast::value(value, &env).map_err(at)?;
                if let Some(decl) = decls.get(var.index()) {
                    in_range(&v, decl.range, "variable", &decl.name).map_err(at)?;
                }
                state.vars[var.index()] = v;
            }
            Instr::Assign {
                target,
                index: element_index,
                waveform,
                mechanism,
            } => {
                let env = env!();
                cx.waveform.clear();
                let mut last = cx.now;
                let mut first_delay = 0.0;
                let signal = cx.design_signals.get(target.index());
                for (value, delay) in waveform {
                    let v = match value {
                        Some(value) => {
                            let v = super::fast::value(value, &env).map_err(at)?;
                            if let Some(s) = signal {
                                in_range(&v, s.range, "signal", &s.name).map_err(at)?;
                            }
                            Some(v)
                        }
                        // A null transaction (elaboration allows it on guarded signals only).
                        None => None,
                    };
                    let d = seconds_of(delay, &env).map_err(at)?;
                    if cx.waveform.is_empty() {
                        first_delay = d;
                    }
                    let t = later(cx.now, d);
                    if d < 0.0 || t < last {
                        return Err(at(EvalError::new(
                            format!("waveform delay {d} s is negative or out of order"),
                            "delays in a waveform must be non-negative and increasing \
                             (LRM 10.5.2.1)",
                        )));
                    }
                    last = t;
                    cx.waveform.push((v, t));
                }
                // The rejection interval starts at the first element's time minus the limit,
                // `now + d1 - r`, computed on the time grid as the transactions' times are.
                let delay = match mechanism {
                    DelayMechanism::Transport => Delay::Transport,
                    DelayMechanism::Inertial { reject: Some(r) } => {
                        let r = seconds_of(r, &env).map_err(at)?;
                        Delay::Inertial(later(cx.now, (first_delay - r).max(0.0)))
                    }
                    // Without `reject`, the limit is the first element's delay: the interval
                    // starts now.
                    DelayMechanism::Inertial { reject: None } => Delay::Inertial(cx.now),
                };
                let no_driver = || {
                    // `Signals::new` creates a driver for every assignment of every process.
                    at(EvalError::new(
                        "assignment to a signal without a driver",
                        "this is a kernel bug",
                    ))
                };
                // The process's own whole-signal assignment seen before: its driver as found.
                let known = match state.running {
                    None => state.driver_at.get(pc).copied().flatten(),
                    Some(_) => None,
                };
                if let Some(d) = known {
                    cx.signals.assign(d, cx.waveform, delay);
                    continue;
                }
                match (element_index, cx.signals.split(*target)) {
                    (None, None) => {
                        let d = cx
                            .signals
                            .driver(index, *target, None)
                            .ok_or_else(no_driver)?;
                        if state.running.is_none()
                            && let Some(slot) = state.driver_at.get_mut(pc)
                        {
                            *slot = Some(d);
                        }
                        cx.signals.assign(d, cx.waveform, delay);
                    }
                    (Some(i), Some(n)) => {
                        let i = integer(&eval(i, &env).map_err(at)?).map_err(at)?;
                        let ty = signal.map_or(&vams_design::Type::Integer, |s| &s.ty);
                        let k = offset(ty, i, n).map_err(at)?;
                        let d = cx
                            .signals
                            .driver(index, *target, Some(k))
                            .ok_or_else(no_driver)?;
                        cx.signals.assign(d, cx.waveform, delay);
                    }
                    // A whole assignment to a signal driven element by element.
                    (None, Some(n)) => {
                        assign_elements(index, *target, n, delay, cx).map_err(at)?;
                    }
                    (Some(_), None) => return Err(no_driver()),
                }
            }
            Instr::Wait { until, timeout, .. } => {
                let env = env!();
                let timeout = match timeout {
                    Some(t) => {
                        let d = seconds_of(t, &env).map_err(at)?;
                        if d < 0.0 {
                            return Err(at(EvalError::new(
                                format!("wait for a negative time ({d} s)"),
                                "the timeout of a wait must not be negative (LRM 10.2)",
                            )));
                        }
                        Some(later(cx.now, d))
                    }
                    None => None,
                };
                if state.running.is_some() {
                    // A wait inside a procedure (rare): its sensitivity is computed here.
                    let sens = &mut state.procedure_sensitivity;
                    sens.clear();
                    match (code.get(pc), until) {
                        (Some(Instr::Wait { on, .. }), _) if !on.is_empty() => {
                            sens.extend_from_slice(on)
                        }
                        (_, Some(u)) => sens.extend(u.signals()),
                        _ => {}
                    }
                }
                let sensitive = match state.running {
                    Some(_) => !state.procedure_sensitivity.is_empty(),
                    None => !state.sensitivity[pc].is_empty(),
                };
                if until.is_none() && timeout.is_none() && !sensitive {
                    state.halted = true;
                    return Ok(Suspend::Halt);
                }
                state.waiting_at = Some(pc);
                state.timeout_at = timeout;
                return Ok(Suspend::Wait);
            }
            Instr::Jump(target) => state.pc = *target,
            Instr::JumpIfNot { cond, target } => {
                let env = env!();
                if !super::fast::condition(cond, &env).map_err(at)? {
                    state.pc = *target;
                }
            }
            Instr::Stop => return Ok(Suspend::Stop),
            Instr::Halt => {
                state.halted = true;
                return Ok(Suspend::Halt);
            }
            // The rarer instructions, out of this loop's frame.
            _ => {
                if let Some(suspend) = run_other(index, process, state, cx, instr)? {
                    return Ok(suspend);
                }
                (code, decls, spans) = code_of(process, subs, state.running);
                ops = match state.running {
                    None => lowered,
                    Some(_) => &[],
                };
            }
        }
    }
    Err(SimError::Runaway {
        process: process.name.clone(),
        time: cx.now,
        limit: INSTRUCTION_LIMIT,
        span: process.span,
    })
}

/// The run-time error of `e` in `process` at `span`.
fn runtime_error(process: &Process, now: f64, e: EvalError, span: Span) -> SimError {
    match e.is_interrupted() {
        true => SimError::Interrupted { time: now },
        false => SimError::Runtime {
            process: process.name.clone(),
            time: now,
            message: e.message,
            span,
            help: e.help.to_string(),
        },
    }
}

/// The instructions [`run`] leaves out of its loop (heap, files, element assignments of
/// variables, assertions, breaks, procedure calls and returns): `Some` when the process
/// suspends. `state.pc` is already past `instr`.
#[inline(never)]
fn run_other(
    index: usize,
    process: &Process,
    state: &mut ProcState,
    cx: &mut Context,
    instr: &Instr,
) -> Result<Option<Suspend>, SimError> {
    let now = cx.now;
    let fail = |e: EvalError, span: Span| runtime_error(process, now, e, span);
    let subs = cx.subprograms;
    let (_, decls, spans) = code_of(process, subs, state.running);
    let pc = state.pc - 1;
    let at = |e: EvalError| fail(e, spans.get(pc).copied().unwrap_or(process.span));
    macro_rules! env {
        () => {
            process_env!(cx, state, subs, index)
        };
    }
    match instr {
        Instr::SetHeap { pointer, value } => {
            let env = env!();
            super::textio::set_heap(pointer, value, &env).map_err(at)?;
        }
        Instr::Native {
            op,
            args,
            copy_back,
            ..
        } => {
            let env = env!();
            let back = super::textio::call(op, args, copy_back, &env).map_err(at)?;
            for (var, v) in back {
                state.vars[var.index()] = v;
            }
        }
        Instr::SetVarElement { var, index, value } => {
            let env = env!();
            let i = integer(&eval(index, &env).map_err(at)?).map_err(at)?;
            let v = eval(value, &env).map_err(at)?;
            let ty = &decls[var.index()].ty;
            set_element(&mut state.vars[var.index()], ty, i, v).map_err(at)?;
        }
        Instr::Assert {
            cond,
            report,
            severity,
            span,
        } => {
            let env = env!();
            let at = |e: EvalError| fail(e, *span);
            if let Some(c) = cond {
                if truth(&eval(c, &env).map_err(at)?).map_err(at)? {
                    return Ok(None);
                }
            }
            let (message, severity) =
                assertion_report(report.as_ref(), severity, &env).map_err(at)?;
            // The reports of the functions the message called come first.
            emit_function_reports(cx, &process.name);
            let report = Report {
                time: cx.now,
                severity,
                message,
                process: process.name.clone(),
                span: *span,
            };
            (cx.on_report)(&report);
            cx.reports.push(report);
            if severity == Severity::Failure {
                return Ok(Some(Suspend::Failure));
            }
        }
        Instr::Break { reinit, when, span } => {
            let env = env!();
            let at = |e: EvalError| fail(e, *span);
            if let Some(c) = when {
                if !truth(&eval(c, &env).map_err(at)?).map_err(at)? {
                    return Ok(None);
                }
            }
            *cx.break_count += 1;
            for r in reinit {
                let v = eval(&r.value, &env).map_err(at)?;
                let x = v.as_f64().ok_or_else(|| {
                    at(EvalError::new(
                        "a break value is not a number",
                        "break values must be real expressions",
                    ))
                })?;
                cx.breaks.push((r.quantity, x));
            }
        }
        Instr::Call { sub, args, .. } => {
            let env = env!();
            let Some(callee) = subs.get(sub.index()) else {
                return Err(at(EvalError::new(
                    "a call of a subprogram the design does not have",
                    "this is a bug in elaboration",
                )));
            };
            if state.stack.len() + 1 >= call_depth_limit() {
                return Err(at(too_deep(&callee.name)));
            }
            let values = args
                .iter()
                .map(|a| eval(a, &env))
                .collect::<Result<Vec<_>, _>>()
                .map_err(at)?;
            let callee_vars = frame(callee, values);
            state.stack.push(Frame {
                running: state.running,
                pc: state.pc,
                vars: std::mem::replace(&mut state.vars, callee_vars),
            });
            state.running = Some(*sub);
            state.pc = 0;
        }
        Instr::Return(_) => {
            let Some(caller) = state.stack.pop() else {
                return Err(at(EvalError::new(
                    "`return` outside a subprogram",
                    "this is a bug in elaboration",
                )));
            };
            let callee_vars = std::mem::replace(&mut state.vars, caller.vars);
            state.running = caller.running;
            state.pc = caller.pc;
            let (code, ..) = code_of(process, subs, state.running);
            // `out` and `inout` parameters go back to the caller's variables.
            if let Some(Instr::Call { copy_back, .. }) = code.get(state.pc.wrapping_sub(1)) {
                for (param, actual) in copy_back {
                    state.vars[actual.index()] = callee_vars[param.index()].clone();
                }
            }
        }
        _ => {}
    }
    Ok(None)
}

/// A whole assignment of `cx.waveform` to `target`, a signal driven element by element
/// (`n` elements): each element of each value goes to that element's driver.
#[inline(never)]
fn assign_elements(
    index: usize,
    target: SignalId,
    n: usize,
    delay: Delay,
    cx: &mut Context,
) -> Result<(), EvalError> {
    let no_driver = || {
        EvalError::new(
            "assignment to a signal without a driver",
            "this is a kernel bug",
        )
    };
    let whole = &*cx.waveform;
    let split: Vec<Option<Vec<Value>>> = whole
        .iter()
        .map(|(v, _)| v.as_ref().map(Value::elements))
        .collect();
    for k in 0..n {
        let d = cx
            .signals
            .driver(index, target, Some(k))
            .ok_or_else(no_driver)?;
        let mut wave: Vec<(Option<Value>, f64)> = Vec::with_capacity(whole.len());
        for ((_, t), values) in whole.iter().zip(&split) {
            // A null transaction disconnects every element's driver.
            let Some(values) = values else {
                wave.push((None, *t));
                continue;
            };
            let v = values.get(k).cloned().ok_or_else(|| {
                EvalError::new(
                    format!(
                        "a value of {} element(s) assigned to a signal of {n}",
                        values.len()
                    ),
                    "an array assignment needs a value of the target's length",
                )
            })?;
            wave.push((Some(v), *t));
        }
        cx.signals.assign(d, &mut wave, delay);
    }
    Ok(())
}

/// The value of delay or timeout `e` in seconds; a literal one (`after 5 ns`, `wait for
/// 1 ns`, the usual case) is read without evaluating it.
#[inline(always)]
fn seconds_of(e: &Expr, env: &Env) -> Result<f64, EvalError> {
    match e {
        Expr::Const(Value::Time(t) | Value::Real(t)) => Ok(*t),
        _ => evaluated_seconds(e, env),
    }
}

#[inline(never)]
fn evaluated_seconds(e: &Expr, env: &Env) -> Result<f64, EvalError> {
    seconds(&eval(e, env)?)
}

/// A delay or timeout in seconds.
fn seconds(v: &Value) -> Result<f64, EvalError> {
    match v {
        Value::Time(t) | Value::Real(t) => Ok(*t),
        _ => Err(EvalError::new(
            "a delay is not a time",
            "delays and timeouts must be of type time",
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::later;

    #[test]
    fn rounding_is_the_library_s() {
        let mut x = 0.123_456_789f64;
        let mut checked = 0;
        while x < 9.0e15 {
            for v in [
                x,
                -x,
                x.floor() + 0.5,
                -(x.floor() + 0.5),
                x.floor() + 0.49999999999999994,
            ] {
                assert_eq!(super::round(v), v.round(), "{v}");
                checked += 1;
            }
            x *= 1.37;
        }
        for v in [
            0.0,
            -0.0,
            0.5,
            -0.5,
            1.5,
            2.5,
            0.49999999999999994,
            4503599627370495.5,
        ] {
            assert_eq!(super::round(v), v.round(), "{v}");
        }
        assert!(checked > 400);
    }

    #[test]
    fn times_stay_on_the_femtosecond_grid_whatever_the_sum() {
        let (mut fast, mut slow) = (0.0, 0.0);
        for _ in 0..64995 {
            fast = later(fast, 5e-6);
        }
        for _ in 0..4333 {
            slow = later(slow, 75e-6);
        }
        assert_eq!(fast, slow);
        assert_eq!(fast, later(0.0, 0.324975));
        // A delta cycle stays at `now`, even between grid points (an analog crossing).
        let crossing = 0.006875000500000004;
        assert_eq!(later(crossing, 0.0), crossing);
        assert!(later(crossing, 1e-16) >= crossing);
    }
}
