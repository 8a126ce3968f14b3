//! `vams ac`: small-signal frequency response. The quiescent point as `vams op` finds it, the
//! model linearised about it (`analog::small_signal`, on the solver's reduced system; probes
//! of eliminated quantities through their formulas' derivatives), `(G + jw C) X = B` solved at each
//! frequency (`solver::ac`), the probed quantities written as CSV (magnitude in dB and phase
//! in degrees, or real and imaginary parts) and drawn as a Bode plot.

use std::io::Write;
use std::path::PathBuf;
use std::time::Instant;

use clap::Args;
use faer::c64;
use miette::Report;

use crate::analog::{AnalogOptions, AnalogSystem, SmallSignalModel};
use crate::design::{Design, QuantityId, SignalId, SignalKind};
use crate::kernel::{SimOptions, operating_point_and_system};
use crate::output::atomic::write_atomically;
use crate::output::bode::{BodeTrace, plot_bode};
use crate::output::csv::push_number;
use crate::solver::ac::{AcSolver, Spacing, db, degrees, frequencies};

use super::ac_assert::{AcAssertion, assertion_probes, check_assertions};
use super::compile::{DesignArgs, compile, discard_at_exit};
use super::error::CliError;
use super::render::{render, render_located, render_sim_error};
use super::run::plot_path;

/// Arguments of `vams ac`.
#[derive(Debug, Args)]
#[command(after_help = "Examples:
  vams ac rc.vhd --from 1Hz --to 1MHz --probe vout -o rc.csv --plot rc.svg
  vams ac filters/ --top tb_rlc --from 100Hz --to 100kHz --points-per-decade 100 --probe vc
  vams ac rc.vhd --from 1kHz --to 2kHz --linear 11 --complex

