//! The `[metrics]` table of a sweep spec as written, and its validation into [`Metric`]s.
//!
//! Every value keeps its byte span in the TOML text (`toml::Spanned`), so that a
//! [`MetricSpecError`] points at the exact value to fix (a window that ends before it starts,
//! `nth = 0`, an unknown kind). Syntax errors (an unknown key, a string where a number goes)
//! are serde's, with toml's own spans.

use std::fmt;
use std::ops::Range;

use miette::Diagnostic;
use serde::Deserialize;
use serde::de::{self, Deserializer, MapAccess, Visitor};
use thiserror::Error;
use toml::Spanned;

use super::{Band, Edge, Limit, Metric, MetricKind, Stat, Window};
use crate::app::time::{TIME_FORMS, format_time, parse_time};

/// The `[metrics]` table: metric names and their inline tables, in the order written.
#[derive(Clone, Debug, Default)]
pub struct MetricTable(pub Vec<(Spanned<String>, Spanned<MetricSpec>)>);

/// One metric's inline table, e.g.
/// `{ kind = "max", of = "dut.i_motor", from = "0 s", to = "6 s", max = 2.0 }`.
/// Which keys a kind takes is checked by [`MetricSpec::validate`].
#[derive(Clone, Debug, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MetricSpec {
    pub kind: Spanned<String>,
    pub of: Option<Spanned<String>>,
    pub from: Option<Spanned<NumberOrText>>,
    pub to: Option<Spanned<NumberOrText>>,
    pub time: Option<Spanned<NumberOrText>>,
    pub band: Option<Spanned<NumberOrText>>,
    pub target: Option<Spanned<f64>>,
    pub value: Option<Spanned<f64>>,
    pub edge: Option<Spanned<String>>,
    pub nth: Option<Spanned<i64>>,
    pub min: Option<Spanned<NumberOrText>>,
    pub max: Option<Spanned<NumberOrText>>,
}

/// A value written as a number or as a string: a time (`"3 s"`, or seconds), a band
/// (`"2%"`, or absolute), a limit (a time string for time-valued metrics).
#[derive(Clone, Debug, PartialEq)]
pub enum NumberOrText {
    Number(f64),
    Text(String),
}

/// A metric's table that does not make sense, with the span of the value at fault.
#[derive(Clone, Debug, PartialEq, Error, Diagnostic)]
#[error("metric `{metric}`: {message}")]
#[diagnostic(code(vams::sweep::metric))]
pub struct MetricSpecError {
    /// The metric's name.
    pub metric: String,
    /// What is wrong.
    pub message: String,
    /// How to fix it.
    #[help]
    pub help: String,
    /// Byte range of the offending value (or of the whole table for a missing key) in the
    /// TOML text.
    #[label("here")]
    pub span: Range<usize>,
}

/// The kinds, for error messages.
pub const KINDS: [&str; 12] = [
    "max",
    "min",
    "max_abs",
    "mean",
    "rms",
    "peak_to_peak",
    "final",
    "at",
    "cross",
    "settling_time",
    "overshoot",
    "assertion_failures",
];

/// The keys each kind takes besides `kind`, `min` and `max`.
fn keys_of(kind: &str) -> &'static [&'static str] {
    match kind {
        "final" => &["of"],
        "overshoot" => &["of", "from"],
        "at" => &["of", "time"],
        "cross" => &["of", "value", "edge", "nth", "from", "to"],
        "settling_time" => &["of", "band", "from", "target"],
        "assertion_failures" => &[],
        _ => &["of", "from", "to"],
    }
}

/// The keys a kind cannot do without.
fn required(kind: &str) -> &'static [&'static str] {
    match kind {
        "at" => &["of", "time"],
        "cross" => &["of", "value"],
        "assertion_failures" => &[],
        _ => &["of"],
    }
}

