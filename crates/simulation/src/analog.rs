//! The analog side of an elaborated design as a DAE the solver integrates.
//!
//! **Takes** a [`Design`]; **gives** an [`AnalogSystem`] implementing [`DaeSystem`]: unknowns
//! (terminal potentials, then quantities), the conservation laws generated from the terminal
//! graph, the user's equations compiled to a flat tape with symbolic Jacobians, structural
//! analysis before any number is computed, and the quiescent (and break) initial conditions.
//!
//! May use `design`, `solver`, `source`, `diagnostics`. Knows nothing of processes or time
//! stepping policy: the kernel drives it.
//!
//! Pipeline inside [`AnalogSystem::new`]: `build` (unknowns, residuals with origins, floating
//! terminals) -> `deriv` (symbolic dF/dx and dF/dx') -> `structure` (count rule, matching,
//! Dulmage-Mendelsohn) -> `tape` (residuals and Jacobian entries as flat programs).

use vams_design::{Design, Expr, Instr, QuantityId, SignalId, SignalKind};
use vams_solver::{DaeSystem, OpOptions, SolveError};

mod build;
mod compile;
mod delay;
mod deriv;
mod error;
mod index;
mod listing;
mod lower;
mod quiescent;
mod reduce;
mod small_signal;
mod structure;
mod sym;
mod tape;
mod tolerance;

#[cfg(test)]
mod tests;

pub use build::{Origin, Unknown};
pub use error::{AnalogError, AnalogWarning};
pub use listing::{Dae, DaeEliminated, DaeEquation, DaeIndexReduction, DaeUnknown};
pub use small_signal::SmallSignalModel;
pub use tolerance::TOLERANCE_GROUPS;

/// The absolute tolerance of quantity `q` from its tolerance group (its own, else its
/// branch's), eliminated or not; `None` where no known group applies.
pub fn quantity_abstol(design: &Design, q: QuantityId) -> Option<f64> {
    tolerance::per_unknown(design, &[Unknown::Quantity(q)])[0]
}

use deriv::{Var, derivative};
use lower::lower;
use sym::{Bin, Sym};
use tape::{Tape, TapeBuilder};

/// The compiled DAE of a design.
pub struct AnalogSystem {
    names: Vec<String>,
    unknowns: Vec<Unknown>,
    origins: Vec<Origin>,
    /// Assembly row of each solver row.
    row_source: Vec<usize>,
    /// Solver index of each quantity, `None` when eliminated.
    quantity_slot: Vec<Option<usize>>,
    /// The quantities `quantity_values` fills and where each comes from (all of them until
    /// `select_quantities` says otherwise; built on first use).
    fill: Option<Vec<(u32, QuantitySource)>>,
    /// The eliminated unknowns, for listings.
    eliminated: Vec<Eliminated>,
    differential: Vec<bool>,
    /// Algebraic unknowns of higher index, left out of the local error test
    /// ([`structure::higher_index_algebraic`]).
    error_exempt: Vec<bool>,
    pattern: Vec<(usize, usize)>,
    /// Outputs: the residuals (section [`RESIDUALS`], in solver row order), then the nonzero
    /// dF/dx and dF/dx' entries. One tape, so that the Jacobian at the point whose residual
    /// Newton just computed reuses the work they share (exponentials, conditions).
    newton_tape: Tape,
    /// Newton tape outputs of the terms of each residual (row `i`'s are
    /// `terms[term_start[i]..term_start[i + 1]]`), for [`DaeSystem::residual_scale`].
    terms: Vec<usize>,
    term_start: Vec<usize>,
    /// Per pattern entry, the Newton tape outputs of dF/dx and dF/dx' (if nonzero).
    jac_dx: Vec<Option<usize>>,
    jac_ddot: Vec<Option<usize>>,
    /// Values and `'dot`s of eliminated quantities (see `fill`).
    outputs_tape: Tape,
    /// The arguments of every `exp` in the residuals, for `step_limit`, and scratch for it.
    exp_tape: Tape,
    exp_before: Vec<f64>,
    x_trial: Vec<f64>,
    /// Signal values read by equations; the last slot is the source scale.
    signals: Vec<f64>,
    reads: Vec<bool>,
    above: Vec<SignalId>,
    roots_tape: Tape,
    /// Per unknown, the absolute tolerance of its tolerance group, when known.
    group_abstol: Vec<Option<f64>>,
    /// Per unknown, the largest `|c|` of an eliminated quantity `c * x` without a tolerance
    /// group (0 if none): the default absolute tolerance divided by it bounds `x`'s.
    alias_scale: Vec<f64>,
    /// `Q'delayed` histories, by index into `Design::delays`; their values go to the signal
    /// slots after the source scale (see `delay::history_slot`).
    delay_lines: Vec<delay::DelayLine>,
    /// Number of design signals (the source scale's slot).
    design_signals: usize,
    /// Every residual is affine in the unknowns ([`Sym::is_affine`]).
    linear: bool,
    /// Lone across quantities given an implicit through quantity ([`Unknown::Flow`]).
    implicit_flows: Vec<QuantityId>,
    /// What index reduction did, if the model needed it.
    index_reduced: Option<IndexReduced>,
    /// `(solver row, signal, dF/dsignal)` for the signals of `Design::sampled` (the
    /// small-signal model's transfers through `'zoh` and `'ztf`).
    signal_partials: Vec<(usize, SignalId, Sym)>,
    /// The options this system was built with (a new choice of states rebuilds it).
    options: AnalogOptions,
    /// The quantities last asked for ([`AnalogSystem::select_quantities`]).
    wanted: Option<Vec<bool>>,
    /// The points of the tables of `now` the residuals read (`pwl(drive, now)`), in order:
    /// the integrator steps to each, as a SPICE simulator does to a PWL source's corners.
    table_times: Vec<f64>,
}

