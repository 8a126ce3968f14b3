//! `vams noise`: noise analysis. The design linearised about its quiescent point exactly as
//! `vams ac` does it (`ac::linearise`), its noise source quantities as uncorrelated
//! independent sources of their power spectral densities (spectral sources are zero), the
//! output PSD at one probe from one adjoint solve per frequency (`solver::noise`), written as
//! CSV (densities per root hertz), drawn on log-log axes (`output::noise_plot`), and
//! integrated over the band (trapezoid rule in frequency on the grid) to an RMS value.

use faer::c64;

use crate::design::{Design, QuantityId};
use crate::output::csv::{format_number, push_number};
use crate::solver::ac::AcSolver;
use crate::solver::noise::{Injection, integrate, noise_at};

use super::ac::{Linearised, NotLinearised, linearise};
use super::error::CliError;
use super::render::render_located;

/// The noise at each frequency.
pub struct NoiseTable {
    pub frequencies: Vec<f64>,
    /// Per frequency, each source's contribution to the output PSD.
    pub contributions: Vec<Vec<f64>>,
    /// Per frequency, the output PSD.
    pub total: Vec<f64>,
    /// Per frequency, the transfer from the input to the output (with --input).
    pub input_gain: Option<Vec<c64>>,
}

/// The index of the spectral source quantity `name` in `design.spectral_sources`.
pub fn input_source(design: &Design, name: &str) -> Result<usize, CliError> {
    let wanted = name.trim().to_ascii_lowercase();
    let quantity_name = |k: usize| design.quantities[k].name.as_str();
    let found =
        (design.spectral_sources.iter()).position(|s| quantity_name(s.quantity.index()) == wanted);
    if let Some(k) = found {
        return Ok(k);
    }
    let spectral: Vec<&str> = (design.spectral_sources.iter())
        .map(|s| quantity_name(s.quantity.index()))
        .collect();
    let problem = if design.quantities.iter().any(|q| q.name == wanted) {
        "a quantity, but not a spectral source quantity".to_string()
    } else {
        "no quantity of that name".to_string()
    };
    let help = if spectral.is_empty() {
        "the input is a spectral source quantity (`quantity ac_in : real spectrum 1.0, 0.0;`) \
         where the signal enters; the design has none"
            .to_string()
    } else {
        format!("the spectral source quantities: {}", spectral.join(", "))
    };
    Err(CliError::NoiseInput {
        name: name.to_string(),
        problem,
        help,
    })
}

/// Runs the analysis on an elaborated design: the noise at `probe` at each frequency, and
/// the transfer from the spectral source `input` (an index of `design.spectral_sources`).
pub fn analyse(
    design: &Design,
    sources: &crate::source::SourceMap,
    probe: QuantityId,
    input: Option<usize>,
    frequencies: Vec<f64>,
) -> Result<NoiseTable, NotLinearised> {
    let top = || design.top.clone();
    let solve_error = |reason: String| NotLinearised {
        diagnostics: String::new(),
        error: CliError::AcSolve { top: top(), reason },
    };
    let Linearised {
        system,
        x,
        xdot,
        mut model,
    } = linearise(design, sources)?;
    let output = system
        .linear_output(probe, &x, &xdot)
        .ok_or_else(|| solve_error("the probe has no small-signal expression".into()))?;
    let injections: Vec<Injection> = (model.noise_injections().into_iter())
        .map(|(row, coefficient)| Injection { row, coefficient })
        .collect();
    let extra: Vec<Injection> = (input.and_then(|k| model.spectral_injection(k)))
        .map(|(row, coefficient)| Injection { row, coefficient })
        .into_iter()
        .collect();
    let mut solver = AcSolver::new(model.system.clone()).map_err(|e| solve_error(e.to_string()))?;
    let mut table = NoiseTable {
        contributions: Vec::with_capacity(frequencies.len()),
        total: Vec::with_capacity(frequencies.len()),
        input_gain: input.map(|_| Vec::with_capacity(frequencies.len())),
        frequencies,
    };
    for &f in &table.frequencies {
        let densities = model.noise_densities(f).map_err(|e| NotLinearised {
            diagnostics: render_located(&e, sources),
            error: CliError::NoiseDensity { top: top() },
        })?;
        let point = noise_at(&mut solver, f, &output, &injections, &densities, &extra)
            .map_err(|e| solve_error(e.to_string()))?;
        if let (Some(gains), Some(&g)) = (&mut table.input_gain, point.gains.first()) {
            gains.push(g);
        }
        table.contributions.push(point.contributions);
        table.total.push(point.total);
    }
    Ok(table)
}

/// `_V` (the unit) for a column name, or nothing for a quantity without a unit.
fn unit_suffix(unit: Option<&str>) -> String {
    unit.map(|u| format!("_{u}")).unwrap_or_default()
}

