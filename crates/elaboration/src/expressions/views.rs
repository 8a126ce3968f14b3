//! An element or a slice of an object named where a whole object is expected: a port actual
//! (`in1 => parity(1)`, `d => bus(7 downto 4)`), a signal alias, a signal parameter
//! (`rising_edge(clocks(0))`), a sensitivity list, an attribute prefix (`bus(3)'event`). The
//! index or range must be static (LRM 1.1.1.2: a port actual is a globally static name).
//!
//! An element of a terminal or quantity array is that element's scalar object. An element or
//! slice of a signal becomes a view signal ([`SignalKind::View`]): a signal of its own for
//! events, attributes and sensitivity, whose value the kernel derives from the parent's
//! elements and whose assignments drive them. One view per distinct element or slice.

use std::rc::Rc;

use vams_design::{Expr, Signal, SignalId, SignalKind};
use vams_syntax::ast::{self, Actual, ExprKind};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::expressions::expr::Typed;
use crate::names::scope::{Item, Part, Scope};
use crate::names::types::{ArrayTy, Ty, bounds_len};
use crate::{Elab, R};

impl<'a> Elab<'a> {
    /// What `prefix(args)` denotes as an object: an element of a terminal or quantity array,
    /// or a view of a signal's element or slice.
    pub(crate) fn element_item(
        &mut self,
        sc: &Scope<'a>,
        e: &ast::Expr,
        prefix: &ast::Expr,
        args: &[ast::Assoc],
    ) -> R<Item<'a>> {
        let items = self.lookup(sc, prefix)?;
        // A slice of a terminal or quantity array (`n(1 to 2)`, `v(2 to 3)`): the array of
        // its elements.
        if let [
            ast::Assoc {
                formal: None,
                actual: Actual::Range(range),
                ..
            },
        ] = args
        {
            match &items[0] {
                Item::TerminalArray { elements, nature } => {
                    let (elements, nature) = (elements.clone(), *nature);
                    let elements = self.slice_elements(sc, &elements, range, e.span)?;
                    return Ok(Item::TerminalArray { elements, nature });
                }
                Item::QuantityArray(elements) => {
                    let elements = elements.clone();
                    let elements = self.slice_elements(sc, &elements, range, e.span)?;
                    return Ok(Item::QuantityArray(elements));
                }
                _ => {}
            }
        }
        match &items[0] {
            Item::TerminalArray { nature, .. } => {
                let nature = *nature;
                let (id, _) = self.indexed_terminal(sc, prefix, args, e.span)?;
                Ok(Item::Terminal { id, nature })
            }
            Item::QuantityArray(elements) => {
                let elements = elements.clone();
                Ok(Item::Quantity(self.indexed_quantity(
                    sc, &elements, args, e.span,
                )?))
            }
            Item::Signal {
                id,
                ty: Ty::Array(a),
            } if a.bounds.is_some() => {
                let (id, a) = (*id, a.clone());
                self.signal_view(sc, e, id, &a, args)
            }
            Item::Variable {
                id,
                ty: ty @ Ty::Array(a),
                readonly,
                path,
            } => {
                let (id, readonly) = (*id, *readonly);
                let (container, element) = (ty.to_design(), a.element.clone());
                let mut path = path.to_vec();
                let (part, ty) = match args {
                    [
                        ast::Assoc {
                            actual: Actual::Expr(ie),
                            formal: None,
                            ..
                        },
                    ] => {
                        let what = format!("the index of `{}`", self.sources.snippet(e.span));
                        let i = self.static_int(sc, ie, &what)?;
                        let index = Expr::Const(vams_design::Value::Integer(i));
                        (Part::Element { index, container }, element)
                    }
                    [
                        ast::Assoc {
                            actual: Actual::Range(r),
                            formal: None,
                            ..
                        },
                    ] => {
                        let (first, len, ty) = self.slice(sc, a, r, e.span)?;
                        (Part::Slice { first, len }, ty)
                    }
                    _ => {
                        return Err(self.error(ElabError::unsupported(
                            e.span,
                            "multi-dimensional indexing",
                            "index one element: `v(i)`",
                        )));
                    }
                };
                path.push(part);
                Ok(Item::Variable {
                    id,
                    ty,
                    readonly,
                    path: path.into(),
                })
            }
            // `to_bit(s)`, `integer(s)`: a conversion, in a port map or a signal parameter.
            Item::Subprogram(_) | Item::Type(_) => Err(self.error(ElabError::unsupported(
                e.span,
                "a conversion function or type conversion as the actual of a port or signal parameter",
                "convert in a signal assignment of its own (`b_bit <= to_bit(b);`, one delta cycle later) and associate that signal",
            ))),
            _ => Err(self.error(ElabError::unsupported(
                e.span,
                "an element or a slice where a whole object is named",
                "vams associates, aliases and drives whole signals, and elements or slices of signal, quantity and terminal arrays, here",
            ))),
        }
    }

    /// `e` where a signal is expected (an attribute's prefix, a sensitivity list, a signal
    /// parameter's actual): a view for a static element or slice of an array signal or a
    /// field of a record signal, else `e` as an expression.
    pub(crate) fn signal_expr(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> R<Typed> {
        if let ExprKind::Apply(prefix, args) = &e.kind
            && let ExprKind::Name(id) | ExprKind::Selected(_, id) = &prefix.kind
            && let Some(Item::Signal {
                ty: Ty::Array(_), ..
            }) = self.resolved_item(sc, id)
            && let Item::Signal { id, ty } = self.element_item(sc, e, prefix, args)?
        {
            return Ok(Typed::new(Expr::Signal(id), ty));
        }
        if let ExprKind::Selected(prefix, suffix) = &e.kind
            && !self.analysed.names.contains_key(&suffix.span)
            && let ExprKind::Name(id) | ExprKind::Selected(_, id) = &prefix.kind
            && let Some(Item::Signal {
                ty: Ty::Record(_), ..
            }) = self.resolved_item(sc, id)
            && let Some(Item::Signal { id, ty }) = self.lookup(sc, e)?.first()
        {
            return Ok(Typed::new(Expr::Signal(*id), ty.clone()));
        }
        self.expr(sc, e, None)
    }

    /// The view of `parent(args)`, `parent` an array signal of type `a`: an element for a
    /// static index, a slice for a static range.
    fn signal_view(
        &mut self,
        sc: &Scope<'a>,
        e: &ast::Expr,
        parent: SignalId,
        a: &Rc<ArrayTy>,
        args: &[ast::Assoc],
    ) -> R<Item<'a>> {
        // Guarded by the caller.
        let (left, right, asc) = a.bounds.expect("a constrained array");
        let position = |i: i64| -> Option<usize> {
            let (lo, hi) = if asc { (left, right) } else { (right, left) };
            (lo..=hi)
                .contains(&i)
                .then(|| (if asc { i - left } else { left - i }) as usize)
        };
        let range_text = || format!("{left} {} {right}", if asc { "to" } else { "downto" });
        let name = self.sources.snippet(e.span).to_string();
        let [arg] = args else {
            return Err(self.error(ElabError::unsupported(
                e.span,
                "multi-dimensional indexing",
                "index one element: `s(k)`",
            )));
        };
        let index = self.sources.snippet(arg.span).to_string();
        let (first, len, ty, span) = match &arg.actual {
            Actual::Expr(ie) => {
                let what = format!("the index of `{name}` (it names a signal element here)");
                let i = self.static_value(sc, ie, &a.index, &what)?;
                let i = crate::names::types::position(&i).unwrap_or(i64::MIN);
                let Some(k) = position(i) else {
                    return Err(self.error(ElabError::IndexRange {
                        span: ie.span,
                        name: name.clone(),
                        index: i,
                        range: range_text(),
                    }));
                };
                (k, None, a.element.clone(), ie.span)
            }
            Actual::Range(r) => {
                // A signal named here must be a static name (LRM 6.1): as an assignment
                // target a slice may have run-time bounds, not here.
                let Some((l, rr, dir)) = self.where_static(|me| me.range_bounds(sc, r))? else {
                    return Err(self.error(ElabError::NotStatic {
                        span: arg.span,
                        what: format!("the bounds of `{name}` (it names a signal slice here)"),
                    }));
                };
                let n = bounds_len(l, rr, dir);
                let (Some(k), Some(_)) = (position(l), position(rr)) else {
                    return Err(self.error(ElabError::invalid(
                        arg.span,
                        format!(
                            "the slice is outside the bounds {} of `{}`",
                            range_text(),
                            name
                        ),
                        None,
                    )));
                };
                if dir != asc || n == 0 {
                    return Err(self.error(ElabError::invalid(
                        arg.span,
                        format!("this slice of `{name}` is null or runs against its direction"),
                        Some(format!(
                            "the signal's index runs `{}`: slice it the same way",
                            if asc { "to" } else { "downto" }
                        )),
                    )));
                }
                (k, Some(n), a.with_bounds(Some((l, rr, dir))), arg.span)
            }
            Actual::Open(s) => {
                return Err(self.error(ElabError::invalid(*s, "expected an index", None)));
            }
        };
        let id = self.view(parent, (first, len), &ty, &format!("({index})"), span)?;
        Ok(Item::Signal { id, ty })
    }

    /// The view of field `suffix` of `parent`, a signal of record type `r`.
    pub(crate) fn field_view(
        &mut self,
        parent: SignalId,
        record: &Ty,
        suffix: &ast::Ident,
    ) -> R<Item<'a>> {
        let (pos, ty) = self.record_field(record, suffix, suffix.span)?;
        let id = self.view(
            parent,
            (pos, None),
            &ty,
            &format!(".{}", suffix.name),
            suffix.span,
        )?;
        Ok(Item::Signal { id, ty })
    }

    /// The view signal of `len` elements (one element: `None`) of `parent` from position
    /// `first`, of type `ty`, named `parent` followed by `suffix` (`(3)`, `.hours`); a view
    /// of a slice view is a view of the latter's parent. The kernel drives a signal by its
    /// top-level elements, so a part of one element (`s.pos.x`, `words(2)(7)`) has no view.
    fn view(
        &mut self,
        parent: SignalId,
        (first, len): (usize, Option<usize>),
        ty: &Ty,
        suffix: &str,
        span: Span,
    ) -> R<SignalId> {
        // An element of a gathered port is its actual's element; a slice, a gather of theirs.
        if let SignalKind::Gather { elements } = &self.design.signals[parent.index()].kind {
            let n = len.unwrap_or(1);
            let Some(parts) = elements.get(first..first + n).map(<[_]>::to_vec) else {
                return Err(crate::Reported);
            };
            return match (len, parts[0]) {
                (None, (root, None)) => Ok(root),
                (None, (root, Some(k))) => self.view(root, (k, None), ty, suffix, span),
                (Some(_), _) => {
                    let name = format!("{}{suffix}", self.design.signals[parent.index()].name);
                    Ok(self.gather_signal(name, ty, parts, span))
                }
            };
        }
        let (parent, first) = match self.design.signals[parent.index()].kind {
            SignalKind::View {
                parent: root,
                first: offset,
                len: Some(_),
            } => (root, offset + first),
            SignalKind::View { len: None, .. } => {
                return Err(self.error(ElabError::unsupported(
                    span,
                    "naming a part of one element of a composite signal as a signal",
                    "vams names and drives whole elements and fields of signals (`s(3)`, `s.f`): assign the whole element, or declare the part as its own signal",
                )));
            }
            _ => (parent, first),
        };
        if let Some(&id) = self.signals.views.get(&(parent, first, len)) {
            return Ok(id);
        }
        let p = &self.design.signals[parent.index()];
        // The caller checked the position against the parent's bounds.
        let init = p.init.view(first, len).unwrap_or_else(|| p.init.clone());
        let name = format!("{}{suffix}", p.name);
        let id = SignalId(self.design.signals.len() as u32);
        self.design.signals.push(Signal {
            name,
            ty: ty.to_design(),
            init,
            kind: SignalKind::View { parent, first, len },
            span,
            range: None,
            resolution: None,
            guarded: None,
        });
        self.signals.views.insert((parent, first, len), id);
        Ok(id)
    }
}

