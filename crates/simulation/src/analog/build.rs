//! From a [`Design`] to unknowns and residuals: terminal potentials, quantities, the user's
//! equations, the across definitions and the conservation laws, each with its origin.
//!
//! Unknown order: the potential `v(<terminal>)` of every non-reference terminal some branch
//! quantity refers to (terminal order), then every quantity (quantity order), then the
//! implicit flows asked for (see [`Unknown::Flow`]). Equation order:
//! user equations, then one across definition per across quantity, then one conservation law
//! per potential unknown whose terminal carries a through quantity (a terminal reached only by
//! across quantities carries no current: `0 = 0` is no equation).

use petgraph::graph::{NodeIndex, UnGraph};
use petgraph::visit::Dfs;

use super::delay;
use super::error::AnalogError;
use super::lower::lower;
use super::sym::Sym;
use vams_design::{Design, Expr, QuantityId, QuantityKind, TerminalId};
use vams_syntax::source::Span;

/// What an unknown is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Unknown {
    Potential(TerminalId),
    Quantity(QuantityId),
    /// The implicit through quantity of a lone across quantity that an equation sets
    /// (`quantity vs across p to m; vs == 5.0;`, the University of Cincinnati's way of writing
    /// a voltage source): the branch's flow from `plus` to `minus`, an unknown of the
    /// conservation laws at both ends, as if the declaration had named a through quantity.
    Flow(QuantityId),
    /// The `order`-th time derivative of assembled unknown `of`, an unknown of its own after
    /// index reduction (`analog::index`): a dummy derivative, or a state between a second
    /// derivative and its unknown.
    Derivative {
        of: u32,
        order: u8,
    },
}

/// Where an equation comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Origin {
    /// Index into [`Design::equations`].
    User(usize),
    /// `q - (v(plus) - v(minus)) = 0`.
    Across(QuantityId),
    /// Sum of through quantities leaving the terminal minus those entering.
    Conservation(TerminalId),
    /// Index into [`Design::delays`]: `output - input(t - delay) = 0` (`output - input` at the
    /// quiescent point).
    Delayed(usize),
    /// The `order`-th time derivative of assembled equation `of` (index reduction).
    Differentiated { of: u32, order: u8 },
    /// `x'dot - x1 = 0`: an intermediate derivative of assembled unknown `of` kept as a state.
    StateChain { of: u32 },
}

/// Unknowns and residuals, not yet compiled. Names are made on demand ([`Unknown::name`]):
/// only the survivors of elimination and diagnostics need them.
pub struct Assembled {
    pub unknowns: Vec<Unknown>,
    /// Slot of each quantity, by `QuantityId`.
    pub quantity_slot: Vec<usize>,
    pub residuals: Vec<Sym>,
    pub origins: Vec<Origin>,
}

impl Origin {
    /// The span a diagnostic about this equation points at.
    pub fn span(self, design: &Design) -> Span {
        match self {
            Origin::User(i) => design.equations[i].span,
            Origin::Across(q) => design.quantities[q.index()].span,
            Origin::Conservation(t) => design.terminals[t.index()].span,
            Origin::Delayed(k) => design.delays[k].span,
            Origin::Differentiated { .. } | Origin::StateChain { .. } => Span::default(),
        }
    }

    /// [`Origin::span`] of equation `k` among `origins`, a derivative's that of its equation.
    pub fn span_among(origins: &[Origin], k: usize, design: &Design) -> Span {
        match origins[k] {
            Origin::Differentiated { of, .. } => origins[of as usize].span(design),
            other => other.span(design),
        }
    }

    /// [`Origin::describe`] of equation `k` among `origins`.
    pub fn describe_among(
        origins: &[Origin],
        unknowns: &[String],
        k: usize,
        design: &Design,
    ) -> String {
        match origins[k] {
            Origin::Differentiated { of, order } => format!(
                "{} of {}",
                derivative_words(order),
                origins[of as usize].describe(design)
            ),
            Origin::StateChain { of } => format!(
                "state {}'dot",
                unknowns.get(of as usize).map_or("?", String::as_str)
            ),
            other => other.describe(design),
        }
    }

