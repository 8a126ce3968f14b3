//! The analyzer's state, the order of analysis and the context of each unit: libraries,
//! `use` clauses, and the regions a secondary unit sees of its primary unit.

use rustc_hash::FxHashMap;

use vams_syntax::ast::{
    Binding, ConcKind, ConcStmt, ContextItem, Decl as AstDeclItem, DeclKind as AstDecl, DesignUnit,
    Expr, ExprKind, Ident, InstantiatedUnit, LibraryUnit,
};
use vams_syntax::source::{FileId, Span};

use super::error::AnalysisError;
use super::scope::{DeclId, DeclKind, Declaration, Nature, Region, RegionId, Staticness};
use super::types::{TypeId, TypeTable, UNKNOWN};
use super::{AnalysedUnit, Analysis, Marks, UnitKind, UnitMap, canonical_library, unit_name};

/// The types of `std.standard` that the language itself refers to (conditions are boolean,
/// `'image` is a string); unknown until `std.standard` is analysed.
#[derive(Clone, Copy, Debug)]
pub(super) struct Standard {
    pub boolean: TypeId,
    pub bit: TypeId,
    pub integer: TypeId,
    pub real: TypeId,
    pub time: TypeId,
    pub string: TypeId,
    pub severity: TypeId,
}

impl Default for Standard {
    fn default() -> Self {
        Standard {
            boolean: UNKNOWN,
            bit: UNKNOWN,
            integer: UNKNOWN,
            real: UNKNOWN,
            time: UNKNOWN,
            string: UNKNOWN,
            severity: UNKNOWN,
        }
    }
}

pub(super) struct Analyzer<'a> {
    pub src: &'a [(String, FileId, &'a DesignUnit)],
    pub out: Analysis,
    /// Entities and packages by (library, name).
    pub primaries: UnitMap,
    /// The region of each analysed primary unit and its declaration (`use work.p;`).
    pub unit_decl: FxHashMap<usize, DeclId>,
    /// The unit being analysed and the regions visible in it, innermost last.
    pub cur: usize,
    pub scope: Vec<RegionId>,
    /// The methods' region of the protected type whose body is being analysed.
    pub protected_methods: Option<RegionId>,
    /// Result type of each enclosing function (`None` in a procedure or process).
    pub returns: Vec<Option<TypeId>>,
    pub std: Standard,
    /// The decl every ambiguous use-visible name resolves to (an opaque one).
    ambiguous: DeclId,
    libraries: FxHashMap<String, DeclId>,
    state: Vec<Visit>,
    /// Units whose context is incomplete (a dependency lost to a cycle, a missing package or
    /// entity): their undeclared names are that loss's consequence, not errors of their own.
    cut: Vec<usize>,
    /// Set while a secondary unit re-applies its primary unit's context clause.
    muted: bool,
    /// Units analysed so far.
    analysed: Vec<bool>,
    /// The current unit's resolved names by the span of their use, and the staticness of
    /// its expressions analysed so far (see `statics`).
    pub ref_at: FxHashMap<Span, DeclId>,
    pub static_memo: FxHashMap<Span, Staticness>,
}

#[derive(Clone, Copy, PartialEq)]
enum Visit {
    New,
    Active,
    Done,
}

