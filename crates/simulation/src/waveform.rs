//! Recorded waveforms: what a simulation gives and what the writers (CSV, VCD, plots) take.
//!
//! The kernel records into a [`WaveformSink`]: told the columns once ([`WaveformSink::start`]),
//! then one row per accepted time point, as the run goes. [`Waveforms`] is the sink that keeps
//! everything in memory (`vams test`, `vams extract`, the tests, library users);
//! `output::stream` writes the files of `vams run` as the rows come, in memory that does not
//! grow with the run.
//!
//! **Invariant:** every column has exactly `times.len()` values; times are non-decreasing
//! (equal times appear when a discontinuity is recorded as a before/after pair).

use vams_design::Type;

/// Where a run's rows go, one way: the kernel calls [`start`](Self::start) once, then
/// [`row`](Self::row) for every accepted time point, in time order. Ending (closing files,
/// marking a partial run) is the owner's business once the run has returned.
pub trait WaveformSink {
    /// The recorded columns (their `values` empty) and the run's stop time, before any row.
    fn start(&mut self, header: &Header) -> Result<(), SinkError>;
    /// One row: `values[c]` for column `c`. An error stops the run.
    fn row(&mut self, time: f64, values: &[f64]) -> Result<(), SinkError>;
    /// False when the sink would drop every row (`vams run` without an output file or a
    /// plot): the kernel then builds none. Asked once, after [`WaveformSink::start`].
    fn wants_rows(&self) -> bool {
        true
    }
}

/// What a sink learns before the first row.
#[derive(Clone, Debug)]
pub struct Header {
    /// The probes in column order, without values.
    pub columns: Vec<Column>,
    /// The run's stop time in seconds (no row comes later).
    pub stop: f64,
}

/// A sink that cannot take more rows (a full disk, a plot layout naming no column); the sink
/// keeps the details for its owner, the kernel only stops.
#[derive(Clone, Debug, PartialEq, thiserror::Error)]
#[error("{0}")]
pub struct SinkError(pub String);

/// The in-memory sink: the whole run, as [`Waveforms`].
impl WaveformSink for Waveforms {
    fn start(&mut self, header: &Header) -> Result<(), SinkError> {
        self.times.clear();
        self.columns = header.columns.clone();
        Ok(())
    }

    fn row(&mut self, time: f64, values: &[f64]) -> Result<(), SinkError> {
        self.times.push(time);
        for (column, &v) in self.columns.iter_mut().zip(values) {
            column.values.push(v);
        }
        Ok(())
    }
}

/// Sampled results of one run, one row per accepted time point.
#[derive(Clone, Debug, Default)]
pub struct Waveforms {
    pub times: Vec<f64>,
    pub columns: Vec<Column>,
}

/// One probed quantity or signal.
#[derive(Clone, Debug)]
pub struct Column {
    /// Hierarchical name relative to the top (`vref`, `dut.u_motor.i`).
    pub name: String,
    pub kind: ColumnKind,
    /// One value per time point; signals as numbers ([`vams_design::Value::as_f64`]).
    pub values: Vec<f64>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ColumnKind {
    /// An analog quantity with its unit symbol, if known.
    Quantity { unit: Option<String> },
    /// A signal of the given type (boolean and enumeration values are positions).
    Signal { ty: Type },
}

impl Waveforms {
    /// The column with the given name.
    pub fn column(&self, name: &str) -> Option<&Column> {
        self.columns.iter().find(|c| c.name == name)
    }

    /// Linear interpolation of column `name` at time `t` (the last sample at or before `t` for
    /// signals); `None` for an unknown name or an empty record.
    pub fn value_at(&self, name: &str, t: f64) -> Option<f64> {
        let col = self.column(name)?;
        let n = self.times.partition_point(|&x| x <= t);
        if n == 0 {
            return col.values.first().copied();
        }
        let i = n - 1;
        if i + 1 >= self.times.len() || matches!(col.kind, ColumnKind::Signal { .. }) {
            return Some(col.values[i]);
        }
        let (t0, t1) = (self.times[i], self.times[i + 1]);
        if t1 <= t0 {
            return Some(col.values[i]);
        }
        let w = (t - t0) / (t1 - t0);
        Some(col.values[i] + w * (col.values[i + 1] - col.values[i]))
    }
}
