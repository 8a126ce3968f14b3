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
    plain(to_report(diag, sources).as_ref())
}

/// Renders a diagnostic as plain text (no colour, fixed width).
fn plain(diag: &dyn Diagnostic) -> String {
    let handler = GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor())
        .with_width(100)
        .with_links(false);
    let mut out = String::new();
    // Writing into a String cannot fail.
    let _ = handler.render_report(&mut out, diag);
    out
}

/// How serious a [`Finding`] is.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Level {
    Error,
    Warning,
}

impl Level {
    pub fn name(self) -> &'static str {
        match self {
            Level::Error => "error",
            Level::Warning => "warning",
        }
    }
}

/// A diagnostic as data for library users (the Python package): where it is (file name, line
/// and column from 1; an empty file and 0 for a diagnostic about no place in the sources),
/// its level, code, message, label and help, and the report it renders from.
#[derive(Debug)]
pub struct Finding {
    pub file: String,
    pub line: usize,
    pub column: usize,
    pub level: Level,
    pub code: Option<String>,
    pub message: String,
    pub label: Option<String>,
    pub help: Option<String>,
    /// The diagnostic with its file's text attached, for rendering.
    pub report: Report,
}

impl Finding {
    /// A diagnostic located in `sources`, rendered with its file's text as `vams check`
    /// renders it; one whose span is not in `sources` is taken as about no place.
    pub fn located<D: Located>(d: &D, sources: &SourceMap, level: Level) -> Finding {
        let span = d.primary_span();
        if span.file.0 as usize >= sources.len() {
            return Finding::unlocated(Report::new(d.clone()), level);
        }
        let (line, column) = sources.line_col(span);
        Finding {
            file: sources.file(span.file).name.clone(),
            line,
            column,
            ..Finding::unlocated(to_report(d, sources), level)
        }
    }

    /// A diagnostic about no place in the sources (a missing file, a summary).
    pub fn unlocated(report: Report, level: Level) -> Finding {
        let d: &dyn Diagnostic = report.as_ref();
        let code = d.code().map(|c| c.to_string());
        let message = d.to_string();
        let label = (d.labels().into_iter().flatten()).find_map(|l| l.label().map(str::to_string));
        let help = d.help().map(|h| h.to_string());
        Finding {
            file: String::new(),
            line: 0,
            column: 0,
            level,
            code,
            message,
            label,
            help,
            report,
        }
    }

    /// The text `vams check` prints for it when stderr is not a terminal.
    pub fn render_plain(&self) -> String {
        plain(self.report.as_ref())
    }
}
