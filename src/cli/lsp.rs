//! `vams lsp`: starts the language server ([`crate::lsp`]) on standard input and output.

use std::time::Duration;

use clap::Args;
use miette::Report;

/// Arguments of `vams lsp`.
#[derive(Debug, Args)]
pub struct LspArgs {
    /// Analyse an edit after this many milliseconds without another one.
    #[arg(long, value_name = "MS", default_value_t = 150)]
    pub debounce: u64,
    /// Use standard input and output (the only transport; accepted because editors pass it).
    #[arg(long)]
    pub stdio: bool,
}

pub fn run(args: &LspArgs) -> Result<(), Report> {
    crate::lsp::serve_stdio(Duration::from_millis(args.debounce))?;
    Ok(())
}
