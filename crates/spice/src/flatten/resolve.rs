//! The deck-level cards, resolved against the flat circuit.
//!
//! Takes the deck and the global scope, after the elements are flat; gives the circuit's
//! analyses (numbers checked: a positive step, a stop after the start, a whole point count),
//! options, `.ic` / `.nodeset` values and output vectors (hierarchical node and element names
//! looked up, with "did you mean").

use rustc_hash::FxHashSet;

use super::Flattener;
use crate::circuit::{
    Analysis, AnalysisSpec, ElementId, Method, NodeId, NodeValue, OptionValue, OutputSpec, Probe,
    Sweep, SweepTarget,
};
use crate::deck::{self, Deck, ElementKind, Name, Vector};
use crate::error::SpiceError;
use crate::eval::Scope;
use crate::expr::Expr;
use crate::suggest::suggest;

impl Flattener {
    pub(super) fn finish(&mut self, deck: &Deck, global: &Scope<'_>) {
        for card in &deck.analyses {
            if let Some(analysis) = self.analysis(global, &card.analysis) {
                self.circuit.analyses.push(AnalysisSpec {
                    analysis,
                    span: card.span,
                });
            }
        }
        self.options(deck, global);
        for (list, out) in [(&deck.initial, 0), (&deck.nodesets, 1)] {
            for nv in list {
                let node = self.node_ref(&nv.node);
                let value = self.value(global, &nv.value);
                if let (Some(node), Some(value)) = (node, value) {
                    let v = NodeValue {
                        node,
                        value,
                        span: nv.node.span.to(nv.value.span),
                    };
                    if out == 0 {
                        self.circuit.initial.push(v);
                    } else {
                        self.circuit.nodesets.push(v);
                    }
                }
            }
        }
        for out in &deck.outputs {
            let probes = out.vectors.iter().filter_map(|v| self.probe(v)).collect();
            self.circuit.outputs.push(OutputSpec {
                card: out.card,
                analysis: out.analysis,
                probes,
                span: out.span,
            });
        }
        // The same mistake in a subcircuit body is met once per instance: report it once.
        let mut seen = FxHashSet::default();
        self.errors
            .retain(|e| seen.insert((e.span().file, e.span().start, e.span().end, e.to_string())));
    }

    /// A value that must be positive (`> 0`), or `>= 0` when `zero_ok`.
    fn checked(
        &mut self,
        scope: &Scope<'_>,
        e: &Expr,
        what: &str,
        zero_ok: bool,
        help: &'static str,
    ) -> Option<f64> {
        let v = self.value(scope, e)?;
        let ok = if zero_ok { v >= 0.0 } else { v > 0.0 };
        if ok {
            return Some(v);
        }
        self.errors.push(SpiceError::InvalidValue {
            span: e.span,
            what: what.to_string(),
            must: if zero_ok {
                "zero or positive"
            } else {
                "positive"
            },
            value: format!("{v}"),
            help,
        });
        None
    }

    fn analysis(&mut self, g: &Scope<'_>, a: &deck::Analysis) -> Option<Analysis> {
        let tran_help = "write `.tran tstep tstop [tstart [tmax]]` with times in seconds";
        let ac_help = "write `.ac dec|oct|lin points fstart fstop`";
        Some(match a {
            deck::Analysis::Op => Analysis::Op,
            deck::Analysis::Tran {
                tstep,
                tstop,
                tstart,
                tmax,
                uic,
            } => {
                let step = self.checked(g, tstep, "the time step", false, tran_help);
                let stop = self.checked(g, tstop, "the stop time", false, tran_help);
                let start = match tstart {
                    Some(e) => Some(self.checked(g, e, "the start time", true, tran_help)?),
                    None => None,
                };
                let max = match tmax {
                    Some(e) => Some(self.checked(g, e, "the maximum step", false, tran_help)?),
                    None => None,
                };
                let (step, stop) = (step?, stop?);
                if let (Some(s), Some(e)) = (start, tstart) {
                    if s >= stop {
                        self.errors.push(SpiceError::InvalidValue {
                            span: e.span,
                            what: "the start time".into(),
                            must: "before the stop time",
                            value: format!("{s}"),
                            help: tran_help,
                        });
                        return None;
                    }
                }
                Analysis::Tran {
                    tstep: step,
                    tstop: stop,
                    tstart: start,
                    tmax: max,
                    uic: *uic,
                }
            }
            deck::Analysis::Dc { sweeps } => {
                let mut out = Vec::new();
                for s in sweeps {
                    let target = self.sweep_target(&s.target);
                    let start = self.value(g, &s.start);
                    let stop = self.value(g, &s.stop);
                    let step = self.value(g, &s.step);
                    let (target, start, stop, step) = (target?, start?, stop?, step?);
                    if step == 0.0 || (stop - start) * step < 0.0 {
                        self.errors.push(SpiceError::InvalidValue {
                            span: s.step.span,
                            what: "the sweep step".into(),
                            must: "non-zero, with the sign of stop - start",
                            value: format!("{step}"),
                            help: "write `.dc source start stop step`, e.g. `.dc v1 0 5 0.1`",
                        });
                        return None;
                    }
                    out.push(Sweep {
                        target,
                        start,
                        stop,
                        step,
                    });
                }
                Analysis::Dc { sweeps: out }
            }
            deck::Analysis::Ac {
                scale,
                points,
                fstart,
                fstop,
            } => {
                let n = self.value(g, points);
                let lin = *scale == deck::AcScale::Lin;
                let f0 = self.checked(g, fstart, "the start frequency", lin, ac_help);
                let f1 = self.checked(g, fstop, "the stop frequency", false, ac_help);
                let (n, f0, f1) = (n?, f0?, f1?);
                if n < 1.0 || n.fract() != 0.0 || n > f64::from(u32::MAX) {
                    self.errors.push(SpiceError::InvalidValue {
                        span: points.span,
                        what: "the number of points".into(),
                        must: "a whole number from 1",
                        value: format!("{n}"),
                        help: ac_help,
                    });
                    return None;
                }
                if f1 < f0 {
                    self.errors.push(SpiceError::InvalidValue {
                        span: fstop.span,
                        what: "the stop frequency".into(),
                        must: "at least the start frequency",
                        value: format!("{f1}"),
                        help: ac_help,
                    });
                    return None;
                }
                Analysis::Ac {
                    scale: *scale,
                    points: n as u32,
                    fstart: f0,
                    fstop: f1,
                }
            }
        })
    }

