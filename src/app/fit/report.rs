//! What `vams fit` prints and writes: the table for people, `--json` for scripts, the
//! `name=value` file for `vams run --params`, and the warnings a fit deserves.

use std::fmt::Write as _;

use crate::fit::{Fitted, FreeParam, Series};
use crate::output::csv::format_number;

/// What the report shows beyond the fit.
pub struct Context<'a> {
    pub params: &'a [FreeParam],
    pub series: &'a [Series],
    /// The capture file of each experiment.
    pub captures: &'a [String],
    pub seconds: f64,
}

impl Context<'_> {
    /// How parameter `k` is named in reports: its generic, and for one of a single
    /// experiment (`--free-each`) `@` and the capture's file stem (its number where two
    /// captures share a stem).
    pub fn label(&self, k: usize) -> String {
        let Some(p) = self.params.get(k) else {
            // An offset's coordinate follows the parameters'.
            let o = k - self.params.len();
            return match self.series.iter().find(|s| s.offset == Some(o)) {
                Some(s) => format!("the offset of {}", s.label),
                None => format!("offset {o}"),
            };
        };
        let Some(e) = p.experiment else {
            return p.name.clone();
        };
        let stem = |path: &str| {
            std::path::Path::new(path)
                .file_stem()
                .map(|s| s.to_string_lossy().into_owned())
                .unwrap_or_default()
        };
        let own = self.captures.get(e).map(|c| stem(c)).unwrap_or_default();
        let shared = self.captures.iter().filter(|c| stem(c) == own).count() > 1;
        if own.is_empty() || shared {
            format!("{}@{}", p.name, e + 1)
        } else {
            format!("{}@{own}", p.name)
        }
    }
}

fn range(r: Option<(f64, f64)>, value: f64) -> String {
    match r {
        Some((lo, hi)) => {
            let rel = 100.0 * (hi - lo) / 2.0 / value.abs().max(f64::MIN_POSITIVE);
            if value != 0.0 && rel.is_finite() {
                format!("{lo:.4e} .. {hi:.4e} (±{rel:.2} %)")
            } else {
                format!("{lo:.4e} .. {hi:.4e}")
            }
        }
        None => "-".to_string(),
    }
}

/// The warnings: parameters at a bound, directions the captures do not determine, an
/// iteration that did not converge.
pub fn warnings(f: &Fitted, c: &Context) -> Vec<String> {
    let mut w = Vec::new();
    for (k, e) in f.estimates.iter().enumerate() {
        if e.at_bound {
            w.push(format!(
                "`{}` ended at its bound ({}): the captures ask for a value beyond it; widen the bound if it is not physical, otherwise the other parameters absorb the difference",
                c.label(k),
                format_number(e.value)
            ));
        }
    }
    for u in &f.uncertainty.unidentified {
        let names: Vec<String> = u
            .parameters
            .iter()
            .map(|(k, _)| format!("`{}`", c.label(*k)))
            .collect();
        // Where the parameters involved show most: the capture that carries their effect.
        let mut influence = vec![0.0; c.captures.len()];
        for (k, _) in &u.parameters {
            let Some(estimate) = f.estimates.get(*k) else {
                continue;
            };
            for (e, v) in estimate.influence.iter().enumerate() {
                influence[e] += v;
            }
        }
        let best = influence
            .iter()
            .enumerate()
            .max_by(|a, b| a.1.total_cmp(b.1))
            .map(|(e, _)| c.captures[e].clone())
            .unwrap_or_default();
        let what = if names.len() == 1 {
            format!(
                "{} is not identifiable from these captures (its effect on them is below their noise)",
                names[0]
            )
        } else {
            format!(
                "{} are not separately identifiable from these captures: only a combination of them is (their effects on the waveforms are nearly proportional)",
                names.join(" and ")
            )
        };
        let hint = if best.is_empty() || influence.iter().all(|v| *v == 0.0) {
            "no capture responds to it: add one whose experiment exercises it".to_string()
        } else {
            format!(
                "{} most in `{best}`: a longer or less noisy capture of that experiment, or one where {}, would determine {}; or fix {} with -g",
                if names.len() == 1 {
                    "it shows"
                } else {
                    "they show"
                },
                if names.len() == 1 {
                    "it acts more strongly"
                } else {
                    "they act differently"
                },
                if names.len() == 1 { "it" } else { "them" },
                if names.len() == 1 {
                    "it"
                } else {
                    "one of them"
                }
            )
        };
        w.push(format!("{what}; {hint}"));
    }
    if f.ending == crate::fit::Ending::IterationLimit {
        w.push(
            "the fit stopped at its iteration limit before converging: the values may not be the best; start nearer".to_string(),
        );
    }
    for (e, ratio) in &f.traded {
        w.push(format!(
            "the fit follows `{}` less closely than its start did (weighted RMS misfit {:.2} times the start's): it trades that capture's agreement for the others', which the model cannot follow all at once exactly; check that capture's experiment, or that the model has what it shows",
            c.captures.get(*e).map_or("?", String::as_str),
            ratio
        ));
    }
    if f.start_reported {
        w.push(format!(
            "the fit ended worse than its start on {}: the model cannot follow these captures together (an experiment the testbench does not reproduce: a supply, a load, a switching time), so the start is reported, not the fit; check each capture's setup against its experiment",
            worse_captures(f, c)
        ));
    }
    w
}

