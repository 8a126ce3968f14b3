//! The event-driven half of the simulation cycle: signal update, process resumption and
//! execution, delta cycles at one time point, and the next time anything digital is due.

use vams_design::{Design, Instr, Process, QuantityId, SignalId, Value};

use super::error::SimError;
use super::eval::Env;
use super::io::{Files, Heap, Io};
use super::lower::{self, Op, Ran, lower};
use super::process::{self, Context, ProcState, Suspend};
use super::signals::Signals;
use super::timeouts::{Due, Timeouts};
use super::{Outcome, Report};
use std::cell::RefCell;

/// Delta cycles allowed at one time point before the run counts as an endless zero-delay loop.
pub(crate) const DELTA_LIMIT: usize = 10_000;

/// The analog solution processes read: quantity values and derivatives by `QuantityId`.
pub(crate) struct AnalogView<'a> {
    pub values: &'a [f64],
    pub derivatives: &'a [f64],
}

pub(crate) struct EventKernel<'d> {
    design: &'d Design,
    pub signals: Signals,
    procs: Vec<ProcState>,
    /// Every process's code lowered ([`super::lower`]), one process after the other in
    /// process order: a cycle runs its processes in that order, so their instructions are
    /// read as one forward stream (a vector per process scattered them over the heap, among
    /// lowering's temporaries).
    lowered: Vec<Op<'d>>,
    /// Where each process's lowered code starts in `lowered`, and after the last process
    /// where it ends.
    lowered_at: Vec<usize>,
    /// Per process, its [`lower::idle_branch`]: resumed while that branch's condition is
    /// false, the process is left waiting, and while it holds it goes on after it.
    idle: Vec<Option<lower::IdleBranch>>,
    /// Break values executed since the last [`EventKernel::take_breaks`].
    breaks: Vec<(QuantityId, f64)>,
    break_count: usize,
    pub reports: Vec<Report>,
    waveform: Vec<(Option<Value>, f64)>,
    resume: Vec<usize>,
    /// The timeouts of the waiting processes, earliest first; an entry whose process no
    /// longer waits with that timeout (it resumed on an event) is stale, and dropped when it
    /// comes to the top.
    timeouts: Timeouts,
    /// Per process, the timeout it waits with (infinity when none): what makes an entry of
    /// `timeouts` current, kept beside the processes' states for a cheap look.
    timeout_of: Vec<f64>,
    /// Per signal, the processes with a wait of their own code sensitive to it.
    waiters: Vec<Vec<usize>>,
    /// Per process, whether a wait of its own code has a condition (`wait until`).
    has_until: Vec<bool>,
    /// Per process, whether it has one wait, without a condition, and calls no procedure
    /// (a process with a sensitivity list): waiting, it waits there, so a signal whose
    /// waiters list it is on, with an event, resumes it without a look at its sensitivity.
    one_plain_wait: Vec<bool>,
    /// The processes that call procedures, whose waits (on their signal parameters) are known
    /// only when they suspend: looked at in every cycle.
    dynamic: Vec<usize>,
    /// The earliest time anything is due, as the last time point found it when it ended
    /// (`None`: not known). Only a time point's cycles change transactions and timeouts, so
    /// the loop's look at the next time between two time points need not scan again.
    next_due: Option<f64>,
    last_process: usize,
    /// Time of the last simulation cycle (initialisation counts as one at 0).
    last_cycle: f64,
    /// Signal events and delta cycles so far.
    pub events: usize,
    pub delta_cycles: usize,
    /// Break statements executed so far.
    pub breaks_total: usize,
    /// The heap and the files of the run.
    pub io: Io,
}

