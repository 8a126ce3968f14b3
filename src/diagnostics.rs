//! Diagnostics as data.
//!
//! Each stage has its own error enum with a code range of its own (`vams::parse::*` here,
//! `vams::analysis::*` in `analysis`); every variant carries the [`Span`] it is about and a help
//! line saying how to fix it. This module also renders any of them against a [`SourceMap`] with
//! miette, so the CLI and the golden tests print exactly the same text.

use miette::{Diagnostic, GraphicalReportHandler, GraphicalTheme, Report};
use thiserror::Error;

use crate::source::{SourceMap, Span};

/// Lexical and syntax errors (codes `vams::parse::*`).
#[derive(Clone, Debug, Error, Diagnostic, PartialEq)]
pub enum SyntaxError {
    /// `x := 3 $ 4;`
    #[error("unexpected character `{text}`")]
    #[diagnostic(
        code(vams::parse::bad_character),
        help(
            "VHDL source uses the ISO 8859-1 graphic characters; remove it or put it in a comment"
        )
    )]
    BadCharacter {
        #[label("not a VHDL token")]
        span: Span,
        text: String,
    },

    /// `s := "abc;` (no closing quote on the line)
    #[error("unterminated {what}")]
    #[diagnostic(
        code(vams::parse::unterminated),
        help("close it with `{closer}` (a literal cannot span lines; join strings with `&`)")
    )]
    Unterminated {
        #[label("starts here")]
        span: Span,
        what: &'static str,
        closer: &'static str,
    },

    /// `signal a__b : bit;`
    #[error("malformed identifier `{text}`")]
    #[diagnostic(code(vams::parse::bad_identifier), help("{problem} (LRM 15.4.2)"))]
    BadIdentifier {
        #[label("here")]
        span: Span,
        text: String,
        problem: &'static str,
    },

    /// `constant c : integer := 16#FG#;`
    #[error("malformed literal `{text}`")]
    #[diagnostic(code(vams::parse::bad_literal), help("{problem} (LRM 15.5)"))]
    BadNumber {
        #[label("here")]
        span: Span,
        text: String,
        problem: &'static str,
    },

    /// `x := ((((((...))))));` nested deeper than the limit.
    #[error("parentheses nested more than {limit} deep")]
    #[diagnostic(
        code(vams::parse::too_deep),
        help("split the expression with intermediate constants or variables")
    )]
    TooDeep {
        #[label("this level is too deep")]
        span: Span,
        limit: usize,
    },

    /// `entity e is port (a : in bit) end;` (missing `;`)
    #[error("syntax error: unexpected {found}")]
    #[diagnostic(code(vams::parse::unexpected))]
    Unexpected {
        #[label("{expected}")]
        span: Span,
        found: String,
        expected: String,
        #[help]
        help: Option<String>,
    },

    /// A file that stops in the middle of a design unit.
    #[error("syntax error: the file ends in the middle of a design unit")]
    #[diagnostic(
        code(vams::parse::unexpected_eof),
        help(
            "complete the unit: every `entity`, `architecture`, `process` ... needs its `end ...;`"
        )
    )]
    UnexpectedEof {
        #[label("{expected}")]
        span: Span,
        expected: String,
    },

    /// `end architecture wrong_name;`
    #[error("the closing label `{found}` does not match `{expected}`")]
    #[diagnostic(
        code(vams::parse::end_label),
        help("write `{expected}` after `end`, or leave the label out (LRM 1.2)")
    )]
    EndLabel {
        #[label("should be `{expected}`")]
        span: Span,
        found: String,
        expected: String,
    },

    /// A construct the grammar accepts but vams does not support yet.
    #[error("{what} is not supported")]
    #[diagnostic(code(vams::parse::unsupported))]
    Unsupported {
        #[label("here")]
        span: Span,
        what: String,
        #[help]
        help: Option<String>,
    },
}

impl SyntaxError {
    pub fn span(&self) -> Span {
        match self {
            SyntaxError::BadCharacter { span, .. }
            | SyntaxError::Unterminated { span, .. }
            | SyntaxError::BadIdentifier { span, .. }
            | SyntaxError::BadNumber { span, .. }
            | SyntaxError::TooDeep { span, .. }
            | SyntaxError::Unexpected { span, .. }
            | SyntaxError::UnexpectedEof { span, .. }
            | SyntaxError::EndLabel { span, .. }
            | SyntaxError::Unsupported { span, .. } => *span,
        }
    }
}

/// Anything that can be rendered against the source map: a diagnostic with a primary span.
pub trait Located: Diagnostic + Send + Sync + Clone + 'static {
    fn primary_span(&self) -> Span;
}

impl Located for SyntaxError {
    fn primary_span(&self) -> Span {
        self.span()
    }
}

/// Wraps a diagnostic with the text of the file its span points into.
pub fn to_report<D: Located>(diag: &D, sources: &SourceMap) -> Report {
    let file = diag.primary_span().file;
    Report::new(diag.clone()).with_source_code(sources.named_source(file))
}

/// Renders a diagnostic as plain text (no colour, fixed width): what the CLI prints when
/// stderr is not a terminal, and what golden tests compare.
pub fn render_plain<D: Located>(diag: &D, sources: &SourceMap) -> String {
    let report = to_report(diag, sources);
    let handler = GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor())
        .with_width(100)
        .with_links(false);
    let mut out = String::new();
    // Writing into a String cannot fail.
    let _ = handler.render_report(&mut out, report.as_ref());
    out
}
