//! The command line: parses arguments with clap and dispatches to one subcommand.
//!
//! Takes argv; gives an exit code: 0 on success, 1 on a diagnosed error (printed by miette's
//! graphical handler), 2 on a usage error (clap's). Each subcommand keeps its arguments and
//! its run function in `cli/<name>.rs`; nothing here knows what a subcommand computes.

pub mod check;
pub mod extract;

use clap::{Parser, Subcommand};
use std::process::ExitCode;

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
    /// Extract DC motor parameters from four oscilloscope captures (inrush, blocked rotor,
    /// constant speed, coast), the paper's way and refined by a joint fit.
    Extract(extract::ExtractArgs),
}

/// Parses the command line, runs the subcommand, prints any error; returns the exit code.
pub fn run() -> ExitCode {
    let cli = Cli::parse();
    let result = match cli.command {
        Command::Check(args) => check::run(&args),
        Command::Extract(args) => extract::run(&args),
    };
    match result {
        Ok(()) => ExitCode::SUCCESS,
        Err(report) => {
            eprintln!("{report:?}");
            ExitCode::from(1)
        }
    }
}
