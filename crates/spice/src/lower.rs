//! From a flat [`Circuit`] to the simulator's elaborated [`Design`].
//!
//! Takes a `Circuit` (what `flatten` gives); gives the `Design` that elaborating the same
//! circuit written in VHDL-AMS would give, so that the analog solver and the event kernel run
//! a SPICE deck exactly as they run a VHDL-AMS design: one nature `electrical` (tolerance
//! groups `DEFAULT_VOLTAGE` and `DEFAULT_CURRENT`, as `ieee.electrical_systems` declares
//! them) whose reference terminal is node `0`, one terminal per other node (named after the
//! node: `2`, `x1.n3`), and per element the branch quantities and the equation of its
//! ngspice device. Never simulates and never picks analysis options (see [`transient`]).
//!
//! Names: the across quantity `v(n)` of every node (and `v(a,b)` of every such probe) and
//! the through quantity `i(vname)` of every voltage source (and of every element an `i(...)`
//! probe names) are ngspice's vector names, so a run's columns read like ngspice's; every
//! other quantity is `element.v`, `element.i`, `element.vc` (a controlling voltage).
//!
//! Submodules: `sources` (the time functions of V and I), `diode` (the D element, with its
//! junction charge), `mosfet` (the M element, level 1, and `mosfet::charge`), `bjt` (the Q
//! element, Gummel-Poon, and `bjt::charge`), `switch` (S and W, a state signal driven by
//! `'above` thresholds) and `coupling` (K, after every inductor).

mod bjt;
mod coupling;
mod diode;
mod junction;
mod mosfet;
mod sources;
mod switch;

use std::collections::{HashMap, HashSet};
use std::sync::Arc;

use vams_design::{
    Design, Equation, Expr, Nature, NatureId, Quantity, QuantityId, QuantityKind, Signal,
    SignalKind, Terminal, TerminalId, Type, Value,
};
use vams_syntax::source::Span;

use crate::circuit::{
    Analysis, Circuit, ElementId, FlatElement, FlatModel, ModelId, NodeId, Probe,
};
use crate::deck::{ElementKind, OutputCard, Part, PrintAnalysis};
use crate::error::SpiceError;

/// A `.tran` card's numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct TranSpec {
    pub tstep: f64,
    pub tstop: f64,
    pub tstart: Option<f64>,
    pub tmax: Option<f64>,
    pub uic: bool,
}

/// The first `.tran` of the circuit, if any.
pub fn transient(circuit: &Circuit) -> Option<TranSpec> {
    circuit.analyses.iter().find_map(|a| match a.analysis {
        Analysis::Tran {
            tstep,
            tstop,
            tstart,
            tmax,
            uic,
        } => Some(TranSpec {
            tstep,
            tstop,
            tstart,
            tmax,
            uic,
        }),
        _ => None,
    })
}

/// The quantity names of the transient `.print` / `.probe` vectors, in order, without
/// repetitions; with none, every node voltage `v(n)` in node order.
pub fn outputs(circuit: &Circuit) -> Vec<String> {
    let mut names: Vec<String> = Vec::new();
    let push = |names: &mut Vec<String>, n: String| {
        if !names.contains(&n) {
            names.push(n);
        }
    };
    for o in &circuit.outputs {
        if !matches!(o.card, OutputCard::Print | OutputCard::Probe)
            || !matches!(o.analysis, None | Some(PrintAnalysis::Tran))
        {
            continue;
        }
        for p in &o.probes {
            match p {
                Probe::All { .. } => {
                    for n in node_voltages(circuit) {
                        push(&mut names, n);
                    }
                }
                _ => {
                    if let Some(n) = probe_name(circuit, p) {
                        push(&mut names, n);
                    }
                }
            }
        }
    }
    if names.is_empty() {
        names = node_voltages(circuit);
    }
    names
}

/// `v(n)` of every node but ground, in node order.
fn node_voltages(circuit: &Circuit) -> Vec<String> {
    circuit
        .nodes
        .iter()
        .skip(1)
        .map(|n| format!("v({n})"))
        .collect()
}

/// ngspice's name of a probe's vector (`v(2)`, `v(a,b)`, `i(v1)`); `None` for the complex
/// parts (`vdb(2)`), which have no transient vector.
fn probe_name(circuit: &Circuit, p: &Probe) -> Option<String> {
    match p {
        Probe::Voltage {
            part: Part::Value,
            pos,
            neg,
            ..
        } => Some(voltage_name(circuit, *pos, *neg)),
        Probe::Current {
            part: Part::Value,
            element,
            ..
        } => circuit
            .elements
            .get(element.0 as usize)
            .map(|e| format!("i({})", e.name)),
        _ => None,
    }
}

