//! The diode `d n+ n- model [area]`: ngspice's level 1 junction with its charge.
//!
//! Takes a D element and its `.model d`; gives the Shockley current
//! `id == area*is*(exp(v/(n*vt)) - 1) + gmin*v` (`vt = k*T/q` at TEMP, 27 C by default, with
//! ngspice's constants; `gmin` 1e-12 S unless `.options gmin=`), and for `rs > 0` the series
//! resistance `rs/area` to an internal node `name#internal`, as ngspice names it. Above 40
//! thermal voltages the exponential continues as its tangent, so that no Newton iterate
//! overflows. With `cjo` (`cj0`, `cj`) or `tt`, the junction stores ngspice's charge
//! `Q(v) = tt*(id - gmin*v) + Qdep(v)`: the depletion charge of `cjo*area`, `vj` (`pb`,
//! default 1) and `m` (`mj`, default 0.5) below `fc*vj` (`fc` default 0.5) and ngspice's
//! linear-capacitance extension above it (`dioload.c`; `m` limited to 0.9 and `fc` to 0.95
//! as `diosetup.c` does). The charge is a quantity of its own, scaled to volts,
//! `name.qv == Q(v)/cs`, and the branch current is `i == id + cs*name.qv'dot`, so the charge
//! is conserved whatever the step. Breakdown (`bv`), sidewall charge and temperature scaling
//! (TEMP other than TNOM) are refused as not supported yet, never ignored.

use vams_design::{BinaryOp, Builtin, Expr, Quantity, QuantityId, QuantityKind, TerminalId};

use super::{Lowerer, add, bin, junction, mul, sub};
use crate::circuit::{ElementId, FlatElement, FlatModel, ModelId};
use crate::error::SpiceError;

/// Boltzmann's constant and the elementary charge as ngspice 39 has them (`const.h`).
const BOLTZMANN: f64 = 1.380_648_52e-23;
const CHARGE: f64 = 1.602_176_620_8e-19;
const CELSIUS_TO_KELVIN: f64 = 273.15;

/// Where the exponential turns into its tangent, in thermal voltages.
const EXP_LIMIT: f64 = 40.0;

/// Model parameters that change nothing at TEMP = TNOM.
const INERT: [&str; 3] = ["eg", "xti", "tnom"];

/// The model parameters lowered, aliases included.
const LOWERED: [&str; 12] = [
    "is", "n", "rs", "cjo", "cj0", "cj", "vj", "pb", "m", "mj", "fc", "tt",
];

