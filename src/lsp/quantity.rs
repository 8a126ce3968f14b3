//! What hover tells of a quantity beyond its type: its role (across or through a branch and
//! which, free, a spectrum or noise source, a port) and tolerance group, from its
//! declaration's syntax, and its unit: the `symbol` attribute of its subtype (`attribute
//! symbol of voltage : subtype is "V";` in the discipline packages), which elaboration reads
//! and analysis does not record. Names are followed through the analysis's resolutions, so a
//! subtype is the one the declaration denotes, not any of its name.

use crate::analysis::{AnalysisHost, DeclId, DeclKind};
use crate::ast::{self, EntityNames, InterfaceDecl, NatureDef, QuantityDecl};
use crate::source::{SourceMap, Span};

use super::syntax::{Node, declaration_around, walk_file};

/// A quantity's role and tolerance group, from its declaration's syntax.
pub fn role(node: Node, name: Span, sources: &SourceMap) -> Option<String> {
    let text = |e: &ast::Expr| sources.snippet(e.span).to_string();
    let tolerance = |t: Option<&ast::Expr>| {
        t.map(|e| format!("; tolerance group {}", text(e)))
            .unwrap_or_default()
    };
    match node {
        Node::Decl(d) => match &d.kind {
            ast::DeclKind::Quantity(QuantityDecl::Branch {
                across,
                through,
                plus,
                minus,
            }) => {
                let branch = match (plus, minus) {
                    (Some(p), Some(m)) => format!(" from `{}` to `{}`", text(p), text(m)),
                    (Some(p), None) => format!(" from `{}` to the reference", text(p)),
                    _ => String::new(),
                };
                let find = |list: &[ast::BranchName]| {
                    list.iter()
                        .find(|b| b.names.iter().any(|n| n.span == name))
                        .map(|b| tolerance(b.tolerance.as_ref()))
                };
                if let Some(tol) = find(across) {
                    Some(format!("**across** quantity of the branch{branch}{tol}"))
                } else {
                    find(through)
                        .map(|tol| format!("**through** quantity of the branch{branch}{tol}"))
                }
            }
            ast::DeclKind::Quantity(QuantityDecl::Free { subtype, .. }) => Some(format!(
                "**free** quantity{}",
                tolerance(subtype.tolerance.as_ref())
            )),
            ast::DeclKind::Quantity(QuantityDecl::Source {
                subtype, spectrum, ..
            }) => {
                let kind = if spectrum.is_some() {
                    "spectrum"
                } else {
                    "noise"
                };
                Some(format!(
                    "**{kind} source** quantity{}",
                    tolerance(subtype.tolerance.as_ref())
                ))
            }
            _ => None,
        },
        Node::Interface(InterfaceDecl {
            class: Some(ast::ObjectClass::Quantity),
            mode,
            subtype,
            ..
        }) => {
            let mode = mode.map_or("in".to_string(), |m| format!("{m:?}").to_ascii_lowercase());
            Some(format!(
                "**quantity port** (mode {mode}){}",
                tolerance(subtype.tolerance.as_ref())
            ))
        }
        Node::Interface(_) => None,
    }
}

/// The subtype of the quantity named at `name` (declared by `node`) and its unit symbol.
pub fn unit(host: &AnalysisHost, node: Node, name: Span) -> Option<(String, String)> {
    let analysis = host.analysis();
    let resolve = |e: &ast::Expr| analysis.declaration_at(e.span.file, e.span.start);
    let subtype = match node {
        Node::Decl(d) => match &d.kind {
            ast::DeclKind::Quantity(QuantityDecl::Free { subtype, .. })
            | ast::DeclKind::Quantity(QuantityDecl::Source { subtype, .. }) => {
                resolve(&subtype.type_mark)?
            }
            ast::DeclKind::Quantity(QuantityDecl::Branch { across, plus, .. }) => {
                let is_across = across
                    .iter()
                    .any(|b| b.names.iter().any(|n| n.span == name));
                branch_subtype(host, plus.as_ref()?, is_across)?
            }
            _ => return None,
        },
        Node::Interface(InterfaceDecl {
            class: Some(ast::ObjectClass::Quantity),
            subtype,
            ..
        }) => resolve(&subtype.type_mark)?,
        Node::Interface(_) => return None,
    };
    let symbol = symbol_of(host, subtype)?;
    Some((analysis.decl(subtype).name.clone(), symbol))
}

/// The across (or through) subtype of the nature of the terminal `plus` names.
fn branch_subtype(host: &AnalysisHost, plus: &ast::Expr, across: bool) -> Option<DeclId> {
    let analysis = host.analysis();
    let terminal = analysis.declaration_at(plus.span.file, plus.span.start)?;
    let nature_mark = match syntax_of(host, terminal)? {
        Node::Decl(d) => match &d.kind {
            ast::DeclKind::Terminal { nature, .. } => nature.type_mark.clone(),
            _ => return None,
        },
        Node::Interface(i) => i.subtype.type_mark.clone(),
    };
    let nature = analysis.declaration_at(nature_mark.span.file, nature_mark.span.start)?;
    if !matches!(analysis.decl(nature).kind, DeclKind::Nature(_)) {
        return None;
    }
    let Node::Decl(d) = syntax_of(host, nature)? else {
        return None;
    };
    let ast::DeclKind::Nature {
        def:
            NatureDef::Scalar {
                across: a,
                through: t,
                ..
            },
        ..
    } = &d.kind
    else {
        return None;
    };
    let mark = if across { a } else { t };
    analysis.declaration_at(mark.span.file, mark.span.start)
}

/// The declaration syntax of `d`.
fn syntax_of(host: &AnalysisHost, d: DeclId) -> Option<Node<'_>> {
    let span = host.analysis().decl(d).span;
    let (_, ast) = host.files().iter().find(|(f, _)| *f == span.file)?;
    declaration_around(ast, span)
}

/// The value of `attribute symbol of <subtype> : subtype is "..."` in any file.
fn symbol_of(host: &AnalysisHost, subtype: DeclId) -> Option<String> {
    let analysis = host.analysis();
    let mut found = None;
    for (_, ast) in host.files() {
        walk_file(ast, &mut |node| {
            let Node::Decl(d) = node else { return };
            let ast::DeclKind::AttributeSpec {
                attribute,
                entities: EntityNames::List(names),
                value,
                ..
            } = &d.kind
            else {
                return;
            };
            let names_it = names
                .iter()
                .any(|n| analysis.declaration_at(n.span.file, n.span.start) == Some(subtype));
            if attribute.name == "symbol" && names_it {
                if let ast::ExprKind::Literal(ast::Literal::String(s)) = &value.kind {
                    found = Some(s.clone());
                }
            }
        });
        if found.is_some() {
            break;
        }
    }
    found
}
