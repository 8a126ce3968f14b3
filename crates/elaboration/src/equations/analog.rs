//! Analog objects: natures (with their reference terminals), terminals, free and branch
//! quantities, `limit` specifications, and the implicit objects of `Q'dot'dot`, `Q'integ`
//! and `Q'above(E)`.

use std::rc::Rc;
use std::sync::Arc;

use vams_design::{
    BinaryOp, BreakReinit, Equation, Expr, Instr, Limit, Nature, NatureId, NoiseSource, Process,
    Quantity, QuantityId, QuantityKind, Signal, SignalId, SignalKind, SpectralSource, Terminal,
    TerminalId, Value,
};
use vams_syntax::ast::{self, EntityNames, Ident, NatureDef, QuantityDecl};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::names::composite::NatureMark;
use crate::names::scope::{Item, Scope};
use crate::names::types::{Sub, Ty};
use crate::tables::NatureInfo;
use crate::{Elab, R};

/// The terminals of one end of a branch, their nature, and `(left, ascending)` of a
/// terminal array's index.
pub(crate) type BranchEnd = (Vec<TerminalId>, usize, Option<(i64, bool)>);

/// The minus end of a branch whose nature the plus end gave: its terminals and index origin.
type MinusEnd = (Vec<TerminalId>, Option<(i64, bool)>);

impl<'a> Elab<'a> {
    pub(crate) fn nature_decl(
        &mut self,
        sc: &mut Scope<'a>,
        name: &Ident,
        def: &NatureDef,
        span: Span,
    ) -> R<()> {
        let (across, through, reference) = match def {
            NatureDef::Scalar {
                across,
                through,
                reference,
            } => (across, through, reference),
            NatureDef::Array { indexes, element } => {
                return self.array_nature_decl(sc, name, indexes, element, span);
            }
            NatureDef::Record(fields) => {
                return self.record_nature_decl(sc, name, fields);
            }
        };
        let across = self.type_mark(sc, across)?;
        let through = self.type_mark(sc, through)?;
        for (sub, mark) in [(&across, "across"), (&through, "through")] {
            if sub.ty != Ty::Real {
                return Err(self.error(ElabError::TypeMismatch {
                    span,
                    expected: format!("a real {mark} type"),
                    found: sub.ty.to_string(),
                    help: None,
                }));
            }
        }
        let idx = self.analog.natures.len();
        self.analog.natures.push(NatureInfo {
            name: name.name.clone(),
            across,
            through,
            id: None,
            base: None,
        });
        sc.declare_at(&name.name, name.span, Item::Nature(idx));
        match reference {
            Some(reference) => {
                sc.declare_at(
                    &reference.name,
                    reference.span,
                    Item::RefTerminal { nature: idx },
                );
            }
            None => self
                .design
                .warnings
                .push(vams_design::DesignWarning::UnnamedReference {
                    nature: name.name.clone(),
                    span,
                }),
        }
        Ok(())
    }

    /// The table entry of the nature that `idx` is, or is a subnature of.
    pub(crate) fn nature_root(&self, idx: usize) -> usize {
        self.analog.natures[idx].base.unwrap_or(idx)
    }

    /// Whether terminals of natures `a` and `b` may be joined (a subnature is its base nature).
    pub(crate) fn same_nature(&self, a: usize, b: usize) -> bool {
        self.nature_root(a) == self.nature_root(b)
    }

    /// `subnature accurate is electrical tolerance "v" across "i" through;`: a scalar
    /// subnature with groups of its own gets a table entry whose across and through subtypes
    /// carry them (its branch quantities' `'tolerance`); otherwise it is its base nature.
    pub(crate) fn subnature_decl(
        &mut self,
        sc: &mut Scope<'a>,
        name: &Ident,
        nature: &ast::SubtypeIndication,
        through_tolerance: Option<&ast::Expr>,
    ) -> R<()> {
        let item = match self.nature_indication(sc, nature)? {
            NatureMark::Scalar(n) => {
                let (across, _) = self.tolerance_and_init(sc, nature.tolerance.as_ref(), None)?;
                let (through, _) = self.tolerance_and_init(sc, through_tolerance, None)?;
                if across.is_none() && through.is_none() {
                    Item::Nature(n)
                } else {
                    let base = &self.analog.natures[n];
                    let with = |sub: &Rc<Sub>, group: Option<String>| match group {
                        Some(g) => Rc::new(Sub {
                            tolerance: Some(g.into()),
                            ..(**sub).clone()
                        }),
                        None => sub.clone(),
                    };
                    let info = NatureInfo {
                        name: base.name.clone(),
                        across: with(&base.across, across),
                        through: with(&base.through, through),
                        id: None,
                        base: Some(self.nature_root(n)),
                    };
                    self.analog.natures.push(info);
                    Item::Nature(self.analog.natures.len() - 1)
                }
            }
            NatureMark::Array(a) => Item::ArrayNature(a),
            NatureMark::Record(r) => Item::RecordNature(r),
        };
        self.declare(sc, name, item)
    }

