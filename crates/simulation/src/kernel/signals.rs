//! Signals and their drivers: projected output waveforms, the update phase, resolution.
//!
//! Each process that assigns a signal has one driver for it (LRM 14.7.2). A driver holds its
//! current driving value and its projected waveform: transactions in increasing time order.
//! An assignment edits the waveform by the LRM's rules for transport and inertial delay
//! (10.5.2.2); the update phase makes every transaction that has come due the driver's current
//! value and recomputes the signal's effective value (resolved with the std_logic table when
//! several drivers act on a `std_ulogic` signal). `'above` signals have no driver: the analog
//! side forces their values at threshold crossings.

use std::collections::VecDeque;

use vams_design::GuardedKind;
use vams_design::{Design, Expr, Resolution, SignalId, SignalKind, Type, Value};

use super::error::SimError;
use super::lower::Kind;

/// A signal's visible state.
#[derive(Clone, Debug)]
pub(crate) struct SignalState {
    pub value: Value,
    pub last_value: Value,
    /// Time of the last event; `None` before the first.
    pub last_event: Option<f64>,
    /// Time the signal was last active; `None` before the first transaction.
    pub last_active: Option<f64>,
    /// An event (value change) in the current simulation cycle.
    pub event: bool,
    /// A transaction (with or without a change) in the current simulation cycle.
    pub active: bool,
}

#[derive(Clone, Debug)]
struct Transaction {
    time: f64,
    /// `None`: a null transaction, which disconnects the driver (LRM 12.6.2).
    value: Option<Value>,
}

impl Transaction {
    /// A slot to fill in place ([`Signals::assign_scalar`]).
    const EMPTY: Transaction = Transaction {
        time: 0.0,
        value: None,
    };
}

/// How an assignment edits the projected waveform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Delay {
    Transport,
    /// Inertial; the pulse-rejection interval starts at this time (the first new transaction's
    /// time minus the rejection limit, on the femtosecond grid as the caller computes times:
    /// in floating point, `t + 4.6 ns - 4.6 ns` may miss a transaction at `t`).
    Inertial(f64),
}

#[derive(Clone, Debug)]
struct Driver {
    signal: SignalId,
    /// The element it drives, for a signal some process assigns element by element (every
    /// driver of such a signal drives one element: LRM 12.6.1's driver per scalar
    /// subelement); `None` for a whole signal.
    element: Option<usize>,
    current: Value,
    /// False after a null transaction, until the next value: a disconnected driver of a
    /// guarded signal takes no part in its resolution.
    connected: bool,
    waveform: VecDeque<Transaction>,
    /// In [`Signals::pending`].
    pending: bool,
}

/// A signal driven element by element with at most one driver per element, updated in
/// place: only the elements whose drivers had a transaction are compared, and `last_value`
/// is brought up to date through the elements that changed at the last event instead of a
/// copy of the whole array (a 1001-element register shifting at each edge copied and
/// compared all of it in every cycle).
#[derive(Clone, Debug)]
struct ElementDriven {
    /// The element drivers with a transaction in the current update phase.
    due: Vec<u32>,
    /// The elements that changed at the signal's last event: the only ones where
    /// `last_value` differs from the value.
    changed: Vec<u32>,
}

/// An implicit `S'stable(T)` or `S'quiet(T)` signal.
#[derive(Clone, Copy, Debug)]
struct Stable {
    signal: SignalId,
    source: SignalId,
    delay: f64,
    quiet: bool,
    driver: usize,
}

/// An element of a gathered port: a root signal and the position in it (`None`: all of it).
type GatherElement = (SignalId, Option<usize>);

/// What a driver of a process drives: a signal, and its element for a signal driven element
/// by element.
type DriverKey = (SignalId, Option<usize>);

/// Every signal's state and every driver.
mod converted;
mod drivers;

pub(crate) struct Signals {
    pub states: Vec<SignalState>,
    drivers: Vec<Driver>,
    /// Driver indices of each signal.
    by_signal: Vec<Vec<usize>>,
    /// Per process, its drivers by `(signal, element)`, sorted: a process drives few
    /// signals, and a binary search of them costs less than hashing at every assignment.
    drivers_of: Vec<Vec<(DriverKey, usize)>>,
    /// The drivers with a projected transaction, in no order: the update phase and the next
    /// time look at these only, not at every driver.
    pending: Vec<usize>,
    /// The signals active in the last update phase: the only ones with `active` or `event`
    /// set.
    active: Vec<SignalId>,
    /// Signals driven element by element, with their number of elements.
    split: Vec<Option<usize>>,
    /// Signals resolved with the std_logic table.
    resolved: Vec<bool>,
    /// User-defined resolution functions (`Signal::resolution`).
    resolution: Vec<Option<Resolution>>,
    /// `bus` or `register` (`Signal::guarded`).
    guarded: Vec<Option<GuardedKind>>,
    /// What each view signal shows of its parent: `(parent, first, len)`
    /// ([`SignalKind::View`]); `None` for other signals.
    view_of: Vec<Option<(SignalId, usize, Option<usize>)>>,
    /// The view signals, in increasing order.
    views: Vec<SignalId>,
    /// What each gathered port shows: one parent element per element
    /// ([`SignalKind::Gather`]); `None` for other signals.
    gather_of: Vec<Option<Vec<GatherElement>>>,
    /// The gathered ports, in increasing order.
    gathers: Vec<SignalId>,
    /// `(signal, source)` of the converted signals ([`SignalKind::Converted`]), in
    /// increasing order.
    converted: Vec<(SignalId, SignalId)>,
    /// The views whose parent is a converted signal, in increasing order: updated after it.
    views_of_converted: Vec<SignalId>,
    /// `(S'transaction, S)` pairs ([`SignalKind::Transaction`]).
    transactions: Vec<(SignalId, SignalId)>,
    /// `S'stable(T)` and `S'quiet(T)` ([`SignalKind::Stable`]), in signal order, each with
    /// the driver the kernel schedules its return to true on.
    stables: Vec<Stable>,
    /// `'above` values to apply in the next update phase.
    forced: Vec<(SignalId, Value)>,
    /// Whether there are views, gathered ports, converted signals, `S'transaction`,
    /// `S'stable` or `S'quiet` signals (which [`Signals::update_derived`] updates).
    derived: bool,
    /// Whether events are recorded for [`Signals::take_changed`].
    track_changes: bool,
    /// Per signal driven element by element, unguarded, without a resolution function and
    /// with at most one driver per element: its element drivers and the elements that
    /// changed ([`ElementDriven`]).
    element_drivers: Vec<Option<ElementDriven>>,
    /// Per signal, its one driver when it has one, drives it whole and has no resolution
    /// function (`u32::MAX` otherwise): [`Signals::single_driver`] when that is connected.
    sole: Vec<u32>,
    /// The earliest transaction of the pending drivers, unless `next_stale` (an inertial
    /// rejection deleted transactions since it was found).
    next: f64,
    next_stale: bool,
    /// Signals with an event in the last update phase.
    pub events: Vec<SignalId>,
    /// Signals with an event since [`Signals::take_changed`] was last called.
    changed: Vec<bool>,
    changed_list: Vec<SignalId>,
}

