//! `vams noise`: the command line of [`crate::app::noise`]: its arguments, and the results
//! printed.

use crate::app::ac::probes;
use crate::app::compile::discard_at_exit;
use crate::app::error::CliError;
use crate::app::noise::{analyse, format_csv, format_summary, input_source};
use crate::cli::args::{DesignArgs, FrequencyArgs, csv_path, plot_path};
use crate::cli::compile::{compile, not_linearised};
use crate::cli::output::write_text;
use crate::design::QuantityId;
use crate::output::csv::format_number;
use crate::output::noise_plot::{NoiseTrace, plot_noise};
use clap::Args;
use miette::Report;
use std::path::PathBuf;
use std::time::Instant;

/// Arguments of `vams noise`.
#[derive(Debug, Args)]
#[command(after_help = "Examples:
  vams noise rc.vhd --probe vout --from 1Hz --to 1GHz -o rc_noise.csv --plot rc_noise.svg
  vams noise amp.vhd --top tb_amp --probe vout --input ac_in --from 10Hz --to 100kHz

The sources are the design's noise source quantities, `quantity vn : real noise psd;` (psd
in the quantity's units squared per hertz; it may call `frequency`), uncorrelated, zero
outside the noise analysis; spectral sources are zero during it. The CSV gives densities
(units per root hertz): the total at the probe, each source's contribution at the probe
(sqrt(|H_k|^2 S_k); the total is the root of the sum of their squares), and with --input the
input-referred density (total / |H_input|, H_input the transfer from the spectral source
quantity to the probe). The integrated noise, sqrt of the output PSD integrated over the
band by the trapezoid rule on the grid, is printed on standard output (on standard error
when the CSV goes to standard output).")]
pub struct NoiseArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    #[command(flatten)]
    pub sweep: FrequencyArgs,
    /// The output: the quantity whose noise is computed (hierarchical name, e.g. dut.vout).
    #[arg(long, value_name = "NAME")]
    pub probe: String,
    /// Refer the noise to this spectral source quantity (the amplifier's input).
    #[arg(long, value_name = "NAME")]
    pub input: Option<String>,
    /// Write the densities to FILE (.csv). Default: standard output.
    #[arg(short = 'o', long = "out", value_name = "FILE", value_parser = csv_path)]
    pub output: Option<PathBuf>,
    /// Draw the densities to FILE (.svg or .png) on log-log axes.
    #[arg(long, value_name = "FILE", value_parser = plot_path)]
    pub plot: Option<PathBuf>,
}

/// Runs `vams noise`.
pub fn run(args: &NoiseArgs) -> Result<(), Report> {
    let started = Instant::now();
    let grid = args.sweep.grid().frequencies()?;
    let compiled = compile(&args.design)?;
    let design = &compiled.design;
    if design.noise_sources.is_empty() {
        return Err(CliError::NoNoiseSource {
            top: design.top.clone(),
        }
        .into());
    }
    // One name gives one quantity or an error.
    let probe = probes(design, std::slice::from_ref(&args.probe))?[0];
    let input = args
        .input
        .as_deref()
        .map(|name| input_source(design, name))
        .transpose()?;
    let table =
        analyse(design, &compiled.loaded.sources, probe, input, grid).map_err(not_linearised)?;
    let quantity = |q: QuantityId| {
        let q = &design.quantities[q.index()];
        (q.name.as_str(), q.unit.as_deref())
    };
    let probe_named = quantity(probe);
    let source_names: Vec<&str> = (design.noise_sources.iter())
        .map(|s| quantity(s.quantity).0)
        .collect();
    let input_named = input.map(|k| quantity(design.spectral_sources[k].quantity));
    let csv = format_csv(probe_named, &source_names, input_named, &table);
    let mut written: Vec<String> = write_text(args.output.as_deref(), &csv)?
        .into_iter()
        .collect();
    if let Some(path) = &args.plot {
        let trace = |name: String, psd: &mut dyn Iterator<Item = f64>| NoiseTrace {
            name,
            points: table
                .frequencies
                .iter()
                .copied()
                .zip(psd.map(f64::sqrt))
                .collect(),
        };
        let mut traces = vec![trace(
            format!("{} (total)", probe_named.0),
            &mut table.total.iter().copied(),
        )];
        for (k, name) in source_names.iter().enumerate() {
            traces.push(trace(
                name.to_string(),
                &mut table.contributions.iter().map(|c| c[k]),
            ));
        }
        let unit = format!("{}/√Hz", probe_named.1.unwrap_or("units"));
        plot_noise(path, &format!("{} (noise)", design.top), &unit, &traces)?;
        written.push(path.display().to_string());
    }
    let summary = format_summary(probe_named, &source_names, input_named, &table);
    // Standard output carries the CSV when there is no -o: the summary must not break it.
    if args.output.is_some() {
        print!("{summary}");
    } else {
        eprint!("{summary}");
    }
    let files = if written.is_empty() {
        String::new()
    } else {
        format!("; wrote {}", written.join(", "))
    };
    eprintln!(
        "analysed the noise of {} at {} frequencies from {} Hz to {} Hz in {:.2} s{files}",
        design.top,
        table.frequencies.len(),
        format_number(args.sweep.from),
        format_number(args.sweep.to),
        started.elapsed().as_secs_f64()
    );
    discard_at_exit(compiled);
    Ok(())
}
