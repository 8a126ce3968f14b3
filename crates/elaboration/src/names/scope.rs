//! Named things and the regions that make them visible.
//!
//! A [`Scope`] is a stack of regions (innermost last); the outermost holds what `use` clauses
//! made visible. A name found in an inner region hides the outer ones (LRM 12.3), except that
//! overloadable items (subprograms, enumeration literals) of the same region are all returned.

use rustc_hash::FxHashMap;
use std::cell::RefCell;
use std::rc::Rc;

use vams_design::{
    BinaryOp, Builtin, Expr, ParamMode, QuantityId, SignalId, SubprogramId, TerminalId, Type,
    Value, VarId,
};
use vams_syntax::ast;
use vams_syntax::source::Span;

use crate::names::composite::{ArrayNature, Elements, RecordNature};
use crate::names::types::{Sub, Ty};

/// How component instances are bound: the component, the binding indication (`None`: the
/// default binding) and the configuration of the bound entity's architecture.
#[derive(Clone, Copy, Debug)]
pub struct BindingRef<'a> {
    pub component: &'a ast::Expr,
    pub binding: Option<&'a ast::Binding>,
    pub block: Option<&'a ast::BlockConfig>,
}

/// What a name denotes.
#[derive(Clone, Debug)]
pub enum Item<'a> {
    /// A constant or generic, folded.
    Constant {
        value: Value,
        ty: Ty,
    },
    Signal {
        id: SignalId,
        ty: Ty,
    },
    /// Scalar quantities are `real`.
    Quantity(QuantityId),
    Terminal {
        id: TerminalId,
        nature: usize,
    },
    /// A terminal array, expanded into scalar terminals of the element nature.
    TerminalArray {
        elements: Rc<Elements<TerminalId>>,
        nature: usize,
    },
    /// A quantity array (`real_vector(1 to 3)`), expanded into scalar quantities.
    QuantityArray(Rc<Elements<QuantityId>>),
    /// A record nature, a terminal of one and a record quantity (expanded field by field).
    RecordNature(Rc<RecordNature>),
    TerminalRecord(Rc<RecordObject<'a>>),
    QuantityRecord(Rc<RecordObject<'a>>),
    /// A nature's reference terminal, created in the design on first use.
    RefTerminal {
        nature: usize,
    },
    /// A process variable; loop parameters are read-only. `path` selects a part of it (an
    /// alias of a field, element or slice, `alias pc is regs.program_counter;`), and `ty` is
    /// that part's type. Empty for the whole variable.
    Variable {
        id: VarId,
        ty: Ty,
        readonly: bool,
        path: Rc<[Part]>,
    },
    Type(Rc<Sub>),
    /// Index into the elaborator's nature table.
    Nature(usize),
    ArrayNature(Rc<ArrayNature>),
    EnumLiteral {
        ty: Ty,
        pos: u32,
    },
    Subprogram(Rc<Subprogram<'a>>),
    /// A unit of the physical type `time`, in femtoseconds (integral, so that `1 sec` is
    /// exactly 1.0 s).
    TimeUnit(f64),
    /// A unit of a physical type of the user's own, with its value in the primary unit.
    Unit {
        ty: Ty,
        factor: i64,
    },
    Library(String),
    Package(Rc<PackageScope<'a>>),
    Component(&'a ast::Decl),
    /// A configuration specification, or a component configuration of a configuration
    /// declaration, declared under ` for LABEL`, ` for all COMPONENT` or ` for others
    /// COMPONENT` (names no identifier can clash with).
    Binding(BindingRef<'a>),
    /// The block configurations of some iterations of a generate statement (`for
    /// gen(0 to 2) ... end for;`), declared under ` iterations LABEL`: each iteration of
    /// `LABEL` that one selects applies its bindings in its own region.
    IterationConfigs(Rc<Vec<&'a ast::BlockConfig>>),
    /// A user-declared attribute (`attribute symbol : string;`), with its type.
    Attribute(Rc<Sub>),
    /// Declared, but its declaration could not be elaborated (a stdlib declaration using an
    /// unsupported construct): the reason, reported where it is used (`None`: the declaration's
    /// own error was reported already).
    Poison(Option<Rc<str>>),
    /// An alias of a predefined operator (`alias "*" is "and" [bit, bit return bit];`): the
    /// operator's symbol, without quotes.
    OperatorAlias(Rc<str>),
    /// A private variable of a shared variable of protected type, in its methods' bodies:
    /// field `field` of the record on the heap that access value `object` designates.
    PrivateVariable {
        object: Value,
        field: usize,
        record: Type,
        ty: Ty,
    },
    /// A shared variable of protected type: its methods by name (each shared variable has
    /// its own, whose bodies reach its own private variables).
    SharedObject {
        ty: Ty,
        methods: Rc<FxHashMap<String, Vec<Item<'a>>>>,
    },
}

/// One selection from a composite value, outermost first in a path.
#[derive(Clone, Debug)]
pub enum Part {
    /// The element at `index`, in the bounds of the composite's type `container` (a
    /// record's field by its position).
    Element { index: Expr, container: Type },
    /// `len` elements from position `first` (from the left).
    Slice { first: Expr, len: Expr },
}

impl Part {
    /// This part of `whole`.
    pub fn of(&self, whole: Expr) -> Expr {
        match self {
            Part::Element { index, container } => Expr::Index {
                array: Box::new(whole),
                index: Box::new(index.clone()),
                ty: container.clone(),
            },
            Part::Slice { first, len } => {
                Expr::Call(Builtin::Slice, vec![whole, first.clone(), len.clone()])
            }
        }
    }
}

/// `base` with the part that `path` selects replaced by `value` (`v.f(i) := x`), each
/// level spliced into the one above.
pub fn updated(base: Expr, path: &[Part], value: Expr) -> Expr {
    let Some((part, rest)) = path.split_first() else {
        return value;
    };
    let inner = updated(part.of(base.clone()), rest, value);
    let (first, len, value) = match part {
        Part::Element { index, container } => {
            let (left, ascending) = container.index_origin();
            let (l, i) = (
                Box::new(Expr::Const(Value::Integer(left))),
                Box::new(index.clone()),
            );
            let position = if ascending {
                Expr::Binary(BinaryOp::Sub, i, l)
            } else {
                Expr::Binary(BinaryOp::Sub, l, i)
            };
            let one = Expr::Aggregate {
                elems: vec![inner],
                string: *container == Type::String,
            };
            (position, Expr::Const(Value::Integer(1)), one)
        }
        Part::Slice { first, len } => (first.clone(), len.clone(), inner),
    };
    Expr::Call(Builtin::Splice, vec![base, first, len, value])
}

impl<'a> Item<'a> {
    /// "a signal", "a quantity", ... for wrong-class diagnostics.
    pub fn class(&self) -> &'static str {
        match self {
            Item::Constant { .. } => "a constant",
            Item::Signal { .. } => "a signal",
            Item::Quantity(_) => "a quantity",
            Item::QuantityArray(_) => "a quantity array",
            Item::RecordNature(_) => "a record nature",
            Item::TerminalRecord(_) => "a terminal of a record nature",
            Item::QuantityRecord(_) => "a record quantity",
            Item::TerminalArray { .. } => "a terminal array",
            Item::ArrayNature(_) => "an array nature",
            Item::Terminal { .. } | Item::RefTerminal { .. } => "a terminal",
            Item::Variable { .. } => "a variable",
            Item::Type(_) => "a type",
            Item::Nature(_) => "a nature",
            Item::EnumLiteral { .. } => "an enumeration literal",
            Item::Subprogram(_) => "a subprogram",
            Item::TimeUnit(_) => "a unit of time",
            Item::Unit { .. } => "a unit",
            Item::Library(_) => "a library",
            Item::Package(_) => "a package",
            Item::Component(_) => "a component",
            Item::Binding(_) => "a configuration specification",
            Item::IterationConfigs(_) => "a block configuration",
            Item::Attribute(_) => "an attribute",
            Item::OperatorAlias(_) => "an operator",
            Item::PrivateVariable { .. } => "a variable",
            Item::SharedObject { .. } => "a shared variable",
            Item::Poison(_) => "an unsupported declaration",
        }
    }

    /// The same declaration's item (for those shared by `Rc`: types, subprograms, poison).
    fn same(&self, other: &Item<'a>) -> bool {
        match (self, other) {
            (Item::Type(a), Item::Type(b)) => Rc::ptr_eq(a, b),
            (Item::Subprogram(a), Item::Subprogram(b)) => Rc::ptr_eq(a, b),
            (Item::Poison(Some(a)), Item::Poison(Some(b))) => Rc::ptr_eq(a, b),
            _ => false,
        }
    }

    fn overloadable(&self) -> bool {
        matches!(self, Item::Subprogram(_) | Item::EnumLiteral { .. })
    }
}

/// Index bounds `(left, right, ascending)`.
pub type Bounds = (i64, i64, bool);

/// A subprogram lowered into the design for one set of actual signals (of its signal
/// parameters) and actual bounds (of its unconstrained array parameters, one per parameter).
#[derive(Debug)]
pub struct Instance {
    pub signals: Vec<SignalId>,
    pub bounds: Vec<Option<Bounds>>,
    /// The static actuals of the parameters that bound the body's declarations
    /// (`variable result : bit_vector(0 to length - 1)`), one per parameter; empty when
    /// there are none.
    pub constants: Vec<Option<Value>>,
    /// The shared variables bound to its parameters of protected type (by the identity of
    /// their methods), one per such parameter.
    pub objects: Vec<usize>,
    pub id: SubprogramId,
    /// The static bounds of the function's result, when every `return` of this instance
    /// returns a value with the same ones.
    pub result: Option<Bounds>,
}

/// A function or procedure declaration.
#[derive(Debug)]
pub struct Subprogram<'a> {
    pub name: String,
    pub params: Vec<Param<'a>>,
    /// `None` for a procedure.
    pub ret: Option<Ty>,
    pub native: Option<Native>,
    pub span: Span,
    /// The body, once seen (a package body completes its package's declarations).
    pub body: RefCell<Option<Rc<Body<'a>>>>,
    /// Lowered instances in the design, by the actual signals of the signal parameters and
    /// the bounds of the actuals of unconstrained array parameters.
    pub instances: RefCell<Vec<Instance>>,
}

#[derive(Clone, Debug)]
pub struct Param<'a> {
    pub name: String,
    /// Where the parameter is declared.
    pub span: Span,
    pub ty: Ty,
    pub has_default: bool,
    pub default: Option<&'a ast::Expr>,
    /// `signal` parameters are bound to their actual signal; the others are variables of the
    /// subprogram's frame.
    pub is_signal: bool,
    pub mode: ParamMode,
}

/// A subprogram body and the scope it is elaborated in (the declarations visible where the
/// body is written; the variables of an enclosing process are hidden).
pub struct Body<'a> {
    pub decls: &'a [ast::Decl],
    pub stmts: &'a [ast::SeqStmt],
    pub scope: Scope<'a>,
    /// Where the body declares each parameter (a body completing a declaration repeats the
    /// parameters, and names in the body denote the body's).
    pub params: Vec<Span>,
    /// The variables of the enclosing process (or subprogram) that the body may use (LRM
    /// 2.1.1.1): passed to each call after the parameters and, for a procedure, copied back
    /// on return, as `inout` parameters would be. Each with the span of its declaration.
    pub captured: Vec<(Span, VarId, Ty)>,
    /// Per parameter: whether it is an `in` parameter that bounds a declaration of the body
    /// (`variable result : bit_vector(0 to length - 1)`), so calls with a static actual for it
    /// get an instance of their own.
    pub bounding: Vec<bool>,
}

impl std::fmt::Debug for Body<'_> {
    // The scope holds the subprogram itself: printing it would not end.
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        write!(f, "Body({} statements)", self.stmts.len())
    }
}

