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

use vams_design::{BinaryOp, Design, Expr, Instr, Subprogram, Type, UnaryOp, Value, VarId};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::expressions::fold::fold;
use crate::{Elab, R};

/// Deepest nesting of inlined calls (a function that calls itself with operands that do not
/// fold never ends).
const MAX_INLINE_DEPTH: usize = 32;

/// Instructions executed over every path of one equation's calls: enough for a loop over a
/// table of a few thousand points, or a binary search over a million; beyond it, the function
/// is refused rather than expanded into an equation too large to evaluate.
const MAX_STEPS: usize = 50_000;

/// Conditions open at once on one path (each is a level of recursion here, a few kilobytes
/// of stack in a debug build): a linear search through a table of this many points, a binary
/// search through any table.
const MAX_OPEN_BRANCHES: usize = 64;

/// Why a call could not be inlined: the function's name and the reason.
#[derive(Debug, PartialEq)]
pub(crate) struct NotInlinable {
    pub name: String,
    pub reason: String,
    /// The assertion of severity error or failure that fails for the call's arguments, if
    /// that is the reason: then no evaluation at any time could give a value.
    pub failed_assertion: Option<Span>,
}

/// `e` with every `FnCall` replaced by what its function computes.
pub(crate) fn inline(design: &Design, e: &Expr, depth: usize) -> Result<Expr, NotInlinable> {
    Expander::new(design, Vec::new()).expr(e, depth)
}

/// What the body of a simultaneous procedural statement, lowered as `body` (a procedure
/// without parameters), leaves in each of `outputs` (the variables standing for the
/// quantities it assigns), starting from `frame`.
pub(crate) fn procedural_values(
    design: &Design,
    body: &Subprogram,
    frame: &[Expr],
    outputs: &[VarId],
) -> Result<Vec<Expr>, NotInlinable> {
    Expander::new(design, outputs.to_vec()).run(body, 0, frame.to_vec(), PROCEDURAL)
}

/// The call depth of a procedural's own body (functions it calls run deeper).
const PROCEDURAL: usize = 0;

/// The value of `e` when its user function calls, executed for their arguments, leave it
/// static (a constant initialised by a pure function of constants: `time2real(t_step)`).
pub(crate) fn static_call_value(design: &Design, e: &Expr) -> Option<Value> {
    static_call(design, e).ok()
}

/// [`static_call_value`], or why not: `Some` when an assertion of the function fails for
/// these arguments (an error of the model, not a limit of vams).
pub(crate) fn static_call(design: &Design, e: &Expr) -> Result<Value, Option<NotInlinable>> {
    match inline(design, e, 0).map(|e| fold_parts(&e)) {
        Ok(Ok(Expr::Const(v))) => Ok(v),
        Err(refusal) if refusal.failed_assertion.is_some() => Err(Some(refusal)),
        _ => Err(None),
    }
}

struct Expander<'d> {
    design: &'d Design,
    steps: usize,
    /// Conditions forked and not yet joined on the current path.
    open: usize,
    /// What the conditions taken on the current path say about the operands (`x > 1.0` on
    /// one branch, `x <= 1.0` on the other): a later comparison they decide is not forked,
    /// so a table lookup does not expand paths that no operand can take (where an index runs
    /// off the table).
    facts: Vec<Comparison>,
    /// For a procedural: the variables whose values at the end of the body are its results.
    outputs: Vec<VarId>,
}

impl<'d> Expander<'d> {
    fn new(design: &'d Design, outputs: Vec<VarId>) -> Expander<'d> {
        Expander {
            design,
            steps: 0,
            open: 0,
            facts: Vec::new(),
            outputs,
        }
    }
}

/// `e op bound`, `op` one of `<`, `<=`, `>`, `>=`.
#[derive(Clone, Debug, PartialEq)]
struct Comparison {
    e: Expr,
    op: BinaryOp,
    bound: f64,
}

impl Comparison {
    /// `c` as `e op bound` with a numeric constant on one side.
    fn of(c: &Expr) -> Option<Comparison> {
        let number = |e: &Expr| match e {
            Expr::Const(Value::Real(x)) => Some(*x),
            Expr::Const(Value::Integer(i)) => Some(*i as f64),
            _ => None,
        };
        match c {
            Expr::Unary(UnaryOp::Not, inner) => Comparison::of(inner).map(|c| c.negated()),
            Expr::Binary(
                op @ (BinaryOp::Lt | BinaryOp::Le | BinaryOp::Gt | BinaryOp::Ge),
                a,
                b,
            ) => match (number(a), number(b)) {
                (None, Some(bound)) => Some(Comparison {
                    e: (**a).clone(),
                    op: *op,
                    bound,
                }),
                (Some(bound), None) => Some(Comparison {
                    e: (**b).clone(),
                    op: match op {
                        BinaryOp::Lt => BinaryOp::Gt,
                        BinaryOp::Le => BinaryOp::Ge,
                        BinaryOp::Gt => BinaryOp::Lt,
                        _ => BinaryOp::Le,
                    },
                    bound,
                }),
                _ => None,
            },
            _ => None,
        }
    }

