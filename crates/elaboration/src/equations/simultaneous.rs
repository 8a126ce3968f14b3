//! Simultaneous statements to [`Equation`]s: `lhs == rhs` gives the residual `lhs - rhs`;
//! a simultaneous if or case gives one equation per position whose residual is a chain of
//! [`Expr::If`] over its branches.

use rustc_hash::FxHashMap;

use vams_design::{
    BinaryOp, Equation, Expr, Instr, QuantityId, Subprogram, SubprogramKind, UnaryOp, Value, VarId,
};
use vams_syntax::ast::{self, Choice, ConcKind, ConcStmt, SimKind};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::names::scope::{Item, Scope};
use crate::names::types::Ty;
use crate::sequential::process::{Proc, SubContext};
use crate::{Elab, R};

/// A branch of a simultaneous if or case: its condition (`None` for the default) and body.
type Arm<'s> = (Option<(Expr, Span)>, &'s [ConcStmt]);

/// The quantity attributes that apply to a quantity array element by element (`'dot` has
/// its own arm: it also applies to derivatives).
const ELEMENTWISE: [&str; 6] = ["integ", "slew", "ltf", "zoh", "ztf", "delayed"];

/// What a composite side knows of the other side of its equation: its number of scalar
/// elements and, when it names a quantity array, that array's left bound and direction (an
/// aggregate with `others` and named choices places its elements by them).
#[derive(Clone, Copy)]
struct Extent {
    len: usize,
    bounds: Option<(i64, bool)>,
}

/// An equation before it is placed in the design.
struct Eqn {
    residual: Expr,
    span: Span,
    text: String,
}

impl<'a> Elab<'a> {
    /// Elaborates one simultaneous statement into the design's equations.
    pub(crate) fn simultaneous(&mut self, sc: &Scope<'a>, stmt: &'a ConcStmt, kind: &'a SimKind) {
        if let Ok(eqns) = self.sim_equations(sc, stmt, kind) {
            for e in eqns {
                self.design.equations.push(Equation {
                    residual: e.residual,
                    span: e.span,
                    instance: self.here.instance.clone(),
                    text: e.text,
                });
            }
        }
    }

    fn analog(&mut self, sc: &Scope<'a>, e: &ast::Expr, ty: &Ty) -> R<Expr> {
        let t = self.expr_of(sc, e, ty)?;
        self.analog_value(t.e, t.ty, e.span)
    }

    /// `e` of type `ty` (the expression at `span`) as an equation reads it: calls inlined,
    /// folded, and checked to read only what an equation may.
    pub(crate) fn analog_value(&mut self, e: Expr, ty: Ty, span: Span) -> R<Expr> {
        let inlined = self.inline_calls(e, span)?;
        let t = self.folded(inlined, ty, span)?;
        if !t.e.is_analog() {
            return Err(self.error(ElabError::invalid(
                span,
                "this expression cannot appear in a simultaneous statement",
                Some("equations read quantities, signals, constants and `now`; not variables, array elements of signals, images or signal attributes".into()),
            )));
        }
        Ok(t.e)
    }

