//! Statements: sequential (in processes, subprograms and procedurals), concurrent and
//! simultaneous; instances are checked against the interface of what they instantiate.

use vams_syntax::ast::{
    Actual, Assertion, Assoc, BreakStmt, Choice, ConcKind, ConcStmt, DelayMechanism, DiscreteRange,
    Expr, ExprKind, InstantiatedUnit, LoopScheme, ObjectClass, Sensitivity, SeqKind, SeqStmt,
    SimKind, Waveform,
};

use vams_syntax::source::Span;

use super::error::AnalysisError;
use super::scope::{DeclKind, RegionId, Staticness};
use super::types::{TypeId, UNKNOWN};
use super::units::Analyzer;

impl Analyzer<'_> {
    fn condition(&mut self, e: &Expr) {
        let boolean = self.std.boolean;
        self.expr(e, boolean);
    }

    /// Runs `f` in a new region covering `span` (recorded for the names-visible query).
    fn in_region(&mut self, span: Span, f: impl FnOnce(&mut Self)) {
        let r = self.new_region();
        self.scope.push(r);
        self.record_scope(span);
        f(self);
        self.scope.pop();
    }

    /// `if c then ... elsif ... else ...` (sequential) or `if c use ... end use`
    /// (simultaneous): boolean conditions, each branch's statements by `body`.
    fn if_branches<S>(
        &mut self,
        branches: &[(Expr, Vec<S>)],
        otherwise: Option<&[S]>,
        body: fn(&mut Self, &[S]),
    ) {
        for (c, stmts) in branches {
            self.condition(c);
            body(self, stmts);
        }
        if let Some(stmts) = otherwise {
            body(self, stmts);
        }
    }

    /// A case statement of either kind: choices of the selector's type.
    fn case_alternatives<S>(
        &mut self,
        selector: &Expr,
        alternatives: &[(Vec<Choice>, Vec<S>)],
        body: fn(&mut Self, &[S]),
    ) {
        let t = self.expr_any(selector);
        for (choices, stmts) in alternatives {
            self.case_choices(choices, t);
            body(self, stmts);
        }
    }

    // -----------------------------------------------------------------------------------
    // Sequential

    pub fn seq_stmts(&mut self, stmts: &[SeqStmt]) {
        for s in stmts {
            self.seq_stmt(s);
        }
    }

    fn seq_stmt(&mut self, s: &SeqStmt) {
        match &s.kind {
            SeqKind::Wait { on, until, timeout } => {
                for x in on {
                    self.expr_any(x);
                }
                if let Some(c) = until {
                    self.condition(c);
                }
                if let Some(t) = timeout {
                    let time = self.std.time;
                    self.expr(t, time);
                }
            }
            SeqKind::SignalAssign {
                target,
                waveform,
                delay,
            } => {
                let t = self.target(target);
                self.delay(delay);
                self.waveform(waveform, t);
            }
            SeqKind::VariableAssign { target, value } => {
                let t = self.target(target);
                self.expr(value, t);
            }
            SeqKind::If {
                branches,
                otherwise,
            } => self.if_branches(branches, otherwise.as_deref(), Self::seq_stmts),
            SeqKind::Case {
                selector,
                alternatives,
            } => self.case_alternatives(selector, alternatives, Self::seq_stmts),
            SeqKind::Loop { scheme, body } => match scheme {
                LoopScheme::Forever => self.seq_stmts(body),
                LoopScheme::While(c) => {
                    self.condition(c);
                    self.seq_stmts(body);
                }
                LoopScheme::For(param, range) => {
                    let t = self.discrete_range(range);
                    self.in_region(s.span, |a| {
                        // A loop parameter takes its values as the loop runs.
                        a.declare(
                            &param.name,
                            param.span,
                            DeclKind::Object {
                                class: ObjectClass::Constant,
                                ty: t,
                                value: Staticness::None,
                            },
                        );
                        a.seq_stmts(body);
                    });
                }
            },
            SeqKind::Next { condition, .. } | SeqKind::Exit { condition, .. } => {
                if let Some(c) = condition {
                    self.condition(c);
                }
            }
            SeqKind::Return(value) => {
                if let Some(v) = value {
                    let t = self.returns.last().copied().flatten().unwrap_or(UNKNOWN);
                    self.expr(v, t);
                }
            }
            SeqKind::Null => {}
            SeqKind::Assert(a) => self.assertion(a),
            SeqKind::Report { message, severity } => {
                let (string, sev) = (self.std.string, self.std.severity);
                self.expr(message, string);
                if let Some(s) = severity {
                    self.expr(s, sev);
                }
            }
            SeqKind::ProcedureCall(call) => self.procedure_call(call),
            SeqKind::Break(b) => self.break_stmt(b),
        }
    }

    /// The type of an assignment target (a name, an element, a slice, an aggregate).
    fn target(&mut self, e: &Expr) -> TypeId {
        match &e.kind {
            ExprKind::Aggregate(elements) => {
                for el in elements {
                    self.expr_any(&el.value);
                }
                UNKNOWN
            }
            _ => self.expr_any(e),
        }
    }

    fn delay(&mut self, d: &DelayMechanism) {
        if let DelayMechanism::Inertial { reject: Some(r) } = d {
            let time = self.std.time;
            self.expr(r, time);
        }
    }

    fn waveform(&mut self, w: &Waveform, ty: TypeId) {
        if let Waveform::Elements(elements) = w {
            for el in elements {
                if let Some(v) = &el.value {
                    self.expr(v, ty);
                }
                if let Some(after) = &el.after {
                    let time = self.std.time;
                    self.expr(after, time);
                }
            }
        }
    }

    fn assertion(&mut self, a: &Assertion) {
        self.condition(&a.condition);
        let (string, sev) = (self.std.string, self.std.severity);
        if let Some(r) = &a.report {
            self.expr(r, string);
        }
        if let Some(s) = &a.severity {
            self.expr(s, sev);
        }
    }

    fn break_stmt(&mut self, b: &BreakStmt) {
        for el in &b.elements {
            if let Some(sel) = &el.selector {
                self.expr_any(sel);
            }
            let t = self.expr_any(&el.quantity);
            self.expr(&el.value, t);
        }
        for s in &b.sensitivity {
            self.expr_any(s);
        }
        if let Some(c) = &b.condition {
            self.condition(c);
        }
    }

    // -----------------------------------------------------------------------------------
    // Concurrent and simultaneous

    pub fn conc_stmts(&mut self, stmts: &[ConcStmt]) {
        // Labels are visible in the whole region, their own statement included
        // (`timing_check'path_name` inside the process labelled `timing_check`).
        let region = *self.scope.last().expect("a unit always has a region");
        for label in stmts.iter().filter_map(|s| s.label.as_ref()) {
            let known = self.out.regions[region.0 as usize]
                .names
                .contains_key(&label.name);
            if !known {
                self.declare(&label.name, label.span, DeclKind::Opaque);
            }
        }
        for s in stmts {
            self.conc_stmt(s);
        }
    }

    fn conc_stmt(&mut self, s: &ConcStmt) {
        match &s.kind {
            ConcKind::Process {
                sensitivity,
                decls,
                stmts,
            } => {
                if let Some(Sensitivity::List(names)) = sensitivity {
                    for n in names {
                        self.expr_any(n);
                    }
                }
                self.in_region(s.span, |a| {
                    a.returns.push(None);
                    a.decls(decls);
                    a.seq_stmts(stmts);
                    a.returns.pop();
                });
            }
            ConcKind::ConditionalAssign {
                target,
                guarded,
                delay,
                branches,
            } => {
                if *guarded {
                    self.guard_signal(target.span);
                }
                let t = self.target(target);
                self.delay(delay);
                for (w, c) in branches {
                    self.waveform(w, t);
                    if let Some(c) = c {
                        self.condition(c);
                    }
                }
            }
            ConcKind::SelectedAssign {
                selector,
                target,
                guarded,
                delay,
                alternatives,
            } => {
                if *guarded {
                    self.guard_signal(target.span);
                }
                let sel = self.expr_any(selector);
                let t = self.target(target);
                self.delay(delay);
                for (w, choices) in alternatives {
                    self.waveform(w, t);
                    self.case_choices(choices, sel);
                }
            }
            ConcKind::Instance {
                unit,
                generic_map,
                port_map,
            } => self.instance(unit, generic_map, port_map),
            ConcKind::ForGenerate {
                param,
                range,
                decls,
                stmts,
            } => {
                let t = self.discrete_range(range);
                if let DiscreteRange::Range(r) = range {
                    self.require_static_range(r, "a generate range", Staticness::Global);
                }
                self.in_region(s.span, |a| {
                    // A generate parameter is globally static (LRM 7.4.2 (c)).
                    a.declare(
                        &param.name,
                        param.span,
                        DeclKind::Object {
                            class: ObjectClass::Constant,
                            ty: t,
                            value: Staticness::Global,
                        },
                    );
                    a.decls(decls);
                    a.conc_stmts(stmts);
                });
            }
            ConcKind::IfGenerate {
                condition,
                decls,
                stmts,
            } => {
                self.condition(condition);
                self.require_static(condition, "a generate condition", Staticness::Global);
                self.in_region(s.span, |a| {
                    a.decls(decls);
                    a.conc_stmts(stmts);
                });
            }
            ConcKind::Block {
                guard,
                header,
                decls,
                stmts,
            } => {
                if let Some(g) = guard {
                    self.condition(g);
                }
                // The maps' actuals are the enclosing region's names; the formals are the
                // block's own interface, declared in its region.
                for a in header.generic_map.iter().chain(&header.port_map) {
                    if let Actual::Expr(e) = &a.actual {
                        self.expr_any(e);
                    }
                }
                self.in_region(s.span, |a| {
                    // A guarded block declares the implicit signal GUARD (LRM 9.1), at the
                    // guard expression.
                    if let Some(g) = guard {
                        let boolean = a.std.boolean;
                        a.declare(
                            "guard",
                            g.span,
                            DeclKind::Object {
                                class: ObjectClass::Signal,
                                ty: boolean,
                                value: Staticness::None,
                            },
                        );
                    }
                    a.interfaces(&header.generics, super::scope::InterfaceRole::Generic);
                    a.interfaces(&header.ports, super::scope::InterfaceRole::Port);
                    a.decls(decls);
                    a.conc_stmts(stmts);
                });
            }
            ConcKind::Assert(a) => self.assertion(a),
            ConcKind::ProcedureCall(call) => self.procedure_call(call),
            ConcKind::Break(b) => self.break_stmt(b),
            ConcKind::Simultaneous(sim) => self.simultaneous(sim, s.span),
        }
    }

    fn simultaneous(&mut self, sim: &SimKind, span: Span) {
        match sim {
            SimKind::Simple {
                lhs,
                rhs,
                tolerance,
            } => {
                // Both sides have one type: the one the left side has when it has one,
                // else the right side's.
                let l = self.infer(lhs);
                let ty = self
                    .types()
                    .single_definite(&l)
                    .or_else(|| self.types().single_definite(&self.infer(rhs)))
                    .unwrap_or(UNKNOWN);
                self.expr(lhs, ty);
                self.expr(rhs, ty);
                if let Some(t) = tolerance {
                    let string = self.std.string;
                    self.expr(t, string);
                }
            }
            SimKind::If {
                branches,
                otherwise,
            } => self.if_branches(branches, otherwise.as_deref(), Self::conc_stmts),
            SimKind::Case {
                selector,
                alternatives,
            } => self.case_alternatives(selector, alternatives, Self::conc_stmts),
            SimKind::Procedural { decls, stmts } => self.in_region(span, |a| {
                a.returns.push(None);
                a.decls(decls);
                a.seq_stmts(stmts);
                a.returns.pop();
            }),
            SimKind::Null => {}
        }
    }

    /// A component or entity instance: formals are looked up in its interface, actuals
    /// checked against their formal's type.
    /// A guarded assignment needs a signal `GUARD` in sight: a guarded block's, or one
    /// declared (LRM 9.5).
    fn guard_signal(&mut self, at: Span) {
        match self.lookup("guard").as_deref() {
            Some([d]) if matches!(self.out.decl(*d).kind, DeclKind::Object { .. }) => {
                self.reference(at, *d);
            }
            _ => self.error(AnalysisError::Undeclared {
                span: at,
                name: "guard".into(),
                help: Some(
                    "a guarded assignment sits in a guarded block, `b : block (en = '1') is ... end block;`, or sees a boolean signal `guard`"
                        .into(),
                ),
            }),
        }
    }

    fn instance(&mut self, unit: &InstantiatedUnit, generics: &[Assoc], ports: &[Assoc]) {
        // An entity declared in several files (a folder of variants) is not one interface to
        // check the formals against, but the variant the name resolved to still gives the
        // actuals their types.
        let mut variants = false;
        let (region, name): (Option<RegionId>, String) = match unit {
            InstantiatedUnit::Component(n) | InstantiatedUnit::Entity { name: n, .. } => {
                let found = self.resolve_name(n);
                let unit_name = match &n.kind {
                    ExprKind::Name(id) | ExprKind::Selected(_, id) => id.name.clone(),
                    _ => String::new(),
                };
                let region = match found.as_deref() {
                    Some([d]) => match self.out.decl(*d).kind {
                        DeclKind::Component(r) => Some(r),
                        DeclKind::Entity(r) => {
                            variants = self.declared_twice(d);
                            Some(r)
                        }
                        _ => None,
                    },
                    _ => None,
                };
                (region, unit_name)
            }
            InstantiatedUnit::Configuration(_) => (None, String::new()),
        };
        self.associations(region, &name, variants, generics, ports);
    }

    /// The generic and port maps of an instance or binding indication: each formal found in
    /// the interface `region` of `name` (a component or entity; not checked when it has
    /// `variants` in several files), each actual analysed with the formal's type.
    fn associations(
        &mut self,
        region: Option<RegionId>,
        name: &str,
        variants: bool,
        generics: &[Assoc],
        ports: &[Assoc],
    ) {
        for (assocs, what) in [(generics, "generic"), (ports, "port")] {
            for a in assocs {
                // `to_bool(y) => yb`: a conversion of the port `y`, read where the instance
                // is, with the interface's names visible; it gives a value of the actual's
                // type.
                if let (
                    Some(
                        f @ Expr {
                            kind: ExprKind::Apply(prefix, _),
                            ..
                        },
                    ),
                    Some(r),
                    Actual::Expr(x),
                ) = (&a.formal, region, &a.actual)
                    && what == "port"
                    && !matches!(&prefix.kind, ExprKind::Name(p) if self.lookup_in(r, &p.name).is_some())
                {
                    let actual_ty = self.expr(x, UNKNOWN);
                    self.scope.push(r);
                    self.expr(f, actual_ty);
                    self.scope.pop();
                    continue;
                }
                let formal_ty = match (&a.formal, region) {
                    (
                        Some(Expr {
                            kind: ExprKind::Name(id),
                            ..
                        }),
                        Some(r),
                    ) => match self.lookup_in(r, &id.name).as_deref() {
                        Some([d]) => {
                            self.reference(id.span, *d);
                            match self.out.decl(*d).kind {
                                DeclKind::Object { ty, .. } => Some(ty),
                                _ => None,
                            }
                        }
                        Some(_) => None,
                        None if variants => None,
                        None => {
                            self.error(AnalysisError::UnknownFormal {
                                span: id.span,
                                name: id.name.clone(),
                                what,
                                unit: name.to_string(),
                                help: None,
                            });
                            None
                        }
                    },
                    _ => None,
                };
                match &a.actual {
                    Actual::Expr(x) => {
                        self.expr(x, formal_ty.unwrap_or(UNKNOWN));
                    }
                    Actual::Range(r) => {
                        self.range(r, UNKNOWN);
                    }
                    Actual::Open(_) => {}
                }
            }
        }
    }

    /// The maps of a binding indication (`use entity work.reg(rtl) generic map (t_pd =>
    /// 150 ps, width => width)`): formals of the entity, actuals read where the component
    /// `component` (its interface region) is instantiated, so that its local generics and
    /// ports are visible. Returns the unit of the entity bound.
    pub fn binding_maps(
        &mut self,
        binding: &vams_syntax::ast::Binding,
        component: Option<RegionId>,
    ) -> Option<usize> {
        let mut variants = false;
        let mut unit = None;
        let (region, name) = match &binding.unit {
            Some(InstantiatedUnit::Entity { name: n, .. }) => {
                let n: &Expr = n;
                let found = self.resolve_name(n);
                let region = match found.as_deref() {
                    Some([d]) => match self.out.decl(*d).kind {
                        DeclKind::Entity(r) => {
                            variants = self.declared_twice(d);
                            unit = self.unit_declaring(*d);
                            Some(r)
                        }
                        _ => None,
                    },
                    _ => None,
                };
                (region, super::simple_name(n).to_string())
            }
            _ => (None, String::new()),
        };
        if let Some(c) = component {
            self.scope.push(c);
        }
        self.associations(
            region,
            &name,
            variants,
            &binding.generic_map,
            &binding.port_map,
        );
        if component.is_some() {
            self.scope.pop();
        }
        unit
    }
}