/// The CSV text of a table: densities per root hertz (see `NoiseArgs`).
pub fn format_csv(
    probe: (&str, Option<&str>),
    source_names: &[&str],
    input: Option<(&str, Option<&str>)>,
    table: &NoiseTable,
) -> String {
    let (name, unit) = probe;
    let per = format!("{}_per_rtHz", unit_suffix(unit));
    let mut out = format!("frequency,{name}_noise{per}");
    for source in source_names {
        out.push_str(&format!(",{name}_from_{source}{per}"));
    }
    if let Some((input, unit)) = input {
        out.push_str(&format!(",{input}_referred{}_per_rtHz", unit_suffix(unit)));
    }
    out.push('\n');
    for (k, &f) in table.frequencies.iter().enumerate() {
        push_number(&mut out, f);
        out.push(',');
        push_number(&mut out, table.total[k].sqrt());
        for &c in &table.contributions[k] {
            out.push(',');
            push_number(&mut out, c.sqrt());
        }
        if let Some(gains) = &table.input_gain {
            out.push(',');
            // A missing gain (never: one per frequency) reads NaN rather than panicking.
            let gain = gains.get(k).map_or(f64::NAN, |g| g.norm());
            push_number(&mut out, table.total[k].sqrt() / gain);
        }
        out.push('\n');
    }
    out
}

/// The band's integrated noise as text: the output RMS, each source's share, and the
/// input-referred RMS (the input-referred PSD integrated the same way).
pub fn format_summary(
    probe: (&str, Option<&str>),
    source_names: &[&str],
    input: Option<(&str, Option<&str>)>,
    table: &NoiseTable,
) -> String {
    let f = &table.frequencies;
    let unit = |u: Option<&str>| u.map(|u| format!(" {u}")).unwrap_or_default();
    let total = integrate(f, &table.total);
    let (first, last) = (f.first().copied(), f.last().copied());
    let mut out = format!(
        "integrated output noise at {}: {:.6e}{} rms over {} Hz to {} Hz ({} points; the PSD \
         integrated by the trapezoid rule in frequency on the grid)\n",
        probe.0,
        total.sqrt(),
        unit(probe.1),
        format_number(first.unwrap_or(f64::NAN)),
        format_number(last.unwrap_or(f64::NAN)),
        f.len()
    );
    for (k, name) in source_names.iter().enumerate() {
        let column: Vec<f64> = table.contributions.iter().map(|c| c[k]).collect();
        let power = integrate(f, &column);
        let share = if total > 0.0 {
            power / total * 100.0
        } else {
            0.0
        };
        out.push_str(&format!(
            "  from {name}: {:.6e}{} rms ({share:.2} % of the power)\n",
            power.sqrt(),
            unit(probe.1)
        ));
    }
    if let (Some((name, u)), Some(gains)) = (input, &table.input_gain) {
        let referred: Vec<f64> = (table.total.iter().zip(gains))
            .map(|(p, g)| p / g.norm_sqr())
            .collect();
        out.push_str(&format!(
            "integrated input-referred noise at {name}: {:.6e}{} rms\n",
            integrate(f, &referred).sqrt(),
            unit(u)
        ));
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    fn table() -> NoiseTable {
        NoiseTable {
            frequencies: vec![1.0, 3.0],
            contributions: vec![vec![9e-18, 16e-18], vec![1e-18, 0.0]],
            total: vec![25e-18, 1e-18],
            input_gain: Some(vec![c64::new(0.0, 10.0), c64::new(10.0, 0.0)]),
        }
    }

    #[test]
    fn csv_has_densities_per_root_hertz() {
        let csv = format_csv(
            ("vout", Some("V")),
            &["vn1", "vn2"],
            Some(("ac_in", None)),
            &table(),
        );
        let mut lines = csv.lines();
        assert_eq!(
            lines.next(),
            Some(
                "frequency,vout_noise_V_per_rtHz,vout_from_vn1_V_per_rtHz,vout_from_vn2_V_per_rtHz,ac_in_referred_per_rtHz"
            )
        );
        let row: Vec<f64> = (lines.next().unwrap().split(','))
            .map(|v| v.parse().unwrap())
            .collect();
        let expected = [1.0, 5e-9, 3e-9, 4e-9, 5e-10];
        for (a, b) in row.iter().zip(expected) {
            assert!((a / b - 1.0).abs() < 1e-12, "{row:?}");
        }
    }

    #[test]
    fn summary_integrates_by_trapezoids() {
        let text = format_summary(
            ("vout", Some("V")),
            &["vn1", "vn2"],
            Some(("ac_in", None)),
            &table(),
        );
        // (3 - 1) (25 + 1) / 2 = 26 (e-18): 5.099020e-9 V rms.
        assert!(text.contains("vout: 5.099020e-9 V rms"), "{text}");
        // vn1: 2 * (9 + 1) / 2 = 10; vn2: 16.
        assert!(
            text.contains("from vn1: 3.162278e-9 V rms (38.46 %"),
            "{text}"
        );
        assert!(
            text.contains("from vn2: 4.000000e-9 V rms (61.54 %"),
            "{text}"
        );
        // Referred: (25/100 + 1/100) = 0.26 -> 2 * 0.26 / 2 = 0.26 (e-18).
        assert!(text.contains("ac_in: 5.099020e-10 rms"), "{text}");
    }
}