    fn sweep_target(&mut self, name: &Name) -> Option<SweepTarget> {
        if name.key == "temp" {
            return Some(SweepTarget::Temperature);
        }
        let id = self.element_ref(name, "source")?;
        let kind = self.circuit.elements[id.0 as usize].kind;
        if matches!(kind, ElementKind::V | ElementKind::I | ElementKind::R) {
            Some(SweepTarget::Element(id))
        } else {
            self.errors.push(SpiceError::WrongReference {
                span: name.span,
                name: name.text.clone(),
                wanted: "a source, a resistor or `temp`",
                found: kind.noun(),
                hint: "`.dc` sweeps an independent source's value, a resistance, or the temperature",
            });
            None
        }
    }

    fn options(&mut self, deck: &Deck, g: &Scope<'_>) {
        for item in &deck.options {
            let key = item.name.key.as_str();
            let number = match &item.value {
                Some(deck::OptionValue::Expr(e)) => match self.value(g, e) {
                    Some(v) => Some(v),
                    None => continue,
                },
                _ => None,
            };
            let o = &mut self.circuit.options;
            let slot = match key {
                "reltol" => Some(&mut o.reltol),
                "abstol" => Some(&mut o.abstol),
                "vntol" => Some(&mut o.vntol),
                "gmin" => Some(&mut o.gmin),
                "temp" => Some(&mut o.temp),
                "tnom" => Some(&mut o.tnom),
                _ => None,
            };
            match (slot, number, key) {
                (Some(slot), Some(v), _) => *slot = Some(v),
                (Some(_), None, _) => self.errors.push(SpiceError::syntax(
                    item.name.span,
                    format!("option `{}` needs a number", item.name.text),
                    "needs `=value`",
                    format!("write `.options {}=value`", item.name.key),
                )),
                (None, _, "method") => {
                    let word = match &item.value {
                        Some(deck::OptionValue::Word(w)) => w.key.as_str(),
                        _ => "",
                    };
                    match word {
                        "trap" | "trapezoidal" => o.method = Some(Method::Trap),
                        "gear" => o.method = Some(Method::Gear),
                        _ => self.errors.push(SpiceError::syntax(
                            item.name.span,
                            "`method` is `trap` or `gear`",
                            "unknown integration method",
                            "write `.options method=trap` or `method=gear`",
                        )),
                    }
                }
                (None, _, _) => {
                    let value = match (&item.value, number) {
                        (_, Some(v)) => OptionValue::Number(v),
                        (Some(deck::OptionValue::Word(w)), _) => OptionValue::Word(w.key.clone()),
                        _ => OptionValue::Flag,
                    };
                    o.other.push((key.to_string(), value, item.name.span));
                }
            }
        }
        for t in &deck.temps {
            if let Some(v) = self.value(g, t) {
                self.circuit.options.temp = Some(v);
            }
        }
    }

    /// A node named in a card (hierarchical, as flattened).
    fn node_ref(&mut self, name: &Name) -> Option<NodeId> {
        if name.key == "0" || name.key == "gnd" {
            return Some(NodeId::GROUND);
        }
        if let Some(id) = self.node_ids.get(&name.key) {
            return Some(*id);
        }
        let suggestion = suggest(&name.key, self.circuit.nodes.iter().map(String::as_str));
        self.errors.push(SpiceError::UnknownReference {
            span: name.span,
            what: "node",
            name: name.text.clone(),
            suggestion,
            hint: "a node inside a subcircuit instance is named `x1.node` (nested: `x1.x2.node`)",
        });
        None
    }

    /// An element named in a card (hierarchical, as flattened).
    fn element_ref(&mut self, name: &Name, what: &'static str) -> Option<ElementId> {
        if let Some(id) = self.element_ids.get(&name.key) {
            return Some(*id);
        }
        let suggestion = suggest(&name.key, self.element_ids.keys().map(String::as_str));
        self.errors.push(SpiceError::UnknownReference {
            span: name.span,
            what,
            name: name.text.clone(),
            suggestion,
            hint: "an element inside a subcircuit instance is named like `v.x1.vname` (its letter, the instance path, its name)",
        });
        None
    }

    fn probe(&mut self, v: &Vector) -> Option<Probe> {
        Some(match v {
            Vector::Voltage {
                part,
                pos,
                neg,
                span,
            } => {
                let p = self.node_ref(pos);
                let n = match neg {
                    Some(n) => Some(self.node_ref(n)?),
                    None => None,
                };
                Probe::Voltage {
                    part: *part,
                    pos: p?,
                    neg: n,
                    span: *span,
                }
            }
            Vector::Current {
                part,
                element,
                span,
            } => Probe::Current {
                part: *part,
                element: self.element_ref(element, "element")?,
                span: *span,
            },
            Vector::All { span } => Probe::All { span: *span },
        })
    }
}
