//! What a sweep's table says, in a few lines: per metric the worst cases and the runs that
//! gave them, the mean and sigma, how many runs met the limits; the yield; the failed runs;
//! and for a sensitivity plan, each metric's normalised sensitivity to each parameter.

use std::fmt::Write as _;

use super::metric::Metric;
use super::plan::Plan;
use super::table::{Row, Status};

/// One metric over the runs that count (Monte Carlo's samples; every run of other plans).
#[derive(Clone, Debug, PartialEq)]
pub struct MetricStats {
    pub name: String,
    /// Runs with a value.
    pub count: usize,
    pub mean: f64,
    /// The sample standard deviation (0 for a single value).
    pub sigma: f64,
    /// `(value, run)` of the smallest and the largest.
    pub min: (f64, usize),
    pub max: (f64, usize),
}

/// The statistics of metric `m` over `rows` (those with a value).
pub fn metric_stats(name: &str, rows: &[&Row], m: usize) -> Option<MetricStats> {
    let values: Vec<(f64, usize)> = rows
        .iter()
        .filter_map(|r| r.metrics.get(m).copied().flatten().map(|v| (v, r.index)))
        .collect();
    let first = *values.first()?;
    let n = values.len() as f64;
    let mean = values.iter().map(|v| v.0).sum::<f64>() / n;
    let var = if values.len() > 1 {
        values.iter().map(|v| (v.0 - mean).powi(2)).sum::<f64>() / (n - 1.0)
    } else {
        0.0
    };
    let (mut min, mut max) = (first, first);
    for &v in &values {
        if v.0 < min.0 {
            min = v;
        }
        if v.0 > max.0 {
            max = v;
        }
    }
    Some(MetricStats {
        name: name.to_string(),
        count: values.len(),
        mean,
        sigma: var.sqrt(),
        min,
        max,
    })
}

/// Normalised sensitivities of a sensitivity plan's metrics: `(dM / M) / (dp / p)` by the
/// central difference of the two perturbed runs, and each side alone (for the tornado):
/// `[metric][parameter] -> (low side, high side, central)`; `None` where a run lacks the
/// value or the nominal metric is 0.
pub type Sensitivities = Vec<Vec<Option<(f64, f64, f64)>>>;

pub fn sensitivities(plan: &Plan, rows: &[Row], metrics: usize) -> Option<Sensitivities> {
    let Plan::Sensitivity { names, delta, .. } = plan else {
        return None;
    };
    let value = |index: usize, m: usize| {
        rows.iter()
            .find(|r| r.index == index)
            .and_then(|r| r.metrics.get(m).copied().flatten())
    };
    Some(
        (0..metrics)
            .map(|m| {
                (0..names.len())
                    .map(|p| {
                        let m0 = value(0, m).filter(|v| *v != 0.0)?;
                        let lo = value(1 + 2 * p, m)?;
                        let hi = value(2 + 2 * p, m)?;
                        let low = (lo - m0) / m0 / -delta;
                        let high = (hi - m0) / m0 / delta;
                        let central = (hi - lo) / (2.0 * delta * m0);
                        Some((low, high, central))
                    })
                    .collect()
            })
            .collect(),
    )
}

/// The parameter values (`v_bat = 16`) that every run out of its limits shares and some run
/// within them does not: where a worst case lives.
pub fn shared_by_failing(names: &[String], rows: &[&Row]) -> Vec<String> {
    let failing: Vec<&&Row> = rows.iter().filter(|r| r.pass == Some(false)).collect();
    let Some(first) = failing.first() else {
        return Vec::new();
    };
    names
        .iter()
        .enumerate()
        .filter_map(|(p, name)| {
            let value = first.values.get(p)?;
            let all = failing.iter().all(|r| r.values.get(p) == Some(value));
            let telling = rows
                .iter()
                .any(|r| r.pass == Some(true) && r.values.get(p) != Some(value));
            (all && telling).then(|| format!("{name} = {value}"))
        })
        .collect()
}

