//! The drivers of a design's signals, in the steps [`Signals::new`](super::Signals::new)
//! takes: what each process's assignments drive (the longest static prefix of each target,
//! through views and gathered ports), which signals are driven element by element, one
//! driver per process and signal (or element), the kernel's own drivers of `S'stable` and
//! `S'quiet`, and the check that an unresolved signal has at most one driver per element.

use std::borrow::Cow;
use std::collections::VecDeque;

use rustc_hash::FxHashMap;

use vams_design::{Design, Expr, SignalId, SignalKind, Type, Value};

use super::super::error::SimError;
use super::{
    Driven, Driver, ElementDriven, GatherElement, Signals, Stable, element_count, element_of,
    view_slots,
};

/// A driver's key: the process, the signal, and the element (`None`: the whole signal).
pub(super) type DriverKey = (usize, SignalId, Option<usize>);

/// Per process, the targets its assignments drive, each with its driver's initial value: the
/// default of the port the process drives it through, else the signal's own (an element's for
/// a position). An assignment to a view drives its elements of the parent (statically known
/// ones); one to a gathered port drives each element's parent.
pub(super) fn assigned_targets<'d>(
    design: &'d Design,
    view_of: &[Option<(SignalId, usize, Option<usize>)>],
    gather_of: &[Option<Vec<GatherElement>>],
) -> Vec<Vec<(SignalId, Driven, Cow<'d, Value>)>> {
    design
        .processes
        .iter()
        .map(|p| {
            let mut out = Vec::new();
            for (target, index) in design.assignments(&p.code) {
                let driven = match index {
                    None => Driven::Whole,
                    Some(Expr::Const(Value::Integer(i))) => Driven::Static(*i),
                    Some(_) => Driven::Dynamic,
                };
                let port_default = p
                    .driver_inits
                    .iter()
                    .find(|(s, _)| *s == target)
                    .map(|(_, v)| v);
                let signal = &design.signals[target.index()];
                let init = port_default.unwrap_or(&signal.init);
                // An assignment to a gathered port drives each element's parent: an
                // element of an array, or a whole scalar signal.
                if let Some(parts) = &gather_of[target.index()] {
                    let own = init.elements();
                    let n = parts.len();
                    let slots: Vec<usize> = match driven {
                        Driven::Static(i) => match super::super::eval::offset(&signal.ty, i, n) {
                            Ok(k) => vec![k],
                            Err(_) => (0..n).collect(),
                        },
                        _ => (0..n).collect(),
                    };
                    for k in slots {
                        let (parent, position) = parts[k];
                        let v = own.get(k).cloned().unwrap_or_else(|| init.clone());
                        let driven = position.map_or(Driven::Whole, Driven::Position);
                        out.push((parent, driven, Cow::Owned(v)));
                    }
                    continue;
                }
                match view_of[target.index()] {
                    Some((parent, first, len)) => {
                        // A slice's element k - first of its (port's) initial value, which
                        // elaboration gives the slice's length; else the parent's element.
                        let own = init.elements();
                        let parent_init = &design.signals[parent.index()].init;
                        for k in view_slots(&signal.ty, first, len, driven) {
                            let v = match len {
                                None => init.clone(),
                                Some(_) => (own.get(k - first).cloned())
                                    .or_else(|| parent_init.view(k, None))
                                    .unwrap_or_else(|| init.clone()),
                            };
                            out.push((parent, Driven::Position(k), Cow::Owned(v)));
                        }
                    }
                    // Borrowed: n processes driving one element each of an n-element
                    // signal would copy it n times.
                    None => out.push((target, driven, Cow::Borrowed(init))),
                }
            }
            out
        })
        .collect()
}