/// What a stdlib subprogram without body is, natively.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Native {
    Builtin(Builtin),
    /// `log2(x)`, lowered to `log(x) / log(2)`.
    Log2,
    /// `log(x, base)`, lowered to `log(x) / log(base)`.
    LogBase,
    Now,
    /// `frequency`: the analysis frequency in hertz, in spectral source expressions only.
    Frequency,
    Stop,
    Finish,
    /// math_real's `"**"` of a real or integer base and a real exponent.
    Pow,
    /// Text and file input and output, and `deallocate`.
    Io(IoNative),
    /// A native subprogram vams does not implement.
    Missing,
}

/// The native procedures of `std.textio` and the implicit operations of file and access
/// types (which overload each is comes from its parameters' types).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum IoNative {
    ReadLine,
    WriteLine,
    Read,
    Write,
    HRead,
    ORead,
    HWrite,
    OWrite,
    FileOpen,
    FileClose,
    EndFile,
    Deallocate,
}

/// The declarations of a package (and its body's deferred constants).
#[derive(Debug, Default)]
pub struct PackageScope<'a> {
    pub name: String,
    pub items: FxHashMap<String, Vec<Item<'a>>>,
}

/// One declarative region. The items are shared until written (`Rc::make_mut`), so that the
/// use region of a context clause is built once and handed to every instance that has it.
#[derive(Debug, Default, Clone)]
pub struct Region<'a> {
    pub items: Rc<FxHashMap<String, Vec<Item<'a>>>>,
    /// The items declared here by the span of their declaration's identifier: what a name
    /// that analysis resolved denotes (see `Elab::resolved`).
    pub decls: Rc<FxHashMap<Span, Item<'a>>>,
}

