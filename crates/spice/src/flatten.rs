//! Subcircuit expansion: a [`Deck`] to a flat [`Circuit`].
//!
//! Takes a deck (as the reader gives it); gives the flat circuit, or every error found. Walks
//! the top level and, recursively, each `X` instance's subcircuit body, giving every node
//! and element its hierarchical name (ngspice's, see `circuit`), evaluating every value in
//! the instance's parameter scope, resolving models, subcircuits, controlling sources and
//! output vectors, and checking what a simulator would otherwise trip over: unknown names,
//! node counts, recursion, duplicate names, model types, analysis values.
//!
//! Scoping, as ngspice does it (checked against ngspice 39): parameters are *dynamic*, a
//! subcircuit's body sees its own `params:` (overridden by the `X` line's `k=v`, which are
//! evaluated in the caller's scope) and its own `.param`s, then its caller's scope, up to the
//! global `.param`s; subcircuit definitions and models are *lexical*, a name is looked up in
//! the body it is used in, then in the bodies that enclose that body's definition, so a
//! subcircuit-local `.model` shadows a global one. Models defined in a subcircuit are
//! instantiated per instance (their parameters may use the instance's). Nodes `0` and `gnd`
//! are ground everywhere; `.global` nodes are never prefixed. An element's controlling source
//! (F, H, W) and a K's inductors are looked up in the same body.
//!
//! Never returns a `Circuit` when there is an error, and never invents a value.

use rustc_hash::{FxHashMap, FxHashSet};
use vams_syntax::source::Span;

use crate::circuit::{Circuit, ElementId, FlatElement, FlatModel, ModelId, NodeId};
use crate::deck::{Body, Deck, Element, ElementKind, ModelKind, Name, Source, Subckt};
use crate::error::SpiceError;
use crate::eval::{Def, Fail, Scope};
use crate::expr::Expr;
use crate::suggest::suggest;

/// Deepest subcircuit nesting accepted.
pub const MAX_HIERARCHY: usize = 100;

