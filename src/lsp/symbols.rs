//! Document symbols: the outline of one file. Design units at the top; within them generics,
//! ports, signals, quantities, terminals, constants, types, natures, components and
//! subprograms, and the concurrent statements that nest (processes, blocks, generates,
//! instances, procedurals) with what they declare.

use lsp_types::{DocumentSymbol, Range, SymbolKind};

use crate::ast::{
    ConcKind, ConcStmt, Decl, DeclKind, DesignFile, Ident, InterfaceDecl, LibraryUnit, ObjectClass,
    QuantityDecl, SimKind,
};
use crate::source::Span;

use super::position::LineIndex;

pub fn document_symbols(file: &DesignFile, index: &LineIndex) -> Vec<DocumentSymbol> {
    let outline = Outline { index };
    file.units
        .iter()
        .map(|unit| match &unit.unit {
            LibraryUnit::Entity(e) => {
                let mut children = outline.interfaces(&e.generics, SymbolKind::CONSTANT);
                children.extend(outline.interfaces(&e.ports, SymbolKind::FIELD));
                children.extend(outline.decls(&e.decls));
                children.extend(outline.statements(&e.stmts));
                outline.symbol(&e.name, "entity", SymbolKind::INTERFACE, e.span, children)
            }
            LibraryUnit::Architecture(a) => {
                let mut children = outline.decls(&a.decls);
                children.extend(outline.statements(&a.stmts));
                let detail = format!("architecture of {}", a.entity.name);
                outline.symbol(&a.name, &detail, SymbolKind::CLASS, a.span, children)
            }
            LibraryUnit::Package(p) => {
                let children = outline.decls(&p.decls);
                outline.symbol(&p.name, "package", SymbolKind::PACKAGE, p.span, children)
            }
            LibraryUnit::PackageBody(b) => {
                let children = outline.decls(&b.decls);
                outline.symbol(
                    &b.name,
                    "package body",
                    SymbolKind::PACKAGE,
                    b.span,
                    children,
                )
            }
            LibraryUnit::Configuration(c) => outline.symbol(
                &c.name,
                "configuration",
                SymbolKind::MODULE,
                c.span,
                Vec::new(),
            ),
        })
        .collect()
}

struct Outline<'a, 'b> {
    index: &'b LineIndex<'a>,
}

impl Outline<'_, '_> {
    /// A symbol for `name` declared by the construct at `span`.
    fn symbol(
        &self,
        name: &Ident,
        detail: &str,
        kind: SymbolKind,
        span: Span,
        children: Vec<DocumentSymbol>,
    ) -> DocumentSymbol {
        self.named(&name.name, name.span, detail, kind, span, children)
    }

    fn named(
        &self,
        name: &str,
        selection: Span,
        detail: &str,
        kind: SymbolKind,
        span: Span,
        children: Vec<DocumentSymbol>,
    ) -> DocumentSymbol {
        let range = self.index.range(span.to(selection));
        // A client rejects a selection outside the range; the name is inside its construct,
        // but a recovered parse may say otherwise.
        let mut selection_range = self.index.range(selection);
        if !contains(range, selection_range) {
            selection_range = range;
        }
        #[allow(deprecated)] // `deprecated` is a required field of the struct
        DocumentSymbol {
            name: if name.is_empty() {
                "?".to_string()
            } else {
                name.to_string()
            },
            detail: (!detail.is_empty()).then(|| detail.to_string()),
            kind,
            tags: None,
            deprecated: None,
            range,
            selection_range,
            children: (!children.is_empty()).then_some(children),
        }
    }

    fn interfaces(&self, list: &[InterfaceDecl], default: SymbolKind) -> Vec<DocumentSymbol> {
        let mut out = Vec::new();
        for i in list {
            let (kind, word) = match i.class {
                Some(ObjectClass::Quantity) => (SymbolKind::PROPERTY, "quantity"),
                Some(ObjectClass::Terminal) => (SymbolKind::FIELD, "terminal"),
                Some(ObjectClass::Signal) => (SymbolKind::VARIABLE, "signal"),
                Some(ObjectClass::Constant) => (SymbolKind::CONSTANT, "constant"),
                _ => (default, ""),
            };
            for n in &i.names {
                out.push(self.symbol(n, word, kind, i.span, Vec::new()));
            }
        }
        out
    }