The stimulus is the design's spectral source quantities, `quantity ac_in : real spectrum
magnitude, phase;` (phase in radians; both may call `frequency`), zero outside the frequency
domain. Frequencies: a number of hertz (1e3) or a number and Hz, kHz, MHz, GHz, THz or mHz
(100Hz, 2.5 kHz, 1MHz).")]
pub struct AcArgs {
    #[command(flatten)]
    pub design: DesignArgs,
    #[command(flatten)]
    pub sweep: SweepArgs,
    /// Write the response to FILE (.csv): `frequency`, then per probe `NAME_db` and
    /// `NAME_deg` (or `NAME_re` and `NAME_im` with --complex). Default: standard output.
    #[arg(short = 'o', long = "out", value_name = "FILE", value_parser = csv_path)]
    pub output: Option<PathBuf>,
    /// Draw a Bode plot to FILE (.svg or .png): magnitude and phase over a log frequency axis.
    #[arg(long, value_name = "FILE", value_parser = plot_path)]
    pub plot: Option<PathBuf>,
    /// Report this quantity (hierarchical name, e.g. dut.vout); repeatable. Default: every
    /// quantity but the spectral and noise sources.
    #[arg(long, value_name = "NAME")]
    pub probe: Vec<String>,
    /// Write real and imaginary parts instead of magnitude (dB) and phase (degrees).
    #[arg(long)]
    pub complex: bool,
    /// Check the response (repeatable; exit 1 when one fails): `gain_db(vout, 1kHz) > -3.1`,
    /// `gain(vout, 10Hz) >= 0.99`, `phase_deg(vout, 1kHz) < -40`, each solved at exactly its
    /// frequency.
    #[arg(long = "assert", value_name = "EXPR")]
    pub assertions: Vec<String>,
}

/// The analysis frequencies, shared by `vams ac` and `vams noise`.
#[derive(Debug, Args)]
pub struct SweepArgs {
    /// Lowest analysis frequency.
    #[arg(long, value_name = "FREQ", value_parser = parse_frequency)]
    pub from: f64,
    /// Highest analysis frequency.
    #[arg(long, value_name = "FREQ", value_parser = parse_frequency)]
    pub to: f64,
    /// Logarithmic sweep with N points per decade (the default, 20).
    #[arg(long, value_name = "N", value_parser = clap::value_parser!(u32).range(1..=100_000))]
    pub points_per_decade: Option<u32>,
    /// Linear sweep of N points, both ends included.
    #[arg(long, value_name = "N", conflicts_with = "points_per_decade",
          value_parser = clap::value_parser!(u32).range(2..=10_000_000))]
    pub linear: Option<u32>,
}

impl SweepArgs {
    /// The grid the options ask for; an error if `--to` is below `--from`.
    pub fn frequencies(&self) -> Result<Vec<f64>, CliError> {
        if self.to < self.from {
            return Err(CliError::FrequencyRange {
                from: self.from,
                to: self.to,
            });
        }
        let spacing = match self.linear {
            Some(n) => Spacing::Linear(n as usize),
            None => Spacing::PerDecade(self.points_per_decade.unwrap_or(20) as usize),
        };
        Ok(frequencies(self.from, self.to, spacing))
    }
}

/// Writes `text` to `path` atomically, or to standard output when there is none; the
/// path written, if any.
pub(super) fn write_text(
    path: Option<&std::path::Path>,
    text: &str,
) -> Result<Option<String>, CliError> {
    let write_error = |path: &std::path::Path, e: &dyn std::fmt::Display| CliError::Write {
        path: path.display().to_string(),
        reason: e.to_string(),
    };
    match path {
        Some(path) => {
            write_atomically(path, |w| w.write_all(text.as_bytes()))
                .map_err(|e| write_error(path, &e))?;
            Ok(Some(path.display().to_string()))
        }
        None => {
            let mut stdout = std::io::stdout().lock();
            stdout
                .write_all(text.as_bytes())
                .and_then(|()| stdout.flush())
                .map_err(|e| write_error(std::path::Path::new("<stdout>"), &e))?;
            Ok(None)
        }
    }
}

/// Accepts `.csv` paths.
pub(super) fn csv_path(text: &str) -> Result<PathBuf, String> {
    let path = PathBuf::from(text);
    match path.extension().and_then(|e| e.to_str()) {
        Some(e) if e.eq_ignore_ascii_case("csv") => Ok(path),
        _ => Err(format!(
            "`{text}` has an unknown extension; name the file with .csv"
        )),
    }
}

/// A positive frequency: hertz, or a number and a unit with an SI prefix (`1kHz`, `2.5 MHz`).
/// The prefix is case-sensitive where SI makes it so (`mHz` is millihertz, `MHz` megahertz).
pub fn parse_frequency(text: &str) -> Result<f64, String> {
    let t = text.trim();
    let bad = || format!("`{t}` is not a positive frequency (e.g. 1e3, 100Hz, 2.5 kHz, 1MHz)");
    let (number, scale) = match t.len().checked_sub(2).filter(|&k| t.is_char_boundary(k)) {
        Some(k) if t[k..].eq_ignore_ascii_case("hz") => {
            let body = t[..k].trim_end();
            let scale = match body.chars().last() {
                Some('k' | 'K') => Some(1e3),
                Some('M') => Some(1e6),
                Some('G' | 'g') => Some(1e9),
                Some('T' | 't') => Some(1e12),
                Some('m') => Some(1e-3),
                _ => None,
            };
            match scale {
                // A prefix letter is ASCII: one byte.
                Some(s) => (body[..body.len() - 1].trim_end(), s),
                None => (body, 1.0),
            }
        }
        _ => (t, 1.0),
    };
    match number.parse::<f64>() {
        Ok(v) if v.is_finite() && v > 0.0 => Ok(v * scale),
        _ => Err(bad()),
    }
}

/// The probed quantities: the named ones, or every quantity but the spectral and noise
/// sources and those elaboration generated (named with a tick, as `vams run` leaves them out).
pub fn probes(design: &Design, names: &[String]) -> Result<Vec<QuantityId>, CliError> {
    if names.is_empty() {
        let sources: Vec<QuantityId> = (design.spectral_sources.iter().map(|s| s.quantity))
            .chain(design.noise_sources.iter().map(|s| s.quantity))
            .collect();
        return Ok((0..design.quantities.len())
            .map(|q| QuantityId(q as u32))
            .filter(|q| !sources.contains(q) && !design.quantities[q.index()].name.contains('\''))
            .collect());
    }
    let mut out = Vec::new();
    for name in names {
        let wanted = name.trim().to_ascii_lowercase();
        match design.quantities.iter().position(|q| q.name == wanted) {
            Some(q) => out.push(QuantityId(q as u32)),
            None => {
                let problem = if design.signals.iter().any(|s| s.name == wanted) {
                    "a signal keeps its quiescent value in a small-signal analysis".to_string()
                } else {
                    "no quantity of that name".to_string()
                };
                let nearest = (design.quantities.iter())
                    .map(|q| (strsim::levenshtein(&wanted, &q.name), q.name.as_str()))
                    .min_by_key(|&(d, _)| d);
                let help = match nearest {
                    Some((d, n)) if d <= wanted.len().max(3) / 2 + 1 => {
                        format!("did you mean `{n}`?")
                    }
                    _ => "probe quantities by hierarchical, lower-case name (dut.vout); \
                          without --probe every quantity is reported"
                        .into(),
                };
                return Err(CliError::AcProbe {
                    name: name.clone(),
                    problem,
                    help,
                });
            }
        }
    }
    Ok(out)
}

/// The response of each probe at each frequency.
pub struct Response {
    pub frequencies: Vec<f64>,
    /// Per probe, per frequency.
    pub values: Vec<Vec<c64>>,
}

/// The design linearised about its quiescent point: the solver's system, the point, and the
/// small-signal model.
pub struct Linearised {
    pub system: AnalogSystem,
    pub x: Vec<f64>,
    pub xdot: Vec<f64>,
    pub model: SmallSignalModel,
}

/// Why a design could not be linearised: the diagnostics, rendered, and the summary error.
pub struct NotLinearised {
    pub diagnostics: String,
    pub error: CliError,
}

impl NotLinearised {
    /// Prints the diagnostics on stderr and gives the summary error.
    pub fn print(self) -> Report {
        eprint!("{}", self.diagnostics);
        self.error.into()
    }
}

/// Linearises an elaborated design about its quiescent point (see [`respond`]); the errors
/// are printed.
pub(super) fn linearise(
    design: &Design,
    sources: &crate::source::SourceMap,
) -> Result<Linearised, Report> {
    linearise_quietly(design, sources).map_err(NotLinearised::print)
}

/// [`linearise`], the diagnostics rendered into the failure rather than printed (`vams
/// test` reports them with the testbench).
pub fn linearise_quietly(
    design: &Design,
    sources: &crate::source::SourceMap,
) -> Result<Linearised, NotLinearised> {
    let top = || design.top.clone();
    // The quiescent point exactly as `vams op` finds it (processes to their first wait,
    // breaks, `domain = quiescent_domain`), on the reduced system the kernel builds.
    let (point, kernel_system) = operating_point_and_system(design, &SimOptions::default())
        .map_err(|e| NotLinearised {
            diagnostics: render_sim_error(&e, sources),
            error: CliError::Simulation { top: top() },
        })?;
    let nq = design.quantities.len();
    let quantity_values: Vec<f64> = point.iter().take(nq).map(|(_, v)| *v).collect();
    let explicit = (design.signals.iter().enumerate())
        .filter(|(_, s)| s.kind == SignalKind::Explicit)
        .map(|(i, _)| SignalId(i as u32));
    let signal_values: Vec<(SignalId, f64)> = explicit
        .zip(point.iter().skip(nq).map(|(_, v)| *v))
        .filter(|(_, v)| v.is_finite())
        .collect();
    // The solver's reduced system, as the kernel builds it; unreduced where `'delayed`,
    // `'zoh` or `'ztf` is read (see `analog::small_signal`).
    let options = AnalogOptions {
        eliminate: design.delays.is_empty() && design.sampled.is_empty(),
        ..AnalogOptions::default()
    };
    let all = |errors: &[crate::analog::AnalogError]| -> String {
        errors.iter().map(|e| render_located(e, sources)).collect()
    };
    // The kernel's system is the reduced one (default options): reused when that is the one
    // wanted, since building it costs about as much as the quiescent point. Its explicit
    // signals are set from the point below, as a new system's would be.
    let mut system = match kernel_system {
        Some(system) if options.eliminate => system,
        _ => AnalogSystem::with_options(design, &options).map_err(|errors| NotLinearised {
            diagnostics: all(&errors),
            error: CliError::Analog {
                count: errors.len(),
            },
        })?,
    };
    let (x, xdot) = system
        .point_from_quantities(&quantity_values, &signal_values)
        .map_err(|e| NotLinearised {
            diagnostics: render(&e),
            error: CliError::Simulation { top: top() },
        })?;
    let model = system
        .small_signal(design, &x, &xdot)
        .map_err(|errors| NotLinearised {
            diagnostics: all(&errors),
            error: CliError::FrequencyDomain {
                count: errors.len(),
            },
        })?;
    Ok(Linearised {
        system,
        x,
        xdot,
        model,
    })
}

