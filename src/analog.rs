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

use crate::design::{Design, QuantityId, SignalId, SignalKind};
use crate::solver::{DaeSystem, OpOptions, SolveError};

mod build;
mod delay;
mod deriv;
mod error;
mod listing;
mod lower;
mod quiescent;
mod structure;
mod sym;
mod tape;
mod tolerance;

#[cfg(test)]
mod tests;

pub use build::{Origin, Unknown};
pub use error::AnalogError;
pub use tolerance::TOLERANCE_GROUPS;

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
    quantity_slot: Vec<usize>,
    /// The residuals as assembled (before source scaling), for listings.
    residuals: Vec<Sym>,
    differential: Vec<bool>,
    pattern: Vec<(usize, usize)>,
    residual_tape: Tape,
    /// Outputs: the nonzero dF/dx and dF/dx' entries.
    jacobian_tape: Tape,
    /// Per pattern entry, the jacobian tape outputs of dF/dx and dF/dx' (if nonzero).
    jac_dx: Vec<Option<usize>>,
    jac_ddot: Vec<Option<usize>>,
    /// Signal values read by equations; the last slot is the source scale.
    signals: Vec<f64>,
    reads: Vec<bool>,
    above: Vec<SignalId>,
    roots_tape: Tape,
    /// `x'` of the last residual evaluation, for root functions that read a `'dot`.
    last_xdot: Vec<f64>,
    /// Per unknown, the absolute tolerance of its tolerance group, when known.
    group_abstol: Vec<Option<f64>>,
    /// `Q'delayed` histories, by index into `Design::delays`; their values go to the signal
    /// slots after the source scale (see `delay::history_slot`).
    delay_lines: Vec<delay::DelayLine>,
    /// Number of design signals (the source scale's slot).
    design_signals: usize,
}

/// Multiplies every top-level additive term of `e` that reads no unknown by the source-scale
/// pseudo-signal `scale`, so that source stepping ramps the independent sources.
fn scale_sources(e: Sym, scale: usize) -> Sym {
    let reads_unknown = |e: &Sym| {
        let mut found = false;
        e.visit(&mut |n| found |= matches!(n, Sym::X(_) | Sym::Dot(_)));
        found
    };
    match e {
        Sym::Bin(op @ (Bin::Add | Bin::Sub), a, b) => {
            Sym::bin(op, scale_sources(*a, scale), scale_sources(*b, scale))
        }
        Sym::Un(sym::Un::Neg, a) => Sym::neg(scale_sources(*a, scale)),
        e if !reads_unknown(&e) && e.as_const() != Some(0.0) => Sym::mul(e, Sym::Signal(scale)),
        e => e,
    }
}

