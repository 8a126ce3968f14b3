//! Structural and compile errors of the analog system (codes `vams::analog::*`).
//!
//! Every variant points at a span from the design (a user equation's statement, or for
//! generated equations the quantity or terminal declaration) and names the equations and
//! quantities involved, so the message stands on its own when the span is in another file.

use miette::Diagnostic;
use thiserror::Error;

use vams_syntax::diagnostics::Located;
use vams_syntax::source::Span;

#[derive(Clone, Debug, Error, Diagnostic, PartialEq)]
pub enum AnalogError {
    /// More or fewer equations than unknowns.
    ///
    /// Example: `quantity x, y : real; x == 1.0;` (two unknowns, one equation).
    #[error("{equations} equations for {unknowns} unknowns")]
    #[diagnostic(code(vams::analog::count))]
    Count {
        #[label("{label}")]
        span: Span,
        /// What the span shows: a quantity in no equation, or the first equation.
        label: &'static str,
        equations: usize,
        unknowns: usize,
        #[help]
        help: Option<String>,
    },

    /// Some equations constrain fewer quantities than they are (a structurally redundant or
    /// contradictory set, found by the Dulmage-Mendelsohn decomposition).
    ///
    /// Example: `x == 1.0; x == 2.0;` while `y` appears in no equation.
    #[error("over-determined: {count} equations ({equations}) for the quantities {quantities}")]
    #[diagnostic(code(vams::analog::overdetermined))]
    Overdetermined {
        #[label("one of the over-determining equations")]
        span: Span,
        count: usize,
        equations: String,
        quantities: String,
        #[help]
        help: String,
    },

    /// Some quantities appear in fewer equations than they are.
    ///
    /// Example: `x == 1.0; x == 2.0;` with `y` in no equation: `y` is under-determined (and the
    /// two equations over-determine `x`).
    #[error("under-determined: {count} quantities ({quantities}) are fixed only by {equations}")]
    #[diagnostic(
        code(vams::analog::underdetermined),
        help(
            "add an equation for one of these quantities, or connect the terminals they belong \
             to (LRM 1076.1 12.6.6: one equation per quantity)"
        )
    )]
    Underdetermined {
        #[label("one of the under-determined quantities")]
        span: Span,
        count: usize,
        quantities: String,
        equations: String,
    },

    /// Index reduction found no unknown for an equation however often it is differentiated,
    /// or would differentiate a `'delayed` value.
    #[error("cannot reduce the index: {reason}")]
    #[diagnostic(code(vams::analog::index), help("{help}"))]
    Index {
        #[label("this equation")]
        span: Span,
        reason: String,
        help: &'static str,
    },

    /// Terminals with no branch path to their nature's reference: their potentials float.
    ///
    /// Example: a capacitor between `a` and `b`, neither connected to anything else.
    #[error("floating terminals {terminals}: no branch connects them to the reference")]
    #[diagnostic(
        code(vams::analog::floating),
        help(
            "connect one of them to the reference terminal (a resistor to ground, or a port \
             map to a grounded terminal); branches involved: {quantities}"
        )
    )]
    Floating {
        #[label("this terminal floats")]
        span: Span,
        terminals: String,
        quantities: String,
    },

    /// An equation uses something that has no value on the analog side.
    ///
    /// Example: `x == v;` where `v` is a process variable.
    #[error("an equation uses {what}, which the analog solver cannot evaluate")]
    #[diagnostic(
        code(vams::analog::not_analog),
        help("simultaneous statements may use quantities, signals, constants and `now` only")
    )]
    NotAnalog {
        #[label("here")]
        span: Span,
        what: String,
    },

    /// A small-signal (frequency-domain) analysis meets a construct whose frequency response
    /// vams does not compute; it refuses rather than give a wrong number.
    ///
    /// Example: an equation reading `v'zoh(1.0e-3)` in `vams ac`.
    #[error("the frequency-domain analysis does not support {what}")]
    #[diagnostic(code(vams::analog::frequency_domain), help("{help}"))]
    FrequencyDomain {
        #[label("here")]
        span: Span,
        what: String,
        help: String,
    },

    /// A noise source's power spectral density is negative or not a number at a frequency
    /// of the noise analysis.
    ///
    /// Example: `quantity n : real noise 1.0e-16 * (1.0 - frequency / 1.0e3);` above 1 kHz.
    #[error("the noise density of `{name}` is {value:e} at {frequency} Hz")]
    #[diagnostic(
        code(vams::analog::noise_density),
        help(
            "a noise source's density is a power per hertz (units squared per hertz): it must be a finite number at least 0 at every analysed frequency"
        )
    )]
    NoiseDensity {
        #[label("this source")]
        span: Span,
        name: String,
        value: f64,
        frequency: f64,
    },

    /// The design breaks an index invariant of the IR (an elaboration bug, not a model error).
    #[error("malformed design: {what}")]
    #[diagnostic(
        code(vams::analog::malformed),
        help("this is a bug in vams's elaboration; please report it with the model")
    )]
    Malformed {
        #[label("here")]
        span: Span,
        what: String,
    },
}

impl Located for AnalogError {
    fn primary_span(&self) -> Span {
        match self {
            AnalogError::Count { span, .. }
            | AnalogError::Overdetermined { span, .. }
            | AnalogError::Underdetermined { span, .. }
            | AnalogError::Floating { span, .. }
            | AnalogError::Index { span, .. }
            | AnalogError::NotAnalog { span, .. }
            | AnalogError::FrequencyDomain { span, .. }
            | AnalogError::NoiseDensity { span, .. }
            | AnalogError::Malformed { span, .. } => *span,
        }
    }
}

/// What the analog system accepted with a warning (codes `vams::analog::*`).
#[derive(Clone, Debug, Error, Diagnostic, PartialEq)]
pub enum AnalogWarning {
    /// A lone across quantity that an equation sets (`quantity vs across p to m; vs ==
    /// 5.0;`): its branch got an implicit through quantity, as a source's current.
    #[error(
        "`{name}` is set by an equation but has no through quantity: vams gives its branch one"
    )]
    #[diagnostic(
        code(vams::analog::implicit_through),
        severity(Warning),
        help(
            "the branch carries whatever flow the equation needs, like a voltage source; LRM 1076.1 12.6.6 counts only through and free quantities, so other simulators refuse this: declare the flow, `quantity {name} across i_{name} through ...;`"
        )
    )]
    ImplicitThrough {
        #[label("an across quantity without a through quantity")]
        span: Span,
        name: String,
    },
}

impl Located for AnalogWarning {
    fn primary_span(&self) -> Span {
        match self {
            AnalogWarning::ImplicitThrough { span, .. } => *span,
        }
    }
}
