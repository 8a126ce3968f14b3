//! Packages and context clauses: a package's declarations are elaborated once, on first `use`
//! (its body's deferred constants with it), and the use region a context clause builds is kept
//! by the clause's text, since every copy of a model says `use ieee.electrical_systems.all;`.
//!
//! Reads the [`Library`](crate::units::library::Library) of units; writes [`PackageCache`].

use rustc_hash::{FxHashMap, FxHashSet};
use std::rc::Rc;

use vams_syntax::ast::{ContextItem, ExprKind};
use vams_syntax::source::Span;

use crate::declarations::decls;
use crate::error::ElabError;
use crate::names::scope::{self, Item, PackageScope, Scope};
use crate::units::library::{Unit, canonical_library};
use crate::{Elab, R};

/// The packages elaborated so far and the use regions built.
#[derive(Default)]
pub(crate) struct PackageCache<'a> {
    /// Packages elaborated so far, by unit index.
    pub done: FxHashMap<usize, Rc<PackageScope<'a>>>,
    /// Packages being elaborated (a package that uses itself is an error).
    pub in_progress: FxHashSet<usize>,
    /// The items of every package elaborated so far, by the span of their declaration.
    pub decls: FxHashMap<Span, Item<'a>>,
    /// Use regions already built, by [`context_key`].
    pub use_regions: FxHashMap<String, scope::Region<'a>>,
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

impl<'a> Elab<'a> {
    /// A new scope with the implicit context (`library std, work; use std.standard.all`) and
    /// the unit's own context clause. The use region is built once per distinct clause text and
    /// library (every copy of a model says `use ieee.electrical_systems.all;`), unless building
    /// it reported an error, so that the error is reported wherever the clause is.
    pub(crate) fn unit_scope(
        &mut self,
        library: &str,
        contexts: &[&'a [ContextItem]],
    ) -> Scope<'a> {
        let mut key = context_key(library, contexts);
        if self.lib.has_namesakes()
            && let Some(key) = &mut key
        {
            // Which namesake package a clause names depends on where the unit is.
            key.push_str(&self.unit_at.to_string());
        }
        if let Some(region) = key.as_ref().and_then(|k| self.packages.use_regions.get(k)) {
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
            self.packages.use_regions.insert(key, sc.regions[0].clone());
        }
        sc
    }

    /// `use lib.pkg.all;`, `use lib.pkg.name;`, `use lib.pkg;`
    pub(crate) fn use_clause(
        &mut self,
        sc: &mut Scope<'a>,
        name: &vams_syntax::ast::Expr,
    ) -> R<()> {
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

    pub(crate) fn library_name(
        &mut self,
        sc: &Scope<'a>,
        lib: &vams_syntax::ast::Ident,
    ) -> R<String> {
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
    pub(crate) fn package(
        &mut self,
        lib: &str,
        name: &str,
        span: Option<Span>,
    ) -> R<Rc<PackageScope<'a>>> {
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
    pub(crate) fn package_unit(
        &mut self,
        unit: Unit<'a, vams_syntax::ast::Package>,
        span: Option<Span>,
    ) -> R<Rc<PackageScope<'a>>> {
        if let Some(p) = self.packages.done.get(&unit.index) {
            return Ok(p.clone());
        }
        let key = (unit.library.clone(), unit.unit.name.name.clone());
        if !self.packages.in_progress.insert(unit.index) {
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
            std::mem::take(&mut self.here.path),
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
        (self.quiet, self.native_names, self.here.path, self.unit_at) = saved;
        self.packages.in_progress.remove(&unit.index);
        let region = sc.regions.pop().unwrap_or_default();
        self.packages
            .decls
            .extend(region.decls.iter().map(|(s, i)| (*s, i.clone())));
        let pkg = Rc::new(PackageScope {
            name: key.1.clone(),
            items: Rc::unwrap_or_clone(region.items),
        });
        self.packages.done.insert(unit.index, pkg.clone());
        Ok(pkg)
    }
}