/// The incidence of the assembled residuals (the unknowns each one names).
fn incidence(asm: &build::Assembled) -> structure::Incidence {
    let mut pattern = Vec::new();
    let mut cols = Vec::new();
    for (row, r) in asm.residuals.iter().enumerate() {
        cols.clear();
        r.structural_unknowns(&mut cols);
        cols.sort_unstable();
        cols.dedup();
        pattern.extend(cols.iter().map(|&c| (row, c)));
    }
    structure::Incidence::new(asm.residuals.len(), asm.unknowns.len(), &pattern)
}

/// Exponential arguments below this are not limited (`exp(10)` is a diode well below
/// conduction for any practical saturation current).
const EXP_LIMIT_FROM: f64 = 10.0;

/// The Newton tape's section of the residuals.
const RESIDUALS: usize = 0;

/// An unknown solved for and substituted (indices of the system as assembled).
pub struct Eliminated {
    /// Index among the assembled unknowns.
    pub unknown: usize,
    /// The quantity, unless the unknown is a terminal potential.
    pub quantity: Option<QuantityId>,
    /// Assembly row of the equation it was solved from.
    pub solved_from: usize,
    /// Its value in terms of the solver's unknowns.
    replacement: Sym,
}

/// Where `quantity_values` takes a quantity's value and `'dot` from.
#[derive(Clone, Copy, Debug)]
enum QuantitySource {
    /// Solver unknown.
    State(u32),
    /// Outputs-tape entries of an eliminated quantity.
    Output(u32, u32),
}

/// Multiplies every top-level additive term of `e` that reads no unknown by the source-scale
/// pseudo-signal `scale`, so that source stepping ramps the independent sources.
fn scale_sources(e: Sym, scale: usize) -> Sym {
    match e {
        Sym::Bin(op @ (Bin::Add | Bin::Sub), a, b) => {
            Sym::bin(op, scale_sources(*a, scale), scale_sources(*b, scale))
        }
        Sym::Un(sym::Un::Neg, a) => Sym::neg(scale_sources(*a, scale)),
        e if !e.reads_unknown() && e.as_const() != Some(0.0) => Sym::mul(e, Sym::Signal(scale)),
        e => e,
    }
}

/// Choices made when compiling a design.
#[derive(Clone, Debug, PartialEq)]
pub struct AnalogOptions {
    /// Solve equations for unknowns they give explicitly and substitute them (see
    /// `reduce`): branch quantities of circuits disappear from the solver's system.
    pub eliminate: bool,
    /// The initial break values (by `QuantityId`), where index reduction chooses its states:
    /// a quantity not given counts at its initial guess, and one given stays a state where
    /// the point allows ([`AnalogSystem::choose_states`]).
    pub state_point: Vec<(QuantityId, f64)>,
    /// The values of the model's own unknowns (assembled order) where index reduction
    /// chooses its states during a run ([`AnalogSystem::choose_states_again`]).
    pub state_values: Vec<f64>,
}

impl Default for AnalogOptions {
    fn default() -> Self {
        AnalogOptions {
            eliminate: true,
            state_point: Vec::new(),
            state_values: Vec::new(),
        }
    }
}

/// Symbolic derivatives of `residuals` by every unknown they read (`x` and `x'`): the
/// structural nonzeros, which unknowns appear differentiated, and the derivative expressions.
struct Derivatives {
    pattern: Vec<(usize, usize)>,
    differential: Vec<bool>,
    exprs: Vec<(Option<Sym>, Option<Sym>)>,
}

fn derivatives(residuals: &[Sym], n: usize) -> Derivatives {
    let mut differential = vec![false; n];
    let mut pattern = Vec::new();
    let mut exprs = Vec::new();
    // (column, read as x', read as x) per occurrence: a tree that does not read `x_j` (or
    // `x_j'`) has derivative 0 by it, so only the forms that occur are differentiated.
    let mut cols: Vec<(usize, bool)> = Vec::new();
    for (row, r) in residuals.iter().enumerate() {
        cols.clear();
        r.visit(&mut |e| match e {
            Sym::X(j) => cols.push((*j, false)),
            Sym::Dot(j) => {
                differential[*j] = true;
                cols.push((*j, true));
            }
            _ => {}
        });
        cols.sort_unstable();
        cols.dedup();
        for (k, &(col, is_dot)) in cols.iter().enumerate() {
            if k > 0 && cols[k - 1].0 == col {
                continue; // (col, false) came first and handled both forms
            }
            let reads_x = !is_dot;
            let reads_dot = is_dot || cols.get(k + 1) == Some(&(col, true));
            let nonzero = |d: Sym| (d.as_const() != Some(0.0)).then_some(d);
            let dx = reads_x
                .then(|| derivative(r, Var::X(col)))
                .and_then(nonzero);
            let ddot = reads_dot
                .then(|| derivative(r, Var::Dot(col)))
                .and_then(nonzero);
            if dx.is_some() || ddot.is_some() {
                pattern.push((row, col));
                exprs.push((dx, ddot));
            }
        }
    }
    Derivatives {
        pattern,
        differential,
        exprs,
    }
}

