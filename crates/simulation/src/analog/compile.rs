//! The steps of [`AnalogSystem::with_options`](super::AnalogSystem::with_options), in order:
//! assembly with the structure checked, source scaling and elimination of explicit unknowns,
//! the survivors renumbered, the solver's row order from a matching, the tapes of residuals,
//! Jacobians and roots, and the tolerances the eliminated quantities hand to their survivors.
//!
//! Each step is a function of what the previous ones gave; `with_options` reads as the list.

use vams_design::{Design, QuantityId, SignalId, SignalKind};

use super::build::{self, Assembled, Origin, Unknown};
use super::deriv::{Var, derivative};
use super::error::AnalogError;
use super::lower::lower;
use super::reduce::{self, Elimination};
use super::sym::{self, Sym};
use super::tape::{Tape, TapeBuilder};
use super::{
    AnalogOptions, Eliminated, IndexReduced, RESIDUALS, incidence, protected_unknowns,
    scale_sources, structure, tolerance,
};

/// The system as written, its structure checked, so that diagnostics name the model's own
/// equations and quantities. A lone across quantity that an equation sets gets an implicit
/// through quantity, one at a time (each changes the matching); they are returned too.
pub(super) fn assemble_checked(
    design: &Design,
) -> Result<(Assembled, Vec<QuantityId>), Vec<AnalogError>> {
    let mut implicit_flows = Vec::new();
    loop {
        let asm = build::assemble(design, &implicit_flows)?;
        let inc = incidence(&asm);
        let names = structure::Names {
            design,
            unknowns: &asm.unknowns,
            origins: &asm.origins,
        };
        match structure::implicit_flow(&inc, &names) {
            Some(q) => implicit_flows.push(q),
            None => {
                structure::check(&inc, &names)?;
                return Ok((asm, implicit_flows));
            }
        }
    }
}

/// Which of the design's signals the residuals read.
pub(super) fn signals_read(design: &Design, residuals: &[Sym]) -> Vec<bool> {
    let mut reads = vec![false; design.signals.len()];
    for r in residuals {
        r.visit(&mut |e| {
            // Slots past the design's signals are the scale and the delay histories.
            if let Sym::Signal(s) = e
                && let Some(flag) = reads.get_mut(*s)
            {
                *flag = true;
            }
        });
    }
    reads
}

/// Source scaling, then elimination of the unknowns that an equation gives explicitly.
/// Scaling comes first so that a source's value keeps its scale factor wherever substitution
/// carries it. `abstol` is each unknown's tolerance (`None` outside every tolerance group).
pub(super) fn scale_and_eliminate(
    design: &Design,
    residuals: Vec<Sym>,
    asm: &Assembled,
    abstol: &[Option<f64>],
    options: &AnalogOptions,
) -> Elimination {
    let n = asm.unknowns.len();
    let scale = design.signals.len();
    let scaled: Vec<Sym> = (residuals.into_iter().zip(&asm.origins))
        .map(|(r, origin)| match origin {
            Origin::User(_) => scale_sources(r, scale),
            _ => r,
        })
        .collect();
    let protected = if options.eliminate {
        let mut protected = protected_unknowns(design, &asm.quantity_slot, n);
        for r in &scaled {
            reduce::mark_nonlinear(r, &mut protected);
        }
        protected
    } else {
        vec![true; n]
    };
    let potential: Vec<bool> = (asm.unknowns.iter())
        .map(|u| matches!(u, Unknown::Potential(_)))
        .collect();
    // Unknowns outside every tolerance group are judged on the voltage scale.
    let pivot_scale: Vec<f64> = abstol.iter().map(|a| a.unwrap_or(1e-6)).collect();
    let row_abstol: Vec<Option<f64>> = (asm.origins.iter())
        .map(|origin| match origin {
            Origin::Conservation(t) => tolerance::through_abstol(design, *t),
            _ => None,
        })
        .collect();
    reduce::eliminate(
        scaled,
        &reduce::Candidates {
            protected: &protected,
            potential: &potential,
            abstol: &pivot_scale,
            row_abstol: &row_abstol,
        },
    )
}

