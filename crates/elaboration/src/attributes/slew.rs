//! `Q'slew(rise, fall)`: a quantity following `Q` with a bounded slope, exactly, by modes.
//!
//! An implicit mode signal `m` selects the defining equation: tracking (`m = 0`,
//! `Q'slew == Q`), rising (`m = 1`, `Q'slew == y0 + rise (now - t0)`) or falling (`m = -1`,
//! the same with `fall`), where `y0` and `t0` are the value and time at the switch, kept in
//! implicit signals. The output stays algebraic in every mode (a differential output would
//! inherit the quiescent point's zero derivative and fail the first step when `Q` is already
//! moving at time 0). Two `'above`-style signals, whose root functions depend on the mode,
//! tell a generated process when to switch: while tracking, `Q'dot` leaving `[fall, rise]`;
//! while slewing, the output catching up with `Q`. A switch is a discontinuity, so the
//! integrator restarts on it; the crossings are located as roots.

use vams_design::{BinaryOp, DelayMechanism, Expr, Instr, Process, QuantityId, Signal};
use vams_design::{SignalId, SignalKind, Type, Value, VarId, Variable};
use vams_syntax::ast;
use vams_syntax::source::Span;

use crate::attributes::synth::{add, arg, bin, cond, mul, now_seconds, real, sub};
use crate::error::ElabError;
use crate::names::scope::Scope;
use crate::{Elab, R};

impl<'a> Elab<'a> {
    /// `q'slew(rise [, fall])`; without arguments the output is `q`.
    pub(crate) fn quantity_slew_attribute(
        &mut self,
        sc: &Scope<'a>,
        q: QuantityId,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<Expr> {
        let Some(first) = arg(args, 0) else {
            return Ok(Expr::Quantity(q));
        };
        let rise = self.static_real(sc, first, "the rising slope")?;
        let fall = match arg(args, 1) {
            Some(e) => self.static_real(sc, e, "the falling slope")?,
            None => -rise,
        };
        if !(rise > 0.0 && fall < 0.0) {
            return Err(self.error(ElabError::invalid(
                span,
                "`'slew` needs a positive rising slope and a negative falling slope",
                Some("`q'slew(1.0e6, -1.0e6)`: units per second".into()),
            )));
        }
        let y = self.aux_quantity(q, "slew");
        let base = self.qname(y);
        let m = self.implicit_signal(format!("{base}.mode"), 0.0, span);
        let y0 = self.implicit_signal(format!("{base}.y0"), 0.0, span);
        let t0 = self.implicit_signal(format!("{base}.t0"), 0.0, span);
        let mode = || Expr::Signal(m);
        let is = |op: BinaryOp| bin(op, mode(), real(0.0));
        let (qx, yx) = (Expr::Quantity(q), Expr::Quantity(y));
        let rate = cond(is(BinaryOp::Gt), real(rise), real(fall));
        let ramp = add(
            Expr::Signal(y0),
            mul(rate, sub(now_seconds(), Expr::Signal(t0))),
        );
        let residual = cond(
            is(BinaryOp::Eq),
            sub(yx.clone(), qx.clone()),
            sub(yx.clone(), ramp),
        );
        let text = format!(
            "{base} == {}, slope limited to [{fall}, {rise}]",
            self.qname(q)
        );
        self.generated_equation(residual, span, text);
        let up = cond(
            is(BinaryOp::Gt),
            sub(qx.clone(), yx.clone()),
            sub(Expr::Dot(q), real(rise)),
        );
        let down = cond(is(BinaryOp::Lt), sub(yx, qx), sub(real(fall), Expr::Dot(q)));
        let up = self.root_signal(format!("{base}.up"), up, span);
        let down = self.root_signal(format!("{base}.down"), down, span);
        self.design.processes.push(Process {
            spans: Vec::new(),
            name: format!("{base}_mode"),
            vars: vec![
                Variable {
                    range: None,
                    name: format!("{base}.switched"),
                    ty: Type::Real,
                    init: Value::Real(-1.0),
                },
                Variable {
                    range: None,
                    name: format!("{base}.next"),
                    ty: Type::Real,
                    init: Value::Real(0.0),
                },
            ],
            code: mode_code([m, y0, t0], y, up, down),
            span,
            driver_inits: Vec::new(),
        });
        Ok(Expr::Quantity(y))
    }

    /// A boolean signal true while `f > 0`, its changes located as roots of `f`.
    fn root_signal(&mut self, name: String, f: Expr, span: Span) -> SignalId {
        let id = SignalId(self.design.signals.len() as u32);
        self.design.signals.push(Signal {
            range: None,
            name,
            ty: Type::Boolean,
            init: Value::Boolean(false),
            kind: SignalKind::Above {
                quantity: f,
                level: real(0.0),
            },
            span,
            resolution: None,
            guarded: None,
        });
        id
    }
}

/// The mode process. A mode entered at time `switched` is kept through that instant: the new
/// root function starts at zero there and its sign is rounding noise.
fn mode_code(
    [m, y0, t0]: [SignalId; 3],
    y: QuantityId,
    up: SignalId,
    down: SignalId,
) -> Vec<Instr> {
    let (switched, next) = (VarId(0), VarId(1));
    let assign = |target: SignalId, value: Expr| Instr::Assign {
        index: None,
        target,
        waveform: vec![(Some(value), Expr::Const(Value::Time(0.0)))],
        mechanism: DelayMechanism::Transport,
    };
    let s = Expr::Signal;
    let just_switched = bin(BinaryOp::Eq, Expr::Var(switched), now_seconds());
    let mode_is = |op: BinaryOp| bin(op, s(m), real(0.0));
    let track = cond(s(up), real(1.0), cond(s(down), real(-1.0), real(0.0)));
    let keep = |flag: SignalId, value: f64| {
        cond(
            bin(BinaryOp::Or, s(flag), just_switched.clone()),
            real(value),
            real(0.0),
        )
    };
    let new_mode = cond(
        mode_is(BinaryOp::Eq),
        track,
        cond(mode_is(BinaryOp::Gt), keep(up, 1.0), keep(down, -1.0)),
    );
    vec![
        /* 0 */
        Instr::Wait {
            on: vec![up, down],
            until: None,
            timeout: None,
        },
        /* 1 */ Instr::SetVar {
            var: next,
            value: new_mode,
        },
        /* 2 */
        Instr::JumpIfNot {
            cond: bin(BinaryOp::Ne, Expr::Var(next), s(m)),
            target: 0,
        },
        /* 3 */
        Instr::SetVar {
            var: switched,
            value: now_seconds(),
        },
        /* 4 */ assign(m, Expr::Var(next)),
        /* 5 */ assign(y0, Expr::Quantity(y)),
        /* 6 */ assign(t0, now_seconds()),
        /* 7 */ Instr::Jump(0),
    ]
}
