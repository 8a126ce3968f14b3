//! `vams poles`: the command line of [`crate::app::poles`]: its arguments, and the results
//! printed.

use crate::app::ac::{Linearised, linearise, probes};
use crate::app::compile::discard_at_exit;
use crate::app::error::CliError;
use crate::app::poles::*;
use crate::cli::args::DesignArgs;
use crate::cli::compile::{compile, not_linearised};
use crate::solver::poles::{poles, zeros};
use clap::Args;
use faer::c64;
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
    let model = &linearised.model;
    let (finite, infinite) = poles(&model.system).map_err(|e| CliError::Poles {
        top: design.top.clone(),
        reason: e.to_string(),
    })?;
    print!(
        "{}",
        format_poles(&design.top, model.system.n, &finite, infinite)
    );
    if let (Some(input), Some(output)) = (&args.input, &args.output) {
        let (input_name, output_name) = (input.trim().to_ascii_lowercase(), output.trim());
        let source = (design.spectral_sources.iter())
            .position(|s| design.quantities[s.quantity.index()].name == input_name);
        let injection = source.and_then(|k| model.spectral_injection(k));
        let Some(injection) = injection else {
            let names: Vec<&str> = (design.spectral_sources.iter())
                .map(|s| design.quantities[s.quantity.index()].name.as_str())
                .collect();
            return Err(CliError::ZerosInput {
                name: input.clone(),
                sources: if names.is_empty() {
                    "none: declare one, e.g. `quantity ac_in : real spectrum 1.0, 0.0;`".into()
                } else {
                    names.join(", ")
                },
            }
            .into());
        };
        let probe = probes(design, &[output_name.to_string()])?;
        let Linearised {
            system, x, xdot, ..
        } = &linearised;
        let terms = (probe.first())
            .and_then(|&q| system.linear_output(q, x, xdot))
            .unwrap_or_default();
        let (zeros, at_infinity) =
            zeros(&linearised.model.system, injection, &terms).map_err(|e| CliError::Poles {
                top: design.top.clone(),
                reason: e.to_string(),
            })?;
        // A zero at the origin (a differentiator) comes out of QZ as rounding around the
        // poles' scale.
        let scale = finite.iter().fold(1.0_f64, |m, p| m.max(p.norm()));
        let zeros: Vec<c64> = (zeros.into_iter())
            .map(|z| {
                if z.norm() <= 1e-9 * scale {
                    c64::new(0.0, 0.0)
                } else {
                    z
                }
            })
            .collect();
        print!(
            "{}",
            format_zeros(
                &input_name,
                &output_name.to_ascii_lowercase(),
                &zeros,
                at_infinity
            )
        );
    }
    discard_at_exit((compiled, linearised));
    Ok(())
}
