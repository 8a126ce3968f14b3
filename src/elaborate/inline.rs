//! Inlining of user functions into equations: the analog engine differentiates expression
//! trees, so a function called in a simultaneous statement is replaced by what its body
//! computes, as an expression of its actual arguments. The body is executed symbolically:
//! each variable holds an expression (folded to a constant where its operands are static), a
//! condition that folds decides the way on, and one that depends on a quantity (or `now`, or a
//! signal) forks into both ways, joined as `Expr::If`. So `if`, `case`, loops with static
//! bounds or static exits, early `return`s and element assignments of local arrays with static
//! values expand; a loop whose exit depends on a quantity expands one level of `if` per
//! iteration it can take (a binary search over a table of n points: about 2 log2 n levels). The
//! analog engine evaluates only the branch taken, and differentiates it exactly.

use crate::design::{Design, Expr, Instr, Subprogram, Type, Value};
use crate::source::Span;

use super::error::ElabError;
use super::fold::fold;
use super::{Elab, R};

/// Deepest nesting of inlined calls (a function that calls itself with operands that do not
/// fold never ends).
const MAX_INLINE_DEPTH: usize = 32;

/// Instructions executed over every path of one equation's calls: enough for a loop over a
/// table of a few thousand points, or a binary search over a million; beyond it, the function
/// is refused rather than expanded into an equation too large to evaluate.
const MAX_STEPS: usize = 50_000;

/// Conditions open at once on one path (each is a level of recursion here): a linear search
/// through a table of this many points.
const MAX_OPEN_BRANCHES: usize = 256;

/// Why a call could not be inlined: the function's name and the reason.
#[derive(Debug, PartialEq)]
pub(super) struct NotInlinable {
    pub name: String,
    pub reason: String,
}

/// `e` with every `FnCall` replaced by what its function computes.
pub(super) fn inline(design: &Design, e: &Expr, depth: usize) -> Result<Expr, NotInlinable> {
    Expander {
        design,
        steps: 0,
        open: 0,
    }
    .expr(e, depth)
}

struct Expander<'d> {
    design: &'d Design,
    steps: usize,
    /// Conditions forked and not yet joined on the current path.
    open: usize,
}

