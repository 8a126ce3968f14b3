//! Inlining of user functions into equations: the analog engine differentiates expression
//! trees, so a function called in a simultaneous statement is replaced by its body when that
//! body is straight-line (variable assignments, then `return`): each variable is substituted by
//! the expression last assigned to it.

use crate::design::{Design, Expr, Instr};
use crate::source::Span;

use super::error::ElabError;
use super::{Elab, R};

/// Deepest nesting of inlined calls (a straight-line function that calls itself never ends).
const MAX_INLINE_DEPTH: usize = 32;

/// Why a call could not be inlined: the function's name and the reason.
#[derive(Debug, PartialEq)]
pub(super) struct NotInlinable {
    pub name: String,
    pub reason: &'static str,
}

/// `e` with every `FnCall` replaced by its function's body.
pub(super) fn inline(design: &Design, e: &Expr, depth: usize) -> Result<Expr, NotInlinable> {
    let go = |e: &Expr| inline(design, e, depth);
    let b = |e: &Expr| go(e).map(Box::new);
    Ok(match e {
        Expr::FnCall { sub, args, .. } => {
            let Some(f) = design.subprograms.get(sub.index()) else {
                return Err(NotInlinable {
                    name: String::new(),
                    reason: "it is not in the design",
                });
            };
            let fail = |reason| NotInlinable {
                name: f.name.clone(),
                reason,
            };
            if depth >= MAX_INLINE_DEPTH {
                return Err(fail("it calls itself"));
            }
            let mut frame: Vec<Expr> = args.iter().map(&go).collect::<Result<_, _>>()?;
            // A function whose body was not lowered (its package body failed, or it has
            // none) has no variables for its parameters yet.
            let Some(locals) = f.vars.get(frame.len()..) else {
                return Err(fail("its body could not be elaborated"));
            };
            frame.extend(locals.iter().map(|v| Expr::Const(v.init.clone())));
            for instr in &f.code {
                match instr {
                    Instr::SetVar { var, value } => {
                        let v = substitute(value, &frame);
                        frame[var.index()] = v;
                    }
                    Instr::Return(Some(r)) => {
                        return inline(design, &substitute(r, &frame), depth + 1);
                    }
                    _ => {
                        return Err(fail(
                            "its body is not straight-line (branches, loops, element assignments or reports)",
                        ));
                    }
                }
            }
            return Err(fail("its body does not end in a return"));
        }
        Expr::Const(_)
        | Expr::Quantity(_)
        | Expr::Dot(_)
        | Expr::Signal(_)
        | Expr::Var(_)
        | Expr::Now
        | Expr::SignalAttr(..) => e.clone(),
        Expr::Unary(op, a) => Expr::Unary(*op, b(a)?),
        Expr::Binary(op, l, r) => Expr::Binary(*op, b(l)?, b(r)?),
        Expr::Call(f, args) => Expr::Call(*f, args.iter().map(go).collect::<Result<_, _>>()?),
        Expr::If(c, x, y) => Expr::If(b(c)?, b(x)?, b(y)?),
        Expr::Index { array, index, ty } => Expr::Index {
            array: b(array)?,
            index: b(index)?,
            ty: ty.clone(),
        },
        Expr::Image(ty, x) => Expr::Image(ty.clone(), b(x)?),
    })
}

