//! Hover: what the name under the cursor denotes. The declaration as written (its source
//! text), its kind, name and type or nature from the analysis, and for a quantity its role
//! (across or through a branch, free, a spectrum or noise source) and tolerance group, which
//! only the syntax records.

use lsp_types::{Hover, HoverContents, MarkupContent, MarkupKind};

use crate::analysis::{Analysis, DeclKind, Declaration};
use crate::source::{FileId, Span};

use super::quantity;
use super::syntax::declaration_around;
use super::workspace::Workspace;

/// Longest declaration text shown, in lines.
const MAX_LINES: usize = 8;

pub fn hover(ws: &Workspace, file: FileId, offset: u32) -> Option<Hover> {
    let host = ws.host();
    let analysis = host.analysis();
    let id = super::navigation::target(analysis, file, offset)?;
    let decl = analysis.decl(id);
    let mut text = String::new();
    let node = host
        .files()
        .iter()
        .find(|(f, _)| *f == decl.span.file && decl.span != Span::default())
        .and_then(|(_, ast)| declaration_around(ast, decl.span));
    if let Some(node) = node {
        let source = excerpt(host.sources().snippet(node.span()));
        text.push_str(&format!("```vhdl\n{source}\n```\n\n"));
    }
    text.push_str(&describe(analysis, decl));
    if let Some(role) = node.and_then(|n| quantity::role(n, decl.span, host.sources())) {
        text.push_str(&format!("\n\n{role}"));
    }
    if let Some((subtype, unit)) = node.and_then(|n| quantity::unit(host, n, decl.span)) {
        text.push_str(&format!("\n\nsubtype `{subtype}`, unit `{unit}`"));
    }
    if decl.span != Span::default() {
        let sources = host.sources();
        let (line, _) = sources.line_col(decl.span);
        let name = &sources.file(decl.span.file).name;
        text.push_str(&format!("\n\n*declared in {name}:{line}*"));
    }
    Some(Hover {
        contents: HoverContents::Markup(MarkupContent {
            kind: MarkupKind::Markdown,
            value: text,
        }),
        range: None,
    })
}

/// The kind, name and type or nature of a declaration, in a line.
pub fn describe(analysis: &Analysis, decl: &Declaration) -> String {
    let name = &decl.name;
    let ty = |t| analysis.types.name(t).to_string();
    let nature = |n: &crate::analysis::NatureId| &analysis.natures[n.0 as usize];
    match &decl.kind {
        DeclKind::Object { class, ty: t, .. } => {
            let class = format!("{class:?}").to_ascii_lowercase();
            format!("{class} `{name}` : `{}`", ty(*t))
        }
        DeclKind::Terminal(n) => {
            let n = nature(n);
            format!(
                "terminal `{name}` of nature `{}` (across `{}`, through `{}`)",
                n.name,
                ty(n.across),
                ty(n.through)
            )
        }
        DeclKind::Nature(n) => {
            let n = nature(n);
            format!(
                "nature `{name}`: across `{}`, through `{}`",
                ty(n.across),
                ty(n.through)
            )
        }
        DeclKind::Type(t) if ty(*t) == *name => format!("type `{name}`"),
        DeclKind::Type(t) => format!("subtype `{name}` of type `{}`", ty(*t)),
        DeclKind::EnumLiteral(t) => format!("enumeration literal `{name}` of type `{}`", ty(*t)),
        DeclKind::Unit(t) => format!("unit `{name}` of physical type `{}`", ty(*t)),
        DeclKind::Subprogram(sig) => {
            let params: Vec<String> = sig
                .params
                .iter()
                .map(|p| format!("{} : {}", p.name, ty(p.ty)))
                .collect();
            match sig.result {
                Some(r) => format!(
                    "function `{name}`({}) return `{}`",
                    params.join("; "),
                    ty(r)
                ),
                None => format!("procedure `{name}`({})", params.join("; ")),
            }
        }
        DeclKind::Alias(t) => format!("alias `{name}` : `{}`", ty(*t)),
        DeclKind::Attribute(t) => format!("attribute `{name}` : `{}`", ty(*t)),
        DeclKind::Entity(_) => format!("entity `{name}`"),
        DeclKind::Package(_) => format!("package `{name}`"),
        DeclKind::Component(_) => format!("component `{name}`"),
        DeclKind::Library => format!("library `{name}`"),
        DeclKind::Opaque => format!("`{name}`"),
    }
}

/// The first lines of a declaration's text, with its own indentation removed.
fn excerpt(text: &str) -> String {
    let lines: Vec<&str> = text.lines().collect();
    let indent = lines
        .iter()
        .skip(1)
        .filter(|l| !l.trim().is_empty())
        .map(|l| l.len() - l.trim_start().len())
        .min()
        .unwrap_or(0);
    let mut out: Vec<&str> = lines
        .iter()
        .enumerate()
        .map(|(i, l)| {
            if i == 0 {
                l.trim_start()
            } else {
                l.get(indent..).unwrap_or(l.trim_start())
            }
        })
        .take(MAX_LINES)
        .collect();
    if lines.len() > MAX_LINES {
        out.push("...");
    }
    out.join("\n")
}