impl AnalogSystem {
    /// Builds unknowns and equations, checks the structure, compiles residuals and Jacobians.
    pub fn new(design: &Design) -> Result<AnalogSystem, Vec<AnalogError>> {
        let asm = build::assemble(design)?;
        let n = asm.unknowns.len();
        let n_eq = asm.residuals.len();

        // Symbolic derivatives: every unknown a residual reads, by x and by x'.
        let mut differential = vec![false; n];
        let mut pattern = Vec::new();
        let mut jac_exprs: Vec<(Option<Sym>, Option<Sym>)> = Vec::new();
        for (row, r) in asm.residuals.iter().enumerate() {
            let mut cols = Vec::new();
            r.visit(&mut |e| match e {
                Sym::X(j) => cols.push(*j),
                Sym::Dot(j) => {
                    differential[*j] = true;
                    cols.push(*j);
                }
                _ => {}
            });
            cols.sort_unstable();
            cols.dedup();
            for col in cols {
                let nonzero = |d: Sym| (d.as_const() != Some(0.0)).then_some(d);
                let dx = nonzero(derivative(r, Var::X(col)));
                let ddot = nonzero(derivative(r, Var::Dot(col)));
                if dx.is_some() || ddot.is_some() {
                    pattern.push((row, col));
                    jac_exprs.push((dx, ddot));
                }
            }
        }

        let inc = structure::Incidence::new(n_eq, n, &pattern);
        structure::check(
            &inc,
            &structure::Names {
                design,
                unknowns: &asm.unknowns,
                names: &asm.names,
                origins: &asm.origins,
            },
        )?;

        // Solver row j is the equation matched to unknown j: the diagonal is then a structural
        // nonzero (gmin stamps a real entry), and the sparse LU's fill-reducing order sees no
        // spurious couplings between an unrelated equation and unknown that happen to share an
        // index (on an RC ladder those made the fill grow with the square of the size).
        let matching = structure::maximum_matching(&inc);
        let row_source: Vec<usize> = match matching.col_match.iter().copied().collect() {
            Some(rows) if n == n_eq => rows,
            // `check` passed, so the matching is perfect; keep assembly order otherwise.
            _ => (0..n_eq).collect(),
        };
        let mut solver_row = vec![0; n_eq];
        for (new, &old) in row_source.iter().enumerate() {
            solver_row[old] = new;
        }
        for entry in &mut pattern {
            entry.0 = solver_row[entry.0];
        }

        let scale = design.signals.len();
        let mut rb = TapeBuilder::default();
        for (r, origin) in row_source
            .iter()
            .map(|&old| (&asm.residuals[old], &asm.origins[old]))
        {
            let r = match origin {
                Origin::User(_) => scale_sources(r.clone(), scale),
                _ => r.clone(),
            };
            rb.push(&r);
        }
        let mut jb = TapeBuilder::default();
        let mut jac_dx = Vec::with_capacity(pattern.len());
        let mut jac_ddot = Vec::with_capacity(pattern.len());
        for (dx, ddot) in &jac_exprs {
            jac_dx.push(dx.as_ref().map(|d| jb.push(d)));
            jac_ddot.push(ddot.as_ref().map(|d| jb.push(d)));
        }

        let mut reads = vec![false; design.signals.len()];
        for r in &asm.residuals {
            r.visit(&mut |e| {
                // Slots past the design's signals are the scale and the delay histories.
                if let Sym::Signal(s) = e
                    && let Some(flag) = reads.get_mut(*s)
                {
                    *flag = true;
                }
            });
        }

        let slot_of = |q: usize| asm.quantity_slot[q];
        let mut above = Vec::new();
        let mut roots = TapeBuilder::default();
        let mut errors = Vec::new();
        for (i, s) in design.signals.iter().enumerate() {
            if let SignalKind::Above { quantity, level } = &s.kind {
                match (lower(quantity, &slot_of), lower(level, &slot_of)) {
                    (Ok(q), Ok(l)) => {
                        roots.push(&Sym::sub(q, l));
                        above.push(SignalId(i as u32));
                    }
                    (Err(e), _) | (_, Err(e)) => errors.push(AnalogError::NotAnalog {
                        span: s.span,
                        what: e.0.to_string(),
                    }),
                }
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }

        let mut signals: Vec<f64> = design
            .signals
            .iter()
            .map(|s| s.init.as_f64().unwrap_or(0.0))
            .collect();
        signals.push(1.0);
        // History not ready: `Q'delayed(T) = Q` (the quiescent domain).
        signals.push(0.0);
        signals.extend(design.delays.iter().map(|_| 0.0));
        let delay_lines = design
            .delays
            .iter()
            .map(|d| delay::DelayLine::new(asm.quantity_slot[d.input.index()], d.delay))
            .collect();
        let group_abstol = tolerance::per_unknown(design, &asm.unknowns);
        Ok(AnalogSystem {
            names: asm.names,
            unknowns: asm.unknowns,
            origins: asm.origins,
            row_source,
            quantity_slot: asm.quantity_slot,
            residuals: asm.residuals,
            differential,
            pattern,
            residual_tape: rb.finish(),
            jacobian_tape: jb.finish(),
            jac_dx,
            jac_ddot,
            signals,
            reads,
            above,
            roots_tape: roots.finish(),
            last_xdot: vec![0.0; n],
            group_abstol,
            delay_lines,
            design_signals: design.signals.len(),
        })
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
    ) -> Option<(String, crate::source::Span)> {
        let origin = *self.origins.get(*self.row_source.get(row)?)?;
        Some((origin.describe(design), origin.span(design)))
    }

    /// Name and declaration span of unknown `col` (a [`SolveError`]'s column index).
    pub fn unknown_site(
        &self,
        design: &Design,
        col: usize,
    ) -> Option<(String, crate::source::Span)> {
        let unknown = *self.unknowns.get(col)?;
        Some((self.names[col].clone(), unknown.span(design)))
    }

    /// Index of quantity `q` in the unknown vector (`q` must belong to the design the system
    /// was built from).
    pub fn quantity_slot(&self, q: QuantityId) -> usize {
        self.quantity_slot[q.index()]
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
            .map(|a| a.unwrap_or(default))
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
        quiescent::solve(self, t, guess, fixed, reltol, abstol, options)
    }

    /// The equation system as text for `vams dae`: unknowns, then each equation with its
    /// source location (`file:line`) and text.
    pub fn listing(&self, design: &Design, sources: &crate::source::SourceMap) -> String {
        listing::listing(self, design, sources)
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
        self.jacobian_tape.eval(t, x, xdot, &self.signals);
        for (k, o) in out.iter_mut().enumerate() {
            let part = if dot_columns[self.pattern[k].1] {
                self.jac_ddot[k]
            } else {
                self.jac_dx[k]
            };
            *o = part.map_or(0.0, |i| self.jacobian_tape.output(i));
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

    fn pattern(&self) -> &[(usize, usize)] {
        &self.pattern
    }

    fn residual(&mut self, t: f64, x: &[f64], xdot: &[f64], out: &mut [f64]) {
        self.load_delays(t);
        self.residual_tape.eval(t, x, xdot, &self.signals);
        for (i, o) in out.iter_mut().enumerate().take(self.residuals.len()) {
            *o = self.residual_tape.output(i);
        }
        if !self.above.is_empty() {
            self.last_xdot.copy_from_slice(xdot);
        }
    }

    fn jacobian(&mut self, t: f64, x: &[f64], xdot: &[f64], alpha: f64, out: &mut [f64]) {
        self.load_delays(t);
        self.jacobian_tape.eval(t, x, xdot, &self.signals);
        let tape = &self.jacobian_tape;
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

    fn roots(&mut self, t: f64, x: &[f64], out: &mut [f64]) {
        self.load_delays(t);
        self.roots_tape.eval(t, x, &self.last_xdot, &self.signals);
        for (i, o) in out.iter_mut().enumerate().take(self.above.len()) {
            *o = self.roots_tape.output(i);
        }
    }

    fn set_source_scale(&mut self, s: f64) {
        // The slot after the design's signals is the source scale (see `scale_sources`).
        if let Some(scale) = self.signals.get_mut(self.design_signals) {
            *scale = s;
        }
    }
}
