//! Signals and their drivers: projected output waveforms, the update phase, resolution.
//!
//! Each process that assigns a signal has one driver for it (LRM 14.7.2). A driver holds its
//! current driving value and its projected waveform: transactions in increasing time order.
//! An assignment edits the waveform by the LRM's rules for transport and inertial delay
//! (10.5.2.2); the update phase makes every transaction that has come due the driver's current
//! value and recomputes the signal's effective value (resolved with the std_logic table when
//! several drivers act on a `std_ulogic` signal). `'above` signals have no driver: the analog
//! side forces their values at threshold crossings.

use std::collections::{HashMap, HashSet, VecDeque};

use crate::design::{Design, Expr, Instr, SignalId, Type, Value};

use super::error::SimError;

/// A signal's visible state.
#[derive(Clone, Debug)]
pub(crate) struct SignalState {
    pub value: Value,
    pub last_value: Value,
    /// Time of the last event; `None` before the first.
    pub last_event: Option<f64>,
    /// An event (value change) in the current simulation cycle.
    pub event: bool,
    /// A transaction (with or without a change) in the current simulation cycle.
    pub active: bool,
}

#[derive(Clone, Debug)]
struct Transaction {
    time: f64,
    value: Value,
}

/// How an assignment edits the projected waveform.
#[derive(Clone, Copy, Debug, PartialEq)]
pub(crate) enum Delay {
    Transport,
    /// Inertial with this pulse-rejection limit in seconds.
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
    waveform: VecDeque<Transaction>,
}

/// Every signal's state and every driver.
pub(crate) struct Signals {
    pub states: Vec<SignalState>,
    drivers: Vec<Driver>,
    /// Driver indices of each signal.
    by_signal: Vec<Vec<usize>>,
    /// Driver index of `(process, signal, element)`.
    index: HashMap<(usize, SignalId, Option<usize>), usize>,
    /// Signals driven element by element, with their number of elements.
    split: Vec<Option<usize>>,
    /// Signals resolved with the std_logic table.
    resolved: Vec<bool>,
    /// `'above` values to apply in the next update phase.
    forced: Vec<(SignalId, Value)>,
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
}

