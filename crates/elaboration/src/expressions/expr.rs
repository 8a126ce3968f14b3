//! Expressions: AST expressions to typed [`Expr`]s, with VHDL's typing rules (no implicit
//! conversion between integer and real), overload resolution by argument and expected types,
//! and folding of every static sub-expression.

use std::rc::Rc;

use vams_design::{BinaryOp, Builtin, Expr, UnaryOp, Value};
use vams_syntax::ast::{self, Actual, ExprKind, Literal};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::expressions::fold::{self, is_logical};
use crate::names::scope::{IoNative, Item, Native, Part, Scope, Subprogram};
use crate::names::types::{ArrayTy, RecordTy, Sub, Ty, bounds_len, position};
use crate::{Elab, R};

/// A lowered expression and its type.
#[derive(Clone, Debug)]
pub struct Typed {
    pub e: Expr,
    pub ty: Ty,
}

impl Typed {
    pub(crate) fn new(e: Expr, ty: Ty) -> Typed {
        Typed { e, ty }
    }

    pub fn value(&self) -> Option<&Value> {
        match &self.e {
            Expr::Const(v) => Some(v),
            _ => None,
        }
    }
}

const INT_REAL_HELP: &str = "VHDL never converts between integer and real implicitly: write a real literal \
(`2.0`, not `2`) or convert with `real(i)` / `integer(x)`";

fn map_binop(op: ast::BinaryOp) -> BinaryOp {
    use ast::BinaryOp as A;
    match op {
        A::And => BinaryOp::And,
        A::Or => BinaryOp::Or,
        A::Nand => BinaryOp::Nand,
        A::Nor => BinaryOp::Nor,
        A::Xor => BinaryOp::Xor,
        A::Xnor => BinaryOp::Xnor,
        A::Eq => BinaryOp::Eq,
        A::Ne => BinaryOp::Ne,
        A::Lt => BinaryOp::Lt,
        A::Le => BinaryOp::Le,
        A::Gt => BinaryOp::Gt,
        A::Ge => BinaryOp::Ge,
        A::Add => BinaryOp::Add,
        A::Sub => BinaryOp::Sub,
        A::Concat => BinaryOp::Concat,
        A::Mul => BinaryOp::Mul,
        A::Div => BinaryOp::Div,
        A::Mod => BinaryOp::Mod,
        A::Rem => BinaryOp::Rem,
        A::Pow => BinaryOp::Pow,
        A::Sll => BinaryOp::Sll,
        A::Srl => BinaryOp::Srl,
        A::Sla => BinaryOp::Sla,
        A::Sra => BinaryOp::Sra,
        A::Rol => BinaryOp::Rol,
        A::Ror => BinaryOp::Ror,
    }
}

fn op_text(op: BinaryOp) -> &'static str {
    match op {
        BinaryOp::Add => "+",
        BinaryOp::Sub => "-",
        BinaryOp::Mul => "*",
        BinaryOp::Div => "/",
        BinaryOp::Pow => "**",
        BinaryOp::Mod => "mod",
        BinaryOp::Rem => "rem",
        BinaryOp::Eq => "=",
        BinaryOp::Ne => "/=",
        BinaryOp::Lt => "<",
        BinaryOp::Le => "<=",
        BinaryOp::Gt => ">",
        BinaryOp::Ge => ">=",
        BinaryOp::And => "and",
        BinaryOp::Or => "or",
        BinaryOp::Nand => "nand",
        BinaryOp::Nor => "nor",
        BinaryOp::Xor => "xor",
        BinaryOp::Xnor => "xnor",
        BinaryOp::Concat => "&",
        BinaryOp::Sll => "sll",
        BinaryOp::Srl => "srl",
        BinaryOp::Sla => "sla",
        BinaryOp::Sra => "sra",
        BinaryOp::Rol => "rol",
        BinaryOp::Ror => "ror",
    }
}

/// True for an expression whose type depends on the context: an overloaded name (`now`, an
/// enumeration literal) or a character or string literal.
fn context_typed(e: &ast::Expr) -> bool {
    match &e.kind {
        ExprKind::Name(id) => id.name == "now",
        ExprKind::Literal(Literal::Char(_) | Literal::String(_) | Literal::BitString(_))
        | ExprKind::Aggregate(_) => true,
        ExprKind::Paren(inner) => context_typed(inner),
        _ => false,
    }
}

