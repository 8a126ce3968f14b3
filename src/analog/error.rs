//! Structural and compile errors of the analog system (codes `vams::analog::*`).

use miette::Diagnostic;
use thiserror::Error;

use crate::diagnostics::Located;
use crate::source::Span;

#[derive(Clone, Debug, Error, Diagnostic, PartialEq)]
pub enum AnalogError {
    /// More or fewer equations than unknowns.
    #[error("{equations} equations for {unknowns} unknowns")]
    #[diagnostic(code(vams::analog::count))]
    Count {
        #[label("in this design")]
        span: Span,
        equations: usize,
        unknowns: usize,
        #[help]
        help: Option<String>,
    },
}

impl Located for AnalogError {
    fn primary_span(&self) -> Span {
        match self {
            AnalogError::Count { span, .. } => *span,
        }
    }
}
