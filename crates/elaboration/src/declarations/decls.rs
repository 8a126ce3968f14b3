//! Declarations: types, subtypes, constants, signals, aliases, attribute specifications,
//! components and subprogram declarations; natures, terminals and quantities are in `analog`.

use std::rc::Rc;

use vams_design::{Builtin, GuardedKind, Signal, SignalId, SignalKind, Value};
use vams_syntax::ast::{
    self, Decl, DeclKind, Designator, EntityNames, EnumLiteral, IndexDef, SubprogramSpec, TypeDef,
};

use crate::error::ElabError;
use crate::expressions::expr::constrain;
use crate::names::scope::{IoNative, Item, Native, Scope};
use crate::names::types::{ArrayTy, EnumTy, RecordTy, Sub, Ty, position};
use crate::{Elab, R};

/// The name a subprogram is declared under (`sqrt`, `"and"`).
pub(crate) fn designator(spec: &SubprogramSpec) -> String {
    match &spec.designator {
        Designator::Ident(id) => id.name.clone(),
        Designator::Operator(op, _) => format!("\"{op}\""),
    }
}

/// The names a declaration declares (for poisoning them when it fails).
fn declared_names(d: &Decl) -> Vec<&str> {
    match &d.kind {
        DeclKind::Constant { names, .. }
        | DeclKind::Signal { names, .. }
        | DeclKind::Variable { names, .. }
        | DeclKind::File { names, .. }
        | DeclKind::Terminal { names, .. } => names.iter().map(|n| n.name.as_str()).collect(),
        DeclKind::Type { name, .. }
        | DeclKind::Subtype { name, .. }
        | DeclKind::Nature { name, .. }
        | DeclKind::Subnature { name, .. }
        | DeclKind::Alias { name, .. }
        | DeclKind::Attribute { name, .. }
        | DeclKind::Group { name, .. }
        | DeclKind::Component { name, .. } => vec![name.name.as_str()],
        DeclKind::Quantity(q) => match q {
            ast::QuantityDecl::Free { names, .. } | ast::QuantityDecl::Source { names, .. } => {
                names.iter().map(|n| n.name.as_str()).collect()
            }
            ast::QuantityDecl::Branch {
                across, through, ..
            } => across
                .iter()
                .chain(through)
                .flat_map(|b| b.names.iter().map(|n| n.name.as_str()))
                .collect(),
        },
        _ => Vec::new(),
    }
}

/// Maps a bodiless stdlib subprogram to its native implementation.
pub(crate) fn native(name: &str, arity: usize, is_function: bool) -> Native {
    use Builtin::*;
    let b = match (name, arity) {
        ("now", 0) => return Native::Now,
        ("frequency", 0) if is_function => return Native::Frequency,
        ("stop", _) if !is_function => return Native::Stop,
        ("finish", _) if !is_function => return Native::Finish,
        ("log2", 1) => return Native::Log2,
        ("log", 2) => return Native::LogBase,
        ("\"**\"", 2) => return Native::Pow,
        ("readline", 2) if !is_function => return Native::Io(IoNative::ReadLine),
        ("writeline", 2) if !is_function => return Native::Io(IoNative::WriteLine),
        ("read", 2 | 3) if !is_function => return Native::Io(IoNative::Read),
        ("write", 4 | 5) if !is_function => return Native::Io(IoNative::Write),
        ("hread", 2 | 3) if !is_function => return Native::Io(IoNative::HRead),
        ("oread", 2 | 3) if !is_function => return Native::Io(IoNative::ORead),
        ("hwrite", 4) if !is_function => return Native::Io(IoNative::HWrite),
        ("owrite", 4) if !is_function => return Native::Io(IoNative::OWrite),
        ("exp", 1) => Exp,
        ("log", 1) => Log,
        ("log10", 1) => Log10,
        ("sqrt", 1) => Sqrt,
        ("sin", 1) => Sin,
        ("cos", 1) => Cos,
        ("tan", 1) => Tan,
        ("arcsin", 1) => Asin,
        ("arccos", 1) => Acos,
        ("arctan", 1) => Atan,
        ("arctan", 2) => Atan2,
        ("sinh", 1) => Sinh,
        ("cosh", 1) => Cosh,
        ("tanh", 1) => Tanh,
        ("arcsinh", 1) => Asinh,
        ("arccosh", 1) => Acosh,
        ("arctanh", 1) => Atanh,
        ("floor", 1) => Floor,
        ("ceil", 1) => Ceil,
        ("round", 1) => Round,
        ("trunc", 1) => Trunc,
        ("sign", 1) => Sign,
        ("realmax", 2) => Realmax,
        ("realmin", 2) => Realmin,
        ("pwl", 2) => Pwl,
        _ => return Native::Missing,
    };
    Native::Builtin(b)
}

