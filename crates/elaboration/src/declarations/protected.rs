//! Protected types and shared variables (VHDL-2002, LRM 3.5): a shared variable's private
//! variables are one record on the simulation's heap, and its methods are subprograms whose
//! bodies read and write that record through its access value (`Instr::SetHeap`), so every
//! process that calls them sees the same object. Each shared variable elaborates the
//! methods of its type anew, bound to its own object.

use std::rc::Rc;

use vams_design::{Type, Value};
use vams_syntax::ast::{self, Decl, DeclKind};

use crate::error::ElabError;
use crate::names::scope::{Item, Scope};
use crate::names::types::{ProtectedTy, Sub, Ty};
use crate::{Elab, R};

impl<'a> Elab<'a> {
    /// `type t is protected ... end protected;`: the methods wait for the body.
    pub(crate) fn protected_type(
        &mut self,
        sc: &mut Scope<'a>,
        name: &ast::Ident,
        methods: &'a [Decl],
    ) -> R<()> {
        let ty = Ty::Protected(Rc::new(ProtectedTy {
            name: name.name.clone(),
            decl: name.span,
        }));
        self.pending.protected.insert(name.span, (methods, None));
        self.declare(sc, name, Item::Type(Rc::new(Sub::of(ty, &name.name))))
    }

    /// `type t is protected body ... end protected body;`: kept for the shared variables.
    pub(crate) fn protected_body(
        &mut self,
        sc: &Scope<'a>,
        name: &ast::Ident,
        decls: &'a [Decl],
    ) -> R<()> {
        let ty = self.resolved_item(sc, name);
        let Some(Item::Type(sub)) = ty else {
            return Err(self.error(ElabError::invalid(
                name.span,
                format!(
                    "`{}` is not a protected type declared before its body",
                    name.name
                ),
                None,
            )));
        };
        let Ty::Protected(p) = &sub.ty else {
            return Err(self.error(ElabError::invalid(
                name.span,
                format!("`{}` is not a protected type", name.name),
                None,
            )));
        };
        if let Some(entry) = self.pending.protected.get_mut(&p.decl) {
            entry.1 = Some(decls);
        }
        Ok(())
    }

