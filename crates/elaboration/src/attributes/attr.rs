//! Attributes: `Q'dot`, `Q'integ`, `Q'above(E)` on quantities (and the AMS attributes
//! lowered in `ltf`, `sampled`, `follow` and `delay`), `'event`, `'active`, `'last_value`,
//! `'last_event` on signals, `T'image(x)`, and the static `'high`, `'low`,
//! `'left`, `'right`, `'length`, `'ascending`; ranges, including `a'range`.

use std::rc::Rc;

use vams_design::{BinaryOp, Builtin, Expr, SignalAttr, Value};
use vams_syntax::ast::{self, Actual, Ident, Range};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::expressions::expr::Typed;
use crate::names::scope::{Item, Scope};
use crate::names::types::{Sub, Ty, index_value, position};
use crate::{Elab, R, Reported};

impl<'a> Elab<'a> {
    pub(crate) fn type_mark(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> R<Rc<Sub>> {
        let items = self.lookup(sc, e)?;
        match &items[0] {
            Item::Type(sub) => Ok(sub.clone()),
            other => Err(self.error(ElabError::WrongClass {
                span: e.span,
                name: self.sources.snippet(e.span).to_string(),
                found: other.class().into(),
                expected: "a type".into(),
                help: None,
            })),
        }
    }

    pub(crate) fn attribute(
        &mut self,
        sc: &Scope<'a>,
        prefix: &ast::Expr,
        attr: &Ident,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<Typed> {
        let name = attr.name.as_str();
        if let Some(Item::Attribute(_)) = sc.lookup(name).and_then(|items| items.first()) {
            return self.user_attribute(sc, prefix, attr, span);
        }
        let arg = |i: usize| match args.get(i) {
            Some(ast::Assoc {
                actual: Actual::Expr(e),
                ..
            }) => Some(e),
            _ => None,
        };
        match name {
            "dot" | "integ" => {
                let p = self.expr(sc, prefix, None)?;
                let q = match p.e {
                    Expr::Quantity(q) => q,
                    Expr::Dot(q) => self.dot_quantity(q),
                    _ => return Err(self.wrong_class(prefix, &p, "a quantity", name)),
                };
                if name == "dot" {
                    // In a procedural that assigns `q'dot`, reads see the assigned value.
                    let e = match self.analog.dot_targets.get(&q) {
                        Some(&var) => Expr::Var(var),
                        None => Expr::Dot(q),
                    };
                    Ok(Typed { e, ty: Ty::Real })
                } else {
                    Ok(Typed { e: Expr::Quantity(self.integ_quantity(q)), ty: Ty::Real })
                }
            }
            "reference" | "contribution" => {
                let (t, nature) = self.terminal(sc, prefix)?;
                let q = self.terminal_quantity(t, nature, name == "contribution", span);
                Ok(Typed { e: Expr::Quantity(q), ty: Ty::Real })
            }
            "above" => {
                let p = self.expr(sc, prefix, None)?;
                let Expr::Quantity(q) = p.e else {
                    return Err(self.wrong_class(prefix, &p, "a quantity", name));
                };
                let Some(level) = arg(0) else {
                    return Err(self.error(ElabError::invalid(span, "`'above` needs a level: `q'above(0.5)`", None)));
                };
                let level = self.expr_of(sc, level, &Ty::Real)?;
                if !level.e.is_analog() {
                    return Err(self.error(ElabError::invalid(span, "the level of `'above` must be an analog expression", None)));
                }
                let s = self.above_signal(q, level.e, span);
                Ok(Typed { e: Expr::Signal(s), ty: Ty::Boolean })
            }
            "ltf" | "zoh" | "ztf" | "delayed" => {
                let p = if name == "delayed" {
                    self.signal_expr(sc, prefix)?
                } else {
                    self.expr(sc, prefix, None)?
                };
                if let (Expr::Signal(s), "delayed") = (&p.e, name) {
                    let delay = match arg(0) {
                        Some(t) => match self.static_value(sc, t, &Ty::Time, "the delay of `'delayed`")? {
                            Value::Time(d) if d >= 0.0 => d,
                            _ => {
                                return Err(self.error(ElabError::invalid(t.span, "the delay of `'delayed` must not be negative", None)));
                            }
                        },
                        None => 0.0,
                    };
                    let d = self.delayed_signal(*s, delay, span);
                    return Ok(Typed { e: Expr::Signal(d), ty: p.ty });
                }
                let Expr::Quantity(q) = p.e else {
                    return Err(self.wrong_class(prefix, &p, "a quantity", name));
                };
                let e = match name {
                    "ltf" => self.ltf_attribute(sc, q, args, span)?,
                    "zoh" => self.zoh_attribute(sc, q, args, span)?,
                    "ztf" => self.ztf_attribute(sc, q, args, span)?,
                    _ => self.delayed_attribute(sc, q, args, span)?,
                };
                Ok(Typed { e, ty: Ty::Real })
            }
            "ramp" | "slew" => {
                let p = self.expr(sc, prefix, None)?;
                let e = match p.e {
                    Expr::Signal(s) if p.ty.same(&Ty::Real) => {
                        self.signal_follow_attribute(sc, s, name, args, span)?
                    }
                    Expr::Quantity(q) if name == "slew" => self.quantity_slew_attribute(sc, q, args, span)?,
                    _ if name == "slew" => {
                        return Err(self.wrong_class(prefix, &p, "a real signal or a quantity", name));
                    }
                    _ => return Err(self.wrong_class(prefix, &p, "a real signal", name)),
                };
                Ok(Typed { e, ty: Ty::Real })
            }
            // Implicit signals (LRM 14.1): `S'stable(T)` is false from an event on `S` until `T`
            // after it (the next delta cycle for 0), `S'quiet(T)` likewise for a transaction.
            "stable" | "quiet" => {
                let p = self.signal_expr(sc, prefix)?;
                let Expr::Signal(s) = p.e else {
                    return Err(self.wrong_class(prefix, &p, "a signal", name));
                };
                let t = match arg(0) {
                    Some(t) => match self.static_value(sc, t, &Ty::Time, "the time of a signal attribute")? {
                        Value::Time(d) if d >= 0.0 => d,
                        _ => return Err(self.error(ElabError::invalid(t.span, "the time must not be negative", None))),
                    },
                    None => 0.0,
                };
                let id = self.stable_signal(s, t, name == "quiet", span);
                Ok(Typed { e: Expr::Signal(id), ty: Ty::Boolean })
            }
            "event" | "active" | "last_value" | "last_event" | "last_active" | "driving"
            | "driving_value" => {
                let p = self.signal_expr(sc, prefix)?;
                let Expr::Signal(s) = p.e else {
                    return Err(self.wrong_class(prefix, &p, "a signal", name));
                };
                let (a, ty) = match name {
                    "event" => (SignalAttr::Event, Ty::Boolean),
                    "active" => (SignalAttr::Active, Ty::Boolean),
                    "last_value" => (SignalAttr::LastValue, p.ty),
                    "last_active" => (SignalAttr::LastActive, Ty::Time),
                    "driving" => (SignalAttr::Driving, Ty::Boolean),
                    "driving_value" => (SignalAttr::DrivingValue, p.ty),
                    _ => (SignalAttr::LastEvent, Ty::Time),
                };
                Ok(Typed { e: Expr::SignalAttr(s, a), ty })
            }
            // The name of a named entity (LRM 14.1), as declared (lower case), and its path
            // from the top: `:tb:dut:s`, or with the design entities `:tb(test):dut@dff(rtl):s`;
            // the path of a region (the top, a process) ends in `:`.
            "simple_name" | "path_name" | "instance_name" => {
                let (ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id)) = &prefix.kind else {
                    return Err(self.error(ElabError::invalid(
                        prefix.span,
                        format!("`'{name}` needs a name as its prefix"),
                        None,
                    )));
                };
                let text = if name == "simple_name" {
                    id.name.clone()
                } else {
                    self.path_name(sc, id, name == "instance_name")
                };
                let string = self.standard_type("string").unwrap_or(Ty::Integer);
                Ok(Typed { e: Expr::Const(Value::String(text)), ty: string })
            }
            "transaction" => {
                let p = self.signal_expr(sc, prefix)?;
                let Expr::Signal(s) = p.e else {
                    return Err(self.wrong_class(prefix, &p, "a signal", name));
                };
                let bit = self.standard_type("bit").unwrap_or(Ty::Boolean);
                let t = self.transaction_signal(s, &bit, span);
                Ok(Typed { e: Expr::Signal(t), ty: bit })
            }
            "image" => {
                let ty = self.type_mark(sc, prefix)?.ty.clone();
                let Some(x) = arg(0) else {
                    return Err(self.error(ElabError::invalid(span, "`'image` takes one argument: `real'image(x)`", None)));
                };
                let x = self.expr_of(sc, x, &ty)?;
                let string = self.standard_type("string").unwrap_or(Ty::Integer);
                Ok(Typed { e: Expr::Image(ty.to_design(), Box::new(x.e)), ty: string })
            }
            "high" | "low" | "left" | "right" | "length" | "ascending" => {
                let dimension = self.dimension_arg(sc, args)?;
                self.bound_attribute(sc, prefix, name, dimension, span)
            }
            // The tolerance group of a subtype or a quantity (LRM 1076.1 14.1), "" without one.
            "tolerance" => {
                let items = self.lookup(sc, prefix)?;
                let group = match &items[0] {
                    Item::Type(sub) => sub.tolerance.clone(),
                    // A branch quantity's group is its declaration's, else its nature's (a
                    // subnature's own groups included).
                    Item::Quantity(q) => self.design.quantities[q.index()].tolerance.clone(),
                    other => {
                        let class = other.class();
                        return Err(self.error(ElabError::invalid(
                            prefix.span,
                            format!("`'tolerance` applies to a subtype or a quantity, not {class}"),
                            None,
                        )));
                    }
                };
                let string = self.standard_type("string").unwrap_or(Ty::Integer);
                let text = group.map(|g| g.to_string()).unwrap_or_default();
                Ok(Typed { e: Expr::Const(Value::String(text)), ty: string })
            }
            "value" => {
                let ty = self.type_mark(sc, prefix)?.ty.clone();
                let kind = match &ty {
                    Ty::Enum(e) => Value::Array(e.literals.iter().map(|l| Value::String(l.clone())).collect()),
                    Ty::Integer => Value::String("integer".into()),
                    Ty::Real => Value::String("real".into()),
                    Ty::Time => Value::String("time".into()),
                    Ty::Boolean => Value::String("boolean".into()),
                    // The units and their values: `[("ohm", 1), ("kohm", 1000)]`.
                    Ty::Physical(p) => Value::Array(
                        p.units
                            .iter()
                            .map(|(u, f)| Value::Array(vec![Value::String(u.clone()), Value::Integer(*f)]))
                            .collect(),
                    ),
                    Ty::Array(_) | Ty::Record(_) | Ty::Access(_) | Ty::File(_) | Ty::Protected(_) => {
                        return Err(self.error(ElabError::invalid(span, format!("`'value` applies to scalar types, not `{ty}`"), None)));
                    }
                };
                let Some(x) = arg(0) else {
                    return Err(self.error(ElabError::invalid(span, "`'value` takes one argument: `t'value(\"...\")`", None)));
                };
                let string = self.standard_type("string").unwrap_or(Ty::Integer);
                let x = self.expr_of(sc, x, &string)?;
                self.folded(Expr::Call(Builtin::ValueOf, vec![x.e, Expr::Const(kind)]), ty, span)
            }
            "pos" | "val" | "succ" | "pred" | "leftof" | "rightof" => {
                let Some(x) = arg(0) else {
                    return Err(self.error(ElabError::invalid(
                        span,
                        format!("`'{name}` takes one argument: `t'{name}(x)`"),
                        None,
                    )));
                };
                self.position_attribute(sc, prefix, name, x, span)
            }
            // `electrical'across(x)`: a conversion to the nature's subtype.
            "across" | "through" if !args.is_empty() => {
                let sub = self.nature_subtype(sc, prefix, attr, span)?;
                self.conversion(sc, &sub.ty, args, span)
            }
            "across" | "through" => {
                // Of anything but a nature this says what the prefix must be.
                self.nature_subtype(sc, prefix, attr, span)?;
                Err(self.error(ElabError::invalid(
                    span,
                    format!("`N'{name}` is a subtype, not a value"),
                    Some(format!(
                        "convert a value to it, `N'{name}(x)`, or qualify one, `N'{name}'(1.0)`"
                    )),
                )))
            }
            _ => Err(self.error(ElabError::unsupported(
                attr.span,
                format!("the attribute `'{name}`"),
                "supported: 'dot 'integ 'above 'delayed 'ltf 'zoh 'ztf 'ramp 'slew 'event 'active 'last_value 'last_event 'last_active 'transaction 'driving 'driving_value 'image 'value 'tolerance 'high 'low 'left 'right 'length 'range 'pos 'val 'succ 'pred 'leftof 'rightof",
            ))),
        }
    }

    /// `id'path_name`, or with `instance` `id'instance_name` (LRM 14.1), named where the
    /// elaboration stands.
    fn path_name(&self, sc: &Scope<'a>, id: &Ident, instance: bool) -> String {
        let top = match self.here.units.get("") {
            Some(unit) if instance => unit.clone(),
            _ => self.design.top.clone(),
        };
        let mut path = format!(":{top}");
        let mut at = String::new();
        for part in self.here.path.split('.').filter(|p| !p.is_empty()) {
            if !at.is_empty() {
                at.push('.');
            }
            at.push_str(part);
            path.push(':');
            path.push_str(part);
            if let Some(unit) = self.here.units.get(&at).filter(|_| instance) {
                path.push('@');
                path.push_str(unit);
            }
        }
        path.push(':');
        if self.here.path.is_empty() && id.name == self.design.top {
            return path;
        }
        if let Some(label) = &self.here.process_label {
            let local = matches!(
                sc.lookup(&id.name).and_then(|items| items.first()),
                Some(Item::Variable { .. })
            );
            if *label == id.name || local {
                path.push_str(label);
                path.push(':');
            }
            if *label == id.name {
                return path;
            }
        }
        path.push_str(&id.name);
        path
    }

    /// An attribute specification (LRM 5.1): the value of attribute `attribute` of each named
    /// entity, declared in the current region under keys no identifier can clash with (see
    /// [`attribute_keys`]), where the entities' attribute names find it. A value computed at
    /// run time is reported where it is read, not here.
    pub(crate) fn attribute_specification(
        &mut self,
        sc: &mut Scope<'a>,
        attribute: &str,
        entities: &ast::EntityNames,
        class: &str,
        value: &ast::Expr,
    ) {
        let Some(Item::Attribute(sub)) = sc.lookup(attribute).and_then(|i| i.first()).cloned()
        else {
            return;
        };
        let before = self.errors.len();
        let item = match self.static_value(sc, value, &sub.ty, "an attribute value") {
            Ok(value) => Item::Constant {
                value,
                ty: sub.ty.clone(),
            },
            Err(_) => {
                let reason = self.errors.get(before).map(|e| e.to_string());
                self.errors.truncate(before);
                Item::Poison(Some(reason.unwrap_or_else(|| "its value".into()).into()))
            }
        };
        let keys = match entities {
            ast::EntityNames::List(names) => names
                .iter()
                .flat_map(|n| attribute_keys(&self.analysed.names, n, attribute, false))
                .collect(),
            // Every entity of the class declared in this region (`all`), or every one not
            // named by an earlier specification of the attribute (`others`).
            all_or_others => {
                let others = matches!(all_or_others, ast::EntityNames::Others);
                let region = sc
                    .regions
                    .last()
                    .map(|r| r.items.clone())
                    .unwrap_or_default();
                region
                    .iter()
                    .filter(|(_, items)| items.iter().any(|i| of_class(i, class)))
                    .map(|(name, _)| format!("'{attribute} of {name}"))
                    .filter(|key| !others || !region.contains_key(key))
                    .collect::<Vec<_>>()
            }
        };
        for key in keys {
            sc.declare(&key, item.clone());
        }
    }

    /// The value of a user-defined attribute of a named entity (LRM 6.6), as the attribute
    /// specification in the entity's declarative region gave it.
    fn user_attribute(
        &mut self,
        sc: &Scope<'a>,
        prefix: &ast::Expr,
        attr: &Ident,
        span: Span,
    ) -> R<Typed> {
        let found = attribute_keys(&self.analysed.names, prefix, &attr.name, true)
            .into_iter()
            .find_map(|key| sc.lookup(&key).and_then(|items| items.first()).cloned());
        match found {
            Some(Item::Constant { value, ty }) => Ok(Typed {
                e: Expr::Const(value),
                ty,
            }),
            Some(Item::Poison(Some(reason))) => Err(self.error(ElabError::unsupported(
                span,
                format!("the value of `'{}` here: {reason}", attr.name),
                "give the attribute specification a value known before the run (literals, constants and generics)",
            ))),
            Some(Item::Poison(None)) => Err(crate::Reported),
            _ => Err(self.error(ElabError::invalid(
                span,
                format!(
                    "no attribute specification gives `{}` a value of `'{}`",
                    self.text(prefix.span),
                    attr.name
                ),
                Some(format!(
                    "add `attribute {} of {} : <class> is <value>;` where it is declared (LRM 5.1)",
                    attr.name,
                    self.text(prefix.span)
                )),
            ))),
        }
    }

    /// The quantity of `T'reference` (the across quantity from `T` to its nature's reference
    /// terminal) or, with `contribution`, of `T'contribution` (a through quantity: the sum of
    /// the through quantities of the branches at `T` in the region that reads it and below,
    /// those leaving `T` positive; LRM 1076.1 14.1): one per terminal, and for a contribution
    /// per region too.
    fn terminal_quantity(
        &mut self,
        t: vams_design::TerminalId,
        nature: usize,
        contribution: bool,
        span: Span,
    ) -> vams_design::QuantityId {
        let region = contribution.then(|| self.here.instance.clone());
        if let Some(&q) = self.analog.terminal_attrs.get(&(t, region.clone())) {
            return q;
        }
        let terminal = self.design.terminals[t.index()].name.clone();
        let (name, kind, sub) = match &region {
            None => {
                let minus = self.reference_terminal(nature);
                let kind = vams_design::QuantityKind::Across { plus: t, minus };
                let name = format!("{terminal}'reference");
                (name, kind, self.analog.natures[nature].across.clone())
            }
            Some(region) => {
                let name = match region.is_empty() {
                    true => format!("{terminal}'contribution"),
                    false => format!("{region}.{terminal}'contribution"),
                };
                let kind = vams_design::QuantityKind::Free;
                (name, kind, self.analog.natures[nature].through.clone())
            }
        };
        // Named after the terminal (and the region), wherever it is read.
        let saved = std::mem::take(&mut self.here.path);
        let q = self.new_quantity(&name, kind, &sub, None, None, span);
        self.here.path = saved;
        if let Some(region) = &region {
            self.analog.contributions.push((q, t, region.clone(), span));
        }
        self.analog.terminal_attrs.insert((t, region), q);
        q
    }

    /// The equation of each `T'contribution`: `T'contribution == sum of the through
    /// quantities at T` declared in its instance and below (plus where `T` is the plus
    /// terminal, minus where it is the minus one).
    pub(crate) fn contribution_equations(&mut self) {
        use vams_design::{BinaryOp, QuantityKind};
        for (q, t, instance, span) in std::mem::take(&mut self.analog.contributions) {
            let inside = |name: &str| {
                instance.is_empty()
                    || name
                        .strip_prefix(instance.as_str())
                        .is_some_and(|rest| rest.starts_with('.'))
            };
            let mut sum = Expr::Quantity(q);
            let mut terms = Vec::new();
            for (k, quantity) in self.design.quantities.iter().enumerate() {
                let QuantityKind::Through { plus, minus } = quantity.kind else {
                    continue;
                };
                if plus == minus || !inside(&quantity.name) {
                    continue;
                }
                let op = if plus == t {
                    BinaryOp::Sub
                } else if minus == t {
                    BinaryOp::Add
                } else {
                    continue;
                };
                let id = vams_design::QuantityId(k as u32);
                sum = Expr::Binary(op, Box::new(sum), Box::new(Expr::Quantity(id)));
                terms.push(format!(
                    "{} {}",
                    if op == BinaryOp::Sub { "+" } else { "-" },
                    quantity.name
                ));
            }
            let name = self.design.quantities[q.index()].name.clone();
            let rhs = if terms.is_empty() {
                "0.0".to_string()
            } else {
                terms.join(" ").trim_start_matches("+ ").to_string()
            };
            let saved = std::mem::replace(&mut self.here.instance, instance);
            self.generated_equation(sum, span, format!("{name} == {rhs}"));
            self.here.instance = saved;
        }
    }

    /// `T'pos`, `T'val`, `T'succ`, `T'pred`, `T'leftof`, `T'rightof` of an integer,
    /// enumeration, boolean or `time` type (LRM 14.1; the types are ascending, so `leftof` is
    /// `pred`). Positions of enumerations count from 0, of `time` in femtoseconds; a result
    /// outside the type is a run-time error.
    fn position_attribute(
        &mut self,
        sc: &Scope<'a>,
        prefix: &ast::Expr,
        name: &str,
        x: &ast::Expr,
        span: Span,
    ) -> R<Typed> {
        let ty = self.type_mark(sc, prefix)?.ty.clone();
        let literals = match &ty {
            Ty::Enum(e) => Some(e.literals.len() as i64),
            Ty::Boolean => Some(2),
            Ty::Integer | Ty::Time | Ty::Physical(_) => None,
            Ty::Real
            | Ty::Array(_)
            | Ty::Record(_)
            | Ty::Access(_)
            | Ty::File(_)
            | Ty::Protected(_) => {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!(
                        "`'{name}` applies to integer, enumeration and physical types, not `{ty}`"
                    ),
                    Some("for a real, convert: `integer(x)`".into()),
                )));
            }
        };
        let int = |i: i64| Expr::Const(Value::Integer(i));
        let pos = |e: Expr| match ty {
            Ty::Integer => e,
            Ty::Time => Expr::Call(Builtin::TimePos, vec![e]),
            _ => Expr::Call(Builtin::Pos, vec![e]),
        };
        let val = |i: Expr| match (&ty, literals) {
            (Ty::Time, _) => Expr::Call(Builtin::TimeVal, vec![i]),
            (_, Some(n)) => Expr::Call(
                Builtin::EnumVal,
                vec![i, int(n), int(i64::from(matches!(ty, Ty::Boolean)))],
            ),
            _ => i,
        };
        let (e, result) = match name {
            "pos" => (pos(self.expr_of(sc, x, &ty)?.e), Ty::Integer),
            "val" => (val(self.expr_of(sc, x, &Ty::Integer)?.e), ty.clone()),
            _ => {
                let step = if matches!(name, "succ" | "rightof") {
                    BinaryOp::Add
                } else {
                    BinaryOp::Sub
                };
                let p = pos(self.expr_of(sc, x, &ty)?.e);
                (
                    val(Expr::Binary(step, Box::new(p), Box::new(int(1)))),
                    ty.clone(),
                )
            }
        };
        self.folded(e, result, span)
    }

    fn wrong_class(
        &mut self,
        prefix: &ast::Expr,
        p: &Typed,
        expected: &str,
        attr: &str,
    ) -> Reported {
        let found = match p.e {
            Expr::Signal(_) => "a signal",
            Expr::Quantity(_) => "a quantity",
            Expr::Var(_) => "a variable",
            Expr::Const(_) => "a constant",
            _ => "an expression",
        };
        self.error(ElabError::WrongClass {
            span: prefix.span,
            name: self.sources.snippet(prefix.span).to_string(),
            found: found.into(),
            expected: expected.into(),
            help: Some(format!("`'{attr}` applies to {expected}")),
        })
    }

    /// The dimension an array attribute's optional argument names (`m'range(2)`), from 1.
    fn dimension_arg(&mut self, sc: &Scope<'a>, args: &[ast::Assoc]) -> R<usize> {
        match args {
            [] => Ok(1),
            [
                ast::Assoc {
                    actual: Actual::Expr(e),
                    ..
                },
            ] => {
                let n = self.static_int(sc, e, "an attribute's dimension")?;
                usize::try_from(n).ok().filter(|&n| n >= 1).ok_or_else(|| {
                    self.error(ElabError::invalid(
                        e.span,
                        "a dimension counts from 1",
                        None,
                    ))
                })
            }
            [a, ..] => Err(self.error(ElabError::invalid(
                a.span,
                "this attribute takes at most one argument, the dimension",
                None,
            ))),
        }
    }

    /// Dimension `n` (from 1) of the array type `ty` (itself for 1).
    fn nth_dimension(&mut self, ty: Ty, n: usize, span: Span) -> R<Ty> {
        let mut level = ty;
        for _ in 1..n {
            let next = match &level {
                Ty::Array(a) => a.next_dimension().cloned(),
                _ => None,
            };
            let Some(next) = next else {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("`{level}` has fewer than {n} dimensions"),
                    None,
                )));
            };
            level = Ty::Array(next);
        }
        Ok(level)
    }

    /// `'high`, `'low`, `'left`, `'right`, `'length`, `'ascending` of a type or an array
    /// (of its dimension `dimension`).
    /// `'length`, `'left`, ... of an unconstrained array object on the heap (a textio line):
    /// its bounds start at the index subtype's low end (`string`: 1) and ascend, as those of
    /// `new string'("...")` and of a line `readline` made do.
    fn run_time_bound(
        &mut self,
        object: Expr,
        a: Rc<crate::names::types::ArrayTy>,
        name: &str,
        span: Span,
    ) -> R<Typed> {
        use vams_design::{BinaryOp, Builtin};
        let length = Expr::Call(Builtin::Length, vec![object]);
        let low = Expr::Const(Value::Integer(a.index_low));
        let high = Expr::Binary(
            BinaryOp::Sub,
            Box::new(Expr::Binary(
                BinaryOp::Add,
                Box::new(low.clone()),
                Box::new(length.clone()),
            )),
            Box::new(Expr::Const(Value::Integer(1))),
        );
        let (e, ty) = match name {
            "length" => (length, Ty::Integer),
            "left" | "low" => (low, a.index.clone()),
            "right" | "high" => (high, a.index.clone()),
            "ascending" => (Expr::Const(Value::Boolean(true)), Ty::Boolean),
            _ => {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("`'{name}` of an object an access value designates"),
                    None,
                )));
            }
        };
        Ok(Typed { e, ty })
    }

    fn bound_attribute(
        &mut self,
        sc: &Scope<'a>,
        prefix: &ast::Expr,
        name: &str,
        dimension: usize,
        span: Span,
    ) -> R<Typed> {
        let items = self.lookup(sc, prefix)?;
        let (ty, range) = match &items[0] {
            Item::Type(sub) => (sub.ty.clone(), sub.range.clone()),
            Item::TerminalArray { elements, .. } => (elements.ty(), None),
            Item::QuantityArray(elements) => (elements.ty(), None),
            Item::ArrayNature(nature) if let Some(ty) = nature.bounds_ty() => (ty, None),
            _ => {
                let value = self.expr(sc, prefix, None)?;
                if let Ty::Access(_) = value.ty {
                    let object = self.deref(value, prefix.span)?;
                    if let Ty::Array(a) = &object.ty
                        && a.bounds.is_none()
                    {
                        return self.run_time_bound(object.e, a.clone(), name, span);
                    }
                    (object.ty, None)
                } else {
                    (value.ty, None)
                }
            }
        };
        let ty = self.nth_dimension(ty, dimension, span)?;
        if let Ty::Array(a) = &ty {
            let Some((l, r, asc)) = a.bounds else {
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("`{}` is unconstrained: it has no bounds", a.name),
                    None,
                )));
            };
            let (lo, hi) = if asc { (l, r) } else { (r, l) };
            let index = |p| index_value(&a.index, p);
            let v = match name {
                "high" => index(hi),
                "low" => index(lo),
                "left" => index(l),
                "right" => index(r),
                "length" => Value::Integer(crate::names::types::bounds_len(l, r, asc) as i64),
                _ => Value::Boolean(asc),
            };
            let ty = match name {
                "ascending" => Ty::Boolean,
                "length" => Ty::Integer,
                _ => a.index.clone(),
            };
            return Ok(Typed {
                e: Expr::Const(v),
                ty,
            });
        }
        let Some((left, right)) = range.or_else(|| ty.scalar_bounds()) else {
            return Err(self.error(ElabError::invalid(
                span,
                format!("`'{name}` needs a scalar type or an array"),
                None,
            )));
        };
        let asc = !matches!(
            crate::expressions::fold::eval(&Expr::Binary(
                vams_design::BinaryOp::Gt,
                Box::new(Expr::Const(left.clone())),
                Box::new(Expr::Const(right.clone()))
            )),
            Ok(Value::Boolean(true))
        );
        let v = match name {
            "high" => {
                if asc {
                    right
                } else {
                    left
                }
            }
            "low" => {
                if asc {
                    left
                } else {
                    right
                }
            }
            "left" => left,
            "right" => right,
            "ascending" => {
                return Ok(Typed {
                    e: Expr::Const(Value::Boolean(asc)),
                    ty: Ty::Boolean,
                });
            }
            _ => {
                return Err(self.error(ElabError::invalid(
                    span,
                    "`'length` applies to arrays",
                    None,
                )));
            }
        };
        Ok(Typed {
            e: Expr::Const(v),
            ty,
        })
    }

    /// The bounds of a range as expressions: `(left, right, ascending)`.
    pub(crate) fn range_exprs(&mut self, sc: &Scope<'a>, r: &Range) -> R<(Typed, Typed, bool)> {
        match r {
            Range::Explicit {
                left, dir, right, ..
            } => {
                let l = self.expr(sc, left, None)?;
                let r = self.expr_of(sc, right, &l.ty)?;
                Ok((l, r, *dir == ast::Direction::To))
            }
            Range::Attribute(e) => {
                // `m'range(2)`: the attribute with its dimension.
                let (e, dimension) = match &e.kind {
                    ast::ExprKind::Apply(inner, args)
                        if matches!(inner.kind, ast::ExprKind::Attribute(..)) =>
                    {
                        (&**inner, self.dimension_arg(sc, args)?)
                    }
                    _ => (&**e, 1),
                };
                let ast::ExprKind::Attribute(prefix, attr) = &e.kind else {
                    return Err(self.error(ElabError::invalid(e.span, "expected a range", None)));
                };
                if attr.name != "range" && attr.name != "reverse_range" {
                    return Err(self.error(ElabError::invalid(e.span, "expected `x'range`", None)));
                }
                let items = self.lookup(sc, prefix)?;
                let (ty, range) = match &items[0] {
                    Item::Type(sub) => (sub.ty.clone(), sub.range.clone()),
                    Item::TerminalArray { elements, .. } => (elements.ty(), None),
                    Item::QuantityArray(elements) => (elements.ty(), None),
                    _ => (self.expr(sc, prefix, None)?.ty, None),
                };
                let ty = self.nth_dimension(ty, dimension, e.span)?;
                let (l, r, asc) = match (&ty, range) {
                    (Ty::Array(a), _) => match a.bounds {
                        Some((l, r, asc)) => {
                            (index_value(&a.index, l), index_value(&a.index, r), asc)
                        }
                        None => {
                            return Err(self.error(ElabError::invalid(
                                e.span,
                                "an unconstrained array has no range",
                                None,
                            )));
                        }
                    },
                    (_, Some((l, r))) => (l, r, true),
                    (t, None) => match t.scalar_bounds() {
                        Some((l, r)) => (l, r, true),
                        None => {
                            return Err(self.error(ElabError::invalid(e.span, "no range", None)));
                        }
                    },
                };
                let elem_ty = match &ty {
                    Ty::Array(a) => a.index.clone(),
                    t => t.clone(),
                };
                let (l, r, asc) = if attr.name == "reverse_range" {
                    (r, l, !asc)
                } else {
                    (l, r, asc)
                };
                Ok((
                    Typed {
                        e: Expr::Const(l),
                        ty: elem_ty.clone(),
                    },
                    Typed {
                        e: Expr::Const(r),
                        ty: elem_ty,
                    },
                    asc,
                ))
            }
        }
    }

    /// A static discrete range, as positions (an enumeration's literals by position).
    pub(crate) fn range_bounds(&mut self, sc: &Scope<'a>, r: &Range) -> R<(i64, i64, bool)> {
        self.range_bounds_typed(sc, r)
            .map(|(l, r, asc, _)| (l, r, asc))
    }

    /// [`Elab::range_bounds`] with the range's type.
    pub(crate) fn range_bounds_typed(
        &mut self,
        sc: &Scope<'a>,
        r: &Range,
    ) -> R<(i64, i64, bool, Ty)> {
        let span = match r {
            Range::Explicit { span, .. } => *span,
            Range::Attribute(e) => e.span,
        };
        let (l, rr, asc) = self.range_exprs(sc, r)?;
        let discrete = matches!(l.ty, Ty::Integer | Ty::Enum(_) | Ty::Boolean);
        match (l.value().and_then(position), rr.value().and_then(position)) {
            (Some(a), Some(b)) if discrete => Ok((a, b, asc, l.ty)),
            _ if !discrete => Err(self.error(ElabError::TypeMismatch {
                span,
                expected: "a discrete range (integers or an enumeration)".into(),
                found: l.ty.to_string(),
                help: None,
            })),
            _ => Err(self.error(ElabError::NotStatic {
                span,
                what: "this range".into(),
            })),
        }
    }

    /// A static discrete range: `1 to 4`, `x'range`, `natural range 0 to 3`, `state`,
    /// `state range idle to busy`, as positions.
    pub(crate) fn discrete_range(
        &mut self,
        sc: &Scope<'a>,
        r: &ast::DiscreteRange,
    ) -> R<(i64, i64, bool)> {
        self.discrete_range_typed(sc, r)
            .map(|(l, r, asc, _)| (l, r, asc))
    }

    /// [`Elab::discrete_range`] with the range's type.
    pub(crate) fn discrete_range_typed(
        &mut self,
        sc: &Scope<'a>,
        r: &ast::DiscreteRange,
    ) -> R<(i64, i64, bool, Ty)> {
        match r {
            ast::DiscreteRange::Range(r) => self.range_bounds_typed(sc, r),
            ast::DiscreteRange::Subtype(si) => match &si.range {
                Some(r) => self.range_bounds_typed(sc, r),
                None => {
                    let sub = self.type_mark(sc, &si.type_mark)?;
                    let range = sub.range.clone().or_else(|| match &sub.ty {
                        Ty::Enum(_) | Ty::Boolean => sub.ty.scalar_bounds(),
                        _ => None,
                    });
                    let bounds = range.and_then(|(l, r)| Some((position(&l)?, position(&r)?)));
                    match bounds {
                        Some((l, r)) if !matches!(sub.ty, Ty::Real | Ty::Time) => {
                            Ok((l, r, true, sub.ty.clone()))
                        }
                        _ => Err(self.error(ElabError::unsupported(
                            si.span,
                            "this discrete range",
                            "write an explicit range: `0 to 3`",
                        ))),
                    }
                }
            },
        }
    }
}

