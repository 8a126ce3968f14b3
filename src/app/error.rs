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

    /// A SPICE deck with errors (each printed above).
    #[error("{count} error(s) in the SPICE deck `{path}`")]
    #[diagnostic(
        code(vams::cli::netlist),
        help("see the errors above: each names the line and how to fix it")
    )]
    Netlist { path: String, count: usize },

    /// A SPICE deck without `.tran` run without `--stop`.
    #[error("the SPICE deck `{top}` has no .tran")]
    #[diagnostic(
        code(vams::cli::no_tran),
        help("add `.tran TSTEP TSTOP` to the deck, or pass --stop TIME")
    )]
    NoTran { top: String },

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

    /// `vams ac` on a design without a spectral source: nothing excites the small-signal model.
    #[error("`{top}` has no spectral source quantity: an AC analysis has nothing to excite")]
    #[diagnostic(
        code(vams::cli::no_spectral_source),
        help(
            "declare one and add it where the stimulus enters, e.g. `quantity ac_in : real spectrum 1.0, 0.0;` and `vin == 2.0 + ac_in;` (magnitude 1, phase 0 radians; zero in the quiescent and time domains)"
        )
    )]
    NoSpectralSource { top: String },

    /// `vams noise` on a design without a noise source quantity.
    #[error("`{top}` has no noise source quantity: a noise analysis has nothing to add up")]
    #[diagnostic(
        code(vams::cli::no_noise_source),
        help(
            "declare one and add it where the noise enters, e.g. `quantity vn : real noise 4.0 * 1.380649e-23 * 300.0 * r;` and `v == r * i + vn;` (a power spectral density in the quantity's units squared per hertz, which may call `frequency`; zero in the other analyses)"
        )
    )]
    NoNoiseSource { top: String },

    /// `vams noise --input` names no spectral source quantity.
    #[error("--input `{name}`: {problem}")]
    #[diagnostic(code(vams::cli::noise_input), help("{help}"))]
    NoiseInput {
        name: String,
        problem: String,
        help: String,
    },

    /// A noise source's density was invalid at some frequency; the error was printed.
    #[error("the noise analysis of `{top}` stopped at a noise density it cannot use")]
    #[diagnostic(
        code(vams::cli::noise_density),
        help("see the error above: the density must be finite and at least 0 over the band")
    )]
    NoiseDensity { top: String },

    /// `vams ac --probe` names no quantity.
    #[error("--probe `{name}`: {problem}")]
    #[diagnostic(code(vams::cli::ac_probe), help("{help}"))]
    AcProbe {
        name: String,
        problem: String,
        help: String,
    },

    /// `vams ac --from F1 --to F2` with F2 below F1.
    #[error("the frequency range is empty: --to {to} Hz is below --from {from} Hz")]
    #[diagnostic(
        code(vams::cli::frequency_range),
        help("give --from the lower frequency")
    )]
    FrequencyRange { from: f64, to: f64 },

    /// The small-signal model uses what the frequency domain does not support; the errors
    /// were printed.
    #[error("{count} construct(s) the frequency-domain analysis does not support")]
    #[diagnostic(
        code(vams::cli::frequency_domain),
        help("see the errors above; `vams run` simulates these in the time domain")
    )]
    FrequencyDomain { count: usize },

    /// A frequency point had no solution.
    #[error("the AC analysis of `{top}` failed: {reason}")]
    #[diagnostic(
        code(vams::cli::ac_solve),
        help(
            "a singular small-signal matrix means some quantity is not fixed at that frequency (a capacitor-only node at 0 Hz, an ideal LC tank exactly at resonance): add a leak, or move the frequency"
        )
    )]
    AcSolve { top: String, reason: String },

    /// `vams poles` could not compute the eigenvalues.
    #[error("the poles of `{top}` could not be computed: {reason}")]
    #[diagnostic(
        code(vams::app::poles),
        help("`vams ac` gives the frequency response of a system of any size")
    )]
    Poles { top: String, reason: String },

    /// An assertion on a small-signal response that does not read.
    #[error("assertion `{text}`: {problem}")]
    #[diagnostic(
        code(vams::cli::ac_assertion),
        help(
            "write MEASURE(PROBE, FREQUENCY) OP NUMBER, e.g. `gain_db(vout, 1kHz) > -3.1`; MEASURE is gain_db, gain or phase_deg, OP is <, <=, > or >="
        )
    )]
    AcAssertion { text: String, problem: String },

    /// Some assertions on a small-signal response failed (each was printed).
    #[error("{failed} of {total} assertion(s) on the response failed")]
    #[diagnostic(code(vams::cli::ac_assertions_failed))]
    AcAssertions { failed: usize, total: usize },

    /// `vams dc --probe` names no quantity or signal.
    #[error("--probe `{name}`: no quantity or signal of that name")]
    #[diagnostic(code(vams::cli::dc_probe), help("{help}"))]
    DcProbe { name: String, help: String },

    /// `vams dc --sweep NAME FROM TO STEP` that gives no sequence of points.
    #[error("--sweep {name}: {problem}")]
    #[diagnostic(
        code(vams::cli::sweep_range),
        help(
            "e.g. --sweep vin 0 5 0.1 sweeps vin from 0 to 5 in steps of 0.1; a negative step sweeps down"
        )
    )]
    SweepRange { name: String, problem: String },

    /// A point of `vams dc` had no quiescent solution, even approached in smaller steps.
    #[error("the DC sweep of `{top}` stopped at {name} = {value}: no quiescent point there")]
    #[diagnostic(
        code(vams::cli::sweep_failed),
        help(
            "the solver's diagnostic is above; the points before it were written. A model that has no solution there (a fold of its characteristic) cannot be swept through it; sweep from the other side, or with --both-ways"
        )
    )]
    SweepFailed {
        top: String,
        name: String,
        value: String,
    },

    /// `vams poles --input` names no spectral source quantity.
    #[error("--input `{name}` is not a spectral source quantity of the design")]
    #[diagnostic(
        code(vams::cli::zeros_input),
        help("the zeros are from a spectral source quantity; the design's are: {sources}")
    )]
    ZerosInput { name: String, sources: String },

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
    /// `-- vams: assert gain_db(vout) > 1`
    #[error("the assertion comment does not read: {problem}")]
    #[diagnostic(
        code(vams::cli::bad_assert_comment),
        help(
            "write e.g. `-- vams: assert gain_db(vout, 1kHz) > -3.1` (gain_db, gain or phase_deg; <, <=, > or >=)"
        )
    )]
    BadAssertComment {
        #[label("here")]
        span: Span,
        problem: String,
    },
}

impl Located for SourceError {
    fn primary_span(&self) -> Span {
        match self {
            SourceError::BadStopComment { span, .. }
            | SourceError::BadAssertComment { span, .. } => *span,
        }
    }
}