    /// The design nature of table entry `idx`, created with its reference terminal on first use.
    pub(crate) fn nature_id(&mut self, idx: usize) -> NatureId {
        let idx = self.nature_root(idx);
        if let Some(id) = self.analog.natures[idx].id {
            return id;
        }
        let id = NatureId(self.design.natures.len() as u32);
        let reference = TerminalId(self.design.terminals.len() as u32);
        let info = &self.analog.natures[idx];
        self.design.terminals.push(Terminal {
            name: format!("{}_ref", info.name),
            nature: id,
            is_reference: true,
            span: Span::default(),
        });
        self.design.natures.push(Nature {
            name: info.name.clone(),
            across_tolerance: info.across.tolerance.as_deref().map(String::from),
            through_tolerance: info.through.tolerance.as_deref().map(String::from),
            reference,
        });
        self.analog.natures[idx].id = Some(id);
        id
    }

    pub(crate) fn reference_terminal(&mut self, nature: usize) -> TerminalId {
        let id = self.nature_id(nature);
        self.design.natures[id.index()].reference
    }

    pub(crate) fn new_terminal(&mut self, name: &str, nature: usize, span: Span) -> TerminalId {
        let nid = self.nature_id(nature);
        let id = TerminalId(self.design.terminals.len() as u32);
        self.design.terminals.push(Terminal {
            name: self.hier_name(name),
            nature: nid,
            is_reference: false,
            span,
        });
        id
    }

    pub(crate) fn terminal_decl(
        &mut self,
        sc: &mut Scope<'a>,
        names: &[Ident],
        nature: &ast::SubtypeIndication,
    ) -> R<()> {
        let n = match self.nature_indication(sc, nature)? {
            NatureMark::Scalar(n) => n,
            NatureMark::Array(array) => {
                for name in names {
                    self.terminal_array_decl(sc, name, &array)?;
                }
                return Ok(());
            }
            NatureMark::Record(record) => {
                for name in names {
                    let item = self.new_record_terminal(&name.name, &record, name.span)?;
                    self.declare(sc, name, item)?;
                }
                return Ok(());
            }
        };
        for name in names {
            let id = self.new_terminal(&name.name, n, name.span);
            if !sc.declare_at(&name.name, name.span, Item::Terminal { id, nature: n }) {
                return Err(self.error(ElabError::Redeclared {
                    span: name.span,
                    name: name.name.clone(),
                }));
            }
        }
        Ok(())
    }