fn voltage_name(circuit: &Circuit, pos: NodeId, neg: Option<NodeId>) -> String {
    match neg {
        Some(n) if n != NodeId::GROUND => {
            format!("v({},{})", circuit.node_name(pos), circuit.node_name(n))
        }
        _ => format!("v({})", circuit.node_name(pos)),
    }
}

/// The design of a circuit (see the module doc), or every reason it has none.
pub fn lower(circuit: &Circuit) -> Result<Design, Vec<SpiceError>> {
    let mut l = Lowerer::new(circuit);
    l.run();
    if l.errors.is_empty() {
        l.design.shrink_to_fit();
        Ok(l.design)
    } else {
        Err(l.errors)
    }
}

/// The two kinds of electrical quantity: subtype, tolerance group and unit.
struct Flavour {
    subtype: Arc<str>,
    tolerance: Arc<str>,
    unit: Arc<str>,
}

pub(crate) struct Lowerer<'c> {
    circuit: &'c Circuit,
    design: Design,
    errors: Vec<SpiceError>,
    nature: NatureId,
    tran: Option<TranSpec>,
    /// Elements an `i(...)` probe names: their through quantity is `i(name)`.
    probed: HashSet<ElementId>,
    /// The through quantity of each voltage source, by element index (for F and H).
    source_current: Vec<Option<QuantityId>>,
    voltage: Flavour,
    current: Flavour,
    /// Diode models checked so far, and whether each is usable.
    diode_models: HashMap<ModelId, bool>,
}

