//! `vams op`: prints the quiescent operating point ([`crate::app::op`]).

use clap::Args;
use miette::Report;

use crate::app::compile::discard_at_exit;
use crate::app::error::CliError;
use crate::app::op::format_point;
use crate::app::render::render_sim_error;
use crate::kernel::{SimOptions, operating_point};

use super::args::DesignArgs;
use super::compile::compile;

/// Arguments of `vams op`.
#[derive(Debug, Args)]
#[command(after_help = "Example:\n  vams op models/ --top tb_tracking -g vref0=2.0")]
pub struct OpArgs {
    #[command(flatten)]
    pub design: DesignArgs,
}

/// Runs `vams op`.
pub fn run(args: &OpArgs) -> Result<(), Report> {
    let compiled = compile(&args.design)?;
    let point = operating_point(&compiled.design, &SimOptions::default()).map_err(|e| {
        eprint!("{}", render_sim_error(&e, &compiled.loaded.sources));
        CliError::Simulation {
            top: compiled.design.top.clone(),
        }
    })?;
    print!("{}", format_point(&compiled.design, &point));
    discard_at_exit(compiled);
    Ok(())
}
