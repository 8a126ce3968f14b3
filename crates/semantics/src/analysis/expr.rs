//! Expressions: names resolved to declarations, types inferred bottom-up (`infer`, which
//! reports nothing) and checked top-down against the type the context expects (`expr`, which
//! reports and records), overloads chosen from the operands and the expected type.

use vams_syntax::ast::{
    Actual, Assoc, BinaryOp, Choice, ElementAssoc, Expr, ExprKind, Ident, Literal, UnaryOp,
};
use vams_syntax::source::Span;

use super::error::AnalysisError;
use super::scope::{DeclId, DeclKind, Signature, Staticness};
use super::types::{
    AGGREGATE, NULL, STRING_LITERAL, TypeId, TypeKind, UNIVERSAL_INTEGER, UNIVERSAL_REAL, UNKNOWN,
};
use super::units::Analyzer;

/// What a name denotes.
enum Named {
    Decls(Vec<DeclId>),
    /// Not declared (the identifier that is missing).
    Missing,
    /// A selection from a value (a record field), not a declaration.
    Value,
}

/// The formal part of a named association, as overload resolution reads it.
#[derive(Clone, Copy, Debug)]
pub enum Formal<'e> {
    /// `x => ...`
    Whole(&'e str),
    /// An element or a slice of the parameter: `bv(0) => ...`, `bv(1 to 2) => ...`.
    Part(&'e str),
    /// A conversion function or another form analysis does not model.
    Other,
}

/// One argument of a call or operator: its formal name if named, and its expression.
struct Arg<'e> {
    formal: Option<Formal<'e>>,
    expr: Option<&'e Expr>,
    types: Vec<TypeId>,
}