impl<'a> Elab<'a> {
    /// What the (simple or selected) name `id` denotes, when analysis resolved it to one
    /// declaration and elaboration has its item: in `sc`, or among the items of the packages
    /// elaborated so far. `None` leaves the name to the visibility rules of `sc` (a name
    /// analysis could not resolve to one declaration, such as an overloaded name without
    /// context, or a declaration elaboration could not build).
    pub(crate) fn resolved_item(&self, sc: &Scope<'a>, id: &ast::Ident) -> Option<Item<'a>> {
        self.resolved_at(sc, id.span)
    }

    /// [`Elab::resolved_item`] of the name or operator application at `span`.
    pub(crate) fn resolved_at(&self, sc: &Scope<'a>, span: Span) -> Option<Item<'a>> {
        let decl = self.analysed.names.get(&span)?;
        let item = sc
            .declared(*decl)
            .or_else(|| self.packages.decls.get(decl))?;
        (!matches!(item, Item::Poison(_))).then(|| item.clone())
    }

    /// The implicit operations named `id` of the access or file type analysis resolved it
    /// to (`deallocate`, `file_open`, ...; analysis knows them by the type's declaration).
    fn implicit_operations(&self, sc: &Scope<'a>, id: &ast::Ident) -> Option<Vec<Item<'a>>> {
        let decl = *self.analysed.names.get(&id.span)?;
        let subs: Vec<Item<'a>> = sc
            .lookup_overloads(&id.name)?
            .into_iter()
            .filter(|i| matches!(i, Item::Subprogram(s) if s.span == decl))
            .collect();
        (!subs.is_empty()).then_some(subs)
    }

    /// Elaborates the package whose declarations include `decl`, if there is one and it was
    /// not elaborated yet; true when it was.
    fn elaborate_package_declaring(&mut self, decl: Span) -> bool {
        let Some(unit) = self.lib.packages.values().flatten().find(|p| {
            let s = p.unit.span;
            s.file == decl.file && s.start <= decl.start && decl.end <= s.end
        }) else {
            return false;
        };
        !self.packages.done.contains_key(&unit.index)
            && self.package_unit(unit.clone(), None).is_ok()
    }

    /// The item a (simple or selected) name denotes: the one built for the declaration
    /// analysis resolved the name to. Elaboration does no name lookup of its own: a name
    /// analysis left unresolved is an error (analysis reported it, or it names a construct
    /// vams does not support, which is said here).
    pub(crate) fn lookup(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> R<Vec<Item<'a>>> {
        let (ExprKind::Name(id) | ExprKind::Selected(_, id)) = &e.kind else {
            if let ExprKind::Apply(prefix, args) = &e.kind {
                return Ok(vec![self.element_item(sc, e, prefix, args)?]);
            }
            // `T'base`: the base type, without the subtype's range (LRM 14.1).
            if let ExprKind::Attribute(prefix, attr) = &e.kind
                && attr.name == "base"
                && let Some(Item::Type(sub)) = self.lookup(sc, prefix)?.first()
            {
                let base = Sub::of(sub.ty.clone(), &sub.ty.to_string());
                return Ok(vec![Item::Type(Rc::new(base))]);
            }
            // `electrical'reference`: the nature's reference terminal. Not in 1076.1 (issue
            // report IR1.99.05 asks for it), but SEAMS and the University of Cincinnati's
            // test suite write it, and it can mean nothing else.
            if let ExprKind::Attribute(prefix, attr) = &e.kind
                && attr.name == "reference"
                && let Some(&Item::Nature(nature)) = self.lookup(sc, prefix)?.first()
            {
                return Ok(vec![Item::RefTerminal { nature }]);
            }
            // `electrical'across`, `electrical'through`: the nature's subtypes, as type marks
            // (`electrical'across(x)`, `electrical'through'(1.0)`, `electrical'across'high`).
            if let ExprKind::Attribute(prefix, attr) = &e.kind
                && (attr.name == "across" || attr.name == "through")
            {
                let sub = self.nature_subtype(sc, prefix, attr, e.span)?;
                return Ok(vec![Item::Type(sub)]);
            }
            return Err(self.error(ElabError::invalid(e.span, "expected a name", None)));
        };
        if let ExprKind::Selected(prefix, suffix) = &e.kind
            && let Some(methods) = self.methods(sc, prefix, suffix)
        {
            return methods;
        }
        if let Some(field) = self.record_part(sc, e) {
            return Ok(vec![field]);
        }
        if let Some(item) = self.resolved_item(sc, id) {
            if let Item::Type(sub) = &item
                && matches!(sub.ty, Ty::Access(_) | Ty::File(_))
                && let Some(subs) = self.implicit_operations(sc, id)
            {
                return Ok(subs);
            }
            return Ok(vec![item]);
        }
        if let Some(&decl) = self.analysed.names.get(&id.span) {
            // Declared in a package no `use` clause made elaboration build yet
            // (`work.pkg.item`): build it, then take the item.
            if self.elaborate_package_declaring(decl)
                && let Some(item) = self.resolved_item(sc, id)
            {
                return Ok(vec![item]);
            }
            return Err(self.unbuilt(sc, e, decl));
        }
        match &e.kind {
            ExprKind::Selected(prefix, suffix) => {
                let outer = self.lookup(sc, prefix)?;
                match outer.first() {
                    Some(Item::Library(lib)) => {
                        let lib = lib.clone();
                        let pkg = self.package(&lib, &suffix.name, Some(suffix.span))?;
                        Ok(vec![Item::Package(pkg)])
                    }
                    Some(Item::Package(pkg)) => Err(self.error(ElabError::Undeclared {
                        span: suffix.span,
                        name: format!("{}.{}", pkg.name, suffix.name),
                        help: Some(format!(
                            "package `{}` declares no `{}`",
                            pkg.name, suffix.name
                        )),
                    })),
                    Some(Item::Signal {
                        id,
                        ty: ty @ Ty::Record(_),
                    }) => {
                        let (id, ty) = (*id, ty.clone());
                        Ok(vec![self.field_view(id, &ty, suffix)?])
                    }
                    Some(Item::Variable {
                        id,
                        ty: ty @ Ty::Record(_),
                        readonly,
                        path,
                    }) => {
                        let (id, ty, readonly) = (*id, ty.clone(), *readonly);
                        let mut path = path.to_vec();
                        let (pos, field) = self.record_field(&ty, suffix, e.span)?;
                        path.push(Part::Element {
                            index: Expr::Const(Value::Integer(pos as i64)),
                            container: ty.to_design(),
                        });
                        Ok(vec![Item::Variable {
                            id,
                            ty: field,
                            readonly,
                            path: path.into(),
                        }])
                    }
                    Some(Item::Constant {
                        value,
                        ty: ty @ Ty::Record(_),
                    }) => {
                        let rec = Typed::new(Expr::Const(value.clone()), ty.clone());
                        let f = self.field(rec, suffix, e.span)?;
                        let value = f.value().cloned().ok_or(crate::Reported)?;
                        Ok(vec![Item::Constant { value, ty: f.ty }])
                    }
                    Some(other) => {
                        let class = other.class();
                        Err(self.error(ElabError::unsupported(
                            e.span,
                            format!("selecting `.{}` from {class}", suffix.name),
                            "records are not supported yet; selected names reach package items (`lib.pkg.item`)",
                        )))
                    }
                    None => Err(crate::Reported),
                }
            }
            _ => {
                // Visibility is consulted only to word the error.
                let help = if sc.lookup(&id.name).is_some() {
                    "several declarations of this name are visible and nothing here decides between them; qualify the name or the expression (`pkg.name`, `t'(...)`)".to_string()
                } else if let Some(s) = sc.suggest(&id.name) {
                    format!("did you mean `{s}`?")
                } else {
                    "declare it, or make it visible with a `use` clause".to_string()
                };
                Err(self.error(ElabError::Undeclared {
                    span: id.span,
                    name: id.name.clone(),
                    help: Some(help),
                }))
            }
        }
    }

    /// The error for a name analysis resolved to `decl` that has no usable item: a standard
    /// declaration vams cannot elaborate, or a declaration whose own elaboration failed
    /// (reported there).
    fn unbuilt(&mut self, sc: &Scope<'a>, e: &ast::Expr, decl: Span) -> crate::Reported {
        match sc.declared(decl).or_else(|| self.packages.decls.get(&decl)) {
            Some(Item::Poison(Some(reason))) => self.error(ElabError::unsupported(
                e.span,
                format!("`{}` ({reason})", self.sources.snippet(e.span)),
                "vams's standard packages declare it, but its declaration uses a construct vams cannot elaborate yet",
            )),
            _ if !self.errors.is_empty() => crate::Reported,
            _ => self.error(ElabError::unsupported(
                e.span,
                format!("`{}`", self.sources.snippet(e.span)),
                "what this name denotes is declared with a construct vams cannot elaborate yet",
            )),
        }
    }

    /// Lowers `e`; `want` is a hint for overload resolution only (use [`Elab::expr_of`] to
    /// check the type).
    pub(crate) fn expr(&mut self, sc: &Scope<'a>, e: &ast::Expr, want: Option<&Ty>) -> R<Typed> {
        match &e.kind {
            ExprKind::Literal(lit) => self.literal(sc, lit, e.span, want),
            ExprKind::Selected(prefix, suffix) if !self.analysed.names.contains_key(&suffix.span) => {
                // A field of a record quantity or terminal: its object.
                if let Some(field) = self.record_part(sc, e) {
                    return self.object(sc, &[field], e, want);
                }
                // Analysis resolves the suffix of every selected name but a record field's.
                let rec = match &prefix.kind {
                    ExprKind::Name(_) => {
                        let items = self.lookup(sc, prefix)?;
                        if let Some(Item::Library(_) | Item::Package(_)) = items.first() {
                            let items = self.lookup(sc, e)?;
                            return self.object(sc, &items, e, want);
                        }
                        self.object(sc, &items, prefix, None)?
                    }
                    _ => self.expr(sc, prefix, None)?,
                };
                self.field(rec, suffix, e.span)
            }
            ExprKind::Name(_) | ExprKind::Selected(..) => {
                let items = self.lookup(sc, e)?;
                self.object(sc, &items, e, want)
            }
            ExprKind::Paren(inner) => self.expr(sc, inner, want),
            ExprKind::Qualified(mark, inner) => {
                let ty = self.type_mark(sc, mark)?.ty.clone();
                let t = self.expr_of(sc, inner, &ty)?;
                // A constrained array subtype gives the value its bounds (LRM 7.3.4: the
                // operand's value belongs to the subtype), so `bv4'(a & b & f(v))` has length 4
                // where the concatenation's own length is known only at run time: a parameter
                // or local array sized by it can be elaborated. The length is checked.
                match (&ty, &t.ty) {
                    (Ty::Array(a), Ty::Array(b)) if a.len().is_some() && b.len().is_none() => {
                        let what = |_: &Self| format!("the value qualified by `{ty}`");
                        let e = self.fit_length(t, &ty, what, inner.span)?;
                        Ok(Typed::new(e, ty))
                    }
                    _ => Ok(t),
                }
            }
            ExprKind::Aggregate(elems) => self.aggregate(sc, elems, e.span, want),
            ExprKind::Unary(op, a) => {
                let op = self
                    .aliased_operator(sc, e.span)
                    .map_or(*op, |(u, _)| u.unwrap_or(*op));
                let a = self.expr(sc, a, want)?;
                // The operator function analysis chose (`-a` of numeric_std's signed, `not`
                // of std_logic), else the predefined one.
                if let Some(r) = self.user_operator(sc, vec![a.clone()], e.span) {
                    return r;
                }
                self.unary(op, a, e.span)
            }
            ExprKind::Binary(op, l, r) => {
                let op = self
                    .aliased_operator(sc, e.span)
                    .map_or(*op, |(_, b)| b.unwrap_or(*op));
                self.binary(sc, op, l, r, e.span, want)
            }
            ExprKind::Attribute(prefix, attr) => {
                self.attribute(sc, prefix, attr, &[], e.span)
            }
            ExprKind::Apply(prefix, args) => {
                if let ExprKind::Attribute(p, attr) = &prefix.kind {
                    return self.attribute(sc, p, attr, args, e.span);
                }
                let field = matches!(&prefix.kind,
                    ExprKind::Selected(_, s) if !self.analysed.names.contains_key(&s.span))
                    && self.record_part(sc, prefix).is_none();
                if matches!(prefix.kind, ExprKind::Apply(..)) || field {
                    // An element of an element (`table(i)(k)`, an array of arrays), of
                    // what a call returns (`f(x)(k)`), or of a record field or an object
                    // an access value designates (`r.v(k)`, `p.all(k)`).
                    let array = self.expr(sc, prefix, None)?;
                    return self.index(sc, array, args, e.span);
                }
                if let Some(op) = self.predefined_operator_call(sc, prefix, args, e.span) {
                    return self.expr(sc, &op, want);
                }
                let items = self.lookup(sc, prefix)?;
                match items.first() {
                    Some(Item::Subprogram(_)) => {
                        let subs = items
                            .iter()
                            .filter_map(|i| match i {
                                Item::Subprogram(s) => Some(s.clone()),
                                _ => None,
                            })
                            .collect();
                        self.call(sc, subs, args, e.span, designator_span(prefix))
                    }
                    Some(Item::Type(sub)) => {
                        let target = sub.ty.clone();
                        self.conversion(sc, &target, args, e.span)
                    }
                    Some(Item::QuantityArray(elements)) => {
                        // A process may read an element by an index computed from its
                        // variables: the index selects among the quantities' values at run
                        // time (in an equation the index must be static).
                        if let [
                            ast::Assoc {
                                formal: None,
                                actual: Actual::Expr(ie),
                                ..
                            },
                        ] = args.as_slice()
                        {
                            let i = self.expr_of(sc, ie, &Ty::Integer)?;
                            if !i.e.is_analog() {
                                let elems =
                                    elements.ids.iter().map(|q| Expr::Quantity(*q)).collect();
                                let array = Expr::Aggregate {
                                    elems,
                                    string: false,
                                };
                                let ty = elements.ty().to_design();
                                let index = Box::new(i.e);
                                let e = Expr::Index {
                                    array: Box::new(array),
                                    index,
                                    ty,
                                };
                                return Ok(Typed::new(e, Ty::Real));
                            }
                        }
                        let q = self.indexed_quantity(sc, elements, args, e.span)?;
                        Ok(Typed::new(Expr::Quantity(q), Ty::Real))
                    }
                    _ => {
                        let array = self.object(sc, &items, prefix, None)?;
                        self.index(sc, array, args, e.span)
                    }
                }
            }
            ExprKind::New(inner) => self.allocator(sc, inner, want, e.span),
            ExprKind::Signed(..) => Err(self.error(ElabError::invalid(
                e.span,
                "a name with a signature is no value",
                Some("a signature selects an overload only as the prefix of an attribute name (`f [integer return integer]'attr`)".into()),
            ))),
        }
    }

    /// `"+"(a, b)` or `"-"(a)` where the operator symbol names a predefined operator (not a
    /// user function): the operation itself, as if written `a + b`.
    fn predefined_operator_call(
        &self,
        sc: &Scope<'a>,
        prefix: &ast::Expr,
        args: &[ast::Assoc],
        span: Span,
    ) -> Option<ast::Expr> {
        // `"+"(a, b)`, or by expanded name `std.standard."<"(a, b)`, `work.p."="(x, y)`:
        // analysis resolves a predefined operator to its type's declaration, never to a
        // subprogram.
        let (ExprKind::Name(id) | ExprKind::Selected(_, id)) = &prefix.kind else {
            return None;
        };
        let alias = match self.resolved_item(sc, id) {
            Some(Item::Subprogram(_)) => return None,
            Some(Item::OperatorAlias(symbol)) => Some(symbol),
            _ => None,
        };
        let symbol = match &alias {
            Some(symbol) => symbol,
            None => id.name.strip_prefix('"')?.strip_suffix('"')?,
        };
        let operand = |a: &ast::Assoc| match a {
            ast::Assoc {
                actual: ast::Actual::Expr(x),
                ..
            } => Some(Box::new(x.clone())),
            _ => None,
        };
        let kind = match args {
            [a] => ExprKind::Unary(ast::UnaryOp::from_symbol(symbol)?, operand(a)?),
            [a, b] => ExprKind::Binary(
                ast::BinaryOp::from_symbol(symbol)?,
                operand(a)?,
                operand(b)?,
            ),
            _ => return None,
        };
        Some(ast::Expr { kind, span })
    }

    /// The operator an application at `span` applies when analysis resolved it to an alias of
    /// a predefined operator (`a * b` with `alias "*" is "and" [...]`): as a unary and as a
    /// binary operator.
    fn aliased_operator(
        &self,
        sc: &Scope<'a>,
        span: Span,
    ) -> Option<(Option<ast::UnaryOp>, Option<ast::BinaryOp>)> {
        let Item::OperatorAlias(symbol) = self.resolved_at(sc, span)? else {
            return None;
        };
        Some((
            ast::UnaryOp::from_symbol(&symbol),
            ast::BinaryOp::from_symbol(&symbol),
        ))
    }

    /// Lowers `e` and checks that its type is `ty`.
    pub(crate) fn expr_of(&mut self, sc: &Scope<'a>, e: &ast::Expr, ty: &Ty) -> R<Typed> {
        let t = self.expr(sc, e, Some(ty))?;
        self.check_type(&t, ty, e.span)?;
        Ok(t)
    }

    pub(crate) fn check_type(&mut self, t: &Typed, want: &Ty, span: Span) -> R<()> {
        if t.ty.same(want) {
            return Ok(());
        }
        let help = if t.ty.is_numeric() && want.is_numeric() {
            INT_REAL_HELP.to_string()
        } else if matches!(want, Ty::Time) && t.ty.is_numeric() {
            "multiply by a unit to get a time: `x * 1 sec`, `10 ms`".to_string()
        } else if *want == Ty::Boolean {
            "a condition must be boolean: compare explicitly, e.g. `n /= 0` (VHDL has no implicit conversion)".to_string()
        } else {
            format!("VHDL has no implicit conversion: give a value of type {want}")
        };
        let help = Some(help);
        Err(self.error(ElabError::TypeMismatch {
            span,
            expected: want.to_string(),
            found: t.ty.to_string(),
            help,
        }))
    }

    /// The value of a static expression of type `ty`.
    pub(crate) fn static_value(
        &mut self,
        sc: &Scope<'a>,
        e: &ast::Expr,
        ty: &Ty,
        what: &str,
    ) -> R<Value> {
        let t = self.expr_of(sc, e, ty)?;
        match t.e {
            Expr::Const(v) => Ok(v),
            call => match crate::expressions::inline::static_call(&self.design, &call) {
                Ok(v) => Ok(v),
                Err(Some(refusal)) => {
                    let at = refusal.failed_assertion.unwrap_or(e.span);
                    let (line, col) = self.sources.line_col(at);
                    let file = &self.sources.file(at.file).name;
                    Err(self.error(ElabError::invalid(
                        e.span,
                        format!("computing {what}: `{}`: {}", refusal.name, refusal.reason),
                        Some(format!(
                            "the assertion at {file}:{line}:{col} fails for the arguments given here: change them (the defaults of generics?)"
                        )),
                    )))
                }
                Err(None) => Err(self.error(ElabError::NotStatic {
                    span: e.span,
                    what: what.to_string(),
                })),
            },
        }
    }

    /// A static integer (range bounds, generate parameters).
    pub(crate) fn static_int(&mut self, sc: &Scope<'a>, e: &ast::Expr, what: &str) -> R<i64> {
        match self.static_value(sc, e, &Ty::Integer, what)? {
            Value::Integer(i) => Ok(i),
            _ => Err(self.error(ElabError::invalid(e.span, "expected an integer", None))),
        }
    }

    /// Folds a freshly built expression, reporting static errors at `span`.
    pub(crate) fn folded(&mut self, e: Expr, ty: Ty, span: Span) -> R<Typed> {
        match fold::fold(e) {
            Ok(e) => Ok(Typed::new(e, ty)),
            Err(m) => Err(self.error(ElabError::invalid(span, m, None))),
        }
    }

    fn literal(
        &mut self,
        sc: &Scope<'a>,
        lit: &Literal,
        span: Span,
        want: Option<&Ty>,
    ) -> R<Typed> {
        Ok(match lit {
            Literal::Integer(i) => Typed::new(Expr::Const(Value::Integer(*i)), Ty::Integer),
            Literal::Real(x) => Typed::new(Expr::Const(Value::Real(*x)), Ty::Real),
            Literal::Physical(n, unit) => {
                let factor = match self.resolved_item(sc, unit) {
                    Some(Item::TimeUnit(f)) => f,
                    Some(Item::Unit { ty, factor }) => {
                        let n = match **n {
                            Literal::Integer(i) => i as f64,
                            Literal::Real(x) => x,
                            _ => 1.0,
                        };
                        let v = Value::Integer((n * factor as f64).round() as i64);
                        return Ok(Typed::new(Expr::Const(v), ty));
                    }
                    _ => {
                        return Err(self.error(ElabError::Undeclared {
                            span: unit.span,
                            name: unit.name.clone(),
                            help: Some(
                                "the units of time are fs, ps, ns, us, ms, sec, min and hr".into(),
                            ),
                        }));
                    }
                };
                let n = match **n {
                    Literal::Integer(i) => i as f64,
                    Literal::Real(x) => x,
                    _ => 1.0,
                };
                Typed::new(Expr::Const(Value::Time(n * factor / 1e15)), Ty::Time)
            }
            Literal::Char(c) => {
                let name = format!("'{c}'");
                // The literal analysis chose from the context.
                if let Some(decl) = self.analysed.names.get(&span)
                    && let Some(item @ Item::EnumLiteral { .. }) =
                        sc.declared(*decl).or_else(|| self.packages.decls.get(decl))
                {
                    let item = item.clone();
                    return self.enum_literal(&[item], want, span);
                }
                let help = if sc.lookup_overloads(&name).is_some() {
                    "several enumeration types have this literal and nothing here decides between them; qualify it (`bit'('1')`)"
                } else {
                    "no visible enumeration type has this character literal"
                };
                return Err(self.error(ElabError::Undeclared {
                    span,
                    name,
                    help: Some(help.into()),
                }));
            }
            Literal::String(s) | Literal::BitString(s) => {
                self.string_literal(s, span, want, matches!(lit, Literal::BitString(_)))?
            }
            Literal::Null => match want {
                Some(ty @ Ty::Access(_)) => Typed::new(Expr::Const(Value::Access(0)), ty.clone()),
                _ => {
                    return Err(self.error(ElabError::invalid(
                        span,
                        "the access type of `null` is not known here",
                        Some(
                            "compare or assign it with an access value: `p = null`, `p := null`"
                                .into(),
                        ),
                    )));
                }
            },
        })
    }

    fn string_literal(&mut self, s: &str, span: Span, want: Option<&Ty>, bits: bool) -> R<Typed> {
        let target = match want {
            Some(Ty::Array(a)) if a.name != "string" => Some(a.clone()),
            Some(_) => None,
            None if bits => match self.standard_type("bit_vector") {
                Some(Ty::Array(a)) => Some(a),
                _ => None,
            },
            None => None,
        };
        let Some(arr) = target else {
            let ty = string_type(self.standard_type("string"), s.chars().count());
            return Ok(Typed::new(Expr::Const(Value::String(s.to_string())), ty));
        };
        let Ty::Enum(elem) = &arr.element else {
            return Err(self.error(ElabError::TypeMismatch {
                span,
                expected: arr.name.clone(),
                found: "a string literal".into(),
                help: None,
            }));
        };
        let mut values = Vec::new();
        for c in s.chars() {
            let lit = format!("'{c}'");
            match elem.literals.iter().position(|l| *l == lit) {
                Some(p) => values.push(Value::Enum(p as u32)),
                None => {
                    return Err(self.error(ElabError::invalid(
                        span,
                        format!("{lit} is not a literal of {}", elem.name),
                        None,
                    )));
                }
            }
        }
        let ty = constrain(&arr, values.len());
        Ok(Typed::new(Expr::Const(Value::Array(values)), ty))
    }

    fn enum_literal(&mut self, items: &[Item<'a>], want: Option<&Ty>, span: Span) -> R<Typed> {
        let lits: Vec<(&Ty, u32)> = items
            .iter()
            .filter_map(|i| match i {
                Item::EnumLiteral { ty, pos } => Some((ty, *pos)),
                _ => None,
            })
            .collect();
        let chosen = want
            .and_then(|w| lits.iter().find(|(t, _)| t.same(w)))
            .or(lits.first())
            .copied();
        let Some((ty, pos)) = chosen else {
            return Err(self.error(ElabError::invalid(
                span,
                "expected an enumeration literal",
                None,
            )));
        };
        let v = if matches!(ty, Ty::Boolean) {
            Value::Boolean(pos == 1)
        } else {
            Value::Enum(pos)
        };
        Ok(Typed::new(Expr::Const(v), ty.clone()))
    }

    /// The value of a name used as an expression.
    fn object(
        &mut self,
        sc: &Scope<'a>,
        items: &[Item<'a>],
        e: &ast::Expr,
        want: Option<&Ty>,
    ) -> R<Typed> {
        let first = items[0].clone();
        Ok(match first {
            Item::Constant { value, ty } => Typed::new(Expr::Const(value), ty),
            Item::Signal { id, ty } => Typed::new(Expr::Signal(id), ty),
            Item::Quantity(id) => Typed::new(Expr::Quantity(id), Ty::Real),
            // A whole quantity array as a value (`vector_multiply(source_position, k)`): the
            // array of its quantities' values.
            Item::QuantityArray(elements) => {
                let elems = elements.ids.iter().map(|&q| Expr::Quantity(q)).collect();
                // Of type `real_vector` (the quantity array's own declared type is not kept),
                // with its bounds.
                let ty = match (self.standard_type("real_vector"), elements.ty()) {
                    (Some(Ty::Array(rv)), Ty::Array(own)) => match own.bounds {
                        Some(b) => rv.with_bounds(Some(b)),
                        None => Ty::Array(own),
                    },
                    (_, own) => own,
                };
                Typed::new(
                    Expr::Aggregate {
                        elems,
                        string: false,
                    },
                    ty,
                )
            }
            Item::Variable { id, ty, path, .. } => {
                let e = path.iter().fold(Expr::Var(id), |e, part| part.of(e));
                Typed::new(e, ty)
            }
            Item::EnumLiteral { .. } => return self.enum_literal(items, want, e.span),
            // A unit alone is one of it (`ohm`, LRM 3.1.3).
            Item::Unit { ty, factor } => Typed::new(Expr::Const(Value::Integer(factor)), ty),
            // A protected type has no values (LRM 3.5): no assignment, no comparison.
            Item::SharedObject { .. } => {
                return Err(self.error(ElabError::invalid(
                    e.span,
                    "a shared variable of a protected type has no value",
                    Some(
                        "call its methods, `v.method(...)`, or pass it to a parameter of its type"
                            .into(),
                    ),
                )));
            }
            Item::PrivateVariable {
                object,
                field,
                record,
                ty,
            } => {
                let e = Expr::Index {
                    array: Box::new(Expr::Deref(Box::new(Expr::Const(object)))),
                    index: Box::new(Expr::Const(Value::Integer(field as i64))),
                    ty: record,
                };
                Typed::new(e, ty)
            }
            // Femtoseconds.
            Item::TimeUnit(fs) => Typed::new(Expr::Const(Value::Time(fs * 1e-15)), Ty::Time),
            Item::Subprogram(_) => {
                let subs = items
                    .iter()
                    .filter_map(|i| match i {
                        Item::Subprogram(s) => Some(s.clone()),
                        _ => None,
                    })
                    .collect();
                return self.call(sc, subs, &[], e.span, designator_span(e));
            }
            other => {
                return Err(self.error(ElabError::WrongClass {
                    span: e.span,
                    name: self.sources.snippet(e.span).to_string(),
                    found: other.class().to_string(),
                    expected: "a value".into(),
                    help: Some(
                        "an expression reads constants, signals, quantities and variables".into(),
                    ),
                }));
            }
        })
    }

    fn unary(&mut self, op: ast::UnaryOp, a: Typed, span: Span) -> R<Typed> {
        let (uop, ok) = match op {
            ast::UnaryOp::Minus => (UnaryOp::Neg, a.ty.is_numeric() || is_physical(&a.ty)),
            ast::UnaryOp::Plus => (UnaryOp::Plus, a.ty.is_numeric() || is_physical(&a.ty)),
            ast::UnaryOp::Abs => (UnaryOp::Abs, a.ty.is_numeric() || is_physical(&a.ty)),
            ast::UnaryOp::Not => (
                UnaryOp::Not,
                is_logical_scalar(&a.ty) || logical_array(&a.ty),
            ),
        };
        if !ok {
            let name = match op {
                ast::UnaryOp::Minus => "-",
                ast::UnaryOp::Plus => "+",
                ast::UnaryOp::Abs => "abs",
                ast::UnaryOp::Not => "not",
            };
            return Err(self.error(ElabError::BadOperands {
                span,
                op: name.into(),
                left: "(unary)".into(),
                right: a.ty.to_string(),
                help: Some(logic_help(&a.ty)),
            }));
        }
        let ty = a.ty.clone();
        self.folded(Expr::Unary(uop, Box::new(a.e)), ty, span)
    }

    fn binary(
        &mut self,
        sc: &Scope<'a>,
        op: ast::BinaryOp,
        l: &ast::Expr,
        r: &ast::Expr,
        span: Span,
        want: Option<&Ty>,
    ) -> R<Typed> {
        let bop = map_binop(op);
        let arith = matches!(
            bop,
            BinaryOp::Add
                | BinaryOp::Sub
                | BinaryOp::Mul
                | BinaryOp::Div
                | BinaryOp::Mod
                | BinaryOp::Rem
        );
        let mut hint = if arith || is_logical(bop) { want } else { None };
        // `B"10001010" sll 3`: a literal shifted with no type from the context is a
        // bit_vector, the one predefined shift operand a bit-string literal can be (shifts
        // apply to one-dimensional arrays of bit and boolean, LRM 7.2.3).
        let bits;
        if bop.is_shift() && context_typed(l) {
            bits = match want {
                Some(t @ Ty::Array(_)) => Some(t.clone()),
                _ => self.standard_type("bit_vector"),
            };
            hint = bits.as_ref();
        }
        // A context-typed left operand (`now - t`, `'1' = b`) takes its type from the right.
        let (lt, rt) = if context_typed(l) && !context_typed(r) && !bop.is_shift() {
            let rt = self.expr(sc, r, hint);
            let lt = self.expr(sc, l, rt.as_ref().ok().map(|t| &t.ty).or(hint));
            (lt?, rt?)
        } else {
            let lt = self.expr(sc, l, hint);
            let rhint = match (&lt, bop) {
                (Ok(t), BinaryOp::Pow) if t.ty == Ty::Real => Some(Ty::Integer),
                (Ok(_), op) if op.is_shift() => Some(Ty::Integer),
                (Ok(t), BinaryOp::Mul | BinaryOp::Div) if t.ty == Ty::Time => None,
                (Ok(t), _) => Some(t.ty.clone()),
                _ => None,
            };
            let rt = self.expr(sc, r, rhint.as_ref().or(hint));
            (lt?, rt?)
        };
        // `time'pos(t) * 1.0e-15`: universal_integer times universal_real is real.
        let (lt, rt) = if self.analysed.mixed_universal.contains(&span) {
            let real = |t: Typed| match t.ty {
                Ty::Integer => Typed::new(Expr::Call(Builtin::ToReal, vec![t.e]), Ty::Real),
                _ => t,
            };
            (real(lt), real(rt))
        } else {
            (lt, rt)
        };
        // The operator function analysis chose (an explicit `"="` of numeric_std hides the
        // predefined one, LRM 10.3); the predefined operator otherwise.
        if let Some(r) = self.user_operator(sc, vec![lt.clone(), rt.clone()], span) {
            return r;
        }
        if bop == BinaryOp::Concat
            && let Some(r) = self.element_concat(&lt, &rt, want, span)
        {
            return r;
        }
        let ty = match result_type(bop, &lt.ty, &rt.ty) {
            Some(t) => t,
            None => {
                let help = if lt.ty.is_numeric() && rt.ty.is_numeric() {
                    INT_REAL_HELP.to_string()
                } else {
                    logic_help(&lt.ty)
                };
                return Err(self.error(ElabError::BadOperands {
                    span,
                    op: op_text(bop).into(),
                    left: lt.ty.to_string(),
                    right: rt.ty.to_string(),
                    help: Some(help),
                }));
            }
        };
        // Operands of known lengths give a result of known length (LRM 7.2.4: indexed from
        // the index subtype's left bound, in its direction).
        let ty = match (&ty, bop) {
            (Ty::Array(a), BinaryOp::Concat) => match (operand_len(&lt, a), operand_len(&rt, a)) {
                (Some(l), Some(r)) => constrain(a, l + r),
                _ => ty,
            },
            _ => ty,
        };
        // A physical value times or over a real: computed in reals, rounded to the unit.
        if let Ty::Physical(_) = ty
            && (lt.ty == Ty::Real || rt.ty == Ty::Real)
        {
            let real = |t: Typed| match t.ty {
                Ty::Real => t.e,
                _ => Expr::Call(Builtin::ToReal, vec![t.e]),
            };
            let product = Expr::Binary(bop, Box::new(real(lt)), Box::new(real(rt)));
            return self.folded(Expr::Call(Builtin::ToInteger, vec![product]), ty, span);
        }
        self.folded(Expr::Binary(bop, Box::new(lt.e), Box::new(rt.e)), ty, span)
    }

    /// `'a' & 'b'` and `'1' & '0'`: two elements joined into an array of them, the array the
    /// context wants, else `string` of characters and `bit_vector` of bits (LRM 7.2.4; the
    /// comparison `'a' & 'b' = "ab"` gives no other context).
    fn element_concat(
        &mut self,
        lt: &Typed,
        rt: &Typed,
        want: Option<&Ty>,
        span: Span,
    ) -> Option<R<Typed>> {
        if matches!(lt.ty, Ty::Array(_)) || matches!(rt.ty, Ty::Array(_)) || !lt.ty.same(&rt.ty) {
            return None;
        }
        let array = match want {
            Some(t @ Ty::Array(a)) if a.element.same(&lt.ty) => t.clone(),
            _ if lt.ty.is_enum_named("character") => self.standard_type("string")?,
            _ if lt.ty.is_enum_named("bit") => self.standard_type("bit_vector")?,
            _ => return None,
        };
        let Ty::Array(a) = &array else {
            return None;
        };
        let ty = a.with_bounds(None);
        // Characters join into a string value: `"" & 'a'` is one.
        let left = if lt.ty.is_enum_named("character") {
            let empty = Box::new(Expr::Const(Value::String(String::new())));
            Expr::Binary(BinaryOp::Concat, empty, Box::new(lt.e.clone()))
        } else {
            lt.e.clone()
        };
        let e = Expr::Binary(BinaryOp::Concat, Box::new(left), Box::new(rt.e.clone()));
        Some(self.folded(e, ty, span))
    }

    /// A call of one of `subs` (overloads of one name).
    pub(crate) fn call(
        &mut self,
        sc: &Scope<'a>,
        subs: Vec<Rc<Subprogram<'a>>>,
        args: &[ast::Assoc],
        span: Span,
        name_span: Span,
    ) -> R<Typed> {
        let (sub, slots) = self.resolve_call(subs, args, true, span, name_span)?;
        let ret = sub.ret.clone().unwrap_or(Ty::Real);
        let Some(native) = self.native_of(&sub) else {
            let e = self.user_function_call(sc, &sub, &slots, span)?;
            let ty = self.call_result(&sub, &e).unwrap_or(ret);
            return Ok(Typed::new(e, ty));
        };
        let mut args = Vec::new();
        for (p, slot) in sub.params.iter().zip(&slots) {
            match slot {
                Some(ae) => args.push(self.expr_of(sc, ae, &p.ty)?.e),
                None => {
                    return Err(self.error(ElabError::unsupported(
                        span,
                        format!("leaving out the parameter `{}`", p.name),
                        "give every argument",
                    )));
                }
            }
        }
        let e = self.native_call(&sub, native, args, span, name_span)?;
        self.folded(e, ret, span)
    }

    /// The expression of a call of the native (bodiless stdlib) subprogram `sub`, computed
    /// as `native`, on `args`, one per parameter.
    pub(crate) fn native_call(
        &mut self,
        sub: &Subprogram<'a>,
        native: Native,
        args: Vec<Expr>,
        span: Span,
        name_span: Span,
    ) -> R<Expr> {
        let name = &sub.name;
        let ret = sub.ret.clone().unwrap_or(Ty::Real);
        Ok(match native {
            Native::Builtin(Builtin::Pwl) => {
                if let Some(Expr::Const(Value::Array(items))) = args.first() {
                    let at = |k: usize| items[k].as_f64().unwrap_or(f64::NAN);
                    if let Err(e) = vams_design::pwl::check(items.len(), at) {
                        return Err(self.error(ElabError::invalid(
                            span,
                            e.to_string(),
                            Some(vams_design::pwl::TableError::HELP.into()),
                        )));
                    }
                }
                Expr::Call(Builtin::Pwl, args)
            }
            Native::Builtin(b) => Expr::Call(b, args),
            Native::Log2 => Expr::Binary(
                BinaryOp::Div,
                Box::new(Expr::Call(Builtin::Log, args)),
                Box::new(Expr::real(std::f64::consts::LN_2)),
            ),
            Native::LogBase => {
                let mut it = args.into_iter();
                let (x, b) = (it.next(), it.next());
                match (x, b) {
                    (Some(x), Some(b)) => Expr::Binary(
                        BinaryOp::Div,
                        Box::new(Expr::Call(Builtin::Log, vec![x])),
                        Box::new(Expr::Call(Builtin::Log, vec![b])),
                    ),
                    _ => return Err(crate::Reported),
                }
            }
            // VHDL-AMS's `now return real` (seconds) beside `now return delay_length`.
            Native::Now if ret == Ty::Real => Expr::Call(Builtin::ToReal, vec![Expr::Now]),
            Native::Now => Expr::Now,
            Native::Frequency if self.analog.in_spectrum => {
                Expr::Signal(self.frequency_signal(span))
            }
            Native::Frequency => {
                return Err(self.error(ElabError::invalid(
                    name_span,
                    "`frequency` is readable only in the magnitude and phase of a spectral source quantity and the density of a noise source quantity",
                    Some("LRM 1076.1: FREQUENCY is the small-signal analysis's frequency; declare `quantity ac : real spectrum mag, phase;` or `quantity n : real noise psd;` and use it there".into()),
                )));
            }
            // `"**"(x, y)` called by name.
            Native::Pow => {
                let mut it = args.into_iter();
                match (it.next(), it.next()) {
                    (Some(x), Some(y)) => {
                        let x = match sub.params.first().map(|p| &p.ty) {
                            Some(Ty::Integer) => Expr::Call(Builtin::ToReal, vec![x]),
                            _ => x,
                        };
                        Expr::Binary(BinaryOp::Pow, Box::new(x), Box::new(y))
                    }
                    _ => return Err(crate::Reported),
                }
            }
            Native::Io(IoNative::EndFile) => match args.into_iter().next() {
                Some(f) => Expr::EndFile(Box::new(f)),
                None => return Err(crate::Reported),
            },
            Native::Stop | Native::Finish | Native::Io(_) => {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("`{name}` is a procedure"),
                    None,
                )));
            }
            Native::Missing => {
                return Err(self.error(ElabError::unsupported(
                    name_span,
                    format!("the standard function `{name}`"),
                    "vams implements exp, log, log2, log10, sqrt, the trigonometric and hyperbolic functions, floor, ceil, round, trunc, sign, realmax and realmin",
                )));
            }
        })
    }

    /// `real(i)`, `integer(x)` and conversions between closely related types.
    pub(crate) fn conversion(
        &mut self,
        sc: &Scope<'a>,
        target: &Ty,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<Typed> {
        let [
            ast::Assoc {
                actual: Actual::Expr(ae),
                ..
            },
        ] = args
        else {
            return Err(self.error(ElabError::invalid(
                span,
                "a type conversion takes one expression",
                None,
            )));
        };
        let a = self.expr(sc, ae, None)?;
        let e = match (target, &a.ty) {
            (Ty::Real, Ty::Integer) => Expr::Call(Builtin::ToReal, vec![a.e]),
            (Ty::Integer, Ty::Real) => Expr::Call(Builtin::ToInteger, vec![a.e]),
            (t, from) if t.same(from) => a.e,
            // Closely related array types (LRM 7.3.5): the same elements, index types that
            // convert; the result keeps the operand's bounds unless the target has its own.
            (Ty::Array(t), Ty::Array(f))
                if t.element.same(&f.element)
                    && t.dimensions() == f.dimensions()
                    && (t.index.same(&f.index) || t.index.is_numeric() && f.index.is_numeric()) =>
            {
                if let (Some(n), Some(m)) = (t.len(), f.len())
                    && n != m
                {
                    return Err(self.error(ElabError::invalid(
                        span,
                        format!(
                            "a value of {m} element(s) converted to {t} of {n}",
                            t = t.name
                        ),
                        None,
                    )));
                }
                let ty = match t.bounds {
                    Some(_) => target.clone(),
                    None => t.with_bounds(f.bounds),
                };
                let e = match t.name == "string" || f.name == "string" {
                    true if t.name != f.name => {
                        let string = Expr::Const(Value::Boolean(ty.is_string()));
                        Expr::Call(Builtin::Restring, vec![a.e, string])
                    }
                    _ => a.e,
                };
                return self.folded(e, ty, span);
            }
            (t, from) => {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("cannot convert {from} to {t}"),
                    Some("VHDL converts between integer and real, between closely related array types, and within one type".into()),
                )));
            }
        };
        self.folded(e, target.clone(), span)
    }

