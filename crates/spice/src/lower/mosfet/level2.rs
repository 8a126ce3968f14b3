//! ngspice's MOSFET level 2 (Grove-Frohman, its `mos2` device) drain current, at TEMP = TNOM.
//!
//! Takes the model's and instance's numbers; gives the channel current, `von` and `vdsat` of
//! the mode-local voltages (nmos sense, `vds >= 0`), as expressions over a few free
//! quantities that hold intermediate values (the short-channel `gamma`, `n`, `von`, the
//! mobility factor, the saturation voltage, the length factor), each started where its
//! definition holds. The equations are those of `mos2load.c`: the short-channel threshold
//! (`xj`), the narrow-channel factor (`delta`), the fast surface states (`nfs`:
//! `von = vth + n*vt`, below it `cdson*exp((vgs - von)/(n*vt))`), the mobility degradation
//! (`ucrit`, `uexp`; `utra` is read and unused, as in ngspice), Grove-Frohman's saturation
//! voltage, the channel-length modulation (`lambda`, else computed from `nsub`) and the
//! punch-through limit. `vto`, `gamma` and `phi` follow from `nsub`, `nss` and `tpg` when not
//! given; `tox` defaults to 1e-7 and `mjsw` to 0.33, as in mos2.
//!
//! Refused: `vmax` (velocity saturation, Baum's quartic; `neff` is accepted, without effect
//! as in ngspice when `vmax` is absent).

use vams_design::build::{add, bin, cond, div, mul, sub};
use vams_design::{BinaryOp, Builtin, Expr, QuantityKind};

use super::{BOLTZMANN, CELSIUS_TO_KELVIN, CHARGE, EPS_OX, Level1, Lowerer};
use crate::circuit::{FlatElement, FlatModel};
use crate::error::SpiceError;

/// Silicon's permittivity as ngspice's mos2 has it.
const EPS_SIL: f64 = 11.7 * 8.854_214_871e-12;

/// The model parameters level 2 adds to level 1's.
pub(super) const USED: [&str; 13] = [
    "nsub", "nss", "nfs", "xj", "ucrit", "uexp", "utra", "vmax", "neff", "delta", "tpg", "vt0",
    "u0",
];

/// The level 2 numbers of one instance (nmos sense).
pub(super) struct Level2 {
    /// `type*vto - gamma*sqrt(phi)` (ngspice's `tVbi*type`).
    vbi: f64,
    pub(super) phi: f64,
    gamma: f64,
    /// The narrow-channel factor and `1 + factor`.
    factor: f64,
    eta: f64,
    /// The depletion width factor (0 without `nsub`).
    xd: f64,
    xj: f64,
    leff: f64,
    /// `1 + q*nfs/cox` (per area), 0 without `nfs`.
    xn0: Option<f64>,
    /// The critical voltage `ucrit*eps_si/cox_per_area` and `uexp`.
    ucrit: f64,
    uexp: f64,
    lambda: f64,
    nsub: bool,
    pb: f64,
    beta: f64,
    vt: f64,
}

fn c(x: f64) -> Expr {
    Expr::real(x)
}

fn lt(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Lt, a, b)
}

fn le(a: Expr, b: Expr) -> Expr {
    bin(BinaryOp::Le, a, b)
}

/// `x` kept at least `floor` (so that a root, a logarithm or a quotient of it is finite).
fn floor(x: Expr, f: f64) -> Expr {
    cond(lt(x.clone(), c(f)), c(f), x)
}

fn sqrt(x: Expr) -> Expr {
    Expr::Call(Builtin::Sqrt, vec![floor(x, 1e-12)])
}

/// `a / b` with `b` kept away from 0 (its sign kept).
fn sdiv(a: Expr, b: Expr) -> Expr {
    let b = cond(
        lt(vams_design::build::abs(b.clone()), c(1e-30)),
        c(1e-30),
        b,
    );
    div(a, b)
}

fn max(a: Expr, b: Expr) -> Expr {
    cond(lt(a.clone(), b.clone()), b, a)
}

