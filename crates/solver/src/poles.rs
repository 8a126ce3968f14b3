//! The natural frequencies of a linearised system: the finite generalised eigenvalues `s` of
//! `(G + s C) x = 0`, by faer's dense QZ on the pencil `(G, -C)`. An algebraic part gives
//! eigenvalues at infinity (`beta` = 0), which are counted, not listed.
//!
//! [`zeros`] gives the transmission zeros from an input to an output the same way, on
//! Rosenbrock's system matrix.
//!
//! Knows nothing of VHDL: the caller names the system.

use faer::{Mat, c64};
use thiserror::Error;

use super::ac::SmallSignal;

/// Unknowns beyond which the dense QZ (cubic in time, quadratic in memory) is refused.
pub const MAX_UNKNOWNS: usize = 2_000;

/// Why the poles could not be computed.
#[derive(Debug, Error, Clone, PartialEq)]
pub enum PolesError {
    #[error("the system has {n} unknowns; the dense eigenvalue solver takes at most {max}")]
    TooLarge { n: usize, max: usize },
    #[error("the system reads a 'delayed value: its characteristic equation is not polynomial")]
    Delayed,
    #[error(
        "the system reads a 'zoh or 'ztf value: a sampled-data loop has no finite set of poles in s"
    )]
    Sampled,
    #[error("the generalised eigenvalue solver did not converge: {0}")]
    Solver(String),
}

/// The finite poles (`s`, in 1/s, sorted by magnitude then imaginary part) and the number of
/// eigenvalues at infinity.
pub fn poles(system: &SmallSignal) -> Result<(Vec<c64>, usize), PolesError> {
    let n = system.n;
    if n > MAX_UNKNOWNS {
        return Err(PolesError::TooLarge {
            n,
            max: MAX_UNKNOWNS,
        });
    }
    if !system.delays.is_empty() {
        return Err(PolesError::Delayed);
    }
    if !system.sampled.is_empty() {
        return Err(PolesError::Sampled);
    }
    // Complex matrices: faer 0.24's real QZ asks for too little scratch on some inputs
    // (a 2 x 2 oscillator panicked in `gevd`); the complex QZ does not.
    let mut g = Mat::<c64>::zeros(n, n);
    let mut minus_c = Mat::<c64>::zeros(n, n);
    for (k, &(row, col)) in system.pattern.iter().enumerate() {
        g[(row, col)] = c64::new(system.g[k], 0.0);
        minus_c[(row, col)] = c64::new(-system.c[k], 0.0);
    }
    finite_eigenvalues(&g, &minus_c)
}

/// The transmission zeros from an input to an output of a linearised system: the finite `s`
/// where `y = (a + s d)^T X` vanishes for `(G + s C) X = b u`, the generalised eigenvalues of
/// Rosenbrock's system matrix `[[G + s C, -b], [a^T + s d^T, 0]]`. `input` is `(row,
/// coefficient)` of `b`; `output` the `(unknown, a_j, d_j)` terms of `y`. Counted at infinity
/// as in [`poles`].
pub fn zeros(
    system: &SmallSignal,
    input: (usize, f64),
    output: &[(usize, f64, f64)],
) -> Result<(Vec<c64>, usize), PolesError> {
    let n = system.n;
    if n + 1 > MAX_UNKNOWNS {
        return Err(PolesError::TooLarge {
            n,
            max: MAX_UNKNOWNS,
        });
    }
    if !system.delays.is_empty() {
        return Err(PolesError::Delayed);
    }
    if !system.sampled.is_empty() {
        return Err(PolesError::Sampled);
    }
    let mut a = Mat::<c64>::zeros(n + 1, n + 1);
    let mut minus_e = Mat::<c64>::zeros(n + 1, n + 1);
    for (k, &(row, col)) in system.pattern.iter().enumerate() {
        a[(row, col)] = c64::new(system.g[k], 0.0);
        minus_e[(row, col)] = c64::new(-system.c[k], 0.0);
    }
    let (row, coefficient) = input;
    if row < n {
        a[(row, n)] = c64::new(-coefficient, 0.0);
    }
    for &(j, value, derivative) in output {
        if j < n {
            a[(n, j)] += c64::new(value, 0.0);
            minus_e[(n, j)] -= c64::new(derivative, 0.0);
        }
    }
    finite_eigenvalues(&a, &minus_e)
}

