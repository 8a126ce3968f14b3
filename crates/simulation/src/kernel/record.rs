//! Probes and output rows: which quantities and signals are recorded, one row per time point,
//! handed to a [`WaveformSink`] as each point is accepted (nothing is kept here but the row
//! being built and the last time).

use crate::waveform::{Column, ColumnKind, Header, WaveformSink};
use vams_design::{Design, QuantityId, SignalId, SignalKind, Type};

use super::error::SimError;
use super::signals::SignalState;

#[derive(Clone, Copy, Debug)]
enum Probe {
    Quantity(QuantityId),
    Signal(SignalId),
}

pub(crate) struct Recorder<'s> {
    probes: Vec<Probe>,
    sink: &'s mut dyn WaveformSink,
    /// The row being handed over, reused.
    row: Vec<f64>,
    last: Option<f64>,
    /// False when the sink drops every row ([`WaveformSink::wants_rows`]).
    wanted: bool,
}

impl<'s> Recorder<'s> {
    /// Resolves `names` and tells `sink` the columns; without names, every quantity except
    /// auxiliary quantities (names with a `'`), and every explicit scalar signal.
    pub fn new(
        design: &Design,
        names: &[String],
        stop: f64,
        sink: &'s mut dyn WaveformSink,
    ) -> Result<Recorder<'s>, SimError> {
        let probes = if names.is_empty() {
            default_probes(design)
        } else {
            names
                .iter()
                .map(|n| find(design, n))
                .collect::<Result<_, _>>()?
        };
        let columns = probes
            .iter()
            .map(|p| match *p {
                Probe::Quantity(q) => {
                    let q = &design.quantities[q.index()];
                    Column {
                        name: q.name.clone(),
                        kind: ColumnKind::Quantity {
                            unit: q.unit.as_deref().map(String::from),
                        },
                        values: Vec::new(),
                    }
                }
                Probe::Signal(s) => {
                    let s = &design.signals[s.index()];
                    Column {
                        name: s.name.clone(),
                        kind: ColumnKind::Signal { ty: s.ty.clone() },
                        values: Vec::new(),
                    }
                }
            })
            .collect();
        sink.start(&Header { columns, stop })
            .map_err(output_error)?;
        Ok(Recorder {
            wanted: sink.wants_rows(),
            row: Vec::with_capacity(probes.len()),
            probes,
            sink,
            last: None,
        })
    }

    /// Hands a row to the sink; `quantities` by `QuantityId`.
    pub fn record(
        &mut self,
        t: f64,
        quantities: &[f64],
        signals: &[SignalState],
    ) -> Result<(), SimError> {
        self.last = Some(t);
        if !self.wanted {
            return Ok(());
        }
        self.row.clear();
        self.row.extend(self.probes.iter().map(|p| match *p {
            Probe::Quantity(q) => quantities[q.index()],
            Probe::Signal(s) => signals[s.index()].value.as_f64().unwrap_or(f64::NAN),
        }));
        self.sink.row(t, &self.row).map_err(output_error)
    }

    /// The recorded quantities.
    pub fn quantities(&self) -> impl Iterator<Item = QuantityId> + '_ {
        self.probes.iter().filter_map(|p| match *p {
            Probe::Quantity(q) => Some(q),
            Probe::Signal(_) => None,
        })
    }

    /// False when the sink drops every row: what only the rows would show need not be
    /// computed.
    pub fn wanted(&self) -> bool {
        self.wanted
    }

    /// Time of the last row.
    pub fn last_time(&self) -> Option<f64> {
        self.last
    }
}

fn output_error(e: crate::waveform::SinkError) -> SimError {
    SimError::Output { message: e.0 }
}

fn default_probes(design: &Design) -> Vec<Probe> {
    // `std.standard.domain` is the simulator's own phase, not the model's.
    let domain = design.domain_signal();
    let quantities = design
        .quantities
        .iter()
        .enumerate()
        .filter(|(_, q)| !q.name.contains('\''))
        .map(|(i, _)| Probe::Quantity(QuantityId(i as u32)));
    let signals = design
        .signals
        .iter()
        .enumerate()
        .filter(|(_, s)| {
            s.kind == SignalKind::Explicit
                && !matches!(
                    s.ty,
                    Type::String | Type::Array { .. } | Type::Record { .. }
                )
        })
        .map(|(i, _)| SignalId(i as u32))
        .filter(|&s| Some(s) != domain)
        .map(Probe::Signal);
    quantities.chain(signals).collect()
}

fn find(design: &Design, name: &str) -> Result<Probe, SimError> {
    let wanted = name.to_lowercase();
    if let Some(q) = design.quantities.iter().position(|q| q.name == wanted) {
        return Ok(Probe::Quantity(QuantityId(q as u32)));
    }
    if let Some(s) = design.signals.iter().position(|s| s.name == wanted) {
        return Ok(Probe::Signal(SignalId(s as u32)));
    }
    let names = design
        .quantities
        .iter()
        .map(|q| q.name.as_str())
        .chain(design.signals.iter().map(|s| s.name.as_str()));
    let best = names
        .map(|n| (strsim::levenshtein(&wanted, n), n))
        .min_by_key(|&(d, _)| d);
    let help = match best {
        Some((d, n)) if d <= wanted.len().max(3) / 2 + 1 => format!("did you mean `{n}`?"),
        _ => "probe names are hierarchical and lower case, e.g. `dut.u_motor.i`; \
              run without --probe to record everything"
            .to_string(),
    };
    Err(SimError::UnknownProbe {
        name: name.to_string(),
        help,
    })
}
