//! Elaboration: parsed and analysed design files -> one flat [`Design`].
//!
//! **Takes** the parsed files of a compilation (user files in library `work`, the bundled
//! stdlib in `std` and `ieee`, as recorded in the [`SourceMap`]), their [`Analysis`], and the
//! name of the top entity with generic overrides. **Gives** a [`Design`] or every error found,
//! each an [`ElabError`] with the span it is about and a help line.
//!
//! The units come from the analysis's unit table (which architecture belongs to which entity,
//! which body to which package). Inside a unit, name lookup and lowering are still one walk:
//! starting at the top entity, each instance's declarations are resolved in a
//! [`scope::Scope`] and lowered at once (constants and generics fold to values, objects get
//! their ids), so no intermediate annotated tree exists. Packages are elaborated once, on
//! first `use`.
//!
//! May use `analysis`, `ast`, `source`, `design`, `diagnostics`. Never touches the solver or
//! the kernel.

use rustc_hash::{FxHashMap, FxHashSet};
use std::rc::Rc;

use vams_design::{Design, Expr, QuantityId, SignalId, Value};
use vams_semantics::analysis::{Analysis, analyse};
use vams_syntax::ast::{self, ContextItem, DesignFile, ExprKind};
use vams_syntax::source::{FileId, SourceMap, Span};

mod analog;
mod arrays;
mod attr;
mod candidates;
mod decls;
mod delay;
mod error;
mod expr;
mod fold;
mod follow;
mod generics;
mod hier;
mod inline;
mod intrinsic;
mod io;
mod lengths;
mod library;
mod ltf;
mod port_conversions;
mod process;
mod protected;
mod record_natures;
mod resolution;
mod sampled;
mod scope;
mod sensitivity;
mod signal_slices;
mod simultaneous;
mod slew;
mod subprogram;
mod synth;
#[cfg(test)]
mod tests;
mod types;
mod views;

pub use candidates::TopCandidate;
pub use error::{ElabError, ElabWarning};

use library::{Library, Unit, canonical_library};
use scope::{Item, PackageScope, Scope};
use types::Sub;

/// What to elaborate.
#[derive(Clone, Debug, Default)]
pub struct ElabOptions {
    /// The top entity (lower case); its architecture is the last one analysed for it.
    pub top: String,
    /// Generic overrides `(name, value text)`, from `-g NAME=VALUE`, `--params` and sweeps;
    /// the text is a VHDL literal (`4.0`, `1e-3`, `12`, `true`, `10 ms`). A plain name is a
    /// generic of the top; a dotted one names an instance's generic by its hierarchical
    /// path (`dut.u_motor.r`), winning over the instance's generic map and default.
    pub generics: Vec<(String, String)>,
}

/// Analyses `files` and elaborates `options.top` from them (analysis errors are not
/// reported here: [`vams_semantics::analysis::analyse`] and [`elaborate_analysed`] for that).
pub fn elaborate(
    sources: &SourceMap,
    files: &[(FileId, DesignFile)],
    options: &ElabOptions,
) -> Result<Design, Vec<ElabError>> {
    elaborate_analysed(&analyse(sources, files), sources, files, options)
}

/// Elaborates `options.top` from `files`, which `analysis` analysed.
pub fn elaborate_analysed(
    analysis: &Analysis,
    sources: &SourceMap,
    files: &[(FileId, DesignFile)],
    options: &ElabOptions,
) -> Result<Design, Vec<ElabError>> {
    let mut elab = Elab::new(analysis, sources, files);
    elab.top(options);
    elab.check_instance_overrides();
    elab.check_converted_actuals();
    if elab.errors.is_empty() {
        elab.resolve_signals();
        elab.contribution_equations();
    }
    elab.release_bodies();
    if elab.errors.is_empty() {
        let mut design = elab.design;
        design.shrink_to_fit();
        Ok(design)
    } else {
        Err(elab.errors)
    }
}

