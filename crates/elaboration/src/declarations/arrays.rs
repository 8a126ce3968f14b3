//! Array natures, terminal arrays and quantity arrays. The design stays scalar: an array object
//! is expanded at its declaration into one scalar terminal or quantity per element, named
//! `name(i)` like generate instances (`gen(3).x`), and an indexed name `n(k)` with a static
//! index denotes that element wherever a terminal or a quantity is expected.

use std::rc::Rc;

use vams_design::{QuantityId, QuantityKind, TerminalId, Value};
use vams_syntax::ast::{self, Actual, ExprKind, Ident, IndexDef};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::names::composite::{ArrayNature, Elements, NatureMark, index_at, indexes};
use crate::names::scope::{Item, Scope};
use crate::names::types::{Sub, Ty};
use crate::{Elab, R, Reported};

impl<'a> Elab<'a> {
    pub(crate) fn array_nature_decl(
        &mut self,
        sc: &mut Scope<'a>,
        name: &Ident,
        index_defs: &[IndexDef],
        element: &ast::SubtypeIndication,
        span: Span,
    ) -> R<()> {
        let NatureMark::Scalar(element) = self.nature_indication(sc, element)? else {
            return Err(self.error(ElabError::unsupported(
                span,
                "array natures of array natures",
                "use a one-dimensional array of a scalar nature",
            )));
        };
        let [index] = index_defs else {
            // Several dimensions: declared (and read by attributes) with constrained ranges.
            let mut dims = Vec::with_capacity(index_defs.len());
            for index in index_defs {
                let IndexDef::Constrained(r) = index else {
                    return Err(self.error(ElabError::unsupported(
                        span,
                        "unconstrained multi-dimensional array natures",
                        "give each index a range",
                    )));
                };
                let (l, r, asc, ty) = self.discrete_range_typed(sc, r)?;
                dims.push((Some((l, r, asc)), l.min(r), ty));
            }
            let nature = ArrayNature {
                name: name.name.clone(),
                element,
                bounds: dims[0].0,
                shape: Some(crate::declarations::decls::array_type(
                    &name.name,
                    dims,
                    Ty::Real,
                )),
            };
            if sc.declare_at(&name.name, name.span, Item::ArrayNature(Rc::new(nature))) {
                return Ok(());
            }
            return Err(self.error(ElabError::Redeclared {
                span: name.span,
                name: name.name.clone(),
            }));
        };
        let bounds = match index {
            IndexDef::Unconstrained(mark) => {
                if self.type_mark(sc, mark)?.ty != Ty::Integer {
                    return Err(self.error(ElabError::unsupported(
                        mark.span,
                        "array natures indexed by a non-integer type",
                        "index the nature with `natural range <>` or an integer range",
                    )));
                }
                None
            }
            IndexDef::Constrained(r) => Some(self.discrete_range(sc, r)?),
        };
        let nature = ArrayNature {
            name: name.name.clone(),
            element,
            bounds,
            shape: None,
        };
        if sc.declare_at(&name.name, name.span, Item::ArrayNature(Rc::new(nature))) {
            Ok(())
        } else {
            Err(self.error(ElabError::Redeclared {
                span: name.span,
                name: name.name.clone(),
            }))
        }
    }