    fn decls(&self, list: &[Decl]) -> Vec<DocumentSymbol> {
        let mut out = Vec::new();
        for d in list {
            let mut each = |names: &[Ident], word: &str, kind: SymbolKind| {
                for n in names {
                    out.push(self.symbol(n, word, kind, d.span, Vec::new()));
                }
            };
            match &d.kind {
                DeclKind::Signal { names, .. } => each(names, "signal", SymbolKind::VARIABLE),
                DeclKind::Constant { names, .. } => each(names, "constant", SymbolKind::CONSTANT),
                DeclKind::Variable { names, .. } => each(names, "variable", SymbolKind::VARIABLE),
                DeclKind::Terminal { names, .. } => each(names, "terminal", SymbolKind::FIELD),
                DeclKind::Quantity(QuantityDecl::Free { names, .. }) => {
                    each(names, "free quantity", SymbolKind::PROPERTY)
                }
                DeclKind::Quantity(QuantityDecl::Source { names, .. }) => {
                    each(names, "source quantity", SymbolKind::PROPERTY)
                }
                DeclKind::Quantity(QuantityDecl::Branch {
                    across, through, ..
                }) => {
                    for b in across {
                        each(&b.names, "across quantity", SymbolKind::PROPERTY);
                    }
                    for b in through {
                        each(&b.names, "through quantity", SymbolKind::PROPERTY);
                    }
                }
                DeclKind::Type { name, .. } | DeclKind::Subtype { name, .. } => {
                    each(std::slice::from_ref(name), "type", SymbolKind::STRUCT)
                }
                DeclKind::Nature { name, .. } | DeclKind::Subnature { name, .. } => {
                    each(std::slice::from_ref(name), "nature", SymbolKind::STRUCT)
                }
                DeclKind::Component { name, .. } => each(
                    std::slice::from_ref(name),
                    "component",
                    SymbolKind::INTERFACE,
                ),
                DeclKind::Alias { name, .. } => {
                    each(std::slice::from_ref(name), "alias", SymbolKind::VARIABLE)
                }
                DeclKind::Subprogram(spec) | DeclKind::SubprogramBody { spec, .. } => {
                    if let crate::ast::Designator::Ident(name) = &spec.designator {
                        let word = if spec.is_function {
                            "function"
                        } else {
                            "procedure"
                        };
                        each(std::slice::from_ref(name), word, SymbolKind::FUNCTION);
                    }
                }
                _ => {}
            }
        }
        out
    }

    fn statements(&self, list: &[ConcStmt]) -> Vec<DocumentSymbol> {
        let mut out = Vec::new();
        for s in list {
            let (word, kind, children) = match &s.kind {
                ConcKind::Process { decls, .. } => {
                    ("process", SymbolKind::EVENT, self.decls(decls))
                }
                ConcKind::Block {
                    header,
                    decls,
                    stmts,
                    ..
                } => {
                    let mut c = self.interfaces(&header.generics, SymbolKind::CONSTANT);
                    c.extend(self.interfaces(&header.ports, SymbolKind::FIELD));
                    c.extend(self.decls(decls));
                    c.extend(self.statements(stmts));
                    ("block", SymbolKind::NAMESPACE, c)
                }
                ConcKind::ForGenerate { decls, stmts, .. }
                | ConcKind::IfGenerate { decls, stmts, .. } => {
                    let mut c = self.decls(decls);
                    c.extend(self.statements(stmts));
                    ("generate", SymbolKind::NAMESPACE, c)
                }
                ConcKind::Instance { .. } => ("instance", SymbolKind::OBJECT, Vec::new()),
                ConcKind::Simultaneous(SimKind::Procedural { decls, .. }) => {
                    ("procedural", SymbolKind::EVENT, self.decls(decls))
                }
                // Unlabelled simple statements would only clutter the outline.
                _ if s.label.is_none() => continue,
                _ => ("statement", SymbolKind::EVENT, Vec::new()),
            };
            let symbol = match &s.label {
                Some(label) => self.symbol(label, word, kind, s.span, children),
                None => {
                    let head = Span {
                        end: s.span.start.saturating_add(1).min(s.span.end),
                        ..s.span
                    };
                    self.named(word, head, "", kind, s.span, children)
                }
            };
            out.push(symbol);
        }
        out
    }
}

fn contains(outer: Range, inner: Range) -> bool {
    let le = |a: lsp_types::Position, b: lsp_types::Position| {
        (a.line, a.character) <= (b.line, b.character)
    };
    le(outer.start, inner.start) && le(inner.end, outer.end)
}
