//! The mixed-signal simulation cycle (LRM 1076.1 12.6.4): initialisation with the quiescent
//! point, then alternating analog integration up to the next digital event and delta cycles
//! at that time, with a restart of the integrator after every discontinuity.
//!
//! Time points are where digital activity happens: scheduled transactions, process timeouts,
//! and threshold crossings of `'above` signals, which the integrator locates as roots and which
//! become events at the crossing time. After the delta cycles at a time point, a change of a
//! signal the equations read, or an executed break, is a discontinuity: new signal values go to
//! the analog system, break values replace quantities, and the integrator restarts (order 1).

use vams_design::{Design, Expr, QuantityId, SignalId, Value};
use vams_solver::{Advance, OpOptions, Transient, TransientOptions};

use super::analog_model::AnalogModel;
use super::coupling::Coupling;
use super::error::SimError;
use super::eval::{Env, eval};
use super::events::{AnalogView, EventKernel};
use super::progress::Throttle;
use super::record::Recorder;
use super::solve_error::solve_error;
use super::{Outcome, Report, SimEnd, SimOptions, SimStats};

/// Absolute tolerance of unknowns without a tolerance group (when `--abstol` is not given).
pub(crate) const DEFAULT_ABSTOL: f64 = 1e-9;

/// The analog half: the system, its integrator and reused buffers.
struct Analog<A> {
    sys: A,
    /// Unknown index of each quantity, by `QuantityId` (`None`: eliminated).
    slots: Vec<Option<usize>>,
    /// The `'above` signal of each root function.
    above: Vec<SignalId>,
    integ: Transient,
    x: Vec<f64>,
    g: Vec<f64>,
    /// Per root function: how far past its level a quantity must go before its `'above`
    /// changes (the absolute tolerance of the quantity it compares, else of unknowns without
    /// a group): see [`hysteresis`] and [`Simulation::synchronise`].
    root_band: Vec<f64>,
    /// Per root function: when its `'above` last changed, and the factor its band is widened
    /// by while it chatters (see [`Analog::flipped`]).
    last_flip: Vec<f64>,
    widen: Vec<f64>,
    /// The quiescent point (every `x'` zero), before the integrator's consistent
    /// initialisation gives the derivatives their values at `0+`: what `vams op` reports.
    quiescent: Vec<f64>,
    /// Which digital activity needs an analog solution point (the rest runs between steps).
    coupling: Coupling,
    /// Interpolation buffers for the points of digital-only activity.
    xi: Vec<f64>,
    xdi: Vec<f64>,
    /// The integrator's options (a new choice of states starts a new integrator).
    topts: TransientOptions,
    /// `--abstol`, if given (else each unknown's tolerance group).
    abstol: Option<f64>,
    /// The counters of integrators replaced by a new choice of states.
    earlier: vams_solver::Stats,
}

pub(crate) struct Simulation<'d, A> {
    design: &'d Design,
    stop: f64,
    kernel: EventKernel<'d>,
    analog: Option<Analog<A>>,
    /// Quantity values and derivatives at the current time, by `QuantityId`.
    values: Vec<f64>,
    derivatives: Vec<f64>,
    changed: Vec<SignalId>,
    breaks: Vec<(QuantityId, f64)>,
    outcome: Option<Outcome>,
    progress: Throttle,
    cancel: Option<super::Cancel>,
}

