//! Metrics of a sweep's runs, like SPICE's `.measure`: each turns one run's waveforms and
//! reports into one number (a peak, a mean, a crossing time, a settling time, a count of
//! failed assertions), checked against optional limits.
//!
//! Takes the `[metrics]` table of a sweep spec ([`spec`]: serde types with the byte spans of
//! every value, validated into [`Metric`]s with errors that point at the offending value) and,
//! per run, [`Waveforms`] and [`Report`]s ([`eval`]). Gives a finite number or a
//! [`MetricError`] saying why there is none; never NaN or infinity, so a sweep can record a
//! metric that cannot be evaluated as failed for that run. Never runs a simulation.
//!
//! Quantities are piecewise linear between samples, signals piecewise constant ([`curve`]).

mod curve;
pub mod eval;
pub mod spec;

#[cfg(test)]
mod tests;

pub use eval::MetricError;
pub use spec::{MetricSpec, MetricSpecError, MetricTable};

use crate::kernel::{Report, Severity};
use crate::waveform::{ColumnKind, Waveforms};

/// One validated metric.
#[derive(Clone, Debug, PartialEq)]
pub struct Metric {
    /// Its key in the `[metrics]` table.
    pub name: String,
    pub kind: MetricKind,
    pub limit: Limit,
}

/// What a metric computes.
#[derive(Clone, Debug, PartialEq)]
pub enum MetricKind {
    /// A statistic of column `of` over a window.
    Stat {
        stat: Stat,
        of: String,
        window: Window,
    },
    /// The last sample of `of`.
    Final { of: String },
    /// The value of `of` at `time` seconds.
    At { of: String, time: f64 },
    /// The time (seconds) of the `nth` crossing of `value` by `of` on `edge`, in a window.
    Cross {
        of: String,
        value: f64,
        edge: Edge,
        nth: usize,
        window: Window,
    },
    /// The time from `from` until `of` enters the band around its final value (or `target`)
    /// for good.
    SettlingTime {
        of: String,
        from: Option<f64>,
        band: Band,
        target: Option<f64>,
    },
    /// The peak of `of` beyond its final value in the direction of the step from `from`, in
    /// percent of the step.
    Overshoot { of: String, from: Option<f64> },
    /// The number of reports of severity error or failure.
    AssertionFailures,
}

/// The statistics over a window.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Stat {
    Max,
    Min,
    MaxAbs,
    Mean,
    Rms,
    PeakToPeak,
}

/// A time window in seconds; `None` is the start (or the end) of the run.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Window {
    pub from: Option<f64>,
    pub to: Option<f64>,
}

/// The direction of a crossing.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Edge {
    Rising,
    Falling,
    Either,
}

/// The half-width of a settling band.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Band {
    /// In the column's unit.
    Absolute(f64),
    /// In percent of the step: |final (or target) - value at `from`|.
    Percent(f64),
}

/// Pass/fail limits, inclusive.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Limit {
    pub min: Option<f64>,
    pub max: Option<f64>,
}

impl Metric {
    /// The column names it reads, so that a sweep can record only those.
    pub fn probes(&self) -> Vec<String> {
        match self.column() {
            Some(of) => vec![of.to_string()],
            None => Vec::new(),
        }
    }

    /// The column it reads, if any.
    pub fn column(&self) -> Option<&str> {
        match &self.kind {
            MetricKind::Stat { of, .. }
            | MetricKind::Final { of }
            | MetricKind::At { of, .. }
            | MetricKind::Cross { of, .. }
            | MetricKind::SettlingTime { of, .. }
            | MetricKind::Overshoot { of, .. } => Some(of),
            MetricKind::AssertionFailures => None,
        }
    }

    /// True when its value is a time in seconds (a crossing or a settling time), so that its
    /// limits may be written as times.
    pub fn is_time_valued(&self) -> bool {
        self.kind.is_time_valued()
    }

    /// Pass (`Some(true)`) or fail against its limits, `None` when it has none.
    pub fn check(&self, value: f64) -> Option<bool> {
        let Limit { min, max } = self.limit;
        if min.is_none() && max.is_none() {
            return None;
        }
        Some(min.is_none_or(|m| value >= m) && max.is_none_or(|m| value <= m))
    }

    /// The unit of its values for labels: `s` for times, `%` for an overshoot, the column's
    /// unit for quantities, none for counts and signals.
    pub fn unit_hint(&self, waves: &Waveforms) -> Option<String> {
        match &self.kind {
            k if k.is_time_valued() => Some("s".into()),
            MetricKind::Overshoot { .. } => Some("%".into()),
            MetricKind::AssertionFailures => None,
            _ => {
                let column = waves.column(self.column()?)?;
                match &column.kind {
                    ColumnKind::Quantity { unit } => unit.clone(),
                    ColumnKind::Signal { .. } => None,
                }
            }
        }
    }

    /// Its value on one run: see [`eval`].
    pub fn evaluate(&self, waves: &Waveforms, reports: &[Report]) -> Result<f64, MetricError> {
        if let MetricKind::AssertionFailures = self.kind {
            let failures = reports
                .iter()
                .filter(|r| matches!(r.severity, Severity::Error | Severity::Failure))
                .count();
            return Ok(failures as f64);
        }
        eval::evaluate(self, waves)
    }
}

impl MetricKind {
    fn is_time_valued(&self) -> bool {
        matches!(
            self,
            MetricKind::Cross { .. } | MetricKind::SettlingTime { .. }
        )
    }
}
