//! Diagnostics of the commands themselves (codes `vams::cli::*`): what to simulate, for how
//! long, and the final verdicts. Errors of the stages (syntax, elaboration, analog, simulation)
//! keep their own types and codes; these only summarise them.

use miette::Diagnostic;
use thiserror::Error;

use crate::diagnostics::Located;
use crate::source::Span;

#[derive(Debug, Error, Diagnostic)]
pub enum CliError {
    #[error("{count} error(s) found")]
    #[diagnostic(code(vams::check::failed))]
    CheckFailed { count: usize },

    /// The sources do not parse: nothing is elaborated.
    #[error("{count} syntax error(s): nothing was elaborated")]
    #[diagnostic(
        code(vams::cli::syntax),
        help("fix the errors above (`vams check FILES` lists them all)")
    )]
    Syntax { count: usize },

    /// No entity is left uninstantiated.
    #[error("no top entity found: every entity is instantiated by another")]
    #[diagnostic(
        code(vams::cli::no_top),
        help("name the entity to simulate with --top NAME")
    )]
    NoTop,

    /// Several candidates for `--top`.
    #[error("several entities could be the top: {}", candidates.join(", "))]
    #[diagnostic(
        code(vams::cli::ambiguous_top),
        help("choose one with --top NAME, e.g. --top {}", candidates[0])
    )]
    AmbiguousTop { candidates: Vec<String> },

    /// Elaboration failed; the errors were printed.
    /// Some design unit does not analyse; the errors were printed.
    #[error("{count} analysis error(s): nothing was elaborated")]
    #[diagnostic(
        code(vams::cli::analysis),
        help("fix the errors above (`vams check FILES` lists every diagnostic)")
    )]
    Analysis { count: usize },

    #[error("{count} elaboration error(s)")]
    #[diagnostic(code(vams::cli::elaboration), help("fix the errors above"))]
    Elaboration { count: usize },

    /// The analog system could not be built; the errors were printed.
    #[error("{count} error(s) in the analog system")]
    #[diagnostic(code(vams::cli::analog), help("fix the errors above"))]
    Analog { count: usize },

    /// The simulation stopped with an error; the error was printed.
    #[error("the simulation of `{top}` stopped with an error")]
    #[diagnostic(
        code(vams::cli::simulation),
        help("see the error above; --reltol, --abstol and --max-step tune the solver")
    )]
    Simulation { top: String },

    /// Ctrl-C during `vams run`: the run stopped, its waveforms so far were written.
    #[error("`{top}` was interrupted")]
    #[diagnostic(code(vams::cli::interrupted))]
    Interrupted { top: String },

    /// Neither `--stop` nor a stop comment.
    #[error("no stop time for `{top}`")]
    #[diagnostic(
        code(vams::cli::no_stop),
        help(
            "pass --stop TIME (e.g. --stop 6s), or put a comment `-- vams: stop 6 sec` in the file that declares `{top}`"
        )
    )]
    NoStop { top: String },

    /// A `--panel` names a column that was not recorded.
    #[error("--panel names `{name}`, which was not recorded")]
    #[diagnostic(code(vams::cli::unknown_panel_name), help("recorded: {recorded}"))]
    UnknownPanelName { name: String, recorded: String },

    /// Writing an output file failed.
    #[error("cannot write `{path}`: {reason}")]
    #[diagnostic(
        code(vams::cli::write),
        help("check that the directory exists and is writable")
    )]
    Write { path: String, reason: String },

    /// The simulation ended with an assertion of severity failure.
    #[error("the run failed at {time}: {message}")]
    #[diagnostic(
        code(vams::cli::run_failed),
        help("an assertion of severity failure ends the run; see the report above")
    )]
    RunFailed { time: String, message: String },

    /// `vams test`: some testbenches failed.
    #[error("{failed} of {total} testbench(es) failed")]
    #[diagnostic(code(vams::cli::tests_failed))]
    TestsFailed { failed: usize, total: usize },

    /// `vams test`: nothing to run.
    #[error("no testbench found in {paths}")]
    #[diagnostic(
        code(vams::cli::no_testbench),
        help(
            "a testbench is an entity without ports whose name starts with `tb_` or `test_`{filter}"
        )
    )]
    NoTestbench { paths: String, filter: String },
}

/// Errors located in a source file (rendered with the file's text).
#[derive(Clone, Debug, Error, Diagnostic)]
pub enum SourceError {
    /// `-- vams: stop soon`
    #[error("the stop comment does not give a time: {problem}")]
    #[diagnostic(
        code(vams::cli::bad_stop_comment),
        help("write e.g. `-- vams: stop 6 sec`")
    )]
    BadStopComment {
        #[label("here")]
        span: Span,
        problem: String,
    },
}

impl Located for SourceError {
    fn primary_span(&self) -> Span {
        match self {
            SourceError::BadStopComment { span, .. } => *span,
        }
    }
}
