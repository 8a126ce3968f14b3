//! Array lengths where a value meets an object of a constrained array subtype: assignment to
//! a variable or signal (whole, element or slice), an initial value, a parameter of a
//! constrained array subtype, a function's result of one. VHDL converts the value to the
//! target's subtype, which keeps the target's bounds, and requires the lengths to match
//! (LRM 8.4, 8.5, 2.1.1.1). Where both lengths are known at elaboration a mismatch is an
//! elaboration error here; where only the target's is, the value is wrapped in
//! [`Builtin::CheckLength`], which the kernel checks at the assignment. Never checks a
//! target that is not an array, so scalar assignments cost nothing.

use vams_design::{Builtin, Expr, Value, length_mismatch};
use vams_syntax::source::Span;

use crate::error::ElabError;
use crate::expressions::expr::Typed;
use crate::names::types::Ty;
use crate::{Elab, R};

/// The help of a length mismatch found at elaboration.
pub(crate) const HELP: &str = "an array value must have its target's length (LRM 8.4, 8.5: the target keeps its bounds); resize the value (a slice, `resize`, an aggregate with `others`) or the target";

/// The number of elements of array value `v` (characters of a string).
pub(crate) fn value_len(v: &Value) -> Option<i64> {
    match v {
        Value::Array(items) => Some(items.len() as i64),
        Value::String(s) => Some(s.chars().count() as i64),
        _ => None,
    }
}

/// The number of elements of `t`, an array value of type `t.ty`, where elaboration knows it.
fn static_len(t: &Typed) -> Option<i64> {
    match (&t.ty, &t.e) {
        // A literal typed in the target's context may carry the target's bounds.
        (_, Expr::Const(v)) if value_len(v).is_some() => value_len(v),
        (Ty::Array(a), _) => a.len().map(|n| n as i64),
        _ => None,
    }
}

impl Elab<'_> {
    /// `value` as assigned to `target` (of type `ty`; `what` says what it is, as
    /// "variable `v`"): unchanged when `ty` is not an array of known length or the lengths
    /// match, an error at `span` when they differ, and checked at run time when the value's
    /// length is known only then.
    pub(crate) fn fit_length(
        &mut self,
        value: Typed,
        ty: &Ty,
        what: impl FnOnce(&Self) -> String,
        span: Span,
    ) -> R<Expr> {
        let Ty::Array(a) = ty else {
            return Ok(value.e);
        };
        let Some(n) = a.len().map(|n| n as i64) else {
            return Ok(value.e);
        };
        match static_len(&value) {
            Some(m) if m == n => Ok(value.e),
            Some(m) => Err(self.error(ElabError::LengthMismatch {
                span,
                message: length_mismatch(&what(self), n, m),
                found: m,
                help: Some(HELP.into()),
            })),
            None if !matches!(value.ty, Ty::Array(_)) => Ok(value.e),
            None => Ok(Expr::Call(
                Builtin::CheckLength,
                vec![
                    value.e,
                    Expr::Const(Value::Integer(n)),
                    Expr::Const(Value::String(what(self))),
                ],
            )),
        }
    }
}