impl MetricTable {
    /// Validates every metric, in order; all the errors when some do not make sense.
    pub fn validate(&self) -> Result<Vec<Metric>, Vec<MetricSpecError>> {
        let (mut metrics, mut errors) = (Vec::new(), Vec::new());
        for (name, spec) in &self.0 {
            match spec.get_ref().validate(name.get_ref(), spec.span()) {
                Ok(m) => metrics.push(m),
                Err(e) => errors.push(e),
            }
        }
        if errors.is_empty() {
            Ok(metrics)
        } else {
            Err(errors)
        }
    }
}

impl MetricSpec {
    /// The metric `name` this table describes; `span` is the table's, for missing keys.
    pub fn validate(&self, name: &str, span: Range<usize>) -> Result<Metric, MetricSpecError> {
        let fail = |message: String, help: String, span: Range<usize>| MetricSpecError {
            metric: name.to_string(),
            message,
            help,
            span,
        };
        let kind = self.kind.get_ref().as_str();
        if !KINDS.contains(&kind) {
            let mut kinds = KINDS.to_vec();
            kinds.sort_by_key(|k| strsim::levenshtein(kind, k));
            return Err(fail(
                format!("unknown kind `{kind}`"),
                format!("the kinds are {}", kinds.join(", ")),
                self.kind.span(),
            ));
        }
        let allowed = keys_of(kind);
        for (key, span) in self.present() {
            if key != "min" && key != "max" && !allowed.contains(&key) {
                let keys: Vec<&str> = allowed.iter().copied().chain(["min", "max"]).collect();
                return Err(fail(
                    format!("`{key}` does not apply to a `{kind}` metric"),
                    format!("a `{kind}` metric takes {}", keys.join(", ")),
                    span,
                ));
            }
        }
        for key in required(kind) {
            if !self.present().iter().any(|(k, _)| k == key) {
                return Err(fail(
                    format!("a `{kind}` metric needs `{key}`"),
                    format!("add `{key} = ...`: {}", example(key)),
                    span.clone(),
                ));
            }
        }
        // From here on, the required keys are present: a default below is never used.
        let of = self.of.as_ref().map(|o| o.get_ref().clone());
        let of = || of.clone().unwrap_or_default();
        let time = |v: &Option<Spanned<NumberOrText>>| -> Result<Option<f64>, MetricSpecError> {
            let Some(v) = v else { return Ok(None) };
            time_of(v).map(Some).map_err(|(m, h)| fail(m, h, v.span()))
        };
        let (from, to) = (time(&self.from)?, time(&self.to)?);
        if let (Some(a), Some(b), Some(f)) = (from, to, &self.from)
            && a >= b
        {
            return Err(fail(
                format!(
                    "the window starts at {}, not before it ends at {}",
                    format_time(a),
                    format_time(b)
                ),
                "give `from` before `to`".into(),
                f.span(),
            ));
        }
        let window = Window { from, to };
        let finite = |v: &Spanned<f64>, what: &str| {
            if v.get_ref().is_finite() {
                Ok(*v.get_ref())
            } else {
                Err(fail(
                    format!("`{what}` must be a finite number"),
                    format!("give `{what}` in the column's unit"),
                    v.span(),
                ))
            }
        };
        let kind = match kind {
            "final" => MetricKind::Final { of: of() },
            "at" => MetricKind::At {
                of: of(),
                time: time(&self.time)?.unwrap_or_default(),
            },
            "cross" => MetricKind::Cross {
                of: of(),
                value: self
                    .value
                    .as_ref()
                    .map(|v| finite(v, "value"))
                    .transpose()?
                    .unwrap_or_default(),
                edge: match &self.edge {
                    None => Edge::Either,
                    Some(e) => match e.get_ref().as_str() {
                        "rising" => Edge::Rising,
                        "falling" => Edge::Falling,
                        "either" => Edge::Either,
                        other => {
                            return Err(fail(
                                format!("unknown edge `{other}`"),
                                "the edges are rising, falling and either (the default)".into(),
                                e.span(),
                            ));
                        }
                    },
                },
                nth: match &self.nth {
                    None => 1,
                    Some(n) => match usize::try_from(*n.get_ref()) {
                        Ok(k) if k >= 1 => k,
                        _ => {
                            return Err(fail(
                                format!("`nth = {}` counts no crossing", n.get_ref()),
                                "crossings are counted from 1 (the first)".into(),
                                n.span(),
                            ));
                        }
                    },
                },
                window,
            },
            "settling_time" => MetricKind::SettlingTime {
                of: of(),
                from,
                band: match &self.band {
                    Some(b) => band_of(b).map_err(|(m, h)| fail(m, h, b.span()))?,
                    // The common engineering default, as a percentage of the step.
                    None => Band::Percent(2.0),
                },
                target: self
                    .target
                    .as_ref()
                    .map(|v| finite(v, "target"))
                    .transpose()?,
            },
            "overshoot" => MetricKind::Overshoot { of: of(), from },
            "assertion_failures" => MetricKind::AssertionFailures,
            stat => MetricKind::Stat {
                stat: match stat {
                    "max" => Stat::Max,
                    "min" => Stat::Min,
                    "max_abs" => Stat::MaxAbs,
                    "mean" => Stat::Mean,
                    "rms" => Stat::Rms,
                    _ => Stat::PeakToPeak,
                },
                of: of(),
                window,
            },
        };
        let limit_of = |v: &Option<Spanned<NumberOrText>>| -> Result<Option<f64>, MetricSpecError> {
            let Some(v) = v else { return Ok(None) };
            match v.get_ref() {
                NumberOrText::Number(x) if x.is_finite() => Ok(Some(*x)),
                NumberOrText::Number(_) => Err(fail(
                    "a limit must be a finite number".into(),
                    "leave the limit out for none".into(),
                    v.span(),
                )),
                NumberOrText::Text(t) if kind.is_time_valued() => parse_time(t)
                    .map(Some)
                    .map_err(|e| fail(e, format!("a time is {TIME_FORMS}"), v.span())),
                NumberOrText::Text(t) => Err(fail(
                    format!("`\"{t}\"` is text, but this metric's value is not a time"),
                    "give the limit as a number in the metric's unit".into(),
                    v.span(),
                )),
            }
        };
        let limit = Limit {
            min: limit_of(&self.min)?,
            max: limit_of(&self.max)?,
        };
        if let (Some(lo), Some(hi), Some(m)) = (limit.min, limit.max, &self.min)
            && lo > hi
        {
            return Err(fail(
                format!("the limits are empty: min = {lo} is above max = {hi}"),
                "give `min` at most `max`".into(),
                m.span(),
            ));
        }
        Ok(Metric {
            name: name.to_string(),
            kind,
            limit,
        })
    }

