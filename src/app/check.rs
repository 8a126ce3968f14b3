//! `vams check FILES|DIRS...`: reads the given sources (a directory means its `.vhd`, `.vhdl`
//! and `.ams` files, recursively) together with the bundled stdlib, and reports every
//! diagnostic with file, line, column and a help line. Exit 0 when clean, 1 on any error.
//!
//! Four stages: parsing every file; when that is clean, analysing every design unit of every
//! file, reached by a top or not (names, types, overloads); elaborating every top candidate
//! (an entity of `work` that nothing instantiates) with its default generics (an error that
//! analysis reported already is not repeated); building the analog system of each elaborated
//! top (equation count, matching, floating terminals). Candidates that cannot stand alone are
//! not elaborated, with a note: generics without a default have no value, and open terminal
//! or quantity ports would make the analog checks report what is only the missing
//! surroundings. What depends on their generics' values is checked as part of any top that
//! instantiates them. A diagnostic that several tops share is printed once.

use std::collections::HashSet;
use std::path::{Path, PathBuf};

use crate::analog::AnalogSystem;
use crate::analysis::{Analysis, analyse};
use crate::ast::DesignFile;
use crate::diagnostics::{Finding, Level, Located};
use crate::elaborate::{
    ElabOptions, ElabWarning, TopCandidate, elaborate_analysed, top_candidates,
};
use crate::source::{FileId, Span};

use super::compile::located;
use super::load::{InputError, LibrarySources, Loaded, load_with_libraries};
use super::netlist::{compile_netlist, single_deck};
use super::notes::Notes;
use super::render::{render, render_capped};

/// Diagnostics shown as they are found: at most `max` of a file or a top, to `notes`.
#[derive(Clone, Copy)]
pub struct Echo<'a> {
    pub max: usize,
    pub notes: &'a dyn Notes,
}

/// What the check found, stage by stage.
#[derive(Default)]
struct Tally<'a> {
    syntax: usize,
    analysis: usize,
    elaboration: usize,
    analog: usize,
    /// Tops elaborated, and those whose analog system was built.
    elaborated: usize,
    analog_checked: usize,
    /// Rendered diagnostics already found (tops share instantiated entities).
    seen: HashSet<String>,
    /// Where diagnostics go as they are found; `None`: nowhere.
    echo: Option<Echo<'a>>,
    /// Every diagnostic, once, in the order found.
    found: Vec<Finding>,
    /// Why some candidates were not elaborated or checked alone.
    notes: Vec<String>,
    /// Where analysis reported an error: elaboration, which still does its own name lookup,
    /// finds the same ones again.
    analysed_spans: Vec<Span>,
}

impl Tally<'_> {
    fn errors(&self) -> usize {
        self.syntax + self.analysis + self.elaboration + self.analog
    }

    /// True when analysis reported an error at `span`, or within it when `span` is an
    /// expression's (at most a line or so): elaboration's view of the same error from further
    /// out (`this range must be static` around analysis's `top_lane is not static`).
    fn already_analysed(&self, span: Span) -> bool {
        const EXPRESSION: u32 = 160;
        self.analysed_spans.iter().any(|a| {
            *a == span
                || (a.file == span.file
                    && span.end - span.start <= EXPRESSION
                    && span.start <= a.start
                    && a.end <= span.end)
        })
    }

    /// Keeps the diagnostics not found before (and prints them, at most the echo's number);
    /// returns how many were new.
    fn keep<D: Located>(&mut self, errors: &[D], loaded: &Loaded, level: Level) -> usize {
        let mut new = 0;
        let max = self.echo.map_or(0, |e| e.max);
        for e in errors {
            if self.already_analysed(e.primary_span()) {
                continue;
            }
            let finding = Finding::located(e, &loaded.sources, level);
            if self.seen.insert(finding.render_plain()) {
                if let Some(echo) = self.echo.filter(|_| new < max) {
                    echo.notes.note(&render(finding.report.as_ref()));
                }
                new += 1;
                self.found.push(finding);
            }
        }
        if let Some(echo) = self.echo.filter(|_| new > max) {
            echo.notes
                .note(&format!("  ... and {} more\n\n", new - max));
        }
        new
    }

    /// A note on what was not checked, printed when echoing.
    fn note(&mut self, text: String) {
        if let Some(echo) = self.echo {
            echo.notes.note(&format!("note: {text}\n"));
        }
        self.notes.push(text);
    }
}

