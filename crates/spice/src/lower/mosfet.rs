//! The MOSFET `m d g s b model [l= w= ad= as= pd= ps= nrd= nrs= m=]`: ngspice's level 1
//! (Shichman-Hodges), at DC and in time.
//!
//! Takes an M element and its `.model nmos|pmos`; gives, with ngspice's parameter names,
//! defaults and semantics (its `mos1` device at TEMP = TNOM):
//! * the channel current `ids` through drain to source: cutoff, linear and saturation with
//!   channel-length modulation `lambda` and the body effect `gamma`, `phi` (the threshold
//!   `vto + gamma*(sqrt(phi - vbs) - sqrt(phi))`, continued linearly for `vbs > 0` as ngspice
//!   does), `beta = kp*m*w/leff`, `leff = l - 2*ld`, `kp` from `uo` (600 cm^2/Vs) and `tox`
//!   when `kp` is absent; when `vds < 0` the drain and the source swap, written as `if`
//!   expressions on `vds`, so the equation is symmetric and its symbolic derivatives exact;
//!   pmos by flipping the sign of every voltage and current;
//! * the bulk-drain and bulk-source junctions `is*(exp(v/vt) - 1) + gmin*v` (`is*m`, or
//!   `js*ad*m` and `js*as*m` when `js`, `ad` and `as` are all non-zero), continued as their
//!   tangent above 40 thermal voltages so that no Newton iterate overflows;
//! * `rd`, `rs` (else `rsh*nrd`, `rsh*nrs`, squares 1 by default), divided by `m`, as series
//!   resistors to the internal nodes `name#drain` and `name#source`, as ngspice names them;
//! * the bulk junctions' depletion charge (`cbd`, `cbs`, else `cj*ad`, `cj*as`, plus
//!   `cjsw*pd`, `cjsw*ps`; `mj`, `mjsw`, `pb`, `fc`), as charges: a free quantity `name.qbd`
//!   (`name.qbs`) holds the charge over its zero-bias capacitance, in volts, and the junction
//!   current adds that capacitance times its `'dot`;
//! * Meyer's gate capacitances from `cox = eps_ox/tox*w*leff*m` plus the overlaps
//!   `cgso*w*m`, `cgdo*w*m`, `cgbo*leff*m`, as capacitances (`i == C(v)*v'dot`), as ngspice
//!   has them (see `charge`).
//!
//! Level 2 (`level=2`, ngspice's mos2) shares all of this but the channel current and the
//! `von`, `vdsat` of Meyer's capacitances, which come from `level2`.
//!
//! Refused, never ignored: `nsub`, `nss`, `tpg` and every other parameter not listed, other
//! levels, `off`, initial conditions, TEMP other than TNOM, and values out of range (`pb`,
//! `tox`, `fc`, `mj`, `mjsw`).

use vams_design::{BinaryOp, Builtin, Expr, QuantityKind};

mod charge;
mod level2;

use super::Lowerer;
use crate::circuit::{ElementId, FlatElement, FlatModel, OptionValue};
use crate::deck::ModelKind;
use crate::error::SpiceError;
use vams_design::build::{add, bin, cond, mul, sub};

/// Boltzmann's constant and the elementary charge as ngspice 39 has them (`const.h`).
const BOLTZMANN: f64 = 1.380_648_52e-23;
const CHARGE: f64 = 1.602_176_620_8e-19;
const CELSIUS_TO_KELVIN: f64 = 273.15;
/// The oxide's permittivity as ngspice's mos1 computes it (3.9 times that of vacuum).
const EPS_OX: f64 = 3.9 * 8.854_214_871e-12;

/// Where the junction exponential turns into its tangent, in thermal voltages.
const EXP_LIMIT: f64 = 40.0;

/// Model parameters the lowering uses.
const USED: [&str; 26] = [
    "vto", "vt0", "kp", "gamma", "phi", "lambda", "rd", "rs", "rsh", "is", "js", "tox", "uo", "u0",
    "ld", "cbd", "cbs", "cj", "cjsw", "mj", "mjsw", "pb", "fc", "cgso", "cgdo", "cgbo",
];

