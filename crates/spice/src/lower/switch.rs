//! The switches `S name n+ n- nc+ nc- model [on|off]` and `W name n+ n- vname model [on|off]`.
//!
//! Takes an S or W element and its `.model sw(vt vh ron roff)` / `csw(it ih ron roff)`; gives
//! what a VHDL-AMS model of ngspice's switch would elaborate to: a boolean state signal
//! `name.on` (initially true for `on`, else false), two `'above` signals on the control (the
//! across quantity `name.vc` of S, the current `i(vname)` of W) at `vt + |vh|` and
//! `vt - |vh|`, a process `wait on hi, lo, domain; if hi then on <= true; elsif not lo then
//! on <= false; end if;`, and the branch equation `i == (if on then 1/ron else 1/roff) * v`.
//! The kernel treats each change of `on` as a discontinuity (the equations read it), so no
//! explicit break is needed.
//!
//! ngspice's semantics: the switch turns on when the control rises above `vt + vh`, off when it
//! falls below `vt - vh`, and keeps its state inside the window; at the operating point the
//! state is the control's where the control lies outside the window, else the instance's
//! `on`/`off` (default off). Here the operating point is solved with the initial state, and
//! the process corrects it in the first delta cycle at time 0 (the `'above` signals and
//! `domain` all have events there), after which the analog system restarts. Defaults as
//! ngspice's: vt = vh = 0, ron = 1, roff = 1/gmin. A negative hysteresis (a different state
//! machine in ngspice) is refused as not supported.

use vams_design::{
    DelayMechanism, Expr, Instr, Process, QuantityId, Signal, SignalId, SignalKind, Type, UnaryOp,
    Value,
};

use super::{Lowerer, mul};
use crate::circuit::{ElementId, FlatElement};
use crate::deck::{ElementKind, InitialState, ModelKind};

impl Lowerer<'_> {
    pub(super) fn switch(&mut self, id: ElementId, el: &FlatElement) {
        let current = el.kind == ElementKind::W;
        let (letter, kind, names) = if current {
            ("W", ModelKind::Csw, ["it", "ih"])
        } else {
            ("S", ModelKind::Sw, ["vt", "vh"])
        };
        let (Some(p), Some(m)) = (self.node(el, 0), self.node(el, 1)) else {
            return;
        };
        if !self.check_params(el, &[], true) {
            return;
        }
        let circuit = self.circuit;
        let model = el.model.and_then(|k| circuit.models.get(k.0 as usize));
        let Some(model) = model.filter(|m| m.kind == kind) else {
            let card = if current { "csw" } else { "sw" };
            self.not_supported(
                el,
                format!("a switch `{}` without a `{card}` model", el.name),
                &format!("give the {letter} switch a `.model name {card}(...)` after its control"),
            );
            return;
        };
        let mut ok = true;
        for (name, _) in &model.params {
            if !names.contains(&name.as_str()) && !matches!(name.as_str(), "ron" | "roff") {
                ok = false;
                self.not_supported(
                    el,
                    format!("the switch model parameter `{name}` of `{}`", model.name),
                    &format!(
                        "remove `{name}=`: the switch is lowered with {}, {}, ron and roff",
                        names[0], names[1]
                    ),
                );
            }
        }
        let gmin = circuit.options.gmin.unwrap_or(1e-12);
        let vt = model.param(names[0]).unwrap_or(0.0);
        let vh = model.param(names[1]).unwrap_or(0.0);
        let ron = model.param("ron").unwrap_or(1.0);
        let roff = model.param("roff").unwrap_or(1.0 / gmin);
        if vh < 0.0 {
            ok = false;
            self.not_supported(
                el,
                format!(
                    "a negative hysteresis `{}={vh}` in `{}`",
                    names[1], model.name
                ),
                "give a hysteresis >= 0",
            );
        }
        if !(ron > 0.0 && roff > 0.0 && ron.is_finite() && roff.is_finite()) {
            ok = false;
            self.not_supported(
                el,
                format!(
                    "a switch resistance ron={ron} roff={roff} in `{}`",
                    model.name
                ),
                "give ron and roff finite positive values",
            );
        }
        if !ok {
            return;
        }
        let control = if current {
            match self.control_current(el) {
                Some(q) => q,
                None => return,
            }
        } else {
            let (Some(cp), Some(cm)) = (self.node(el, 2), self.node(el, 3)) else {
                return;
            };
            self.across(format!("{}.vc", el.name), cp, cm, el.span)
        };
        let (v, i) = self.branch(id, el, p, m);
        let on_init = el.state == Some(InitialState::On);
        let on = self.push_signal(
            format!("{}.on", el.name),
            Value::Boolean(on_init),
            SignalKind::Explicit,
            el,
        );
        let hi = self.above(control, vt + vh, el);
        let lo = self.above(control, vt - vh, el);
        let mut sensitivity = vec![hi, lo];
        sensitivity.extend(self.design.domain_signal());
        let assign = |value: bool| Instr::Assign {
            target: on,
            index: None,
            waveform: vec![(Some(Expr::Const(Value::Boolean(value))), Expr::real(0.0))],
            mechanism: DelayMechanism::Inertial { reject: None },
        };
        let code = vec![
            /* 0 */
            Instr::Wait {
                on: sensitivity,
                until: None,
                timeout: None,
            },
            /* 1 */
            Instr::JumpIfNot {
                cond: Expr::Signal(hi),
                target: 4,
            },
            /* 2 */ assign(true),
            /* 3 */ Instr::Jump(0),
            /* 4 */
            Instr::JumpIfNot {
                cond: Expr::Unary(UnaryOp::Not, Box::new(Expr::Signal(lo))),
                target: 0,
            },
            /* 5 */ assign(false),
            /* 6 */ Instr::Jump(0),
        ];
        self.design.processes.push(Process {
            name: format!("{}.state", el.name),
            vars: Vec::new(),
            code,
            spans: Vec::new(),
            span: el.span,
            driver_inits: Vec::new(),
        });
        let g = Expr::If(
            Box::new(Expr::Signal(on)),
            Box::new(Expr::real(1.0 / ron)),
            Box::new(Expr::real(1.0 / roff)),
        );
        let text = format!(
            "{} == (if {}.on then {:?} else {:?}) * {}",
            self.qname(i),
            el.name,
            1.0 / ron,
            1.0 / roff,
            self.qname(v)
        );
        self.equation(el, Expr::Quantity(i), mul(g, Expr::Quantity(v)), text);
    }

    /// `control'above(level)`.
    fn above(&mut self, control: QuantityId, level: f64, el: &FlatElement) -> SignalId {
        let name = format!("{}'above({level:?})", self.qname(control));
        self.push_signal(
            name,
            Value::Boolean(false),
            SignalKind::Above {
                quantity: Expr::Quantity(control),
                level: Expr::real(level),
            },
            el,
        )
    }

    fn push_signal(
        &mut self,
        name: String,
        init: Value,
        kind: SignalKind,
        el: &FlatElement,
    ) -> SignalId {
        self.design.signals.push(Signal {
            name,
            ty: Type::Boolean,
            init,
            kind,
            span: el.span,
            range: None,
            resolution: None,
            guarded: None,
        });
        SignalId(self.design.signals.len() as u32 - 1)
    }
}
