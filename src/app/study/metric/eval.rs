//! Evaluating a metric on one run's waveforms.
//!
//! A quantity is piecewise linear between its samples: a crossing time is interpolated
//! between the two samples around it, a window boundary between samples takes the
//! interpolated value, and means and RMS values are integrals over time (exact on each linear
//! piece), not averages of samples, so that a variable time step does not weigh the result.
//! A signal holds its value until the next sample. Two samples at the same time are a jump;
//! the value "at" that time is the one after it. Whatever cannot be evaluated is a
//! [`MetricError`], never NaN or infinity.

use miette::Diagnostic;
use thiserror::Error;

use super::curve::{Curve, integral, integral_of_square};
use super::{Band, Edge, Metric, MetricKind, Stat, Window};
use crate::app::time::format_time;
use crate::waveform::{ColumnKind, Waveforms};

/// A value for a message: 6 significant digits, so a band edge computed as 1.9 - 0.05 reads
/// 1.85, not 1.8499999999999999.
fn short(x: f64) -> String {
    let rounded: f64 = format!("{x:.5e}").parse().unwrap_or(x);
    crate::output::csv::format_number(rounded)
}

/// Why a metric has no value on a run (the sweep records it as failed for that run).
#[derive(Clone, Debug, PartialEq, Error, Diagnostic)]
pub enum MetricError {
    #[error("metric `{metric}`: no column `{column}` was recorded")]
    #[diagnostic(
        code(vams::sweep::metric_column),
        help("the recorded columns, closest first: {known}")
    )]
    UnknownColumn {
        metric: String,
        column: String,
        known: String,
    },
    #[error("metric `{metric}`: the run recorded no sample")]
    #[diagnostic(code(vams::sweep::metric_empty))]
    EmptyRun { metric: String },
    #[error("metric `{metric}`: {what} {time} is outside the run, which spans {start} to {end}")]
    #[diagnostic(
        code(vams::sweep::metric_window),
        help("move the time into the run, or lengthen the run")
    )]
    OutsideRun {
        metric: String,
        what: &'static str,
        time: String,
        start: String,
        end: String,
    },
    #[error(
        "metric `{metric}`: `{column}` crosses {} {edge} {found} time(s) in the window, \
         not {nth}", short(*value)
    )]
    #[diagnostic(code(vams::sweep::metric_cross))]
    NoCrossing {
        metric: String,
        column: String,
        value: f64,
        edge: &'static str,
        nth: usize,
        found: usize,
    },
    #[error(
        "metric `{metric}`: `{column}` is still outside the band {} to {} at the end \
         of the run", short(*low), short(*high)
    )]
    #[diagnostic(code(vams::sweep::metric_settle))]
    NeverSettles {
        metric: String,
        column: String,
        low: f64,
        high: f64,
    },
    #[error("metric `{metric}`: `{column}` makes no step after {from} (it is {} there)", short(*value))]
    #[diagnostic(
        code(vams::sweep::metric_step),
        help("a percentage band and an overshoot are relative to the step; give an absolute band")
    )]
    ZeroStep {
        metric: String,
        column: String,
        from: String,
        value: f64,
    },
    #[error("metric `{metric}`: the value is not finite (`{column}` has NaN or infinite samples)")]
    #[diagnostic(code(vams::sweep::metric_finite))]
    NotFinite { metric: String, column: String },
}

/// `metric` (any kind but the count of assertion failures) on `waves`.
pub(super) fn evaluate(metric: &Metric, waves: &Waveforms) -> Result<f64, MetricError> {
    let name = || metric.name.clone();
    // Every kind evaluated here reads a column (`Metric::evaluate` counts the reports).
    let of = metric.column().unwrap_or_default();
    let Some(column) = waves.column(of) else {
        return Err(MetricError::UnknownColumn {
            metric: name(),
            column: of.to_string(),
            known: closest(of, waves),
        });
    };
    if waves.times.is_empty() {
        return Err(MetricError::EmptyRun { metric: name() });
    }
    let signal = matches!(column.kind, ColumnKind::Signal { .. });
    let curve = Curve::new(&waves.times, &column.values, signal);
    let (start, end) = (curve.start(), curve.end());
    // A time written in the spec that lands a rounding error outside the run is its end.
    let slack = 1e-9 * start.abs().max(end.abs()).max(f64::MIN_POSITIVE);
    let inside = |what: &'static str, t: f64| {
        if t < start - slack || t > end + slack {
            Err(MetricError::OutsideRun {
                metric: name(),
                what,
                time: format_time(t),
                start: format_time(start),
                end: format_time(end),
            })
        } else {
            Ok(t.clamp(start, end))
        }
    };
    let span = |w: &Window| -> Result<(f64, f64), MetricError> {
        let a = w
            .from
            .map(|t| inside("the window's start", t))
            .transpose()?;
        let b = w.to.map(|t| inside("the window's end", t)).transpose()?;
        Ok((a.unwrap_or(start), b.unwrap_or(end)))
    };
    let zero_step = |from: f64, value: f64| MetricError::ZeroStep {
        metric: name(),
        column: of.to_string(),
        from: format_time(from),
        value,
    };
    let value = match &metric.kind {
        MetricKind::Stat { stat, window, .. } => {
            let (a, b) = span(window)?;
            statistic(*stat, &curve.window(a, b), b - a)
        }
        MetricKind::Final { .. } => curve.last(),
        MetricKind::At { time, .. } => curve.value_at(inside("the time", *time)?),
        MetricKind::Cross {
            value,
            edge,
            nth,
            window,
            ..
        } => {
            let (a, b) = span(window)?;
            let times = crossings(&curve.window(a, b), *value, *edge);
            match times.get(nth - 1) {
                Some(&t) => t,
                None => {
                    return Err(MetricError::NoCrossing {
                        metric: name(),
                        column: of.to_string(),
                        value: *value,
                        edge: match edge {
                            Edge::Rising => "rising",
                            Edge::Falling => "falling",
                            Edge::Either => "either way",
                        },
                        nth: *nth,
                        found: times.len(),
                    });
                }
            }
        }
        MetricKind::SettlingTime {
            from, band, target, ..
        } => {
            let a = from
                .map(|t| inside("`from`", t))
                .transpose()?
                .unwrap_or(start);
            let initial = curve.value_at(a);
            let reference = target.unwrap_or(curve.last());
            let half = match *band {
                Band::Absolute(x) => x,
                Band::Percent(p) => {
                    let step = (reference - initial).abs();
                    if is_zero_step(step, reference, initial) {
                        return Err(zero_step(a, initial));
                    }
                    p / 100.0 * step
                }
            };
            match settling(&curve.window(a, end), reference, half) {
                Some(t) => t - a,
                None => {
                    return Err(MetricError::NeverSettles {
                        metric: name(),
                        column: of.to_string(),
                        low: reference - half,
                        high: reference + half,
                    });
                }
            }
        }
        MetricKind::Overshoot { from, .. } => {
            let a = from
                .map(|t| inside("`from`", t))
                .transpose()?
                .unwrap_or(start);
            let initial = curve.value_at(a);
            let last = curve.last();
            let step = last - initial;
            if is_zero_step(step.abs(), last, initial) {
                return Err(zero_step(a, initial));
            }
            let pts = curve.window(a, end);
            let beyond = if step > 0.0 {
                pts.iter().map(|p| p.1 - last).fold(0.0, f64::max)
            } else {
                pts.iter().map(|p| last - p.1).fold(0.0, f64::max)
            };
            100.0 * beyond / step.abs()
        }
        MetricKind::AssertionFailures => 0.0,
    };
    if value.is_finite() {
        Ok(value)
    } else {
        Err(MetricError::NotFinite {
            metric: name(),
            column: of.to_string(),
        })
    }
}

