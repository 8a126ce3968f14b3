//! Processes: sequential statements lowered to [`Instr`]s with jumps, and the equivalent
//! processes of concurrent signal assignments, assertions, procedure calls and breaks
//! (LRM 11.3-11.6, 1076.1 12.6.4).

use vams_design::{
    BinaryOp, BreakReinit, DelayMechanism, Expr, Instr, Process, SignalId, Value, VarId, Variable,
};
use vams_syntax::ast::{
    self, Actual, Assertion, BreakStmt, ConcStmt, DelayMechanism as AstDelay, Ident, LoopScheme,
    Sensitivity, SeqKind, SeqStmt, Waveform,
};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::names::scope::{Item, Native, Part, Scope, updated};
use crate::names::types::{ArrayTy, Ty};
use crate::sequential::sensitivity::{reads, reads_of_code};
use crate::{Elab, R, Reported};

/// A process (or subprogram body) being lowered.
#[derive(Default)]
pub(crate) struct Proc {
    vars: Vec<Variable>,
    code: Vec<Instr>,
    /// The statement each instruction comes from (for run-time errors), and the statement
    /// being lowered.
    spans: Vec<Span>,
    at: Span,
    loops: Vec<LoopFrame>,
    /// Set while lowering a subprogram body.
    pub(crate) subprogram: Option<SubContext>,
    /// In a function body, after a `return` that every path to here takes: the statements
    /// that follow are not lowered (with a condition that folds, `if size = 0 then return
    /// none; end if;`, what follows would index `none` or recurse on `size - 1` forever).
    dead: bool,
}

/// What a subprogram body may do.
pub(crate) struct SubContext {
    /// The function's result type; `None` for a procedure.
    pub(crate) ret: Option<Ty>,
    /// The static bounds of each value a `return` returns (`None` for one without): when
    /// they agree, the call's result has them (`to_signed(x, 8)` is 8 elements long where an
    /// unconstrained parameter receives it).
    pub(crate) returned: Vec<Option<crate::names::scope::Bounds>>,
}

struct LoopFrame {
    label: Option<String>,
    /// `Jump` instructions to patch to the loop's end.
    exits: Vec<usize>,
    /// `Jump` instructions to patch to the loop's continuation.
    nexts: Vec<usize>,
}

impl Proc {
    /// The variables, the instructions and the statement span of each instruction.
    pub(crate) fn into_parts(self) -> (Vec<Variable>, Vec<Instr>, Vec<Span>) {
        (self.vars, self.code, self.spans)
    }

    pub(crate) fn emit(&mut self, i: Instr) -> usize {
        self.code.push(i);
        self.spans.push(self.at);
        self.code.len() - 1
    }

    pub(crate) fn here(&self) -> usize {
        self.code.len()
    }

    pub(crate) fn patch(&mut self, at: usize, target: usize) {
        match &mut self.code[at] {
            Instr::Jump(t) | Instr::JumpIfNot { target: t, .. } => *t = target,
            _ => {}
        }
    }

    /// Gives variable `id` the integer range its assignments must stay within.
    pub(crate) fn bound(&mut self, id: VarId, range: Option<(i64, i64)>) {
        if let Some(v) = self.vars.get_mut(id.index()) {
            v.range = range;
        }
    }

    pub(crate) fn new_var(&mut self, name: &str, ty: &Ty, init: Value) -> VarId {
        self.vars.push(Variable {
            range: None,
            name: name.to_string(),
            ty: ty.to_design(),
            init,
        });
        VarId(self.vars.len() as u32 - 1)
    }
}

/// The index, in the object's own type `own`, of the element at index `i` of the view
/// `view` (an alias with other bounds: the same position); `i` itself when the bounds agree.
pub(crate) fn own_index(i: Expr, view: &ArrayTy, own: Option<&vams_design::Type>) -> Expr {
    let (
        Some((vl, _, vasc)),
        Some(&vams_design::Type::Array {
            left, ascending, ..
        }),
    ) = (view.bounds, own)
    else {
        return i;
    };
    if (vl, vasc) == (left, ascending) {
        return i;
    }
    // A static index stays static (it decides which element a process drives); one that
    // overflows is left to the kernel's checked arithmetic.
    if let Expr::Const(Value::Integer(k)) = i {
        let pos = if vasc {
            k.checked_sub(vl)
        } else {
            vl.checked_sub(k)
        };
        let own = pos.and_then(|p| {
            if ascending {
                left.checked_add(p)
            } else {
                left.checked_sub(p)
            }
        });
        if let Some(own) = own {
            return Expr::Const(Value::Integer(own));
        }
    }
    use vams_design::BinaryOp::{Add, Sub};
    let int = |k: i64| Expr::Const(Value::Integer(k));
    let bin = |op, a, b| Expr::Binary(op, Box::new(a), Box::new(b));
    let pos = if vasc {
        bin(Sub, i, int(vl))
    } else {
        bin(Sub, int(vl), i)
    };
    if ascending {
        bin(Add, int(left), pos)
    } else {
        bin(Sub, int(left), pos)
    }
}

impl<'a> Elab<'a> {
    fn push_process(&mut self, label: Option<&Ident>, span: Span, p: Proc) {
        let name = match label {
            Some(l) => self.hier_name(&l.name),
            None => {
                let n = self.next_unlabelled();
                self.hier_name(&format!("_p{n}"))
            }
        };
        // A design may hold one process per instance: no spare capacity in each.
        let (mut vars, mut code, mut spans) = p.into_parts();
        vars.shrink_to_fit();
        code.shrink_to_fit();
        spans.shrink_to_fit();
        // Innermost port first: a port's default applies to the processes inside it.
        let path = self.here.path.as_str();
        self.signals
            .port_defaults
            .retain(|(p, ..)| encloses(p, path));
        let mut driver_inits: Vec<(SignalId, Value)> = Vec::new();
        for (_, s, v) in self.signals.port_defaults.iter().rev() {
            if !driver_inits.iter().any(|(d, _)| d == s) {
                driver_inits.push((*s, v.clone()));
            }
        }
        self.design.processes.push(Process {
            name,
            vars,
            code,
            spans,
            span,
            driver_inits,
        });
    }

    /// The number of the next unlabelled process under the current path. Only the counters of
    /// the current path and of the paths enclosing it are kept: labels are unique, so a region
    /// once left never comes back, and a design's worth of paths is never held.
    fn next_unlabelled(&mut self) -> usize {
        let path = self.here.path.as_str();
        self.here.unlabelled.retain(|(p, _)| encloses(p, path));
        if let Some((_, n)) = self.here.unlabelled.iter_mut().find(|(p, _)| p == path) {
            *n += 1;
            return *n - 1;
        }
        self.here.unlabelled.push((path.to_string(), 1));
        0
    }

    /// An explicit process statement.
    pub(crate) fn process(
        &mut self,
        sc: &mut Scope<'a>,
        stmt: &'a ConcStmt,
        sensitivity: &Option<Sensitivity>,
        decls: &'a [ast::Decl],
        stmts: &'a [SeqStmt],
    ) {
        let mut p = Proc::default();
        sc.push();
        let outer = std::mem::replace(
            &mut self.here.process_label,
            stmt.label.as_ref().map(|l| l.name.clone()),
        );
        let ok = self.process_decls(sc, &mut p, decls).is_ok();
        // The body loops back past the initial values the declarations assign.
        let body = p.here();
        let mut on = Vec::new();
        if let Some(Sensitivity::List(names)) = sensitivity {
            for n in names {
                if let Ok(s) = self.signal_name(sc, n) {
                    if !on.contains(&s) {
                        on.push(s);
                    }
                }
            }
        }
        self.seq(sc, &mut p, stmts);
        sc.pop();
        self.here.process_label = outer;
        if sensitivity.is_some() {
            if stmts.iter().any(contains_wait) {
                self.error(ElabError::invalid(
                    stmt.span,
                    "a process with a sensitivity list cannot contain `wait`",
                    Some("remove the sensitivity list or the wait statements (LRM 11.3)".into()),
                ));
            }
            if matches!(sensitivity, Some(Sensitivity::All)) {
                on = self.sensitivity(reads_of_code(&p.code));
            }
            p.emit(Instr::Wait {
                on,
                until: None,
                timeout: None,
            });
        }
        p.emit(Instr::Jump(body));
        if ok {
            self.push_process(stmt.label.as_ref(), stmt.span, p);
        }
    }