    /// The declarations of protected body `name` in the body of the package being
    /// elaborated, if it has one there.
    fn protected_body_in_package_body(&self, name: &str) -> Option<&'a [Decl]> {
        let body = self.lib.bodies.get(&self.unit_at)?;
        body.unit.decls.iter().find_map(|d| match &d.kind {
            DeclKind::ProtectedBody { name: n, decls } if n.name == name => Some(decls.as_slice()),
            _ => None,
        })
    }

    /// A shared variable of a type that is not protected: a record of one field on the heap
    /// (so that it is read and written as a protected type's private variable is), with the
    /// declaration's initial value.
    fn plain_shared_variable(
        &mut self,
        sc: &mut Scope<'a>,
        names: &[ast::Ident],
        sub: &crate::names::types::Sub,
        value: Option<&ast::Expr>,
    ) -> R<()> {
        let init = match value {
            Some(e) => self.static_value(sc, e, &sub.ty, "a shared variable's initial value")?,
            None => crate::declarations::decls::default_value(sub),
        };
        for n in names {
            let object = Value::Access(self.design.shared_objects.len() as u32 + 1);
            self.design
                .shared_objects
                .push(Value::Array(vec![init.clone()]));
            let record = Type::Record {
                name: n.name.clone(),
                fields: vec![(n.name.clone(), sub.ty.to_design())],
            };
            let item = Item::PrivateVariable {
                object,
                field: 0,
                record,
                ty: sub.ty.clone(),
            };
            self.declare(sc, n, item)?;
        }
        Ok(())
    }

    /// `shared variable v : t;` of a protected type: its object and its methods. Of any
    /// other type (VHDL-93's shared variables, which VHDL-2002 reserves to protected types
    /// and textbooks still use): one object on the heap that every process reads and writes.
    pub(crate) fn shared_variable(
        &mut self,
        sc: &mut Scope<'a>,
        names: &[ast::Ident],
        subtype: &ast::SubtypeIndication,
        value: Option<&ast::Expr>,
        span: vams_syntax::source::Span,
    ) -> R<()> {
        let sub = self.subtype_indication(sc, subtype)?;
        let Ty::Protected(p) = &sub.ty else {
            return self.plain_shared_variable(sc, names, &sub, value);
        };
        let Some(&(methods, body)) = self.pending.protected.get(&p.decl) else {
            return Err(crate::Reported);
        };
        // A shared variable of a package declaration whose type's body is in the package
        // body (the usual layout): that body, elaborated where the variable is declared.
        let body = body.or_else(|| self.protected_body_in_package_body(&p.name));
        let Some(body) = body else {
            return Err(self.error(ElabError::invalid(
                span,
                format!(
                    "the protected type `{}` has no body before this declaration",
                    p.name
                ),
                Some("put `type ... is protected body ... end protected body;` first".into()),
            )));
        };
        for n in names {
            let object = Value::Access(self.design.shared_objects.len() as u32 + 1);
            let mut inner = sc.clone();
            inner.push();
            self.decls(&mut inner, methods);
            inner.push();
            // Types and constants first, in order, with the private variables and their
            // initial values (the object's record); then the subprograms, whose bodies see
            // the private variables.
            let mut fields = Vec::new();
            let mut values = Vec::new();
            for d in body {
                if matches!(
                    d.kind,
                    DeclKind::Subprogram(_) | DeclKind::SubprogramBody { .. }
                ) {
                    continue;
                }
                if let DeclKind::Variable {
                    names,
                    subtype,
                    value,
                    ..
                } = &d.kind
                {
                    let s = self.subtype_indication(&inner, subtype)?;
                    let v = match value {
                        Some(e) => self.static_value(
                            &inner,
                            e,
                            &s.ty,
                            "a private variable's initial value",
                        )?,
                        None => crate::declarations::decls::default_value(&s),
                    };
                    for vn in names {
                        fields.push((vn.clone(), s.ty.clone()));
                        values.push(v.clone());
                    }
                } else {
                    self.decl(&mut inner, d);
                }
            }
            let record = Type::Record {
                name: p.name.clone(),
                fields: fields
                    .iter()
                    .map(|(n, t)| (n.name.clone(), t.to_design()))
                    .collect(),
            };
            for (field, (vn, ty)) in fields.into_iter().enumerate() {
                let item = Item::PrivateVariable {
                    object: object.clone(),
                    field,
                    record: record.clone(),
                    ty,
                };
                self.declare(&mut inner, &vn, item)?;
            }
            for d in body {
                if matches!(
                    d.kind,
                    DeclKind::Subprogram(_) | DeclKind::SubprogramBody { .. }
                ) {
                    self.decl(&mut inner, d);
                }
            }
            self.design.shared_objects.push(Value::Array(values));
            let methods = inner.regions[inner.regions.len() - 2].items.clone();
            let item = Item::SharedObject {
                ty: sub.ty.clone(),
                methods,
            };
            self.declare(sc, n, item)?;
        }
        Ok(())
    }

    /// The methods named `suffix` of the shared variable `prefix` names, if it names one.
    pub(crate) fn methods(
        &mut self,
        sc: &Scope<'a>,
        prefix: &ast::Expr,
        suffix: &ast::Ident,
    ) -> Option<R<Vec<Item<'a>>>> {
        let (ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id)) = &prefix.kind else {
            return None;
        };
        let Some(Item::SharedObject { methods, ty }) = self.resolved_item(sc, id) else {
            return None;
        };
        Some(match methods.get(&suffix.name) {
            Some(items) if !items.is_empty() => Ok(items.clone()),
            _ => Err(self.error(ElabError::Undeclared {
                span: suffix.span,
                name: suffix.name.clone(),
                help: Some(format!("the protected type `{ty}` declares no such method")),
            })),
        })
    }
}