/// The keys under which the value of `entity'attribute` is declared (by a specification) or
/// looked up (by an attribute name, `use`), the most specific first: by the declaration the
/// name denotes, as analysis resolved it (an overload named with its signature), then by the
/// name (the entities of an `all` or `others` specification, every overload of a name
/// specified without a signature, and a statement label, which a specification names before
/// the statement declares it). A specification with a signature decorates its overload only.
fn attribute_keys(
    resolved: &rustc_hash::FxHashMap<Span, Span>,
    entity: &ast::Expr,
    attribute: &str,
    use_: bool,
) -> Vec<String> {
    let (name, signed) = match &entity.kind {
        ast::ExprKind::Signed(name, _) => (name.as_ref(), true),
        _ => (entity, false),
    };
    let id = match &name.kind {
        ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id) => id,
        _ => return Vec::new(),
    };
    let by_decl = resolved
        .get(&id.span)
        .map(|decl| format!("'{attribute} of {decl:?}"));
    let by_name =
        (use_ || !signed || by_decl.is_none()).then(|| format!("'{attribute} of {}", id.name));
    by_decl.into_iter().chain(by_name).collect()
}

/// Whether `item` is a named entity of entity class `class` (LRM 5.1).
fn of_class(item: &Item, class: &str) -> bool {
    match class {
        "signal" => matches!(item, Item::Signal { .. }),
        "constant" => matches!(item, Item::Constant { .. }),
        "variable" => matches!(item, Item::Variable { .. }),
        "quantity" => matches!(item, Item::Quantity(_) | Item::QuantityArray(_)),
        "terminal" => matches!(item, Item::Terminal { .. } | Item::TerminalArray { .. }),
        "type" | "subtype" => matches!(item, Item::Type(_)),
        "nature" | "subnature" => matches!(item, Item::Nature(_) | Item::ArrayNature(_)),
        "function" | "procedure" => matches!(item, Item::Subprogram(_)),
        "literal" => matches!(item, Item::EnumLiteral { .. }),
        "component" => matches!(item, Item::Component(_)),
        "units" => matches!(item, Item::Unit { .. } | Item::TimeUnit(_)),
        _ => false,
    }
}