/// The signal slots at the start (see `delay::ready_slot`): the design's signals at their
/// initial values, the source scale 1, history not ready (`Q'delayed(T) = Q`, the quiescent
/// domain), time running (0 only while `quiescent` solves), and no delayed values yet.
fn initial_signals(design: &Design) -> Vec<f64> {
    let mut signals: Vec<f64> = (design.signals.iter())
        .map(|s| s.init.as_f64().unwrap_or(0.0))
        .collect();
    signals.extend([1.0, 0.0, 1.0]);
    signals.extend(design.delays.iter().map(|_| 0.0));
    signals
}

/// What index reduction did, for `vams dae`.
pub struct IndexReduced {
    /// The structural index of the model as written.
    pub index: usize,
    /// Every unknown of the reduced system (the model's, then the derivatives made unknowns).
    pub names: Vec<String>,
    /// The equations it added: derivatives of the model's and state chains, with origins.
    pub equations: Vec<(String, Sym)>,
    /// The derivatives made algebraic unknowns (dummy derivatives).
    pub dummies: Vec<String>,
    /// The unknowns whose derivatives remain: the states.
    pub states: Vec<String>,
    reduction: index::Reduction,
    selection: index::Selection,
    /// Assembled unknowns before reduction (the model's own).
    base_unknowns: usize,
    /// The solver slot of each of them, `None` where eliminated (set once eliminated).
    base_slot: Vec<Option<usize>>,
}

/// A choice of states is kept while its blocks' Hadamard ratio ([`index::Reduction::grip`])
/// stays above this; below, another choice is taken if it grips at least twice as firmly.
const FIRM_GRIP: f64 = 0.5;

/// Pantelides and dummy derivatives on the assembled system (`index`): the system unchanged
/// when its index is 0 or 1, else with the hidden constraints differentiated and a state
/// chosen at `options.state_point`.
fn reduce_index(
    design: &Design,
    asm: build::Assembled,
    options: &AnalogOptions,
) -> Result<(build::Assembled, Option<IndexReduced>), Vec<AnalogError>> {
    let history_from = delay::history_slot(design.signals.len(), 0);
    let time_slot = delay::time_slot(design.signals.len());
    let describe = |k: usize| asm.origins[k].describe(design);
    let found = index::Reduction::find(&asm.residuals, asm.unknowns.len(), history_from, time_slot);
    let reduction = match found {
        // Index 2 is integrated as written: BDF handles it, the higher-index algebraic
        // unknowns sitting out the error test (`structure::higher_index_algebraic`), and the
        // rigid couplings of mechanics disappear in elimination. Reducing it is not safe on
        // circuits: a cluster of nodes joined only by capacitors (two in parallel, a loop)
        // has a common-mode potential that Kirchhoff's laws fix algebraically through a
        // cancellation no structural method sees, and dummy derivatives would make it a state
        // (a singular Jacobian a few steps in). From index 3 on (a mechanism's position
        // constraint) BDF cannot start at all, and the reduction is the way.
        Ok(Some(r)) if r.index() >= 3 => r,
        Ok(_) => return Ok((asm, None)),
        Err(e) => {
            let (k, reason, help) = match e {
                index::IndexError::Singular { equation } => (
                    equation,
                    format!(
                        "{} reads no unknown of its own however often it is differentiated",
                        describe(equation)
                    ),
                    "the equations are structurally singular: check that each constraint                      leaves some quantity free to satisfy it",
                ),
                index::IndexError::Delayed { equation } => (
                    equation,
                    format!(
                        "{} must be differentiated, and it reads a 'delayed value",
                        describe(equation)
                    ),
                    "write the constraint without 'delayed, or give the delayed value a                      quantity of its own with a derivative",
                ),
            };
            return Err(vec![AnalogError::Index {
                span: asm.origins[k].span(design),
                reason,
                help,
            }]);
        }
    };
    let mut point: Vec<f64> = asm
        .unknowns
        .iter()
        .map(|u| match u {
            Unknown::Quantity(q) => design.quantities[q.index()].initial_guess.unwrap_or(0.0),
            _ => 0.0,
        })
        .collect();
    let mut held = vec![false; point.len()];
    for &(q, v) in &options.state_point {
        if let Some(&slot) = asm.quantity_slot.get(q.index()) {
            point[slot] = v;
            held[slot] = true;
        }
    }
    for (p, &v) in point.iter_mut().zip(&options.state_values) {
        *p = v;
    }
    let selection = reduction.select(&point, &held, &initial_signals(design));
    let reduced = reduction.assemble(&asm, &selection);
    let names = Unknown::names(&reduced.unknowns, design);
    let equations = (asm.residuals.len()..reduced.residuals.len())
        .map(|k| {
            let from = build::Origin::describe_among(&reduced.origins, &names, k, design);
            (from, reduced.residuals[k].clone())
        })
        .collect();
    let mut differential = vec![false; reduced.unknowns.len()];
    for r in &reduced.residuals {
        r.visit(&mut |e| {
            if let Sym::Dot(j) = e {
                differential[*j] = true;
            }
        });
    }
    // The derivatives made unknowns that are not states themselves.
    let dummies = (asm.unknowns.len()..reduced.unknowns.len())
        .filter(|&j| !differential[j])
        .map(|j| names[j].clone())
        .collect();
    let states = (0..differential.len())
        .filter(|&j| differential[j])
        .map(|j| names[j].clone())
        .collect();
    let info = IndexReduced {
        index: reduction.index(),
        names,
        equations,
        dummies,
        states,
        base_unknowns: asm.unknowns.len(),
        base_slot: Vec::new(),
        reduction,
        selection,
    };
    Ok((reduced, Some(info)))
}