impl<'a> Elab<'a> {
    /// A signal port of an array type associated element by element (`port map (i(1) => a,
    /// i(2) => b, i(3 to 4) => pair)`): a gathered signal ([`SignalKind::Gather`]) whose
    /// elements are the actuals'. An unconstrained port takes the formals' indexes as its
    /// range, ascending from the lowest (LRM 3.2.1.1: the index subtype's direction; vams's
    /// array index subtypes ascend). Formal indexes and actuals are read in the instantiating
    /// scope `parent`.
    pub(crate) fn signal_port_elements(
        &mut self,
        sc: &Scope<'a>,
        parent: &Scope<'a>,
        name: &ast::Ident,
        decl: &ast::InterfaceDecl,
        assocs: &[&ast::Assoc],
    ) -> R<Item<'a>> {
        let sub = self.subtype_indication(sc, &decl.subtype)?;
        let full = self.hier_name(&name.name);
        let (id, ty) = self.gathered(parent, &name.name, full, &sub.ty, assocs, name.span)?;
        Ok(Item::Signal { id, ty })
    }

    /// The gathered signal (hierarchical name `full`) of formal `name` of type `ty`
    /// associated element by element by `assocs`, read in scope `parent`: a port's, or a
    /// signal parameter's (`all_possible_values(bv(0) => sel0, bv(1) => sel1, ...)`).
    pub(crate) fn gathered(
        &mut self,
        parent: &Scope<'a>,
        name: &str,
        full: String,
        ty: &Ty,
        assocs: &[&ast::Assoc],
        span: Span,
    ) -> R<(SignalId, Ty)> {
        let first = assocs.first().map_or(span, |a| a.span);
        let arr = match ty {
            Ty::Array(arr) if arr.dimensions() == 1 && arr.index == Ty::Integer => arr.clone(),
            _ => {
                return Err(self.error(ElabError::unsupported(
                    first,
                    format!("element associations of `{name}` of type {ty}"),
                    "associate it whole",
                )));
            }
        };
        // Each association's formal indexes, left to right.
        let mut formals = Vec::with_capacity(assocs.len());
        for a in assocs {
            let Some(ExprKind::Apply(_, args)) = a.formal.as_ref().map(|f| &f.kind) else {
                return Err(crate::Reported);
            };
            let at = match args.as_slice() {
                [
                    ast::Assoc {
                        actual: Actual::Range(r),
                        ..
                    },
                ] => crate::names::composite::indexes(self.range_bounds(parent, r)?),
                _ => {
                    let (i, _) = self.static_index(parent, args, name, a.span)?;
                    vec![i]
                }
            };
            formals.push((at, a));
        }
        let bounds = match arr.bounds {
            Some(b) => b,
            None => {
                let all = formals.iter().flat_map(|(at, _)| at.iter().copied());
                let (lo, hi) = all.fold((i64::MAX, i64::MIN), |(lo, hi), i| (lo.min(i), hi.max(i)));
                (lo, hi, true)
            }
        };
        let (left, right, ascending) = bounds;
        self.array_size(&[bounds], first)?;
        let count = bounds_len(left, right, ascending);
        let mut elements: Vec<Option<(SignalId, Option<usize>)>> = vec![None; count];
        for (at, a) in formals {
            let Actual::Expr(actual) = &a.actual else {
                return Err(self.error(ElabError::invalid(
                    a.span,
                    format!("an element of `{}` needs a signal", name),
                    Some("connect a signal to each element: `i(1) => a`".into()),
                )));
            };
            let whole = at.len() == 1
                && !matches!(a.formal.as_ref().map(|f| &f.kind),
                Some(ExprKind::Apply(_, args)) if matches!(args.as_slice(), [ast::Assoc { actual: Actual::Range(_), .. }]));
            let parts = self.gathered_actual(parent, actual, &arr, at.len(), whole, name)?;
            for (i, part) in at.into_iter().zip(parts) {
                let inside = if ascending {
                    left <= i && i <= right
                } else {
                    right <= i && i <= left
                };
                if !inside {
                    return Err(self.error(ElabError::invalid(
                        a.span,
                        format!("index {i} is outside `{}`'s range", name),
                        None,
                    )));
                }
                let pos = i.abs_diff(left) as usize;
                if elements[pos].replace(part).is_some() {
                    return Err(self.error(ElabError::invalid(
                        a.span,
                        format!("`{}({i})` is associated twice", name),
                        Some("associate each element of the port once".into()),
                    )));
                }
            }
        }
        let mut parts = Vec::with_capacity(count);
        for (pos, part) in elements.into_iter().enumerate() {
            let Some(part) = part else {
                let i = if ascending {
                    left + pos as i64
                } else {
                    left - pos as i64
                };
                return Err(self.error(ElabError::invalid(
                    first,
                    format!("element `{}({i})` of `{}` is not associated", name, name),
                    Some(format!(
                        "associate every element of `{}`, or the whole port",
                        name
                    )),
                )));
            };
            parts.push(part);
        }
        let ty = arr.with_bounds(Some(bounds));
        let id = self.gather_signal(full, &ty, parts, span);
        Ok((id, ty))
    }

    /// The parent elements an actual gives a gathered port: one element (`whole`, the actual
    /// a signal of the element type) or `n` elements of an array signal, each as a root
    /// signal (never a view) and a position in it (`None`: the whole scalar signal).
    fn gathered_actual(
        &mut self,
        parent: &Scope<'a>,
        actual: &ast::Expr,
        arr: &ArrayTy,
        n: usize,
        whole: bool,
        port: &str,
    ) -> R<Vec<(SignalId, Option<usize>)>> {
        let t = self.signal_expr(parent, actual)?;
        let Expr::Signal(s) = t.e else {
            return Err(self.error(ElabError::invalid(
                actual.span,
                format!("an element of port `{port}` needs a signal"),
                Some("connect a signal (or an element or slice of one) to each element".into()),
            )));
        };
        let expected = if whole {
            arr.element.clone()
        } else {
            arr.with_bounds(None)
        };
        if !t.ty.same(&expected) {
            return Err(self.error(ElabError::TypeMismatch {
                span: actual.span,
                expected: expected.to_string(),
                found: t.ty.to_string(),
                help: Some(format!(
                    "the elements of port `{port}` are of type {}",
                    arr.element
                )),
            }));
        }
        let parts = match (&self.design.signals[s.index()].kind, whole) {
            (
                SignalKind::View {
                    parent,
                    first,
                    len: None,
                },
                true,
            ) => vec![(*parent, Some(*first))],
            (
                SignalKind::View {
                    parent,
                    first,
                    len: Some(len),
                },
                false,
            ) => (*first..first + len).map(|k| (*parent, Some(k))).collect(),
            (SignalKind::Gather { elements }, false) => elements.clone(),
            (SignalKind::View { .. } | SignalKind::Gather { .. }, _) => {
                return Err(self.error(ElabError::unsupported(
                    actual.span,
                    "an element of a port associated element by element that is itself a part of a composite element",
                    "associate a signal of the element type",
                )));
            }
            (_, true) => vec![(s, None)],
            (_, false) => (0..self.design.signals[s.index()].init.elements().len())
                .map(|k| (s, Some(k)))
                .collect(),
        };
        if parts.len() != n {
            return Err(self.error(ElabError::invalid(
                actual.span,
                format!(
                    "the formal names {n} element(s) of `{port}`, the actual has {}",
                    parts.len()
                ),
                Some("associate a slice of the same length".into()),
            )));
        }
        Ok(parts)
    }

    /// A gathered signal of type `ty` with the hierarchical name `name` over root signal
    /// elements `parts`, its initial value theirs.
    fn gather_signal(
        &mut self,
        name: String,
        ty: &Ty,
        parts: Vec<(SignalId, Option<usize>)>,
        span: Span,
    ) -> SignalId {
        let elements = parts
            .iter()
            .map(|&(p, k)| {
                let init = &self.design.signals[p.index()].init;
                k.and_then(|k| init.view(k, None))
                    .unwrap_or_else(|| init.clone())
            })
            .collect();
        let string = matches!(ty, Ty::Array(a) if a.name == "string");
        let init = vams_design::aggregate_value(elements, string);
        let id = SignalId(self.design.signals.len() as u32);
        self.design.signals.push(Signal {
            name,
            ty: ty.to_design(),
            init,
            kind: SignalKind::Gather { elements: parts },
            span,
            range: None,
            resolution: None,
            guarded: None,
        });
        id
    }
}