    fn index(&mut self, sc: &Scope<'a>, array: Typed, args: &[ast::Assoc], span: Span) -> R<Typed> {
        let array = self.deref(array, span)?;
        let Ty::Array(arr) = &array.ty else {
            return Err(self.error(ElabError::invalid(
                span,
                format!("a value of type {} cannot be indexed or called", array.ty),
                Some("only arrays are indexed and only functions are called".into()),
            )));
        };
        if let [
            ast::Assoc {
                actual: Actual::Range(r),
                formal: None,
                ..
            },
        ] = args
        {
            let arr = arr.clone();
            let (first, len, ty) = self.slice(sc, &arr, r, span)?;
            let e = Expr::Call(Builtin::Slice, vec![array.e, first, len]);
            return self.folded(e, ty, span);
        }
        self.dimension_count(arr, args.len(), span, "index")?;
        // One index per dimension, each selecting a row of the next.
        let (mut e, mut ty) = (array.e, array.ty);
        for a in args {
            let ast::Assoc {
                actual: Actual::Expr(ie),
                formal: None,
                ..
            } = a
            else {
                return Err(self.error(ElabError::invalid(
                    a.span,
                    "expected an index",
                    Some("a slice takes one range: `a(1 to 3)`".into()),
                )));
            };
            let Ty::Array(level) = &ty else {
                // One index per dimension, checked above.
                break;
            };
            let level = level.clone();
            let index = self.index_position(sc, ie, &level.index)?;
            e = Expr::Index {
                array: Box::new(e),
                index: Box::new(index),
                ty: ty.to_design(),
            };
            ty = level.element.clone();
        }
        self.folded(e, ty, span)
    }