impl<'a> Elab<'a> {
    pub(crate) fn decls(&mut self, sc: &mut Scope<'a>, decls: &'a [Decl]) {
        for d in decls {
            self.decl(sc, d);
        }
    }

    /// One declaration; on failure its names are poisoned so that later uses do not cascade
    /// (in the stdlib, silently: the error is reported where a model uses the name).
    pub(crate) fn decl(&mut self, sc: &mut Scope<'a>, d: &'a Decl) {
        let before = self.errors.len();
        let failed = self.decl_inner(sc, d).is_err();
        if !failed && self.errors.len() == before {
            return;
        }
        let reason: Option<Rc<str>> = if self.quiet {
            let r = self
                .errors
                .get(before)
                .map(|e| e.to_string())
                .unwrap_or_else(|| "not supported".into());
            self.errors.truncate(before);
            Some(r.into())
        } else {
            None
        };
        for n in declared_names(d) {
            let declared_here = sc.regions.last().is_some_and(|r| r.items.contains_key(n));
            if !declared_here {
                sc.declare(n, Item::Poison(reason.clone()));
            }
        }
    }

    pub(crate) fn declare(
        &mut self,
        sc: &mut Scope<'a>,
        name: &ast::Ident,
        item: Item<'a>,
    ) -> R<()> {
        if sc.declare_at(&name.name, name.span, item) {
            Ok(())
        } else {
            Err(self.error(ElabError::Redeclared {
                span: name.span,
                name: name.name.clone(),
            }))
        }
    }