    /// A short description for messages: the statement text, or what was generated.
    pub fn describe(self, design: &Design) -> String {
        match self {
            Origin::User(i) => {
                let eq = &design.equations[i];
                if eq.instance.is_empty() {
                    format!("`{}`", eq.text)
                } else {
                    format!("`{}` in {}", eq.text, eq.instance)
                }
            }
            Origin::Across(q) => format!("across {}", design.quantities[q.index()].name),
            Origin::Conservation(t) => {
                format!("conservation at {}", design.terminals[t.index()].name)
            }
            Origin::Delayed(k) => {
                let d = &design.delays[k];
                format!("history of {}", design.quantities[d.output.index()].name)
            }
            Origin::Differentiated { of, order } => {
                format!("{} of equation {of}", derivative_words(order))
            }
            Origin::StateChain { of } => format!("state chain of unknown {of}"),
        }
    }
}

/// "the derivative", "the 2nd derivative", ...
fn derivative_words(order: u8) -> String {
    match order {
        1 => "the derivative".to_string(),
        2 => "the 2nd derivative".to_string(),
        3 => "the 3rd derivative".to_string(),
        k => format!("the {k}th derivative"),
    }
}

impl Unknown {
    /// The quantity's name, or `v(<terminal>)` for a terminal potential.
    pub fn name(self, design: &Design) -> String {
        match self {
            Unknown::Potential(t) => format!("v({})", design.terminals[t.index()].name),
            Unknown::Quantity(q) => design.quantities[q.index()].name.clone(),
            Unknown::Flow(q) => format!("through({})", design.quantities[q.index()].name),
            Unknown::Derivative { of, order } => format!("#{of}{}", "'dot".repeat(order.into())),
        }
    }

    /// The names of `unknowns`, a derivative's from its unknown's: `x'dot'dot`.
    pub fn names(unknowns: &[Unknown], design: &Design) -> Vec<String> {
        let mut names: Vec<String> = unknowns.iter().map(|u| u.name(design)).collect();
        for (j, u) in unknowns.iter().enumerate() {
            if let Unknown::Derivative { of, order } = *u
                && let Some(base) = unknowns.get(of as usize).map(|b| b.name(design))
            {
                names[j] = format!("{base}{}", "'dot".repeat(order.into()));
            }
        }
        names
    }

    /// The span of the declaration; a derivative has none of its own.
    pub fn span(self, design: &Design) -> Span {
        match self {
            Unknown::Potential(t) => design.terminals[t.index()].span,
            Unknown::Quantity(q) | Unknown::Flow(q) => design.quantities[q.index()].span,
            Unknown::Derivative { .. } => Span::default(),
        }
    }
}

/// True for a nature's reference terminal (potential 0).
fn is_reference(design: &Design, t: TerminalId) -> bool {
    let term = &design.terminals[t.index()];
    term.is_reference || design.natures[term.nature.index()].reference == t
}

fn branch(kind: QuantityKind) -> Option<(TerminalId, TerminalId)> {
    match kind {
        QuantityKind::Across { plus, minus } | QuantityKind::Through { plus, minus } => {
            Some((plus, minus))
        }
        QuantityKind::Free => None,
    }
}