/// What an assignment drives: the longest static prefix of its target (LRM 6.1, 12.6.1).
#[derive(Clone, Copy, Debug, PartialEq)]
enum Driven {
    /// The whole signal.
    Whole,
    /// An element whose index is known only at run time: every element.
    Dynamic,
    /// The element of this static index.
    Static(i64),
    /// The element at this position from the left (through a view).
    Position(usize),
}

/// The parent elements (positions from the left) that an assignment of `driven` to the view
/// `(first, len)` of type `ty` drives: `None` when the index is not known statically.
fn view_slots(ty: &Type, first: usize, len: Option<usize>, driven: Driven) -> Vec<usize> {
    match (len, driven) {
        (None, _) => vec![first],
        (Some(n), Driven::Static(i)) => match super::eval::offset(ty, i, n) {
            Ok(k) => vec![first + k],
            Err(_) => (first..first + n).collect(),
        },
        (Some(n), _) => (first..first + n).collect(),
    }
}

impl Signals {
    /// Creates a driver for every `(process, target)` pair of the design's assignments and
    /// rejects unresolved signals with several drivers.
    pub fn new(design: &Design) -> Result<Signals, SimError> {
        let states: Vec<SignalState> = design
            .signals
            .iter()
            .map(|s| SignalState {
                value: s.init.clone(),
                last_value: s.init.clone(),
                last_event: None,
                last_active: None,
                event: false,
                active: false,
            })
            .collect();
        let view_of: Vec<Option<(SignalId, usize, Option<usize>)>> = design
            .signals
            .iter()
            .map(|s| match s.kind {
                SignalKind::View { parent, first, len } => Some((parent, first, len)),
                _ => None,
            })
            .collect();
        let gather_of: Vec<Option<Vec<GatherElement>>> = design
            .signals
            .iter()
            .map(|s| match &s.kind {
                SignalKind::Gather { elements } => Some(elements.clone()),
                _ => None,
            })
            .collect();
        let assigned = drivers::assigned_targets(design, &view_of, &gather_of);
        let split = drivers::split_signals(design, &assigned);
        let (mut drivers, mut by_signal, index) =
            drivers::process_drivers(design, &assigned, &split);
        let stables = drivers::stable_drivers(design, &mut drivers, &mut by_signal);
        let resolved: Vec<bool> = design
            .signals
            .iter()
            .map(|s| is_std_ulogic(&s.ty))
            .collect();
        drivers::check_drivers(design, &drivers, &by_signal, &index, &split, &resolved)?;
        let n = states.len();
        let mut drivers_of = vec![Vec::new(); design.processes.len()];
        for (&(p, signal, element), &d) in &index {
            drivers_of[p].push(((signal, element), d));
        }
        for list in &mut drivers_of {
            list.sort_unstable();
        }
        let mut signals = Signals {
            states,
            drivers,
            by_signal,
            drivers_of,
            pending: Vec::new(),
            active: Vec::new(),
            split,
            resolved,
            resolution: design
                .signals
                .iter()
                .map(|s| s.resolution.clone())
                .collect(),
            guarded: design.signals.iter().map(|s| s.guarded).collect(),
            views: (0..view_of.len())
                .filter(|&s| view_of[s].is_some())
                .map(|s| SignalId(s as u32))
                .collect(),
            view_of,
            gathers: (0..gather_of.len())
                .filter(|&s| gather_of[s].is_some())
                .map(|s| SignalId(s as u32))
                .collect(),
            gather_of,
            converted: converted::of(design),
            views_of_converted: Vec::new(),
            transactions: design
                .signals
                .iter()
                .enumerate()
                .filter_map(|(k, s)| match s.kind {
                    SignalKind::Transaction { source } => Some((SignalId(k as u32), source)),
                    _ => None,
                })
                .collect(),
            stables,
            forced: Vec::new(),
            derived: false,
            track_changes: true,
            element_drivers: Vec::new(),
            sole: Vec::new(),
            next: f64::INFINITY,
            next_stale: false,
            events: Vec::new(),
            changed: vec![false; n],
            changed_list: Vec::new(),
        };
        signals.element_drivers = signals.element_driven();
        signals.sole = signals.sole_drivers();
        signals.derived = !(signals.views.is_empty()
            && signals.gathers.is_empty()
            && signals.converted.is_empty()
            && signals.transactions.is_empty()
            && signals.stables.is_empty());
        signals.views_of_converted = signals
            .views
            .iter()
            .copied()
            .filter(|v| {
                signals.view_of[v.index()]
                    .is_some_and(|(parent, ..)| signals.converted.iter().any(|&(c, _)| c == parent))
            })
            .collect();
        signals.initialize(design)?;
        Ok(signals)
    }

