//! Golden listing of a small design (`vams dae`).

use super::fixture::*;
use vams_design::{Builtin, NatureId};

#[test]
fn rc_with_a_diode_clamp_listing() {
    let mut b = Builder::new();
    let el = NatureId(0);
    let gnd = b.ground(el);
    let a = b.terminal("a", el);
    let out = b.terminal("out", el);
    let u = b.signal("u", 1.0);
    let (vs, _) = b.branch("vs", "is", a, gnd);
    b.equation(
        "vs == 5.0 * u;",
        q(vs),
        mul(c(5.0), vams_design::Expr::Signal(u)),
    );
    let (vr, ir) = b.branch("vr", "ir", a, out);
    b.equation("vr == 1.0e3 * ir;", q(vr), mul(c(1e3), q(ir)));
    let (vc, ic) = b.branch("vc", "ic", out, gnd);
    b.equation("ic == 1.0e-6 * vc'dot;", q(ic), mul(c(1e-6), dot(vc)));
    let idd = b.through("id", out, gnd);
    b.equation(
        "id == 1.0e-12 * (exp(vc / 0.025) - 1.0);",
        q(idd),
        mul(
            c(1e-12),
            sub(
                call(
                    Builtin::Exp,
                    bin(vams_design::BinaryOp::Div, q(vc), c(0.025)),
                ),
                c(1.0),
            ),
        ),
    );
    let (d, sources) = b.finish();
    let sys = system(&d);
    insta::assert_snapshot!(sys.listing(&d, &sources));
}
