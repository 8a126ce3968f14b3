//! The diagnostics of `vams extract`: each names the capture file and what was expected.
//!
//! Codes live under `vams::extract::*`. Examples of what triggers each:
//!
//! * `io`: `--inrush nope.csv` where the file does not exist.
//! * `empty_file`: a zero-byte export, or one with only metadata lines.
//! * `missing_column`: header `Time,CH1,CH2` without `--voltage-col CH1 --current-col CH2`.
//! * `bad_row`: a data line `0.001,12.` cut off by a full disk (`truncated` when the file has
//!   too few samples altogether).
//! * `no_ripple`: a constant-speed capture whose current shows no commutation ripple.
//! * `no_step`: an inrush or blocked capture where the voltage never rises.
//! * `coast_never_stops`: a coast capture that ends while the rotor still turns.
//! * `estimate_failed`: a capture whose numbers give a non-physical value (e.g. R <= 0).
//! * `write`: an output file (`--params`, `--plot`) that cannot be written.
//!
//! What the capture reader diagnoses beyond these (a channel clipped everywhere) keeps its
//! own `vams::capture::*` code.

use miette::{Diagnostic, NamedSource, SourceSpan};
use std::path::PathBuf;
use thiserror::Error;

/// An error of the extraction, with the capture it concerns.
#[derive(Debug, Error, Diagnostic)]
pub enum ExtractError {
    /// The file cannot be read.
    #[error("cannot read the {role} capture `{}`: {source}", path.display())]
    #[diagnostic(code(vams::extract::io), help("check the path given to --{role}"))]
    Io {
        role: &'static str,
        path: PathBuf,
        source: std::io::Error,
    },

    /// No data at all.
    #[error("the {role} capture `{}` is empty: expected a header line and samples", path.display())]
    #[diagnostic(
        code(vams::extract::empty_file),
        help(
            "export the oscilloscope record again as CSV with a header such as `time,voltage,current`"
        )
    )]
    Empty { role: &'static str, path: PathBuf },

    /// A required column is not in the header.
    #[error(transparent)]
    #[diagnostic(transparent)]
    MissingColumn(Box<MissingColumn>),

    /// A data line that does not hold numbers in the needed columns.
    #[error(transparent)]
    #[diagnostic(transparent)]
    BadRow(Box<BadRow>),

    /// Too few samples.
    #[error("the {role} capture `{}` is truncated: {rows} samples, at least {min} expected", path.display())]
    #[diagnostic(
        code(vams::extract::truncated),
        help("export the whole record (scopes export 1,000 to 100,000 points)")
    )]
    Truncated {
        role: &'static str,
        path: PathBuf,
        rows: usize,
        min: usize,
    },

    /// No commutation ripple where one is needed.
    #[error("the {role} capture `{}` shows no commutation ripple: {what}", path.display())]
    #[diagnostic(
        code(vams::extract::no_ripple),
        help(
            "capture the current with a finer vertical scale (AC coupling or zoom) so the ripple spans several codes, and check that the motor turns"
        )
    )]
    NoRipple {
        role: &'static str,
        path: PathBuf,
        what: String,
    },

    /// No voltage step in a capture that starts the motor.
    #[error("the {role} capture `{}` has no voltage step: {what}", path.display())]
    #[diagnostic(
        code(vams::extract::no_step),
        help(
            "trigger on the rising supply voltage with some pre-trigger so the record starts at rest"
        )
    )]
    NoStep {
        role: &'static str,
        path: PathBuf,
        what: String,
    },

    /// The coast never reaches standstill.
    #[error("the coast capture `{}` never stops: {what}", path.display())]
    #[diagnostic(
        code(vams::extract::coast_never_stops),
        help(
            "use a longer time base so the record covers the rotor coming to rest (voltage back to 0 V)"
        )
    )]
    CoastNeverStops { path: PathBuf, what: String },

    /// A capture gives a non-physical value.
    #[error("cannot estimate {param} from the {role} capture `{}`: {what}", path.display())]
    #[diagnostic(
        code(vams::extract::estimate_failed),
        help(
            "check that the capture shows the experiment named by --{role} and that the columns are the right way round"
        )
    )]
    EstimateFailed {
        role: &'static str,
        path: PathBuf,
        param: &'static str,
        what: String,
    },

    /// Any other diagnostic of the capture reader.
    #[error(transparent)]
    #[diagnostic(transparent)]
    Capture(Box<crate::capture::CaptureError>),

    /// An output file cannot be written.
    #[error("cannot write `{}`: {what}", path.display())]
    #[diagnostic(
        code(vams::extract::write),
        help("check that the directory exists and is writable")
    )]
    Write { path: PathBuf, what: String },
}

/// A required column is not in the header (boxed: it carries the file's text).
#[derive(Debug, Error, Diagnostic)]
#[error("the {role} capture `{}` has no column `{column}` (found: {found})", path.display())]
#[diagnostic(
    code(vams::extract::missing_column),
    help("name the column with {flag} NAME, e.g. {flag} \"{suggestion}\"")
)]
pub struct MissingColumn {
    pub role: &'static str,
    pub path: PathBuf,
    pub column: String,
    pub found: String,
    pub flag: &'static str,
    pub suggestion: String,
    #[source_code]
    pub src: NamedSource<String>,
    #[label("header without `{column}`")]
    pub span: SourceSpan,
}

/// A data line that does not hold numbers in the needed columns (boxed: it carries the
/// file's text).
#[derive(Debug, Error, Diagnostic)]
#[error("the {role} capture `{}` has a bad sample on line {line}: {reason}", path.display())]
#[diagnostic(
    code(vams::extract::bad_row),
    help("the file looks truncated or edited; export the record again")
)]
pub struct BadRow {
    pub role: &'static str,
    pub path: PathBuf,
    pub line: usize,
    pub reason: String,
    #[source_code]
    pub src: NamedSource<String>,
    #[label("{reason}")]
    pub span: SourceSpan,
}