    /// Checks that `given` indexes (or index ranges, `what`) name one per dimension of `arr`.
    pub(crate) fn dimension_count(
        &mut self,
        arr: &ArrayTy,
        given: usize,
        span: Span,
        what: &str,
    ) -> R<()> {
        let n = arr.dimensions();
        if given == n {
            return Ok(());
        }
        Err(self.error(ElabError::invalid(
            span,
            format!("`{}` has {n} dimension(s), not {given}", arr.name),
            Some(format!("give one {what} per dimension")),
        )))
    }

    /// Index `ie` of an array whose index type is `index`, as a position (an enumeration
    /// literal's position, a boolean's 0 or 1, an integer itself).
    pub(crate) fn index_position(&mut self, sc: &Scope<'a>, ie: &ast::Expr, index: &Ty) -> R<Expr> {
        let i = self.expr_of(sc, ie, index)?;
        Ok(match index {
            Ty::Integer => i.e,
            _ => {
                self.folded(Expr::Call(Builtin::Pos, vec![i.e]), Ty::Integer, ie.span)?
                    .e
            }
        })
    }

    /// The slice `r` of an array of type `arr`: the position of its first element from the
    /// left, its length (run-time expressions when `r` is not static) and its type (with
    /// the slice's bounds when they are static). The slice runs in the array's direction.
    pub(crate) fn slice(
        &mut self,
        sc: &Scope<'a>,
        arr: &Rc<ArrayTy>,
        r: &ast::Range,
        span: Span,
    ) -> R<(Expr, Expr, Ty)> {
        let Some((left, _, asc)) = arr.bounds else {
            return Err(self.error(ElabError::unsupported(
                span,
                "a slice of an array whose bounds are known only at run time",
                "give the array a constrained subtype",
            )));
        };
        let (l, rr, dir) = self.range_exprs(sc, r)?;
        if dir != asc {
            return Err(self.error(ElabError::invalid(
                span,
                "this slice runs against its array's direction",
                Some(format!(
                    "the array's index runs `{}`: slice it the same way",
                    if asc { "to" } else { "downto" }
                )),
            )));
        }
        use vams_design::BinaryOp::{Add, Sub};
        let int = |k: i64| Expr::Const(Value::Integer(k));
        let bin = |op, a: Expr, b: Expr| Expr::Binary(op, Box::new(a), Box::new(b));
        let (first, len) = if asc {
            (
                bin(Sub, l.e.clone(), int(left)),
                bin(Add, bin(Sub, rr.e.clone(), l.e.clone()), int(1)),
            )
        } else {
            (
                bin(Sub, int(left), l.e.clone()),
                bin(Add, bin(Sub, l.e.clone(), rr.e.clone()), int(1)),
            )
        };
        let first = self.folded(first, Ty::Integer, span)?.e;
        let len = self.folded(len, Ty::Integer, span)?.e;
        let bounds = match (&l.e, &rr.e) {
            (Expr::Const(Value::Integer(a)), Expr::Const(Value::Integer(b))) => Some((*a, *b, asc)),
            _ => None,
        };
        Ok((first, len, arr.with_bounds(bounds)))
    }

