//! SPICE diagnostics as data.
//!
//! Takes nothing; gives [`SpiceError`], the one enum of everything the reader and `flatten`
//! report (codes `vams::spice::*`), each variant with the [`Span`] of the exact token it is
//! about, a label, and a help line saying how to fix it. It implements
//! [`vams_syntax::diagnostics::Located`], so `render_plain` and `Finding` show SPICE
//! diagnostics exactly as they show VHDL ones. Warnings are variants too (their miette severity
//! says so, [`SpiceError::is_warning`]); the reader and `flatten` keep them apart from errors.

use miette::Diagnostic;
use thiserror::Error;
use vams_syntax::diagnostics::Located;
use vams_syntax::source::Span;

/// `" (did you mean `x`?)"` or nothing: the tail of a help line.
pub(crate) fn did_you_mean(suggestion: &Option<String>) -> String {
    match suggestion {
        Some(s) => format!("did you mean `{s}`? "),
        None => String::new(),
    }
}

/// `1 node`, `2 nodes`.
pub(crate) fn plural(n: usize, what: &str) -> String {
    if n == 1 {
        format!("1 {what}")
    } else {
        format!("{n} {what}s")
    }
}

/// Everything the SPICE frontend reports.
#[derive(Clone, Debug, Error, Diagnostic, PartialEq)]
pub enum SpiceError {
    /// `r1 a b 1k }` (a character that starts no SPICE token here)
    #[error("unexpected `{text}`")]
    #[diagnostic(
        code(vams::spice::bad_token),
        help("remove it, or put the value in braces: `{{...}}` holds an expression")
    )]
    BadToken {
        #[label("not a SPICE token")]
        span: Span,
        text: String,
    },

    /// `r1 a b {1k*2` (no closing brace on the line)
    #[error("unterminated {what}")]
    #[diagnostic(
        code(vams::spice::unterminated),
        help("close it with `{closer}` on the same line")
    )]
    Unterminated {
        #[label("starts here")]
        span: Span,
        what: &'static str,
        closer: &'static str,
    },

    /// `.tran 1n` (a card or element missing a field, or with a wrong one)
    #[error("{message}")]
    #[diagnostic(code(vams::spice::syntax))]
    Syntax {
        #[label("{label}")]
        span: Span,
        message: String,
        label: String,
        #[help]
        help: Option<String>,
    },

    /// `r1 a b 1k5` (a value that is no SPICE number)
    #[error("`{text}` is not a number")]
    #[diagnostic(
        code(vams::spice::bad_number),
        help(
            "write digits, an optional exponent and an optional scale factor (t g meg k m u n p f mil), e.g. `1.5k` or `2e-9`{extra}"
        )
    )]
    BadNumber {
        #[label("{reason}")]
        span: Span,
        text: String,
        reason: &'static str,
        extra: &'static str,
    },

    /// `.param x={((((...))))}` nested past the limit
    #[error("expression nested more than {limit} deep")]
    #[diagnostic(
        code(vams::spice::too_deep),
        help("split it into several `.param` lines")
    )]
    TooDeep {
        #[label("this level is too deep")]
        span: Span,
        limit: usize,
    },

    /// `{sqr(2)}`
    #[error("unknown function `{name}`")]
    #[diagnostic(
        code(vams::spice::unknown_function),
        help("{}the functions are {known}", did_you_mean(suggestion))
    )]
    UnknownFunction {
        #[label("no such function")]
        span: Span,
        name: String,
        suggestion: Option<String>,
        known: &'static str,
    },

    /// `{pow(2)}`
    #[error("`{name}` takes {expected}, not {found}")]
    #[diagnostic(code(vams::spice::arity), help("call it as `{usage}`"))]
    Arity {
        #[label("{found} given")]
        span: Span,
        name: String,
        expected: String,
        found: usize,
        usage: &'static str,
    },

    /// `r1 a b {rr}` with no `.param rr`
    #[error("unknown parameter `{name}`")]
    #[diagnostic(
        code(vams::spice::unknown_param),
        help(
            "{}define it with `.param {name}=...` (or in the subcircuit's `params:`)",
            did_you_mean(suggestion)
        )
    )]
    UnknownParam {
        #[label("not defined here")]
        span: Span,
        name: String,
        suggestion: Option<String>,
    },

    /// `{1/(a-a)}`
    #[error("division by zero")]
    #[diagnostic(
        code(vams::spice::division_by_zero),
        help("the divisor evaluates to 0 here; check the parameters it uses")
    )]
    DivisionByZero {
        #[label("this divisor is 0")]
        span: Span,
    },

    /// `{sqrt(-1)}`, `{exp(1000)}`
    #[error("the value of this expression is not a finite number")]
    #[diagnostic(
        code(vams::spice::not_finite),
        help("it evaluates to {what}; a SPICE value must be a finite number")
    )]
    NotFinite {
        #[label("evaluates to {what}")]
        span: Span,
        what: &'static str,
    },

    /// `.param a={b} b={a+1}`
    #[error("parameter `{name}` is defined in terms of itself")]
    #[diagnostic(
        code(vams::spice::param_cycle),
        help(
            "the definitions form a cycle: {cycle}; give one of them a value that does not depend on the others"
        )
    )]
    ParamCycle {
        #[label("used in its own definition")]
        span: Span,
        name: String,
        cycle: String,
    },

    /// `.fourier v(1)` (no such card)
    #[error("unknown card `{card}`")]
    #[diagnostic(code(vams::spice::unknown_card))]
    UnknownCard {
        #[label("not a SPICE card")]
        span: Span,
        card: String,
        #[help]
        help: String,
    },

    /// `y1 a b 1k` (no element starts with `y`)
    #[error("unknown element `{name}`")]
    #[diagnostic(code(vams::spice::unknown_element))]
    UnknownElement {
        #[label("`{letter}` starts no element vams reads")]
        span: Span,
        name: String,
        letter: char,
        #[help]
        help: String,
    },

    /// `.include "missing.lib"`
    #[error("cannot read `{path}`: {reason}")]
    #[diagnostic(
        code(vams::spice::include_not_found),
        help("the path is relative to the including file's folder; check its name")
    )]
    IncludeNotFound {
        #[label("included here")]
        span: Span,
        path: String,
        reason: String,
    },

    /// `a.cir` includes `b.cir`, which includes `a.cir`
    #[error("`{path}` includes itself")]
    #[diagnostic(
        code(vams::spice::include_cycle),
        help("the includes form a cycle: {chain}; remove one of them")
    )]
    IncludeCycle {
        #[label("this include closes the cycle")]
        span: Span,
        path: String,
        chain: String,
    },

    /// `.lib models.lib fast` where `models.lib` has no `.lib fast`
    #[error("`{file}` has no library section `{section}`")]
    #[diagnostic(
        code(vams::spice::lib_section),
        help("{}the sections in it are: {available}", did_you_mean(suggestion))
    )]
    LibSection {
        #[label("no such section")]
        span: Span,
        file: String,
        section: String,
        suggestion: Option<String>,
        available: String,
    },

    /// `.subckt amp a b` with no `.ends`
    #[error("subcircuit `{name}` is not closed")]
    #[diagnostic(
        code(vams::spice::unclosed_subckt),
        help("end its body with `.ends {name}`")
    )]
    UnclosedSubckt {
        #[label("opened here")]
        span: Span,
        name: String,
    },

    /// `.ends` outside any `.subckt`, `.endl` outside a `.lib` section
    #[error("`{card}` closes nothing")]
    #[diagnostic(
        code(vams::spice::stray_end),
        help("remove it, or open the block it closes before it")
    )]
    StrayEnd {
        #[label("nothing open here")]
        span: Span,
        card: String,
    },

    /// `.subckt amp ...` ... `.ends buf`
    #[error("`.ends {found}` closes subcircuit `{expected}`")]
    #[diagnostic(
        code(vams::spice::ends_name),
        help("write `.ends {expected}`, or `.ends` alone")
    )]
    EndsName {
        #[label("should be `{expected}`")]
        span: Span,
        found: String,
        expected: String,
    },

    /// Two `.subckt amp` (or two `.model m`) in one scope
    #[error("{what} `{name}` is defined twice")]
    #[diagnostic(
        code(vams::spice::duplicate_definition),
        help("rename one of them (the first is at line {first_line} of {first_file})")
    )]
    DuplicateDefinition {
        #[label("defined again here")]
        span: Span,
        what: &'static str,
        name: String,
        first_line: usize,
        first_file: String,
    },

    /// `.model m1 bjt(...)`
    #[error("unknown model type `{kind}`")]
    #[diagnostic(
        code(vams::spice::unknown_model_type),
        help(
            "{}the model types are r c l d npn pnp njf pjf nmos pmos sw csw",
            did_you_mean(suggestion)
        )
    )]
    UnknownModelType {
        #[label("not a model type")]
        span: Span,
        kind: String,
        suggestion: Option<String>,
    },

    /// `x1 a b amp` with no `.subckt amp`
    #[error("unknown subcircuit `{name}`")]
    #[diagnostic(
        code(vams::spice::unknown_subckt),
        help(
            "{}define it with `.subckt {name} ...` ... `.ends`, or `.include` the file that does",
            did_you_mean(suggestion)
        )
    )]
    UnknownSubckt {
        #[label("no such subcircuit in scope")]
        span: Span,
        name: String,
        suggestion: Option<String>,
    },

    /// `x1 a b amp` where `.subckt amp in out vdd`
    #[error(
        "`{instance}` connects {}, but subcircuit `{subckt}` has {}",
        plural(*.found, "node"),
        plural(*.expected, "port")
    )]
    #[diagnostic(
        code(vams::spice::node_count),
        help("give one node per port of `.subckt {subckt} {ports}`")
    )]
    SubcktNodeCount {
        #[label("these nodes")]
        span: Span,
        instance: String,
        subckt: String,
        expected: usize,
        found: usize,
        ports: String,
    },

    /// `.subckt a ...` instantiates `b`, which instantiates `a`
    #[error("subcircuit `{name}` instantiates itself")]
    #[diagnostic(
        code(vams::spice::recursive_subckt),
        help("the instances form a cycle: {chain}; a subcircuit cannot contain itself")
    )]
    RecursiveSubckt {
        #[label("this instance closes the cycle")]
        span: Span,
        name: String,
        chain: String,
    },

    /// `x1 a b amp gain=3` where `amp` has no parameter `gain`
    #[error("subcircuit `{subckt}` has no parameter `{name}`")]
    #[diagnostic(
        code(vams::spice::unknown_instance_param),
        help("{}its parameters are: {known}", did_you_mean(suggestion))
    )]
    UnknownInstanceParam {
        #[label("not a parameter of `{subckt}`")]
        span: Span,
        name: String,
        subckt: String,
        suggestion: Option<String>,
        known: String,
    },

    /// `d1 a k dmod` with no `.model dmod`
    #[error("unknown model `{name}`")]
    #[diagnostic(
        code(vams::spice::unknown_model),
        help(
            "{}define it with `.model {name} {kind} (...)`",
            did_you_mean(suggestion)
        )
    )]
    UnknownModel {
        #[label("no such model in scope")]
        span: Span,
        name: String,
        kind: &'static str,
        suggestion: Option<String>,
    },

    /// `d1 a k qmod` where `qmod` is an `npn` model
    #[error("`{element}` needs {wanted} model, but `{model}` is `{found}`")]
    #[diagnostic(
        code(vams::spice::model_kind),
        help("name {wanted} model here, or change the type on the `.model` line")
    )]
    ModelKind {
        #[label("`{model}` is a `{found}` model")]
        span: Span,
        element: String,
        model: String,
        wanted: &'static str,
        found: String,
    },

    /// Two elements that flatten to the same name
    #[error("element `{name}` is defined twice")]
    #[diagnostic(
        code(vams::spice::duplicate_element),
        help("element names are unique in a circuit and within each subcircuit body; rename one")
    )]
    DuplicateElement {
        #[label("defined again here")]
        span: Span,
        name: String,
        /// The first definition, when it is in the same file.
        #[label("first defined here")]
        first: Option<Span>,
    },

    /// `f1 a b vx 2` with no `vx` in the same scope
    #[error("unknown {what} `{name}`")]
    #[diagnostic(
        code(vams::spice::unknown_reference),
        help("{}{hint}", did_you_mean(suggestion))
    )]
    UnknownReference {
        #[label("no such {what}")]
        span: Span,
        what: &'static str,
        name: String,
        suggestion: Option<String>,
        hint: &'static str,
    },

    /// `f1 a b r1 2` (the controlling element must be a voltage source)
    #[error("`{name}` is not {wanted}")]
    #[diagnostic(code(vams::spice::wrong_reference), help("{hint}"))]
    WrongReference {
        #[label("a {found}")]
        span: Span,
        name: String,
        wanted: &'static str,
        found: &'static str,
        hint: &'static str,
    },

    /// `.tran 0 1m`
    #[error("{what} must be {must}")]
    #[diagnostic(code(vams::spice::invalid_value), help("{help}"))]
    InvalidValue {
        #[label("this is {value}")]
        span: Span,
        what: String,
        must: &'static str,
        value: String,
        help: &'static str,
    },

    /// `q1 c b e npn1` when lowering to a design (an element kind, model parameter, option
    /// or card the lowering does not handle yet)
    #[error("{what} is not supported yet")]
    #[diagnostic(code(vams::spice::not_supported), help("{help}"))]
    NotSupported {
        #[label("{label}")]
        span: Span,
        what: String,
        label: String,
        help: String,
    },

    /// Subcircuits nested (instantiated within one another) deeper than the limit
    #[error("subcircuit instances nested more than {limit} deep")]
    #[diagnostic(
        code(vams::spice::hierarchy_too_deep),
        help("flatten part of the hierarchy: {chain}")
    )]
    HierarchyTooDeep {
        #[label("this instance is too deep")]
        span: Span,
        limit: usize,
        chain: String,
    },

    /// A `.control` ... `.endc` block (warning: skipped)
    #[error("`.control` block skipped")]
    #[diagnostic(
        code(vams::spice::control_skipped),
        severity(Warning),
        help(
            "vams runs the analyses of the deck's dot-cards (`.tran`, `.ac`, `.dc`, `.op`); nutmeg scripts are not run"
        )
    )]
    ControlSkipped {
        #[label("skipped up to its `.endc`")]
        span: Span,
    },

    /// A card read but ignored (warning), e.g. `.width`
    #[error("`{card}` ignored")]
    #[diagnostic(code(vams::spice::ignored_card), severity(Warning), help("{why}"))]
    IgnoredCard {
        #[label("has no effect in vams")]
        span: Span,
        card: String,
        why: &'static str,
    },

    /// A deck with no `.end` (warning)
    #[error("the deck has no `.end`")]
    #[diagnostic(
        code(vams::spice::no_end),
        severity(Warning),
        help("end the deck with a `.end` line; SPICE stops reading there")
    )]
    NoEnd {
        #[label("the deck ends here")]
        span: Span,
    },
}