#[derive(Debug, Default, Clone)]
pub struct Scope<'a> {
    pub regions: Vec<Region<'a>>,
}

impl<'a> Scope<'a> {
    pub fn new() -> Scope<'a> {
        Scope {
            regions: vec![Region::default()],
        }
    }

    /// A scope whose use region is `used` (shared, copied only if written).
    pub fn with_use_region(used: Region<'a>) -> Scope<'a> {
        Scope {
            regions: vec![used],
        }
    }

    pub fn push(&mut self) {
        self.regions.push(Region::default());
    }

    pub fn pop(&mut self) {
        self.regions.pop();
    }

    /// Declares `name` in the innermost region. Returns false when it is already declared
    /// there and neither declaration is overloadable.
    pub fn declare(&mut self, name: &str, item: Item<'a>) -> bool {
        // Invariant: a scope always has at least its use region.
        let region = self.regions.last_mut().expect("scope has a region");
        let entry = Rc::make_mut(&mut region.items)
            .entry(name.to_string())
            .or_default();
        let clash = entry.iter().any(|old| {
            !(matches!(old, Item::Poison(_)) || old.overloadable() && item.overloadable())
        });
        if clash {
            return false;
        }
        entry.retain(|old| !matches!(old, Item::Poison(_)));
        entry.push(item);
        true
    }

    /// [`Scope::declare`] for a declaration whose identifier is written at `decl`: names that
    /// analysis resolved to it find it by that span.
    pub fn declare_at(&mut self, name: &str, decl: Span, item: Item<'a>) -> bool {
        if !self.declare(name, item.clone()) {
            return false;
        }
        // Invariant: a scope always has at least its use region.
        let region = self.regions.last_mut().expect("scope has a region");
        Rc::make_mut(&mut region.decls).insert(decl, item);
        true
    }

    /// Makes names that analysis resolved to `decl` denote `item` too (an incomplete type
    /// declaration denotes its completion).
    pub fn declared_also_at(&mut self, decl: Span, item: Item<'a>) {
        // Invariant: a scope always has at least its use region.
        let region = self.regions.last_mut().expect("scope has a region");
        Rc::make_mut(&mut region.decls).insert(decl, item);
    }

    /// The item declared at `decl` (the span of its identifier) in the innermost region that
    /// has one.
    pub fn declared(&self, decl: Span) -> Option<&Item<'a>> {
        self.regions.iter().rev().find_map(|r| r.decls.get(&decl))
    }

    /// Makes `item` use-visible (outermost region); repeated imports are harmless.
    pub fn import(&mut self, name: &str, item: Item<'a>) {
        let region = &mut self.regions[0];
        Rc::make_mut(&mut region.items)
            .entry(name.to_string())
            .or_default()
            .push(item);
    }

    /// Replaces the items of `name` in the innermost region that declares it (by their
    /// declarations' spans too, when one item replaces one).
    pub fn replace(&mut self, name: &str, items: Vec<Item<'a>>) {
        for region in self.regions.iter_mut().rev() {
            if let Some(old) = region.items.get(name) {
                if let ([old], [new]) = (old.as_slice(), items.as_slice()) {
                    let at: Vec<Span> = (region.decls.iter())
                        .filter(|(_, item)| item.same(old))
                        .map(|(span, _)| *span)
                        .collect();
                    for span in at {
                        Rc::make_mut(&mut region.decls).insert(span, new.clone());
                    }
                }
                Rc::make_mut(&mut region.items).insert(name.to_string(), items);
                return;
            }
        }
    }

    /// Every item the innermost region declaring `name` holds for it.
    pub fn lookup(&self, name: &str) -> Option<&[Item<'a>]> {
        self.regions
            .iter()
            .rev()
            .find_map(|r| r.items.get(name).filter(|v| !v.is_empty()))
            .map(|v| v.as_slice())
    }

    /// Like [`Scope::lookup`], but when the innermost items are all overloadable the
    /// overloadable items of outer regions come too (a package's `'0'` of `std_ulogic` does
    /// not hide `bit`'s `'0'`, LRM 12.3).
    pub fn lookup_overloads(&self, name: &str) -> Option<Vec<Item<'a>>> {
        let mut out: Vec<Item<'a>> = Vec::new();
        for region in self.regions.iter().rev() {
            let Some(items) = region.items.get(name).filter(|v| !v.is_empty()) else {
                continue;
            };
            if !items.iter().all(Item::overloadable) {
                if out.is_empty() {
                    out.extend(items.iter().cloned());
                }
                break;
            }
            out.extend(items.iter().cloned());
        }
        (!out.is_empty()).then_some(out)
    }

    /// The visible name closest to `name` by edit distance, if close enough to be a typo.
    pub fn suggest(&self, name: &str) -> Option<String> {
        let limit = (name.len() / 3).max(1);
        self.regions
            .iter()
            .flat_map(|r| r.items.keys())
            .filter(|k| !k.starts_with('"') && !k.starts_with('\''))
            .map(|k| (strsim::levenshtein(name, k), k))
            .filter(|(d, _)| *d <= limit)
            .min()
            .map(|(_, k)| k.clone())
    }
}

/// `x, y and z` for help lines.
pub fn list_names(names: &[String]) -> String {
    match names {
        [] => "none".to_string(),
        [one] => format!("`{one}`"),
        _ => {
            let (last, rest) = names.split_last().unwrap_or((&names[0], &[]));
            let rest: Vec<String> = rest.iter().map(|n| format!("`{n}`")).collect();
            format!("{} and `{last}`", rest.join(", "))
        }
    }
}

/// The objects of a record terminal or quantity, one per field (a terminal, a terminal array,
/// a quantity, a quantity array, or a nested record).
#[derive(Debug)]
pub struct RecordObject<'a> {
    pub fields: Vec<(String, Item<'a>)>,
}

impl<'a> RecordObject<'a> {
    pub fn field(&self, name: &str) -> Option<&Item<'a>> {
        self.fields.iter().find(|(f, _)| f == name).map(|(_, i)| i)
    }

    /// Whether its fields are those of `nature` (a port's record nature).
    pub fn is_of(&self, nature: &RecordNature) -> bool {
        self.fields.len() == nature.fields.len()
            && self
                .fields
                .iter()
                .zip(&nature.fields)
                .all(|((a, _), (b, _))| a == b)
    }
}
