//! Declarations and visibility: the declaration arena, declarative regions (a package's,
//! an entity's, a process's) and the stack of regions visible at a point of a unit.

use rustc_hash::FxHashMap;

use vams_syntax::ast::ObjectClass;
use vams_syntax::source::Span;

use super::types::TypeId;

pub use super::ids::{DeclId, NatureId, RegionId};

/// A nature's across and through types (unknown for composite natures).
#[derive(Clone, Debug, PartialEq)]
pub struct Nature {
    pub name: String,
    pub across: TypeId,
    pub through: TypeId,
}

/// One declared name. Implicit declarations (the predefined operators of a type) carry the
/// span of the type declaration that brings them.
#[derive(Clone, Debug, PartialEq)]
pub struct Declaration {
    /// Lower case; operators as `"+"`, character literals as `'0'`.
    pub name: String,
    pub span: Span,
    pub kind: DeclKind,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    pub name: String,
    pub class: ObjectClass,
    pub ty: TypeId,
    pub has_default: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Signature {
    pub params: Vec<Param>,
    /// `Some` for a function.
    pub result: Option<TypeId>,
    pub purity: Purity,
}

/// What kind of subprogram, as far as the staticness of a call goes (LRM 7.4).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Purity {
    /// A predefined operator: locally static with locally static operands.
    Predefined,
    /// A pure function: globally static with globally static arguments.
    Pure,
    /// An impure function, a procedure, an implicit file or access subprogram: never static.
    Impure,
}

/// How static an expression is (LRM 7.4), ordered so that a compound expression is as static
/// as the least static of its parts.
#[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord, Hash)]
pub enum Staticness {
    /// Its value depends on the simulation (a signal, a variable, a call of `now`), or on a
    /// subprogram call's actuals (a parameter), or analysis cannot tell.
    None,
    /// Known once the design is elaborated (generics, constants, pure calls of those).
    Global,
    /// Known when the unit is analysed (literals, constants initialised with such).
    Local,
}

#[derive(Clone, Debug, PartialEq)]
pub enum DeclKind {
    Library,
    /// A package, entity or component: its declarations are in the region.
    Package(RegionId),
    Entity(RegionId),
    Component(RegionId),
    /// A constant, generic, signal, port, variable, file, parameter or quantity; `value`: how
    /// static its value is as a primary of an expression.
    Object {
        class: ObjectClass,
        ty: TypeId,
        value: Staticness,
    },
    Terminal(NatureId),
    Type(TypeId),
    Nature(NatureId),
    EnumLiteral(TypeId),
    /// A unit of a physical type (`ns`).
    Unit(TypeId),
    Subprogram(Signature),
    Alias(TypeId),
    Attribute(TypeId),
    /// Something analysis does not model yet: names resolve to it without diagnostics and
    /// its uses have an unknown type.
    Opaque,
}

impl DeclKind {
    /// Subprograms and enumeration literals overload; everything else hides.
    pub fn overloadable(&self) -> bool {
        matches!(self, DeclKind::Subprogram(_) | DeclKind::EnumLiteral(_))
    }
}

/// The names declared in one declarative region, each with its declarations in order.
#[derive(Clone, Debug, Default)]
pub struct Region {
    pub names: FxHashMap<String, Vec<DeclId>>,
}

impl Region {
    pub fn add(&mut self, name: &str, id: DeclId) {
        self.names.entry(name.to_string()).or_default().push(id);
    }

    /// Adds `id` behind the declarations of `name` already here, so that those win (the
    /// last declaration of a region wins a non-overloadable name).
    pub fn add_behind(&mut self, name: &str, id: DeclId) {
        self.names
            .entry(name.to_string())
            .or_default()
            .insert(0, id);
    }
}

/// What an interface list declares.
#[derive(Clone, Copy, PartialEq)]
pub enum InterfaceRole {
    Generic,
    Port,
    Parameter,
}

/// Two signatures that declare the same subprogram (homographs).
pub(super) fn same_profile(a: &Signature, b: &Signature) -> bool {
    a.result == b.result
        && a.params.len() == b.params.len()
        && a.params.iter().zip(&b.params).all(|(x, y)| x.ty == y.ty)
}