    /// The scalar subelements, in order, of one side of a simple simultaneous statement of a
    /// composite type: a quantity array or a slice of one, a record quantity, an aggregate
    /// (`others` takes its length from `len`, the other side's), a constant array, a call of
    /// a function returning an array, `'dot` of any of the quantity forms. `None` when the
    /// side is scalar.
    fn composite_side(
        &mut self,
        sc: &Scope<'a>,
        e: &'a ast::Expr,
        len: Option<Extent>,
    ) -> R<Option<Vec<Expr>>> {
        use ast::ExprKind;
        match &e.kind {
            ExprKind::Paren(inner) => self.composite_side(sc, inner, len),
            ExprKind::Aggregate(elems) => self.equation_aggregate(sc, e, elems, len).map(Some),
            ExprKind::Attribute(prefix, attr) if attr.name == "dot" => {
                let Some(inner) = self.composite_side(sc, prefix, len)? else {
                    return Ok(None);
                };
                inner
                    .into_iter()
                    .map(|x| match x {
                        Expr::Quantity(q) => Ok(Expr::Dot(q)),
                        Expr::Dot(q) => Ok(Expr::Dot(self.dot_quantity(q))),
                        _ => Err(self.error(ElabError::invalid(
                            prefix.span,
                            "`'dot` applies to quantities",
                            None,
                        ))),
                    })
                    .collect::<R<Vec<_>>>()
                    .map(Some)
            }
            ExprKind::Name(_) | ExprKind::Selected(..) => {
                let items = self.lookup(sc, e)?;
                Ok(composite_item(&items[0]))
            }
            // `v'slew(1.0e6, -1.0e6)`, `v'integ`, `v'ltf(num, den)` of a quantity array: the
            // attribute of each element.
            ExprKind::Attribute(prefix, attr) if ELEMENTWISE.contains(&attr.name.as_str()) => {
                self.elementwise_attribute(sc, prefix, attr, &[], e.span, len)
            }
            ExprKind::Apply(target, args)
                if matches!(&target.kind, ExprKind::Attribute(_, attr)
                    if ELEMENTWISE.contains(&attr.name.as_str())) =>
            {
                let ExprKind::Attribute(prefix, attr) = &target.kind else {
                    return Ok(None);
                };
                self.elementwise_attribute(sc, prefix, attr, args, e.span, len)
            }
            ExprKind::Apply(prefix, args) => {
                let is_object = matches!(prefix.kind, ExprKind::Name(_) | ExprKind::Selected(..));
                let items = if is_object {
                    self.lookup(sc, prefix)?
                } else {
                    Vec::new()
                };
                match items.first() {
                    Some(Item::QuantityArray(_))
                        if matches!(
                            args.as_slice(),
                            [ast::Assoc {
                                actual: ast::Actual::Range(_),
                                ..
                            }]
                        ) =>
                    {
                        let item = self.element_item(sc, e, prefix, args)?;
                        Ok(composite_item(&item))
                    }
                    // A conversion to a closely related array type, `real_vector(v_out)`
                    // of an array of a subtype of real: the same elements.
                    Some(Item::Type(_)) => match args.as_slice() {
                        [
                            ast::Assoc {
                                formal: None,
                                actual: ast::Actual::Expr(inner),
                                ..
                            },
                        ] => self.composite_side(sc, inner, len),
                        _ => Ok(None),
                    },
                    // A call of a function returning an array of reals.
                    Some(Item::Subprogram(_)) => {
                        let t = self.expr(sc, e, None)?;
                        let Ty::Array(a) = &t.ty else {
                            return Ok(None);
                        };
                        let Some(bounds) = a.bounds.filter(|_| a.element == Ty::Real) else {
                            return Ok(None);
                        };
                        let ty = t.ty.to_design();
                        Ok(Some(
                            crate::names::composite::indexes(bounds)
                                .into_iter()
                                .map(|i| Expr::Index {
                                    array: Box::new(t.e.clone()),
                                    index: Box::new(Expr::Const(Value::Integer(i))),
                                    ty: ty.clone(),
                                })
                                .collect(),
                        ))
                    }
                    _ => Ok(None),
                }
            }
            _ => Ok(None),
        }
    }