impl<'a> Analyzer<'a> {
    pub fn new(src: &'a [(String, FileId, &'a DesignUnit)]) -> Analyzer<'a> {
        let mut out = Analysis::default();
        let mut primaries = UnitMap::default();
        for (i, (library, file, du)) in src.iter().enumerate() {
            let (name, kind) = unit_name(&du.unit);
            let key = (library.clone(), name.to_string());
            if let UnitKind::Entity | UnitKind::Package = kind {
                primaries.entry(key).or_default().push(i);
            }
            out.units.push(AnalysedUnit {
                library: library.clone(),
                name: name.to_string(),
                kind,
                file: *file,
                span: du.span,
                primary: None,
                depends_on: Vec::new(),
                errors: Vec::new(),
                references: Vec::new(),
                types: Vec::new(),
                statics: Vec::new(),
                // Allocated when the unit is analysed.
                region: RegionId(u32::MAX),
                decl: None,
                incomplete: false,
                scopes: Vec::new(),
            });
        }
        for (u, (library, _, du)) in src.iter().enumerate() {
            let name = match &du.unit {
                LibraryUnit::Architecture(a) => &a.entity.name,
                LibraryUnit::PackageBody(b) => &b.name.name,
                LibraryUnit::Configuration(c) => match &out.units[u].kind {
                    UnitKind::Configuration { entity } => entity,
                    _ => &c.name.name,
                },
                _ => continue,
            };
            out.units[u].primary = primary_of(&primaries, library, name, u);
        }
        let ambiguous = DeclId(0);
        out.decls.push(Declaration {
            name: String::new(),
            span: Span::default(),
            kind: DeclKind::Opaque,
        });
        Analyzer {
            state: vec![Visit::New; src.len()],
            src,
            out,
            primaries,
            unit_decl: FxHashMap::default(),
            cur: 0,
            scope: Vec::new(),
            protected_methods: None,
            returns: Vec::new(),
            std: Standard::default(),
            ambiguous,
            libraries: FxHashMap::default(),
            cut: Vec::new(),
            muted: false,
            analysed: vec![false; src.len()],
            ref_at: FxHashMap::default(),
            static_memo: FxHashMap::default(),
        }
    }

    pub fn finish(self) -> Analysis {
        self.out
    }

    // -----------------------------------------------------------------------------------
    // Order

    /// Every unit once, each after the units it depends on; a dependency that closes a
    /// cycle is reported on the unit that names it and not followed. The units of `last`
    /// (files just edited) and every unit that depends on them, directly or not, come after
    /// all the others, so that a re-analysis after the next edit of those files keeps
    /// everything before them. Nothing else depends on the order: the units outside that set
    /// never reach into it, so each unit's dependencies and diagnostics are those of any
    /// other order (the depth-first walks of both parts follow file order, as from scratch).
    pub fn order(&mut self, last: &[FileId]) -> Vec<usize> {
        let mut order = Vec::with_capacity(self.src.len());
        let mut path = Vec::new();
        let deferred = self.dependents_of(last);
        // std.standard first: every unit depends on it implicitly.
        if let Some(s) = self.primary("std", "standard", usize::MAX) {
            self.visit(s, &mut path, &mut order);
        }
        for u in (0..self.src.len()).filter(|&u| !deferred[u]) {
            self.visit(u, &mut path, &mut order);
        }
        for u in (0..self.src.len()).filter(|&u| deferred[u]) {
            self.visit(u, &mut path, &mut order);
        }
        order
    }

    /// True when [`Analyzer::order`] found a dependency cycle.
    pub fn found_cycles(&self) -> bool {
        !self.cut.is_empty()
    }

    /// The units of `files` and every unit that depends on one of them, directly or not.
    fn dependents_of(&self, files: &[FileId]) -> Vec<bool> {
        let mut marked: Vec<bool> = self.src.iter().map(|(_, f, _)| files.contains(f)).collect();
        if !marked.contains(&true) {
            return marked;
        }
        let mut users: Vec<Vec<usize>> = vec![Vec::new(); self.src.len()];
        for u in 0..self.src.len() {
            for (d, _) in self.dependencies(u) {
                users[d].push(u);
            }
        }
        let mut stack: Vec<usize> = (0..marked.len()).filter(|&u| marked[u]).collect();
        while let Some(u) = stack.pop() {
            for &user in &users[u] {
                if !marked[user] {
                    marked[user] = true;
                    stack.push(user);
                }
            }
        }
        marked
    }

    fn visit(&mut self, u: usize, path: &mut Vec<usize>, order: &mut Vec<usize>) {
        if self.state[u] != Visit::New {
            return;
        }
        self.state[u] = Visit::Active;
        path.push(u);
        for (d, span) in self.dependencies(u) {
            match self.state[d] {
                Visit::Done => {}
                Visit::New => self.visit(d, path, order),
                Visit::Active => {
                    let from = path.iter().position(|&p| p == d).unwrap_or(0);
                    let mut names: Vec<String> =
                        path[from..].iter().map(|&p| self.describe(p)).collect();
                    names.push(self.describe(d));
                    self.cut.push(u);
                    self.out.units[u]
                        .errors
                        .push(AnalysisError::CircularDependency {
                            span,
                            cycle: names.join(" uses "),
                        });
                    continue;
                }
            }
            if !self.out.units[u].depends_on.contains(&d) {
                self.out.units[u].depends_on.push(d);
            }
        }
        path.pop();
        self.state[u] = Visit::Done;
        order.push(u);
    }

    fn describe(&self, u: usize) -> String {
        let unit = &self.out.units[u];
        match &unit.kind {
            UnitKind::Architecture { entity } => {
                format!("architecture `{}` of `{entity}`", unit.name)
            }
            UnitKind::PackageBody => format!("package body `{}`", unit.name),
            UnitKind::Entity => format!("entity `{}`", unit.name),
            UnitKind::Package => format!("package `{}`", unit.name),
            UnitKind::Configuration { .. } => format!("configuration `{}`", unit.name),
        }
    }

    /// The units `u` needs analysed first, with the span that names each.
    fn dependencies(&self, u: usize) -> Vec<(usize, Span)> {
        let (library, _, du) = &self.src[u];
        let mut deps = Vec::new();
        let mut contexts: Vec<&[ContextItem]> = vec![&du.context];
        match &du.unit {
            LibraryUnit::Architecture(a) => {
                if let Some(e) = self.primary(library, &a.entity.name, u) {
                    deps.push((e, a.entity.span));
                    contexts.push(&self.src[e].2.context);
                }
                entity_instances(&a.stmts, &mut |name| {
                    if let Some(d) = self.named_unit(library, name, u) {
                        deps.push(d);
                    }
                });
                for d in bound_entities(&a.decls).chain(nested_bound_entities(&a.stmts)) {
                    if let Some(d) = self.named_unit(library, d, u) {
                        deps.push(d);
                    }
                }
            }
            LibraryUnit::PackageBody(b) => {
                if let Some(p) = self.primary(library, &b.name.name, u) {
                    deps.push((p, b.name.span));
                    contexts.push(&self.src[p].2.context);
                }
            }
            LibraryUnit::Configuration(c) => {
                // The entity, its architecture the configuration names, and every entity a
                // component configuration binds.
                if let Some(e) = self.out.units[u].primary {
                    deps.push((e, c.entity.span));
                    let arch = super::simple_name(&c.block.spec);
                    deps.extend(
                        (0..self.src.len())
                            .filter(|&a| {
                                self.out.units[a].primary == Some(e)
                                    && matches!(
                                        self.out.units[a].kind,
                                        UnitKind::Architecture { .. }
                                    )
                                    && self.out.units[a].name == arch
                            })
                            .map(|a| (a, c.block.spec.span)),
                    );
                }
                for name in configured_entities(&c.block) {
                    if let Some(d) = self.named_unit(library, name, u) {
                        deps.push(d);
                    }
                }
            }
            _ => {}
        }
        let decls: &[AstDeclItem] = match &du.unit {
            LibraryUnit::Entity(e) => &e.decls,
            LibraryUnit::Architecture(a) => &a.decls,
            LibraryUnit::Package(p) => &p.decls,
            LibraryUnit::PackageBody(b) => &b.decls,
            LibraryUnit::Configuration(_) => &[],
        };
        let uses = contexts
            .iter()
            .flat_map(|c| c.iter())
            .flat_map(|item| match item {
                ContextItem::Use(names, _) => names.as_slice(),
                ContextItem::Library(..) => &[],
            })
            .chain(decls.iter().flat_map(|d| match &d.kind {
                AstDecl::Use(names) => names.as_slice(),
                _ => &[],
            }));
        for name in uses {
            if let Some(d) = self.named_unit(library, name, u) {
                deps.push(d);
            }
        }
        // Units named by selected names anywhere in the unit (`work.pkg.item` with no
        // `use` clause): `work`, and the libraries the context clauses name.
        let libraries: Vec<&str> = contexts
            .iter()
            .flat_map(|c| c.iter())
            .flat_map(|item| match item {
                ContextItem::Library(names, _) => names.as_slice(),
                ContextItem::Use(..) => &[],
            })
            .map(|id| canonical_library(&id.name))
            .chain(["std"])
            .collect();
        for (lib, unit) in &du.dotted {
            let lib = match canonical_library(&lib.name) {
                "work" => library.as_str(),
                other if libraries.contains(&other) => other,
                _ => continue,
            };
            if let Some(d) = self.primary(lib, &unit.name, u) {
                deps.push((d, unit.span));
            }
        }
        // Each unit once, by the first span that names it.
        let mut seen = Vec::with_capacity(deps.len());
        deps.retain(|&(d, _)| {
            let new = d != u && !seen.contains(&d);
            seen.push(d);
            new
        });
        deps
    }

    /// The primary unit `lib.unit[...]` names, if it is one of this compilation's.
    fn named_unit(&self, library: &str, name: &Expr, before: usize) -> Option<(usize, Span)> {
        let path = dotted(name)?;
        let [lib, unit, ..] = path.as_slice() else {
            return None;
        };
        let lib = match canonical_library(&lib.name) {
            "work" => library,
            other => other,
        };
        self.primary(lib, &unit.name, before)
            .map(|u| (u, unit.span))
    }

    // -----------------------------------------------------------------------------------
    // Units

    /// Analyses unit `u`: its context, then its declarations and statements.
    pub fn unit(&mut self, u: usize) {
        self.cur = u;
        self.ref_at.clear();
        self.static_memo.clear();
        let (library, _, du) = &self.src[u];
        let (library, du) = (library.as_str(), *du);
        // The use-visible names (std.standard, the libraries, what context clauses import).
        let uses = self.new_region();
        self.scope = vec![uses];
        self.returns.clear();
        for lib in ["std", "work"] {
            let d = self.library(lib);
            self.out.regions[uses.0 as usize].add(lib, d);
        }
        if (library, unit_name(&du.unit).0) != ("std", "standard") {
            if let Some(s) = self.primary("std", "standard", usize::MAX) {
                self.import_all(uses, self.out.units[s].region);
            }
        }
        let own = self.new_region();
        self.out.units[u].region = own;
        let primary = match &du.unit {
            LibraryUnit::Architecture(a) => self.primary(library, &a.entity.name, u),
            LibraryUnit::PackageBody(b) => self.primary(library, &b.name.name, u),
            LibraryUnit::Configuration(_) => self.out.units[u].primary,
            _ => None,
        };
        if let Some(p) = primary.filter(|&p| self.state_done(p)) {
            // Its problems are reported with the primary unit.
            self.muted = true;
            self.context(&self.src[p].2.context);
            self.muted = false;
        }
        self.context(&du.context);
        if let Some(p) = primary {
            let decl = self.unit_decl.get(&p).copied();
            if let Some(d) = decl {
                // The primary unit's own name, behind what the context clauses import: an
                // entity named `failure` does not hide std.standard's `failure`.
                let name = self.out.units[p].name.clone();
                self.out.regions[uses.0 as usize].add_behind(&name, d);
            }
            self.scope.push(self.out.units[p].region);
        }
        self.scope.push(own);
        self.record_scope(du.span);
        match &du.unit {
            LibraryUnit::Entity(e) => {
                // A unit's name belongs to its library, not to its own region: visible in
                // it, behind what the context clauses import.
                let d = self.declare_unit(u, &e.name, DeclKind::Entity(own));
                self.out.regions[uses.0 as usize].add_behind(&e.name.name, d);
                self.interfaces(&e.generics, super::scope::InterfaceRole::Generic);
                self.interfaces(&e.ports, super::scope::InterfaceRole::Port);
                self.decls(&e.decls);
                self.conc_stmts(&e.stmts);
            }
            LibraryUnit::Architecture(a) => {
                if primary.is_none() {
                    self.missing_unit(a.entity.span, "entity", &a.entity.name, library);
                    // Its ports and generics are unknown: names they would declare are not
                    // errors of their own.
                    self.cut.push(u);
                }
                // Its own name, for attribute specifications of the architecture (`attribute
                // cell_name of std_cell : architecture is ...`); any declaration of that name
                // inside wins.
                let d = self.push_decl(&a.name.name, a.name.span, DeclKind::Opaque);
                self.out.regions[own.0 as usize].add_behind(&a.name.name, d);
                self.decls(&a.decls);
                self.conc_stmts(&a.stmts);
            }
            LibraryUnit::Package(p) => {
                let d = self.declare_unit(u, &p.name, DeclKind::Package(own));
                self.out.regions[uses.0 as usize].add_behind(&p.name.name, d);
                let standard = (library, p.name.name.as_str()) == ("std", "standard");
                if standard {
                    self.universal_arithmetic();
                }
                self.decls(&p.decls);
                if standard {
                    self.standard_types(own);
                }
            }
            LibraryUnit::PackageBody(b) => {
                if primary.is_none() {
                    self.missing_unit(b.name.span, "package", &b.name.name, library);
                    self.cut.push(u);
                }
                self.decls(&b.decls);
            }
            LibraryUnit::Configuration(c) => {
                if primary.is_none() {
                    let name = super::simple_name(&c.entity).to_string();
                    self.missing_unit(c.entity.span, "entity", &name, library);
                    self.cut.push(u);
                }
                // The entities the components are bound to must exist, and the bindings'
                // maps are read where the architecture declares the components.
                match primary {
                    Some(e) => self.block_configuration(&c.block, e),
                    None => {
                        for name in configured_entities(&c.block) {
                            self.resolve_name(name);
                        }
                    }
                }
            }
        }
        self.analysed[u] = true;
        self.out.units[u].incomplete = self.cut.contains(&u);
    }

    /// The block configuration `block` of an architecture of entity unit `entity`: each
    /// component configuration's binding analysed in the architecture's scope (its
    /// components, signals and context), the nested block configurations of the entities
    /// bound likewise. An architecture not analysed is left alone (its absence is reported
    /// where the configuration is elaborated).
    fn block_configuration(&mut self, block: &vams_syntax::ast::BlockConfig, entity: usize) {
        let name = super::simple_name(&block.spec);
        let arch = (0..self.src.len()).find(|&a| {
            let unit = &self.out.units[a];
            unit.primary == Some(entity)
                && matches!(unit.kind, UnitKind::Architecture { .. })
                && unit.name == name
                && self.state_done(a)
        });
        let Some(arch) = arch else {
            for name in configured_entities(block) {
                self.resolve_name(name);
            }
            return;
        };
        let unit = &self.out.units[arch];
        let Some(scope) = unit
            .scopes
            .iter()
            .find(|(span, _)| *span == unit.span)
            .map(|(_, scope)| scope.clone())
        else {
            return;
        };
        // The architecture's names within the configuration's (whose context clause may
        // name the libraries of the entities bound).
        let mut inner = self.scope.clone();
        inner.extend(scope);
        let outer = std::mem::replace(&mut self.scope, inner);
        self.configuration_items(&block.items);
        self.scope = outer;
    }

    fn configuration_items(&mut self, items: &[vams_syntax::ast::ConfigItem]) {
        for item in items {
            match item {
                // A block or generate statement of the architecture; for some iterations of
                // a generate, the index or range selecting them is read in its scope.
                vams_syntax::ast::ConfigItem::Block(b) => {
                    if let vams_syntax::ast::ExprKind::Apply(_, args) = &b.spec.kind {
                        for a in args {
                            match &a.actual {
                                vams_syntax::ast::Actual::Range(r) => {
                                    self.range(r, UNKNOWN);
                                }
                                vams_syntax::ast::Actual::Expr(e) => {
                                    self.expr(e, UNKNOWN);
                                }
                                vams_syntax::ast::Actual::Open(_) => {}
                            }
                        }
                    }
                    self.configuration_items(&b.items)
                }
                vams_syntax::ast::ConfigItem::Component(c) => {
                    let component = match self.peek_name(&c.component).as_deref() {
                        Some([d]) => match self.out.decl(*d).kind {
                            DeclKind::Component(r) => {
                                self.reference(simple_span(&c.component), *d);
                                Some(r)
                            }
                            _ => None,
                        },
                        _ => None,
                    };
                    let bound = c
                        .binding
                        .as_ref()
                        .and_then(|b| self.binding_maps(b, component));
                    if let Some(block) = &c.block {
                        match bound {
                            Some(e) => self.block_configuration(block, e),
                            None => {
                                for name in configured_entities(block) {
                                    self.resolve_name(name);
                                }
                            }
                        }
                    }
                }
            }
        }
    }

    /// True when unit `u` has been analysed (its region and declarations exist).
    fn state_done(&self, u: usize) -> bool {
        self.analysed[u]
    }

    fn declare_unit(&mut self, u: usize, name: &Ident, kind: DeclKind) -> DeclId {
        let d = self.push_decl(&name.name, name.span, kind);
        self.unit_decl.insert(u, d);
        self.out.units[u].decl = Some(d);
        d
    }

    fn missing_unit(&mut self, span: Span, what: &'static str, name: &str, library: &str) {
        self.error(AnalysisError::MissingUnit {
            span,
            what,
            name: name.to_string(),
            library: library.to_string(),
            help: Some(format!("give vams the file that declares {what} `{name}`")),
        });
    }

    /// Records `std.standard`'s types that the language refers to and declares the
    /// universal operators that need them.
    fn standard_types(&mut self, region: RegionId) {
        self.std = self.find_standard(region);
        self.universal_relations(region);
    }

    fn find_standard(&self, region: RegionId) -> Standard {
        let find = |a: &Analyzer, name: &str| -> TypeId {
            a.out.regions[region.0 as usize]
                .names
                .get(name)
                .and_then(|ds| {
                    ds.iter().find_map(|&d| match a.out.decl(d).kind {
                        DeclKind::Type(t) => Some(t),
                        _ => None,
                    })
                })
                .unwrap_or(UNKNOWN)
        };
        Standard {
            boolean: find(self, "boolean"),
            bit: find(self, "bit"),
            integer: find(self, "integer"),
            real: find(self, "real"),
            time: find(self, "time"),
            string: find(self, "string"),
            severity: find(self, "severity_level"),
        }
    }

    // -----------------------------------------------------------------------------------
    // Reuse after an edit

    /// Records the tables' sizes before the next unit is analysed.
    pub fn mark(&mut self) {
        let out = &mut self.out;
        out.marks.push(Marks {
            decls: out.decls.len(),
            types: out.types.len(),
            natures: out.natures.len(),
            regions: out.regions.len(),
        });
    }

    /// Takes over from `prev` (the analysis before the files `changed` changed) the longest
    /// prefix of `order` that the edit leaves alone, and returns its length. A unit is kept
    /// when it is the same unit of an unchanged file (same place), its dependencies are the
    /// kept units its old dependencies were (with as many namesakes as before: an entity
    /// declared in a second file changes how instances of it are checked), and nothing it
    /// needed was missing (an added file may provide it).
    pub fn adopt(&mut self, mut prev: Analysis, changed: &[FileId], order: &[usize]) -> usize {
        let primary_key = |u: &AnalysedUnit| match u.kind {
            UnitKind::Entity | UnitKind::Package => Some((u.library.clone(), u.name.clone())),
            _ => None,
        };
        // How many entities or packages share each name, before and after the edit (counted
        // once, not per dependency).
        let namesakes = |units: &[AnalysedUnit]| {
            let mut counts: FxHashMap<(String, String), usize> = FxHashMap::default();
            for key in units.iter().filter_map(primary_key) {
                *counts.entry(key).or_default() += 1;
            }
            counts
        };
        let (now, before) = (namesakes(&self.out.units), namesakes(&prev.units));
        let count = |counts: &FxHashMap<(String, String), usize>, u: &AnalysedUnit| {
            primary_key(u).and_then(|key| counts.get(&key).copied())
        };
        let mut to_prev: FxHashMap<usize, usize> = FxHashMap::default();
        let mut k = 0;
        while k < order.len() && k < prev.order.len() {
            let (u, p) = (order[k], prev.order[k]);
            let (new, old) = (&self.out.units[u], &prev.units[p]);
            let same_unit = new.file == old.file
                && !changed.contains(&new.file)
                && new.span == old.span
                && new.library == old.library;
            let deps_same = new.depends_on.len() == old.depends_on.len()
                && new.depends_on.iter().zip(&old.depends_on).all(|(d, o)| {
                    to_prev.get(d) == Some(o)
                        && count(&now, &self.out.units[*d]) == count(&before, &prev.units[*o])
                });
            let complete = !old.incomplete
                && new.errors.is_empty()
                && !old.errors.iter().any(|e| {
                    matches!(
                        e,
                        AnalysisError::MissingUnit { .. }
                            | AnalysisError::CircularDependency { .. }
                    )
                });
            if !(same_unit && deps_same && complete) {
                break;
            }
            to_prev.insert(u, p);
            k += 1;
        }
        if k == 0 {
            return 0;
        }
        let m = prev.marks.get(k).copied().unwrap_or(Marks {
            decls: prev.decls.len(),
            types: prev.types.len(),
            natures: prev.natures.len(),
            regions: prev.regions.len(),
        });
        prev.decls.truncate(m.decls);
        prev.types.truncate(m.types);
        prev.natures.truncate(m.natures);
        prev.regions.truncate(m.regions);
        prev.marks.truncate(k);
        let out = &mut self.out;
        out.decls = std::mem::take(&mut prev.decls);
        out.types = std::mem::take(&mut prev.types);
        out.natures = std::mem::take(&mut prev.natures);
        out.regions = std::mem::take(&mut prev.regions);
        out.marks = std::mem::take(&mut prev.marks);
        for &u in &order[..k] {
            let old = &mut prev.units[to_prev[&u]];
            let unit = &mut self.out.units[u];
            unit.errors = std::mem::take(&mut old.errors);
            unit.references = std::mem::take(&mut old.references);
            unit.types = std::mem::take(&mut old.types);
            unit.statics = std::mem::take(&mut old.statics);
            unit.scopes = std::mem::take(&mut old.scopes);
            unit.region = old.region;
            unit.decl = old.decl;
            unit.incomplete = old.incomplete;
            if let Some(d) = old.decl {
                self.unit_decl.insert(u, d);
            }
            if old.incomplete {
                self.cut.push(u);
            }
            self.analysed[u] = true;
        }
        for (i, d) in self.out.decls.iter().enumerate() {
            if d.kind == DeclKind::Library {
                self.libraries.insert(d.name.clone(), DeclId(i as u32));
            }
        }
        if let Some(s) = self
            .primary("std", "standard", usize::MAX)
            .filter(|&s| self.analysed[s])
        {
            self.std = self.find_standard(self.out.units[s].region);
        }
        k
    }

    // -----------------------------------------------------------------------------------
    // Context clauses

    fn context(&mut self, items: &[ContextItem]) {
        for item in items {
            match item {
                ContextItem::Library(names, _) => {
                    for n in names {
                        let d = self.library(canonical_library(&n.name));
                        let uses = self.scope[0];
                        self.out.regions[uses.0 as usize].add(&n.name, d);
                    }
                }
                ContextItem::Use(names, _) => {
                    let uses = self.scope[0];
                    for n in names {
                        self.use_clause(uses, n);
                    }
                }
            }
        }
    }

    fn library(&mut self, name: &str) -> DeclId {
        if let Some(&d) = self.libraries.get(name) {
            return d;
        }
        let d = self.push_decl(name, Span::default(), DeclKind::Library);
        self.libraries.insert(name.to_string(), d);
        d
    }

    /// `use lib.pkg.all;`, `use lib.pkg.item;`, `use lib.pkg;` into `region`.
    pub fn use_clause(&mut self, region: RegionId, name: &Expr) {
        let Some(path) = dotted(name) else {
            return;
        };
        let (first, rest) = path.split_first().expect("a dotted name has a first part");
        // The prefix: a library (then a package of it), or a package made visible by an
        // earlier `use lib.pkg;`.
        let (package, rest) = match self.lookup(&first.name).as_deref() {
            Some([d]) if self.out.decl(*d).kind == DeclKind::Library => {
                let Some((unit, rest)) = rest.split_first() else {
                    return;
                };
                if unit.name == "all" {
                    // `use work.all;`: every primary unit of the library by its name (only
                    // selected names use them, and those resolve through the library).
                    self.reference(first.span, *d);
                    return;
                }
                let lib = match canonical_library(&first.name) {
                    "work" => self.out.units[self.cur].library.clone(),
                    other => other.to_string(),
                };
                self.reference(first.span, *d);
                let Some(p) = self.primary(&lib, &unit.name, self.cur) else {
                    self.missing_unit(unit.span, "package", &unit.name, &lib);
                    // What it would make visible is unknown: no cascade of undeclared names.
                    self.cut.push(self.cur);
                    return;
                };
                if !self.state_done(p) {
                    return; // A cycle, reported where the order was computed.
                }
                (p, rest)
            }
            Some([d]) => {
                let Some(unit) = self
                    .unit_decl
                    .iter()
                    .find_map(|(&u, &ud)| (ud == *d).then_some(u))
                else {
                    return;
                };
                (unit, rest)
            }
            Some(_) => return,
            None => {
                self.undeclared(first);
                return;
            }
        };
        let pkg_region = self.out.units[package].region;
        match rest {
            [] => {
                if let Some(&d) = self.unit_decl.get(&package) {
                    let n = self.out.units[package].name.clone();
                    self.out.regions[region.0 as usize].add(&n, d);
                }
            }
            [item] if item.name == "all" => self.import_all(region, pkg_region),
            [item] => {
                let found = self.out.regions[pkg_region.0 as usize]
                    .names
                    .get(&item.name)
                    .cloned();
                match found {
                    Some(ds) => {
                        for d in ds {
                            self.import(region, &item.name, d);
                        }
                    }
                    None => self.undeclared(item),
                }
            }
            _ => {}
        }
    }

    pub fn import_all(&mut self, into: RegionId, from: RegionId) {
        let names: Vec<(String, Vec<DeclId>)> = self.out.regions[from.0 as usize]
            .names
            .iter()
            .map(|(k, v)| (k.clone(), v.clone()))
            .collect();
        for (name, ds) in names {
            for d in ds {
                self.import(into, &name, d);
            }
        }
    }

    /// Makes `d` use-visible as `name` in `into`. Two different non-overloadable
    /// declarations of one name make it ambiguous (LRM 10.4: neither is visible).
    fn import(&mut self, into: RegionId, name: &str, d: DeclId) {
        let overloadable = self.out.decl(d).kind.overloadable();
        let ambiguous = self.ambiguous;
        let decls = &self.out.decls;
        let entry = self.out.regions[into.0 as usize]
            .names
            .entry(name.to_string())
            .or_default();
        if entry.contains(&d) {
            return;
        }
        let clash = entry
            .iter()
            .any(|&e| !overloadable || !decls[e.0 as usize].kind.overloadable());
        if clash {
            entry.clear();
            entry.push(ambiguous);
        } else {
            entry.push(d);
        }
    }

    // -----------------------------------------------------------------------------------
    // Scopes and records

    pub fn new_region(&mut self) -> RegionId {
        self.out.regions.push(Region::default());
        RegionId(self.out.regions.len() as u32 - 1)
    }

    pub fn push_decl(&mut self, name: &str, span: Span, kind: DeclKind) -> DeclId {
        self.out.decls.push(Declaration {
            name: name.to_string(),
            span,
            kind,
        });
        DeclId(self.out.decls.len() as u32 - 1)
    }

    /// Declares `name` in the innermost region.
    pub fn declare(&mut self, name: &str, span: Span, kind: DeclKind) -> DeclId {
        let d = self.push_decl(name, span, kind);
        let region = *self.scope.last().expect("a unit always has a region");
        self.out.regions[region.0 as usize].add(name, d);
        self.reference(span, d);
        d
    }

    /// The declarations `name` denotes here: the innermost non-overloadable one, or every
    /// overloadable one out to the first region that hides them.
    pub fn lookup(&self, name: &str) -> Option<Vec<DeclId>> {
        let mut found: Vec<DeclId> = Vec::new();
        for region in self.scope.iter().rev() {
            let Some(ds) = self.out.regions[region.0 as usize].names.get(name) else {
                continue;
            };
            if ds.is_empty() {
                continue;
            }
            let all_overloadable = ds.iter().all(|&d| self.out.decl(d).kind.overloadable());
            if !all_overloadable {
                if found.is_empty() {
                    // The last declaration of a name in a region wins (a completed
                    // deferred constant, a type completing its incomplete declaration).
                    found.push(*ds.last().expect("non-empty"));
                }
                break;
            }
            // A subprogram declared in an inner region hides its homographs outside it (LRM
            // 10.3): an architecture's `"<"` on bit_vector, not std.standard's.
            let inner = found.len();
            for &d in ds {
                if !found.contains(&d) && !self.hidden_by(d, &found[..inner]) {
                    found.push(d);
                }
            }
        }
        (!found.is_empty()).then_some(found)
    }

    /// True when `d` is a subprogram with the profile of one of `inner`'s.
    fn hidden_by(&self, d: DeclId, inner: &[DeclId]) -> bool {
        let DeclKind::Subprogram(sig) = &self.out.decl(d).kind else {
            return false;
        };
        inner.iter().any(|&i| {
            matches!(&self.out.decl(i).kind, DeclKind::Subprogram(s) if super::scope::same_profile(s, sig))
        })
    }

    /// The declarations of `name` in `region` only (a selected name `pkg.name`).
    pub fn lookup_in(&self, region: RegionId, name: &str) -> Option<Vec<DeclId>> {
        self.out.regions[region.0 as usize]
            .names
            .get(name)
            .filter(|ds| !ds.is_empty())
            .cloned()
    }

    /// The primary unit `unit` of the library declaration `lib`.
    pub fn library_unit(&self, lib: &str, unit: &str) -> Option<usize> {
        let lib = match canonical_library(lib) {
            "work" => self.out.units[self.cur].library.clone(),
            other => other.to_string(),
        };
        self.primary(&lib, unit, self.cur)
            .filter(|&u| self.state_done(u) || u == self.cur)
    }

    /// True when the unit declaration `d` (an entity's or package's) has namesakes in its
    /// library.
    /// The design unit whose own declaration (an entity's, a package's) `d` is.
    pub fn unit_declaring(&self, d: DeclId) -> Option<usize> {
        self.unit_decl
            .iter()
            .find(|&(_, &ud)| ud == d)
            .map(|(&u, _)| u)
    }

    pub fn declared_twice(&self, d: &DeclId) -> bool {
        self.unit_decl.iter().any(|(&u, ud)| {
            ud == d && {
                let unit = &self.out.units[u];
                self.primaries
                    .get(&(unit.library.clone(), unit.name.clone()))
                    .is_some_and(|all| all.len() > 1)
            }
        })
    }

    /// The entity or package `name` of `lib` that unit `before` sees: the last one declared
    /// before it in file order (a file's architecture belongs to the entity above it, as when
    /// files are analysed in order), else the last of all.
    pub fn primary(&self, lib: &str, name: &str, before: usize) -> Option<usize> {
        primary_of(&self.primaries, lib, name, before)
    }

    pub fn error(&mut self, e: AnalysisError) {
        if self.muted {
            return;
        }
        let errors = &mut self.out.units[self.cur].errors;
        if !errors.contains(&e) {
            errors.push(e);
        }
    }

    pub fn reference(&mut self, span: Span, d: DeclId) {
        self.ref_at.insert(span, d);
        self.out.units[self.cur].references.push((span, d));
    }

    /// Records that the regions now in scope are those visible within `span`.
    pub fn record_scope(&mut self, span: Span) {
        let scope = self.scope.clone();
        self.out.units[self.cur].scopes.push((span, scope));
    }

    pub fn record_type(&mut self, span: Span, t: TypeId) {
        self.out.units[self.cur].types.push((span, t));
    }

    /// True when the current unit lost a dependency to a cycle.
    pub fn cut_here(&self) -> bool {
        self.cut.contains(&self.cur)
    }

    pub fn undeclared(&mut self, id: &Ident) {
        if self.cut_here() {
            return;
        }
        let help = self
            .suggest(&id.name)
            .map(|s| format!("did you mean `{s}`?"));
        self.error(AnalysisError::Undeclared {
            span: id.span,
            name: id.name.clone(),
            help,
        });
    }

    /// The visible name closest to `name` by edit distance, if close enough to be a typo.
    fn suggest(&self, name: &str) -> Option<String> {
        let limit = (name.len() / 3).max(1);
        self.scope
            .iter()
            .flat_map(|r| self.out.regions[r.0 as usize].names.keys())
            .filter(|k| !k.starts_with('"') && !k.starts_with('\''))
            .map(|k| (strsim::levenshtein(name, k), k))
            .filter(|(d, _)| *d <= limit)
            .min()
            .map(|(_, k)| k.clone())
    }

    pub fn types(&self) -> &TypeTable {
        &self.out.types
    }

    pub fn nature(&self, n: super::scope::NatureId) -> &Nature {
        &self.out.natures[n.0 as usize]
    }
}