    fn aggregate(
        &mut self,
        sc: &Scope<'a>,
        elems: &[ast::ElementAssoc],
        span: Span,
        want: Option<&Ty>,
    ) -> R<Typed> {
        if let Some(Ty::Record(rec)) = want {
            let rec = rec.clone();
            return self.record_aggregate(sc, &rec, elems, span);
        }
        let Some(Ty::Array(arr)) = want else {
            return Err(self.error(ElabError::invalid(
                span,
                "the type of this aggregate is not known here",
                Some("qualify it: `my_array'(1.0, 2.0)`".into()),
            )));
        };
        let arr = arr.clone();
        let elem = arr.element.clone();
        // Element values may be computed at run time; the choices are static.
        let mut positional = Vec::new();
        let mut others = None;
        let mut named: Vec<(i64, Expr)> = Vec::new();
        for el in elems {
            let v = self.expr_of(sc, &el.value, &elem)?.e;
            if el.choices.is_empty() {
                positional.push(v);
                continue;
            }
            for c in &el.choices {
                match c {
                    ast::Choice::Others(_) => others = Some(v.clone()),
                    ast::Choice::Expr(ce) => {
                        let i = self.static_value(sc, ce, &arr.index, "an aggregate choice")?;
                        let Some(i) = position(&i) else {
                            return Err(self.error(ElabError::invalid(
                                ce.span,
                                "an aggregate choice must be an index value",
                                None,
                            )));
                        };
                        named.push((i, v.clone()));
                    }
                    ast::Choice::Range(r) => {
                        let (l, rr, asc) = self.range_bounds(sc, r)?;
                        let (lo, hi) = if asc { (l, rr) } else { (rr, l) };
                        for i in lo..=hi {
                            named.push((i, v.clone()));
                        }
                    }
                }
            }
        }
        let (left, right, asc) = match arr.bounds {
            Some(b) => b,
            None if named.is_empty() => (
                arr.index_low,
                arr.index_low + positional.len() as i64 - 1,
                true,
            ),
            None => {
                let lo = named.iter().map(|n| n.0).min().unwrap_or(arr.index_low);
                let hi = named.iter().map(|n| n.0).max().unwrap_or(lo - 1);
                (lo, hi, true)
            }
        };
        let n = bounds_len(left, right, asc);
        let mut values: Vec<Option<Expr>> = vec![None; n];
        for (k, v) in positional.into_iter().enumerate() {
            if k >= n {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("too many elements for {n} positions"),
                    None,
                )));
            }
            values[k] = Some(v);
        }
        for (i, v) in named {
            let off = if asc { i - left } else { left - i };
            if off < 0 || off as usize >= n {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("index {i} is outside the array's range"),
                    None,
                )));
            }
            values[off as usize] = Some(v);
        }
        let mut out = Vec::with_capacity(n);
        for v in values {
            match v.or_else(|| others.clone()) {
                Some(v) => out.push(v),
                None => {
                    return Err(self.error(ElabError::invalid(
                        span,
                        format!("the aggregate does not give all {n} elements"),
                        Some("add the missing elements or `others => value`".into()),
                    )));
                }
            }
        }
        let ty = arr.with_bounds(Some((left, right, asc)));
        let string = ty.is_string();
        Ok(Typed::new(composite(out, string), ty))
    }
}

