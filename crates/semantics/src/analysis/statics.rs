//! The staticness of expressions (LRM 7.4): locally static (known when the unit is analysed),
//! globally static (known once the design is elaborated), or neither.
//!
//! Computed from the names analysis resolved in the current unit, bottom-up and memoised per
//! expression span, so marking every analysed expression costs one visit each. The rules err
//! towards "not static": an expression is marked only when the LRM's rules certainly make it
//! so (calls of functions whose purity is unknown, attributes of objects, and whatever analysis
//! could not resolve are left unmarked).

use vams_syntax::ast::{Actual, Assoc, Expr, ExprKind, Literal};
use vams_syntax::source::Span;

use super::scope::{DeclKind, Purity, Staticness};
use super::units::Analyzer;

impl Analyzer<'_> {
    /// How static `e` is; its names must have been analysed (resolved) already.
    pub fn staticness(&mut self, e: &Expr) -> Staticness {
        if let Some(&s) = self.static_memo.get(&e.span) {
            return s;
        }
        let s = match &e.kind {
            ExprKind::Literal(Literal::Null) => Staticness::None,
            ExprKind::Literal(_) => Staticness::Local,
            ExprKind::Name(id) | ExprKind::Selected(_, id) => self.name_staticness(id.span),
            ExprKind::Paren(x) | ExprKind::Qualified(_, x) => self.staticness(x),
            ExprKind::Unary(_, x) => {
                let operand = self.staticness(x);
                self.operator_staticness(e.span, operand)
            }
            ExprKind::Binary(_, l, r) => {
                let operands = self.staticness(l).min(self.staticness(r));
                self.operator_staticness(e.span, operands)
            }
            ExprKind::Apply(prefix, args) => self.apply_staticness(prefix, args),
            ExprKind::Attribute(prefix, _) => self.attribute_staticness(prefix),
            // A literal or subprogram named with its signature.
            ExprKind::Signed(..) => Staticness::Local,
            // An aggregate of globally static elements is globally static (LRM 7.4.2 (h)).
            ExprKind::Aggregate(elements) => elements
                .iter()
                .map(|el| self.staticness(&el.value))
                .fold(Staticness::Global, Staticness::min),
            ExprKind::New(_) => Staticness::None,
        };
        self.static_memo.insert(e.span, s);
        s
    }

    /// A simple or selected name: what its declaration's value is.
    fn name_staticness(&self, span: Span) -> Staticness {
        let Some(&d) = self.ref_at.get(&span) else {
            return Staticness::None;
        };
        match &self.out.decl(d).kind {
            DeclKind::Object { value, .. } => *value,
            DeclKind::EnumLiteral(_) | DeclKind::Unit(_) => Staticness::Local,
            // A parameterless call (`now`, a pure constant function).
            DeclKind::Subprogram(sig) => call(sig.purity, Staticness::Local),
            _ => Staticness::None,
        }
    }

    /// An operator whose operands are `operands` static: a predefined one keeps that, a pure
    /// user-defined one is at most globally static.
    fn operator_staticness(&self, span: Span, operands: Staticness) -> Staticness {
        match self.ref_at.get(&span).map(|&d| &self.out.decl(d).kind) {
            Some(DeclKind::Subprogram(sig)) => call(sig.purity, operands),
            _ => Staticness::None,
        }
    }

    /// `prefix(args)`: a call, a type conversion, an indexed name or an attribute with
    /// arguments.
    fn apply_staticness(&mut self, prefix: &Expr, args: &[Assoc]) -> Staticness {
        let mut actuals = Staticness::Local;
        for a in args {
            actuals = actuals.min(match &a.actual {
                Actual::Expr(x) => self.staticness(x),
                Actual::Range(_) | Actual::Open(_) => Staticness::None,
            });
        }
        if let ExprKind::Attribute(p, _) = &prefix.kind {
            return self.attribute_staticness(p).min(actuals);
        }
        let Some(span) = prefix.name_ident().map(|id| id.span) else {
            return Staticness::None;
        };
        let Some(&d) = self.ref_at.get(&span) else {
            return Staticness::None;
        };
        match &self.out.decl(d).kind {
            DeclKind::Subprogram(sig) => call(sig.purity, actuals),
            // A conversion to a type: as static as its operand (LRM 7.4.1 (g), 7.4.2 (d)).
            DeclKind::Type(_) => actuals,
            // An indexed name of a static array (LRM 7.4.2 (e)): globally static at most.
            DeclKind::Object { value, .. } => (*value).min(actuals).min(Staticness::Global),
            _ => Staticness::None,
        }
    }

    /// `prefix'attribute`: a value attribute of a type is globally static (locally when the
    /// type's bounds are, LRM 7.4.1 (e), which analysis does not track yet: a subtype's
    /// bounds may be generics); an attribute of an object (a signal's `'event`, a quantity's
    /// `'dot`, an array's `'length`) is not marked.
    fn attribute_staticness(&self, prefix: &Expr) -> Staticness {
        let Some(span) = prefix.name_ident().map(|id| id.span) else {
            return Staticness::None;
        };
        match self.ref_at.get(&span).map(|&d| &self.out.decl(d).kind) {
            Some(DeclKind::Type(_)) => Staticness::Global,
            _ => Staticness::None,
        }
    }
}