/// `a.b.c` as its parts.
pub fn dotted(e: &Expr) -> Option<Vec<&Ident>> {
    match &e.kind {
        ExprKind::Name(id) => Some(vec![id]),
        ExprKind::Selected(prefix, suffix) => {
            let mut p = dotted(prefix)?;
            p.push(suffix);
            Some(p)
        }
        _ => None,
    }
}

/// Calls `f` with the name of every directly instantiated entity (`entity work.e`).
fn entity_instances<'e>(stmts: &'e [ConcStmt], f: &mut impl FnMut(&'e Expr)) {
    for s in stmts {
        match &s.kind {
            ConcKind::Instance {
                unit: InstantiatedUnit::Entity { name, .. },
                ..
            } => f(name),
            ConcKind::ForGenerate { stmts, .. }
            | ConcKind::IfGenerate { stmts, .. }
            | ConcKind::Block { stmts, .. } => entity_instances(stmts, f),
            _ => {}
        }
    }
}

/// The entities the component configurations of `block` (and of the blocks nested in it) bind.
fn configured_entities(block: &vams_syntax::ast::BlockConfig) -> Vec<&Expr> {
    let mut out = Vec::new();
    for item in &block.items {
        match item {
            vams_syntax::ast::ConfigItem::Block(b) => out.extend(configured_entities(b)),
            vams_syntax::ast::ConfigItem::Component(c) => {
                if let Some(Binding {
                    unit: Some(InstantiatedUnit::Entity { name, .. }),
                    ..
                }) = &c.binding
                {
                    out.push(name);
                }
                if let Some(b) = &c.block {
                    out.extend(configured_entities(b));
                }
            }
        }
    }
    out
}