    /// The elements of an aggregate side of an equation, in order: positional (`(1.0, x)`),
    /// named (`(1 => x, 2 to 3 => 0.0)`, in ascending index order, as the aggregate's own
    /// bounds are when the other side gives none) or either with `others`, which fills the
    /// other side's length, named choices placed by its bounds (`len`).
    fn equation_aggregate(
        &mut self,
        sc: &Scope<'a>,
        e: &'a ast::Expr,
        elems: &'a [ast::ElementAssoc],
        len: Option<Extent>,
    ) -> R<Vec<Expr>> {
        let mut positional = Vec::new();
        let mut named: Vec<(i64, Expr, Span)> = Vec::new();
        let mut others = None;
        for el in elems {
            if el.choices.is_empty() {
                positional.push(self.analog(sc, &el.value, &Ty::Real)?);
                continue;
            }
            if let [Choice::Others(_)] = el.choices.as_slice() {
                others = Some(&el.value);
                continue;
            }
            let v = self.analog(sc, &el.value, &Ty::Real)?;
            for c in &el.choices {
                match c {
                    Choice::Expr(ce) => {
                        let i = match self.static_value(
                            sc,
                            ce,
                            &Ty::Integer,
                            "an aggregate choice",
                        )? {
                            Value::Integer(i) => i,
                            _ => {
                                return Err(self.error(ElabError::invalid(
                                    ce.span,
                                    "an aggregate choice of a quantity array must be an integer index",
                                    None,
                                )));
                            }
                        };
                        named.push((i, v.clone(), ce.span));
                    }
                    Choice::Range(r) => {
                        let (l, rr, asc) = self.range_bounds(sc, r)?;
                        let (lo, hi) = if asc { (l, rr) } else { (rr, l) };
                        for i in lo..=hi {
                            named.push((i, v.clone(), choice_span(c)));
                        }
                    }
                    Choice::Others(s) => {
                        return Err(self.error(ElabError::invalid(
                            *s,
                            "`others` stands alone as the last choice of an aggregate",
                            None,
                        )));
                    }
                }
            }
        }
        if !named.is_empty() && !positional.is_empty() {
            return Err(self.error(ElabError::invalid(
                e.span,
                "an aggregate mixes positional and named elements",
                Some(
                    "write all elements by position or all by name (`others` may end either)"
                        .into(),
                ),
            )));
        }
        let Some(o) = others else {
            if named.is_empty() {
                return Ok(positional);
            }
            // No `others`: the aggregate's bounds are its choices', ascending.
            named.sort_by_key(|n| n.0);
            for w in named.windows(2) {
                if w[1].0 != w[0].0 + 1 {
                    let (what, span) = if w[1].0 == w[0].0 {
                        (format!("index {} is given twice", w[1].0), w[1].2)
                    } else {
                        (
                            format!("no element is given for index {}", w[0].0 + 1),
                            e.span,
                        )
                    };
                    return Err(self.error(ElabError::invalid(
                        span,
                        format!("this aggregate's choices do not cover one range: {what}"),
                        Some("give each index once, or end with `others => ...`".into()),
                    )));
                }
            }
            return Ok(named.into_iter().map(|n| n.1).collect());
        };
        let Some(extent) = len else {
            return Err(self.error(ElabError::invalid(
                e.span,
                "the length of this aggregate is not known here",
                Some("put the quantity array on the left: `v == (others => 0.0);`".into()),
            )));
        };
        let fill = self.analog(sc, o, &Ty::Real)?;
        let mut out = positional;
        if out.len() < extent.len {
            out.resize(extent.len, fill);
        }
        if named.is_empty() {
            return Ok(out);
        }
        let Some((left, ascending)) = extent.bounds else {
            return Err(self.error(ElabError::invalid(
                e.span,
                "the bounds of this aggregate are not known here",
                Some("put a quantity array on the left (`v == (1 => x, others => 0.0);`), or write the elements in order".into()),
            )));
        };
        for (i, v, span) in named {
            let pos = if ascending { i - left } else { left - i };
            match usize::try_from(pos).ok().filter(|&p| p < out.len()) {
                Some(p) => out[p] = v,
                None => {
                    return Err(self.error(ElabError::invalid(
                        span,
                        format!("index {i} is outside the other side's bounds"),
                        None,
                    )));
                }
            }
        }
        Ok(out)
    }

    /// The left bound and direction of `e` when it names a whole quantity array.
    fn quantity_array_bounds(&mut self, sc: &Scope<'a>, e: &'a ast::Expr) -> Option<(i64, bool)> {
        match &e.kind {
            ast::ExprKind::Paren(inner) => self.quantity_array_bounds(sc, inner),
            ast::ExprKind::Name(_) | ast::ExprKind::Selected(..) => {
                match self.lookup(sc, e).ok()?.first() {
                    Some(Item::QuantityArray(a)) => Some((a.left, a.ascending)),
                    _ => None,
                }
            }
            _ => None,
        }
    }

    /// `prefix'attr(args)` applied to each element of a quantity array `prefix`; `None` when
    /// `prefix` is scalar.
    fn elementwise_attribute(
        &mut self,
        sc: &Scope<'a>,
        prefix: &'a ast::Expr,
        attr: &ast::Ident,
        args: &[ast::Assoc],
        span: Span,
        len: Option<Extent>,
    ) -> R<Option<Vec<Expr>>> {
        let Some(elements) = self.composite_side(sc, prefix, len)? else {
            return Ok(None);
        };
        let mut out = Vec::with_capacity(elements.len());
        for x in elements {
            let Expr::Quantity(q) = x else {
                return Err(self.error(ElabError::invalid(
                    prefix.span,
                    format!("`'{}` applies to quantities", attr.name),
                    None,
                )));
            };
            out.push(match attr.name.as_str() {
                "integ" => Expr::Quantity(self.integ_quantity(q)),
                "slew" => self.quantity_slew_attribute(sc, q, args, span)?,
                "ltf" => self.ltf_attribute(sc, q, args, span)?,
                "zoh" => self.zoh_attribute(sc, q, args, span)?,
                "ztf" => self.ztf_attribute(sc, q, args, span)?,
                _ => self.delayed_attribute(sc, q, args, span)?,
            });
        }
        Ok(Some(out))
    }