/// The response of `probes` at `frequencies` of a linearised design.
pub fn respond(
    top: &str,
    linearised: &mut Linearised,
    probes: &[QuantityId],
    frequencies: Vec<f64>,
) -> Result<Response, CliError> {
    let Linearised {
        system,
        x,
        xdot,
        model,
    } = linearised;
    let failed = |e: crate::solver::ac::AcSolveError| CliError::AcSolve {
        top: top.to_string(),
        reason: e.to_string(),
    };
    // Each probe as a combination of the solver's unknowns (an eliminated quantity by the
    // linearisation of its formula); the frequency-domain signals are set by now.
    let outputs: Vec<Vec<(usize, f64, f64)>> = (probes.iter())
        .map(|&q| system.linear_output(q, x, xdot).unwrap_or_default())
        .collect();
    let n = model.system.n;
    let mut solver = AcSolver::new(model.system.clone()).map_err(failed)?;
    let mut values = vec![Vec::with_capacity(frequencies.len()); probes.len()];
    let mut rhs = vec![c64::default(); n];
    for &f in &frequencies {
        rhs.iter_mut().for_each(|b| *b = c64::default());
        for (row, magnitude, phase) in model.excitation(f) {
            rhs[row] += c64::from_polar(magnitude, phase);
        }
        let x = solver.solve(f, &rhs).map_err(failed)?;
        let omega = std::f64::consts::TAU * f;
        for (column, output) in values.iter_mut().zip(&outputs) {
            let mut z = c64::default();
            for &(j, a, b) in output {
                // The slots come from the same system as the solution.
                z += c64::new(a, omega * b) * x.get(j).copied().unwrap_or(c64::new(f64::NAN, 0.0));
            }
            // A quantity without an expression (never expected) reads NaN, not 0.
            column.push(if output.is_empty() {
                c64::new(f64::NAN, f64::NAN)
            } else {
                z
            });
        }
    }
    Ok(Response {
        frequencies,
        values,
    })
}

