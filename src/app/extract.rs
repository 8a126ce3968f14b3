//! `vams extract`: arguments, and the run that reads captures, extracts, and writes the
//! table, `--json`, `--params` and `--plot` outputs. `--demo DIR` writes example captures.

use crate::app::fit::motor::MotorFit;
use crate::extract::{Estimate, Extraction, MotorParams};
use std::fmt::Write as _;

pub fn context(fit: &MotorFit, seconds: f64) -> crate::app::fit::report::Context<'_> {
    crate::app::fit::report::Context {
        params: &fit.params,
        series: &fit.series,
        captures: &fit.captures,
        seconds,
    }
}

const UNITS: [&str; 7] = ["ohm", "H", "V s/rad", "N m/A", "kg m^2", "N m s/rad", "N m"];
const ROLES: [&str; 4] = ["inrush", "blocked", "speed", "coast"];
const RESIDUAL_UNITS: [&str; 4] = ["A", "A", "A", "V"];

fn paper_values(x: &Extraction) -> [Estimate; 7] {
    let p = &x.paper;
    [p.r, p.l, p.ke, p.kt, p.j, p.d, p.tcst_motor]
}

fn cell(value: f64, se: f64) -> String {
    let rel = 100.0 * se / value.abs().max(1e-300);
    if rel.is_finite() {
        format!("{value:.4e} ± {rel:.2} %")
    } else {
        format!("{value:.4e}")
    }
}

/// The fitted motor parameter `k` (in [`MotorParams::NAMES`] order; kt is ke) and its
/// estimate of the fit.
fn estimate(fit: &MotorFit, k: usize) -> &crate::fit::Estimate {
    // r l ke kt j d tcst -> the fit's r l ke j d tcst.
    let index = [0, 1, 2, 2, 3, 4, 5][k];
    &fit.fitted.estimates[index]
}

fn interval(r: Option<(f64, f64)>) -> String {
    r.map_or_else(
        || "-".to_string(),
        |(lo, hi)| format!("{lo:.4e} .. {hi:.4e}"),
    )
}

/// The table for people.
pub fn table(x: &Extraction, fit: &MotorFit, commutations: u32, seconds: f64) -> String {
    let mut s = String::new();
    let se = fit.se();
    let _ = writeln!(
        s,
        "DC motor parameters ({commutations} commutations per revolution)\n"
    );
    let _ = writeln!(
        s,
        "{:<11} {:<24} {:<24} {:<25} {:<25} unit",
        "parameter",
        "paper's method",
        "joint fit (dc_motor)",
        "95 % (covariance)",
        "95 % (with model error)"
    );
    let fitted = fit.motor.values();
    for (k, e) in paper_values(x).iter().enumerate() {
        let est = estimate(fit, k);
        let _ = writeln!(
            s,
            "{:<11} {:<24} {:<24} {:<25} {:<25} {}",
            MotorParams::NAMES[k],
            cell(e.value, e.se),
            cell(fitted[k], se[k]),
            interval(est.interval),
            interval(est.robust),
            UNITS[k]
        );
    }
    let bench = |name: &str, e: usize| {
        fit.params
            .iter()
            .position(|p| p.name == name && p.experiment == Some(e))
            .map(|k| fit.fitted.estimates[k].value)
    };
    let _ = writeln!(s, "\nbench supplies (fitted with the motor)");
    for (e, role) in ROLES.iter().enumerate() {
        let vs = bench("vs", e).unwrap_or(f64::NAN);
        let rs = match bench("rs", e) {
            Some(rs) => format!("behind {rs:.4} ohm"),
            None => "(its current is constant: vs is its terminal voltage)".into(),
        };
        let _ = writeln!(s, "{role:<11} {vs:.4} V {rs}");
    }
    let _ = writeln!(
        s,
        "\nRMS residual of the simulated capture (start: the paper's values, R and L from the blocked rotor fitted alone)"
    );
    let _ = writeln!(s, "{:<11} {:>14} {:>14}", "capture", "start", "joint fit");
    for k in 0..4 {
        let f = &fit.fitted.series[fit.main_series[k]];
        let _ = writeln!(
            s,
            "{:<11} {:>12.4e} {} {:>12.4e} {}",
            ROLES[k], f.rms_start, RESIDUAL_UNITS[k], f.rms, RESIDUAL_UNITS[k]
        );
    }
    let w = x.prepared.w_cst;
    let _ = writeln!(
        s,
        "\nspeed from the ripple: {:.2} Hz -> {:.2} rad/s ({:.0} rpm); first revolution: {} commutations in {:.2} ms",
        x.prepared.ripple_hz,
        w.value,
        w.value * 60.0 / (2.0 * std::f64::consts::PI),
        x.prepared.first_rev_events.len(),
        1e3 * (x.prepared.first_rev_events.last().copied().unwrap_or(0.0)
            - x.prepared.caps[0].t[x.prepared.inrush_step]),
    );
    let _ = writeln!(
        s,
        "joint fit: {} iterations, {} simulations of models/fit/tb_motor_bench.vhd, {:.2} s",
        fit.fitted.iterations, fit.fitted.simulations, seconds
    );
    let _ = writeln!(
        s,
        "{}",
        crate::app::fit::report::status_line(&fit.fitted, &context(fit, seconds))
    );
    s
}

