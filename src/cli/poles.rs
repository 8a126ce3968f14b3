//! `vams poles`: the command line of [`crate::app::poles`]: its arguments, and the results
//! printed.

use crate::app::ac::linearise;
use crate::app::compile::discard_at_exit;
use crate::app::poles::{format_poles, format_zeros, poles_of, zeros_of};
use crate::cli::args::DesignArgs;
use crate::cli::compile::{compile, not_linearised};
use clap::Args;
use miette::Report;

#[derive(Debug, Args)]
#[command(after_help = "Examples:
  vams poles models/dc_motor.vhd tests/analog/motor_step.vhd --top motor_step
  vams poles tests/ac/rlc_series.vhd

  vams poles tests/ac/rc_lowpass.vhd --input ac_in --output ir

Each pole s (1/s) with its natural frequency |s| / 2 pi, its damping ratio -Re(s) / |s| and,
when it decays, its time constant -1 / Re(s). A conjugate pair is one line (+-). Spectral
sources need not be declared, except as the --input of the zeros, the values of s where the
response from --input to --output vanishes.")]
pub struct PolesArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    /// Also list the transmission zeros from this spectral source quantity to --output.
    #[arg(long, value_name = "SOURCE", requires = "output")]
    pub input: Option<String>,
    /// The quantity whose zeros from --input are listed (hierarchical name, e.g. dut.vout).
    #[arg(long, value_name = "NAME", requires = "input")]
    pub output: Option<String>,
}

pub fn run(args: &PolesArgs) -> Result<(), Report> {
    let compiled = compile(&args.design)?;
    let design = &compiled.design;
    let linearised = linearise(design, &compiled.loaded.sources).map_err(not_linearised)?;
    let poles = poles_of(design, &linearised)?;
    print!(
        "{}",
        format_poles(&design.top, poles.unknowns, &poles.finite, poles.infinite)
    );
    if let (Some(input), Some(output)) = (&args.input, &args.output) {
        let zeros = zeros_of(design, &linearised, &poles, input, output)?;
        print!(
            "{}",
            format_zeros(&zeros.input, &zeros.output, &zeros.finite, zeros.infinite)
        );
    }
    discard_at_exit((compiled, linearised));
    Ok(())
}
