//! `vams dc`: the command line of [`crate::app::dc`]: its arguments, and the results
//! printed.

use crate::app::compile::discard_at_exit;
use crate::app::dc::{GenericSweep, format_csv, panels, sweep_points};
use crate::app::error::CliError;
use crate::cli::args::DesignArgs;
use crate::cli::args::csv_path;
use crate::cli::args::plot_path;
use crate::cli::compile::{fail, prepare};
use crate::cli::interrupt::{cancel_on_ctrl_c, remove_on_exit};
use crate::cli::notes::Printed;
use crate::output::atomic::{commit, temp_path};
use crate::output::plot::plot_panels_over;
use clap::Args;
use miette::Report;
use std::io::Write;
use std::path::{Path, PathBuf};
use std::time::Instant;

/// Arguments of `vams dc`.
#[derive(Debug, Args)]
#[command(after_help = "Examples:
  vams dc diode.vhd --sweep vs -1 0.8 0.01 --probe id -o iv.csv --plot iv.svg
  vams dc models/ --top tb_bridge --sweep v_bat 9 16 0.5 --probe motor_v
  vams dc schmitt.vhd --sweep vin 0 5 0.05 --both-ways --probe vout --plot hyst.svg

NAME is a generic of the top entity (a source's level is usually one); an integer generic is
swept when FROM, TO and STEP are whole numbers. Each point starts from the last one's
quantities, so a model with two stable states (a Schmitt trigger) keeps its state along the
sweep and --both-ways shows its hysteresis. Signals keep the values their processes give them
at initialisation, as in `vams op`.")]
pub struct DcArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    /// The generic to sweep and its values: from FROM to TO (included) in steps of STEP.
    #[arg(long, num_args = 4, required = true, allow_negative_numbers = true,
          value_names = ["NAME", "FROM", "TO", "STEP"])]
    pub sweep: Vec<String>,
    /// GenericSweep to TO, then back to FROM (a `direction` column: 1 up, -1 down).
    #[arg(long)]
    pub both_ways: bool,
    /// Write the curves to FILE (.csv): the swept generic, then each probe. Default: standard
    /// output.
    #[arg(short = 'o', long = "out", value_name = "FILE", value_parser = csv_path)]
    pub output: Option<PathBuf>,
    /// Draw the curves to FILE (.svg or .png): a panel per probe over the swept value.
    #[arg(long, value_name = "FILE", value_parser = plot_path)]
    pub plot: Option<PathBuf>,
    /// Report this quantity or signal (hierarchical name, e.g. dut.vout); repeatable. Default:
    /// every quantity but the spectral sources.
    #[arg(long, value_name = "NAME")]
    pub probe: Vec<String>,
}

/// Runs `vams dc`.
pub fn run(args: &DcArgs) -> Result<(), Report> {
    let started = Instant::now();
    let sweep = GenericSweep::parse(&args.sweep)?;
    let prepared = prepare(&args.design)?;
    let csv = args.output.as_deref().map(Pending::create).transpose()?;
    let plot = match args.plot.as_deref().map(Pending::create).transpose() {
        Ok(p) => p,
        Err(e) => {
            if let Some(c) = &csv {
                c.abandon();
            }
            return Err(e.into());
        }
    };
    let pending: Vec<&Pending> = csv.iter().chain(plot.iter()).collect();
    remove_on_exit(pending.iter().map(|p| p.temp.clone()).collect());
    let abandon = || pending.iter().for_each(|p| p.abandon());

    let cancel = cancel_on_ctrl_c();
    let swept =
        sweep_points(&prepared, &sweep, args.both_ways, &cancel, Some(&Printed)).map_err(|e| {
            abandon();
            fail(e)
        })?;
    let ending = &swept.ending;
    // What was computed is written, whole or cut short.
    let curves = swept.curves(&args.probe).inspect_err(|_| abandon())?;
    let note = ending.as_ref().map(|(text, _)| text.as_str());
    let mut written = Vec::new();
    if curves.rows.is_empty() {
        abandon();
    } else {
        let text = format_csv(&sweep.name, &curves, args.both_ways, note);
        match &csv {
            Some(pending) => {
                std::fs::write(&pending.temp, text.as_bytes())
                    .map_err(|e| write_error(&pending.path, &e))
                    .and_then(|()| pending.commit())
                    .inspect_err(|_| abandon())?;
                written.push(pending.path.display().to_string());
            }
            None => {
                let mut stdout = std::io::stdout().lock();
                stdout
                    .write_all(text.as_bytes())
                    .and_then(|()| stdout.flush())
                    .map_err(|e| write_error(Path::new("<stdout>"), &e))?;
            }
        }
        if let Some(pending) = &plot {
            let title = match note {
                Some(n) => format!("{} (DC sweep, {n})", prepared.top),
                None => format!("{} (DC sweep)", prepared.top),
            };
            plot_panels_over(
                &pending.temp,
                &title,
                &sweep.name,
                &panels(&curves, args.both_ways),
            )
            .map_err(Report::from)
            .and_then(|()| pending.commit().map_err(Report::from))
            .inspect_err(|_| pending.abandon())?;
            written.push(pending.path.display().to_string());
        }
    }
    remove_on_exit(Vec::new());
    let files = if written.is_empty() {
        String::new()
    } else {
        format!("; wrote {}", written.join(", "))
    };
    eprintln!(
        "swept {} over {} of {} point(s) in {:.2} s{files}",
        sweep.name,
        curves.rows.len(),
        swept.planned,
        started.elapsed().as_secs_f64()
    );
    discard_at_exit(prepared);
    match swept.ending {
        Some((_, error)) => Err(error.into()),
        None => Ok(()),
    }
}

/// An output file being made: its temporary is created before the sweep (an unwritable path
/// fails before any work) and renamed over the target when complete.
struct Pending {
    path: PathBuf,
    temp: PathBuf,
}

impl Pending {
    fn create(path: &Path) -> Result<Pending, CliError> {
        let temp = temp_path(path);
        std::fs::File::create(&temp).map_err(|e| write_error(path, &e))?;
        Ok(Pending {
            path: path.to_path_buf(),
            temp,
        })
    }

    fn commit(&self) -> Result<(), CliError> {
        commit(&self.temp, &self.path).map_err(|e| write_error(&self.path, &e))
    }

    fn abandon(&self) {
        let _ = std::fs::remove_file(&self.temp);
    }
}

fn write_error(path: &Path, e: &dyn std::fmt::Display) -> CliError {
    CliError::Write {
        path: path.display().to_string(),
        reason: e.to_string(),
    }
}
