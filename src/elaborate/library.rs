//! The library index: every design unit of every file by (library, name), in analysis order.

use std::collections::BTreeSet;

use rustc_hash::FxHashMap;

use crate::ast::{
    Architecture, ConcKind, ConcStmt, ContextItem, DesignFile, Entity, ExprKind, InstantiatedUnit,
    LibraryUnit, Package, PackageBody,
};
use crate::source::{FileId, SourceMap};

/// Design units of one compilation. Library `ieee_proposed` is an alias of `ieee`.
#[derive(Default)]
pub struct Library<'a> {
    pub entities: FxHashMap<(String, String), Unit<'a, Entity>>,
    /// Architectures of each entity in analysis order (the last is the default).
    pub architectures: FxHashMap<(String, String), Vec<Unit<'a, Architecture>>>,
    pub packages: FxHashMap<(String, String), Unit<'a, Package>>,
    pub bodies: FxHashMap<(String, String), Unit<'a, PackageBody>>,
}

/// A unit with its context clause and library.
pub struct Unit<'a, T> {
    pub unit: &'a T,
    pub context: &'a [ContextItem],
    pub library: String,
}

impl<T> Clone for Unit<'_, T> {
    fn clone(&self) -> Self {
        Unit {
            unit: self.unit,
            context: self.context,
            library: self.library.clone(),
        }
    }
}

/// The library a name in a `library` clause or selected name stands for.
pub fn canonical_library(name: &str) -> &str {
    if name == "ieee_proposed" {
        "ieee"
    } else {
        name
    }
}

impl<'a> Library<'a> {
    pub fn index(sources: &SourceMap, files: &'a [(FileId, DesignFile)]) -> Library<'a> {
        let mut lib = Library::default();
        for (file, design) in files {
            let library = sources.file(*file).library.clone();
            for du in &design.units {
                let key = |name: &str| (library.clone(), name.to_string());
                match &du.unit {
                    LibraryUnit::Entity(e) => {
                        lib.entities.insert(
                            key(&e.name.name),
                            Unit {
                                unit: e,
                                context: &du.context,
                                library: library.clone(),
                            },
                        );
                    }
                    LibraryUnit::Architecture(a) => {
                        lib.architectures
                            .entry(key(&a.entity.name))
                            .or_default()
                            .push(Unit {
                                unit: a,
                                context: &du.context,
                                library: library.clone(),
                            });
                    }
                    LibraryUnit::Package(p) => {
                        lib.packages.insert(
                            key(&p.name.name),
                            Unit {
                                unit: p,
                                context: &du.context,
                                library: library.clone(),
                            },
                        );
                    }
                    LibraryUnit::PackageBody(b) => {
                        lib.bodies.insert(
                            key(&b.name.name),
                            Unit {
                                unit: b,
                                context: &du.context,
                                library: library.clone(),
                            },
                        );
                    }
                }
            }
        }
        lib
    }

    /// Entities of library `work`, sorted.
    pub fn work_entities(&self) -> Vec<String> {
        let names: BTreeSet<&String> = self
            .entities
            .keys()
            .filter(|(l, _)| l == "work")
            .map(|(_, n)| n)
            .collect();
        names.into_iter().cloned().collect()
    }

    /// Entities of `work` that no architecture of `work` instantiates, sorted.
    pub fn tops(&self) -> Vec<String> {
        let mut used = BTreeSet::new();
        for ((lib, _), archs) in &self.architectures {
            if lib != "work" {
                continue;
            }
            for arch in archs {
                collect_instantiated(&arch.unit.stmts, &mut used);
            }
        }
        self.work_entities()
            .into_iter()
            .filter(|e| !used.contains(e))
            .collect()
    }
}

/// Names of the entities (or components, bound by name) instantiated in `stmts`.
fn collect_instantiated(stmts: &[ConcStmt], out: &mut BTreeSet<String>) {
    for stmt in stmts {
        match &stmt.kind {
            ConcKind::Instance { unit, .. } => {
                let name = match unit {
                    InstantiatedUnit::Component(n) => n,
                    InstantiatedUnit::Entity { name, .. } => name,
                    InstantiatedUnit::Configuration(_) => continue,
                };
                let simple = match &name.kind {
                    ExprKind::Name(id) => Some(&id.name),
                    ExprKind::Selected(_, id) => Some(&id.name),
                    _ => None,
                };
                if let Some(s) = simple {
                    out.insert(s.clone());
                }
            }
            ConcKind::ForGenerate { stmts, .. }
            | ConcKind::IfGenerate { stmts, .. }
            | ConcKind::Block { stmts, .. } => collect_instantiated(stmts, out),
            _ => {}
        }
    }
}
