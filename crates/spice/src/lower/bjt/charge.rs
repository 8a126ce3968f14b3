//! The Gummel-Poon transistor's charges, as expressions of the npn-sense voltages.
//!
//! Takes the model's numbers (area applied); gives expressions, never equations (the parent
//! writes those). As ngspice's `bjtload` has them: the base-emitter charge
//! `tf*cbe*(1 + argtf)/qb` (for `vbe > 0`, `argtf = xtf*exp(vbc/(1.44*vtf))*(cbe/(cbe + itf))^2`;
//! `tf*cbe` below) plus the depletion charge of `cje`, `vje`, `mje`; the base-collector charge
//! `tr*cbc` plus that of `cjc*xcjc`, `vjc`, `mjc`, and the external base-collector depletion
//! charge of `cjc*(1 - xcjc)`; each depletion charge continued linearly in capacitance above
//! `fc*vj`. The substrate charge of `cjs`, `vjs`, `mjs` has no `fc`: above 0 V it is
//! `v*cjs*(1 + mjs*v/(2*vjs))`.

use vams_design::{BinaryOp, Builtin, Expr};

use vams_design::build::{add, bin, cond, div, mul, sub};

use crate::lower::junction::{depletion, power};

/// The charge numbers of one instance (area applied).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Charges {
    pub tf: f64,
    pub xtf: f64,
    /// `1/(1.44*vtf)`, 0 without `vtf`.
    pub ovtf: f64,
    pub itf: f64,
    pub tr: f64,
    pub cje: f64,
    pub vje: f64,
    pub mje: f64,
    /// `cjc*xcjc` (to the internal base) and `cjc*(1 - xcjc)` (to the external base).
    pub cjc_int: f64,
    pub cjc_ext: f64,
    pub vjc: f64,
    pub mjc: f64,
    pub cjs: f64,
    pub vjs: f64,
    pub mjs: f64,
    pub fc: f64,
}

fn c(x: f64) -> Expr {
    Expr::real(x)
}

fn plus(a: Option<Expr>, b: Option<Expr>) -> Option<Expr> {
    match (a, b) {
        (Some(a), Some(b)) => Some(add(a, b)),
        (a, None) => a,
        (None, b) => b,
    }
}

impl Charges {
    /// The base-emitter charge; `cbe` and `cbc` the transport diodes' currents (no gmin),
    /// `qb` the base charge.
    pub(super) fn base_emitter(&self, vbe: Expr, vbc: Expr, cbe: Expr, qb: Expr) -> Option<Expr> {
        let diffusion = (self.tf != 0.0).then(|| {
            let mut argtf = c(self.xtf);
            if self.xtf != 0.0 {
                if self.ovtf != 0.0 {
                    // exp(vbc*ovtf), its exponent bounded so that no iterate overflows.
                    let x = Expr::Call(Builtin::Realmin, vec![mul(c(self.ovtf), vbc), c(80.0)]);
                    argtf = mul(argtf, Expr::Call(Builtin::Exp, vec![x]));
                }
                if self.itf != 0.0 {
                    let ratio = div(cbe.clone(), add(cbe.clone(), c(self.itf)));
                    argtf = mul(argtf, mul(ratio.clone(), ratio));
                }
            }
            let modulated = div(mul(cbe.clone(), add(c(1.0), argtf)), qb);
            mul(
                c(self.tf),
                cond(bin(BinaryOp::Gt, vbe.clone(), c(0.0)), modulated, cbe),
            )
        });
        plus(
            diffusion,
            depletion(self.cje, self.vje, self.mje, self.fc, vbe),
        )
    }

    /// The internal base-collector charge; `cbc` the reverse transport diode's current.
    pub(super) fn base_collector(&self, vbc: Expr, cbc: Expr) -> Option<Expr> {
        let diffusion = (self.tr != 0.0).then(|| mul(c(self.tr), cbc));
        plus(
            diffusion,
            depletion(self.cjc_int, self.vjc, self.mjc, self.fc, vbc),
        )
    }

    /// The external base-collector charge (`1 - xcjc` of `cjc`).
    pub(super) fn base_external(&self, vbx: Expr) -> Option<Expr> {
        depletion(self.cjc_ext, self.vjc, self.mjc, self.fc, vbx)
    }

    /// The substrate junction's charge.
    pub(super) fn substrate(&self, vsub: Expr) -> Option<Expr> {
        if self.cjs == 0.0 {
            return None;
        }
        let (cz, ps, ms) = (self.cjs, self.vjs, self.mjs);
        let arg = Expr::Call(
            Builtin::Realmax,
            vec![sub(c(1.0), mul(c(1.0 / ps), vsub.clone())), c(1.0)],
        );
        let below = mul(c(ps * cz / (1.0 - ms)), sub(c(1.0), power(arg, 1.0 - ms)));
        let above = mul(
            mul(c(cz), vsub.clone()),
            add(c(1.0), mul(c(ms / (2.0 * ps)), vsub.clone())),
        );
        Some(cond(bin(BinaryOp::Lt, vsub, c(0.0)), below, above))
    }

    /// A scale in farads for a charge quantity: the zero-bias capacitance, else a transit
    /// time's over 1 kOhm.
    pub(super) fn scale(cz: f64, tt: f64) -> f64 {
        if cz > 0.0 {
            cz
        } else if tt > 0.0 {
            tt * 1e-3
        } else {
            1e-12
        }
    }
}