/// Flattens a deck (see the module doc).
pub fn flatten(deck: &Deck) -> Result<Circuit, Vec<SpiceError>> {
    let mut f = Flattener {
        errors: Vec::new(),
        circuit: Circuit {
            title: deck.title.clone(),
            nodes: vec!["0".to_string()],
            ..Circuit::default()
        },
        node_ids: FxHashMap::default(),
        element_ids: FxHashMap::default(),
        instances: FxHashMap::default(),
        globals: deck.globals.iter().map(|g| g.key.clone()).collect(),
    };
    f.node_ids.insert("0".to_string(), NodeId::GROUND);
    let defs: Vec<(String, Def<'_>)> = deck
        .body
        .params
        .iter()
        .map(|p| (p.name.key.clone(), Def::Expr(&p.value)))
        .collect();
    let (global, errors) = Scope::new(None, &defs);
    f.errors.extend(errors);
    let models = f.models_of(&deck.body, &global, "");
    let top = Frame {
        path: String::new(),
        ports: FxHashMap::default(),
        scope: &global,
        bodies: vec![&deck.body],
        models: vec![&models],
        stack: Vec::new(),
    };
    f.expand(&top);
    f.finish(deck, &global);
    let mut params: Vec<(String, f64)> = defs
        .iter()
        .filter_map(|(n, _)| Some((n.clone(), global.get(n)??)))
        .collect();
    params.sort_by(|a, b| a.0.cmp(&b.0));
    params.dedup_by(|a, b| a.0 == b.0);
    f.circuit.params = params;
    if f.errors.is_empty() {
        Ok(f.circuit)
    } else {
        Err(f.errors)
    }
}

type ModelMap = FxHashMap<String, ModelId>;

/// Where the walk is: one body being expanded.
struct Frame<'d, 'f> {
    /// `""` at the top, `x1`, `x1.x2` inside instances.
    path: String,
    /// The subcircuit's ports, by local name.
    ports: FxHashMap<String, NodeId>,
    scope: &'f Scope<'f>,
    /// The lexical chain: the top body first, this body last.
    bodies: Vec<&'d Body>,
    /// The models of each body of `bodies`, for this instance.
    models: Vec<&'f ModelMap>,
    /// The instances around this one: subcircuit and `X` name.
    stack: Vec<(&'d Subckt, &'d Name)>,
}

struct Flattener {
    errors: Vec<SpiceError>,
    circuit: Circuit,
    node_ids: FxHashMap<String, NodeId>,
    element_ids: FxHashMap<String, ElementId>,
    /// Instance paths met, with their `X` line.
    instances: FxHashMap<String, Span>,
    globals: FxHashSet<String>,
}

impl Flattener {
    fn value(&mut self, scope: &Scope<'_>, expr: &Expr) -> Option<f64> {
        match scope.eval(expr) {
            Ok(v) => Some(v),
            Err(Fail::Error(e)) => {
                self.errors.push(e);
                None
            }
            Err(Fail::Reported) => None,
        }
    }

    fn intern(&mut self, name: String) -> NodeId {
        if let Some(id) = self.node_ids.get(&name) {
            return *id;
        }
        let id = NodeId(self.circuit.nodes.len() as u32);
        self.circuit.nodes.push(name.clone());
        self.node_ids.insert(name, id);
        id
    }

    fn node(&mut self, frame: &Frame<'_, '_>, name: &Name) -> NodeId {
        let key = name.key.as_str();
        if key == "0" || key == "gnd" {
            return NodeId::GROUND;
        }
        if let Some(id) = frame.ports.get(key) {
            return *id;
        }
        if frame.path.is_empty() || self.globals.contains(key) {
            self.intern(key.to_string())
        } else {
            self.intern(format!("{}.{key}", frame.path))
        }
    }

    /// The models a body defines, for one instance (`prefix` is its path).
    fn models_of(&mut self, body: &Body, scope: &Scope<'_>, prefix: &str) -> ModelMap {
        let mut map = ModelMap::default();
        for m in &body.models {
            let name = if prefix.is_empty() {
                m.name.key.clone()
            } else {
                format!("{prefix}:{}", m.name.key)
            };
            let level = m.level.as_ref().and_then(|l| {
                let v = self.value(scope, l)?;
                if v >= 1.0 && v.fract() == 0.0 && v <= f64::from(u32::MAX) {
                    Some(v as u32)
                } else {
                    self.errors.push(SpiceError::InvalidValue {
                        span: l.span,
                        what: format!("the level of model `{}`", m.name.text),
                        must: "a whole number from 1",
                        value: format!("{v}"),
                        help: "write `level=1`, `level=2`, ...",
                    });
                    None
                }
            });
            let params = m
                .params
                .iter()
                .filter_map(|p| Some((p.name.key.clone(), self.value(scope, &p.value)?)))
                .collect();
            let id = ModelId(self.circuit.models.len() as u32);
            self.circuit.models.push(FlatModel {
                name,
                kind: m.kind,
                level,
                params,
                span: m.span,
            });
            map.insert(m.name.key.clone(), id);
        }
        map
    }

    fn expand(&mut self, frame: &Frame<'_, '_>) {
        // `bodies` always holds the top body at least.
        let Some(body) = frame.bodies.last().copied() else {
            return;
        };
        let mut local: FxHashMap<&str, ElementId> = FxHashMap::default();
        let mut pending: Vec<(ElementId, &Element)> = Vec::new();
        for el in &body.elements {
            if el.kind == ElementKind::X {
                self.instantiate(frame, el);
                continue;
            }
            let id = self.element(frame, el);
            if let Some(id) = id {
                local.insert(el.name.key.as_str(), id);
                if !el.controls.is_empty() {
                    pending.push((id, el));
                }
            }
        }
        for (id, el) in pending {
            let wanted = match el.kind {
                ElementKind::K => ElementKind::L,
                _ => ElementKind::V,
            };
            let mut controls = Vec::new();
            for c in &el.controls {
                match local.get(c.key.as_str()) {
                    Some(&cid) => {
                        let kind = self.circuit.elements[cid.0 as usize].kind;
                        if kind == wanted {
                            controls.push(cid);
                        } else {
                            self.errors.push(SpiceError::WrongReference {
                                span: c.span,
                                name: c.text.clone(),
                                wanted: wanted.noun(),
                                found: kind.noun(),
                                hint: if wanted == ElementKind::L {
                                    "a K element couples two inductors (L elements)"
                                } else {
                                    "the controlling current of F, H and W is the current through a voltage source; add a 0 V source in series to measure it"
                                },
                            });
                        }
                    }
                    None => {
                        let names: Vec<&str> = local
                            .iter()
                            .filter(|(_, i)| self.circuit.elements[i.0 as usize].kind == wanted)
                            .map(|(n, _)| *n)
                            .collect();
                        self.errors.push(SpiceError::UnknownReference {
                            span: c.span,
                            what: if wanted == ElementKind::L {
                                "inductor"
                            } else {
                                "voltage source"
                            },
                            name: c.text.clone(),
                            suggestion: suggest(&c.key, names),
                            hint: "it must be defined in the same circuit or subcircuit body",
                        });
                    }
                }
            }
            self.circuit.elements[id.0 as usize].controls = controls;
        }
    }

    fn lookup_model(frame: &Frame<'_, '_>, key: &str) -> Option<ModelId> {
        frame.models.iter().rev().find_map(|m| m.get(key).copied())
    }

    /// One non-`X` element: flattened, pushed, and its id (`None` when its name is taken).
    fn element(&mut self, frame: &Frame<'_, '_>, el: &Element) -> Option<ElementId> {
        let name = if frame.path.is_empty() {
            el.name.key.clone()
        } else {
            let letter = el.name.key.chars().next().unwrap_or('?');
            format!("{letter}.{}.{}", frame.path, el.name.key)
        };
        let nodes = el.nodes.iter().map(|n| self.node(frame, n)).collect();
        let mut values: Vec<f64> = el
            .values
            .iter()
            .filter_map(|v| self.value(frame.scope, v))
            .collect();
        let params = el
            .params
            .iter()
            .filter_map(|p| Some((p.name.key.clone(), self.value(frame.scope, &p.value)?)))
            .collect();
        let mut model = None;
        if let Some(m) = &el.model {
            match Self::lookup_model(frame, &m.key) {
                Some(id) => {
                    self.check_model_kind(el, m, id);
                    model = Some(id);
                }
                None => {
                    let is_value =
                        matches!(el.kind, ElementKind::R | ElementKind::C | ElementKind::L)
                            && el.values.is_empty();
                    match frame.scope.get(&m.key) {
                        // ngspice reads `r1 a b rval` with `.param rval=...` as the value.
                        Some(v) if is_value => values.extend(v),
                        _ => {
                            let names: Vec<&str> = frame
                                .models
                                .iter()
                                .flat_map(|map| map.keys().map(String::as_str))
                                .collect();
                            self.errors.push(SpiceError::UnknownModel {
                                span: m.span,
                                name: m.text.clone(),
                                kind: model_noun(el.kind),
                                suggestion: suggest(&m.key, names),
                            });
                        }
                    }
                }
            }
        }
        let source = el.source.as_ref().map(|s| self.source(frame.scope, s));
        if let Some(&first) = self.element_ids.get(&name) {
            let first_span = self.circuit.elements[first.0 as usize].span;
            self.errors.push(SpiceError::DuplicateElement {
                span: el.name.span,
                name: name.clone(),
                first: (first_span.file == el.name.span.file).then_some(first_span),
            });
            return None;
        }
        let id = ElementId(self.circuit.elements.len() as u32);
        self.element_ids.insert(name.clone(), id);
        self.circuit.elements.push(FlatElement {
            kind: el.kind,
            name,
            nodes,
            controls: Vec::new(),
            model,
            values,
            params,
            state: el.state,
            source,
            span: el.span,
        });
        Some(id)
    }

    fn check_model_kind(&mut self, el: &Element, m: &Name, id: ModelId) {
        use ElementKind as E;
        use ModelKind as M;
        let kind = self.circuit.models[id.0 as usize].kind;
        let (ok, wanted) = match el.kind {
            E::R => (kind == M::R, "an `r`"),
            E::C => (kind == M::C, "a `c`"),
            E::L => (kind == M::L, "an `l`"),
            E::D => (kind == M::D, "a `d`"),
            E::Q => (matches!(kind, M::Npn | M::Pnp), "an `npn` or `pnp`"),
            E::M => (matches!(kind, M::Nmos | M::Pmos), "an `nmos` or `pmos`"),
            E::S => (kind == M::Sw, "an `sw`"),
            E::W => (kind == M::Csw, "a `csw`"),
            _ => (true, ""),
        };
        if !ok {
            self.errors.push(SpiceError::ModelKind {
                span: m.span,
                element: el.name.text.clone(),
                model: m.text.clone(),
                wanted,
                found: kind.name().to_string(),
            });
        }
    }

    fn source(&mut self, scope: &Scope<'_>, s: &Source<Expr>) -> Source<f64> {
        // A value that fails is reported, and then no `Circuit` is returned: the 0 never leaves.
        s.map(&mut |e: &Expr| self.value(scope, e).unwrap_or(0.0))
    }
}

/// What kind of model an element names, for "define it with `.model name KIND`".
fn model_noun(kind: ElementKind) -> &'static str {
    match kind {
        ElementKind::R => "r",
        ElementKind::C => "c",
        ElementKind::L => "l",
        ElementKind::D => "d",
        ElementKind::Q => "npn",
        ElementKind::M => "nmos",
        ElementKind::S => "sw",
        ElementKind::W => "csw",
        _ => "...",
    }
}

mod instance;
mod resolve;
#[cfg(test)]
mod tests;
