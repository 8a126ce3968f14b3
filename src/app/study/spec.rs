//! The sweep spec: a TOML file naming the design (`[design]`), one plan (`[grid]`,
//! `[corners]`, `[monte_carlo]` or `[sensitivity]`, each with its `parameters`), the metrics
//! (`[metrics]`) and the plots (`[plots]`). Parsed and checked here, every error a
//! diagnostic pointing at its line of the file; the plan becomes a [`Plan`].

use std::path::{Path, PathBuf};
use std::sync::Arc;

use indexmap::IndexMap;
use miette::{Diagnostic, NamedSource, SourceSpan};
use serde::Deserialize;
use thiserror::Error;
use toml::Spanned;

use super::metric::{Metric, MetricTable};
use super::plan::{Corner, CornerSet, Level, ParamValue, Plan, tidy};
use super::sample::{Distribution, Sampler, SamplerError, Sampling};
use crate::app::params::is_generic_path;
use crate::app::time::parse_positive_time;

/// A checked spec.
#[derive(Debug)]
pub struct Spec {
    pub path: PathBuf,
    pub source: Arc<NamedSource<String>>,
    /// Tells the spec's text from another's: a sweep resumed or collected under a changed
    /// spec is refused.
    pub fingerprint: u64,
    pub design: DesignSpec,
    pub plan: Plan,
    /// Where the plan section and each parameter are written (for errors found later:
    /// a parameter the design lacks, a plan too large).
    pub plan_span: SourceSpan,
    pub parameter_spans: Vec<SourceSpan>,
    pub metrics: Vec<Metric>,
    /// Where each metric is written.
    pub metric_spans: Vec<SourceSpan>,
    /// The waveforms drawn as a band over all runs.
    pub envelope: Vec<String>,
    pub envelope_spans: Vec<SourceSpan>,
    /// The plots' file extension: `svg` (default) or `png`.
    pub plot_format: &'static str,
}

/// The design and the simulator's settings, for every run.
#[derive(Debug)]
pub struct DesignSpec {
    /// Sources, relative to the spec's folder already resolved.
    pub files: Vec<PathBuf>,
    pub libraries: Vec<(String, PathBuf)>,
    pub top: Option<String>,
    pub stop: Option<f64>,
    pub reltol: f64,
    pub abstol: Option<f64>,
    pub max_step: Option<f64>,
    /// Generics set alike in every run.
    pub generics: Vec<(String, String)>,
}

/// A problem with the spec, at its place in the file.
#[derive(Debug, Error, Diagnostic)]
#[error("{path}:{line}: {message}")]
#[diagnostic(code(vams::sweep::spec))]
pub struct SpecError {
    pub path: String,
    pub line: usize,
    pub message: String,
    #[help]
    pub help: Option<String>,
    #[source_code]
    pub src: Arc<NamedSource<String>>,
    #[label("here")]
    pub span: SourceSpan,
}

