//! The level 1 MOSFET's charge: the bulk junctions' depletion charge and Meyer's gate
//! capacitances, as expressions of the nmos-sense voltages.
//!
//! Takes the model's and instance's numbers; gives expressions, never equations (the parent
//! writes those). The depletion charge is ngspice's (`mos1load`): below `fc*pb`
//! `pb*cz*(1 - (1 - v/pb)^(1-mj))/(1-mj)` plus the sidewall term with `mjsw`, above it the
//! quadratic continuation `f4 + v*(f2 + v*f3/2)`; it is a charge, so the current is its
//! time derivative and charge is conserved. Meyer's model (`DEVqmeyer`) is a set of
//! capacitances, not of charges: as in ngspice the gate currents are `C(v)*v'dot`, which
//! does not conserve charge exactly (nor does ngspice's).

use vams_design::{BinaryOp, Expr};

use vams_design::build::{add, bin, cond, div, mul, sub};

use crate::lower::junction::power;

/// The charge numbers of one instance (nmos sense, multiplier applied).
#[derive(Clone, Copy, Debug, Default)]
pub(super) struct Charges {
    /// Bottom and sidewall zero-bias junction capacitances, drain and source.
    pub czbd: f64,
    pub czbdsw: f64,
    pub czbs: f64,
    pub czbssw: f64,
    pub mj: f64,
    pub mjsw: f64,
    pub pb: f64,
    pub fc: f64,
    /// `eps_ox/tox * w * leff * m` (0 without `tox`).
    pub cox: f64,
    /// The overlaps `cgso*w*m`, `cgdo*w*m`, `cgbo*leff*m`.
    pub cgs_overlap: f64,
    pub cgd_overlap: f64,
    pub cgb_overlap: f64,
}

fn c(x: f64) -> Expr {
    Expr::real(x)
}

impl Charges {
    /// The depletion charge of a junction with capacitances `cz` (bottom) and `czsw`
    /// (sidewall) at the nmos-sense voltage `v`; `None` when both are 0.
    pub(super) fn depletion(&self, cz: f64, czsw: f64, v: Expr) -> Option<Expr> {
        if cz == 0.0 && czsw == 0.0 {
            return None;
        }
        let (mj, mjsw, pb, fc) = (self.mj, self.mjsw, self.pb, self.fc);
        let dep = fc * pb;
        // The coefficients of the quadratic continuation (ngspice's f2, f3, f4).
        let arg0 = 1.0 - fc;
        let (s0, s0sw) = (arg0.powf(-mj), arg0.powf(-mjsw));
        let f2 = cz * (1.0 - fc * (1.0 + mj)) * s0 / arg0
            + czsw * (1.0 - fc * (1.0 + mjsw)) * s0sw / arg0;
        let f3 = cz * mj * s0 / arg0 / pb + czsw * mjsw * s0sw / arg0 / pb;
        let f4 = cz * pb * (1.0 - arg0 * s0) / (1.0 - mj)
            + czsw * pb * (1.0 - arg0 * s0sw) / (1.0 - mjsw)
            - f3 / 2.0 * dep * dep
            - dep * f2;
        let below = bin(BinaryOp::Lt, v.clone(), c(dep));
        // 1 - v/pb, kept at 1 on the branch that does not use it.
        let arg = cond(
            below.clone(),
            sub(c(1.0), mul(c(1.0 / pb), v.clone())),
            c(1.0),
        );
        let graded = add(
            mul(
                c(pb * cz / (1.0 - mj)),
                sub(c(1.0), power(arg.clone(), 1.0 - mj)),
            ),
            mul(
                c(pb * czsw / (1.0 - mjsw)),
                sub(c(1.0), power(arg, 1.0 - mjsw)),
            ),
        );
        let quadratic = add(c(f4), mul(v.clone(), add(c(f2), mul(c(f3 / 2.0), v))));
        Some(cond(below, graded, quadratic))
    }

    /// Meyer's `(cgs, cgd, cgb)` without the overlaps, in the normal mode (`vds >= 0`): the
    /// full capacitances (twice what `DEVqmeyer` returns, which is one half of a trapezoid).
    pub(super) fn meyer(
        &self,
        phi: f64,
        vgs: Expr,
        vgd: Expr,
        von: Expr,
        vdsat: Expr,
    ) -> (Expr, Expr, Expr) {
        let cox = self.cox;
        let le = |a: Expr, b: Expr| bin(BinaryOp::Le, a, b);
        let vgst = sub(vgs.clone(), von);
        let vdsat = cond(bin(BinaryOp::Gt, vdsat.clone(), c(0.025)), vdsat, c(0.025));
        let vds = sub(vgs, vgd);
        let triode = bin(BinaryOp::Lt, vds.clone(), vdsat.clone());
        // 2*vdsat - vds, kept at 1 where not used (it is > vdsat > 0 where it is).
        let vddif = cond(
            triode.clone(),
            sub(mul(c(2.0), vdsat.clone()), vds.clone()),
            c(1.0),
        );
        let vddif2 = mul(vddif.clone(), vddif);
        let vddif1 = sub(vdsat.clone(), vds);
        let source_share = sub(c(1.0), div(mul(vddif1.clone(), vddif1), vddif2.clone()));
        let drain_share = sub(c(1.0), div(mul(vdsat.clone(), vdsat), vddif2));
        // Depletion and weak inversion: -phi < vgst <= 0.
        let weak = add(mul(c(cox / (1.5 * phi)), vgst.clone()), c(cox / 3.0));
        let strong = c(cox / 3.0);
        let cgs = cond(
            le(vgst.clone(), c(-phi / 2.0)),
            c(0.0),
            cond(
                le(vgst.clone(), c(0.0)),
                cond(
                    triode.clone(),
                    mul(weak.clone(), source_share.clone()),
                    weak.clone(),
                ),
                cond(
                    triode.clone(),
                    mul(strong.clone(), source_share),
                    strong.clone(),
                ),
            ),
        );
        let cgd = cond(
            le(vgst.clone(), c(-phi / 2.0)),
            c(0.0),
            cond(
                le(vgst.clone(), c(0.0)),
                cond(triode.clone(), mul(weak, drain_share.clone()), c(0.0)),
                cond(triode, mul(strong, drain_share), c(0.0)),
            ),
        );
        let cgb = cond(
            le(vgst.clone(), c(-phi)),
            c(cox / 2.0),
            cond(
                le(vgst.clone(), c(0.0)),
                mul(c(-cox / (2.0 * phi)), vgst),
                c(0.0),
            ),
        );
        let twice = |e: Expr| mul(c(2.0), e);
        (twice(cgs), twice(cgd), twice(cgb))
    }
}
