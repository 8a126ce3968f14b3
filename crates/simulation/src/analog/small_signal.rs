//! The small-signal model of an analog system (LRM 1076.1 12.6.4, the frequency domain): the
//! system linearised about its quiescent point, `(G + jw C) X = B`, with `B` from the
//! spectral source quantities.
//!
//! The linearised system is the solver's (reduced) one, as the kernel builds it: a spectral
//! source quantity is never eliminated, so its generated equation `q == 0.0` is a row of its
//! own, which becomes `q == S(f)` there (its row of `B` is `dF/dq * S`, whatever sign the
//! residual was written with). An eliminated quantity a user probes is the linearisation of
//! its formula in the survivors: `X_q = sum_j (d r/d x_j + jw d r/d x'_j) X_j`
//! ([`AnalogSystem::linear_output`]), exact as the formula's symbolic derivatives are. A design
//! with `'delayed` is analysed unreduced (`eliminate: false`): an eliminated delayed output's
//! formula would read its input as it stands at the quiescent point, without `e^{-jwT}`.
//!
//! What the frequency domain changes: `Q'dot` is `jw Q` (`C`), so `'integ` and `'ltf`, which
//! elaboration realises with derivatives, follow exactly; `Q'delayed(T)` is `e^{-jwT} Q`
//! (its history row's entry at the input turns by that factor); signals keep their quiescent
//! values (LRM: only quantities vary in a small-signal analysis), `domain` reads
//! `frequency_domain` while `G` and `C` are evaluated (the point itself is the quiescent one,
//! solved with `quiescent_domain`). `Q'zoh(T)` is `(1 - e^{-jwT}) / (jwT) Q`, the sample and
//! hold's response, and `Q'ztf(num, den, T)` is `H(e^{jwT}) Q` (LRM: the z-domain transfer on
//! the unit circle), both read through the equations' derivatives in the signals their
//! processes drive (a design with them is analysed unreduced, so that `Q` is an unknown).
//! Refused with a diagnostic: equations that read the signals of `'slew` or `S'ramp`
//! (generated processes that shape in time, whose frequency response the small-signal model
//! would get wrong).

use super::deriv::{Var, derivative};
use super::{AnalogError, AnalogSystem, Origin, Sym, delay, lower};
use vams_design::{Design, QuantityId, SignalId, SignalKind, Type};
use vams_solver::ac::{SampledTerm, SampledTransfer, SmallSignal};
use vams_solver::{DaeSystem, OpOptions, SolveError};
use vams_syntax::source::Span;

/// A spectral source's row of `B`.
struct SourceRow {
    row: usize,
    /// `dF/dq` of its row at the point.
    coefficient: f64,
    magnitude: Sym,
    phase: Sym,
}

/// A noise source's row: where its independent source enters and its density.
struct NoiseRow {
    row: usize,
    /// `dF/dq` of its row at the point.
    coefficient: f64,
    density: Sym,
    span: Span,
    name: String,
}

/// The linearised system and how to build its right side at a frequency.
pub struct SmallSignalModel {
    pub system: SmallSignal,
    sources: Vec<SourceRow>,
    noise: Vec<NoiseRow>,
    x: Vec<f64>,
    xdot: Vec<f64>,
    signals: Vec<f64>,
    frequency_slot: Option<usize>,
}

impl SmallSignalModel {
    /// The nonzero entries of `B` at `frequency` (hertz), each `(row, magnitude, phase in
    /// radians)`: the spectral sources' `mag * e^{j phase}` times their rows' coefficients
    /// (a negative coefficient turns the phase by pi).
    pub fn excitation(&mut self, frequency: f64) -> Vec<(usize, f64, f64)> {
        if let Some(slot) = self.frequency_slot {
            self.signals[slot] = frequency;
        }
        let (x, xdot, signals) = (&self.x, &self.xdot, &self.signals);
        self.sources
            .iter()
            .map(|s| {
                let magnitude = s.magnitude.eval(0.0, x, xdot, signals);
                let phase = s.phase.eval(0.0, x, xdot, signals);
                (s.row, magnitude * s.coefficient, phase)
            })
            .collect()
    }

