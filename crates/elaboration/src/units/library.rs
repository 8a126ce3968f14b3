//! The library index: every design unit of every file by (library, name), built from the
//! analysis, whose unit table says which entity each architecture belongs to and which
//! package each body completes (the rule lives there only).

use std::collections::BTreeSet;

use rustc_hash::FxHashMap;

use vams_semantics::analysis::Analysis;
use vams_syntax::ast::{
    Architecture, ConcKind, ConcStmt, Configuration, ContextItem, DesignFile, Entity,
    InstantiatedUnit, LibraryUnit, Package, PackageBody,
};
use vams_syntax::source::FileId;

/// Design units of one compilation. Library `ieee_proposed` is an alias of `ieee`.
#[derive(Default)]
pub struct Library<'a> {
    /// The entities of each name, in file order (a folder of testbenches may declare one
    /// in several files).
    pub entities: FxHashMap<(String, String), Vec<Unit<'a, Entity>>>,
    /// Architectures of each entity (by its unit index) in file order (the last is the
    /// default).
    pub architectures: FxHashMap<usize, Vec<Unit<'a, Architecture>>>,
    /// The packages of each name, in file order.
    pub packages: FxHashMap<(String, String), Vec<Unit<'a, Package>>>,
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
                    lib.entities
                        .entry(key(&e.name.name))
                        .or_default()
                        .push(unit);
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
                    lib.packages
                        .entry(key(&p.name.name))
                        .or_default()
                        .push(unit);
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

    /// The entity `key` that unit `before` sees (see [`seen_from`]).
    pub fn entity(&self, key: &(String, String), before: usize) -> Option<&Unit<'a, Entity>> {
        seen_from(self.entities.get(key)?, before)
    }

    /// The entity `key` for an instance in unit `before` that names architecture `arch`: the
    /// one it sees, unless only another namesake has that architecture (a folder where two
    /// files declare `reg`, and the instance names the architecture of the second).
    pub fn entity_with(
        &self,
        key: &(String, String),
        before: usize,
        arch: Option<&str>,
    ) -> Option<&Unit<'a, Entity>> {
        let seen = self.entity(key, before)?;
        let has = |e: &Unit<'a, Entity>| {
            arch.is_none_or(|a| {
                self.architectures
                    .get(&e.index)
                    .is_some_and(|archs| archs.iter().any(|x| x.unit.name.name == a))
            })
        };
        if has(seen) {
            return Some(seen);
        }
        let all = self.entities.get(key)?;
        let before_first = all.iter().rev().filter(|u| u.index < before);
        let after = all.iter().rev().filter(|u| u.index >= before);
        Some(before_first.chain(after).find(|e| has(e)).unwrap_or(seen))
    }

    /// The package `key` that unit `before` sees (see [`seen_from`]).
    pub fn package(&self, key: &(String, String), before: usize) -> Option<&Unit<'a, Package>> {
        seen_from(self.packages.get(key)?, before)
    }

    /// True when some entity or package name is declared by several units, so that which
    /// one a unit sees depends on where the unit is.
    pub fn has_namesakes(&self) -> bool {
        self.entities.values().any(|v| v.len() > 1) || self.packages.values().any(|v| v.len() > 1)
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

/// Of the namesake primary units `all` (in file order), the one unit `before` sees: the last
/// declared before it, else the last of all. This is analysis's rule (a folder analysed file
/// by file in order), so that elaboration builds the unit analysis resolved names into.
fn seen_from<'u, 'a, T>(all: &'u [Unit<'a, T>], before: usize) -> Option<&'u Unit<'a, T>> {
    all.iter().rev().find(|u| u.index < before).or(all.last())
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
fn collect_bound(decls: &[vams_syntax::ast::Decl], out: &mut BTreeSet<String>) {
    for d in decls {
        if let vams_syntax::ast::DeclKind::Configuration { binding, .. } = &d.kind
            && let Some(InstantiatedUnit::Entity { name, .. }) = &binding.unit
            && let Some(id) = name.name_ident()
        {
            out.insert(id.name.clone());
        }
    }
}