/// Unknowns the elimination must keep: break targets (their value is set from outside), the
/// inputs of `'delayed` (their history is recorded from the state), and quantities whose
/// `'dot` something other than an equation reads (processes, thresholds, subprograms).
fn protected_unknowns(design: &Design, quantity_slot: &[usize], n: usize) -> Vec<bool> {
    let mut protected = vec![false; n];
    let mut protect = |q: QuantityId| {
        if let Some(&slot) = quantity_slot.get(q.index()) {
            protected[slot] = true;
        }
    };
    let mut dots = Vec::new();
    let mut read_dots = |e: &Expr| {
        e.visit(&mut |e| {
            if let Expr::Dot(q) = e {
                dots.push(*q);
            }
        })
    };
    let code = design
        .processes
        .iter()
        .flat_map(|p| &p.code)
        .chain(design.subprograms.iter().flat_map(|s| &s.code));
    for instr in code {
        instr.visit_exprs(&mut read_dots);
        if let Instr::Break { reinit, .. } = instr {
            for r in reinit {
                protect(r.selector);
                protect(r.quantity);
            }
        }
    }
    for s in &design.signals {
        if let SignalKind::Above { quantity, level } = &s.kind {
            read_dots(quantity);
            read_dots(level);
        }
    }
    for l in &design.limits {
        read_dots(&l.max_step);
    }
    for d in &design.delays {
        protect(d.input);
    }
    // A spectral source keeps its equation `q == 0.0`: the small-signal analysis puts its
    // phasor in that row (substituted, the constant 0 would leave no trace of it).
    for s in &design.spectral_sources {
        protect(s.quantity);
    }
    // A noise source likewise: the noise analysis injects its density there.
    for s in &design.noise_sources {
        protect(s.quantity);
    }
    for q in dots {
        protect(q);
    }
    protected
}

impl AnalogSystem {
    /// Builds unknowns and equations, checks the structure, eliminates explicit unknowns and
    /// compiles residuals and Jacobians.
    pub fn new(design: &Design) -> Result<AnalogSystem, Vec<AnalogError>> {
        AnalogSystem::with_options(design, &AnalogOptions::default())
    }

    /// [`AnalogSystem::new`] with explicit choices.
    pub fn with_options(
        design: &Design,
        options: &AnalogOptions,
    ) -> Result<AnalogSystem, Vec<AnalogError>> {
        let (asm, implicit_flows) = compile::assemble_checked(design)?;
        let (mut asm, mut reduction) = reduce_index(design, asm, options)?;
        let reads = compile::signals_read(design, &asm.residuals);
        let abstol = tolerance::per_unknown(design, &asm.unknowns);
        let residuals = std::mem::take(&mut asm.residuals);
        let mut elim = compile::scale_and_eliminate(design, residuals, &asm, &abstol, options);
        let all_unknowns = std::mem::take(&mut asm.unknowns);
        let survivors = compile::survivors(design, all_unknowns.clone(), &elim, &mut reduction);
        let live = &survivors.live;
        let n = survivors.unknowns.len();
        let (kept_rows, residuals) = compile::kept_equations(&mut elim, live);
        let Derivatives {
            mut pattern,
            differential,
            exprs: jac_exprs,
        } = derivatives(&residuals, n);
        let rows = compile::row_order(
            &mut pattern,
            &jac_exprs,
            &differential,
            &survivors.unknowns,
            &kept_rows,
        );
        let signal_partials = compile::signal_partials(design, &rows.order, &residuals);
        let tapes = compile::tapes(&rows.order, residuals, jac_exprs);
        // Eliminated quantities are evaluated from the survivors for output and processes.
        let quantity_slot: Vec<Option<usize>> = (asm.quantity_slot.iter())
            .map(|&j| (live[j] != usize::MAX).then_some(live[j]))
            .collect();
        let (above, roots_tape) = compile::above_roots(design, &asm.quantity_slot, &elim, live)?;
        // Delay inputs are protected, so they survive elimination.
        let delay_lines = (design.delays.iter())
            .map(|d| delay::DelayLine::new(live[asm.quantity_slot[d.input.index()]], d.delay))
            .collect();
        let (group_abstol, alias_scale) = compile::survivor_tolerances(&elim, live, &abstol, n);
        let eliminated = compile::eliminated(elim, live, &all_unknowns);
        Ok(AnalogSystem {
            names: survivors.names,
            unknowns: survivors.unknowns,
            origins: asm.origins,
            row_source: rows.row_source,
            quantity_slot,
            fill: None,
            eliminated,
            differential,
            error_exempt: rows.error_exempt,
            pattern,
            newton_tape: tapes.newton,
            terms: tapes.terms,
            term_start: tapes.term_start,
            jac_dx: tapes.jac_dx,
            jac_ddot: tapes.jac_ddot,
            outputs_tape: Tape::default(),
            exp_before: vec![0.0; tapes.exp.len()],
            exp_tape: tapes.exp,
            x_trial: vec![0.0; n],
            signals: initial_signals(design),
            reads,
            above,
            roots_tape,
            group_abstol,
            alias_scale,
            delay_lines,
            design_signals: design.signals.len(),
            linear: tapes.linear,
            implicit_flows,
            index_reduced: reduction,
            signal_partials,
            options: options.clone(),
            wanted: None,
            table_times: tapes.table_times,
        })
    }

