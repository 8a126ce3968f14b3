//! `vams extract`: the command line of [`crate::app::extract`]: its arguments, and the results
//! printed.

use crate::app::extract::{context, json, params_file, table};
use crate::app::fit::motor;
use crate::cli::args::PlotFormat;
use crate::extract::synth::{self, SynthOptions};
use crate::extract::{Columns, ExtractError, MotorParams, extract_files};
use clap::Args;
use std::path::PathBuf;

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
    /// Print JSON (keys r, l, ke, kt, j, d, tcst_motor in SI units, fitted; `ci95` and
    /// `ci95_bootstrap` their intervals) instead of a table.
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
    /// Compare at most N samples per capture in the joint fit (block means of the samples).
    #[arg(long, value_name = "N", default_value_t = 1500, value_parser = clap::value_parser!(u32).range(100..=1_000_000))]
    pub points: u32,
    /// Simulations run at once (default: the machine's cores).
    #[arg(short = 'j', long = "jobs", value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub jobs: Option<u32>,
    /// Write four example captures (a simulated 10.5 V actuator motor, the blocked rotor
    /// taken at 3 V) into DIR and stop.
    #[arg(long, value_name = "DIR", conflicts_with_all = ["inrush", "blocked", "speed", "coast"])]
    pub demo: Option<PathBuf>,
}

/// Runs `vams extract`.
pub fn run(args: &ExtractArgs) -> miette::Result<()> {
    if let Some(dir) = &args.demo {
        let caps = synth::generate(&MotorParams::example(), &SynthOptions::lab());
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
    let started = std::time::Instant::now();
    let x = extract_files([a, b, c, d], &cols, args.commutations)?;
    let jobs = crate::app::parallel::threads(args.jobs);
    let fit = motor::fit(
        &x.prepared,
        &x.paper,
        args.points as usize,
        jobs,
        1,
        args.commutations,
    )?;
    let seconds = started.elapsed().as_secs_f64();
    if args.json {
        println!("{}", json(&x, &fit, seconds));
    } else {
        print!("{}", table(&x, &fit, args.commutations, seconds));
    }
    use std::io::Write as _;
    let _ = std::io::stdout().flush();
    for w in crate::app::fit::report::warnings(&fit.fitted, &context(&fit, seconds)) {
        eprintln!("\nwarning: {w}");
    }
    if let Some(path) = &args.params {
        std::fs::write(path, params_file(&fit.motor)).map_err(|e| ExtractError::Write {
            path: path.clone(),
            what: e.to_string(),
        })?;
    }
    if let Some(dir) = &args.plot {
        let ext = match args.plot_format {
            PlotFormat::Svg => "svg",
            PlotFormat::Png => "png",
        };
        let captures: Vec<String> = motor::ROLES.iter().map(|r| r.to_string()).collect();
        crate::app::fit::plot::plots(dir, ext, &fit.fitted, &fit.series, &captures)?;
    }
    if !fit.fitted.converged() {
        return Err(crate::app::fit::FitCliError::NotConverged {
            reasons: crate::app::fit::report::unconverged_reasons(
                &fit.fitted,
                &context(&fit, seconds),
            ),
        }
        .into());
    }
    Ok(())
}
