//! Declarations: objects, types and subtypes, natures, terminals and quantities,
//! subprograms (a body analysed in its own region), components, aliases and attributes.

use vams_syntax::ast::{
    Decl, DeclKind as AstDecl, DiscreteRange, EnumLiteral, IndexDef, InterfaceDecl, NatureDef,
    ObjectClass, QuantityDecl, Range, SubprogramSpec, SubtypeIndication, TypeDef,
};
use vams_syntax::ast::{Designator, Expr, ExprKind, Ident};

use super::AnalysisError;
use super::scope::{
    DeclId, DeclKind, InterfaceRole, Nature, NatureId, Param, Purity, Signature, Staticness,
    same_profile,
};
use super::types::{TypeId, TypeKind, UNKNOWN};
use super::units::Analyzer;

impl Analyzer<'_> {
    pub fn decls(&mut self, decls: &[Decl]) {
        for d in decls {
            self.decl(d);
        }
    }

    fn decl(&mut self, d: &Decl) {
        match &d.kind {
            AstDecl::Constant {
                names,
                subtype,
                value,
            } => self.objects(ObjectClass::Constant, names, subtype, value.as_ref()),
            AstDecl::Signal {
                names,
                subtype,
                value,
                ..
            } => self.objects(ObjectClass::Signal, names, subtype, value.as_ref()),
            AstDecl::Variable {
                names,
                subtype,
                value,
                ..
            } => self.objects(ObjectClass::Variable, names, subtype, value.as_ref()),
            AstDecl::File {
                names,
                subtype,
                open_kind,
                logical_name,
            } => {
                let ty = self.subtype(subtype);
                for e in open_kind.iter() {
                    self.expr_any(e);
                }
                if let Some(e) = logical_name {
                    let string = self.std.string;
                    self.expr(e, string);
                }
                self.declare_objects(names, ObjectClass::File, ty, Staticness::None);
            }
            AstDecl::Type { name, def } => self.type_decl(name, def.as_ref()),
            AstDecl::ProtectedBody { name, decls } => self.protected_body(name, decls),
            AstDecl::Subtype { name, subtype } => {
                let ty = self.subtype(subtype);
                self.declare(&name.name, name.span, DeclKind::Type(ty));
            }
            AstDecl::Nature { name, def } => {
                let nature = match def {
                    NatureDef::Scalar {
                        across,
                        through,
                        reference,
                    } => {
                        let across = self.type_mark(across);
                        let through = self.type_mark(through);
                        let n = self.add_nature(&name.name, across, through);
                        if let Some(reference) = reference {
                            self.declare(&reference.name, reference.span, DeclKind::Terminal(n));
                        }
                        n
                    }
                    NatureDef::Array { indexes, element } => {
                        for i in indexes {
                            self.index_def(i);
                        }
                        self.nature_mark(&element.type_mark);
                        self.add_nature(&name.name, UNKNOWN, UNKNOWN)
                    }
                    NatureDef::Record(fields) => {
                        for f in fields {
                            self.nature_mark(&f.subtype.type_mark);
                        }
                        self.add_nature(&name.name, UNKNOWN, UNKNOWN)
                    }
                };
                self.declare(&name.name, name.span, DeclKind::Nature(nature));
            }
            AstDecl::Subnature {
                name,
                nature,
                through_tolerance,
            } => {
                let n = self.nature_mark(&nature.type_mark);
                let string = self.std.string;
                for group in nature.tolerance.iter().chain(through_tolerance) {
                    self.expr(group, string);
                }
                let kind = match n {
                    Some(n) => DeclKind::Nature(n),
                    None => DeclKind::Opaque,
                };
                self.declare(&name.name, name.span, kind);
            }
            AstDecl::Terminal { names, nature } => {
                let kind = match self.nature_mark(&nature.type_mark) {
                    Some(n) => DeclKind::Terminal(n),
                    None => DeclKind::Opaque,
                };
                for n in names {
                    self.declare(&n.name, n.span, kind.clone());
                }
            }
            AstDecl::Quantity(q) => self.quantity(q),
            AstDecl::Alias {
                name,
                target,
                signature: Some(signature),
                ..
            } => self.overload_alias(name, target, signature),
            AstDecl::Alias {
                name,
                subtype,
                target,
                signature: None,
            } => {
                // An alias of a type is that type, and declares aliases of its enumeration
                // literals right after it (LRM 4.3.3.2): `alias status is work.t.state;`
                // makes `idle` visible.
                if subtype.is_none()
                    && let ExprKind::Name(_) | ExprKind::Selected(..) = &target.kind
                    && let Some([d]) = self.resolve_name(target).as_deref()
                    && let DeclKind::Type(t) = self.out.decl(*d).kind
                {
                    self.declare(&name.name, name.span, DeclKind::Type(t));
                    let region = *self.scope.last().expect("a unit always has a region");
                    // Its literals and predefined operators (LRM 4.3.3.2).
                    let literals: Vec<(String, DeclId)> = (self.out.decls.iter().enumerate())
                        .filter(|(_, decl)| match &decl.kind {
                            DeclKind::EnumLiteral(u) => *u == t,
                            DeclKind::Subprogram(sig) => {
                                sig.purity == Purity::Predefined
                                    && (sig.result == Some(t)
                                        || sig.params.iter().any(|p| p.ty == t))
                            }
                            _ => false,
                        })
                        .map(|(i, decl)| (decl.name.clone(), DeclId(i as u32)))
                        .collect();
                    for (lit, id) in literals {
                        self.out.regions[region.0 as usize].add(&lit, id);
                    }
                    return;
                }
                let ty = match subtype {
                    Some(s) => {
                        let ty = self.subtype(s);
                        self.expr_any(target);
                        ty
                    }
                    None => self.alias_target(target),
                };
                self.declare(&name.name, name.span, DeclKind::Alias(ty));
            }
            AstDecl::Attribute { name, type_mark } => {
                let ty = self.type_mark(type_mark);
                self.declare(&name.name, name.span, DeclKind::Attribute(ty));
            }
            AstDecl::AttributeSpec {
                attribute,
                entities,
                value,
                ..
            } => {
                // The named entities are declared in this declarative part (LRM 5.1); a name
                // not found here (a label, a unit) is left unresolved, not reported.
                if let vams_syntax::ast::EntityNames::List(names) = entities {
                    let region = *self.scope.last().expect("a unit always has a region");
                    for n in names {
                        match &n.kind {
                            ExprKind::Name(id) => {
                                if let Some([d]) = self.lookup_in(region, &id.name).as_deref() {
                                    self.reference(id.span, *d);
                                }
                            }
                            ExprKind::Signed(name, signature) => {
                                self.signed_name(name, signature);
                            }
                            _ => {}
                        }
                    }
                }
                let ty = match self.lookup(&attribute.name).as_deref() {
                    Some([d]) => match self.out.decl(*d).kind {
                        DeclKind::Attribute(t) => {
                            self.reference(attribute.span, *d);
                            t
                        }
                        _ => UNKNOWN,
                    },
                    Some(_) => UNKNOWN,
                    None => {
                        self.undeclared(attribute);
                        UNKNOWN
                    }
                };
                self.expr(value, ty);
            }
            AstDecl::Component {
                name,
                generics,
                ports,
            } => {
                let region = self.new_region();
                self.declare(&name.name, name.span, DeclKind::Component(region));
                self.scope.push(region);
                self.interfaces(generics, InterfaceRole::Generic);
                self.interfaces(ports, InterfaceRole::Port);
                self.scope.pop();
            }
            AstDecl::Subprogram(spec) => {
                self.subprogram_spec(spec);
            }
            AstDecl::SubprogramBody { spec, decls, stmts } => {
                let sig = self.subprogram_spec(spec);
                let region = self.new_region();
                self.scope.push(region);
                self.record_scope(d.span);
                for (p, iface) in sig.params.iter().zip(param_names(&spec.params)) {
                    self.declare(
                        &p.name,
                        iface.span,
                        DeclKind::Object {
                            class: p.class,
                            ty: p.ty,
                            value: Staticness::None,
                        },
                    );
                }
                self.returns.push(sig.result);
                self.decls(decls);
                self.seq_stmts(stmts);
                self.returns.pop();
                self.scope.pop();
            }
            AstDecl::Limit {
                quantities,
                type_mark,
                value,
            } => {
                if let vams_syntax::ast::EntityNames::List(names) = quantities {
                    for n in names {
                        self.resolve_name(n);
                    }
                }
                self.type_mark(type_mark);
                let real = self.std.real;
                self.expr(value, real);
            }
            AstDecl::Configuration {
                component, binding, ..
            } => {
                // The component must be visible here, and the entity it is bound to exist.
                let region = match self.resolve_name(component).as_deref() {
                    Some([d]) => match self.out.decl(*d).kind {
                        DeclKind::Component(r) => Some(r),
                        _ => None,
                    },
                    _ => None,
                };
                self.binding_maps(binding, region);
            }
            AstDecl::Disconnect {
                signals,
                type_mark,
                after,
            } => {
                if let vams_syntax::ast::EntityNames::List(names) = signals {
                    for n in names {
                        self.resolve_name(n);
                    }
                }
                self.type_mark(type_mark);
                let time = self.std.time;
                self.expr(after, time);
            }
            AstDecl::Group { name, template } => {
                // A group's constituents are names of this region (LRM 4.7), left unresolved
                // like an attribute specification's; its template is checked.
                let template = template.as_ref().map(|t| match &t.kind {
                    ExprKind::Apply(prefix, _) => &**prefix,
                    _ => t,
                });
                if let Some(t) = template {
                    self.resolve_name(t);
                }
                self.declare(&name.name, name.span, DeclKind::Opaque);
            }
            AstDecl::Use(names) => {
                let region = *self.scope.last().expect("a unit always has a region");
                for n in names {
                    self.use_clause(region, n);
                }
            }
        }
    }

    fn objects(
        &mut self,
        class: ObjectClass,
        names: &[vams_syntax::ast::Ident],
        subtype: &SubtypeIndication,
        value: Option<&Expr>,
    ) {
        let ty = self.subtype(subtype);
        let init = value.map(|v| {
            self.expr(v, ty);
            self.staticness(v)
        });
        // A constant is globally static (a deferred one too), locally static when its value
        // is (LRM 7.4.1 (b), 7.4.2 (b)); other objects' values are the simulation's.
        let value = match (class, init) {
            (ObjectClass::Constant, Some(Staticness::Local)) => Staticness::Local,
            (ObjectClass::Constant, _) => Staticness::Global,
            _ => Staticness::None,
        };
        self.declare_objects(names, class, ty, value);
    }

    fn declare_objects(
        &mut self,
        names: &[vams_syntax::ast::Ident],
        class: ObjectClass,
        ty: TypeId,
        value: Staticness,
    ) {
        for n in names {
            self.declare(&n.name, n.span, DeclKind::Object { class, ty, value });
        }
    }

    fn quantity(&mut self, q: &QuantityDecl) {
        match q {
            QuantityDecl::Free {
                names,
                subtype,
                value,
            } => self.objects(ObjectClass::Quantity, names, subtype, value.as_ref()),
            QuantityDecl::Branch {
                across,
                through,
                plus,
                minus,
            } => {
                let nature = plus.as_ref().and_then(|p| self.terminal_nature(p));
                if let Some(m) = minus {
                    self.terminal_nature(m);
                }
                let (a, t) = match nature {
                    Some(n) => (self.nature(n).across, self.nature(n).through),
                    None => (UNKNOWN, UNKNOWN),
                };
                for (names, ty) in [(across, a), (through, t)] {
                    for b in names {
                        if let Some(v) = &b.value {
                            self.expr(v, ty);
                        }
                        if let Some(tol) = &b.tolerance {
                            let string = self.std.string;
                            self.expr(tol, string);
                        }
                        self.declare_objects(&b.names, ObjectClass::Quantity, ty, Staticness::None);
                    }
                }
            }
            QuantityDecl::Source {
                names,
                subtype,
                spectrum,
                noise,
            } => {
                let ty = self.subtype(subtype);
                if let Some((m, p)) = spectrum {
                    self.expr_any(m);
                    self.expr_any(p);
                }
                if let Some(n) = noise {
                    self.expr_any(n);
                }
                self.declare_objects(names, ObjectClass::Quantity, ty, Staticness::None);
            }
        }
    }

    /// The nature of a terminal name (`p`, `pkg.p`, `t(1)` of an array: unknown).
    fn terminal_nature(&mut self, e: &Expr) -> Option<NatureId> {
        match &e.kind {
            ExprKind::Name(_) | ExprKind::Selected(..) => match self.resolve_name(e)?.as_slice() {
                [d] => match self.out.decl(*d).kind {
                    DeclKind::Terminal(n) => Some(n),
                    _ => None,
                },
                _ => None,
            },
            _ => {
                self.expr_any(e);
                None
            }
        }
    }

    fn add_nature(&mut self, name: &str, across: TypeId, through: TypeId) -> NatureId {
        self.out.natures.push(Nature {
            name: name.to_string(),
            across,
            through,
        });
        NatureId(self.out.natures.len() as u32 - 1)
    }

    /// A nature mark (`electrical`, `electrical_vector(1 to 3)`: unknown for composites).
    fn nature_mark(&mut self, e: &Expr) -> Option<NatureId> {
        match &e.kind {
            ExprKind::Apply(prefix, args) => {
                self.nature_mark(prefix);
                for a in args {
                    self.assoc_any(a);
                }
                None
            }
            _ => match self.resolve_name(e)?.as_slice() {
                [d] => match self.out.decl(*d).kind {
                    DeclKind::Nature(n) => Some(n),
                    _ => None,
                },
                _ => None,
            },
        }
    }

    /// The type an alias without a subtype gets from its target.
    /// An alias of a subprogram or enumeration literal: the overload of the target whose
    /// parameter and result types the signature gives. The alias is declared as what it
    /// denotes (overloadable, with the target's profile), and the target name refers to the
    /// overload chosen, so that elaboration takes that one.
    fn overload_alias(
        &mut self,
        name: &Ident,
        target: &Expr,
        signature: &vams_syntax::ast::Signature,
    ) {
        let params: Vec<TypeId> = signature.params.iter().map(|t| self.type_mark(t)).collect();
        let result = signature.result.as_ref().map(|t| self.type_mark(t));
        let Some(cands) = self.resolve_name(target) else {
            // Reported; its uses are not errors of their own.
            self.declare(&name.name, name.span, DeclKind::Opaque);
            return;
        };
        let fits = |kind: &DeclKind| match kind {
            DeclKind::Subprogram(sig) => {
                sig.result == result
                    && sig.params.len() == params.len()
                    && sig.params.iter().zip(&params).all(|(p, &t)| p.ty == t)
            }
            DeclKind::EnumLiteral(t) => params.is_empty() && result == Some(*t),
            _ => false,
        };
        // `resolve_name` referred the target to its declaration when it had only one.
        let overloaded = cands.len() > 1;
        let chosen: Vec<DeclId> = cands
            .into_iter()
            .filter(|&d| fits(&self.out.decl(d).kind))
            .collect();
        let target_id = match &target.kind {
            ExprKind::Selected(_, s) | ExprKind::Name(s) => Some(s),
            _ => None,
        };
        match chosen.as_slice() {
            [d] => {
                if let Some(id) = target_id.filter(|_| overloaded) {
                    self.reference(id.span, *d);
                }
                let kind = self.out.decl(*d).kind.clone();
                self.declare(&name.name, name.span, kind);
            }
            _ if params
                .iter()
                .chain(&result)
                .all(|&t| self.types().is_known(t)) =>
            {
                let describe = |ts: &[TypeId]| {
                    ts.iter()
                        .map(|&t| self.types().describe(t))
                        .collect::<Vec<_>>()
                        .join(", ")
                };
                let operands = match result {
                    Some(r) => format!("[{} return {}]", describe(&params), describe(&[r])),
                    None => format!("[{}]", describe(&params)),
                };
                self.error(AnalysisError::NoOverload {
                    span: signature.span,
                    name: target_id.map_or_else(String::new, |id| id.name.clone()),
                    operands,
                    help: Some(
                        "no declaration of this name has exactly the signature's parameter and result types".into(),
                    ),
                });
                self.declare(&name.name, name.span, DeclKind::Opaque);
            }
            _ => {
                self.declare(&name.name, name.span, DeclKind::Opaque);
            }
        }
    }

    fn alias_target(&mut self, target: &Expr) -> TypeId {
        if let ExprKind::Name(_) | ExprKind::Selected(..) = &target.kind {
            if let Some(ds) = self.resolve_name(target) {
                return match ds.as_slice() {
                    [d] => match &self.out.decl(*d).kind {
                        DeclKind::Object { ty, .. } | DeclKind::Alias(ty) => *ty,
                        _ => UNKNOWN,
                    },
                    _ => UNKNOWN,
                };
            }
            return UNKNOWN;
        }
        self.expr_any(target)
    }

    // -----------------------------------------------------------------------------------
    // Types

    /// The base type of a subtype indication; constraints and tolerances are checked.
    pub fn subtype(&mut self, s: &SubtypeIndication) -> TypeId {
        if let Some(r) = &s.resolution {
            if let ExprKind::Name(_) | ExprKind::Selected(..) = r.kind {
                self.resolve_name(r);
            }
        }
        let ty = self.type_mark(&s.type_mark);
        if let Some(r) = &s.range {
            self.range(r, ty);
        }
        if let Some(t) = &s.tolerance {
            let string = self.std.string;
            self.expr(t, string);
        }
        ty
    }

    /// The type a type mark denotes; an index constraint (`real_vector(1 to 3)`) is checked
    /// against the type's index types.
    pub fn type_mark(&mut self, e: &Expr) -> TypeId {
        match &e.kind {
            ExprKind::Apply(prefix, args) => {
                let ty = self.type_mark(prefix);
                let indexes = match self.types().kind(ty) {
                    TypeKind::Array { indexes, .. } => indexes.clone(),
                    _ => Vec::new(),
                };
                for (i, a) in args.iter().enumerate() {
                    let index = indexes.get(i).copied().unwrap_or(UNKNOWN);
                    match &a.actual {
                        vams_syntax::ast::Actual::Range(r) => {
                            self.range(r, index);
                        }
                        // `natural range 0 to 3` arrives as a subtype name: a type mark.
                        vams_syntax::ast::Actual::Expr(x) if self.is_type_mark(x) => {
                            self.type_mark(x);
                        }
                        vams_syntax::ast::Actual::Expr(x) => {
                            self.expr(x, index);
                        }
                        vams_syntax::ast::Actual::Open(_) => {}
                    }
                }
                ty
            }
            ExprKind::Attribute(prefix, attr) => {
                // `q'across`, `n'through`, `t'base`: the type the attribute names.
                match attr.name.as_str() {
                    "across" | "through" => match self.nature_mark(prefix) {
                        Some(n) if attr.name == "across" => self.nature(n).across,
                        Some(n) => self.nature(n).through,
                        None => UNKNOWN,
                    },
                    "base" => self.type_mark(prefix),
                    _ => {
                        self.expr_any(e);
                        UNKNOWN
                    }
                }
            }
            ExprKind::Name(_) | ExprKind::Selected(..) => match self.resolve_name(e) {
                Some(ds) => match ds.as_slice() {
                    [d] => match self.out.decl(*d).kind {
                        DeclKind::Type(t) => t,
                        _ => UNKNOWN,
                    },
                    _ => UNKNOWN,
                },
                None => UNKNOWN,
            },
            _ => {
                self.expr_any(e);
                UNKNOWN
            }
        }
    }

    /// True when `e` names a type (without reporting anything).
    pub fn is_type_mark(&self, e: &Expr) -> bool {
        match &e.kind {
            ExprKind::Name(id) => self.lookup(&id.name).is_some_and(|ds| {
                ds.len() == 1 && matches!(self.out.decl(ds[0]).kind, DeclKind::Type(_))
            }),
            ExprKind::Selected(..) => self.peek_name(e).is_some_and(|ds| {
                ds.len() == 1 && matches!(self.out.decl(ds[0]).kind, DeclKind::Type(_))
            }),
            _ => false,
        }
    }

    /// Checks a range's bounds against `ty` (unknown: the bounds decide it); returns the
    /// range's type.
    pub fn range(&mut self, r: &Range, ty: TypeId) -> TypeId {
        match r {
            Range::Explicit { left, right, .. } => {
                let ty = if self.types().is_known(ty) {
                    ty
                } else {
                    self.bounds_type(left, right)
                };
                self.expr(left, ty);
                self.expr(right, ty);
                ty
            }
            Range::Attribute(e) => {
                let t = self.range_attribute(e);
                if self.types().is_known(ty) { ty } else { t }
            }
        }
    }

    /// The type of a range `l to r` from its bounds alone: the one known type among their
    /// interpretations, `integer` for two universal integers (the LRM's rule for a loop or
    /// index range), `real` for two universal reals.
    fn bounds_type(&mut self, left: &Expr, right: &Expr) -> TypeId {
        let l = self.infer(left);
        let r = self.infer(right);
        let types = self.types();
        if let Some(t) = types
            .single_definite(&l)
            .or_else(|| types.single_definite(&r))
        {
            return t;
        }
        let universal = |set: &[TypeId], u: TypeId| set == [u];
        if universal(&l, super::types::UNIVERSAL_INTEGER)
            && universal(&r, super::types::UNIVERSAL_INTEGER)
        {
            return self.std.integer;
        }
        if universal(&l, super::types::UNIVERSAL_REAL)
            && universal(&r, super::types::UNIVERSAL_REAL)
        {
            return self.std.real;
        }
        UNKNOWN
    }

    /// The type of a discrete range (a loop's or a generate's parameter).
    pub fn discrete_range(&mut self, r: &DiscreteRange) -> TypeId {
        match r {
            DiscreteRange::Range(r) => self.range(r, UNKNOWN),
            DiscreteRange::Subtype(s) => self.subtype(s),
        }
    }

    fn index_def(&mut self, i: &IndexDef) -> TypeId {
        match i {
            IndexDef::Unconstrained(mark) => self.type_mark(mark),
            IndexDef::Constrained(r) => self.discrete_range(r),
        }
    }

    fn type_decl(&mut self, name: &vams_syntax::ast::Ident, def: Option<&TypeDef>) {
        // A full declaration completes an incomplete one of the same region.
        let incomplete = self
            .scope
            .last()
            .and_then(|r| self.lookup_in(*r, &name.name))
            .and_then(|ds| {
                ds.iter().find_map(|&d| match self.out.decl(d).kind {
                    DeclKind::Type(t) if *self.types().kind(t) == TypeKind::Incomplete => Some(t),
                    _ => None,
                })
            });
        let Some(def) = def else {
            let t = self.out.types.add(&name.name, TypeKind::Incomplete);
            self.declare(&name.name, name.span, DeclKind::Type(t));
            return;
        };
        let ty = match incomplete {
            Some(t) => t,
            None => {
                let t = self.out.types.add(&name.name, TypeKind::Incomplete);
                self.declare(&name.name, name.span, DeclKind::Type(t));
                t
            }
        };
        let kind = match def {
            TypeDef::Enumeration(literals) => {
                let mut chars = false;
                for l in literals {
                    let (n, span) = match l {
                        EnumLiteral::Ident(id) => (id.name.clone(), id.span),
                        EnumLiteral::Char(c, span) => {
                            chars = true;
                            (format!("'{c}'"), *span)
                        }
                    };
                    self.declare(&n, span, DeclKind::EnumLiteral(ty));
                }
                TypeKind::Enum { chars }
            }
            TypeDef::Range(r) => {
                let (l, rr) = match r {
                    Range::Explicit { left, right, .. } => (self.infer(left), self.infer(right)),
                    Range::Attribute(_) => (vec![UNKNOWN], vec![UNKNOWN]),
                };
                let real = |s: &[TypeId]| {
                    s.iter().any(|&t| {
                        matches!(
                            self.types().kind(t),
                            TypeKind::UniversalReal | TypeKind::Real
                        )
                    })
                };
                let kind = if real(&l) || real(&rr) {
                    TypeKind::Real
                } else {
                    TypeKind::Integer
                };
                self.range(r, UNKNOWN);
                kind
            }
            TypeDef::Physical {
                range,
                primary,
                secondary,
            } => {
                self.range(range, UNKNOWN);
                self.out.types.complete(ty, TypeKind::Physical);
                self.declare(&primary.name, primary.span, DeclKind::Unit(ty));
                for (unit, value) in secondary {
                    self.expr(value, ty);
                    self.declare(&unit.name, unit.span, DeclKind::Unit(ty));
                }
                TypeKind::Physical
            }
            TypeDef::Array { indexes, element } => {
                let indexes = indexes.iter().map(|i| self.index_def(i)).collect();
                let element = self.subtype(element);
                TypeKind::Array { indexes, element }
            }
            TypeDef::Record(fields) => {
                let mut out = Vec::new();
                for f in fields {
                    let t = self.subtype(&f.subtype);
                    for n in &f.names {
                        out.push((n.name.clone(), t));
                    }
                }
                TypeKind::Record { fields: out }
            }
            TypeDef::Access(s) => TypeKind::Access(self.subtype(s)),
            TypeDef::File(mark) => TypeKind::File(self.type_mark(mark)),
            TypeDef::Protected(methods) => {
                // The methods see the declarations around the type (and each other).
                let region = self.new_region();
                self.scope.push(region);
                self.decls(methods);
                self.scope.pop();
                TypeKind::Protected(region)
            }
        };
        self.out.types.complete(ty, kind);
        self.implicit_operators(ty, name.span);
    }

    // -----------------------------------------------------------------------------------
    // Interfaces and subprograms

    pub fn interfaces(&mut self, list: &[InterfaceDecl], role: InterfaceRole) -> Vec<Param> {
        let mut params = Vec::new();
        for i in list {
            let class = i.class.unwrap_or(match role {
                InterfaceRole::Generic => ObjectClass::Constant,
                InterfaceRole::Port => ObjectClass::Signal,
                InterfaceRole::Parameter => match i.mode {
                    Some(vams_syntax::ast::Mode::Out | vams_syntax::ast::Mode::Inout) => {
                        ObjectClass::Variable
                    }
                    _ => ObjectClass::Constant,
                },
            });
            if class == ObjectClass::Terminal {
                let kind = match self.nature_mark(&i.subtype.type_mark) {
                    Some(n) => DeclKind::Terminal(n),
                    None => DeclKind::Opaque,
                };
                for n in &i.names {
                    if role != InterfaceRole::Parameter {
                        self.declare(&n.name, n.span, kind.clone());
                    }
                    params.push(Param {
                        name: n.name.clone(),
                        class,
                        ty: UNKNOWN,
                        has_default: false,
                    });
                }
                continue;
            }
            let ty = self.subtype(&i.subtype);
            if let Some(d) = &i.default {
                self.expr(d, ty);
            }
            for n in &i.names {
                // Parameters are declared in the body's region, not where the spec is.
                if role != InterfaceRole::Parameter {
                    // A generic is globally static; a port is a signal or a quantity.
                    let value = match role {
                        InterfaceRole::Generic => Staticness::Global,
                        _ => Staticness::None,
                    };
                    self.declare(&n.name, n.span, DeclKind::Object { class, ty, value });
                }
                params.push(Param {
                    name: n.name.clone(),
                    class,
                    ty,
                    has_default: i.default.is_some(),
                });
            }
        }
        params
    }

    /// Declares a subprogram (once: a body completing a declaration of the same region
    /// adds nothing) and returns its signature.
    fn subprogram_spec(&mut self, spec: &SubprogramSpec) -> Signature {
        let params = self.interfaces(&spec.params, InterfaceRole::Parameter);
        let result = spec.return_type.as_ref().map(|r| self.type_mark(r));
        let purity = if spec.is_function && spec.pure {
            Purity::Pure
        } else {
            Purity::Impure
        };
        let sig = Signature {
            params,
            result,
            purity,
        };
        let (name, span) = match &spec.designator {
            Designator::Ident(id) => (id.name.clone(), id.span),
            Designator::Operator(op, span) => (format!("\"{op}\""), *span),
        };
        let region = *self.scope.last().expect("a unit always has a region");
        // A declaration completed by this body; an implicit operator of the same profile is
        // not one: the explicit declaration hides it (LRM 10.3, numeric_std's `"<"` on
        // `unsigned`).
        let existing: Option<DeclId> = self.lookup_in(region, &name).and_then(|ds| {
            ds.into_iter().find(|&d| match &self.out.decl(d).kind {
                DeclKind::Subprogram(s) => s.purity != Purity::Predefined && same_profile(s, &sig),
                _ => false,
            })
        });
        if existing.is_none() {
            let implicit: Vec<DeclId> = (self.lookup_in(region, &name).unwrap_or_default())
                .into_iter()
                .filter(|&d| {
                    matches!(&self.out.decl(d).kind,
                        DeclKind::Subprogram(s) if s.purity == Purity::Predefined && same_profile(s, &sig))
                })
                .collect();
            if !implicit.is_empty()
                && let Some(ds) = self.out.regions[region.0 as usize].names.get_mut(&name)
            {
                ds.retain(|d| !implicit.contains(d));
            }
        }
        match existing {
            Some(d) => self.reference(span, d),
            None => {
                // A package body completes its package's declaration (another region).
                let declared = self.lookup(&name).and_then(|ds| {
                    ds.into_iter().find(|&d| match &self.out.decl(d).kind {
                        DeclKind::Subprogram(s) => {
                            same_profile(s, &sig) && self.out.decl(d).span.file == span.file
                        }
                        _ => false,
                    })
                });
                match declared {
                    Some(d) if self.completes_package(d) => self.reference(span, d),
                    _ => {
                        self.declare(&name, span, DeclKind::Subprogram(sig.clone()));
                    }
                }
            }
        }
        sig
    }

    /// `type t is protected body ... end protected body;`: private declarations and method
    /// bodies in a region inside the type's methods, so that each body completes its method
    /// and every method sees the others.
    fn protected_body(&mut self, name: &vams_syntax::ast::Ident, decls: &[Decl]) {
        let methods = self.lookup(&name.name).and_then(|ds| {
            ds.into_iter().find_map(|d| match &self.out.decl(d).kind {
                DeclKind::Type(t) => match self.types().kind(*t) {
                    TypeKind::Protected(r) => Some((d, *r)),
                    _ => None,
                },
                _ => None,
            })
        });
        let Some((decl, methods)) = methods else {
            self.undeclared(name);
            return;
        };
        self.reference(name.span, decl);
        let saved = self.protected_methods.replace(methods);
        self.scope.push(methods);
        let private = self.new_region();
        self.scope.push(private);
        self.decls(decls);
        self.scope.pop();
        self.scope.pop();
        self.protected_methods = saved;
    }

    /// True when `d` is declared in the package this unit is the body of, or is a method of
    /// the protected type whose body is being analysed.
    fn completes_package(&self, d: DeclId) -> bool {
        if let Some(r) = self.protected_methods
            && self.out.regions[r.0 as usize]
                .names
                .values()
                .any(|ds| ds.contains(&d))
        {
            return true;
        }
        self.scope.len() >= 2
            && matches!(self.out.units[self.cur].kind, super::UnitKind::PackageBody)
            && self.out.regions[self.scope[1].0 as usize]
                .names
                .values()
                .any(|ds| ds.contains(&d))
    }
}

/// The interface declaration of each parameter name, in order.
fn param_names(params: &[InterfaceDecl]) -> impl Iterator<Item = &vams_syntax::ast::Ident> {
    params.iter().flat_map(|p| p.names.iter())
}