    /// The number of spectral sources.
    pub fn source_count(&self) -> usize {
        self.sources.len()
    }

    /// Where spectral source `k` (in [`Design::spectral_sources`] order) enters: `(row,
    /// coefficient)`; a unit phasor of the source quantity is `coefficient` in `row` of `B`.
    pub fn spectral_injection(&self, k: usize) -> Option<(usize, f64)> {
        self.sources.get(k).map(|s| (s.row, s.coefficient))
    }

    /// Where each noise source (in [`Design::noise_sources`] order) enters: `(row,
    /// coefficient)`, as [`SmallSignalModel::spectral_injection`].
    pub fn noise_injections(&self) -> Vec<(usize, f64)> {
        self.noise.iter().map(|n| (n.row, n.coefficient)).collect()
    }

    /// Each noise source's power spectral density at `frequency` (hertz), in the units of its
    /// quantity squared per hertz. A density that is negative or not a number is an error
    /// naming the source: a power is never negative, and a silent NaN would poison the sum.
    pub fn noise_densities(&mut self, frequency: f64) -> Result<Vec<f64>, AnalogError> {
        if let Some(slot) = self.frequency_slot {
            self.signals[slot] = frequency;
        }
        let (x, xdot, signals) = (&self.x, &self.xdot, &self.signals);
        (self.noise.iter())
            .map(|n| {
                let value = n.density.eval(0.0, x, xdot, signals);
                if value >= 0.0 && value.is_finite() {
                    Ok(value)
                } else {
                    Err(AnalogError::NoiseDensity {
                        span: n.span,
                        name: n.name.clone(),
                        value,
                        frequency,
                    })
                }
            })
            .collect()
    }
}

/// The position of `literal` in the type of signal `s`, when it is an enumeration.
fn literal_position(design: &Design, s: SignalId, literal: &str) -> Option<f64> {
    match &design.signals[s.index()].ty {
        Type::Enum { literals, .. } => literals.iter().position(|l| l == literal).map(|p| p as f64),
        _ => None,
    }
}

impl AnalogSystem {
    /// The quiescent point as the unknowns of this system, from the quantities' values at the
    /// quiescent point the kernel found (`quantities`, by `QuantityId`) and the signals' values
    /// there: every differential quantity is held at its value (its `x'` solved, zero at an
    /// equilibrium, as the kernel's break values leave it otherwise; if that is singular,
    /// none is), the rest solved by Newton from those values (terminal potentials and implicit flows start at 0; the
    /// across definitions give them in one step). Returns `(x, x')`.
    pub fn point_from_quantities(
        &mut self,
        quantities: &[f64],
        signals: &[(SignalId, f64)],
    ) -> Result<(Vec<f64>, Vec<f64>), SolveError> {
        for &(s, v) in signals {
            self.set_signal(s, v);
        }
        let n = self.len();
        let mut guess = vec![0.0; n];
        let mut fixed = Vec::new();
        for (q, slot) in self.quantity_slot.iter().enumerate() {
            let (Some(j), Some(&v)) = (*slot, quantities.get(q)) else {
                continue;
            };
            if !v.is_finite() {
                continue;
            }
            guess[j] = v;
            if self.differential[j] {
                fixed.push((j, v));
            }
        }
        // Tight tolerances first: the response is linear in the point's errors; looser ones
        // if rounding keeps Newton from the tight ones. Holding every differential quantity
        // reproduces break values; where a held quantity's `x'` appears in no equation of the
        // quiescent branch (`if domain = quiescent_domain use y == u; else ... y'dot ...`) it
        // is singular, and the plain quiescent point (`x' = 0`, the undetermined held at
        // their values) is the one the kernel found.
        let mut attempt = |fixed: &[(usize, f64)], reltol: f64, scale: f64| {
            let abstol: Vec<f64> = self.abstol(1e-9).iter().map(|a| a * scale).collect();
            self.quiescent_point(0.0, &guess, fixed, reltol, &abstol, &OpOptions::default())
        };
        let mut result = Err(SolveError::InvalidSystem {
            reason: "no attempt",
            index: 0,
        });
        for held in [&fixed[..], &[]] {
            for (reltol, scale) in [(1e-10, 1e-4), (1e-6, 1e-2), (1e-3, 1.0)] {
                result = attempt(held, reltol, scale);
                if result.is_ok() {
                    return result;
                }
            }
        }
        result
    }

