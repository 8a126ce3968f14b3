//! `vams check`: the command line of [`crate::app::check`]: its arguments, and the results
//! printed.

use crate::app::check::{Echo, diagnose};
use crate::app::error::CliError;
use crate::cli::notes::Printed;
use clap::Args;
use miette::Report;
use std::path::PathBuf;

/// Arguments of `vams check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// Source files or directories.
    #[arg(required = true)]
    pub paths: Vec<PathBuf>,
    /// Analyse the sources under PATH into library NAME (repeatable): `--lib util=../util`
    /// for files that say `library util;`.
    #[arg(long = "lib", value_name = "NAME=PATH", value_parser = crate::app::load::parse_library)]
    pub libraries: Vec<crate::app::load::LibrarySources>,
    /// Show at most this many diagnostics per file (syntax) or per top entity.
    #[arg(long, default_value_t = 20)]
    pub max_errors: usize,
}

/// Runs the check; every diagnostic goes to stderr.
pub fn run(args: &CheckArgs) -> Result<(), Report> {
    let checked = diagnose(
        &args.paths,
        &args.libraries,
        Some(Echo {
            max: args.max_errors,
            notes: &Printed,
        }),
    )?;
    eprintln!("{}", checked.summary);
    match checked.errors {
        0 => Ok(()),
        count => Err(CliError::CheckFailed { count }.into()),
    }
}