    /// Chooses the quantities [`AnalogSystem::quantity_values`] fills (by `QuantityId`; all by
    /// default): eliminated quantities cost an evaluation at every accepted step, so a run
    /// asks only for those it records or its processes read.
    pub fn select_quantities(&mut self, wanted: &[bool]) {
        self.wanted = Some(wanted.to_vec());
        let mut ob = TapeBuilder::default();
        let mut output = vec![None; self.quantity_slot.len()];
        for e in &self.eliminated {
            let Some(q) = e.quantity else { continue };
            if !wanted.get(q.index()).copied().unwrap_or(false) {
                continue;
            }
            // The `'dot` of a quantity whose expression reads `'dot`s or `now` is not
            // available (NaN); quantities whose `'dot` is read elsewhere are never eliminated.
            let dot = match e.replacement.any(|n| matches!(n, Sym::Now | Sym::Dot(_))) {
                false => reduce::time_derivative(&e.replacement).unwrap_or(Sym::Const(f64::NAN)),
                true => Sym::Const(f64::NAN),
            };
            output[q.index()] = Some((ob.push(&e.replacement) as u32, ob.push(&dot) as u32));
        }
        self.fill = Some(
            self.quantity_slot
                .iter()
                .zip(output)
                .enumerate()
                .filter(|(q, _)| wanted.get(*q).copied().unwrap_or(false))
                .filter_map(|(q, (slot, out))| {
                    let source = match (slot, out) {
                        (Some(j), _) => QuantitySource::State(*j as u32),
                        (None, Some((v, d))) => QuantitySource::Output(v, d),
                        (None, None) => return None,
                    };
                    Some((q as u32, source))
                })
                .collect(),
        );
        self.outputs_tape = ob.finish();
    }

    /// Index reduction's choice of states made again at the initial break values `point`
    /// (by `QuantityId`; other quantities at their initial guesses): a pendulum's states
    /// are the coordinates its constraint does not pin down there. Rebuilds a reduced
    /// system; a model of index 0 to 2 is left as it is.
    pub fn choose_states(&mut self, design: &Design, point: &[(QuantityId, f64)]) {
        if self.index_reduced.is_none() {
            return;
        }
        let options = AnalogOptions {
            state_point: point.to_vec(),
            ..self.options.clone()
        };
        // A failure leaves the first choice in place.
        if let Some(rebuilt) = self.rebuilt(design, &options) {
            *self = rebuilt;
        }
    }

    /// This system built again from `design` with other index-reduction `options` (only the
    /// states can differ: it was built once from the same design), with the quantities asked
    /// for and the signal slots as they are now.
    fn rebuilt(&self, design: &Design, options: &AnalogOptions) -> Option<AnalogSystem> {
        let mut rebuilt = AnalogSystem::with_options(design, options).ok()?;
        if let Some(wanted) = &self.wanted {
            rebuilt.select_quantities(wanted);
        }
        rebuilt.signals.clone_from(&self.signals);
        // The `'delayed` histories are the run's, not the system's: a new choice of states
        // moves their inputs to other slots, not their past.
        for (new, old) in rebuilt.delay_lines.iter_mut().zip(&self.delay_lines) {
            new.copy_history(old);
        }
        Some(rebuilt)
    }