impl Analyzer<'_> {
    // -----------------------------------------------------------------------------------
    // Names

    /// The declarations a (selected) name denotes, without reporting anything.
    pub fn peek_name(&self, e: &Expr) -> Option<Vec<DeclId>> {
        match self.named(e) {
            Named::Decls(ds) => Some(ds),
            _ => None,
        }
    }

    fn named(&self, e: &Expr) -> Named {
        match &e.kind {
            ExprKind::Name(id) => match self.lookup(&id.name) {
                Some(ds) => Named::Decls(ds),
                None => Named::Missing,
            },
            ExprKind::Selected(prefix, suffix) => {
                let (ExprKind::Name(_) | ExprKind::Selected(..)) = prefix.kind else {
                    return Named::Value;
                };
                let ds = match self.named(prefix) {
                    Named::Decls(ds) => ds,
                    Named::Missing => return Named::Missing,
                    Named::Value => return Named::Value,
                };
                let [d] = ds.as_slice() else {
                    return Named::Value;
                };
                let decl = self.out.decl(*d);
                match &decl.kind {
                    DeclKind::Library => match self.library_unit(&decl.name, &suffix.name) {
                        Some(u) => match self.unit_decl.get(&u) {
                            Some(&ud) => Named::Decls(vec![ud]),
                            None => Named::Decls(vec![DeclId(0)]),
                        },
                        None => Named::Missing,
                    },
                    DeclKind::Package(r) | DeclKind::Component(r) | DeclKind::Entity(r) => {
                        match self.lookup_in(*r, &suffix.name) {
                            Some(ds) => Named::Decls(ds),
                            None => Named::Missing,
                        }
                    }
                    DeclKind::Opaque => Named::Decls(vec![*d]),
                    // `counter.increment`: a method of a shared variable of protected type.
                    DeclKind::Object { ty, .. } => match self.types().kind(*ty) {
                        TypeKind::Protected(r) => match self.lookup_in(*r, &suffix.name) {
                            Some(ds) => Named::Decls(ds),
                            None => Named::Missing,
                        },
                        _ => Named::Value,
                    },
                    _ => Named::Value,
                }
            }
            _ => Named::Value,
        }
    }

    /// The declarations a (selected) name denotes, recording the reference; `None` (after a
    /// diagnostic, if the name is certainly undeclared) when there are none.
    pub fn resolve_name(&mut self, e: &Expr) -> Option<Vec<DeclId>> {
        match self.named(e) {
            Named::Decls(ds) => {
                let (span, prefix) = match &e.kind {
                    ExprKind::Name(id) => (id.span, None),
                    ExprKind::Selected(p, s) => (s.span, Some(p)),
                    _ => (e.span, None),
                };
                if let Some(p) = prefix {
                    self.resolve_name(p);
                }
                if let [d] = ds.as_slice() {
                    self.reference(span, *d);
                }
                Some(ds)
            }
            Named::Missing => {
                match &e.kind {
                    ExprKind::Name(id) => self.undeclared(id),
                    ExprKind::Selected(p, s) => {
                        if let Some(ds) = self.peek_name(p) {
                            self.resolve_name(p);
                            let library = match ds.as_slice() {
                                [d] if self.out.decl(*d).kind == DeclKind::Library => {
                                    Some(self.out.decl(*d).name.clone())
                                }
                                _ => None,
                            };
                            match library {
                                Some(lib) if !self.cut_here() => {
                                    let lib = match super::canonical_library(&lib) {
                                        "work" => self.out.units[self.cur].library.clone(),
                                        other => other.to_string(),
                                    };
                                    self.error(AnalysisError::MissingUnit {
                                        span: s.span,
                                        what: "design unit",
                                        name: s.name.clone(),
                                        library: lib,
                                        help: Some(format!(
                                            "give vams the file that declares `{}` (a directory \
                                             stands for all its .vhd files)",
                                            s.name
                                        )),
                                    });
                                }
                                Some(_) => {}
                                None => self.undeclared(s),
                            }
                        } else {
                            self.resolve_name(p);
                        }
                    }
                    _ => {}
                }
                None
            }
            Named::Value => {
                // A field of a record object (`regs.pc`): the object is still named.
                if let ExprKind::Selected(p, _) = &e.kind
                    && let ExprKind::Name(_) | ExprKind::Selected(..) = p.kind
                {
                    self.resolve_name(p);
                }
                None
            }
        }
    }

    /// The types a declaration has when named as a value.
    fn value_types(&self, d: DeclId, out: &mut Vec<TypeId>) {
        match &self.out.decl(d).kind {
            DeclKind::Object { ty, .. }
            | DeclKind::Alias(ty)
            | DeclKind::EnumLiteral(ty)
            | DeclKind::Unit(ty) => out.push(*ty),
            DeclKind::Subprogram(sig) => {
                if let Some(r) = sig.result {
                    if sig.params.iter().all(|p| p.has_default) {
                        out.push(r);
                    }
                }
            }
            DeclKind::Terminal(_)
            | DeclKind::Opaque
            | DeclKind::Library
            | DeclKind::Package(_)
            | DeclKind::Entity(_)
            | DeclKind::Component(_)
            | DeclKind::Type(_)
            | DeclKind::Nature(_)
            | DeclKind::Attribute(_) => out.push(UNKNOWN),
        }
    }

    // -----------------------------------------------------------------------------------
    // Inference (no diagnostics)

    /// Every type `e` can have, whatever the context; `[UNKNOWN]` when analysis cannot tell.
    pub fn infer(&self, e: &Expr) -> Vec<TypeId> {
        let mut out = match &e.kind {
            ExprKind::Literal(l) => vec![self.literal_type(l)],
            ExprKind::Name(_) | ExprKind::Selected(..) => match self.named(e) {
                Named::Decls(ds) => {
                    let mut out = Vec::new();
                    for d in ds {
                        self.value_types(d, &mut out);
                    }
                    out
                }
                Named::Missing => vec![UNKNOWN],
                Named::Value => match &e.kind {
                    ExprKind::Selected(prefix, suffix) => self
                        .infer(prefix)
                        .into_iter()
                        .map(|t| self.field(t, &suffix.name))
                        .collect(),
                    _ => vec![UNKNOWN],
                },
            },
            ExprKind::Apply(prefix, args) => self.infer_apply(prefix, args),
            ExprKind::Attribute(prefix, attr) => vec![self.attribute_type(prefix, attr)],
            // Only the prefix of an attribute name.
            ExprKind::Signed(..) => vec![UNKNOWN],
            ExprKind::Qualified(mark, _) => vec![self.peek_type_mark(mark)],
            ExprKind::Aggregate(_) => vec![AGGREGATE],
            ExprKind::Paren(inner) => self.infer(inner),
            ExprKind::Unary(op, x) => {
                let args = [self.arg(None, Some(x))];
                self.operator_results(unary_name(*op), &args)
            }
            ExprKind::Binary(op, l, r) => {
                let args = [self.arg(None, Some(l)), self.arg(None, Some(r))];
                self.operator_results(binary_name(*op), &args)
            }
            ExprKind::New(_) => vec![UNKNOWN],
        };
        if out.is_empty() {
            out.push(UNKNOWN);
        }
        out.sort();
        out.dedup();
        out
    }

    fn literal_type(&self, l: &Literal) -> TypeId {
        match l {
            Literal::Integer(_) => UNIVERSAL_INTEGER,
            Literal::Real(_) => UNIVERSAL_REAL,
            Literal::Physical(_, unit) => match self.lookup(&unit.name).as_deref() {
                Some([d]) => match self.out.decl(*d).kind {
                    DeclKind::Unit(t) => t,
                    _ => UNKNOWN,
                },
                _ => UNKNOWN,
            },
            Literal::Char(_) => UNKNOWN, // overloaded: see `char_types`
            Literal::String(_) | Literal::BitString(_) => STRING_LITERAL,
            Literal::Null => NULL,
        }
    }

    fn char_types(&self, c: char) -> Option<Vec<TypeId>> {
        let ds = self.lookup(&format!("'{c}'"))?;
        let mut out = Vec::new();
        for d in ds {
            self.value_types(d, &mut out);
        }
        Some(out)
    }

    fn arg<'e>(&self, formal: Option<Formal<'e>>, expr: Option<&'e Expr>) -> Arg<'e> {
        let types = match expr {
            Some(Expr {
                kind: ExprKind::Literal(Literal::Char(c)),
                ..
            }) => self.char_types(*c).unwrap_or_else(|| vec![UNKNOWN]),
            Some(e) => self.infer(e),
            None => vec![UNKNOWN],
        };
        Arg {
            formal,
            expr,
            types,
        }
    }

    fn args<'e>(&self, assocs: &'e [Assoc]) -> Vec<Arg<'e>> {
        assocs
            .iter()
            .map(|a| {
                let (formal, expr) = formal_and_actual(a);
                self.arg(formal, expr)
            })
            .collect()
    }

    fn infer_apply(&self, prefix: &Expr, args: &[Assoc]) -> Vec<TypeId> {
        if let ExprKind::Name(_) | ExprKind::Selected(..) = prefix.kind {
            if let Named::Decls(ds) = self.named(prefix) {
                if let [d] = ds.as_slice() {
                    match &self.out.decl(*d).kind {
                        DeclKind::Type(t) => return vec![*t],
                        DeclKind::Object { ty, .. } | DeclKind::Alias(ty) => {
                            return vec![self.indexed(*ty, args)];
                        }
                        _ => {}
                    }
                }
                let args = self.args(args);
                let calls = self.viable(&ds, &args, true);
                return calls.iter().filter_map(|&d| self.result(d)).collect();
            }
        }
        if let ExprKind::Attribute(p, attr) = &prefix.kind {
            return vec![self.attribute_type(p, attr)];
        }
        self.infer(prefix)
            .into_iter()
            .map(|t| self.indexed(t, args))
            .collect()
    }

    /// The type of `a(args)` for an array `a` of type `t`: a slice (a range argument) has
    /// the array's type, an index its element's.
    fn indexed(&self, t: TypeId, args: &[Assoc]) -> TypeId {
        match self.types().kind(t) {
            TypeKind::Array { .. } => {
                let slice = args.len() == 1
                    && match &args[0].actual {
                        Actual::Range(_) => true,
                        Actual::Expr(e) => self.is_type_mark(e),
                        Actual::Open(_) => false,
                    };
                if slice { t } else { self.types().element(t) }
            }
            TypeKind::Access(_) => UNKNOWN,
            _ => UNKNOWN,
        }
    }

    fn field(&self, t: TypeId, name: &str) -> TypeId {
        match self.types().kind(t) {
            TypeKind::Record { fields } => fields
                .iter()
                .find(|(n, _)| n == name)
                .map_or(UNKNOWN, |(_, t)| *t),
            _ => UNKNOWN,
        }
    }

    fn result(&self, d: DeclId) -> Option<TypeId> {
        match &self.out.decl(d).kind {
            DeclKind::Subprogram(s) => s.result,
            _ => None,
        }
    }

    fn operator_results(&self, name: &str, args: &[Arg]) -> Vec<TypeId> {
        let Some(ds) = self.lookup(&format!("\"{name}\"")) else {
            return vec![UNKNOWN];
        };
        self.viable(&ds, args, true)
            .iter()
            .filter_map(|&d| self.result(d))
            .collect()
    }

    /// The subprograms of `cands` that `args` can call (functions or procedures).
    fn viable(&self, cands: &[DeclId], args: &[Arg], functions: bool) -> Vec<DeclId> {
        cands
            .iter()
            .copied()
            .filter(|&d| match &self.out.decl(d).kind {
                DeclKind::Subprogram(sig) => {
                    sig.result.is_some() == functions && self.matches(sig, args).is_some()
                }
                DeclKind::Opaque => true,
                _ => false,
            })
            .collect()
    }

    /// The parameter each argument goes to, if `args` fit `sig`.
    /// Empty when an argument associates a part of its parameter (no argument then takes a
    /// parameter's type as its own).
    fn matches(&self, sig: &Signature, args: &[Arg]) -> Option<Vec<usize>> {
        let mut used = vec![false; sig.params.len()];
        let mut to = Vec::with_capacity(args.len());
        let mut parts = false;
        for (i, a) in args.iter().enumerate() {
            let p = match a.formal {
                None => i,
                // A formal part analysis does not model: accept without checking.
                Some(Formal::Other) => return Some(Vec::new()),
                Some(Formal::Whole(name)) => sig.params.iter().position(|p| p.name == name)?,
                // Elements and slices of one parameter, each associated once (not checked
                // here): the actual is of the parameter's element type or of its type.
                Some(Formal::Part(name)) => {
                    // Else a conversion function (`to_bit(q) => s`): not modelled.
                    let Some(p) = sig.params.iter().position(|p| p.name == name) else {
                        return Some(Vec::new());
                    };
                    let ty = sig.params[p].ty;
                    let element = self.types().element(ty);
                    let fits =
                        |&t: &TypeId| self.types().fits(t, ty) || self.types().fits(t, element);
                    if !a.types.iter().any(fits) {
                        return None;
                    }
                    used[p] = true;
                    parts = true;
                    continue;
                }
            };
            if p >= sig.params.len() || used[p] {
                return None;
            }
            used[p] = true;
            let ty = sig.params[p].ty;
            if !a.types.iter().any(|&t| self.types().fits(t, ty)) {
                return None;
            }
            to.push(p);
        }
        let complete = sig
            .params
            .iter()
            .zip(&used)
            .all(|(p, &u)| u || p.has_default);
        if parts {
            to.clear();
        }
        complete.then_some(to)
    }

    /// The type a type mark denotes, without reporting anything.
    fn peek_type_mark(&self, e: &Expr) -> TypeId {
        match &e.kind {
            ExprKind::Name(_) | ExprKind::Selected(..) => match self.peek_name(e).as_deref() {
                Some([d]) => match self.out.decl(*d).kind {
                    DeclKind::Type(t) => t,
                    _ => UNKNOWN,
                },
                _ => UNKNOWN,
            },
            ExprKind::Apply(p, _) => self.peek_type_mark(p),
            _ => UNKNOWN,
        }
    }

    /// The type of `prefix'attr` (arguments, if any, do not change it).
    fn attribute_type(&self, prefix: &Expr, attr: &Ident) -> TypeId {
        let std = self.std;
        // What the prefix is: a type, an object of a type, a terminal.
        let (as_type, object) = match &prefix.kind {
            ExprKind::Name(_) | ExprKind::Selected(..) => match self.peek_name(prefix).as_deref() {
                Some([d]) => match &self.out.decl(*d).kind {
                    DeclKind::Type(t) => (Some(*t), None),
                    DeclKind::Object { ty, .. } | DeclKind::Alias(ty) => (None, Some(*ty)),
                    DeclKind::Terminal(n) => {
                        let n = self.nature(*n);
                        return match attr.name.as_str() {
                            "reference" => n.across,
                            "contribution" => n.through,
                            _ => UNKNOWN,
                        };
                    }
                    _ => (None, None),
                },
                _ => (None, None),
            },
            _ => {
                let t = self.infer(prefix);
                (None, (t.len() == 1).then(|| t[0]))
            }
        };
        let index = |t: TypeId| match self.types().kind(t) {
            TypeKind::Array { indexes, .. } => indexes.first().copied().unwrap_or(UNKNOWN),
            _ => t,
        };
        match attr.name.as_str() {
            "dot" | "integ" | "delayed" | "slew" | "ramp" | "zoh" | "ltf" | "ztf"
            | "last_value" | "driving_value" => object.unwrap_or(UNKNOWN),
            "above" | "event" | "active" | "stable" | "quiet" | "driving" | "ascending" => {
                std.boolean
            }
            "last_event" | "last_active" => std.time,
            "length" | "pos" => UNIVERSAL_INTEGER,
            "high" | "low" | "left" | "right" => match (as_type, object) {
                (Some(t), _) => index(t),
                (None, Some(t)) => match self.types().kind(t) {
                    TypeKind::Array { .. } => index(t),
                    _ => UNKNOWN,
                },
                _ => UNKNOWN,
            },
            "val" | "succ" | "pred" | "leftof" | "rightof" | "value" => as_type.unwrap_or(UNKNOWN),
            "image" | "simple_name" | "path_name" | "instance_name" | "tolerance" => std.string,
            name => match self.lookup(name).as_deref() {
                Some([d]) => match self.out.decl(*d).kind {
                    DeclKind::Attribute(t) => t,
                    _ => UNKNOWN,
                },
                _ => UNKNOWN,
            },
        }
    }

    /// The type of a range attribute `x'range` / `x'reverse_range` (its index type).
    pub fn range_attribute(&mut self, e: &Expr) -> TypeId {
        let (prefix, _) = match &e.kind {
            ExprKind::Attribute(p, a) => (p, a),
            ExprKind::Apply(inner, args) => {
                for a in args {
                    self.assoc_any(a);
                }
                return self.range_attribute(inner);
            }
            _ => {
                self.expr_any(e);
                return UNKNOWN;
            }
        };
        self.prefix(prefix);
        let t = match &prefix.kind {
            ExprKind::Name(_) | ExprKind::Selected(..) => match self.peek_name(prefix).as_deref() {
                Some([d]) => match &self.out.decl(*d).kind {
                    DeclKind::Type(t) | DeclKind::Object { ty: t, .. } | DeclKind::Alias(t) => *t,
                    _ => UNKNOWN,
                },
                _ => UNKNOWN,
            },
            _ => {
                let t = self.infer(prefix);
                if t.len() == 1 { t[0] } else { UNKNOWN }
            }
        };
        match self.types().kind(t) {
            TypeKind::Array { indexes, .. } => indexes.first().copied().unwrap_or(UNKNOWN),
            _ => t,
        }
    }

    // -----------------------------------------------------------------------------------
    // Checking

    /// Checks `e` where no particular type is expected; returns its type if it has one.
    pub fn expr_any(&mut self, e: &Expr) -> TypeId {
        self.expr(e, UNKNOWN)
    }

    pub fn assoc_any(&mut self, a: &Assoc) {
        match &a.actual {
            Actual::Expr(e) => {
                self.expr_any(e);
            }
            Actual::Range(r) => {
                self.range(r, UNKNOWN);
            }
            Actual::Open(_) => {}
        }
    }

    /// Checks `e` against `expected` (`UNKNOWN`: anything), reporting what is wrong and
    /// recording names and types; returns the type chosen for `e`.
    pub fn expr(&mut self, e: &Expr, expected: TypeId) -> TypeId {
        let t = self.expr_inner(e, expected);
        self.record_type(e.span, t);
        let s = self.staticness(e);
        if s != Staticness::None {
            self.out.units[self.cur].statics.push((e.span, s));
        }
        t
    }

    fn expr_inner(&mut self, e: &Expr, expected: TypeId) -> TypeId {
        match &e.kind {
            ExprKind::Literal(Literal::Char(c)) => {
                let Some(ds) = self.lookup(&format!("'{c}'")) else {
                    return UNKNOWN;
                };
                let mut types = Vec::new();
                for &d in &ds {
                    self.value_types(d, &mut types);
                }
                let chosen = self.choose(e.span, &types, expected);
                if let Some(&d) = ds.iter().find(
                    |&&d| matches!(self.out.decl(d).kind, DeclKind::EnumLiteral(t) if t == chosen),
                ) {
                    self.reference(e.span, d);
                }
                chosen
            }
            ExprKind::Literal(l) => {
                if let Literal::Physical(_, unit) = l {
                    let unit_expr = Expr {
                        kind: ExprKind::Name(unit.clone()),
                        span: unit.span,
                    };
                    self.resolve_name(&unit_expr);
                }
                let t = self.literal_type(l);
                self.choose(e.span, &[t], expected)
            }
            ExprKind::Name(_) | ExprKind::Selected(..) => self.name_expr(e, expected),
            ExprKind::Apply(prefix, args) => self.apply(e, prefix, args, expected),
            ExprKind::Attribute(prefix, attr) => {
                self.prefix(prefix);
                let t = self.attribute_type(prefix, attr);
                self.choose(e.span, &[t], expected)
            }
            ExprKind::Signed(name, signature) => {
                self.signed_name(name, signature);
                UNKNOWN
            }
            ExprKind::Qualified(mark, inner) => {
                let t = self.type_mark(mark);
                self.expr(inner, t);
                self.choose(e.span, &[t], expected)
            }
            ExprKind::Aggregate(elements) => {
                let kind = self.types().kind(expected).clone();
                match kind {
                    TypeKind::Array { indexes, element } => {
                        self.array_aggregate(elements, &indexes, element);
                    }
                    TypeKind::Record { fields } => {
                        for (i, el) in elements.iter().enumerate() {
                            let ty = match el.choices.as_slice() {
                                [] => fields.get(i).map_or(UNKNOWN, |f| f.1),
                                [
                                    Choice::Expr(Expr {
                                        kind: ExprKind::Name(id),
                                        ..
                                    }),
                                ] => fields
                                    .iter()
                                    .find(|f| f.0 == id.name)
                                    .map_or(UNKNOWN, |f| f.1),
                                _ => UNKNOWN,
                            };
                            self.expr(&el.value, ty);
                        }
                    }
                    _ => {
                        for el in elements {
                            self.expr_any(&el.value);
                        }
                    }
                }
                self.choose(e.span, &[AGGREGATE], expected)
            }
            ExprKind::Paren(inner) => self.expr(inner, expected),
            ExprKind::Unary(op, x) => {
                let args = [Some(&**x)];
                self.call(unary_name(*op), e.span, &args.map(|x| (None, x)), expected)
            }
            ExprKind::Binary(op, l, r) => {
                let args = [(None, Some(&**l)), (None, Some(&**r))];
                self.call(binary_name(*op), e.span, &args, expected)
            }
            ExprKind::New(x) => {
                if let ExprKind::Qualified(..) = x.kind {
                    self.expr_any(x);
                } else {
                    // `new natural`, `new time_array(1 to 10)`: a subtype indication.
                    self.type_mark(x);
                }
                UNKNOWN
            }
        }
    }

    /// The prefix of an attribute: a name is resolved (and reported if undeclared), an
    /// expression checked.
    fn prefix(&mut self, p: &Expr) {
        match &p.kind {
            ExprKind::Name(_) | ExprKind::Selected(..) => {
                self.resolve_name(p);
            }
            ExprKind::Signed(name, signature) => {
                self.signed_name(name, signature);
            }
            _ => {
                self.expr_any(p);
            }
        }
    }

    /// The declaration that a name with a signature denotes (`inc [integer return integer]`,
    /// `idle [return state]`): the one overload whose parameter and result types are the
    /// signature's (LRM 2.3.2). Its type marks are resolved either way.
    pub fn signed_name(
        &mut self,
        name: &Expr,
        signature: &vams_syntax::ast::Signature,
    ) -> Option<DeclId> {
        let params: Vec<TypeId> = signature.params.iter().map(|t| self.type_mark(t)).collect();
        let result = signature.result.as_ref().map(|t| self.type_mark(t));
        let Named::Decls(ds) = self.named(name) else {
            self.resolve_name(name);
            return None;
        };
        let same = |a: TypeId, b: TypeId| a == b || a == UNKNOWN || b == UNKNOWN;
        let matching: Vec<DeclId> = ds
            .into_iter()
            .filter(|&d| match &self.out.decl(d).kind {
                DeclKind::EnumLiteral(t) => params.is_empty() && result.is_none_or(|r| same(r, *t)),
                DeclKind::Subprogram(sig) => {
                    sig.params.len() == params.len()
                        && sig.params.iter().zip(&params).all(|(p, &t)| same(p.ty, t))
                        && match (sig.result, result) {
                            (Some(a), Some(b)) => same(a, b),
                            (None, None) => true,
                            _ => false,
                        }
                }
                _ => true,
            })
            .collect();
        let span = match &name.kind {
            ExprKind::Name(id) | ExprKind::Selected(_, id) => id.span,
            _ => name.span,
        };
        if let ExprKind::Selected(p, _) = &name.kind {
            self.resolve_name(p);
        }
        match matching.as_slice() {
            [d] => {
                self.reference(span, *d);
                Some(*d)
            }
            _ => None,
        }
    }

    /// The elements of an aggregate of an array with these index types: a multi-dimensional
    /// array's aggregate is an aggregate of aggregates (or strings) of its other dimensions
    /// (LRM 7.3.2.2), typed level by level.
    fn array_aggregate(&mut self, elements: &[ElementAssoc], indexes: &[TypeId], element: TypeId) {
        let Some((&index, rest)) = indexes.split_first() else {
            return;
        };
        for el in elements {
            for c in &el.choices {
                self.choice(c, index);
            }
            if rest.is_empty() {
                self.expr(&el.value, element);
                continue;
            }
            match &el.value.kind {
                ExprKind::Aggregate(inner) => self.array_aggregate(inner, rest, element),
                // A row of characters written as a string literal.
                _ => {
                    self.expr_any(&el.value);
                }
            }
        }
    }

    fn choice(&mut self, c: &Choice, ty: TypeId) {
        match c {
            Choice::Expr(x) => {
                if self.is_type_mark(x) {
                    self.type_mark(x);
                } else {
                    self.expr(x, ty);
                }
            }
            Choice::Range(r) => {
                self.range(r, ty);
            }
            Choice::Others(_) => {}
        }
    }

    /// Checks the choices of a case alternative against the selector's type.
    pub fn choices(&mut self, choices: &[Choice], ty: TypeId) {
        for c in choices {
            self.choice(c, ty);
        }
    }

    /// The choices of a case alternative: of the selector's type and locally static (LRM
    /// 8.8, 9.5.2).
    pub fn case_choices(&mut self, choices: &[Choice], ty: TypeId) {
        self.choices(choices, ty);
        for c in choices {
            match c {
                Choice::Expr(x) => self.require_static(x, "a case choice", Staticness::Local),
                Choice::Range(r) => {
                    self.require_static_range(r, "a case choice", Staticness::Local)
                }
                Choice::Others(_) => {}
            }
        }
    }

    /// Both bounds of an explicit range (an attribute range names an object or a type, whose
    /// bounds are not read as values).
    pub fn require_static_range(
        &mut self,
        r: &vams_syntax::ast::Range,
        what: &'static str,
        required: Staticness,
    ) {
        if let vams_syntax::ast::Range::Explicit { left, right, .. } = r {
            self.require_static(left, what, required);
            self.require_static(right, what, required);
        }
    }

    /// Picks the type among `types` that fits `expected`, reporting a mismatch when none
    /// does and both sides are known.
    fn choose(&mut self, span: Span, types: &[TypeId], expected: TypeId) -> TypeId {
        if let Some(&t) = types.iter().find(|&&t| self.types().fits(t, expected)) {
            return if self.types().is_known(expected) && !self.types().is_known(t) {
                expected
            } else {
                t
            };
        }
        if types.len() == 1 && self.types().is_known(types[0]) && self.types().is_known(expected) {
            let found = self.types().describe(types[0]);
            let expected_name = self.types().describe(expected);
            let help = self.conversion_help(types[0], expected);
            self.error(AnalysisError::TypeMismatch {
                span,
                expected: expected_name,
                found,
                help,
            });
        }
        types.first().copied().unwrap_or(UNKNOWN)
    }

    fn conversion_help(&self, found: TypeId, expected: TypeId) -> Option<String> {
        let (f, x) = (self.types().kind(found), self.types().kind(expected));
        Some(match (f, x) {
            (TypeKind::UniversalReal, TypeKind::Integer) => {
                "an integer needs an integer literal (`2`, not `2.0`), or a conversion such as \
                 `integer(x)`"
                    .to_string()
            }
            (TypeKind::UniversalInteger, TypeKind::Real) => {
                "a real needs a real literal (`2.0`, not `2`), or a conversion such as `real(n)`"
                    .to_string()
            }
            (TypeKind::Integer, TypeKind::Real) | (TypeKind::Real, TypeKind::Integer) => format!(
                "VHDL converts nothing implicitly: write `{}(...)` around the value",
                self.types().name(expected)
            ),
            _ => return None,
        })
    }

    fn name_expr(&mut self, e: &Expr, expected: TypeId) -> TypeId {
        match self.named(e) {
            Named::Decls(_) => {
                let Some(ds) = self.resolve_name(e) else {
                    return UNKNOWN;
                };
                let mut types = Vec::new();
                for &d in &ds {
                    self.value_types(d, &mut types);
                }
                if types.is_empty() {
                    return UNKNOWN; // A procedure named as a value: elaboration says so.
                }
                let chosen = self.choose(e.span, &types, expected);
                if ds.len() > 1 {
                    let span = match &e.kind {
                        ExprKind::Name(id) | ExprKind::Selected(_, id) => id.span,
                        _ => e.span,
                    };
                    let mut pick = ds.iter().filter(|&&d| {
                        let mut t = Vec::new();
                        self.value_types(d, &mut t);
                        t.contains(&chosen)
                    });
                    if let (Some(&d), None) = (pick.next(), pick.next()) {
                        self.reference(span, d);
                    }
                }
                chosen
            }
            Named::Missing => {
                self.resolve_name(e);
                UNKNOWN
            }
            Named::Value => {
                let ExprKind::Selected(prefix, suffix) = &e.kind else {
                    return UNKNOWN;
                };
                let pt = self.expr_any(prefix);
                let t = self.field(pt, &suffix.name);
                self.choose(e.span, &[t], expected)
            }
        }
    }

    fn apply(&mut self, e: &Expr, prefix: &Expr, args: &[Assoc], expected: TypeId) -> TypeId {
        if let ExprKind::Name(_) | ExprKind::Selected(..) = prefix.kind {
            if let Named::Decls(ds) = self.named(prefix) {
                if let [d] = ds.as_slice() {
                    match self.out.decl(*d).kind.clone() {
                        DeclKind::Type(t) => {
                            self.resolve_name(prefix);
                            for a in args {
                                self.assoc_any(a);
                            }
                            return self.choose(e.span, &[t], expected);
                        }
                        DeclKind::Object { ty, .. } | DeclKind::Alias(ty) => {
                            self.resolve_name(prefix);
                            let t = self.index_args(ty, args);
                            return self.choose(e.span, &[t], expected);
                        }
                        _ => {}
                    }
                }
                let name_span = match &prefix.kind {
                    ExprKind::Name(id) | ExprKind::Selected(_, id) => id.span,
                    _ => prefix.span,
                };
                if let ExprKind::Selected(p, _) = &prefix.kind {
                    self.resolve_name(p);
                }
                let list: Vec<(Option<Formal>, Option<&Expr>)> =
                    args.iter().map(formal_and_actual).collect();
                let functions: Vec<DeclId> = ds
                    .iter()
                    .copied()
                    .filter(|&d| {
                        matches!(&self.out.decl(d).kind, DeclKind::Subprogram(s) if s.result.is_some())
                    })
                    .collect();
                if functions.is_empty() {
                    // An element of a terminal array, or something analysis does not model.
                    if let [d] = ds.as_slice() {
                        self.reference(name_span, *d);
                    }
                    for a in args {
                        self.assoc_any(a);
                    }
                    return UNKNOWN;
                }
                let name = self.out.decl(functions[0]).name.clone();
                return self.call_among(&name, name_span, functions, &list, expected, e.span);
            }
            if let Named::Missing = self.named(prefix) {
                self.resolve_name(prefix);
                for a in args {
                    self.assoc_any(a);
                }
                return UNKNOWN;
            }
        }
        if let ExprKind::Attribute(p, attr) = &prefix.kind {
            self.prefix(p);
            for a in args {
                self.assoc_any(a);
            }
            let t = self.attribute_type(p, attr);
            return self.choose(e.span, &[t], expected);
        }
        let pt = self.expr_any(prefix);
        let t = self.index_args(pt, args);
        self.choose(e.span, &[t], expected)
    }

    /// Checks the index (or slice) arguments of an array of type `t`; the result's type.
    fn index_args(&mut self, t: TypeId, args: &[Assoc]) -> TypeId {
        let result = self.indexed(t, args);
        let indexes = match self.types().kind(t) {
            TypeKind::Array { indexes, .. } => indexes.clone(),
            _ => Vec::new(),
        };
        for (i, a) in args.iter().enumerate() {
            let ty = indexes.get(i).copied().unwrap_or(UNKNOWN);
            match &a.actual {
                Actual::Expr(x) if self.is_type_mark(x) => {
                    self.type_mark(x);
                }
                Actual::Expr(x) => {
                    self.expr(x, ty);
                }
                Actual::Range(r) => {
                    self.range(r, ty);
                }
                Actual::Open(_) => {}
            }
        }
        result
    }

    /// An operator application: the visible declarations of `"op"`.
    fn call(
        &mut self,
        op: &str,
        span: Span,
        args: &[(Option<Formal>, Option<&Expr>)],
        expected: TypeId,
    ) -> TypeId {
        let name = format!("\"{op}\"");
        let Some(cands) = self.lookup(&name) else {
            for (_, a) in args {
                if let Some(a) = a {
                    self.expr_any(a);
                }
            }
            return UNKNOWN;
        };
        self.call_among(op, span, cands, args, expected, span)
    }

    /// Resolves a call of one of `cands` with `args` against `expected`, then checks the
    /// arguments against the chosen declaration's parameters.
    pub fn call_among(
        &mut self,
        name: &str,
        name_span: Span,
        cands: Vec<DeclId>,
        args: &[(Option<Formal>, Option<&Expr>)],
        expected: TypeId,
        span: Span,
    ) -> TypeId {
        let infos: Vec<Arg> = args.iter().map(|&(f, x)| self.arg(f, x)).collect();
        let viable = self.viable(&cands, &infos, true);
        let fitting: Vec<DeclId> = viable
            .iter()
            .copied()
            .filter(|&d| {
                self.result(d)
                    .is_none_or(|r| self.types().fits(r, expected))
            })
            .collect();
        let all_known = infos
            .iter()
            .all(|a| a.types.iter().all(|&t| self.types().is_known(t)) && a.expr.is_some())
            && cands
                .iter()
                .all(|&d| matches!(self.out.decl(d).kind, DeclKind::Subprogram(_)));
        let chosen: Vec<DeclId> = if fitting.is_empty() {
            viable.clone()
        } else {
            fitting.clone()
        };
        let chosen = self.prefer_exact(chosen, &infos);
        if viable.is_empty() {
            if all_known && !cands.is_empty() && !self.cut_here() {
                let operands = infos
                    .iter()
                    .map(|a| match a.types.as_slice() {
                        [t] => self.types().describe(*t),
                        ts => ts
                            .iter()
                            .map(|t| self.types().describe(*t))
                            .collect::<Vec<_>>()
                            .join(" or "),
                    })
                    .collect::<Vec<_>>()
                    .join(" and ");
                let help = self.operand_help(&infos);
                self.error(AnalysisError::NoOverload {
                    span: name_span,
                    name: name.trim_matches('"').to_string(),
                    operands,
                    help,
                });
            }
            for (_, a) in args {
                if let Some(a) = a {
                    self.expr_any(a);
                }
            }
            return UNKNOWN;
        }
        // Each argument against its parameter where every remaining candidate agrees.
        let params: Vec<Option<TypeId>> = (0..args.len())
            .map(|i| {
                let mut ts = chosen.iter().filter_map(|&d| {
                    let DeclKind::Subprogram(sig) = &self.out.decl(d).kind else {
                        return None;
                    };
                    let to = self.matches(sig, &infos)?;
                    to.get(i).map(|&p| sig.params[p].ty)
                });
                let first = ts.next()?;
                ts.all(|t| t == first).then_some(first)
            })
            .collect();
        for ((_, a), p) in args.iter().zip(params) {
            if let Some(a) = a {
                self.expr(a, p.unwrap_or(UNKNOWN));
            }
        }
        if let [d] = chosen.as_slice() {
            self.reference(name_span, *d);
        }
        let results: Vec<TypeId> = chosen.iter().filter_map(|&d| self.result(d)).collect();
        if fitting.is_empty() && all_known {
            // Callable, but nothing it returns fits here.
            let mut rs = results.clone();
            rs.dedup();
            if let [r] = rs.as_slice() {
                return self.choose(span, &[*r], expected);
            }
        }
        match results.as_slice() {
            [r, rest @ ..] if rest.iter().all(|x| x == r) => *r,
            _ => expected,
        }
    }

    /// Among several callable declarations, those that need no implicit conversion of a
    /// universal operand, when there are such (`2 * 3` is integer's `*` where an integer is
    /// expected, and duplicates of one declaration collapse).
    fn prefer_exact(&self, mut chosen: Vec<DeclId>, args: &[Arg]) -> Vec<DeclId> {
        if chosen.len() < 2 {
            return chosen;
        }
        chosen.dedup_by(|a, b| self.out.decl(*a).kind == self.out.decl(*b).kind);
        let exact: Vec<DeclId> = chosen
            .iter()
            .copied()
            .filter(|&d| {
                let DeclKind::Subprogram(sig) = &self.out.decl(d).kind else {
                    return false;
                };
                let Some(to) = self.matches(sig, args) else {
                    return false;
                };
                to.iter()
                    .zip(args)
                    .all(|(&p, a)| a.types.contains(&sig.params[p].ty))
            })
            .collect();
        if exact.is_empty() { chosen } else { exact }
    }

    fn operand_help(&self, args: &[Arg]) -> Option<String> {
        let kinds: Vec<Option<&TypeKind>> = args
            .iter()
            .map(|a| match a.types.as_slice() {
                [t] => Some(self.types().kind(*t)),
                _ => None,
            })
            .collect();
        let real =
            |k: &Option<&TypeKind>| matches!(k, Some(TypeKind::Real | TypeKind::UniversalReal));
        let int = |k: &Option<&TypeKind>| {
            matches!(k, Some(TypeKind::Integer | TypeKind::UniversalInteger))
        };
        let mixed = kinds.iter().any(real) && kinds.iter().any(int);
        mixed.then(|| {
            "VHDL converts nothing implicitly between integer and real: write the literal as \
             `2.0`, or convert with `real(n)` / `integer(x)`"
                .to_string()
        })
    }

    /// A procedure call statement: `p(args);` or `p;`.
    pub fn procedure_call(&mut self, e: &Expr) {
        let (prefix, args): (&Expr, &[Assoc]) = match &e.kind {
            ExprKind::Apply(p, a) => (p, a),
            _ => (e, &[]),
        };
        let ds = match self.named(prefix) {
            Named::Decls(ds) => ds,
            Named::Missing => {
                self.resolve_name(prefix);
                for a in args {
                    self.assoc_any(a);
                }
                return;
            }
            Named::Value => {
                self.expr_any(e);
                return;
            }
        };
        if let ExprKind::Selected(p, _) = &prefix.kind {
            self.resolve_name(p);
        }
        let infos = self.args(args);
        let viable = self.viable(&ds, &infos, false);
        let chosen = self.prefer_exact(viable, &infos);
        let span = match &prefix.kind {
            ExprKind::Name(id) | ExprKind::Selected(_, id) => id.span,
            _ => prefix.span,
        };
        if let [d] = chosen.as_slice() {
            self.reference(span, *d);
            let DeclKind::Subprogram(sig) = self.out.decl(*d).kind.clone() else {
                return;
            };
            let to = self.matches(&sig, &infos).unwrap_or_default();
            for (i, a) in args.iter().enumerate() {
                let ty = to.get(i).map_or(UNKNOWN, |&p| sig.params[p].ty);
                match &a.actual {
                    Actual::Expr(x) => {
                        self.expr(x, ty);
                    }
                    Actual::Range(r) => {
                        self.range(r, UNKNOWN);
                    }
                    Actual::Open(_) => {}
                }
            }
        } else {
            if chosen.len() > 1 && !self.cut_here() {
                let now = args.iter().any(|a| {
                    matches!(&a.actual, Actual::Expr(Expr { kind: ExprKind::Name(id), .. }) if id.name == "now")
                });
                let help = if now {
                    "VHDL-AMS declares `now` twice, returning `delay_length` and `real`: qualify it, `time'(now)` or `real'(now)`"
                } else {
                    "qualify an argument with its type (`real'(x)`, `string'(\"...\")`) so that one declaration fits"
                };
                let name = match &prefix.kind {
                    ExprKind::Name(id) | ExprKind::Selected(_, id) => id.name.clone(),
                    _ => String::new(),
                };
                self.error(AnalysisError::Ambiguous {
                    span,
                    name,
                    count: chosen.len(),
                    help: help.into(),
                });
            }
            for a in args {
                self.assoc_any(a);
            }
        }
    }
}