    pub(crate) fn process_decls(
        &mut self,
        sc: &mut Scope<'a>,
        p: &mut Proc,
        decls: &'a [ast::Decl],
    ) -> R<()> {
        let mut result = Ok(());
        for d in decls {
            // An initial value assigned when the call or the process starts fails here.
            let enclosing = std::mem::replace(&mut p.at, d.span);
            if let ast::DeclKind::Variable {
                names,
                subtype,
                value,
                ..
            } = &d.kind
            {
                let r = (|| {
                    let sub = self.subtype_indication(sc, subtype)?;
                    // An initial value that is not static (a subprogram's parameter, a
                    // signal or quantity a process snapshots) is assigned when the call or
                    // the process starts (LRM 12.3.1.4).
                    let what = |_: &Self| match names.as_slice() {
                        [n] => format!("variable `{}`", n.name),
                        _ => "the variables declared here".to_string(),
                    };
                    let (init, dynamic) = match value {
                        Some(v) => {
                            let t = self.expr_of(sc, v, &sub.ty)?;
                            match self.fit_length(t, &sub.ty, what, v.span)? {
                                Expr::Const(c) => {
                                    self.check_initial(&sub, &c, v.span)?;
                                    (c, None)
                                }
                                e if let Some(c) =
                                    crate::expressions::inline::static_call_value(
                                        &self.design,
                                        &e,
                                    ) =>
                                {
                                    self.check_initial(&sub, &c, v.span)?;
                                    (c, None)
                                }
                                e => (crate::declarations::decls::default_value(&sub), Some(e)),
                            }
                        }
                        None => (crate::declarations::decls::default_value(&sub), None),
                    };
                    let ty = crate::declarations::decls::fit_array(&sub.ty, &init);
                    for n in names {
                        let id = p.new_var(&n.name, &ty, init.clone());
                        p.bound(id, crate::declarations::decls::integer_bounds(&sub));
                        if let Some(e) = &dynamic {
                            p.emit(Instr::SetVar {
                                var: id,
                                value: e.clone(),
                            });
                        }
                        if !sc.declare_at(
                            &n.name,
                            n.span,
                            Item::Variable {
                                id,
                                ty: ty.clone(),
                                readonly: false,
                                path: std::rc::Rc::from([]),
                            },
                        ) {
                            return Err(self.error(ElabError::Redeclared {
                                span: n.span,
                                name: n.name.clone(),
                            }));
                        }
                    }
                    Ok(())
                })();
                if r.is_err() {
                    result = r;
                }
            } else if let ast::DeclKind::File {
                names,
                subtype,
                open_kind,
                logical_name: Some(name),
            } = &d.kind
                && let Some(r) =
                    self.dynamic_file_decl(sc, p, names, subtype, open_kind.as_ref(), name)
            {
                if r.is_err() {
                    result = r;
                }
            } else if let ast::DeclKind::Constant {
                names,
                subtype,
                value: Some(value),
            } = &d.kind
            {
                // A subprogram's constant may depend on the parameters, a process's on what it
                // reads when it starts (a file a function loads, LRM 12.3.1.4): then it is a
                // read-only variable assigned when the call or the process starts.
                let r = (|| {
                    let sub = self.subtype_indication(sc, subtype)?;
                    let t = self.expr_of(sc, value, &sub.ty)?;
                    let what = |_: &Self| match names.as_slice() {
                        [n] => format!("constant `{}`", n.name),
                        _ => "the constants declared here".to_string(),
                    };
                    let e = self.fit_length(t, &sub.ty, what, value.span)?;
                    let e = match crate::expressions::inline::static_call_value(&self.design, &e) {
                        Some(v) => Expr::Const(v),
                        None => e,
                    };
                    for n in names {
                        let item = match &e {
                            Expr::Const(v) => Item::Constant {
                                value: v.clone(),
                                ty: crate::declarations::decls::fit_array(&sub.ty, v),
                            },
                            e => {
                                let id = p.new_var(&n.name, &sub.ty, sub.ty.default_value());
                                p.emit(Instr::SetVar {
                                    var: id,
                                    value: e.clone(),
                                });
                                Item::Variable {
                                    id,
                                    ty: sub.ty.clone(),
                                    readonly: true,
                                    path: std::rc::Rc::from([]),
                                }
                            }
                        };
                        if !sc.declare_at(&n.name, n.span, item) {
                            return Err(self.error(ElabError::Redeclared {
                                span: n.span,
                                name: n.name.clone(),
                            }));
                        }
                    }
                    Ok(())
                })();
                if r.is_err() {
                    result = r;
                }
            } else if matches!(
                d.kind,
                ast::DeclKind::Signal { .. }
                    | ast::DeclKind::Quantity(_)
                    | ast::DeclKind::Terminal { .. }
            ) {
                result = Err(self.error(ElabError::invalid(
                    d.span,
                    "signals, quantities and terminals cannot be declared in a process",
                    Some("declare them in the architecture".into()),
                )));
            } else {
                self.decl(sc, d);
            }
            p.at = enclosing;
        }
        result
    }

