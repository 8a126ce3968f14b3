//! User-defined functions and procedures: declarations and bodies (a package body completes
//! its package's declarations), overload resolution and argument association at a call
//! (positional, named, defaults), and lowering of a body to a [`design::Subprogram`] on its
//! first call, once per distinct set of actual signals of its signal parameters (those are
//! bound at elaboration, so the body reads and drives the actual signals).

use std::cell::RefCell;
use std::rc::Rc;

use vams_design::{
    self as design, Expr, Instr, ParamMode, SignalId, SubprogramId, SubprogramKind, Value, VarId,
};
use vams_syntax::ast::{
    self, Actual, Decl, Designator, ExprKind, Mode, ObjectClass, SeqStmt, SubprogramSpec,
};
use vams_syntax::source::Span;

use crate::declarations::decls::{designator, native};
use crate::error::ElabError;
use crate::expressions::expr::Typed;
use crate::names::scope::{Body, Bounds, Instance, Item, Native, Param, Part, Scope, Subprogram};
use crate::names::types::Ty;
use crate::sequential::process::{PartActual, Proc, SubContext};
use crate::{Elab, R};

/// Arguments bound to a subprogram's parameters: one optional actual per parameter, and the
/// element associations of a parameter associated element by element (`bv(0) => sel0`).
pub(crate) struct Slots<'e> {
    actuals: Vec<Option<&'e ast::Expr>>,
    elements: Vec<Vec<&'e ast::Assoc>>,
}

impl<'s, 'e> IntoIterator for &'s Slots<'e> {
    type Item = &'s Option<&'e ast::Expr>;
    type IntoIter = std::slice::Iter<'s, Option<&'e ast::Expr>>;
    fn into_iter(self) -> Self::IntoIter {
        self.actuals.iter()
    }
}

/// The actuals of `args` by parameter of `sub`, or `None` when they do not fit (unknown formal,
/// too many actuals, a parameter without actual or default).
fn bind<'e>(sub: &Subprogram<'_>, args: &'e [ast::Assoc]) -> Option<Slots<'e>> {
    let mut slots: Vec<Option<&'e ast::Expr>> = vec![None; sub.params.len()];
    let mut elements: Vec<Vec<&'e ast::Assoc>> = vec![Vec::new(); sub.params.len()];
    let mut taken = vec![false; sub.params.len()];
    for (k, a) in args.iter().enumerate() {
        // `open` leaves the parameter to its default (LRM 2.1.1).
        let actual = match &a.actual {
            Actual::Expr(actual) => Some(actual),
            Actual::Open(_) => None,
            _ => return None,
        };
        let slot = match &a.formal {
            Some(f) => match &f.kind {
                ExprKind::Name(id) => sub.params.iter().position(|p| p.name == id.name)?,
                // An element or slice of a parameter: gathered with the others of it.
                ExprKind::Apply(prefix, _) => {
                    let ExprKind::Name(id) = &prefix.kind else {
                        return None;
                    };
                    let slot = sub.params.iter().position(|p| p.name == id.name)?;
                    if taken[slot] || actual.is_none() {
                        return None;
                    }
                    elements[slot].push(a);
                    continue;
                }
                _ => return None,
            },
            None => k,
        };
        if slot >= slots.len() || taken[slot] || !elements[slot].is_empty() {
            return None;
        }
        taken[slot] = true;
        slots[slot] = actual;
    }
    let complete = (slots.iter().zip(&elements).zip(&sub.params))
        .all(|((s, e), p)| s.is_some() || !e.is_empty() || p.has_default);
    complete.then_some(Slots {
        actuals: slots,
        elements,
    })
}

fn mode(m: Option<Mode>) -> ParamMode {
    match m {
        None | Some(Mode::In | Mode::Linkage) => ParamMode::In,
        Some(Mode::Out) => ParamMode::Out,
        Some(Mode::Inout | Mode::Buffer) => ParamMode::InOut,
    }
}

/// A copy of `sc` in which the variables of an enclosing process (or subprogram) are not its
/// own (their ids index the enclosing frame), with those variables: the body reaches them as
/// implicit parameters ([`Body::captured`]), declared again in each instance. An alias of a
/// part of such a variable stays hidden.
fn body_scope<'a>(sc: &Scope<'a>) -> (Scope<'a>, Vec<(Span, VarId, Ty)>) {
    let mut out = sc.clone();
    let mut captured = Vec::new();
    for region in &mut out.regions {
        // Only regions that hold a variable are copied (the rest stay shared).
        let has_variable = region
            .items
            .values()
            .flatten()
            .any(|i| matches!(i, Item::Variable { .. }));
        if !has_variable {
            continue;
        }
        let hidden = || {
            Item::Poison(Some(
                "a part of a variable of the enclosing process named by an alias, which a subprogram cannot reach; pass the variable as a parameter".into(),
            ))
        };
        for (decl, item) in std::rc::Rc::make_mut(&mut region.decls).iter_mut() {
            if let Item::Variable { id, ty, path, .. } = item {
                if path.is_empty() {
                    captured.push((*decl, *id, ty.clone()));
                }
                *item = hidden();
            }
        }
        for items in std::rc::Rc::make_mut(&mut region.items).values_mut() {
            for item in items.iter_mut() {
                if matches!(item, Item::Variable { .. }) {
                    *item = hidden();
                }
            }
        }
    }
    // In declaration order: the order of the implicit parameters.
    captured.sort_by_key(|c| (c.0.file, c.0.start));
    (out, captured)
}

