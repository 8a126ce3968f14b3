//! The bipolar transistor `q c b e [s] model [area]`: ngspice's Gummel-Poon (level 1), at DC
//! and in time.
//!
//! Takes a Q element and its `.model npn|pnp`; gives, with ngspice's names, aliases (`va`,
//! `vb`, `ik`, `c2`, `c4`, `pe`, `me`, `pc`, `mc`, `csub`/`ccs`, `ps`, `ms`) and defaults (its
//! `bjt` device at TEMP = TNOM):
//! * the transport current `(cbe - cbc)/qb` from the internal collector to the internal
//!   emitter, `cbe = is*(exp(vbe/(nf*vt)) - 1)`, `cbc` likewise with `nr`, the base charge
//!   `qb = q1*(1 + sqrt(1 + 4*(cbe/ikf + cbc/ikr)))/2`, `q1 = 1/(1 - vbc/vaf - vbe/var)`;
//! * the base currents `cbe/bf + ise*(exp(vbe/(ne*vt)) - 1) + gmin*vbe` (base to emitter) and
//!   `cbc/br + isc*(exp(vbc/(nc*vt)) - 1) + gmin*vbc` (base to collector); every exponential
//!   continued as its tangent above 40 emission voltages (no Newton iterate overflows) and,
//!   as ngspice does, as `-is*(1 + (3*n*vt/(v*e))^3)` below `-3*n*vt`;
//! * `rc`, `re` and `rb` (with `rbm` and `irb` as ngspice varies it with the base current),
//!   divided by the area, as series resistors to the internal nodes `name#collector`,
//!   `name#emitter` and `name#base`, as ngspice names them; `gmin` from the substrate;
//! * the charges (see `charge`), each a quantity of its own scaled to volts
//!   (`name.qbe == Q/cs`) whose `'dot` times `cs` adds to its branch current, so charge is
//!   conserved whatever the step;
//! * pnp by flipping the sign of every voltage and current; `area` scales `is`, `ise`,
//!   `isc`, `ikf`, `ikr`, `irb`, `itf` and the capacitances, and divides the resistances.
//!
//! Refused, never ignored: every parameter not listed (`ptf`, `nkf`, `ibe`, `ibc`, `iss`,
//! the quasi-saturation `rco`, `vo`, `gamma`, `qco`, the `tlev` temperature parameters),
//! other levels, `off`, initial conditions, `m`, `areab`, `areac`, TEMP other than TNOM
//! (`xtb`, `eg`, `xti`, `kf`, `af` are accepted: they change nothing at TNOM or in a
//! transient), and values out of range.

use vams_design::{BinaryOp, Builtin, Expr, QuantityKind, TerminalId};

mod charge;

use super::Lowerer;
use crate::circuit::{ElementId, FlatElement, FlatModel};
use crate::deck::ModelKind;
use crate::error::SpiceError;
use charge::Charges;
use vams_design::build::{add, bin, cond, div, mul, sub};

/// Boltzmann's constant and the elementary charge as ngspice 39 has them (`const.h`).
const BOLTZMANN: f64 = 1.380_648_52e-23;
const CHARGE: f64 = 1.602_176_620_8e-19;
const CELSIUS_TO_KELVIN: f64 = 273.15;

/// Where the exponentials turn into their tangents, in emission voltages.
const EXP_LIMIT: f64 = 40.0;

/// Model parameters the lowering uses, aliases included.
const USED: [&str; 49] = [
    "is", "bf", "br", "nf", "nr", "vaf", "va", "var", "vb", "ikf", "ik", "ikr", "ise", "c2", "ne",
    "isc", "c4", "nc", "rb", "rbm", "irb", "re", "rc", "cje", "vje", "pe", "mje", "me", "tf",
    "xtf", "vtf", "itf", "cjc", "vjc", "pc", "mjc", "mc", "xcjc", "tr", "cjs", "csub", "ccs",
    "vjs", "ps", "mjs", "ms", "fc", "subs", "tnom",
];