impl Expander<'_> {
    fn expr(&mut self, e: &Expr, depth: usize) -> Result<Expr, NotInlinable> {
        let design = self.design;
        let mut go = |e: &Expr| self.expr(e, depth);
        Ok(match e {
            Expr::FnCall { sub, args, .. } => {
                let Some(f) = design.subprograms.get(sub.index()) else {
                    return Err(NotInlinable {
                        name: String::new(),
                        reason: "it is not in the design".into(),
                    });
                };
                if depth >= MAX_INLINE_DEPTH {
                    return Err(refuse(f, "it calls itself"));
                }
                let mut frame: Vec<Expr> = args.iter().map(&mut go).collect::<Result<_, _>>()?;
                // A function whose body was not lowered (its package body failed, or it has
                // none) has no variables for its parameters yet.
                let Some(locals) = f.vars.get(frame.len()..) else {
                    return Err(refuse(f, "its body could not be elaborated"));
                };
                frame.extend(locals.iter().map(|v| Expr::Const(v.init.clone())));
                self.run(f, 0, frame, depth + 1)?
            }
            Expr::Const(_)
            | Expr::Quantity(_)
            | Expr::Dot(_)
            | Expr::Signal(_)
            | Expr::Var(_)
            | Expr::Now
            | Expr::SignalAttr(..) => e.clone(),
            Expr::Unary(op, a) => Expr::Unary(*op, Box::new(go(a)?)),
            Expr::Binary(op, l, r) => Expr::Binary(*op, Box::new(go(l)?), Box::new(go(r)?)),
            Expr::Call(f, args) => Expr::Call(*f, args.iter().map(go).collect::<Result<_, _>>()?),
            Expr::If(c, x, y) => Expr::If(Box::new(go(c)?), Box::new(go(x)?), Box::new(go(y)?)),
            Expr::Index { array, index, ty } => Expr::Index {
                array: Box::new(go(array)?),
                index: Box::new(go(index)?),
                ty: ty.clone(),
            },
            Expr::Image(ty, x) => Expr::Image(ty.clone(), Box::new(go(x)?)),
        })
    }

    /// `e` in `frame`, its calls inlined, folded where static.
    fn value(
        &mut self,
        f: &Subprogram,
        e: &Expr,
        frame: &[Expr],
        depth: usize,
    ) -> Result<Expr, NotInlinable> {
        let e = self.expr(&substitute(e, frame), depth)?;
        fold_parts(e).map_err(|m| NotInlinable {
            name: f.name.clone(),
            reason: m,
        })
    }

    /// The result of `f` from instruction `pc` with its variables at `frame`.
    fn run(
        &mut self,
        f: &Subprogram,
        mut pc: usize,
        mut frame: Vec<Expr>,
        depth: usize,
    ) -> Result<Expr, NotInlinable> {
        loop {
            self.steps += 1;
            if self.steps > MAX_STEPS || self.open > MAX_OPEN_BRANCHES {
                return Err(refuse(
                    f,
                    "a loop in it runs a number of times that depends on a quantity, or its branches multiply beyond what an equation can hold",
                ));
            }
            let Some(instr) = f.code.get(pc) else {
                return Err(refuse(f, "its body does not end in a return"));
            };
            match instr {
                Instr::SetVar { var, value } => {
                    let v = self.value(f, value, &frame, depth)?;
                    frame[var.index()] = v;
                    pc += 1;
                }
                Instr::SetVarElement { var, index, value } => {
                    let i = self.value(f, index, &frame, depth)?;
                    let v = self.value(f, value, &frame, depth)?;
                    let ty = f.vars.get(var.index()).map(|v| &v.ty);
                    set_element(&mut frame[var.index()], ty, &i, v)
                        .map_err(|reason| refuse(f, reason))?;
                    pc += 1;
                }
                Instr::Jump(target) => pc = *target,
                Instr::JumpIfNot { cond, target } => match self.value(f, cond, &frame, depth)? {
                    Expr::Const(Value::Boolean(true)) => pc += 1,
                    Expr::Const(Value::Boolean(false)) => pc = *target,
                    c => {
                        self.open += 1;
                        let then = self.run(f, pc + 1, frame.clone(), depth);
                        let other =
                            then.and_then(|then| Ok((then, self.run(f, *target, frame, depth)?)));
                        self.open -= 1;
                        let (then, other) = other?;
                        return Ok(Expr::If(Box::new(c), Box::new(then), Box::new(other)));
                    }
                },
                Instr::Assert { cond, .. } => {
                    // An assertion that holds statically costs nothing; one that depends on
                    // the operands is not checked in an equation (see the README).
                    if let Some(c) = cond {
                        let c = self.value(f, c, &frame, depth)?;
                        if c == Expr::Const(Value::Boolean(false)) {
                            return Err(refuse(
                                f,
                                "one of its assertions fails for these arguments",
                            ));
                        }
                    }
                    pc += 1;
                }
                Instr::Return(Some(r)) => return self.value(f, r, &frame, depth),
                _ => {
                    return Err(refuse(
                        f,
                        "it assigns a signal, waits, stops the simulation or calls a procedure",
                    ));
                }
            }
        }
    }
}

/// `e` with every static part folded (an element of a constant table at a static index, the
/// branch of an `if` whose condition is static), bottom-up; the untaken branch of a static
/// condition is dropped unevaluated.
fn fold_parts(e: Expr) -> Result<Expr, String> {
    let part = |e: Box<Expr>| fold_parts(*e).map(Box::new);
    let e = match e {
        Expr::Unary(op, a) => Expr::Unary(op, part(a)?),
        Expr::Binary(op, l, r) => Expr::Binary(op, part(l)?, part(r)?),
        Expr::Call(f, args) => Expr::Call(
            f,
            args.into_iter().map(fold_parts).collect::<Result<_, _>>()?,
        ),
        Expr::If(c, x, y) => match fold_parts(*c)? {
            Expr::Const(Value::Boolean(true)) => return fold_parts(*x),
            Expr::Const(Value::Boolean(false)) => return fold_parts(*y),
            c => Expr::If(Box::new(c), part(x)?, part(y)?),
        },
        Expr::Index { array, index, ty } => Expr::Index {
            array: part(array)?,
            index: part(index)?,
            ty,
        },
        Expr::Image(ty, x) => Expr::Image(ty, part(x)?),
        other => other,
    };
    fold(e)
}

fn refuse(f: &Subprogram, reason: &str) -> NotInlinable {
    NotInlinable {
        name: f.name.clone(),
        reason: reason.into(),
    }
}

