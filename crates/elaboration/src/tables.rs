//! The tables elaboration keeps while it walks the design, one per concern: what waits for a
//! later declaration or the end ([`Pending`]), the implicit signals and driver checks
//! ([`SignalTables`]), the analog side ([`AnalogTables`]) and where the walk is
//! ([`InstanceContext`]). Plain data; the passes that fill and read them are the modules named
//! on each field.

use rustc_hash::FxHashMap;
use std::rc::Rc;

use vams_design::{Expr, QuantityId, SignalId, TerminalId, Value, VarId};
use vams_syntax::ast;
use vams_syntax::source::Span;

use crate::names::scope;
use crate::names::types::{self, Sub};

/// Declarations completed or released later.
#[derive(Default)]
pub(crate) struct Pending<'a> {
    /// Protected types by the span of their name: the methods' declarations and, once seen,
    /// the body's declarations (`protected`).
    pub protected: FxHashMap<Span, (&'a [ast::Decl], Option<&'a [ast::Decl]>)>,
    /// Incomplete type declarations (`type node;`) not completed yet: the name, the span of
    /// its identifier, and the access types declared since that designate it (`decls`).
    pub incomplete: Vec<(String, Span, Vec<Rc<types::AccessTy>>)>,
    /// Every subprogram given a body: the body's scope holds the region that declares the
    /// subprogram (recursion sees itself), an `Rc` cycle that `Elab::release_bodies` breaks
    /// once elaboration is done (else each elaborated design leaked its scopes).
    pub with_bodies: Vec<Rc<scope::Subprogram<'a>>>,
    /// Access types to an incomplete type completed later (`type node; type link is access
    /// node; type node is record next : link; ... end record;`): the record holds the access
    /// type, which holds the record, a cycle `release_bodies` breaks too.
    pub completed_access: Vec<Rc<types::AccessTy>>,
}

/// Implicit signals, views of signals, resolution, and the checks that wait for every process.
#[derive(Default)]
pub(crate) struct SignalTables<'a> {
    /// Implicit `Q'above(level)` signals, one per distinct pair (`analog`).
    pub above: Vec<(QuantityId, Expr, SignalId)>,
    /// Views of signal elements and slices (`SignalKind::View`), one per distinct
    /// `(parent, first, len)` (`views`).
    pub views: FxHashMap<(SignalId, usize, Option<usize>), SignalId>,
    /// The defaults of `out` and `inout` ports associated with an actual signal, with the
    /// instance path they apply in: the initial driving value of the processes under it
    /// that drive the signal. Only the entries of the instances enclosing the current one
    /// are kept (`hier`, `process`).
    pub port_defaults: Vec<(String, SignalId, Value)>,
    /// The user-defined resolution functions that subtypes name (`Sub::resolution` indexes
    /// this), and the signals of such subtypes with their function: each gets an instance
    /// of it per number of driving values once all processes are known
    /// (`Elab::resolve_signals`, in `resolution`).
    pub resolvers: Vec<Rc<scope::Subprogram<'a>>>,
    pub resolved: Vec<(SignalId, usize)>,
    /// The actuals converted from `out` ports (`to_bool(y) => yb`), checked for other
    /// drivers once every process is known (`port_conversions`).
    pub converted_actuals: Vec<(SignalId, Span)>,
    /// The implicit signals of `s'delayed(t)`, by signal and delay (its bits).
    pub delayed: FxHashMap<(SignalId, u64), SignalId>,
    /// `S'transaction` signals by `S`.
    pub transaction: FxHashMap<SignalId, SignalId>,
    /// `S'stable(T)` and `S'quiet(T)` signals by `S`, `T` (its bits) and whether quiet.
    pub stable: FxHashMap<(SignalId, u64, bool), SignalId>,
    /// Disconnection delays of guarded signals in seconds (`disconnect s : t after 3 ns;`).
    pub disconnect_delays: FxHashMap<SignalId, f64>,
    /// The `GUARD` signals of the guarded blocks being elaborated, innermost last: the guard
    /// of a guarded assignment.
    pub guards: Vec<SignalId>,
}

/// A scalar nature of the elaborator's table; it enters the design on first use.
#[derive(Debug)]
pub(crate) struct NatureInfo {
    pub name: String,
    pub across: Rc<Sub>,
    pub through: Rc<Sub>,
    pub id: Option<vams_design::NatureId>,
    /// The nature a subnature with tolerance groups of its own belongs to: its terminals
    /// connect to the base nature's and share its reference terminal.
    pub base: Option<usize>,
}

/// Natures, auxiliary quantities and contributions (`analog`, `attr`, `simultaneous`).
#[derive(Default)]
pub(crate) struct AnalogTables {
    /// The scalar natures, by the index nature marks and items carry.
    pub natures: Vec<NatureInfo>,
    /// Auxiliary quantities of `Q'dot'dot`, by the quantity they derive from.
    pub dot_aux: FxHashMap<QuantityId, QuantityId>,
    /// Auxiliary quantities of `Q'integ`, by the quantity they integrate.
    pub integ_aux: FxHashMap<QuantityId, QuantityId>,
    /// `T'reference` quantities, one per terminal (no region), and `T'contribution` ones, one
    /// per terminal and instance path.
    pub terminal_attrs: FxHashMap<(TerminalId, Option<String>), QuantityId>,
    /// Each `T'contribution` with its terminal and the instance path it was read in: its
    /// equation sums the through quantities at `T` declared there and below, once every
    /// branch is known (`Elab::contribution_equations`).
    pub contributions: Vec<(QuantityId, TerminalId, String, Span)>,
    /// While a simultaneous procedural is lowered: the variable standing for each `q'dot`
    /// it assigns (`x(1)'dot := ...`); empty elsewhere.
    pub dot_targets: FxHashMap<QuantityId, VarId>,
    /// True while a spectral source's magnitude and phase are lowered: only there may
    /// `frequency` be called (LRM 1076.1 14.2).
    pub in_spectrum: bool,
}

/// Where the walk is in the hierarchy (`hier`, `process`, `attr`).
#[derive(Default)]
pub(crate) struct InstanceContext {
    /// Hierarchical prefix of the objects being declared (`""` at the top, `dut.u_motor`).
    pub path: String,
    /// Instance path of the architecture being elaborated (no block or generate labels).
    pub instance: String,
    /// The label of the process being elaborated, for `'path_name` (`None` outside a
    /// process, and in an unlabelled one).
    pub process_label: Option<String>,
    /// `entity(architecture)` of each design entity elaborated, by its instance path (`""`
    /// for the top), for `'instance_name`.
    pub units: FxHashMap<String, String>,
    /// Unlabelled processes so far, per path (for `_pN` names): the current path and the
    /// paths enclosing it, outermost first.
    pub unlabelled: Vec<(String, usize)>,
    /// Overrides of instance generics by hierarchical name (`dut.u_motor.r`, from `-g` and
    /// sweeps), each with whether an instance took it: one left untaken is an error.
    pub overrides: Vec<(String, String, bool)>,
    /// The hierarchical names of every instance generic met, for the help of an override
    /// that names none.
    pub generics_met: Vec<String>,
}