    /// The keys written besides `kind`, with their spans.
    fn present(&self) -> Vec<(&'static str, Range<usize>)> {
        let mut keys = Vec::new();
        let mut add = |key, span: Option<Range<usize>>| {
            if let Some(s) = span {
                keys.push((key, s));
            }
        };
        add("of", self.of.as_ref().map(Spanned::span));
        add("from", self.from.as_ref().map(Spanned::span));
        add("to", self.to.as_ref().map(Spanned::span));
        add("time", self.time.as_ref().map(Spanned::span));
        add("band", self.band.as_ref().map(Spanned::span));
        add("target", self.target.as_ref().map(Spanned::span));
        add("value", self.value.as_ref().map(Spanned::span));
        add("edge", self.edge.as_ref().map(Spanned::span));
        add("nth", self.nth.as_ref().map(Spanned::span));
        add("min", self.min.as_ref().map(Spanned::span));
        add("max", self.max.as_ref().map(Spanned::span));
        keys
    }
}

/// An example of a required key, for help lines.
fn example(key: &str) -> &'static str {
    match key {
        "of" => "the column it reads, e.g. `of = \"dut.i_motor\"`",
        "time" => "e.g. `time = \"2.9 s\"`",
        "value" => "the level crossed, e.g. `value = 2.5`",
        _ => "see the metric kinds in the documentation",
    }
}

