//! Elaboration diagnostics (codes `vams::elab::*`), each with the span it is about and a help
//! line saying how to fix it.

use miette::Diagnostic;
use thiserror::Error;

use vams_syntax::diagnostics::Located;
use vams_syntax::source::Span;

#[derive(Clone, Debug, Error, Diagnostic, PartialEq)]
pub enum ElabError {
    /// `x := y;` where `y` is declared nowhere visible.
    #[error("`{name}` is not declared")]
    #[diagnostic(code(vams::elab::undeclared))]
    Undeclared {
        #[label("not found")]
        span: Span,
        name: String,
        #[help]
        help: Option<String>,
    },

    /// `s <= 1.0;` where `s` is a quantity; `q'dot` where `q` is a signal.
    #[error("`{name}` is {found}, but {expected} is needed here")]
    #[diagnostic(code(vams::elab::wrong_class))]
    WrongClass {
        #[label("{found}")]
        span: Span,
        name: String,
        found: String,
        expected: String,
        #[help]
        help: Option<String>,
    },

    /// `x == 2;` with `x` real (VHDL has no implicit conversion).
    #[error("type mismatch: expected {expected}, found {found}")]
    #[diagnostic(code(vams::elab::type_mismatch))]
    TypeMismatch {
        #[label("this is {found}")]
        span: Span,
        expected: String,
        found: String,
        #[help]
        help: Option<String>,
    },

    /// `a + b` with operand types the operator is not defined for.
    #[error("operator `{op}` is not defined for {left} and {right}")]
    #[diagnostic(code(vams::elab::bad_operands))]
    BadOperands {
        #[label("here")]
        span: Span,
        op: String,
        left: String,
        right: String,
        #[help]
        help: Option<String>,
    },

    /// `v := a * b;` with `v : signed(11 downto 0)` and `a * b` of 10 elements: an array
    /// value must have its target's length (LRM 8.4, 8.5; also initial values, and
    /// parameters and results of constrained array subtypes).
    #[error("{message}")]
    #[diagnostic(code(vams::elab::length_mismatch))]
    LengthMismatch {
        #[label("{found} element(s)")]
        span: Span,
        message: String,
        found: i64,
        #[help]
        help: Option<String>,
    },

