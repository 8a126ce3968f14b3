//! Analysis: parsed design files -> a library of analysed design units.
//!
//! **Takes** the parsed files of a compilation (user files in library `work`, the bundled
//! stdlib in `std` and `ieee`, as recorded in the [`SourceMap`]). **Gives** an [`Analysis`]:
//! every design unit of every file, analysed on its own whether or not a top reaches it, in
//! dependency order whatever the file order (`units` computes the order from context clauses,
//! secondary units and direct entity instantiations, and reports cycles). In each unit every
//! name is resolved to its declaration (`references`: the span of the use and the declaration
//! id), every expression has its type (`types`), and every diagnostic belongs to the unit it
//! is found in, so one bad unit does not hide errors in another.
//!
//! Types are base types ([`types::TypeId`]); an overloaded name (`"*"`, `now`, `'0'`) is
//! resolved from its operands and the type the context expects, with the universal literal
//! conversions as the only implicit ones. What analysis does not model yet gets the unknown
//! type, which matches everything: analysis reports an error only where it is certain, and
//! elaboration still checks what it folds.
//!
//! [`AnalysisHost`] keeps an analysis up to date as files are added, replaced and removed
//! (the base of editor support); it parses, so it also uses `parser` and `stdlib`.
//!
//! May use `ast`, `source`, `diagnostics` (and, for the host, `parser`, `stdlib`). Never
//! touches elaboration, the solver or the kernel.

use rustc_hash::FxHashMap;

use vams_syntax::ast::{DesignFile, DesignUnit, LibraryUnit};
use vams_syntax::source::{FileId, SourceMap, Span};

mod declare;
mod error;
mod expr;
mod host;
mod ids;
mod operators;
mod scope;
mod statics;
mod stmt;
#[cfg(test)]
mod tests;
pub mod types;
mod units;

pub use error::AnalysisError;
pub use host::AnalysisHost;
pub use scope::{
    DeclId, DeclKind, Declaration, Nature, NatureId, Param, Purity, Region, RegionId, Signature,
    Staticness,
};
pub use types::{TypeId, TypeInfo, TypeKind, TypeTable};

/// What kind of design unit.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum UnitKind {
    Entity,
    Architecture { entity: String },
    Package,
    PackageBody,
    Configuration { entity: String },
}

/// One analysed design unit.
#[derive(Clone, Debug)]
pub struct AnalysedUnit {
    pub library: String,
    /// The unit's own name (an architecture's, a package body's package name).
    pub name: String,
    pub kind: UnitKind,
    pub file: FileId,
    pub span: Span,
    /// For an architecture its entity, for a package body its package (indexes into
    /// `units`): the one declared before it when several share the name (a folder of
    /// variants), else the last.
    pub primary: Option<usize>,
    /// Units analysed before this one because it needs them (indexes into `units`).
    pub depends_on: Vec<usize>,
    pub errors: Vec<AnalysisError>,
    /// Each resolved name: where it is used and what it denotes.
    pub references: Vec<(Span, DeclId)>,
    /// The type of each analysed expression.
    pub types: Vec<(Span, TypeId)>,
    /// Each analysed expression that is locally or globally static (LRM 7.4).
    pub statics: Vec<(Span, Staticness)>,
    /// The declarations of the unit (for a package or entity, what it exports).
    pub region: RegionId,
    /// The declaration of an entity or package itself (what `use work.p;` makes visible).
    pub decl: Option<DeclId>,
    /// Part of its context is missing (a package not given, a dependency cycle): its
    /// undeclared names are not reported.
    pub incomplete: bool,
    /// The regions visible within each declarative part (the unit, a process, a
    /// subprogram, a loop, a block), innermost last.
    pub scopes: Vec<(Span, Vec<RegionId>)>,
}

/// The predefined attributes vams analyses and elaborates (LRM 16.1 and 1076.1's
/// `'dot`, `'integ`, `'above`, ...; user attributes are declared names), sorted: what an
/// editor offers after a tick.
pub const PREDEFINED_ATTRIBUTES: &[&str] = &[
    "above",
    "across",
    "active",
    "ascending",
    "base",
    "contribution",
    "delayed",
    "dot",
    "driving",
    "driving_value",
    "event",
    "high",
    "image",
    "instance_name",
    "integ",
    "last_active",
    "last_event",
    "last_value",
    "left",
    "leftof",
    "length",
    "low",
    "ltf",
    "path_name",
    "pos",
    "pred",
    "quiet",
    "ramp",
    "range",
    "reference",
    "reverse_range",
    "right",
    "rightof",
    "simple_name",
    "slew",
    "stable",
    "succ",
    "through",
    "tolerance",
    "transaction",
    "val",
    "value",
    "zoh",
    "ztf",
];