    fn decl_inner(&mut self, sc: &mut Scope<'a>, d: &'a Decl) -> R<()> {
        match &d.kind {
            DeclKind::Constant {
                names,
                subtype,
                value,
            } => {
                let sub = self.subtype_indication(sc, subtype)?;
                let Some(value) = value else {
                    for n in names {
                        let reason = format!(
                            "deferred constant `{}` has no value in the package body",
                            n.name
                        );
                        sc.declare_at(&n.name, n.span, Item::Poison(Some(reason.into())));
                    }
                    return Ok(());
                };
                let v = self.static_value(sc, value, &sub.ty, "the value of a constant")?;
                self.check_initial(&sub, &v, value.span)?;
                let ty = fit_array(&sub.ty, &v);
                for n in names {
                    self.declare(
                        sc,
                        n,
                        Item::Constant {
                            value: v.clone(),
                            ty: ty.clone(),
                        },
                    )?;
                }
                Ok(())
            }
            DeclKind::Signal {
                names,
                subtype,
                value,
                guarded,
            } => {
                let sub = self.subtype_indication(sc, subtype)?;
                let init = match value {
                    Some(v) => {
                        let init =
                            self.static_value(sc, v, &sub.ty, "the initial value of a signal")?;
                        self.check_initial(&sub, &init, v.span)?;
                        init
                    }
                    None => default_value(&sub),
                };
                if guarded.is_some() && sub.resolution.is_none() && !is_std_logic(&sub.ty) {
                    return Err(self.error(ElabError::invalid(
                        subtype.span,
                        "a guarded signal (`bus` or `register`) must be of a resolved subtype",
                        Some("name a resolution function: `signal s : wired_or bit bus;`, or declare `subtype t is wired_or bit;`".into()),
                    )));
                }
                for n in names {
                    let id = self.new_signal(&n.name, &sub, init.clone(), n.span);
                    self.design.signals[id.index()].guarded = guarded.map(|g| match g {
                        ast::GuardedKind::Bus => GuardedKind::Bus,
                        ast::GuardedKind::Register => GuardedKind::Register,
                    });
                    self.declare(
                        sc,
                        n,
                        Item::Signal {
                            id,
                            ty: sub.ty.clone(),
                        },
                    )?;
                }
                Ok(())
            }
            DeclKind::Variable {
                names,
                subtype,
                value,
                ..
            } => self.shared_variable(sc, names, subtype, value.as_ref(), d.span),
            DeclKind::ProtectedBody { name, decls } => self.protected_body(sc, name, decls),
            DeclKind::File {
                names,
                subtype,
                open_kind,
                logical_name,
            } => self.file_decl(
                sc,
                names,
                subtype,
                open_kind.as_ref(),
                logical_name.as_ref(),
            ),
            DeclKind::Type { name, def } => match def {
                // Completed by a later declaration of the same name; access types declared
                // in between designate it (see `Elab::incomplete`).
                None => {
                    self.pending
                        .incomplete
                        .push((name.name.clone(), name.span, Vec::new()));
                    Ok(())
                }
                Some(def) => {
                    self.type_decl(sc, name, def, d)?;
                    self.complete(sc, name);
                    Ok(())
                }
            },
            DeclKind::Subtype { name, subtype } => {
                let mut sub = (*self.subtype_indication(sc, subtype)?).clone();
                sub.name = name.name.as_str().into();
                self.declare(sc, name, Item::Type(Rc::new(sub)))
            }
            DeclKind::Nature { name, def } => self.nature_decl(sc, name, def, d.span),
            DeclKind::Subnature {
                name,
                nature,
                through_tolerance,
            } => self.subnature_decl(sc, name, nature, through_tolerance.as_ref()),
            DeclKind::Terminal { names, nature } => self.terminal_decl(sc, names, nature),
            DeclKind::Quantity(q) => self.quantity_decl(sc, q, d.span),
            DeclKind::Alias {
                name,
                subtype,
                target,
                signature: _,
            } => {
                let mut items = self.lookup(sc, target)?;
                if let Some(si) = subtype {
                    // `alias lv : std_logic_vector(1 to l'length) is l;`: the same object
                    // seen with the alias's bounds (values are positional).
                    let sub = self.subtype_indication(sc, si)?;
                    for item in &mut items {
                        self.retype_alias(item, &sub.ty, si.span)?;
                    }
                }
                let operator = matches!(&target.kind,
                    ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id) if id.name.starts_with('"'));
                if operator && !matches!(items.first(), Some(Item::Subprogram(_))) {
                    // A predefined operator has no subprogram to alias: the alias stands for
                    // its symbol, which the operator applications and calls it names lower.
                    let (ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id)) = &target.kind
                    else {
                        return Err(crate::Reported);
                    };
                    let symbol = id.name.trim_matches('"');
                    items = vec![Item::OperatorAlias(symbol.into())];
                }
                for item in items {
                    if !sc.declare_at(&name.name, name.span, item) {
                        return Err(self.error(ElabError::Redeclared {
                            span: name.span,
                            name: name.name.clone(),
                        }));
                    }
                }
                Ok(())
            }
            DeclKind::Attribute { name, type_mark } => {
                let sub = self.type_mark(sc, type_mark)?;
                self.declare(sc, name, Item::Attribute(sub))
            }
            // Groups only carry user attributes, which the simulator does not read.
            DeclKind::Group { .. } => Ok(()),
            DeclKind::Disconnect {
                signals,
                type_mark,
                after,
            } => {
                let Value::Time(delay) =
                    self.static_value(sc, after, &Ty::Time, "a disconnection delay")?
                else {
                    return Err(crate::Reported);
                };
                let names = match signals {
                    ast::EntityNames::List(names) => names,
                    // The guarded signals of the type declared in this region so far (the
                    // specification follows their declarations, LRM 5.3); `others`: those
                    // without a specification of their own.
                    all_or_others => {
                        let ty = self.type_mark(sc, type_mark)?.ty.to_design();
                        let prefix = self.hier_name("");
                        for (k, s) in self.design.signals.iter().enumerate() {
                            let here = s
                                .name
                                .strip_prefix(prefix.as_str())
                                .is_some_and(|n| !n.contains('.'));
                            let id = SignalId(k as u32);
                            if here
                                && s.guarded.is_some()
                                && s.ty == ty
                                && s.kind == SignalKind::Explicit
                                && (matches!(all_or_others, ast::EntityNames::All)
                                    || !self.signals.disconnect_delays.contains_key(&id))
                            {
                                self.signals.disconnect_delays.insert(id, delay);
                            }
                        }
                        return Ok(());
                    }
                };
                for n in names {
                    let items = self.lookup(sc, n)?;
                    match items.first() {
                        Some(Item::Signal { id, .. }) if self.is_guarded(*id) => {
                            self.signals.disconnect_delays.insert(*id, delay);
                        }
                        _ => {
                            return Err(self.error(ElabError::invalid(
                                n.span,
                                "a disconnection specification names guarded signals (`bus` or `register`)",
                                None,
                            )));
                        }
                    }
                }
                Ok(())
            }
            DeclKind::AttributeSpec {
                attribute,
                entities,
                class,
                value,
            } => {
                self.attribute_specification(sc, &attribute.name, entities, &class.name, value);
                let EntityNames::List(names) = entities else {
                    return Ok(());
                };
                // `symbol` of a subtype is also the unit of its quantities (`Quantity::unit`).
                if attribute.name != "symbol" {
                    return Ok(());
                }
                let Some(string) = self.standard_type("string") else {
                    return Ok(());
                };
                let Value::String(symbol) =
                    self.static_value(sc, value, &string, "an attribute value")?
                else {
                    return Ok(());
                };
                for n in names {
                    let ast::ExprKind::Name(id) = &n.kind else {
                        continue;
                    };
                    let named = self
                        .analysed
                        .names
                        .get(&id.span)
                        .and_then(|d| sc.declared(*d));
                    if let Some(Item::Type(sub)) = named {
                        let mut s = (**sub).clone();
                        s.unit = Some(symbol.as_str().into());
                        sc.replace(&id.name, vec![Item::Type(Rc::new(s))]);
                    }
                }
                Ok(())
            }
            DeclKind::Component { name, .. } => self.declare(sc, name, Item::Component(d)),
            DeclKind::Subprogram(spec) => self.subprogram_decl(sc, spec, None),
            DeclKind::SubprogramBody { spec, decls, stmts } => {
                self.subprogram_decl(sc, spec, Some((decls, stmts)))
            }
            DeclKind::Limit {
                quantities,
                type_mark,
                value,
            } => self.limit(sc, quantities, type_mark, value),
            DeclKind::Use(names) => {
                for n in names {
                    self.use_clause(sc, n)?;
                }
                Ok(())
            }
            DeclKind::Configuration {
                labels,
                component,
                binding,
            } => {
                let item = Item::Binding(crate::names::scope::BindingRef {
                    component,
                    binding: Some(binding),
                    block: None,
                });
                for key in binding_keys(labels, component) {
                    if !sc.declare(&key, item.clone()) {
                        return Err(self.error(ElabError::invalid(
                            d.span,
                            "this instance is bound by an earlier configuration specification too",
                            Some("give each instance one binding".into()),
                        )));
                    }
                }
                Ok(())
            }
        }
    }

    fn type_decl(
        &mut self,
        sc: &mut Scope<'a>,
        name: &ast::Ident,
        def: &'a TypeDef,
        d: &Decl,
    ) -> R<()> {
        match def {
            TypeDef::Enumeration(lits) => {
                let literals: Vec<String> = lits
                    .iter()
                    .map(|l| match l {
                        EnumLiteral::Ident(id) => id.name.clone(),
                        EnumLiteral::Char(c, _) => format!("'{c}'"),
                    })
                    .collect();
                let ty = if name.name == "boolean" {
                    Ty::Boolean
                } else {
                    Ty::Enum(Rc::new(EnumTy {
                        name: name.name.clone(),
                        literals: literals.clone(),
                    }))
                };
                self.declare(
                    sc,
                    name,
                    Item::Type(Rc::new(Sub::of(ty.clone(), &name.name))),
                )?;
                for (pos, (lit, def)) in literals.iter().zip(lits).enumerate() {
                    let span = match def {
                        EnumLiteral::Ident(id) => id.span,
                        EnumLiteral::Char(_, span) => *span,
                    };
                    let item = Item::EnumLiteral {
                        ty: ty.clone(),
                        pos: pos as u32,
                    };
                    sc.declare_at(lit, span, item);
                }
                Ok(())
            }
            TypeDef::Range(r) => {
                let (l, rr, _) = self.range_exprs(sc, r)?;
                let (Some(lv), Some(rv)) = (l.value().cloned(), rr.value().cloned()) else {
                    return Err(self.error(ElabError::NotStatic {
                        span: d.span,
                        what: "a type's range".into(),
                    }));
                };
                let ty = match lv {
                    Value::Integer(_) => Ty::Integer,
                    Value::Real(_) => Ty::Real,
                    _ => {
                        return Err(self.error(ElabError::invalid(
                            d.span,
                            "a range type needs integer or real bounds",
                            None,
                        )));
                    }
                };
                let mut sub = Sub::of(ty, &name.name);
                // The predefined types keep their full range; user range types are subtypes.
                if name.name != "integer" && name.name != "real" {
                    sub.range = Some((lv, rv));
                }
                self.declare(sc, name, Item::Type(Rc::new(sub)))
            }
            TypeDef::Physical {
                primary, secondary, ..
            } => {
                if name.name != "time" {
                    return self.physical_type(sc, name, d);
                }
                self.declare(sc, name, Item::Type(Rc::new(Sub::of(Ty::Time, "time"))))?;
                sc.declare_at(&primary.name, primary.span, Item::TimeUnit(1.0));
                for (unit, value) in secondary {
                    let Value::Time(s) =
                        self.static_value(sc, value, &Ty::Time, "a unit's value")?
                    else {
                        return Err(crate::Reported);
                    };
                    sc.declare_at(&unit.name, unit.span, Item::TimeUnit((s * 1e15).round()));
                }
                Ok(())
            }
            TypeDef::Array { indexes, element } => {
                let elem = self.subtype_indication(sc, element)?.ty.clone();
                // Each index's bounds (positions), lowest index value and base type.
                let mut dims = Vec::with_capacity(indexes.len());
                for index in indexes {
                    dims.push(match index {
                        IndexDef::Unconstrained(mark) => {
                            let sub = self.type_mark(sc, mark)?;
                            let low = match &sub.range {
                                Some((l, _)) => position(l).unwrap_or(i32::MIN as i64),
                                None if matches!(sub.ty, Ty::Enum(_) | Ty::Boolean) => 0,
                                None => i32::MIN as i64,
                            };
                            (None, low, sub.ty.clone())
                        }
                        IndexDef::Constrained(r) => {
                            let (l, r, asc, ty) = self.discrete_range_typed(sc, r)?;
                            (Some((l, r, asc)), l.min(r), ty)
                        }
                    });
                }
                let bounds: Option<Vec<_>> = dims.iter().map(|d| d.0).collect();
                if let Some(bounds) = bounds {
                    self.array_size(&bounds, d.span)?;
                }
                let ty = array_type(&name.name, dims, elem);
                self.declare(sc, name, Item::Type(Rc::new(Sub::of(ty, &name.name))))
            }
            TypeDef::Record(fields) => {
                let (mut out, mut defaults) = (Vec::new(), Vec::new());
                for f in fields {
                    let sub = self.subtype_indication(sc, &f.subtype)?;
                    let ty = sub.ty.clone();
                    if let Ty::Array(a) = &ty
                        && a.bounds.is_none()
                    {
                        return Err(self.error(ElabError::invalid(
                            f.subtype.span,
                            "a record field needs a constrained subtype",
                            Some(format!("give the bounds: `{}(0 to 7)`", a.name)),
                        )));
                    }
                    for n in &f.names {
                        out.push((n.name.clone(), ty.clone()));
                        defaults.push(default_value(&sub));
                    }
                }
                let ty = Ty::Record(Rc::new(RecordTy {
                    name: name.name.clone(),
                    fields: out,
                    defaults,
                }));
                self.declare(sc, name, Item::Type(Rc::new(Sub::of(ty, &name.name))))
            }
            TypeDef::Access(designated) => self.access_type(sc, name, designated),
            TypeDef::File(mark) => self.file_type(sc, name, mark),
            TypeDef::Protected(methods) => self.protected_type(sc, name, methods),
        }
    }

    /// A physical type of the user's own (LRM 3.1.3): its range in primary units, each
    /// secondary unit's value in primary units (`kohm = 1000 ohm`, `Mohm = 1000 kohm`).
    fn physical_type(&mut self, sc: &mut Scope<'a>, name: &ast::Ident, d: &ast::Decl) -> R<()> {
        let ast::DeclKind::Type {
            def:
                Some(TypeDef::Physical {
                    range,
                    primary,
                    secondary,
                }),
            ..
        } = &d.kind
        else {
            return Err(crate::Reported);
        };
        let (l, r, _) = self.range_exprs(sc, range)?;
        let bound = |v: Option<&Value>| match v {
            Some(Value::Integer(i)) => Some(*i),
            Some(Value::Real(x)) if x.is_finite() && x.fract() == 0.0 => Some(*x as i64),
            _ => None,
        };
        let (Some(lo), Some(hi)) = (bound(l.value()), bound(r.value())) else {
            return Err(self.error(ElabError::invalid(
                d.span,
                "a physical type's range needs static integer bounds",
                None,
            )));
        };
        let mut units = vec![(primary.name.clone(), 1i64)];
        let provisional = |units: &[(String, i64)]| {
            Ty::Physical(Rc::new(crate::names::types::PhysicalTy {
                name: name.name.clone(),
                units: units.to_vec(),
            }))
        };
        sc.declare_at(
            &primary.name,
            primary.span,
            Item::Unit {
                ty: provisional(&units),
                factor: 1,
            },
        );
        for (unit, value) in secondary {
            let ty = provisional(&units);
            let Value::Integer(factor) = self.static_value(sc, value, &ty, "a unit's value")?
            else {
                return Err(crate::Reported);
            };
            units.push((unit.name.clone(), factor));
            sc.declare_at(&unit.name, unit.span, Item::Unit { ty, factor });
        }
        // The units again, of the finished type (the same type by name).
        let ty = provisional(&units);
        for (unit, factor) in std::iter::once(primary)
            .chain(secondary.iter().map(|(u, _)| u))
            .zip(units.iter().map(|u| u.1))
        {
            let item = Item::Unit {
                ty: ty.clone(),
                factor,
            };
            sc.declare_at(&unit.name, unit.span, item);
        }
        let mut sub = Sub::of(ty, &name.name);
        sub.range = Some((Value::Integer(lo), Value::Integer(hi)));
        self.declare(sc, name, Item::Type(Rc::new(sub)))
    }

    /// `type_mark [range ...] [tolerance "..."]`, including index constraints `t(1 to 3)`.
    /// Gives an aliased array object the alias's array subtype, after checking that the two
    /// have the same element type and, where both are known, the same length.
    fn retype_alias(
        &mut self,
        item: &mut Item<'a>,
        alias: &Ty,
        span: vams_syntax::source::Span,
    ) -> R<()> {
        let (Item::Variable { ty, .. } | Item::Signal { ty, .. } | Item::Constant { ty, .. }) =
            item
        else {
            return Ok(());
        };
        let (Ty::Array(new), Ty::Array(old)) = (alias, &*ty) else {
            return Ok(());
        };
        let (expected, found) = (ty.to_string(), alias.to_string());
        if !new.element.same(&old.element)
            || matches!((new.len(), old.len()), (Some(a), Some(b)) if a != b)
        {
            return Err(self.error(ElabError::TypeMismatch {
                span,
                expected,
                found,
                help: Some(
                    "an alias's array subtype needs the object's element type and length".into(),
                ),
            }));
        }
        *ty = alias.clone();
        Ok(())
    }

    pub(crate) fn subtype_indication(
        &mut self,
        sc: &Scope<'a>,
        si: &ast::SubtypeIndication,
    ) -> R<Rc<Sub>> {
        let base = match &si.type_mark.kind {
            ast::ExprKind::Apply(mark, args) => {
                let sub = self.type_mark(sc, mark)?;
                let Ty::Array(arr) = &sub.ty else {
                    return Err(self.error(ElabError::invalid(
                        si.span,
                        format!("`{}` is not an array type", sub.name),
                        None,
                    )));
                };
                self.dimension_count(arr, args.len(), si.span, "index range")?;
                let mut bounds = Vec::with_capacity(args.len());
                for ast::Assoc { actual, .. } in args {
                    let (l, r, asc) = match actual {
                        ast::Actual::Range(r) => self.range_bounds(sc, r)?,
                        ast::Actual::Expr(e) if matches!(e.kind, ast::ExprKind::Attribute(..)) => {
                            let r = ast::Range::Attribute(Box::new(e.clone()));
                            self.range_bounds(sc, &r)?
                        }
                        // A type mark: its whole range (`table(state)`).
                        ast::Actual::Expr(e) => {
                            let si = ast::SubtypeIndication {
                                resolution: None,
                                type_mark: e.clone(),
                                range: None,
                                tolerance: None,
                                span: e.span,
                            };
                            self.discrete_range(sc, &ast::DiscreteRange::Subtype(si))?
                        }
                        ast::Actual::Open(s) => {
                            return Err(self.error(ElabError::invalid(
                                *s,
                                "expected a range",
                                None,
                            )));
                        }
                    };
                    bounds.push((l, r, asc));
                }
                // All dimensions at once: each may be small and their product not.
                self.array_size(&bounds, si.span)?;
                let ty = constrained(arr, &bounds);
                Rc::new(Sub {
                    ty,
                    ..(*sub).clone()
                })
            }
            ast::ExprKind::Attribute(prefix, attr) => {
                self.nature_subtype(sc, prefix, attr, si.span)?
            }
            _ => self.type_mark(sc, &si.type_mark)?,
        };
        if si.range.is_none() && si.tolerance.is_none() && si.resolution.is_none() {
            return Ok(base);
        }
        let mut sub = (*base).clone();
        if let Some(f) = &si.resolution
            && !is_std_logic(&sub.ty)
        {
            let items = self.lookup(sc, f)?;
            let Some(Item::Subprogram(s)) = items.first() else {
                return Err(self.error(ElabError::invalid(
                    f.span,
                    "a resolution function is named here",
                    Some("name a function of one unconstrained array parameter: `subtype t is wired_or bit;`".into()),
                )));
            };
            sub.resolution = Some(self.signals.resolvers.len());
            self.signals.resolvers.push(s.clone());
        }
        if let Some(r) = &si.range {
            if sub.ty.is_numeric() || matches!(sub.ty, Ty::Time | Ty::Enum(_) | Ty::Boolean) {
                let (l, r, _) = self.range_exprs(sc, r)?;
                match (l.value(), r.value()) {
                    (Some(a), Some(b)) if l.ty.same(&sub.ty) => {
                        sub.range = Some((a.clone(), b.clone()))
                    }
                    (Some(_), Some(_)) => {
                        return Err(self.error(ElabError::TypeMismatch {
                            span: si.span,
                            expected: sub.ty.to_string(),
                            found: l.ty.to_string(),
                            help: None,
                        }));
                    }
                    _ => {
                        return Err(self.error(ElabError::NotStatic {
                            span: si.span,
                            what: "a subtype's range".into(),
                        }));
                    }
                }
            }
        }
        if let Some(t) = &si.tolerance {
            let Some(string) = self.standard_type("string") else {
                return Err(crate::Reported);
            };
            if let Value::String(group) = self.static_value(sc, t, &string, "a tolerance group")? {
                sub.tolerance = Some(group.into());
            }
        }
        Ok(Rc::new(sub))
    }

    /// A declared signal of subtype `sub` (its integer range checked at each assignment).
    pub(crate) fn new_signal(
        &mut self,
        name: &str,
        sub: &Sub,
        init: Value,
        span: vams_syntax::source::Span,
    ) -> SignalId {
        let id = SignalId(self.design.signals.len() as u32);
        if let Some(r) = sub.resolution {
            self.signals.resolved.push((id, r));
        }
        self.design.signals.push(Signal {
            range: integer_bounds(sub),
            name: self.hier_name(name),
            ty: sub.ty.to_design(),
            init,
            kind: SignalKind::Explicit,
            span,
            resolution: None,
            guarded: None,
        });
        id
    }
}

