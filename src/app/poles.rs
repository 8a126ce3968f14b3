//! `vams poles`: the natural frequencies of a design linearised about its quiescent point
//! (the same small-signal model as `vams ac`, `analog::small_signal`), from the finite
//! generalised eigenvalues of `(G + s C) x = 0` (`solver::poles`). For teaching: a DC motor
//! shows its electrical and mechanical time constants, an RLC its resonance and damping.

use std::fmt::Write as _;

use faer::c64;

use crate::app::ac::{Linearised, probes};
use crate::app::error::CliError;
use crate::design::Design;
use crate::solver::poles::{poles, zeros};

/// The natural frequencies of a linearised design.
pub struct Poles {
    /// The finite poles (1/s).
    pub finite: Vec<c64>,
    /// How many are at infinity (the algebraic part).
    pub infinite: usize,
    /// The unknowns of the small-signal system.
    pub unknowns: usize,
}

/// The transmission zeros from a spectral source to a quantity.
pub struct Zeros {
    /// The source and the output as the user named them, lower case.
    pub input: String,
    pub output: String,
    pub finite: Vec<c64>,
    pub infinite: usize,
}

/// The poles of `linearised`, the small-signal model of `design`.
pub fn poles_of(design: &Design, linearised: &Linearised) -> Result<Poles, CliError> {
    let system = &linearised.model.system;
    let (finite, infinite) = poles(system).map_err(|e| CliError::Poles {
        top: design.top.clone(),
        reason: e.to_string(),
    })?;
    Ok(Poles {
        finite,
        infinite,
        unknowns: system.n,
    })
}

/// The zeros from the spectral source quantity `input` to the quantity `output`
/// (hierarchical names); `poles` gives the scale below which a zero is taken as the origin.
pub fn zeros_of(
    design: &Design,
    linearised: &Linearised,
    poles: &Poles,
    input: &str,
    output: &str,
) -> Result<Zeros, CliError> {
    let (input_name, output_name) = (input.trim().to_ascii_lowercase(), output.trim());
    let model = &linearised.model;
    let source = (design.spectral_sources.iter())
        .position(|s| design.quantities[s.quantity.index()].name == input_name);
    let Some(injection) = source.and_then(|k| model.spectral_injection(k)) else {
        let names: Vec<&str> = (design.spectral_sources.iter())
            .map(|s| design.quantities[s.quantity.index()].name.as_str())
            .collect();
        return Err(CliError::ZerosInput {
            name: input.to_string(),
            sources: if names.is_empty() {
                "none: declare one, e.g. `quantity ac_in : real spectrum 1.0, 0.0;`".into()
            } else {
                names.join(", ")
            },
        });
    };
    let probe = probes(design, &[output_name.to_string()])?;
    let Linearised {
        system, x, xdot, ..
    } = linearised;
    let terms = (probe.first())
        .and_then(|&q| system.linear_output(q, x, xdot))
        .unwrap_or_default();
    let (found, infinite) =
        zeros(&model.system, injection, &terms).map_err(|e| CliError::Poles {
            top: design.top.clone(),
            reason: e.to_string(),
        })?;
    // A zero at the origin (a differentiator) comes out of QZ as rounding around the poles'
    // scale.
    let scale = (poles.finite.iter()).fold(1.0_f64, |m, p| m.max(p.norm()));
    let finite = (found.into_iter())
        .map(|z| {
            if z.norm() <= 1e-9 * scale {
                c64::new(0.0, 0.0)
            } else {
                z
            }
        })
        .collect();
    Ok(Zeros {
        input: input_name,
        output: output_name.to_ascii_lowercase(),
        finite,
        infinite,
    })
}

/// The table of poles: one line per real pole or conjugate pair.
pub fn format_poles(top: &str, unknowns: usize, finite: &[c64], infinite: usize) -> String {
    let mut out = format!(
        "poles of {top}: {} finite, {infinite} at infinity (algebraic), {unknowns} unknowns\n",
        finite.len()
    );
    out.push_str(&format_roots(finite));
    out
}

/// The table of roots: a line per real root or conjugate pair.
fn format_roots(finite: &[c64]) -> String {
    let mut out = String::new();
    let _ = writeln!(
        out,
        "  {:>14}  {:>14}  {:>14}  {:>8}  {:>14}",
        "real [1/s]", "imag [rad/s]", "frequency [Hz]", "damping", "time constant"
    );
    // Rounding leaves a real pole an imaginary part of about 1e-16 of its size.
    let is_real = |p: &c64| p.im.abs() <= 1e-9 * p.norm();
    // And an undamped pair a real part of the same order.
    let on_axis = |p: &c64| p.re.abs() <= 1e-9 * p.norm();
    for p in finite.iter().filter(|p| is_real(p) || p.im > 0.0) {
        let p = &if on_axis(p) { c64::new(0.0, p.im) } else { *p };
        let imag = if is_real(p) {
            "0".to_string()
        } else {
            format!("+-{:.6e}", p.im)
        };
        // `+ 0.0`: an undamped pair reads 0, not -0.
        let damping = if p.norm() > 0.0 {
            -p.re / p.norm() + 0.0
        } else {
            1.0
        };
        let tau = if p.re < 0.0 {
            format!("{:.6e} s", -1.0 / p.re)
        } else if p.re > 0.0 {
            "grows".to_string()
        } else {
            "undamped".to_string()
        };
        let _ = writeln!(
            out,
            "  {:>14.6e}  {imag:>14}  {:>14.6e}  {damping:>8.4}  {tau:>14}",
            p.re,
            p.norm() / std::f64::consts::TAU
        );
    }
    out
}

/// The zeros' table, as the poles'.
pub fn format_zeros(input: &str, output: &str, finite: &[c64], infinite: usize) -> String {
    let mut out = format!(
        "zeros from {input} to {output}: {} finite, {infinite} at infinity\n",
        finite.len()
    );
    out.push_str(&format_roots(finite));
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_pair_is_one_line_with_its_damping() {
        let table = format_poles(
            "t",
            3,
            &[
                c64::new(-1.0, -2.0),
                c64::new(-1.0, 2.0),
                c64::new(-10.0, 0.0),
            ],
            1,
        );
        assert!(table.contains("3 finite, 1 at infinity"), "{table}");
        let lines: Vec<&str> = table.lines().collect();
        assert_eq!(lines.len(), 4, "{table}");
        assert!(lines[2].contains("+-2.000000e0"), "{table}");
        assert!(lines[2].contains("0.4472"), "{table}");
        assert!(lines[3].contains("1.000000e-1 s"), "{table}");
    }
}