/// The captures the fit made worse, quoted and joined.
fn worse_captures(f: &Fitted, c: &Context) -> String {
    f.worse_than_start
        .iter()
        .map(|&e| format!("`{}`", c.captures.get(e).map_or("?", String::as_str)))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The labels of the parameters that ended at a bound.
fn bound_hits(f: &Fitted, c: &Context) -> Vec<String> {
    (f.estimates.iter().enumerate())
        .filter(|(_, e)| e.at_bound)
        .map(|(k, _)| c.label(k))
        .collect()
}

/// Why a fit's result is not a converged least-squares estimate (empty: it is): one short
/// reason each, for the table's status line and the JSON.
pub fn unconverged_reasons(f: &Fitted, c: &Context) -> Vec<String> {
    let mut reasons = Vec::new();
    if f.ending == crate::fit::Ending::IterationLimit {
        reasons.push("stopped at the iteration limit".to_string());
    }
    let bound: Vec<String> = bound_hits(f, c)
        .iter()
        .map(|label| format!("`{label}`"))
        .collect();
    if !bound.is_empty() {
        reasons.push(format!("at a bound: {}", bound.join(", ")));
    }
    if f.start_reported {
        reasons.push(format!(
            "worse than the start on {} (the start is reported)",
            worse_captures(f, c)
        ));
    }
    reasons
}

/// The status line of a table: converged, or why not and that the intervals are not
/// reliable.
pub fn status_line(f: &Fitted, c: &Context) -> String {
    let reasons = unconverged_reasons(f, c);
    if reasons.is_empty() {
        "status: converged".to_string()
    } else {
        format!(
            "status: NOT CONVERGED ({}): the intervals are not reliable",
            reasons.join("; ")
        )
    }
}

/// The JSON fields of the fit's status: `converged`, `ending`, `bound_hits`,
/// `worse_than_start` (captures), `start_reported`, `intervals_reliable`, `reasons`.
pub fn status_json(f: &Fitted, c: &Context) -> serde_json::Map<String, serde_json::Value> {
    use serde_json::json;
    let ending = match f.ending {
        crate::fit::Ending::Converged => "converged",
        crate::fit::Ending::NoBetterStep => "no better step",
        crate::fit::Ending::IterationLimit => "iteration limit",
    };
    let worse: Vec<&str> = (f.worse_than_start.iter())
        .filter_map(|&e| c.captures.get(e).map(String::as_str))
        .collect();
    let mut m = serde_json::Map::new();
    m.insert("converged".into(), json!(f.converged()));
    m.insert("ending".into(), json!(ending));
    m.insert("bound_hits".into(), json!(bound_hits(f, c)));
    m.insert("worse_than_start".into(), json!(worse));
    m.insert("start_reported".into(), json!(f.start_reported));
    m.insert("intervals_reliable".into(), json!(f.converged()));
    m.insert("reasons".into(), json!(unconverged_reasons(f, c)));
    m
}

/// The table for people.
pub fn table(f: &Fitted, c: &Context) -> String {
    let mut s = String::new();
    let samples: usize = c.series.iter().map(|s| s.measured.len()).sum();
    let _ = writeln!(
        s,
        "fit of {} free generic(s) to {} capture(s) ({} compared samples): {} iterations, {} simulations, {:.2} s\n",
        c.params.len(),
        c.captures.len(),
        samples,
        f.iterations,
        f.simulations,
        c.seconds
    );
    let _ = writeln!(s, "{}\n", status_line(f, c));
    let labels: Vec<String> = (0..c.params.len()).map(|k| c.label(k)).collect();
    let w = labels
        .iter()
        .map(|l| l.chars().count())
        .max()
        .unwrap_or(4)
        .max(7);
    let _ = writeln!(
        s,
        "{:<w$}  {:<11}  {:<11}  {:<36}  95 % with model error",
        "generic", "guess", "fitted", "95 % from the covariance"
    );
    for ((p, e), label) in c.params.iter().zip(&f.estimates).zip(&labels) {
        let _ = writeln!(
            s,
            "{:<w$}  {:<11}  {:<11.5e}  {:<36}  {}{}",
            label,
            format_number(p.guess),
            e.value,
            range(e.interval, e.value),
            range(e.robust, e.value),
            if e.at_bound { "  (at bound)" } else { "" }
        );
    }
    let n = c.params.len();
    if n > 1 {
        let _ = writeln!(s, "\ncorrelations");
        let _ = write!(s, "{:<w$}", "");
        for label in &labels {
            let _ = write!(s, " {:>8}", short(label));
        }
        let _ = writeln!(s);
        for (a, label) in labels.iter().enumerate() {
            let _ = write!(s, "{:<w$}", label);
            for b in 0..n {
                let v = f.uncertainty.correlation[a][b];
                if v.is_finite() {
                    let _ = write!(s, " {v:>8.3}");
                } else {
                    let _ = write!(s, " {:>8}", "-");
                }
            }
            let _ = writeln!(s);
        }
    }
    let _ = writeln!(
        s,
        "\n{:<36} {:>12} {:>12}",
        "series", "RMS at guess", "RMS fitted"
    );
    for (ser, fit) in c.series.iter().zip(&f.series) {
        let _ = writeln!(
            s,
            "{:<36} {:>12.4e} {:>12.4e}",
            ser.label, fit.rms_start, fit.rms
        );
    }
    s
}

fn short(name: &str) -> String {
    let last = name.rsplit('.').next().unwrap_or(name);
    last.chars().take(8).collect()
}

fn json_num(v: f64) -> serde_json::Value {
    serde_json::Number::from_f64(v).map_or(serde_json::Value::Null, serde_json::Value::Number)
}

fn json_range(r: Option<(f64, f64)>) -> serde_json::Value {
    match r {
        Some((a, b)) => serde_json::Value::Array(vec![json_num(a), json_num(b)]),
        None => serde_json::Value::Null,
    }
}

/// `--json`.
pub fn json(f: &Fitted, c: &Context) -> String {
    use serde_json::{Map, Value, json};
    let mut params = Map::new();
    for (k, (p, e)) in c.params.iter().zip(&f.estimates).enumerate() {
        params.insert(
            c.label(k),
            json!({
                "value": json_num(e.value),
                "guess": json_num(p.guess),
                "ci95": json_range(e.interval),
                "ci95_bootstrap": json_range(e.robust),
                "at_bound": e.at_bound,
            }),
        );
    }
    let correlation: Vec<Value> = f
        .uncertainty
        .correlation
        .iter()
        .map(|row| Value::Array(row.iter().map(|v| json_num(*v)).collect()))
        .collect();
    let series: Vec<Value> = c
        .series
        .iter()
        .zip(&f.series)
        .map(|(s, r)| {
            json!({
                "label": s.label,
                "capture": c.captures[s.experiment],
                "quantity": s.simulated,
                "samples": s.measured.len(),
                "rms_start": json_num(r.rms_start),
                "rms": json_num(r.rms),
            })
        })
        .collect();
    let mut out = json!({
        "parameters": Value::Object(params),
        "names": (0..c.params.len()).map(|k| c.label(k)).collect::<Vec<_>>(),
        "correlation": correlation,
        "series": series,
        "iterations": f.iterations,
        "simulations": f.simulations,
        "seconds": json_num(c.seconds),
        "warnings": warnings(f, c),
    });
    if let Value::Object(m) = &mut out {
        m.extend(status_json(f, c));
    }
    serde_json::to_string_pretty(&out).unwrap_or_default()
}

/// `name=value` lines for `vams run --params`.
pub fn params_file(f: &Fitted, c: &Context) -> String {
    let mut s = String::from("# fitted by vams fit\n");
    for (k, (p, e)) in c.params.iter().zip(&f.estimates).enumerate() {
        // A value of one capture's experiment is no generic of the design: kept as a comment.
        let comment = if p.experiment.is_some() { "# " } else { "" };
        let _ = writeln!(s, "{comment}{}={}", c.label(k), format_number(e.value));
    }
    s
}
