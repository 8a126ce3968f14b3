//! Implicit sensitivity (LRM 8.1): the signals a `wait until` without an `on` list, a
//! process with `all`, or a concurrent statement waits on. A name's longest static prefix
//! goes in the set: `s(1)` read with a constant index makes the process wait on that element
//! (as a view signal of `s`), not on all of `s`, so that an event on `s(0)` alone does not
//! wake it; a signal also read whole, through an attribute or by a non-static index stays
//! whole.

use rustc_hash::FxHashMap;

use super::Elab;
use crate::design::{Expr, Instr, Signal, SignalId, SignalKind, Type, Value};

/// A signal read, for sensitivity.
#[derive(Clone, Debug, PartialEq)]
pub(super) enum Read {
    Whole(SignalId),
    /// An element at a static index of an array (or a record field by position), with the
    /// array's (record's) type.
    Element(SignalId, i64, Type),
}

/// The signal reads of `exprs`, in order of first appearance.
pub(super) fn reads<'e>(exprs: impl IntoIterator<Item = &'e Expr>) -> Vec<Read> {
    let mut order: Vec<SignalId> = Vec::new();
    // Per signal: its name nodes, those of them that are the prefix of a static element read,
    // whether it is read through an attribute or as a signal actual, and its static elements.
    let mut nodes: FxHashMap<SignalId, usize> = FxHashMap::default();
    let mut prefixes: FxHashMap<SignalId, usize> = FxHashMap::default();
    let mut whole: FxHashMap<SignalId, bool> = FxHashMap::default();
    let mut elements: FxHashMap<SignalId, Vec<(i64, Type)>> = FxHashMap::default();
    for e in exprs {
        e.visit(&mut |e| match e {
            Expr::Signal(s) => {
                if !order.contains(s) {
                    order.push(*s);
                }
                *nodes.entry(*s).or_default() += 1;
            }
            Expr::SignalAttr(s, _) => {
                if !order.contains(s) {
                    order.push(*s);
                }
                whole.insert(*s, true);
            }
            Expr::FnCall { signals, .. } => {
                for s in signals {
                    if !order.contains(s) {
                        order.push(*s);
                    }
                    whole.insert(*s, true);
                }
            }
            Expr::Index { array, index, ty } => {
                if let (Expr::Signal(s), Expr::Const(Value::Integer(i))) = (&**array, &**index) {
                    *prefixes.entry(*s).or_default() += 1;
                    let list = elements.entry(*s).or_default();
                    if !list.iter().any(|(k, _)| k == i) {
                        list.push((*i, ty.clone()));
                    }
                }
            }
            _ => {}
        });
    }
    let mut out = Vec::new();
    for s in order {
        let reads_whole = whole.get(&s).copied().unwrap_or(false)
            || nodes.get(&s).copied().unwrap_or(0) > prefixes.get(&s).copied().unwrap_or(0);
        match elements.remove(&s) {
            Some(list) if !reads_whole => {
                out.extend(list.into_iter().map(|(i, ty)| Read::Element(s, i, ty)))
            }
            _ => out.push(Read::Whole(s)),
        }
    }
    out
}

/// The signal reads of `code` (a wait's own condition is not part of a process's implicit
/// sensitivity).
pub(super) fn reads_of_code(code: &[Instr]) -> Vec<Read> {
    let mut exprs: Vec<Expr> = Vec::new();
    for i in code {
        match i {
            Instr::Wait { .. } => {}
            Instr::Call { sub, signals, .. } => {
                i.visit_exprs(&mut |e| exprs.push(e.clone()));
                // The signal actuals, as one expression that reads them all.
                exprs.push(Expr::FnCall {
                    sub: *sub,
                    args: Vec::new(),
                    signals: signals.clone(),
                });
            }
            _ => i.visit_exprs(&mut |e| exprs.push(e.clone())),
        }
    }
    reads(&exprs)
}

impl Elab<'_> {
    /// The signals to wait on for `reads`, without repetitions: a static element read as the
    /// element's view signal (of a declared signal; an element of a port view or gather
    /// stays its whole signal).
    pub(super) fn sensitivity(&mut self, reads: Vec<Read>) -> Vec<SignalId> {
        let mut out = Vec::new();
        for r in reads {
            let s = match r {
                Read::Whole(s) => s,
                Read::Element(s, i, ty) => self.element_view(s, i, &ty).unwrap_or(s),
            };
            if !out.contains(&s) {
                out.push(s);
            }
        }
        out
    }

    /// The view signal of the element at index `i` of the declared signal `s` of type `ty`.
    fn element_view(&mut self, s: SignalId, i: i64, ty: &Type) -> Option<SignalId> {
        let signal = &self.design.signals[s.index()];
        if signal.kind != SignalKind::Explicit {
            return None;
        }
        let Value::Array(items) = &signal.init else {
            return None;
        };
        let (left, ascending) = ty.index_origin();
        let pos = if ascending { i - left } else { left - i };
        let pos = usize::try_from(pos).ok().filter(|&p| p < items.len())?;
        let element = match ty {
            Type::Array { element, .. } => (**element).clone(),
            Type::Record { fields, .. } => fields.get(pos)?.1.clone(),
            _ => return None,
        };
        if let Some(&id) = self.views.get(&(s, pos, None)) {
            return Some(id);
        }
        let id = SignalId(self.design.signals.len() as u32);
        let view = Signal {
            name: format!("{}({i})", signal.name),
            ty: element,
            init: items[pos].clone(),
            kind: SignalKind::View {
                parent: s,
                first: pos,
                len: None,
            },
            span: signal.span,
            range: None,
            resolution: None,
            guarded: None,
        };
        self.design.signals.push(view);
        self.views.insert((s, pos, None), id);
        Some(id)
    }
}