/// `std_ulogic` or an array of it, whose resolution (`ieee.std_logic_1164.resolved`) the
/// kernel does itself.
fn is_std_logic(ty: &Ty) -> bool {
    match ty {
        Ty::Enum(e) => e.name == "std_ulogic",
        Ty::Array(a) => is_std_logic(&a.element),
        _ => false,
    }
}

/// One index of an array type declaration: its bounds as positions (`None`: unconstrained),
/// its lowest index value and its index type.
pub(crate) type Dimension = (Option<(i64, i64, bool)>, i64, Ty);

/// The type of an array named `name` with these dimensions (bounds as positions, lowest
/// index, index type), outermost first: one level of [`ArrayTy`] per dimension, the inner
/// ones marked by their `dimension`.
pub(crate) fn array_type(name: &str, dims: Vec<Dimension>, element: Ty) -> Ty {
    dims.into_iter()
        .enumerate()
        .rev()
        .fold(element, |element, (k, (bounds, index_low, index))| {
            Ty::Array(Rc::new(ArrayTy {
                name: name.to_string(),
                element,
                bounds,
                index_low,
                index,
                dimension: k as u8,
            }))
        })
}

/// `arr` (and its inner dimensions) with `bounds`, one per dimension from `arr`'s on.
fn constrained(arr: &ArrayTy, bounds: &[(i64, i64, bool)]) -> Ty {
    let Some((&first, rest)) = bounds.split_first() else {
        return Ty::Array(Rc::new(ArrayTy {
            name: arr.name.clone(),
            element: arr.element.clone(),
            bounds: arr.bounds,
            index_low: arr.index_low,
            index: arr.index.clone(),
            dimension: arr.dimension,
        }));
    };
    let element = match arr.next_dimension() {
        Some(inner) if !rest.is_empty() => constrained(inner, rest),
        _ => arr.element.clone(),
    };
    Ty::Array(Rc::new(ArrayTy {
        name: arr.name.clone(),
        element,
        bounds: Some(first),
        index_low: arr.index_low,
        index: arr.index.clone(),
        dimension: arr.dimension,
    }))
}

