//! `vams poles`: the natural frequencies of a design linearised about its quiescent point
//! (the same small-signal model as `vams ac`, `analog::small_signal`), from the finite
//! generalised eigenvalues of `(G + s C) x = 0` (`solver::poles`). For teaching: a DC motor
//! shows its electrical and mechanical time constants, an RLC its resonance and damping.

use std::fmt::Write as _;

use faer::c64;

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