    /// The initial effective values (LRM 12.6.4): each driven signal's from its drivers'
    /// initial values (which a port's default may set), then each view's from its parent.
    fn initialize(&mut self, design: &Design) -> Result<(), SimError> {
        for s in 0..self.states.len() {
            if self.by_signal[s].is_empty() {
                continue;
            }
            let Some(value) = self.effective(s, design, 0.0)? else {
                continue;
            };
            let st = &mut self.states[s];
            st.last_value = value.clone();
            st.value = value;
        }
        for &v in &self.views {
            if let Some((parent, first, len)) = self.view_of[v.index()]
                && let Some(value) = self.states[parent.index()].value.view(first, len)
            {
                let st = &mut self.states[v.index()];
                st.last_value = value.clone();
                st.value = value;
            }
        }
        for k in 0..self.gathers.len() {
            let g = self.gathers[k];
            let value = self.gathered(g);
            let st = &mut self.states[g.index()];
            st.last_value = value.clone();
            st.value = value;
        }
        self.initialize_converted(design)
    }

    /// The value of gathered port `g` from its parents' current values.
    fn gathered(&self, g: SignalId) -> Value {
        let parts = self.gather_of[g.index()].as_deref().unwrap_or_default();
        let elements = parts
            .iter()
            .map(|&(parent, position)| {
                let value = &self.states[parent.index()].value;
                // Elaboration placed each position within its parent's bounds.
                position
                    .and_then(|k| value.view(k, None))
                    .unwrap_or_else(|| value.clone())
            })
            .collect();
        let string = matches!(self.states[g.index()].value, Value::String(_));
        vams_design::aggregate_value(elements, string)
    }

    /// The driver of `signal` in process `process` (every assignment has one), or of its
    /// `element` (an offset from the left) when the signal is driven element by element.
    pub fn driver(
        &self,
        process: usize,
        signal: SignalId,
        element: Option<usize>,
    ) -> Option<usize> {
        let key = match &self.gather_of[signal.index()] {
            Some(parts) => *parts.get(element?)?,
            None => match (self.view_of[signal.index()], element) {
                (Some((parent, first, None)), _) => (parent, Some(first)),
                (Some((parent, first, Some(_))), Some(k)) => (parent, Some(first + k)),
                _ => (signal, element),
            },
        };
        let list = self.drivers_of.get(process)?;
        let k = list.binary_search_by_key(&key, |&(key, _)| key).ok()?;
        Some(list[k].1)
    }

    /// `S'driving` and `S'driving_value` for `process` (LRM 14.1): whether its driver of
    /// `signal` is connected and the driver's current value (of a signal driven element by
    /// element, the array of its element drivers'); `None` when the process has no driver.
    pub fn driving(&self, process: usize, signal: SignalId) -> Option<(bool, Value)> {
        if let (None, Some(n)) = (self.view_of[signal.index()], self.split(signal)) {
            let mut connected = true;
            let mut values = Vec::with_capacity(n);
            for k in 0..n {
                let d = &self.drivers[self.driver(process, signal, Some(k))?];
                connected &= d.connected;
                values.push(d.current.clone());
            }
            let string = matches!(self.states[signal.index()].value, Value::String(_));
            return Some((connected, vams_design::aggregate_value(values, string)));
        }
        let d = &self.drivers[self.driver(process, signal, None)?];
        Some((d.connected, d.current.clone()))
    }

    /// The number of elements of a signal driven element by element; `None` for a signal
    /// driven whole.
    pub fn split(&self, signal: SignalId) -> Option<usize> {
        match self.view_of[signal.index()] {
            // A slice view is driven element by element; an element view as a whole.
            Some((_, _, len)) => len,
            None => match &self.gather_of[signal.index()] {
                Some(parts) => Some(parts.len()),
                None => self.split[signal.index()],
            },
        }
    }

    /// Schedules `value` on signal `s` in the next update phase (an `'above` crossing).
    pub fn force(&mut self, s: SignalId, value: Value) {
        self.forced.push((s, value));
    }

    pub fn has_forced(&self) -> bool {
        !self.forced.is_empty()
    }

    /// Applies an assignment's waveform `(value, absolute time)` to driver `d` (LRM 10.5.2.2).
    /// `elements` is non-empty with non-decreasing times, all at or after `now`.
    pub fn assign(&mut self, d: usize, elements: &mut Vec<(Option<Value>, f64)>, delay: Delay) {
        let Some(&(ref first_value, first_time)) = elements.first() else {
            return;
        };
        let driver = &mut self.drivers[d];
        self.next_stale |= edit(driver, first_value, first_time, delay);
        if first_time < self.next {
            self.next = first_time;
        }
        let w = &mut driver.waveform;
        if let [(value, time)] = elements.as_mut_slice() {
            // One element (the usual case): moved without a drain.
            let value = value.take();
            w.push_back(Transaction { time: *time, value });
            elements.clear();
        } else {
            for (value, time) in elements.drain(..) {
                w.push_back(Transaction { time, value });
            }
        }
        if !driver.pending {
            driver.pending = true;
            self.pending.push(d);
        }
    }