impl Analyzer<'_> {
    /// Reports the first name in `e` (an analysed expression) whose value only the simulation
    /// knows (a signal, a variable, a quantity, a loop or subprogram parameter), where the LRM
    /// asks for a `required` static expression as `what`. Only such names are reported: they
    /// make any expression non-static, whatever the standard's revision, so the diagnostic is
    /// certain (constants initialised by calls are locally static in some revisions only).
    pub fn require_static(&mut self, e: &Expr, what: &'static str, required: Staticness) {
        if let Some((span, name)) = self.dynamic_name(e) {
            let (required, help) = match required {
                Staticness::Local => (
                    "locally static",
                    "use literals, or constants declared with literal values",
                ),
                _ => (
                    "globally static",
                    "use literals, constants and generics (a signal's or variable's value is known only as the design runs)",
                ),
            };
            self.error(super::AnalysisError::NotStatic {
                span,
                what,
                required,
                name,
                help: Some(help.into()),
            });
        }
    }

    fn dynamic_name(&self, e: &Expr) -> Option<(Span, String)> {
        match &e.kind {
            ExprKind::Name(id) | ExprKind::Selected(_, id) => {
                let d = *self.ref_at.get(&id.span)?;
                match self.out.decl(d).kind {
                    DeclKind::Object {
                        value: Staticness::None,
                        ..
                    } => Some((id.span, id.name.clone())),
                    _ => None,
                }
            }
            ExprKind::Apply(prefix, args) => {
                if !matches!(prefix.kind, ExprKind::Attribute(..)) {
                    if let Some(found) = self.dynamic_name(prefix) {
                        return Some(found);
                    }
                }
                args.iter().find_map(|a| match &a.actual {
                    Actual::Expr(x) => self.dynamic_name(x),
                    _ => None,
                })
            }
            ExprKind::Paren(x) | ExprKind::Qualified(_, x) | ExprKind::Unary(_, x) => {
                self.dynamic_name(x)
            }
            ExprKind::Binary(_, l, r) => self.dynamic_name(l).or_else(|| self.dynamic_name(r)),
            ExprKind::Aggregate(elements) => {
                elements.iter().find_map(|el| self.dynamic_name(&el.value))
            }
            // An attribute's prefix is not read (`s'length` of a signal is static).
            ExprKind::Attribute(..)
            | ExprKind::Signed(..)
            | ExprKind::Literal(_)
            | ExprKind::New(_) => None,
        }
    }
}

/// A call of a subprogram of `purity` with actuals that are `actuals` static.
fn call(purity: Purity, actuals: Staticness) -> Staticness {
    match purity {
        Purity::Predefined => actuals,
        Purity::Pure => actuals.min(Staticness::Global),
        Purity::Impure => Staticness::None,
    }
}
