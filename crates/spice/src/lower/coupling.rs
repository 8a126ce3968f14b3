//! The coupled inductors `K name l1 l2 k`.
//!
//! Takes the K elements of the circuit after every other element is lowered (an inductor's
//! equation `v == l * i'dot` must exist); gives no quantity of its own but adds the mutual
//! terms to the two inductor equations, `v1 == l1*i1'dot + m*i2'dot` and
//! `v2 == l2*i2'dot + m*i1'dot` with `m = k*sqrt(l1*l2)`, ngspice's dot convention (each
//! inductor's first node dotted, each current flowing from its first node to its second).
//! Several K on the same inductor add up. Never accepts `|k| > 1` (the inductance matrix would
//! not be positive semi-definite) nor a K naming anything but two distinct inductors.

use vams_design::{BinaryOp, Expr, QuantityId};

use super::{Lowerer, mul, sub};
use crate::circuit::{ElementId, FlatElement};
use crate::deck::ElementKind;

impl Lowerer<'_> {
    /// The mutual terms of every K element.
    pub(super) fn couplings(&mut self) {
        let c = self.circuit;
        for el in c.elements.iter().filter(|e| e.kind == ElementKind::K) {
            self.coupling(el);
        }
    }

    fn coupling(&mut self, el: &FlatElement) {
        if !self.check_params(el, &[], false) {
            return;
        }
        let c = self.circuit;
        let inductors: Vec<(ElementId, &FlatElement)> = el
            .controls
            .iter()
            .filter_map(|&id| c.elements.get(id.0 as usize).map(|e| (id, e)))
            .filter(|(_, e)| e.kind == ElementKind::L)
            .collect();
        let [(id1, l1), (id2, l2)] = inductors[..] else {
            self.not_supported(
                el,
                format!("the coupling `{}` of anything but two inductors", el.name),
                "name two inductors and the coupling, e.g. `k1 l1 l2 0.99`",
            );
            return;
        };
        if id1 == id2 {
            self.not_supported(
                el,
                format!("the coupling `{}` of `{}` with itself", el.name, l1.name),
                "name two distinct inductors",
            );
            return;
        }
        let Some(k) = el.values.first().copied() else {
            self.not_supported(
                el,
                format!("the coupling `{}` without a coefficient", el.name),
                "write the coupling coefficient after the inductors, e.g. `k1 l1 l2 0.99`",
            );
            return;
        };
        if k.is_nan() || k.abs() > 1.0 {
            self.not_supported(
                el,
                format!("the coupling coefficient {k} of `{}`", el.name),
                "give a coupling coefficient with |k| <= 1",
            );
            return;
        }
        // An inductor that failed to lower has its own error already.
        let (Some((e1, i1, x1)), Some((e2, i2, x2))) =
            (self.inductor(id1, l1), self.inductor(id2, l2))
        else {
            return;
        };
        let m = k * (x1 * x2).sqrt();
        let (n1, n2) = (self.qname(i1).to_string(), self.qname(i2).to_string());
        for (eq, other, name) in [(e1, i2, n2), (e2, i1, n1)] {
            let Some(e) = self.design.equations.get_mut(eq) else {
                continue;
            };
            let old = std::mem::replace(&mut e.residual, Expr::real(0.0));
            e.residual = sub(old, mul(Expr::real(m), Expr::Dot(other)));
            e.text = format!("{} + {m:?} * {name}'dot", e.text);
        }
    }

    /// The equation index, the through quantity and the inductance of a lowered inductor:
    /// the equation `v == l * i'dot` (with the mutual terms of earlier K subtracted after it).
    fn inductor(&self, id: ElementId, el: &FlatElement) -> Option<(usize, QuantityId, f64)> {
        let name = self.current_name(id, el);
        self.design.equations.iter().enumerate().find_map(|(k, e)| {
            let mut r = &e.residual;
            // Down the mutual terms to `v - l * i'dot`.
            while let Expr::Binary(BinaryOp::Sub, lhs, _) = r
                && !matches!(lhs.as_ref(), Expr::Quantity(_))
            {
                r = lhs;
            }
            let Expr::Binary(BinaryOp::Sub, lhs, rhs) = r else {
                return None;
            };
            let (Expr::Quantity(_), Expr::Binary(BinaryOp::Mul, l, dot)) =
                (lhs.as_ref(), rhs.as_ref())
            else {
                return None;
            };
            match (l.as_ref(), dot.as_ref()) {
                (Expr::Const(value), Expr::Dot(i)) if self.qname(*i) == name => {
                    value.as_f64().map(|x| (k, *i, x))
                }
                _ => None,
            }
        })
    }
}