impl<'d> EventKernel<'d> {
    pub fn new(design: &'d Design) -> Result<EventKernel<'d>, SimError> {
        let heap = RefCell::new(Heap::default());
        // The shared variables' objects first, so that the k-th is `Access(k + 1)`.
        for object in &design.shared_objects {
            heap.borrow_mut()
                .alloc(object.clone())
                .map_err(|e| SimError::BadOption { message: e.message })?;
        }
        let signals = Signals::new(design)?;
        let calls = |p: &Process| p.code.iter().any(|c| matches!(c, Instr::Call { .. }));
        let mut lowered = Vec::new();
        let mut lowered_at = Vec::with_capacity(design.processes.len() + 1);
        let has_until: Vec<bool> = (design.processes.iter())
            .map(|p| (p.code.iter()).any(|c| matches!(c, Instr::Wait { until: Some(_), .. })))
            .collect();
        let one_plain_wait: Vec<bool> = (design.processes.iter().enumerate())
            .map(|(i, p)| {
                let waits = p.code.iter().filter(|c| matches!(c, Instr::Wait { .. }));
                waits.count() == 1 && !has_until[i] && !calls(p)
            })
            .collect();
        let mut idle = Vec::with_capacity(design.processes.len());
        // Idle branches with equal conditions of signals alone share a class.
        let mut classes = rustc_hash::FxHashMap::default();
        for (i, p) in design.processes.iter().enumerate() {
            lowered_at.push(lowered.len());
            let ops = lower(design, &signals, i, p);
            let mut branch = lower::idle_branch(&ops, p).filter(|_| one_plain_wait[i]);
            if let Some(at) = &mut branch
                && let Some(key) = lower::idle_key(&ops, *at)
            {
                let next = u32::try_from(classes.len()).unwrap_or(lower::NO_CLASS);
                at.class = *classes.entry(key).or_insert(next);
            }
            idle.push(branch);
            lowered.extend(ops);
        }
        lowered_at.push(lowered.len());
        let procs: Vec<ProcState> = design.processes.iter().map(ProcState::new).collect();
        let mut waiters = vec![Vec::new(); design.signals.len()];
        for (i, p) in procs.iter().enumerate() {
            let mut on: Vec<SignalId> = p.own_sensitivity().collect();
            on.sort_unstable();
            on.dedup();
            for s in on {
                waiters[s.index()].push(i);
            }
        }
        let dynamic = (design.processes.iter().enumerate())
            .filter(|(_, p)| calls(p))
            .map(|(i, _)| i)
            .collect();
        Ok(EventKernel {
            design,
            has_until,
            one_plain_wait,
            signals,
            procs,
            lowered,
            lowered_at,
            idle,
            timeouts: Timeouts::default(),
            timeout_of: vec![f64::INFINITY; design.processes.len()],
            waiters,
            dynamic,
            breaks: Vec::new(),
            break_count: 0,
            reports: Vec::new(),
            waveform: Vec::new(),
            resume: Vec::with_capacity(design.processes.len()),
            next_due: None,
            last_process: 0,
            last_cycle: 0.0,
            events: 0,
            delta_cycles: 0,
            breaks_total: 0,
            io: Io {
                function_reports: std::cell::RefCell::default(),
                cancel: None,
                heap,
                files: std::cell::RefCell::new(Files::new(&design.files).map_err(|(k, e)| {
                    SimError::FileOpen {
                        message: e.message,
                        span: design.files[k].span,
                        help: e.help.to_string(),
                    }
                })?),
            },
        })
    }

    /// The initialisation phase: every process runs until its first wait, at time 0.
    pub fn initialize(
        &mut self,
        analog: &AnalogView,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<Option<Outcome>, SimError> {
        self.resume.clear();
        self.resume.extend(0..self.procs.len());
        self.next_due = None;
        self.run_resumed(0.0, analog, on_report)
    }

    /// The earliest time at which a transaction or a timeout is due (infinity if none).
    #[inline]
    pub fn next_time(&mut self, now: f64) -> f64 {
        if self.signals.has_forced() {
            return now;
        }
        match self.next_due {
            Some(t) => t,
            None => self.scan_next_time(),
        }
    }

    /// [`EventKernel::next_time`] from the pending transactions and the timeouts.
    #[inline]
    fn scan_next_time(&mut self) -> f64 {
        self.signals.next_time().min(self.next_timeout())
    }

    /// The earliest timeout of a waiting process (infinity if none), the stale entries
    /// before it dropped.
    #[inline]
    fn next_timeout(&mut self) -> f64 {
        while let Some(Due(t, i)) = self.timeouts.peek() {
            if self.waits_until(i, t) {
                return t;
            }
            self.timeouts.pop();
        }
        f64::INFINITY
    }

    /// Whether process `i` waits with timeout `t`.
    #[inline]
    fn waits_until(&self, i: usize, t: f64) -> bool {
        self.timeout_of[i] == t
    }

    /// The earliest time at which something due needs the analog solution (see
    /// [`super::coupling`]): a transaction on a signal that wakes the analog side, or a
    /// coupled process's timeout.
    pub fn next_coupled_time(&self, now: f64, coupling: &super::coupling::Coupling) -> f64 {
        if self.signals.has_forced() {
            return now;
        }
        self.procs
            .iter()
            .enumerate()
            .filter(|(i, p)| !p.halted && coupling.is_coupled(*i))
            .filter_map(|(_, p)| p.timeout_at)
            .fold(
                self.signals.next_time_where(|s| coupling.wakes(s)),
                f64::min,
            )
    }

    /// Runs simulation cycles at `now` until nothing more is due at `now`.
    pub fn run_time_point(
        &mut self,
        now: f64,
        analog: &AnalogView,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<Option<Outcome>, SimError> {
        self.time_point(now, analog, on_report)
    }

    /// Every time point from 0 up to `stop` back to back, for a run without an analog side
    /// whose rows nobody wants (`Simulation::run_digital`); `between(t)` runs before each
    /// new time `t` (the progress bar, the cancel check). Returns the time reached and the
    /// outcome, if the run ended before `stop`. The time points run in this function's loop
    /// (with [`EventKernel::time_point`] inlined), not through a call each: its prologue,
    /// epilogue and result were about 40 instructions per time point of the counter.
    pub fn run_digital(
        &mut self,
        stop: f64,
        analog: &AnalogView,
        on_report: &mut dyn FnMut(&Report),
        mut between: impl FnMut(f64) -> Result<(), SimError>,
    ) -> Result<(f64, Option<Outcome>), SimError> {
        let mut t = 0.0;
        loop {
            let next = self.next_time(t);
            if next <= t {
                let outcome = self.time_point(t, analog, on_report)?;
                self.discard_breaks();
                if outcome.is_some() {
                    return Ok((t, outcome));
                }
                continue;
            }
            if t >= stop {
                return Ok((t, None));
            }
            t = next.min(stop);
            between(t)?;
        }
    }

    /// [`EventKernel::run_time_point`].
    #[inline(always)]
    fn time_point(
        &mut self,
        now: f64,
        analog: &AnalogView,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<Option<Outcome>, SimError> {
        for _ in 0..=DELTA_LIMIT {
            // A cycle that does not advance time is a delta cycle (LRM 14.7.5.1).
            if now == self.last_cycle {
                self.delta_cycles += 1;
            }
            self.last_cycle = now;
            self.next_due = None;
            if let Some(outcome) = self.cycle(now, analog, on_report)? {
                return Ok(Some(outcome));
            }
            if self.signals.has_forced() {
                continue;
            }
            let next = self.scan_next_time();
            if next > now {
                self.next_due = Some(next);
                return Ok(None);
            }
        }
        let p = &self.design.processes[self.last_process];
        Err(SimError::DeltaLimit {
            time: now,
            limit: DELTA_LIMIT,
            process: p.name.clone(),
            span: p.span,
        })
    }

    /// One simulation cycle: update signals, then run the processes that resume. Inlined
    /// into [`EventKernel::time_point`], as the compiler did before that was inlined into
    /// [`EventKernel::run_digital`] (then it made this a call of its own, twice per time point).
    #[inline(always)]
    fn cycle(
        &mut self,
        now: f64,
        analog: &AnalogView,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<Option<Outcome>, SimError> {
        self.signals.update(now, self.design)?;
        self.events += self.signals.events.len();
        // The processes that may resume: those whose timeout is due, those waiting on a
        // signal with an event, those whose waits are known only at run time; in process
        // order, as the LRM's "each process" reads in every simulator.
        self.resume.clear();
        while let Some(Due(t, i)) = self.timeouts.peek()
            && t <= now
        {
            self.timeouts.pop();
            if self.waits_until(i, t) {
                self.resume.push(i);
            }
        }
        // A waiters list alone is in order without repeats (as built in `new`).
        let mut in_order = self.resume.is_empty();
        for s in &self.signals.events {
            let waiters = &self.waiters[s.index()];
            if !waiters.is_empty() {
                in_order = self.resume.is_empty();
                self.resume.extend_from_slice(waiters);
            }
        }
        if !self.dynamic.is_empty() {
            in_order = false;
            self.resume.extend_from_slice(&self.dynamic);
        }
        if self.resume.len() > 1 && !in_order {
            self.resume.sort_unstable();
            self.resume.dedup();
        }
        let mut k = 0;
        for j in 0..self.resume.len() {
            let i = self.resume[j];
            let p = &self.procs[i];
            if p.halted || p.waiting_at.is_none() {
                continue;
            }
            // Due, or on the waiters list of a signal with an event (the only other way
            // such a process comes here).
            if self.one_plain_wait[i] || p.timeout_at.is_some_and(|t| t <= now) {
                self.resume[k] = i;
                k += 1;
                continue;
            }
            let states = &self.signals.states;
            if !p.sensitivity().iter().any(|s| states[s.index()].event) {
                continue;
            }
            let subs = &self.design.subprograms;
            // Not looked up for a process none of whose own waits has a condition (the
            // process's code is far in memory from its state).
            let until = match p.running {
                None if !self.has_until[i] => None,
                _ => p.until(&self.design.processes[i], subs),
            };
            if let Some(cond) = until {
                let env = Env {
                    signals: states,
                    vars: &p.vars,
                    quantities: analog.values,
                    derivatives: analog.derivatives,
                    now,
                    subprograms: subs,
                    depth: 0,
                    io: &self.io,
                    drivers: Some((&self.signals, i)),
                };
                let process = &self.design.processes[i];
                let holds = super::fast::condition(cond, &env).map_err(|e| SimError::Runtime {
                    process: process.name.clone(),
                    time: now,
                    message: e.message,
                    span: process.span,
                    help: e.help.to_string(),
                })?;
                if !holds {
                    continue;
                }
            }
            self.resume[k] = i;
            k += 1;
        }
        self.resume.truncate(k);
        if self.resume.is_empty() {
            return Ok(None);
        }
        self.run_resumed(now, analog, on_report)
    }

    fn run_resumed(
        &mut self,
        now: f64,
        analog: &AnalogView,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<Option<Outcome>, SimError> {
        let before = self.break_count;
        let mut outcome = None;
        // The class of the last idle-branch condition of signals alone evaluated in this
        // cycle, and its value (see `lower::CondKey`): signals do not change while processes
        // run.
        let mut known = (lower::NO_CLASS, None);
        for k in 0..self.resume.len() {
            let i = self.resume[k];
            self.last_process = i;
            let code = &self.lowered[self.lowered_at[i]..self.lowered_at[i + 1]];
            let state = &mut self.procs[i];
            // Waiting at its one wait (not at the start of the run), resumed at its first
            // branch: with the condition false it would go back to that wait as it is
            // (nothing to report from a function either, or that would be emitted in its
            // name); with the condition true it goes on after the branch. A condition of
            // signals alone that an earlier process of this cycle evaluated is not evaluated
            // again (nor its instruction read).
            let mut resumed = lower::Resume::Run;
            if let Some(at) = self.idle[i]
                && state.waiting_at.is_some()
                && self.io.function_reports.borrow().is_empty()
            {
                resumed = at.resume(code, &self.signals.states, &state.vars, &mut known);
            }
            self.timeout_of[i] = f64::INFINITY;
            // The lowered instructions first, without the interpreter's context.
            let ran = match resumed {
                lower::Resume::Idle => continue,
                lower::Resume::At { pc, steps } => {
                    state.pc = pc;
                    lower::run_from(code, state, &mut self.signals, now, steps)
                }
                lower::Resume::Run => lower::run(code, state, &mut self.signals, now),
            };
            let suspend = match ran {
                Ran::Suspended(s) if self.io.function_reports.borrow().is_empty() => s,
                ran => self.run_general(i, ran, now, analog, on_report)?,
            };
            match suspend {
                Suspend::Wait => {
                    if let Some(t) = self.procs[i].timeout_at {
                        self.timeout_of[i] = t;
                        self.timeouts.push(Due(t, i));
                    }
                }
                Suspend::Halt => {}
                Suspend::Stop => {
                    outcome = Some(Outcome::Stopped { time: now });
                    break;
                }
                Suspend::Failure => {
                    outcome = Some(Outcome::Failed { time: now });
                    break;
                }
            }
        }
        self.breaks_total += self.break_count - before;
        Ok(outcome)
    }

    /// Process `i` after [`lower::run`]: the interpreter from where that declined, and the
    /// reports of the functions called since the last process ran. Out of
    /// [`EventKernel::run_resumed`]'s loop, whose frame stays small.
    #[inline(never)]
    fn run_general(
        &mut self,
        i: usize,
        ran: Ran,
        now: f64,
        analog: &AnalogView,
        on_report: &mut dyn FnMut(&Report),
    ) -> Result<Suspend, SimError> {
        let process = &self.design.processes[i];
        let mut cx = Context {
            signals: &mut self.signals,
            quantities: analog.values,
            derivatives: analog.derivatives,
            now,
            breaks: &mut self.breaks,
            break_count: &mut self.break_count,
            reports: &mut self.reports,
            on_report,
            waveform: &mut self.waveform,
            subprograms: &self.design.subprograms,
            design_signals: &self.design.signals,
            io: &self.io,
        };
        let suspend = match ran {
            Ran::Suspended(s) => Ok(s),
            Ran::Declined { steps } => {
                let state = &mut self.procs[i];
                let code = &self.lowered[self.lowered_at[i]..self.lowered_at[i + 1]];
                process::run(i, process, code, state, &mut cx, steps)
            }
        };
        // What the instruction the process suspended at (`wait until f(x)`) reported, and
        // what the conditions of the waits reported.
        process::emit_function_reports(&mut cx, &process.name);
        suspend
    }

    /// True when a break statement ran since the last call; `out` receives the reinitialisation
    /// values in execution order (a later value for the same quantity wins).
    pub fn take_breaks(&mut self, out: &mut Vec<(QuantityId, f64)>) -> bool {
        out.clear();
        out.append(&mut self.breaks);
        std::mem::replace(&mut self.break_count, 0) > 0
    }

    /// Forgets the breaks executed since the last call (a run without an analog side).
    #[inline]
    pub fn discard_breaks(&mut self) {
        if self.break_count > 0 || !self.breaks.is_empty() {
            self.breaks.clear();
            self.break_count = 0;
        }
    }

    /// Current value of signal `s`.
    pub fn value(&self, s: SignalId) -> &Value {
        &self.signals.states[s.index()].value
    }
}
