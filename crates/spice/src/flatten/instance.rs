//! One `X` line: finding its subcircuit, checking it, and expanding its body.
//!
//! Takes the frame the `X` line is in; gives (through `Flattener::expand`) the instance's
//! elements, nodes and models, or the diagnostics: unknown subcircuit, node count, unknown
//! parameter override, recursion, nesting depth.

use std::ptr;

use rustc_hash::FxHashMap;

use super::{Flattener, Frame, MAX_HIERARCHY};
use crate::deck::{Element, Subckt};
use crate::error::SpiceError;
use crate::eval::{Def, Scope};
use crate::suggest::suggest;

impl Flattener {
    pub(super) fn instantiate<'d>(&mut self, frame: &Frame<'d, '_>, el: &'d Element) {
        // The reader gives every `X` its subcircuit name.
        let Some(sub_name) = &el.model else {
            return;
        };
        let found = frame
            .bodies
            .iter()
            .enumerate()
            .rev()
            .find_map(|(level, body)| {
                body.subckts
                    .iter()
                    .find(|s| s.name.key == sub_name.key)
                    .map(|s| (level, s))
            });
        let Some((level, sub)) = found else {
            let names: Vec<&str> = frame
                .bodies
                .iter()
                .flat_map(|b| b.subckts.iter().map(|s| s.name.key.as_str()))
                .collect();
            self.errors.push(SpiceError::UnknownSubckt {
                span: sub_name.span,
                name: sub_name.text.clone(),
                suggestion: suggest(&sub_name.key, names),
            });
            return;
        };
        if let Some(at) = frame.stack.iter().position(|(s, _)| ptr::eq(*s, sub)) {
            let mut chain: Vec<String> = frame.stack[at..]
                .iter()
                .map(|(s, x)| format!("{} (in {})", s.name.text, x.text))
                .collect();
            chain.push(format!("{} (in {})", sub.name.text, el.name.text));
            self.errors.push(SpiceError::RecursiveSubckt {
                span: sub_name.span,
                name: sub.name.text.clone(),
                chain: chain.join(" -> "),
            });
            return;
        }
        if frame.stack.len() >= MAX_HIERARCHY {
            let chain: Vec<&str> = frame
                .stack
                .iter()
                .map(|(s, _)| s.name.text.as_str())
                .collect();
            self.errors.push(SpiceError::HierarchyTooDeep {
                span: el.name.span,
                limit: MAX_HIERARCHY,
                chain: chain.join(" -> "),
            });
            return;
        }
        if el.nodes.len() != sub.ports.len() {
            let ports: Vec<&str> = sub.ports.iter().map(|p| p.text.as_str()).collect();
            let span = match (el.nodes.first(), el.nodes.last()) {
                (Some(a), Some(b)) => a.span.to(b.span),
                _ => el.name.span,
            };
            self.errors.push(SpiceError::SubcktNodeCount {
                span,
                instance: el.name.text.clone(),
                subckt: sub.name.text.clone(),
                expected: sub.ports.len(),
                found: el.nodes.len(),
                ports: ports.join(" "),
            });
            return;
        }
        let path = if frame.path.is_empty() {
            el.name.key.clone()
        } else {
            format!("{}.{}", frame.path, el.name.key)
        };
        if let Some(&first) = self.instances.get(&path) {
            self.errors.push(SpiceError::DuplicateElement {
                span: el.name.span,
                name: path,
                first: (first.file == el.name.span.file).then_some(first),
            });
            return;
        }
        self.instances.insert(path.clone(), el.span);
        let mut ports = FxHashMap::default();
        for (port, node) in sub.ports.iter().zip(&el.nodes) {
            let id = self.node(frame, node);
            ports.insert(port.key.clone(), id);
        }
        let scope_defs = self.instance_defs(frame, el, sub);
        let (scope, errors) = Scope::new(Some(frame.scope), &scope_defs);
        self.errors.extend(errors);
        let models = self.models_of(&sub.body, &scope, &path);
        let mut bodies = frame.bodies[..=level].to_vec();
        bodies.push(&sub.body);
        let mut model_chain = frame.models[..=level].to_vec();
        model_chain.push(&models);
        let mut stack = frame.stack.clone();
        stack.push((sub, &el.name));
        let child = Frame {
            path,
            ports,
            scope: &scope,
            bodies,
            models: model_chain,
            stack,
        };
        self.expand(&child);
    }

    /// The instance's parameter definitions: the `params:` defaults, the body's `.param`s,
    /// then the `X` line's overrides (evaluated in the caller's scope), later ones winning.
    fn instance_defs<'e>(
        &mut self,
        frame: &Frame<'_, '_>,
        el: &'e Element,
        sub: &'e Subckt,
    ) -> Vec<(String, Def<'e>)> {
        let mut defs: Vec<(String, Def<'e>)> = sub
            .params
            .iter()
            .chain(&sub.body.params)
            .map(|p| (p.name.key.clone(), Def::Expr(&p.value)))
            .collect();
        for o in &el.params {
            if !sub.params.iter().any(|p| p.name.key == o.name.key) {
                let known: Vec<&str> = sub.params.iter().map(|p| p.name.key.as_str()).collect();
                self.errors.push(SpiceError::UnknownInstanceParam {
                    span: o.name.span,
                    name: o.name.text.clone(),
                    subckt: sub.name.text.clone(),
                    suggestion: suggest(&o.name.key, known.iter().copied()),
                    known: if known.is_empty() {
                        "none (declare them with `params:` on the `.subckt` line)".into()
                    } else {
                        known.join(", ")
                    },
                });
                continue;
            }
            let value = self.value(frame.scope, &o.value);
            defs.push((o.name.key.clone(), Def::Value(value, o.name.span)));
        }
        defs
    }
}