impl Elab<'_> {
    /// Drops the bodies of the subprograms (see `with_bodies`) and the designated types of
    /// late-completed access types (`completed_access`), ending the `Rc` cycles through them;
    /// nothing elaborates after this.
    fn release_bodies(&mut self) {
        for sub in self.with_bodies.drain(..) {
            sub.body.borrow_mut().take();
        }
        for access in self.completed_access.drain(..) {
            access.designated.borrow_mut().take();
        }
    }
}

/// Entities of library `work` that no architecture instantiates: the candidates for `--top`.
pub fn find_tops(analysis: &Analysis, files: &[(FileId, DesignFile)]) -> Vec<String> {
    Library::index(analysis, files).tops()
}

/// The candidates of [`find_tops`] with what keeps each from being elaborated alone.
pub fn top_candidates(analysis: &Analysis, files: &[(FileId, DesignFile)]) -> Vec<TopCandidate> {
    candidates::candidates(&Library::index(analysis, files))
}

/// The library and the context clauses as text (`work;l:ieee;u:ieee.math_real.all;`), or
/// `None` when a clause names something other than a dotted name.
fn context_key(library: &str, contexts: &[&[ContextItem]]) -> Option<String> {
    fn dotted(e: &vams_syntax::ast::Expr, out: &mut String) -> Option<()> {
        match &e.kind {
            ExprKind::Name(id) => out.push_str(&id.name),
            ExprKind::Selected(prefix, suffix) => {
                dotted(prefix, out)?;
                out.push('.');
                out.push_str(&suffix.name);
            }
            _ => return None,
        }
        Some(())
    }
    // Built once per instance: room for a typical clause, so that it is one allocation.
    let mut key = String::with_capacity(128);
    key.push_str(library);
    key.push(';');
    for item in contexts.iter().flat_map(|c| c.iter()) {
        match item {
            ContextItem::Library(names, _) => {
                for n in names {
                    key.push_str("l:");
                    key.push_str(&n.name);
                    key.push(';');
                }
            }
            ContextItem::Use(names, _) => {
                for n in names {
                    key.push_str("u:");
                    dotted(n, &mut key)?;
                    key.push(';');
                }
            }
        }
    }
    Some(key)
}

/// Marks a failure whose diagnostic is already in `Elab::errors`.
#[derive(Debug, Clone, Copy)]
struct Reported;

type R<T> = Result<T, Reported>;

/// A scalar nature of the elaborator's table; it enters the design on first use.
#[derive(Debug)]
struct NatureInfo {
    name: String,
    across: Rc<Sub>,
    through: Rc<Sub>,
    id: Option<vams_design::NatureId>,
    /// The nature a subnature with tolerance groups of its own belongs to: its terminals
    /// connect to the base nature's and share its reference terminal.
    base: Option<usize>,
}

