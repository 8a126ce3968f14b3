//! `vams fit`: the command line of [`crate::app::fit`]: its arguments, and the results
//! printed.

use crate::app::compile::{Prepared, unknown_probe_help};
use crate::app::fit::experiment::{Match, Measured};
use crate::app::fit::simulate::{DesignSimulator, Setup};
use crate::app::fit::*;
use crate::app::render::render_located;
use crate::capture::ReadOptions;
use crate::cli::args::DesignArgs;
use crate::cli::args::PlotFormat;
use crate::cli::compile::prepare;
use crate::fit::{Fit, FreeParam, Series, Settings};
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

/// Runs `vams fit`.
pub fn run(args: &FitArgs) -> Result<(), Report> {
    let started = Instant::now();
    let parsed = parse(args)?;
    let (series, driven) = load_series(&parsed, args.points as usize)?;
    let prepared: Prepared = prepare(&args.design)?;
    let setups: Vec<Setup> = parsed
        .measured
        .iter()
        .enumerate()
        .map(|(e, m)| {
            let mut generics = m.generics.clone();
            generics.extend(driven[e].iter().cloned());
            Setup::new(
                m.top.clone().unwrap_or_else(|| prepared.top.clone()),
                generics,
                e,
                &series,
            )
        })
        .collect();
    let jobs = crate::app::parallel::threads(args.jobs);
    let sim = DesignSimulator {
        prepared: &prepared,
        setups,
        names: parsed
            .params
            .iter()
            .map(|p| (p.name.clone(), p.experiment))
            .collect(),
        reltol: args.reltol,
        abstol: args.abstol,
        max_step: args.max_step,
        jobs,
    };
    check_design(&sim, &parsed)?;
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

/// The arguments checked and parsed.
struct Parsed {
    params: Vec<FreeParam>,
    measured: Vec<Measured>,
    drives: Vec<(String, String)>,
    matches: Vec<Match>,
    read: ReadOptions,
}

fn parse(args: &FitArgs) -> Result<Parsed, FitCliError> {
    let measured = args
        .measured
        .iter()
        .map(|m| Measured::parse(m))
        .collect::<Result<Vec<_>, _>>()?;
    let mut params: Vec<FreeParam> = Vec::new();
    let each = args.free_each.iter().map(|f| (f, true));
    for (f, each) in args.free.iter().map(|f| (f, false)).chain(each) {
        let p = FreeParam::parse(f).map_err(|e| FitCliError::Free(e.to_string()))?;
        if params.iter().any(|q| q.name == p.name) {
            return Err(FitCliError::Free(format!("`{}` is given twice", p.name)));
        }
        if each {
            // One copy per experiment, each set only in its own simulations.
            params.extend((0..measured.len()).map(|e| FreeParam {
                experiment: Some(e),
                ..p.clone()
            }));
        } else {
            params.push(p);
        }
    }
    for m in &measured {
        if let Some((name, _)) = m
            .generics
            .iter()
            .find(|(g, _)| params.iter().any(|p| &p.name == g))
        {
            return Err(FitCliError::FreeAndFixed {
                name: name.clone(),
                capture: m.name(),
            });
        }
    }
    let matches = args
        .matches
        .iter()
        .map(|m| experiment::parse_match(m))
        .collect::<Result<Vec<_>, _>>()?;
    let scales = args
        .scale
        .iter()
        .map(|s| experiment::parse_scale(s))
        .collect::<Result<Vec<_>, _>>()?;
    let drives = args
        .drive
        .iter()
        .map(|d| experiment::parse_drive(d))
        .collect::<Result<Vec<_>, _>>()?;
    if let Some((g, _)) = drives
        .iter()
        .find(|(g, _)| params.iter().any(|p| &p.name == g))
    {
        return Err(FitCliError::FreeAndFixed {
            name: g.clone(),
            capture: "--drive".into(),
        });
    }
    Ok(Parsed {
        params,
        measured,
        drives,
        matches,
        read: ReadOptions {
            time_column: args.time_col.clone(),
            scales,
            ..ReadOptions::default()
        },
    })
}

/// The captures read, their warnings printed, their series, and per experiment the
/// generics of its `--drive` tables.
#[allow(clippy::type_complexity)]
fn load_series(
    p: &Parsed,
    points: usize,
) -> Result<(Vec<Series>, Vec<Vec<(String, String)>>), Report> {
    let mut series = Vec::new();
    let mut loaded = Vec::new();
    let mut driven = Vec::new();
    for (e, m) in p.measured.iter().enumerate() {
        let l = experiment::load(m, &p.read, points)?;
        for w in &l.capture.warnings {
            eprintln!("{:?}", Report::new(w.clone()));
        }
        series.extend(experiment::series(e, m, &l, &p.matches)?);
        driven.push(
            (p.drives.iter())
                .map(|d| experiment::drive_generic(&l, d))
                .collect::<Result<Vec<_>, _>>()?,
        );
        loaded.push(l);
    }
    // Every matched column must be in some capture.
    for mt in &p.matches {
        if !series.iter().any(|s| {
            s.simulated == mt.quantity && loaded[s.experiment].capture.channel(&mt.column).is_some()
        }) {
            let available: Vec<String> = loaded
                .iter()
                .flat_map(|l| l.capture.channels.iter().map(|c| c.name.clone()))
                .collect();
            // Suggested by the rule that finds channels (`1` is `CH1`, `ch3` is not `ch1`).
            let help =
                match crate::capture::closest(&mt.column, available.iter().map(String::as_str)) {
                    Some(n) => format!("did you mean `{n}`?"),
                    None => format!("the captures' columns are {}", available.join(", ")),
                };
            return Err(FitCliError::NoColumn {
                quantity: mt.quantity.clone(),
                column: mt.column.clone(),
                help,
            }
            .into());
        }
    }
    Ok((series, driven))
}

/// Elaborates each experiment at the guesses: a generic the design lacks or a matched quantity
/// it does not have is reported here, at its source, not as a failure of every simulation.
fn check_design(sim: &DesignSimulator, p: &Parsed) -> Result<(), Report> {
    let guesses: Vec<f64> = p.params.iter().map(|q| q.guess).collect();
    for (e, setup) in sim.setups.iter().enumerate() {
        let design = match sim
            .prepared
            .try_elaborate_top(&setup.top, &sim.generics(e, &guesses))
        {
            Ok(d) => d,
            Err(errors) => {
                for err in &errors {
                    eprint!("{}", render_located(err, &sim.prepared.loaded.sources));
                }
                return Err(crate::app::error::CliError::Elaboration {
                    count: errors.len(),
                }
                .into());
            }
        };
        for probe in &setup.probes {
            let Some(help) = unknown_probe_help(&design, probe) else {
                continue;
            };
            return Err(FitCliError::NoQuantity {
                top: setup.top.clone(),
                name: probe.clone(),
                help,
            }
            .into());
        }
    }
    Ok(())
}