impl Lowerer<'_> {
    /// The level 2 numbers, or `None` after reporting why there are none; fixes in `p` the
    /// level 1 numbers level 2 defaults differently (`mjsw`, `tox`, `phi`).
    pub(super) fn level2(
        &mut self,
        el: &FlatElement,
        model: &FlatModel,
        p: &mut Level1,
    ) -> Option<Level2> {
        let circuit = self.circuit;
        let pm = |k: &str| model.param(k);
        let temp = circuit.options.temp.unwrap_or(27.0);
        let tnom_k = temp + CELSIUS_TO_KELVIN;
        let vtnom = BOLTZMANN * tnom_k / CHARGE;
        let tox = pm("tox").unwrap_or(1e-7);
        if tox <= 0.0 {
            self.push_once(SpiceError::syntax(
                model.span,
                format!("`.model {}` has tox = {tox}, not positive", model.name),
                "tox must be positive",
                "give the level 2 MOSFET a positive `tox=` (1e-7 by default)",
            ));
            return None;
        }
        let coxf = EPS_OX / tox;
        let uo_cm = pm("uo").or(pm("u0")).unwrap_or(600.0);
        let kp = pm("kp").unwrap_or(uo_cm * 1e-4 * coxf);
        let mut phi = pm("phi").unwrap_or(0.6);
        let mut gamma = pm("gamma").unwrap_or(0.0);
        let mut vto = pm("vto").or(pm("vt0")).unwrap_or(0.0);
        let mut xd = 0.0;
        let nsub = pm("nsub").unwrap_or(0.0);
        let nsub_given = pm("nsub").is_some();
        if nsub_given {
            if nsub * 1e6 <= 1.45e16 {
                self.push_once(SpiceError::syntax(
                    model.span,
                    format!(
                        "`.model {}` has nsub = {nsub}, below the intrinsic 1.45e10",
                        model.name
                    ),
                    "nsub below ni",
                    "give `nsub=` (per cm^3) above 1.45e10, or remove it",
                ));
                return None;
            }
            let t = p.sign;
            if pm("phi").is_none() {
                phi = (2.0 * vtnom * (nsub * 1e6 / 1.45e16).ln()).max(0.1);
            }
            let egfet1 = 1.16 - (7.02e-4 * tnom_k * tnom_k) / (tnom_k + 1108.0);
            let fermis = t * 0.5 * phi;
            let tpg = pm("tpg").unwrap_or(1.0);
            let wkfng = if tpg != 0.0 {
                3.25 + 0.5 * egfet1 - t * tpg * 0.5 * egfet1
            } else {
                3.2
            };
            let wkfngs = wkfng - (3.25 + 0.5 * egfet1 + fermis);
            if pm("gamma").is_none() {
                gamma = (2.0 * EPS_SIL * CHARGE * nsub * 1e6).sqrt() / coxf;
            }
            if pm("vto").or(pm("vt0")).is_none() {
                let nss = pm("nss").unwrap_or(0.0);
                let vfb = wkfngs - nss * 1e4 * CHARGE / coxf;
                vto = vfb + t * (gamma * phi.sqrt() + phi);
            }
            xd = ((EPS_SIL + EPS_SIL) / (CHARGE * nsub * 1e6)).sqrt();
        }
        if phi <= 0.0 {
            return None;
        }
        let vmax = pm("vmax").unwrap_or(0.0);
        if vmax > 0.0 {
            self.refuse_model(
                model,
                "the level 2 MOSFET model parameter `vmax` (velocity saturation)".into(),
                "remove `vmax=`: the level 2 MOSFET is lowered without velocity saturation \
                 (`neff` then has no effect, as in ngspice)"
                    .into(),
            );
            return None;
        }
        let inst = |k: &str, option: &str, default: f64| {
            el.param(k)
                .or_else(|| self.numeric_option(option))
                .unwrap_or(default)
        };
        let l = inst("l", "defl", 1e-4);
        let w = inst("w", "defw", 1e-4);
        let m = el.param("m").unwrap_or(1.0);
        let leff = l - 2.0 * pm("ld").unwrap_or(0.0);
        let unscaled_cox = coxf * leff * w;
        let factor = 0.125 * pm("delta").unwrap_or(0.0) * 2.0 * std::f64::consts::PI * EPS_SIL
            / unscaled_cox
            * leff;
        let nfs = pm("nfs").unwrap_or(0.0);
        p.phi = phi;
        p.charge.mjsw = pm("mjsw").unwrap_or(0.33);
        p.charge.cox = unscaled_cox * m;
        Some(Level2 {
            vbi: p.sign * vto - gamma * phi.sqrt(),
            phi,
            gamma,
            factor,
            eta: 1.0 + factor,
            xd,
            xj: pm("xj").unwrap_or(0.0),
            leff,
            xn0: (nfs != 0.0).then(|| 1.0 + CHARGE * nfs * 1e4 / coxf),
            ucrit: pm("ucrit").unwrap_or(1e4) * 100.0 * EPS_SIL / coxf,
            uexp: pm("uexp").unwrap_or(0.0),
            lambda: pm("lambda").unwrap_or(0.0),
            nsub: nsub_given,
            pb: pm("pb").unwrap_or(0.8),
            beta: kp * w * m / leff,
            vt: p.vt,
        })
    }

    /// A free quantity `name.key` defined as `e`; the quantity.
    fn define(&mut self, el: &FlatElement, key: &str, e: Expr) -> Expr {
        self.define_from(el, key, e, 0.0)
    }

    /// As `define`, the Newton iteration starting from `init`.
    fn define_from(&mut self, el: &FlatElement, key: &str, e: Expr, init: f64) -> Expr {
        let name = format!("{}.{key}", el.name);
        let qv = self.quantity(name.clone(), QuantityKind::Free, el.span);
        // Start the Newton iteration where the definition holds at the starting point (every
        // other quantity at its initial guess, 0 without one).
        let start = {
            let q = &self.design.quantities;
            eval(&e, &|id| {
                q.get(id as usize)
                    .and_then(|x| x.initial_guess)
                    .unwrap_or(0.0)
            })
        };
        let init = start.filter(|v| v.is_finite()).unwrap_or(init);
        self.design.quantities[qv.0 as usize].initial_guess = Some(init);
        self.equation(
            el,
            Expr::Quantity(qv),
            e,
            format!("{name} == mos2_{key}(...)"),
        );
        Expr::Quantity(qv)
    }

    /// `(cdrain, von, vdsat)` of the mode-local nmos-sense voltages (`vds >= 0`).
    pub(super) fn level2_channel(
        &mut self,
        el: &FlatElement,
        p: &Level2,
        vgs: Expr,
        vbs: Expr,
        vds: Expr,
    ) -> (Expr, Expr, Expr) {
        let phi = p.phi;
        let sphi = phi.sqrt();
        let sphi3 = phi * sphi;
        let l = p.leff;
        let phi_min_vbs = sub(c(phi), vbs.clone());
        // sqrt(phi - v) for v <= 0, else sphi/(1 + v/(2 phi)); and its derivative.
        let root = |v: Expr| {
            let reverse = le(v.clone(), c(0.0));
            let r = cond(
                reverse.clone(),
                sqrt(sub(c(phi), v.clone())),
                sdiv(c(sphi), add(c(1.0), mul(c(0.5 / phi), v))),
            );
            (reverse, r)
        };
        let (rs, s_expr) = root(vbs.clone());
        let sarg = s_expr;
        let (rd, b_expr) = root(sub(vbs.clone(), vds.clone()));
        let barg = b_expr;
        let dr = |rev: Expr, r: Expr| {
            cond(
                rev,
                sdiv(c(-0.5), r.clone()),
                mul(c(-0.5 / sphi3), mul(r.clone(), r)),
            )
        };
        let dsrgdb = dr(rs, sarg.clone());
        let dbrgdb = dr(rd, barg.clone());
        let vbin = add(c(p.vbi), mul(c(p.factor), phi_min_vbs.clone()));

        // The short-channel threshold.
        let (gamasd, dgddvb) = if p.xj > 0.0 && p.xd > 0.0 {
            let argxs = add(c(1.0), mul(c(2.0 * p.xd / p.xj), sarg.clone()));
            let argxd = add(c(1.0), mul(c(2.0 * p.xd / p.xj), barg.clone()));
            let args = sqrt(argxs);
            let argd = sqrt(argxd);
            let k = 0.5 * p.xj / l;
            let argss = mul(c(k), sub(args.clone(), c(1.0)));
            let argsd = mul(c(k), sub(argd.clone(), c(1.0)));
            let gamasd = mul(c(p.gamma), sub(sub(c(1.0), argss), argsd));
            let dbargs = sdiv(mul(c(0.5 / l * p.xd), dsrgdb.clone()), args);
            let dbargd = sdiv(mul(c(0.5 / l * p.xd), dbrgdb), argd);
            (gamasd, mul(c(-p.gamma), add(dbargs, dbargd)))
        } else {
            (c(p.gamma), c(0.0))
        };
        let gamasd = self.define(el, "gamasd", gamasd);
        let vth = add(vbin.clone(), mul(gamasd.clone(), sarg.clone()));
        let (von, xn) = match p.xn0 {
            Some(xn0) => {
                let cdonco = add(
                    Expr::Unary(
                        vams_design::UnaryOp::Neg,
                        Box::new(add(mul(gamasd.clone(), dsrgdb), mul(dgddvb, sarg.clone()))),
                    ),
                    c(p.factor),
                );
                let xn = self.define_from(el, "xn", add(c(xn0), cdonco), xn0);
                (add(vth.clone(), mul(c(p.vt), xn.clone())), Some(xn))
            }
            None => (vth.clone(), None),
        };
        let von = self.define(el, "von", von);
        let vgst = sub(vgs.clone(), von.clone());
        // Mobility degradation.
        let ufact = if p.uexp != 0.0 {
            cond(
                le(vgst.clone(), c(p.ucrit)),
                c(1.0),
                Expr::Call(
                    Builtin::Exp,
                    vec![mul(
                        c(p.uexp),
                        Expr::Call(
                            Builtin::Log,
                            vec![sdiv(c(p.ucrit), floor(vgst.clone(), p.ucrit))],
                        ),
                    )],
                ),
            )
        } else {
            c(1.0)
        };
        let ufact = self.define_from(el, "ufact", ufact, 1.0);
        let vgsx = if xn.is_some() {
            max(vgs.clone(), von.clone())
        } else {
            vgs.clone()
        };
        let eta = p.eta;
        let gammad = mul(c(1.0 / eta), gamasd.clone());
        let drive = mul(c(1.0 / eta), sub(vgsx, vbin.clone()));
        let drive = self.define(el, "drive", drive);
        // Grove-Frohman.
        let gf = if p.gamma != 0.0 {
            let gammd2 = mul(gammad.clone(), gammad.clone());
            let argv = add(drive.clone(), phi_min_vbs.clone());
            let arg1 = sqrt(add(c(1.0), sdiv(mul(c(4.0), argv.clone()), gammd2.clone())));
            let v = add(
                drive.clone(),
                mul(mul(c(0.5), gammd2.clone()), sub(c(1.0), arg1)),
            );
            cond(
                le(gammad.clone(), c(0.0)),
                max(drive.clone(), c(0.0)),
                cond(le(argv, c(0.0)), c(0.0), max(v, c(0.0))),
            )
        } else {
            max(drive.clone(), c(0.0))
        };
        let vdsat_gf = self.define(el, "vdsat_gf", gf);
        let sarg3 = mul(sarg.clone(), mul(sarg.clone(), sarg.clone()));
        let vdsat = vdsat_gf;
        let vdsat = self.define(el, "vdsat", vdsat);
        // bsarg: the root at the saturation voltage.
        let (_, bs) = root(sub(vbs.clone(), vdsat.clone()));
        let bsarg = bs;
        // Channel-length modulation: the shortening over the length, xlamda*vds.
        let short = if p.lambda > 0.0 || !p.nsub {
            mul(c(p.lambda), vds.clone())
        } else {
            let argv = mul(c(0.25), sub(vds.clone(), vdsat.clone()));
            let sargv = sqrt(add(c(1.0), mul(argv.clone(), argv.clone())));
            mul(c(p.xd / l), sqrt(add(argv, sargv)))
        };
        let short = cond(lt(c(0.0), vds.clone()), short, c(0.0));
        let clfact = sub(c(1.0), short.clone());
        // Punch-through.
        let xwb0 = p.xd * p.pb.sqrt();
        let xld = l - xwb0;
        let xwb = if p.nsub { xwb0 } else { 0.25e-6 };
        let xleff = mul(c(l), clfact.clone());
        let deltal = mul(c(l), short);
        let limited = mul(
            c(1.0 / l),
            sdiv(c(xwb), add(c(1.0), mul(c(1.0 / xwb), sub(deltal, c(xld))))),
        );
        let clfact = cond(lt(xleff, c(xwb)), limited, clfact);
        let clfact = self.define_from(el, "clfact", clfact, 1.0);
        let beta1 = sdiv(mul(c(p.beta), ufact), floor(clfact, 1e-3));
        let beta1 = self.define_from(el, "beta1", beta1, p.beta);
        let cube = |x: &Expr| mul(x.clone(), mul(x.clone(), x.clone()));
        let body = sub(cube(&barg), sarg3.clone());
        let bodys = sub(cube(&bsarg), sarg3);
        let g15 = mul(c(1.0 / 1.5), gamasd.clone());
        let linear = mul(
            beta1.clone(),
            sub(
                mul(
                    sub(
                        sub(vgs.clone(), vbin.clone()),
                        mul(c(eta / 2.0), vds.clone()),
                    ),
                    vds.clone(),
                ),
                mul(g15.clone(), body.clone()),
            ),
        );
        let saturation = mul(
            beta1.clone(),
            sub(
                mul(
                    sub(
                        sub(vgs.clone(), vbin.clone()),
                        mul(c(eta / 2.0), vdsat.clone()),
                    ),
                    vdsat.clone(),
                ),
                mul(g15.clone(), bodys.clone()),
            ),
        );
        let strong = cond(le(vds.clone(), vdsat.clone()), linear, saturation);
        // ngspice takes the current as 0 for vds <= 1e-10 but loads the conductance; the
        // formulas below give that 0 at vds = 0 and keep the conductance in the derivative.
        let cdrain = match xn {
            Some(xn) => {
                let vdson = cond(lt(vds.clone(), vdsat.clone()), vds.clone(), vdsat.clone());
                let body_on = cond(lt(vdsat.clone(), vds.clone()), bodys, body);
                let cdson = mul(
                    beta1,
                    sub(
                        mul(
                            sub(sub(von.clone(), vbin), mul(c(eta / 2.0), vdson.clone())),
                            vdson,
                        ),
                        mul(g15, body_on),
                    ),
                );
                let x = sdiv(sub(vgs.clone(), von.clone()), mul(c(p.vt), floor(xn, 1e-3)));
                let x = cond(lt(x.clone(), c(-700.0)), c(-700.0), x);
                let x = cond(lt(c(0.0), x.clone()), c(0.0), x);
                let weak = mul(cdson, Expr::Call(Builtin::Exp, vec![x]));
                let weak = cond(le(vdsat.clone(), c(0.0)), c(0.0), weak);
                cond(lt(von.clone(), vgs.clone()), strong, weak)
            }
            None => cond(lt(vbin, vgs.clone()), strong, c(0.0)),
        };
        (cdrain, von, vdsat)
    }
}

