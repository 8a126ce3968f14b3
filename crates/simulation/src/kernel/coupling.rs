//! Which digital activity the analog solver must stop for (issue: a counter clocked every
//! nanosecond beside an RC filter cost an analog step and a Newton solve per clock edge).
//!
//! A process is *coupled* when it may read the analog solution (a quantity, `Q'dot`), execute
//! a `break`, or drive a signal whose events may reach the analog side: one that the equations
//! read, or one that a coupled process waits on. Everything else is digital-only: a time
//! point where only transactions of signals no coupled process waits on, read by no equation,
//! and timeouts of digital-only processes are due, runs its delta cycles between analog steps,
//! without an analog solution of its own (its processes read none, and its events change
//! nothing the equations read). The analysis is static and conservative: a process that calls
//! a subprogram reading quantities or waiting counts by everything that subprogram does.

use rustc_hash::FxHashSet;

use vams_design::{Design, Expr, Instr, SignalId, SignalKind, SubprogramId};

pub(crate) struct Coupling {
    /// Per process: whether its activity needs the analog solution at its time.
    coupled: Vec<bool>,
    /// Per signal: whether a transaction on it may need the analog solution at its time.
    wakes: Vec<bool>,
}

/// What one process's code (with the subprograms it calls) does that matters here.
#[derive(Default)]
struct Reach {
    analog: bool,
    waits_on: Vec<SignalId>,
    drives: Vec<SignalId>,
}

fn reach(design: &Design, code: &[Instr]) -> Reach {
    let mut out = Reach::default();
    let mut seen: FxHashSet<SubprogramId> = FxHashSet::default();
    let mut todo: Vec<&[Instr]> = vec![code];
    let mut calls: Vec<SubprogramId> = Vec::new();
    while let Some(code) = todo.pop() {
        for instr in code {
            let mut expr = |e: &Expr| {
                e.visit(&mut |x| match x {
                    Expr::Quantity(_) | Expr::Dot(_) => out.analog = true,
                    Expr::FnCall { sub, .. } => calls.push(*sub),
                    _ => {}
                })
            };
            instr.visit_exprs(&mut expr);
            match instr {
                Instr::Break { .. } => out.analog = true,
                Instr::Wait { on, until, .. } => {
                    out.waits_on.extend(on);
                    // With an empty `on`, the signals `until` reads.
                    if let Some(u) = until {
                        u.visit(&mut |x| {
                            if let Expr::Signal(s) = x {
                                out.waits_on.push(*s);
                            }
                        });
                    }
                }
                Instr::Assign { target, .. } => out.drives.push(*target),
                Instr::Call { sub, signals, .. } => {
                    calls.push(*sub);
                    // A procedure may wait on its signal parameters.
                    out.waits_on.extend(signals);
                }
                _ => {}
            }
        }
        for sub in calls.drain(..) {
            if let Some(s) = design.subprograms.get(sub.index())
                && seen.insert(sub)
            {
                todo.push(&s.code);
            }
        }
    }
    out
}

impl Coupling {
    /// The coupling of `design`'s processes; `read_by_equations(s)` tells whether an
    /// equation reads signal `s`.
    pub fn new(design: &Design, read_by_equations: impl Fn(SignalId) -> bool) -> Coupling {
        let reaches: Vec<Reach> = (design.processes.iter())
            .map(|p| reach(design, &p.code))
            .collect();
        let n = design.signals.len();
        let mut wakes: Vec<bool> = (0..n)
            .map(|s| read_by_equations(SignalId(s as u32)))
            .collect();
        let mut coupled: Vec<bool> = reaches.iter().map(|r| r.analog).collect();
        // The signals an event on a signal causes events on: its views, gathers,
        // conversions and `'transaction`, `'stable` and `'quiet` (their own drivers are
        // their parents').
        let mut sources: Vec<Vec<usize>> = vec![Vec::new(); n];
        for (k, s) in design.signals.iter().enumerate() {
            match &s.kind {
                SignalKind::View { parent, .. } => sources[k].push(parent.index()),
                SignalKind::Gather { elements } => {
                    sources[k].extend(elements.iter().map(|(p, _)| p.index()));
                }
                SignalKind::Transaction { source }
                | SignalKind::Stable { source, .. }
                | SignalKind::Converted { source, .. } => sources[k].push(source.index()),
                _ => {}
            }
        }
        loop {
            let mut changed = false;
            for (p, r) in reaches.iter().enumerate() {
                if coupled[p] {
                    for s in &r.waits_on {
                        changed |= !std::mem::replace(&mut wakes[s.index()], true);
                    }
                }
            }
            for k in (0..n).rev() {
                if wakes[k] {
                    for &p in &sources[k] {
                        changed |= !std::mem::replace(&mut wakes[p], true);
                    }
                }
            }
            for (p, r) in reaches.iter().enumerate() {
                // Assigning a view or a gather drives its parents (see `Signals::new`).
                let drives_waking = r
                    .drives
                    .iter()
                    .any(|s| wakes[s.index()] || sources[s.index()].iter().any(|&q| wakes[q]));
                if !coupled[p] && drives_waking {
                    coupled[p] = true;
                    changed = true;
                }
            }
            if !changed {
                break;
            }
        }
        Coupling { coupled, wakes }
    }

    /// Whether process `p`'s activity needs the analog solution at its time.
    pub fn is_coupled(&self, p: usize) -> bool {
        self.coupled.get(p).copied().unwrap_or(true)
    }

    /// Whether a transaction on signal `s` may need the analog solution at its time.
    pub fn wakes(&self, s: SignalId) -> bool {
        self.wakes.get(s.index()).copied().unwrap_or(true)
    }
}