/// The signals `code` assigns, directly or in the procedures it calls (a procedure drives
/// its signal parameters through the calling process's drivers, LRM 14.7.2), each with
/// what the assignment drives.
fn assigned_signals(design: &Design, code: &[Instr]) -> Vec<(SignalId, Driven)> {
    let mut out = Vec::new();
    let mut seen = HashSet::new();
    let mut todo = vec![code];
    while let Some(code) = todo.pop() {
        for instr in code {
            match instr {
                Instr::Assign { target, index, .. } => out.push((
                    *target,
                    match index {
                        None => Driven::Whole,
                        Some(Expr::Const(Value::Integer(i))) => Driven::Static(*i),
                        Some(_) => Driven::Dynamic,
                    },
                )),
                Instr::Call { sub, .. } => {
                    if let Some(s) = design.subprograms.get(sub.index()) {
                        if seen.insert(*sub) {
                            todo.push(&s.code);
                        }
                    }
                }
                _ => {}
            }
        }
    }
    out
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
                event: false,
                active: false,
            })
            .collect();
        let mut drivers = Vec::new();
        let mut by_signal = vec![Vec::new(); design.signals.len()];
        let mut index = HashMap::new();
        let assigned: Vec<Vec<(SignalId, Driven)>> = design
            .processes
            .iter()
            .map(|p| assigned_signals(design, &p.code))
            .collect();
        let mut split: Vec<Option<usize>> = vec![None; design.signals.len()];
        for &(target, _) in assigned
            .iter()
            .flatten()
            .filter(|(_, d)| *d != Driven::Whole)
        {
            split[target.index()] = Some(elements(&design.signals[target.index()].init).len());
        }
        for (p, targets) in assigned.iter().enumerate() {
            for &(target, driven) in targets {
                let signal = &design.signals[target.index()];
                let slots: Vec<Option<usize>> = match (split[target.index()], driven) {
                    (None, _) => vec![None],
                    // A static index drives its element only (processes of a generate may
                    // each drive one element of an unresolved array).
                    (Some(n), Driven::Static(i)) => match super::eval::offset(&signal.ty, i, n) {
                        Ok(k) => vec![Some(k)],
                        Err(_) => (0..n).map(Some).collect(),
                    },
                    (Some(n), _) => (0..n).map(Some).collect(),
                };
                let initial = match split[target.index()] {
                    Some(_) => elements(&signal.init),
                    None => vec![signal.init.clone()],
                };
                for element in slots {
                    index.entry((p, target, element)).or_insert_with(|| {
                        by_signal[target.index()].push(drivers.len());
                        let current = initial[element.unwrap_or(0)].clone();
                        drivers.push(Driver {
                            signal: target,
                            element,
                            current,
                            waveform: VecDeque::new(),
                        });
                        drivers.len() - 1
                    });
                }
            }
        }
        let resolved: Vec<bool> = design
            .signals
            .iter()
            .map(|s| is_std_ulogic(&s.ty))
            .collect();
        // An unresolved signal (or element) has at most one driver: processes may drive
        // different elements of one array.
        for (s, ds) in by_signal.iter().enumerate() {
            if resolved[s] {
                continue;
            }
            let element = |d: &usize| drivers[*d].element;
            let Some(shared) = ds
                .iter()
                .find(|d| ds.iter().filter(|e| element(e) == element(d)).count() > 1)
                .map(element)
            else {
                continue;
            };
            let mut processes: Vec<&str> = index
                .keys()
                .filter(|(_, sig, e)| sig.index() == s && *e == shared)
                .map(|(p, _, _)| design.processes[*p].name.as_str())
                .collect();
            processes.sort_unstable();
            let signal = &design.signals[s];
            let name = match (shared, &signal.ty) {
                (
                    Some(k),
                    Type::Array {
                        left, ascending, ..
                    },
                ) => {
                    let i = if *ascending {
                        left + k as i64
                    } else {
                        left - k as i64
                    };
                    format!("{}({i})", signal.name)
                }
                _ => signal.name.clone(),
            };
            return Err(SimError::MultipleDrivers {
                signal: name,
                count: processes.len(),
                processes: processes.join(", "),
                span: signal.span,
            });
        }
        let n = states.len();
        Ok(Signals {
            states,
            drivers,
            by_signal,
            index,
            split,
            resolved,
            forced: Vec::new(),
            events: Vec::new(),
            changed: vec![false; n],
            changed_list: Vec::new(),
        })
    }

    /// The driver of `signal` in process `process` (every assignment has one), or of its
    /// `element` (an offset from the left) when the signal is driven element by element.
    pub fn driver(
        &self,
        process: usize,
        signal: SignalId,
        element: Option<usize>,
    ) -> Option<usize> {
        self.index.get(&(process, signal, element)).copied()
    }

    /// The number of elements of a signal driven element by element; `None` for a signal
    /// driven whole.
    pub fn split(&self, signal: SignalId) -> Option<usize> {
        self.split[signal.index()]
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
    pub fn assign(&mut self, d: usize, elements: &mut Vec<(Value, f64)>, delay: Delay) {
        let Some(&(ref first_value, first_time)) = elements.first() else {
            return;
        };
        let w = &mut self.drivers[d].waveform;
        // Old transactions at or after the first new one are deleted (both mechanisms).
        while w.back().is_some_and(|tr| tr.time >= first_time) {
            w.pop_back();
        }
        if let Delay::Inertial(reject) = delay {
            // Within the rejection interval, keep only the run of old transactions directly
            // before the new one that already carries its value; delete the rest.
            let start = first_time - reject;
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
        w.extend(
            elements
                .drain(..)
                .map(|(value, time)| Transaction { time, value }),
        );
    }

    /// The earliest pending transaction, or infinity.
    pub fn next_time(&self) -> f64 {
        self.drivers
            .iter()
            .filter_map(|d| d.waveform.front().map(|t| t.time))
            .fold(f64::INFINITY, f64::min)
    }

    /// The update phase at `now`: transactions due become driving values; effective values are
    /// recomputed; `events` lists the signals whose value changed.
    pub fn update(&mut self, now: f64) {
        for st in &mut self.states {
            st.event = false;
            st.active = false;
        }
        self.events.clear();
        for d in 0..self.drivers.len() {
            let driver = &mut self.drivers[d];
            let mut due = false;
            while driver.waveform.front().is_some_and(|t| t.time <= now) {
                // The loop condition guarantees an element.
                let tr = driver.waveform.pop_front().unwrap();
                driver.current = tr.value;
                due = true;
            }
            if due {
                self.states[driver.signal.index()].active = true;
            }
        }
        for s in 0..self.states.len() {
            if !self.states[s].active {
                continue;
            }
            let value = self.effective(s);
            self.set(SignalId(s as u32), value, now);
        }
        let forced = std::mem::take(&mut self.forced);
        for (s, value) in &forced {
            self.states[s.index()].active = true;
            self.set(*s, value.clone(), now);
        }
        self.forced = forced;
        self.forced.clear();
    }

    fn set(&mut self, s: SignalId, value: Value, now: f64) {
        let st = &mut self.states[s.index()];
        if st.value != value {
            st.last_value = std::mem::replace(&mut st.value, value);
            st.last_event = Some(now);
            st.event = true;
            self.events.push(s);
            if !self.changed[s.index()] {
                self.changed[s.index()] = true;
                self.changed_list.push(s);
            }
        }
    }

    fn effective(&self, s: usize) -> Value {
        let ds = &self.by_signal[s];
        if let Some(n) = self.split[s] {
            let mut columns: Vec<Vec<&Value>> = vec![Vec::new(); n];
            for &d in ds {
                let driver = &self.drivers[d];
                if let Some(k) = driver.element.filter(|&k| k < n) {
                    columns[k].push(&driver.current);
                }
            }
            let value = &self.states[s].value;
            let values = columns
                .iter()
                .zip(elements(value))
                .map(|(column, old)| match column.as_slice() {
                    [] => old,
                    [one] => (*one).clone(),
                    many => resolve(many),
                })
                .collect();
            return crate::design::aggregate_value(values, matches!(value, Value::String(_)));
        }
        if ds.len() == 1 || !self.resolved[s] {
            return self.drivers[ds[0]].current.clone();
        }
        let values: Vec<&Value> = ds.iter().map(|&d| &self.drivers[d].current).collect();
        resolve(&values)
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

/// The elements of an array value (a string's characters as enumeration positions); a
/// scalar is its own one element.
pub(super) fn elements(v: &Value) -> Vec<Value> {
    match v {
        Value::Array(items) => items.clone(),
        Value::String(s) => s.chars().map(|c| Value::Enum(c as u32)).collect(),
        other => vec![other.clone()],
    }
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
