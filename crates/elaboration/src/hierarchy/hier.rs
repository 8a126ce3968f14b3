//! The hierarchy: the top entity, entity and component instances with their generic and port
//! maps, generate statements and blocks. Ports are aliases of their actuals; an unconnected
//! port gets a fresh object named `instance.port`.

use rustc_hash::FxHashMap;

use vams_design::Value;
use vams_syntax::ast::{
    self, Actual, Architecture, Assoc, ConcKind, ConcStmt, Entity, InstantiatedUnit, InterfaceDecl,
};
use vams_syntax::source::Span;

use crate::declarations::decls::{BindingKey, binding_key, integer_bounds};
use crate::error::ElabError;
use crate::names::scope::{BindingRef, Item, Scope, list_names};
use crate::names::types::Ty;
use crate::units::generics::parse_literal;
use crate::units::library::{Unit, canonical_library};
use crate::{Elab, ElabOptions, R, Reported};

/// Instances nested deeper than this are taken as a recursive instantiation.
const MAX_DEPTH: usize = 64;

/// Where an instance's generics and ports come from.
enum Actuals<'x, 'a> {
    Top(&'x [(String, String)]),
    Map {
        parent: &'x Scope<'a>,
        generics: &'x [Assoc],
        ports: &'x [Assoc],
    },
}

/// Element associations of port arrays (`t(1) => a, t(2) => b`), by formal name.
type Elementwise<'x> = FxHashMap<String, Vec<&'x Assoc>>;

/// The conversions on formals (`to_bool(y) => yb`), by port name: the whole formal.
type FormalConversions<'x> = FxHashMap<String, &'x ast::Expr>;

/// What a port is associated with: the whole formal (or nothing), or its elements one by one.
pub(crate) enum PortActual<'x> {
    Whole(Option<&'x Assoc>),
    Elements(&'x [&'x Assoc]),
}

/// Interface names in declaration order with their declarations.
/// The most iterations of one `for ... generate`: each elaborates its statements again (a
/// bound typed a few digits too long is a diagnostic, not hours of elaboration and gigabytes).
const MAX_GENERATE_ITERATIONS: usize = 1 << 20;

fn flatten(decls: &[InterfaceDecl]) -> Vec<(&ast::Ident, &InterfaceDecl)> {
    decls
        .iter()
        .flat_map(|d| d.names.iter().map(move |n| (n, d)))
        .collect()
}

impl<'a> Elab<'a> {
    pub(crate) fn top(&mut self, options: &ElabOptions) {
        let mut name = options.top.to_ascii_lowercase();
        let mut key = ("work".to_string(), name.clone());
        // `--top cfg` names a configuration declaration: its entity, configured.
        let mut config = None;
        let mut arch_name = None;
        if !self.lib.entities.contains_key(&key)
            && let Some(cfg) = self.lib.configurations.get(&key)
        {
            let (entity, arch, block) = configured(cfg);
            if let Some(id) = entity {
                name = id.name.clone();
                key = (cfg.library.clone(), name.clone());
            }
            arch_name = arch;
            config = Some(block);
        }
        let Some(entity) = self.lib.entity(&key, usize::MAX).cloned() else {
            let cands = self.lib.tops();
            let help = match self
                .lib
                .work_entities()
                .iter()
                .map(|e| (strsim::levenshtein(&name, e), e.clone()))
                .min()
            {
                Some((d, best)) if d <= 2 => {
                    format!("did you mean `{best}`? candidates: {}", list_names(&cands))
                }
                _ => format!("top-level candidates: {}", list_names(&cands)),
            };
            self.error(ElabError::UnknownTop {
                span: None,
                name,
                help: Some(help),
            });
            return;
        };
        let generic_names: Vec<String> = flatten(&entity.unit.generics)
            .iter()
            .map(|(n, _)| n.name.clone())
            .collect();
        let mut overrides = Vec::new();
        for (g, text) in &options.generics {
            let g = g.to_ascii_lowercase();
            if g.contains('.') {
                self.here.overrides.push((g, text.clone(), false));
            } else if generic_names.contains(&g) {
                overrides.push((g, text.clone()));
            } else {
                self.error(ElabError::UnknownGeneric {
                    span: entity.unit.name.span,
                    name: g,
                    entity: name.clone(),
                    help: Some(format!("its generics are {}", list_names(&generic_names))),
                });
            }
        }
        let Ok(arch) = self.architecture(&entity, arch_name, entity.unit.name.span) else {
            return;
        };
        self.design.top = name;
        let _ = self.instance_body(&entity, &arch, Actuals::Top(&overrides), config, 0);
    }

