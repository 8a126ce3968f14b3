//! Ports of an instance: each formal is an alias of its actual (a terminal, a quantity, a
//! signal, or an element-by-element association), a new object named `instance.port` when it
//! is open, a signal of a constant value for a static expression on an `in` port, and a
//! conversion where the port map converts (`port_conversions`).
//!
//! Reads the instance's scope and its parent's; writes the port items into the instance's
//! scope and the port defaults of `out` ports (`Elab::signals`).

use vams_design::{self as design, QuantityKind};
use vams_syntax::ast::{self, Actual, Assoc, InterfaceDecl, ObjectClass};

use crate::error::ElabError;
use crate::hierarchy::hier::PortActual;
use crate::names::composite::NatureMark;
use crate::names::scope::{Item, Scope};
use crate::names::types::Ty;
use crate::{Elab, R, Reported};

/// A port's actual expression with the scope it is read in (the parent's).
type ActualIn<'x, 'a> = Option<(&'x ast::Expr, &'x Scope<'a>)>;

impl<'a> Elab<'a> {
    /// Declares port `name` in the instance's scope `sc`, associated with `actual` read in
    /// `parent` (the top has no parent: its ports are new objects).
    pub(crate) fn port(
        &mut self,
        sc: &mut Scope<'a>,
        name: &ast::Ident,
        decl: &InterfaceDecl,
        actual: PortActual<'_>,
        conversion: Option<&ast::Expr>,
        parent: Option<&Scope<'a>>,
    ) -> R<()> {
        let actual = match (actual, parent) {
            (PortActual::Whole(a), _) => a,
            (PortActual::Elements(elements), Some(parent)) => {
                let item = match decl.class {
                    Some(ObjectClass::Quantity) => {
                        self.quantity_port_elements(sc, parent, name, decl, elements)?
                    }
                    Some(ObjectClass::Terminal) => {
                        self.terminal_port_elements(sc, parent, name, decl, elements)?
                    }
                    _ => self.signal_port_elements(sc, parent, name, decl, elements)?,
                };
                sc.declare_at(&name.name, name.span, item);
                return Ok(());
            }
            (PortActual::Elements(_), None) => None,
        };
        let actual_expr = match (actual, parent) {
            (
                Some(Assoc {
                    actual: Actual::Expr(e),
                    ..
                }),
                Some(p),
            ) => Some((e, p)),
            (
                Some(Assoc {
                    actual: Actual::Range(_),
                    span,
                    ..
                }),
                _,
            ) => {
                return Err(self.error(ElabError::invalid(
                    *span,
                    "a range is not a port actual",
                    None,
                )));
            }
            _ => None,
        };
        let item = match decl.class.unwrap_or(ObjectClass::Signal) {
            ObjectClass::Terminal => self.terminal_port(sc, name, decl, actual_expr)?,
            ObjectClass::Quantity => match self.quantity_port(sc, name, decl, actual_expr)? {
                Some(item) => item,
                None => return Ok(()),
            },
            ObjectClass::Signal => {
                self.signal_port(sc, name, decl, conversion, parent, actual_expr)?
            }
            other => {
                return Err(self.error(ElabError::unsupported(
                    decl.span,
                    format!("{other:?} ports").to_lowercase(),
                    "ports are signals, quantities or terminals",
                )));
            }
        };
        sc.declare_at(&name.name, name.span, item);
        Ok(())
    }

    /// A port connected to an object of the wrong class (a signal on a terminal port).
    fn port_class_error(
        &mut self,
        name: &ast::Ident,
        e: &ast::Expr,
        found: &str,
        expected: &str,
    ) -> Reported {
        self.error(ElabError::PortClass {
            span: e.span,
            port: name.name.clone(),
            expected: expected.into(),
            found: found.into(),
            help: Some(format!(
                "connect a {expected} (or `open`) to `{}`",
                name.name
            )),
        })
    }

    /// A terminal port: the terminal (or terminal array, or record terminal) its actual
    /// names, of the port's nature, or a new one when open.
    fn terminal_port(
        &mut self,
        sc: &Scope<'a>,
        name: &ast::Ident,
        decl: &InterfaceDecl,
        actual_expr: ActualIn<'_, 'a>,
    ) -> R<Item<'a>> {
        let nature = match self.nature_indication(sc, &decl.subtype)? {
            NatureMark::Scalar(n) => n,
            NatureMark::Array(array) => {
                let item = self.terminal_array_port(name, &array, actual_expr)?;
                return Ok(item);
            }
            // A port of a record nature is the whole record terminal it is associated
            // with, or new terminals when it is open.
            NatureMark::Record(record) => {
                let item = match actual_expr {
                    Some((e, p)) => match self.lookup(p, e)?.first() {
                        Some(Item::TerminalRecord(r)) if r.is_of(&record) => {
                            Item::TerminalRecord(r.clone())
                        }
                        Some(other) => {
                            return Err(self.port_class_error(
                                name,
                                e,
                                other.class(),
                                &format!("terminal of nature {}", record.name),
                            ));
                        }
                        None => return Err(crate::Reported),
                    },
                    None => self.new_record_terminal(&name.name, &record, name.span)?,
                };
                return Ok(item);
            }
        };
        Ok(match actual_expr {
            Some((e, p)) => {
                let items = match &e.kind {
                    ast::ExprKind::Apply(prefix, args) => {
                        let (id, nature) = self.indexed_terminal(p, prefix, args, e.span)?;
                        vec![Item::Terminal { id, nature }]
                    }
                    _ => self.lookup(p, e)?,
                };
                let (id, n) = match items[0] {
                    Item::Terminal { id, nature } => (id, nature),
                    Item::RefTerminal { nature } => (self.reference_terminal(nature), nature),
                    ref other => {
                        return Err(self.port_class_error(name, e, other.class(), "terminal"));
                    }
                };
                if !self.same_nature(n, nature) {
                    let (a, b) = (
                        self.analog.natures[nature].name.clone(),
                        self.analog.natures[n].name.clone(),
                    );
                    return Err(self.error(ElabError::TypeMismatch {
                        span: e.span,
                        expected: format!("a terminal of nature {a}"),
                        found: format!("a terminal of nature {b}"),
                        help: Some(
                            "a terminal port connects to a terminal of the same nature".into(),
                        ),
                    }));
                }
                Item::Terminal { id, nature }
            }
            None => Item::Terminal {
                id: self.new_terminal(&name.name, nature, name.span),
                nature,
            },
        })
    }

    /// A quantity port: the quantity its actual names, a new quantity equal to an
    /// expression actual (mode `in`), or a new free quantity when open. `None` when it is a
    /// quantity array port, which `quantity_array_port` declared.
    fn quantity_port(
        &mut self,
        sc: &mut Scope<'a>,
        name: &ast::Ident,
        decl: &InterfaceDecl,
        actual_expr: ActualIn<'_, 'a>,
    ) -> R<Option<Item<'a>>> {
        let sub = self.subtype_indication(sc, &decl.subtype)?;
        if let Ty::Array(arr) = &sub.ty
            && arr.element == Ty::Real
            && arr.dimensions() == 1
        {
            self.quantity_array_port(sc, name, decl, &sub, actual_expr)?;
            return Ok(None);
        }
        if sub.ty != Ty::Real {
            return Err(self.error(ElabError::unsupported(
                decl.subtype.span,
                format!("quantity ports of type {}", sub.ty),
                "declare one scalar quantity port per element",
            )));
        }
        // The quantity a name actual denotes; `None` for an expression, a constant or
        // a signal.
        let named = match actual_expr {
            Some((e, p))
                if matches!(e.kind, ast::ExprKind::Name(_) | ast::ExprKind::Selected(..)) =>
            {
                match self.lookup(p, e)?[0] {
                    Item::Quantity(q) => Some(q),
                    Item::Constant { .. } | Item::Signal { .. } | Item::Variable { .. } => None,
                    ref other => {
                        return Err(self.port_class_error(name, e, other.class(), "quantity"));
                    }
                }
            }
            _ => None,
        };
        let item = match (named, actual_expr) {
            (Some(q), _) => Item::Quantity(q),
            (None, Some((e, p))) if matches!(decl.mode, None | Some(ast::Mode::In)) => {
                let value = self.expr_of(p, e, &Ty::Real)?;
                let value = self.analog_value(value.e, value.ty, e.span)?;
                let q =
                    self.new_quantity(&name.name, QuantityKind::Free, &sub, None, None, name.span);
                let text = format!("{} => {}", name.name, self.text(e.span));
                let residual = crate::attributes::synth::sub(design::Expr::Quantity(q), value);
                self.generated_equation(residual, e.span, text);
                Item::Quantity(q)
            }
            (None, Some((e, _))) => {
                return Err(self.error(ElabError::invalid(
                    e.span,
                    format!(
                        "the actual of `{}`, a quantity port of mode {}, must name a quantity",
                        name.name,
                        if decl.mode == Some(ast::Mode::Out) {
                            "out"
                        } else {
                            "inout"
                        }
                    ),
                    Some("an expression is an actual only for a port of mode in".into()),
                )));
            }
            (None, None) => Item::Quantity(self.new_quantity(
                &name.name,
                QuantityKind::Free,
                &sub,
                None,
                None,
                name.span,
            )),
        };
        Ok(Some(item))
    }

    /// A signal port: converted (`to_bool(y) => yb`), a signal of a static `in` actual's
    /// value, the actual signal itself (with the port's default as its drivers' initial value
    /// for `out` ports), or a new signal when open.
    fn signal_port(
        &mut self,
        sc: &Scope<'a>,
        name: &ast::Ident,
        decl: &InterfaceDecl,
        conversion: Option<&ast::Expr>,
        parent: Option<&Scope<'a>>,
        actual_expr: ActualIn<'_, 'a>,
    ) -> R<Item<'a>> {
        let sub = self.subtype_indication(sc, &decl.subtype)?;
        if let (Some(c), Some(p)) = (conversion, parent) {
            let e = actual_expr.map(|(e, _)| e);
            let item = self.converted_out_port(p, name, &sub, decl.mode, c, e)?;
            return Ok(item);
        }
        if let Some((e, p)) = actual_expr
            && matches!(decl.mode, None | Some(ast::Mode::In))
            && let Some(item) = self.converted_in_port(p, name, &sub, e)?
        {
            return Ok(item);
        }
        // An `in` port's actual may be a static expression (LRM 1.1.1.2): the port
        // is then a signal of that constant value.
        let constant = actual_expr.filter(|(e, p)| {
            matches!(decl.mode, None | Some(ast::Mode::In))
                && match &e.kind {
                    ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id) => {
                        matches!(self.resolved_item(p, id), Some(Item::Constant { .. }))
                    }
                    ast::ExprKind::Literal(_)
                    | ast::ExprKind::Aggregate(_)
                    | ast::ExprKind::Qualified(..)
                    | ast::ExprKind::Unary(..)
                    | ast::ExprKind::Binary(..)
                    | ast::ExprKind::Paren(_) => true,
                    // A function call or type conversion of static values
                    // (`a => to_bit(enabled)`); of a signal it is converted above.
                    ast::ExprKind::Apply(prefix, _) => match &prefix.kind {
                        ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id) => {
                            matches!(
                                self.resolved_item(p, id),
                                Some(Item::Subprogram(_) | Item::Type(_))
                            )
                        }
                        _ => false,
                    },
                    _ => false,
                }
        });
        if let Some((e, p)) = constant {
            let value = self.static_value(p, e, &sub.ty, "a port's actual expression")?;
            self.check_initial(&sub, &value, e.span)?;
            let id = self.new_signal(&name.name, &sub, value, name.span);
            return Ok(Item::Signal {
                id,
                ty: sub.ty.clone(),
            });
        }
        Ok(match actual_expr {
            Some((e, p)) => {
                let items = self.lookup(p, e)?;
                match &items[0] {
                    Item::Signal { id, ty } => {
                        if !ty.same(&sub.ty) {
                            return Err(self.error(ElabError::TypeMismatch {
                                span: e.span,
                                expected: sub.ty.to_string(),
                                found: ty.to_string(),
                                help: Some(format!("port `{}` is of type {}", name.name, sub.ty)),
                            }));
                        }
                        // An unconstrained port takes its bounds from the actual.
                        let ty = match &sub.ty {
                            Ty::Array(a) if a.bounds.is_none() => ty.clone(),
                            _ => sub.ty.clone(),
                        };
                        if let (
                            Some(d),
                            Some(ast::Mode::Out | ast::Mode::Inout | ast::Mode::Buffer),
                        ) = (&decl.default, decl.mode)
                        {
                            let v = self.static_value(sc, d, &ty, "a port's default")?;
                            self.signals
                                .port_defaults
                                .push((self.here.path.clone(), *id, v));
                        }
                        // A `bus` port's drivers disconnect: the signal they drive
                        // through it is guarded (ports share their actual's id).
                        if decl.bus {
                            let root = self.view_root(*id);
                            let signal = &mut self.design.signals[root.index()];
                            signal.guarded = signal.guarded.or(Some(design::GuardedKind::Bus));
                        }
                        Item::Signal { id: *id, ty }
                    }
                    other => {
                        return Err(self.port_class_error(name, e, other.class(), "signal"));
                    }
                }
            }
            None => {
                let init = match &decl.default {
                    Some(d) => self.static_value(sc, d, &sub.ty, "a port's default")?,
                    None => crate::declarations::decls::default_value(&sub),
                };
                let id = self.new_signal(&name.name, &sub, init, name.span);
                if decl.bus {
                    self.design.signals[id.index()].guarded = Some(design::GuardedKind::Bus);
                }
                Item::Signal {
                    id,
                    ty: sub.ty.clone(),
                }
            }
        })
    }
}