/// The value of `e` with quantity `k` at `q(k)`, for the expressions built here; `None` for
/// anything else.
fn eval(e: &Expr, q: &dyn Fn(u32) -> f64) -> Option<f64> {
    use vams_design::{UnaryOp, Value};
    let truth = |b: bool| if b { 1.0 } else { 0.0 };
    Some(match e {
        Expr::Const(Value::Real(x)) => *x,
        Expr::Const(Value::Boolean(b)) => truth(*b),
        Expr::Quantity(id) => q(id.0),
        Expr::Unary(op, a) => {
            let a = eval(a, q)?;
            match op {
                UnaryOp::Neg => -a,
                UnaryOp::Plus => a,
                UnaryOp::Abs => a.abs(),
                UnaryOp::Not => truth(a == 0.0),
            }
        }
        Expr::Binary(op, a, b) => {
            let (a, b) = (eval(a, q)?, eval(b, q)?);
            match op {
                BinaryOp::Add => a + b,
                BinaryOp::Sub => a - b,
                BinaryOp::Mul => a * b,
                BinaryOp::Div => a / b,
                BinaryOp::Lt => truth(a < b),
                BinaryOp::Le => truth(a <= b),
                BinaryOp::Gt => truth(a > b),
                BinaryOp::Ge => truth(a >= b),
                BinaryOp::And => truth(a != 0.0 && b != 0.0),
                _ => return None,
            }
        }
        Expr::Call(f, args) => {
            let a = eval(args.first()?, q)?;
            match f {
                Builtin::Exp => a.exp(),
                Builtin::Log => a.ln(),
                Builtin::Sqrt => a.sqrt(),
                Builtin::Atan => a.atan(),
                Builtin::Cos => a.cos(),
                _ => return None,
            }
        }
        Expr::If(c, a, b) => {
            if eval(c, q)? != 0.0 {
                eval(a, q)?
            } else {
                eval(b, q)?
            }
        }
        _ => return None,
    })
}