/// The finite eigenvalues `alpha / beta` of the pencil `(a, b)` (`a x = s b x`), sorted by
/// magnitude then imaginary part, and the number at infinity.
fn finite_eigenvalues(a: &Mat<c64>, b: &Mat<c64>) -> Result<(Vec<c64>, usize), PolesError> {
    let n = a.nrows();
    if n == 0 {
        return Ok((Vec::new(), 0));
    }
    let mut scale = 0.0_f64;
    for j in 0..n {
        for i in 0..n {
            scale = scale.max(b[(i, j)].norm());
        }
    }
    // faer's QZ has panicked on a valid input (above); a failure of the library must reach
    // the user as a diagnostic, not an abort.
    let eigen = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| a.generalized_eigen(b)))
        .map_err(|_| PolesError::Solver("the QZ iteration failed inside faer".into()))?
        .map_err(|e| PolesError::Solver(format!("{e:?}")))?;
    let (alpha, beta) = (eigen.S_a(), eigen.S_b());
    let mut finite = Vec::new();
    let mut infinite = 0;
    for k in 0..n {
        let (a, b) = (alpha[k], beta[k]);
        // QZ leaves `beta` on the scale of `C`'s entries; one at rounding level of them is
        // an algebraic direction, not a pole far out.
        if b.norm() <= 1e-12 * scale.max(f64::MIN_POSITIVE) * n as f64 {
            infinite += 1;
        } else {
            finite.push(a / b);
        }
    }
    finite.sort_by(|p, q| (p.norm().total_cmp(&q.norm())).then(p.im.total_cmp(&q.im)));
    Ok((finite, infinite))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// `x1' = -x1 + x2`, `x2' = -x2`, `x3 = 2 x1` (algebraic): poles -1 twice, one at infinity.
    #[test]
    fn a_triangular_system_has_its_diagonal_and_an_algebraic_direction() {
        let system = SmallSignal {
            n: 3,
            pattern: vec![(0, 0), (0, 1), (1, 1), (2, 0), (2, 2)],
            // Residuals x1' + x1 - x2, x2' + x2, x3 - 2 x1.
            g: vec![1.0, -1.0, 1.0, -2.0, 1.0],
            c: vec![1.0, 0.0, 1.0, 0.0, 0.0],
            delays: Vec::new(),
            sampled: Vec::new(),
        };
        let (finite, infinite) = poles(&system).expect("solves");
        assert_eq!(infinite, 1);
        assert_eq!(finite.len(), 2);
        for p in finite {
            assert!((p - c64::new(-1.0, 0.0)).norm() < 1e-6, "{p}");
        }
    }

    /// An undamped oscillator `x' = w v`, `v' = -w x`: poles at `+-j w`.
    #[test]
    fn an_oscillator_has_a_conjugate_pair() {
        let w = 3.0;
        let system = SmallSignal {
            n: 2,
            pattern: vec![(0, 0), (0, 1), (1, 0), (1, 1)],
            g: vec![0.0, -w, w, 0.0],
            c: vec![1.0, 0.0, 0.0, 1.0],
            delays: Vec::new(),
            sampled: Vec::new(),
        };
        let (finite, infinite) = poles(&system).expect("solves");
        assert_eq!(infinite, 0);
        assert!((finite[0] - c64::new(0.0, -w)).norm() < 1e-12, "{finite:?}");
        assert!((finite[1] - c64::new(0.0, w)).norm() < 1e-12, "{finite:?}");
    }

    /// An RC low-pass with its output taken across the resistor, `x0 - u = 0` (input row 0),
    /// `c x1' + (x1 - x0) / r = 0`: from `u` to `x0 - x1` (the resistor's voltage,
    /// `s r c / (1 + s r c)`) a zero at `s = 0`; to `x1 + r c x1'` a zero at `-1 / (r c)`.
    #[test]
    fn zeros_of_a_high_pass_and_of_an_output_with_a_derivative() {
        let (r, c) = (1e3, 1e-6);
        let system = SmallSignal {
            n: 2,
            pattern: vec![(0, 0), (1, 0), (1, 1)],
            g: vec![1.0, -1.0 / r, 1.0 / r],
            c: vec![0.0, 0.0, c],
            delays: Vec::new(),
            sampled: Vec::new(),
        };
        let (finite, _) = zeros(&system, (0, 1.0), &[(0, 1.0, 0.0), (1, -1.0, 0.0)]).unwrap();
        assert_eq!(finite.len(), 1, "{finite:?}");
        assert!(finite[0].norm() < 1e-9, "{finite:?}");
        let (finite, _) = zeros(&system, (0, 1.0), &[(1, 1.0, r * c)]).unwrap();
        assert_eq!(finite.len(), 1, "{finite:?}");
        assert!(
            (finite[0] - c64::new(-1.0 / (r * c), 0.0)).norm() < 1e-6,
            "{finite:?}"
        );
        // The plain low-pass output has no finite zero.
        let (finite, _) = zeros(&system, (0, 1.0), &[(1, 1.0, 0.0)]).unwrap();
        assert!(finite.is_empty(), "{finite:?}");
    }
}