/// A time in seconds: a non-negative number, or a string with a unit.
fn time_of(v: &Spanned<NumberOrText>) -> Result<f64, (String, String)> {
    match v.get_ref() {
        NumberOrText::Number(x) if x.is_finite() && *x >= 0.0 => Ok(*x),
        NumberOrText::Number(x) => Err((
            format!("`{x}` is not a time: it must be finite and not negative"),
            format!("a time is {TIME_FORMS}"),
        )),
        NumberOrText::Text(t) => parse_time(t).map_err(|e| (e, format!("a time is {TIME_FORMS}"))),
    }
}

/// A settling band: a non-negative number (absolute) or a percentage string (`"2%"`).
fn band_of(v: &Spanned<NumberOrText>) -> Result<Band, (String, String)> {
    const HELP: &str = "give an absolute band in the column's unit (`band = 0.05`) or a \
                        percentage of the step (`band = \"2%\"`)";
    let (x, band): (Option<f64>, fn(f64) -> Band) = match v.get_ref() {
        NumberOrText::Number(x) => (Some(*x), Band::Absolute),
        NumberOrText::Text(t) => (
            t.trim()
                .strip_suffix('%')
                .and_then(|n| n.trim().parse::<f64>().ok()),
            Band::Percent,
        ),
    };
    match x {
        Some(x) if x.is_finite() && x >= 0.0 => Ok(band(x)),
        Some(x) => Err((
            format!("the band `{x}` is negative or not finite"),
            HELP.into(),
        )),
        None => Err((
            "the band is not a number or a percentage".into(),
            HELP.into(),
        )),
    }
}

impl<'de> Deserialize<'de> for NumberOrText {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl Visitor<'_> for V {
            type Value = NumberOrText;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a number or a string such as \"3 s\" or \"2%\"")
            }
            fn visit_f64<E: de::Error>(self, v: f64) -> Result<NumberOrText, E> {
                Ok(NumberOrText::Number(v))
            }
            fn visit_i64<E: de::Error>(self, v: i64) -> Result<NumberOrText, E> {
                Ok(NumberOrText::Number(v as f64))
            }
            fn visit_u64<E: de::Error>(self, v: u64) -> Result<NumberOrText, E> {
                Ok(NumberOrText::Number(v as f64))
            }
            fn visit_str<E: de::Error>(self, v: &str) -> Result<NumberOrText, E> {
                Ok(NumberOrText::Text(v.to_string()))
            }
        }
        d.deserialize_any(V)
    }
}

impl<'de> Deserialize<'de> for MetricTable {
    fn deserialize<D: Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        struct V;
        impl<'de> Visitor<'de> for V {
            type Value = MetricTable;
            fn expecting(&self, f: &mut fmt::Formatter) -> fmt::Result {
                f.write_str("a table of metrics, each an inline table with a `kind`")
            }
            fn visit_map<A: MapAccess<'de>>(self, mut map: A) -> Result<MetricTable, A::Error> {
                let mut entries = Vec::new();
                while let Some(entry) = map.next_entry()? {
                    entries.push(entry);
                }
                // toml hands keys over sorted; the tables' spans give the written order back.
                entries.sort_by_key(|(_, spec): &(Spanned<String>, Spanned<MetricSpec>)| {
                    spec.span().start
                });
                Ok(MetricTable(entries))
            }
        }
        d.deserialize_map(V)
    }
}

/// Parses the `[metrics]` table of a spec written in TOML, for the tests.
#[cfg(test)]
pub(super) fn parse_metrics(text: &str) -> Result<Vec<Metric>, Vec<MetricSpecError>> {
    #[derive(Deserialize)]
    struct Spec {
        metrics: MetricTable,
    }
    let spec: Spec = toml::from_str(text).map_err(|e| {
        vec![MetricSpecError {
            metric: String::new(),
            message: e.message().to_string(),
            help: String::new(),
            span: e.span().unwrap_or_default(),
        }]
    })?;
    spec.metrics.validate()
}