impl<'a> Elab<'a> {
    /// A record aggregate (LRM 7.3.2.1): positional elements first, then named fields
    /// (`hours | minutes => 0`), `others` for the rest. Each value is typed by its field, so
    /// an `others` value is lowered once per field it gives.
    fn record_aggregate(
        &mut self,
        sc: &Scope<'a>,
        rec: &Rc<RecordTy>,
        elems: &[ast::ElementAssoc],
        span: Span,
    ) -> R<Typed> {
        let n = rec.fields.len();
        let mut given: Vec<Option<&ast::Expr>> = vec![None; n];
        let mut others = None;
        for (k, el) in elems.iter().enumerate() {
            if el.choices.is_empty() {
                if k >= n {
                    return Err(self.error(ElabError::invalid(
                        el.span,
                        format!("too many elements: record `{}` has {n} fields", rec.name),
                        None,
                    )));
                }
                given[k] = Some(&el.value);
                continue;
            }
            for c in &el.choices {
                let field = match c {
                    ast::Choice::Others(_) => {
                        others = Some(&el.value);
                        continue;
                    }
                    ast::Choice::Expr(ast::Expr {
                        kind: ExprKind::Name(id),
                        ..
                    }) => rec.field(&id.name).map(|f| f.0),
                    _ => None,
                };
                let Some(pos) = field else {
                    let names: Vec<&str> = rec.fields.iter().map(|f| f.0.as_str()).collect();
                    return Err(self.error(ElabError::invalid(
                        el.span,
                        format!("record `{}` has no such field", rec.name),
                        Some(format!("its fields are {}", names.join(", "))),
                    )));
                };
                given[pos] = Some(&el.value);
            }
        }
        let mut out = Vec::with_capacity(n);
        for ((name, ty), value) in rec.fields.iter().zip(given) {
            let Some(value) = value.or(others) else {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("the aggregate gives no value for field `{name}`"),
                    Some("add `name => value` or `others => value`".into()),
                )));
            };
            out.push(self.expr_of(sc, value, ty)?.e);
        }
        Ok(Typed::new(composite(out, false), Ty::Record(rec.clone())))
    }

    /// The position and type of field `suffix` of a value of type `ty` (`span`: the whole
    /// selected name).
    pub(crate) fn record_field(
        &mut self,
        ty: &Ty,
        suffix: &ast::Ident,
        span: Span,
    ) -> R<(usize, Ty)> {
        let Ty::Record(r) = ty else {
            return Err(self.error(ElabError::invalid(
                span,
                format!("a value of type {ty} has no field `{}`", suffix.name),
                Some("only records have fields".into()),
            )));
        };
        match r.field(&suffix.name) {
            Some((pos, ty)) => Ok((pos, ty.clone())),
            None => {
                let names: Vec<&str> = r.fields.iter().map(|f| f.0.as_str()).collect();
                Err(self.error(ElabError::Undeclared {
                    span: suffix.span,
                    name: suffix.name.clone(),
                    help: Some(format!(
                        "record `{}` has the fields {}",
                        r.name,
                        names.join(", ")
                    )),
                }))
            }
        }
    }

    /// `prefix.field` of a record value.
    pub(crate) fn field(&mut self, rec: Typed, suffix: &ast::Ident, span: Span) -> R<Typed> {
        let rec = self.deref(rec, span)?;
        if suffix.name == "all" {
            return Ok(rec);
        }
        let (pos, ty) = self.record_field(&rec.ty, suffix, span)?;
        let design = rec.ty.to_design();
        self.folded(
            Expr::Index {
                array: Box::new(rec.e),
                index: Box::new(Expr::Const(Value::Integer(pos as i64))),
                ty: design,
            },
            ty,
            span,
        )
    }
}

