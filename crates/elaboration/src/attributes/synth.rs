//! Building blocks for what elaboration generates behind the AMS attributes (`'ltf`, `'zoh`,
//! `'ztf`, `'ramp`, `'slew`, `'delayed`): implicit signals, auxiliary quantities, equations
//! and the attributes' static arguments; the expression constructors are the design's
//! (`vams_design::build`), re-exported here.

use vams_design::Value;
use vams_design::{Equation, Expr, QuantityId, Signal, SignalId, SignalKind, Type};
use vams_syntax::ast;
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::names::scope::Scope;
use crate::names::types::Ty;
use crate::{Elab, R};

pub(crate) use vams_design::build::{
    abs, add, bin, cond, div, linear, mul, now_seconds, real, sub,
};

/// One positional argument of an attribute, if given.
pub(crate) fn arg(args: &[ast::Assoc], i: usize) -> Option<&ast::Expr> {
    match args.get(i) {
        Some(ast::Assoc {
            actual: ast::Actual::Expr(e),
            ..
        }) => Some(e),
        _ => None,
    }
}

impl<'a> Elab<'a> {
    /// A static real argument of attribute `attr`.
    pub(crate) fn static_real(&mut self, sc: &Scope<'a>, e: &ast::Expr, what: &str) -> R<f64> {
        match self.static_value(sc, e, &Ty::Real, what)? {
            Value::Real(v) => Ok(v),
            _ => Err(self.error(ElabError::invalid(
                e.span,
                format!("{what} must be a real"),
                None,
            ))),
        }
    }

    /// A static `real_vector` of coefficients (a single real counts as a one-element vector).
    pub(crate) fn coefficients(
        &mut self,
        sc: &Scope<'a>,
        e: &ast::Expr,
        what: &str,
    ) -> R<Vec<f64>> {
        let want = self.standard_type("real_vector");
        let t = self.expr(sc, e, want.as_ref())?;
        let bad = |this: &mut Self, message: String| {
            this.error(ElabError::invalid(
                e.span,
                message,
                Some(
                    "give a constant real_vector in ascending powers, e.g. \
                     `constant den : real_vector := (1.0, 1.0e-3);`"
                        .into(),
                ),
            ))
        };
        match t.e {
            Expr::Const(Value::Real(v)) => Ok(vec![v]),
            Expr::Const(Value::Array(items)) => {
                let mut out = Vec::with_capacity(items.len());
                for item in items {
                    match item {
                        Value::Real(v) => out.push(v),
                        _ => return Err(bad(self, format!("{what} must be a vector of reals"))),
                    }
                }
                if out.is_empty() {
                    return Err(bad(self, format!("{what} is empty")));
                }
                Ok(out)
            }
            Expr::Const(_) => Err(bad(self, format!("{what} must be a real_vector"))),
            _ => Err(self.error(ElabError::NotStatic {
                span: e.span,
                what: what.to_string(),
            })),
        }
    }

    /// A real signal that a generated process drives.
    pub(crate) fn implicit_signal(&mut self, name: String, init: f64, span: Span) -> SignalId {
        let id = SignalId(self.design.signals.len() as u32);
        self.design.signals.push(Signal {
            range: None,
            name,
            ty: Type::Real,
            init: Value::Real(init),
            kind: SignalKind::Implicit,
            span,
            resolution: None,
            guarded: None,
        });
        id
    }

    /// A generated equation `residual = 0`, listed as `text`.
    pub(crate) fn generated_equation(&mut self, residual: Expr, span: Span, text: String) {
        self.design.equations.push(Equation {
            residual,
            span,
            instance: self.here.instance.clone(),
            text,
        });
    }

    /// The name of quantity `q`, for generated names and listings.
    pub(crate) fn qname(&self, q: QuantityId) -> String {
        self.design.quantities[q.index()].name.clone()
    }
}
