//! `vams ac`: small-signal frequency response. The quiescent point as `vams op` finds it, the
//! model linearised about it (`analog::small_signal`, on the solver's reduced system; probes
//! of eliminated quantities through their formulas' derivatives), `(G + jw C) X = B` solved at each
//! frequency (`solver::ac`), the probed quantities written as CSV (magnitude in dB and phase
//! in degrees, or real and imaginary parts) and drawn as a Bode plot.

use faer::c64;

use crate::analog::{AnalogOptions, AnalogSystem, SmallSignalModel};
use crate::design::{Design, QuantityId, SignalId, SignalKind};
use crate::kernel::{SimOptions, operating_point_and_system};
use crate::output::csv::push_number;
use crate::solver::ac::{AcSolver, Spacing, db, degrees, frequencies};

use super::error::CliError;
use super::render::{render, render_located, render_sim_error};

/// The analysis frequencies, shared by `vams ac` and `vams noise`.
#[derive(Debug, Clone)]
pub struct FrequencyGrid {
    /// Lowest analysis frequency (Hz).
    pub from: f64,
    /// Highest analysis frequency (Hz).
    pub to: f64,
    /// Logarithmic grid with N points per decade (the default, 20).
    pub points_per_decade: Option<u32>,
    /// Linear grid of N points, both ends included (wins over `points_per_decade`).
    pub linear: Option<u32>,
}

impl FrequencyGrid {
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

/// Linearises an elaborated design about its quiescent point (see [`respond`]); the
/// diagnostics are rendered into the failure (`vams test` reports them with the testbench,
/// the commands print them).
pub fn linearise(
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