/// A composite value from its elements in order: a constant when every element is one, else
/// built at run time (`string`: a character array held as a `Value::String`).
fn composite(elems: Vec<Expr>, string: bool) -> Expr {
    let values = elems
        .iter()
        .map(|e| match e {
            Expr::Const(v) => Some(v.clone()),
            _ => None,
        })
        .collect::<Option<Vec<Value>>>();
    match values {
        Some(values) => Expr::Const(vams_design::aggregate_value(values, string)),
        None => Expr::Aggregate { elems, string },
    }
}

/// `time` or a physical type of the user's own.
fn is_physical(t: &Ty) -> bool {
    matches!(t, Ty::Time | Ty::Physical(_))
}

/// The result type of `l op r`, or `None` when the operator is not defined for them.
fn result_type(op: BinaryOp, l: &Ty, r: &Ty) -> Option<Ty> {
    use BinaryOp::*;
    // A user's physical type counts its primary unit in integers (LRM 7.2.4, 7.2.6).
    if let (Ty::Physical(_), _) | (_, Ty::Physical(_)) = (l, r) {
        return match (op, l, r) {
            (Add | Sub, Ty::Physical(_), _) if l.same(r) => Some(l.clone()),
            (Mul, Ty::Physical(_), Ty::Integer | Ty::Real) => Some(l.clone()),
            (Mul, Ty::Integer | Ty::Real, Ty::Physical(_)) => Some(r.clone()),
            (Div, Ty::Physical(_), Ty::Integer | Ty::Real) => Some(l.clone()),
            (Div, Ty::Physical(_), _) if l.same(r) => Some(Ty::Integer),
            (Eq | Ne | Lt | Le | Gt | Ge, _, _) if l.same(r) => Some(Ty::Boolean),
            _ => None,
        };
    }
    match op {
        Add | Sub => (l.same(r) && (l.is_numeric() || *l == Ty::Time)).then(|| l.clone()),
        Mul => match (l, r) {
            (Ty::Integer, Ty::Integer) | (Ty::Real, Ty::Real) => Some(l.clone()),
            (Ty::Time, Ty::Integer | Ty::Real) | (Ty::Integer | Ty::Real, Ty::Time) => {
                Some(Ty::Time)
            }
            _ => None,
        },
        Div => match (l, r) {
            (Ty::Integer, Ty::Integer) | (Ty::Real, Ty::Real) => Some(l.clone()),
            (Ty::Time, Ty::Integer | Ty::Real) => Some(Ty::Time),
            (Ty::Time, Ty::Time) => Some(Ty::Integer),
            _ => None,
        },
        Mod | Rem => (l.same(r) && l.is_numeric()).then(|| l.clone()),
        Pow => match (l, r) {
            (Ty::Integer, Ty::Integer) => Some(Ty::Integer),
            (Ty::Real, Ty::Integer | Ty::Real) | (Ty::Integer, Ty::Real) => Some(Ty::Real),
            _ => None,
        },
        Eq | Ne => l.same(r).then_some(Ty::Boolean),
        // Arrays of a discrete type compare lexicographically (LRM 7.2.2).
        Lt | Le | Gt | Ge => (l.same(r)
            && (l.is_scalar()
                || l.is_string()
                || matches!(l, Ty::Array(a) if matches!(a.element, Ty::Enum(_) | Ty::Integer | Ty::Boolean))))
        .then_some(Ty::Boolean),
        And | Or | Nand | Nor | Xor | Xnor => {
            (l.same(r) && (is_logical_scalar(l) || logical_array(l))).then(|| l.clone())
        }
        Sll | Srl | Sla | Sra | Rol | Ror => {
            (logical_array(l) && *r == Ty::Integer).then(|| l.clone())
        }
        Concat => match (l, r) {
            (Ty::Array(a), Ty::Array(b)) if a.name == b.name => Some(a.with_bounds(None)),
            (Ty::Array(a), e) | (e, Ty::Array(a)) if a.element.same(e) => {
                Some(a.with_bounds(None))
            }
            _ => None,
        },
    }
}