    /// A generic with no default, no map entry and no override.
    #[error("generic `{name}` of `{entity}` has no value")]
    #[diagnostic(
        code(vams::elab::missing_generic),
        help("give it a value in the generic map, a default in the entity, or `-g {name}=VALUE`")
    )]
    MissingGeneric {
        #[label("declared here without a default")]
        span: Span,
        name: String,
        entity: String,
    },

    /// `generic map (rr => 1.0)` where the entity has no generic `rr`.
    #[error("`{name}` is not a {what} of `{unit}`")]
    #[diagnostic(code(vams::elab::unknown_formal))]
    UnknownFormal {
        #[label("no such {what}")]
        span: Span,
        name: String,
        what: &'static str,
        unit: String,
        #[help]
        help: Option<String>,
    },

    /// `-g rr=1.0` where the top entity has no generic `rr`.
    #[error("the top entity `{entity}` has no generic `{name}`")]
    #[diagnostic(code(vams::elab::unknown_generic))]
    UnknownGeneric {
        #[label("entity declared here")]
        span: Span,
        name: String,
        entity: String,
        #[help]
        help: Option<String>,
    },

    /// `-g dut.u_motr.r=4` where no instance at that path has that generic.
    #[error("no instance of the design has a generic `{name}`")]
    #[diagnostic(code(vams::elab::unknown_instance_generic))]
    UnknownInstanceGeneric {
        name: String,
        #[help]
        help: Option<String>,
    },

    /// `-g r=abc` that is not a literal of the generic's type.
    #[error("`{text}` is not a value of type {ty} for generic `{name}`")]
    #[diagnostic(code(vams::elab::bad_generic_value))]
    BadGenericValue {
        #[label("generic declared here")]
        span: Span,
        name: String,
        text: String,
        ty: String,
        #[help]
        help: Option<String>,
    },

    /// A port actual of the wrong class (a signal for a terminal port, ...).
    #[error("port `{port}` is a {expected} port, but the actual is {found}")]
    #[diagnostic(code(vams::elab::port_class))]
    PortClass {
        #[label("{found}")]
        span: Span,
        port: String,
        expected: String,
        found: String,
        #[help]
        help: Option<String>,
    },

    /// `--top foo` where no entity `foo` exists in library work.
    #[error("there is no entity `{name}` in library work")]
    #[diagnostic(code(vams::elab::unknown_top))]
    UnknownTop {
        #[label("instantiated here")]
        span: Option<Span>,
        name: String,
        #[help]
        help: Option<String>,
    },

    /// An entity without an architecture (or without the named one).
    #[error("entity `{entity}` has no architecture{named}")]
    #[diagnostic(code(vams::elab::no_architecture))]
    NoArchitecture {
        #[label("needed here")]
        span: Span,
        entity: String,
        named: String,
        #[help]
        help: Option<String>,
    },

    /// A value that must be known at elaboration time but reads a signal, a quantity or a
    /// variable.
    #[error("{what} must be a static expression")]
    #[diagnostic(
        code(vams::elab::not_static),
        help("use only literals, constants and generics here (they are fixed at elaboration)")
    )]
    NotStatic {
        #[label("not static")]
        span: Span,
        what: String,
    },

    /// A simultaneous if or case whose branches define different numbers of equations.
    #[error("the branches of this simultaneous {what} have different numbers of equations")]
    #[diagnostic(
        code(vams::elab::branch_equations),
        help(
            "every branch must give the same number of equations ({counts}); add `null;` or an equation such as `q == 0.0;` (LRM 15.2)"
        )
    )]
    BranchEquations {
        #[label("here")]
        span: Span,
        what: &'static str,
        counts: String,
    },

    /// Something that cannot be computed: a division by zero in a constant, an index out of
    /// range, a wrong number of arguments.
    #[error("{message}")]
    #[diagnostic(code(vams::elab::invalid))]
    Invalid {
        #[label("here")]
        span: Span,
        message: String,
        #[help]
        help: Option<String>,
    },

    /// `n(11)` where `n` is declared `(0 to 10)`.
    #[error("index {index} is out of the range of `{name}` ({range})")]
    #[diagnostic(
        code(vams::elab::index_range),
        help("`{name}` is indexed {range}: use an index in that range, or widen its declaration")
    )]
    IndexRange {
        #[label("out of range")]
        span: Span,
        name: String,
        index: i64,
        range: String,
    },

    /// A name declared twice in the same region.
    #[error("`{name}` is already declared in this region")]
    #[diagnostic(
        code(vams::elab::redeclared),
        help("rename one of them (only subprograms and enumeration literals may be overloaded)")
    )]
    Redeclared {
        #[label("second declaration")]
        span: Span,
        name: String,
    },

    /// A construct vams does not elaborate yet.
    #[error("not supported yet: {what}")]
    #[diagnostic(code(vams::elab::unsupported))]
    Unsupported {
        #[label("here")]
        span: Span,
        what: String,
        #[help]
        help: Option<String>,
    },
}