/// Per signal, its element count when some assignment drives a part of it (`None`: driven
/// whole only).
pub(super) fn split_signals(
    design: &Design,
    assigned: &[Vec<(SignalId, Driven, Cow<'_, Value>)>],
) -> Vec<Option<usize>> {
    let mut split: Vec<Option<usize>> = vec![None; design.signals.len()];
    for (target, ..) in assigned
        .iter()
        .flatten()
        .filter(|(_, d, _)| *d != Driven::Whole)
    {
        // Counted, not copied: once per assignment of a generate's n processes.
        split[target.index()] = Some(element_count(&design.signals[target.index()].init));
    }
    split
}

/// One driver per process and driven signal (or element), in process order: the drivers,
/// each signal's drivers, and the drivers by key.
pub(super) fn process_drivers(
    design: &Design,
    assigned: &[Vec<(SignalId, Driven, Cow<'_, Value>)>],
    split: &[Option<usize>],
) -> (Vec<Driver>, Vec<Vec<usize>>, FxHashMap<DriverKey, usize>) {
    let mut drivers = Vec::new();
    let mut by_signal = vec![Vec::new(); design.signals.len()];
    let mut index = FxHashMap::default();
    for (p, targets) in assigned.iter().enumerate() {
        for (target, driven, init) in targets {
            let (target, driven) = (*target, *driven);
            let signal = &design.signals[target.index()];
            let slots: Vec<Option<usize>> = match (split[target.index()], driven) {
                (None, _) => vec![None],
                // A static index drives its element only (processes of a generate may
                // each drive one element of an unresolved array).
                (Some(n), Driven::Static(i)) => {
                    match super::super::eval::offset(&signal.ty, i, n) {
                        Ok(k) => vec![Some(k)],
                        Err(_) => (0..n).map(Some).collect(),
                    }
                }
                (Some(_), Driven::Position(k)) => vec![Some(k)],
                (Some(n), _) => (0..n).map(Some).collect(),
            };
            // Element k of the initial value (not the whole value split into a vector
            // for each process: a generate of n processes each driving one element of an
            // n-element signal took n^2 copies).
            let whole = matches!(driven, Driven::Position(_)) || split[target.index()].is_none();
            for element in slots {
                index.entry((p, target, element)).or_insert_with(|| {
                    by_signal[target.index()].push(drivers.len());
                    let current = match element {
                        Some(k) if !whole => {
                            element_of(init, k).unwrap_or_else(|| Value::clone(init))
                        }
                        _ => Value::clone(init),
                    };
                    drivers.push(Driver {
                        signal: target,
                        element,
                        current,
                        connected: true,
                        waveform: VecDeque::new(),
                        pending: false,
                    });
                    drivers.len() - 1
                });
            }
        }
    }
    (drivers, by_signal, index)
}

/// `S'stable(T)` and `S'quiet(T)`: a driver of the kernel's own each, for the return to true
/// (no process drives them; `update` applies it, not the pending list).
pub(super) fn stable_drivers(
    design: &Design,
    drivers: &mut Vec<Driver>,
    by_signal: &mut [Vec<usize>],
) -> Vec<Stable> {
    let mut stables = Vec::new();
    for (k, signal) in design.signals.iter().enumerate() {
        if let SignalKind::Stable {
            source,
            delay,
            quiet,
        } = signal.kind
        {
            by_signal[k].push(drivers.len());
            stables.push(Stable {
                signal: SignalId(k as u32),
                source,
                delay,
                quiet,
                driver: drivers.len(),
            });
            drivers.push(Driver {
                signal: SignalId(k as u32),
                element: None,
                current: signal.init.clone(),
                connected: true,
                waveform: VecDeque::new(),
                pending: false,
            });
        }
    }
    stables
}

/// An unresolved signal (or element) has at most one driver: processes may drive different
/// elements of one array. A signal with a resolution function of its own is driven whole.
pub(super) fn check_drivers(
    design: &Design,
    drivers: &[Driver],
    by_signal: &[Vec<usize>],
    index: &FxHashMap<DriverKey, usize>,
    split: &[Option<usize>],
    resolved: &[bool],
) -> Result<(), SimError> {
    for (s, ds) in by_signal.iter().enumerate() {
        let signal = &design.signals[s];
        if signal.resolution.is_some() && split[s].is_some() {
            return Err(SimError::Runtime {
                process: format!("resolution of `{}`", signal.name),
                time: 0.0,
                message: "a signal with a resolution function of its own is driven element by element".into(),
                span: signal.span,
                help: "assign the whole signal in each process (its resolution function resolves whole values)".into(),
            });
        }
        if resolved[s] || signal.resolution.is_some() {
            continue;
        }
        let element = |d: &usize| drivers[*d].element;
        // Counted once (n generated processes each driving an element of an n-element
        // signal made n^2 comparisons); the first driver in order whose element another
        // driver drives too.
        let mut count: FxHashMap<Option<usize>, usize> = FxHashMap::default();
        for d in ds {
            *count.entry(element(d)).or_default() += 1;
        }
        let Some(shared) = ds.iter().map(element).find(|e| count[e] > 1) else {
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
    Ok(())
}

impl Signals {
    /// Per signal driven element by element, unguarded, without a resolution function and
    /// with at most one driver per element: its [`ElementDriven`] state.
    pub(super) fn element_driven(&self) -> Vec<Option<ElementDriven>> {
        (0..self.states.len())
            .map(|s| {
                let n = self.split[s]?;
                if self.resolution[s].is_some()
                    || self.guarded[s].is_some()
                    || !matches!(&self.states[s].value, Value::Array(items) if items.len() == n)
                {
                    return None;
                }
                let mut of = vec![u32::MAX; n];
                for &d in &self.by_signal[s] {
                    let k = self.drivers[d].element?;
                    let slot = of.get_mut(k)?;
                    if *slot != u32::MAX {
                        return None;
                    }
                    *slot = u32::try_from(d).ok()?;
                }
                // Each element has at most one driver (`of` only checks that).
                Some(ElementDriven {
                    due: Vec::new(),
                    changed: Vec::new(),
                })
            })
            .collect()
    }

    /// Per signal, its one driver when it has one, drives it whole and has no resolution
    /// function (`u32::MAX` otherwise).
    pub(super) fn sole_drivers(&self) -> Vec<u32> {
        (0..self.states.len())
            .map(|s| match self.by_signal[s].as_slice() {
                [d] if self.split[s].is_none() && self.resolution[s].is_none() => {
                    u32::try_from(*d).unwrap_or(u32::MAX)
                }
                _ => u32::MAX,
            })
            .collect()
    }
}
