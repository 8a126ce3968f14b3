//! What the semiconductor devices' junctions share: ngspice's depletion charge of a graded
//! junction (continued linearly in capacitance above `fc*vj`, as `dioload` and `bjtload` have
//! it) and the power of a positive expression. The diode and the BJT use both; the MOSFET,
//! whose bulk junctions add a sidewall term in ngspice's own form, the power.

use vams_design::build::{add, bin, cond, mul, sub};
use vams_design::{BinaryOp, Builtin, Expr};

fn c(x: f64) -> Expr {
    Expr::real(x)
}

/// `x^p` for `x > 0`, as `exp(p*log(x))`.
pub(crate) fn power(x: Expr, p: f64) -> Expr {
    Expr::Call(
        Builtin::Exp,
        vec![mul(c(p), Expr::Call(Builtin::Log, vec![x]))],
    )
}

/// The depletion charge of zero-bias capacitance `cz` at `v`, with ngspice's linear
/// capacitance above `fc*vj`; `None` when `cz` is 0.
pub(crate) fn depletion(cz: f64, vj: f64, m: f64, fc: f64, v: Expr) -> Option<Expr> {
    if cz == 0.0 {
        return None;
    }
    let fcvj = fc * vj;
    // 1 - v/vj, kept above 1 - fc so that the branch not taken stays finite.
    let arg = Expr::Call(
        Builtin::Realmax,
        vec![sub(c(1.0), mul(c(1.0 / vj), v.clone())), c(1.0 - fc)],
    );
    let below = mul(c(vj * cz / (1.0 - m)), sub(c(1.0), power(arg, 1.0 - m)));
    let f1 = vj * (1.0 - (1.0 - fc).powf(1.0 - m)) / (1.0 - m);
    let f2 = (1.0 - fc).powf(1.0 + m);
    let f3 = 1.0 - fc * (1.0 + m);
    let above = add(
        c(cz * f1),
        mul(
            c(cz / f2),
            add(
                mul(c(f3), sub(v.clone(), c(fcvj))),
                mul(
                    c(m / (2.0 * vj)),
                    sub(mul(v.clone(), v.clone()), c(fcvj * fcvj)),
                ),
            ),
        ),
    );
    Some(cond(bin(BinaryOp::Lt, v, c(fcvj)), below, above))
}