    /// The equations of a composite simple simultaneous statement, element by element.
    fn composite_equations(
        &mut self,
        stmt: &'a ConcStmt,
        lhs: &'a ast::Expr,
        rhs: &'a ast::Expr,
        l: Option<Vec<Expr>>,
        r: Option<Vec<Expr>>,
    ) -> R<Vec<Eqn>> {
        let (Some(l), Some(r)) = (l, r) else {
            return Err(self.error(ElabError::invalid(
                stmt.span,
                "one side of this equation is composite (an array or a record), the other scalar",
                Some("give both sides the same type: index the array, `v(1) == 0.0`, or write an aggregate, `v == (others => 0.0)`".into()),
            )));
        };
        if l.len() != r.len() {
            return Err(self.error(ElabError::invalid(
                stmt.span,
                format!(
                    "the sides of this equation have {} and {} elements",
                    l.len(),
                    r.len()
                ),
                Some("equate arrays of the same length".into()),
            )));
        }
        let text = self.text(stmt.span);
        let mut eqns = Vec::with_capacity(l.len());
        for (k, (a, b)) in l.into_iter().zip(r).enumerate() {
            let a = self.analog_value(a, Ty::Real, lhs.span)?;
            let b = self.analog_value(b, Ty::Real, rhs.span)?;
            let residual = Expr::Binary(BinaryOp::Sub, Box::new(a), Box::new(b));
            let residual = self.folded(residual, Ty::Real, stmt.span)?.e;
            eqns.push(Eqn {
                residual,
                span: stmt.span,
                text: format!("{text} (element {})", k + 1),
            });
        }
        Ok(eqns)
    }

    fn sim_equations(
        &mut self,
        sc: &Scope<'a>,
        stmt: &'a ConcStmt,
        kind: &'a SimKind,
    ) -> R<Vec<Eqn>> {
        match kind {
            SimKind::Simple { lhs, rhs, .. } => {
                // A composite statement (`v == (1.0, 2.0, 3.0)`, `w == v(2 to 3)`): one
                // equation per scalar subelement (LRM 1076.1 15.1).
                let l = self.composite_side(sc, lhs, None)?;
                let extent = l.as_ref().map(|l| Extent {
                    len: l.len(),
                    bounds: self.quantity_array_bounds(sc, lhs),
                });
                let r = self.composite_side(sc, rhs, extent)?;
                if l.is_some() || r.is_some() {
                    return self.composite_equations(stmt, lhs, rhs, l, r);
                }
                let l = self.analog(sc, lhs, &Ty::Real);
                let r = self.analog(sc, rhs, &Ty::Real);
                let residual = Expr::Binary(BinaryOp::Sub, Box::new(l?), Box::new(r?));
                let residual = self.folded(residual, Ty::Real, stmt.span)?.e;
                Ok(vec![Eqn {
                    residual,
                    span: stmt.span,
                    text: self.text(stmt.span),
                }])
            }
            SimKind::Null => Ok(Vec::new()),
            SimKind::Procedural { decls, stmts } => self.procedural(sc, stmt, decls, stmts),
            SimKind::If {
                branches,
                otherwise,
            } => {
                let mut arms = Vec::new();
                for (cond, body) in branches {
                    let c = self.analog(sc, cond, &Ty::Boolean)?;
                    arms.push((Some((c, cond.span)), body.as_slice()));
                }
                arms.push((None, otherwise.as_deref().unwrap_or(&[])));
                self.combine(sc, stmt, "if", arms)
            }
            SimKind::Case {
                selector,
                alternatives,
            } => {
                let sel = self.expr(sc, selector, None)?;
                if !sel.e.is_analog() {
                    return Err(self.error(ElabError::invalid(
                        selector.span,
                        "this selector cannot appear in a simultaneous statement",
                        None,
                    )));
                }
                let mut arms = Vec::new();
                let mut has_others = false;
                for (choices, body) in alternatives {
                    if choices.iter().any(|c| matches!(c, Choice::Others(_))) {
                        has_others = true;
                        arms.push((None, body.as_slice()));
                        continue;
                    }
                    let c = self.choices_condition(sc, &sel.e, &sel.ty, choices)?;
                    let span = choices.first().map_or(stmt.span, choice_span);
                    arms.push((Some((c, span)), body.as_slice()));
                }
                if !has_others {
                    // The LRM requires the choices to cover the selector's type; without
                    // `others` the last alternative is taken as the default.
                    if let Some(last) = arms.last_mut() {
                        last.0 = None;
                    }
                }
                self.combine(sc, stmt, "case", arms)
            }
        }
    }

