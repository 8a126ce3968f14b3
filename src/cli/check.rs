//! `vams check FILES|DIRS...`: reads the given sources (a directory means its `.vhd`, `.vhdl`
//! and `.ams` files, recursively) together with the bundled stdlib, and reports every
//! diagnostic with file, line, column and a help line. Exit 0 when clean, 1 on any error.
//!
//! Today this runs the lexer and the parser; semantic analysis is the next stage to plug in.

use std::path::PathBuf;

use clap::Args;
use miette::Report;

use super::error::CliError;
use super::load::load;

/// Arguments of `vams check`.
#[derive(Debug, Args)]
pub struct CheckArgs {
    /// Source files or directories.
    #[arg(required = true)]
    pub paths: Vec<PathBuf>,
    /// Show at most this many diagnostics per file.
    #[arg(long, default_value_t = 20)]
    pub max_errors: usize,
}

/// Runs the check; every diagnostic goes to stderr.
pub fn run(args: &CheckArgs) -> Result<(), Report> {
    let loaded = load(&args.paths)?;
    loaded.print_syntax_errors(args.max_errors);
    let count = loaded.error_count();
    if count > 0 {
        return Err(CliError::CheckFailed { count }.into());
    }
    eprintln!(
        "checked {} file(s), {} design unit(s): no errors",
        loaded.sources.len(),
        loaded.unit_count()
    );
    Ok(())
}
