//! Constructors of [`Expr`] trees for the frontends that generate equations and processes
//! (the VHDL-AMS elaborator behind `'ltf`, `'slew`, `'zoh`; the SPICE lowering of device
//! equations): `add(a, b)` instead of `Expr::Binary(BinaryOp::Add, Box::new(a), Box::new(b))`.

use crate::{BinaryOp, Builtin, Expr, UnaryOp};

pub fn real(v: f64) -> Expr {
    Expr::real(v)
}

pub fn bin(op: BinaryOp, a: Expr, b: Expr) -> Expr {
    Expr::Binary(op, Box::new(a), Box::new(b))
}

pub fn add(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Add, a, b)
}

pub fn sub(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Sub, a, b)
}

pub fn mul(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Mul, a, b)
}

pub fn div(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Div, a, b)
}

pub fn abs(a: Expr) -> Expr {
    Expr::Unary(UnaryOp::Abs, Box::new(a))
}

/// `if c then a else b`.
pub fn cond(c: Expr, a: Expr, b: Expr) -> Expr {
    Expr::If(Box::new(c), Box::new(a), Box::new(b))
}

/// `now` as a real number of seconds: processes keep `time` and `real` apart.
pub fn now_seconds() -> Expr {
    Expr::Call(Builtin::ToReal, vec![Expr::Now])
}

/// `c0 * x0 + c1 * x1 + ...`, dropping zero coefficients (`0.0` when all are zero).
pub fn linear(terms: impl IntoIterator<Item = (f64, Expr)>) -> Expr {
    let mut sum: Option<Expr> = None;
    for (c, x) in terms {
        if c == 0.0 {
            continue;
        }
        let term = if c == 1.0 { x } else { mul(real(c), x) };
        sum = Some(match sum {
            None => term,
            Some(s) => add(s, term),
        });
    }
    sum.unwrap_or_else(|| real(0.0))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn linear_drops_zero_terms_and_unit_coefficients() {
        let x = Expr::Now;
        assert!(matches!(linear([(0.0, x.clone())]), Expr::Const(_)));
        assert!(matches!(linear([(1.0, x.clone())]), Expr::Now));
        assert!(matches!(
            linear([(2.0, x.clone()), (1.0, x)]),
            Expr::Binary(BinaryOp::Add, ..)
        ));
    }
}