    /// [`Signals::assign`] of a one-element waveform of a scalar value (a lowered
    /// assignment's: `x` of kind `kind`), without the waveform's vector; the value is built
    /// where the transaction is stored (a value built by the caller and read back here whole
    /// stalled on its parts' stores).
    #[inline]
    pub fn assign_scalar(&mut self, d: usize, kind: Kind, x: i64, time: f64, delay: Delay) {
        let driver = &mut self.drivers[d];
        let w = &mut driver.waveform;
        // With no old transaction (the usual case) there is nothing to delete or reject.
        if !w.is_empty() {
            self.next_stale |= edit_scalar(w, kind.value(x), time, delay, &driver.current);
        }
        // The transaction pushed as a constant and its time and value written into it
        // afterwards: built before the push (which may grow the queue), the value was
        // assembled on the stack in parts and copied in whole, which stalled on those
        // stores; and a pushed `Transaction { time, value: None }` was, depending on the
        // inlining around it, also built on the stack and copied (half of this function's
        // samples under `perf`).
        w.push_back(Transaction::EMPTY);
        if let Some(tr) = w.back_mut() {
            tr.time = time;
            tr.value = Some(kind.value(x));
        }
        // Not `f64::min`, whose NaN handling costs more: times are numbers.
        if time < self.next {
            self.next = time;
        }
        if !driver.pending {
            driver.pending = true;
            self.pending.push(d);
        }
    }

    /// The earliest pending transaction, or infinity.
    #[inline]
    pub fn next_time(&self) -> f64 {
        if self.next_stale || !self.stables.is_empty() {
            return self.next_time_where(|_| true);
        }
        self.next
    }

    /// The earliest transaction due on a signal for which `counts` holds.
    pub fn next_time_where(&self, counts: impl Fn(SignalId) -> bool) -> f64 {
        let mut next = f64::INFINITY;
        let stables = self.stables.iter().map(|st| st.driver);
        for d in self.pending.iter().copied().chain(stables) {
            let d = &self.drivers[d];
            if let Some(tr) = d.waveform.front()
                && counts(d.signal)
            {
                next = next.min(tr.time);
            }
        }
        next
    }

    /// Marks signal `s` active at `now`.
    fn activate(&mut self, s: SignalId, now: f64) {
        let st = &mut self.states[s.index()];
        // Already active in this phase, it has `now` as its `last_active` (the update phase
        // clears the flags it set, all at one `now`): a signal driven element by element is
        // activated once per due driver.
        if !st.active {
            st.active = true;
            st.last_active = Some(now);
            self.active.push(s);
        }
    }

    /// The update phase at `now`: transactions due become driving values; effective values are
    /// recomputed; `events` lists the signals whose value changed. Inlined into the kernel's
    /// cycle always: in `EventKernel::run_digital`'s loop the compiler otherwise made it a
    /// call of its own, twice per time point.
    #[inline(always)]
    pub fn update(&mut self, now: f64, design: &Design) -> Result<(), SimError> {
        // Only the signals active in the last phase have flags set (`set` gives an event
        // to active signals only).
        for &s in &self.active {
            let st = &mut self.states[s.index()];
            st.event = false;
            st.active = false;
        }
        self.active.clear();
        self.events.clear();
        let mut k = 0;
        // The earliest transaction left.
        let mut next = f64::INFINITY;
        while k < self.pending.len() {
            let d = self.pending[k];
            let driver = &mut self.drivers[d];
            let mut due = false;
            let Driver {
                waveform,
                current,
                connected,
                ..
            } = driver;
            while let Some(tr) = waveform.front_mut()
                && tr.time <= now
            {
                *connected = tr.value.is_some();
                // Read in place, not moved out whole through the stack (its parts' stores
                // stalled the load of the whole).
                if let Some(v) = &mut tr.value
                    && !copy_scalar(current, v)
                {
                    *current = std::mem::replace(v, Value::Boolean(false));
                }
                waveform.pop_front();
                due = true;
            }
            let (signal, element) = (driver.signal, driver.element);
            match driver.waveform.front() {
                None => {
                    driver.pending = false;
                    self.pending.swap_remove(k);
                }
                Some(tr) => {
                    if tr.time < next {
                        next = tr.time;
                    }
                    k += 1;
                }
            }
            if due {
                if element.is_some()
                    && let Some(split) = &mut self.element_drivers[signal.index()]
                {
                    // Fits: `element_drivers` is only for signals whose drivers' indices do.
                    split.due.push(d as u32);
                }
                self.activate(signal, now);
            }
        }
        self.next = next;
        self.next_stale = false;
        // Effective values in signal order, as the events list them.
        self.active.sort_unstable();
        for k in 0..self.active.len() {
            let s = self.active[k].index();
            // Without the `Result` of the general case, which is large.
            if let Some(d) = self.single_driver(s) {
                // Read in place: a scalar driving value is copied, not cloned.
                if store(&mut self.states[s], &self.drivers[d].current) {
                    self.event(SignalId(s as u32), now);
                }
                continue;
            }
            if self.element_drivers[s].is_some() {
                self.update_elements(s, now);
                continue;
            }
            if let Some(value) = self.effective(s, design, now)? {
                self.set(SignalId(s as u32), value, now);
            }
        }
        if !self.forced.is_empty() {
            let mut forced = std::mem::take(&mut self.forced);
            for (s, value) in forced.drain(..) {
                self.activate(s, now);
                self.set(s, value, now);
            }
            self.forced = forced;
        }
        if self.derived {
            self.update_derived(now, design)?;
        }
        Ok(())
    }