impl<'c> Lowerer<'c> {
    fn new(circuit: &'c Circuit) -> Lowerer<'c> {
        let mut probed = HashSet::new();
        for o in &circuit.outputs {
            for p in &o.probes {
                if let Probe::Current { element, .. } = p {
                    probed.insert(*element);
                }
            }
        }
        Lowerer {
            circuit,
            design: Design {
                top: top_name(&circuit.title),
                ..Design::default()
            },
            errors: Vec::new(),
            nature: NatureId(0),
            tran: transient(circuit),
            probed,
            source_current: vec![None; circuit.elements.len()],
            voltage: Flavour {
                subtype: "voltage".into(),
                tolerance: "DEFAULT_VOLTAGE".into(),
                unit: "V".into(),
            },
            current: Flavour {
                subtype: "current".into(),
                tolerance: "DEFAULT_CURRENT".into(),
                unit: "A".into(),
            },
            diode_models: HashMap::new(),
        }
    }

    fn run(&mut self) {
        self.domain();
        self.check_cards();
        self.terminals();
        let c = self.circuit;
        // Voltage sources first: F and H refer to their currents.
        for (k, el) in c.elements.iter().enumerate() {
            if el.kind == ElementKind::V {
                self.voltage_source(ElementId(k as u32), el);
            }
        }
        for (k, el) in c.elements.iter().enumerate() {
            self.element(ElementId(k as u32), el);
        }
        self.couplings();
        self.probes();
    }

    /// `std.standard.domain`, which every elaborated design has: the kernel switches it from
    /// `quiescent_domain` to `time_domain` after the operating point.
    fn domain(&mut self) {
        self.design.signals.push(Signal {
            name: "domain".into(),
            ty: Type::Enum {
                name: "domain_type".into(),
                literals: ["quiescent_domain", "time_domain", "frequency_domain"]
                    .map(String::from)
                    .to_vec(),
            },
            init: Value::Enum(0),
            kind: SignalKind::Explicit,
            span: Span::default(),
            range: None,
            resolution: None,
            guarded: None,
        });
    }

    /// What the circuit asks for that a design cannot say yet.
    fn check_cards(&mut self) {
        let c = self.circuit;
        for ic in &c.initial {
            self.errors.push(SpiceError::NotSupported {
                span: ic.span,
                what: "`.ic`".into(),
                label: "initial conditions are not lowered".into(),
                help: "remove the `.ic` card: the transient then starts from the operating point"
                    .into(),
            });
        }
        for a in &c.analyses {
            if let Analysis::Tran { uic: true, .. } = a.analysis {
                self.errors.push(SpiceError::NotSupported {
                    span: a.span,
                    what: "`.tran ... uic`".into(),
                    label: "`uic` is not lowered".into(),
                    help: "remove `uic`: the transient then starts from the operating point".into(),
                });
            }
        }
    }

    /// The nature, its reference terminal `0`, and one terminal per node (index = node id).
    fn terminals(&mut self) {
        let c = self.circuit;
        let mut spans = vec![None; c.nodes.len()];
        for el in &c.elements {
            for n in &el.nodes {
                if let Some(s) = spans.get_mut(n.0 as usize)
                    && s.is_none()
                {
                    *s = Some(el.span);
                }
            }
        }
        for (k, name) in c.nodes.iter().enumerate() {
            self.design.terminals.push(Terminal {
                name: name.clone(),
                nature: self.nature,
                is_reference: k == 0,
                span: spans[k].unwrap_or_default(),
            });
        }
        if self.design.terminals.is_empty() {
            // `flatten` always names ground; a circuit built by hand may not.
            self.design.terminals.push(Terminal {
                name: "0".into(),
                nature: self.nature,
                is_reference: true,
                span: Span::default(),
            });
        }
        self.design.natures.push(Nature {
            name: "electrical".into(),
            across_tolerance: Some("DEFAULT_VOLTAGE".into()),
            through_tolerance: Some("DEFAULT_CURRENT".into()),
            reference: TerminalId(0),
        });
    }

    /// The across quantity of every node and of every voltage probe, under ngspice's name.
    fn probes(&mut self) {
        let c = self.circuit;
        let mut seen: HashSet<String> = HashSet::new();
        let mut wanted: Vec<(NodeId, Option<NodeId>, Span)> = (1..c.nodes.len())
            .map(|k| (NodeId(k as u32), None, self.design.terminals[k].span))
            .collect();
        for o in &c.outputs {
            for p in &o.probes {
                if let Probe::Voltage { pos, neg, span, .. } = p {
                    wanted.push((*pos, *neg, *span));
                }
            }
        }
        for (pos, neg, span) in wanted {
            let known = |n: NodeId| (n.0 as usize) < c.nodes.len();
            if !known(pos) || neg.is_some_and(|n| !known(n)) {
                continue;
            }
            let name = voltage_name(c, pos, neg);
            if !seen.insert(name.clone()) {
                continue;
            }
            let plus = self.terminal(pos);
            let minus = neg.map_or(TerminalId(0), |n| self.terminal(n));
            self.across(name, plus, minus, span);
        }
    }

    fn terminal(&self, n: NodeId) -> TerminalId {
        TerminalId(n.0)
    }

    /// A new terminal inside an element (a diode's series resistance).
    pub(crate) fn internal_terminal(&mut self, name: String, span: Span) -> TerminalId {
        self.design.terminals.push(Terminal {
            name,
            nature: self.nature,
            is_reference: false,
            span,
        });
        TerminalId(self.design.terminals.len() as u32 - 1)
    }

    fn quantity(&mut self, name: String, kind: QuantityKind, span: Span) -> QuantityId {
        let f = match kind {
            QuantityKind::Through { .. } => &self.current,
            _ => &self.voltage,
        };
        self.design.quantities.push(Quantity {
            name,
            kind,
            tolerance: Some(f.tolerance.clone()),
            subtype: f.subtype.clone(),
            unit: Some(f.unit.clone()),
            initial_guess: None,
            span,
        });
        QuantityId(self.design.quantities.len() as u32 - 1)
    }

    pub(crate) fn across(
        &mut self,
        name: String,
        plus: TerminalId,
        minus: TerminalId,
        span: Span,
    ) -> QuantityId {
        self.quantity(name, QuantityKind::Across { plus, minus }, span)
    }

    pub(crate) fn through(
        &mut self,
        name: String,
        plus: TerminalId,
        minus: TerminalId,
        span: Span,
    ) -> QuantityId {
        self.quantity(name, QuantityKind::Through { plus, minus }, span)
    }

    /// The name of an element's through quantity: ngspice's `i(name)` for a voltage source
    /// or a probed element, else `name.i`.
    fn current_name(&self, id: ElementId, el: &FlatElement) -> String {
        if el.kind == ElementKind::V || self.probed.contains(&id) {
            format!("i({})", el.name)
        } else {
            format!("{}.i", el.name)
        }
    }

    /// `v across i through plus to minus` of an element.
    fn branch(
        &mut self,
        id: ElementId,
        el: &FlatElement,
        plus: TerminalId,
        minus: TerminalId,
    ) -> (QuantityId, QuantityId) {
        let v = self.across(format!("{}.v", el.name), plus, minus, el.span);
        let i = self.through(self.current_name(id, el), plus, minus, el.span);
        (v, i)
    }

    /// The equation `lhs == rhs` of element `el`, listed as `text`.
    pub(crate) fn equation(&mut self, el: &FlatElement, lhs: Expr, rhs: Expr, text: String) {
        self.design.equations.push(Equation {
            residual: sub(lhs, rhs),
            span: el.span,
            instance: instance_of(&el.name),
            text,
        });
    }

    pub(crate) fn qname(&self, q: QuantityId) -> &str {
        self.design
            .quantities
            .get(q.index())
            .map_or("?", |q| q.name.as_str())
    }

    pub(crate) fn not_supported(&mut self, el: &FlatElement, what: String, help: &str) {
        self.errors.push(SpiceError::NotSupported {
            span: el.span,
            label: format!("in `{}`", el.name),
            what,
            help: help.into(),
        });
    }

    /// Terminal `k` of the element's nodes; an error when the element has too few.
    fn node(&mut self, el: &FlatElement, k: usize) -> Option<TerminalId> {
        match el.nodes.get(k) {
            Some(n) if (n.0 as usize) < self.circuit.nodes.len() => Some(self.terminal(*n)),
            Some(n) => {
                self.errors.push(SpiceError::syntax(
                    el.span,
                    format!("`{}` names node {}, which the circuit lacks", el.name, n.0),
                    "unknown node",
                    "build the circuit with `flatten`, which interns every node",
                ));
                None
            }
            None => {
                self.errors.push(SpiceError::syntax(
                    el.span,
                    format!("`{}` has {} node(s), too few", el.name, el.nodes.len()),
                    "missing nodes",
                    "write every node of the element",
                ));
                None
            }
        }
    }

    /// Rejects every instance parameter but `allowed`, and a model where `model` is false.
    fn check_params(&mut self, el: &FlatElement, allowed: &[&str], model: bool) -> bool {
        let mut ok = true;
        for (name, _) in &el.params {
            if !allowed.contains(&name.as_str()) {
                ok = false;
                let known = if allowed.is_empty() {
                    "this element takes no instance parameter here".to_string()
                } else {
                    format!("the parameters lowered here are {}", allowed.join(", "))
                };
                self.not_supported(
                    el,
                    format!("instance parameter `{name}` of `{}`", el.name),
                    &format!("remove `{name}=`; {known}"),
                );
            }
        }
        if !model && el.model.is_some() {
            ok = false;
            self.not_supported(
                el,
                format!("a model on `{}`", el.name),
                "give the element its value instead of a model",
            );
        }
        ok
    }

    /// The value of R, C or L: the positional one, else `key=`.
    fn passive_value(&mut self, el: &FlatElement, key: &str, what: &str) -> Option<f64> {
        match el.values.first().copied().or_else(|| el.param(key)) {
            Some(v) => Some(v),
            None => {
                self.errors.push(SpiceError::syntax(
                    el.span,
                    format!("the {what} `{}` has no value", el.name),
                    "no value",
                    format!("write the value after the nodes, e.g. `{} a b 1k`", el.name),
                ));
                None
            }
        }
    }

    fn gain(&mut self, el: &FlatElement) -> Option<f64> {
        match el.values.first() {
            Some(v) => Some(*v),
            None => {
                self.errors.push(SpiceError::syntax(
                    el.span,
                    format!("`{}` has no gain", el.name),
                    "no gain",
                    "write the gain after the nodes (E, G) or the controlling source (F, H)",
                ));
                None
            }
        }
    }

    fn voltage_source(&mut self, id: ElementId, el: &FlatElement) {
        let (Some(p), Some(m)) = (self.node(el, 0), self.node(el, 1)) else {
            return;
        };
        if !self.check_params(el, &[], false) {
            return;
        }
        let (v, i) = self.branch(id, el, p, m);
        if let Some(slot) = self.source_current.get_mut(id.0 as usize) {
            *slot = Some(i);
        }
        if let Some(value) = self.source_value(el) {
            let text = format!("{} == {}", self.qname(v), el.name);
            self.equation(el, Expr::Quantity(v), value, text);
        }
    }

    fn source_value(&mut self, el: &FlatElement) -> Option<Expr> {
        let Some(src) = &el.source else {
            return Some(Expr::real(0.0));
        };
        match sources::value(src, self.tran.as_ref(), el) {
            Ok(e) => Some(e),
            Err(e) => {
                self.errors.push(e);
                None
            }
        }
    }

    /// The current of the voltage source that controls F or H.
    fn control_current(&mut self, el: &FlatElement) -> Option<QuantityId> {
        let q = el
            .controls
            .first()
            .and_then(|c| self.source_current.get(c.0 as usize).copied().flatten());
        if q.is_none() {
            self.errors.push(SpiceError::syntax(
                el.span,
                format!("`{}` has no controlling voltage source", el.name),
                "no controlling source",
                "name a voltage source after the nodes, e.g. `f1 a b vsense 2`",
            ));
        }
        q
    }

    fn element(&mut self, id: ElementId, el: &FlatElement) {
        use ElementKind::*;
        let q = Expr::Quantity;
        match el.kind {
            V => {}
            R | C | L => {
                let (key, what) = match el.kind {
                    R => ("r", "resistor"),
                    C => ("c", "capacitor"),
                    _ => ("l", "inductor"),
                };
                let allowed: &[&str] = match el.kind {
                    R => &["r"],
                    C => &["c", "ic"],
                    _ => &["l", "ic"],
                };
                let (Some(p), Some(m)) = (self.node(el, 0), self.node(el, 1)) else {
                    return;
                };
                if !self.check_params(el, allowed, false) {
                    return;
                }
                let Some(x) = self.passive_value(el, key, what) else {
                    return;
                };
                let (v, i) = self.branch(id, el, p, m);
                let (vn, iname) = (self.qname(v).to_string(), self.qname(i).to_string());
                let (lhs, rhs, text) = match el.kind {
                    R => (
                        q(v),
                        mul(Expr::real(x), q(i)),
                        format!("{vn} == {x:?} * {iname}"),
                    ),
                    C => (
                        q(i),
                        mul(Expr::real(x), Expr::Dot(v)),
                        format!("{iname} == {x:?} * {vn}'dot"),
                    ),
                    _ => (
                        q(v),
                        mul(Expr::real(x), Expr::Dot(i)),
                        format!("{vn} == {x:?} * {iname}'dot"),
                    ),
                };
                self.equation(el, lhs, rhs, text);
            }
            I => {
                let (Some(p), Some(m)) = (self.node(el, 0), self.node(el, 1)) else {
                    return;
                };
                if !self.check_params(el, &[], false) {
                    return;
                }
                let i = self.through(self.current_name(id, el), p, m, el.span);
                if let Some(value) = self.source_value(el) {
                    let text = format!("{} == {}", self.qname(i), el.name);
                    self.equation(el, q(i), value, text);
                }
            }
            E | G => {
                let nodes: Vec<_> = (0..4).map(|k| self.node(el, k)).collect();
                let [Some(p), Some(m), Some(cp), Some(cm)] = nodes[..] else {
                    return;
                };
                if !self.check_params(el, &[], false) {
                    return;
                }
                let Some(g) = self.gain(el) else { return };
                let vc = self.across(format!("{}.vc", el.name), cp, cm, el.span);
                let vcn = self.qname(vc).to_string();
                if el.kind == E {
                    let (v, _) = self.branch(id, el, p, m);
                    let text = format!("{} == {g:?} * {vcn}", self.qname(v));
                    self.equation(el, q(v), mul(Expr::real(g), q(vc)), text);
                } else {
                    let i = self.through(self.current_name(id, el), p, m, el.span);
                    let text = format!("{} == {g:?} * {vcn}", self.qname(i));
                    self.equation(el, q(i), mul(Expr::real(g), q(vc)), text);
                }
            }
            F | H => {
                let (Some(p), Some(m)) = (self.node(el, 0), self.node(el, 1)) else {
                    return;
                };
                if !self.check_params(el, &[], false) {
                    return;
                }
                let (Some(g), Some(ic)) = (self.gain(el), self.control_current(el)) else {
                    return;
                };
                let icn = self.qname(ic).to_string();
                if el.kind == F {
                    let i = self.through(self.current_name(id, el), p, m, el.span);
                    let text = format!("{} == {g:?} * {icn}", self.qname(i));
                    self.equation(el, q(i), mul(Expr::real(g), q(ic)), text);
                } else {
                    let (v, _) = self.branch(id, el, p, m);
                    let text = format!("{} == {g:?} * {icn}", self.qname(v));
                    self.equation(el, q(v), mul(Expr::real(g), q(ic)), text);
                }
            }
            D => {
                let (Some(p), Some(m)) = (self.node(el, 0), self.node(el, 1)) else {
                    return;
                };
                self.diode(id, el, p, m);
            }
            M => self.mosfet(id, el),
            S | W => self.switch(id, el),
            K => {} // after every inductor: `couplings`
            Q => self.bjt(id, el),
            X => {
                self.not_supported(
                    el,
                    format!("a subcircuit instance left after flattening (X) `{}`", el.name),
                    "remove it, or model it with the elements that are lowered: R, C, L, K, V, I, E, F, G, H, S, W, D, M and Q",
                );
            }
        }
    }
}

/// The series resistances of the semiconductor devices (a diode's RS, a MOSFET's RD and RS, a
/// BJT's RC, RE and RB), to internal nodes named as ngspice names them (`d1#internal`,
/// `m1#drain`, `q1#collector`).
impl Lowerer<'_> {
    /// A branch from `outer` to a new internal node `element#suffix`, its quantities named
    /// `element.key.v` and `element.key.i`: the node and the two quantities.
    pub(super) fn internal_branch(
        &mut self,
        el: &FlatElement,
        outer: TerminalId,
        suffix: &str,
        key: &str,
    ) -> (TerminalId, QuantityId, QuantityId) {
        let inner = self.internal_terminal(format!("{}#{suffix}", el.name), el.span);
        let v = self.across(format!("{}.{key}.v", el.name), outer, inner, el.span);
        let i = self.through(format!("{}.{key}.i", el.name), outer, inner, el.span);
        (inner, v, i)
    }