/// The elaboration of one design.
struct Elab<'a> {
    /// Calls being lowered for static scalar arguments, innermost last (see
    /// `Elab::specialised`).
    specialising: usize,
    sources: &'a SourceMap,
    lib: Library<'a>,
    design: Design,
    errors: Vec<ElabError>,
    /// Protected types by the span of their name: the methods' declarations and, once seen,
    /// the body's declarations.
    protected: FxHashMap<Span, (&'a [ast::Decl], Option<&'a [ast::Decl]>)>,
    /// Incomplete type declarations (`type node;`) not completed yet: the name, the span of
    /// its identifier, and the access types declared since that designate it.
    incomplete: Vec<(String, Span, Vec<Rc<types::AccessTy>>)>,
    /// Packages elaborated so far, by unit index.
    packages: FxHashMap<usize, Rc<PackageScope<'a>>>,
    /// Every subprogram given a body: the body's scope holds the region that declares the
    /// subprogram (recursion sees itself), an `Rc` cycle that [`Elab::release_bodies`] breaks
    /// once elaboration is done (else each elaborated design leaked its scopes).
    with_bodies: Vec<Rc<scope::Subprogram<'a>>>,
    /// Access types to an incomplete type completed later (`type node; type link is access
    /// node; type node is record next : link; ... end record;`): the record holds the access
    /// type, which holds the record, a cycle `release_bodies` breaks too.
    completed_access: Vec<Rc<types::AccessTy>>,
    packages_in_progress: FxHashSet<usize>,
    /// The unit whose text is being elaborated: which of several namesake units a name
    /// in it denotes ([`Library::package`]).
    unit_at: usize,
    natures: Vec<NatureInfo>,
    /// Implicit `Q'above(level)` signals, one per distinct pair.
    above: Vec<(QuantityId, Expr, SignalId)>,
    /// Views of signal elements and slices ([`SignalKind::View`]), one per distinct
    /// `(parent, first, len)`.
    views: FxHashMap<(SignalId, usize, Option<usize>), SignalId>,
    /// The defaults of `out` and `inout` ports associated with an actual signal, with the
    /// instance path they apply in: the initial driving value of the processes under it
    /// that drive the signal. Only the entries of the instances enclosing the current one
    /// are kept.
    port_defaults: Vec<(String, SignalId, Value)>,
    /// The user-defined resolution functions that subtypes name (`Sub::resolution` indexes
    /// this), and the signals of such subtypes with their function: each gets an instance
    /// of it per number of driving values once all processes are known
    /// (`Elab::resolve_signals`).
    resolvers: Vec<Rc<scope::Subprogram<'a>>>,
    resolved_signals: Vec<(SignalId, usize)>,
    /// The actuals converted from `out` ports (`to_bool(y) => yb`), checked for other
    /// drivers once every process is known.
    converted_actuals: Vec<(SignalId, Span)>,
    /// While a simultaneous procedural is lowered: the variable standing for each `q'dot`
    /// it assigns (`x(1)'dot := ...`); empty elsewhere.
    dot_targets: FxHashMap<vams_design::QuantityId, vams_design::VarId>,
    /// The implicit signals of `s'delayed(t)`, by signal and delay (its bits).
    delayed_signals: FxHashMap<(SignalId, u64), SignalId>,
    /// `S'transaction` signals by `S`.
    transaction_signals: FxHashMap<SignalId, SignalId>,
    /// `S'stable(T)` and `S'quiet(T)` signals by `S`, `T` (its bits) and whether quiet.
    stable_signals: FxHashMap<(SignalId, u64, bool), SignalId>,
    /// Disconnection delays of guarded signals in seconds (`disconnect s : t after 3 ns;`).
    disconnect_delays: FxHashMap<SignalId, f64>,
    /// The `GUARD` signals of the guarded blocks being elaborated, innermost last: the guard
    /// of a guarded assignment.
    guards: Vec<SignalId>,
    /// Auxiliary quantities of `Q'dot'dot` and `Q'integ`, by the quantity they derive from.
    dot_aux: FxHashMap<QuantityId, QuantityId>,
    /// True while a spectral source's magnitude and phase are lowered: only there may
    /// `frequency` be called (LRM 1076.1 14.2).
    in_spectrum: bool,
    /// `T'reference` quantities, one per terminal (no region), and `T'contribution` ones, one
    /// per terminal and instance path.
    terminal_attrs: FxHashMap<(vams_design::TerminalId, Option<String>), QuantityId>,
    /// Each `T'contribution` with its terminal and the instance path it was read in: its
    /// equation sums the through quantities at `T` declared there and below, once every
    /// branch is known (`Elab::contribution_equations`).
    contributions: Vec<(QuantityId, vams_design::TerminalId, String, Span)>,
    integ_aux: FxHashMap<QuantityId, QuantityId>,
    /// Overrides of instance generics by hierarchical name (`dut.u_motor.r`, from `-g` and
    /// sweeps), each with whether an instance took it: one left untaken is an error.
    instance_overrides: Vec<(String, String, bool)>,
    /// The hierarchical names of every instance generic met, for the help of an override
    /// that names none.
    instance_generics: Vec<String>,
    /// Hierarchical prefix of the objects being declared (`""` at the top, `dut.u_motor`).
    path: String,
    /// Instance path of the architecture being elaborated (no block or generate labels).
    instance: String,
    /// The label of the process being elaborated, for `'path_name` (`None` outside a
    /// process, and in an unlabelled one).
    process_label: Option<String>,
    /// `entity(architecture)` of each design entity elaborated, by its instance path (`""`
    /// for the top), for `'instance_name`.
    instance_units: FxHashMap<String, String>,
    /// Unlabelled processes so far, per path (for `_pN` names): the current path and the
    /// paths enclosing it, outermost first.
    unlabelled: Vec<(String, usize)>,
    /// While elaborating a stdlib package: its subprograms that have no body (native ones).
    native_names: Option<FxHashSet<String>>,
    /// Errors in stdlib declarations poison the names instead of being reported.
    quiet: bool,
    /// Use regions already built, by [`context_key`].
    use_regions: FxHashMap<String, scope::Region<'a>>,
    /// The declaration analysis resolved each name to: the span of the name as used -> the
    /// span of the declaration's identifier (for a call, the overload it chose). Elaboration
    /// finds what a name denotes by the latter ([`Scope::declared`], `package_decls`).
    resolved: FxHashMap<Span, Span>,
    /// The items of every package elaborated so far, by the span of their declaration.
    package_decls: FxHashMap<Span, Item<'a>>,
    /// The multiplications and divisions analysis resolved to the mixed universal operators
    /// (`universal_integer * universal_real`, LRM 7.5.5): their integer operand is converted.
    mixed_universal: FxHashSet<Span>,
}

