//! The workspace's diagnostics as LSP diagnostics: syntax and analysis errors of every user
//! file after each change (the front end's, at once), elaboration and analog-system errors of
//! the workspace's testbenches after a save (those that reach the saved file), with the message, label and help line that
//! `vams check` prints. [`Published`] remembers what each file was last sent, so that only
//! changes go out and a fixed file is cleared.

use std::collections::HashMap;

use lsp_types::{Diagnostic, DiagnosticSeverity, NumberOrString, PublishDiagnosticsParams, Url};
use rustc_hash::FxHashMap;

use crate::analog::AnalogSystem;
use crate::analysis::UnitKind;
use crate::diagnostics::Located;
use crate::elaborate::{
    ElabOptions, ElabWarning, TopCandidate, elaborate_analysed, top_candidates,
};
use crate::source::{FileId, Span};

use super::position::LineIndex;
use super::workspace::Workspace;

/// Diagnostics by file.
pub type ByFile = FxHashMap<FileId, Vec<Diagnostic>>;

/// One diagnostic of ours, located in `index`'s text.
pub fn to_lsp<D: Located>(d: &D, index: &LineIndex, severity: DiagnosticSeverity) -> Diagnostic {
    let mut message = d.to_string();
    if let Some(label) = d
        .labels()
        .into_iter()
        .flatten()
        .find_map(|l| l.label().map(str::to_string))
    {
        message.push_str(&format!("\n{label}"));
    }
    if let Some(help) = d.help() {
        message.push_str(&format!("\nhelp: {help}"));
    }
    Diagnostic {
        range: index.range(d.primary_span()),
        severity: Some(severity),
        code: d.code().map(|c| NumberOrString::String(c.to_string())),
        source: Some("vams".to_string()),
        message,
        ..Diagnostic::default()
    }
}

/// Syntax errors of every user file, and analysis errors of the user files without syntax
/// errors (as `vams check`, which leaves those out of the analysis: what a broken file's
/// analysis says is mostly the parser's recovery).
pub fn front_end(ws: &Workspace) -> ByFile {
    let host = ws.host();
    let mut out = ByFile::default();
    for (id, _, _) in ws.user_files() {
        out.insert(id, Vec::new());
    }
    for (id, errors) in host.syntax_errors() {
        if let Some(list) = out.get_mut(id) {
            let index = LineIndex::new(ws.text(*id));
            list.extend(
                errors
                    .iter()
                    .map(|e| to_lsp(e, &index, DiagnosticSeverity::ERROR)),
            );
        }
    }
    let broken = |id: FileId| host.syntax_errors().iter().any(|(f, _)| *f == id);
    let mut indexes: FxHashMap<FileId, LineIndex> = FxHashMap::default();
    for e in host.analysis().errors() {
        let file = e.primary_span().file;
        let Some(list) = out.get_mut(&file).filter(|_| !broken(file)) else {
            continue;
        };
        let index = indexes
            .entry(file)
            .or_insert_with(|| LineIndex::new(ws.text(file)));
        list.push(to_lsp(e, index, DiagnosticSeverity::ERROR));
    }
    out
}

/// What elaborating one testbench found, and the files its units were in (a save of one of
/// them, then or now, elaborates it again).
#[derive(Default)]
pub struct Bench {
    files: Vec<FileId>,
    found: ByFile,
}

/// Elaborates the testbenches of the workspace (an entity without ports, or named `tb_*`,
/// that nothing instantiates and that has an architecture and defaults for its generics) that
/// reach file `saved` (all when `None`), and builds the analog system of each that has no
/// open analog port: the errors and warnings found, leaving out those at a place analysis
/// reported already (as `vams check`). `benches` holds each bench's last findings; those of
/// benches that are gone are dropped.
pub fn testbenches(ws: &Workspace, saved: Option<FileId>, benches: &mut FxHashMap<String, Bench>) {
    let host = ws.host();
    let (analysis, files) = (host.analysis(), host.files());
    let analysed: Vec<Span> = analysis.errors().map(|e| e.primary_span()).collect();
    let mut now = FxHashMap::default();
    for top in top_candidates(analysis, files) {
        let is_user = ws.uri(top.span.file).is_some();
        let is_bench = top.name.starts_with("tb_") || !entity_has_ports(ws, top.span);
        if !(is_user && is_bench && top.has_architecture && top.can_elaborate()) {
            continue;
        }
        let entity = analysis.units.iter().position(|u| {
            u.kind == UnitKind::Entity && u.name == top.name && u.file == top.span.file
        });
        let mut reached: Vec<FileId> = (entity.map(|e| analysis.reached_from(e)))
            .into_iter()
            .flatten()
            .map(|u| analysis.units[u].file)
            .collect();
        reached.sort();
        reached.dedup();
        let previous = benches.remove(&top.name);
        let unchanged =
            |b: &Bench| saved.is_some_and(|f| !b.files.contains(&f) && !reached.contains(&f));
        let bench = match previous {
            Some(b) if unchanged(&b) => b,
            _ => Bench {
                found: elaborate_bench(ws, &top, &analysed),
                files: reached,
            },
        };
        now.insert(top.name.clone(), bench);
    }
    *benches = now;
}