/// The bounds, low first, that an integer object of subtype `sub` must stay within: its range
/// constraint, or `integer`'s own (-2**31 to 2**31 - 1) without one. `None` for other types.
pub(crate) fn integer_bounds(sub: &Sub) -> Option<(i64, i64)> {
    if sub.ty != Ty::Integer {
        return None;
    }
    match &sub.range {
        Some((Value::Integer(a), Value::Integer(b))) => Some(((*a).min(*b), (*a).max(*b))),
        _ => Some((i32::MIN as i64, i32::MAX as i64)),
    }
}

/// The default initial value of an object of subtype `sub`: `T'left` (LRM 4.3.1.1), so a
/// `positive` starts at 1.
pub(crate) fn default_value(sub: &Sub) -> Value {
    match (&sub.ty, &sub.range) {
        (Ty::Integer | Ty::Physical(_), Some((left @ Value::Integer(_), _)))
        | (Ty::Enum(_), Some((left @ Value::Enum(_), _)))
        | (Ty::Boolean, Some((left @ Value::Boolean(_), _))) => left.clone(),
        _ => sub.ty.default_value(),
    }
}

/// The most elements an array may have: each is a value in memory (and a column or a
/// signal's worth of events), so a bound typed a few digits too long is a diagnostic rather
/// than an allocation of gigabytes.
const MAX_ARRAY_ELEMENTS: usize = 1 << 24;