/// What elaboration takes from analysis's resolution of names, in one pass over the
/// references: every name resolved to one declaration (the name's span -> the declaration's;
/// operators left out, since an implicit operator carries its type's span and elaboration
/// lowers operators by their symbol), and the operations resolved to `"*"` or `"/"` of a
/// universal integer and a universal real operand.
fn resolutions(analysis: &Analysis) -> (FxHashMap<Span, Span>, FxHashSet<Span>) {
    use vams_semantics::analysis::DeclKind;
    use vams_semantics::analysis::types::{UNIVERSAL_INTEGER, UNIVERSAL_REAL};
    let count = analysis.units.iter().map(|u| u.references.len()).sum();
    let mut names = FxHashMap::with_capacity_and_hasher(count, Default::default());
    let mut mixed = FxHashSet::default();
    for &(span, d) in analysis.units.iter().flat_map(|u| &u.references) {
        let decl = analysis.decl(d);
        if span != decl.span {
            // Operators too: an application's span to the operator function it calls (a
            // predefined operator's "declaration" is its type's, where no function is).
            names.insert(span, decl.span);
        }
        if let DeclKind::Subprogram(sig) = &decl.kind
            && matches!(decl.name.as_str(), "\"*\"" | "\"/\"")
            && sig.params.iter().any(|p| p.ty == UNIVERSAL_INTEGER)
            && sig.params.iter().any(|p| p.ty == UNIVERSAL_REAL)
        {
            mixed.insert(span);
        }
    }
    (names, mixed)
}