    /// Index reduction's states chosen again at the state `(t, x, x')` of a run, where the
    /// current choice loses its grip (a pendulum's rod nearing the horizontal while `y` is
    /// the dummy) and another holds at least twice as firmly: the system is rebuilt around
    /// the new choice and the new state vector returned, for the integrator to restart from
    /// (its differential unknowns are the model's own, at their values now). `None`: keep
    /// going as is (always, for a model of index 0 to 2).
    pub fn choose_states_again(
        &mut self,
        design: &Design,
        t: f64,
        x: &[f64],
        xdot: &[f64],
    ) -> Option<Vec<f64>> {
        let r = self.index_reduced.as_ref()?;
        let mut values = vec![0.0; r.base_unknowns];
        let mut derivatives = vec![0.0; r.base_unknowns];
        for (j, slot) in r.base_slot.iter().enumerate() {
            if let Some(k) = *slot {
                values[j] = x[k];
                derivatives[j] = xdot[k];
            }
        }
        for e in &self.eliminated {
            if e.unknown < r.base_unknowns {
                values[e.unknown] = e.replacement.eval(t, x, xdot, &self.signals);
            }
        }
        let grip = r
            .reduction
            .grip(&r.selection, &values, &derivatives, &self.signals);
        if grip >= FIRM_GRIP {
            return None;
        }
        let other = r.reduction.select(&values, &[], &self.signals);
        if other == r.selection
            || r.reduction
                .grip(&other, &values, &derivatives, &self.signals)
                < 2.0 * grip
        {
            return None;
        }
        let options = AnalogOptions {
            state_point: Vec::new(),
            state_values: values.clone(),
            ..self.options.clone()
        };
        let rebuilt = self.rebuilt(design, &options)?;
        let base_slot = rebuilt.index_reduced.as_ref()?.base_slot.clone();
        let mut state = vec![0.0; rebuilt.len()];
        for (j, slot) in base_slot.iter().enumerate() {
            if let Some(k) = *slot {
                state[k] = values[j];
            }
        }
        *self = rebuilt;
        Some(state)
    }

    /// What index reduction did, `None` for a model of index 0 or 1.
    pub fn index_reduced(&self) -> Option<&IndexReduced> {
        self.index_reduced.as_ref()
    }

    /// What the system accepted with a warning: each lone across quantity given an implicit
    /// through quantity.
    pub fn warnings(&self, design: &Design) -> Vec<AnalogWarning> {
        (self.implicit_flows.iter())
            .map(|&q| {
                let quantity = &design.quantities[q.index()];
                AnalogWarning::ImplicitThrough {
                    span: quantity.span,
                    name: quantity.name.clone(),
                }
            })
            .collect()
    }

    /// Names of the unknowns in solver order (quantity names; `v(t)` for terminal potentials).
    pub fn unknown_names(&self) -> &[String] {
        &self.names
    }

    /// What each unknown is, in solver order.
    pub fn unknowns(&self) -> &[Unknown] {
        &self.unknowns
    }

    /// Where each equation comes from, in assembly order (user equations, across definitions,
    /// conservation laws: the order `vams dae` lists them); solver row `j` is assembly row
    /// [`Self::row_source`]`[j]`.
    pub fn origins(&self) -> &[Origin] {
        &self.origins
    }

    /// The assembly row of each solver row (solver row `j` is matched to unknown `j`).
    pub fn row_source(&self) -> &[usize] {
        &self.row_source
    }

    /// Description and span of equation `row` (a [`SolveError`]'s row index), for messages:
    /// `None` when `row` is out of range. `design` must be the one the system was built from.
    pub fn equation_site(
        &self,
        design: &Design,
        row: usize,
    ) -> Option<(String, vams_syntax::source::Span)> {
        let k = *self.row_source.get(row)?;
        self.origins.get(k)?;
        let names = self
            .index_reduced
            .as_ref()
            .map_or(&[][..], |r| &r.names[..]);
        Some((
            Origin::describe_among(&self.origins, names, k, design),
            Origin::span_among(&self.origins, k, design),
        ))
    }

    /// Name and declaration span of unknown `col` (a [`SolveError`]'s column index).
    pub fn unknown_site(
        &self,
        design: &Design,
        col: usize,
    ) -> Option<(String, vams_syntax::source::Span)> {
        let unknown = *self.unknowns.get(col)?;
        Some((self.names[col].clone(), unknown.span(design)))
    }

    /// Index of quantity `q` in the unknown vector; `None` when `q` was eliminated or belongs
    /// to another design.
    pub fn quantity_slot(&self, q: QuantityId) -> Option<usize> {
        self.quantity_slot.get(q.index()).copied().flatten()
    }

    /// The unknowns solved for and substituted before compiling.
    pub fn eliminated(&self) -> &[Eliminated] {
        &self.eliminated
    }

    /// The selected quantities' values and `'dot`s at the state `(t, x, x')` (see
    /// [`AnalogSystem::select_quantities`]; others are left as they are): surviving ones read
    /// from the state, eliminated ones evaluated (a `'dot` that cannot be, because the quantity's
    /// expression reads `'dot`s or `now`, is NaN; such quantities are kept when read).
    pub fn quantity_values(
        &mut self,
        t: f64,
        x: &[f64],
        xdot: &[f64],
        values: &mut [f64],
        derivatives: &mut [f64],
    ) {
        if self.fill.is_none() {
            self.select_quantities(&vec![true; self.quantity_slot.len()]);
        }
        if !self.outputs_tape.is_empty() {
            self.load_delays(t);
            self.outputs_tape.eval(t, x, xdot, &self.signals);
        }
        let fill = self.fill.as_deref().unwrap_or_default();
        for &(q, source) in fill {
            let (v, d) = match source {
                QuantitySource::State(j) => (x[j as usize], xdot[j as usize]),
                QuantitySource::Output(v, d) => (
                    self.outputs_tape.output(v as usize),
                    self.outputs_tape.output(d as usize),
                ),
            };
            values[q as usize] = v;
            derivatives[q as usize] = d;
        }
    }

