//! `vams run`: the command line of [`crate::app::run`]: its arguments, and the results
//! printed.

use crate::app::compile::discard_at_exit;
use crate::app::error::CliError;
use crate::app::render::{format_report, render_sim_error};
use crate::app::run::{probe_list, stats_table, summary};
use crate::app::stop::{declaring_file, panel_comments, stop_time};
use crate::app::time::{format_time, parse_positive_time};
use crate::cli::args::DesignArgs;
use crate::cli::args::{output_path, plot_path, positive_number};
use crate::cli::compile::{compile, fail};
use crate::cli::progress::ProgressBar;
use crate::kernel::{Outcome, SimError, SimOptions, simulate_into};
use crate::output::stream::{PlotRequest, Request, StreamError, Streams};
use clap::Args;
use miette::Report;
use std::path::PathBuf;
use std::time::Instant;

/// Arguments of `vams run`.
#[derive(Debug, Args)]
#[command(after_help = "Examples:
  vams run models/ --top tb_tracking -o tracking.csv --plot tracking.svg
  vams run models/ --top tb_overvoltage --params models/headlight.params -g r=5.0 \\
      --probe v_supply --probe v_motor --probe ov --plot ov.png
  vams run rc.vhd --stop 10ms -o rc.vcd --stats

Times: a number of seconds (1e-3) or a number and a unit: fs, ps, ns, us, ms, s or sec, min,
hr (6s, 6 sec, 10 ms, 2.5 us).")]
pub struct RunArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    /// Simulated time to stop at; default: the comment `-- vams: stop TIME` in the file that
    /// declares the top entity (a SPICE deck's: its `.tran` TSTOP).
    #[arg(long, value_name = "TIME", value_parser = parse_positive_time)]
    pub stop: Option<f64>,
    /// Write the waveforms to FILE, by extension: .csv (time and one column per probe) or .vcd
    /// (for GTKWave, Surfer; 1 fs resolution). Written as the run goes. Repeatable.
    #[arg(short = 'o', long = "out", value_name = "FILE", value_parser = output_path)]
    pub outputs: Vec<PathBuf>,
    /// Plot the waveforms to FILE (.svg or .png): stacked panels on a shared time axis.
    #[arg(long, value_name = "FILE", value_parser = plot_path)]
    pub plot: Option<PathBuf>,
    /// Relative tolerance of the analog solver: the run's error, not each step's, stays
    /// within a few times this fraction of each quantity's size [default: 1e-3, or a SPICE
    /// deck's `.options reltol`].
    #[arg(long, value_name = "X", value_parser = positive_number)]
    pub reltol: Option<f64>,
    /// A relative tolerance by name, instead of --reltol: draft (1e-2), default (1e-3) or
    /// fine (1e-6). On a mass-spring-damper over six periods the largest error is 1.9 %,
    /// 0.39 % and 6.9e-6 of the final displacement, with 126, 174 and 503 steps.
    #[arg(long, value_enum, conflicts_with = "reltol")]
    pub accuracy: Option<Accuracy>,
    /// Absolute tolerance for every unknown (default: per tolerance group, or a SPICE deck's
    /// `.options abstol` for its currents).
    #[arg(long, value_name = "X", value_parser = positive_number)]
    pub abstol: Option<f64>,
    /// Largest analog time step (default: a SPICE deck's `.tran` TMAX).
    #[arg(long, value_name = "TIME", value_parser = parse_positive_time)]
    pub max_step: Option<f64>,
    /// Highest order of the variable-order BDF integrator, 1 (backward Euler: first order,
    /// damps everything) to 5 (fewest steps for smooth waveforms at tight tolerances).
    #[arg(long, value_name = "N", default_value_t = 5, value_parser = clap::value_parser!(u8).range(1..=5))]
    pub max_order: u8,
    /// Solve for every unknown of the model, without eliminating those an equation gives
    /// explicitly (slower; to compare, or to debug a model).
    #[arg(long)]
    pub keep_unknowns: bool,
    /// Record this quantity or signal (hierarchical name, e.g. dut.u_motor.i; in a SPICE
    /// deck ngspice's vectors, v(2), i(vcc)); repeatable. Default: every quantity and
    /// explicit signal (a deck's `.print` vectors).
    #[arg(long, value_name = "NAME")]
    pub probe: Vec<String>,
    /// Draw these names together in one plot panel (comma separated, repeatable, e.g.
    /// --panel vref,vfb --panel i_motor); only the named panels are drawn. Default: one panel
    /// per probe, or per unit when there are more than six probes.
    #[arg(long, value_name = "NAMES")]
    pub panel: Vec<String>,
    /// Print every solver and kernel counter at the end.
    #[arg(long)]
    pub stats: bool,
}