impl<'d, A: AnalogModel> Simulation<'d, A> {
    /// Initialisation: processes run to their first wait; with an analog system, the quiescent
    /// point with the breaks executed so far as its fixed values, the `'above` signals' initial
    /// values from it, and the integrator.
    pub fn start(
        design: &'d Design,
        options: &SimOptions,
        analog: Option<A>,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<Self, SimError> {
        options.validate()?;
        let mut kernel = EventKernel::new(design)?;
        kernel.io.cancel = options.cancel.clone();
        let values: Vec<f64> = design
            .quantities
            .iter()
            .map(|q| q.initial_guess.unwrap_or(0.0))
            .collect();
        let derivatives = vec![0.0; values.len()];
        let view = AnalogView {
            values: &values,
            derivatives: &derivatives,
        };
        let outcome = kernel.initialize(&view, on_report)?;
        let mut this = Simulation {
            design,
            stop: options.stop,
            kernel,
            analog: None,
            values,
            derivatives,
            changed: Vec::new(),
            breaks: Vec::new(),
            outcome,
            progress: Throttle::new(options.progress.clone()),
            cancel: options.cancel.clone(),
        };
        if let Some(sys) = analog {
            this.analog = Some(this.quiescent(sys, options)?);
            this.refresh()?;
        }
        // Signal changes from here on count as discontinuities; initial values are pushed.
        this.kernel.signals.take_changed(&mut this.changed);
        if this.analog.is_none() {
            this.kernel.signals.stop_tracking_changes();
        }
        this.enter_time_domain();
        Ok(this)
    }

    /// `std.standard.domain` was `quiescent_domain` for the quiescent point; it becomes
    /// `time_domain` with an event in the first delta cycle at time 0 (LRM 1076.1, 12.6.4), so
    /// that `wait until domain = time_domain` resumes and equations that read it switch (a
    /// discontinuity: the integrator restarts from the quiescent point in the new equations).
    fn enter_time_domain(&mut self) {
        let Some(s) = self.design.domain_signal() else {
            return;
        };
        let vams_design::Type::Enum { literals, .. } = &self.design.signals[s.index()].ty else {
            return;
        };
        if let Some(p) = literals.iter().position(|l| l == "time_domain") {
            self.kernel.signals.force(s, Value::Enum(p as u32));
        }
    }

    fn quiescent(&mut self, mut sys: A, options: &SimOptions) -> Result<Analog<A>, SimError> {
        let design = self.design;
        self.kernel.take_breaks(&mut self.breaks);
        // Where index reduction chooses its states: the initial break values.
        sys.choose_states(design, &self.breaks);
        for s in 0..design.signals.len() {
            let s = SignalId(s as u32);
            if sys.reads_signal(s) {
                sys.set_signal(s, number(self.kernel.value(s)));
            }
        }
        let slots: Vec<Option<usize>> = (0..design.quantities.len())
            .map(|q| sys.quantity_slot(QuantityId(q as u32)))
            .collect();
        let n = sys.len();
        let mut guess = vec![0.0; n];
        for (q, slot) in design.quantities.iter().zip(&slots) {
            if let Some(slot) = *slot {
                guess[slot] = q.initial_guess.unwrap_or(0.0);
            }
        }
        // A later break value for the same quantity replaces an earlier one.
        // (A position per slot keeps this linear: a ladder has one break per capacitor.)
        let mut fixed: Vec<(usize, f64)> = Vec::new();
        let mut position: Vec<Option<usize>> = vec![None; n];
        for &(q, v) in &self.breaks {
            // Break targets are never eliminated (see `analog::reduce`).
            let Some(slot) = slots[q.index()] else {
                continue;
            };
            match position[slot] {
                Some(k) => fixed[k].1 = v,
                None => {
                    position[slot] = Some(fixed.len());
                    fixed.push((slot, v));
                }
            }
        }
        let abstol = match options.abstol {
            Some(a) => vec![a; n],
            None => sys.abstol(DEFAULT_ABSTOL),
        };
        let point = sys.quiescent_point(
            0.0,
            &guess,
            &fixed,
            options.reltol,
            &abstol,
            &quiescent_options(),
        );
        let (x, _) = point.map_err(|e| solve_error(e, 0.0, &sys, &slots, design))?;
        let above = sys.above_signals().to_vec();
        let mut g = vec![0.0; sys.root_count().max(above.len())];
        // The quiescent point: every `x'` is zero.
        sys.roots(0.0, &x, &vec![0.0; x.len()], &mut g);
        // The processes ran their initialisation with every `'above` signal false (its value
        // before the quiescent point exists); one that is true at the quiescent point changes
        // with an event in the first delta cycle, so that processes sensitive to it re-run.
        for (&s, &gi) in above.iter().zip(&g) {
            let value = Value::Boolean(gi > 0.0);
            if *self.kernel.value(s) != value {
                self.kernel.signals.force(s, value);
            }
        }
        // `Q'delayed` reads accepted history only if no step is longer than its delay.
        let max_step = self
            .max_step(options)?
            .min(sys.shortest_delay().unwrap_or(f64::INFINITY));
        let root_band = above
            .iter()
            .map(|&s| {
                let own = match &design.signals[s.index()].kind {
                    vams_design::SignalKind::Above {
                        quantity: Expr::Quantity(q),
                        ..
                    } => match (options.abstol, slots[q.index()]) {
                        (None, Some(slot)) => Some(abstol[slot]),
                        // Eliminated: its own group's tolerance, as if it were solved for.
                        (None, None) => crate::analog::quantity_abstol(design, *q),
                        (Some(a), _) => Some(a),
                    },
                    _ => None,
                };
                own.unwrap_or(options.abstol.unwrap_or(DEFAULT_ABSTOL))
            })
            .collect::<Vec<f64>>();
        let topts = TransientOptions {
            reltol: vams_solver::local_reltol(options.reltol),
            abstol: abstol.iter().copied().fold(DEFAULT_ABSTOL, f64::min),
            abstol_per_unknown: abstol,
            max_step,
            max_order: options.max_order,
            // No unknown beyond a few tolerances, however large the system (see the norm).
            norm: vams_solver::ErrorNorm::Bounded,
            ..TransientOptions::default()
        };
        let integ = Transient::new(&mut sys, 0.0, &x, topts.clone());
        let mut integ = integ.map_err(|e| solve_error(e, 0.0, &sys, &slots, design))?;
        integ.add_breakpoints(sys.table_times());
        for (i, (&s, &band)) in above.iter().zip(&root_band).enumerate() {
            let now = matches!(self.kernel.value(s), Value::Boolean(true));
            integ.set_root_offset(i, hysteresis(now, band));
        }
        let m = above.len();
        let coupling = Coupling::new(design, |s| sys.reads_signal(s));
        Ok(Analog {
            coupling,
            xi: vec![0.0; n],
            xdi: vec![0.0; n],
            sys,
            slots,
            above,
            integ,
            root_band,
            last_flip: vec![f64::NEG_INFINITY; m],
            widen: vec![1.0; m],
            x: vec![0.0; n],
            g,
            quiescent: x,
            topts,
            abstol: options.abstol,
            earlier: vams_solver::Stats::default(),
        })
    }

    /// The largest step: `--max-step` and every `limit` specification (applied to all
    /// quantities, a conservative reading of a per-quantity limit).
    fn max_step(&self, options: &SimOptions) -> Result<f64, SimError> {
        let mut h = options.max_step.unwrap_or(f64::INFINITY);
        for limit in &self.design.limits {
            let step = self
                .eval_at(&limit.max_step, 0.0)
                .ok()
                .and_then(|v| v.as_f64())
                .filter(|s| *s > 0.0)
                .ok_or_else(|| SimError::BadOption {
                    message: "a limit specification's step is not a positive number".into(),
                })?;
            h = h.min(step);
        }
        Ok(h)
    }

    /// `e` (of signals, quantities and `now`, outside any process) at time `now`.
    fn eval_at(&self, e: &Expr, now: f64) -> Result<Value, super::eval::EvalError> {
        self.eval_with(e, now, &self.values, &self.derivatives)
    }

    /// [`Simulation::eval_at`] with the quantities' `values` and `derivatives` given.
    fn eval_with(
        &self,
        e: &Expr,
        now: f64,
        values: &[f64],
        derivatives: &[f64],
    ) -> Result<Value, super::eval::EvalError> {
        let env = Env {
            signals: &self.kernel.signals.states,
            vars: &[],
            quantities: values,
            derivatives,
            now,
            subprograms: &self.design.subprograms,
            depth: 0,
            io: &super::io::Io::default(),
            drivers: None,
        };
        eval(e, &env)
    }

    /// Copies the integrator's state into the per-quantity values processes read, and into
    /// the `Q'delayed` histories (every caller has just accepted a point).
    /// A quantity that is not a number (or infinite) stops the run here, before it reaches
    /// a process or the waveforms.
    fn refresh(&mut self) -> Result<(), SimError> {
        if let Some(a) = &mut self.analog {
            let (x, xd) = (a.integ.state(), a.integ.derivative());
            let t = a.integ.time();
            a.sys.record_history(t, x, xd);
            a.sys
                .quantity_values(t, x, xd, &mut self.values, &mut self.derivatives);
            if let Some(q) = self.values.iter().position(|v| !v.is_finite()) {
                return Err(not_finite(self.design, q, self.values[q], t));
            }
            self.check_branch_covers(t)?;
        }
        Ok(())
    }

    /// A simultaneous if without `else` none of whose conditions holds at the accepted
    /// point `t` gives no equations there: the run stops, naming it and the first time in
    /// the step where it held no more.
    fn check_branch_covers(&mut self, t: f64) -> Result<(), SimError> {
        let design = self.design;
        for cover in &design.branch_covers {
            if let Ok(Value::Boolean(false)) = self.eval_at(&cover.condition, t) {
                return Err(SimError::NoBranch {
                    time: self.first_uncovered(&cover.condition, t),
                    span: cover.span,
                });
            }
        }
        Ok(())
    }

    /// Where in the step that ended at `t` the cover `condition` turned false, by bisection
    /// on the integrator's dense output (to 1e-9 of the step, or rounding).
    fn first_uncovered(&mut self, condition: &Expr, t: f64) -> f64 {
        let (mut values, mut derivatives) = (self.values.clone(), self.derivatives.clone());
        let Some(start) = self.analog.as_ref().and_then(|a| a.integ.last_step_start()) else {
            return t;
        };
        let (mut covered, mut uncovered) = (start, t);
        for _ in 0..32 {
            let mid = 0.5 * (covered + uncovered);
            if mid <= covered || mid >= uncovered {
                break;
            }
            let Some(a) = self.analog.as_mut() else {
                break;
            };
            if a.integ
                .interpolate_with_derivative(mid, &mut a.xi, &mut a.xdi)
                .is_err()
            {
                break;
            }
            a.sys
                .quantity_values(mid, &a.xi, &a.xdi, &mut values, &mut derivatives);
            match self.eval_with(condition, mid, &values, &derivatives) {
                Ok(Value::Boolean(false)) => uncovered = mid,
                _ => covered = mid,
            }
        }
        uncovered
    }

    /// The analog system, for a caller done with the simulation.
    pub fn into_analog(self) -> Option<A> {
        self.analog.map(|a| a.sys)
    }

    /// The quiescent point by name: every quantity, then every explicit signal.
    pub fn operating_point(&mut self) -> Vec<(String, f64)> {
        let mut values = self.values.clone();
        if let Some(a) = &mut self.analog {
            let zeros = vec![0.0; a.quiescent.len()];
            let mut derivatives = vec![0.0; values.len()];
            a.sys
                .quantity_values(0.0, &a.quiescent, &zeros, &mut values, &mut derivatives);
        }
        let quantities = self
            .design
            .quantities
            .iter()
            .zip(values)
            .map(|(q, v)| (q.name.clone(), v));
        let signals = self
            .design
            .signals
            .iter()
            .enumerate()
            .filter(|(_, s)| s.kind == vams_design::SignalKind::Explicit)
            .map(|(i, s)| {
                let v = &self.kernel.signals.states[i].value;
                (s.name.clone(), v.as_f64().unwrap_or(f64::NAN))
            });
        quantities.chain(signals).collect()
    }

    /// Runs from time 0 to the stop time (or a stop or failure), every accepted point going
    /// to `recorder`'s sink as it comes.
    pub fn run(
        mut self,
        mut recorder: Recorder,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<SimEnd, SimError> {
        self.run_recording(&mut recorder, on_report)?;
        let stats = self.stats();
        Ok(SimEnd {
            reports: std::mem::take(&mut self.kernel.reports),
            outcome: self.outcome.unwrap_or(Outcome::Finished),
            stats,
        })
    }

    fn run_recording(
        &mut self,
        recorder: &mut Recorder,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<(), SimError> {
        let mut t = 0.0;
        recorder.record(t, &self.values, &self.kernel.signals.states)?;
        if self.analog.is_none() && !recorder.wanted() {
            // Nothing to synchronise and no rows: the time points back to back.
            t = self.run_digital(on_report)?;
            recorder.record(t, &self.values, &self.kernel.signals.states)?;
            return Ok(());
        }
        // Synchronisations at the current time point: a crossing that flips back at every
        // analog restart would otherwise loop here forever.
        let mut settling = (t, 0usize);
        while self.outcome.is_none() {
            let next = self.kernel.next_time(t);
            if next <= t {
                self.check_cancelled(t)?;
                settling = if settling.0 == t {
                    (t, settling.1 + 1)
                } else {
                    (t, 1)
                };
                if settling.1 > super::events::DELTA_LIMIT {
                    let mut names: Vec<&str> = (self.changed.iter())
                        .map(|s| self.design.signals[s.index()].name.as_str())
                        .collect();
                    names.sort_unstable();
                    names.dedup();
                    let shown: Vec<String> =
                        names.iter().take(4).map(|n| format!("`{n}`")).collect();
                    let more = names.len().saturating_sub(4);
                    return Err(SimError::SettleLimit {
                        time: t,
                        limit: super::events::DELTA_LIMIT,
                        signals: if more > 0 {
                            format!("{} and {more} more", shown.join(", "))
                        } else {
                            shown.join(", ")
                        },
                    });
                }
                if recorder.last_time() != Some(t) {
                    recorder.record(t, &self.values, &self.kernel.signals.states)?;
                }
                let events = self.kernel.events;
                let view = AnalogView {
                    values: &self.values,
                    derivatives: &self.derivatives,
                };
                self.outcome = self.kernel.run_time_point(t, &view, on_report)?;
                let restarted = self.synchronise(t)?;
                if restarted || self.kernel.events != events {
                    recorder.record(t, &self.values, &self.kernel.signals.states)?;
                }
                continue;
            }
            if t >= self.stop {
                break;
            }
            // The analog solver stops only where something needs its solution; digital-only
            // activity runs between its steps (see `digital_between`).
            t = match &self.analog {
                Some(a) => {
                    let target = self.kernel.next_coupled_time(t, &a.coupling).min(self.stop);
                    self.advance(t, target, recorder, on_report)?
                }
                None => next.min(self.stop),
            };
            self.progress.tick(t);
            self.check_cancelled(t)?;
        }
        // Digital-only runs end with the last event: close the record at the end time.
        if recorder.last_time().is_some_and(|last| last < t) {
            recorder.record(t, &self.values, &self.kernel.signals.states)?;
        }
        Ok(())
    }

    /// The loop of [`Simulation::run_recording`] for a design without an analog side whose
    /// rows nobody wants: every time point up to the stop time, nothing recorded; returns
    /// the time reached.
    fn run_digital(&mut self, on_report: &mut dyn FnMut(&Report)) -> Result<f64, SimError> {
        if self.outcome.is_some() {
            return Ok(0.0);
        }
        let view = AnalogView {
            values: &self.values,
            derivatives: &self.derivatives,
        };
        let (progress, cancel) = (&mut self.progress, &self.cancel);
        let between = |t: f64| {
            progress.tick(t);
            match cancel {
                Some(c) if c.is_cancelled() => Err(SimError::Interrupted { time: t }),
                _ => Ok(()),
            }
        };
        let (t, outcome) = self
            .kernel
            .run_digital(self.stop, &view, on_report, between)?;
        self.outcome = outcome;
        Ok(t)
    }

    /// Integrates from `t` towards `target`, recording every accepted step; stops early at a
    /// threshold crossing (forcing the `'above` signals that crossed). Returns the time reached.
    fn advance(
        &mut self,
        t: f64,
        target: f64,
        recorder: &mut Recorder,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<f64, SimError> {
        if target < self.stop {
            if let Some(a) = self.analog.as_mut() {
                a.integ.add_breakpoint(target);
            }
        }
        loop {
            let advance = self.step(t, target)?;
            let reached = match advance {
                Advance::StepAccepted(t1) | Advance::Reached(t1) => t1,
                Advance::Root { t: tr, .. } => tr,
            };
            self.digital_between(reached, recorder, on_report)?;
            if self.outcome.is_some() {
                return Ok(reached);
            }
            match advance {
                Advance::StepAccepted(t1) => {
                    self.refresh()?;
                    let crossed = self.sync_above(t1);
                    recorder.record(t1, &self.values, &self.kernel.signals.states)?;
                    self.progress.tick(t1);
                    self.check_cancelled(t1)?;
                    if crossed || self.choose_states_again(t1)? {
                        return Ok(t1);
                    }
                }
                Advance::Reached(t1) => {
                    self.refresh()?;
                    self.sync_above(t1);
                    recorder.record(t1, &self.values, &self.kernel.signals.states)?;
                    return Ok(t1);
                }
                Advance::Root {
                    t: tr,
                    index,
                    rising,
                } => {
                    self.force_above(tr, index, rising);
                    // Further crossings at the same instant come one call each.
                    while let Advance::Root { index, rising, .. } = self.step(tr, tr)? {
                        self.force_above(tr, index, rising);
                    }
                    self.refresh()?;
                    recorder.record(tr, &self.values, &self.kernel.signals.states)?;
                    return Ok(tr);
                }
            }
        }
    }

    /// Runs the digital-only time points due before `until` (the time the integrator just
    /// reached), each recorded with the quantities interpolated inside the step: their
    /// processes read no quantity and their events change nothing the equations read, so
    /// the analog solution needs no point of its own there (nor an interpolation, when no
    /// row is wanted).
    fn digital_between(
        &mut self,
        until: f64,
        recorder: &mut Recorder,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<(), SimError> {
        let mut values = Vec::new();
        let mut derivatives = Vec::new();
        let interpolate = recorder.wanted();
        loop {
            let td = self.kernel.next_time(until);
            if td >= until || self.outcome.is_some() {
                return Ok(());
            }
            if interpolate && values.is_empty() {
                values = self.values.clone();
                derivatives = self.derivatives.clone();
            }
            if interpolate
                && let Some(a) = self.analog.as_mut()
                && a.integ
                    .interpolate_with_derivative(td, &mut a.xi, &mut a.xdi)
                    .is_ok()
            {
                a.sys
                    .quantity_values(td, &a.xi, &a.xdi, &mut values, &mut derivatives);
            }
            if recorder.last_time() != Some(td) {
                recorder.record(td, &values, &self.kernel.signals.states)?;
            }
            let events = self.kernel.events;
            // Without interpolation, the values at the step's start: read by no process here.
            let view = match interpolate {
                true => AnalogView {
                    values: &values,
                    derivatives: &derivatives,
                },
                false => AnalogView {
                    values: &self.values,
                    derivatives: &self.derivatives,
                },
            };
            self.outcome = self.kernel.run_time_point(td, &view, on_report)?;
            if self.kernel.events != events {
                recorder.record(td, &values, &self.kernel.signals.states)?;
            }
            self.progress.tick(td);
            self.check_cancelled(td)?;
        }
    }

    /// Stops the run when the caller cancelled it (the points recorded so far stay).
    fn check_cancelled(&self, t: f64) -> Result<(), SimError> {
        match &self.cancel {
            Some(c) if c.is_cancelled() => Err(SimError::Interrupted { time: t }),
            _ => Ok(()),
        }
    }

    /// One call of the integrator.
    fn step(&mut self, t: f64, target: f64) -> Result<Advance, SimError> {
        let design = self.design;
        let Some(a) = self.analog.as_mut() else {
            return Ok(Advance::Reached(target));
        };
        a.integ
            .advance(&mut a.sys, target)
            .map_err(|e| solve_error(e, t, &a.sys, &a.slots, design))
    }

    /// Schedules the new value of the `'above` signal of root function `index`.
    fn force_above(&mut self, t: f64, index: usize, rising: bool) {
        let Some(a) = self.analog.as_mut() else {
            return;
        };
        if let Some(&s) = a.above.get(index)
            && *self.kernel.value(s) != Value::Boolean(rising)
        {
            self.kernel.signals.force(s, Value::Boolean(rising));
            a.flipped(t, index, rising);
        }
    }

    /// Forces every `'above` signal whose value disagrees with its root function at the
    /// current state, by more than the function's band ([`Analog::root_band`]): crossings the
    /// integrator cannot see, because the function started a step within its band or a break
    /// moved the quantity across its threshold. True if any.
    fn sync_above(&mut self, t: f64) -> bool {
        let Some(a) = self.analog.as_mut() else {
            return false;
        };
        if a.g.is_empty() {
            return false;
        }
        a.sys
            .roots(t, a.integ.state(), a.integ.derivative(), &mut a.g);
        let mut any = false;
        for i in 0..a.above.len() {
            let s = a.above[i];
            let now = matches!(self.kernel.value(s), Value::Boolean(true));
            // The integrator holds the signal's hysteresis (set where it last changed).
            let beyond = a.g[i] + a.integ.root_offset(i);
            if (beyond > 0.0 && !now) || (beyond < 0.0 && now) {
                self.kernel.signals.force(s, Value::Boolean(!now));
                a.flipped(t, i, !now);
                any = true;
            }
        }
        any
    }

    /// After the delta cycles at `t`: pushes changed signals the equations read, applies break
    /// values and restarts the integrator if either happened. True on a restart.
    fn synchronise(&mut self, t: f64) -> Result<bool, SimError> {
        if self.analog.is_none() {
            // Nothing to push the changes and breaks to (the changes are not recorded).
            self.kernel.discard_breaks();
            return Ok(false);
        }
        self.kernel.signals.take_changed(&mut self.changed);
        let broke = self.kernel.take_breaks(&mut self.breaks);
        let design = self.design;
        let Some(a) = self.analog.as_mut() else {
            return Ok(false);
        };
        let mut discontinuity = broke;
        for &s in &self.changed {
            if a.sys.reads_signal(s) {
                a.sys.set_signal(s, number(self.kernel.value(s)));
                discontinuity = true;
            }
        }
        if !discontinuity {
            return Ok(false);
        }
        a.x.copy_from_slice(a.integ.state());
        for &(q, v) in &self.breaks {
            // Break targets are never eliminated (see `analog::reduce`).
            if let Some(slot) = a.slots[q.index()] {
                a.x[slot] = v;
            }
        }
        a.integ
            .restart(&mut a.sys, t, &a.x)
            .map_err(|e| solve_error(e, t, &a.sys, &a.slots, design))?;
        self.refresh()?;
        // A restart that lands within tolerance of a threshold does not cross it: a limiter
        // in a feedback loop sits on its threshold (sliding), and each set of equations puts
        // the solution a rounding error on the other side (4.8 + 2e-11 with `vout == vin`,
        // 4.8 - 1e-11 limited), which would flip the `'above` and restart forever.
        self.sync_above(t);
        Ok(true)
    }

    /// A model whose index was reduced may need other states as it moves (a pendulum's rod
    /// passing the horizontal, see `AnalogSystem::choose_states_again`): the system is
    /// rebuilt and a new integrator starts at `t` from the state reached, at order 1 as
    /// after a break. True when it did.
    fn choose_states_again(&mut self, t: f64) -> Result<bool, SimError> {
        let design = self.design;
        let Some(a) = self.analog.as_mut() else {
            return Ok(false);
        };
        let Some(x) = a
            .sys
            .choose_states_again(design, t, a.integ.state(), a.integ.derivative())
        else {
            return Ok(false);
        };
        let n = x.len();
        a.slots = (0..design.quantities.len())
            .map(|q| a.sys.quantity_slot(QuantityId(q as u32)))
            .collect();
        let mut topts = a.topts.clone();
        topts.abstol_per_unknown = match a.abstol {
            Some(tol) => vec![tol; n],
            None => a.sys.abstol(DEFAULT_ABSTOL),
        };
        topts.abstol = (topts.abstol_per_unknown.iter().copied()).fold(DEFAULT_ABSTOL, f64::min);
        let mut integ = Transient::new(&mut a.sys, t, &x, topts)
            .map_err(|e| solve_error(e, t, &a.sys, &a.slots, design))?;
        integ.add_breakpoints(a.sys.table_times());
        for i in 0..a.above.len() {
            integ.set_root_offset(i, a.integ.root_offset(i));
        }
        let old = std::mem::replace(&mut a.integ, integ);
        a.earlier = add_stats(a.earlier, old.stats());
        a.x = vec![0.0; n];
        a.xi = vec![0.0; n];
        a.xdi = vec![0.0; n];
        self.refresh()?;
        Ok(true)
    }

    fn stats(&self) -> SimStats {
        let solver = self
            .analog
            .as_ref()
            .map(|a| add_stats(a.earlier, a.integ.stats()))
            .unwrap_or_default();
        SimStats {
            accepted_steps: solver.accepted_steps,
            rejected_steps: solver.rejected_steps + solver.newton_failures,
            newton_failures: solver.newton_failures,
            newton_iterations: solver.newton_iterations,
            factorizations: solver.factorizations,
            pivot_searches: solver.pivot_searches,
            residual_evaluations: solver.residual_evals,
            events: self.kernel.events,
            delta_cycles: self.kernel.delta_cycles,
            breaks: self.kernel.breaks_total,
        }
    }
}

impl<A> Analog<A> {
    /// Root function `i`'s `'above` changed to `above` at `t`: its hysteresis follows. A
    /// change back within a hair of time of the last one is chattering (a diode at its knee
    /// with an inductor's current through it: each state's solution lands a solver tolerance
    /// on the other side, and the signal would flip at every step of a few femtoseconds):
    /// the band widens tenfold each time, up to 10^4 times the quantity's tolerance, until a
    /// change comes after a real interval again.
    fn flipped(&mut self, t: f64, i: usize, above: bool) {
        const MAX_WIDEN: f64 = 1e4;
        let chattering = t - self.last_flip[i] <= 1e-12 * t.abs().max(1e-6);
        self.widen[i] = match chattering {
            true => (self.widen[i] * 10.0).min(MAX_WIDEN),
            false => 1.0,
        };
        self.last_flip[i] = t;
        let band = self.root_band[i] * self.widen[i];
        self.integ.set_root_offset(i, hysteresis(above, band));
    }
}

/// The offset of an `'above` root function in state `above` (true: the quantity is above
/// its level) with band `band`: the integrator locates the next crossing where the quantity
/// is `band` past the level on the other side, so that a quantity sitting on its threshold
/// (a limiter in a feedback loop, a diode at its knee held by an inductor: each state's
/// equations put it a hair on the other side) does not flip the signal at every step, and a
/// crossing is located to within the quantity's own tolerance.
/// The sum of two integrators' counters.
fn add_stats(a: vams_solver::Stats, b: vams_solver::Stats) -> vams_solver::Stats {
    vams_solver::Stats {
        accepted_steps: a.accepted_steps + b.accepted_steps,
        rejected_steps: a.rejected_steps + b.rejected_steps,
        newton_failures: a.newton_failures + b.newton_failures,
        newton_iterations: a.newton_iterations + b.newton_iterations,
        factorizations: a.factorizations + b.factorizations,
        pivot_searches: a.pivot_searches + b.pivot_searches,
        residual_evals: a.residual_evals + b.residual_evals,
        root_evals: a.root_evals + b.root_evals,
    }
}

fn hysteresis(above: bool, band: f64) -> f64 {
    if above { band } else { -band }
}

/// A signal's value as the equations see it (booleans and enumerations as positions).
/// The error for quantity `q` at `value` (NaN or infinite) at time `t`, with the equations
/// that name it.
fn not_finite(design: &Design, q: usize, value: f64, t: f64) -> SimError {
    let quantity = &design.quantities[q];
    let id = QuantityId(q as u32);
    let mut equations: Vec<String> = Vec::new();
    for e in &design.equations {
        let mut names = false;
        e.residual
            .visit(&mut |x| names |= matches!(x, Expr::Quantity(v) | Expr::Dot(v) if *v == id));
        if names && equations.len() < 3 {
            equations.push(format!("`{}`", e.text));
        }
    }
    let mut help = "an equation computes it outside its domain: the square root or logarithm \
                    of a negative number, a division by zero, an exponential that overflows"
        .to_string();
    if !equations.is_empty() {
        help.push_str("; the equations that name it: ");
        help.push_str(&equations.join(", "));
    }
    SimError::NotFinite {
        quantity: quantity.name.clone(),
        value: if value.is_nan() {
            "not a number".into()
        } else {
            format!("{value}")
        },
        time: t,
        span: quantity.span,
        help,
    }
}

fn number(v: &Value) -> f64 {
    v.as_f64().unwrap_or(f64::NAN)
}

/// The quiescent point is a result of its own (`vams op`, and the state the run starts from):
/// Newton stops at a hundredth of the usual update bound, which costs about one more
/// quadratically convergent iteration, or where rounding stalls it within the usual bound.
fn quiescent_options() -> OpOptions {
    let defaults = OpOptions::default();
    OpOptions {
        newton: vams_solver::NewtonOptions {
            tol: 0.01,
            stall_tol: Some(defaults.newton.tol),
            ..defaults.newton
        },
        ..defaults
    }
}