    /// The rest of the update phase: the signals whose values follow others' (views,
    /// gathered ports, converted signals, `S'transaction`, `S'stable(T)` and `S'quiet(T)`).
    #[inline(never)]
    fn update_derived(&mut self, now: f64, design: &Design) -> Result<(), SimError> {
        // Views follow their parents (never views themselves) after these are updated.
        for i in 0..self.views.len() {
            self.follow_view(self.views[i], now);
        }
        // Gathered ports follow theirs the same way.
        for k in 0..self.gathers.len() {
            let g = self.gathers[k];
            let parts = self.gather_of[g.index()].as_deref().unwrap_or_default();
            if !parts.iter().any(|(p, _)| self.states[p.index()].active) {
                continue;
            }
            let value = self.gathered(g);
            self.activate(g, now);
            self.set(g, value, now);
        }
        self.update_converted(now, design)?;
        // `S'transaction` toggles whenever `S` is active; in signal order, so the transaction
        // signal of a transaction signal follows its source.
        for k in 0..self.transactions.len() {
            let (t, source) = self.transactions[k];
            if self.states[source.index()].active {
                let toggled = match self.states[t.index()].value {
                    Value::Enum(b) => Value::Enum(1 - b.min(1)),
                    _ => Value::Enum(1),
                };
                self.activate(t, now);
                self.set(t, toggled, now);
            }
        }
        // `S'stable(T)` falls in the cycle of an event on `S` (`S'quiet(T)`: of a transaction)
        // and rises `T` after the last one: a new event cancels the pending return, as a
        // transport assignment `<= false, true after T` would, but without its delta cycle of
        // delay. Their drivers stay out of `pending`, so that a return due in the phase of a
        // new event is cancelled, not applied and undone (no event).
        for k in 0..self.stables.len() {
            let st = self.stables[k];
            let source = &self.states[st.source.index()];
            let driver = &mut self.drivers[st.driver];
            let value = if (st.quiet && source.active) || (!st.quiet && source.event) {
                driver.waveform.clear();
                driver.waveform.push_back(Transaction {
                    time: super::process::later(now, st.delay),
                    value: Some(Value::Boolean(true)),
                });
                false
            } else if driver.waveform.front().is_some_and(|t| t.time <= now) {
                driver.waveform.clear();
                true
            } else {
                continue;
            };
            driver.current = Value::Boolean(value);
            self.activate(st.signal, now);
            self.set(st.signal, Value::Boolean(value), now);
        }
        Ok(())
    }

    /// View `v` takes its elements of its parent's value, when the parent is active.
    fn follow_view(&mut self, v: SignalId, now: f64) {
        let Some((parent, first, len)) = self.view_of[v.index()] else {
            return;
        };
        let p = &self.states[parent.index()];
        if !p.active {
            return;
        }
        // Elaboration placed the view within its parent's bounds.
        if let Some(value) = p.value.view(first, len) {
            self.activate(v, now);
            self.set(v, value, now);
        }
    }

    fn set(&mut self, s: SignalId, value: Value, now: f64) {
        let st = &mut self.states[s.index()];
        let changed = match store_scalar(st, &value) {
            Some(changed) => changed,
            None if st.value != value => {
                st.last_value = std::mem::replace(&mut st.value, value);
                true
            }
            None => false,
        };
        if changed {
            self.event(s, now);
        }
    }

    /// Signal `s`, given a new value by [`store`], has an event at `now`.
    #[inline]
    fn event(&mut self, s: SignalId, now: f64) {
        let st = &mut self.states[s.index()];
        st.last_event = Some(now);
        st.event = true;
        self.events.push(s);
        if self.track_changes && !self.changed[s.index()] {
            self.changed[s.index()] = true;
            self.changed_list.push(s);
        }
    }

    /// [`Signals::effective`] and [`Signals::set`] of a signal driven element by element
    /// with at most one driver per element (`element_drivers`): the elements of the drivers
    /// with a transaction in this phase compared and written in place (the others still
    /// hold their drivers' values, as every element does after each update), `last_value`
    /// brought up to date at the first change through the elements of the last event.
    #[inline(never)]
    fn update_elements(&mut self, s: usize, now: f64) {
        let Some(split) = &mut self.element_drivers[s] else {
            return;
        };
        let st = &mut self.states[s];
        let (Value::Array(items), Value::Array(last)) = (&mut st.value, &mut st.last_value) else {
            split.due.clear();
            return;
        };
        if last.len() != items.len() {
            // Not the shape `initialize` and this function keep; brought back to it.
            last.clone_from(items);
            split.changed.clear();
        }
        let mut event = false;
        for d in split.due.drain(..) {
            let driver = &self.drivers[d as usize];
            let Some(k) = driver.element.filter(|&k| k < items.len()) else {
                continue;
            };
            if same(&driver.current, &items[k]) {
                continue;
            }
            if !event {
                // `last_value` becomes the value before this phase: it differed only at the
                // elements that changed at the last event.
                for &k in &split.changed {
                    let (to, from) = (&mut last[k as usize], &items[k as usize]);
                    if !copy_scalar(to, from) {
                        to.clone_from(from);
                    }
                }
                split.changed.clear();
                event = true;
            }
            if !copy_scalar(&mut items[k], &driver.current) {
                items[k].clone_from(&driver.current);
            }
            split.changed.push(k as u32);
        }
        if event {
            self.event(SignalId(s as u32), now);
        }
    }

