//! `Q'delayed(T)`: an auxiliary quantity and a [`Delay`] line; the analog engine defines it
//! from the integrator's history (see `analog::delay`).

use vams_design::{Delay, Expr, QuantityId};
use vams_syntax::ast;
use vams_syntax::source::Span;

use crate::attributes::synth::arg;
use crate::error::ElabError;
use crate::names::scope::Scope;
use crate::{Elab, R};

impl<'a> Elab<'a> {
    /// `q'delayed(T)`; `T = 0` is `q` itself.
    pub(crate) fn delayed_attribute(
        &mut self,
        sc: &Scope<'a>,
        q: QuantityId,
        args: &[ast::Assoc],
        span: Span,
    ) -> R<Expr> {
        let (Some(t), None) = (arg(args, 0), arg(args, 1)) else {
            return Err(self.error(ElabError::invalid(
                span,
                "`'delayed` takes one argument: the delay in seconds",
                Some("`q'delayed(1.0e-3)` (a static real)".into()),
            )));
        };
        let delay = self.static_real(sc, t, "the delay of `'delayed`")?;
        if !(delay >= 0.0 && delay.is_finite()) {
            return Err(self.error(ElabError::invalid(
                t.span,
                "the delay of `'delayed` must be a non-negative real",
                Some("`q'delayed(1.0e-3)`: seconds".into()),
            )));
        }
        if delay == 0.0 {
            return Ok(Expr::Quantity(q));
        }
        if let Some(d) = self
            .design
            .delays
            .iter()
            .find(|d| d.input == q && d.delay == delay)
        {
            return Ok(Expr::Quantity(d.output));
        }
        let output = self.aux_quantity(q, &format!("delayed({delay})"));
        self.design.delays.push(Delay {
            output,
            input: q,
            delay,
            span,
        });
        Ok(Expr::Quantity(output))
    }
}
