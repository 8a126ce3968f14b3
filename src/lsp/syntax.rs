//! Finding the syntax of a declaration: the innermost declaration (or interface element) of a
//! parsed file around a span, for hover to show how a name was declared and what analysis
//! does not record (a quantity's across or through role, its tolerance group).

use crate::ast::{
    ConcKind, ConcStmt, Decl, DeclKind, DesignFile, InterfaceDecl, LibraryUnit, SimKind,
};
use crate::source::Span;

/// A declaration in the syntax tree.
#[derive(Clone, Copy, Debug)]
pub enum Node<'a> {
    Decl(&'a Decl),
    Interface(&'a InterfaceDecl),
}

impl Node<'_> {
    pub fn span(&self) -> Span {
        match self {
            Node::Decl(d) => d.span,
            Node::Interface(i) => i.span,
        }
    }
}

/// The smallest declaration of `file` whose span contains `span`.
pub fn declaration_around(file: &DesignFile, span: Span) -> Option<Node<'_>> {
    let mut best: Option<Node> = None;
    walk_file(file, &mut |node| {
        let s = node.span();
        let inside = s.start <= span.start && span.end <= s.end;
        if inside && best.is_none_or(|b| s.len() < b.span().len()) {
            best = Some(node);
        }
    });
    best
}

/// Every declaration of `file`, outer before inner.
pub fn walk_file<'a>(file: &'a DesignFile, visit: &mut impl FnMut(Node<'a>)) {
    for unit in &file.units {
        match &unit.unit {
            LibraryUnit::Entity(e) => {
                interfaces(&e.generics, visit);
                interfaces(&e.ports, visit);
                decls(&e.decls, visit);
                statements(&e.stmts, visit);
            }
            LibraryUnit::Architecture(a) => {
                decls(&a.decls, visit);
                statements(&a.stmts, visit);
            }
            LibraryUnit::Package(p) => decls(&p.decls, visit),
            LibraryUnit::PackageBody(b) => decls(&b.decls, visit),
            LibraryUnit::Configuration(_) => {}
        }
    }
}

fn interfaces<'a>(list: &'a [InterfaceDecl], visit: &mut impl FnMut(Node<'a>)) {
    for i in list {
        visit(Node::Interface(i));
    }
}

fn decls<'a>(list: &'a [Decl], visit: &mut impl FnMut(Node<'a>)) {
    for d in list {
        visit(Node::Decl(d));
        match &d.kind {
            DeclKind::Component {
                generics, ports, ..
            } => {
                interfaces(generics, visit);
                interfaces(ports, visit);
            }
            DeclKind::Subprogram(spec) => interfaces(&spec.params, visit),
            DeclKind::SubprogramBody { spec, decls: d, .. } => {
                interfaces(&spec.params, visit);
                decls(d, visit);
            }
            DeclKind::ProtectedBody { decls: d, .. } => decls(d, visit),
            _ => {}
        }
    }
}

fn statements<'a>(list: &'a [ConcStmt], visit: &mut impl FnMut(Node<'a>)) {
    for s in list {
        match &s.kind {
            ConcKind::Process { decls: d, .. } => decls(d, visit),
            ConcKind::ForGenerate {
                decls: d, stmts, ..
            }
            | ConcKind::IfGenerate {
                decls: d, stmts, ..
            } => {
                decls(d, visit);
                statements(stmts, visit);
            }
            ConcKind::Block {
                header,
                decls: d,
                stmts,
                ..
            } => {
                interfaces(&header.generics, visit);
                interfaces(&header.ports, visit);
                decls(d, visit);
                statements(stmts, visit);
            }
            ConcKind::Simultaneous(SimKind::Procedural { decls: d, .. }) => decls(d, visit),
            ConcKind::Simultaneous(SimKind::If {
                branches,
                otherwise,
            }) => {
                for (_, stmts) in branches {
                    statements(stmts, visit);
                }
                statements(otherwise.as_deref().unwrap_or_default(), visit);
            }
            ConcKind::Simultaneous(SimKind::Case { alternatives, .. }) => {
                for (_, stmts) in alternatives {
                    statements(stmts, visit);
                }
            }
            _ => {}
        }
    }
}