    /// The common case of [`Signals::effective`], a signal driven whole by one connected
    /// driver without a resolution function: that driver, whose value is the signal's (this
    /// runs at every transaction).
    #[inline]
    fn single_driver(&self, s: usize) -> Option<usize> {
        let d = self.sole[s] as usize;
        (d < self.drivers.len() && self.drivers[d].connected).then_some(d)
    }

    /// The effective value of signal `s` from its connected drivers (LRM 12.6.2): `None`
    /// when it keeps its value (a `register` with every driver disconnected).
    fn effective(&self, s: usize, design: &Design, now: f64) -> Result<Option<Value>, SimError> {
        let ds = &self.by_signal[s];
        let value = &self.states[s].value;
        let z = self.resolved[s] && self.guarded[s] == Some(GuardedKind::Bus);
        if let Some(n) = self.split[s] {
            let mut columns: Vec<Vec<&Value>> = vec![Vec::new(); n];
            for &d in ds {
                let driver = &self.drivers[d];
                if let Some(k) = driver.element.filter(|&k| k < n && driver.connected) {
                    columns[k].push(&driver.current);
                }
            }
            let values = columns
                .iter()
                .zip(value.elements())
                .map(|(column, old)| match column.as_slice() {
                    [] if z => all_z(&old),
                    [] => old,
                    [one] => (*one).clone(),
                    many => resolve(many),
                })
                .collect();
            let string = matches!(value, Value::String(_));
            return Ok(Some(vams_design::aggregate_value(values, string)));
        }
        if let Some(d) = self.single_driver(s) {
            return Ok(Some(self.drivers[d].current.clone()));
        }
        let on: Vec<&Value> = ds
            .iter()
            .map(|&d| &self.drivers[d])
            .filter(|d| d.connected)
            .map(|d| &d.current)
            .collect();
        if let Some(r) = &self.resolution[s] {
            if on.is_empty() && self.guarded[s] == Some(GuardedKind::Register) {
                return Ok(None);
            }
            return self.resolve_with(s, r, &on, design, now).map(Some);
        }
        Ok(match on.as_slice() {
            [] if z => Some(all_z(value)),
            [] => None,
            [one] => Some((*one).clone()),
            _ if !self.resolved[s] => Some(on[0].clone()),
            _ => Some(resolve(&on)),
        })
    }

    /// Signal `s`'s resolution function `r` applied to the driving values `on`.
    fn resolve_with(
        &self,
        s: usize,
        r: &Resolution,
        on: &[&Value],
        design: &Design,
        now: f64,
    ) -> Result<Value, SimError> {
        let signal = &design.signals[s];
        let fail = |message: String, help: &str| SimError::Runtime {
            process: format!("resolution of `{}`", signal.name),
            time: now,
            message,
            span: signal.span,
            help: help.to_string(),
        };
        let Some(&function) = r.by_count.get(on.len()) else {
            return Err(fail(
                format!(
                    "`{}` has {} driving values, more than elaboration counted",
                    signal.name,
                    on.len()
                ),
                "this is a bug in vams's count of drivers",
            ));
        };
        let character = matches!(&signal.ty, Type::Enum { name, .. } if name == "character");
        let values =
            vams_design::aggregate_value(on.iter().map(|v| (*v).clone()).collect(), character);
        // A resolution function's objects live for its call only.
        let io = super::io::Io::default();
        let env = self.update_env(design, now, &io);
        super::call::call_function(function, &[Expr::Const(values)], &env)
            .map_err(|e| fail(format!("in `{}`: {}", r.name, e.message), e.help))
    }

    /// Where a function that the update phase calls (a resolution function, a conversion)
    /// is evaluated: the signals' current values, no variables, quantities or drivers.
    fn update_env<'e>(
        &'e self,
        design: &'e Design,
        now: f64,
        io: &'e super::io::Io,
    ) -> super::eval::Env<'e> {
        super::eval::Env {
            signals: &self.states,
            vars: &[],
            quantities: &[],
            derivatives: &[],
            now,
            subprograms: &design.subprograms,
            depth: 0,
            io,
            drivers: None,
        }
    }

    /// Stops recording the signals with an event for [`Signals::take_changed`] (a run
    /// without an analog side, which takes none).
    pub fn stop_tracking_changes(&mut self) {
        self.track_changes = false;
        self.changed_list.clear();
        self.changed.fill(false);
    }

    /// Moves the signals with an event since the last call into `out` (cleared first).
    pub fn take_changed(&mut self, out: &mut Vec<SignalId>) {
        out.clear();
        for s in self.changed_list.drain(..) {
            self.changed[s.index()] = false;
            out.push(s);
        }
    }
}

/// The projected waveform of `driver` edited for a new waveform whose first element is
/// `first_value` at `first_time` (LRM 10.5.2.2), before its elements are appended; true if
/// transactions before the new ones may have gone (an inertial rejection).
#[inline]
fn edit(driver: &mut Driver, first_value: &Option<Value>, first_time: f64, delay: Delay) -> bool {
    let w = &mut driver.waveform;
    // Old transactions at or after the first new one are deleted (both mechanisms).
    while w.back().is_some_and(|tr| tr.time >= first_time) {
        w.pop_back();
    }
    // With no old transaction left there is nothing to reject (the usual case).
    if let Delay::Inertial(start) = delay
        && !w.is_empty()
    {
        reject(w, start, first_value, &driver.current);
        return true;
    }
    false
}

/// [`edit`] of a non-empty projected waveform for a new scalar transaction `value` at
/// `time`; true if transactions before it may have gone (an inertial rejection).
#[inline(never)]
fn edit_scalar(
    w: &mut VecDeque<Transaction>,
    value: Value,
    time: f64,
    delay: Delay,
    current: &Value,
) -> bool {
    // Old transactions at or after the new one are deleted (both mechanisms).
    while w.back().is_some_and(|tr| tr.time >= time) {
        w.pop_back();
    }
    if let Delay::Inertial(start) = delay
        && !w.is_empty()
    {
        reject(w, start, &Some(value), current);
        return true;
    }
    false
}