    fn negated(self) -> Comparison {
        let op = match self.op {
            BinaryOp::Lt => BinaryOp::Ge,
            BinaryOp::Le => BinaryOp::Gt,
            BinaryOp::Gt => BinaryOp::Le,
            _ => BinaryOp::Lt,
        };
        Comparison { op, ..self }
    }

    /// Whether `facts` make this comparison always true or always false.
    fn decided_by(&self, facts: &[Comparison]) -> Option<bool> {
        // The interval of `e`: (lo, lo closed), (hi, hi closed).
        let (mut lo, mut lo_closed) = (f64::NEG_INFINITY, false);
        let (mut hi, mut hi_closed) = (f64::INFINITY, false);
        for f in facts.iter().filter(|f| f.e == self.e) {
            let v = f.bound;
            match f.op {
                BinaryOp::Lt if v < hi || (v == hi && hi_closed) => (hi, hi_closed) = (v, false),
                BinaryOp::Le if v < hi => (hi, hi_closed) = (v, true),
                BinaryOp::Gt if v > lo || (v == lo && lo_closed) => (lo, lo_closed) = (v, false),
                BinaryOp::Ge if v > lo => (lo, lo_closed) = (v, true),
                _ => {}
            }
        }
        let c = self.bound;
        // Always below c (or at most c), always above c (or at least c).
        let below = hi < c || (hi == c && !hi_closed);
        let at_most = hi <= c;
        let above = lo > c || (lo == c && !lo_closed);
        let at_least = lo >= c;
        match self.op {
            BinaryOp::Lt if below => Some(true),
            BinaryOp::Lt if at_least => Some(false),
            BinaryOp::Le if at_most => Some(true),
            BinaryOp::Le if above => Some(false),
            BinaryOp::Gt if above => Some(true),
            BinaryOp::Gt if at_most => Some(false),
            BinaryOp::Ge if at_least => Some(true),
            BinaryOp::Ge if below => Some(false),
            _ => None,
        }
    }
}

impl Expander<'_> {
    fn expr(&mut self, e: &Expr, depth: usize) -> Result<Expr, NotInlinable> {
        let Expr::FnCall { sub, args, .. } = e else {
            return e.try_map_children(|c| self.expr(c, depth));
        };
        let Some(f) = self.design.subprograms.get(sub.index()) else {
            return Err(NotInlinable {
                name: String::new(),
                reason: "it is not in the design".into(),
                failed_assertion: None,
            });
        };
        if depth >= MAX_INLINE_DEPTH {
            return Err(refuse(f, "it calls itself"));
        }
        let mut frame: Vec<Expr> = args
            .iter()
            .map(|a| self.expr(a, depth))
            .collect::<Result<_, _>>()?;
        // A function whose body was not lowered (its package body failed, or it has none) has
        // no variables for its parameters yet.
        let Some(locals) = f.vars.get(frame.len()..) else {
            return Err(refuse(f, "its body could not be elaborated"));
        };
        frame.extend(locals.iter().map(|v| Expr::Const(v.init.clone())));
        // A function's run has its one result.
        let mut result = self.run(f, 0, frame, depth + 1)?;
        result.pop().ok_or_else(|| refuse(f, "it has no result"))
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
        fold_parts(&e).map_err(|m| refuse(f, &m))
    }

    /// [`Expander::run`] on one way of a forked condition, knowing `fact` there.
    fn branch(
        &mut self,
        f: &Subprogram,
        pc: usize,
        frame: Vec<Expr>,
        depth: usize,
        fact: Option<Comparison>,
    ) -> Result<Vec<Expr>, NotInlinable> {
        self.open += 1;
        let known = fact.is_some();
        self.facts.extend(fact);
        let result = self.run(f, pc, frame, depth);
        if known {
            self.facts.pop();
        }
        self.open -= 1;
        result
    }