/// The `--panel` groups: each argument is one panel of comma-separated names.
fn panel_groups(raw: &[String]) -> Vec<Vec<String>> {
    raw.iter()
        .map(|group| {
            group
                .split(',')
                .map(|n| n.trim().to_ascii_lowercase())
                .filter(|n| !n.is_empty())
                .collect::<Vec<_>>()
        })
        .filter(|g| !g.is_empty())
        .collect()
}

/// Runs `vams run`.
pub fn run(args: &RunArgs) -> Result<(), Report> {
    let started = Instant::now();
    let compiled = compile(&args.design)?;
    let (loaded, design) = (&compiled.loaded, &compiled.design);
    let netlist = compiled.netlist.as_ref();
    let stop = match (args.stop, netlist) {
        (None, Some(deck)) => match &deck.transient {
            Some(tran) => tran.tstop,
            None => {
                let top = design.top.clone();
                return Err(CliError::NoTran { top }.into());
            }
        },
        (given, _) => stop_time(loaded, &design.top, given).map_err(fail)?,
    };
    let panels = panel_groups(&args.panel);
    // A deck's `.print` vectors are its columns unless --probe names others.
    let probes = match netlist {
        Some(deck) if args.probe.is_empty() => probe_list(&deck.outputs, &panels),
        _ => probe_list(&args.probe, &panels),
    };
    let reltol = (args.accuracy.map(Accuracy::reltol).or(args.reltol))
        .or(netlist.and_then(|d| d.reltol))
        .unwrap_or(DEFAULT_RELTOL);
    let bar = ProgressBar::for_stderr(stop);
    let options = SimOptions {
        stop,
        reltol,
        abstol: args.abstol.or(netlist.and_then(|d| d.abstol)),
        max_step: (args.max_step).or(netlist.and_then(|d| d.transient.as_ref()?.tmax)),
        max_order: usize::from(args.max_order),
        probes,
        progress: bar.as_ref().map(ProgressBar::hook),
        keep_unknowns: args.keep_unknowns,
        cancel: Some(crate::cli::interrupt::cancel_on_ctrl_c()),
    };
    let mut print = |r: &crate::kernel::Report| {
        if let Some(bar) = &bar {
            bar.clear();
        }
        eprintln!("{}", format_report(r, &loaded.sources));
    };
    // Without --panel, the testbench's own `-- vams: panel` comments lay out the plot.
    let file_panels = match declaring_file(loaded, &design.top) {
        Some(f) if panels.is_empty() => panel_comments(&loaded.sources, f),
        _ => Vec::new(),
    };
    let request = Request {
        outputs: args.outputs.clone(),
        plot: args.plot.as_ref().map(|path| PlotRequest {
            path: path.clone(),
            panels: panels.clone(),
            file_panels,
        }),
        top: design.top.clone(),
    };
    // Every output is created (as its temporary) before the run: a path that cannot be
    // written fails now, not after the simulation.
    let mut streams = Streams::create(&request).map_err(stream_error)?;
    crate::cli::interrupt::remove_on_exit(streams.temporaries());
    let result = simulate_into(design, &options, &mut streams, &mut print);
    if let Some(bar) = &bar {
        bar.clear();
    }
    let title = |partial: Option<&str>| match partial {
        Some(p) => format!("{} ({p})", design.top),
        None => format!("{} (stop {})", design.top, format_time(stop)),
    };
    let end = match result {
        Ok(end) => end,
        Err(error) => {
            if let Some(failure) = streams.take_failure() {
                streams.abandon();
                return Err(stream_error(failure));
            }
            eprint!("{}", render_sim_error(&error, &loaded.sources));
            // What the run computed before the error is kept: the waveforms up to it.
            match streams.last_time() {
                Some(last) => {
                    let why = match error {
                        SimError::Interrupted { .. } => "interrupted",
                        _ => "stopped by an error",
                    };
                    let ending = format!("{why} at t = {}", format_time(last));
                    let written = streams
                        .finish(Some(&ending), &title(Some(&ending)))
                        .map_err(stream_error)?;
                    if !written.is_empty() {
                        eprintln!(
                            "wrote the waveforms up to t = {} to {}",
                            format_time(last),
                            names(&written)
                        );
                    }
                }
                None => streams.abandon(),
            }
            crate::cli::interrupt::remove_on_exit(Vec::new());
            let top = design.top.clone();
            return Err(match error {
                SimError::Interrupted { .. } => CliError::Interrupted { top },
                _ => CliError::Simulation { top },
            }
            .into());
        }
    };
    let ending = match end.outcome {
        Outcome::Failed { time } => Some(format!(
            "stopped by an assertion of severity failure at t = {}",
            format_time(time)
        )),
        Outcome::Finished | Outcome::Stopped { .. } => None,
    };
    let written = streams
        .finish(ending.as_deref(), &title(ending.as_deref()))
        .map_err(stream_error)?;
    crate::cli::interrupt::remove_on_exit(Vec::new());
    let written: Vec<String> = written.iter().map(|p| p.display().to_string()).collect();
    eprintln!(
        "{}",
        summary(
            &design.top,
            stop,
            &end,
            started.elapsed().as_secs_f64(),
            &written
        )
    );
    if args.stats {
        eprint!("{}", stats_table(&end.stats));
    }
    let outcome = end.outcome;
    let failure = end
        .reports
        .iter()
        .rev()
        .find(|r| r.severity == crate::kernel::Severity::Failure)
        .map(|r| r.message.clone());
    discard_at_exit((compiled, end));
    if let Outcome::Failed { time } = outcome {
        let message = failure.unwrap_or_else(|| "assertion of severity failure".into());
        return Err(CliError::RunFailed {
            time: format_time(time),
            message,
        }
        .into());
    }
    Ok(())
}