/// Inertial rejection (LRM 10.5.2.2) in `w`, none of whose transactions is at or after the
/// new waveform's first element `first_value`; `start` is the rejection interval's start.
#[inline(never)]
fn reject(w: &mut VecDeque<Transaction>, start: f64, first_value: &Option<Value>, current: &Value) {
    let by_element = first_value
        .as_ref()
        .is_some_and(|new| reject_by_element(w, start, new, current));
    if !by_element {
        // Within the rejection interval, keep only the run of old transactions directly
        // before the new one that already carries its value; delete the rest.
        let mut kept = VecDeque::with_capacity(w.len());
        let mut chain = true;
        while let Some(tr) = w.pop_back() {
            if tr.time < start {
                w.push_back(tr);
                break;
            }
            chain = chain && tr.value == *first_value;
            if chain {
                kept.push_front(tr);
            }
        }
        w.extend(kept);
    }
}

/// Element `k` of `v` as [`Value::elements`] lists them, without copying the others.
fn element_of(v: &Value, k: usize) -> Option<Value> {
    match v {
        Value::Array(items) => items.get(k).cloned(),
        Value::String(s) => s.chars().nth(k).map(|c| Value::Enum(c as u32)),
        other => (k == 0).then(|| other.clone()),
    }
}

/// The number of elements [`Value::elements`] lists, without copying them.
fn element_count(v: &Value) -> usize {
    match v {
        Value::Array(items) => items.len(),
        Value::String(s) => s.chars().count(),
        _ => 1,
    }
}

/// `a == b`, for two scalars of one kind (an element's driver and the element, at each
/// transaction) without the call to `Value`'s general comparison.
#[inline(always)]
fn same(a: &Value, b: &Value) -> bool {
    match (a, b) {
        (Value::Enum(x), Value::Enum(y)) => x == y,
        (Value::Integer(x), Value::Integer(y)) => x == y,
        (Value::Boolean(x), Value::Boolean(y)) => x == y,
        _ => a == b,
    }
}

/// `*to = *from` for two scalars of one kind, in place; false (having done nothing) for other
/// values.
#[inline(always)]
fn copy_scalar(to: &mut Value, from: &Value) -> bool {
    match (to, from) {
        (Value::Integer(a), Value::Integer(b)) => *a = *b,
        (Value::Enum(a), Value::Enum(b)) => *a = *b,
        (Value::Boolean(a), Value::Boolean(b)) => *a = *b,
        (Value::Real(a), Value::Real(b)) => *a = *b,
        (Value::Time(a), Value::Time(b)) => *a = *b,
        _ => return false,
    }
    true
}

/// Gives `st` the value `v`, its old value becoming `last_value` when it changes; true if it
/// changed.
#[inline(always)]
fn store(st: &mut SignalState, v: &Value) -> bool {
    match store_scalar(st, v) {
        Some(changed) => changed,
        None => store_general(st, v),
    }
}

/// [`store`] of a scalar replacing a scalar of its kind (the usual transaction), written in
/// place without comparing, cloning or dropping a general `Value` (the comparison is
/// `Value`'s `==` all the same); `None` for other values.
#[inline(always)]
fn store_scalar(st: &mut SignalState, v: &Value) -> Option<bool> {
    macro_rules! scalar {
        ($variant:ident, $old:expr, $new:expr) => {{
            if *$old == *$new {
                return Some(false);
            }
            let previous = std::mem::replace($old, *$new);
            match &mut st.last_value {
                Value::$variant(last) => *last = previous,
                last => *last = Value::$variant(previous),
            }
            Some(true)
        }};
    }
    match (&mut st.value, v) {
        (Value::Integer(old), Value::Integer(new)) => scalar!(Integer, old, new),
        (Value::Enum(old), Value::Enum(new)) => scalar!(Enum, old, new),
        (Value::Boolean(old), Value::Boolean(new)) => scalar!(Boolean, old, new),
        (Value::Real(old), Value::Real(new)) => scalar!(Real, old, new),
        (Value::Time(old), Value::Time(new)) => scalar!(Time, old, new),
        _ => None,
    }
}

#[inline(never)]
fn store_general(st: &mut SignalState, v: &Value) -> bool {
    if st.value == *v {
        return false;
    }
    st.last_value = std::mem::replace(&mut st.value, v.clone());
    true
}

fn is_std_ulogic(ty: &Type) -> bool {
    match ty {
        Type::Enum { name, literals } => {
            matches!(name.as_str(), "std_ulogic" | "std_logic") && literals.len() == 9
        }
        Type::Array { element, .. } => is_std_ulogic(element),
        _ => false,
    }
}

/// IEEE 1164's resolution table, positions `U X 0 1 Z W L H -`.
const RESOLUTION: [[u32; 9]; 9] = [
    [0, 0, 0, 0, 0, 0, 0, 0, 0],
    [0, 1, 1, 1, 1, 1, 1, 1, 1],
    [0, 1, 2, 1, 2, 2, 2, 2, 1],
    [0, 1, 1, 3, 3, 3, 3, 3, 1],
    [0, 1, 2, 3, 4, 5, 6, 7, 1],
    [0, 1, 2, 3, 5, 5, 5, 5, 1],
    [0, 1, 2, 3, 6, 5, 6, 5, 1],
    [0, 1, 2, 3, 7, 5, 5, 7, 1],
    [0, 1, 1, 1, 1, 1, 1, 1, 1],
];