    /// The results of `f` from instruction `pc` with its variables at `frame`: a function's
    /// value, or a procedural's outputs.
    fn run(
        &mut self,
        f: &Subprogram,
        mut pc: usize,
        mut frame: Vec<Expr>,
        depth: usize,
    ) -> Result<Vec<Expr>, NotInlinable> {
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
                        let known = Comparison::of(&c);
                        match known.as_ref().and_then(|k| k.decided_by(&self.facts)) {
                            Some(true) => pc += 1,
                            Some(false) => pc = *target,
                            None => {
                                let then =
                                    self.branch(f, pc + 1, frame.clone(), depth, known.clone());
                                let other = then.and_then(|then| {
                                    let negated = known.map(Comparison::negated);
                                    Ok((then, self.branch(f, *target, frame, depth, negated)?))
                                });
                                let (then, other) = other?;
                                let join = |(a, b)| {
                                    Expr::If(Box::new(c.clone()), Box::new(a), Box::new(b))
                                };
                                return Ok(then.into_iter().zip(other).map(join).collect());
                            }
                        }
                    }
                },
                Instr::Assert {
                    cond,
                    report,
                    severity,
                    span,
                } => {
                    // An assertion that holds statically costs nothing; one that depends on
                    // the operands is not checked in an equation (see the README). A note or
                    // a warning that fails does not stop a simulation either.
                    if let Some(c) = cond
                        && self.value(f, c, &frame, depth)? == Expr::Const(Value::Boolean(false))
                        && !matches!(
                            self.value(f, severity, &frame, depth),
                            Ok(Expr::Const(Value::Enum(0 | 1)))
                        )
                    {
                        let message = match report {
                            Some(r) => match self.value(f, r, &frame, depth) {
                                Ok(Expr::Const(Value::String(m))) => format!(": \"{m}\""),
                                _ => String::new(),
                            },
                            None => String::new(),
                        };
                        let mut refusal = refuse(
                            f,
                            &format!("its assertion fails for these arguments{message}"),
                        );
                        refusal.failed_assertion = Some(*span);
                        return Err(refusal);
                    }
                    pc += 1;
                }
                Instr::Return(Some(r)) => return Ok(vec![self.value(f, r, &frame, depth)?]),
                Instr::Return(None) if depth == PROCEDURAL && !self.outputs.is_empty() => {
                    return Ok(self
                        .outputs
                        .iter()
                        .map(|v| frame[v.index()].clone())
                        .collect());
                }
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
fn fold_parts(e: &Expr) -> Result<Expr, String> {
    let e = match e {
        Expr::If(c, x, y) => match fold_parts(c)? {
            Expr::Const(Value::Boolean(true)) => return fold_parts(x),
            Expr::Const(Value::Boolean(false)) => return fold_parts(y),
            c => Expr::If(
                Box::new(c),
                Box::new(fold_parts(x)?),
                Box::new(fold_parts(y)?),
            ),
        },
        _ => e.try_map_children(fold_parts)?,
    };
    fold(e)
}

fn refuse(f: &Subprogram, reason: &str) -> NotInlinable {
    NotInlinable {
        name: f.name.clone(),
        reason: reason.into(),
        failed_assertion: None,
    }
}

/// `array(index) := value` at a static index, with the array type's bounds: on a local array
/// whose value is static, or one that holds run-time values (a procedural's quantity array).
fn set_element(
    array: &mut Expr,
    ty: Option<&Type>,
    index: &Expr,
    value: Expr,
) -> Result<(), &'static str> {
    let (
        Some(Type::Array {
            left, ascending, ..
        }),
        Expr::Const(Value::Integer(i)),
    ) = (ty, index)
    else {
        return Err("it assigns an element of an array at an index that depends on a quantity");
    };
    let pos = if *ascending { i - left } else { left - i };
    let out_of_bounds = "it assigns an array element outside the array's bounds";
    let pos = usize::try_from(pos).map_err(|_| out_of_bounds)?;
    match (array, value) {
        (Expr::Const(Value::Array(elements)), Expr::Const(v)) => {
            *elements.get_mut(pos).ok_or(out_of_bounds)? = v;
        }
        (array @ Expr::Const(Value::Array(_)), value) => {
            let Expr::Const(Value::Array(elements)) = std::mem::replace(array, Expr::Now) else {
                unreachable!("matched above");
            };
            let mut elems: Vec<Expr> = elements.into_iter().map(Expr::Const).collect();
            *elems.get_mut(pos).ok_or(out_of_bounds)? = value;
            *array = Expr::Aggregate {
                elems,
                string: false,
            };
        }
        (Expr::Aggregate { elems, .. }, value) => {
            *elems.get_mut(pos).ok_or(out_of_bounds)? = value;
        }
        _ => {
            return Err(
                "it assigns an element of an array whose value is not known element by element",
            );
        }
    }
    Ok(())
}

