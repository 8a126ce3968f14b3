//! `S'ramp(tr, tf)` and `S'slew(rise, fall)` on a real signal: a value following the signal
//! with linear ramps of a given duration (`'ramp`) or maximum slope (`'slew`); without
//! arguments it follows at once.
//!
//! Lowering: a generated process keeps the ramp in three implicit signals, `v0`, `slope` and
//! `t0`, and the attribute is the expression `v0 + slope * (now - t0)`, piecewise linear in
//! time. On an event of `S` the process starts a ramp from the current value to the new one;
//! it waits with a timeout at the ramp's end, where it settles (`slope <= 0`). Both are kernel
//! time points, so the integrator lands on them, and both change a signal the equations read,
//! so the integrator restarts there: the breakpoints at the ramp's start and end.

use vams_design::{BinaryOp, DelayMechanism, Expr, Instr, Process, SignalId, Type, Value};
use vams_design::{VarId, Variable};
use vams_syntax::ast;
use vams_syntax::source::Span;

use crate::attributes::synth::{abs, add, arg, bin, cond, div, mul, now_seconds, real, sub};
use crate::error::ElabError;
use crate::names::scope::Scope;
use crate::{Elab, R};

/// How long a ramp from `cur` to `tgt` lasts.
#[derive(Clone, Copy, Debug)]
enum Pace {
    /// `'ramp(rise, fall)`: fixed durations, seconds.
    Duration { rise: f64, fall: f64 },
    /// `'slew(rise, fall)`: slopes, units per second (`fall` negative).
    Slope { rise: f64, fall: f64 },
}

impl Pace {
    fn duration(self, tgt: Expr, cur: Expr) -> Expr {
        let rising = bin(BinaryOp::Gt, tgt.clone(), cur.clone());
        match self {
            Pace::Duration { rise, fall } => cond(rising, real(rise), real(fall)),
            Pace::Slope { rise, fall } => {
                let delta = sub(tgt, cur);
                cond(
                    rising,
                    div(delta.clone(), real(rise)),
                    div(delta, real(fall)),
                )
            }
        }
    }
}

impl<'a> Elab<'a> {
    /// `s'ramp(...)` or `s'slew(...)` of real signal `s`.
    pub(crate) fn signal_follow_attribute(
        &mut self,
        sc: &Scope<'a>,
        s: SignalId,
        name: &str,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<Expr> {
        let first = match arg(args, 0) {
            Some(e) => Some(self.static_real(sc, e, "the first argument")?),
            None => None,
        };
        let second = match arg(args, 1) {
            Some(e) => Some(self.static_real(sc, e, "the second argument")?),
            None => None,
        };
        let pace = if name == "ramp" {
            let rise = first.unwrap_or(0.0);
            let fall = second.unwrap_or(rise);
            if !(rise >= 0.0 && fall >= 0.0 && rise.is_finite() && fall.is_finite()) {
                return Err(self.error(ElabError::invalid(
                    span,
                    "the rise and fall times of `'ramp` must be non-negative",
                    Some("`s'ramp(1.0e-6, 2.0e-6)`: times in seconds, as reals".into()),
                )));
            }
            Pace::Duration { rise, fall }
        } else {
            let rise = first.unwrap_or(f64::INFINITY);
            let fall = second.unwrap_or(-rise);
            if !(rise > 0.0 && fall < 0.0) {
                return Err(self.error(ElabError::invalid(
                    span,
                    "`'slew` needs a positive rising slope and a negative falling slope",
                    Some("`s'slew(1.0e6, -1.0e6)`: units per second".into()),
                )));
            }
            Pace::Slope { rise, fall }
        };
        let signal = &self.design.signals[s.index()];
        let base = format!("{}'{name}", signal.name);
        let init = signal.init.as_f64().unwrap_or(0.0);
        let v0 = self.implicit_signal(format!("{base}.v0"), init, span);
        let slope = self.implicit_signal(format!("{base}.slope"), 0.0, span);
        let t0 = self.implicit_signal(format!("{base}.t0"), 0.0, span);
        let value = add(
            Expr::Signal(v0),
            mul(Expr::Signal(slope), sub(now_seconds(), Expr::Signal(t0))),
        );
        let code = follow_code(s, [v0, slope, t0], &value, pace);
        let vars = ["tgt", "endt", "cur", "d"]
            .iter()
            .zip([init, -1.0, 0.0, 0.0])
            .map(|(n, v)| Variable {
                range: None,
                name: format!("{base}.{n}"),
                ty: Type::Real,
                init: Value::Real(v),
            })
            .collect();
        self.design.processes.push(Process {
            spans: Vec::new(),
            name: format!("{base}_follower"),
            vars,
            code,
            span,
            driver_inits: Vec::new(),
        });
        Ok(value)
    }
}

/// The follower process over variables `tgt, endt, cur, d` (see the module comment).
fn follow_code(
    s: SignalId,
    [v0, slope, t0]: [SignalId; 3],
    value: &Expr,
    pace: Pace,
) -> Vec<Instr> {
    let (tgt, endt, cur, d) = (VarId(0), VarId(1), VarId(2), VarId(3));
    let v = Expr::Var;
    let assign = |target: SignalId, value: Expr| Instr::Assign {
        index: None,
        target,
        waveform: vec![(Some(value), Expr::Const(Value::Time(0.0)))],
        mechanism: DelayMechanism::Transport,
    };
    let set = |var: VarId, value: Expr| Instr::SetVar { var, value };
    // The ramp has ended when the wake-up time reached its end (timeouts are computed as
    // `now + (endt - now)`, so allow for rounding).
    let ended = bin(
        BinaryOp::Le,
        sub(v(endt), now_seconds()),
        add(mul(real(1e-12), abs(v(endt))), real(1e-21)),
    );
    let ramping = bin(
        BinaryOp::And,
        bin(BinaryOp::Gt, v(d), real(0.0)),
        bin(BinaryOp::Ne, v(tgt), v(cur)),
    );
    vec![
        /* 0 */
        Instr::JumpIfNot {
            cond: bin(BinaryOp::Gt, v(endt), now_seconds()),
            target: 3,
        },
        /* 1 */
        Instr::Wait {
            on: vec![s],
            until: None,
            timeout: Some(sub(v(endt), now_seconds())),
        },
        /* 2 */ Instr::Jump(4),
        /* 3 */
        Instr::Wait {
            on: vec![s],
            until: None,
            timeout: None,
        },
        /* 4 */ set(cur, cond(ended, v(tgt), value.clone())),
        /* 5 */ set(tgt, Expr::Signal(s)),
        /* 6 */ set(d, pace.duration(v(tgt), v(cur))),
        /* 7 */ Instr::JumpIfNot {
            cond: ramping,
            target: 13,
        },
        /* 8 */ assign(v0, v(cur)),
        /* 9 */ assign(slope, div(sub(v(tgt), v(cur)), v(d))),
        /* 10 */ assign(t0, now_seconds()),
        /* 11 */ set(endt, add(now_seconds(), v(d))),
        /* 12 */ Instr::Jump(0),
        /* 13 */ assign(v0, v(tgt)),
        /* 14 */ assign(slope, real(0.0)),
        /* 15 */ set(endt, real(-1.0)),
        /* 16 */ Instr::Jump(0),
    ]
}
