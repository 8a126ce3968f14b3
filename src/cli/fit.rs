//! `vams fit`: the command line of [`crate::app::fit`]: its arguments, and the results
//! printed.

use crate::app::compile::Prepared;
use crate::app::fit::experiment::Measured;
use crate::app::fit::problem::{
    FitSpec, Problem, SimulationSettings, check_design, load_series, simulator,
};
use crate::app::fit::{FitCliError, plot, report};
use crate::cli::args::DesignArgs;
use crate::cli::args::PlotFormat;
use crate::cli::compile::prepare;
use crate::cli::notes::Printed;
use crate::fit::{Fit, Settings};
use clap::Args;
use miette::Report;
use std::path::PathBuf;
use std::time::Instant;

/// Arguments of `vams fit`.
#[derive(Debug, Args)]
#[command(
    after_help = "Example (two captures of one testbench, selected by a generic):\n  vams fit bench.vhd --top tb_rc \\\n      --measured step.csv:mode=0 --measured release.csv:mode=1,shift=1ms \\\n      --match vout=CH2 --free r=1e3:10:1e6 --free c=1e-6 --plot fit/"
)]
pub struct FitArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    /// A capture and its experiment: `FILE` or `FILE:KEY=VALUE,...` with `top=ENTITY`,
    /// `shift=TIME` (added to the capture's times; default: its first sample at time 0) or
    /// `trigger=CHANNEL@LEVEL` [`edge=falling`] [`at=TIME`] (the first crossing placed at
    /// `at`, default 0), `from=TIME`, `to=TIME` (capture times compared), and generics of
    /// that experiment.
    #[arg(long, value_name = "FILE[:K=V,...]", required = true)]
    pub measured: Vec<String>,
    /// A generic to estimate, with its first guess and optional bounds (repeatable):
    /// `r=8`, `r=8:1:20`, `dut.u_motor.j=1e-6:1e-8:`.
    #[arg(
        long = "free",
        value_name = "NAME=GUESS[:MIN:MAX]",
        required_unless_present = "free_each"
    )]
    pub free: Vec<String>,
    /// A generic estimated separately for each capture (repeatable), e.g. the time each
    /// capture's switch closed or its probe's offset: reported as `NAME@CAPTURE`.
    #[arg(long = "free-each", value_name = "NAME=GUESS[:MIN:MAX]")]
    pub free_each: Vec<String>,
    /// A quantity or signal of the testbench compared with a column of the captures
    /// (repeatable): `dut.i=current`.
    #[arg(long = "match", value_name = "QUANTITY=COLUMN", required = true)]
    pub matches: Vec<String>,
    /// Drive an input of the testbench from a column of each capture (repeatable): the
    /// `real_vector` generic GENERIC gets the column as a `vams.tables.pwl` table of time
    /// (`drive=voltage`, with `vsup == pwl(drive, now);` in the testbench): every edge kept,
    /// the noise averaged where the column is flat. For an input the experiment measured
    /// rather than set: a supply that sagged, a stimulus of unknown shape.
    #[arg(long, value_name = "GENERIC=COLUMN")]
    pub drive: Vec<String>,
    /// Multiply a column of the captures (repeatable): `current=0.1` for a 100 mV/A probe.
    #[arg(long, value_name = "COLUMN=FACTOR")]
    pub scale: Vec<String>,
    /// The time column of the captures (default: `time`, `x-axis`, ... or the first).
    #[arg(long, value_name = "NAME")]
    pub time_col: Option<String>,
    /// Compare at most N samples per capture (block means of the samples).
    #[arg(long, value_name = "N", default_value_t = 2000, value_parser = clap::value_parser!(u32).range(16..=10_000_000))]
    pub points: u32,
    /// The simulations' relative tolerance (tight: differences of simulations are the
    /// sensitivities).
    #[arg(long, default_value_t = 1e-6)]
    pub reltol: f64,
    /// The simulations' absolute tolerance.
    #[arg(long)]
    pub abstol: Option<f64>,
    /// The simulations' largest time step, e.g. `1us`.
    #[arg(long, value_name = "TIME", value_parser = crate::app::time::parse_time)]
    pub max_step: Option<f64>,
    /// Simulations run at once (default: the machine's cores).
    #[arg(short = 'j', long = "jobs", value_name = "N", value_parser = clap::value_parser!(u32).range(1..=1024))]
    pub jobs: Option<u32>,
    /// Seed of the bootstrap.
    #[arg(long, default_value_t = 1)]
    pub seed: u64,
    /// Print JSON instead of the table.
    #[arg(long)]
    pub json: bool,
    /// Write the fitted values as `name=value` lines (for `vams run --params`).
    #[arg(long, value_name = "FILE")]
    pub write_params: Option<PathBuf>,
    /// Draw each capture with the fitted simulation and the residual into DIR.
    #[arg(long, value_name = "DIR")]
    pub plot: Option<PathBuf>,
    /// Picture format of --plot.
    #[arg(long, value_enum, default_value = "svg")]
    pub plot_format: PlotFormat,
}