/// `e` with each `Var(v)` replaced by `frame[v]`.
fn substitute(e: &Expr, frame: &[Expr]) -> Expr {
    let replaced = match e {
        Expr::Var(v) => return frame.get(v.index()).cloned().unwrap_or_else(|| e.clone()),
        _ => e.try_map_children(|c| Ok::<_, std::convert::Infallible>(substitute(c, frame))),
    };
    match replaced {
        Ok(e) => e,
        Err(never) => match never {},
    }
}

impl Elab<'_> {
    /// `e` (an equation's expression) with its function calls inlined, or a diagnostic at
    /// `span` naming the function that cannot be.
    pub(crate) fn inline_calls(&mut self, e: Expr, span: Span) -> R<Expr> {
        let mut has_call = false;
        e.visit(&mut |x| has_call |= matches!(x, Expr::FnCall { .. }));
        if !has_call {
            return Ok(e);
        }
        match inline(&self.design, &e, 0) {
            Ok(e) => Ok(e),
            Err(NotInlinable { name, reason, .. }) => Err(self.error(ElabError::invalid(
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
    use vams_design::{
        BinaryOp, ParamMode, QuantityId, Subprogram, SubprogramId, SubprogramKind, Type, Value,
        VarId, Variable,
    };
    use vams_syntax::source::Span;

    fn var(name: &str) -> Variable {
        Variable {
            range: None,
            name: name.into(),
            ty: Type::Real,
            init: Value::Real(0.0),
        }
    }

    fn function(code: Vec<Instr>) -> Design {
        Design {
            subprograms: vec![Subprogram {
                spans: Vec::new(),
                name: "f".into(),
                kind: SubprogramKind::Function,
                params: vec![ParamMode::In],
                vars: vec![var("t"), var("k")],
                code,
                span: Span::default(),
                intrinsic: None,
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

    #[test]
    fn comparisons_taken_decide_later_ones() {
        let q = Expr::Quantity(QuantityId(0));
        let cmp = |op, bound| Comparison {
            e: q.clone(),
            op,
            bound,
        };
        // On the way where x > 1 and x <= 4 were taken:
        let facts = [cmp(BinaryOp::Gt, 1.0), cmp(BinaryOp::Le, 4.0)];
        assert_eq!(cmp(BinaryOp::Gt, 0.5).decided_by(&facts), Some(true));
        assert_eq!(cmp(BinaryOp::Le, 1.0).decided_by(&facts), Some(false));
        assert_eq!(cmp(BinaryOp::Le, 4.0).decided_by(&facts), Some(true));
        assert_eq!(cmp(BinaryOp::Gt, 4.0).decided_by(&facts), Some(false));
        assert_eq!(cmp(BinaryOp::Lt, 4.0).decided_by(&facts), None);
        assert_eq!(cmp(BinaryOp::Ge, 2.0).decided_by(&facts), None);
        // `3.0 < x` reads as `x > 3.0`; `not (x > 1.0)` as `x <= 1.0`.
        let flipped = gt(Expr::real(3.0), q.clone());
        assert_eq!(Comparison::of(&flipped), Some(cmp(BinaryOp::Lt, 3.0)));
        let negated = Expr::Unary(UnaryOp::Not, Box::new(gt(q.clone(), Expr::real(1.0))));
        assert_eq!(Comparison::of(&negated), Some(cmp(BinaryOp::Le, 1.0)));
        // Another operand is not constrained by these facts.
        let other = Comparison {
            e: Expr::Quantity(QuantityId(1)),
            op: BinaryOp::Gt,
            bound: 0.5,
        };
        assert_eq!(other.decided_by(&facts), None);
    }
}