/// Model parameters that change nothing at TEMP = TNOM (temperature, noise, the type).
const INERT: [&str; 8] = ["tref", "xtb", "eg", "xti", "kf", "af", "npn", "pnp"];

/// The Gummel-Poon numbers of one instance (area applied).
struct GummelPoon {
    /// +1 npn, -1 pnp.
    sign: f64,
    is: f64,
    ise: f64,
    isc: f64,
    bf: f64,
    br: f64,
    nf: f64,
    nr: f64,
    ne: f64,
    nc: f64,
    inv_vaf: f64,
    inv_var: f64,
    inv_ikf: f64,
    inv_ikr: f64,
    rb: f64,
    rbm: f64,
    irb: f64,
    re: f64,
    rc: f64,
    /// Substrate junction to the collector (vertical) or from the base (lateral).
    vertical: bool,
    gmin: f64,
    vt: f64,
    charge: Charges,
}

fn c(x: f64) -> Expr {
    Expr::real(x)
}

/// ngspice's junction current `is*(exp(v/nvt) - 1)`: the tangent above 40 `nvt`, the cubic
/// `-is*(1 + (3*nvt/(v*e))^3)` below `-3*nvt`.
fn junction(v: Expr, is: f64, nvt: f64) -> Expr {
    if is == 0.0 {
        return c(0.0);
    }
    let x = mul(c(1.0 / nvt), v.clone());
    let exp = cond(
        bin(BinaryOp::Gt, x.clone(), c(EXP_LIMIT)),
        mul(c(EXP_LIMIT.exp()), add(c(1.0 - EXP_LIMIT), x.clone())),
        Expr::Call(Builtin::Exp, vec![x]),
    );
    let knee = -3.0 * nvt;
    let k = (3.0 * nvt / std::f64::consts::E).powi(3);
    // v kept at or below the knee, so that the branch not taken stays finite.
    let vl = Expr::Call(Builtin::Realmin, vec![v.clone(), c(knee)]);
    let cubic = mul(
        c(-is),
        add(c(1.0), div(c(k), mul(vl.clone(), mul(vl.clone(), vl)))),
    );
    cond(
        bin(BinaryOp::Ge, v, c(knee)),
        mul(c(is), sub(exp, c(1.0))),
        cubic,
    )
}