impl Elab<'_> {
    /// An array constrained to these dimensions (`left to/downto right` each), or a
    /// diagnostic at `span` when it would hold more than [`MAX_ARRAY_ELEMENTS`].
    pub(crate) fn array_size(
        &mut self,
        dims: &[(i64, i64, bool)],
        span: vams_syntax::source::Span,
    ) -> R<()> {
        // i128 and saturating: no bounds an i64 holds overflow here.
        let n = dims.iter().fold(1i128, |n, &(left, right, ascending)| {
            let len = (i128::from(right) - i128::from(left)) * if ascending { 1 } else { -1 } + 1;
            n.saturating_mul(len.max(0))
        });
        if n > MAX_ARRAY_ELEMENTS as i128 {
            return Err(self.error(ElabError::unsupported(
                span,
                format!("an array of {n} elements"),
                format!(
                    "vams holds arrays of up to {MAX_ARRAY_ELEMENTS} elements; check the bounds"
                ),
            )));
        }
        Ok(())
    }

    /// `init` for an object of subtype `sub`, or a diagnostic at `span` when it is outside the
    /// subtype's integer range.
    pub(crate) fn check_initial(
        &mut self,
        sub: &Sub,
        init: &Value,
        span: vams_syntax::source::Span,
    ) -> R<()> {
        if let (Ty::Array(a), Some(m)) = (&sub.ty, crate::expressions::lengths::value_len(init))
            && let Some(n) = a.len().map(|n| n as i64)
            && n != m
        {
            return Err(self.error(ElabError::LengthMismatch {
                span,
                message: format!("the initial value has {m} element(s), but its subtype has {n}"),
                found: m,
                help: Some(crate::expressions::lengths::HELP.into()),
            }));
        }
        match (init, integer_bounds(sub)) {
            (Value::Integer(i), Some((lo, hi))) if *i < lo || *i > hi => {
                Err(self.error(ElabError::invalid(
                    span,
                    format!("the initial value {i} is outside the subtype's range {lo} to {hi}"),
                    Some("give an initial value within the subtype's range".into()),
                )))
            }
            _ => Ok(()),
        }
    }
}