impl SpiceError {
    /// The token the diagnostic is about.
    pub fn span(&self) -> Span {
        use SpiceError::*;
        match self {
            BadToken { span, .. }
            | Unterminated { span, .. }
            | Syntax { span, .. }
            | BadNumber { span, .. }
            | TooDeep { span, .. }
            | UnknownFunction { span, .. }
            | Arity { span, .. }
            | UnknownParam { span, .. }
            | DivisionByZero { span }
            | NotFinite { span, .. }
            | ParamCycle { span, .. }
            | UnknownCard { span, .. }
            | UnknownElement { span, .. }
            | IncludeNotFound { span, .. }
            | IncludeCycle { span, .. }
            | LibSection { span, .. }
            | UnclosedSubckt { span, .. }
            | StrayEnd { span, .. }
            | EndsName { span, .. }
            | DuplicateDefinition { span, .. }
            | UnknownModelType { span, .. }
            | UnknownSubckt { span, .. }
            | SubcktNodeCount { span, .. }
            | RecursiveSubckt { span, .. }
            | UnknownInstanceParam { span, .. }
            | UnknownModel { span, .. }
            | ModelKind { span, .. }
            | DuplicateElement { span, .. }
            | UnknownReference { span, .. }
            | WrongReference { span, .. }
            | InvalidValue { span, .. }
            | NotSupported { span, .. }
            | HierarchyTooDeep { span, .. }
            | ControlSkipped { span }
            | IgnoredCard { span, .. }
            | NoEnd { span } => *span,
        }
    }

    /// Whether it is a warning (the deck is still usable) rather than an error.
    pub fn is_warning(&self) -> bool {
        self.severity() == Some(miette::Severity::Warning)
    }

    /// A syntax error: `message` as the headline, `label` on the token, and a help line.
    pub(crate) fn syntax(
        span: Span,
        message: impl Into<String>,
        label: impl Into<String>,
        help: impl Into<String>,
    ) -> SpiceError {
        let help = help.into();
        SpiceError::Syntax {
            span,
            message: message.into(),
            label: label.into(),
            help: (!help.is_empty()).then_some(help),
        }
    }
}

impl Located for SpiceError {
    fn primary_span(&self) -> Span {
        self.span()
    }
}