/// `e` with each `Var(v)` replaced by `frame[v]`.
fn substitute(e: &Expr, frame: &[Expr]) -> Expr {
    let s = |e: &Expr| Box::new(substitute(e, frame));
    match e {
        Expr::Var(v) => frame.get(v.index()).cloned().unwrap_or_else(|| e.clone()),
        Expr::Const(_)
        | Expr::Quantity(_)
        | Expr::Dot(_)
        | Expr::Signal(_)
        | Expr::Now
        | Expr::SignalAttr(..) => e.clone(),
        Expr::Unary(op, a) => Expr::Unary(*op, s(a)),
        Expr::Binary(op, l, r) => Expr::Binary(*op, s(l), s(r)),
        Expr::Call(f, args) => Expr::Call(*f, args.iter().map(|a| substitute(a, frame)).collect()),
        Expr::FnCall { sub, args, signals } => Expr::FnCall {
            sub: *sub,
            args: args.iter().map(|a| substitute(a, frame)).collect(),
            signals: signals.clone(),
        },
        Expr::If(c, x, y) => Expr::If(s(c), s(x), s(y)),
        Expr::Index { array, index, ty } => Expr::Index {
            array: s(array),
            index: s(index),
            ty: ty.clone(),
        },
        Expr::Image(ty, x) => Expr::Image(ty.clone(), s(x)),
    }
}

impl Elab<'_> {
    /// `e` (an equation's expression) with its function calls inlined, or a diagnostic at
    /// `span` naming the function that cannot be.
    pub(super) fn inline_calls(&mut self, e: Expr, span: Span) -> R<Expr> {
        let mut has_call = false;
        e.visit(&mut |x| has_call |= matches!(x, Expr::FnCall { .. }));
        if !has_call {
            return Ok(e);
        }
        match inline(&self.design, &e, 0) {
            Ok(e) => Ok(e),
            Err(NotInlinable { name, reason }) => Err(self.error(ElabError::invalid(
                span,
                format!("the function `{name}` cannot be used in a simultaneous statement: {reason}"),
                Some("equations inline functions whose body is constant and variable declarations, variable assignments and one final `return`; write the expression inline, or compute the value in a process".into()),
            ))),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::design::{
        BinaryOp, ParamMode, QuantityId, Subprogram, SubprogramId, SubprogramKind, Type, Value,
        VarId, Variable,
    };
    use crate::source::Span;

    fn var(name: &str) -> Variable {
        Variable {
            name: name.into(),
            ty: Type::Real,
            init: Value::Real(0.0),
        }
    }

    fn function(code: Vec<Instr>) -> Design {
        Design {
            subprograms: vec![Subprogram {
                name: "f".into(),
                kind: SubprogramKind::Function,
                params: vec![ParamMode::In],
                vars: vec![var("t"), var("k")],
                code,
                span: Span::default(),
            }],
            ..Design::default()
        }
    }

    fn mul(a: Expr, b: Expr) -> Expr {
        Expr::Binary(BinaryOp::Mul, Box::new(a), Box::new(b))
    }

    #[test]
    fn straight_line_body_is_substituted() {
        // k := 2 * t; return k * t;   called with q0  ->  (2 * q0) * q0
        let d = function(vec![
            Instr::SetVar {
                var: VarId(1),
                value: mul(Expr::real(2.0), Expr::Var(VarId(0))),
            },
            Instr::Return(Some(mul(Expr::Var(VarId(1)), Expr::Var(VarId(0))))),
        ]);
        let q = Expr::Quantity(QuantityId(0));
        let call = Expr::FnCall {
            sub: SubprogramId(0),
            args: vec![q.clone()],
            signals: vec![],
        };
        let want = mul(mul(Expr::real(2.0), q.clone()), q);
        assert_eq!(inline(&d, &call, 0), Ok(want));
    }

    #[test]
    fn branches_and_self_calls_are_refused() {
        let call = Expr::FnCall {
            sub: SubprogramId(0),
            args: vec![Expr::real(1.0)],
            signals: vec![],
        };
        let branchy = function(vec![Instr::Jump(0), Instr::Return(Some(Expr::real(1.0)))]);
        let err = inline(&branchy, &call, 0).unwrap_err();
        assert!(err.reason.contains("straight-line"), "{err:?}");
        let recursive = function(vec![Instr::Return(Some(call.clone()))]);
        let err = inline(&recursive, &call, 0).unwrap_err();
        assert_eq!(err.reason, "it calls itself");
    }
}