/// A library of analysed units with the declarations and types they share.
#[derive(Clone, Debug, Default)]
pub struct Analysis {
    /// In file order.
    pub units: Vec<AnalysedUnit>,
    /// Indexes into `units` in the order they were analysed.
    pub order: Vec<usize>,
    pub decls: Vec<Declaration>,
    pub types: TypeTable,
    pub natures: Vec<Nature>,
    pub regions: Vec<Region>,
    /// The sizes of the tables above before each unit of `order` was analysed: a unit adds
    /// only to their ends, so an edit keeps the tables up to the first unit it affects.
    pub marks: Vec<Marks>,
    /// How many units (the first of `order`) were taken over from a previous analysis.
    pub reused: usize,
}

/// Sizes of an analysis's shared tables at one point.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct Marks {
    pub decls: usize,
    pub types: usize,
    pub natures: usize,
    pub regions: usize,
}

impl Analysis {
    /// Every diagnostic, unit by unit in file order.
    pub fn errors(&self) -> impl Iterator<Item = &AnalysisError> {
        self.units.iter().flat_map(|u| u.errors.iter())
    }

    /// The units elaborating unit `start` can reach: what it depends on, the secondary units
    /// of each primary unit reached (an entity's architectures, a package's body), and so
    /// on; `start` included, in index order.
    pub fn reached_from(&self, start: usize) -> Vec<usize> {
        let mut secondaries: FxHashMap<usize, Vec<usize>> = FxHashMap::default();
        for (u, unit) in self.units.iter().enumerate() {
            if let Some(p) = unit.primary {
                secondaries.entry(p).or_default().push(u);
            }
        }
        let mut seen = vec![false; self.units.len()];
        let mut stack = vec![start];
        while let Some(u) = stack.pop() {
            if u >= seen.len() || seen[u] {
                continue;
            }
            seen[u] = true;
            stack.extend(&self.units[u].depends_on);
            stack.extend(secondaries.get(&u).into_iter().flatten());
        }
        (0..seen.len()).filter(|&u| seen[u]).collect()
    }

    pub fn decl(&self, id: DeclId) -> &Declaration {
        &self.decls[id.0 as usize]
    }

    /// The declaration the name at byte `offset` of `file` denotes (the innermost name).
    pub fn declaration_at(&self, file: FileId, offset: u32) -> Option<DeclId> {
        innermost(
            self.units
                .iter()
                .filter(|u| u.file == file)
                .flat_map(|u| u.references.iter()),
            offset,
        )
    }

    /// The declaration whose own name is at byte `offset` of `file` (the name written in a
    /// declaration, where `declaration_at` finds no use), for an editor's cursor on it.
    pub fn declared_at(&self, file: FileId, offset: u32) -> Option<DeclId> {
        let named = |d: &Declaration| {
            d.span.file == file
                && d.span.start <= offset
                && offset < d.span.end.max(d.span.start + 1)
                && d.span.len() == d.name.len()
        };
        let i = self.decls.iter().position(named)?;
        Some(DeclId(i as u32))
    }

    /// Every use of declaration `d`, in file order of the units (its declaration included).
    pub fn references_to(&self, d: DeclId) -> Vec<Span> {
        self.units
            .iter()
            .flat_map(|u| u.references.iter())
            .filter(|(_, r)| *r == d)
            .map(|(s, _)| *s)
            .collect()
    }

    /// The names visible at byte `offset` of `file` (for completion), sorted: those of the
    /// innermost declarative part there and of every region around it, operators and
    /// character literals left out.
    pub fn names_at(&self, file: FileId, offset: u32) -> Vec<String> {
        let scope = self
            .units
            .iter()
            .filter(|u| u.file == file)
            .flat_map(|u| u.scopes.iter())
            .filter(|(s, _)| s.start <= offset && offset <= s.end)
            .min_by_key(|(s, _)| s.end - s.start);
        let Some((_, regions)) = scope else {
            return Vec::new();
        };
        let mut names: Vec<String> = regions
            .iter()
            .flat_map(|r| self.regions[r.0 as usize].names.keys())
            .filter(|n| !n.starts_with('"') && !n.starts_with('\'') && !n.is_empty())
            .cloned()
            .collect();
        names.sort();
        names.dedup();
        names
    }

    /// How static the innermost analysed expression at byte `offset` of `file` is
    /// ([`Staticness::None`] when it is not static or nothing is there).
    pub fn staticness_at(&self, file: FileId, offset: u32) -> Staticness {
        let units = || self.units.iter().filter(|u| u.file == file);
        // The innermost expression (every analysed one has a type), then its mark: `statics`
        // holds only the static ones.
        let Some(&(span, _)) = innermost_entry(units().flat_map(|u| u.types.iter()), offset) else {
            return Staticness::None;
        };
        units()
            .flat_map(|u| u.statics.iter())
            .find(|(s, _)| *s == span)
            .map_or(Staticness::None, |&(_, st)| st)
    }