/// How many column names an unknown-column error lists.
const LISTED: usize = 8;

/// The recorded column names, closest to `wanted` first, at most [`LISTED`] of them.
fn closest(wanted: &str, waves: &Waveforms) -> String {
    let mut known: Vec<&str> = waves.columns.iter().map(|c| c.name.as_str()).collect();
    if known.is_empty() {
        return "none".into();
    }
    known.sort_by_key(|k| strsim::levenshtein(wanted, k));
    let more = known.len().saturating_sub(LISTED);
    known.truncate(LISTED);
    let mut list = known.join(", ");
    if more > 0 {
        list += &format!(" and {more} more");
    }
    list
}

/// A step too small to divide by: zero, or rounding noise on the values.
fn is_zero_step(step: f64, a: f64, b: f64) -> bool {
    step <= 1e-12 * a.abs().max(b.abs()) || step == 0.0
}

/// `stat` of the piecewise-linear `points` spanning `width` seconds.
fn statistic(stat: Stat, points: &[(f64, f64)], width: f64) -> f64 {
    let values = points.iter().map(|p| p.1);
    let (lo, hi) = values
        .clone()
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    match stat {
        Stat::Max => hi,
        Stat::Min => lo,
        Stat::MaxAbs => values.fold(0.0, |m, v: f64| m.max(v.abs())),
        Stat::PeakToPeak => hi - lo,
        // A window of no width (a run of one instant) has the value there.
        Stat::Mean if width <= 0.0 => points[0].1,
        Stat::Rms if width <= 0.0 => points[0].1.abs(),
        Stat::Mean => integral(points) / width,
        Stat::Rms => (integral_of_square(points) / width).max(0.0).sqrt(),
    }
}

/// The times at which the piecewise-linear `points` pass `level` in direction `edge`. A
/// passage goes from strictly one side to strictly the other; its time is when the level is
/// first reached (so touching the level and going back is no crossing, and resting on it
/// counts once).
fn crossings(points: &[(f64, f64)], level: f64, edge: Edge) -> Vec<f64> {
    let mut out = Vec::new();
    // The side of the last point off the level, and when the level was reached since.
    let mut side = 0.0;
    let mut reached: Option<f64> = None;
    for (k, &(t, v)) in points.iter().enumerate() {
        let s = if v > level {
            1.0
        } else if v < level {
            -1.0
        } else {
            reached.get_or_insert(t);
            continue;
        };
        if side != 0.0 && s != side {
            let wanted = match edge {
                Edge::Rising => s > 0.0,
                Edge::Falling => s < 0.0,
                Edge::Either => true,
            };
            if wanted {
                // Without a stop on the level, the previous point is on the other side.
                out.push(reached.unwrap_or_else(|| {
                    let (t0, v0) = points[k - 1];
                    t0 + (level - v0) / (v - v0) * (t - t0)
                }));
            }
        }
        side = s;
        reached = None;
    }
    out
}

/// The time at which the piecewise-linear `points` enter `reference ± half` for good (the
/// first time when they are in it from the start); `None` when they end outside it.
fn settling(points: &[(f64, f64)], reference: f64, half: f64) -> Option<f64> {
    let outside = |v: f64| (v - reference).abs() > half;
    let Some(k) = points.iter().rposition(|p| outside(p.1)) else {
        return Some(points[0].0);
    };
    let &(t1, v1) = points.get(k + 1)?;
    let (t0, v0) = points[k];
    let edge = if v0 > reference {
        reference + half
    } else {
        reference - half
    };
    Some(if t1 > t0 {
        t0 + (edge - v0) / (v1 - v0) * (t1 - t0)
    } else {
        t1
    })
}