impl Lowerer<'_> {
    /// Whether a BJT model has only parameters the lowering handles; reports the others.
    fn bjt_model_ok(&mut self, model: &FlatModel) -> bool {
        let mut ok = true;
        for (name, _) in &model.params {
            let n = name.as_str();
            if USED.contains(&n) || INERT.contains(&n) {
                continue;
            }
            ok = false;
            let why = match n {
                "rco" | "vo" | "gamma" | "qco" => " (quasi-saturation is not modelled)",
                "ptf" => " (excess phase is not modelled)",
                _ => "",
            };
            self.refuse_model(
                model,
                format!("the BJT model parameter `{name}`{why}"),
                format!(
                    "remove `{name}=`: the Gummel-Poon BJT is lowered with {}",
                    USED.join(", ")
                ),
            );
        }
        if let Some(level) = model.level.filter(|&l| l != 1) {
            ok = false;
            self.refuse_model(
                model,
                format!("BJT model level {level}"),
                "remove `level=`: the BJT is lowered as level 1 (Gummel-Poon)".into(),
            );
        }
        let p = |names: &[&str], default: f64| {
            names.iter().find_map(|n| model.param(n)).unwrap_or(default)
        };
        let checks: [(&str, f64, bool); 11] = [
            ("nf", p(&["nf"], 1.0), p(&["nf"], 1.0) > 0.0),
            ("nr", p(&["nr"], 1.0), p(&["nr"], 1.0) > 0.0),
            ("ne", p(&["ne"], 1.5), p(&["ne"], 1.5) > 0.0),
            ("nc", p(&["nc"], 2.0), p(&["nc"], 2.0) > 0.0),
            ("bf", p(&["bf"], 100.0), p(&["bf"], 100.0) != 0.0),
            ("br", p(&["br"], 1.0), p(&["br"], 1.0) != 0.0),
            (
                "vje",
                p(&["vje", "pe"], 0.75),
                p(&["vje", "pe"], 0.75) > 0.0,
            ),
            (
                "vjc",
                p(&["vjc", "pc"], 0.75),
                p(&["vjc", "pc"], 0.75) > 0.0,
            ),
            (
                "vjs",
                p(&["vjs", "ps"], 0.75),
                p(&["vjs", "ps"], 0.75) > 0.0,
            ),
            ("fc", p(&["fc"], 0.5), (0.0..1.0).contains(&p(&["fc"], 0.5))),
            (
                "mje, mjc, mjs",
                p(&["mje", "me"], 0.33)
                    .max(p(&["mjc", "mc"], 0.33))
                    .max(p(&["mjs", "ms"], 0.0)),
                [
                    p(&["mje", "me"], 0.33),
                    p(&["mjc", "mc"], 0.33),
                    p(&["mjs", "ms"], 0.0),
                ]
                .iter()
                .all(|&m| (0.0..1.0).contains(&m)),
            ),
        ];
        for (k, v, valid) in checks {
            if !valid || !v.is_finite() {
                ok = false;
                self.push_once(SpiceError::syntax(
                    model.span,
                    format!("`.model {}` has {k} = {v}, out of its range", model.name),
                    "parameter out of range",
                    "nf, nr, ne, nc and the junction potentials must be positive, bf and br \
                     non-zero, fc and the grading coefficients in [0, 1)",
                ));
            }
        }
        ok
    }

    /// The instance's numbers, or `None` after reporting why there are none.
    fn gummel_poon(&mut self, el: &FlatElement, model: &FlatModel) -> Option<GummelPoon> {
        let circuit = self.circuit;
        let mut ok = self.check_params(el, &["area"], true);
        ok &= self.bjt_model_ok(model);
        if el.state.is_some() {
            ok = false;
            self.not_supported(
                el,
                format!("`on`/`off` on `{}`", el.name),
                "remove `off`: the operating point starts from zero without it",
            );
        }
        let temp = circuit.options.temp.unwrap_or(27.0);
        let tnom = model
            .param("tnom")
            .or(model.param("tref"))
            .or(circuit.options.tnom)
            .unwrap_or(27.0);
        if temp != tnom {
            ok = false;
            self.not_supported(
                el,
                format!(
                    "a BJT at TEMP {temp} C other than TNOM {tnom} C (the temperature \
                     dependence of xtb, eg, xti)"
                ),
                "simulate at the nominal temperature (remove `.temp` / `.options temp=`)",
            );
        }
        let area = el
            .values
            .first()
            .copied()
            .or_else(|| el.param("area"))
            .unwrap_or(1.0);
        if ok && !(area > 0.0 && area.is_finite()) {
            ok = false;
            self.errors.push(SpiceError::syntax(
                el.span,
                format!("`{}` has area {area}, not positive", el.name),
                "non-positive area",
                "give a positive area factor (1 by default)",
            ));
        }
        if !ok {
            return None;
        }
        let p = |names: &[&str], default: f64| {
            names.iter().find_map(|n| model.param(n)).unwrap_or(default)
        };
        let inverse = |names: &[&str]| {
            let x = p(names, 0.0);
            if x != 0.0 { 1.0 / x } else { 0.0 }
        };
        let is = p(&["is"], 1e-16);
        // ise and isc below 1e-4 are currents, above it factors of is (ngspice's c2, c4).
        let leak = |names: &[&str]| {
            let x = p(names, 0.0);
            if x > 1e-4 { x * is } else { x }
        };
        let sign = if model.kind == ModelKind::Pnp {
            -1.0
        } else {
            1.0
        };
        // `subs` 1 vertical, -1 lateral, anything else the type's default (ngspice's).
        let vertical = match model.param("subs").map(|x| x.round() as i64) {
            Some(1) => true,
            Some(-1) => false,
            _ => sign > 0.0,
        };
        let rb = p(&["rb"], 0.0);
        let cjc = p(&["cjc"], 0.0) * area;
        let xcjc = p(&["xcjc"], 1.0);
        let vtf = p(&["vtf"], 0.0);
        let charge = Charges {
            tf: p(&["tf"], 0.0),
            xtf: p(&["xtf"], 0.0),
            ovtf: if vtf != 0.0 { 1.0 / (1.44 * vtf) } else { 0.0 },
            itf: p(&["itf"], 0.0) * area,
            tr: p(&["tr"], 0.0),
            cje: p(&["cje"], 0.0) * area,
            vje: p(&["vje", "pe"], 0.75),
            mje: p(&["mje", "me"], 0.33),
            cjc_int: cjc * xcjc,
            cjc_ext: cjc - cjc * xcjc,
            vjc: p(&["vjc", "pc"], 0.75),
            mjc: p(&["mjc", "mc"], 0.33),
            cjs: p(&["cjs", "csub", "ccs"], 0.0) * area,
            vjs: p(&["vjs", "ps"], 0.75),
            mjs: p(&["mjs", "ms"], 0.0),
            fc: p(&["fc"], 0.5).min(0.9999),
        };
        Some(GummelPoon {
            sign,
            is: is * area,
            ise: leak(&["ise", "c2"]) * area,
            isc: leak(&["isc", "c4"]) * area,
            bf: p(&["bf"], 100.0),
            br: p(&["br"], 1.0),
            nf: p(&["nf"], 1.0),
            nr: p(&["nr"], 1.0),
            ne: p(&["ne"], 1.5),
            nc: p(&["nc"], 2.0),
            inv_vaf: inverse(&["vaf", "va"]),
            inv_var: inverse(&["var", "vb"]),
            inv_ikf: inverse(&["ikf", "ik"]) / area,
            inv_ikr: inverse(&["ikr"]) / area,
            rb: rb / area,
            rbm: p(&["rbm"], rb) / area,
            irb: p(&["irb"], 0.0) * area,
            re: p(&["re"], 0.0) / area,
            rc: p(&["rc"], 0.0) / area,
            vertical,
            gmin: circuit.options.gmin.unwrap_or(1e-12),
            vt: BOLTZMANN * (temp + CELSIUS_TO_KELVIN) / CHARGE,
            charge,
        })
    }

    /// A charge `q` (npn sense) as a scaled quantity `name.key`; gives `cs*name.key'dot`.
    fn bjt_charge(&mut self, el: &FlatElement, key: &str, q: Expr, cs: f64) -> Expr {
        let name = format!("{}.{key}", el.name);
        let qv = self.quantity(name.clone(), QuantityKind::Free, el.span);
        let text = format!("{name} == {key}(...) / {cs:?}");
        self.equation(el, Expr::Quantity(qv), mul(c(1.0 / cs), q), text);
        mul(c(cs), Expr::Dot(qv))
    }

    pub(super) fn bjt(&mut self, _id: ElementId, el: &FlatElement) {
        let circuit = self.circuit;
        if el.nodes.len() != 3 && el.nodes.len() != 4 {
            self.not_supported(
                el,
                format!("a BJT with {} nodes (`{}`)", el.nodes.len(), el.name),
                "write the nodes collector, base, emitter and optionally substrate, then the model",
            );
            return;
        }
        let nodes: Vec<_> = (0..el.nodes.len()).map(|k| self.node(el, k)).collect();
        let (Some(cn), Some(bn), Some(en)) = (nodes[0], nodes[1], nodes[2]) else {
            return;
        };
        let sn = match nodes.get(3) {
            Some(Some(s)) => *s,
            Some(None) => return,
            None => TerminalId(0),
        };
        let Some(model) = el.model.and_then(|m| circuit.models.get(m.0 as usize)) else {
            self.not_supported(
                el,
                format!("a BJT without a model (`{}`)", el.name),
                "give the BJT a `.model name npn(...)` and name it after the nodes",
            );
            return;
        };
        let Some(p) = self.gummel_poon(el, model) else {
            return;
        };
        let q = Expr::Quantity;
        let t = p.sign;
        let vt = p.vt;
        let ci = self.series_resistor(el, cn, p.rc, "collector", "rc");
        let ei = self.series_resistor(el, en, p.re, "emitter", "re");
        // The base resistance depends on the base current (RBM, IRB): its own equation below.
        let base_resistor = (p.rb > 0.0).then(|| self.internal_branch(el, bn, "base", "rb"));
        let bi = base_resistor.map_or(bn, |(inner, _, _)| inner);

        let vbe = self.across(format!("{}.vbe", el.name), bi, ei, el.span);
        let vbc = self.across(format!("{}.vbc", el.name), bi, ci, el.span);
        // Voltages in the npn sense.
        let nvbe = mul(c(t), q(vbe));
        let nvbc = mul(c(t), q(vbc));
        let cbe = junction(nvbe.clone(), p.is, p.nf * vt);
        let cbc = junction(nvbc.clone(), p.is, p.nr * vt);
        let cben = add(
            junction(nvbe.clone(), p.ise, p.ne * vt),
            mul(c(p.gmin), nvbe.clone()),
        );
        let cbcn = add(
            junction(nvbc.clone(), p.isc, p.nc * vt),
            mul(c(p.gmin), nvbc.clone()),
        );
        // The base charge: q1 from the Early voltages (its denominator kept positive),
        // with the high-injection roll-off.
        let den = sub(
            sub(c(1.0), mul(c(p.inv_vaf), nvbc.clone())),
            mul(c(p.inv_var), nvbe.clone()),
        );
        let q1 = div(c(1.0), Expr::Call(Builtin::Realmax, vec![den, c(1e-6)]));
        let qb = if p.inv_ikf == 0.0 && p.inv_ikr == 0.0 {
            q1
        } else {
            let q2 = add(
                mul(c(p.inv_ikf), cbe.clone()),
                mul(c(p.inv_ikr), cbc.clone()),
            );
            let arg = add(c(1.0), mul(c(4.0), q2));
            let root = Expr::Call(
                Builtin::Sqrt,
                vec![Expr::Call(Builtin::Realmax, vec![arg.clone(), c(1e-30)])],
            );
            let sqarg = cond(bin(BinaryOp::Gt, arg, c(0.0)), root, c(1.0));
            mul(mul(c(0.5), q1), add(c(1.0), sqarg))
        };

        // The transport current, internal collector to internal emitter.
        let it = self.through(format!("{}.it", el.name), ci, ei, el.span);
        let transport = div(sub(cbe.clone(), cbc.clone()), qb.clone());
        let text = format!(
            "{} == {t:?} * (cbe - cbc) / qb (is {:?}, nf {:?}, nr {:?}, vaf^-1 {:?}, var^-1 {:?}, ikf^-1 {:?}, ikr^-1 {:?})",
            self.qname(it),
            p.is,
            p.nf,
            p.nr,
            p.inv_vaf,
            p.inv_var,
            p.inv_ikf,
            p.inv_ikr
        );
        self.equation(el, q(it), mul(c(t), transport), text);

        let ch = p.charge;
        // Base to emitter.
        let ibe = self.through(format!("{}.ibe", el.name), bi, ei, el.span);
        let mut current = add(div(cbe.clone(), c(p.bf)), cben.clone());
        let mut text = format!(
            "{} == {t:?} * (cbe / {:?} + ise_diode + gmin * vbe",
            self.qname(ibe),
            p.bf
        );
        if let Some(qbe) = ch.base_emitter(nvbe.clone(), nvbc.clone(), cbe.clone(), qb.clone()) {
            let cs = Charges::scale(ch.cje, ch.tf);
            current = add(current, self.bjt_charge(el, "qbe", qbe, cs));
            text.push_str(" + qbe'dot");
        }
        text.push(')');
        self.equation(el, q(ibe), mul(c(t), current), text);
        // Base to collector.
        let ibc = self.through(format!("{}.ibc", el.name), bi, ci, el.span);
        let mut current = add(div(cbc.clone(), c(p.br)), cbcn.clone());
        let mut text = format!(
            "{} == {t:?} * (cbc / {:?} + isc_diode + gmin * vbc",
            self.qname(ibc),
            p.br
        );
        if let Some(qbc) = ch.base_collector(nvbc.clone(), cbc.clone()) {
            let cs = Charges::scale(ch.cjc_int, ch.tr);
            current = add(current, self.bjt_charge(el, "qbc", qbc, cs));
            text.push_str(" + qbc'dot");
        }
        text.push(')');
        self.equation(el, q(ibc), mul(c(t), current), text);
        // The external base to the internal collector (cjc*(1 - xcjc)).
        if ch.cjc_ext > 0.0 {
            let vbx = self.across(format!("{}.vbx", el.name), bn, ci, el.span);
            let ibx = self.through(format!("{}.ibx", el.name), bn, ci, el.span);
            if let Some(qbx) = ch.base_external(mul(c(t), q(vbx))) {
                let dq = self.bjt_charge(el, "qbx", qbx, ch.cjc_ext);
                let text = format!("{} == {t:?} * qbx'dot", self.qname(ibx));
                self.equation(el, q(ibx), mul(c(t), dq), text);
            }
        }
        // The substrate junction: gmin and its depletion charge.
        let (anode, cathode) = if p.vertical { (sn, ci) } else { (bi, sn) };
        if anode != cathode {
            let vsub = self.across(format!("{}.vsub", el.name), anode, cathode, el.span);
            let isub = self.through(format!("{}.isub", el.name), anode, cathode, el.span);
            let nvsub = mul(c(t), q(vsub));
            let mut current = mul(c(p.gmin), nvsub.clone());
            let mut text = format!("{} == {t:?} * ({:?} * vsub", self.qname(isub), p.gmin);
            if let Some(qs) = ch.substrate(nvsub) {
                current = add(current, self.bjt_charge(el, "qsub", qs, ch.cjs));
                text.push_str(" + qsub'dot");
            }
            text.push(')');
            self.equation(el, q(isub), mul(c(t), current), text);
        }
        // The base resistance: rbm + (rb - rbm)/qb, or ngspice's irb form of the base
        // current.
        if let Some((_, v, i)) = base_resistor {
            let rbpi = p.rb - p.rbm;
            let rbb = if p.irb != 0.0 {
                let cb = add(add(div(cbe, c(p.bf)), cben), add(div(cbc, c(p.br)), cbcn));
                let arg1 = Expr::Call(Builtin::Realmax, vec![mul(c(1.0 / p.irb), cb), c(1e-9)]);
                let z = div(
                    sub(
                        Expr::Call(
                            Builtin::Sqrt,
                            vec![add(c(1.0), mul(c(14.59025), arg1.clone()))],
                        ),
                        c(1.0),
                    ),
                    mul(c(2.4317), Expr::Call(Builtin::Sqrt, vec![arg1])),
                );
                let tan = Expr::Call(Builtin::Tan, vec![z.clone()]);
                add(
                    c(p.rbm),
                    div(
                        mul(c(3.0 * rbpi), sub(tan.clone(), z.clone())),
                        mul(z, mul(tan.clone(), tan)),
                    ),
                )
            } else if rbpi != 0.0 {
                add(c(p.rbm), div(c(rbpi), qb))
            } else {
                c(p.rb)
            };
            let text = format!(
                "{} == rbb * {} (rb {:?}, rbm {:?}, irb {:?})",
                self.qname(v),
                self.qname(i),
                p.rb,
                p.rbm,
                p.irb
            );
            self.equation(el, q(v), mul(rbb, q(i)), text);
        }
    }
}