impl Located for ElabError {
    fn primary_span(&self) -> Span {
        match self {
            ElabError::UnknownTop { span, .. } => span.unwrap_or_default(),
            // Named on the command line or in a sweep spec, not in the sources.
            ElabError::UnknownInstanceGeneric { .. } => Span::default(),
            ElabError::Undeclared { span, .. }
            | ElabError::WrongClass { span, .. }
            | ElabError::TypeMismatch { span, .. }
            | ElabError::BadOperands { span, .. }
            | ElabError::LengthMismatch { span, .. }
            | ElabError::MissingGeneric { span, .. }
            | ElabError::UnknownFormal { span, .. }
            | ElabError::UnknownGeneric { span, .. }
            | ElabError::BadGenericValue { span, .. }
            | ElabError::PortClass { span, .. }
            | ElabError::NoArchitecture { span, .. }
            | ElabError::NotStatic { span, .. }
            | ElabError::BranchEquations { span, .. }
            | ElabError::Invalid { span, .. }
            | ElabError::IndexRange { span, .. }
            | ElabError::Redeclared { span, .. }
            | ElabError::Unsupported { span, .. } => *span,
        }
    }
}

impl ElabError {
    pub fn unsupported(span: Span, what: impl Into<String>, help: impl Into<String>) -> ElabError {
        ElabError::Unsupported {
            span,
            what: what.into(),
            help: Some(help.into()),
        }
    }

    pub fn invalid(span: Span, message: impl Into<String>, help: Option<String>) -> ElabError {
        ElabError::Invalid {
            span,
            message: message.into(),
            help,
        }
    }
}

/// What is legal but probably not meant; elaboration goes on.
#[derive(Clone, Debug, Error, Diagnostic, PartialEq)]
pub enum ElabWarning {
    /// `u : component fpu` where no entity `fpu` is visible and nothing configures `u`.
    #[error(
        "component instance `{label}` is unbound: library `{library}` has no entity `{component}`"
    )]
    #[diagnostic(
        code(vams::elab::unbound),
        severity(Warning),
        help(
            "it is elaborated as nothing (LRM 5.2.2); pass the file that declares entity `{component}`, or bind the instance with `for {label} : {component} use entity lib.e(arch);`"
        )
    )]
    Unbound {
        #[label("no entity binds this component")]
        span: Span,
        label: String,
        component: String,
        library: String,
    },
    /// `function exp (x : real) return real;` with no body anywhere.
    #[error("the function `{name}` has no body: its calls compute the built-in `{name}`")]
    #[diagnostic(
        code(vams::elab::builtin_stand_in),
        severity(Warning),
        help(
            "VHDL requires a body (in the package body); `use ieee.math_real.all;` declares the standard elementary functions (and `x ** y` for a power) instead"
        )
    )]
    BuiltinStandIn {
        #[label("declared without a body")]
        span: Span,
        name: String,
    },
    /// `nature electrical is real across real through;`
    #[error("the nature `{nature}` names no reference terminal")]
    #[diagnostic(
        code(vams::elab::unnamed_reference),
        severity(Warning),
        help(
            "VHDL-AMS requires one (`... through {nature}_ref reference;`, LRM 1076.1 4.8); vams gives it one without a name, reached as `{nature}'reference`"
        )
    )]
    UnnamedReference {
        #[label("no `... reference` here")]
        span: Span,
        nature: String,
    },
}

impl From<&vams_design::DesignWarning> for ElabWarning {
    fn from(w: &vams_design::DesignWarning) -> ElabWarning {
        match w {
            vams_design::DesignWarning::Unbound(u) => ElabWarning::Unbound {
                span: u.span,
                label: u.label.clone(),
                component: u.component.clone(),
                library: u.library.clone(),
            },
            vams_design::DesignWarning::BuiltinStandIn { name, span } => {
                ElabWarning::BuiltinStandIn {
                    span: *span,
                    name: name.clone(),
                }
            }
            vams_design::DesignWarning::UnnamedReference { nature, span } => {
                ElabWarning::UnnamedReference {
                    span: *span,
                    nature: nature.clone(),
                }
            }
        }
    }
}

impl Located for ElabWarning {
    fn primary_span(&self) -> Span {
        match self {
            ElabWarning::Unbound { span, .. }
            | ElabWarning::BuiltinStandIn { span, .. }
            | ElabWarning::UnnamedReference { span, .. } => *span,
        }
    }
}