    fn signal_name(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> R<SignalId> {
        let t = self.signal_expr(sc, e)?;
        match t.e {
            Expr::Signal(s) => Ok(s),
            _ => Err(self.error(ElabError::WrongClass {
                span: e.span,
                name: self.sources.snippet(e.span).into(),
                found: "not a signal".into(),
                expected: "a signal".into(),
                help: Some("sensitivity lists and `wait on` name signals (a quantity threshold is `q'above(level)`)".into()),
            })),
        }
    }

    pub(crate) fn seq(&mut self, sc: &mut Scope<'a>, p: &mut Proc, stmts: &'a [SeqStmt]) {
        for s in stmts {
            if p.dead {
                break;
            }
            let enclosing = std::mem::replace(&mut p.at, s.span);
            let _ = self.seq_stmt(sc, p, s);
            p.at = enclosing;
        }
    }

    fn cond(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> R<Expr> {
        Ok(self.expr_of(sc, e, &Ty::Boolean)?.e)
    }

    fn severity(&mut self, sc: &Scope<'a>, e: Option<&ast::Expr>, default: u32) -> R<Expr> {
        let Some(e) = e else {
            return Ok(Expr::Const(Value::Enum(default)));
        };
        let Some(ty) = self.standard_type("severity_level") else {
            return Err(Reported);
        };
        Ok(self.expr_of(sc, e, &ty)?.e)
    }

    fn message(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> R<Expr> {
        let t = self.expr(sc, e, None)?;
        if !t.ty.is_string() {
            return Err(self.error(ElabError::TypeMismatch {
                span: e.span,
                expected: "string".into(),
                found: t.ty.to_string(),
                help: Some("convert numbers with `real'image(x)` and join with `&`".into()),
            }));
        }
        Ok(t.e)
    }

    fn assertion(&mut self, sc: &Scope<'a>, a: &Assertion, span: Span) -> R<Instr> {
        let cond = self.cond(sc, &a.condition);
        let report = match &a.report {
            Some(r) => Some(self.message(sc, r)?),
            None => None,
        };
        let severity = self.severity(sc, a.severity.as_ref(), 2)?;
        Ok(Instr::Assert {
            cond: Some(cond?),
            report,
            severity,
            span,
        })
    }

    /// Whether a procedure call names a native I/O procedure (silently: the call's own
    /// elaboration reports what is wrong with it).
    fn calls_native_io(&mut self, sc: &Scope<'a>, call: &ast::Expr) -> bool {
        let name = match &call.kind {
            ast::ExprKind::Apply(prefix, _) => &**prefix,
            _ => call,
        };
        let before = self.errors.len();
        let native = self.lookup(sc, name).is_ok_and(|items| {
            items.iter().any(
                |i| matches!(i, Item::Subprogram(s) if matches!(s.native, Some(Native::Io(_)))),
            )
        });
        self.errors.truncate(before);
        native
    }

    fn seq_stmt(&mut self, sc: &mut Scope<'a>, p: &mut Proc, s: &'a SeqStmt) -> R<()> {
        let in_function = p.subprogram.as_ref().is_some_and(|c| c.ret.is_some());
        let forbidden = match &s.kind {
            SeqKind::Wait { .. } => Some("wait"),
            SeqKind::SignalAssign { .. } => Some("assign signals"),
            // The native I/O procedures (`readline`, `read`, ...) change nothing but their
            // arguments and files: a function loading a table from a file may call them.
            SeqKind::ProcedureCall(c) if in_function && !self.calls_native_io(sc, c) => {
                Some("call procedures")
            }
            SeqKind::Break(_) => Some("execute `break`"),
            _ => None,
        };
        if let (true, Some(what)) = (in_function, forbidden) {
            return Err(self.error(ElabError::invalid(
                s.span,
                format!("a function cannot {what}"),
                Some("make it a procedure (LRM 4.2: functions compute a value and have no side effects on signals)".into()),
            )));
        }
        match &s.kind {
            SeqKind::Wait { on, until, timeout } => {
                if on.is_empty() && until.is_none() && timeout.is_none() {
                    p.emit(Instr::Halt);
                    return Ok(());
                }
                let mut sigs = Vec::new();
                for n in on {
                    let sig = self.signal_name(sc, n)?;
                    if !sigs.contains(&sig) {
                        sigs.push(sig);
                    }
                }
                let until = match until {
                    Some(u) => Some(self.cond(sc, u)?),
                    None => None,
                };
                let timeout = match timeout {
                    Some(t) => Some(self.expr_of(sc, t, &Ty::Time)?.e),
                    None => None,
                };
                if on.is_empty() {
                    sigs = self.sensitivity(reads(until.iter()));
                }
                p.emit(Instr::Wait {
                    on: sigs,
                    until,
                    timeout,
                });
            }
            SeqKind::SignalAssign {
                target,
                delay,
                waveform,
            } => {
                if let Some(slice) = self.runtime_signal_slice(sc, target)? {
                    return self.assign_runtime_slice(sc, p, target, slice, delay, waveform);
                }
                for i in self.assign(sc, target, delay, waveform)? {
                    p.emit(i);
                }
            }
            SeqKind::VariableAssign { target, value } => {
                if let ast::ExprKind::Aggregate(elems) = &target.kind {
                    // `(hi, lo) := v;`: the value goes to a temporary first, so that a target
                    // read by the value (`(a, b) := swapped(a, b)`) is read before any changes.
                    let mut vars = Vec::new();
                    for t in self.aggregate_targets(elems, target.span)? {
                        vars.push(self.target_variable(sc, t)?);
                    }
                    let v = self.expr(sc, value, None)?;
                    let ty = v.ty.clone();
                    let tmp = p.new_var("(aggregate target)", &ty, ty.default_value());
                    let types: Vec<Ty> = vars.iter().map(|v| v.1.clone()).collect();
                    let parts = self.split_array(
                        crate::expressions::expr::Typed::new(Expr::Var(tmp), ty),
                        &types,
                        value.span,
                    )?;
                    p.emit(Instr::SetVar {
                        var: tmp,
                        value: v.e,
                    });
                    for ((var, _), part) in vars.into_iter().zip(parts) {
                        p.emit(Instr::SetVar { var, value: part });
                    }
                    return Ok(());
                }
                if self.may_reach_heap(sc, target)
                    && let Some((pointer, path, ty)) = self.heap_target(sc, target)?
                {
                    let v = self.expr_of(sc, value, &ty)?;
                    let v = self.fit_length(
                        v,
                        &ty,
                        |e: &Self| e.target_name("variable", target),
                        value.span,
                    )?;
                    let object = Expr::Deref(Box::new(pointer.clone()));
                    let value = updated(object, &path, v);
                    p.emit(Instr::SetHeap { pointer, value });
                    return Ok(());
                }
                let (id, path, ty) = self.variable_target(sc, &p.vars, target)?;
                let v = self.expr_of(sc, value, &ty)?;
                let v = self.fit_length(
                    v,
                    &ty,
                    |e: &Self| e.target_name("variable", target),
                    value.span,
                )?;
                p.emit(match path.as_slice() {
                    [] => Instr::SetVar { var: id, value: v },
                    [Part::Element { index, .. }] => Instr::SetVarElement {
                        var: id,
                        index: index.clone(),
                        value: v,
                    },
                    _ => Instr::SetVar {
                        var: id,
                        value: updated(Expr::Var(id), &path, v),
                    },
                });
            }
            SeqKind::If {
                branches,
                otherwise,
            } => {
                // In a function, a branch whose condition folds is taken or left out (a
                // function assigns no signals, so code that cannot run has no driver to
                // keep); `dead` then says whether the branch taken returns.
                let mut ends = Vec::new();
                let mut taken = false;
                for (c, body) in branches {
                    let cond = self
                        .cond(sc, c)
                        .unwrap_or(Expr::Const(Value::Boolean(false)));
                    if in_function && let Expr::Const(Value::Boolean(holds)) = cond {
                        if holds {
                            p.dead = false;
                            self.seq(sc, p, body);
                            taken = true;
                            break;
                        }
                        continue;
                    }
                    let skip = p.emit(Instr::JumpIfNot { cond, target: 0 });
                    self.seq(sc, p, body);
                    p.dead = false;
                    ends.push(p.emit(Instr::Jump(0)));
                    let next = p.here();
                    p.patch(skip, next);
                }
                if !taken && let Some(body) = otherwise {
                    self.seq(sc, p, body);
                }
                let end = p.here();
                if !ends.is_empty() {
                    // A branch taken at run time may fall through.
                    p.dead = false;
                }
                for j in ends {
                    p.patch(j, end);
                }
            }
            SeqKind::Case {
                selector,
                alternatives,
            } => {
                let sel = self.expr(sc, selector, None)?;
                let mut ends = Vec::new();
                for (choices, body) in alternatives {
                    let cond = self.choices_condition(sc, &sel.e, &sel.ty, choices)?;
                    let cond = self.folded(cond, Ty::Boolean, s.span)?.e;
                    let skip = p.emit(Instr::JumpIfNot { cond, target: 0 });
                    self.seq(sc, p, body);
                    p.dead = false;
                    ends.push(p.emit(Instr::Jump(0)));
                    let next = p.here();
                    p.patch(skip, next);
                }
                let end = p.here();
                for j in ends {
                    p.patch(j, end);
                }
            }
            SeqKind::Loop { scheme, body } => {
                let r = self.loop_stmt(sc, p, s, scheme, body);
                // `next` and `exit` leave the body: what follows the loop runs.
                p.dead = false;
                r?
            }
            SeqKind::Next { label, condition } | SeqKind::Exit { label, condition } => {
                let is_exit = matches!(s.kind, SeqKind::Exit { .. });
                let frame = match label {
                    Some(l) => p
                        .loops
                        .iter()
                        .rposition(|f| f.label.as_deref() == Some(l.name.as_str())),
                    None => p.loops.len().checked_sub(1),
                };
                let Some(frame) = frame else {
                    return Err(self.error(ElabError::invalid(
                        s.span,
                        match label {
                            Some(l) => format!("no enclosing loop is labelled `{}`", l.name),
                            None => "`next` and `exit` must be inside a loop".into(),
                        },
                        None,
                    )));
                };
                let skip = match condition {
                    Some(c) => {
                        let cond = self.cond(sc, c)?;
                        Some(p.emit(Instr::JumpIfNot { cond, target: 0 }))
                    }
                    None => None,
                };
                let j = p.emit(Instr::Jump(0));
                if is_exit {
                    p.loops[frame].exits.push(j);
                } else {
                    p.loops[frame].nexts.push(j);
                }
                if let Some(skip) = skip {
                    let next = p.here();
                    p.patch(skip, next);
                }
            }
            SeqKind::Return(value) => {
                let Some(ctx) = &p.subprogram else {
                    return Err(self.error(ElabError::invalid(
                        s.span,
                        "`return` outside a subprogram",
                        None,
                    )));
                };
                let value = match (&ctx.ret, value) {
                    (Some(ty), Some(v)) => {
                        let ty = ty.clone();
                        let t = self.expr_of(sc, v, &ty)?;
                        // A constrained result subtype gives the result its bounds.
                        let bounds = match (&ty, &t.ty) {
                            (Ty::Array(r), _) if r.bounds.is_some() => r.bounds,
                            (_, Ty::Array(a)) => a.bounds,
                            _ => None,
                        };
                        if let Some(ctx) = &mut p.subprogram {
                            ctx.returned.push(bounds);
                        }
                        let what = |_: &Self| "the function's result".to_string();
                        Some(self.fit_length(t, &ty, what, v.span)?)
                    }
                    (None, None) => None,
                    (Some(_), None) => {
                        return Err(self.error(ElabError::invalid(
                            s.span,
                            "a function's `return` needs a value",
                            Some("write `return expression;`".into()),
                        )));
                    }
                    (None, Some(v)) => {
                        return Err(self.error(ElabError::invalid(
                            v.span,
                            "a procedure's `return` has no value",
                            Some("write `return;` (results leave through `out` parameters)".into()),
                        )));
                    }
                };
                p.emit(Instr::Return(value));
                p.dead = in_function;
            }
            SeqKind::Null => {}
            SeqKind::Assert(a) => {
                let i = self.assertion(sc, a, s.span)?;
                p.emit(i);
            }
            SeqKind::Report { message, severity } => {
                let report = self.message(sc, message)?;
                let severity = self.severity(sc, severity.as_ref(), 0)?;
                p.emit(Instr::Assert {
                    cond: None,
                    report: Some(report),
                    severity,
                    span: s.span,
                });
            }
            SeqKind::ProcedureCall(call) => {
                let (mut i, parts) = self.procedure_call(sc, &p.vars, call)?;
                // Parts of variables as `out` actuals: copied back into temporaries, then
                // spliced into their variables.
                let mut updates = Vec::new();
                for part in parts {
                    let tmp = p.new_var("(actual)", &part.ty, part.ty.default_value());
                    match &mut i {
                        Instr::Call { copy_back, .. } => copy_back.push((part.param, tmp)),
                        Instr::Native { copy_back, .. } => {
                            copy_back.push((part.param.index(), tmp));
                        }
                        _ => {}
                    }
                    let value = updated(Expr::Var(part.var), &part.path, Expr::Var(tmp));
                    updates.push(Instr::SetVar {
                        var: part.var,
                        value,
                    });
                }
                p.emit(i);
                for u in updates {
                    p.emit(u);
                }
            }
            SeqKind::Break(b) => {
                if let Some(first) = b.sensitivity.first() {
                    return Err(self.error(ElabError::invalid(
                        first.span,
                        "a sequential break has no `on` list",
                        Some("use `break ... when cond;` or a concurrent break".into()),
                    )));
                }
                let i = self.break_instr(sc, b, s.span)?;
                p.emit(i);
            }
        }
        Ok(())
    }

    fn loop_stmt(
        &mut self,
        sc: &mut Scope<'a>,
        p: &mut Proc,
        s: &'a SeqStmt,
        scheme: &'a LoopScheme,
        body: &'a [SeqStmt],
    ) -> R<()> {
        let label = s.label.as_ref().map(|l| l.name.clone());
        let mut pushed = false;
        let (top, exit_test, step): (usize, Option<usize>, Option<(VarId, bool)>) = match scheme {
            LoopScheme::Forever => (p.here(), None, None),
            LoopScheme::While(c) => {
                let cond = self.cond(sc, c)?;
                let top = p.here();
                (
                    top,
                    Some(p.emit(Instr::JumpIfNot { cond, target: 0 })),
                    None,
                )
            }
            LoopScheme::For(param, range) => {
                let (left, right, asc) = match range {
                    ast::DiscreteRange::Range(r) => {
                        let (l, r, asc) = self.range_exprs(sc, r)?;
                        (l, r, asc)
                    }
                    ast::DiscreteRange::Subtype(_) => {
                        let (l, r, asc, ty) = self.discrete_range_typed(sc, range)?;
                        let value = |v| crate::expressions::expr::Typed {
                            e: Expr::Const(crate::names::types::index_value(&ty, v)),
                            ty: ty.clone(),
                        };
                        (value(l), value(r), asc)
                    }
                };
                // An enumeration or boolean range is counted by position; the parameter is
                // the literal at the counter's position.
                let param_ty = left.ty.clone();
                let literals = match &param_ty {
                    Ty::Integer => None,
                    Ty::Enum(e) => Some((e.literals.len() as i64, 0)),
                    Ty::Boolean => Some((2, 1)),
                    _ => {
                        return Err(self.error(ElabError::invalid(
                            param.span,
                            format!("a loop runs over a discrete range, not over {param_ty}"),
                            None,
                        )));
                    }
                };
                let pos = |e: Expr| match literals {
                    None => e,
                    Some(_) => {
                        let p = Expr::Call(vams_design::Builtin::Pos, vec![e]);
                        crate::expressions::fold::fold(p.clone()).unwrap_or(p)
                    }
                };
                let (left, right) = (
                    crate::expressions::expr::Typed::new(pos(left.e), Ty::Integer),
                    crate::expressions::expr::Typed::new(pos(right.e), Ty::Integer),
                );
                let counter = format!("{}'pos", param.name);
                let var = match literals {
                    None => p.new_var(&param.name, &Ty::Integer, Value::Integer(0)),
                    Some(_) => p.new_var(&counter, &Ty::Integer, Value::Integer(0)),
                };
                p.emit(Instr::SetVar { var, value: left.e });
                let right = match right.e {
                    Expr::Const(_) => right.e,
                    e => {
                        let hidden = p.new_var(
                            &format!("{}'right", param.name),
                            &Ty::Integer,
                            Value::Integer(0),
                        );
                        p.emit(Instr::SetVar {
                            var: hidden,
                            value: e,
                        });
                        Expr::Var(hidden)
                    }
                };
                let top = p.here();
                let op = if asc { BinaryOp::Le } else { BinaryOp::Ge };
                let cond = Expr::Binary(op, Box::new(Expr::Var(var)), Box::new(right));
                let test = p.emit(Instr::JumpIfNot { cond, target: 0 });
                let visible = match literals {
                    None => var,
                    Some((n, boolean)) => {
                        let init = param_ty.default_value();
                        let visible = p.new_var(&param.name, &param_ty, init);
                        let int = |k| Expr::Const(Value::Integer(k));
                        p.emit(Instr::SetVar {
                            var: visible,
                            value: Expr::Call(
                                vams_design::Builtin::EnumVal,
                                vec![Expr::Var(var), int(n), int(boolean)],
                            ),
                        });
                        visible
                    }
                };
                sc.push();
                pushed = true;
                sc.declare_at(
                    &param.name,
                    param.span,
                    Item::Variable {
                        id: visible,
                        ty: param_ty,
                        readonly: true,
                        path: std::rc::Rc::from([]),
                    },
                );
                (top, Some(test), Some((var, asc)))
            }
        };
        p.loops.push(LoopFrame {
            label,
            exits: Vec::new(),
            nexts: Vec::new(),
        });
        self.seq(sc, p, body);
        if pushed {
            sc.pop();
        }
        let cont = p.here();
        if let Some((var, asc)) = step {
            let op = if asc { BinaryOp::Add } else { BinaryOp::Sub };
            p.emit(Instr::SetVar {
                var,
                value: Expr::Binary(
                    op,
                    Box::new(Expr::Var(var)),
                    Box::new(Expr::Const(Value::Integer(1))),
                ),
            });
        }
        p.emit(Instr::Jump(top));
        let end = p.here();
        // Invariant: pushed above and popped only here.
        let frame = p.loops.pop().expect("loop frame");
        for j in frame.exits {
            p.patch(j, end);
        }
        for j in frame.nexts {
            p.patch(j, cont);
        }
        if let Some(t) = exit_test {
            p.patch(t, end);
        }
        Ok(())
    }

    /// The delay mechanism of a signal assignment (`transport`, `[reject t] inertial`).
    pub(crate) fn delay_mechanism(
        &mut self,
        sc: &Scope<'a>,
        delay: &AstDelay,
    ) -> R<DelayMechanism> {
        Ok(match delay {
            AstDelay::Default => DelayMechanism::Inertial { reject: None },
            AstDelay::Transport => DelayMechanism::Transport,
            AstDelay::Inertial { reject } => DelayMechanism::Inertial {
                reject: match reject {
                    Some(r) => Some(self.expr_of(sc, r, &Ty::Time)?.e),
                    None => None,
                },
            },
        })
    }

    /// A signal assignment: one `Assign` for a signal target, one per element for an
    /// aggregate of signals (`(c_out, s) <= v;`: each takes its element of the value, which is
    /// evaluated once per target; nothing between them can change it). None for a `null`
    /// waveform's statement of an unguarded signal.
    fn assign(
        &mut self,
        sc: &Scope<'a>,
        target: &ast::Expr,
        delay: &AstDelay,
        waveform: &Waveform,
    ) -> R<Vec<Instr>> {
        let targets = match &target.kind {
            ast::ExprKind::Aggregate(elems) => self.aggregate_targets(elems, target.span)?,
            _ => vec![target],
        };
        let mut sigs = Vec::with_capacity(targets.len());
        for t in &targets {
            sigs.push(self.target_signal(sc, t)?);
        }
        let Waveform::Elements(elems) = waveform else {
            return Ok(Vec::new());
        };
        let mechanism = self.delay_mechanism(sc, delay)?;
        let aggregate = matches!(target.kind, ast::ExprKind::Aggregate(_));
        let types: Vec<Ty> = sigs.iter().map(|s| s.1.clone()).collect();
        // Each waveform element's value (the whole array for an aggregate target) and delay.
        let mut wave = Vec::new();
        for el in elems {
            let Some(v) = &el.value else {
                // A null transaction disconnects the driver (LRM 8.4.1): guarded signals only.
                if let Some((s, ..)) = sigs.iter().find(|(s, ..)| !self.is_guarded(*s)) {
                    let name = self.design.signals[s.index()].name.clone();
                    return Err(self.error(ElabError::invalid(
                        el.span,
                        format!("`null` disconnects a driver, and `{name}` is not a guarded signal"),
                        Some("declare the signal `bus` or `register` (of a resolved subtype) to disconnect its drivers".into()),
                    )));
                }
                let d = match &el.after {
                    Some(a) => self.expr_of(sc, a, &Ty::Time)?.e,
                    None => Expr::Const(Value::Time(0.0)),
                };
                wave.push((vec![None; sigs.len()], d));
                continue;
            };
            let v = if aggregate {
                let v = self.expr(sc, v, None)?;
                self.split_array(v, &types, el.span)?
            } else {
                let t = self.expr_of(sc, v, &sigs[0].1)?;
                vec![self.fit_length(
                    t,
                    &sigs[0].1,
                    |e: &Self| e.target_name("signal", target),
                    v.span,
                )?]
            };
            let v = v.into_iter().map(Some).collect::<Vec<_>>();
            let d = match &el.after {
                Some(a) => self.expr_of(sc, a, &Ty::Time)?.e,
                None => Expr::Const(Value::Time(0.0)),
            };
            wave.push((v, d));
        }
        Ok(sigs
            .iter()
            .enumerate()
            .map(|(k, (sig, _, index))| Instr::Assign {
                target: *sig,
                index: index.clone(),
                waveform: wave
                    .iter()
                    .map(|(v, d)| (v[k].clone(), d.clone()))
                    .collect(),
                mechanism: mechanism.clone(),
            })
            .collect())
    }

    /// A variable target `v`, `v(i)`, `v.f`, `v(i).f`, `v.f(i)`, ...: the variable, the
    /// selections from it down to the target (each an index in the bounds of the composite
    /// it selects from, a record's field by its position, with that composite's type), and
    /// the target's type.
    pub(crate) fn variable_target(
        &mut self,
        sc: &Scope<'a>,
        vars: &[Variable],
        target: &ast::Expr,
    ) -> R<(VarId, Vec<Part>, Ty)> {
        // `x(1)'dot := ...` in a simultaneous procedural: the variable standing for it.
        if let ast::ExprKind::Attribute(prefix, attr) = &target.kind
            && attr.name == "dot"
            && !self.analog.dot_targets.is_empty()
            && let Some(Item::Quantity(q)) = self.lookup(sc, prefix)?.first()
            && let Some(&var) = self.analog.dot_targets.get(q)
        {
            return Ok((var, Vec::new(), Ty::Real));
        }
        match &target.kind {
            ast::ExprKind::Selected(prefix, suffix)
                if !self.analysed.names.contains_key(&suffix.span) =>
            {
                let (id, mut path, ty) = self.variable_target(sc, vars, prefix)?;
                let (pos, field) = self.record_field(&ty, suffix, target.span)?;
                path.push(Part::Element {
                    index: Expr::Const(Value::Integer(pos as i64)),
                    container: ty.to_design(),
                });
                Ok((id, path, field))
            }
            ast::ExprKind::Apply(prefix, args) => {
                let (id, mut path, ty) = self.variable_target(sc, vars, prefix)?;
                let Ty::Array(arr) = &ty else {
                    return Err(self.error(ElabError::invalid(
                        target.span,
                        format!("a value of type {ty} cannot be indexed"),
                        Some("only arrays are indexed".into()),
                    )));
                };
                if let [
                    ast::Assoc {
                        actual: Actual::Range(r),
                        formal: None,
                        ..
                    },
                ] = args.as_slice()
                {
                    let (first, len, slice) = self.slice(sc, arr, r, target.span)?;
                    path.push(Part::Slice { first, len });
                    return Ok((id, path, slice));
                }
                self.dimension_count(arr, args.len(), target.span, "index")?;
                let mut level = ty.clone();
                for a in args {
                    let (
                        ast::Assoc {
                            actual: Actual::Expr(i),
                            formal: None,
                            ..
                        },
                        Ty::Array(arr),
                    ) = (a, &level)
                    else {
                        return Err(self.error(ElabError::unsupported(
                            a.span,
                            "this assignment target",
                            "assign a variable, an element `v(i) := x`, a field `v.f := x` or a slice",
                        )));
                    };
                    let arr = arr.clone();
                    let i = self.index_position(sc, i, &arr.index)?;
                    // The first selection is in the variable's own bounds (an alias may
                    // differ).
                    let own = vars.get(id.index()).map(|v| &v.ty);
                    let own = own.filter(|_| path.is_empty());
                    let container = own.cloned().unwrap_or_else(|| level.to_design());
                    let index = own_index(i, &arr, own);
                    path.push(Part::Element { index, container });
                    level = arr.element.clone();
                }
                Ok((id, path, level))
            }
            _ => {
                let items = self.lookup(sc, target)?;
                match &items[0] {
                    Item::Variable {
                        id,
                        ty,
                        readonly: false,
                        path,
                    } if !path.is_empty() => Ok((*id, path.to_vec(), ty.clone())),
                    _ => {
                        let (id, ty) = self.target_variable(sc, target)?;
                        Ok((id, Vec::new(), ty))
                    }
                }
            }
        }
    }

    /// How a length error names an assignment's target: "variable `v(3 downto 0)`".
    pub(crate) fn target_name(&self, class: &str, target: &ast::Expr) -> String {
        format!("{class} `{}`", self.sources.snippet(target.span))
    }

    /// The variable a (simple) target names, with its type.
    fn target_variable(&mut self, sc: &Scope<'a>, target: &ast::Expr) -> R<(VarId, Ty)> {
        let items = self.lookup(sc, target)?;
        match &items[0] {
            Item::Variable { readonly: true, .. } => Err(self.error(ElabError::invalid(
                target.span,
                "a loop parameter cannot be assigned",
                Some("copy it into a variable".into()),
            ))),
            Item::Variable { id, ty, .. } => Ok((*id, ty.clone())),
            other => Err(self.wrong_target(other, target, "a variable")),
        }
    }

    /// The error for assigning `item` with the other assignment (or not at all).
    fn wrong_target(&mut self, item: &Item<'a>, target: &ast::Expr, expected: &str) -> Reported {
        let help = match item {
            Item::Quantity(_) => {
                "quantities are defined by simultaneous statements (`q == expr;`) or set by `break q => value;`"
            }
            Item::Signal { .. } => "signals are assigned with `<=`",
            Item::Variable { .. } => "variables are assigned with `:=`",
            _ if expected == "a signal" => "only signals are assigned with `<=`",
            _ => "only variables are assigned with `:=`",
        };
        self.error(ElabError::WrongClass {
            span: target.span,
            name: self.sources.snippet(target.span).into(),
            found: item.class().into(),
            expected: expected.into(),
            help: Some(help.into()),
        })
    }

    /// The names of an aggregate target, in order (positional associations only).
    fn aggregate_targets<'e>(
        &mut self,
        elems: &'e [ast::ElementAssoc],
        span: Span,
    ) -> R<Vec<&'e ast::Expr>> {
        if elems.iter().any(|e| !e.choices.is_empty()) {
            return Err(self.error(ElabError::unsupported(
                span,
                "an aggregate target with named associations",
                "list the targets by position: `(a, b, c) <= v;`",
            )));
        }
        Ok(elems.iter().map(|e| &e.value).collect())
    }

    /// The signal a target names, with the type assigned: a whole signal, or one element
    /// of an array signal (`dout(i)`, with the index expression).
    fn target_signal(
        &mut self,
        sc: &Scope<'a>,
        target: &ast::Expr,
    ) -> R<(SignalId, Ty, Option<Expr>)> {
        if let ast::ExprKind::Apply(prefix, args) = &target.kind
            && let [
                ast::Assoc {
                    actual: Actual::Expr(i),
                    formal: None,
                    ..
                },
            ] = args.as_slice()
            && let Some(Item::Signal {
                id,
                ty: Ty::Array(arr),
            }) = self.lookup(sc, prefix)?.first()
        {
            let (id, arr) = (*id, arr.clone());
            if let Some(vams_design::SignalKind::View { len: None, .. }) =
                self.design.signals.get(id.index()).map(|s| &s.kind)
            {
                return Err(self.error(ElabError::unsupported(
                    target.span,
                    "assigning an element of one element or field of a composite signal",
                    "vams drives whole elements and fields of signals (`s(3) <= ...`, `s.f <= ...`): assign the whole field, or declare the part as its own signal",
                )));
            }
            let i = self.index_position(sc, i, &arr.index)?;
            let own = self.design.signals.get(id.index()).map(|s| &s.ty);
            return Ok((id, arr.element.clone(), Some(own_index(i, &arr, own))));
        }
        let items = self.lookup(sc, target)?;
        match &items[0] {
            Item::Signal { id, ty } => Ok((*id, ty.clone(), None)),
            other => Err(self.wrong_target(other, target, "a signal")),
        }
    }

    /// The elements of array value `v`, left to right, for targets of the given types: the
    /// array's length must be their number, its element type theirs.
    fn split_array(
        &mut self,
        v: crate::expressions::expr::Typed,
        targets: &[Ty],
        span: Span,
    ) -> R<Vec<Expr>> {
        let n = targets.len();
        let bounds = match &v.ty {
            Ty::Array(arr) => arr.bounds.map(|b| (b, arr.element.clone())),
            _ => None,
        };
        let Some(((left, right, asc), element)) = bounds else {
            return Err(self.error(ElabError::TypeMismatch {
                span,
                expected: "an array of known length (one element per target)".into(),
                found: v.ty.to_string(),
                help: Some("qualify the value with a constrained array subtype".into()),
            }));
        };
        let len = crate::names::types::bounds_len(left, right, asc);
        if len != n {
            return Err(self.error(ElabError::invalid(
                span,
                format!("the value has {len} element(s) for {n} target(s)"),
                None,
            )));
        }
        if let Some(ty) = targets.iter().find(|ty| !ty.same(&element)) {
            return Err(self.error(ElabError::TypeMismatch {
                span,
                expected: ty.to_string(),
                found: format!("an array of {element}"),
                help: None,
            }));
        }
        let ty = v.ty.to_design();
        Ok((0..n as i64)
            .map(|k| Expr::Index {
                array: Box::new(v.e.clone()),
                index: Box::new(Expr::Const(Value::Integer(if asc {
                    left + k
                } else {
                    left - k
                }))),
                ty: ty.clone(),
            })
            .collect())
    }

    fn procedure_call(
        &mut self,
        sc: &Scope<'a>,
        vars: &[Variable],
        call: &ast::Expr,
    ) -> R<(Instr, Vec<PartActual>)> {
        let name = match &call.kind {
            ast::ExprKind::Apply(prefix, _) => &**prefix,
            _ => call,
        };
        let items = self.lookup(sc, name)?;
        let native = items.iter().find_map(|i| match i {
            Item::Subprogram(s) if s.ret.is_none() => Some(s.native),
            _ => None,
        });
        match native {
            Some(Some(Native::Stop | Native::Finish)) => Ok((Instr::Stop, Vec::new())),
            Some(Some(Native::Io(_))) => {
                let subs = items
                    .iter()
                    .filter_map(|i| match i {
                        Item::Subprogram(s) if matches!(s.native, Some(Native::Io(_))) => {
                            Some(s.clone())
                        }
                        _ => None,
                    })
                    .collect();
                self.native_procedure_call(sc, vars, subs, call)
            }
            Some(None) => {
                let subs = items
                    .iter()
                    .filter_map(|i| match i {
                        Item::Subprogram(s) if s.native.is_none() => Some(s.clone()),
                        _ => None,
                    })
                    .collect();
                let (args, name_span) = match &call.kind {
                    ast::ExprKind::Apply(prefix, args) => (
                        args.as_slice(),
                        crate::expressions::expr::designator_span(prefix),
                    ),
                    _ => (&[][..], crate::expressions::expr::designator_span(call)),
                };
                let (sub, slots) = self.resolve_call(subs, args, false, call.span, name_span)?;
                self.user_procedure_call(sc, vars, &sub, &slots, call.span)
            }
            Some(Some(_)) => Err(self.error(ElabError::unsupported(
                name.span,
                format!(
                    "the standard procedure `{}`",
                    self.sources.snippet(name.span)
                ),
                "of the standard procedures vams implements std.env.stop and std.env.finish",
            ))),
            None => Err(self.error(ElabError::WrongClass {
                span: name.span,
                name: self.sources.snippet(name.span).into(),
                found: items[0].class().into(),
                expected: "a procedure".into(),
                help: None,
            })),
        }
    }

    fn break_instr(&mut self, sc: &Scope<'a>, b: &BreakStmt, span: Span) -> R<Instr> {
        let mut reinit = Vec::with_capacity(b.elements.len());
        for el in &b.elements {
            let quantity = self.quantity_name(sc, &el.quantity)?;
            let selector = match &el.selector {
                Some(s) => self.quantity_name(sc, s)?,
                None => quantity,
            };
            let value = self.expr_of(sc, &el.value, &Ty::Real)?.e;
            reinit.push(BreakReinit {
                selector,
                quantity,
                value,
            });
        }
        let when = match &b.condition {
            Some(c) => Some(self.cond(sc, c)?),
            None => None,
        };
        Ok(Instr::Break { reinit, when, span })
    }

    pub(crate) fn quantity_name(
        &mut self,
        sc: &Scope<'a>,
        e: &ast::Expr,
    ) -> R<vams_design::QuantityId> {
        // `break x => 0.0, x'dot => 0.1;`: the initial slope of a second-order equation.
        if let ast::ExprKind::Attribute(prefix, attr) = &e.kind
            && attr.name == "dot"
        {
            let q = self.quantity_name(sc, prefix)?;
            return Ok(self.dot_quantity(q));
        }
        // `break v'integ => -v'integ;` (the book's bouncing ball): the state of the integral.
        if let ast::ExprKind::Attribute(prefix, attr) = &e.kind
            && attr.name == "integ"
        {
            let q = self.quantity_name(sc, prefix)?;
            return Ok(self.integ_quantity(q));
        }
        let (name, index) = match &e.kind {
            ast::ExprKind::Apply(prefix, args) => (&**prefix, Some(args)),
            _ => (e, None),
        };
        let items = self.lookup(sc, name)?;
        match (&items[0], index) {
            (Item::Quantity(q), None) => Ok(*q),
            (Item::QuantityArray(elements), Some(args)) => {
                self.indexed_quantity(sc, elements, args, e.span)
            }
            (other, _) => Err(self.error(ElabError::WrongClass {
                span: e.span,
                name: self.sources.snippet(e.span).into(),
                found: other.class().into(),
                expected: "a quantity".into(),
                help: Some("a break list sets quantities: `break q => value;`".into()),
            })),
        }
    }

    /// The equivalent process of a concurrent statement: `body`, then wait on the signals it
    /// reads (or on `on` when given); a body that reads no signal runs once.
    fn equivalent(&mut self, stmt: &ConcStmt, p: Proc, on: Option<Vec<SignalId>>) {
        self.equivalent_process(stmt.label.as_ref(), stmt.span, p, on);
    }

    /// [`Elab::equivalent`] for a process of `span` with an optional label.
    fn equivalent_process(
        &mut self,
        label: Option<&Ident>,
        span: Span,
        mut p: Proc,
        on: Option<Vec<SignalId>>,
    ) {
        let on = match on.filter(|o| !o.is_empty()) {
            Some(on) => on,
            None => self.sensitivity(reads_of_code(&p.code)),
        };
        if on.is_empty() {
            p.emit(Instr::Halt);
        } else {
            p.emit(Instr::Wait {
                on,
                until: None,
                timeout: None,
            });
            p.emit(Instr::Jump(0));
        }
        self.push_process(label, span, p);
    }

    /// `s'delayed(t)` (LRM 14.1): an implicit signal following `s` by a transport delay of
    /// `t` seconds (0: one delta cycle), kept by the LRM's equivalent process
    /// `s'transaction`: a `bit` signal the kernel toggles whenever `s` is active. One per
    /// signal.
    pub(crate) fn transaction_signal(&mut self, s: SignalId, bit: &Ty, span: Span) -> SignalId {
        if let Some(&t) = self.signals.transaction.get(&s) {
            return t;
        }
        let id = SignalId(self.design.signals.len() as u32);
        let signal = vams_design::Signal {
            name: self.hier_name(self.sources.snippet(span)),
            ty: bit.to_design(),
            init: Value::Enum(0),
            kind: vams_design::SignalKind::Transaction { source: s },
            span,
            range: None,
            resolution: None,
            guarded: None,
        };
        self.design.signals.push(signal);
        self.signals.transaction.insert(s, id);
        id
    }

    /// `s'stable(t)` or `s'quiet(t)` (LRM 14.1): an implicit `boolean` signal that the kernel
    /// keeps ([`vams_design::SignalKind::Stable`]). One per signal, delay and attribute.
    pub(crate) fn stable_signal(
        &mut self,
        s: SignalId,
        delay: f64,
        quiet: bool,
        span: Span,
    ) -> SignalId {
        let key = (s, delay.to_bits(), quiet);
        if let Some(&id) = self.signals.stable.get(&key) {
            return id;
        }
        let id = SignalId(self.design.signals.len() as u32);
        self.design.signals.push(vams_design::Signal {
            name: self.hier_name(self.sources.snippet(span)),
            ty: Ty::Boolean.to_design(),
            init: Value::Boolean(true),
            kind: vams_design::SignalKind::Stable {
                source: s,
                delay,
                quiet,
            },
            span,
            range: None,
            resolution: None,
            guarded: None,
        });
        self.signals.stable.insert(key, id);
        id
    }

    /// `process (s) begin d <= transport s after t; end process;`. One per signal and delay.
    pub(crate) fn delayed_signal(&mut self, s: SignalId, t: f64, span: Span) -> SignalId {
        if let Some(&d) = self.signals.delayed.get(&(s, t.to_bits())) {
            return d;
        }
        let name = self.hier_name(self.sources.snippet(span));
        let source = &self.design.signals[s.index()];
        let id = SignalId(self.design.signals.len() as u32);
        let signal = vams_design::Signal {
            name,
            ty: source.ty.clone(),
            init: source.init.clone(),
            kind: vams_design::SignalKind::Implicit,
            span,
            range: None,
            resolution: None,
            guarded: None,
        };
        self.design.signals.push(signal);
        self.signals.delayed.insert((s, t.to_bits()), id);
        let mut p = Proc::default();
        p.emit(Instr::Assign {
            target: id,
            index: None,
            waveform: vec![(Some(Expr::Signal(s)), Expr::Const(Value::Time(t)))],
            mechanism: DelayMechanism::Transport,
        });
        self.equivalent_process(None, span, p, Some(vec![s]));
        id
    }

    /// The implicit signal `GUARD` of the guarded block `block` (LRM 9.1), declared in `sc`
    /// and kept equal to `guard` by an equivalent process.
    pub(crate) fn guard_signal(
        &mut self,
        sc: &mut Scope<'a>,
        block: &ConcStmt,
        guard: &ast::Expr,
    ) -> R<SignalId> {
        let cond = self.cond(sc, guard)?;
        let init = match &cond {
            Expr::Const(v) => v.clone(),
            _ => Value::Boolean(false),
        };
        let boolean = crate::names::types::Sub::of(Ty::Boolean, "boolean");
        let label = block.label.as_ref().map_or("block", |l| l.name.as_str());
        let id = self.new_signal(&format!("{label}.guard"), &boolean, init, guard.span);
        sc.declare_at(
            "guard",
            guard.span,
            Item::Signal {
                id,
                ty: Ty::Boolean,
            },
        );
        let mut p = Proc {
            at: guard.span,
            ..Default::default()
        };
        p.emit(Instr::Assign {
            target: id,
            index: None,
            waveform: vec![(Some(cond), Expr::Const(Value::Time(0.0)))],
            mechanism: DelayMechanism::Inertial { reject: None },
        });
        self.equivalent_process(None, guard.span, p, None);
        Ok(id)
    }

    /// The guard of a guarded assignment (`target <= guarded ...`, LRM 9.5.1), and for a
    /// guarded target signal the null transaction that disconnects its driver while the
    /// guard is false, after its disconnection delay (`disconnect s : t after 3 ns;`, 0 by
    /// default).
    fn guarded_assignment(
        &mut self,
        sc: &Scope<'a>,
        target: &ast::Expr,
    ) -> R<(Expr, Option<Instr>)> {
        // The guard is the signal named GUARD visible here (LRM 9.5): a guarded block's
        // implicit one, or a boolean signal the model declares with that name (a block that
        // drives its own `guard <= false;`).
        let declared = || match sc.lookup("guard") {
            Some(
                [
                    Item::Signal {
                        id,
                        ty: Ty::Boolean,
                    },
                    ..,
                ],
            ) => Some(*id),
            _ => None,
        };
        let Some(guard) = self.signals.guards.last().copied().or_else(declared) else {
            return Err(self.error(ElabError::invalid(
                target.span,
                "a guarded assignment needs a signal named GUARD",
                Some("put it in a block with a guard expression, `b : block (en = '1') is begin ... end block;`, or declare `signal guard : boolean;`".into()),
            )));
        };
        let targets = match &target.kind {
            ast::ExprKind::Aggregate(elems) => self.aggregate_targets(elems, target.span)?,
            _ => vec![target],
        };
        let mut disconnect = Vec::new();
        for t in targets {
            let (sig, _, index) = self.target_signal(sc, t)?;
            if self.is_guarded(sig) {
                let root = self.view_root(sig);
                let delay = self
                    .signals
                    .disconnect_delays
                    .get(&root)
                    .copied()
                    .unwrap_or(0.0);
                disconnect.push(Instr::Assign {
                    target: sig,
                    index,
                    waveform: vec![(None, Expr::Const(Value::Time(delay)))],
                    mechanism: DelayMechanism::Inertial { reject: None },
                });
            }
        }
        let disconnect = match disconnect.len() {
            0 => None,
            1 => disconnect.pop(),
            _ => {
                return Err(self.error(ElabError::unsupported(
                    target.span,
                    "a guarded aggregate target with guarded signals",
                    "assign each guarded signal in its own guarded assignment",
                )));
            }
        };
        Ok((Expr::Signal(guard), disconnect))
    }

    /// The signal a view shows part of (the signal itself when it is not a view).
    pub(crate) fn view_root(&self, s: SignalId) -> SignalId {
        match self.design.signals[s.index()].kind {
            vams_design::SignalKind::View { parent, .. } => parent,
            _ => s,
        }
    }

    /// Whether `s` (or the signal it is a view of) is a guarded signal (`bus`, `register`).
    pub(crate) fn is_guarded(&self, s: SignalId) -> bool {
        self.design.signals[self.view_root(s).index()]
            .guarded
            .is_some()
    }

    /// A concurrent statement's equivalent process, waiting on the signals it reads.
    pub(crate) fn concurrent_assign(&mut self, sc: &Scope<'a>, stmt: &ConcStmt) -> R<()> {
        self.concurrent_process(sc, stmt)
    }

    fn concurrent_process(&mut self, sc: &Scope<'a>, stmt: &ConcStmt) -> R<()> {
        let mut p = Proc::default();
        // `target <= guarded ...`: the whole statement is skipped while GUARD is false (and a
        // guarded target's driver disconnected).
        let guard = match &stmt.kind {
            ast::ConcKind::ConditionalAssign {
                target,
                guarded: true,
                ..
            }
            | ast::ConcKind::SelectedAssign {
                target,
                guarded: true,
                ..
            } => {
                let (g, disconnect) = self.guarded_assignment(sc, target)?;
                Some((p.emit(Instr::JumpIfNot { cond: g, target: 0 }), disconnect))
            }
            _ => None,
        };
        match &stmt.kind {
            ast::ConcKind::ConditionalAssign {
                target,
                delay,
                branches,
                ..
            } => {
                let mut ends = Vec::new();
                for (wave, cond) in branches {
                    let skip = match cond {
                        Some(c) => {
                            let cond = self.cond(sc, c)?;
                            Some(p.emit(Instr::JumpIfNot { cond, target: 0 }))
                        }
                        None => None,
                    };
                    for i in self.assign(sc, target, delay, wave)? {
                        p.emit(i);
                    }
                    if let Some(skip) = skip {
                        ends.push(p.emit(Instr::Jump(0)));
                        let next = p.here();
                        p.patch(skip, next);
                    }
                }
                let end = p.here();
                for j in ends {
                    p.patch(j, end);
                }
            }
            ast::ConcKind::SelectedAssign {
                selector,
                target,
                delay,
                alternatives,
                ..
            } => {
                let sel = self.expr(sc, selector, None)?;
                let mut ends = Vec::new();
                for (wave, choices) in alternatives {
                    let cond = self.choices_condition(sc, &sel.e, &sel.ty, choices)?;
                    let cond = self.folded(cond, Ty::Boolean, stmt.span)?.e;
                    let skip = p.emit(Instr::JumpIfNot { cond, target: 0 });
                    for i in self.assign(sc, target, delay, wave)? {
                        p.emit(i);
                    }
                    ends.push(p.emit(Instr::Jump(0)));
                    let next = p.here();
                    p.patch(skip, next);
                }
                let end = p.here();
                for j in ends {
                    p.patch(j, end);
                }
                end_guard(&mut p, guard);
                // The selector is read even when no choice matches.
                let mut code_reads = reads_of_code(&p.code);
                code_reads.extend(reads([&sel.e]));
                let on = self.sensitivity(code_reads);
                self.equivalent(stmt, p, Some(on));
                return Ok(());
            }
            ast::ConcKind::Assert(a) => {
                let i = self.assertion(sc, a, stmt.span)?;
                p.emit(i);
            }
            ast::ConcKind::ProcedureCall(call) => {
                // A concurrent call has no variables to pass parts of.
                let (i, _) = self.procedure_call(sc, &[], call)?;
                p.emit(i);
            }
            ast::ConcKind::Break(b) => {
                let i = self.break_instr(sc, b, stmt.span)?;
                p.emit(i);
                let mut on = Vec::new();
                for s in &b.sensitivity {
                    let sig = self.signal_name(sc, s)?;
                    if !on.contains(&sig) {
                        on.push(sig);
                    }
                }
                // Without an `on` list a break is sensitive to its condition's signals only.
                if on.is_empty() {
                    if let Some(c) = b.condition.as_ref() {
                        let c = self.cond(sc, c)?;
                        on = self.sensitivity(reads([&c]));
                    }
                    if on.is_empty() {
                        p.emit(Instr::Halt);
                        self.push_process(stmt.label.as_ref(), stmt.span, p);
                        return Ok(());
                    }
                }
                self.equivalent(stmt, p, Some(on));
                return Ok(());
            }
            _ => return Ok(()),
        }
        end_guard(&mut p, guard);
        self.equivalent(stmt, p, None);
        Ok(())
    }
}

/// Ends a guarded assignment's body: the guard's jump lands here, on the null transaction
/// of a guarded target if there is one (skipped when the guard is true).
fn end_guard(p: &mut Proc, guard: Option<(usize, Option<Instr>)>) {
    let Some((skip, disconnect)) = guard else {
        return;
    };
    match disconnect {
        None => {
            let end = p.here();
            p.patch(skip, end);
        }
        Some(instr) => {
            let over = p.emit(Instr::Jump(0));
            let here = p.here();
            p.patch(skip, here);
            p.emit(instr);
            let end = p.here();
            p.patch(over, end);
        }
    }
}

fn contains_wait(s: &SeqStmt) -> bool {
    let mut found = false;
    s.walk(&mut |s| found |= matches!(s.kind, SeqKind::Wait { .. }));
    found
}

/// Whether hierarchical path `outer` is `inner` or encloses it (`a` encloses `a.b` and `a(1)`,
/// not `ab`).
fn encloses(outer: &str, inner: &str) -> bool {
    outer.is_empty()
        || inner
            .strip_prefix(outer)
            .is_some_and(|rest| rest.is_empty() || rest.starts_with(['.', '(']))
}

/// An `out` or `inout` actual that is a part of a variable: the callee's parameter `param`
/// is copied into the part of `var` at `path` after the call.
pub(crate) struct PartActual {
    pub param: VarId,
    pub var: VarId,
    pub path: Vec<Part>,
    pub ty: Ty,
}

#[cfg(test)]
mod tests {
    use super::encloses;

    #[test]
    fn a_path_encloses_itself_and_its_nested_regions_only() {
        assert!(encloses("", "dut.u1"));
        assert!(encloses("dut", "dut"));
        assert!(encloses("dut", "dut.u1"));
        assert!(encloses("dut.g", "dut.g(3).b"));
        assert!(!encloses("dut", "dut2"));
        assert!(!encloses("dut.u1", "dut"));
        assert!(!encloses("dut.g(1)", "dut.g(2)"));
    }
}