/// Checks the index invariants of `design` that this module relies on, so that a malformed
/// design gives an error rather than a panic.
fn check_indices(design: &Design) -> Result<(), AnalogError> {
    let malformed = |span: Span, what: String| AnalogError::Malformed { span, what };
    for n in &design.natures {
        if n.reference.index() >= design.terminals.len() {
            return Err(malformed(
                Span::default(),
                format!("nature {} has no reference terminal", n.name),
            ));
        }
    }
    for t in &design.terminals {
        if t.nature.index() >= design.natures.len() {
            return Err(malformed(
                t.span,
                format!("terminal {} has an unknown nature", t.name),
            ));
        }
    }
    for q in &design.quantities {
        if let Some((p, m)) = branch(q.kind)
            && (p.index() >= design.terminals.len() || m.index() >= design.terminals.len())
        {
            return Err(malformed(
                q.span,
                format!("quantity {} names an unknown terminal", q.name),
            ));
        }
    }
    let check_expr = |e: &Expr, span: Span| {
        let mut bad = None;
        e.visit(&mut |e| match e {
            Expr::Quantity(q) | Expr::Dot(q) if q.index() >= design.quantities.len() => {
                bad = Some("an unknown quantity")
            }
            Expr::Signal(s) if s.index() >= design.signals.len() => bad = Some("an unknown signal"),
            _ => {}
        });
        match bad {
            Some(what) => Err(malformed(span, format!("an equation refers to {what}"))),
            None => Ok(()),
        }
    };
    for eq in &design.equations {
        check_expr(&eq.residual, eq.span)?;
    }
    for d in &design.delays {
        let n = design.quantities.len();
        if d.output.index() >= n || d.input.index() >= n {
            return Err(malformed(
                d.span,
                "a 'delayed names an unknown quantity".into(),
            ));
        }
    }
    for s in &design.signals {
        if let vams_design::SignalKind::Above { quantity, level } = &s.kind {
            check_expr(quantity, s.span)?;
            check_expr(level, s.span)?;
        }
    }
    Ok(())
}

/// Builds unknowns and residuals; reports malformed expressions and floating node sets.
/// `flows` are the lone across quantities (of [`Design::lone_across`]) whose branches get an
/// implicit through quantity ([`Unknown::Flow`]).
pub fn assemble(design: &Design, flows: &[QuantityId]) -> Result<Assembled, Vec<AnalogError>> {
    check_indices(design).map_err(|e| vec![e])?;
    // Potential slots: non-reference terminals that some branch refers to.
    let mut used = vec![false; design.terminals.len()];
    for q in &design.quantities {
        if let Some((p, m)) = branch(q.kind) {
            used[p.index()] = true;
            used[m.index()] = true;
        }
    }
    let mut unknowns = Vec::new();
    let mut potential_slot = vec![None; design.terminals.len()];
    for i in 0..design.terminals.len() {
        let id = TerminalId(i as u32);
        if used[i] && !is_reference(design, id) {
            potential_slot[i] = Some(unknowns.len());
            unknowns.push(Unknown::Potential(id));
        }
    }
    let mut quantity_slot = Vec::with_capacity(design.quantities.len());
    for i in 0..design.quantities.len() {
        quantity_slot.push(unknowns.len());
        unknowns.push(Unknown::Quantity(QuantityId(i as u32)));
    }
    let flow_start = unknowns.len();
    unknowns.extend(flows.iter().map(|&q| Unknown::Flow(q)));

    let floating = floating_sets(design, &potential_slot);
    if !floating.is_empty() {
        return Err(floating);
    }

    let mut residuals = Vec::new();
    let mut origins = Vec::new();
    let mut errors = Vec::new();
    let slot_of = |q: usize| quantity_slot[q];
    for (i, eq) in design.equations.iter().enumerate() {
        match lower(&eq.residual, &slot_of) {
            Ok(s) => {
                residuals.push(s);
                origins.push(Origin::User(i));
            }
            Err(e) => errors.push(AnalogError::NotAnalog {
                span: eq.span,
                what: e.0.to_string(),
            }),
        }
    }
    if !errors.is_empty() {
        return Err(errors);
    }
    for (k, d) in design.delays.iter().enumerate() {
        let n = design.signals.len();
        let delayed = Sym::cond(
            Sym::Signal(delay::ready_slot(n)),
            Sym::Signal(delay::history_slot(n, k)),
            Sym::X(quantity_slot[d.input.index()]),
        );
        residuals.push(Sym::sub(Sym::X(quantity_slot[d.output.index()]), delayed));
        origins.push(Origin::Delayed(k));
    }
    let potential = |t: TerminalId| match potential_slot[t.index()] {
        Some(slot) => Sym::X(slot),
        None => Sym::Const(0.0),
    };
    for (i, q) in design.quantities.iter().enumerate() {
        if let QuantityKind::Across { plus, minus } = q.kind {
            let drop = Sym::sub(potential(plus), potential(minus));
            residuals.push(Sym::sub(Sym::X(quantity_slot[i]), drop));
            origins.push(Origin::Across(QuantityId(i as u32)));
        }
    }
    // The through quantities at each terminal, in quantity order: (slot, leaves the terminal).
    // One pass over the quantities, so building the laws stays linear in the design's size.
    let mut incident: Vec<Vec<(usize, bool)>> = vec![Vec::new(); design.terminals.len()];
    for (i, q) in design.quantities.iter().enumerate() {
        if let QuantityKind::Through { plus, minus } = q.kind {
            incident[plus.index()].push((quantity_slot[i], true));
            if minus != plus {
                incident[minus.index()].push((quantity_slot[i], false));
            }
        }
    }
    for (k, q) in flows.iter().enumerate() {
        if let Some(QuantityKind::Across { plus, minus }) =
            design.quantities.get(q.index()).map(|q| q.kind)
            && plus != minus
        {
            incident[plus.index()].push((flow_start + k, true));
            incident[minus.index()].push((flow_start + k, false));
        }
    }
    for (t, slot) in potential_slot.iter().enumerate() {
        if slot.is_none() {
            continue;
        }
        let sum = incident[t]
            .iter()
            .map(|&(x, leaves)| {
                if leaves {
                    Sym::X(x)
                } else {
                    Sym::neg(Sym::X(x))
                }
            })
            .reduce(Sym::add);
        if let Some(s) = sum {
            residuals.push(s);
            origins.push(Origin::Conservation(TerminalId(t as u32)));
        }
    }
    Ok(Assembled {
        unknowns,
        quantity_slot,
        residuals,
        origins,
    })
}