/// `boolean` or `bit`: the types the predefined logical operators apply to (LRM 7.2.1).
fn is_logical_scalar(t: &Ty) -> bool {
    *t == Ty::Boolean || t.is_enum_named("bit")
}

/// A one-dimensional array of `bit` or `boolean` (`bit_vector`): logical operators apply
/// element by element, and the shift and rotate operators apply (LRM 7.2.1, 7.2.3).
fn logical_array(t: &Ty) -> bool {
    matches!(t, Ty::Array(a) if is_logical_scalar(&a.element))
}

/// The number of elements an operand of `&` whose result is of type `result` contributes,
/// where elaboration knows it: an element's one, an array's length.
fn operand_len(t: &Typed, result: &ArrayTy) -> Option<usize> {
    match (&t.ty, &t.e) {
        (Ty::Array(a), e) if a.name == result.name && a.dimension == result.dimension => match e {
            _ if a.bounds.is_some() => a.len(),
            Expr::Const(Value::Array(v)) => Some(v.len()),
            Expr::Const(Value::String(s)) => Some(s.chars().count()),
            _ => None,
        },
        _ => Some(1),
    }
}

/// `arr` constrained to `n` elements from its index subtype's low bound.
pub(crate) fn constrain(arr: &ArrayTy, n: usize) -> Ty {
    arr.with_bounds(Some((arr.index_low, arr.index_low + n as i64 - 1, true)))
}

/// The type of a string literal of `n` characters.
fn string_type(string: Option<Ty>, n: usize) -> Ty {
    match string {
        Some(Ty::Array(a)) => constrain(&a, n),
        Some(other) => other,
        _ => Ty::Array(Rc::new(ArrayTy {
            name: "string".into(),
            element: Ty::Integer,
            bounds: Some((1, n as i64, true)),
            index_low: 1,
            index: Ty::Integer,
            dimension: 0,
        })),
    }
}

fn logic_help(ty: &Ty) -> String {
    if ty.is_enum_named("std_ulogic") {
        "the std_logic_1164 operators on std_ulogic are visible with `library ieee; use ieee.std_logic_1164.all;`".into()
    } else {
        "logical operators take two boolean or two bit operands; arithmetic takes two numbers of the same type".into()
    }
}

/// The span of the identifier a (selected) name ends in, where analysis records what it
/// denotes; the whole span for any other expression.
pub(crate) fn designator_span(e: &ast::Expr) -> Span {
    e.name_ident().map_or(e.span, |id| id.span)
}
