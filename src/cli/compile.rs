//! The design arguments to an elaborated design, as every subcommand does it: the
//! application layer compiles ([`crate::app::compile`]); this prints its findings on stderr.

use miette::Report;

use crate::app::ac::NotLinearised;
use crate::app::compile::{self, Compiled, NotCompiled, Prepared};
use crate::app::render::{render, render_capped};
use crate::design::Design;
use crate::diagnostics::Finding;

use super::args::DesignArgs;

/// Syntax errors printed per file: a file that is not VHDL at all would fill the screen.
const SYNTAX_ERRORS_PER_FILE: usize = 20;

/// Prints findings (errors or warnings) on stderr.
pub fn print_findings(findings: &[Finding]) {
    for f in findings {
        eprint!("{}", render(f.report.as_ref()));
    }
}

/// Prints why the sources gave no design (syntax errors at most 20 a file) and gives the
/// summary error.
pub fn fail(not: NotCompiled) -> Report {
    if not.is_syntax() {
        eprint!("{}", render_capped(&not.findings, SYNTAX_ERRORS_PER_FILE));
    } else {
        print_findings(&not.findings);
    }
    not.error
}

/// Loads, parses and analyses the sources and chooses the top, printing what fails.
pub fn prepare(args: &DesignArgs) -> Result<Prepared, Report> {
    compile::prepare(&args.options()).map_err(fail)
}

/// Elaborates a prepared design with `extra` generics, printing errors and warnings.
pub fn elaborate(prepared: &Prepared, extra: &[(String, String)]) -> Result<Design, Report> {
    let design = prepared.elaborate(extra).map_err(fail)?;
    print_findings(&prepared.warnings(&design));
    Ok(design)
}

/// Loads, parses and elaborates, printing every diagnostic (the warnings too).
pub fn compile(args: &DesignArgs) -> Result<Compiled, Report> {
    let compiled = compile::compile(&args.options()).map_err(fail)?;
    print_findings(&compiled.warnings);
    Ok(compiled)
}

/// Prints why a design could not be linearised and gives the summary error.
pub fn not_linearised(not: NotLinearised) -> Report {
    eprint!("{}", not.diagnostics);
    not.error.into()
}
