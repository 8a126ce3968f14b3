//! The library index: every design unit of every file by (library, name), built from the
//! analysis, whose unit table says which entity each architecture belongs to and which
//! package each body completes (the rule lives there only).

use std::collections::BTreeSet;

use rustc_hash::FxHashMap;

use crate::analysis::Analysis;
use crate::ast::{
    Architecture, ConcKind, ConcStmt, Configuration, ContextItem, DesignFile, Entity,
    InstantiatedUnit, LibraryUnit, Package, PackageBody,
};
use crate::source::FileId;

/// Design units of one compilation. Library `ieee_proposed` is an alias of `ieee`.
#[derive(Default)]
pub struct Library<'a> {
    /// The last entity of each name.
    pub entities: FxHashMap<(String, String), Unit<'a, Entity>>,
    /// Architectures of each entity (by its unit index) in file order (the last is the
    /// default).
    pub architectures: FxHashMap<usize, Vec<Unit<'a, Architecture>>>,
    /// The last package of each name.
    pub packages: FxHashMap<(String, String), Unit<'a, Package>>,
    /// The body of each package (by its unit index; the last when several complete it).
    pub bodies: FxHashMap<usize, Unit<'a, PackageBody>>,
    /// Configuration declarations by (library, name).
    pub configurations: FxHashMap<(String, String), Unit<'a, Configuration>>,
    /// Architectures of an entity that is not in the compilation (they still instantiate).
    pub orphans: Vec<Unit<'a, Architecture>>,
}

/// A unit with its context clause, library and index in the analysis's unit table.
pub struct Unit<'a, T> {
    pub unit: &'a T,
    pub context: &'a [ContextItem],
    pub library: String,
    pub index: usize,
}

impl<'a, T> Unit<'a, T> {
    fn new(unit: &'a T, context: &'a [ContextItem], library: &str, index: usize) -> Self {
        Unit {
            unit,
            context,
            library: library.to_string(),
            index,
        }
    }
}

impl<T> Clone for Unit<'_, T> {
    fn clone(&self) -> Self {
        Unit {
            unit: self.unit,
            context: self.context,
            library: self.library.clone(),
            index: self.index,
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
    /// The units of `files`, which `analysis` analysed (its units are theirs, in file order).
    pub fn index(analysis: &Analysis, files: &'a [(FileId, DesignFile)]) -> Library<'a> {
        let mut lib = Library::default();
        let units = files.iter().flat_map(|(_, design)| design.units.iter());
        for (index, (du, au)) in units.zip(&analysis.units).enumerate() {
            let library = &au.library;
            let key = |name: &str| (library.clone(), name.to_string());
            let context = du.context.as_slice();
            match &du.unit {
                LibraryUnit::Entity(e) => {
                    let unit = Unit::new(e, context, library, index);
                    lib.entities.insert(key(&e.name.name), unit);
                }
                LibraryUnit::Architecture(a) => {
                    let unit = Unit::new(a, context, library, index);
                    match au.primary {
                        Some(entity) => lib.architectures.entry(entity).or_default().push(unit),
                        None => lib.orphans.push(unit),
                    }
                }
                LibraryUnit::Package(p) => {
                    let unit = Unit::new(p, context, library, index);
                    lib.packages.insert(key(&p.name.name), unit);
                }
                LibraryUnit::Configuration(c) => {
                    let unit = Unit::new(c, context, library, index);
                    lib.configurations.insert(key(&c.name.name), unit);
                }
                LibraryUnit::PackageBody(b) => {
                    let Some(package) = au.primary else { continue };
                    lib.bodies
                        .insert(package, Unit::new(b, context, library, index));
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
        for archs in self.architectures.values().chain([&self.orphans]) {
            for arch in archs.iter().filter(|a| a.library == "work") {
                collect_instantiated(&arch.unit.stmts, &mut used);
                collect_bound(&arch.unit.decls, &mut used);
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
                if let Some(id) = name.name_ident() {
                    out.insert(id.name.clone());
                }
            }
            ConcKind::ForGenerate { stmts, .. }
            | ConcKind::IfGenerate { stmts, .. }
            | ConcKind::Block { stmts, .. } => collect_instantiated(stmts, out),
            _ => {}
        }
    }
}

/// Names of the entities that configuration specifications among `decls` bind components to.
fn collect_bound(decls: &[crate::ast::Decl], out: &mut BTreeSet<String>) {
    for d in decls {
        if let crate::ast::DeclKind::Configuration { binding, .. } = &d.kind
            && let Some(InstantiatedUnit::Entity { name, .. }) = &binding.unit
            && let Some(id) = name.name_ident()
        {
            out.insert(id.name.clone());
        }
    }
}
