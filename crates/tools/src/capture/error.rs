//! The diagnostics of capture reading: each names the file and says how to fix it.
//!
//! Codes live under `vams::capture::*`. Examples of what triggers each:
//!
//! * `io`: `scope.csv` does not exist or is not UTF-8 text.
//! * `empty_file`: a zero-byte export, or one with blank lines only.
//! * `no_data`: metadata lines or a header `Time,CH1` without any sample row.
//! * `missing_channel`: `--time-col t` (or a fit naming channel `vout`) when the header is
//!   `Time,CH1,CH2`.
//! * `bad_row`: a data line `0.001,12.` cut off by a full disk, or `0.002,abc`.
//! * `too_few_samples`: a record of 10 samples (at least 32 are needed).
//! * `time_not_increasing`: a row whose time is not after the previous row's.
//! * `all_clipped`: a channel sitting at the ADC's rail in more than 90 % of its samples.
//! * `unknown_scale`: `--scale curent=0.1` when the capture has no channel `curent`.

use miette::{Diagnostic, NamedSource, SourceSpan};
use std::path::PathBuf;
use thiserror::Error;

/// An error reading a capture, with the file it concerns.
#[derive(Debug, Error, Diagnostic)]
pub enum CaptureError {
    /// The file cannot be read.
    #[error("cannot read the capture `{}`: {source}", path.display())]
    #[diagnostic(
        code(vams::capture::io),
        help("check the path, and that the file is the scope's CSV export (text, UTF-8)")
    )]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },

    /// Nothing but blank lines.
    #[error("the capture `{}` is empty: expected a header line and samples", path.display())]
    #[diagnostic(
        code(vams::capture::empty_file),
        help(
            "export the oscilloscope record again as CSV with a header such as `time,voltage,current`"
        )
    )]
    Empty { path: PathBuf },

    /// Text, but no row of numbers.
    #[error("the capture `{}` has no samples: {what}", path.display())]
    #[diagnostic(
        code(vams::capture::no_data),
        help(
            "export the whole record as CSV (Save > Waveform > CSV), not the setup or a screenshot"
        )
    )]
    NoData {
        path: PathBuf,
        /// What was found instead (`a header but no row of numbers`).
        what: &'static str,
        /// Whether a line names the time column (a header cut off before its samples).
        has_header: bool,
    },

    /// A channel (or the time column) that is not in the capture.
    #[error(transparent)]
    #[diagnostic(transparent)]
    MissingChannel(Box<MissingChannel>),

    /// A data line that does not hold numbers where the header promises them.
    #[error(transparent)]
    #[diagnostic(transparent)]
    BadRow(Box<BadRow>),

    /// A row whose time does not come after the previous row's.
    #[error(transparent)]
    #[diagnostic(transparent)]
    TimeNotIncreasing(Box<NotIncreasing>),

    /// Too few samples to fit or measure anything.
    #[error("the capture `{}` has only {rows} samples, at least {min} expected", path.display())]
    #[diagnostic(
        code(vams::capture::too_few_samples),
        help("export the whole record (scopes export 1,000 to 100,000 points)")
    )]
    TooFewSamples {
        path: PathBuf,
        rows: usize,
        min: usize,
    },

    /// A channel at the ADC's rails almost everywhere.
    #[error(
        "the channel `{channel}` of the capture `{}` is clipped in {clipped} of its {samples} samples",
        path.display()
    )]
    #[diagnostic(
        code(vams::capture::all_clipped),
        help(
            "increase the volts/div of that channel so the signal fits the screen, and capture again"
        )
    )]
    AllClipped {
        path: PathBuf,
        channel: String,
        clipped: usize,
        samples: usize,
    },

    /// `--scale NAME=FACTOR` naming a channel the capture does not have.
    #[error("cannot scale `{channel}`: the capture `{}` has no such channel (it has: {found})", path.display())]
    #[diagnostic(
        code(vams::capture::unknown_scale),
        help(
            "{}",
            did_you_mean(suggestion, "name one of the channels in --scale NAME=FACTOR")
        )
    )]
    UnknownScale {
        path: PathBuf,
        channel: String,
        found: String,
        suggestion: Option<String>,
    },
}

fn did_you_mean(suggestion: &Option<String>, otherwise: &str) -> String {
    match suggestion {
        Some(s) => format!("did you mean `{s}`?"),
        None => otherwise.to_string(),
    }
}

/// A channel that is not in the capture (boxed: it may carry the file's text).
#[derive(Debug, Error, Diagnostic)]
#[error("the capture `{}` has no channel `{channel}` (it has: {})", path.display(), list(found))]
#[diagnostic(
    code(vams::capture::missing_channel),
    help(
        "{}",
        did_you_mean(suggestion, "name one of the columns of the header")
    )
)]
pub struct MissingChannel {
    /// The capture file.
    pub path: PathBuf,
    /// The name asked for.
    pub channel: String,
    /// Every column of the header, as written (time included).
    pub found: Vec<String>,
    /// The closest name, if one is close.
    pub suggestion: Option<String>,
    /// The file's text, when the error comes from parsing it.
    #[source_code]
    pub src: Option<NamedSource<String>>,
    /// The header line.
    #[label("header without `{channel}`")]
    pub span: Option<SourceSpan>,
}

fn list(found: &[String]) -> String {
    if found.is_empty() {
        "no header line".into()
    } else {
        found.join(", ")
    }
}

/// A data line that does not hold numbers, or whose time does not increase (boxed: it
/// carries the file's text).
#[derive(Debug, Error, Diagnostic)]
#[error("the capture `{}` has a bad sample on line {line}: {reason}", path.display())]
#[diagnostic(
    code(vams::capture::bad_row),
    help("the file looks truncated or edited; export the record again")
)]
pub struct BadRow {
    /// The capture file.
    pub path: PathBuf,
    /// The line, from 1.
    pub line: usize,
    /// What is wrong with it.
    pub reason: String,
    /// The file's text.
    #[source_code]
    pub src: NamedSource<String>,
    /// The field (or line) at fault.
    #[label("{reason}")]
    pub span: SourceSpan,
}

/// A row whose time is not after the previous row's (boxed: it carries the file's text).
#[derive(Debug, Error, Diagnostic)]
#[error("the capture `{}` goes back in time on line {line}: {time} s after {previous} s", path.display())]
#[diagnostic(
    code(vams::capture::time_not_increasing),
    help(
        "the rows must be in time order, one record per file: split a segmented or concatenated export, or name the time column with --time-col"
    )
)]
pub struct NotIncreasing {
    /// The capture file.
    pub path: PathBuf,
    /// The line, from 1.
    pub line: usize,
    /// Its time, s.
    pub time: f64,
    /// The previous row's time, s.
    pub previous: f64,
    /// The file's text.
    #[source_code]
    pub src: NamedSource<String>,
    /// The time field.
    #[label("not after the previous row")]
    pub span: SourceSpan,
}
