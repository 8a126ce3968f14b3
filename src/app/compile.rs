//! What every command shares: the design options (sources, top, generics) and the way from
//! them to an elaborated [`Design`] (parse, analyse every unit, elaborate the top). Each
//! stage's diagnostics come back as [`Finding`]s: on failure in [`NotCompiled`], the
//! elaboration warnings beside the design in [`Compiled`]. Nothing here prints.

use std::path::PathBuf;

use miette::Report;

use crate::analysis::{Analysis, analyse};
use crate::design::Design;
use crate::diagnostics::{Finding, Level, Located};
use crate::elaborate::{ElabError, ElabOptions, ElabWarning, elaborate_analysed, find_tops};
use crate::source::SourceMap;

use super::error::CliError;
use super::load::{LibrarySources, Loaded, load_with_libraries};
use super::netlist::{NetlistRun, compile_netlist, single_deck};
use super::params::{merge_generics, read_params};

/// Sources, top entity and generic overrides: what every command elaborates.
#[derive(Debug, Clone, Default)]
pub struct DesignOptions {
    /// Source files or directories (directories are searched for .vhd, .vhdl and .ams files).
    pub paths: Vec<PathBuf>,
    /// Sources analysed into libraries of their own (`--lib NAME=PATH`).
    pub libraries: Vec<LibrarySources>,
    /// The entity to elaborate; `None`: the only entity that nothing instantiates.
    pub top: Option<String>,
    /// Generic overrides of the top entity (win over `params`).
    pub generics: Vec<(String, String)>,
    /// A file of `name=value` generic overrides.
    pub params: Option<PathBuf>,
}

/// Sources and the design elaborated from them.
pub struct Compiled {
    pub loaded: Loaded,
    pub design: Design,
    /// The elaboration's warnings (the design is usable).
    pub warnings: Vec<Finding>,
    /// What a SPICE deck asks of a run (`None` for VHDL-AMS sources).
    pub netlist: Option<NetlistRun>,
}

/// Why sources did not give a design: the diagnostics of the stage that failed, and the
/// summary error (for a library user to show or raise; the commands print them).
#[derive(Debug)]
pub struct NotCompiled {
    pub findings: Vec<Finding>,
    pub error: Report,
}

impl NotCompiled {
    fn new<D: Located>(errors: &[D], sources: &SourceMap, error: CliError) -> NotCompiled {
        NotCompiled {
            findings: located(errors, sources, Level::Error),
            error: error.into(),
        }
    }

    /// A failure with no located diagnostics (a file that cannot be read, no top entity).
    pub fn bare(error: impl Into<Report>) -> NotCompiled {
        NotCompiled {
            findings: Vec::new(),
            error: error.into(),
        }
    }

    /// True when the sources did not parse.
    pub fn is_syntax(&self) -> bool {
        matches!(
            self.error.downcast_ref::<CliError>(),
            Some(CliError::Syntax { .. })
        )
    }
}

/// Each of `diagnostics` as a [`Finding`] of `level`.
pub(super) fn located<D: Located>(
    diagnostics: &[D],
    sources: &SourceMap,
    level: Level,
) -> Vec<Finding> {
    (diagnostics.iter())
        .map(|d| Finding::located(d, sources, level))
        .collect()
}

/// The top entity: the one given, or the single candidate.
pub fn choose_top(given: Option<&str>, candidates: Vec<String>) -> Result<String, CliError> {
    if let Some(top) = given {
        return Ok(top.to_ascii_lowercase());
    }
    match candidates.len() {
        0 => Err(CliError::NoTop),
        1 => Ok(candidates.into_iter().next().unwrap_or_default()),
        _ => Err(CliError::AmbiguousTop { candidates }),
    }
}

/// Sources parsed and analysed, the top chosen: what elaborating once per parameter set
/// (`vams dc`'s sweep) reuses, so that a sweep re-parameterises the design without parsing
/// it again.
pub struct Prepared {
    pub loaded: Loaded,
    pub analysis: Analysis,
    pub top: String,
    /// The overrides of `-g` and `--params`, merged.
    pub generics: Vec<(String, String)>,
}

impl Prepared {
    /// Elaborates the top with the command's generics and then `extra` (which win), giving
    /// the errors to the caller (`vams sweep` records them per run).
    pub fn try_elaborate(&self, extra: &[(String, String)]) -> Result<Design, Vec<ElabError>> {
        self.try_elaborate_top(&self.top, extra)
    }

    /// [`Prepared::try_elaborate`] of another entity of the same sources (`vams fit`'s
    /// experiments may each have their testbench).
    pub fn try_elaborate_top(
        &self,
        top: &str,
        extra: &[(String, String)],
    ) -> Result<Design, Vec<ElabError>> {
        let options = ElabOptions {
            top: top.to_string(),
            generics: merge_generics(self.generics.clone(), extra),
        };
        let loaded = &self.loaded;
        elaborate_analysed(&self.analysis, &loaded.sources, &loaded.files, &options)
    }

    /// [`Prepared::try_elaborate`] with the errors as [`Finding`]s (the warnings are in the
    /// design: [`Prepared::warnings`]).
    pub fn elaborate(&self, extra: &[(String, String)]) -> Result<Design, NotCompiled> {
        self.try_elaborate(extra).map_err(|errors| {
            let count = errors.len();
            NotCompiled::new(
                &errors,
                &self.loaded.sources,
                CliError::Elaboration { count },
            )
        })
    }