impl<'a> Elab<'a> {
    /// A subprogram declaration, or a body (which completes a visible declaration of the same
    /// signature, or declares the subprogram).
    pub(crate) fn subprogram_decl(
        &mut self,
        sc: &mut Scope<'a>,
        spec: &'a SubprogramSpec,
        body: Option<(&'a [Decl], &'a [SeqStmt])>,
    ) -> R<()> {
        let name = designator(spec);
        let mut params = Vec::new();
        for p in &spec.params {
            let sub = self.subtype_indication(sc, &p.subtype)?;
            for n in &p.names {
                params.push(Param {
                    name: n.name.clone(),
                    span: n.span,
                    ty: sub.ty.clone(),
                    has_default: p.default.is_some(),
                    default: p.default.as_ref(),
                    is_signal: p.class == Some(ObjectClass::Signal),
                    mode: mode(p.mode),
                });
            }
        }
        let ret = match &spec.return_type {
            Some(t) => Some(self.type_mark(sc, t)?.ty.clone()),
            None => None,
        };
        if let Some((decls, stmts)) = body {
            // The declaration this body completes: the one analysis bound it to.
            let bound = self
                .analysed
                .names
                .get(&designator_span(spec))
                .and_then(|d| sc.declared(*d))
                .and_then(|i| match i {
                    Item::Subprogram(s) if s.body.borrow().is_none() && s.native.is_none() => {
                        Some(s.clone())
                    }
                    _ => None,
                });
            if let Some(s) = bound {
                let (scope, captured) = body_scope(sc);
                *s.body.borrow_mut() = Some(Rc::new(Body {
                    decls,
                    stmts,
                    scope,
                    params: params.iter().map(|p| p.span).collect(),
                    captured,
                    bounding: self.bounding_params(decls, &s.params),
                }));
                self.pending.with_bodies.push(s);
                return Ok(());
            }
        }
        let native = match &self.native_names {
            Some(names) if names.contains(&name) && body.is_none() => {
                Some(native(&name, params.len(), spec.is_function))
            }
            _ => None,
        };
        let sub = Rc::new(Subprogram {
            name: name.clone(),
            params,
            ret,
            native,
            span: spec.span,
            body: RefCell::new(None),
            instances: RefCell::new(Vec::new()),
        });
        sc.declare_at(&name, designator_span(spec), Item::Subprogram(sub.clone()));
        if let Some((decls, stmts)) = body {
            // Declared first, so that the body sees itself (recursion).
            let (scope, captured) = body_scope(sc);
            *sub.body.borrow_mut() = Some(Rc::new(Body {
                decls,
                stmts,
                scope,
                params: sub.params.iter().map(|p| p.span).collect(),
                captured,
                bounding: self.bounding_params(decls, &sub.params),
            }));
            self.pending.with_bodies.push(sub);
        }
        Ok(())
    }