/// The unknowns that elimination left, renumbered in their original order.
pub(super) struct Survivors {
    /// The new index of each original unknown, `usize::MAX` where eliminated.
    pub live: Vec<usize>,
    pub names: Vec<String>,
    pub unknowns: Vec<Unknown>,
}

pub(super) fn survivors(
    design: &Design,
    all_unknowns: Vec<Unknown>,
    elim: &Elimination,
    reduction: &mut Option<IndexReduced>,
) -> Survivors {
    let mut live = vec![usize::MAX; all_unknowns.len()];
    let mut names = Vec::new();
    let mut unknowns = Vec::new();
    let mut all_names = Unknown::names(&all_unknowns, design);
    for (j, unknown) in all_unknowns.into_iter().enumerate() {
        if elim.replacement[j].is_none() {
            live[j] = unknowns.len();
            names.push(std::mem::take(&mut all_names[j]));
            unknowns.push(unknown);
        }
    }
    if let Some(r) = reduction {
        r.base_slot = (live[..r.base_unknowns].iter())
            .map(|&k| (k != usize::MAX).then_some(k))
            .collect();
    }
    Survivors {
        live,
        names,
        unknowns,
    }
}

/// The equations elimination kept, over the survivors' numbering, with the assembly row each
/// came from.
pub(super) fn kept_equations(elim: &mut Elimination, live: &[usize]) -> (Vec<usize>, Vec<Sym>) {
    let kept_rows = elim.kept.iter().map(|(row, _)| *row).collect();
    let residuals = (std::mem::take(&mut elim.kept).into_iter())
        .map(|(_, mut r)| {
            reduce::renumber_in_place(&mut r, &|k| live[k]);
            r
        })
        .collect();
    (kept_rows, residuals)
}

/// Where each equation goes in the solver and which unknowns the error control skips.
pub(super) struct RowOrder {
    /// The equation (index into the kept residuals) of each solver row.
    pub order: Vec<usize>,
    /// The assembly row of each solver row.
    pub row_source: Vec<usize>,
    /// Per unknown: excluded from the local error estimate.
    pub error_exempt: Vec<bool>,
}

/// Solver row j is the equation matched to unknown j: the diagonal is then a structural
/// nonzero (gmin stamps a real entry), and the sparse LU's fill-reducing order sees no
/// spurious couplings between an unrelated equation and unknown that happen to share an
/// index (on an RC ladder those made the fill grow with the square of the size). Renumbers
/// `pattern`'s rows to solver rows.
pub(super) fn row_order(
    pattern: &mut [(usize, usize)],
    jac_exprs: &[(Option<Sym>, Option<Sym>)],
    differential: &[bool],
    unknowns: &[Unknown],
    kept_rows: &[usize],
) -> RowOrder {
    let (n_eq, n) = (kept_rows.len(), unknowns.len());
    let inc = structure::Incidence::new(n_eq, n, pattern);
    let index1_pattern: Vec<(usize, usize)> = (pattern.iter().zip(jac_exprs))
        .filter(|&(&(_, c), (dx, ddot))| {
            if differential[c] {
                ddot.is_some()
            } else {
                dx.is_some()
            }
        })
        .map(|(&entry, _)| entry)
        .collect();
    let mut error_exempt = structure::higher_index_algebraic(
        &structure::Incidence::new(n_eq, n, &index1_pattern),
        differential,
    );
    // A derivative made an unknown follows its state's accuracy (a constraint's
    // derivative gives it); its own scale is not known to judge it on.
    for (exempt, unknown) in error_exempt.iter_mut().zip(unknowns) {
        *exempt |= matches!(unknown, Unknown::Derivative { .. });
    }
    let matching = structure::maximum_matching(&inc);
    let order: Vec<usize> = match matching.col_match.iter().copied().collect() {
        Some(rows) if n == n_eq => rows,
        // The full system passed `check`; keep this order if elimination lost the
        // structure (the factorisation then reports the singular row).
        _ => (0..n_eq).collect(),
    };
    let mut solver_row = vec![0; n_eq];
    for (new, &old) in order.iter().enumerate() {
        solver_row[old] = new;
    }
    for entry in pattern.iter_mut() {
        entry.0 = solver_row[entry.0];
    }
    let row_source = order.iter().map(|&k| kept_rows[k]).collect();
    RowOrder {
        order,
        row_source,
        error_exempt,
    }
}

