//! `vams extract`: arguments, and the run that reads captures, extracts, and writes the
//! table, `--json`, `--params` and `--plot` outputs. `--demo DIR` writes example captures.

use crate::extract::synth::{self, SynthOptions};
use crate::extract::{Columns, Estimate, ExtractError, Extraction, MotorParams, extract_files};
use crate::output::plot::{Panel, Trace, plot_panels};
use clap::{Args, ValueEnum};
use std::fmt::Write as _;
use std::path::{Path, PathBuf};

/// Picture format of `--plot`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum PlotFormat {
    /// Scalable vector graphics.
    Svg,
    /// Portable network graphics.
    Png,
}

/// Arguments of `vams extract`.
#[derive(Debug, Args)]
#[command(
    after_help = "Example:\n  vams extract --demo demo/\n  vams extract --inrush demo/inrush.csv --blocked demo/blocked.csv \\\n      --speed demo/speed.csv --coast demo/coast.csv --params motor.params --plot plots/"
)]
pub struct ExtractArgs {
    /// Capture a: the motor starting from rest, unloaded (with pre-trigger at 0 V).
    #[arg(long, value_name = "CSV", required_unless_present = "demo")]
    pub inrush: Option<PathBuf>,
    /// Capture b: the rotor blocked, supply on until the current is steady.
    #[arg(long, value_name = "CSV", required_unless_present = "demo")]
    pub blocked: Option<PathBuf>,
    /// Capture c: unloaded at constant speed (the current's commutation ripple gives the speed).
    #[arg(long, value_name = "CSV", required_unless_present = "demo")]
    pub speed: Option<PathBuf>,
    /// Capture d: the supply disconnected from the running motor, until it stops.
    #[arg(long, value_name = "CSV", required_unless_present = "demo")]
    pub coast: Option<PathBuf>,
    /// Name of the time column (seconds, or per the units row).
    #[arg(long, value_name = "NAME", default_value = "time")]
    pub time_col: String,
    /// Name of the voltage column (volts across the motor).
    #[arg(long, value_name = "NAME", default_value = "voltage")]
    pub voltage_col: String,
    /// Name of the current column (amperes through the motor).
    #[arg(long, value_name = "NAME", default_value = "current")]
    pub current_col: String,
    /// Current commutations per rotor revolution.
    #[arg(long, value_name = "N", default_value_t = 4, value_parser = clap::value_parser!(u32).range(1..=64))]
    pub commutations: u32,
    /// Print JSON (keys r, l, ke, kt, j, d, tcst_motor in SI units, refined) instead of a table.
    #[arg(long)]
    pub json: bool,
    /// Write `name=value` lines for `vams run --params` (the dc_motor generics).
    #[arg(long, value_name = "FILE")]
    pub params: Option<PathBuf>,
    /// Draw each capture with the fitted simulation over it into DIR.
    #[arg(long, value_name = "DIR")]
    pub plot: Option<PathBuf>,
    /// Picture format of --plot.
    #[arg(long, value_enum, default_value = "svg")]
    pub plot_format: PlotFormat,
    /// Write four example captures (a simulated 12 V actuator motor) into DIR and stop.
    #[arg(long, value_name = "DIR", conflicts_with_all = ["inrush", "blocked", "speed", "coast"])]
    pub demo: Option<PathBuf>,
}

