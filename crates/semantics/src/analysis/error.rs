//! Analysis diagnostics (codes `vams::analysis::*`), each with the span it is about and a help
//! line saying how to fix it.

use miette::Diagnostic;
use thiserror::Error;

use vams_syntax::diagnostics::Located;
use vams_syntax::source::Span;

#[derive(Clone, Debug, Error, Diagnostic, PartialEq)]
pub enum AnalysisError {
    /// `x := y;` where `y` is declared nowhere visible.
    #[error("`{name}` is not declared")]
    #[diagnostic(code(vams::analysis::undeclared))]
    Undeclared {
        #[label("not found")]
        span: Span,
        name: String,
        #[help]
        help: Option<String>,
    },

    /// `signal s : integer := 1.5;` (VHDL converts nothing implicitly).
    #[error("type mismatch: expected {expected}, found {found}")]
    #[diagnostic(code(vams::analysis::type_mismatch))]
    TypeMismatch {
        #[label("this is {found}")]
        span: Span,
        expected: String,
        found: String,
        #[help]
        help: Option<String>,
    },

    /// `x * 2` with `x` real: no visible `"*"` takes these operands.
    #[error("no `{name}` takes {operands}")]
    #[diagnostic(code(vams::analysis::no_overload))]
    NoOverload {
        #[label("no matching declaration of `{name}`")]
        span: Span,
        name: String,
        operands: String,
        #[help]
        help: Option<String>,
    },

    /// `write(l, now)` in VHDL-AMS: several declarations fit the arguments equally well.
    #[error("ambiguous call: {count} declarations of `{name}` fit these arguments")]
    #[diagnostic(code(vams::analysis::ambiguous))]
    Ambiguous {
        #[label("which `{name}`?")]
        span: Span,
        name: String,
        count: usize,
        #[help]
        help: String,
    },

    /// `generic map (rr => 1.0)` where the unit has no generic `rr`.
    #[error("`{name}` is not a {what} of `{unit}`")]
    #[diagnostic(code(vams::analysis::unknown_formal))]
    UnknownFormal {
        #[label("no such {what}")]
        span: Span,
        name: String,
        what: &'static str,
        unit: String,
        #[help]
        help: Option<String>,
    },

    /// `use work.p.all;` where no package `p` was given.
    #[error("no {what} `{name}` in library `{library}`")]
    #[diagnostic(code(vams::analysis::missing_unit))]
    MissingUnit {
        #[label("not found")]
        span: Span,
        what: &'static str,
        name: String,
        library: String,
        #[help]
        help: Option<String>,
    },

    /// `when s =>` with `s` a signal: where the LRM asks for a static expression, a name
    /// whose value only the simulation knows.
    #[error("{what} must be {required}, and `{name}` is not")]
    #[diagnostic(code(vams::analysis::not_static))]
    NotStatic {
        #[label("its value is known only as the design runs")]
        span: Span,
        what: &'static str,
        required: &'static str,
        name: String,
        #[help]
        help: Option<String>,
    },

    /// Package `a` uses `b` and `b` uses `a`: neither can be analysed first.
    #[error("circular dependency: {cycle}")]
    #[diagnostic(
        code(vams::analysis::circular_dependency),
        help(
            "a unit can only use what is analysed before it: move the shared declarations \
              into a package that both use"
        )
    )]
    CircularDependency {
        #[label("this makes the cycle")]
        span: Span,
        cycle: String,
    },
}

impl Located for AnalysisError {
    fn primary_span(&self) -> Span {
        match self {
            AnalysisError::Undeclared { span, .. }
            | AnalysisError::TypeMismatch { span, .. }
            | AnalysisError::NoOverload { span, .. }
            | AnalysisError::Ambiguous { span, .. }
            | AnalysisError::UnknownFormal { span, .. }
            | AnalysisError::MissingUnit { span, .. }
            | AnalysisError::NotStatic { span, .. }
            | AnalysisError::CircularDependency { span, .. } => *span,
        }
    }
}