/// The type of a constant: an unconstrained array type takes its bounds from the value.
pub(crate) fn fit_array(ty: &Ty, v: &Value) -> Ty {
    match (ty, v) {
        (Ty::Array(a), Value::Array(items)) if a.bounds.is_none() => constrain(a, items.len()),
        (Ty::Array(a), Value::String(s)) if a.bounds.is_none() => constrain(a, s.chars().count()),
        _ => ty.clone(),
    }
}

/// The names a binding of `labels` of `component` is declared under in a scope (see
/// [`Item::Binding`]).
pub(crate) fn binding_keys(labels: &ast::EntityNames, component: &ast::Expr) -> Vec<String> {
    let component = component.name_ident().map_or("", |id| id.name.as_str());
    match labels {
        ast::EntityNames::All => vec![binding_key(BindingKey::All, component)],
        ast::EntityNames::Others => vec![binding_key(BindingKey::Others, component)],
        ast::EntityNames::List(names) => names
            .iter()
            .filter_map(|n| match &n.kind {
                ast::ExprKind::Name(id) => Some(binding_key(BindingKey::Label, &id.name)),
                _ => None,
            })
            .collect(),
    }
}

/// Which instances a binding names: one label, or `all` or `others` of a component.
#[derive(Clone, Copy)]
pub(crate) enum BindingKey {
    Label,
    All,
    Others,
}

/// The scope name of a binding for the label or component `name`: ` for u1`, ` for all c`,
/// ` for others c` (no identifier can clash with them).
pub(crate) fn binding_key(key: BindingKey, name: &str) -> String {
    match key {
        BindingKey::Label => format!(" for {name}"),
        BindingKey::All => format!(" for all {name}"),
        BindingKey::Others => format!(" for others {name}"),
    }
}