/// The entities that configuration specifications among `decls` bind components to.
fn bound_entities(decls: &[vams_syntax::ast::Decl]) -> impl Iterator<Item = &Expr> {
    decls.iter().filter_map(|d| match &d.kind {
        AstDecl::Configuration { binding, .. } => match &binding.unit {
            Some(InstantiatedUnit::Entity { name, .. }) => Some(name),
            _ => None,
        },
        _ => None,
    })
}

/// [`bound_entities`] of the declarative parts of blocks and generate statements.
fn nested_bound_entities(stmts: &[ConcStmt]) -> Vec<&Expr> {
    let mut out = Vec::new();
    for s in stmts {
        match &s.kind {
            ConcKind::ForGenerate { decls, stmts, .. }
            | ConcKind::IfGenerate { decls, stmts, .. }
            | ConcKind::Block { decls, stmts, .. } => {
                out.extend(bound_entities(decls));
                out.extend(nested_bound_entities(stmts));
            }
            _ => {}
        }
    }
    out
}

/// The primary unit `lib.name` declared last before unit `before`, else the last of them.
fn primary_of(primaries: &UnitMap, lib: &str, name: &str, before: usize) -> Option<usize> {
    let all = primaries.get(&(lib.to_string(), name.to_string()))?;
    all.iter()
        .rev()
        .find(|&&p| p < before)
        .or(all.last())
        .copied()
}

/// The span of the identifier a (selected) name ends in.
fn simple_span(e: &Expr) -> Span {
    match &e.kind {
        vams_syntax::ast::ExprKind::Name(id) | vams_syntax::ast::ExprKind::Selected(_, id) => {
            id.span
        }
        _ => e.span,
    }
}