    /// Sets the value that equations read for signal `s` (booleans and enums as positions).
    /// Signals of another design are ignored.
    pub fn set_signal(&mut self, s: SignalId, value: f64) {
        // Slots from `design_signals` on are the source scale and the delay histories.
        if s.index() < self.design_signals {
            self.signals[s.index()] = value;
        }
    }

    /// Records an accepted point `(t, x, x')` in the `Q'delayed` histories; from the first
    /// one on, delayed quantities read their history instead of equalling their input.
    pub fn record_history(&mut self, t: f64, x: &[f64], xdot: &[f64]) {
        if self.delay_lines.is_empty() {
            return;
        }
        for line in &mut self.delay_lines {
            line.record(t, x[line.input], xdot[line.input]);
        }
        self.signals[delay::ready_slot(self.design_signals)] = 1.0;
    }

    /// The shortest `Q'delayed` delay: the integrator's step must not exceed it, so that
    /// every delayed value comes from accepted history.
    pub fn shortest_delay(&self) -> Option<f64> {
        self.delay_lines.iter().map(|l| l.delay).reduce(f64::min)
    }

    /// Puts each line's value at `t - delay` in its signal slot, before a tape evaluation.
    fn load_delays(&mut self, t: f64) {
        for (k, line) in self.delay_lines.iter().enumerate() {
            if !line.is_empty() {
                self.signals[delay::history_slot(self.design_signals, k)] =
                    line.value_at(t - line.delay);
            }
        }
    }

    /// True when some equation reads signal `s` (a change is then a discontinuity).
    /// The corners of the tables of time the equations read, in increasing order
    /// (breakpoints of the integration).
    pub fn table_times(&self) -> &[f64] {
        &self.table_times
    }

    pub fn reads_signal(&self, s: SignalId) -> bool {
        self.reads.get(s.index()).copied().unwrap_or(false)
    }

    /// The `'above` signals; root function `i` of [`DaeSystem::roots`] is
    /// `quantity - level` of `above_signals()[i]`.
    pub fn above_signals(&self) -> &[SignalId] {
        &self.above
    }

    /// Absolute tolerance per unknown: from the quantity's tolerance group (see
    /// [`TOLERANCE_GROUPS`]; potentials use their nature's across group), else `default`.
    pub fn abstol(&self, default: f64) -> Vec<f64> {
        self.group_abstol
            .iter()
            .zip(&self.alias_scale)
            // A scale of 0 (no such alias) divides to infinity: no bound.
            .map(|(a, scale)| a.unwrap_or(default).min(default / scale))
            .collect()
    }

    /// Quiescent point at time `t`: solves `F(x', x, t) = 0` with `x'_i = 0` for every
    /// differential unknown except those in `fixed`, which are held at the given value with
    /// `x'_i` solved for instead (the LRM's augmentation set with break values). Starts from
    /// `guess`; returns `(x, x')`.
    pub fn quiescent_point(
        &mut self,
        t: f64,
        guess: &[f64],
        fixed: &[(usize, f64)],
        reltol: f64,
        abstol: &[f64],
        options: &OpOptions,
    ) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
        let time = delay::time_slot(self.design_signals);
        self.signals[time] = 0.0;
        let point = quiescent::solve(self, t, guess, fixed, reltol, abstol, options);
        self.signals[time] = 1.0;
        point
    }

    /// The equation system as text for `vams dae`: unknowns, then each equation with its
    /// source location (`file:line`) and text.
    pub fn listing(&self, design: &Design, sources: &vams_syntax::source::SourceMap) -> String {
        listing::listing(self, design, sources)
    }

    /// The equation system as data: what [`AnalogSystem::listing`] shows.
    pub fn dae(&self, design: &Design, sources: &vams_syntax::source::SourceMap) -> Option<Dae> {
        listing::dae(self, design, sources)
    }

    /// Each Jacobian entry `(row, column)` with whether the equation reads the unknown
    /// undifferentiated (`dF/dx` is not identically zero) and differentiated (`dF/dx'`).
    fn jacobian_structure(&self) -> impl Iterator<Item = ((usize, usize), bool, bool)> + '_ {
        (self.pattern.iter().zip(&self.jac_dx).zip(&self.jac_ddot))
            .map(|((&rc, dx), ddot)| (rc, dx.is_some(), ddot.is_some()))
    }

    /// Fills `out` (pattern order) with `dF/dx'` for the columns flagged in `dot_columns` and
    /// `dF/dx` for the others.
    fn jacobian_columns(
        &mut self,
        t: f64,
        x: &[f64],
        xdot: &[f64],
        dot_columns: &[bool],
        out: &mut [f64],
    ) {
        self.load_delays(t);
        self.newton_tape.eval(t, x, xdot, &self.signals);
        for (k, o) in out.iter_mut().enumerate() {
            let part = if dot_columns[self.pattern[k].1] {
                self.jac_ddot[k]
            } else {
                self.jac_dx[k]
            };
            *o = part.map_or(0.0, |i| self.newton_tape.output(i));
        }
    }
}