/// A std_logic value with every element `'Z'`: a `bus` with all its drivers disconnected
/// (`resolved` of no values).
fn all_z(v: &Value) -> Value {
    match v {
        Value::Array(items) => Value::Array(items.iter().map(all_z).collect()),
        _ => Value::Enum(4),
    }
}

/// Resolves the driving values of a std_logic signal (element-wise for vectors).
fn resolve(values: &[&Value]) -> Value {
    match values.first() {
        Some(Value::Array(first)) => Value::Array(
            (0..first.len())
                .map(|i| {
                    let column: Vec<&Value> = values
                        .iter()
                        .filter_map(|v| match v {
                            Value::Array(items) => items.get(i),
                            _ => None,
                        })
                        .collect();
                    resolve(&column)
                })
                .collect(),
        ),
        _ => {
            // 'Z' is the identity of the table.
            let r = values.iter().fold(4u32, |acc, v| match v {
                Value::Enum(p) if (*p as usize) < 9 => RESOLUTION[acc as usize][*p as usize],
                _ => 1,
            });
            Value::Enum(r)
        }
    }
}

/// The scalar subelements of a value, in order (an array's elements, a record's fields,
/// recursively; any other value is one scalar).
fn scalars<'v>(v: &'v Value, out: &mut Vec<&'v Value>) {
    match v {
        Value::Array(items) => items.iter().for_each(|i| scalars(i, out)),
        other => out.push(other),
    }
}

/// `template` with its scalar subelements replaced, in order, by `leaves`.
fn rebuild(template: &Value, leaves: &mut impl Iterator<Item = Value>) -> Value {
    match template {
        Value::Array(items) => Value::Array(items.iter().map(|i| rebuild(i, leaves)).collect()),
        other => leaves.next().unwrap_or_else(|| other.clone()),
    }
}

/// Inertial pulse rejection for a composite value, scalar subelement by scalar subelement: the
/// LRM gives a composite signal a driver per scalar subelement (12.6.1) and marks each one's
/// transactions on its own (12.6.2: in the rejection interval, an old transaction survives only
/// in the run directly before the new one that has the new value). For one element whose old
/// transaction survives beside another whose does not, the transaction is kept with the rejected
/// element's value as it was before it, which gives that element no change. `w` holds the
/// old transactions (none at or after the new one's time), `start` is the first new time minus
/// the rejection limit, `current` the driver's value. Returns false, having changed nothing,
/// for a scalar value or where a transaction in the interval is null or shaped differently; the
/// caller then compares whole values.
fn reject_by_element(
    w: &mut VecDeque<Transaction>,
    start: f64,
    new: &Value,
    current: &Value,
) -> bool {
    if !matches!(new, Value::Array(_)) {
        return false;
    }
    let mut new_leaves = Vec::new();
    scalars(new, &mut new_leaves);
    let first = w.partition_point(|tr| tr.time < start);
    // The value each element has before the interval: the last transaction before it, else the
    // driver's current value.
    let before = match first.checked_sub(1).map(|k| &w[k].value) {
        Some(Some(v)) => v,
        Some(None) => return false,
        None => current,
    };
    let mut previous: Vec<Value> = Vec::new();
    {
        let mut leaves = Vec::new();
        scalars(before, &mut leaves);
        if leaves.len() != new_leaves.len() {
            return false;
        }
        previous.extend(leaves.into_iter().cloned());
    }
    let mut window: Vec<Vec<Value>> = Vec::with_capacity(w.len() - first);
    for tr in w.range(first..) {
        let Some(v) = &tr.value else {
            return false;
        };
        let mut leaves = Vec::new();
        scalars(v, &mut leaves);
        if leaves.len() != new_leaves.len() {
            return false;
        }
        window.push(leaves.into_iter().cloned().collect());
    }
    // Backwards from the new transaction: element k's run of equal values.
    let mut chain = vec![true; new_leaves.len()];
    let mut marked: Vec<Vec<bool>> = vec![Vec::new(); window.len()];
    for (leaves, mark) in window.iter().zip(marked.iter_mut()).rev() {
        for (k, leaf) in leaves.iter().enumerate() {
            chain[k] = chain[k] && leaf == new_leaves[k];
        }
        *mark = chain.clone();
    }
    let old: Vec<Transaction> = w.drain(first..).collect();
    for ((tr, mut leaves), mark) in old.into_iter().zip(window).zip(marked) {
        if !mark.iter().any(|m| *m) {
            continue;
        }
        for (k, leaf) in leaves.iter_mut().enumerate() {
            if mark[k] {
                previous[k] = leaf.clone();
            } else {
                *leaf = previous[k].clone();
            }
        }
        let Some(template) = &tr.value else {
            continue;
        };
        let value = rebuild(template, &mut leaves.into_iter());
        w.push_back(Transaction {
            time: tr.time,
            value: Some(value),
        });
    }
    true
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn std_logic_resolution_follows_the_ieee_table() {
        let (u, x, zero, one, z, w, l, h) = (0, 1, 2, 3, 4, 5, 6, 7);
        let r = |a: u32, b: u32| resolve(&[&Value::Enum(a), &Value::Enum(b)]);
        assert_eq!(r(zero, one), Value::Enum(x));
        assert_eq!(r(z, one), Value::Enum(one));
        assert_eq!(r(l, h), Value::Enum(w));
        assert_eq!(r(h, zero), Value::Enum(zero));
        assert_eq!(r(u, one), Value::Enum(u));
        assert_eq!(r(z, z), Value::Enum(z));
    }
}