    /// The elaboration warnings of `design`.
    pub fn warnings(&self, design: &Design) -> Vec<Finding> {
        let warnings: Vec<ElabWarning> = design.warnings.iter().map(ElabWarning::from).collect();
        located(&warnings, &self.loaded.sources, Level::Warning)
    }
}

/// Loads, parses and analyses every unit and chooses the top.
pub fn prepare(options: &DesignOptions) -> Result<Prepared, NotCompiled> {
    let from_file = match &options.params {
        Some(path) => read_params(path).map_err(NotCompiled::bare)?,
        None => Vec::new(),
    };
    let generics = merge_generics(from_file, &options.generics);
    let loaded =
        load_with_libraries(&options.paths, &options.libraries).map_err(NotCompiled::bare)?;
    prepare_loaded(loaded, options.top.as_deref(), generics)
}

/// [`prepare`] of sources already loaded (a preset's bundled models, texts in memory).
pub fn prepare_loaded(
    loaded: Loaded,
    top: Option<&str>,
    generics: Vec<(String, String)>,
) -> Result<Prepared, NotCompiled> {
    if !loaded.syntax_errors.is_empty() {
        let errors: Vec<_> = (loaded.syntax_errors.iter())
            .flat_map(|(_, errors)| errors.iter().cloned())
            .collect();
        let count = errors.len();
        return Err(NotCompiled::new(
            &errors,
            &loaded.sources,
            CliError::Syntax { count },
        ));
    }
    // Every unit of every file is analysed, as a VHDL tool analyses each file before it
    // elaborates: an error in a unit the top does not reach still fails the run.
    let analysis = analyse(&loaded.sources, &loaded.files);
    let errors: Vec<_> = analysis.errors().cloned().collect();
    if !errors.is_empty() {
        let count = errors.len();
        return Err(NotCompiled::new(
            &errors,
            &loaded.sources,
            CliError::Analysis { count },
        ));
    }
    let candidates = match top {
        Some(_) => Vec::new(),
        None => find_tops(&analysis, &loaded.files),
    };
    let top = choose_top(top, candidates).map_err(NotCompiled::bare)?;
    Ok(Prepared {
        loaded,
        analysis,
        top,
        generics,
    })
}

/// The help for `name` when `design` records no quantity or signal of that name (a sweep's
/// metric column, a fit's matched quantity): the closest name, or how names are written;
/// `None` when it has one.
pub fn unknown_probe_help(design: &Design, name: &str) -> Option<String> {
    let names = (design.quantities.iter().map(|q| q.name.as_str()))
        .chain(design.signals.iter().map(|s| s.name.as_str()));
    unknown_name_help(names, name)
}

/// [`unknown_probe_help`] among the recorded `names` (a run's columns).
pub fn unknown_name_help<'a>(
    names: impl Iterator<Item = &'a str> + Clone,
    name: &str,
) -> Option<String> {
    if names.clone().any(|n| n == name) {
        return None;
    }
    let closest = names
        .map(|n| (strsim::levenshtein(name, n), n))
        .min_by_key(|&(d, _)| d);
    Some(match closest {
        Some((d, n)) if d <= name.len().max(3) / 2 + 1 => format!("did you mean `{n}`?"),
        _ => "columns are quantities and signals by their hierarchical name, e.g. \
              `dut.u_motor.i` (`vams run` records them all)"
            .to_string(),
    })
}

/// Loads, parses, analyses and elaborates: the design and its elaboration warnings, or why
/// there is none.
/// A single SPICE deck among the paths is read by the SPICE frontend ([`super::netlist`]).
pub fn compile(options: &DesignOptions) -> Result<Compiled, NotCompiled> {
    if let Some(deck) = single_deck(&options.paths).map_err(NotCompiled::bare)? {
        return compile_netlist(deck);
    }
    finish(prepare(options)?)
}

/// [`compile`] of sources already loaded.
pub fn compile_loaded(
    loaded: Loaded,
    top: Option<&str>,
    generics: Vec<(String, String)>,
) -> Result<Compiled, NotCompiled> {
    finish(prepare_loaded(loaded, top, generics)?)
}

/// Elaborates what [`prepare`] gave, with no further overrides.
fn finish(prepared: Prepared) -> Result<Compiled, NotCompiled> {
    let design = prepared.elaborate(&[])?;
    let warnings = prepared.warnings(&design);
    Ok(Compiled {
        loaded: prepared.loaded,
        design,
        warnings,
        netlist: None,
    })
}

/// Ends the life of what a one-shot command built without dropping it: the process exits
/// right after the command returns and the OS takes the memory back at once, whereas dropping
/// a large design (or its analog system, or its waveforms) frees millions of small allocations
/// one by one (0.5 s for an RC ladder of 100 000 sections). Only for the last step of `run`,
/// `op` and `dae`: never where more work follows (`vams test` runs many designs in one
/// process).
pub fn discard_at_exit<T>(value: T) {
    std::mem::forget(value);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn top_is_given_or_the_single_candidate() {
        assert_eq!(choose_top(Some("TB_Servo"), vec![]).unwrap(), "tb_servo");
        assert_eq!(choose_top(None, vec!["tb".into()]).unwrap(), "tb");
        assert!(matches!(choose_top(None, vec![]), Err(CliError::NoTop)));
        let err = choose_top(None, vec!["tb_a".into(), "tb_b".into()]).unwrap_err();
        assert_eq!(
            err.to_string(),
            "several entities could be the top: tb_a, tb_b"
        );
    }
}