/// `array(index) := value` on a local array whose value is static, with its type's bounds.
fn set_element(
    array: &mut Expr,
    ty: Option<&Type>,
    index: &Expr,
    value: Expr,
) -> Result<(), &'static str> {
    let (
        Expr::Const(Value::Array(elements)),
        Some(Type::Array {
            left, ascending, ..
        }),
        Expr::Const(Value::Integer(i)),
        Expr::Const(v),
    ) = (array, ty, index, value)
    else {
        return Err(
            "it assigns an element of an array at an index, or a value, that depends on a quantity",
        );
    };
    let pos = if *ascending { i - left } else { left - i };
    match usize::try_from(pos).ok().and_then(|p| elements.get_mut(p)) {
        Some(slot) => {
            *slot = v;
            Ok(())
        }
        None => Err("it assigns an array element outside the array's bounds"),
    }
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
                Some("equations expand a function's body for its arguments: variable assignments, `if`, `case`, loops and `return`, with arrays indexed and loops bounded by what is known before the run or reached through a few branches; compute anything else in a process".into()),
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

    fn gt(a: Expr, b: Expr) -> Expr {
        Expr::Binary(BinaryOp::Gt, Box::new(a), Box::new(b))
    }

    fn call_with(arg: Expr) -> Expr {
        Expr::FnCall {
            sub: SubprogramId(0),
            args: vec![arg],
            signals: vec![],
        }
    }

    #[test]
    fn a_branch_on_an_operand_becomes_a_conditional_expression() {
        // if t > 1.0 then return 1.0; end if; return t;   (a saturation)
        let d = function(vec![
            Instr::JumpIfNot {
                cond: gt(Expr::Var(VarId(0)), Expr::real(1.0)),
                target: 2,
            },
            Instr::Return(Some(Expr::real(1.0))),
            Instr::Return(Some(Expr::Var(VarId(0)))),
        ]);
        let q = Expr::Quantity(QuantityId(0));
        let want = Expr::If(
            Box::new(gt(q.clone(), Expr::real(1.0))),
            Box::new(Expr::real(1.0)),
            Box::new(q.clone()),
        );
        assert_eq!(inline(&d, &call_with(q), 0), Ok(want));
        // With a static operand the branch is decided and nothing is left but the value.
        assert_eq!(
            inline(&d, &call_with(Expr::real(3.0)), 0),
            Ok(Expr::real(1.0))
        );
    }

    #[test]
    fn a_loop_with_static_bounds_unrolls() {
        // k := 0; loop: if not k < 3 goto end; t := t * 2; k := k + 1; goto loop; end: return t
        let int = |i| Expr::Const(Value::Integer(i));
        let d = function(vec![
            Instr::SetVar {
                var: VarId(1),
                value: int(0),
            },
            Instr::JumpIfNot {
                cond: Expr::Binary(
                    BinaryOp::Lt,
                    Box::new(Expr::Var(VarId(1))),
                    Box::new(int(3)),
                ),
                target: 5,
            },
            Instr::SetVar {
                var: VarId(0),
                value: mul(Expr::Var(VarId(0)), Expr::real(2.0)),
            },
            Instr::SetVar {
                var: VarId(1),
                value: Expr::Binary(
                    BinaryOp::Add,
                    Box::new(Expr::Var(VarId(1))),
                    Box::new(int(1)),
                ),
            },
            Instr::Jump(1),
            Instr::Return(Some(Expr::Var(VarId(0)))),
        ]);
        let q = Expr::Quantity(QuantityId(0));
        let want = mul(
            mul(mul(q.clone(), Expr::real(2.0)), Expr::real(2.0)),
            Expr::real(2.0),
        );
        assert_eq!(inline(&d, &call_with(q), 0), Ok(want));
    }

    #[test]
    fn endless_loops_and_self_calls_are_refused() {
        let endless = function(vec![Instr::Jump(0), Instr::Return(Some(Expr::real(1.0)))]);
        let err = inline(&endless, &call_with(Expr::real(1.0)), 0).unwrap_err();
        assert!(err.reason.contains("depends on a quantity"), "{err:?}");
        // A loop whose exit depends on the operand forks at every iteration: refused once the
        // paths outgrow the budget, not expanded forever.
        let unbounded = function(vec![
            Instr::JumpIfNot {
                cond: gt(Expr::Var(VarId(0)), Expr::real(0.0)),
                target: 3,
            },
            Instr::SetVar {
                var: VarId(0),
                value: mul(Expr::Var(VarId(0)), Expr::real(0.5)),
            },
            Instr::Jump(0),
            Instr::Return(Some(Expr::Var(VarId(0)))),
        ]);
        let q = Expr::Quantity(QuantityId(0));
        let err = inline(&unbounded, &call_with(q), 0).unwrap_err();
        assert!(err.reason.contains("depends on a quantity"), "{err:?}");
        let call = call_with(Expr::Quantity(QuantityId(0)));
        let recursive = function(vec![Instr::Return(Some(call.clone()))]);
        let err = inline(&recursive, &call, 0).unwrap_err();
        assert_eq!(err.reason, "it calls itself");
    }
}
