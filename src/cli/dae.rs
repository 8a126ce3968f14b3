//! `vams dae`: the analog equation system of a design as text: unknowns, then each equation
//! with its source location (the analog engine's listing).

use clap::Args;
use miette::Report;

use crate::analog::AnalogSystem;

use super::args::DesignArgs;
use super::compile::compile;
use crate::app::compile::discard_at_exit;
use crate::app::error::CliError;
use crate::app::render::render_located;

/// Arguments of `vams dae`.
#[derive(Debug, Args)]
#[command(after_help = "Example:\n  vams dae models/ --top dc_motor")]
pub struct DaeArgs {
    #[command(flatten)]
    pub design: DesignArgs,
}

/// Runs `vams dae`.
pub fn run(args: &DaeArgs) -> Result<(), Report> {
    let compiled = compile(&args.design)?;
    let system = AnalogSystem::new(&compiled.design).map_err(|errors| {
        for e in &errors {
            eprint!("{}", render_located(e, &compiled.loaded.sources));
        }
        CliError::Analog {
            count: errors.len(),
        }
    })?;
    for w in system.warnings(&compiled.design) {
        eprint!("{}", render_located(&w, &compiled.loaded.sources));
    }
    print!(
        "{}",
        system.listing(&compiled.design, &compiled.loaded.sources)
    );
    discard_at_exit((compiled, system));
    Ok(())
}