    /// A simultaneous procedural statement (LRM 1076.1 15.4): equivalent to one equation per
    /// quantity it assigns, `q == (the value its body leaves in q)`. The body is lowered like a
    /// procedure, each assigned quantity a variable that starts at the quantity's value (so a
    /// read before the assignment reads the quantity), and executed symbolically as a function
    /// called in an equation is (`inline`): branches on quantities become conditional
    /// expressions, loops with static bounds unroll.
    fn procedural(
        &mut self,
        sc: &Scope<'a>,
        stmt: &'a ConcStmt,
        decls: &'a [ast::Decl],
        stmts: &'a [ast::SeqStmt],
    ) -> R<Vec<Eqn>> {
        let mut targets: Vec<&ast::Ident> = Vec::new();
        assigned_names(stmts, &mut targets);
        let mut inner = sc.clone();
        inner.push();
        let mut p = Proc::default();
        p.subprogram = Some(SubContext {
            ret: None,
            returned: Vec::new(),
        });
        // Each assigned quantity, quantity array or derivative (`x(1)'dot := ...`), as the
        // unknowns its value gives (`Expr::Quantity`, `Expr::Dot`), with the variable
        // standing for it.
        let mut outputs: Vec<(Vec<Expr>, VarId)> = Vec::new();
        let mut frame_of: Vec<(VarId, Expr)> = Vec::new();
        for id in targets {
            let Some(decl) = self.analysed.names.get(&id.span).copied() else {
                continue;
            };
            let (quantities, ty, start) = match self.resolved_item(sc, id) {
                Some(Item::Quantity(q)) => (vec![Expr::Quantity(q)], Ty::Real, Expr::Quantity(q)),
                Some(Item::QuantityArray(elements)) => {
                    let elems: Vec<Expr> =
                        elements.ids.iter().map(|&q| Expr::Quantity(q)).collect();
                    let start = Expr::Aggregate {
                        elems: elems.clone(),
                        string: false,
                    };
                    (elems, elements.ty(), start)
                }
                _ => continue,
            };
            if outputs.iter().any(|(o, _)| *o == quantities) {
                continue;
            }
            let init = ty.default_value();
            let var = p.new_var(&id.name, &ty, init);
            let item = Item::Variable {
                id: var,
                ty,
                readonly: false,
                path: std::rc::Rc::from([]),
            };
            // Declared at the quantity's own declaration, so that the names analysis resolved
            // to the quantity find the variable inside the body.
            inner.declare_at(&id.name, decl, item);
            outputs.push((quantities, var));
            frame_of.push((var, start));
        }
        // `x(1)'dot := ...`: a variable for each derivative assigned, its equation
        // `x(1)'dot == value`.
        let mut dot_prefixes = Vec::new();
        dot_targets(stmts, &mut dot_prefixes);
        let mut derivatives: FxHashMap<QuantityId, VarId> = FxHashMap::default();
        for prefix in dot_prefixes {
            let q = match self.lookup(sc, prefix)?.first() {
                Some(Item::Quantity(q)) => *q,
                _ => {
                    return Err(self.error(ElabError::invalid(
                        prefix.span,
                        "`'dot` assigned in a procedural must be of one quantity, `q'dot` or `q(1)'dot`",
                        None,
                    )));
                }
            };
            if derivatives.contains_key(&q) {
                continue;
            }
            let name = format!("{}'dot", self.text(prefix.span));
            let var = p.new_var(&name, &Ty::Real, Value::Real(0.0));
            derivatives.insert(q, var);
            outputs.push((vec![Expr::Dot(q)], var));
            frame_of.push((var, Expr::Dot(q)));
        }
        if outputs.is_empty() {
            return Err(self.error(ElabError::invalid(
                stmt.span,
                "this procedural assigns no quantity, so it gives no equation",
                Some("assign the quantities it computes with `q := expression;`".into()),
            )));
        }
        let before = self.errors.len();
        let outer_dots = std::mem::replace(&mut self.analog.dot_targets, derivatives);
        let decls_ok = self.process_decls(&mut inner, &mut p, decls).is_ok();
        self.seq(&mut inner, &mut p, stmts);
        self.analog.dot_targets = outer_dots;
        p.emit(Instr::Return(None));
        if !decls_ok || self.errors.len() > before {
            return Err(crate::Reported);
        }
        let (vars, code, spans) = p.into_parts();
        let mut frame: Vec<Expr> = vars.iter().map(|v| Expr::Const(v.init.clone())).collect();
        for (var, start) in frame_of {
            frame[var.index()] = start;
        }
        let body = Subprogram {
            name: "procedural".into(),
            kind: SubprogramKind::Procedure,
            params: Vec::new(),
            vars,
            code,
            spans,
            span: stmt.span,
            intrinsic: None,
        };
        let vars: Vec<VarId> = outputs.iter().map(|&(_, v)| v).collect();
        let values = match crate::expressions::inline::procedural_values(
            &self.design,
            &body,
            &frame,
            &vars,
        ) {
            Ok(values) => values,
            Err(e) => {
                return Err(self.error(ElabError::invalid(
                    stmt.span,
                    format!("this procedural cannot be turned into equations: {}", e.reason),
                    Some("a procedural computes its quantities with variable assignments, `if`, `case`, loops with bounds known before the run, and calls of such functions".into()),
                )));
            }
        };
        let text = self.text(stmt.span);
        let mut eqns = Vec::new();
        for ((unknowns, _), value) in outputs.into_iter().zip(values) {
            let parts = match unknowns.len() {
                1 if !is_array_value(&value) => Some(vec![value]),
                n => array_elements(value, n),
            };
            let Some(parts) = parts.filter(|p| p.iter().all(Expr::is_analog)) else {
                return Err(self.error(ElabError::invalid(
                    stmt.span,
                    "this procedural computes a value an equation cannot hold",
                    Some("equations read quantities, signals, constants and `now`".into()),
                )));
            };
            for (unknown, value) in unknowns.into_iter().zip(parts) {
                let target = match unknown {
                    Expr::Dot(q) => format!("{}'dot", self.qname(q)),
                    Expr::Quantity(q) => self.qname(q),
                    // `outputs` holds these two forms only.
                    _ => String::new(),
                };
                let residual = Expr::Binary(BinaryOp::Sub, Box::new(unknown), Box::new(value));
                let residual = self.folded(residual, Ty::Real, stmt.span)?.e;
                eqns.push(Eqn {
                    residual,
                    span: stmt.span,
                    text: format!("{target} := ... in {text}"),
                });
            }
        }
        Ok(eqns)
    }