/// Runs `vams extract`.
pub fn run(args: &ExtractArgs) -> miette::Result<()> {
    if let Some(dir) = &args.demo {
        let caps = synth::generate(&MotorParams::example(), &SynthOptions::default());
        synth::write_captures(dir, &caps).map_err(|e| ExtractError::Write {
            path: dir.clone(),
            what: e.to_string(),
        })?;
        let d = dir.display();
        println!("wrote {d}/inrush.csv, {d}/blocked.csv, {d}/speed.csv, {d}/coast.csv");
        println!(
            "try: vams extract --inrush {d}/inrush.csv --blocked {d}/blocked.csv --speed {d}/speed.csv --coast {d}/coast.csv"
        );
        return Ok(());
    }
    let (Some(a), Some(b), Some(c), Some(d)) =
        (&args.inrush, &args.blocked, &args.speed, &args.coast)
    else {
        // clap's required_unless_present makes this unreachable; stay graceful anyway.
        return Err(miette::miette!(
            "give --inrush, --blocked, --speed and --coast"
        ));
    };
    let cols = Columns {
        time: args.time_col.clone(),
        voltage: args.voltage_col.clone(),
        current: args.current_col.clone(),
    };
    let x = extract_files([a, b, c, d], &cols, args.commutations)?;
    if args.json {
        println!("{}", json(&x));
    } else {
        print!("{}", table(&x, args.commutations));
    }
    if let Some(path) = &args.params {
        std::fs::write(path, params_file(&x.refined.params)).map_err(|e| ExtractError::Write {
            path: path.clone(),
            what: e.to_string(),
        })?;
    }
    if let Some(dir) = &args.plot {
        plots(&x, dir, args.plot_format)?;
    }
    Ok(())
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

/// The table for people.
pub fn table(x: &Extraction, commutations: u32) -> String {
    let mut s = String::new();
    let refined = x.refined.params.values();
    let _ = writeln!(
        s,
        "DC motor parameters ({commutations} commutations per revolution)\n"
    );
    let _ = writeln!(
        s,
        "{:<11} {:<26} {:<26} unit",
        "parameter", "paper's method", "refined (joint fit)"
    );
    for (k, e) in paper_values(x).iter().enumerate() {
        let _ = writeln!(
            s,
            "{:<11} {:<26} {:<26} {}",
            MotorParams::NAMES[k],
            cell(e.value, e.se),
            cell(refined[k], x.refined.se[k]),
            UNITS[k]
        );
    }
    let _ = writeln!(s, "\nRMS residual of the simulated capture");
    let _ = writeln!(s, "{:<11} {:>12} {:>12}", "capture", "paper", "refined");
    for k in 0..4 {
        let _ = writeln!(
            s,
            "{:<11} {:>10.4e} {} {:>10.4e} {}",
            ROLES[k],
            x.refined.rms_start[k],
            RESIDUAL_UNITS[k],
            x.refined.rms[k],
            RESIDUAL_UNITS[k]
        );
    }
    let w = x.prepared.w_cst;
    let _ = writeln!(
        s,
        "\nspeed from the ripple: {:.2} Hz -> {:.2} rad/s ({:.0} rpm); first revolution: {} commutations in {:.2} ms; {} LM iterations",
        x.prepared.ripple_hz,
        w.value,
        w.value * 60.0 / (2.0 * std::f64::consts::PI),
        x.prepared.first_rev_events.len(),
        1e3 * (x.prepared.first_rev_events.last().copied().unwrap_or(0.0)
            - x.prepared.caps[0].t[x.prepared.inrush_step]),
        x.refined.iterations
    );
    s
}

/// The JSON for tools: refined values at the top level, SI units.
pub fn json(x: &Extraction) -> String {
    let names = MotorParams::NAMES;
    let refined = x.refined.params.values();
    let paper = paper_values(x);
    let obj = |f: &dyn Fn(usize) -> f64| -> serde_json::Value {
        serde_json::Value::Object(
            names
                .iter()
                .enumerate()
                .map(|(k, n)| (n.to_string(), serde_json::json!(f(k))))
                .collect(),
        )
    };
    let rms = |v: &[f64; 4]| -> serde_json::Value {
        serde_json::Value::Object(
            ROLES
                .iter()
                .zip(v)
                .map(|(r, v)| (r.to_string(), serde_json::json!(v)))
                .collect(),
        )
    };
    let mut top = match obj(&|k| refined[k]) {
        serde_json::Value::Object(m) => m,
        _ => serde_json::Map::new(),
    };
    top.insert("se".into(), obj(&|k| x.refined.se[k]));
    top.insert("paper".into(), obj(&|k| paper[k].value));
    top.insert("paper_se".into(), obj(&|k| paper[k].se));
    top.insert(
        "rms_residual".into(),
        serde_json::json!({ "paper": rms(&x.refined.rms_start), "refined": rms(&x.refined.rms) }),
    );
    top.insert(
        "speed_rad_s".into(),
        serde_json::json!(x.prepared.w_cst.value),
    );
    top.insert("ripple_hz".into(), serde_json::json!(x.prepared.ripple_hz));
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

fn plots(x: &Extraction, dir: &Path, format: PlotFormat) -> miette::Result<()> {
    std::fs::create_dir_all(dir).map_err(|e| ExtractError::Write {
        path: dir.to_path_buf(),
        what: e.to_string(),
    })?;
    let ext = match format {
        PlotFormat::Svg => "svg",
        PlotFormat::Png => "png",
    };
    for (k, cap) in x.prepared.caps.iter().enumerate() {
        let pts = |y: &[f64]| {
            cap.t
                .iter()
                .copied()
                .zip(y.iter().copied())
                .collect::<Vec<_>>()
        };
        let sim = x.refined.sim[k].clone();
        let mut panels = if k == 3 {
            vec![
                Panel::new(
                    "voltage",
                    vec![
                        Trace::analog("measured", "V", pts(&cap.v)),
                        Trace::analog("simulated", "V", sim),
                    ],
                ),
                Panel::new("current", vec![Trace::analog("measured", "A", pts(&cap.i))]),
            ]
        } else {
            vec![
                Panel::new("voltage", vec![Trace::analog("measured", "V", pts(&cap.v))]),
                Panel::new(
                    "current",
                    vec![
                        Trace::analog("measured", "A", pts(&cap.i)),
                        Trace::analog("simulated", "A", sim),
                    ],
                ),
            ]
        };
        if k == 0 && !x.prepared.first_rev_events.is_empty() {
            // Commutations of the first revolution as a toggling logic trace.
            let mut level = 0.0;
            let mut steps = vec![(cap.t[0], 0.0)];
            for &e in &x.prepared.first_rev_events {
                level = 1.0 - level;
                steps.push((e, level));
            }
            steps.push((cap.t[cap.len() - 1], level));
            panels.push(Panel::new(
                "",
                vec![Trace::logic("commutation (first revolution)", steps)],
            ));
        }
        let path = dir.join(format!("{}.{ext}", ROLES[k]));
        let title = format!(
            "{} capture `{}` and the fitted simulation",
            ROLES[k],
            cap.path.display()
        );
        plot_panels(&path, &title, &panels)?;
    }
    Ok(())
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
