//! Conversion functions and type conversions in port maps (LRM 1.1.1.2, 4.3.2.2): the actual
//! of a port of mode `in` converted (`a => to_bit(s)`), and the formal of a port of mode
//! `out` or `buffer` (`to_bool(y) => yb`). Either gives a [`SignalKind::Converted`] signal
//! that the kernel updates with its source, without a delta cycle between them: the port
//! `a` in the first case, the actual `yb` in the second (its only source is then the port;
//! [`Elab::check_converted_actuals`] refuses any other driver).

use vams_design::{SignalId, SignalKind};
use vams_syntax::ast;

use crate::error::ElabError;
use crate::names::scope::{Item, Scope};
use crate::names::types::Sub;
use crate::{Elab, R};

/// `f(x)` with one positional argument: the function or type mark `f` and `x`.
fn applied_once(e: &ast::Expr) -> Option<(&ast::Expr, &ast::Expr)> {
    match &e.kind {
        ast::ExprKind::Apply(prefix, args) => match args.as_slice() {
            [
                ast::Assoc {
                    formal: None,
                    actual: ast::Actual::Expr(x),
                    ..
                },
            ] if matches!(
                prefix.kind,
                ast::ExprKind::Name(_) | ast::ExprKind::Selected(..)
            ) =>
            {
                Some((prefix, x))
            }
            _ => None,
        },
        _ => None,
    }
}

impl<'a> Elab<'a> {
    /// The signal of port `name` (of subtype `sub`, mode `in`) whose actual `e` is a
    /// conversion of a signal: a new converted signal. `None` when `e` is not a function
    /// call or type conversion of one signal name (then it is an ordinary actual).
    pub(crate) fn converted_in_port(
        &mut self,
        parent: &Scope<'a>,
        name: &ast::Ident,
        sub: &Sub,
        e: &ast::Expr,
    ) -> R<Option<Item<'a>>> {
        let Some((prefix, x)) = applied_once(e) else {
            return Ok(None);
        };
        let converts = self.lookup(parent, prefix)?.iter().any(|i| {
            matches!(i, Item::Subprogram(s) if s.ret.is_some()) || matches!(i, Item::Type(_))
        });
        if !converts || !self.names_a_signal(parent, x) {
            return Ok(None);
        }
        let source = match self.lookup(parent, x)?.first() {
            Some(Item::Signal { id, .. }) => *id,
            _ => return Ok(None),
        };
        let conversion = self.expr_of(parent, e, &sub.ty)?.e;
        let id = self.new_signal(
            &name.name,
            sub,
            crate::declarations::decls::default_value(sub),
            name.span,
        );
        self.design.signals[id.index()].kind = SignalKind::Converted { source, conversion };
        Ok(Some(Item::Signal {
            id,
            ty: sub.ty.clone(),
        }))
    }

    /// True when `x` is a name (or an element or slice of one) that denotes a signal, told
    /// without reporting anything.
    fn names_a_signal(&self, sc: &Scope<'a>, x: &ast::Expr) -> bool {
        let id = match &x.kind {
            ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id) => id,
            ast::ExprKind::Apply(prefix, _) => match &prefix.kind {
                ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id) => id,
                _ => return false,
            },
            _ => return false,
        };
        matches!(self.resolved_item(sc, id), Some(Item::Signal { .. }))
    }

    /// Port `name` (of subtype `sub`, mode `mode`) associated as `conversion(name) =>
    /// actual`: a new signal for the port, driven by the instance's processes, and the
    /// actual, a whole signal, converted from it.
    pub(crate) fn converted_out_port(
        &mut self,
        parent: &Scope<'a>,
        name: &ast::Ident,
        sub: &Sub,
        mode: Option<ast::Mode>,
        conversion: &ast::Expr,
        actual: Option<&ast::Expr>,
    ) -> R<Item<'a>> {
        match mode {
            Some(ast::Mode::Out | ast::Mode::Buffer) => {}
            Some(ast::Mode::Inout) => {
                return Err(self.error(ElabError::unsupported(
                    conversion.span,
                    "conversions of a port of mode inout",
                    "split the port into one of mode in and one of mode out",
                )));
            }
            _ => {
                return Err(self.error(ElabError::invalid(
                    conversion.span,
                    "the formal of a port of mode in cannot be converted (LRM 1.1.1.2): its value comes from the actual",
                    Some("convert on the actual side: `a => to_bit(s)`".into()),
                )));
            }
        }
        let Some(actual) = actual else {
            return Err(self.error(ElabError::invalid(
                conversion.span,
                "a converted formal needs an actual signal",
                Some("associate it with a signal, or write `y => open`".into()),
            )));
        };
        let (target, ty) = match self.lookup(parent, actual)?.first() {
            Some(Item::Signal { id, ty }) => (*id, ty.clone()),
            Some(other) => {
                let class = other.class();
                return Err(self.error(ElabError::invalid(
                    actual.span,
                    format!("the actual of a converted port must be a signal, not {class}"),
                    None,
                )));
            }
            None => return Err(crate::Reported),
        };
        if self.design.signals[target.index()].kind != SignalKind::Explicit {
            return Err(self.error(ElabError::unsupported(
                actual.span,
                "a converted port whose actual is an element, a slice or another port's conversion",
                "associate the port with a whole signal of its own",
            )));
        }
        let port = self.new_signal(
            &name.name,
            sub,
            crate::declarations::decls::default_value(sub),
            name.span,
        );
        // The conversion reads the port under its own name, in the instantiating region.
        let mut sc = parent.clone();
        sc.push();
        sc.declare_at(
            &name.name,
            name.span,
            Item::Signal {
                id: port,
                ty: sub.ty.clone(),
            },
        );
        let conversion = self.expr_of(&sc, conversion, &ty)?.e;
        self.design.signals[target.index()].kind = SignalKind::Converted {
            source: port,
            conversion,
        };
        self.signals.converted_actuals.push((target, actual.span));
        Ok(Item::Signal {
            id: port,
            ty: sub.ty.clone(),
        })
    }

    /// Once every process is known: an actual converted from an `out` port has that port as
    /// its only source (for an unresolved signal VHDL allows no other; for a resolved one
    /// vams does not combine them yet).
    pub(crate) fn check_converted_actuals(&mut self) {
        if self.signals.converted_actuals.is_empty() {
            return;
        }
        let root = |d: &vams_design::Design, s: SignalId| match d.signals[s.index()].kind {
            SignalKind::View { parent, .. } => parent,
            _ => s,
        };
        for (signal, span) in std::mem::take(&mut self.signals.converted_actuals) {
            let driver = self.design.processes.iter().find(|p| {
                self.design
                    .assignments(&p.code)
                    .into_iter()
                    .any(|(t, _)| root(&self.design, t) == signal)
            });
            if let Some(p) = driver {
                let (name, process) = (
                    self.design.signals[signal.index()].name.clone(),
                    p.name.clone(),
                );
                self.error(ElabError::invalid(
                    span,
                    format!(
                        "`{name}` takes its value from this converted port and is also driven by process `{process}`"
                    ),
                    Some("give the port's value a signal of its own and combine the two in one process".into()),
                ));
            }
        }
    }
}