impl FitArgs {
    /// The problem's text, as the application layer takes it.
    fn spec(&self) -> FitSpec {
        FitSpec {
            measured: self.measured.clone(),
            free: self.free.clone(),
            free_each: self.free_each.clone(),
            matches: self.matches.clone(),
            drive: self.drive.clone(),
            scale: self.scale.clone(),
            time_col: self.time_col.clone(),
        }
    }
}

/// Runs `vams fit`.
pub fn run(args: &FitArgs) -> Result<(), Report> {
    let started = Instant::now();
    let parsed = Problem::parse(&args.spec())?;
    let (series, driven) = load_series(&parsed, args.points as usize, &Printed)?;
    let prepared: Prepared = prepare(&args.design)?;
    let settings = SimulationSettings {
        reltol: args.reltol,
        abstol: args.abstol,
        max_step: args.max_step,
        jobs: crate::app::parallel::threads(args.jobs),
    };
    let sim = simulator(&prepared, &parsed, &series, &driven, settings);
    check_design(&sim, &parsed, &Printed)?;
    let fit = Fit {
        simulator: &sim,
        params: &parsed.params,
        series: &series,
        experiments: parsed.measured.len(),
        settings: Settings::default(),
        seed: args.seed,
    };
    let fitted = fit.run().map_err(|e| FitCliError::Failed {
        message: e.to_string(),
    })?;
    let captures: Vec<String> = parsed.measured.iter().map(Measured::name).collect();
    let context = report::Context {
        params: &parsed.params,
        series: &series,
        captures: &captures,
        seconds: started.elapsed().as_secs_f64(),
    };
    if args.json {
        println!("{}", report::json(&fitted, &context));
    } else {
        print!("{}", report::table(&fitted, &context));
    }
    // The table first, then what to beware of (both go to a terminal in this order).
    use std::io::Write as _;
    let _ = std::io::stdout().flush();
    for w in report::warnings(&fitted, &context) {
        eprintln!("\nwarning: {w}");
    }
    if let Some(path) = &args.write_params {
        std::fs::write(path, report::params_file(&fitted, &context)).map_err(|e| {
            FitCliError::Write {
                path: path.clone(),
                what: e.to_string(),
            }
        })?;
    }
    if let Some(dir) = &args.plot {
        let ext = match args.plot_format {
            PlotFormat::Svg => "svg",
            PlotFormat::Png => "png",
        };
        for path in plot::plots(dir, ext, &fitted, &series, &captures)? {
            eprintln!("wrote {}", path.display());
        }
    }
    if !fitted.converged() {
        return Err(FitCliError::NotConverged {
            reasons: report::unconverged_reasons(&fitted, &context),
        }
        .into());
    }
    Ok(())
}