/// What `vams check` found.
#[derive(Debug)]
pub struct Checked {
    /// Every diagnostic (errors and warnings), each once, in the order found: syntax,
    /// analysis, then elaboration and the analog system top by top.
    pub findings: Vec<Finding>,
    /// Why some top candidates were not elaborated or their analog system not built.
    pub notes: Vec<String>,
    /// The closing line: what was checked and the error counts by stage.
    pub summary: String,
    /// How many errors (warnings not counted).
    pub errors: usize,
}

/// Checks the sources under `paths` (library `work`) and `libraries` as `vams check` does,
/// showing at most `echo.max` diagnostics per file or top to `echo.notes` as they are found
/// (nothing when `None`) and giving them all back.
pub fn diagnose(
    paths: &[PathBuf],
    libraries: &[LibrarySources],
    echo: Option<Echo<'_>>,
) -> Result<Checked, InputError> {
    if let Some(deck) = single_deck(paths)? {
        return Ok(check_netlist(deck, echo));
    }
    let loaded = load_with_libraries(paths, libraries)?;
    let syntax: Vec<Finding> = (loaded.syntax_errors.iter())
        .flat_map(|(_, errors)| errors.iter())
        .map(|e| Finding::located(e, &loaded.sources, Level::Error))
        .collect();
    if let Some(Echo { max, notes }) = echo
        && !syntax.is_empty()
    {
        notes.note(&render_capped(&syntax, max));
    }
    let mut tally = Tally {
        syntax: loaded.error_count(),
        echo,
        ..Tally::default()
    };
    tally.found.extend(syntax);
    // A file with syntax errors is left out; the others are analysed and elaborated, so
    // that one broken file among many does not hide the rest's errors.
    let kept: Vec<(FileId, DesignFile)>;
    let files = if tally.syntax == 0 {
        loaded.files.as_slice()
    } else {
        kept = (loaded.files.iter())
            .filter(|(id, _)| !loaded.has_errors(*id))
            .cloned()
            .collect();
        let left_out: Vec<&str> = (loaded.syntax_errors.iter())
            .map(|(id, _)| loaded.sources.file(*id).name.as_str())
            .collect();
        tally.note(format!(
            "{} file(s) with syntax errors left out of the analysis ({}); what they declare \
             is missing to the other files",
            left_out.len(),
            left_out.join(", ")
        ));
        kept.as_slice()
    };
    // Every unit of every file, whether or not a top reaches it.
    let analysis = analyse(&loaded.sources, files);
    for unit in &analysis.units {
        tally.analysis += tally.keep(&unit.errors, &loaded, Level::Error);
    }
    tally.analysed_spans = analysis.errors().map(|e| e.primary_span()).collect();
    for candidate in top_candidates(&analysis, files) {
        check_top(&candidate, &analysis, &loaded, files, &mut tally);
    }
    Ok(Checked {
        summary: summary(&loaded, &tally),
        errors: tally.errors(),
        findings: tally.found,
        notes: tally.notes,
    })
}

/// Elaborates one candidate and builds its analog system, counting and printing the errors.
fn check_top(
    top: &TopCandidate,
    analysis: &Analysis,
    loaded: &Loaded,
    files: &[(FileId, DesignFile)],
    tally: &mut Tally<'_>,
) {
    if !top.has_architecture && top.configurations.is_empty() {
        tally.note(format!(
            "`{}` is not elaborated: it has no architecture (an entity declaration alone is \
             legal; `vams run` needs one)",
            top.name
        ));
        return;
    }
    if !top.can_elaborate() {
        tally.note(format!(
            "`{}` is not elaborated: no default for generic(s) {}; it is analysed, and what \
             depends on the generics' values is checked where it is instantiated",
            top.name,
            quoted(&top.generics_without_default)
        ));
        return;
    }
    // An entity that configuration declarations configure is elaborated through them.
    let names = match top.configurations.as_slice() {
        [] => std::slice::from_ref(&top.name),
        configurations => configurations,
    };
    for name in names {
        check_elaborated(name, top, analysis, loaded, files, tally);
    }
}