    /// A nature mark, possibly with an index constraint: `electrical`,
    /// `electrical_vector(0 to n)`.
    pub(crate) fn nature_indication(
        &mut self,
        sc: &Scope<'a>,
        si: &ast::SubtypeIndication,
    ) -> R<NatureMark> {
        let (mark, constraint) = match &si.type_mark.kind {
            ExprKind::Apply(mark, args) => (&**mark, Some(args)),
            _ => (&si.type_mark, None),
        };
        let items = self.lookup(sc, mark)?;
        let nature = match &items[0] {
            Item::Nature(n) if constraint.is_none() => return Ok(NatureMark::Scalar(*n)),
            Item::RecordNature(r) if constraint.is_none() => {
                return Ok(NatureMark::Record(r.clone()));
            }
            Item::ArrayNature(a) if a.shape.is_some() => {
                return Err(self.error(ElabError::unsupported(
                    mark.span,
                    format!("terminals of `{}`, a multi-dimensional array nature", a.name),
                    "declare a one-dimensional array nature of the same element nature and index it by row and column",
                )));
            }
            Item::ArrayNature(a) => a.clone(),
            other => {
                let (found, help) = match other {
                    Item::Nature(_) => (
                        "a scalar nature".to_string(),
                        "only array natures take an index range".to_string(),
                    ),
                    _ => (
                        other.class().to_string(),
                        "terminals are declared with a nature: `terminal p : electrical;`"
                            .to_string(),
                    ),
                };
                return Err(self.error(ElabError::WrongClass {
                    span: mark.span,
                    name: self.sources.snippet(mark.span).into(),
                    found,
                    expected: "a nature".into(),
                    help: Some(help),
                }));
            }
        };
        let Some(args) = constraint else {
            return Ok(NatureMark::Array(nature));
        };
        if nature.bounds.is_some() {
            return Err(self.error(ElabError::invalid(
                si.type_mark.span,
                format!("`{}` is already constrained", nature.name),
                Some(format!("use `{}` without an index range", nature.name)),
            )));
        }
        let bounds = self.index_constraint(sc, args, si.type_mark.span)?;
        Ok(NatureMark::Array(Rc::new(ArrayNature {
            name: nature.name.clone(),
            element: nature.element,
            bounds: Some(bounds),
            shape: None,
        })))
    }

    /// The one range of an index constraint `(0 to n)` (or `(v'range)`).
    fn index_constraint(
        &mut self,
        sc: &Scope<'a>,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<(i64, i64, bool)> {
        let [ast::Assoc { actual, .. }] = args else {
            return Err(self.error(ElabError::unsupported(
                span,
                "multi-dimensional index constraints",
                "use one range",
            )));
        };
        let (l, r, asc) = match actual {
            Actual::Range(r) => self.range_bounds(sc, r)?,
            Actual::Expr(e) => {
                self.range_bounds(sc, &ast::Range::Attribute(Box::new(e.clone())))?
            }
            Actual::Open(s) => {
                return Err(self.error(ElabError::invalid(*s, "expected a range", None)));
            }
        };
        self.array_size(&[(l, r, asc)], span)?;
        Ok((l, r, asc))
    }

    /// `electrical'across`, `electrical_vector'through`: the across or through subtype of a
    /// nature; of an array nature, a `real_vector` subtype with the element's tolerance and unit.
    pub(crate) fn nature_subtype(
        &mut self,
        sc: &Scope<'a>,
        prefix: &ast::Expr,
        attr: &Ident,
        span: Span,
    ) -> R<Rc<Sub>> {
        let items = self.lookup(sc, prefix)?;
        let (element, bounds) = match &items[0] {
            Item::Nature(n) => (*n, None),
            Item::ArrayNature(a) => (a.element, Some(a.bounds)),
            other => {
                return Err(self.error(ElabError::WrongClass {
                    span: prefix.span,
                    name: self.sources.snippet(prefix.span).into(),
                    found: other.class().into(),
                    expected: "a nature".into(),
                    help: Some("`'across` and `'through` name the subtypes of a nature".into()),
                }));
            }
        };
        let info = &self.analog.natures[element];
        let scalar = match attr.name.as_str() {
            "across" => info.across.clone(),
            "through" => info.through.clone(),
            _ => {
                return Err(self.error(ElabError::unsupported(
                    span,
                    format!("subtypes of the form `nature'{}`", attr.name),
                    "a subtype of a nature is `N'across` or `N'through`",
                )));
            }
        };
        let Some(bounds) = bounds else {
            return Ok(scalar);
        };
        let Some(Ty::Array(arr)) = self.standard_type("real_vector") else {
            return Err(crate::Reported);
        };
        let ty = arr.with_bounds(bounds);
        Ok(Rc::new(Sub {
            ty,
            name: format!("{}'{}", self.sources.snippet(prefix.span), attr.name).into(),
            tolerance: scalar.tolerance.clone(),
            unit: scalar.unit.clone(),
            range: None,
            resolution: None,
        }))
    }