    /// The one subprogram of `subs` that `args` call: by arity and formal names, then the one
    /// analysis chose for the name at `name_span` (it resolves overloads from the operands'
    /// types and the context; elaboration has no overload rules of its own).
    pub(crate) fn resolve_call<'e>(
        &mut self,
        subs: Vec<Rc<Subprogram<'a>>>,
        args: &'e [ast::Assoc],
        function: bool,
        span: Span,
        name_span: Span,
    ) -> R<(Rc<Subprogram<'a>>, Slots<'e>)> {
        let name = subs.first().map(|s| s.name.clone()).unwrap_or_default();
        let mut cands: Vec<(Rc<Subprogram<'a>>, Slots<'e>)> = subs
            .into_iter()
            .filter(|s| s.ret.is_some() == function)
            .filter_map(|s| bind(&s, args).map(|slots| (s, slots)))
            .collect();
        let what = if function { "function" } else { "procedure" };
        if let [(sub, slots)] = cands.as_slice()
            && let Some((p, assocs)) = (sub.params.iter().zip(&slots.elements))
                .find(|(p, e)| !e.is_empty() && !p.is_signal)
        {
            return Err(self.error(ElabError::unsupported(
                assocs[0].span,
                format!(
                    "the parameter `{}`, not a signal, associated element by element",
                    p.name
                ),
                "associate the whole parameter: an aggregate, `(x, y, z)`",
            )));
        }
        if cands.is_empty()
            && let Some(part) = args.iter().find_map(|a| {
                a.formal
                    .as_ref()
                    .filter(|f| matches!(f.kind, ast::ExprKind::Apply(..)))
            })
        {
            return Err(self.error(ElabError::unsupported(
                part.span,
                "a parameter associated element by element",
                "associate the whole parameter: pass a signal of its type, and connect that signal's elements to the signals",
            )));
        }
        if cands.is_empty() {
            return Err(self.error(ElabError::invalid(
                span,
                format!("no {what} `{name}` takes {} argument(s)", args.len()),
                Some("check the number of arguments and the formal names (procedures are called as statements, functions in expressions)".into()),
            )));
        }
        if cands.len() > 1 {
            // Analysis chose the overload from the operands' types and the context.
            let decl = self.analysed.names.get(&name_span).copied();
            cands.retain(|(s, _)| {
                decl.is_some_and(|d| {
                    s.span.file == d.file && s.span.start <= d.start && d.end <= s.span.end
                })
            });
            if cands.len() != 1 {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("no single overload of `{name}` fits this call"),
                    Some("qualify the arguments (`real'(x)`) or the name (`pkg.f`) so that one declaration fits".into()),
                )));
            }
        }
        Ok(cands.remove(0))
    }

    /// The argument of a parameter: its actual, or its default.
    pub(crate) fn argument(
        &mut self,
        sc: &Scope<'a>,
        p: &Param<'a>,
        actual: Option<&ast::Expr>,
        span: Span,
    ) -> R<Typed> {
        match actual.or(p.default) {
            Some(e) => {
                let t = self.expr_of(sc, e, &p.ty)?;
                // A parameter of a constrained array subtype takes values of its length
                // (LRM 2.1.1.1).
                let ty = t.ty.clone();
                let what = |_: &Self| format!("parameter `{}`", p.name);
                let e = self.fit_length(t, &p.ty, what, e.span)?;
                Ok(Typed::new(e, ty))
            }
            None => Err(self.error(ElabError::invalid(
                span,
                format!("no argument for the parameter `{}`", p.name),
                Some("give it an actual, or declare a default value".into()),
            ))),
        }
    }

    /// The actual signal of a signal parameter: a gathered signal over the actuals of one
    /// associated element by element (`elements`).
    fn signal_actual(
        &mut self,
        sc: &Scope<'a>,
        p: &Param<'a>,
        actual: Option<&ast::Expr>,
        elements: &[&ast::Assoc],
        span: Span,
    ) -> R<SignalId> {
        if !elements.is_empty() {
            let name = self.hier_name(&p.name);
            return Ok(self.gathered(sc, &p.name, name, &p.ty, elements, span)?.0);
        }
        let t = match actual {
            // An element or slice of a signal: its view (type checked by analysis).
            Some(
                e @ ast::Expr {
                    kind: ast::ExprKind::Apply(..),
                    ..
                },
            ) => self.signal_expr(sc, e)?,
            _ => self.argument(sc, p, actual, span)?,
        };
        match t.e {
            Expr::Signal(s) => Ok(s),
            _ => Err(self.error(ElabError::invalid(
                actual.map_or(span, |a| a.span),
                format!(
                    "the parameter `{}` is a signal: its actual must name a signal",
                    p.name
                ),
                None,
            ))),
        }
    }

    /// How a call of `sub` is computed natively: a stdlib subprogram's own native, or, for a
    /// function of the user's with no body anywhere whose name and profile are those of an
    /// elementary function of math_real (`function exp (x : real) return real;`, as the
    /// SEAMS test suite declares them), that function, with a warning once per declaration.
    /// Calls happen after every package body is elaborated, so a missing body stays missing.
    pub(crate) fn native_of(&mut self, sub: &Subprogram<'a>) -> Option<Native> {
        if sub.native.is_some() || sub.body.borrow().is_some() {
            return sub.native;
        }
        let reals = sub.ret == Some(Ty::Real)
            && (sub.params.iter()).all(|p| p.ty == Ty::Real && !p.is_signal && !p.has_default);
        if !reals {
            return None;
        }
        let name = sub.name.to_ascii_lowercase();
        let stand_in = match (name.as_str(), sub.params.len()) {
            ("pow", 2) => Native::Pow,
            (n, arity) => match native(n, arity, true) {
                b @ Native::Builtin(_) => b,
                _ => return None,
            },
        };
        let warning = vams_design::DesignWarning::BuiltinStandIn {
            name: sub.name.clone(),
            span: sub.span,
        };
        if !self.design.warnings.contains(&warning) {
            self.design.warnings.push(warning);
        }
        Some(stand_in)
    }

    /// A call of the user-defined function `sub` with bound actuals.
    pub(crate) fn user_function_call(
        &mut self,
        sc: &Scope<'a>,
        sub: &Rc<Subprogram<'a>>,
        slots: &Slots<'_>,
        span: Span,
    ) -> R<Expr> {
        let mut args = Vec::new();
        let mut signals = Vec::new();
        let mut bounds = Vec::new();
        let mut objects = Vec::new();
        for (k, (p, actual)) in sub.params.iter().zip(slots).enumerate() {
            if p.is_signal {
                signals.push(self.signal_actual(sc, p, *actual, &slots.elements[k], span)?);
                bounds.push(None);
            } else if matches!(p.ty, Ty::Protected(_)) {
                objects.push(self.shared_actual(sc, p, *actual, span)?);
                bounds.push(None);
            } else {
                let t = self.argument(sc, p, *actual, span)?;
                bounds.push(actual_bounds(&p.ty, &t.ty, &t.e));
                args.push(t.e);
            }
        }
        args.extend(self.captured(sc, sub, span)?.into_iter().map(Expr::Var));
        self.function_expr(sub, args, signals, &bounds, &objects, span)
    }

    /// The actual of a parameter of protected type: a shared variable, whose object the
    /// instance of the body is lowered for (its methods are that variable's).
    fn shared_actual(
        &mut self,
        sc: &Scope<'a>,
        p: &Param<'a>,
        actual: Option<&ast::Expr>,
        span: Span,
    ) -> R<Item<'a>> {
        let Some(actual) = actual else {
            return Err(self.error(ElabError::invalid(
                span,
                format!("no argument for the parameter `{}`", p.name),
                Some("pass a shared variable of its protected type".into()),
            )));
        };
        match self.lookup(sc, actual)?.first() {
            Some(item @ Item::SharedObject { ty, .. }) if ty.same(&p.ty) => Ok(item.clone()),
            _ => Err(self.error(ElabError::invalid(
                actual.span,
                format!(
                    "the parameter `{}` is of protected type {}: its actual must be a shared variable of that type",
                    p.name, p.ty
                ),
                None,
            ))),
        }
    }

    /// The result type of `call`, a call of `sub`: its declared type, constrained to the
    /// bounds every `return` of the called instance gives.
    pub(crate) fn call_result(&self, sub: &Subprogram<'a>, call: &Expr) -> Option<Ty> {
        let ret = sub.ret.clone()?;
        let (Ty::Array(a), Expr::FnCall { sub: id, .. }) = (&ret, call) else {
            return Some(ret);
        };
        if a.bounds.is_some() {
            return Some(ret);
        }
        let result = (sub.instances.borrow().iter())
            .find(|i| i.id == *id)
            .and_then(|i| i.result);
        Some(match result {
            Some(b) => a.with_bounds(Some(b)),
            None => ret,
        })
    }

    /// `FnCall` of the instance of `sub` for `signals`, the actuals' `bounds` and the shared
    /// variables `objects` of its protected parameters.
    pub(crate) fn function_expr(
        &mut self,
        sub: &Rc<Subprogram<'a>>,
        args: Vec<Expr>,
        signals: Vec<SignalId>,
        bounds: &[Option<Bounds>],
        objects: &[Item<'a>],
        span: Span,
    ) -> R<Expr> {
        let mut id = self.instance(sub, &signals, bounds, &args, objects, span)?;
        if let Some(special) = self.specialised(sub, id, &signals, bounds, &args, objects, span) {
            id = special;
        }
        Ok(Expr::FnCall {
            sub: id,
            args,
            signals,
        })
    }

    /// For a call of function `sub` whose instance `id` returns an unconstrained array of
    /// bounds known only at run time (its `return`s disagree: `vbuild` returns a null array
    /// or an element joined to its own result for `size - 1`), an instance lowered with every
    /// scalar `in` parameter whose actual among `args` is static as that constant, if its
    /// result's bounds are static then: `to_signed(x, 8)` is 8 elements long, known at
    /// elaboration, so that it can be passed straight to another call (whose unconstrained
    /// parameter needs static bounds) and its length checked against a target's. Conditions
    /// that fold prune the body's dead code (`if size = 0 then return none; end if;`), so the
    /// recursion on a static size ends. Tried at most [`SPECIALISING_DEPTH`] calls deep; a
    /// body that fails to lower this way, or whose result still has no static bounds, keeps
    /// `id` (and no diagnostic).
    #[allow(clippy::too_many_arguments)]
    fn specialised(
        &mut self,
        sub: &Rc<Subprogram<'a>>,
        id: SubprogramId,
        signals: &[SignalId],
        bounds: &[Option<Bounds>],
        args: &[Expr],
        objects: &[Item<'a>],
        span: Span,
    ) -> Option<SubprogramId> {
        let Some(Ty::Array(ret)) = &sub.ret else {
            return None;
        };
        if ret.bounds.is_some() || self.specialising >= SPECIALISING_DEPTH {
            return None;
        }
        let result_of = |sub: &Subprogram<'a>, id: SubprogramId| {
            (sub.instances.borrow().iter())
                .find(|i| i.id == id)
                .and_then(|i| i.result)
        };
        if result_of(sub, id).is_some() {
            return None;
        }
        let current = (sub.instances.borrow().iter())
            .find(|i| i.id == id)
            .map(|i| i.constants.clone())?;
        // Every static actual of a scalar `in` parameter.
        let mut args = args.iter();
        let mut added = false;
        let constants: Vec<Option<Value>> = (sub.params.iter().enumerate())
            .map(|(k, p)| {
                if p.is_signal || matches!(p.ty, Ty::Protected(_)) {
                    return None;
                }
                let arg = args.next();
                if let Some(c) = current.get(k).cloned().flatten() {
                    return Some(c);
                }
                match arg {
                    Some(Expr::Const(v)) if p.mode == ParamMode::In && p.ty.is_scalar() => {
                        added = true;
                        Some(v.clone())
                    }
                    _ => None,
                }
            })
            .collect();
        if !added {
            return None;
        }
        let (errors, first) = (self.errors.len(), self.design.subprograms.len());
        self.specialising += 1;
        let special = self.lowered(sub, signals, bounds, constants, objects, span);
        self.specialising -= 1;
        match special {
            Ok(special) if result_of(sub, special).is_some() => Some(special),
            Ok(_) => None,
            Err(_) => {
                // Lowered with the constants, the body failed where the general instance
                // did not: forget that instance and what it reported.
                self.errors.truncate(errors);
                let failed = SubprogramId(first as u32);
                sub.instances.borrow_mut().retain(|i| i.id != failed);
                None
            }
        }
    }

    /// A call of the user-defined procedure `sub`: `in` arguments by value, `out` and `inout`
    /// actuals (variables) copied back on return, signal actuals bound in the instance. An
    /// actual that is a part of a variable is returned beside the call, for the caller to
    /// copy it back through a temporary (`PartActual`).
    pub(crate) fn user_procedure_call(
        &mut self,
        sc: &Scope<'a>,
        vars: &[design::Variable],
        sub: &Rc<Subprogram<'a>>,
        slots: &Slots<'_>,
        span: Span,
    ) -> R<(Instr, Vec<PartActual>)> {
        let mut args = Vec::new();
        let mut signals = Vec::new();
        let mut copy_back = Vec::new();
        let mut parts = Vec::new();
        let mut bounds = Vec::new();
        let mut objects = Vec::new();
        for (k, (p, actual)) in sub.params.iter().zip(slots).enumerate() {
            if p.is_signal {
                signals.push(self.signal_actual(sc, p, *actual, &slots.elements[k], span)?);
                bounds.push(None);
                continue;
            }
            if matches!(p.ty, Ty::Protected(_)) {
                objects.push(self.shared_actual(sc, p, *actual, span)?);
                bounds.push(None);
                continue;
            }
            let param = VarId(args.len() as u32);
            match p.mode {
                ParamMode::In => {
                    let t = self.argument(sc, p, *actual, span)?;
                    bounds.push(actual_bounds(&p.ty, &t.ty, &t.e));
                    args.push(t.e);
                }
                ParamMode::Out | ParamMode::InOut => {
                    let Some(actual) = actual else {
                        return Err(self.error(ElabError::invalid(
                            span,
                            format!("the `out` parameter `{}` needs an actual variable", p.name),
                            None,
                        )));
                    };
                    // A part of a variable (`swap(a(1), a(2))`, `read_field(r.f)`): passed by
                    // value, and written back into the variable after the call.
                    if let Some(part) = self.variable_part_actual(sc, vars, actual)? {
                        let (id, path, ty) = part;
                        self.actual_of_type(actual, &ty, p)?;
                        self.actual_length(actual, &ty, p)?;
                        let value = path.iter().fold(Expr::Var(id), |e, part| part.of(e));
                        bounds.push(actual_bounds(&p.ty, &ty, &value));
                        args.push(if p.mode == ParamMode::Out {
                            Expr::Const(p.ty.default_value())
                        } else {
                            value
                        });
                        parts.push(PartActual {
                            param,
                            var: id,
                            path,
                            ty,
                        });
                        continue;
                    }
                    let items = self.lookup(sc, actual)?;
                    let Some(Item::Variable {
                        id,
                        ty,
                        readonly: false,
                        ..
                    }) = items.first()
                    else {
                        return Err(self.error(ElabError::WrongClass {
                            span: actual.span,
                            name: self.sources.snippet(actual.span).into(),
                            found: items[0].class().into(),
                            expected: "a variable".into(),
                            help: Some(format!(
                                "the actual of the `out`/`inout` parameter `{}` must be a variable (declare it `signal` to drive a signal)",
                                p.name
                            )),
                        }));
                    };
                    bounds.push(actual_bounds(&p.ty, ty, &Expr::Var(*id)));
                    // Reported; the call is still lowered.
                    let _ = self.actual_of_type(actual, ty, p);
                    self.actual_length(actual, ty, p)?;
                    args.push(if p.mode == ParamMode::Out {
                        Expr::Const(p.ty.default_value())
                    } else {
                        Expr::Var(*id)
                    });
                    copy_back.push((param, *id));
                }
            }
        }
        // The enclosing process's variables: in, and back on return, before the `out` and
        // `inout` parameters are, so that `acc` of `p(5, total)` lands in `total` even though
        // the body could also reach `total` itself (and left the copy it got unchanged).
        let captured = self.captured(sc, sub, span)?;
        let mut back = Vec::with_capacity(captured.len() + copy_back.len());
        for outer in captured {
            back.push((VarId(args.len() as u32), outer));
            args.push(Expr::Var(outer));
        }
        back.append(&mut copy_back);
        let copy_back = back;
        let id = self.instance(sub, &signals, &bounds, &args, &objects, span)?;
        let call = Instr::Call {
            sub: id,
            args,
            copy_back,
            signals,
            span,
        };
        Ok((call, parts))
    }

    /// The error for an `out` or `inout` actual of type `ty` whose parameter `p` has another.
    pub(crate) fn actual_of_type(&mut self, actual: &ast::Expr, ty: &Ty, p: &Param<'a>) -> R<()> {
        if ty.same(&p.ty) {
            return Ok(());
        }
        Err(self.error(ElabError::TypeMismatch {
            span: actual.span,
            expected: p.ty.to_string(),
            found: ty.to_string(),
            help: None,
        }))
    }

    /// The error for an `out` or `inout` actual of type `ty` whose length differs from its
    /// parameter `p`'s, of a constrained array subtype (copied in and back, LRM 2.1.1.1).
    fn actual_length(&mut self, actual: &ast::Expr, ty: &Ty, p: &Param<'a>) -> R<()> {
        let (Ty::Array(f), Ty::Array(a)) = (&p.ty, ty) else {
            return Ok(());
        };
        match (f.len(), a.len()) {
            (Some(n), Some(m)) if n != m => Err(self.error(ElabError::LengthMismatch {
                span: actual.span,
                message: format!(
                    "the actual of `{}` has {m} element(s), but the parameter has {n}",
                    p.name
                ),
                found: m as i64,
                help: Some(crate::expressions::lengths::HELP.into()),
            })),
            _ => Ok(()),
        }
    }

    /// An `out` or `inout` actual naming a part of a variable (a field, an element, a
    /// slice, or an alias of one): the variable, the path to the part and its type; `None`
    /// for a whole variable or anything else.
    fn variable_part_actual(
        &mut self,
        sc: &Scope<'a>,
        vars: &[design::Variable],
        actual: &ast::Expr,
    ) -> R<Option<(VarId, Vec<Part>, Ty)>> {
        let names_variable = |e: &ast::Expr| {
            let mut e = e;
            loop {
                match &e.kind {
                    ast::ExprKind::Apply(prefix, _) | ast::ExprKind::Selected(prefix, _) => {
                        e = prefix
                    }
                    ast::ExprKind::Name(id) => {
                        return matches!(self.resolved_item(sc, id), Some(Item::Variable { .. }));
                    }
                    _ => return false,
                }
            }
        };
        if !names_variable(actual) {
            return Ok(None);
        }
        let (id, path, ty) = self.variable_target(sc, vars, actual)?;
        Ok((!path.is_empty()).then_some((id, path, ty)))
    }

    /// The variables that a call of `sub` at `sc` passes after its parameters: those of the
    /// enclosing process its body uses, as the call site names them (in a subprogram
    /// declared beside `sub`, its own implicit parameters).
    fn captured(&mut self, sc: &Scope<'a>, sub: &Subprogram<'a>, span: Span) -> R<Vec<VarId>> {
        let Some(body) = sub.body.borrow().clone() else {
            return Ok(Vec::new());
        };
        let mut out = Vec::with_capacity(body.captured.len());
        for (decl, ..) in &body.captured {
            match sc.declared(*decl) {
                Some(Item::Variable { id, path, .. }) if path.is_empty() => out.push(*id),
                _ => {
                    return Err(self.error(ElabError::unsupported(
                        span,
                        format!(
                            "calling `{}` where the variable `{}` of its process is out of reach",
                            sub.name,
                            self.sources.snippet(*decl)
                        ),
                        "call it from the process that declares it",
                    )));
                }
            }
        }
        Ok(out)
    }

    /// The design subprogram of `sub` for the actual signals `signals` and the bounds of the
    /// actuals of its unconstrained array parameters (one entry per parameter), lowered on
    /// first use: in the body such a parameter has its actual's bounds, so `x'right` and
    /// `x'range` are static there.
    pub(crate) fn instance(
        &mut self,
        sub: &Rc<Subprogram<'a>>,
        signals: &[SignalId],
        bounds: &[Option<Bounds>],
        args: &[Expr],
        objects: &[Item<'a>],
        span: Span,
    ) -> R<SubprogramId> {
        let constants = self.bounding_constants(sub, args);
        self.lowered(sub, signals, bounds, constants, objects, span)
    }

    /// The instance of `sub` for `signals`, `bounds` and `objects` (see
    /// [`Elab::instance`]) in which the parameters that `constants` gives values (one entry
    /// per parameter, or none) are those constants.
    fn lowered(
        &mut self,
        sub: &Rc<Subprogram<'a>>,
        signals: &[SignalId],
        bounds: &[Option<Bounds>],
        constants: Vec<Option<Value>>,
        objects: &[Item<'a>],
        span: Span,
    ) -> R<SubprogramId> {
        // The shared variables of the protected parameters, by identity.
        let object_keys: Vec<usize> = objects
            .iter()
            .map(|o| match o {
                Item::SharedObject { methods, .. } => Rc::as_ptr(methods) as usize,
                _ => 0,
            })
            .collect();
        if let Some(i) = (sub.instances.borrow().iter()).find(|i| {
            i.signals == signals
                && i.bounds.as_slice() == bounds
                && i.constants == constants
                && i.objects == object_keys
        }) {
            return Ok(i.id);
        }
        let Some(body) = sub.body.borrow().clone() else {
            return Err(self.error(ElabError::invalid(
                span,
                format!("the subprogram `{}` has no body", sub.name),
                Some("write its body (in the package body for a package's subprogram)".into()),
            )));
        };
        let kind = if sub.ret.is_some() {
            SubprogramKind::Function
        } else {
            SubprogramKind::Procedure
        };
        let id = SubprogramId(self.design.subprograms.len() as u32);
        // Registered before the body is lowered, so that recursive calls find it.
        self.design.subprograms.push(design::Subprogram {
            spans: Vec::new(),
            name: self.hier_name(&sub.name),
            kind,
            params: Vec::new(),
            vars: Vec::new(),
            code: vec![Instr::Return(None)],
            span: sub.span,
            intrinsic: crate::expressions::intrinsic::of(sub, signals, self.sources),
        });
        sub.instances.borrow_mut().push(Instance {
            signals: signals.to_vec(),
            bounds: bounds.to_vec(),
            constants: constants.clone(),
            objects: object_keys,
            id,
            result: None,
        });
        let mut sc = body.scope.clone();
        sc.push();
        let mut p = Proc::default();
        p.subprogram = Some(SubContext {
            ret: sub.ret.clone(),
            returned: Vec::new(),
        });
        let mut params = Vec::new();
        let mut signals = signals.iter();
        let mut objects = objects.iter();
        for (i, param) in sub.params.iter().enumerate() {
            // Same length by `same_signature`; the declaration's span otherwise.
            let at = body.params.get(i).copied().unwrap_or(param.span);
            let item = if matches!(param.ty, Ty::Protected(_)) {
                let Some(object) = objects.next() else {
                    return Err(crate::Reported);
                };
                object.clone()
            } else if param.is_signal {
                let Some(s) = signals.next() else {
                    return Err(crate::Reported);
                };
                // An unconstrained parameter takes the bounds of its actual, which this
                // instance of the body is lowered for.
                let ty = match (&param.ty, &self.design.signals[s.index()].ty) {
                    (
                        Ty::Array(a),
                        design::Type::Array {
                            left,
                            right,
                            ascending,
                            ..
                        },
                    ) if a.bounds.is_none() => a.with_bounds(Some((*left, *right, *ascending))),
                    (ty, _) => ty.clone(),
                };
                Item::Signal { id: *s, ty }
            } else {
                params.push(param.mode);
                let ty = match (&param.ty, bounds.get(i).copied().flatten()) {
                    (Ty::Array(a), Some(b)) if a.bounds.is_none() => {
                        // The actual's bounds (a static size argument, `to_signed(x, n)`):
                        // a size no array may have is a diagnostic, not an allocation.
                        self.array_size(&[b], at)?;
                        a.with_bounds(Some(b))
                    }
                    (ty, _) => ty.clone(),
                };
                let var = p.new_var(&param.name, &ty, ty.default_value());
                match constants.get(i).cloned().flatten() {
                    // It bounds a declaration: this instance has it as a constant.
                    Some(value) => Item::Constant { value, ty },
                    None => Item::Variable {
                        id: var,
                        ty,
                        readonly: param.mode == ParamMode::In,
                        path: Rc::from([]),
                    },
                }
            };
            sc.declare_at(&param.name, at, item);
        }
        // The enclosing process's variables, as implicit parameters after the declared ones.
        let mut own = Vec::with_capacity(body.captured.len());
        for (decl, _, ty) in &body.captured {
            let name = self.sources.snippet(*decl).to_string();
            let var = p.new_var(&name, ty, ty.default_value());
            params.push(ParamMode::InOut);
            own.push(var);
            let item = Item::Variable {
                id: var,
                ty: ty.clone(),
                readonly: false,
                path: Rc::from([]),
            };
            sc.declare_at(&name, *decl, item);
        }
        let before = self.errors.len();
        let decls_ok = self.process_decls(&mut sc, &mut p, body.decls).is_ok();
        self.seq(&mut sc, &mut p, body.stmts);
        p.emit(Instr::Return(None));
        if !decls_ok || self.errors.len() > before {
            return Err(crate::Reported);
        }
        let returned = p.subprogram.as_ref().map_or(&[][..], |c| &c.returned);
        if let Some(first) = returned.first().copied().flatten()
            && returned.iter().all(|b| *b == Some(first))
            && let Some(i) = sub.instances.borrow_mut().iter_mut().find(|i| i.id == id)
        {
            i.result = Some(first);
        }
        // A function's call is an expression, with nothing to copy back: its process's
        // variables are read-only in it.
        let (vars, code, spans) = p.into_parts();
        let assigns_captured = code.iter().any(|i| {
            matches!(i, Instr::SetVar { var, .. } | Instr::SetVarElement { var, .. } if own.contains(var))
        });
        if kind == SubprogramKind::Function && assigns_captured {
            return Err(self.error(ElabError::unsupported(
                sub.span,
                format!(
                    "the function `{}` assigns a variable of its process",
                    sub.name
                ),
                "make it a procedure, or pass the variable as a parameter and return the new value",
            )));
        }
        let slot = &mut self.design.subprograms[id.index()];
        slot.params = params;
        slot.vars = vars;
        slot.code = code;
        slot.spans = spans;
        Ok(id)
    }

    /// The user-defined operator (`"and"` on `std_ulogic`) analysis chose for the application
    /// at `span`, applied to `operands`; `None` when analysis chose a predefined one.
    pub(crate) fn user_operator(
        &mut self,
        sc: &Scope<'a>,
        operands: Vec<Typed>,
        span: Span,
    ) -> Option<R<Typed>> {
        // The operator function analysis chose for this application; none when it is a
        // predefined operator (whose "declaration" is its type's).
        let sub = match self.resolved_at(sc, span)? {
            Item::Subprogram(s)
                if s.ret.is_some()
                    && s.params.len() == operands.len()
                    && s.params.iter().all(|p| !p.is_signal) =>
            {
                s
            }
            _ => return None,
        };
        sub.ret.as_ref()?;
        if let Some(native) = self.native_of(&sub) {
            // math_real's `x ** y`, the stdlib's one native operator.
            let ret = sub.ret.clone().unwrap_or(Ty::Real);
            let args = operands.into_iter().map(|t| t.e).collect();
            return Some(
                self.native_call(&sub, native, args, span, span)
                    .and_then(|e| self.folded(e, ret, span)),
            );
        }
        let bounds: Vec<_> = (sub.params.iter().zip(&operands))
            .map(|(p, t)| actual_bounds(&p.ty, &t.ty, &t.e))
            .collect();
        let args = operands.into_iter().map(|t| t.e).collect();
        Some(
            self.function_expr(&sub, args, Vec::new(), &bounds, &[], span)
                .map(|e| {
                    let ty = self.call_result(&sub, &e).unwrap_or(Ty::Real);
                    Typed { e, ty }
                }),
        )
    }
}

impl<'a> Elab<'a> {
    /// The static actuals among `args` (the actuals of the parameters that are not
    /// signals, in order) of the `in` parameters of `sub` that name the bounds of its body's
    /// declarations (`variable result : bit_vector(0 to length - 1)`): one entry per
    /// parameter, or none at all when no such actual is static. An instance of the body is
    /// lowered for each such set, with those parameters constants, so that the bounds are
    /// static there (vams has no arrays whose bounds are known only at run time).
    fn bounding_constants(&self, sub: &Subprogram<'a>, args: &[Expr]) -> Vec<Option<Value>> {
        let Some(body) = sub.body.borrow().clone() else {
            return Vec::new();
        };
        let mut args = args.iter();
        let constants: Vec<Option<Value>> = sub
            .params
            .iter()
            .zip(&body.bounding)
            .map(|(p, &bounding)| {
                if p.is_signal || matches!(p.ty, Ty::Protected(_)) {
                    return None;
                }
                match args.next()? {
                    Expr::Const(v) if bounding => Some(v.clone()),
                    _ => None,
                }
            })
            .collect();
        if constants.iter().all(Option::is_none) {
            Vec::new()
        } else {
            constants
        }
    }

    /// For each of `params`, whether it is an `in` parameter that the bounds of the body's
    /// declarations `decls` name (see [`Elab::bounding_constants`]); found once per body, by
    /// the words of those declarations' subtype indications.
    fn bounding_params(&self, decls: &[ast::Decl], params: &[Param<'a>]) -> Vec<bool> {
        let mut words: Vec<String> = Vec::new();
        for d in decls {
            let span = match &d.kind {
                ast::DeclKind::Constant { subtype, .. }
                | ast::DeclKind::Variable { subtype, .. }
                | ast::DeclKind::Subtype { subtype, .. } => subtype.span,
                ast::DeclKind::Type { .. } => d.span,
                _ => continue,
            };
            let text = self.sources.snippet(span).to_ascii_lowercase();
            words.extend(
                text.split(|c: char| !(c.is_ascii_alphanumeric() || c == '_'))
                    .filter(|w| !w.is_empty())
                    .map(str::to_string),
            );
        }
        params
            .iter()
            .map(|p| p.mode == ParamMode::In && words.contains(&p.name))
            .collect()
    }
}

/// How many calls deep [`Elab::specialised`] lowers instances for static scalar arguments
/// (`vbuild` recurses once per element: 256 covers the products of two 128-bit operands).
const SPECIALISING_DEPTH: usize = 256;

/// The bounds an unconstrained array parameter of type `formal` takes from its actual: the
/// actual's subtype's, or for an unconstrained value (an aggregate) its length from the index
/// subtype's low end. `None` for any other parameter.
fn actual_bounds(formal: &Ty, actual: &Ty, value: &Expr) -> Option<Bounds> {
    let Ty::Array(f) = formal else {
        return None;
    };
    if f.bounds.is_some() {
        return None;
    }
    match (actual, value) {
        (Ty::Array(a), _) if a.bounds.is_some() => a.bounds,
        (_, Expr::Const(Value::Array(v))) => {
            Some((f.index_low, f.index_low + v.len() as i64 - 1, true))
        }
        _ => None,
    }
}

/// The span of a subprogram's designator (its name or operator symbol), where analysis
/// declares it.
fn designator_span(spec: &SubprogramSpec) -> Span {
    match &spec.designator {
        Designator::Ident(id) => id.span,
        Designator::Operator(_, span) => *span,
    }
}