/// Elaborates one testbench and builds its analog system: what they found.
fn elaborate_bench(ws: &Workspace, top: &TopCandidate, analysed: &[Span]) -> ByFile {
    let host = ws.host();
    let (analysis, sources, files) = (host.analysis(), host.sources(), host.files());
    let mut found = Found::default();
    let options = ElabOptions {
        top: top.name.clone(),
        generics: Vec::new(),
    };
    match elaborate_analysed(analysis, sources, files, &options) {
        Err(errors) => found.add(ws, &errors, analysed, DiagnosticSeverity::ERROR),
        Ok(design) => {
            let warnings: Vec<ElabWarning> =
                design.warnings.iter().map(ElabWarning::from).collect();
            found.add(ws, &warnings, analysed, DiagnosticSeverity::WARNING);
            if top.is_closed() && !design.quantities.is_empty() {
                match AnalogSystem::new(&design) {
                    Ok(system) => found.add(
                        ws,
                        &system.warnings(&design),
                        analysed,
                        DiagnosticSeverity::WARNING,
                    ),
                    Err(errors) => found.add(ws, &errors, analysed, DiagnosticSeverity::ERROR),
                }
            }
        }
    }
    found.by_file
}

/// Whether the entity declared at `name` (its identifier's span) has ports.
fn entity_has_ports(ws: &Workspace, name: Span) -> bool {
    let Some(ast) = ws.ast(name.file) else {
        return false;
    };
    ast.units.iter().any(|u| match &u.unit {
        crate::ast::LibraryUnit::Entity(e) => e.name.span == name && !e.ports.is_empty(),
        _ => false,
    })
}

/// Diagnostics gathered over several tops, each once.
#[derive(Default)]
struct Found {
    by_file: ByFile,
}

impl Found {
    fn add<D: Located>(
        &mut self,
        ws: &Workspace,
        diags: &[D],
        analysed: &[Span],
        severity: DiagnosticSeverity,
    ) {
        for d in diags {
            let span = d.primary_span();
            // Only user files have URIs; a span outside the sources means "no place".
            if ws.uri(span.file).is_none() || within_analysed(span, analysed) {
                continue;
            }
            let index = LineIndex::new(ws.text(span.file));
            let diagnostic = to_lsp(d, &index, severity);
            let list = self.by_file.entry(span.file).or_default();
            if !list.contains(&diagnostic) {
                list.push(diagnostic);
            }
        }
    }
}

/// True when analysis reported an error at `span` or, for an expression's span, inside it
/// (elaboration's view of the same error from further out; `vams check`'s rule).
fn within_analysed(span: Span, analysed: &[Span]) -> bool {
    const EXPRESSION: u32 = 160;
    analysed.iter().any(|a| {
        *a == span
            || (a.file == span.file
                && span.end.saturating_sub(span.start) <= EXPRESSION
                && span.start <= a.start
                && a.end <= span.end)
    })
}

/// What the client was last sent, and the two sources of diagnostics.
#[derive(Default)]
pub struct Published {
    front: ByFile,
    benches: FxHashMap<String, Bench>,
    sent: HashMap<Url, Vec<Diagnostic>>,
}

impl Published {
    /// After a change: the front end's diagnostics anew; the testbenches' stay as the last
    /// save left them until the next (as a build's errors do in an editor).
    pub fn changed(&mut self, ws: &Workspace) -> Vec<PublishDiagnosticsParams> {
        self.front = front_end(ws);
        self.updates(ws)
    }

    /// After a save of `file` (of every file when `None`: the workspace loaded): the front
    /// end's anew, and those of the testbenches that reach the file.
    pub fn saved(&mut self, ws: &Workspace, file: Option<FileId>) -> Vec<PublishDiagnosticsParams> {
        self.front = front_end(ws);
        testbenches(ws, file, &mut self.benches);
        self.updates(ws)
    }

    /// A file left the compilation: clear what it was sent.
    pub fn removed(&mut self, uri: &Url) -> Option<PublishDiagnosticsParams> {
        self.sent
            .remove(uri)
            .filter(|d| !d.is_empty())
            .map(|_| PublishDiagnosticsParams::new(uri.clone(), Vec::new(), None))
    }

    /// The files whose diagnostics differ from what was sent.
    fn updates(&mut self, ws: &Workspace) -> Vec<PublishDiagnosticsParams> {
        let mut now: HashMap<Url, Vec<Diagnostic>> = HashMap::new();
        for (id, uri, _) in ws.user_files() {
            let mut list = self.front.get(&id).cloned().unwrap_or_default();
            // Benches in name order, so that the list does not change with a map's order;
            // what several benches share, once.
            let mut names: Vec<&String> = self.benches.keys().collect();
            names.sort();
            for name in names {
                for d in self.benches[name].found.get(&id).into_iter().flatten() {
                    if !list.contains(d) {
                        list.push(d.clone());
                    }
                }
            }
            now.insert(uri.clone(), list);
        }
        let mut out = Vec::new();
        for (uri, list) in &now {
            let before = self.sent.get(uri).map_or(&[][..], Vec::as_slice);
            if before != list.as_slice() {
                out.push(PublishDiagnosticsParams::new(
                    uri.clone(),
                    list.clone(),
                    None,
                ));
            }
        }
        // Files gone since: cleared.
        for (uri, list) in &self.sent {
            if !now.contains_key(uri) && !list.is_empty() {
                out.push(PublishDiagnosticsParams::new(uri.clone(), Vec::new(), None));
            }
        }
        out.sort_by(|a, b| a.uri.as_str().cmp(b.uri.as_str()));
        self.sent = now;
        out
    }
}