/// For the small-signal model: how each row depends on the signals of `'zoh` and `'ztf` (a
/// transfer from their inputs in the frequency domain).
pub(super) fn signal_partials(
    design: &Design,
    order: &[usize],
    residuals: &[Sym],
) -> Vec<(usize, SignalId, Sym)> {
    let mut partials = Vec::new();
    for sampled in &design.sampled {
        let slot = sampled.signal.index();
        for (row, &k) in order.iter().enumerate() {
            if residuals[k].any(|e| matches!(e, Sym::Signal(s) if *s == slot)) {
                let d = derivative(&residuals[k], Var::Signal(slot));
                partials.push((row, sampled.signal, d));
            }
        }
    }
    partials
}

/// The compiled residuals and Jacobian entries, and what the step control reads off them.
pub(super) struct Tapes {
    pub newton: Tape,
    /// Each row's terms (outputs of the residual section), row by row from `term_start`.
    pub terms: Vec<usize>,
    pub term_start: Vec<usize>,
    pub jac_dx: Vec<Option<usize>>,
    pub jac_ddot: Vec<Option<usize>>,
    /// The arguments of every `exp`, for the step control's overflow guard.
    pub exp: Tape,
    /// The breakpoints of the tables of time in the residuals.
    pub table_times: Vec<f64>,
    /// Whether every residual is affine in the unknowns.
    pub linear: bool,
}

/// Compiles the residuals in solver row order, each row's terms, and the Jacobian entries
/// into one hash-consed tape.
pub(super) fn tapes(
    order: &[usize],
    residuals: Vec<Sym>,
    jac_exprs: Vec<(Option<Sym>, Option<Sym>)>,
) -> Tapes {
    let mut nb = TapeBuilder::default();
    for &k in order {
        nb.push(&residuals[k]);
    }
    // Each row's terms, in the residual section: they are the row's own subexpressions
    // (hash-consed onto its instructions), so they cost outputs, not work.
    let mut terms = Vec::new();
    let mut term_start = Vec::with_capacity(order.len() + 1);
    let mut row_terms = Vec::new();
    for &k in order {
        term_start.push(terms.len());
        row_terms.clear();
        residuals[k].terms(&mut row_terms);
        for term in &row_terms {
            terms.push(nb.push(term));
        }
    }
    term_start.push(terms.len());
    let residual_section = nb.end_section();
    debug_assert_eq!(residual_section, RESIDUALS);
    let linear = residuals.iter().all(Sym::is_affine);
    let mut eb = TapeBuilder::default();
    let mut table_times = Vec::new();
    for r in &residuals {
        r.visit(&mut |e| match e {
            Sym::Un(sym::Un::Exp, a) => {
                eb.push(a);
            }
            Sym::Table(f, a) if !f.slope && **a == Sym::Now => {
                table_times.extend_from_slice(f.table.xs());
            }
            _ => {}
        });
    }
    table_times.sort_by(f64::total_cmp);
    table_times.dedup();
    drop(residuals);
    let mut jac_dx = Vec::with_capacity(jac_exprs.len());
    let mut jac_ddot = Vec::with_capacity(jac_exprs.len());
    for (dx, ddot) in &jac_exprs {
        jac_dx.push(dx.as_ref().map(|d| nb.push(d)));
        jac_ddot.push(ddot.as_ref().map(|d| nb.push(d)));
    }
    Tapes {
        newton: nb.finish(),
        terms,
        term_start,
        jac_dx,
        jac_ddot,
        exp: eb.finish(),
        table_times,
        linear,
    }
}

