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

use vams_design::Design;
use vams_semantics::analysis::{Analysis, analyse};
use vams_syntax::ast::DesignFile;
use vams_syntax::source::{FileId, SourceMap, Span};

mod attributes;
mod declarations;
mod equations;
mod error;
mod expressions;
mod hierarchy;
mod names;
mod sequential;
mod tables;
#[cfg(test)]
mod tests;
mod units;

pub use error::{ElabError, ElabWarning};
pub use units::candidates::TopCandidate;

use names::scope::{Item, PackageScope};
use tables::{AnalogTables, InstanceContext, Pending, SignalTables};
use units::library::Library;
use units::packages::PackageCache;

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
        for sub in self.pending.with_bodies.drain(..) {
            sub.body.borrow_mut().take();
        }
        for access in self.pending.completed_access.drain(..) {
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
    units::candidates::candidates(&Library::index(analysis, files))
}

/// Marks a failure whose diagnostic is already in `Elab::errors`.
#[derive(Debug, Clone, Copy)]
struct Reported;

type R<T> = Result<T, Reported>;

/// The elaboration of one design: what it reads (the sources, the library of units, what
/// analysis resolved), what it builds (the design, its errors), and the tables each pass owns.
struct Elab<'a> {
    sources: &'a SourceMap,
    lib: Library<'a>,
    analysed: Resolutions,
    design: Design,
    errors: Vec<ElabError>,
    /// Packages elaborated so far and the use regions built from context clauses.
    packages: PackageCache<'a>,
    /// Declarations completed or released later: protected types, incomplete types and the
    /// `Rc` cycles of subprogram bodies.
    pending: Pending<'a>,
    /// Implicit signals, views, resolution and the driver checks that wait for every process.
    signals: SignalTables<'a>,
    /// Natures, auxiliary quantities and contributions.
    analog: AnalogTables,
    /// Where the walk is: the hierarchical path, the instance, the process.
    here: InstanceContext,
    /// The unit whose text is being elaborated: which of several namesake units a name
    /// in it denotes ([`Library::package`]).
    unit_at: usize,
    /// While elaborating a stdlib package: its subprograms that have no body (native ones).
    native_names: Option<FxHashSet<String>>,
    /// Errors in stdlib declarations poison the names instead of being reported.
    quiet: bool,
    /// Calls being lowered for static scalar arguments, innermost last (see
    /// `Elab::specialised`).
    specialising: usize,
}

/// What elaboration takes from analysis's resolution of names.
struct Resolutions {
    /// The declaration analysis resolved each name to: the span of the name as used -> the
    /// span of the declaration's identifier (for a call, the overload it chose). Elaboration
    /// finds what a name denotes by the latter ([`Scope::declared`], `PackageCache::decls`).
    names: FxHashMap<Span, Span>,
    /// The multiplications and divisions analysis resolved to the mixed universal operators
    /// (`universal_integer * universal_real`, LRM 7.5.5): their integer operand is converted.
    mixed_universal: FxHashSet<Span>,
}

/// [`Resolutions`] in one pass over the references: every name resolved to one declaration
/// (the name's span -> the declaration's; operators left out, since an implicit operator
/// carries its type's span and elaboration lowers operators by their symbol), and the
/// operations resolved to `"*"` or `"/"` of a universal integer and a universal real operand.
fn resolutions(analysis: &Analysis) -> Resolutions {
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
    Resolutions {
        names,
        mixed_universal: mixed,
    }
}

impl<'a> Elab<'a> {
    fn new(
        analysis: &Analysis,
        sources: &'a SourceMap,
        files: &'a [(FileId, DesignFile)],
    ) -> Elab<'a> {
        Elab {
            sources,
            lib: Library::index(analysis, files),
            analysed: resolutions(analysis),
            design: Design::default(),
            errors: Vec::new(),
            packages: PackageCache::default(),
            pending: Pending::default(),
            signals: SignalTables::default(),
            analog: AnalogTables::default(),
            here: InstanceContext::default(),
            unit_at: usize::MAX,
            native_names: None,
            quiet: false,
            specialising: 0,
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
        if self.here.path.is_empty() {
            name.to_string()
        } else {
            // Exact capacity: a design holds one such name per object, and `format!` would
            // leave up to half of each deep hierarchical name unused.
            let mut full = String::with_capacity(self.here.path.len() + 1 + name.len());
            full.push_str(&self.here.path);
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
    fn standard_type(&self, name: &str) -> Option<names::types::Ty> {
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
            .done
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
}