impl DaeSystem for AnalogSystem {
    fn len(&self) -> usize {
        self.names.len()
    }

    fn differential(&self) -> &[bool] {
        &self.differential
    }

    fn error_exempt(&self) -> &[bool] {
        &self.error_exempt
    }

    fn pattern(&self) -> &[(usize, usize)] {
        &self.pattern
    }

    fn residual(&mut self, t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        self.load_delays(t);
        self.newton_tape
            .eval_section(RESIDUALS, t, x, xdot, &self.signals);
        for (i, o) in out.iter_mut().enumerate().take(self.names.len()) {
            *o = self.newton_tape.output(i);
        }
    }

    fn residual_scale(&self, out: &mut [f64]) -> bool {
        for (i, o) in out.iter_mut().enumerate().take(self.names.len()) {
            let terms = &self.terms[self.term_start[i]..self.term_start[i + 1]];
            *o = terms
                .iter()
                .map(|&k| self.newton_tape.output(k).abs())
                .fold(0.0, f64::max);
        }
        true
    }

    fn jacobian(&mut self, t: f64, x: &[f64], xdot: &[f64], alpha: f64, out: &mut [f64]) {
        self.load_delays(t);
        self.newton_tape.eval(t, x, xdot, &self.signals);
        let tape = &self.newton_tape;
        for ((o, dx), ddot) in out.iter_mut().zip(&self.jac_dx).zip(&self.jac_ddot) {
            let a = dx.map_or(0.0, |i| tape.output(i));
            // alpha = 0 (operating point) ignores dF/dx' even where it is not finite.
            *o = match ddot {
                Some(i) if alpha != 0.0 => a + alpha * tape.output(*i),
                _ => a,
            };
        }
    }

    fn root_count(&self) -> usize {
        self.above.len()
    }

    fn roots(&mut self, t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        self.load_delays(t);
        self.roots_tape.eval(t, x, xdot, &self.signals);
        for (i, o) in out.iter_mut().enumerate().take(self.above.len()) {
            *o = self.roots_tape.output(i);
        }
    }

    fn jacobian_parts(
        &mut self,
        t: f64,
        x: &[f64],
        xdot: &[f64],
        dot_columns: &[bool],
        out: &mut [f64],
        _scratch: &mut [f64],
    ) {
        self.jacobian_columns(t, x, xdot, dot_columns, out);
    }

    /// Junction limiting in the spirit of SPICE's `pnjlim`, for any `exp(a)`: where the step
    /// drives `a` past [`EXP_LIMIT_FROM`] by more than 2, `a` may grow only by `ln(1 + da)`
    /// (or to `ln(a)` from below 0); the step is scaled to the most limited argument.
    fn step_limit(&mut self, t: f64, x: &[f64], xdot: &[f64], dx: &[f64]) -> f64 {
        if self.exp_before.is_empty() {
            return 1.0;
        }
        self.load_delays(t);
        self.exp_tape.eval(t, x, xdot, &self.signals);
        for (k, b) in self.exp_before.iter_mut().enumerate() {
            *b = self.exp_tape.output(k);
        }
        for ((xt, &x), &d) in self.x_trial.iter_mut().zip(x).zip(dx) {
            *xt = x + d;
        }
        self.exp_tape.eval(t, &self.x_trial, xdot, &self.signals);
        let mut lambda = 1.0_f64;
        for (k, &a0) in self.exp_before.iter().enumerate() {
            let a1 = self.exp_tape.output(k);
            let da = a1 - a0;
            if !(a1 > EXP_LIMIT_FROM && da > 2.0) {
                continue;
            }
            let limited = if a0 > 0.0 { a0 + da.ln_1p() } else { a1.ln() };
            lambda = lambda.min(((limited - a0) / da).clamp(0.0, 1.0));
        }
        lambda
    }

    fn is_linear(&self) -> bool {
        self.linear
    }

    fn set_source_scale(&mut self, s: f64) {
        // The slot after the design's signals is the source scale (see `scale_sources`).
        if let Some(scale) = self.signals.get_mut(self.design_signals) {
            *scale = s;
        }
    }

    /// The values of the design signals the equations read (not the delay histories, which
    /// move continuously).
    fn mode(&self) -> Option<u64> {
        use std::hash::Hasher;
        if !self.reads.contains(&true) {
            return None;
        }
        let mut h = rustc_hash::FxHasher::default();
        for (value, _) in self
            .signals
            .iter()
            .zip(&self.reads)
            .filter(|(_, read)| **read)
        {
            h.write_u64(value.to_bits());
        }
        Some(h.finish())
    }
}
