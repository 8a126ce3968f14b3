//! Diagnostics and simulation reports rendered as text (the commands print it).
//!
//! Diagnostics are rendered by miette: with colour when stderr is a terminal, otherwise as the
//! plain fixed-width text of [`crate::diagnostics::render_plain`] (what logs and tests see).

use std::io::IsTerminal;

use miette::{Diagnostic, GraphicalReportHandler, GraphicalTheme, Report};

use crate::diagnostics::{Finding, Located, to_report};
use crate::kernel::{Report as SimReport, Severity, SimError};
use crate::source::SourceMap;

use super::time::format_time;

/// Renders any diagnostic (colour on a terminal, plain otherwise).
pub fn render(diag: &dyn Diagnostic) -> String {
    let handler = if std::io::stderr().is_terminal() {
        GraphicalReportHandler::new_themed(GraphicalTheme::unicode())
    } else {
        GraphicalReportHandler::new_themed(GraphicalTheme::unicode_nocolor())
            .with_width(100)
            .with_links(false)
    };
    let mut out = String::new();
    // Writing into a String cannot fail.
    let _ = handler.render_report(&mut out, diag);
    out
}

/// Renders findings, at most `max_per_file` of each file (a file that is not VHDL at all would
/// fill the screen with syntax errors), each file's followed by how many more it has.
pub fn render_capped(findings: &[Finding], max_per_file: usize) -> String {
    let mut out = String::new();
    let mut start = 0;
    while start < findings.len() {
        let file = &findings[start].file;
        let count = (findings[start..].iter())
            .take_while(|f| &f.file == file)
            .count();
        for f in &findings[start..start + count.min(max_per_file)] {
            out.push_str(&render(f.report.as_ref()));
        }
        if count > max_per_file {
            out.push_str(&format!(
                "  ... and {} more in {file}\n\n",
                count - max_per_file
            ));
        }
        start += count;
    }
    out
}

/// Renders a diagnostic located in `sources`.
pub fn render_located<D: Located>(diag: &D, sources: &SourceMap) -> String {
    let report: Report = to_report(diag, sources);
    render(report.as_ref())
}

/// Renders a simulation error; the analog system's errors are located in `sources`.
pub fn render_sim_error(error: &SimError, sources: &SourceMap) -> String {
    let mut out = String::new();
    match error {
        SimError::Analog { errors } => {
            for e in errors {
                out.push_str(&render_located(e, sources));
            }
            out.push_str(&render(error));
        }
        // A real span points into the sources: show the line it is about.
        _ if (error.primary_span().file.0 as usize) < sources.len()
            && error.primary_span() != Default::default() =>
        {
            out.push_str(&render_located(error, sources));
        }
        _ => out.push_str(&render(error)),
    }
    out
}

/// `message at file:line:col` of a located diagnostic, on one line (a table cell, a fit's
/// failed trial); the message alone where it has no span in `sources`.
pub fn located_line<D: Located>(d: &D, sources: &SourceMap) -> String {
    let span = d.primary_span();
    if span == Default::default() || span.file.0 as usize >= sources.len() {
        return d.to_string();
    }
    let (line, col) = sources.line_col(span);
    format!("{d} at {}:{line}:{col}", sources.file(span.file).name)
}

/// A failed simulation on one line: the first of the analog system's errors or the error
/// itself, located, and the last time recorded (`last`) where there is one.
pub fn sim_error_line(error: &SimError, last: Option<f64>, sources: &SourceMap) -> String {
    let message = match error {
        SimError::Analog { errors } if !errors.is_empty() => located_line(&errors[0], sources),
        _ => located_line(error, sources),
    };
    let at = last
        .map(|t| format!(" (t = {})", format_time(t)))
        .unwrap_or_default();
    format!("{message}{at}")
}

/// The lower-case name of a severity, as VHDL spells it.
pub fn severity_name(severity: Severity) -> &'static str {
    match severity {
        Severity::Note => "note",
        Severity::Warning => "warning",
        Severity::Error => "error",
        Severity::Failure => "failure",
    }
}

/// `file:line:col` of a report's statement, when its span points into `sources`.
fn location(report: &SimReport, sources: &SourceMap) -> Option<String> {
    let file = report.span.file;
    if file.0 as usize >= sources.len() {
        return None;
    }
    let (line, col) = sources.line_col(report.span);
    Some(format!("{}:{line}:{col}", sources.file(file).name))
}

/// One report as a line: `12.5 ms: error: <message> (process p, file:line:col)`.
pub fn format_report(report: &SimReport, sources: &SourceMap) -> String {
    let mut whence = Vec::new();
    if !report.process.is_empty() {
        whence.push(format!("process {}", report.process));
    }
    if let Some(at) = location(report, sources) {
        whence.push(at);
    }
    let whence = if whence.is_empty() {
        String::new()
    } else {
        format!(" ({})", whence.join(", "))
    };
    format!(
        "{}: {}: {}{whence}",
        format_time(report.time),
        severity_name(report.severity),
        report.message
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::source::Span;

    #[test]
    fn report_line_has_time_severity_message_process_and_location() {
        let mut sources = SourceMap::new();
        let file = sources.add("tb.vhd", "work", "entity tb is end;\n  assert x;\n".into());
        let report = SimReport {
            time: 0.0125,
            severity: Severity::Error,
            message: "vfb too low".into(),
            process: "check".into(),
            span: Span::new(file, 20, 29),
        };
        assert_eq!(
            format_report(&report, &sources),
            "12.5 ms: error: vfb too low (process check, tb.vhd:2:3)"
        );
        // A span outside the map (a report without a source) prints no location.
        let orphan = SimReport {
            span: Span::new(crate::source::FileId(7), 0, 0),
            process: String::new(),
            ..report
        };
        assert_eq!(
            format_report(&orphan, &sources),
            "12.5 ms: error: vfb too low"
        );
    }
}