/// The JSON for tools: fitted values at the top level, SI units (the paper's where the fit
/// ended worse than them: `start_reported`), and the fit's status (`converged`, ...).
pub fn json(x: &Extraction, fit: &MotorFit, seconds: f64) -> String {
    let names = MotorParams::NAMES;
    let fitted = fit.motor.values();
    let se = fit.se();
    let paper = paper_values(x);
    let num = |v: f64| {
        serde_json::Number::from_f64(v).map_or(serde_json::Value::Null, serde_json::Value::Number)
    };
    let obj = |f: &dyn Fn(usize) -> serde_json::Value| -> serde_json::Value {
        serde_json::Value::Object(
            names
                .iter()
                .enumerate()
                .map(|(k, n)| (n.to_string(), f(k)))
                .collect(),
        )
    };
    let pair = |r: Option<(f64, f64)>| match r {
        Some((a, b)) => serde_json::json!([num(a), num(b)]),
        None => serde_json::Value::Null,
    };
    let rms = |start: bool| -> serde_json::Value {
        serde_json::Value::Object(
            ROLES
                .iter()
                .enumerate()
                .map(|(k, r)| {
                    let f = &fit.fitted.series[fit.main_series[k]];
                    (r.to_string(), num(if start { f.rms_start } else { f.rms }))
                })
                .collect(),
        )
    };
    let mut top = match obj(&|k| num(fitted[k])) {
        serde_json::Value::Object(m) => m,
        _ => serde_json::Map::new(),
    };
    top.insert("se".into(), obj(&|k| num(se[k])));
    top.insert("ci95".into(), obj(&|k| pair(estimate(fit, k).interval)));
    top.insert(
        "ci95_bootstrap".into(),
        obj(&|k| pair(estimate(fit, k).robust)),
    );
    top.insert("paper".into(), obj(&|k| num(paper[k].value)));
    top.insert("paper_se".into(), obj(&|k| num(paper[k].se)));
    top.insert(
        "rms_residual".into(),
        // `start`: the joint fit's start (the paper's values, R and L from the blocked rotor
        // fitted alone); `paper`, its former name, kept for scripts that read it.
        serde_json::json!({ "start": rms(true), "paper": rms(true), "refined": rms(false) }),
    );
    let bench: serde_json::Map<String, serde_json::Value> = fit
        .params
        .iter()
        .zip(&fit.fitted.estimates)
        .skip(6)
        .map(|(p, e)| {
            // Each experiment's own: `vs@speed`, `rs@blocked`, `t_on@inrush`.
            let key = match p.experiment {
                Some(k) => format!("{}@{}", p.name, ROLES[k]),
                None => p.name.clone(),
            };
            (key, num(e.value))
        })
        .collect();
    top.insert("bench".into(), serde_json::Value::Object(bench));
    top.insert("speed_rad_s".into(), num(x.prepared.w_cst.value));
    top.insert("ripple_hz".into(), num(x.prepared.ripple_hz));
    top.insert(
        "iterations".into(),
        serde_json::json!(fit.fitted.iterations),
    );
    top.insert(
        "simulations".into(),
        serde_json::json!(fit.fitted.simulations),
    );
    top.extend(crate::app::fit::report::status_json(
        &fit.fitted,
        &context(fit, seconds),
    ));
    serde_json::Value::Object(top).to_string()
}

/// `name=value` lines for the dc_motor generics (VHDL real literals).
pub fn params_file(p: &MotorParams) -> String {
    MotorParams::NAMES
        .iter()
        .zip(p.values())
        .map(|(n, v)| format!("{n}={v:.6e}\n"))
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn params_lines_are_vhdl_reals_named_as_the_generics() {
        let text = params_file(&MotorParams::example());
        let lines: Vec<&str> = text.lines().collect();
        assert_eq!(lines.len(), 7);
        assert_eq!(lines[0], "r=8.000000e0");
        assert_eq!(lines[6], "tcst_motor=3.000000e-4");
    }
}