/// The root functions of the `Q'above(level)` signals (`Q - level`, over the survivors) and
/// the signals they belong to.
pub(super) fn above_roots(
    design: &Design,
    quantity_slot: &[usize],
    elim: &Elimination,
    live: &[usize],
) -> Result<(Vec<SignalId>, Tape), Vec<AnalogError>> {
    let slot_of = |q: usize| quantity_slot[q];
    let mut above = Vec::new();
    let mut roots = TapeBuilder::default();
    let mut errors = Vec::new();
    for (i, s) in design.signals.iter().enumerate() {
        if let SignalKind::Above { quantity, level } = &s.kind {
            match (lower(quantity, &slot_of), lower(level, &slot_of)) {
                (Ok(q), Ok(l)) => {
                    let mut root = elim.apply(&Sym::sub(q, l));
                    reduce::renumber_in_place(&mut root, &|k| live[k]);
                    roots.push(&root);
                    above.push(SignalId(i as u32));
                }
                (Err(e), _) | (_, Err(e)) => errors.push(AnalogError::NotAnalog {
                    span: s.span,
                    what: e.0.to_string(),
                }),
            }
        }
    }
    if errors.is_empty() {
        Ok((above, roots.finish()))
    } else {
        Err(errors)
    }
}

/// The survivors' absolute tolerances, and per survivor the largest scale of an eliminated
/// alias without a tolerance of its own. An unknown that is a scaled alias of an eliminated
/// quantity (`y = c * x`) inherits that quantity's absolute tolerance divided by `|c|`, so
/// the error control stays as strict as it was on the quantity (a transfer function's
/// internal state is often scaled far below its output).
pub(super) fn survivor_tolerances(
    elim: &Elimination,
    live: &[usize],
    abstol: &[Option<f64>],
    n: usize,
) -> (Vec<Option<f64>>, Vec<f64>) {
    let mut group_abstol: Vec<Option<f64>> = (0..abstol.len())
        .filter(|&j| live[j] != usize::MAX)
        .map(|j| abstol[j])
        .collect();
    let mut alias_scale = vec![0.0_f64; n];
    for (j, r) in elim.replacement.iter().enumerate() {
        let Some(terms) = r.as_ref().and_then(reduce::affine) else {
            continue;
        };
        let [(k, c)] = terms[..] else { continue };
        let (k, c) = (live[k], c.abs());
        if !(c.is_finite() && c > 0.0) {
            continue;
        }
        match abstol[j] {
            Some(a) => {
                let scaled = a / c;
                group_abstol[k] = Some(group_abstol[k].map_or(scaled, |own| own.min(scaled)));
            }
            None => alias_scale[k] = alias_scale[k].max(c),
        }
    }
    (group_abstol, alias_scale)
}

/// The eliminated unknowns with their replacements over the survivors, for output and
/// processes.
pub(super) fn eliminated(
    elim: Elimination,
    live: &[usize],
    all_unknowns: &[Unknown],
) -> Vec<Eliminated> {
    let solved_from = elim.solved_from;
    (elim.replacement.into_iter().enumerate())
        .filter_map(|(j, r)| {
            let mut replacement = r?;
            reduce::renumber_in_place(&mut replacement, &|k| live[k]);
            Some(Eliminated {
                unknown: j,
                quantity: match all_unknowns[j] {
                    Unknown::Quantity(q) => Some(q),
                    Unknown::Potential(_) | Unknown::Flow(_) | Unknown::Derivative { .. } => None,
                },
                solved_from: solved_from[j].unwrap_or(usize::MAX),
                replacement,
            })
        })
        .collect()
}
