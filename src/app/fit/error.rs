//! The diagnostics of `vams fit` itself (codes `vams::fit::*`); the captures' own errors are
//! `vams::capture::*`, the design's are the stages'.

use miette::Diagnostic;
use std::path::PathBuf;
use thiserror::Error;

#[derive(Debug, Error, Diagnostic)]
pub enum FitCliError {
    /// The fit ran and its result was written, but it is not a converged estimate (exit
    /// status 3: the numbers are there, and a script must not take them as the answer).
    #[error("the fit did not converge: {}", reasons.join("; "))]
    #[diagnostic(
        code(vams::fit::not_converged),
        help(
            "the values and intervals above are not reliable; see the warnings: start nearer, widen a bound, or check each capture's experiment"
        )
    )]
    NotConverged { reasons: Vec<String> },

    /// A `--measured` argument that does not parse.
    #[error("`--measured {arg}`: {why}")]
    #[diagnostic(
        code(vams::fit::measured),
        help(
            "write FILE or FILE:KEY=VALUE,...; keys: `top=ENTITY`, `shift=TIME` (added to the capture's times) or `trigger=CHANNEL@LEVEL` with `edge=falling` and `at=TIME`, `from=TIME`, `to=TIME` (the part of the capture compared), any other is a generic of that experiment, e.g. `coast.csv:experiment=3,shift=2 ms`"
        )
    )]
    Measured { arg: String, why: String },

    /// A `--match` or `--scale` argument that does not parse.
    #[error("`--{flag} {arg}`: expected {expected}")]
    #[diagnostic(code(vams::fit::argument))]
    Argument {
        flag: &'static str,
        arg: String,
        expected: &'static str,
    },

    /// A `--free` argument that does not parse.
    #[error("--free {0}")]
    #[diagnostic(code(vams::fit::free))]
    Free(String),

    /// A generic both free and fixed for an experiment.
    #[error("`{name}` is both free (--free) and fixed for `{capture}`")]
    #[diagnostic(
        code(vams::fit::free_and_fixed),
        help("drop `{name}=...` from that --measured, or drop the --free")
    )]
    FreeAndFixed { name: String, capture: String },

    /// A matched column that no capture has.
    #[error("no capture has a column `{column}` (--match {quantity}={column})")]
    #[diagnostic(code(vams::fit::no_column), help("{help}"))]
    NoColumn {
        quantity: String,
        column: String,
        help: String,
    },

    /// A capture that no `--match` compares.
    #[error("`{}` has none of the matched columns ({})", path.display(), columns.join(", "))]
    #[diagnostic(
        code(vams::fit::unmatched_capture),
        help("its columns are {available}; add a --match QUANTITY=COLUMN for one of them")
    )]
    UnmatchedCapture {
        path: PathBuf,
        columns: Vec<String>,
        available: String,
    },

    /// The design records no such quantity or signal.
    #[error("the design `{top}` has no quantity or signal `{name}` (--match {name}=...)")]
    #[diagnostic(code(vams::fit::no_quantity), help("{help}"))]
    NoQuantity {
        top: String,
        name: String,
        help: String,
    },

    /// Too little of a capture is left to compare.
    #[error("`{}`: {why}", path.display())]
    #[diagnostic(
        code(vams::fit::too_short),
        help(
            "the capture must overlap the simulated time (0 to its end) by at least 8 samples: check `shift=`, `from=` and `to=`, and that it is the capture of this experiment"
        )
    )]
    TooShort { path: PathBuf, why: String },

    /// The fit could not proceed.
    #[error("{message}")]
    #[diagnostic(
        code(vams::fit::failed),
        help(
            "start from a better guess (--free NAME=GUESS), bound the parameter (NAME=GUESS:MIN:MAX), or check that each capture belongs to its experiment"
        )
    )]
    Failed { message: String },

    /// An output file cannot be written.
    #[error("cannot write `{}`: {what}", path.display())]
    #[diagnostic(
        code(vams::fit::write),
        help("check that the folder exists and is writable")
    )]
    Write { path: PathBuf, what: String },
}