/// A number for a table: 4 significant digits.
pub fn short(x: f64) -> String {
    if x == 0.0 {
        return "0".into();
    }
    let a = x.abs();
    if (1e-3..1e5).contains(&a) {
        let decimals = (3 - a.log10().floor() as i32).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.3e}")
    }
}

/// The summary printed at the end of a sweep.
pub fn summary(plan: &Plan, metrics: &[Metric], rows: &[Row]) -> String {
    let metric_names: Vec<String> = metrics.iter().map(|m| m.name.clone()).collect();
    let mut out = String::new();
    let counted: Vec<&Row> = rows.iter().filter(|r| plan.is_sample(r.index)).collect();
    let failed: Vec<&Row> = rows.iter().filter(|r| r.status == Status::Failed).collect();
    let _ = writeln!(
        out,
        "{} runs: {} ok, {} failed",
        rows.len(),
        rows.len() - failed.len(),
        failed.len()
    );
    if !metric_names.is_empty() {
        let _ = writeln!(
            out,
            "{:<16} {:>6} {:>11} {:>11} {:>11} {:>7} {:>11} {:>7} {:>8}",
            "metric", "runs", "mean", "sigma", "min", "(run)", "max", "(run)", "failing"
        );
        for (m, name) in metric_names.iter().enumerate() {
            // Runs out of this metric's limits, or without a value where it has limits.
            let failing = match metrics[m].limit {
                l if l.min.is_none() && l.max.is_none() => "-".to_string(),
                _ => counted
                    .iter()
                    .filter(|r| r.metrics[m].is_none_or(|v| metrics[m].check(v) == Some(false)))
                    .count()
                    .to_string(),
            };
            match metric_stats(name, &counted, m) {
                Some(s) => {
                    let _ = writeln!(
                        out,
                        "{:<16} {:>6} {:>11} {:>11} {:>11} {:>7} {:>11} {:>7} {:>8}",
                        name,
                        s.count,
                        short(s.mean),
                        short(s.sigma),
                        short(s.min.0),
                        s.min.1,
                        short(s.max.0),
                        s.max.1,
                        failing
                    );
                }
                None => {
                    let _ = writeln!(out, "{name:<16} {:>6}   (no run gave a value)", 0);
                }
            }
        }
    }
    let judged: Vec<&&Row> = counted.iter().filter(|r| r.pass.is_some()).collect();
    if !judged.is_empty() {
        let passed = judged.iter().filter(|r| r.pass == Some(true)).count();
        let _ = writeln!(
            out,
            "yield: {passed} of {} runs meet every limit ({:.1} %)",
            judged.len(),
            100.0 * passed as f64 / judged.len() as f64
        );
        if let Some(worst) = judged.iter().find(|r| r.pass == Some(false)) {
            let _ = writeln!(
                out,
                "first run out of its limits: run {} ({})",
                worst.index, worst.case
            );
        }
        let shared = shared_by_failing(&plan.names(), &counted);
        if !shared.is_empty() {
            let _ = writeln!(
                out,
                "every run out of its limits has {} (not every run within them does)",
                shared.join(", ")
            );
        }
    }
    for r in failed.iter().take(5) {
        let _ = writeln!(out, "run {} failed: {}", r.index, r.message);
    }
    if failed.len() > 5 {
        let _ = writeln!(
            out,
            "... and {} more failed runs (see the table)",
            failed.len() - 5
        );
    }
    if let (Some(s), Plan::Sensitivity { names, delta, .. }) =
        (sensitivities(plan, rows, metrics.len()), plan)
    {
        let _ = writeln!(
            out,
            "normalised sensitivities (dM/M)/(dp/p), central differences of +-{} %:",
            crate::output::csv::format_number(delta * 100.0)
        );
        let _ = write!(out, "{:<16}", "parameter");
        for name in &metric_names {
            let _ = write!(out, " {name:>12}");
        }
        out.push('\n');
        for (p, param) in names.iter().enumerate() {
            let _ = write!(out, "{param:<16}");
            for per_metric in &s {
                match per_metric[p] {
                    Some((.., c)) => {
                        let _ = write!(out, " {:>12}", short(c));
                    }
                    None => {
                        let _ = write!(out, " {:>12}", "-");
                    }
                }
            }
            out.push('\n');
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn row(index: usize, m: Option<f64>, pass: Option<bool>) -> Row {
        Row {
            index,
            case: "sample".into(),
            values: vec![],
            metrics: vec![m],
            pass,
            status: if m.is_some() {
                Status::Ok
            } else {
                Status::Failed
            },
            message: if m.is_some() {
                ""
            } else {
                "no quiescent point"
            }
            .into(),
        }
    }

    #[test]
    fn statistics_name_the_worst_runs() {
        let rows = [
            row(0, Some(1.0), Some(true)),
            row(1, Some(3.0), Some(false)),
            row(2, None, Some(false)),
            row(3, Some(2.0), Some(true)),
        ];
        let refs: Vec<&Row> = rows.iter().collect();
        let s = metric_stats("settle", &refs, 0).unwrap();
        assert_eq!((s.count, s.mean, s.sigma), (3, 2.0, 1.0));
        assert_eq!((s.min, s.max), ((1.0, 0), (3.0, 1)));
        let plan = Plan::Grid {
            names: vec![],
            values: vec![],
        };
        let metric = Metric {
            name: "settle".into(),
            kind: super::super::metric::MetricKind::Final { of: "x".into() },
            limit: super::super::metric::Limit {
                min: None,
                max: Some(2.5),
            },
        };
        let text = summary(&plan, &[metric], &rows);
        // Run 1 is above the limit and run 2 has no value.
        assert!(text.lines().nth(2).unwrap().ends_with(" 2"), "{text}");
        assert!(text.contains("4 runs: 3 ok, 1 failed"), "{text}");
        assert!(
            text.contains("yield: 2 of 4 runs meet every limit (50.0 %)"),
            "{text}"
        );
        assert!(text.contains("run 2 failed: no quiescent point"), "{text}");
    }

    #[test]
    fn the_values_every_failing_run_shares_are_named() {
        let row = |index: usize, values: [&str; 2], pass: bool| Row {
            index,
            case: "corner".into(),
            values: values.map(String::from).to_vec(),
            metrics: vec![],
            pass: Some(pass),
            status: Status::Ok,
            message: String::new(),
        };
        let rows = [
            row(0, ["9", "1"], true),
            row(1, ["16", "1"], false),
            row(2, ["16", "2"], false),
            row(3, ["16", "3"], true),
        ];
        let refs: Vec<&Row> = rows.iter().collect();
        let names = ["v_bat".to_string(), "r".to_string()];
        assert_eq!(shared_by_failing(&names, &refs), ["v_bat = 16"]);
        assert!(shared_by_failing(&names, &refs[..1]).is_empty());
    }

    #[test]
    fn sensitivities_are_normalised_central_differences() {
        let plan = Plan::Sensitivity {
            names: vec!["r".into()],
            nominal: vec![2.0],
            delta: 0.01,
        };
        // M = p^2: (dM/M)/(dp/p) = 2.
        let m = |p: f64| Some(p * p);
        let rows = [
            row(0, m(2.0), None),
            row(1, m(1.98), None),
            row(2, m(2.02), None),
        ];
        let s = sensitivities(&plan, &rows, 1).unwrap();
        let (low, high, central) = s[0][0].unwrap();
        assert!((central - 2.0).abs() < 1e-9, "{central}");
        assert!((low - 1.99).abs() < 1e-9 && (high - 2.01).abs() < 1e-9);
    }
}