    /// Merges branch equation lists position by position into `If` chains. `arms` ends with
    /// the default branch (condition `None`).
    fn combine(
        &mut self,
        sc: &Scope<'a>,
        stmt: &ConcStmt,
        what: &'static str,
        arms: Vec<Arm<'a>>,
    ) -> R<Vec<Eqn>> {
        let mut lists = Vec::new();
        let mut failed = false;
        for (cond, body) in arms {
            // A static condition selects its branch at elaboration.
            if let Some((Expr::Const(Value::Boolean(false)), _)) = cond {
                continue;
            }
            let mut eqns = Vec::new();
            for s in body {
                match &s.kind {
                    ConcKind::Simultaneous(k) => match self.sim_equations(sc, s, k) {
                        Ok(e) => eqns.extend(e),
                        Err(_) => failed = true,
                    },
                    _ => {
                        failed = true;
                        self.error(ElabError::invalid(
                            s.span,
                            "only simultaneous statements may appear in a simultaneous if or case",
                            Some("move it out of the `use` branch".into()),
                        ));
                    }
                }
            }
            let always = matches!(cond, None | Some((Expr::Const(Value::Boolean(true)), _)));
            lists.push((cond.map(|c| c.0), eqns));
            if always {
                break;
            }
        }
        if failed {
            return Err(crate::Reported);
        }
        // `if c1 use ... elsif c2 use ... end use;` with no `else`, whose branches agree: the
        // conditions usually cover every case (`v > -5.0 * vt` and `v <= -5.0 * vt`, as
        // device models write them), and LRM 1076.1's count rule only fails at a time when
        // none holds. The last branch stands in between accepted points (Newton's iterates
        // may stray there); the kernel stops the run at an accepted point that none covers.
        // A lone `if c use ... end use;` cannot cover anything by itself: it stays an error
        // that `vams check` reports.
        if lists.len() > 2
            && matches!(lists.last(), Some((None, e)) if e.is_empty())
            && arms_implicit_else(&lists)
        {
            lists.pop();
            let condition = (lists.iter().filter_map(|(c, _)| c.clone()))
                .reduce(|a, b| Expr::Binary(BinaryOp::Or, Box::new(a), Box::new(b)));
            if let Some(condition) = condition {
                self.design.branch_covers.push(vams_design::BranchCover {
                    condition,
                    span: stmt.span,
                });
            }
        }
        let counts: Vec<usize> = lists.iter().map(|(_, e)| e.len()).collect();
        if counts.windows(2).any(|w| w[0] != w[1]) {
            let counts = counts
                .iter()
                .map(|c| c.to_string())
                .collect::<Vec<_>>()
                .join(", ");
            return Err(self.error(ElabError::BranchEquations {
                span: stmt.span,
                what,
                counts,
            }));
        }
        let n = counts.first().copied().unwrap_or(0);
        let text = self.text(stmt.span);
        let mut out = Vec::with_capacity(n);
        for k in 0..n {
            let mut acc: Option<Expr> = None;
            let mut span = stmt.span;
            for (cond, eqns) in lists.iter().rev() {
                let r = eqns[k].residual.clone();
                span = eqns[k].span;
                acc = Some(match (cond, acc) {
                    (Some(c), Some(rest)) => {
                        Expr::If(Box::new(c.clone()), Box::new(r), Box::new(rest))
                    }
                    (_, _) => r,
                });
            }
            if let Some(residual) = acc {
                out.push(Eqn {
                    residual,
                    span,
                    text: text.clone(),
                });
            }
        }
        Ok(out)
    }

