//! `Q'ltf(num, den)`: a Laplace transfer function realised at elaboration as a state space in
//! controllable canonical form, with auxiliary quantities and equations.
//!
//! With `den(s) = a0 + a1 s + ... + an s^n` and `num(s) = b0 + ... + bm s^m` (ascending powers,
//! `m <= n`), the states are `x1 = z, x2 = z', ..., xn = z^(n-1)` of the signal `z` with
//! `den(s) z = Q`; the output is `num(s) z`:
//!
//! ```text
//! x1'dot == x2, ..., x(n-1)'dot == xn
//! an * xn'dot + a0 x1 + ... + a(n-1) xn == Q
//! Q'ltf == b0 x1 + ... + b(n-1) xn + bn xn'dot      (bn only when m = n)
//! ```
//!
//! The quiescent point (every derivative zero) gives the DC value `Q b0 / a0`.

use vams_design::{Expr, QuantityId};
use vams_syntax::ast;
use vams_syntax::source::Span;

use crate::attributes::synth::{self, arg, linear, sub};
use crate::error::ElabError;
use crate::names::scope::Scope;
use crate::{Elab, R};

/// A proper transfer function in ascending powers of `s`: `den` has a nonzero last
/// coefficient and `num` is no longer than `den`.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct Transfer {
    pub num: Vec<f64>,
    pub den: Vec<f64>,
}

impl Transfer {
    /// Trims trailing zero coefficients and checks properness; `Err` says what is wrong.
    pub fn new(mut num: Vec<f64>, mut den: Vec<f64>) -> Result<Transfer, String> {
        while den.len() > 1 && den.last() == Some(&0.0) {
            den.pop();
        }
        while num.len() > 1 && num.last() == Some(&0.0) {
            num.pop();
        }
        if den.iter().chain(&num).any(|c| !c.is_finite()) {
            return Err("the coefficients must be finite".into());
        }
        if den.last().copied().unwrap_or(0.0) == 0.0 {
            return Err("the denominator is zero".into());
        }
        if num.len() > den.len() {
            return Err(format!(
                "the numerator has degree {} but the denominator only {}: the transfer \
                 function is not proper",
                num.len() - 1,
                den.len() - 1
            ));
        }
        Ok(Transfer { num, den })
    }

    /// The order `n` (number of states).
    pub fn order(&self) -> usize {
        self.den.len() - 1
    }
}

impl<'a> Elab<'a> {
    /// `q'ltf(num, den)`: the output quantity.
    pub(crate) fn ltf_attribute(
        &mut self,
        sc: &Scope<'a>,
        q: QuantityId,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<Expr> {
        let (Some(num), Some(den), None) = (arg(args, 0), arg(args, 1), arg(args, 2)) else {
            return Err(self.error(ElabError::invalid(
                span,
                "`'ltf` takes two arguments: the numerator and denominator coefficients",
                Some(
                    "`q'ltf(num, den)` with real_vector constants in ascending powers of s".into(),
                ),
            )));
        };
        let num = self.coefficients(sc, num, "the numerator of `'ltf`")?;
        let den = self.coefficients(sc, den, "the denominator of `'ltf`")?;
        let tf = Transfer::new(num, den).map_err(|m| {
            self.error(ElabError::invalid(
                span,
                m,
                Some("`'ltf` needs a proper transfer function: deg num <= deg den".into()),
            ))
        })?;
        Ok(Expr::Quantity(self.ltf_realise(q, &tf, span)))
    }

    /// Auxiliary quantities and equations of `tf` driven by `q`; returns the output.
    fn ltf_realise(&mut self, q: QuantityId, tf: &Transfer, span: Span) -> QuantityId {
        let n = tf.order();
        let input = self.qname(q);
        let out = self.aux_quantity(q, "ltf");
        let out_name = self.qname(out);
        if n == 0 {
            let gain = tf.num[0] / tf.den[0];
            let residual = sub(
                Expr::Quantity(out),
                synth::mul(synth::real(gain), Expr::Quantity(q)),
            );
            self.generated_equation(residual, span, format!("{out_name} == {gain} * {input}"));
            return out;
        }
        let states: Vec<QuantityId> = (1..=n)
            .map(|i| self.aux_quantity(q, &format!("ltf.x{i}")))
            .collect();
        let x = |i: usize| Expr::Quantity(states[i]);
        for i in 0..n - 1 {
            let residual = sub(Expr::Dot(states[i]), x(i + 1));
            let text = format!(
                "{}'dot == {}",
                self.qname(states[i]),
                self.qname(states[i + 1])
            );
            self.generated_equation(residual, span, text);
        }
        let top = Expr::Dot(states[n - 1]);
        let lhs = linear(
            (0..n)
                .map(|i| (tf.den[i], x(i)))
                .chain([(tf.den[n], top.clone())]),
        );
        self.generated_equation(
            sub(lhs, Expr::Quantity(q)),
            span,
            format!("den(s) {out_name}.z == {input}"),
        );
        let bn = tf.num.get(n).copied().unwrap_or(0.0);
        let rhs = linear(
            (0..n)
                .map(|i| (tf.num.get(i).copied().unwrap_or(0.0), x(i)))
                .chain([(bn, top)]),
        );
        self.generated_equation(
            sub(Expr::Quantity(out), rhs),
            span,
            format!("{out_name} == num(s) {out_name}.z"),
        );
        out
    }
}

#[cfg(test)]
mod tests {
    use super::Transfer;

    #[test]
    fn trailing_zeros_are_trimmed() {
        let tf = Transfer::new(vec![1.0, 0.0], vec![1.0, 2.0, 0.0]).unwrap();
        assert_eq!(tf.num, vec![1.0]);
        assert_eq!(tf.den, vec![1.0, 2.0]);
        assert_eq!(tf.order(), 1);
    }

    #[test]
    fn improper_and_zero_denominators_are_refused() {
        assert!(Transfer::new(vec![1.0, 1.0], vec![1.0]).is_err());
        assert!(Transfer::new(vec![1.0], vec![0.0, 0.0]).is_err());
        assert!(Transfer::new(vec![f64::NAN], vec![1.0]).is_err());
    }
}
