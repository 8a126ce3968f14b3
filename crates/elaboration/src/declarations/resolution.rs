//! Resolution functions of signals: once every process is elaborated, each signal of a
//! subtype with a user-defined resolution function (`subtype wired_or_bit is wired_or bit;`)
//! gets the function lowered once per number of values it can be called with, from 0 (a
//! `bus` whose drivers are all disconnected) to the signal's number of drivers. A body is
//! lowered with the bounds of its unconstrained array parameter, as any call's.

use std::collections::HashSet;

use vams_design::{Design, Resolution, SignalId, SignalKind};

use crate::Elab;
use crate::error::ElabError;
use crate::names::types::Ty;

impl<'a> Elab<'a> {
    pub(crate) fn resolve_signals(&mut self) {
        if self.signals.resolved.is_empty() {
            return;
        }
        let counts = driver_counts(&self.design);
        for (signal, r) in std::mem::take(&mut self.signals.resolved) {
            let f = self.signals.resolvers[r].clone();
            let span = self.design.signals[signal.index()].span;
            let low = match (f.params.as_slice(), &f.ret) {
                ([p], Some(_)) if !p.is_signal => match &p.ty {
                    Ty::Array(a) if a.bounds.is_none() => Some(a.index_low),
                    _ => None,
                },
                _ => None,
            };
            let Some(low) = low else {
                self.error(ElabError::invalid(
                    span,
                    format!(
                        "`{}` is not a resolution function: it must take one unconstrained array of the values to resolve and return one value",
                        f.name
                    ),
                    Some("declare `function f (drivers : t_vector) return t;` with `type t_vector is array (natural range <>) of t;`".into()),
                ));
                continue;
            };
            let mut by_count = Vec::new();
            for n in 0..=counts[signal.index()] {
                let bounds = (low, low + n as i64 - 1, true);
                match self.instance(&f, &[], &[Some(bounds)], &[], &[], span) {
                    Ok(id) => by_count.push(id),
                    Err(_) => return,
                }
            }
            self.design.signals[signal.index()].resolution = Some(Resolution {
                name: f.name.clone(),
                by_count,
            });
        }
    }
}

/// The number of processes that drive each signal (a view's drivers counted for the signal
/// it shows part of), directly or in the procedures they call: each has one driver for it.
fn driver_counts(design: &Design) -> Vec<usize> {
    let mut counts = vec![0; design.signals.len()];
    let root = |s: SignalId| match design.signals[s.index()].kind {
        SignalKind::View { parent, .. } => parent,
        _ => s,
    };
    for p in &design.processes {
        let driven: HashSet<SignalId> = design
            .assignments(&p.code)
            .into_iter()
            .map(|(target, _)| root(target))
            .collect();
        for s in driven {
            counts[s.index()] += 1;
        }
    }
    counts
}