/// An association's formal part and its actual expression (`None` for `open` or a range).
fn formal_and_actual(a: &Assoc) -> (Option<Formal<'_>>, Option<&Expr>) {
    let formal = a.formal.as_ref().map(|f| match &f.kind {
        ExprKind::Name(id) => Formal::Whole(&id.name),
        ExprKind::Apply(p, _) => match &p.kind {
            ExprKind::Name(id) => Formal::Part(&id.name),
            _ => Formal::Other,
        },
        _ => Formal::Other,
    });
    let actual = match &a.actual {
        Actual::Expr(x) => Some(x),
        _ => None,
    };
    (formal, actual)
}

fn unary_name(op: UnaryOp) -> &'static str {
    match op {
        UnaryOp::Plus => "+",
        UnaryOp::Minus => "-",
        UnaryOp::Abs => "abs",
        UnaryOp::Not => "not",
    }
}

fn binary_name(op: BinaryOp) -> &'static str {
    use BinaryOp::*;
    match op {
        And => "and",
        Or => "or",
        Nand => "nand",
        Nor => "nor",
        Xor => "xor",
        Xnor => "xnor",
        Eq => "=",
        Ne => "/=",
        Lt => "<",
        Le => "<=",
        Gt => ">",
        Ge => ">=",
        Sll => "sll",
        Srl => "srl",
        Sla => "sla",
        Sra => "sra",
        Rol => "rol",
        Ror => "ror",
        Add => "+",
        Sub => "-",
        Concat => "&",
        Mul => "*",
        Div => "/",
        Mod => "mod",
        Rem => "rem",
        Pow => "**",
    }
}