/// Model parameters that change nothing at TEMP = TNOM (noise, the type flags).
const INERT: [&str; 7] = ["tnom", "kf", "af", "nlev", "gdsnoi", "nmos", "pmos"];

/// The instance parameters lowered.
const INSTANCE: [&str; 9] = ["l", "w", "ad", "as", "pd", "ps", "nrd", "nrs", "m"];

/// The level 1 numbers of one instance.
struct Level1 {
    /// +1 nmos, -1 pmos.
    sign: f64,
    vto: f64,
    gamma: f64,
    phi: f64,
    lambda: f64,
    beta: f64,
    drain_sat: f64,
    source_sat: f64,
    rd: f64,
    rs: f64,
    gmin: f64,
    vt: f64,
    /// The charge numbers (all capacitances 0 without them).
    charge: charge::Charges,
}

impl Lowerer<'_> {
    /// Whether a MOSFET model has only parameters the lowering handles; reports the others.
    fn mosfet_model_ok(&mut self, model: &FlatModel) -> bool {
        let mut ok = true;
        for (name, _) in &model.params {
            let n = name.as_str();
            if USED.contains(&n)
                || INERT.contains(&n)
                || (model.level == Some(2) && level2::USED.contains(&n))
            {
                continue;
            }
            ok = false;
            self.refuse_model(
                model,
                format!("the MOSFET model parameter `{name}`"),
                match model.level {
                    Some(2) => format!(
                        "remove `{name}=`: the level 2 MOSFET is lowered with {}, {}",
                        USED.join(", "),
                        level2::USED.join(", ")
                    ),
                    _ => format!(
                        "remove `{name}=`: the level 1 MOSFET is lowered with {}",
                        USED.join(", ")
                    ),
                },
            );
        }
        let bad = |k: &'static str, default: f64, valid: fn(f64) -> bool| {
            let v = model.param(k).unwrap_or(default);
            (!valid(v)).then_some((k, v))
        };
        let invalid = [
            bad("pb", 0.8, |v| v > 0.0),
            bad("fc", 0.5, |v| (0.0..1.0).contains(&v)),
            bad("mj", 0.5, |v| v != 1.0),
            bad("mjsw", 0.5, |v| v != 1.0),
            bad("tox", 1.0, |v| v >= 0.0),
        ];
        for (k, v) in invalid.into_iter().flatten() {
            ok = false;
            self.push_once(SpiceError::syntax(
                model.span,
                format!("`.model {}` has {k} = {v}, out of its range", model.name),
                "parameter out of range",
                "pb and tox must be positive, fc in [0, 1), mj and mjsw other than 1",
            ));
        }
        if let Some(level) = model.level.filter(|&l| l != 1 && l != 2) {
            ok = false;
            self.refuse_model(
                model,
                format!("MOSFET model level {level}"),
                "remove `level=`: the MOSFET is lowered as level 1 (Shichman-Hodges)".into(),
            );
        }
        let phi = model.param("phi").unwrap_or(0.6);
        if phi <= 0.0 {
            ok = false;
            self.push_once(SpiceError::syntax(
                model.span,
                format!("`.model {}` has phi = {phi}, not positive", model.name),
                "phi must be positive",
                "give the surface potential `phi=` a positive value (0.6 by default)",
            ));
        }
        ok
    }

    /// A numeric `.options` value (`defl`, `defw`, `defad`, `defas`).
    fn numeric_option(&self, key: &str) -> Option<f64> {
        self.circuit
            .options
            .other
            .iter()
            .rev()
            .find_map(|(n, v, _)| match v {
                OptionValue::Number(x) if n == key => Some(*x),
                _ => None,
            })
    }

    /// The instance's numbers, or `None` after reporting why there are none.
    fn level1(&mut self, el: &FlatElement, model: &FlatModel) -> Option<Level1> {
        let circuit = self.circuit;
        let mut ok = self.check_params(el, &INSTANCE, true);
        ok &= self.mosfet_model_ok(model);
        if el.state.is_some() {
            ok = false;
            self.not_supported(
                el,
                format!("`on`/`off` on `{}`", el.name),
                "remove `off`: the operating point starts from zero without it",
            );
        }
        let temp = circuit.options.temp.unwrap_or(27.0);
        let tnom = model.param("tnom").or(circuit.options.tnom).unwrap_or(27.0);
        if temp != tnom {
            ok = false;
            self.not_supported(
                el,
                format!("a MOSFET at TEMP {temp} C other than TNOM {tnom} C"),
                "simulate at the nominal temperature (remove `.temp` / `.options temp=`)",
            );
        }
        let inst = |k: &str, option: &str, default: f64| {
            el.param(k)
                .or_else(|| self.numeric_option(option))
                .unwrap_or(default)
        };
        let l = inst("l", "defl", 1e-4);
        let w = inst("w", "defw", 1e-4);
        let ad = inst("ad", "defad", 0.0);
        let as_ = inst("as", "defas", 0.0);
        let m = el.param("m").unwrap_or(1.0);
        let nrd = el.param("nrd").unwrap_or(1.0);
        let nrs = el.param("nrs").unwrap_or(1.0);
        let ld = model.param("ld").unwrap_or(0.0);
        let leff = l - 2.0 * ld;
        if ok && (leff <= 0.0 || w <= 0.0 || m <= 0.0) {
            ok = false;
            self.errors.push(SpiceError::syntax(
                el.span,
                format!(
                    "`{}` has l - 2*ld = {leff:e}, w = {w:e}, m = {m}: all must be positive",
                    el.name
                ),
                "non-positive size",
                "give positive `l=` (greater than twice the model's `ld`), `w=` and `m=`",
            ));
        }
        if !ok {
            return None;
        }
        let sign = if model.kind == ModelKind::Pmos {
            -1.0
        } else {
            1.0
        };
        let tox = model.param("tox").unwrap_or(0.0);
        let kp = match (model.param("kp"), tox != 0.0) {
            (Some(kp), _) => kp,
            (None, true) => {
                let uo = model.param("uo").or(model.param("u0")).unwrap_or(600.0);
                uo * EPS_OX / tox * 1e-4
            }
            (None, false) => 2e-5,
        };
        let is = model.param("is").unwrap_or(1e-14);
        let js = model.param("js").unwrap_or(0.0);
        let (drain_sat, source_sat) = if js == 0.0 || ad == 0.0 || as_ == 0.0 {
            (m * is, m * is)
        } else {
            (m * js * ad, m * js * as_)
        };
        let pd = el.param("pd").unwrap_or(0.0);
        let ps = el.param("ps").unwrap_or(0.0);
        let cox = if tox > 0.0 {
            EPS_OX / tox * w * leff * m
        } else {
            0.0
        };
        let bottom = |given: &str, area: f64| match (model.param(given), model.param("cj")) {
            (Some(cz), _) => cz * m,
            (None, Some(cj)) => cj * area * m,
            (None, None) => 0.0,
        };
        let cjsw = model.param("cjsw").unwrap_or(0.0);
        let charge = charge::Charges {
            czbd: bottom("cbd", ad),
            czbdsw: cjsw * pd * m,
            czbs: bottom("cbs", as_),
            czbssw: cjsw * ps * m,
            mj: model.param("mj").unwrap_or(0.5),
            mjsw: model.param("mjsw").unwrap_or(0.5),
            pb: model.param("pb").unwrap_or(0.8),
            fc: model.param("fc").unwrap_or(0.5),
            cox,
            cgs_overlap: model.param("cgso").unwrap_or(0.0) * w * m,
            cgd_overlap: model.param("cgdo").unwrap_or(0.0) * w * m,
            cgb_overlap: model.param("cgbo").unwrap_or(0.0) * leff * m,
        };
        let series = |r: Option<f64>, squares: f64| match (r, model.param("rsh")) {
            (Some(r), _) => r / m,
            (None, Some(rsh)) => rsh * squares / m,
            (None, None) => 0.0,
        };
        Some(Level1 {
            sign,
            vto: model.param("vto").or(model.param("vt0")).unwrap_or(0.0),
            gamma: model.param("gamma").unwrap_or(0.0),
            phi: model.param("phi").unwrap_or(0.6),
            lambda: model.param("lambda").unwrap_or(0.0),
            beta: kp * m * w / leff,
            drain_sat,
            source_sat,
            rd: series(model.param("rd"), nrd),
            rs: series(model.param("rs"), nrs),
            gmin: circuit.options.gmin.unwrap_or(1e-12),
            vt: BOLTZMANN * (temp + CELSIUS_TO_KELVIN) / CHARGE,
            charge,
        })
    }

    pub(super) fn mosfet(&mut self, id: ElementId, el: &FlatElement) {
        let circuit = self.circuit;
        if el.nodes.len() != 4 {
            self.not_supported(
                el,
                format!("a MOSFET with {} nodes (`{}`)", el.nodes.len(), el.name),
                "write the four nodes drain, gate, source and bulk, then the model",
            );
            return;
        }
        let nodes: Vec<_> = (0..4).map(|k| self.node(el, k)).collect();
        let [Some(d), Some(g), Some(s), Some(b)] = nodes[..] else {
            return;
        };
        let Some(model) = el.model.and_then(|m| circuit.models.get(m.0 as usize)) else {
            self.not_supported(
                el,
                format!("a MOSFET without a model (`{}`)", el.name),
                "give the MOSFET a `.model name nmos(...)` and name it after the nodes",
            );
            return;
        };
        let Some(mut p) = self.level1(el, model) else {
            return;
        };
        let level2 = match model.level {
            Some(2) => match self.level2(el, model, &mut p) {
                Some(l2) => Some(l2),
                None => return,
            },
            _ => None,
        };
        let d = self.series_resistor(el, d, p.rd, "drain", "rd");
        let s = self.series_resistor(el, s, p.rs, "source", "rs");
        let q = Expr::Quantity;
        let c = Expr::real;
        let vds = self.across(format!("{}.vds", el.name), d, s, el.span);
        let vgs = self.across(format!("{}.vgs", el.name), g, s, el.span);
        let vbs = self.across(format!("{}.vbs", el.name), b, s, el.span);
        let ids = self.through(self.current_name(id, el), d, s, el.span);
        let ibd = self.through(format!("{}.ibd", el.name), b, d, el.span);
        let ibs = self.through(format!("{}.ibs", el.name), b, s, el.span);
        // Voltages in the nmos sense.
        let t = p.sign;
        let nvds = mul(c(t), q(vds));
        let nvgs = mul(c(t), q(vgs));
        let nvbs = mul(c(t), q(vbs));
        let nvbd = sub(nvbs.clone(), nvds.clone());
        let nvgd = sub(nvgs.clone(), nvds.clone());
        let forward = bin(BinaryOp::Ge, nvds.clone(), c(0.0));
        let local = |a: &Expr, b: &Expr| cond(forward.clone(), a.clone(), b.clone());
        let level2 = level2.map(|l2| {
            let lvds = cond(
                forward.clone(),
                nvds.clone(),
                Expr::Unary(vams_design::UnaryOp::Neg, Box::new(nvds.clone())),
            );
            let lvgs = local(&nvgs, &nvgd);
            let (cd, von, vdsat) =
                self.level2_channel(el, &l2, lvgs.clone(), local(&nvbs, &nvbd), lvds.clone());
            (cd, von, vdsat, lvgs, lvds)
        });
        let channel = if let Some((cd, ..)) = &level2 {
            cond(
                forward.clone(),
                cd.clone(),
                Expr::Unary(vams_design::UnaryOp::Neg, Box::new(cd.clone())),
            )
        } else {
            Expr::If(
                Box::new(forward.clone()),
                Box::new(p.drain_current(nvgs.clone(), nvbs.clone(), nvds.clone())),
                Box::new(Expr::Unary(
                    vams_design::UnaryOp::Neg,
                    Box::new(p.drain_current(
                        nvgd.clone(),
                        nvbd.clone(),
                        Expr::Unary(vams_design::UnaryOp::Neg, Box::new(nvds)),
                    )),
                )),
            )
        };
        let (n_ids, n_vds, n_vgs, n_vbs) = (
            self.qname(ids).to_string(),
            self.qname(vds).to_string(),
            self.qname(vgs).to_string(),
            self.qname(vbs).to_string(),
        );
        let kind = if t > 0.0 { "nmos" } else { "pmos" };
        let text = format!(
            "{n_ids} == level{}_{kind}({n_vgs}, {n_vds}, {n_vbs}; vto {:?}, beta {:?}, gamma {:?}, phi {:?}, lambda {:?})",
            if level2.is_some() { 2 } else { 1 },
            p.vto,
            p.beta,
            p.gamma,
            p.phi,
            p.lambda
        );
        self.equation(el, q(ids), mul(c(t), channel), text);
        let ch = p.charge;
        for (i, v, sat, name, cz, czsw) in [
            (ibd, nvbd.clone(), p.drain_sat, "vbd", ch.czbd, ch.czbdsw),
            (ibs, nvbs.clone(), p.source_sat, "vbs", ch.czbs, ch.czbssw),
        ] {
            let mut current = add(
                mul(c(sat), sub(junction_exp(v.clone(), p.vt), c(1.0))),
                mul(c(p.gmin), v.clone()),
            );
            let mut text = format!(
                "{} == {t:?} * ({sat:?} * (exp({name} / {:?}) - 1.0) + {:?} * {name}",
                self.qname(i),
                p.vt,
                p.gmin
            );
            if let Some(charge) = ch.depletion(cz, czsw, v) {
                // The charge over its zero-bias capacitance, in volts: the quantity keeps the
                // voltage tolerances, which suit it.
                let cref = if cz + czsw != 0.0 { cz + czsw } else { 1.0 };
                let qname = format!("{}.q{}", el.name, &name[1..]);
                let qv = self.quantity(qname.clone(), QuantityKind::Free, el.span);
                let qtext = format!("{qname} == depletion_charge({name}) / {cref:?}");
                self.equation(el, q(qv), mul(c(1.0 / cref), charge), qtext);
                current = add(current, mul(c(cref), Expr::Dot(qv)));
                text.push_str(&format!(" + {cref:?} * {qname}'dot"));
            }
            text.push(')');
            self.equation(el, q(i), mul(c(t), current), text);
        }
        if ch.cox > 0.0 || ch.cgs_overlap > 0.0 || ch.cgd_overlap > 0.0 || ch.cgb_overlap > 0.0 {
            let vgd = self.across(format!("{}.vgd", el.name), g, d, el.span);
            let vgb = self.across(format!("{}.vgb", el.name), g, b, el.span);
            let (cgs, cgd, cgb) =
                if let (true, Some((_, von, vdsat, lvgs, lvds))) = (ch.cox > 0.0, &level2) {
                    let (a, b, cb) = ch.meyer(
                        p.phi,
                        lvgs.clone(),
                        sub(lvgs.clone(), lvds.clone()),
                        von.clone(),
                        vdsat.clone(),
                    );
                    (local(&a, &b), local(&b, &a), cb)
                } else if ch.cox > 0.0 {
                    let von_f = p.von(nvbs.clone());
                    let von_r = p.von(nvbd.clone());
                    let (fs, fd, fb) = ch.meyer(
                        p.phi,
                        nvgs.clone(),
                        nvgd.clone(),
                        von_f.clone(),
                        sub(nvgs.clone(), von_f),
                    );
                    let (rd, rs, rb) = ch.meyer(
                        p.phi,
                        nvgd.clone(),
                        nvgs.clone(),
                        von_r.clone(),
                        sub(nvgd.clone(), von_r),
                    );
                    let pick = |a: Expr, b: Expr| cond(forward.clone(), a, b);
                    (pick(fs, rs), pick(fd, rd), pick(fb, rb))
                } else {
                    (c(0.0), c(0.0), c(0.0))
                };
            for (v, plus, minus, cap, overlap, key) in [
                (vgs, g, s, cgs, ch.cgs_overlap, "gs"),
                (vgd, g, d, cgd, ch.cgd_overlap, "gd"),
                (vgb, g, b, cgb, ch.cgb_overlap, "gb"),
            ] {
                let i = self.through(format!("{}.i{key}", el.name), plus, minus, el.span);
                let text = format!(
                    "{} == (meyer_c{key} + {overlap:?}) * {}'dot",
                    self.qname(i),
                    self.qname(v)
                );
                self.equation(el, q(i), mul(add(cap, c(overlap)), Expr::Dot(v)), text);
            }
        }
    }
}