    /// The type of the innermost expression at byte `offset` of `file`.
    pub fn type_at(&self, file: FileId, offset: u32) -> Option<TypeId> {
        innermost(
            self.units
                .iter()
                .filter(|u| u.file == file)
                .flat_map(|u| u.types.iter()),
            offset,
        )
    }
}

/// The value of the shortest span that contains `offset`.
fn innermost<'a, T: Copy + 'a>(
    spans: impl Iterator<Item = &'a (Span, T)>,
    offset: u32,
) -> Option<T> {
    innermost_entry(spans, offset).map(|(_, v)| *v)
}

/// The entry of the shortest span that contains `offset`.
fn innermost_entry<'a, T: 'a>(
    spans: impl Iterator<Item = &'a (Span, T)>,
    offset: u32,
) -> Option<&'a (Span, T)> {
    spans
        .filter(|(s, _)| s.start <= offset && offset < s.end.max(s.start + 1))
        .min_by_key(|(s, _)| s.end - s.start)
}

/// Analyses every design unit of `files`.
pub fn analyse(sources: &SourceMap, files: &[(FileId, DesignFile)]) -> Analysis {
    analyse_from(sources, files, None)
}

/// Analyses `files` again after an edit, reusing `previous` (the analysis of the same files
/// before the texts of `changed` changed, or before those files were added or removed) up to
/// the first unit, in analysis order, that the edit can affect: a unit of a changed file, one
/// whose dependencies changed, or one that depended on something missing. Everything after
/// it is analysed again, so the result is exactly what [`analyse`] gives.
pub fn reanalyse(
    sources: &SourceMap,
    files: &[(FileId, DesignFile)],
    previous: Analysis,
    changed: &[FileId],
) -> Analysis {
    analyse_from(sources, files, Some((previous, changed)))
}

fn analyse_from(
    sources: &SourceMap,
    files: &[(FileId, DesignFile)],
    previous: Option<(Analysis, &[FileId])>,
) -> Analysis {
    let units = flatten(sources, files);
    let mut a = units::Analyzer::new(&units);
    let last = match &previous {
        Some((_, changed)) => *changed,
        None => &[],
    };
    let mut order = a.order(last);
    if !last.is_empty() && a.found_cycles() {
        // A walk that enters a cycle elsewhere closes it at another unit: report cycles
        // where analysis from scratch does.
        a = units::Analyzer::new(&units);
        order = a.order(&[]);
    }
    let kept = match previous {
        Some((prev, changed)) => a.adopt(prev, changed, &order),
        None => 0,
    };
    for &u in &order[kept..] {
        a.mark();
        a.unit(u);
    }
    let mut out = a.finish();
    out.order = order;
    out.reused = kept;
    out
}

/// Every design unit of `files` with its library and file, in file order.
fn flatten<'a>(
    sources: &SourceMap,
    files: &'a [(FileId, DesignFile)],
) -> Vec<(String, FileId, &'a DesignUnit)> {
    files
        .iter()
        .flat_map(|(file, design)| {
            let library = sources.file(*file).library.clone();
            design
                .units
                .iter()
                .map(move |u| (library.clone(), *file, u))
        })
        .collect()
}

/// The name a unit is known by.
fn unit_name(unit: &LibraryUnit) -> (&str, UnitKind) {
    match unit {
        LibraryUnit::Entity(e) => (&e.name.name, UnitKind::Entity),
        LibraryUnit::Architecture(a) => (
            &a.name.name,
            UnitKind::Architecture {
                entity: a.entity.name.clone(),
            },
        ),
        LibraryUnit::Package(p) => (&p.name.name, UnitKind::Package),
        LibraryUnit::PackageBody(b) => (&b.name.name, UnitKind::PackageBody),
        LibraryUnit::Configuration(c) => (
            &c.name.name,
            UnitKind::Configuration {
                entity: simple_name(&c.entity).to_string(),
            },
        ),
    }
}

/// The identifier a (selected) name ends in; empty for other expressions.
fn simple_name(e: &vams_syntax::ast::Expr) -> &str {
    e.name_ident().map_or("", |id| &id.name)
}

/// The library a name in a `library` clause or selected name stands for.
pub fn canonical_library(name: &str) -> &str {
    if name == "ieee_proposed" {
        "ieee"
    } else {
        name
    }
}

/// The units of each (library, name), in file order (a name may be declared in several files).
type UnitMap = FxHashMap<(String, String), Vec<usize>>;