/// `--reltol` when neither it, `--accuracy` nor a deck's `.options` sets it.
const DEFAULT_RELTOL: f64 = 1e-3;

/// `--accuracy`: relative tolerances by name.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Accuracy {
    /// 1e-2: a first look.
    Draft,
    /// 1e-3, as without the option.
    Default,
    /// 1e-6: for results to compare or publish.
    Fine,
}

impl Accuracy {
    pub fn reltol(self) -> f64 {
        match self {
            Accuracy::Draft => 1e-2,
            Accuracy::Default => 1e-3,
            Accuracy::Fine => 1e-6,
        }
    }
}

/// Paths for a message, comma separated.
fn names(paths: &[PathBuf]) -> String {
    let names: Vec<String> = paths.iter().map(|p| p.display().to_string()).collect();
    names.join(", ")
}

/// The command's diagnostic for an output that failed.
fn stream_error(e: StreamError) -> Report {
    match e {
        StreamError::Write { path, source } => CliError::Write {
            path: path.display().to_string(),
            reason: source.to_string(),
        }
        .into(),
        StreamError::UnknownPanel { name, recorded } => {
            CliError::UnknownPanelName { name, recorded }.into()
        }
        StreamError::Plot(e) => e.into(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn output_paths_are_checked_by_extension() {
        assert!(output_path("a.csv").is_ok() && output_path("dir/A.VCD").is_ok());
        assert!(output_path("a.txt").unwrap_err().contains(".csv or .vcd"));
        assert!(plot_path("p.png").is_ok() && plot_path("p").is_err());
        assert!(positive_number("1e-6").is_ok());
        assert!(positive_number("0").is_err() && positive_number("x").is_err());
    }

    #[test]
    fn panel_names_group_and_join_the_probes() {
        let groups = panel_groups(&["VREF, vfb".into(), "i_motor".into(), " ".into()]);
        assert_eq!(groups, [vec!["vref", "vfb"], vec!["i_motor"]]);
        assert_eq!(
            probe_list(&["vfb".into(), "OV".into()], &groups),
            ["vfb", "ov", "vref", "i_motor"]
        );
        assert!(probe_list(&[], &groups).is_empty());
    }
}