    /// A resistance `r` in series with `outer` ([`Lowerer::internal_branch`] with `v == r*i`):
    /// the internal node, or `outer` itself when `r` is 0.
    pub(super) fn series_resistor(
        &mut self,
        el: &FlatElement,
        outer: TerminalId,
        r: f64,
        suffix: &str,
        key: &str,
    ) -> TerminalId {
        if r <= 0.0 {
            return outer;
        }
        let (inner, v, i) = self.internal_branch(el, outer, suffix, key);
        let text = format!("{} == {r:?} * {}", self.qname(v), self.qname(i));
        self.equation(
            el,
            Expr::Quantity(v),
            mul(Expr::real(r), Expr::Quantity(i)),
            text,
        );
        inner
    }
}

/// Errors on `.model` cards, which several instances share: each reported once.
impl Lowerer<'_> {
    /// Pushes a not-supported error on the `.model` card unless the same one is already
    /// there (several instances share one model).
    pub(super) fn refuse_model(&mut self, model: &FlatModel, what: String, help: String) {
        let span = model.span;
        let seen = self.errors.iter().any(|e| {
            matches!(e, SpiceError::NotSupported { span: s, what: w, .. } if *s == span && *w == what)
        });
        if !seen {
            self.errors.push(SpiceError::NotSupported {
                span,
                what,
                label: format!("in `.model {}`", model.name),
                help,
            });
        }
    }

    /// Pushes an error on a `.model` card unless an equal one is already there.
    pub(super) fn push_once(&mut self, e: SpiceError) {
        let text = e.to_string();
        if !self.errors.iter().any(|x| x.to_string() == text) {
            self.errors.push(e);
        }
    }
}

/// The instance path of an element (`r.x1.x2.r2`: `x1.x2`; `r1`: empty).
fn instance_of(name: &str) -> String {
    let parts: Vec<&str> = name.split('.').collect();
    if parts.len() >= 3 {
        parts[1..parts.len() - 1].join(".")
    } else {
        String::new()
    }
}

/// The design's top name: the title's first word, lower case (`circuit` without one).
fn top_name(title: &str) -> String {
    title
        .split_whitespace()
        .next()
        .map_or_else(|| "circuit".to_string(), str::to_ascii_lowercase)
}

pub(crate) use vams_design::build::{add, bin, mul, sub};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn instance_paths_drop_the_letter_and_the_name() {
        assert_eq!(instance_of("r1"), "");
        assert_eq!(instance_of("r.x1.r2"), "x1");
        assert_eq!(instance_of("r.x1.x2.r2"), "x1.x2");
    }
}
