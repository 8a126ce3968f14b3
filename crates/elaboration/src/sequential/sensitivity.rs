//! Implicit sensitivity (LRM 8.1): the signals a `wait until` without an `on` list, a
//! process with `all`, or a concurrent statement waits on. A name's longest static prefix
//! goes in the set: `s(1)` read with a constant index makes the process wait on that element
//! (as a view signal of `s`), not on all of `s`, so that an event on `s(0)` alone does not
//! wake it; a signal also read whole, through an attribute or by a non-static index stays
//! whole.

use rustc_hash::FxHashMap;

use crate::Elab;
use vams_design::{Expr, Instr, Signal, SignalId, SignalKind, Type, Value};

/// A signal read, for sensitivity.
#[derive(Clone, Debug, PartialEq)]
pub(crate) enum Read {
    Whole(SignalId),
    /// An element at a static index of an array (or a record field by position), with the
    /// array's (record's) type.
    Element(SignalId, i64, Type),
}

/// How the expressions read one signal.
#[derive(Default)]
struct SignalUse {
    /// Its name nodes.
    names: usize,
    /// Those of them that are the prefix of a static element read.
    prefixes: usize,
    /// Read through an attribute or as a signal actual.
    whole: bool,
    /// The static elements read, with the array's type.
    elements: Vec<(i64, Type)>,
}

/// The signals read so far, in order of first appearance.
#[derive(Default)]
struct ReadSet {
    order: Vec<SignalId>,
    uses: FxHashMap<SignalId, SignalUse>,
}

impl ReadSet {
    fn signal(&mut self, s: SignalId) -> &mut SignalUse {
        let order = &mut self.order;
        self.uses.entry(s).or_insert_with(|| {
            order.push(s);
            SignalUse::default()
        })
    }

    fn add(&mut self, e: &Expr) {
        e.visit(&mut |e| match e {
            Expr::Signal(s) => self.signal(*s).names += 1,
            Expr::SignalAttr(s, _) => self.signal(*s).whole = true,
            Expr::FnCall { signals, .. } => {
                for s in signals {
                    self.signal(*s).whole = true;
                }
            }
            Expr::Index { array, index, ty } => {
                if let (Expr::Signal(s), Expr::Const(Value::Integer(i))) = (&**array, &**index) {
                    let used = self.signal(*s);
                    used.prefixes += 1;
                    if !used.elements.iter().any(|(k, _)| k == i) {
                        used.elements.push((*i, ty.clone()));
                    }
                }
            }
            _ => {}
        });
    }

    fn finish(mut self) -> Vec<Read> {
        let mut out = Vec::new();
        for s in self.order {
            // Invariant: every signal in `order` has its entry (`signal` adds both).
            let used = self.uses.remove(&s).unwrap_or_default();
            if used.whole || used.names > used.prefixes || used.elements.is_empty() {
                out.push(Read::Whole(s));
            } else {
                out.extend((used.elements.into_iter()).map(|(i, ty)| Read::Element(s, i, ty)));
            }
        }
        out
    }
}

/// The signal reads of `exprs`, in order of first appearance.
pub(crate) fn reads<'e>(exprs: impl IntoIterator<Item = &'e Expr>) -> Vec<Read> {
    let mut set = ReadSet::default();
    for e in exprs {
        set.add(e);
    }
    set.finish()
}

/// The signal reads of `code` (a wait's own condition is not part of a process's implicit
/// sensitivity).
pub(crate) fn reads_of_code(code: &[Instr]) -> Vec<Read> {
    let mut set = ReadSet::default();
    for i in code {
        match i {
            Instr::Wait { .. } => {}
            Instr::Call { signals, .. } => {
                i.visit_exprs(&mut |e| set.add(e));
                // The signal actuals are read whole.
                for s in signals {
                    set.signal(*s).whole = true;
                }
            }
            _ => i.visit_exprs(&mut |e| set.add(e)),
        }
    }
    set.finish()
}

impl Elab<'_> {
    /// The signals to wait on for `reads`, without repetitions: a static element read as the
    /// element's view signal (of a declared signal; an element of a port view or gather
    /// stays its whole signal).
    pub(crate) fn sensitivity(&mut self, reads: Vec<Read>) -> Vec<SignalId> {
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
        if let Some(&id) = self.signals.views.get(&(s, pos, None)) {
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
        self.signals.views.insert((s, pos, None), id);
        Some(id)
    }
}