/// The CSV text of a response.
pub fn format_csv(names: &[&str], response: &Response, complex: bool) -> String {
    let (a, b) = if complex { ("re", "im") } else { ("db", "deg") };
    let mut out = String::from("frequency");
    for name in names {
        out.push_str(&format!(",{name}_{a},{name}_{b}"));
    }
    out.push('\n');
    for (k, &f) in response.frequencies.iter().enumerate() {
        push_number(&mut out, f);
        for column in &response.values {
            let z = column[k];
            let (u, v) = if complex {
                (z.re, z.im)
            } else {
                (db(z), degrees(z))
            };
            out.push(',');
            push_number(&mut out, u);
            out.push(',');
            push_number(&mut out, v);
        }
        out.push('\n');
    }
    out
}

/// Runs `vams ac`.
pub fn run(args: &AcArgs) -> Result<(), Report> {
    let started = Instant::now();
    let grid = args.sweep.frequencies()?;
    let compiled = compile(&args.design)?;
    let design = &compiled.design;
    if design.spectral_sources.is_empty() {
        return Err(CliError::NoSpectralSource {
            top: design.top.clone(),
        }
        .into());
    }
    let probes = probes(design, &args.probe)?;
    let assertions = (args.assertions.iter())
        .map(|text| AcAssertion::parse(text))
        .collect::<Result<Vec<_>, _>>()?;
    let assertion_probes = assertion_probes(design, &assertions)?;
    let mut linearised = linearise(design, &compiled.loaded.sources)?;
    let response = respond(&design.top, &mut linearised, &probes, grid)?;
    let names: Vec<&str> = (probes.iter())
        .map(|q| design.quantities[q.index()].name.as_str())
        .collect();
    let csv = format_csv(&names, &response, args.complex);
    let mut written: Vec<String> = write_text(args.output.as_deref(), &csv)?
        .into_iter()
        .collect();
    if let Some(path) = &args.plot {
        let traces: Vec<BodeTrace> = (names.iter().zip(&response.values))
            .map(|(name, column)| BodeTrace {
                name: name.to_string(),
                points: (response.frequencies.iter().zip(column))
                    .map(|(&f, &z)| (f, db(z), degrees(z)))
                    .collect(),
            })
            .collect();
        plot_bode(path, &format!("{} (AC)", design.top), &traces)?;
        written.push(path.display().to_string());
    }
    let files = if written.is_empty() {
        String::new()
    } else {
        format!("; wrote {}", written.join(", "))
    };
    eprintln!(
        "analysed {} at {} frequencies from {} Hz to {} Hz in {:.2} s{files}",
        design.top,
        response.frequencies.len(),
        crate::output::csv::format_number(args.sweep.from),
        crate::output::csv::format_number(args.sweep.to),
        started.elapsed().as_secs_f64()
    );
    let verdicts = check_assertions(&design.top, &mut linearised, &assertions, &assertion_probes)?;
    discard_at_exit((compiled, linearised));
    let failed = verdicts.iter().filter(|v| !v.holds).count();
    for v in &verdicts {
        eprintln!("{}", v.line());
    }
    if failed > 0 {
        return Err(CliError::AcAssertions {
            failed,
            total: verdicts.len(),
        }
        .into());
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn frequencies_take_si_prefixes() {
        assert_eq!(parse_frequency("1e3"), Ok(1e3));
        assert_eq!(parse_frequency("100Hz"), Ok(100.0));
        assert_eq!(parse_frequency("2.5 kHz"), Ok(2500.0));
        assert_eq!(parse_frequency("1MHz"), Ok(1e6));
        assert_eq!(parse_frequency("10mHz"), Ok(0.01));
        assert_eq!(parse_frequency("3 GHz"), Ok(3e9));
        assert!(parse_frequency("0Hz").is_err());
        assert!(parse_frequency("-1").is_err());
        assert!(parse_frequency("fast").is_err());
        assert!(parse_frequency("kHz").is_err());
        assert!(parse_frequency("é").is_err());
    }

    #[test]
    fn csv_has_magnitude_and_phase_or_parts() {
        let response = Response {
            frequencies: vec![1.0, 10.0],
            values: vec![vec![c64::new(1.0, 0.0), c64::new(0.0, -0.1)]],
        };
        assert_eq!(
            format_csv(&["vout"], &response, false),
            "frequency,vout_db,vout_deg\n1,0,0\n10,-20,-90\n"
        );
        assert_eq!(
            format_csv(&["vout"], &response, true),
            "frequency,vout_re,vout_im\n1,1,0\n10,0,-0.1\n"
        );
    }
}