    /// A terminal named in a branch quantity or a port map: `(id, nature)`.
    /// An end of a branch: one terminal, or the elements of a terminal array with its
    /// `(left, ascending)`, and the (element) nature.
    fn branch_end(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> R<BranchEnd> {
        if let Some(item) = self.record_part(sc, e)
            && let Some(end) = field_terminals(&item)
        {
            return Ok(end);
        }
        if let Some(slice) = self.terminal_slice(sc, e) {
            let (elements, nature) = slice?;
            let bounds = (elements.left, elements.ascending);
            return Ok((elements.ids.clone(), nature, Some(bounds)));
        }
        if let ast::ExprKind::Name(id) | ast::ExprKind::Selected(_, id) = &e.kind
            && let Some(Item::TerminalArray { elements, nature }) = self.resolved_item(sc, id)
        {
            let bounds = (elements.left, elements.ascending);
            return Ok((elements.ids.clone(), nature, Some(bounds)));
        }
        let (t, nature) = self.terminal(sc, e)?;
        Ok((vec![t], nature, None))
    }

    pub(crate) fn terminal(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> R<(TerminalId, usize)> {
        if let ast::ExprKind::Apply(prefix, args) = &e.kind {
            return self.indexed_terminal(sc, prefix, args, e.span);
        }
        let items = self.lookup(sc, e)?;
        match items[0] {
            Item::Terminal { id, nature } => Ok((id, nature)),
            Item::RefTerminal { nature } => Ok((self.reference_terminal(nature), nature)),
            ref other => Err(self.error(ElabError::WrongClass {
                span: e.span,
                name: self.sources.snippet(e.span).into(),
                found: other.class().into(),
                expected: "a terminal".into(),
                help: Some("branch quantities are declared between terminals: `quantity v across i through p to n;`".into()),
            })),
        }
    }

    /// What a branch end names as a whole (a terminal of a record nature, for one).
    fn whole_terminal(&mut self, sc: &Scope<'a>, e: &ast::Expr) -> Option<Item<'a>> {
        if let Some(item) = self.record_part(sc, e) {
            return Some(item);
        }
        match &e.kind {
            ast::ExprKind::Name(id) => self.resolved_item(sc, id),
            _ => None,
        }
    }

    /// The across and through quantities of one branch (between two terminals, or element by
    /// element between terminal arrays, LRM 1076.1 4.3.1.6), one object per name in
    /// declaration order; `field` names them as a record field's (`v.strobe`). A missing
    /// minus end is the nature's reference terminal.
    #[allow(clippy::too_many_arguments)]
    fn branch_objects(
        &mut self,
        sc: &Scope<'a>,
        (ps, nature, plus_bounds): BranchEnd,
        minus: Option<MinusEnd>,
        across: &[ast::BranchName],
        through: &[ast::BranchName],
        field: Option<&str>,
        span: Span,
    ) -> R<Vec<Item<'a>>> {
        let (ms, minus_bounds) = match minus {
            Some(m) => m,
            None => (vec![self.reference_terminal(nature)], None),
        };
        let n = ps.len().max(ms.len());
        if ps.len() != n && ps.len() != 1 || ms.len() != n && ms.len() != 1 {
            return Err(self.error(ElabError::invalid(
                span,
                format!(
                    "the ends of this branch have {} and {} terminals",
                    ps.len(),
                    ms.len()
                ),
                Some(
                    "an array branch joins arrays of the same length, or an array and one terminal"
                        .into(),
                ),
            )));
        }
        let bounds = plus_bounds.or(minus_bounds);
        let across_sub = self.analog.natures[nature].across.clone();
        let through_sub = self.analog.natures[nature].through.clone();
        let mut items = Vec::new();
        let lone_across = through.is_empty();
        for (names, sub, through) in [(across, across_sub, false), (through, through_sub, true)] {
            for b in names {
                let (tol, init) =
                    self.tolerance_and_init(sc, b.tolerance.as_ref(), b.value.as_ref())?;
                for nm in &b.names {
                    let base = match field {
                        Some(f) => format!("{}.{f}", nm.name),
                        None => nm.name.clone(),
                    };
                    let mut ids = Vec::with_capacity(n);
                    for k in 0..n {
                        let (plus, minus) = (ps[k.min(ps.len() - 1)], ms[k.min(ms.len() - 1)]);
                        let kind = match through {
                            false => QuantityKind::Across { plus, minus },
                            true => QuantityKind::Through { plus, minus },
                        };
                        let name = match bounds {
                            Some((left, asc)) => {
                                let i = if asc {
                                    left + k as i64
                                } else {
                                    left - k as i64
                                };
                                format!("{base}({i})")
                            }
                            None => base.clone(),
                        };
                        let id = self.new_quantity(&name, kind, &sub, tol.clone(), init, nm.span);
                        if lone_across && !through {
                            self.design.lone_across.push(id);
                        }
                        ids.push(id);
                    }
                    items.push(match bounds {
                        Some((left, ascending)) => {
                            Item::QuantityArray(Rc::new(crate::names::composite::Elements {
                                name: base,
                                left,
                                ascending,
                                ids,
                            }))
                        }
                        None => Item::Quantity(ids[0]),
                    });
                }
            }
        }
        Ok(items)
    }

    pub(crate) fn new_quantity(
        &mut self,
        name: &str,
        kind: QuantityKind,
        sub: &Sub,
        tolerance: Option<String>,
        initial_guess: Option<f64>,
        span: Span,
    ) -> QuantityId {
        let id = QuantityId(self.design.quantities.len() as u32);
        self.design.quantities.push(Quantity {
            name: self.hier_name(name),
            kind,
            tolerance: tolerance.map(Arc::from).or_else(|| sub.tolerance.clone()),
            subtype: sub.name.clone(),
            unit: sub.unit.clone(),
            initial_guess,
            span,
        });
        id
    }

    pub(crate) fn tolerance_and_init(
        &mut self,
        sc: &Scope<'a>,
        tolerance: Option<&ast::Expr>,
        value: Option<&ast::Expr>,
    ) -> R<(Option<String>, Option<f64>)> {
        let tol = match tolerance {
            Some(t) => {
                let Some(string) = self.standard_type("string") else {
                    return Err(crate::Reported);
                };
                match self.static_value(sc, t, &string, "a tolerance group")? {
                    Value::String(s) => Some(s),
                    _ => None,
                }
            }
            None => None,
        };
        let init = match value {
            Some(v) => self
                .static_value(sc, v, &Ty::Real, "a quantity's initial value")?
                .as_f64(),
            None => None,
        };
        Ok((tol, init))
    }

    pub(crate) fn quantity_decl(
        &mut self,
        sc: &mut Scope<'a>,
        q: &QuantityDecl,
        span: Span,
    ) -> R<()> {
        match q {
            QuantityDecl::Free {
                names,
                subtype,
                value,
            } => {
                let sub = self.subtype_indication(sc, subtype)?;
                if matches!(&sub.ty, Ty::Array(arr) if arr.element == Ty::Real) {
                    return self.quantity_array_decl(sc, names, subtype, &sub, value.as_ref());
                }
                if matches!(sub.ty, Ty::Record(_)) {
                    for n in names {
                        let item = self.record_quantity(&n.name, &sub.ty, &sub, n.span)?;
                        self.declare(sc, n, item)?;
                    }
                    return Ok(());
                }
                if sub.ty != Ty::Real {
                    return Err(self.error(ElabError::unsupported(
                        subtype.span,
                        format!("quantities of type {}", sub.ty),
                        "quantities are reals, arrays of reals and records of them",
                    )));
                }
                let (tol, init) =
                    self.tolerance_and_init(sc, subtype.tolerance.as_ref(), value.as_ref())?;
                for n in names {
                    let id = self.new_quantity(
                        &n.name,
                        QuantityKind::Free,
                        &sub,
                        tol.clone(),
                        init,
                        n.span,
                    );
                    if !sc.declare_at(&n.name, n.span, Item::Quantity(id)) {
                        return Err(self.error(ElabError::Redeclared {
                            span: n.span,
                            name: n.name.clone(),
                        }));
                    }
                }
                Ok(())
            }
            QuantityDecl::Branch {
                across,
                through,
                plus,
                minus,
            } => {
                let Some(plus) = plus else {
                    return Err(self.error(ElabError::invalid(
                        span,
                        "a branch quantity needs its terminals: `... through p to n`",
                        None,
                    )));
                };
                let names: Vec<&Ident> = across
                    .iter()
                    .chain(through)
                    .flat_map(|b| &b.names)
                    .collect();
                // Between terminals of a record nature: field by field.
                if let Some(Item::TerminalRecord(p)) = self.whole_terminal(sc, plus) {
                    let m = match minus {
                        Some(minus) => {
                            match self.whole_terminal(sc, minus) {
                                Some(m @ Item::TerminalRecord(_)) => Some(m),
                                Some(Item::RefTerminal { nature }) => Some(Item::Terminal {
                                    id: self.reference_terminal(nature),
                                    nature,
                                }),
                                Some(m @ Item::Terminal { .. }) => Some(m),
                                _ => {
                                    return Err(self.error(ElabError::TypeMismatch {
                                    span: minus.span,
                                    expected: "a terminal of the same record nature, or a scalar terminal".into(),
                                    found: "another object".into(),
                                    help: Some(
                                        "both ends of a branch must have the same nature".into(),
                                    ),
                                }));
                                }
                            }
                        }
                        None => None,
                    };
                    let mut make = |elab: &mut Self,
                                    field: &str,
                                    p: &Item<'a>,
                                    m: Option<&Item<'a>>|
                     -> R<Vec<Item<'a>>> {
                        // Fields of the same record nature: terminals or terminal arrays.
                        let Some(plus_end) = field_terminals(p) else {
                            return Err(crate::Reported);
                        };
                        let minus_end = match m.map(field_terminals) {
                            Some(Some((ts, n, b))) if n == plus_end.1 => Some((ts, b)),
                            Some(_) => {
                                return Err(elab.error(ElabError::invalid(
                                    span,
                                    format!("the ends of field `{field}` of this branch have different natures"),
                                    Some("both ends of a branch must have the same nature".into()),
                                )));
                            }
                            None => None,
                        };
                        elab.branch_objects(
                            sc,
                            plus_end,
                            minus_end,
                            across,
                            through,
                            Some(field),
                            span,
                        )
                    };
                    let items = self.record_branch(&p, m.as_ref(), &names, span, &mut make)?;
                    for (name, item) in names.iter().zip(items) {
                        self.declare(sc, name, item)?;
                    }
                    return Ok(());
                }
                let plus_end = self.branch_end(sc, plus)?;
                let nature = plus_end.1;
                let minus_end = match minus {
                    Some(minus) => {
                        let (ms, mn, bounds) = self.branch_end(sc, minus)?;
                        if !self.same_nature(mn, nature) {
                            let (a, b) = (
                                self.analog.natures[nature].name.clone(),
                                self.analog.natures[mn].name.clone(),
                            );
                            return Err(self.error(ElabError::TypeMismatch {
                                span: minus.span,
                                expected: format!("a terminal of nature {a}"),
                                found: format!("a terminal of nature {b}"),
                                help: Some(
                                    "both ends of a branch must have the same nature".into(),
                                ),
                            }));
                        }
                        Some((ms, bounds))
                    }
                    None => None,
                };
                let items =
                    self.branch_objects(sc, plus_end, minus_end, across, through, None, span)?;
                for (name, item) in names.iter().zip(items) {
                    self.declare(sc, name, item)?;
                }
                Ok(())
            }
            // A spectral or noise source quantity is zero in the quiescent and time domains
            // (LRM 1076.1 12.6.4). A spectral one's magnitude and phase are kept for the
            // small-signal analysis (`vams ac`), a noise one's density for the noise
            // analysis (`vams noise`).
            QuantityDecl::Source {
                names,
                subtype,
                spectrum,
                noise,
            } => {
                let sub = self.subtype_indication(sc, subtype)?;
                if sub.ty != Ty::Real {
                    return Err(self.error(ElabError::unsupported(
                        subtype.span,
                        format!("source quantities of type {}", sub.ty),
                        "source quantities are scalar reals in vams",
                    )));
                }
                let spectrum = match spectrum {
                    Some((magnitude, phase)) => Some(self.spectrum(sc, magnitude, phase)?),
                    None => None,
                };
                let density = match noise {
                    Some(density) => Some(self.noise_density(sc, density)?),
                    None => None,
                };
                for n in names {
                    let id =
                        self.new_quantity(&n.name, QuantityKind::Free, &sub, None, None, n.span);
                    if !sc.declare_at(&n.name, n.span, Item::Quantity(id)) {
                        return Err(self.error(ElabError::Redeclared {
                            span: n.span,
                            name: n.name.clone(),
                        }));
                    }
                    let text = format!(
                        "{} == 0.0 (a source quantity outside the frequency domain)",
                        n.name
                    );
                    if let Some((magnitude, phase)) = &spectrum {
                        self.design.spectral_sources.push(SpectralSource {
                            quantity: id,
                            magnitude: magnitude.clone(),
                            phase: phase.clone(),
                            equation: self.design.equations.len(),
                            span: n.span,
                        });
                    }
                    if let Some(density) = &density {
                        self.design.noise_sources.push(NoiseSource {
                            quantity: id,
                            density: density.clone(),
                            equation: self.design.equations.len(),
                            span: n.span,
                        });
                    }
                    self.generated_equation(Expr::Quantity(id), n.span, text);
                }
                Ok(())
            }
        }
    }

    /// A spectral source's magnitude and phase as real expressions, in which `frequency`
    /// may be called.
    fn spectrum(
        &mut self,
        sc: &Scope<'a>,
        magnitude: &ast::Expr,
        phase: &ast::Expr,
    ) -> R<(Expr, Expr)> {
        self.analog.in_spectrum = true;
        let m = self.expr_of(sc, magnitude, &Ty::Real);
        let p = self.expr_of(sc, phase, &Ty::Real);
        self.analog.in_spectrum = false;
        Ok((m?.e, p?.e))
    }

    /// A noise source's power spectral density as a real expression, in which `frequency`
    /// may be called.
    fn noise_density(&mut self, sc: &Scope<'a>, density: &ast::Expr) -> R<Expr> {
        self.analog.in_spectrum = true;
        let d = self.expr_of(sc, density, &Ty::Real);
        self.analog.in_spectrum = false;
        Ok(d?.e)
    }

    /// The implicit signal standing for `frequency` (made at its first call).
    pub(crate) fn frequency_signal(&mut self, span: Span) -> SignalId {
        if let Some(s) = self.design.frequency_signal {
            return s;
        }
        let s = self.implicit_signal("frequency".into(), 0.0, span);
        self.design.frequency_signal = Some(s);
        s
    }

    pub(crate) fn limit(
        &mut self,
        sc: &mut Scope<'a>,
        names: &EntityNames,
        _type_mark: &ast::Expr,
        value: &ast::Expr,
    ) -> R<()> {
        let mut quantities = Vec::new();
        match names {
            EntityNames::List(names) => {
                for n in names {
                    match self.lookup(sc, n)?.first() {
                        Some(Item::Quantity(q)) => quantities.push(*q),
                        Some(Item::QuantityArray(elements)) => {
                            quantities.extend(elements.ids.iter().copied());
                        }
                        _ => {
                            return Err(self.error(ElabError::WrongClass {
                                span: n.span,
                                name: self.sources.snippet(n.span).into(),
                                found: "not a quantity".into(),
                                expected: "a quantity".into(),
                                help: None,
                            }));
                        }
                    }
                }
            }
            // Every quantity declared in this region (`all`), or every one no earlier
            // limit specification names (`others`), LRM 1076.1 5.4.
            all_or_others => {
                let limited: Vec<QuantityId> = match all_or_others {
                    EntityNames::Others => self
                        .design
                        .limits
                        .iter()
                        .flat_map(|l| l.quantities.clone())
                        .collect(),
                    _ => Vec::new(),
                };
                let region = sc
                    .regions
                    .last()
                    .map(|r| r.items.clone())
                    .unwrap_or_default();
                let mut here: Vec<QuantityId> = region
                    .values()
                    .flatten()
                    .flat_map(|item| match item {
                        Item::Quantity(q) => vec![*q],
                        Item::QuantityArray(elements) => elements.ids.clone(),
                        _ => Vec::new(),
                    })
                    .filter(|q| !limited.contains(q))
                    .collect();
                here.sort_by_key(|q| q.index());
                here.dedup();
                quantities = here;
            }
        }
        let max_step = self.expr_of(sc, value, &Ty::Real)?;
        if !max_step.e.is_analog() {
            return Err(self.error(ElabError::invalid(
                value.span,
                "the step limit must be an analog expression",
                None,
            )));
        }
        self.design.limits.push(Limit {
            quantities,
            max_step: max_step.e,
        });
        Ok(())
    }

    pub(crate) fn aux_quantity(&mut self, of: QuantityId, suffix: &str) -> QuantityId {
        let base = &self.design.quantities[of.index()];
        let (mut name, span) = (format!("{}'{suffix}", base.name), base.span);
        // A second `q'ltf(...)` or `q'slew(...)` with other arguments: `q'ltf#2`.
        let taken = |n: &str| self.design.quantities.iter().any(|q| q.name == n);
        if taken(&name) {
            let mut k = 2;
            while taken(&format!("{name}#{k}")) {
                k += 1;
            }
            name = format!("{name}#{k}");
        }
        let id = QuantityId(self.design.quantities.len() as u32);
        self.design.quantities.push(Quantity {
            name,
            kind: QuantityKind::Free,
            tolerance: None,
            subtype: "real".into(),
            unit: None,
            initial_guess: None,
            span,
        });
        id
    }

    /// The auxiliary quantity `q'dot` (for `q'dot'dot`), with its equation `q'dot == d q/dt`.
    pub(crate) fn dot_quantity(&mut self, q: QuantityId) -> QuantityId {
        if let Some(a) = self.analog.dot_aux.get(&q) {
            return *a;
        }
        let aux = self.aux_quantity(q, "dot");
        let name = self.design.quantities[aux.index()].name.clone();
        let span = self.design.quantities[q.index()].span;
        self.design.equations.push(Equation {
            residual: Expr::Binary(
                BinaryOp::Sub,
                Box::new(Expr::Quantity(aux)),
                Box::new(Expr::Dot(q)),
            ),
            span,
            instance: self.here.instance.clone(),
            text: format!("{name} == {}'dot", self.design.quantities[q.index()].name),
        });
        self.analog.dot_aux.insert(q, aux);
        aux
    }

    /// The auxiliary quantity `q'integ`: `d(q'integ)/dt == q`, starting from 0 (a generated
    /// process breaks it to 0 once).
    pub(crate) fn integ_quantity(&mut self, q: QuantityId) -> QuantityId {
        if let Some(a) = self.analog.integ_aux.get(&q) {
            return *a;
        }
        let aux = self.aux_quantity(q, "integ");
        let name = self.design.quantities[aux.index()].name.clone();
        let span = self.design.quantities[q.index()].span;
        self.design.equations.push(Equation {
            residual: Expr::Binary(
                BinaryOp::Sub,
                Box::new(Expr::Dot(aux)),
                Box::new(Expr::Quantity(q)),
            ),
            span,
            instance: self.here.instance.clone(),
            text: format!("{name}'dot == {}", self.design.quantities[q.index()].name),
        });
        self.design.processes.push(Process {
            spans: Vec::new(),
            name: format!("{name}_init"),
            vars: Vec::new(),
            code: vec![
                Instr::Break {
                    reinit: vec![BreakReinit {
                        selector: aux,
                        quantity: aux,
                        value: Expr::real(0.0),
                    }],
                    when: None,
                    span,
                },
                Instr::Halt,
            ],
            span,
            driver_inits: Vec::new(),
        });
        self.analog.integ_aux.insert(q, aux);
        aux
    }

    /// The implicit boolean signal `q'above(level)`, one per distinct pair.
    pub(crate) fn above_signal(&mut self, q: QuantityId, level: Expr, span: Span) -> SignalId {
        if let Some((_, _, s)) = self
            .signals
            .above
            .iter()
            .find(|(aq, al, _)| *aq == q && *al == level)
        {
            return *s;
        }
        let level_text = match &level {
            Expr::Const(v) => v
                .as_f64()
                // Shortest readable form: 0.15, not 0.15000000000000002.
                .map_or_else(|| "?".to_string(), |x| format!("{}", x as f32)),
            _ => self.text(span),
        };
        let id = SignalId(self.design.signals.len() as u32);
        self.design.signals.push(Signal {
            range: None,
            name: format!(
                "{}'above({level_text})",
                self.design.quantities[q.index()].name
            ),
            ty: vams_design::Type::Boolean,
            init: Value::Boolean(false),
            kind: SignalKind::Above {
                quantity: Expr::Quantity(q),
                level: level.clone(),
            },
            span,
            resolution: None,
            guarded: None,
        });
        self.signals.above.push((q, level, id));
        id
    }
}

/// A branch end's field object, for `Elab::record_branch`: its terminals and nature.
pub(crate) fn field_terminals(item: &Item) -> Option<BranchEnd> {
    match item {
        Item::Terminal { id, nature } => Some((vec![*id], *nature, None)),
        Item::TerminalArray { elements, nature } => Some((
            elements.ids.clone(),
            *nature,
            Some((elements.left, elements.ascending)),
        )),
        _ => None,
    }
}