    /// The small-signal model at `(x, x')` (see the module comment). `design` must be the one
    /// this system was built from (with `eliminate: false` if it reads `'delayed`).
    pub fn small_signal(
        &mut self,
        design: &Design,
        x: &[f64],
        xdot: &[f64],
    ) -> Result<SmallSignalModel, Vec<AnalogError>> {
        let mut errors = Vec::new();
        for (i, s) in design.signals.iter().enumerate() {
            let id = SignalId(i as u32);
            if s.kind == SignalKind::Implicit
                && self.reads_signal(id)
                && design.frequency_signal != Some(id)
                && !design.sampled.iter().any(|d| d.signal == id)
            {
                errors.push(AnalogError::FrequencyDomain {
                    span: s.span,
                    what: format!("`{}`", s.name),
                    help: "'slew and S'ramp are realised by processes that act in time; in \
                           `vams ac` write the slew-limited path with equations, or analyse it \
                           with `vams run`"
                        .into(),
                });
            }
        }
        let mut sources = Vec::new();
        for source in &design.spectral_sources {
            let site = |what: &str| AnalogError::FrequencyDomain {
                span: source.span,
                what: what.into(),
                help: "this is a bug in vams: spectral sources are never eliminated".into(),
            };
            let (Some(slot), Some(row)) = (
                self.quantity_slot(source.quantity),
                self.solver_row(Origin::User(source.equation)),
            ) else {
                // `protected_unknowns` keeps every spectral source and its equation.
                errors.push(site("a spectral source quantity that was eliminated"));
                continue;
            };
            let slot_of = |q: usize| {
                self.quantity_slot(QuantityId(q as u32))
                    .unwrap_or(usize::MAX)
            };
            match (
                lower(&source.magnitude, &slot_of),
                lower(&source.phase, &slot_of),
            ) {
                (Ok(magnitude), Ok(phase)) => sources.push((row, slot, magnitude, phase)),
                (Err(e), _) | (_, Err(e)) => errors.push(AnalogError::NotAnalog {
                    span: source.span,
                    what: e.0.to_string(),
                }),
            }
        }
        let mut noise = Vec::new();
        for source in &design.noise_sources {
            let (Some(slot), Some(row)) = (
                self.quantity_slot(source.quantity),
                self.solver_row(Origin::User(source.equation)),
            ) else {
                // `protected_unknowns` keeps every noise source and its equation.
                errors.push(AnalogError::FrequencyDomain {
                    span: source.span,
                    what: "a noise source quantity that was eliminated".into(),
                    help: "this is a bug in vams: noise sources are never eliminated".into(),
                });
                continue;
            };
            let slot_of = |q: usize| {
                self.quantity_slot(QuantityId(q as u32))
                    .unwrap_or(usize::MAX)
            };
            match lower(&source.density, &slot_of) {
                Ok(density) => noise.push((row, slot, density, source)),
                Err(e) => errors.push(AnalogError::NotAnalog {
                    span: source.span,
                    what: e.0.to_string(),
                }),
            }
        }
        if !errors.is_empty() {
            return Err(errors);
        }
        if let Some(domain) = design.domain_signal()
            && let Some(position) = literal_position(design, domain, "frequency_domain")
        {
            self.set_signal(domain, position);
        }
        let mut system = SmallSignal::linearise(self, 0.0, x, xdot);
        // `Q'delayed(T)`: the history row reads the input as `e^{-jwT}` times it.
        for (k, line) in self.delay_lines.iter().enumerate() {
            let Some(row) = self.solver_row(Origin::Delayed(k)) else {
                continue;
            };
            if let Some(entry) = system
                .pattern
                .iter()
                .position(|&rc| rc == (row, line.input))
            {
                system.delays.push((entry, line.delay));
            }
        }
        // `Q'zoh(T)`, `Q'ztf(num, den, T)`: a row reading the sampled signal `S` reads
        // `H(jw) Q` in its place, `dF/dS H(jw)` at `Q`'s column (`Q` is an unknown: such
        // designs are analysed unreduced).
        for (row, signal, partial) in &self.signal_partials {
            let Some(sampled) = design.sampled.iter().find(|d| d.signal == *signal) else {
                continue;
            };
            let Some(column) = self.quantity_slot(sampled.input) else {
                return Err(vec![AnalogError::FrequencyDomain {
                    span: sampled.span,
                    what: "a sampled quantity that was eliminated".into(),
                    help: "this is a bug in vams: designs with 'zoh or 'ztf are analysed \
                           unreduced"
                        .into(),
                }]);
            };
            let coefficient = partial.eval(0.0, x, xdot, &self.signals);
            let transfer = match &sampled.filter {
                None => SampledTransfer::Hold {
                    period: sampled.period,
                },
                Some((num, den)) => SampledTransfer::Filter {
                    num: num.clone(),
                    den: den.clone(),
                    period: sampled.period,
                },
            };
            let entry = system.entry(*row, column);
            system.sampled.push(SampledTerm {
                entry,
                coefficient,
                transfer,
            });
        }
        let coefficient = |row: usize, slot: usize| {
            (system.pattern.iter())
                .position(|&rc| rc == (row, slot))
                .map_or(1.0, |k| system.g[k])
        };
        let noise = noise
            .into_iter()
            .map(|(row, slot, density, source)| NoiseRow {
                row,
                coefficient: coefficient(row, slot),
                density,
                span: source.span,
                name: design.quantities[source.quantity.index()].name.clone(),
            })
            .collect();
        let sources = sources
            .into_iter()
            .map(|(row, slot, magnitude, phase)| SourceRow {
                row,
                coefficient: coefficient(row, slot),
                magnitude,
                phase,
            })
            .collect();
        Ok(SmallSignalModel {
            system,
            sources,
            noise,
            x: x.to_vec(),
            xdot: xdot.to_vec(),
            signals: self.signals.clone(),
            frequency_slot: design.frequency_signal.map(SignalId::index),
        })
    }

