//! The command line: parses arguments with clap and dispatches to one subcommand.
//!
//! Takes argv; gives an exit code: 0 on success, 1 on a diagnosed error (rendered by miette,
//! plain when stderr is not a terminal), 2 on a usage error (clap's), 3 for a fit that did not
//! converge, 130 when interrupted. Each subcommand has `cli/<name>.rs`: its clap arguments,
//! turned into the application layer's options (`crate::app`), and a `run` that calls the
//! layer and prints what it gives back. Shared arguments are in `args`, the printing of
//! compile failures in `compile`, Ctrl-C in `interrupt`, the progress bar in `progress`.

pub mod ac;
pub mod args;
pub mod check;
pub mod compile;
pub mod dae;
pub mod dc;
pub mod extract;
pub mod fit;
pub mod interrupt;
pub mod lsp;
pub mod noise;
pub mod notes;
pub mod op;
pub mod output;
pub mod poles;
pub mod progress;
pub mod run;
pub mod sweep;
pub mod test;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

use crate::app::error::CliError;
use crate::app::render;

/// vams: a compiler and simulator for a practical subset of VHDL-AMS (IEEE 1076.1).
#[derive(Debug, Parser)]
#[command(name = "vams", version, about)]
pub struct Cli {
    /// What to do.
    #[command(subcommand)]
    pub command: Command,
}

/// The subcommands.
#[derive(Debug, Subcommand)]
#[allow(clippy::large_enum_variant)] // built once per run
pub enum Command {
    /// Check VHDL-AMS sources (files or directories) and report every error found.
    Check(check::CheckArgs),
    /// Simulate a design to its stop time: print its reports, write waveforms (CSV, VCD) and
    /// a plot (SVG, PNG). Exit 1 when the run fails.
    Run(run::RunArgs),
    /// Print the quiescent operating point: every quantity and signal with its unit.
    Op(op::OpArgs),
    /// Small-signal AC analysis: the frequency response of the quantities to the design's
    /// spectral sources about its quiescent point, as CSV and a Bode plot.
    Ac(ac::AcArgs),
    /// DC transfer curves: the quiescent point at each value of a swept generic, each point
    /// starting from the last, as CSV and a plot.
    Dc(dc::DcArgs),
    /// Noise analysis: the output noise spectral density at a probe from the design's noise
    /// source quantities, each source's contribution, the integrated RMS noise, and the
    /// noise referred to an input.
    Noise(noise::NoiseArgs),
    /// The natural frequencies of the design linearised about its quiescent point: poles with
    /// frequency, damping ratio and time constant.
    Poles(poles::PolesArgs),
    /// Print the analog equation system of a design (unknowns and equations with their source).
    Dae(dae::DaeArgs),
    /// Run every testbench (port-less entity named tb_* or test_*) and report pass or fail.
    Test(test::TestArgs),
    /// Design-space runs from a TOML spec: a grid, corners, Monte Carlo samples or
    /// sensitivities, on every core or as shards of a Slurm job array; metrics per run, a
    /// result table, a summary with the worst cases and the yield, envelope, histogram and
    /// tornado plots.
    Sweep(sweep::SweepArgs),
    /// Extract DC motor parameters from four oscilloscope captures (inrush, blocked rotor,
    /// constant speed, coast), the paper's way and refined by a joint fit.
    Extract(extract::ExtractArgs),
    /// Estimate generics of a testbench from measured waveforms: a joint least-squares fit of
    /// simulations to one or more captures, with 95 % intervals, correlations and a warning for
    /// what the captures do not determine.
    Fit(fit::FitArgs),
    /// Serve editors: a language server (LSP) on standard input and output, with
    /// diagnostics, hover, definitions, references, symbols, completion and testbench runs.
    Lsp(lsp::LspArgs),
}

/// Parses the command line, runs the subcommand, prints any error; returns the exit code.
pub fn run() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Check(args) => check::run(&args),
        Command::Run(args) => run::run(&args),
        Command::Op(args) => op::run(&args),
        Command::Ac(args) => ac::run(&args),
        Command::Dc(args) => dc::run(&args),
        Command::Noise(args) => noise::run(&args),
        Command::Poles(args) => poles::run(&args),
        Command::Dae(args) => dae::run(&args),
        Command::Test(args) => test::run(&args),
        Command::Sweep(args) => sweep::run(&args),
        Command::Extract(args) => extract::run(&args),
        Command::Fit(args) => fit::run(&args),
        Command::Lsp(args) => lsp::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(report) => {
            eprint!("{}", render::render(report.as_ref()));
            match report.downcast_ref::<CliError>() {
                // The shell's convention for a program stopped by SIGINT.
                Some(CliError::Interrupted { .. }) => ExitCode::from(130),
                _ if matches!(
                    report.downcast_ref::<crate::app::study::StudyError>(),
                    Some(crate::app::study::StudyError::Interrupted { .. })
                ) =>
                {
                    ExitCode::from(130)
                }
                // A fit that ran but did not converge: its result is written, and marked.
                _ if matches!(
                    report.downcast_ref::<crate::app::fit::FitCliError>(),
                    Some(crate::app::fit::FitCliError::NotConverged { .. })
                ) =>
                {
                    // 2 is clap's, for a command line it cannot parse.
                    ExitCode::from(3)
                }
                _ => ExitCode::from(1),
            }
        }
    }
}
