//! `vams ac`: the command line of [`crate::app::ac`]: its arguments, and the results
//! printed.

use crate::app::ac::{format_csv, linearise, probes, respond};
use crate::app::ac_assert::{AcAssertion, assertion_probes, check_assertions};
use crate::app::compile::discard_at_exit;
use crate::app::error::CliError;
use crate::cli::args::{DesignArgs, FrequencyArgs, csv_path, plot_path};
use crate::cli::compile::{compile, not_linearised};
use crate::cli::output::write_text;
use crate::output::bode::{BodeTrace, plot_bode};
use crate::solver::ac::{db, degrees};
use clap::Args;
use miette::Report;
use std::path::PathBuf;
use std::time::Instant;

/// Arguments of `vams ac`.
#[derive(Debug, Args)]
#[command(after_help = "Examples:
  vams ac rc.vhd --from 1Hz --to 1MHz --probe vout -o rc.csv --plot rc.svg
  vams ac filters/ --top tb_rlc --from 100Hz --to 100kHz --points-per-decade 100 --probe vc
  vams ac rc.vhd --from 1kHz --to 2kHz --linear 11 --complex

The stimulus is the design's spectral source quantities, `quantity ac_in : real spectrum
magnitude, phase;` (phase in radians; both may call `frequency`), zero outside the frequency
domain. Frequencies: a number of hertz (1e3) or a number and Hz, kHz, MHz, GHz, THz or mHz
(100Hz, 2.5 kHz, 1MHz).")]
pub struct AcArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    #[command(flatten)]
    pub sweep: FrequencyArgs,
    /// Write the response to FILE (.csv): `frequency`, then per probe `NAME_db` and
    /// `NAME_deg` (or `NAME_re` and `NAME_im` with --complex). Default: standard output.
    #[arg(short = 'o', long = "out", value_name = "FILE", value_parser = csv_path)]
    pub output: Option<PathBuf>,
    /// Draw a Bode plot to FILE (.svg or .png): magnitude and phase over a log frequency axis.
    #[arg(long, value_name = "FILE", value_parser = plot_path)]
    pub plot: Option<PathBuf>,
    /// Report this quantity (hierarchical name, e.g. dut.vout); repeatable. Default: every
    /// quantity but the spectral and noise sources.
    #[arg(long, value_name = "NAME")]
    pub probe: Vec<String>,
    /// Write real and imaginary parts instead of magnitude (dB) and phase (degrees).
    #[arg(long)]
    pub complex: bool,
    /// Check the response (repeatable; exit 1 when one fails): `gain_db(vout, 1kHz) > -3.1`,
    /// `gain(vout, 10Hz) >= 0.99`, `phase_deg(vout, 1kHz) < -40`, each solved at exactly its
    /// frequency.
    #[arg(long = "assert", value_name = "EXPR")]
    pub assertions: Vec<String>,
}

/// Runs `vams ac`.
pub fn run(args: &AcArgs) -> Result<(), Report> {
    let started = Instant::now();
    let grid = args.sweep.grid().frequencies()?;
    let compiled = compile(&args.design)?;
    let design = &compiled.design;
    if design.spectral_sources.is_empty() {
        return Err(CliError::NoSpectralSource {
            top: design.top.clone(),
        }
        .into());
    }
    let probes = probes(design, &args.probe)?;
    let assertions = (args.assertions.iter())
        .map(|text| AcAssertion::parse(text))
        .collect::<Result<Vec<_>, _>>()?;
    let assertion_probes = assertion_probes(design, &assertions)?;
    let mut linearised = linearise(design, &compiled.loaded.sources).map_err(not_linearised)?;
    let response = respond(&design.top, &mut linearised, &probes, grid)?;
    let names: Vec<&str> = (probes.iter())
        .map(|q| design.quantities[q.index()].name.as_str())
        .collect();
    let csv = format_csv(&names, &response, args.complex);
    let mut written: Vec<String> = write_text(args.output.as_deref(), &csv)?
        .into_iter()
        .collect();
    if let Some(path) = &args.plot {
        let traces: Vec<BodeTrace> = (names.iter().zip(&response.values))
            .map(|(name, column)| BodeTrace {
                name: name.to_string(),
                points: (response.frequencies.iter().zip(column))
                    .map(|(&f, &z)| (f, db(z), degrees(z)))
                    .collect(),
            })
            .collect();
        plot_bode(path, &format!("{} (AC)", design.top), &traces)?;
        written.push(path.display().to_string());
    }
    let files = if written.is_empty() {
        String::new()
    } else {
        format!("; wrote {}", written.join(", "))
    };
    eprintln!(
        "analysed {} at {} frequencies from {} Hz to {} Hz in {:.2} s{files}",
        design.top,
        response.frequencies.len(),
        crate::output::csv::format_number(args.sweep.from),
        crate::output::csv::format_number(args.sweep.to),
        started.elapsed().as_secs_f64()
    );
    let verdicts = check_assertions(&design.top, &mut linearised, &assertions, &assertion_probes)?;
    discard_at_exit((compiled, linearised));
    let failed = verdicts.iter().filter(|v| !v.holds).count();
    for v in &verdicts {
        eprintln!("{}", v.line());
    }
    if failed > 0 {
        return Err(CliError::AcAssertions {
            failed,
            total: verdicts.len(),
        }
        .into());
    }
    Ok(())
}