/// Groups of terminals (with a potential unknown) that no branch path connects to their
/// nature's reference: their potentials are undetermined.
fn floating_sets(design: &Design, potential_slot: &[Option<usize>]) -> Vec<AnalogError> {
    let mut graph =
        UnGraph::<(), ()>::with_capacity(design.terminals.len(), design.quantities.len());
    for _ in &design.terminals {
        graph.add_node(());
    }
    for q in &design.quantities {
        if let Some((p, m)) = branch(q.kind) {
            graph.add_edge(NodeIndex::new(p.index()), NodeIndex::new(m.index()), ());
        }
    }
    let mut grounded = vec![false; design.terminals.len()];
    let mark = |start: usize, seen: &mut Vec<bool>| -> Vec<usize> {
        let mut group = Vec::new();
        let mut dfs = Dfs::new(&graph, NodeIndex::new(start));
        while let Some(n) = dfs.next(&graph) {
            if !seen[n.index()] {
                seen[n.index()] = true;
                group.push(n.index());
            }
        }
        group
    };
    for n in &design.natures {
        mark(n.reference.index(), &mut grounded);
    }
    for (i, t) in design.terminals.iter().enumerate() {
        if t.is_reference {
            mark(i, &mut grounded);
        }
    }
    let mut errors = Vec::new();
    for start in 0..design.terminals.len() {
        if grounded[start] || potential_slot[start].is_none() {
            continue;
        }
        let mut group = mark(start, &mut grounded);
        group.sort_unstable();
        let terminals: Vec<&str> = group
            .iter()
            .map(|&t| design.terminals[t].name.as_str())
            .collect();
        let quantities: Vec<&str> = design
            .quantities
            .iter()
            .filter(|q| branch(q.kind).is_some_and(|(p, _)| group.contains(&p.index())))
            .map(|q| q.name.as_str())
            .collect();
        errors.push(AnalogError::Floating {
            span: design.terminals[start].span,
            terminals: terminals.join(", "),
            quantities: quantities.join(", "),
        });
    }
    errors
}