/// A spec file that cannot be read.
#[derive(Debug, Error, Diagnostic)]
#[error("cannot read the sweep spec `{path}`: {reason}")]
#[diagnostic(
    code(vams::sweep::unreadable),
    help("give the path of a TOML file (see `vams sweep --help`)")
)]
pub struct UnreadableSpec {
    pub path: String,
    pub reason: String,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSpec {
    design: Spanned<RawDesign>,
    grid: Option<Spanned<RawPlan>>,
    corners: Option<Spanned<RawCorners>>,
    monte_carlo: Option<Spanned<RawMonteCarlo>>,
    sensitivity: Option<Spanned<RawSensitivity>>,
    #[serde(default)]
    metrics: MetricTable,
    #[serde(default)]
    plots: RawPlots,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawDesign {
    files: Vec<Spanned<String>>,
    #[serde(default)]
    libraries: IndexMap<String, Spanned<String>>,
    top: Option<String>,
    stop: Option<Spanned<toml::Value>>,
    reltol: Option<Spanned<f64>>,
    abstol: Option<Spanned<f64>>,
    max_step: Option<Spanned<toml::Value>>,
    #[serde(default)]
    generics: IndexMap<String, Spanned<toml::Value>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPlan {
    parameters: IndexMap<String, Spanned<toml::Value>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCorners {
    parameters: IndexMap<String, Spanned<toml::Value>>,
    set: Option<Spanned<String>>,
    #[serde(default)]
    named: IndexMap<String, Spanned<IndexMap<String, Spanned<String>>>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawMonteCarlo {
    runs: Spanned<i64>,
    seed: Option<Spanned<i64>>,
    sampling: Option<Spanned<String>>,
    parameters: IndexMap<String, Spanned<toml::Value>>,
    #[serde(default)]
    correlations: Vec<Spanned<RawCorrelation>>,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawCorrelation {
    parameters: Vec<String>,
    coefficient: f64,
}

#[derive(Deserialize)]
#[serde(deny_unknown_fields)]
struct RawSensitivity {
    perturbation: Option<Spanned<toml::Value>>,
    parameters: IndexMap<String, Spanned<f64>>,
}

#[derive(Default, Deserialize)]
#[serde(deny_unknown_fields)]
struct RawPlots {
    #[serde(default)]
    envelope: Vec<Spanned<String>>,
    format: Option<Spanned<String>>,
}

/// FNV-1a: a fingerprint of the spec's text, the same on every machine and Rust version.
fn fingerprint(text: &str) -> u64 {
    text.bytes().fold(0xcbf2_9ce4_8422_2325, |h, b| {
        (h ^ u64::from(b)).wrapping_mul(0x0100_0000_01b3)
    })
}

/// Builds located errors for one spec text.
pub struct Locator {
    path: String,
    source: Arc<NamedSource<String>>,
}

impl Locator {
    pub fn new(path: &str, text: &str) -> Locator {
        Locator {
            path: path.to_string(),
            source: Arc::new(NamedSource::new(path, text.to_string()).with_language("toml")),
        }
    }

    /// An error at byte range `span` of the text.
    pub fn error(
        &self,
        span: impl Into<SourceSpan>,
        message: impl Into<String>,
        help: Option<String>,
    ) -> SpecError {
        let span: SourceSpan = span.into();
        let text = self.source.inner();
        let line = text[..span.offset().min(text.len())].matches('\n').count() + 1;
        SpecError {
            path: self.path.clone(),
            line,
            message: message.into(),
            help,
            src: self.source.clone(),
            span,
        }
    }
}

fn span_of<T>(s: &Spanned<T>) -> SourceSpan {
    let r = s.span();
    SourceSpan::new(r.start.into(), r.end - r.start)
}

/// Reads and checks the spec at `path`.
pub fn read_spec(path: &Path) -> Result<Spec, miette::Report> {
    let text = std::fs::read_to_string(path).map_err(|e| UnreadableSpec {
        path: path.display().to_string(),
        reason: e.to_string(),
    })?;
    Ok(parse_spec(path, &text)?)
}

/// Checks the text of a spec read from `path` (relative file names are resolved against
/// its folder).
pub fn parse_spec(path: &Path, text: &str) -> Result<Spec, SpecError> {
    let at = Locator::new(&path.display().to_string(), text);
    let raw: RawSpec = toml::from_str(text).map_err(|e| {
        let span = e.span().unwrap_or(0..0);
        at.error(
            span.start..span.end.max(span.start),
            e.message().trim().to_string(),
            Some(
                "a spec has [design], one of [grid], [corners], [monte_carlo] or \
                 [sensitivity], and optionally [metrics] and [plots]"
                    .into(),
            ),
        )
    })?;
    let folder = path.parent().unwrap_or(Path::new("."));
    let design = design(&at, folder, raw.design)?;
    let mut plans = Vec::new();
    if let Some(grid) = raw.grid {
        plans.push((span_of(&grid), Section::Grid(grid.into_inner())));
    }
    if let Some(c) = raw.corners {
        plans.push((span_of(&c), Section::Corners(c.into_inner())));
    }
    if let Some(m) = raw.monte_carlo {
        plans.push((span_of(&m), Section::MonteCarlo(m.into_inner())));
    }
    if let Some(s) = raw.sensitivity {
        plans.push((span_of(&s), Section::Sensitivity(s.into_inner())));
    }
    let (plan_span, section) = match plans.len() {
        1 => plans.remove(0),
        0 => {
            return Err(at.error(
                0..0,
                "the spec has no plan",
                Some(
                    "add one of [grid], [corners], [monte_carlo] or [sensitivity] with its \
                     parameters"
                        .into(),
                ),
            ));
        }
        _ => {
            return Err(at.error(
                plans[1].0,
                "the spec has more than one plan",
                Some("keep one of [grid], [corners], [monte_carlo] and [sensitivity]".into()),
            ));
        }
    };
    let (plan, parameter_spans) = plan(&at, plan_span, section)?;
    let metric_spans = raw.metrics.0.iter().map(|(_, m)| span_of(m)).collect();
    let metrics = raw.metrics.validate().map_err(|errors| {
        // The first; the user fixes one at a time, as with the rest of the spec.
        let e = &errors[0];
        at.error(
            e.span.clone(),
            format!("metric `{}`: {}", e.metric, e.message),
            Some(e.help.clone()),
        )
    })?;
    let plot_format = match raw
        .plots
        .format
        .as_ref()
        .map(|f| f.get_ref().to_ascii_lowercase())
    {
        None => "svg",
        Some(f) if f == "svg" => "svg",
        Some(f) if f == "png" => "png",
        Some(other) => {
            return Err(at.error(
                raw.plots.format.as_ref().map_or((0..0).into(), span_of),
                format!("unknown plot format `{other}`"),
                Some("format is \"svg\" or \"png\"".into()),
            ));
        }
    };
    Ok(Spec {
        plot_format,
        path: path.to_path_buf(),
        source: at.source.clone(),
        fingerprint: fingerprint(text),
        design,
        plan,
        plan_span,
        parameter_spans,
        metrics,
        metric_spans,
        envelope: raw
            .plots
            .envelope
            .iter()
            .map(|n| n.get_ref().to_ascii_lowercase())
            .collect(),
        envelope_spans: raw.plots.envelope.iter().map(span_of).collect(),
    })
}

enum Section {
    Grid(RawPlan),
    Corners(RawCorners),
    MonteCarlo(RawMonteCarlo),
    Sensitivity(RawSensitivity),
}

/// A number of seconds, or a string with a unit (`"6 s"`, `"10 ms"`).
fn time(at: &Locator, value: &Spanned<toml::Value>) -> Result<f64, SpecError> {
    let parsed = match value.get_ref() {
        toml::Value::Float(x) if *x > 0.0 && x.is_finite() => Ok(*x),
        toml::Value::Integer(n) if *n > 0 => Ok(*n as f64),
        toml::Value::String(s) => parse_positive_time(s),
        _ => Err("expected a positive time".to_string()),
    };
    parsed.map_err(|problem| {
        at.error(
            span_of(value),
            problem,
            Some("write a time as a number of seconds or a string: \"6 s\", \"10 ms\"".into()),
        )
    })
}

/// The VHDL literal of a TOML value given to a generic.
fn literal(at: &Locator, value: &Spanned<toml::Value>) -> Result<String, SpecError> {
    match value.get_ref() {
        toml::Value::Integer(n) => Ok(n.to_string()),
        toml::Value::Float(x) if x.is_finite() => Ok(crate::output::csv::format_number(*x)),
        toml::Value::Boolean(b) => Ok(b.to_string()),
        toml::Value::String(s) if !s.trim().is_empty() => Ok(s.trim().to_string()),
        _ => Err(at.error(
            span_of(value),
            "expected a value for a generic",
            Some("write a number, true/false, or a VHDL literal as a string: \"10 ms\"".into()),
        )),
    }
}

fn parameter_name(at: &Locator, name: &str, span: SourceSpan) -> Result<String, SpecError> {
    if is_generic_path(name) {
        Ok(name.to_ascii_lowercase())
    } else {
        Err(at.error(
            span,
            format!("`{name}` is not a generic's name"),
            Some(
                "name a generic of the top (`r`) or of an instance by its path (\"u_motor.r\", \
                 quoted in TOML)"
                    .into(),
            ),
        ))
    }
}

fn design(at: &Locator, folder: &Path, raw: Spanned<RawDesign>) -> Result<DesignSpec, SpecError> {
    let span = span_of(&raw);
    let raw = raw.into_inner();
    if raw.files.is_empty() {
        return Err(at.error(
            span,
            "[design] names no files",
            Some("list the sources: files = [\"../models\"] (relative to the spec)".into()),
        ));
    }
    let resolve = |p: &str| {
        let p = Path::new(p);
        if p.is_absolute() {
            p.to_path_buf()
        } else {
            folder.join(p)
        }
    };
    let mut generics = Vec::new();
    for (name, value) in &raw.generics {
        let name = parameter_name(at, name, span_of(value))?;
        generics.push((name, literal(at, value)?));
    }
    let positive = |v: &Option<Spanned<f64>>, what: &str| -> Result<Option<f64>, SpecError> {
        match v {
            Some(x) if !(x.get_ref().is_finite() && *x.get_ref() > 0.0) => Err(at.error(
                span_of(x),
                format!("{what} must be a positive number"),
                Some(format!("e.g. {what} = 1e-3")),
            )),
            Some(x) => Ok(Some(*x.get_ref())),
            None => Ok(None),
        }
    };
    Ok(DesignSpec {
        files: raw.files.iter().map(|f| resolve(f.get_ref())).collect(),
        libraries: raw
            .libraries
            .iter()
            .map(|(n, p)| (n.to_ascii_lowercase(), resolve(p.get_ref())))
            .collect(),
        top: raw.top.map(|t| t.to_ascii_lowercase()),
        stop: raw.stop.as_ref().map(|t| time(at, t)).transpose()?,
        reltol: positive(&raw.reltol, "reltol")?.unwrap_or(1e-3),
        abstol: positive(&raw.abstol, "abstol")?,
        max_step: raw.max_step.as_ref().map(|t| time(at, t)).transpose()?,
        generics,
    })
}

/// The keys of an inline table, checked against those allowed.
fn table<'t>(
    at: &Locator,
    value: &'t Spanned<toml::Value>,
    allowed: &[&str],
    example: &str,
) -> Result<&'t toml::Table, SpecError> {
    let toml::Value::Table(t) = value.get_ref() else {
        return Err(at.error(
            span_of(value),
            "expected a table of settings",
            Some(format!("e.g. {example}")),
        ));
    };
    if let Some(bad) = t.keys().find(|k| !allowed.contains(&k.as_str())) {
        return Err(at.error(
            span_of(value),
            format!("unknown key `{bad}`"),
            Some(format!("the keys here are {}", allowed.join(", "))),
        ));
    }
    Ok(t)
}

/// A number or a `"5%"` string: `(value, relative)`.
fn amount(v: &toml::Value) -> Option<(f64, bool)> {
    match v {
        toml::Value::Float(x) => Some((*x, false)),
        toml::Value::Integer(n) => Some((*n as f64, false)),
        toml::Value::String(s) => s
            .trim()
            .strip_suffix('%')
            .and_then(|p| p.trim().parse::<f64>().ok())
            .map(|p| (p / 100.0, true)),
        _ => None,
    }
}

fn number(v: Option<&toml::Value>) -> Option<f64> {
    match v? {
        toml::Value::Float(x) => Some(*x),
        toml::Value::Integer(n) => Some(*n as f64),
        _ => None,
    }
}

fn plan(
    at: &Locator,
    plan_span: SourceSpan,
    section: Section,
) -> Result<(Plan, Vec<SourceSpan>), SpecError> {
    let no_parameters = |what: &str, example: &str| {
        at.error(
            plan_span,
            format!("[{what}] has no parameters"),
            Some(format!("add [{what}.parameters] with e.g. {example}")),
        )
    };
    match section {
        Section::Grid(raw) => {
            if raw.parameters.is_empty() {
                return Err(no_parameters("grid", "r = [4.5, 5.0, 5.5]"));
            }
            let (mut names, mut values, mut spans) = (Vec::new(), Vec::new(), Vec::new());
            for (name, v) in &raw.parameters {
                names.push(parameter_name(at, name, span_of(v))?);
                values.push(grid_values(at, v)?);
                spans.push(span_of(v));
            }
            Ok((Plan::Grid { names, values }, spans))
        }
        Section::Corners(raw) => {
            if raw.parameters.is_empty() {
                return Err(no_parameters(
                    "corners",
                    "r = { min = 4.5, nominal = 5.0, max = 5.5 }",
                ));
            }
            let (mut corners, mut spans) = (Vec::new(), Vec::new());
            for (name, v) in &raw.parameters {
                let name = parameter_name(at, name, span_of(v))?;
                corners.push(corner(at, name, v)?);
                spans.push(span_of(v));
            }
            let set = corner_set(at, &raw, &corners)?;
            Ok((Plan::Corners { corners, set }, spans))
        }
        Section::MonteCarlo(raw) => {
            if raw.parameters.is_empty() {
                return Err(no_parameters(
                    "monte_carlo",
                    "r = { distribution = \"normal\", nominal = 5.0, tolerance = \"5%\" }",
                ));
            }
            let runs = *raw.runs.get_ref();
            if runs < 1 {
                return Err(at.error(
                    span_of(&raw.runs),
                    "runs must be at least 1",
                    Some("e.g. runs = 1000".into()),
                ));
            }
            let seed = match &raw.seed {
                Some(s) if *s.get_ref() < 0 => {
                    return Err(at.error(
                        span_of(s),
                        "the seed must not be negative",
                        Some("e.g. seed = 1".into()),
                    ));
                }
                Some(s) => *s.get_ref() as u64,
                None => 1,
            };
            let sampling = match raw.sampling.as_ref().map(|s| s.get_ref().as_str()) {
                None | Some("random") => Sampling::Random,
                Some("latin_hypercube") => Sampling::LatinHypercube,
                Some(other) => {
                    return Err(at.error(
                        raw.sampling.as_ref().map(span_of).unwrap_or(plan_span),
                        format!("unknown sampling `{other}`"),
                        Some("sampling is \"random\" or \"latin_hypercube\"".into()),
                    ));
                }
            };
            let (mut parameters, mut spans) = (Vec::new(), Vec::new());
            for (name, v) in &raw.parameters {
                let name = parameter_name(at, name, span_of(v))?;
                parameters.push((name, distribution(at, v)?));
                spans.push(span_of(v));
            }
            let correlation = correlation(at, &raw.correlations, &parameters)?;
            let sampler = Sampler::new(parameters, runs as usize, seed, sampling, correlation)
                .map_err(|e| {
                    let help = match e {
                        SamplerError::NotPositiveDefinite => {
                            "the coefficients contradict each other (e.g. a with b 0.9, b with \
                             c 0.9, a with c -0.9): loosen them"
                        }
                        SamplerError::TooManyForLatinHypercube(_) => {
                            "use sampling = \"random\" for this many runs"
                        }
                    };
                    at.error(plan_span, e.to_string(), Some(help.into()))
                })?;
            Ok((Plan::MonteCarlo(sampler), spans))
        }
        Section::Sensitivity(raw) => {
            if raw.parameters.is_empty() {
                return Err(no_parameters("sensitivity", "r = 5.0 (its nominal value)"));
            }
            let delta = match &raw.perturbation {
                None => 0.01,
                Some(p) => match amount(p.get_ref()) {
                    Some((d, true)) if d > 0.0 && d < 1.0 => d,
                    _ => {
                        return Err(at.error(
                            span_of(p),
                            "the perturbation must be a percentage between 0 and 100",
                            Some("e.g. perturbation = \"1%\"".into()),
                        ));
                    }
                },
            };
            let (mut names, mut nominal, mut spans) = (Vec::new(), Vec::new(), Vec::new());
            for (name, v) in &raw.parameters {
                names.push(parameter_name(at, name, span_of(v))?);
                if *v.get_ref() == 0.0 || !v.get_ref().is_finite() {
                    return Err(at.error(
                        span_of(v),
                        "a relative perturbation needs a nonzero nominal value",
                        Some("give the parameter's nominal value, e.g. r = 5.0".into()),
                    ));
                }
                nominal.push(*v.get_ref());
                spans.push(span_of(v));
            }
            Ok((
                Plan::Sensitivity {
                    names,
                    nominal,
                    delta,
                },
                spans,
            ))
        }
    }
}

fn grid_values(at: &Locator, v: &Spanned<toml::Value>) -> Result<Vec<ParamValue>, SpecError> {
    let example = "r = [4.5, 5.0, 5.5] or v_bat = { from = 9.0, to = 16.0, steps = 8 }";
    match v.get_ref() {
        toml::Value::Array(items) if !items.is_empty() => items
            .iter()
            .map(|item| match item {
                toml::Value::Float(x) if x.is_finite() => Ok(ParamValue::Number(*x)),
                toml::Value::Integer(n) => Ok(ParamValue::Number(*n as f64)),
                toml::Value::Boolean(b) => Ok(ParamValue::Text(b.to_string())),
                toml::Value::String(s) if !s.trim().is_empty() => {
                    Ok(ParamValue::Text(s.trim().to_string()))
                }
                _ => Err(at.error(
                    span_of(v),
                    "a grid's values are numbers, booleans or VHDL literals as strings",
                    Some(example.into()),
                )),
            })
            .collect(),
        toml::Value::Array(_) => Err(at.error(
            span_of(v),
            "the list of values is empty",
            Some(example.into()),
        )),
        toml::Value::Table(_) => {
            let t = table(at, v, &["from", "to", "steps", "scale"], example)?;
            let (Some(from), Some(to)) = (number(t.get("from")), number(t.get("to"))) else {
                return Err(at.error(
                    span_of(v),
                    "a range needs numbers `from` and `to`",
                    Some(example.into()),
                ));
            };
            let steps = match t.get("steps") {
                Some(toml::Value::Integer(n)) if *n >= 1 => *n as usize,
                Some(toml::Value::Integer(n)) if *n <= 0 => {
                    return Err(at.error(
                        span_of(v),
                        format!("a range of {n} steps has no values"),
                        Some("steps is the number of values, at least 1 (2: from and to)".into()),
                    ));
                }
                _ => {
                    return Err(at.error(
                        span_of(v),
                        "a range needs `steps`, the number of values (a whole number)",
                        Some(example.into()),
                    ));
                }
            };
            let log = match t.get("scale").and_then(toml::Value::as_str) {
                None | Some("linear") => false,
                Some("log") if from > 0.0 && to > 0.0 => true,
                Some("log") => {
                    return Err(at.error(
                        span_of(v),
                        "a logarithmic range needs positive `from` and `to`",
                        None,
                    ));
                }
                Some(other) => {
                    return Err(at.error(
                        span_of(v),
                        format!("unknown scale `{other}`"),
                        Some("scale is \"linear\" or \"log\"".into()),
                    ));
                }
            };
            if !(from.is_finite() && to.is_finite()) {
                return Err(at.error(span_of(v), "the range's ends must be finite", None));
            }
            Ok((0..steps)
                .map(|k| {
                    let w = if steps == 1 {
                        0.0
                    } else {
                        k as f64 / (steps - 1) as f64
                    };
                    ParamValue::Number(if k + 1 == steps && steps > 1 {
                        to
                    } else if log {
                        tidy(from * (to / from).powf(w))
                    } else {
                        tidy(from + w * (to - from))
                    })
                })
                .collect())
        }
        _ => Err(at.error(
            span_of(v),
            "expected a list of values or a range",
            Some(example.into()),
        )),
    }
}

fn corner(at: &Locator, name: String, v: &Spanned<toml::Value>) -> Result<Corner, SpecError> {
    let example =
        "r = { min = 4.5, nominal = 5.0, max = 5.5 } or r = { nominal = 5.0, tolerance = \"10%\" }";
    let t = table(at, v, &["min", "nominal", "max", "tolerance"], example)?;
    let nominal = number(t.get("nominal")).ok_or_else(|| {
        at.error(
            span_of(v),
            "a corner parameter needs its `nominal` value",
            Some(example.into()),
        )
    })?;
    let (min, max) = match (
        number(t.get("min")),
        number(t.get("max")),
        t.get("tolerance").and_then(amount),
    ) {
        (Some(lo), Some(hi), None) => (lo, hi),
        (None, None, Some((tol, relative))) if tol >= 0.0 => {
            let d = if relative { tol * nominal.abs() } else { tol };
            (tidy(nominal - d), tidy(nominal + d))
        }
        _ => {
            return Err(at.error(
                span_of(v),
                "a corner parameter needs `min` and `max`, or a non-negative `tolerance`",
                Some(example.into()),
            ));
        }
    };
    if !(min <= nominal && nominal <= max && [min, nominal, max].iter().all(|x| x.is_finite())) {
        return Err(at.error(
            span_of(v),
            format!("min {min}, nominal {nominal} and max {max} are not in order"),
            Some("a corner needs min <= nominal <= max".into()),
        ));
    }
    Ok(Corner {
        name,
        min,
        nominal,
        max,
    })
}

fn corner_set(at: &Locator, raw: &RawCorners, corners: &[Corner]) -> Result<CornerSet, SpecError> {
    if !raw.named.is_empty() {
        let mut named = Vec::new();
        for (label, levels) in &raw.named {
            let mut chosen = vec![Level::Nominal; corners.len()];
            for (param, level) in levels.get_ref() {
                let Some(k) = corners
                    .iter()
                    .position(|c| c.name.eq_ignore_ascii_case(param))
                else {
                    return Err(at.error(
                        span_of(levels),
                        format!("corner `{label}` names `{param}`, which is not a parameter"),
                        Some(format!(
                            "the parameters are {}",
                            corners
                                .iter()
                                .map(|c| c.name.as_str())
                                .collect::<Vec<_>>()
                                .join(", ")
                        )),
                    ));
                };
                chosen[k] = match level.get_ref().as_str() {
                    "min" => Level::Min,
                    "nominal" => Level::Nominal,
                    "max" => Level::Max,
                    other => {
                        return Err(at.error(
                            span_of(level),
                            format!("unknown level `{other}`"),
                            Some("a level is \"min\", \"nominal\" or \"max\"".into()),
                        ));
                    }
                };
            }
            named.push((label.clone(), chosen));
        }
        return Ok(CornerSet::Named(named));
    }
    match raw.set.as_ref().map(|s| s.get_ref().as_str()) {
        None | Some("all") => Ok(CornerSet::All),
        Some("extremes") => Ok(CornerSet::Extremes),
        Some(other) => Err(at.error(
            raw.set.as_ref().map(span_of).unwrap_or((0..0).into()),
            format!("unknown corner set `{other}`"),
            Some(
                "set is \"all\" (3^n: min, nominal, max) or \"extremes\" (2^n: min, max); \
                 or name corners in [corners.named]"
                    .into(),
            ),
        )),
    }
}

fn distribution(at: &Locator, v: &Spanned<toml::Value>) -> Result<Distribution, SpecError> {
    let example = "r = { distribution = \"normal\", nominal = 5.0, tolerance = \"5%\" }";
    let t = table(
        at,
        v,
        &[
            "distribution",
            "nominal",
            "mean",
            "sigma",
            "tolerance",
            "min",
            "max",
        ],
        example,
    )?;
    let kind = t
        .get("distribution")
        .and_then(toml::Value::as_str)
        .unwrap_or("normal");
    let bad = |message: String, help: &str| Err(at.error(span_of(v), message, Some(help.into())));
    let nominal = number(t.get("nominal")).or(number(t.get("mean")));
    // The spread: sigma, or tolerance = 3 sigma; either absolute or "x%" of the nominal.
    let sigma = match (t.get("sigma").map(amount), t.get("tolerance").map(amount)) {
        (Some(Some((s, rel))), None) => Some(if rel {
            s * nominal.unwrap_or(0.0).abs()
        } else {
            s
        }),
        (None, Some(Some((s, rel)))) => Some(
            if rel {
                s * nominal.unwrap_or(0.0).abs()
            } else {
                s
            } / 3.0,
        ),
        (None, None) => None,
        (Some(_), Some(_)) => {
            return bad(
                "give `sigma` or `tolerance`, not both".into(),
                "tolerance is three sigma: tolerance = \"6%\" is sigma = \"2%\"",
            );
        }
        _ => {
            return bad(
                "`sigma` and `tolerance` are numbers or percentages".into(),
                "e.g. sigma = 0.1 or tolerance = \"5%\"",
            );
        }
    };
    if let Some(s) = sigma
        && !(s >= 0.0 && s.is_finite())
    {
        return bad(
            format!("the spread must not be negative (sigma {s})"),
            "give sigma or tolerance as a positive number or percentage",
        );
    }
    let (min, max) = (number(t.get("min")), number(t.get("max")));
    let need_nominal = |what: &str| {
        at.error(
            span_of(v),
            format!("a {what} distribution needs `nominal` (or `mean`) and `sigma` or `tolerance`"),
            Some(example.into()),
        )
    };
    let d = match kind {
        "normal" => Distribution::Normal {
            mean: nominal.ok_or_else(|| need_nominal("normal"))?,
            sigma: sigma.ok_or_else(|| need_nominal("normal"))?,
        },
        "uniform" => match (min, max, nominal, t.get("tolerance").and_then(amount)) {
            (Some(lo), Some(hi), _, None) => Distribution::Uniform { min: lo, max: hi },
            (None, None, Some(n), Some((tol, rel))) => {
                let d = if rel { tol * n.abs() } else { tol };
                Distribution::Uniform {
                    min: n - d,
                    max: n + d,
                }
            }
            _ => {
                return bad(
                    "a uniform distribution needs `min` and `max`, or `nominal` and `tolerance` (the half-width)".into(),
                    "e.g. j = { distribution = \"uniform\", min = 1e-6, max = 2e-6 }",
                );
            }
        },
        "lognormal" | "log_normal" => {
            let median = nominal.ok_or_else(|| need_nominal("log-normal"))?;
            if median <= 0.0 {
                return bad(
                    "a log-normal distribution needs a positive nominal (its median)".into(),
                    "use a normal distribution for parameters that can be negative",
                );
            }
            // sigma: of ln x; a tolerance "x%" is three sigma of ln x: ln(1 + x) / 3.
            let s = match (
                t.get("sigma").and_then(amount),
                t.get("tolerance").and_then(amount),
            ) {
                (Some((s, _)), None) => s,
                (None, Some((tol, true))) => (1.0 + tol).ln() / 3.0,
                _ => {
                    return bad(
                        "a log-normal distribution needs `sigma` (of ln x) or a percentage `tolerance`".into(),
                        "e.g. ke = { distribution = \"lognormal\", nominal = 8.7e-3, tolerance = \"10%\" }",
                    );
                }
            };
            Distribution::LogNormal { median, sigma: s }
        }
        "truncated_normal" => {
            let mean = nominal.ok_or_else(|| need_nominal("truncated normal"))?;
            let sigma = sigma.ok_or_else(|| need_nominal("truncated normal"))?;
            let (lo, hi) = (
                min.unwrap_or(mean - 3.0 * sigma),
                max.unwrap_or(mean + 3.0 * sigma),
            );
            if lo >= hi {
                return bad(
                    format!("min {lo} is not below max {hi}"),
                    "a truncated normal lies between min and max",
                );
            }
            Distribution::TruncatedNormal {
                mean,
                sigma,
                min: lo,
                max: hi,
            }
        }
        other => {
            return bad(
                format!("unknown distribution `{other}`"),
                "distribution is \"normal\", \"uniform\", \"lognormal\" or \"truncated_normal\"",
            );
        }
    };
    let finite = match d {
        Distribution::Normal { mean, sigma } => mean.is_finite() && sigma.is_finite(),
        Distribution::Uniform { min, max } => min.is_finite() && max.is_finite() && min <= max,
        Distribution::LogNormal { median, sigma } => {
            median.is_finite() && sigma.is_finite() && sigma >= 0.0
        }
        Distribution::TruncatedNormal { .. } => true,
    };
    if !finite {
        return bad(
            "the distribution's numbers are not finite and in order".into(),
            example,
        );
    }
    Ok(d)
}

fn correlation(
    at: &Locator,
    raw: &[Spanned<RawCorrelation>],
    parameters: &[(String, Distribution)],
) -> Result<Option<Vec<Vec<f64>>>, SpecError> {
    if raw.is_empty() {
        return Ok(None);
    }
    let n = parameters.len();
    let mut c: Vec<Vec<f64>> = (0..n)
        .map(|i| (0..n).map(|j| if i == j { 1.0 } else { 0.0 }).collect())
        .collect();
    let names: Vec<&str> = parameters.iter().map(|(n, _)| n.as_str()).collect();
    for entry in raw {
        let e = entry.get_ref();
        let index = |name: &str| {
            names
                .iter()
                .position(|n| n.eq_ignore_ascii_case(name))
                .ok_or_else(|| {
                    at.error(
                        span_of(entry),
                        format!("`{name}` is not a parameter of [monte_carlo.parameters]"),
                        Some(format!("the parameters are {}", names.join(", "))),
                    )
                })
        };
        let [a, b] = e.parameters.as_slice() else {
            return Err(at.error(
                span_of(entry),
                "a correlation names two parameters",
                Some("e.g. parameters = [\"r\", \"ke\"], coefficient = 0.5".into()),
            ));
        };
        let (i, j) = (index(a)?, index(b)?);
        if i == j || !(-1.0 < e.coefficient && e.coefficient < 1.0) {
            return Err(at.error(
                span_of(entry),
                "a correlation is between two different parameters, with a coefficient strictly between -1 and 1",
                None,
            ));
        }
        c[i][j] = e.coefficient;
        c[j][i] = e.coefficient;
    }
    Ok(Some(c))
}

#[cfg(test)]
mod tests {
    use super::*;

    const DESIGN: &str =
        "[design]\nfiles = [\"../models\"]\ntop = \"tb_tracking\"\nstop = \"6 s\"\n";

    fn parse(body: &str) -> Result<Spec, SpecError> {
        parse_spec(Path::new("sweeps/s.toml"), &format!("{DESIGN}{body}"))
    }

    fn error(body: &str) -> SpecError {
        match parse(body) {
            Ok(_) => panic!("accepted: {body}"),
            Err(e) => e,
        }
    }

    #[test]
    fn reads_a_grid_with_lists_and_ranges() {
        let spec = parse(
            "[grid.parameters]\nr = [4.5, 5.0, 5.5]\nv_bat = { from = 9.0, to = 16.0, steps = 8 }\n\"dut.u_motor.l\" = [1e-3]\n",
        )
        .unwrap();
        assert_eq!(spec.design.files, [PathBuf::from("sweeps/../models")]);
        assert_eq!(spec.design.stop, Some(6.0));
        assert_eq!(spec.plan.names(), ["r", "v_bat", "dut.u_motor.l"]);
        assert_eq!(spec.plan.len(), Some(24));
        let last = spec.plan.run(23);
        let literals: Vec<String> = last.values.iter().map(ParamValue::literal).collect();
        assert_eq!(literals, ["5.5", "16", "0.001"]);
        assert_eq!(spec.plan.run(1).values[1], ParamValue::Number(10.0));
    }

    #[test]
    fn reads_corners_monte_carlo_and_sensitivity() {
        let c = parse("[corners]\nset = \"extremes\"\n[corners.parameters]\nr = { nominal = 5.0, tolerance = \"10%\" }\nv = { min = 9, nominal = 12, max = 16 }\n").unwrap();
        assert_eq!(c.plan.len(), Some(5));
        let m = parse("[monte_carlo]\nruns = 100\nseed = 7\nsampling = \"latin_hypercube\"\n[monte_carlo.parameters]\nr = { nominal = 5.0, tolerance = \"6%\" }\nj = { distribution = \"uniform\", min = 1, max = 2 }\n[[monte_carlo.correlations]]\nparameters = [\"r\", \"j\"]\ncoefficient = 0.5\n").unwrap();
        assert_eq!(m.plan.len(), Some(101));
        assert_eq!(m.plan.run(0).case, "nominal");
        let s = parse("[sensitivity]\nperturbation = \"2%\"\n[sensitivity.parameters]\nr = 5.0\nke = 8.7e-3\n").unwrap();
        assert_eq!(s.plan.len(), Some(5));
    }

    #[test]
    fn errors_name_the_line_and_say_how_to_fix() {
        let e = error("[grid.parameters]\nr = { from = 1.0, to = 2.0, steps = 0 }\n");
        assert_eq!(e.line, 6, "{e}");
        assert!(e.message.contains("0 steps"), "{e}");
        let e = error(
            "[monte_carlo]\nruns = 10\n[monte_carlo.parameters]\nr = { nominal = 5.0, sigma = -0.1 }\n",
        );
        assert_eq!(e.line, 8, "{e}");
        assert!(e.message.contains("must not be negative"), "{e}");
        let e = error("");
        assert!(e.message.contains("no plan"), "{e}");
        let e = error("[grid.parameters]\nr = [1]\n[sensitivity.parameters]\nr = 1.0\n");
        assert!(e.message.contains("more than one plan"), "{e}");
        let e = error("[grid.parameters]\n\"2r\" = [1]\n");
        assert!(e.message.contains("not a generic's name"), "{e}");
        let e = error("[grid.parameters]\nr = [1]\n[plot]\n");
        assert!(e.message.contains("unknown field"), "{e}");
        assert_eq!(e.line, 7);
        let e = error("[corners.parameters]\nr = { min = 6, nominal = 5, max = 7 }\n");
        assert!(e.message.contains("not in order"), "{e}");
        let e = error(
            "[monte_carlo]\nruns = 10\n[monte_carlo.parameters]\nr = { distribution = \"gauss\", nominal = 1.0, sigma = 0.1 }\n",
        );
        assert!(e.message.contains("unknown distribution"), "{e}");
    }
}