    /// Quantity `q` as a linear combination of the solver's unknowns in the frequency domain,
    /// `(unknown, dq/dx, dq/dx')` (its phasor is `sum (a + jw b) X_j`), at the point `(x, x')`
    /// with the signals as [`AnalogSystem::small_signal`] left them: a survivor is itself, an
    /// eliminated quantity the derivatives of its formula. `None` for a quantity of another
    /// design, or one whose formula reads a `'delayed` history (never: such designs are
    /// analysed unreduced).
    pub fn linear_output(
        &self,
        q: QuantityId,
        x: &[f64],
        xdot: &[f64],
    ) -> Option<Vec<(usize, f64, f64)>> {
        if let Some(slot) = self.quantity_slot(q) {
            return Some(vec![(slot, 1.0, 0.0)]);
        }
        let formula = &self
            .eliminated
            .iter()
            .find(|e| e.quantity == Some(q))?
            .replacement;
        let history = delay::history_slot(self.design_signals, 0);
        if formula.any(|e| matches!(e, Sym::Signal(s) if *s >= history)) {
            return None;
        }
        let mut columns = Vec::new();
        formula.visit(&mut |e| {
            if let Sym::X(j) | Sym::Dot(j) = e {
                columns.push(*j);
            }
        });
        columns.sort_unstable();
        columns.dedup();
        let at = |d: Sym| d.eval(0.0, x, xdot, &self.signals);
        Some(
            columns
                .into_iter()
                .map(|j| {
                    let a = at(derivative(formula, Var::X(j)));
                    let b = at(derivative(formula, Var::Dot(j)));
                    (j, a, b)
                })
                .collect(),
        )
    }

    /// The solver row of the equation from `origin`.
    fn solver_row(&self, origin: Origin) -> Option<usize> {
        self.row_source
            .iter()
            .position(|&k| self.origins.get(k) == Some(&origin))
    }
}
