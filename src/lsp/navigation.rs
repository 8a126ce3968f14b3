//! Go to definition and find references: the declaration analysis resolved the name under
//! the cursor to, and every use of it in the workspace's files (`Analysis::references_to`).
//! Declarations in the bundled stdlib have no file the client can open, so they are left out.

use lsp_types::Location;

use crate::analysis::{Analysis, DeclId};
use crate::source::{FileId, Span};

use super::position::LineIndex;
use super::workspace::Workspace;

/// The declaration the name at `offset` denotes: a use's, or the declaration whose own name
/// it is.
pub fn target(analysis: &Analysis, file: FileId, offset: u32) -> Option<DeclId> {
    (analysis.declaration_at(file, offset)).or_else(|| analysis.declared_at(file, offset))
}

pub fn definition(ws: &Workspace, file: FileId, offset: u32) -> Option<Location> {
    let analysis = ws.host().analysis();
    let decl = analysis.decl(target(analysis, file, offset)?);
    location(ws, decl.span)
}

pub fn references(
    ws: &Workspace,
    file: FileId,
    offset: u32,
    include_declaration: bool,
) -> Vec<Location> {
    let analysis = ws.host().analysis();
    let Some(id) = target(analysis, file, offset) else {
        return Vec::new();
    };
    let declared = analysis.decl(id).span;
    let mut spans = analysis.references_to(id);
    if include_declaration && !spans.contains(&declared) {
        spans.insert(0, declared);
    }
    spans.dedup();
    spans
        .into_iter()
        .filter(|s| include_declaration || *s != declared)
        .filter_map(|s| location(ws, s))
        .collect()
}

/// Where `span` is, when it is in a user file.
fn location(ws: &Workspace, span: Span) -> Option<Location> {
    let uri = ws.uri(span.file)?;
    let index = LineIndex::new(ws.text(span.file));
    Some(Location::new(uri.clone(), index.range(span)))
}