    /// `sel = c1 or sel = c2 or c3_low <= sel <= c3_high ...`
    pub(crate) fn choices_condition(
        &mut self,
        sc: &Scope<'a>,
        sel: &Expr,
        ty: &Ty,
        choices: &[Choice],
    ) -> R<Expr> {
        let mut cond: Option<Expr> = None;
        let within = |lo: Expr, hi: Expr| {
            let cmp = |op, b: Expr| Box::new(Expr::Binary(op, Box::new(sel.clone()), Box::new(b)));
            Expr::Binary(BinaryOp::And, cmp(BinaryOp::Ge, lo), cmp(BinaryOp::Le, hi))
        };
        for c in choices {
            let one = match c {
                // A subtype name chooses its range (`when control_transfer_opcodes =>`).
                Choice::Expr(e)
                    if let ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id) = &e.kind
                        && let Some(crate::names::scope::Item::Type(sub)) =
                            self.resolved_item(sc, id) =>
                {
                    let Some((lo, hi)) = sub.range.clone().or_else(|| sub.ty.scalar_bounds())
                    else {
                        return Err(self.error(ElabError::invalid(
                            e.span,
                            format!("`{}` has no range to choose", sub.name),
                            None,
                        )));
                    };
                    within(Expr::Const(lo), Expr::Const(hi))
                }
                Choice::Expr(e) => {
                    let v = self.expr_of(sc, e, ty)?;
                    if !matches!(v.e, Expr::Const(_)) {
                        return Err(self.error(ElabError::NotStatic {
                            span: e.span,
                            what: "a choice".into(),
                        }));
                    }
                    Expr::Binary(BinaryOp::Eq, Box::new(sel.clone()), Box::new(v.e))
                }
                Choice::Range(r) => {
                    let (l, h, asc) = self.range_exprs(sc, r)?;
                    let (lo, hi) = if asc { (l.e, h.e) } else { (h.e, l.e) };
                    within(lo, hi)
                }
                Choice::Others(_) => Expr::Const(Value::Boolean(true)),
            };
            cond = Some(match cond {
                Some(prev) => Expr::Binary(BinaryOp::Or, Box::new(prev), Box::new(one)),
                None => one,
            });
        }
        Ok(cond.unwrap_or(Expr::Unary(
            UnaryOp::Not,
            Box::new(Expr::Const(Value::Boolean(true))),
        )))
    }
}