impl Lowerer<'_> {
    /// Whether a diode model has only parameters the lowering handles; the first diode that
    /// uses it reports the others, on the `.model` card.
    fn diode_model_ok(&mut self, id: ModelId) -> bool {
        if let Some(known) = self.diode_models.get(&id) {
            return *known;
        }
        let circuit = self.circuit;
        let Some(model) = circuit.models.get(id.0 as usize) else {
            return false;
        };
        let mut ok = true;
        let mut refuse = |errors: &mut Vec<SpiceError>, what: String, help: String| {
            ok = false;
            errors.push(SpiceError::NotSupported {
                span: model.span,
                what,
                label: format!("in `.model {}`", model.name),
                help,
            });
        };
        for (name, _) in &model.params {
            let fine = LOWERED.contains(&name.as_str()) || INERT.contains(&name.as_str());
            if !fine {
                refuse(
                    &mut self.errors,
                    format!("the diode model parameter `{name}`"),
                    format!(
                        "remove `{name}=`: the diode is lowered with is, n, rs, cjo, vj, m, fc and tt"
                    ),
                );
            }
        }
        if let Some(level) = model.level.filter(|&l| l != 1) {
            refuse(
                &mut self.errors,
                format!("diode model level {level}"),
                "remove `level=`: the diode is lowered as the level 1 junction".into(),
            );
        }
        self.diode_models.insert(id, ok);
        ok
    }

    pub(super) fn diode(
        &mut self,
        id: ElementId,
        el: &FlatElement,
        anode: TerminalId,
        cathode: TerminalId,
    ) {
        let circuit = self.circuit;
        let Some(model) = el.model.and_then(|m| circuit.models.get(m.0 as usize)) else {
            self.not_supported(
                el,
                format!("a diode without a model (`{}`)", el.name),
                "give the diode a `.model name d(...)` and name it after the nodes",
            );
            return;
        };
        if !self.check_params(el, &["area"], true) {
            return;
        }
        let Some(model_id) = el.model else { return };
        let mut ok = self.diode_model_ok(model_id);
        let temp = circuit.options.temp.unwrap_or(27.0);
        let tnom = model.param("tnom").or(circuit.options.tnom).unwrap_or(27.0);
        if temp != tnom {
            ok = false;
            self.not_supported(
                el,
                format!("a diode at TEMP {temp} C other than TNOM {tnom} C"),
                "simulate at the nominal temperature (remove `.temp` / `.options temp=`)",
            );
        }
        if !ok {
            return;
        }
        let area = el
            .values
            .first()
            .copied()
            .or_else(|| el.param("area"))
            .unwrap_or(1.0);
        let is = model.param("is").unwrap_or(1e-14) * area;
        let n = model.param("n").unwrap_or(1.0);
        let rs = model.param("rs").unwrap_or(0.0) / area;
        let gmin = circuit.options.gmin.unwrap_or(1e-12);
        let vt = BOLTZMANN * (temp + CELSIUS_TO_KELVIN) / CHARGE;
        let nvt = n * vt;

        let junction_anode = self.series_resistor(el, anode, rs, "internal", "rs");
        let (v, i) = self.branch(id, el, junction_anode, cathode);
        let c = Expr::real;
        let x = mul(c(1.0 / nvt), Expr::Quantity(v));
        let exp = |e: Expr| Expr::Call(Builtin::Exp, vec![e]);
        // exp(x) below the limit, its tangent exp(L) * (1 + x - L) above.
        let limited = Expr::If(
            Box::new(bin(BinaryOp::Gt, x.clone(), c(EXP_LIMIT))),
            Box::new(mul(c(EXP_LIMIT.exp()), add(c(1.0 - EXP_LIMIT), x.clone()))),
            Box::new(exp(x)),
        );
        let junction = mul(c(is), sub(limited, c(1.0)));
        let current = add(junction.clone(), mul(c(gmin), Expr::Quantity(v)));
        let mut text = format!(
            "{} == {is:?} * (exp({} / {nvt:?}) - 1.0) + {gmin:?} * {}",
            self.qname(i),
            self.qname(v),
            self.qname(v)
        );
        let charge = Charge::of(model, area);
        if charge.czero != 0.0 && !(charge.vj > 0.0 && charge.czero > 0.0) {
            self.not_supported(
                el,
                format!(
                    "a junction capacitance cjo={} with vj={} in `{}`",
                    charge.czero, charge.vj, model.name
                ),
                "give cjo >= 0 and a junction potential vj > 0",
            );
            return;
        }
        let current = match charge.expr(Expr::Quantity(v), junction) {
            None => current,
            Some(q) => {
                let cs = charge.scale();
                let qv = self.charge_quantity(format!("{}.qv", el.name), el);
                let qtext = format!(
                    "{} == (tt * id + qdep({})) / {cs:?}",
                    self.qname(qv),
                    self.qname(v)
                );
                self.equation(el, Expr::Quantity(qv), mul(c(1.0 / cs), q), qtext);
                text = format!("{text} + {cs:?} * {}'dot", self.qname(qv));
                add(current, mul(c(cs), Expr::Dot(qv)))
            }
        };
        self.equation(el, Expr::Quantity(i), current, text);
    }

    /// A free quantity in volts (the tolerance group `DEFAULT_VOLTAGE`).
    fn charge_quantity(&mut self, name: String, el: &FlatElement) -> QuantityId {
        self.design.quantities.push(Quantity {
            name,
            kind: QuantityKind::Free,
            tolerance: Some(self.voltage.tolerance.clone()),
            subtype: self.voltage.subtype.clone(),
            unit: Some(self.voltage.unit.clone()),
            initial_guess: None,
            span: el.span,
        });
        QuantityId(self.design.quantities.len() as u32 - 1)
    }
}

/// The charge parameters of a diode, as ngspice's `diosetup.c` limits them.
struct Charge {
    /// `cjo * area`.
    czero: f64,
    vj: f64,
    m: f64,
    fc: f64,
    tt: f64,
}

impl Charge {
    fn of(model: &FlatModel, area: f64) -> Charge {
        let p = |names: &[&str]| names.iter().find_map(|n| model.param(n));
        Charge {
            czero: p(&["cjo", "cj0", "cj"]).unwrap_or(0.0) * area,
            vj: p(&["vj", "pb"]).unwrap_or(1.0),
            m: p(&["m", "mj"]).unwrap_or(0.5).min(0.9),
            fc: p(&["fc"]).unwrap_or(0.5).min(0.95),
            tt: p(&["tt"]).unwrap_or(0.0),
        }
    }

    /// The charge's scale in farads: the quantity `qv` is `Q / scale` volts.
    fn scale(&self) -> f64 {
        if self.czero > 0.0 {
            self.czero
        } else {
            // A transit time alone: `qv` is the current times 1 kOhm.
            self.tt * 1e-3
        }
    }

    /// `Q(v)` with `id` the junction current without gmin; `None` without charge (or with a
    /// junction potential ngspice could not use).
    fn expr(&self, v: Expr, id: Expr) -> Option<Expr> {
        let c = Expr::real;
        let Charge {
            czero,
            vj,
            m,
            fc,
            tt,
        } = *self;
        let depletion = czero > 0.0 && vj > 0.0 && vj.is_finite();
        let diffusion = tt > 0.0 && tt.is_finite();
        let mut q = diffusion.then(|| mul(c(tt), id));
        if depletion && let Some(dep) = junction::depletion(czero, vj, m, fc, v) {
            q = Some(match q {
                Some(d) => add(d, dep),
                None => dep,
            });
        }
        q
    }
}
