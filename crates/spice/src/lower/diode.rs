//! The diode `d n+ n- model [area]`: ngspice's junction at DC and in time without charge.
//!
//! Takes a D element and its `.model d`; gives the Shockley current
//! `i == area*is*(exp(v/(n*vt)) - 1) + gmin*v` (`vt = k*T/q` at TEMP, 27 C by default, with
//! ngspice's constants; `gmin` 1e-12 S unless `.options gmin=`), and for `rs > 0` the series
//! resistance `rs/area` to an internal node `name#internal`, as ngspice names it. Above 40
//! thermal voltages the exponential continues as its tangent, so that no Newton iterate
//! overflows. Junction and diffusion charge (`cjo`, `tt`), breakdown (`bv`) and temperature
//! scaling (TEMP other than TNOM) are refused as not supported yet, never ignored.

use vams_design::{BinaryOp, Builtin, Expr, TerminalId};

use super::{Lowerer, add, bin, mul, sub};
use crate::circuit::{ElementId, FlatElement, ModelId};
use crate::error::SpiceError;

/// Boltzmann's constant and the elementary charge as ngspice 39 has them (`const.h`).
const BOLTZMANN: f64 = 1.380_648_52e-23;
const CHARGE: f64 = 1.602_176_620_8e-19;
const CELSIUS_TO_KELVIN: f64 = 273.15;

/// Where the exponential turns into its tangent, in thermal voltages.
const EXP_LIMIT: f64 = 40.0;

/// Model parameters that change nothing at TEMP = TNOM without junction capacitance.
const INERT: [&str; 6] = ["eg", "xti", "tnom", "vj", "m", "fc"];

/// Model parameters that are inert at zero (their default).
const ZERO_ONLY: [&str; 3] = ["cjo", "cj0", "tt"];

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
        for (name, value) in &model.params {
            let fine = matches!(name.as_str(), "is" | "n" | "rs")
                || INERT.contains(&name.as_str())
                || (ZERO_ONLY.contains(&name.as_str()) && *value == 0.0);
            if !fine {
                refuse(
                    &mut self.errors,
                    format!("the diode model parameter `{name}`"),
                    format!(
                        "remove `{name}=`: the diode is lowered with is, n and rs (cjo and tt only at 0)"
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

        let junction_anode = if rs > 0.0 {
            let inner = self.internal_terminal(format!("{}#internal", el.name), el.span);
            let v = self.across(format!("{}.rs.v", el.name), anode, inner, el.span);
            let i = self.through(format!("{}.rs.i", el.name), anode, inner, el.span);
            let text = format!("{} == {rs:?} * {}", self.qname(v), self.qname(i));
            self.equation(
                el,
                Expr::Quantity(v),
                mul(Expr::real(rs), Expr::Quantity(i)),
                text,
            );
            inner
        } else {
            anode
        };
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
        let current = add(
            mul(c(is), sub(limited, c(1.0))),
            mul(c(gmin), Expr::Quantity(v)),
        );
        let text = format!(
            "{} == {is:?} * (exp({} / {nvt:?}) - 1.0) + {gmin:?} * {}",
            self.qname(i),
            self.qname(v),
            self.qname(v)
        );
        self.equation(el, Expr::Quantity(i), current, text);
    }
}