impl<'a> Elab<'a> {
    fn new(
        analysis: &Analysis,
        sources: &'a SourceMap,
        files: &'a [(FileId, DesignFile)],
    ) -> Elab<'a> {
        let (resolved, mixed_universal) = resolutions(analysis);
        Elab {
            specialising: 0,
            sources,
            lib: Library::index(analysis, files),
            resolved,
            mixed_universal,
            package_decls: FxHashMap::default(),
            design: Design::default(),
            errors: Vec::new(),
            incomplete: Vec::new(),
            protected: FxHashMap::default(),
            packages: FxHashMap::default(),
            with_bodies: Vec::new(),
            completed_access: Vec::new(),
            packages_in_progress: FxHashSet::default(),
            unit_at: usize::MAX,
            natures: Vec::new(),
            above: Vec::new(),
            views: FxHashMap::default(),
            port_defaults: Vec::new(),
            instance_units: FxHashMap::default(),
            process_label: None,
            resolvers: Vec::new(),
            resolved_signals: Vec::new(),
            converted_actuals: Vec::new(),
            dot_targets: FxHashMap::default(),
            disconnect_delays: FxHashMap::default(),
            delayed_signals: FxHashMap::default(),
            transaction_signals: FxHashMap::default(),
            stable_signals: FxHashMap::default(),
            guards: Vec::new(),
            dot_aux: FxHashMap::default(),
            in_spectrum: false,
            terminal_attrs: FxHashMap::default(),
            contributions: Vec::new(),
            integ_aux: FxHashMap::default(),
            instance_overrides: Vec::new(),
            instance_generics: Vec::new(),
            path: String::new(),
            instance: String::new(),
            unlabelled: Vec::new(),
            native_names: None,
            quiet: false,
            use_regions: FxHashMap::default(),
        }
    }

    fn error(&mut self, e: ElabError) -> Reported {
        self.errors.push(e);
        Reported
    }

    /// What `f` computes, or `None` where it failed only because a value it needed is not
    /// static (its error withdrawn): for constructs that are legal with run-time values and
    /// that the caller handles another way (a slice target with run-time bounds).
    fn where_static<T>(&mut self, f: impl FnOnce(&mut Self) -> R<T>) -> R<Option<T>> {
        let before = self.errors.len();
        match f(self) {
            Ok(v) => Ok(Some(v)),
            Err(_) if matches!(self.errors.get(before), Some(ElabError::NotStatic { .. })) => {
                self.errors.truncate(before);
                Ok(None)
            }
            Err(e) => Err(e),
        }
    }

    /// `path.name`, or `name` at the top.
    fn hier_name(&self, name: &str) -> String {
        if self.path.is_empty() {
            name.to_string()
        } else {
            // Exact capacity: a design holds one such name per object, and `format!` would
            // leave up to half of each deep hierarchical name unused.
            let mut full = String::with_capacity(self.path.len() + 1 + name.len());
            full.push_str(&self.path);
            full.push('.');
            full.push_str(name);
            full
        }
    }

    /// The source text of a span with whitespace collapsed.
    fn text(&self, span: Span) -> String {
        // Written in place: one allocation per equation of every instance.
        let snippet = self.sources.snippet(span);
        let mut text = String::with_capacity(snippet.len());
        for word in snippet.split_whitespace() {
            if !text.is_empty() {
                text.push(' ');
            }
            text.push_str(word);
        }
        text
    }

    /// A type of std.standard by name, for the types the language itself gives a construct
    /// (a string literal is a `string`, a report's severity a `severity_level`): the
    /// standard's own, whatever a model declares with the same name.
    fn standard_type(&self, name: &str) -> Option<types::Ty> {
        let std = self.standard()?;
        match std.items.get(name)?.first()? {
            Item::Type(sub) => Some(sub.ty.clone()),
            _ => None,
        }
    }

    /// The elaborated std.standard.
    fn standard(&self) -> Option<&Rc<PackageScope<'a>>> {
        let key = ("std".to_string(), "standard".to_string());
        self.packages
            .get(&self.lib.package(&key, usize::MAX)?.index)
    }

    /// A unit of std.standard's `time` by name, in femtoseconds.
    fn standard_time_unit(&self, name: &str) -> Option<f64> {
        let std = self.standard()?;
        match std.items.get(name)?.first()? {
            Item::TimeUnit(f) => Some(*f),
            _ => None,
        }
    }

    /// A new scope with the implicit context (`library std, work; use std.standard.all`) and
    /// the unit's own context clause. The use region is built once per distinct clause text and
    /// library (every copy of a model says `use ieee.electrical_systems.all;`), unless building
    /// it reported an error, so that the error is reported wherever the clause is.
    fn unit_scope(&mut self, library: &str, contexts: &[&'a [ContextItem]]) -> Scope<'a> {
        let mut key = context_key(library, contexts);
        if self.lib.has_namesakes()
            && let Some(key) = &mut key
        {
            // Which namesake package a clause names depends on where the unit is.
            key.push_str(&self.unit_at.to_string());
        }
        if let Some(region) = key.as_ref().and_then(|k| self.use_regions.get(k)) {
            return Scope::with_use_region(region.clone());
        }
        let errors_before = self.errors.len();
        let mut sc = Scope::new();
        sc.import("std", Item::Library("std".into()));
        sc.import("work", Item::Library(library.to_string()));
        if let Ok(std) = self.package("std", "standard", None) {
            for (name, items) in &std.items {
                for item in items {
                    sc.import(name, item.clone());
                }
            }
        }
        for context in contexts {
            for item in context.iter() {
                match item {
                    ContextItem::Library(names, _) => {
                        for n in names {
                            sc.import(&n.name, Item::Library(canonical_library(&n.name).into()));
                        }
                    }
                    ContextItem::Use(names, _) => {
                        for n in names {
                            let _ = self.use_clause(&mut sc, n);
                        }
                    }
                }
            }
        }
        if let Some(key) = key
            && self.errors.len() == errors_before
        {
            self.use_regions.insert(key, sc.regions[0].clone());
        }
        sc
    }

    /// `use lib.pkg.all;`, `use lib.pkg.name;`, `use lib.pkg;`
    fn use_clause(&mut self, sc: &mut Scope<'a>, name: &vams_syntax::ast::Expr) -> R<()> {
        let ExprKind::Selected(prefix, suffix) = &name.kind else {
            return Err(self.error(ElabError::invalid(
                name.span,
                "a use clause names `library.package.all` or `library.package.item`",
                None,
            )));
        };
        if let ExprKind::Name(lib) = &prefix.kind {
            // `use lib.all;` makes the library's units visible by their names: analysis
            // resolved them, and elaboration builds a package when a name first reaches it.
            if suffix.name == "all" {
                return self.library_name(sc, lib).map(|_| ());
            }
            // `use lib.pkg;`
            let lib_name = self.library_name(sc, lib)?;
            let pkg = self.package(&lib_name, &suffix.name, Some(suffix.span))?;
            sc.import(&suffix.name, Item::Package(pkg));
            return Ok(());
        }
        let ExprKind::Selected(lib_expr, pkg_name) = &prefix.kind else {
            return Err(self.error(ElabError::invalid(
                prefix.span,
                "expected `library.package`",
                None,
            )));
        };
        let ExprKind::Name(lib) = &lib_expr.kind else {
            return Err(self.error(ElabError::invalid(
                lib_expr.span,
                "expected a library name",
                None,
            )));
        };
        let lib_name = self.library_name(sc, lib)?;
        let pkg = self.package(&lib_name, &pkg_name.name, Some(pkg_name.span))?;
        if suffix.name == "all" {
            for (n, items) in &pkg.items {
                for item in items {
                    sc.import(n, item.clone());
                }
            }
        } else if let Some(items) = pkg.items.get(&suffix.name) {
            for item in items {
                sc.import(&suffix.name, item.clone());
            }
        } else {
            let names: Vec<&String> = pkg.items.keys().collect();
            let best = names
                .iter()
                .map(|k| (strsim::levenshtein(&suffix.name, k), *k))
                .min()
                .filter(|(d, _)| *d <= 2);
            return Err(self.error(ElabError::Undeclared {
                span: suffix.span,
                name: format!("{}.{}", pkg_name.name, suffix.name),
                help: Some(match best {
                    Some((_, b)) => format!("did you mean `{b}`?"),
                    None => format!("package `{}` declares no such item", pkg_name.name),
                }),
            }));
        }
        Ok(())
    }

    fn library_name(&mut self, sc: &Scope<'a>, lib: &vams_syntax::ast::Ident) -> R<String> {
        match sc.lookup(&lib.name) {
            Some([Item::Library(l), ..]) => Ok(l.clone()),
            _ => Err(self.error(ElabError::Undeclared {
                span: lib.span,
                name: lib.name.clone(),
                help: Some(format!(
                    "declare the library first: `library {};` (std and work are always visible)",
                    lib.name
                )),
            })),
        }
    }

    /// The declarations of package `lib.name`, elaborated on first use.
    fn package(&mut self, lib: &str, name: &str, span: Option<Span>) -> R<Rc<PackageScope<'a>>> {
        let key = (canonical_library(lib).to_string(), name.to_string());
        let Some(unit) = self.lib.package(&key, self.unit_at).cloned() else {
            let err = ElabError::Undeclared {
                span: span.unwrap_or_default(),
                name: format!("{}.{}", key.0, key.1),
                help: Some(format!("library `{}` has no package `{}`", key.0, key.1)),
            };
            return Err(self.error(err));
        };
        self.package_unit(unit, span)
    }

    /// The declarations of the package `unit`, elaborated on first use.
    fn package_unit(
        &mut self,
        unit: Unit<'a, vams_syntax::ast::Package>,
        span: Option<Span>,
    ) -> R<Rc<PackageScope<'a>>> {
        if let Some(p) = self.packages.get(&unit.index) {
            return Ok(p.clone());
        }
        let key = (unit.library.clone(), unit.unit.name.name.clone());
        if !self.packages_in_progress.insert(unit.index) {
            let err = ElabError::invalid(
                span.unwrap_or(unit.unit.name.span),
                format!("package `{}` uses itself", key.1),
                Some("remove the circular use clause".into()),
            );
            return Err(self.error(err));
        }
        let stdlib = matches!(key.0.as_str(), "std" | "ieee" | "vams");
        let body = self.lib.bodies.get(&unit.index).cloned();
        let saved = (
            self.quiet,
            self.native_names.take(),
            std::mem::take(&mut self.path),
            std::mem::replace(&mut self.unit_at, unit.index),
        );
        self.quiet = stdlib;
        if stdlib {
            let with_body: FxHashSet<String> = body
                .iter()
                .flat_map(|b| b.unit.decls.iter())
                .filter_map(|d| match &d.kind {
                    vams_syntax::ast::DeclKind::SubprogramBody { spec, .. } => {
                        Some(decls::designator(spec))
                    }
                    _ => None,
                })
                .collect();
            let native: FxHashSet<String> = unit
                .unit
                .decls
                .iter()
                .filter_map(|d| match &d.kind {
                    vams_syntax::ast::DeclKind::Subprogram(spec) => Some(decls::designator(spec)),
                    _ => None,
                })
                .filter(|n| !with_body.contains(n))
                .collect();
            self.native_names = Some(native);
        }
        let mut sc = if key == ("std".to_string(), "standard".to_string()) {
            let mut sc = Scope::new();
            sc.import("std", Item::Library("std".into()));
            sc
        } else {
            self.unit_scope(&unit.library, &[unit.context])
        };
        sc.push();
        self.decls(&mut sc, &unit.unit.decls);
        self.native_names = None;
        if let Some(body) = body {
            // Deferred constants get their values from the body.
            let mut body_sc = sc.clone();
            for item in body.context {
                match item {
                    ContextItem::Library(names, _) => {
                        for n in names {
                            let lib = Item::Library(canonical_library(&n.name).into());
                            body_sc.import(&n.name, lib);
                        }
                    }
                    ContextItem::Use(names, _) => {
                        for n in names {
                            let _ = self.use_clause(&mut body_sc, n);
                        }
                    }
                }
            }
            body_sc.push();
            self.decls(&mut body_sc, &body.unit.decls);
            if let Some(region) = body_sc.regions.last() {
                for (n, items) in region.items.iter() {
                    let deferred =
                        sc.regions
                            .last()
                            .and_then(|r| r.items.get(n))
                            .is_some_and(|old| {
                                old.iter().any(
                                |i| matches!(i, Item::Poison(Some(r)) if r.starts_with("deferred")),
                            )
                            });
                    if deferred {
                        sc.replace(n, items.clone());
                    }
                }
            }
        }
        (self.quiet, self.native_names, self.path, self.unit_at) = saved;
        self.packages_in_progress.remove(&unit.index);
        let region = sc.regions.pop().unwrap_or_default();
        self.package_decls
            .extend(region.decls.iter().map(|(s, i)| (*s, i.clone())));
        let pkg = Rc::new(PackageScope {
            name: key.1.clone(),
            items: Rc::unwrap_or_clone(region.items),
        });
        self.packages.insert(unit.index, pkg.clone());
        Ok(pkg)
    }
}
