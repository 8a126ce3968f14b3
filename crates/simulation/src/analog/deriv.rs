//! Symbolic differentiation of a [`Sym`] with respect to one unknown or one derivative.
//!
//! Built with the folding constructors, so a term that does not depend on the variable
//! vanishes and `If` becomes an `If` of the branch derivatives. Comparisons, logic, `floor` and
//! the like are piecewise constant: zero derivative. Where the derivative has a singularity
//! (`sqrt` at 0, `log` at 0) it evaluates to inf or NaN, which Newton rejects.

use super::sym::{Bin, Sym, Un};

/// The variable to differentiate by.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Var {
    X(usize),
    Dot(usize),
    /// The time `now` (for a derivative in time of an equation with sources).
    Now,
    /// A signal's value (slot), for the small-signal model of `'zoh` and `'ztf`, which drive
    /// signals that equations read.
    Signal(usize),
}

fn c(v: f64) -> Sym {
    Sym::Const(v)
}

/// `d e / d var`.
pub fn derivative(e: &Sym, var: Var) -> Sym {
    match e {
        Sym::Const(_) => c(0.0),
        Sym::Signal(s) => c(if var == Var::Signal(*s) { 1.0 } else { 0.0 }),
        Sym::Now => c(if var == Var::Now { 1.0 } else { 0.0 }),
        Sym::X(j) => c(if var == Var::X(*j) { 1.0 } else { 0.0 }),
        Sym::Dot(j) => c(if var == Var::Dot(*j) { 1.0 } else { 0.0 }),
        Sym::Un(op, a) => {
            let da = derivative(a, var);
            if da.as_const() == Some(0.0) {
                return c(0.0);
            }
            unary(*op, a, e, da)
        }
        Sym::Bin(op, a, b) => {
            if op.is_logical() {
                return c(0.0);
            }
            let da = derivative(a, var);
            let db = derivative(b, var);
            if da.as_const() == Some(0.0) && db.as_const() == Some(0.0) {
                return c(0.0);
            }
            binary(*op, a, b, e, da, db)
        }
        Sym::If(cond, a, b) => Sym::cond((**cond).clone(), derivative(a, var), derivative(b, var)),
        Sym::Table(f, a) => match f.derivative() {
            None => c(0.0),
            Some(slope) => {
                let da = derivative(a, var);
                if da.as_const() == Some(0.0) {
                    return c(0.0);
                }
                Sym::mul(Sym::table(slope, (**a).clone()), da)
            }
        },
    }
}

/// `d op(a)` given `da` (nonzero) and `e = op(a)` itself for rules that reuse the value.
/// Operands are cloned only by the rules that keep them: most nodes of a circuit's equations
/// are sums, negations and products by constants, whose derivatives need neither.
fn unary(op: Un, a: &Sym, e: &Sym, da: Sym) -> Sym {
    let a = || a.clone();
    let sq = |s: Sym| Sym::mul(s.clone(), s);
    let factor = match op {
        Un::Neg => return Sym::neg(da),
        Un::Abs => Sym::un(Un::Sign, a()),
        Un::Not | Un::Floor | Un::Ceil | Un::Round | Un::Trunc | Un::Sign => return c(0.0),
        Un::Exp => e.clone(),
        Un::Log => return Sym::div(da, a()),
        Un::Log10 => return Sym::div(da, Sym::mul(a(), c(std::f64::consts::LN_10))),
        Un::Sqrt => return Sym::div(da, Sym::mul(c(2.0), e.clone())),
        Un::Sin => Sym::un(Un::Cos, a()),
        Un::Cos => Sym::neg(Sym::un(Un::Sin, a())),
        Un::Tan => Sym::add(c(1.0), sq(e.clone())),
        Un::Asin => return Sym::div(da, Sym::un(Un::Sqrt, Sym::sub(c(1.0), sq(a())))),
        Un::Acos => return Sym::neg(Sym::div(da, Sym::un(Un::Sqrt, Sym::sub(c(1.0), sq(a()))))),
        Un::Atan => return Sym::div(da, Sym::add(c(1.0), sq(a()))),
        Un::Sinh => Sym::un(Un::Cosh, a()),
        Un::Cosh => Sym::un(Un::Sinh, a()),
        Un::Tanh => Sym::sub(c(1.0), sq(e.clone())),
        Un::Asinh => return Sym::div(da, Sym::un(Un::Sqrt, Sym::add(sq(a()), c(1.0)))),
        Un::Acosh => return Sym::div(da, Sym::un(Un::Sqrt, Sym::sub(sq(a()), c(1.0)))),
        Un::Atanh => return Sym::div(da, Sym::sub(c(1.0), sq(a()))),
    };
    Sym::mul(factor, da)
}

/// `d * other` without cloning `other` when `d` is 0: the product folds to 0 whatever `other`
/// is, unless `other` is a constant, which folds numerically (`0 * inf` is NaN).
fn scaled(d: Sym, other: &Sym) -> Sym {
    match d.is_const(0.0) && other.as_const().is_none() {
        true => c(0.0),
        false => Sym::mul(d, other.clone()),
    }
}

/// `other * d`, as [`scaled`].
fn scaled_by(other: &Sym, d: Sym) -> Sym {
    match d.is_const(0.0) && other.as_const().is_none() {
        true => c(0.0),
        false => Sym::mul(other.clone(), d),
    }
}

/// `d op(a, b)` for the arithmetic operations, `e = op(a, b)`. Operands are cloned only by the
/// rules that keep them: sums and products or quotients by constants, most of a circuit's
/// nodes, need neither operand (or only the constant).
fn binary(op: Bin, a: &Sym, b: &Sym, e: &Sym, da: Sym, db: Sym) -> Sym {
    match op {
        Bin::Add => return Sym::add(da, db),
        Bin::Sub => return Sym::sub(da, db),
        Bin::Mul => return Sym::add(scaled(da, b), scaled_by(a, db)),
        // (da - (a/b) db) / b reuses the quotient.
        Bin::Div => return Sym::div(Sym::sub(da, scaled_by(e, db)), b.clone()),
        _ => {}
    }
    let (a, b) = (a.clone(), b.clone());
    match op {
        Bin::Pow => {
            if db.as_const() == Some(0.0) {
                // b a^(b-1) da: defined for negative a with integer b.
                let power = Sym::bin(Bin::Pow, a, Sym::sub(b.clone(), c(1.0)));
                Sym::mul(Sym::mul(b, power), da)
            } else {
                // a^b (db ln a + b da / a).
                let log_part = Sym::mul(db, Sym::un(Un::Log, a.clone()));
                let base_part = Sym::div(Sym::mul(b, da), a);
                Sym::mul(e.clone(), Sym::add(log_part, base_part))
            }
        }
        Bin::Mod => Sym::sub(da, Sym::mul(db, Sym::un(Un::Floor, Sym::div(a, b)))),
        Bin::Rem => Sym::sub(da, Sym::mul(db, Sym::un(Un::Trunc, Sym::div(a, b)))),
        // atan2(y, x): (x dy - y dx) / (x^2 + y^2).
        Bin::Atan2 => {
            let num = Sym::sub(Sym::mul(b.clone(), da), Sym::mul(a.clone(), db));
            let den = Sym::add(Sym::mul(b.clone(), b), Sym::mul(a.clone(), a));
            Sym::div(num, den)
        }
        Bin::Max => Sym::cond(Sym::bin(Bin::Ge, a, b), da, db),
        Bin::Min => Sym::cond(Sym::bin(Bin::Le, a, b), da, db),
        _ => c(0.0),
    }
}