/// `exp(v/vt)` below the limit, its tangent above.
fn junction_exp(v: Expr, vt: f64) -> Expr {
    let c = Expr::real;
    let x = mul(c(1.0 / vt), v);
    Expr::If(
        Box::new(bin(BinaryOp::Gt, x.clone(), c(EXP_LIMIT))),
        Box::new(mul(c(EXP_LIMIT.exp()), add(c(1.0 - EXP_LIMIT), x.clone()))),
        Box::new(Expr::Call(Builtin::Exp, vec![x])),
    )
}

impl Level1 {
    /// ngspice's `von`, the threshold in the nmos sense, at the bulk voltage `vbs` of the
    /// mode's source.
    fn von(&self, vbs: Expr) -> Expr {
        let c = Expr::real;
        let sqrt_phi = self.phi.sqrt();
        let reverse_bias = bin(BinaryOp::Le, vbs.clone(), c(0.0));
        // sqrt(phi - vbs) for vbs <= 0 (its argument kept >= phi on the other branch too),
        // else the tangent sqrt(phi) - vbs/(2 sqrt(phi)), not below 0.
        let root = Expr::Call(
            Builtin::Sqrt,
            vec![cond(
                reverse_bias.clone(),
                sub(c(self.phi), vbs.clone()),
                c(self.phi),
            )],
        );
        let tangent = sub(c(sqrt_phi), mul(c(0.5 / sqrt_phi), vbs));
        let tangent = cond(bin(BinaryOp::Gt, tangent.clone(), c(0.0)), tangent, c(0.0));
        let sarg = cond(reverse_bias, root, tangent);
        // von = vbi*type + gamma*sarg, vbi = vto - type*gamma*sqrt(phi).
        add(
            c(self.sign * self.vto - self.gamma * sqrt_phi),
            mul(c(self.gamma), sarg),
        )
    }

    /// ngspice's `cdrain` in the normal mode (`vds >= 0`) of the nmos-sense voltages.
    fn drain_current(&self, vgs: Expr, vbs: Expr, vds: Expr) -> Expr {
        let c = Expr::real;
        let von = self.von(vbs);
        let vgst = sub(vgs, von);
        let betap = mul(c(self.beta), add(c(1.0), mul(c(self.lambda), vds.clone())));
        let saturation = mul(mul(c(0.5), betap.clone()), mul(vgst.clone(), vgst.clone()));
        let linear = mul(
            mul(betap, vds.clone()),
            sub(vgst.clone(), mul(c(0.5), vds.clone())),
        );
        cond(
            bin(BinaryOp::Le, vgst.clone(), c(0.0)),
            c(0.0),
            cond(bin(BinaryOp::Le, vgst, vds), saturation, linear),
        )
    }
}
