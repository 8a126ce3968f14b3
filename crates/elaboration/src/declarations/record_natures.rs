//! Record natures (LRM 1076.1 4.1.2, `nature electrical_bus is record strobe : electrical;
//! data : electrical_vector(0 to 7); end record;`) and record quantities: their terminals,
//! branch quantities and free quantities are expanded field by field into the scalar and
//! array objects the rest of elaboration knows (`ebus.strobe`, `ebus.data(3)`), and a
//! selected name `v.data` denotes a field's object.

use std::rc::Rc;

use vams_design::QuantityKind;
use vams_syntax::ast::{self, ExprKind, Ident};

use crate::error::ElabError;
use crate::names::composite::{NatureMark, RecordNature};
use crate::names::scope::{Item, RecordObject, Scope};
use crate::names::types::{Sub, Ty};
use crate::{Elab, R};

impl<'a> Elab<'a> {
    /// `nature n is record ... end record;`
    pub(crate) fn record_nature_decl(
        &mut self,
        sc: &mut Scope<'a>,
        name: &Ident,
        fields: &[ast::RecordField],
    ) -> R<()> {
        let mut out = Vec::new();
        for f in fields {
            let mark = self.nature_indication(sc, &f.subtype)?;
            if let NatureMark::Array(a) = &mark
                && a.bounds.is_none()
            {
                return Err(self.error(ElabError::invalid(
                    f.subtype.span,
                    format!(
                        "`{}` is unconstrained: a record field needs an index range",
                        a.name
                    ),
                    Some(format!("give the range: `{}(0 to 7)`", a.name)),
                )));
            }
            for n in &f.names {
                out.push((n.name.clone(), mark.clone()));
            }
        }
        let nature = Rc::new(RecordNature {
            name: name.name.clone(),
            fields: out,
        });
        self.declare(sc, name, Item::RecordNature(nature))
    }

    /// New terminals for a terminal `name` of record nature `nature`, named `name.field`.
    pub(crate) fn new_record_terminal(
        &mut self,
        name: &str,
        nature: &RecordNature,
        span: vams_syntax::source::Span,
    ) -> R<Item<'a>> {
        let mut fields = Vec::new();
        for (field, mark) in &nature.fields {
            let full = format!("{name}.{field}");
            let item = match mark {
                NatureMark::Scalar(n) => Item::Terminal {
                    id: self.new_terminal(&full, *n, span),
                    nature: *n,
                },
                NatureMark::Array(a) => self.new_terminal_array_item(&full, a, span)?,
                NatureMark::Record(r) => self.new_record_terminal(&full, r, span)?,
            };
            fields.push((field.clone(), item));
        }
        Ok(Item::TerminalRecord(Rc::new(RecordObject { fields })))
    }

    /// The field object `e` denotes when `e` selects a field of a record terminal or
    /// quantity (`ebus.strobe`, `v.data`, nested `v.a.b`); `None` for any other name.
    pub(crate) fn record_part(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> Option<Item<'a>> {
        let ExprKind::Selected(prefix, suffix) = &e.kind else {
            return None;
        };
        if self.analysed.names.contains_key(&suffix.span) {
            return None;
        }
        let record = match &prefix.kind {
            ExprKind::Name(id) => self.resolved_item(sc, id)?,
            ExprKind::Selected(..) => self.record_part(sc, prefix)?,
            _ => return None,
        };
        match record {
            Item::TerminalRecord(r) | Item::QuantityRecord(r) => r.field(&suffix.name).cloned(),
            _ => None,
        }
    }

    /// A branch quantity declaration between terminals of a record nature: for each field,
    /// the branch quantities of that field's terminals, gathered into record quantities.
    /// `make` declares one field's branch (the scalar or array case) and returns its across
    /// and through objects in declaration order.
    pub(crate) fn record_branch(
        &mut self,
        plus: &RecordObject<'a>,
        minus: Option<&Item<'a>>,
        names: &[&Ident],
        span: vams_syntax::source::Span,
        make: &mut FieldBranch<'_, 'a>,
    ) -> R<Vec<Item<'a>>> {
        let mut per_name: Vec<Vec<(String, Item<'a>)>> = vec![Vec::new(); names.len()];
        for (field, p) in &plus.fields {
            // The minus end: the same field of a record terminal, or one scalar terminal
            // (a reference) for every field.
            let m = match minus {
                Some(Item::TerminalRecord(m)) => Some(m.field(field).ok_or_else(|| {
                    self.error(ElabError::invalid(
                        span,
                        format!("the ends of this branch are records of different natures (no field `{field}`)"),
                        Some("both ends of a branch must have the same nature".into()),
                    ))
                })?),
                other => other,
            };
            let items = match p {
                Item::TerminalRecord(pr) => self.record_branch(pr, m, names, span, make)?,
                p => make(self, field, p, m)?,
            };
            for (slot, item) in per_name.iter_mut().zip(items) {
                slot.push((field.clone(), item));
            }
        }
        Ok(names
            .iter()
            .zip(per_name)
            .map(|(_, fields)| Item::QuantityRecord(Rc::new(RecordObject { fields })))
            .collect())
    }

    /// `quantity q : rec;` of a record type whose fields are reals or arrays of reals: free
    /// quantities `q.f`, one per field (element).
    pub(crate) fn record_quantity(
        &mut self,
        name: &str,
        ty: &Ty,
        sub: &Sub,
        span: vams_syntax::source::Span,
    ) -> R<Item<'a>> {
        let Ty::Record(r) = ty else {
            return Err(self.error(ElabError::unsupported(
                span,
                format!("quantities of type {ty}"),
                "quantities are reals, arrays of reals or records of them",
            )));
        };
        let mut fields = Vec::new();
        for (field, fty) in &r.fields {
            let full = format!("{name}.{field}");
            let element = Sub {
                name: "real".into(),
                ty: Ty::Real,
                ..sub.clone()
            };
            let item = match fty {
                Ty::Real => Item::Quantity(self.new_quantity(
                    &full,
                    QuantityKind::Free,
                    &element,
                    None,
                    None,
                    span,
                )),
                Ty::Array(a) if a.element == Ty::Real => {
                    let Some(bounds) = a.bounds else {
                        return Err(self.error(ElabError::invalid(
                            span,
                            format!("field `{field}` is unconstrained: a quantity needs bounds"),
                            None,
                        )));
                    };
                    let ids = crate::names::composite::indexes(bounds)
                        .into_iter()
                        .map(|i| {
                            self.new_quantity(
                                &format!("{full}({i})"),
                                QuantityKind::Free,
                                &element,
                                None,
                                None,
                                span,
                            )
                        })
                        .collect();
                    Item::QuantityArray(Rc::new(crate::names::composite::Elements {
                        name: full.clone(),
                        left: bounds.0,
                        ascending: bounds.2,
                        ids,
                    }))
                }
                Ty::Record(_) => self.record_quantity(&full, fty, sub, span)?,
                other => {
                    return Err(self.error(ElabError::unsupported(
                        span,
                        format!("quantities with a field of type {other}"),
                        "a record quantity's fields are reals or arrays of reals",
                    )));
                }
            };
            fields.push((field.clone(), item));
        }
        Ok(Item::QuantityRecord(Rc::new(RecordObject { fields })))
    }
}

/// Declares the branch quantities of one field (its name, its plus and minus objects) and
/// returns them, one per name.
pub(crate) type FieldBranch<'f, 'a> =
    dyn FnMut(&mut Elab<'a>, &str, &Item<'a>, Option<&Item<'a>>) -> R<Vec<Item<'a>>> + 'f;
