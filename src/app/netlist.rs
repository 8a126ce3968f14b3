//! SPICE decks as designs: a file ending in `.cir`, `.sp`, `.spice` or `.net` is read by the
//! SPICE frontend (`vams_spice`: the deck read with its includes, flattened, lowered to a
//! [`Design`]) instead of the VHDL-AMS pipeline, and runs through the same solver, outputs
//! and plots. The deck's `.tran` gives the stop time and the largest step, its `.options`
//! the tolerances the command line does not set, and its `.print`/`.probe` vectors the
//! columns, named as ngspice names them (`v(2)`, `i(vcc)`).

use std::path::{Path, PathBuf};

use crate::diagnostics::Level;
use crate::source::SourceMap;
use vams_spice::{FsLoader, SpiceError, TranSpec, flatten, lower, read_deck};

use super::compile::{Compiled, NotCompiled, located};
use super::error::CliError;
use super::load::{InputError, Loaded, read_text};

/// The file extensions of SPICE decks.
pub const EXTENSIONS: [&str; 4] = ["cir", "sp", "spice", "net"];

/// True for a path that names a SPICE deck (by its extension).
pub fn is_netlist(path: &Path) -> bool {
    (path.extension().and_then(|e| e.to_str()))
        .is_some_and(|e| EXTENSIONS.iter().any(|x| x.eq_ignore_ascii_case(e)))
}

/// What a deck asks of a run besides its circuit.
#[derive(Debug, Clone, Default)]
pub struct NetlistRun {
    /// The deck's `.tran`, if it has one.
    pub transient: Option<TranSpec>,
    /// The quantities its transient `.print`/`.probe` vectors name, in order (every node
    /// voltage when it names none).
    pub outputs: Vec<String>,
    /// `.options reltol` and `abstol`.
    pub reltol: Option<f64>,
    pub abstol: Option<f64>,
}

/// Reads, flattens and lowers the deck at `path`: the design, with the sources it was read
/// from (the deck and its includes) for diagnostics and what the deck asks of a run
/// ([`Compiled::netlist`]).
pub fn compile_netlist(path: &Path) -> Result<Compiled, NotCompiled> {
    let text = read_text(path).map_err(NotCompiled::bare)?;
    let mut sources = SourceMap::new();
    let file = sources.add(path.display().to_string(), "work", text);
    // The reader keeps its warnings (a skipped `.control`) in the deck, apart from errors.
    let (deck, errors) = read_deck(&mut sources, file, &mut FsLoader);
    let warnings = located(&deck.warnings, &sources, Level::Warning);
    let failed = |errors: Vec<SpiceError>, sources: &SourceMap| NotCompiled {
        findings: located(&errors, sources, Level::Error),
        error: CliError::Netlist {
            path: path.display().to_string(),
            count: errors.len(),
        }
        .into(),
    };
    if !errors.is_empty() {
        return Err(failed(errors, &sources));
    }
    let circuit = flatten(&deck).map_err(|e| failed(e, &sources))?;
    let mut design = lower(&circuit).map_err(|e| failed(e, &sources))?;
    design.top = deck_name(path);
    let run = NetlistRun {
        transient: vams_spice::transient(&circuit),
        outputs: vams_spice::outputs(&circuit),
        reltol: circuit.options.reltol,
        abstol: circuit.options.abstol,
    };
    let loaded = Loaded {
        sources,
        files: Vec::new(),
        syntax_errors: Vec::new(),
    };
    Ok(Compiled {
        loaded,
        design,
        warnings,
        netlist: Some(run),
    })
}

/// The design's name: the deck's file name without its extension.
fn deck_name(path: &Path) -> String {
    (path.file_stem().and_then(|s| s.to_str()))
        .map_or_else(|| "deck".to_string(), str::to_ascii_lowercase)
}

/// The deck among `paths`, when they are one deck; an error when a deck comes with other
/// sources (a netlist inside a VHDL-AMS design is not supported yet).
pub fn single_deck(paths: &[PathBuf]) -> Result<Option<&Path>, InputError> {
    match paths {
        [one] if is_netlist(one) => Ok(Some(one)),
        _ => match paths.iter().find(|p| is_netlist(p)) {
            Some(deck) => Err(InputError::NetlistWithSources {
                path: deck.display().to_string(),
            }),
            None => Ok(None),
        },
    }
}
