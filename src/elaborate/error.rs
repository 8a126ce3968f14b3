//! Elaboration diagnostics (codes `vams::elab::*`).

use miette::Diagnostic;
use thiserror::Error;

use crate::diagnostics::Located;
use crate::source::Span;

#[derive(Clone, Debug, Error, Diagnostic, PartialEq)]
pub enum ElabError {
    /// A name that is declared nowhere visible.
    #[error("`{name}` is not declared")]
    #[diagnostic(code(vams::elab::undeclared))]
    Undeclared {
        #[label("not found")]
        span: Span,
        name: String,
        #[help]
        help: Option<String>,
    },
}

impl Located for ElabError {
    fn primary_span(&self) -> Span {
        match self {
            ElabError::Undeclared { span, .. } => *span,
        }
    }
}