fn choice_span(c: &Choice) -> Span {
    match c {
        Choice::Expr(e) => e.span,
        Choice::Range(ast::Range::Explicit { span, .. }) => *span,
        Choice::Range(ast::Range::Attribute(e)) => e.span,
        Choice::Others(s) => *s,
    }
}

/// The simple names assigned with `:=` anywhere in `stmts` (nested statements included).
/// Whether `e` is the value of a whole array (of a procedural's quantity array).
fn is_array_value(e: &Expr) -> bool {
    match e {
        Expr::Aggregate { .. } | Expr::Const(Value::Array(_)) => true,
        Expr::If(_, a, _) => is_array_value(a),
        _ => false,
    }
}

/// The `n` elements of an array value a procedural leaves in a quantity array: an aggregate,
/// a constant, or a choice between such values on a quantity's condition (one conditional
/// expression per element).
fn array_elements(e: Expr, n: usize) -> Option<Vec<Expr>> {
    let elems = match e {
        Expr::Aggregate { elems, .. } => elems,
        Expr::Const(Value::Array(elems)) => elems.into_iter().map(Expr::Const).collect(),
        Expr::If(c, a, b) => {
            let (a, b) = (array_elements(*a, n)?, array_elements(*b, n)?);
            a.into_iter()
                .zip(b)
                .map(|(a, b)| Expr::If(c.clone(), Box::new(a), Box::new(b)))
                .collect()
        }
        _ => return None,
    };
    (elems.len() == n).then_some(elems)
}

fn assigned_names<'s>(stmts: &'s [ast::SeqStmt], out: &mut Vec<&'s ast::Ident>) {
    for s in stmts {
        s.walk(&mut |s| {
            if let ast::SeqKind::VariableAssign { target, .. } = &s.kind {
                // `q := ...`, `q(i) := ...`, `q(1 to 2) := ...`: the quantity named at the root.
                let mut e = target;
                while let ast::ExprKind::Apply(prefix, _) = &e.kind {
                    e = prefix;
                }
                if let ast::ExprKind::Name(id) = &e.kind {
                    out.push(id);
                }
            }
        });
    }
}

/// The prefixes of the `'dot` targets of a procedural's body (`x(1)` of `x(1)'dot := ...`).
fn dot_targets<'s>(stmts: &'s [ast::SeqStmt], out: &mut Vec<&'s ast::Expr>) {
    for s in stmts {
        s.walk(&mut |s| {
            if let ast::SeqKind::VariableAssign { target, .. } = &s.kind
                && let ast::ExprKind::Attribute(prefix, attr) = &target.kind
                && attr.name == "dot"
            {
                out.push(prefix);
            }
        });
    }
}

/// The scalar quantities of a composite object, in order (a record's fields in declaration
/// order, nested records flattened), or the elements of a constant array of reals; `None` for
/// anything else.
fn composite_item(item: &Item) -> Option<Vec<Expr>> {
    match item {
        Item::QuantityArray(elements) => {
            Some(elements.ids.iter().map(|&q| Expr::Quantity(q)).collect())
        }
        Item::QuantityRecord(record) => {
            let mut out = Vec::new();
            for (_, field) in &record.fields {
                match field {
                    Item::Quantity(q) => out.push(Expr::Quantity(*q)),
                    other => out.extend(composite_item(other)?),
                }
            }
            Some(out)
        }
        Item::Constant {
            value: Value::Array(values),
            ty: Ty::Array(a),
        } if a.element == Ty::Real => Some(values.iter().cloned().map(Expr::Const).collect()),
        _ => None,
    }
}

/// Whether the branches of a simultaneous if before its (missing, empty) `else` all give the
/// same number of equations, at least one.
fn arms_implicit_else(lists: &[(Option<Expr>, Vec<Eqn>)]) -> bool {
    let explicit = &lists[..lists.len() - 1];
    let n = explicit[0].1.len();
    n > 0 && explicit.iter().all(|(c, e)| c.is_some() && e.len() == n)
}