    fn architecture(
        &mut self,
        entity: &Unit<'a, Entity>,
        named: Option<&ast::Ident>,
        span: Span,
    ) -> R<Unit<'a, Architecture>> {
        let key = (entity.library.clone(), entity.unit.name.name.clone());
        let archs = self.lib.architectures.get(&entity.index);
        let found = match (archs, named) {
            (Some(a), Some(n)) => a.iter().rev().find(|u| u.unit.name.name == n.name).cloned(),
            (Some(a), None) => a.last().cloned(),
            (None, _) => None,
        };
        if let Some(found) = found {
            return Ok(found);
        }
        let known: Vec<String> = archs
            .map(|a| a.iter().map(|u| u.unit.name.name.clone()).collect())
            .unwrap_or_default();
        Err(self.error(ElabError::NoArchitecture {
            span,
            entity: key.1.clone(),
            named: named.map(|n| format!(" `{}`", n.name)).unwrap_or_default(),
            help: Some(if known.is_empty() {
                format!(
                    "write `architecture a of {} is ... end architecture;` and pass its file",
                    key.1
                )
            } else {
                format!("its architectures are {}", list_names(&known))
            }),
        }))
    }

    /// Matches a map's associations to the formals: `formal name -> actual`, and the element
    /// associations of port arrays (`t(1) => a`) by formal name.
    fn associate<'x>(
        &mut self,
        formals: &[(&ast::Ident, &InterfaceDecl)],
        map: &'x [Assoc],
        what: &'static str,
        unit: &str,
    ) -> (
        FxHashMap<String, &'x Assoc>,
        Elementwise<'x>,
        FormalConversions<'x>,
    ) {
        let mut out = FxHashMap::default();
        let mut elementwise: Elementwise<'x> = FxHashMap::default();
        let mut conversions: FormalConversions<'x> = FxHashMap::default();
        let names: Vec<String> = formals.iter().map(|(n, _)| n.name.clone()).collect();
        for (k, a) in map.iter().enumerate() {
            let name = match &a.formal {
                Some(f) => match &f.kind {
                    ast::ExprKind::Name(id) => id.name.clone(),
                    ast::ExprKind::Apply(prefix, _)
                        if what == "port"
                            && matches!(&prefix.kind, ast::ExprKind::Name(id) if names.contains(&id.name)) =>
                    {
                        if let ast::ExprKind::Name(id) = &prefix.kind {
                            elementwise.entry(id.name.clone()).or_default().push(a);
                        }
                        continue;
                    }
                    // `to_bool(y) => yb`: a conversion of an `out` port's value.
                    ast::ExprKind::Apply(_, args) if what == "port" => {
                        let port = match args.as_slice() {
                            [
                                ast::Assoc {
                                    formal: None,
                                    actual: Actual::Expr(x),
                                    ..
                                },
                            ] => match &x.kind {
                                ast::ExprKind::Name(id) if names.contains(&id.name) => {
                                    Some(id.name.clone())
                                }
                                _ => None,
                            },
                            _ => None,
                        };
                        let Some(port) = port else {
                            self.error(ElabError::invalid(
                                f.span,
                                "a converted formal names one port: `to_bool(y) => yb`",
                                Some(format!("its ports are {}", list_names(&names))),
                            ));
                            continue;
                        };
                        conversions.insert(port.clone(), f);
                        port
                    }
                    _ => {
                        self.error(ElabError::unsupported(
                            f.span,
                            "this form of formal",
                            "name the formal, or an element or slice of it: `p => a`, `p(1) => a`",
                        ));
                        continue;
                    }
                },
                None => match names.get(k) {
                    Some(n) => n.clone(),
                    None => {
                        self.error(ElabError::invalid(
                            a.span,
                            format!(
                                "too many {what} actuals: `{unit}` has {} {what}s",
                                names.len()
                            ),
                            None,
                        ));
                        continue;
                    }
                },
            };
            if !names.contains(&name) {
                let span = a.formal.as_ref().map_or(a.span, |f| f.span);
                let best = names
                    .iter()
                    .map(|n| (strsim::levenshtein(&name, n), n))
                    .min()
                    .filter(|(d, _)| *d <= 2);
                self.error(ElabError::UnknownFormal {
                    span,
                    name,
                    what,
                    unit: unit.to_string(),
                    help: Some(match best {
                        Some((_, b)) => {
                            format!("did you mean `{b}`? its {what}s are {}", list_names(&names))
                        }
                        None => format!("its {what}s are {}", list_names(&names)),
                    }),
                });
                continue;
            }
            out.insert(name, a);
        }
        (out, elementwise, conversions)
    }

    fn instance_body(
        &mut self,
        entity: &Unit<'a, Entity>,
        arch: &Unit<'a, Architecture>,
        actuals: Actuals<'_, 'a>,
        config: Option<&'a ast::BlockConfig>,
        depth: usize,
    ) -> R<()> {
        // The names of the architecture's text denote the units it sees.
        let outer = std::mem::replace(&mut self.unit_at, arch.index);
        let result = self.instance_body_at(entity, arch, actuals, config, depth);
        self.unit_at = outer;
        result
    }

    fn instance_body_at(
        &mut self,
        entity: &Unit<'a, Entity>,
        arch: &Unit<'a, Architecture>,
        actuals: Actuals<'_, 'a>,
        config: Option<&'a ast::BlockConfig>,
        depth: usize,
    ) -> R<()> {
        let ent = entity.unit;
        self.here.units.insert(
            self.here.path.clone(),
            format!("{}({})", ent.name.name, arch.unit.name.name),
        );
        let mut sc = self.unit_scope(&entity.library, &[entity.context, arch.context]);
        sc.push();
        let generics = flatten(&ent.generics);
        let ports = flatten(&ent.ports);
        let (gmap, (pmap, elementwise, conversions), parent) = match &actuals {
            Actuals::Top(_) => (FxHashMap::default(), Default::default(), None),
            Actuals::Map {
                parent,
                generics: g,
                ports: p,
            } => {
                let (gm, ..) = self.associate(&generics, g, "generic", &ent.name.name);
                let pm = self.associate(&ports, p, "port", &ent.name.name);
                (gm, pm, Some(*parent))
            }
        };
        let mut ok = true;
        for (name, decl) in &generics {
            ok &= self
                .generic(
                    &mut sc,
                    name,
                    decl,
                    &actuals,
                    gmap.get(&name.name).copied(),
                    parent,
                    &ent.name.name,
                )
                .is_ok();
        }
        if !ok {
            return Err(Reported);
        }
        for (name, decl) in &ports {
            let actual = match (elementwise.get(&name.name), pmap.get(&name.name)) {
                (Some(_), Some(whole)) => {
                    self.error(ElabError::invalid(
                        whole.span,
                        format!(
                            "port `{}` is associated both whole and by element",
                            name.name
                        ),
                        Some("keep either `t => n` or `t(1) => a, t(2) => b`".into()),
                    ));
                    ok = false;
                    continue;
                }
                (Some(elements), None) => PortActual::Elements(elements),
                (None, whole) => PortActual::Whole(whole.copied()),
            };
            let conversion = conversions.get(&name.name).copied();
            ok &= self
                .port(&mut sc, name, decl, actual, conversion, parent)
                .is_ok();
        }
        if !ok {
            return Err(Reported);
        }
        self.decls(&mut sc, &ent.decls);
        self.conc_stmts(&mut sc, &ent.stmts, depth);
        sc.push();
        self.decls(&mut sc, &arch.unit.decls);
        if let Some(block) = config {
            self.block_config(&mut sc, block)?;
        }
        self.conc_stmts(&mut sc, &arch.unit.stmts, depth);
        Ok(())
    }

    /// Declares the component configurations of `block` (a configuration declaration's, for
    /// the architecture being elaborated) as bindings of its instances. A configuration
    /// specification of the architecture for the same instances stays in force.
    fn block_config(&mut self, sc: &mut Scope<'a>, block: &'a ast::BlockConfig) -> R<()> {
        for item in &block.items {
            match item {
                ast::ConfigItem::Component(c) => {
                    let binding = Item::Binding(BindingRef {
                        component: &c.component,
                        binding: c.binding.as_ref(),
                        block: c.block.as_ref(),
                    });
                    for key in crate::declarations::decls::binding_keys(&c.labels, &c.component) {
                        sc.declare(&key, binding.clone());
                    }
                }
                // A block statement's or a whole generate statement's configuration: its
                // bindings apply to the instances of that label's statements, which see
                // this scope (labels are unique in an architecture).
                ast::ConfigItem::Block(b) if matches!(b.spec.kind, ast::ExprKind::Name(_)) => {
                    self.block_config(sc, b)?;
                }
                // Some iterations of a generate statement: kept for its iterations to select.
                ast::ConfigItem::Block(b) => {
                    let label = match &b.spec.kind {
                        ast::ExprKind::Apply(prefix, args) if args.len() == 1 => {
                            prefix.name_ident()
                        }
                        _ => None,
                    };
                    let Some(label) = label else {
                        return Err(self.error(ElabError::invalid(
                            b.spec.span,
                            "a block configuration names a block or generate statement, with an index or range for some iterations of a generate",
                            None,
                        )));
                    };
                    let key = iterations_key(&label.name);
                    let mut list = match sc.lookup(&key) {
                        Some([Item::IterationConfigs(old)]) => old.as_ref().clone(),
                        _ => Vec::new(),
                    };
                    list.push(b);
                    let item = Item::IterationConfigs(std::rc::Rc::new(list));
                    if sc.lookup(&key).is_some() {
                        sc.replace(&key, vec![item]);
                    } else {
                        sc.declare(&key, item);
                    }
                }
            }
        }
        Ok(())
    }

    /// Applies the block configurations of the generate statement `label` that select the
    /// iteration whose parameter is `i` (`for gen(0 to n - 2)`, `for gen(n - 1)`), in the
    /// iteration's own region.
    fn iteration_configs(&mut self, sc: &mut Scope<'a>, label: &str, i: i64) -> R<()> {
        let configs = match sc.lookup(&iterations_key(label)) {
            Some([Item::IterationConfigs(list)]) => std::rc::Rc::clone(list),
            _ => return Ok(()),
        };
        for b in configs.iter() {
            let ast::ExprKind::Apply(_, args) = &b.spec.kind else {
                continue;
            };
            let selected = match &args[0].actual {
                ast::Actual::Range(r) => {
                    let (l, r, asc) = self.range_bounds(sc, r)?;
                    if asc {
                        l <= i && i <= r
                    } else {
                        r <= i && i <= l
                    }
                }
                ast::Actual::Expr(e) => {
                    match self.static_value(sc, e, &Ty::Integer, "an iteration of a generate")? {
                        Value::Integer(v) => v == i,
                        _ => false,
                    }
                }
                ast::Actual::Open(_) => false,
            };
            if selected {
                self.block_config(sc, b)?;
            }
        }
        Ok(())
    }

    /// The override of the current instance's generic `name`, marked as taken.
    fn instance_override(&mut self, name: &str) -> Option<String> {
        let full = self.hier_name(name);
        let found = self
            .here
            .overrides
            .iter_mut()
            .rev()
            .find(|(n, ..)| *n == full)
            .map(|(_, text, taken)| {
                *taken = true;
                text.clone()
            });
        self.here.generics_met.push(full);
        found
    }

    /// Every instance override that no instance took is an error (a misspelt path would
    /// otherwise be ignored silently, and a sweep of it would vary nothing).
    pub(crate) fn check_instance_overrides(&mut self) {
        let untaken: Vec<String> = self
            .here
            .overrides
            .iter()
            .filter(|(.., taken)| !taken)
            .map(|(n, ..)| n.clone())
            .collect();
        for name in untaken {
            let closest = self
                .here
                .generics_met
                .iter()
                .map(|g| (strsim::levenshtein(&name, g), g))
                .min();
            let help = match closest {
                Some((d, best)) if d <= 3 => format!("did you mean `{best}`?"),
                _ if self.here.generics_met.is_empty() => {
                    "the design's instances have no generics".to_string()
                }
                _ => format!(
                    "instance generics are named by their path from the top, e.g. `{}`",
                    self.here.generics_met[0]
                ),
            };
            self.error(ElabError::UnknownInstanceGeneric {
                name,
                help: Some(help),
            });
        }
    }

    #[allow(clippy::too_many_arguments)]
    fn generic(
        &mut self,
        sc: &mut Scope<'a>,
        name: &ast::Ident,
        decl: &InterfaceDecl,
        actuals: &Actuals<'_, 'a>,
        actual: Option<&Assoc>,
        parent: Option<&Scope<'a>>,
        entity: &str,
    ) -> R<()> {
        let sub = self.subtype_indication(sc, &decl.subtype)?;
        let override_text = match actuals {
            Actuals::Top(o) => o
                .iter()
                .rev()
                .find(|(n, _)| *n == name.name)
                .map(|(_, t)| t.clone()),
            Actuals::Map { .. } => self.instance_override(&name.name),
        };
        // Where the value comes from, for a value outside the subtype's range.
        let (origin, fix) = match (&override_text, actual, &decl.default) {
            (Some(_), ..) => (
                name.span,
                format!("override `{}` with a value in the range", name.name),
            ),
            (None, Some(a), _) if parent.is_some() => {
                (a.span, "give the generic map a value in the range".into())
            }
            (None, _, Some(default)) => (
                default.span,
                "give the default a value in the range (or override it with -g)".into(),
            ),
            _ => (name.span, String::new()),
        };
        let value = if let Some(text) = override_text {
            match parse_literal(&text, &sub.ty, |u| self.standard_time_unit(u)) {
                Some(v) => v,
                None => {
                    return Err(self.error(ElabError::BadGenericValue {
                        span: name.span,
                        name: name.name.clone(),
                        text,
                        ty: sub.ty.to_string(),
                        help: Some(literal_help(&sub.ty)),
                    }));
                }
            }
        } else if let (
            Some(Assoc {
                actual: Actual::Expr(e),
                ..
            }),
            Some(parent),
        ) = (actual, parent)
        {
            self.static_value(parent, e, &sub.ty, "a generic actual")?
        } else if let Some(default) = &decl.default {
            self.static_value(sc, default, &sub.ty, "a generic's default")?
        } else {
            return Err(self.error(ElabError::MissingGeneric {
                span: name.span,
                name: name.name.clone(),
                entity: entity.to_string(),
            }));
        };
        // LRM 12.2.4: a generic's value must belong to its subtype (GHDL: "bound check
        // failure" at elaboration).
        if let (Value::Integer(i), Some((lo, hi))) = (&value, integer_bounds(&sub))
            && (*i < lo || *i > hi)
        {
            return Err(self.error(ElabError::invalid(
                origin,
                format!(
                    "generic `{}` = {i} is outside its subtype's range {lo} to {hi}",
                    name.name
                ),
                Some(fix),
            )));
        }
        let ty = crate::declarations::decls::fit_array(&sub.ty, &value);
        sc.declare_at(&name.name, name.span, Item::Constant { value, ty });
        Ok(())
    }

    pub(crate) fn conc_stmts(&mut self, sc: &mut Scope<'a>, stmts: &'a [ConcStmt], depth: usize) {
        for s in stmts {
            match &s.kind {
                ConcKind::Process {
                    sensitivity,
                    decls,
                    stmts,
                } => self.process(sc, s, sensitivity, decls, stmts),
                ConcKind::ConditionalAssign { .. }
                | ConcKind::SelectedAssign { .. }
                | ConcKind::Assert(_)
                | ConcKind::ProcedureCall(_)
                | ConcKind::Break(_) => {
                    let _ = self.concurrent_assign(sc, s);
                }
                ConcKind::Instance {
                    unit,
                    generic_map,
                    port_map,
                } => {
                    let _ = self.instantiate(sc, s, unit, generic_map, port_map, depth);
                }
                ConcKind::ForGenerate {
                    param,
                    range,
                    decls,
                    stmts,
                } => {
                    let Ok((l, r, asc)) = self.discrete_range(sc, range) else {
                        continue;
                    };
                    let label = s.label.as_ref().map_or("gen", |l| l.name.as_str());
                    // i128: no bounds an i64 holds overflow the count.
                    let count = (i128::from(r) - i128::from(l)) * if asc { 1 } else { -1 } + 1;
                    if count > MAX_GENERATE_ITERATIONS as i128 {
                        self.error(ElabError::unsupported(
                            s.span,
                            format!("a generate statement of {count} iterations"),
                            format!("vams elaborates up to {MAX_GENERATE_ITERATIONS} iterations of one generate statement; check the bounds"),
                        ));
                        continue;
                    }
                    let values: Vec<i64> = if asc {
                        (l..=r).collect()
                    } else {
                        (r..=l).rev().collect()
                    };
                    for i in values {
                        let saved = self.here.path.clone();
                        self.here.path = format!("{}({i})", self.hier_name(label));
                        sc.push();
                        sc.declare_at(
                            &param.name,
                            param.span,
                            Item::Constant {
                                value: Value::Integer(i),
                                ty: Ty::Integer,
                            },
                        );
                        let _ = self.iteration_configs(sc, label, i);
                        self.decls(sc, decls);
                        self.conc_stmts(sc, stmts, depth);
                        sc.pop();
                        self.here.path = saved;
                    }
                }
                ConcKind::IfGenerate {
                    condition,
                    decls,
                    stmts,
                } => {
                    let Ok(v) =
                        self.static_value(sc, condition, &Ty::Boolean, "a generate condition")
                    else {
                        continue;
                    };
                    if v == Value::Boolean(true) {
                        self.nested_region(sc, s, decls, stmts, depth);
                    }
                }
                ConcKind::Block {
                    guard,
                    header,
                    decls,
                    stmts,
                } => {
                    // A guarded block's GUARD is declared in a region of its own around the
                    // block's, under the guard expression's span, which analysis resolves
                    // the name to.
                    sc.push();
                    let guarded = match guard {
                        Some(g) => match self.guard_signal(sc, s, g) {
                            Ok(id) => {
                                self.signals.guards.push(id);
                                true
                            }
                            Err(_) => {
                                sc.pop();
                                continue;
                            }
                        },
                        None => false,
                    };
                    if header.generics.is_empty() && header.ports.is_empty() {
                        self.nested_region(sc, s, decls, stmts, depth);
                    } else {
                        let _ = self.block_with_header(sc, s, header, (decls, stmts), depth);
                    }
                    if guarded {
                        self.signals.guards.pop();
                    }
                    sc.pop();
                }
                ConcKind::Simultaneous(kind) => self.simultaneous(sc, s, kind),
            }
        }
    }

    /// A block with generic and port clauses: its generics take the values of its generic
    /// map (or their defaults), its ports are the actual objects of its port map, as for an
    /// instance, in a region inside the enclosing one.
    fn block_with_header(
        &mut self,
        sc: &mut Scope<'a>,
        s: &ConcStmt,
        header: &'a ast::BlockHeader,
        (decls, stmts): (&'a [ast::Decl], &'a [ConcStmt]),
        depth: usize,
    ) -> R<()> {
        let label = s
            .label
            .as_ref()
            .map_or("block", |l| l.name.as_str())
            .to_string();
        let generics = flatten(&header.generics);
        let ports = flatten(&header.ports);
        let (gmap, ..) = self.associate(&generics, &header.generic_map, "generic", &label);
        let (pmap, elementwise, conversions) =
            self.associate(&ports, &header.port_map, "port", &label);
        if let Some((name, _)) = elementwise.iter().next() {
            let span = header.port_map.first().map_or(s.span, |a| a.span);
            return Err(self.error(ElabError::unsupported(
                span,
                format!("element associations of the block port `{name}`"),
                "associate the whole port",
            )));
        }
        let parent = sc.clone();
        let actuals = Actuals::Map {
            parent: &parent,
            generics: &header.generic_map,
            ports: &header.port_map,
        };
        let saved = self.here.path.clone();
        if let Some(l) = &s.label {
            self.here.path = self.hier_name(&l.name);
        }
        sc.push();
        let mut ok = true;
        for (name, decl) in &generics {
            let actual = gmap.get(&name.name).copied();
            ok &= self
                .generic(sc, name, decl, &actuals, actual, Some(&parent), &label)
                .is_ok();
        }
        for (name, decl) in &ports {
            let actual = PortActual::Whole(pmap.get(&name.name).copied());
            let conversion = conversions.get(&name.name).copied();
            ok &= self
                .port(sc, name, decl, actual, conversion, Some(&parent))
                .is_ok();
        }
        if ok {
            self.decls(sc, decls);
            self.conc_stmts(sc, stmts, depth);
        }
        sc.pop();
        self.here.path = saved;
        if ok { Ok(()) } else { Err(Reported) }
    }

    fn nested_region(
        &mut self,
        sc: &mut Scope<'a>,
        s: &ConcStmt,
        decls: &'a [ast::Decl],
        stmts: &'a [ConcStmt],
        depth: usize,
    ) {
        let saved = self.here.path.clone();
        if let Some(l) = &s.label {
            self.here.path = self.hier_name(&l.name);
        }
        sc.push();
        self.decls(sc, decls);
        self.conc_stmts(sc, stmts, depth);
        sc.pop();
        self.here.path = saved;
    }

    fn instantiate(
        &mut self,
        sc: &mut Scope<'a>,
        s: &ConcStmt,
        unit: &'a InstantiatedUnit,
        generics: &'a [Assoc],
        ports: &'a [Assoc],
        depth: usize,
    ) -> R<()> {
        let mut config = None;
        // A component instance bound by default (LRM 5.2.2) to the entity of its name.
        let mut by_default = false;
        // The entity's maps when a binding indication has its own (composed with the
        // instance's); the instance's otherwise.
        let (mut entity_generics, mut entity_ports) = (None, None);
        let (lib, name, arch_name, name_span) = match unit {
            InstantiatedUnit::Entity { name, architecture } => {
                self.entity_aspect(sc, name, architecture.as_ref())?
            }
            InstantiatedUnit::Component(name) => {
                let items = self.lookup(sc, name)?;
                let Item::Component(decl) = items[0] else {
                    return Err(self.error(ElabError::WrongClass {
                        span: name.span,
                        name: self.sources.snippet(name.span).into(),
                        found: items[0].class().into(),
                        expected: "a component".into(),
                        help: Some("instantiate an entity with `label : entity work.name`".into()),
                    }));
                };
                let simple = match &decl.kind {
                    ast::DeclKind::Component { name, .. } => name.name.clone(),
                    _ => String::new(),
                };
                // Default binding (LRM 7.3.3): the entity of the same name in work.
                let default = ("work".to_string(), simple.clone(), None, name.span);
                match self.binding_of(sc, s, &simple, false) {
                    // A configuration specification or component configuration binds it.
                    Some(b) => {
                        // An incremental binding keeps the primary binding's entity (a
                        // configuration specification's, or the default) and, for a map it
                        // does not give, the primary binding's map.
                        let primary = match b.binding {
                            Some(binding) if binding.incremental => self
                                .binding_of(sc, s, &simple, true)
                                .and_then(|p| p.binding),
                            _ => None,
                        };
                        let entity_aspect = match b.binding {
                            Some(binding) if binding.incremental => primary,
                            other => other,
                        };
                        let mut target = match entity_aspect {
                            Some(binding) => match self.bound_entity(sc, binding)? {
                                Some((target, block)) => {
                                    config = block;
                                    target
                                }
                                // `use open`: the instance stays unbound.
                                None => return Ok(()),
                            },
                            None => {
                                by_default = true;
                                default
                            }
                        };
                        if let (
                            Some(binding),
                            ast::DeclKind::Component {
                                generics: cg,
                                ports: cp,
                                ..
                            },
                        ) = (b.binding, &decl.kind)
                        {
                            let generic_map = match primary {
                                Some(p) if binding.generic_map.is_empty() => &p.generic_map,
                                _ => &binding.generic_map,
                            };
                            let port_map = match primary {
                                Some(p) if binding.port_map.is_empty() => &p.port_map,
                                _ => &binding.port_map,
                            };
                            if !generic_map.is_empty() {
                                entity_generics =
                                    Some(compose(&flatten(cg), generics, generic_map, true));
                            }
                            if !port_map.is_empty() {
                                entity_ports = Some(compose(&flatten(cp), ports, port_map, false));
                            }
                        }
                        if let Some(block) = b.block {
                            // `for arch ... end for;` names the architecture when the binding
                            // did not.
                            if target.2.is_none()
                                && let ast::ExprKind::Name(id) = &block.spec.kind
                            {
                                target.2 = Some(id);
                            }
                            config = Some(block);
                        }
                        target
                    }
                    None => {
                        by_default = true;
                        default
                    }
                }
            }
            // `u : configuration work.cfg port map (...)`: the configuration's entity, with
            // the architecture and the bindings it gives.
            InstantiatedUnit::Configuration(n) => {
                let (target, block) = self.configuration_target(sc, n)?;
                config = Some(block);
                target
            }
        };
        if by_default
            && self
                .lib
                .entity_with(
                    &(canonical_library(&lib).to_string(), name.clone()),
                    self.unit_at,
                    None,
                )
                .is_none()
        {
            // No entity of the component's name: the instance is unbound (LRM 5.2.2), and
            // elaborates as nothing.
            self.design
                .warnings
                .push(vams_design::DesignWarning::Unbound(
                    vams_design::UnboundInstance {
                        label: s
                            .label
                            .as_ref()
                            .map_or_else(String::new, |l| l.name.clone()),
                        component: name,
                        library: lib,
                        span: name_span,
                    },
                ));
            return Ok(());
        }
        let target = (lib, name, arch_name, name_span);
        let maps = (
            entity_generics.as_deref().unwrap_or(generics),
            entity_ports.as_deref().unwrap_or(ports),
        );
        self.instantiate_entity(sc, s, target, maps, config, depth)
    }

    /// The configuration specification of the innermost declarative region that binds
    /// instance `s` of component `component`: one naming its label, else one for `all` or
    /// `others` of that component (LRM 5.2); with `primary`, only one with an entity aspect
    /// (what an incremental binding adds to).
    fn binding_of(
        &self,
        sc: &Scope<'a>,
        s: &ConcStmt,
        component: &str,
        primary: bool,
    ) -> Option<BindingRef<'a>> {
        let here = sc.regions.last()?;
        let keys = [
            s.label
                .as_ref()
                .map(|l| binding_key(BindingKey::Label, &l.name)),
            Some(binding_key(BindingKey::All, component)),
            Some(binding_key(BindingKey::Others, component)),
        ];
        let incremental = |b: &BindingRef<'a>| b.binding.is_some_and(|x| x.incremental);
        // An incremental component configuration (declared after the architecture's
        // configuration specifications) is the one in force; the first other one is the
        // primary binding.
        let mut first = None;
        for key in keys.iter().flatten() {
            for item in here.items.get(key).into_iter().flatten() {
                if let Item::Binding(b) = item
                    && b.component.name_ident().map(|id| id.name.as_str()) == Some(component)
                {
                    if !primary && incremental(b) {
                        return Some(*b);
                    }
                    if first.is_none() && !incremental(b) && !(primary && b.binding.is_none()) {
                        first = Some(*b);
                    }
                }
            }
        }
        first
    }

    /// The entity and architecture a binding indication names, with the block configuration
    /// of a configuration it names; `None` for `use open`.
    #[allow(clippy::type_complexity)]
    fn bound_entity(
        &mut self,
        sc: &Scope<'a>,
        binding: &'a ast::Binding,
    ) -> R<
        Option<(
            (String, String, Option<&'a ast::Ident>, Span),
            Option<&'a ast::BlockConfig>,
        )>,
    > {
        match &binding.unit {
            Some(InstantiatedUnit::Entity { name, architecture }) => Ok(Some((
                self.entity_aspect(sc, name, architecture.as_ref())?,
                None,
            ))),
            Some(InstantiatedUnit::Configuration(n)) => {
                let (target, block) = self.configuration_target(sc, n)?;
                Ok(Some((target, Some(block))))
            }
            Some(InstantiatedUnit::Component(_)) | None => Ok(None),
        }
    }

    /// `configuration lib.cfg`: the entity and architecture the configuration declaration
    /// names, and its block configuration.
    #[allow(clippy::type_complexity)]
    fn configuration_target(
        &mut self,
        sc: &Scope<'a>,
        n: &'a ast::Expr,
    ) -> R<(
        (String, String, Option<&'a ast::Ident>, Span),
        &'a ast::BlockConfig,
    )> {
        let (lib, cfg_name, _, span) = self.entity_aspect(sc, n, None)?;
        let Some(cfg) = self
            .lib
            .configurations
            .get(&(lib.clone(), cfg_name.clone()))
        else {
            return Err(self.error(ElabError::invalid(
                n.span,
                format!("no configuration `{cfg_name}` in library `{lib}`"),
                Some("give vams the file that declares it".into()),
            )));
        };
        let (entity, arch, block) = configured(cfg);
        let Some(entity) = entity else {
            return Err(self.error(ElabError::invalid(
                cfg.unit.entity.span,
                "expected an entity name",
                None,
            )));
        };
        Ok((
            (cfg.library.clone(), entity.name.clone(), arch, span),
            block,
        ))
    }

    /// `entity lib.e(arch)`: the library, the entity's name, the architecture named.
    #[allow(clippy::type_complexity)]
    fn entity_aspect(
        &mut self,
        sc: &Scope<'a>,
        name: &'a ast::Expr,
        architecture: Option<&'a ast::Ident>,
    ) -> R<(String, String, Option<&'a ast::Ident>, Span)> {
        let (lib, ent) = match &name.kind {
            ast::ExprKind::Selected(prefix, ent) => {
                let ast::ExprKind::Name(l) = &prefix.kind else {
                    return Err(self.error(ElabError::invalid(
                        prefix.span,
                        "expected a library name",
                        None,
                    )));
                };
                (self.library_name(sc, l)?, ent)
            }
            ast::ExprKind::Name(ent) => (
                match sc.lookup("work") {
                    Some([Item::Library(l), ..]) => l.clone(),
                    _ => "work".into(),
                },
                ent,
            ),
            _ => {
                return Err(self.error(ElabError::invalid(
                    name.span,
                    "expected an entity name",
                    None,
                )));
            }
        };
        Ok((lib, ent.name.clone(), architecture, name.span))
    }

    /// Instantiates `lib.name(arch_name)` for instance `s`.
    #[allow(clippy::type_complexity)]
    fn instantiate_entity(
        &mut self,
        sc: &mut Scope<'a>,
        s: &ConcStmt,
        (lib, name, arch_name, name_span): (String, String, Option<&'a ast::Ident>, Span),
        (generics, ports): (&[Assoc], &[Assoc]),
        config: Option<&'a ast::BlockConfig>,
        depth: usize,
    ) -> R<()> {
        let key = (canonical_library(&lib).to_string(), name.clone());
        let arch_named = arch_name.map(|a| a.name.as_str());
        let Some(entity) = self
            .lib
            .entity_with(&key, self.unit_at, arch_named)
            .cloned()
        else {
            let cands = self.lib.work_entities();
            let best = cands
                .iter()
                .map(|e| (strsim::levenshtein(&name, e), e))
                .min()
                .filter(|(d, _)| *d <= 2);
            return Err(self.error(ElabError::Undeclared {
                span: name_span,
                name: format!("{}.{}", key.0, key.1),
                help: Some(match best {
                    Some((_, b)) => format!("did you mean `{b}`?"),
                    None => format!(
                        "library {} has no entity `{}`; pass the file that declares it",
                        key.0, key.1
                    ),
                }),
            }));
        };
        let arch = self.architecture(&entity, arch_name, name_span)?;
        if depth >= MAX_DEPTH {
            return Err(self.error(ElabError::invalid(
                s.span,
                format!("instances nested more than {MAX_DEPTH} deep"),
                Some("an entity probably instantiates itself".into()),
            )));
        }
        let label = s
            .label
            .as_ref()
            .map_or_else(|| name.clone(), |l| l.name.clone());
        let path = self.hier_name(&label);
        let saved = (
            std::mem::replace(&mut self.here.path, path),
            std::mem::take(&mut self.here.instance),
        );
        self.here.instance = self.here.path.clone();
        let r = self.instance_body(
            &entity,
            &arch,
            Actuals::Map {
                parent: sc,
                generics,
                ports,
            },
            config,
            depth + 1,
        );
        (self.here.path, self.here.instance) = saved;
        r
    }
}

/// What a configuration declaration configures: its entity's name, the architecture its
/// block configuration names, and that block configuration.
fn configured<'a>(
    cfg: &Unit<'a, ast::Configuration>,
) -> (
    Option<&'a ast::Ident>,
    Option<&'a ast::Ident>,
    &'a ast::BlockConfig,
) {
    let c = cfg.unit;
    let arch = match &c.block.spec.kind {
        ast::ExprKind::Name(id) => Some(id),
        _ => None,
    };
    (c.entity.name_ident(), arch, &c.block)
}

fn literal_help(ty: &Ty) -> String {
    match ty {
        Ty::Real => "write a real number: `-g NAME=4.0` or `1e-3`".into(),
        Ty::Integer => "write an integer: `-g NAME=12`".into(),
        Ty::Time => "write a number and a unit: `-g NAME=\"10 ms\"`".into(),
        Ty::Physical(p) => format!(
            "write a number and a unit of {}: `-g NAME=\"10 {}\"`",
            p.name, p.units[0].0
        ),
        Ty::Boolean => "write `true` or `false`".into(),
        Ty::Enum(e) => format!("write one of {}", list_names(&e.literals)),
        Ty::Array(a) if !matches!(a.element, Ty::Array(_) | Ty::Record(_)) => {
            "write the elements in parentheses, separated by commas: `-g NAME=\"(0.0, 1.0, 2.5)\"`"
                .into()
        }
        Ty::Array(_) | Ty::Record(_) | Ty::Access(_) | Ty::File(_) | Ty::Protected(_) => {
            "generics of arrays of composites, records and access types cannot be set from the command line".into()
        }
    }
}

/// The entity's map from a binding indication's map over the component's formals and the
/// instance's map of those formals (LRM 5.2.1.2): every name of a component formal in a
/// binding actual becomes the instance's actual for it (a generic without one its default
/// value; a port without one leaves the entity's port open), so that the result is evaluated
/// where the instance is.
fn compose(
    formals: &[(&ast::Ident, &InterfaceDecl)],
    instance: &[Assoc],
    binding: &[Assoc],
    generics: bool,
) -> Vec<Assoc> {
    let mut actuals: FxHashMap<&str, Option<ast::Expr>> = FxHashMap::default();
    for (k, (name, decl)) in formals.iter().enumerate() {
        let given = instance
            .iter()
            .find(|a| {
                matches!(&a.formal, Some(ast::Expr { kind: ast::ExprKind::Name(f), .. }) if f.name == name.name)
            })
            .or_else(|| instance.get(k).filter(|a| a.formal.is_none()));
        let actual = match given.map(|a| &a.actual) {
            Some(ast::Actual::Expr(e)) => Some(e.clone()),
            Some(_) => None,
            None if generics => decl.default.clone(),
            None => None,
        };
        actuals.insert(name.name.as_str(), actual);
    }
    binding
        .iter()
        .map(|b| {
            let actual = match &b.actual {
                ast::Actual::Expr(e) => match substitute(e, &actuals) {
                    Some(e) => ast::Actual::Expr(e),
                    None => ast::Actual::Open(b.span),
                },
                other => other.clone(),
            };
            Assoc {
                formal: b.formal.clone(),
                actual,
                span: b.span,
            }
        })
        .collect()
}

/// `e` with each name of a component formal replaced by its actual; `None` when one of them
/// has none (an open port).
fn substitute(e: &ast::Expr, actuals: &FxHashMap<&str, Option<ast::Expr>>) -> Option<ast::Expr> {
    use ast::ExprKind as K;
    let sub = |x: &ast::Expr| substitute(x, actuals).map(Box::new);
    let kind = match &e.kind {
        K::Name(id) => match actuals.get(id.name.as_str()) {
            Some(Some(actual)) => return Some(actual.clone()),
            Some(None) => return None,
            None => K::Name(id.clone()),
        },
        K::Apply(prefix, args) => {
            let mut out = Vec::with_capacity(args.len());
            for a in args {
                let actual = match &a.actual {
                    ast::Actual::Expr(x) => ast::Actual::Expr(substitute(x, actuals)?),
                    other => other.clone(),
                };
                out.push(Assoc {
                    formal: a.formal.clone(),
                    actual,
                    span: a.span,
                });
            }
            K::Apply(sub(prefix)?, out)
        }
        K::Paren(x) => K::Paren(sub(x)?),
        K::Unary(op, x) => K::Unary(*op, sub(x)?),
        K::Binary(op, l, r) => K::Binary(*op, sub(l)?, sub(r)?),
        K::Qualified(t, x) => K::Qualified(t.clone(), sub(x)?),
        other => other.clone(),
    };
    Some(ast::Expr { kind, span: e.span })
}

/// The scope key of a generate statement's iteration configurations (no identifier has a
/// space).
fn iterations_key(label: &str) -> String {
    format!(" iterations {label}")
}
