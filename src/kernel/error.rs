//! Simulation failures (codes `vams::sim::*`).

use miette::Diagnostic;
use thiserror::Error;

use crate::analog::AnalogError;

#[derive(Clone, Debug, Error, Diagnostic)]
pub enum SimError {
    /// The analog system could not be built.
    #[error("the analog system is not well formed")]
    #[diagnostic(code(vams::sim::analog))]
    Analog { errors: Vec<AnalogError> },
}