/// Elaborates the top `name` (an entity, or a configuration of `top`) and builds its analog
/// system.
fn check_elaborated(
    name: &str,
    top: &TopCandidate,
    analysis: &Analysis,
    loaded: &Loaded,
    files: &[(FileId, DesignFile)],
    tally: &mut Tally<'_>,
) {
    let options = ElabOptions {
        top: name.to_string(),
        generics: Vec::new(),
    };
    tally.elaborated += 1;
    let design = match elaborate_analysed(analysis, &loaded.sources, files, &options) {
        Ok(design) => design,
        Err(errors) => {
            tally.elaboration += tally.keep(&errors, loaded, Level::Error);
            return;
        }
    };
    // Warnings are not errors: printed once, not counted.
    let warnings: Vec<ElabWarning> = design.warnings.iter().map(ElabWarning::from).collect();
    tally.keep(&warnings, loaded, Level::Warning);
    if !top.is_closed() {
        tally.note(format!(
            "the analog system of `{}` is not checked alone: port(s) {} would be open",
            top.name,
            quoted(&top.analog_ports)
        ));
        return;
    }
    if design.quantities.is_empty() {
        return; // A digital design has no analog system (as in the kernel).
    }
    tally.analog_checked += 1;
    match AnalogSystem::new(&design) {
        Ok(system) => {
            tally.keep(&system.warnings(&design), loaded, Level::Warning);
        }
        Err(errors) => tally.analog += tally.keep(&errors, loaded, Level::Error),
    }
}

/// `vams check deck.cir`: the deck read, flattened and lowered, and its analog system built
/// (a node with no DC path to ground, a loop of voltage sources).
fn check_netlist(deck: &Path, echo: Option<Echo<'_>>) -> Checked {
    let name = deck.display().to_string();
    let findings = match compile_netlist(deck) {
        Ok(compiled) => {
            let mut found = compiled.warnings;
            let sources = &compiled.loaded.sources;
            match AnalogSystem::new(&compiled.design) {
                Ok(system) => found.extend(located(
                    &system.warnings(&compiled.design),
                    sources,
                    Level::Warning,
                )),
                Err(errors) => found.extend(located(&errors, sources, Level::Error)),
            }
            found
        }
        // A deck that cannot be read has no located diagnostic: its error is the finding.
        Err(not) if not.findings.is_empty() => vec![Finding::unlocated(not.error, Level::Error)],
        Err(not) => not.findings,
    };
    if let Some(echo) = echo {
        echo.notes.note(&render_capped(&findings, echo.max));
    }
    let errors = (findings.iter())
        .filter(|f| f.level == Level::Error)
        .count();
    let summary = match errors {
        0 => format!("checked the SPICE deck {name}: no errors"),
        n => format!("checked the SPICE deck {name}: {n} error(s)"),
    };
    Checked {
        findings,
        notes: Vec::new(),
        summary,
        errors,
    }
}

/// `a`, `b`
fn quoted(names: &[String]) -> String {
    names
        .iter()
        .map(|n| format!("`{n}`"))
        .collect::<Vec<_>>()
        .join(", ")
}

/// The closing line: what was checked and the error counts by stage.
fn summary(loaded: &Loaded, tally: &Tally<'_>) -> String {
    let checked = format!(
        "checked {} file(s), {} design unit(s), {} top(s) elaborated, {} analog system(s) built",
        loaded.sources.len(),
        loaded.unit_count(),
        tally.elaborated,
        tally.analog_checked
    );
    if tally.errors() == 0 {
        format!("{checked}: no errors")
    } else {
        format!(
            "{checked}: {} syntax, {} analysis, {} elaboration and {} analog error(s)",
            tally.syntax, tally.analysis, tally.elaboration, tally.analog
        )
    }
}