    /// The bounds an array object of `nature` is declared with; unconstrained is an error.
    fn object_bounds(&mut self, nature: &ArrayNature, span: Span) -> R<(i64, i64, bool)> {
        nature.bounds.ok_or_else(|| {
            self.error(ElabError::invalid(
                span,
                format!(
                    "`{}` is unconstrained: this terminal needs an index range",
                    nature.name
                ),
                Some(format!("give the range: `{}(0 to 7)`", nature.name)),
            ))
        })
    }

    /// `terminal n : electrical_vector(0 to 3);`: the scalar terminals `n(0)` ... `n(3)`.
    pub(crate) fn terminal_array_decl(
        &mut self,
        sc: &mut Scope<'a>,
        name: &Ident,
        nature: &ArrayNature,
    ) -> R<()> {
        let bounds = self.object_bounds(nature, name.span)?;
        let elements = self.new_terminal_array(&name.name, nature.element, bounds, name.span);
        let item = Item::TerminalArray {
            elements,
            nature: nature.element,
        };
        if sc.declare_at(&name.name, name.span, item) {
            Ok(())
        } else {
            Err(self.error(ElabError::Redeclared {
                span: name.span,
                name: name.name.clone(),
            }))
        }
    }

    /// New terminals for a terminal array of the (constrained) array nature `nature`.
    pub(crate) fn new_terminal_array_item(
        &mut self,
        name: &str,
        nature: &ArrayNature,
        span: Span,
    ) -> R<Item<'a>> {
        let bounds = self.object_bounds(nature, span)?;
        Ok(Item::TerminalArray {
            elements: self.new_terminal_array(name, nature.element, bounds, span),
            nature: nature.element,
        })
    }

    fn new_terminal_array(
        &mut self,
        name: &str,
        nature: usize,
        bounds: (i64, i64, bool),
        span: Span,
    ) -> Rc<Elements<TerminalId>> {
        let ids = indexes(bounds)
            .into_iter()
            .map(|i| self.new_terminal(&format!("{name}({i})"), nature, span))
            .collect();
        Rc::new(Elements {
            name: name.to_string(),
            left: bounds.0,
            ascending: bounds.2,
            ids,
        })
    }

    /// The element `index` of `elements`, with a diagnostic at `span` when out of range.
    fn element<T: Copy>(&mut self, elements: &Elements<T>, index: i64, span: Span) -> R<T> {
        elements.get(index).ok_or_else(|| {
            self.error(ElabError::IndexRange {
                span,
                name: elements.name.clone(),
                index,
                range: elements.range_text(),
            })
        })
    }

    /// The static index of `prefix(args)`: one positional expression.
    pub(crate) fn static_index(
        &mut self,
        sc: &Scope<'a>,
        args: &[ast::Assoc],
        name: &str,
        span: Span,
    ) -> R<(i64, Span)> {
        let [
            ast::Assoc {
                formal: None,
                actual: Actual::Expr(ie),
                ..
            },
        ] = args
        else {
            return Err(self.error(ElabError::unsupported(
                span,
                format!("slices of `{name}` and multi-dimensional indexing"),
                "index one element: `n(k)`",
            )));
        };
        let what = format!("the index of `{name}`");
        Ok((self.static_int(sc, ie, &what)?, ie.span))
    }

    /// `n(k)` where `n` is a terminal array: `(element, nature)`.
    pub(crate) fn indexed_terminal(
        &mut self,
        sc: &Scope<'a>,
        prefix: &ast::Expr,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<(TerminalId, usize)> {
        let items = self.lookup(sc, prefix)?;
        let Item::TerminalArray { elements, nature } = &items[0] else {
            return Err(self.error(ElabError::WrongClass {
                span: prefix.span,
                name: self.sources.snippet(prefix.span).into(),
                found: items[0].class().into(),
                expected: "a terminal array".into(),
                help: Some(
                    "only terminal arrays are indexed here: `terminal n : electrical_vector(0 to 3);`"
                        .into(),
                ),
            }));
        };
        let (index, index_span) = self.static_index(sc, args, &elements.name, span)?;
        Ok((self.element(elements, index, index_span)?, *nature))
    }

    /// `q(k)` where `q` is a quantity array.
    pub(crate) fn indexed_quantity(
        &mut self,
        sc: &Scope<'a>,
        elements: &Elements<QuantityId>,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<QuantityId> {
        let (index, index_span) = self.static_index(sc, args, &elements.name, span)?;
        self.element(elements, index, index_span)
    }

    /// `n(1 to 2)` where `n` is a terminal array, with a static range in `n`'s direction:
    /// the slice's elements and their nature. `None` when `e` is no slice of a terminal
    /// array.
    pub(crate) fn terminal_slice(
        &mut self,
        sc: &Scope<'a>,
        e: &ast::Expr,
    ) -> Option<R<(Rc<Elements<TerminalId>>, usize)>> {
        let ast::ExprKind::Apply(prefix, args) = &e.kind else {
            return None;
        };
        let [
            ast::Assoc {
                formal: None,
                actual: Actual::Range(range),
                ..
            },
        ] = args.as_slice()
        else {
            return None;
        };
        let (ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id)) = &prefix.kind else {
            return None;
        };
        let Some(Item::TerminalArray { elements, nature }) = self.resolved_item(sc, id) else {
            return None;
        };
        Some(
            self.slice_elements(sc, &elements, range, e.span)
                .map(|s| (s, nature)),
        )
    }

    /// The elements of `elements` in the static `range` (which runs in their direction).
    pub(crate) fn slice_elements<T: Copy>(
        &mut self,
        sc: &Scope<'a>,
        elements: &Elements<T>,
        range: &ast::Range,
        span: Span,
    ) -> R<Rc<Elements<T>>> {
        let (left, right, ascending) = self.range_bounds(sc, range)?;
        let null = if ascending {
            left > right
        } else {
            left < right
        };
        if !null && ascending != elements.ascending && elements.ids.len() > 1 {
            return Err(self.error(ElabError::invalid(
                span,
                "this slice runs against its array's direction",
                Some(format!(
                    "`{}` is indexed {}",
                    elements.name,
                    elements.range_text()
                )),
            )));
        }
        let mut ids = Vec::new();
        if !null {
            // Both ends inside the array before any element is collected.
            for end in [left, right] {
                self.element(elements, end, span)?;
            }
            ids = indexes((left, right, ascending))
                .into_iter()
                .filter_map(|i| elements.get(i))
                .collect();
        }
        Ok(Rc::new(Elements {
            name: self.sources.snippet(span).to_string(),
            left,
            ascending,
            ids,
        }))
    }

    /// A terminal port of an array nature: the actual's elements (whole-array association,
    /// matched by position), or fresh terminals when it is open.
    pub(crate) fn terminal_array_port(
        &mut self,
        name: &Ident,
        nature: &ArrayNature,
        actual: Option<(&ast::Expr, &Scope<'a>)>,
    ) -> R<Item<'a>> {
        let Some((e, parent)) = actual else {
            let bounds = self.object_bounds(nature, name.span)?;
            let elements = self.new_terminal_array(&name.name, nature.element, bounds, name.span);
            return Ok(Item::TerminalArray {
                elements,
                nature: nature.element,
            });
        };
        let items = match self.terminal_slice(parent, e) {
            Some(slice) => {
                let (elements, nature) = slice?;
                vec![Item::TerminalArray { elements, nature }]
            }
            None => self.lookup(parent, e)?,
        };
        let Item::TerminalArray {
            elements: actual,
            nature: actual_nature,
        } = &items[0]
        else {
            return Err(self.error(ElabError::PortClass {
                span: e.span,
                port: name.name.clone(),
                expected: format!("terminal array ({})", nature.name),
                found: items[0].class().into(),
                help: Some(format!(
                    "connect a terminal of nature {} (or `open`) to `{}`",
                    nature.name, name.name
                )),
            }));
        };
        if !self.same_nature(*actual_nature, nature.element) {
            let (a, b) = (
                self.analog.natures[nature.element].name.clone(),
                self.analog.natures[*actual_nature].name.clone(),
            );
            return Err(self.error(ElabError::TypeMismatch {
                span: e.span,
                expected: format!("a terminal array of nature {a}"),
                found: format!("a terminal array of nature {b}"),
                help: Some("a terminal port connects to a terminal of the same nature".into()),
            }));
        }
        let (left, ascending) = match nature.bounds {
            None => (actual.left, actual.ascending),
            Some(bounds) => {
                let len = indexes(bounds).len();
                if len != actual.ids.len() {
                    return Err(self.error(ElabError::invalid(
                        e.span,
                        format!(
                            "port `{}` has {len} elements, but `{}` has {} ({})",
                            name.name,
                            actual.name,
                            actual.ids.len(),
                            actual.range_text()
                        ),
                        Some("connect an array of the same length".into()),
                    )));
                }
                (bounds.0, bounds.2)
            }
        };
        Ok(Item::TerminalArray {
            elements: Rc::new(Elements {
                name: name.name.clone(),
                left,
                ascending,
                ids: actual.ids.clone(),
            }),
            nature: nature.element,
        })
    }

    /// A terminal port of a constrained array nature associated element by element,
    /// `port map (t(1) => a, t(2) => b)`: each element exactly once, formal indexes and actuals
    /// read in the instantiating scope `parent`.
    pub(crate) fn terminal_port_elements(
        &mut self,
        sc: &Scope<'a>,
        parent: &Scope<'a>,
        name: &Ident,
        decl: &ast::InterfaceDecl,
        assocs: &[&ast::Assoc],
    ) -> R<Item<'a>> {
        let first = assocs.first().map_or(name.span, |a| a.span);
        if decl.class != Some(ast::ObjectClass::Terminal) {
            return Err(self.error(ElabError::unsupported(
                first,
                format!("element associations of port `{}`", name.name),
                "only terminal array ports are associated element by element; associate the whole port",
            )));
        }
        let NatureMark::Array(nature) = self.nature_indication(sc, &decl.subtype)? else {
            return Err(self.error(ElabError::invalid(
                first,
                format!(
                    "port `{}` is a scalar terminal: it has no elements",
                    name.name
                ),
                Some(format!("associate it whole: `{} => p`", name.name)),
            )));
        };
        let bounds = self.object_bounds(&nature, name.span)?;
        let count = indexes(bounds).len();
        // Index -> position, through the same lookup as the elements themselves.
        let positions = Elements {
            name: name.name.clone(),
            left: bounds.0,
            ascending: bounds.2,
            ids: (0..count).collect(),
        };
        let mut ids: Vec<Option<TerminalId>> = vec![None; count];
        for a in assocs {
            let (Some(formal), Actual::Expr(actual)) = (&a.formal, &a.actual) else {
                return Err(self.error(ElabError::invalid(
                    a.span,
                    format!("an element of port `{}` needs a terminal", name.name),
                    Some("connect a terminal to each element: `t(1) => n(0)`".into()),
                )));
            };
            let ExprKind::Apply(_, args) = &formal.kind else {
                return Err(Reported);
            };
            // A slice of the port, `t(4 to 7) => n(2 to 5)`, or one element, `t(1) => a`.
            let at = self.formal_positions(parent, &positions, args, &name.name, formal.span)?;
            let terminals = match args.as_slice() {
                [
                    ast::Assoc {
                        actual: Actual::Range(_),
                        ..
                    },
                ] => {
                    let items = self.lookup(parent, actual)?;
                    let Item::TerminalArray {
                        elements,
                        nature: n,
                    } = &items[0]
                    else {
                        return Err(self.error(ElabError::invalid(
                            actual.span,
                            format!("a slice of port `{}` needs a terminal array", name.name),
                            None,
                        )));
                    };
                    if !self.same_nature(*n, nature.element) || elements.ids.len() != at.len() {
                        return Err(self.error(ElabError::invalid(
                            actual.span,
                            format!(
                                "the slice has {} elements of nature {}, `{}` {} of nature {}",
                                at.len(),
                                self.analog.natures[nature.element].name,
                                elements.name,
                                elements.ids.len(),
                                self.analog.natures[*n].name
                            ),
                            Some(
                                "associate a terminal array slice of the same length and nature"
                                    .into(),
                            ),
                        )));
                    }
                    elements.ids.clone()
                }
                _ => {
                    let (id, actual_nature) = self.terminal(parent, actual)?;
                    if !self.same_nature(actual_nature, nature.element) {
                        let (a, b) = (
                            self.analog.natures[nature.element].name.clone(),
                            self.analog.natures[actual_nature].name.clone(),
                        );
                        return Err(self.error(ElabError::TypeMismatch {
                            span: actual.span,
                            expected: format!("a terminal of nature {a}"),
                            found: format!("a terminal of nature {b}"),
                            help: Some(
                                "a terminal port connects to a terminal of the same nature".into(),
                            ),
                        }));
                    }
                    vec![id]
                }
            };
            self.associate_elements(&mut ids, &at, terminals, bounds, &name.name, formal.span)?;
        }
        let complete = self.complete_elements(ids, bounds, &name.name, first, "n")?;
        Ok(Item::TerminalArray {
            elements: Rc::new(Elements {
                name: name.name.clone(),
                left: bounds.0,
                ascending: bounds.2,
                ids: complete,
            }),
            nature: nature.element,
        })
    }

    /// The positions (from the left) of the port elements a formal names: `t(3)`, or a
    /// slice `t(4 to 7)` (its range read in the instantiating scope `parent`).
    fn formal_positions(
        &mut self,
        parent: &Scope<'a>,
        positions: &Elements<usize>,
        args: &[ast::Assoc],
        name: &str,
        span: Span,
    ) -> R<Vec<usize>> {
        if let [
            ast::Assoc {
                actual: Actual::Range(r),
                ..
            },
        ] = args
        {
            let bounds = self.range_bounds(parent, r)?;
            return indexes(bounds)
                .into_iter()
                .map(|i| self.element(positions, i, span))
                .collect();
        }
        let (index, index_span) = self.static_index(parent, args, name, span)?;
        Ok(vec![self.element(positions, index, index_span)?])
    }

    /// Associates the port elements at positions `at` with `objects`; an element associated
    /// twice is an error at the formal (`span`).
    fn associate_elements<T>(
        &mut self,
        ids: &mut [Option<T>],
        at: &[usize],
        objects: Vec<T>,
        bounds: (i64, i64, bool),
        name: &str,
        span: Span,
    ) -> R<()> {
        for (&pos, object) in at.iter().zip(objects) {
            if ids[pos].replace(object).is_some() {
                let index = index_at(bounds, pos);
                return Err(self.error(ElabError::invalid(
                    span,
                    format!("`{name}({index})` is associated twice"),
                    Some("associate each element of the port once".into()),
                )));
            }
        }
        Ok(())
    }

    /// The objects of a port associated element by element, left to right; an element left
    /// out is an error at the first association (`actual` names an actual in the help).
    fn complete_elements<T>(
        &mut self,
        ids: Vec<Option<T>>,
        bounds: (i64, i64, bool),
        name: &str,
        first: Span,
        actual: &str,
    ) -> R<Vec<T>> {
        let mut complete = Vec::with_capacity(ids.len());
        for (pos, id) in ids.into_iter().enumerate() {
            let Some(id) = id else {
                let index = index_at(bounds, pos);
                return Err(self.error(ElabError::invalid(
                    first,
                    format!("element `{name}({index})` of port `{name}` is not associated"),
                    Some(format!(
                        "associate every element of `{name}`, or the whole port: `{name} => {actual}`"
                    )),
                )));
            };
            complete.push(id);
        }
        Ok(complete)
    }

    /// A quantity port of an array type (`quantity y : out real_vector(1 to 7)`): the
    /// elements of the quantity array associated with it (whole or a slice; its length must
    /// be the port's), or new free quantities when it is open.
    pub(crate) fn quantity_array_port(
        &mut self,
        sc: &mut Scope<'a>,
        name: &Ident,
        decl: &ast::InterfaceDecl,
        sub: &Sub,
        actual: Option<(&ast::Expr, &Scope<'a>)>,
    ) -> R<()> {
        let bounds = match &sub.ty {
            Ty::Array(arr) => arr.bounds,
            _ => None,
        };
        let Some((e, parent)) = actual else {
            return self.quantity_array_decl(
                sc,
                std::slice::from_ref(name),
                &decl.subtype,
                sub,
                None,
            );
        };
        let Item::QuantityArray(actual) = self.lookup(parent, e)?.swap_remove(0) else {
            return Err(self.error(ElabError::invalid(
                e.span,
                format!(
                    "port `{}` is a quantity array: connect a quantity array",
                    name.name
                ),
                Some(
                    "associate a quantity array of the port's length, or its elements one by one"
                        .into(),
                ),
            )));
        };
        let (left, ascending) = match bounds {
            None => (actual.left, actual.ascending),
            Some(b) => {
                let len = indexes(b).len();
                if len != actual.ids.len() {
                    return Err(self.error(ElabError::invalid(
                        e.span,
                        format!(
                            "port `{}` has {len} elements, but `{}` has {} ({})",
                            name.name,
                            actual.name,
                            actual.ids.len(),
                            actual.range_text()
                        ),
                        Some("connect an array of the same length".into()),
                    )));
                }
                (b.0, b.2)
            }
        };
        let item = Item::QuantityArray(Rc::new(Elements {
            name: name.name.clone(),
            left,
            ascending,
            ids: actual.ids.clone(),
        }));
        sc.declare_at(&name.name, name.span, item);
        Ok(())
    }

    /// A quantity port of a constrained array type associated element by element,
    /// `port map (y(1) => a, y(2 to 3) => b(0 to 1))`: each element exactly once.
    pub(crate) fn quantity_port_elements(
        &mut self,
        sc: &Scope<'a>,
        parent: &Scope<'a>,
        name: &Ident,
        decl: &ast::InterfaceDecl,
        assocs: &[&ast::Assoc],
    ) -> R<Item<'a>> {
        let first = assocs.first().map_or(name.span, |a| a.span);
        let sub = self.subtype_indication(sc, &decl.subtype)?;
        let bounds = match &sub.ty {
            Ty::Array(arr) if arr.element == Ty::Real => arr.bounds,
            _ => None,
        };
        let Some(bounds) = bounds else {
            return Err(self.error(ElabError::unsupported(
                first,
                format!("element associations of port `{}`", name.name),
                "a quantity port associated element by element needs an array of reals with an index range; associate the whole port",
            )));
        };
        let count = indexes(bounds).len();
        let positions = Elements {
            name: name.name.clone(),
            left: bounds.0,
            ascending: bounds.2,
            ids: (0..count).collect(),
        };
        let mut ids: Vec<Option<QuantityId>> = vec![None; count];
        for a in assocs {
            let (Some(formal), Actual::Expr(actual)) = (&a.formal, &a.actual) else {
                return Err(self.error(ElabError::invalid(
                    a.span,
                    format!("an element of port `{}` needs a quantity", name.name),
                    Some("connect a quantity to each element: `q(1) => x`".into()),
                )));
            };
            let ExprKind::Apply(_, args) = &formal.kind else {
                return Err(Reported);
            };
            // The formal's positions, and the actual's quantities for them.
            let at = self.formal_positions(parent, &positions, args, &name.name, formal.span)?;
            let quantities = match args.as_slice() {
                [
                    ast::Assoc {
                        actual: Actual::Range(_),
                        ..
                    },
                ] => {
                    let Item::QuantityArray(q) = self.lookup(parent, actual)?.swap_remove(0) else {
                        return Err(self.error(ElabError::invalid(
                            actual.span,
                            format!("a slice of port `{}` needs a quantity array", name.name),
                            None,
                        )));
                    };
                    if q.ids.len() != at.len() {
                        return Err(self.error(ElabError::invalid(
                            actual.span,
                            format!(
                                "the slice has {} elements, `{}` {}",
                                at.len(),
                                q.name,
                                q.ids.len()
                            ),
                            Some("associate a slice of the same length".into()),
                        )));
                    }
                    q.ids.clone()
                }
                _ => vec![self.quantity_name(parent, actual)?],
            };
            self.associate_elements(&mut ids, &at, quantities, bounds, &name.name, formal.span)?;
        }
        let complete = self.complete_elements(ids, bounds, &name.name, first, "q")?;
        Ok(Item::QuantityArray(Rc::new(Elements {
            name: name.name.clone(),
            left: bounds.0,
            ascending: bounds.2,
            ids: complete,
        })))
    }

    /// `quantity q : real_vector(1 to 3) := (others => 0.5);`: the scalar free quantities
    /// `q(1)` ... `q(3)`, each with its element of the initial value.
    pub(crate) fn quantity_array_decl(
        &mut self,
        sc: &mut Scope<'a>,
        names: &[Ident],
        subtype: &ast::SubtypeIndication,
        sub: &Sub,
        value: Option<&ast::Expr>,
    ) -> R<()> {
        let Some(bounds) = (match &sub.ty {
            Ty::Array(arr) => arr.bounds,
            _ => None,
        }) else {
            return Err(self.error(ElabError::invalid(
                subtype.span,
                format!(
                    "`{}` is unconstrained: this quantity needs an index range",
                    sub.name
                ),
                Some(format!("give the range: `{}(1 to 3)`", sub.name)),
            )));
        };
        let (tolerance, _) = self.tolerance_and_init(sc, subtype.tolerance.as_ref(), None)?;
        let indexes = indexes(bounds);
        let inits: Vec<Option<f64>> = match value {
            None => vec![None; indexes.len()],
            Some(v) => match self.static_value(sc, v, &sub.ty, "a quantity's initial value")? {
                Value::Array(items) if items.len() == indexes.len() => {
                    items.iter().map(Value::as_f64).collect()
                }
                _ => {
                    return Err(self.error(ElabError::invalid(
                        v.span,
                        format!("the initial value needs {} elements", indexes.len()),
                        Some("give one value per element: `(others => 0.0)`".into()),
                    )));
                }
            },
        };
        // The elements are reals with the array subtype's unit and tolerance.
        let element = Sub {
            name: "real".into(),
            ty: Ty::Real,
            ..sub.clone()
        };
        for name in names {
            let ids = indexes
                .iter()
                .zip(&inits)
                .map(|(i, init)| {
                    let elem_name = format!("{}({i})", name.name);
                    let kind = QuantityKind::Free;
                    let tol = tolerance.clone();
                    self.new_quantity(&elem_name, kind, &element, tol, *init, name.span)
                })
                .collect();
            let elements = Rc::new(Elements {
                name: name.name.clone(),
                left: bounds.0,
                ascending: bounds.2,
                ids,
            });
            if !sc.declare_at(&name.name, name.span, Item::QuantityArray(elements)) {
                return Err(self.error(ElabError::Redeclared {
                    span: name.span,
                    name: name.name.clone(),
                }));
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn elements_are_found_by_index_in_both_directions() {
        let up = Elements {
            name: "n".into(),
            left: 2,
            ascending: true,
            ids: vec![10, 11, 12],
        };
        assert_eq!(up.get(2), Some(10));
        assert_eq!(up.get(4), Some(12));
        assert_eq!(up.get(5), None);
        assert_eq!(up.get(1), None);
        assert_eq!(up.range_text(), "2 to 4");
        let down = Elements {
            name: "n".into(),
            left: 3,
            ascending: false,
            ids: vec![7, 6, 5, 4],
        };
        assert_eq!(down.get(3), Some(7));
        assert_eq!(down.get(0), Some(4));
        assert_eq!(down.get(-1), None);
        assert_eq!(down.get(i64::MIN), None);
        assert_eq!(down.range_text(), "3 downto 0");
    }

    #[test]
    fn null_ranges_have_no_indexes() {
        assert!(indexes((3, 2, true)).is_empty());
        assert_eq!(indexes((2, 0, false)), vec![2, 1, 0]);
    }
}
