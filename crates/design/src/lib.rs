//! The elaborated design: the plain data that elaboration produces and simulation consumes.
//!
//! **Owns** the flattened model: terminals (nodes, one reference terminal per nature),
//! quantities (across, through and free unknowns), simultaneous equations as residual
//! expression trees, signals (including the implicit `Q'above(E)` signals), and processes lowered
//! to a flat instruction list with jumps. Every name is resolved to an index; every constant and
//! generic is folded to a number; no AST node and no scope survives here.
//!
//! **Invariants** (established by `elaborate`, relied on by `analog` and `kernel`):
//! * every `QuantityId`, `TerminalId`, `SignalId`, `NatureId`, `VarId` inside an expression or
//!   instruction indexes the corresponding vector of the same [`Design`] (or the process's
//!   `vars`);
//! * a quantity port is the same `QuantityId` as its actual, a terminal port the same
//!   `TerminalId`, a signal port the same `SignalId` (ports are aliases, never copies);
//! * jump targets are valid indices into the process's `code`, and every path through `code`
//!   reaches a `Wait` or `Halt` (a process never runs off the end: elaboration appends
//!   `Jump(0)`);
//! * equation residuals only use the analog subset of [`Expr`] (see [`Expr::is_analog`]).
//!
//! Names are hierarchical paths relative to the top, lower case, dot separated: `vref`,
//! `dut.u_motor.i`, `dut.u_ic.up`.

pub mod build;
pub mod pwl;

use std::sync::Arc;

use vams_syntax::source::Span;

macro_rules! id_type {
    ($($(#[$doc:meta])* $name:ident),* $(,)?) => {$(
        $(#[$doc])*
        #[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
        pub struct $name(pub u32);

        impl $name {
            pub fn index(self) -> usize {
                self.0 as usize
            }
        }
    )*};
}

id_type! {
    /// Index into [`Design::quantities`].
    QuantityId,
    /// Index into [`Design::terminals`].
    TerminalId,
    /// Index into [`Design::natures`].
    NatureId,
    /// Index into [`Design::signals`].
    SignalId,
    /// Index into [`Process::vars`] of the process that uses it (in a subprogram's code: into
    /// [`Subprogram::vars`]).
    VarId,
    /// Index into [`Design::subprograms`].
    SubprogramId,
}

/// A whole elaborated model.
#[derive(Clone, Debug, Default)]
pub struct Design {
    /// Name of the top entity (lower case).
    pub top: String,
    pub natures: Vec<Nature>,
    pub terminals: Vec<Terminal>,
    pub quantities: Vec<Quantity>,
    pub equations: Vec<Equation>,
    pub signals: Vec<Signal>,
    pub processes: Vec<Process>,
    /// `limit` specifications: the largest step for the quantities listed.
    pub limits: Vec<Limit>,
    /// User-defined functions and procedures with bodies, one per distinct set of actual
    /// signals of their signal parameters (those are bound at elaboration).
    pub subprograms: Vec<Subprogram>,
    /// `Q'delayed(T)` lines: each defines its output quantity from the input's history.
    pub delays: Vec<Delay>,
    /// `Q'zoh` and `Q'ztf`: realised by generated processes in time; kept for the frequency
    /// domain, where each is a transfer from its input quantity.
    pub sampled: Vec<Sampled>,
    /// File objects (`file f : text open write_mode is "log.txt";`), by the number a
    /// [`Value::File`] holds.
    pub files: Vec<FileObject>,
    /// The initial values (records of their private variables) of the shared variables of
    /// protected type: the kernel puts them on the heap first, in order, so that the `k`-th
    /// is `Value::Access(k + 1)`.
    pub shared_objects: Vec<Value>,
    /// Across quantities declared without a through quantity (`quantity vs across t1;`):
    /// no flow of their own balances an equation that sets them (the count rule's
    /// diagnostic names them).
    pub lone_across: Vec<QuantityId>,
    /// Simultaneous ifs without `else` whose branches give the same equations: at every
    /// accepted point one of their conditions must hold (the kernel checks).
    pub branch_covers: Vec<BranchCover>,
    /// What elaboration accepted but a user should hear about (an unbound component
    /// instance, a bodiless function standing in for a built-in one).
    pub warnings: Vec<DesignWarning>,
    /// Spectral source quantities (`quantity ac : real spectrum mag, phase;`): zero in the
    /// quiescent and time domains (each has its generated equation `q == 0.0`), the phasor
    /// `mag * e^(j phase)` in a small-signal frequency-domain analysis.
    pub spectral_sources: Vec<SpectralSource>,
    /// Noise source quantities (`quantity n : real noise psd;`): zero in the quiescent and
    /// time domains and in `vams ac` (each has its generated equation `q == 0.0`), an
    /// independent source of power spectral density `psd` in a noise analysis.
    pub noise_sources: Vec<NoiseSource>,
    /// The signal standing for `std.standard.frequency` in spectral expressions (an implicit
    /// real signal nothing drives: 0 outside the frequency domain, where no expression that
    /// reads it is evaluated); `None` when no spectral expression calls `frequency`.
    pub frequency_signal: Option<SignalId>,
}

/// A spectral source quantity (LRM 1076.1 4.3.1.6, 12.6.4).
#[derive(Clone, Debug)]
pub struct SpectralSource {
    pub quantity: QuantityId,
    /// The magnitude and the phase (radians) as analog expressions; they may read
    /// [`Design::frequency_signal`] (hertz) and constants.
    pub magnitude: Expr,
    pub phase: Expr,
    /// Index into [`Design::equations`] of its generated equation `q == 0.0`.
    pub equation: usize,
    pub span: Span,
}

/// A noise source quantity (LRM 1076.1 4.3.1.6, 12.6.4).
#[derive(Clone, Debug)]
pub struct NoiseSource {
    pub quantity: QuantityId,
    /// The power spectral density (the quantity's units squared per hertz) as an analog
    /// expression; it may read [`Design::frequency_signal`] (hertz) and constants.
    pub density: Expr,
    /// Index into [`Design::equations`] of its generated equation `q == 0.0`.
    pub equation: usize,
    pub span: Span,
}

/// `if c1 use ... elsif c2 use ... end use;` without `else`: its equations exist only while
/// `condition` (`c1 or c2 ...`) holds; between accepted points the last branch stands in.
#[derive(Clone, Debug)]
pub struct BranchCover {
    pub condition: Expr,
    /// The simultaneous if.
    pub span: Span,
}

/// Something elaboration accepted with a warning.
#[derive(Clone, Debug, PartialEq)]
pub enum DesignWarning {
    /// Elaborated as nothing (LRM 5.2.2).
    Unbound(UnboundInstance),
    /// A function of the user's that has no body anywhere, whose name and profile are those
    /// of an elementary function of `ieee.math_real` (`function exp (x : real) return real;`
    /// in a package without body, as the University of Cincinnati's SEAMS test suite
    /// declares them): calls compute the built-in function.
    BuiltinStandIn {
        /// The function's name as declared.
        name: String,
        /// Its declaration.
        span: Span,
    },
    /// `nature electrical is real across real through;` (SEAMS's dialect): the nature's
    /// reference terminal has no name, `electrical'reference` reaches it.
    UnnamedReference {
        nature: String,
        /// The nature declaration.
        span: Span,
    },
}

/// A component instance whose default binding found no entity of the component's name.
#[derive(Clone, Debug, PartialEq)]
pub struct UnboundInstance {
    /// The instance's label.
    pub label: String,
    pub component: String,
    pub library: String,
    /// The component name in the instantiation.
    pub span: Span,
}

/// A file object of the design: its name for messages, and the file it is opened on at the
/// start of the simulation (LRM 4.3.1.4), if its declaration says one.
#[derive(Clone, Debug, PartialEq)]
pub struct FileObject {
    pub name: String,
    /// The object's declaration.
    pub span: Span,
    pub open: Option<(String, FileMode)>,
}

/// `std.standard.file_open_kind`, by position.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileMode {
    Read,
    Write,
    Append,
}

impl FileMode {
    /// The mode a `file_open_kind` value's position names.
    pub fn from_position(p: u32) -> Option<FileMode> {
        Some(match p {
            0 => FileMode::Read,
            1 => FileMode::Write,
            2 => FileMode::Append,
            _ => return None,
        })
    }
}

/// What a native procedure (`std.textio`'s, and the implicit ones of file and access
/// types) does; its arguments are those of [`Instr::Native`], in parameter order.
#[derive(Clone, Debug, PartialEq)]
pub enum NativeProc {
    /// `readline(f, l)`.
    ReadLine,
    /// `writeline(f, l)`.
    WriteLine,
    /// `read(l, value [, good])` of a value of type `ty`; `good` says whether the call has
    /// the `good` parameter (without it a failed read is an error).
    Read {
        ty: Type,
        good: bool,
    },
    /// `write(l, value, justified, field [, digits | unit])`.
    Write {
        ty: Type,
    },
    /// `hread` / `oread` (`bits` 4 or 3 a digit) of an array of `ty` (`bit_vector`,
    /// `std_ulogic_vector`: its `'0'` and `'1'` are the bits).
    ReadDigits {
        bits: u32,
        good: bool,
        ty: Type,
    },
    /// `hwrite` / `owrite`.
    WriteDigits {
        bits: u32,
        ty: Type,
    },
    /// `file_open([status,] f, name, kind)`.
    FileOpen {
        status: bool,
    },
    /// The opening of a file object declared in a subprogram or process with a name known
    /// only at run time (`file f : text open read_mode is name_parameter;`): arguments the
    /// file, the name and the `file_open_kind`; a file still open from an earlier call is
    /// closed first, so each call reads from the start (LRM 4.3.1.4).
    FileDeclare,
    FileClose,
    /// `read(f, value)` of a file of `ty` (not `text`): one element per line of the file.
    FileRead {
        ty: Type,
    },
    /// `write(f, value)` of a file of `ty`.
    FileWrite {
        ty: Type,
    },
    /// `deallocate(p)`.
    Deallocate,
}

impl Design {
    /// The signal assignments of `code`, directly or in the procedures it calls (a
    /// procedure drives its signal parameters through the calling process's drivers, LRM
    /// 14.7.2): each target with the index of an element assignment. A procedure's code is
    /// visited once.
    pub fn assignments<'d>(&'d self, code: &'d [Instr]) -> Vec<(SignalId, Option<&'d Expr>)> {
        let mut out = Vec::new();
        let mut seen = std::collections::HashSet::new();
        let mut todo = vec![code];
        while let Some(code) = todo.pop() {
            for instr in code {
                match instr {
                    Instr::Assign { target, index, .. } => out.push((*target, index.as_ref())),
                    Instr::Call { sub, .. } => {
                        if let Some(s) = self.subprograms.get(sub.index())
                            && seen.insert(*sub)
                        {
                            todo.push(&s.code);
                        }
                    }
                    _ => {}
                }
            }
        }
        out
    }

    /// The predefined signal `std.standard.domain` (LRM 1076.1, 12.6.4): the simulator's own
    /// phase, `quiescent_domain` while the quiescent point is computed, then `time_domain`.
    /// Every design has it (`std.standard` is always elaborated) unless a test builds one by hand.
    pub fn domain_signal(&self) -> Option<SignalId> {
        self.signals
            .iter()
            .position(|s| {
                s.name == "domain"
                    && matches!(&s.ty, Type::Enum { name, .. } if name == "domain_type")
            })
            .map(|i| SignalId(i as u32))
    }

    /// Gives back the spare capacity of every table: they grew by doubling during elaboration,
    /// and a large design otherwise carries up to half of each unused into simulation.
    pub fn shrink_to_fit(&mut self) {
        self.natures.shrink_to_fit();
        self.terminals.shrink_to_fit();
        self.quantities.shrink_to_fit();
        self.equations.shrink_to_fit();
        self.signals.shrink_to_fit();
        self.processes.shrink_to_fit();
        self.limits.shrink_to_fit();
        self.subprograms.shrink_to_fit();
        self.delays.shrink_to_fit();
    }
}

/// A function or procedure lowered like a process: its frame is `vars` (the variable
/// parameters first, in declaration order, then the locals), its body `code`, which ends in
/// `Return`. Signal parameters do not appear: the body reads and drives the actual signals.
#[derive(Clone, Debug)]
pub struct Subprogram {
    /// Instance path plus name (`tb.r_of`), for run-time errors.
    pub name: String,
    pub kind: SubprogramKind,
    /// Modes of the variable parameters, `vars[0..params.len()]`.
    pub params: Vec<ParamMode>,
    pub vars: Vec<Variable>,
    pub code: Vec<Instr>,
    /// The source statement of each instruction, as for [`Process::spans`].
    pub spans: Vec<Span>,
    pub span: Span,
    /// What the function computes, when it is one of the bundled packages' whose meaning the
    /// kernel knows (it may then evaluate a call without running `code`, which stays the
    /// reference).
    pub intrinsic: Option<Intrinsic>,
}

/// A bundled function the kernel evaluates without running its body, as an instance bound
/// to its actual signal (a user's own function of the same name is never one).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Intrinsic {
    /// `rising_edge(s)` (`rising`) or `falling_edge(s)` of `ieee.std_logic_1164`:
    /// `s'event and to_x01(s) = '1' and to_x01(s'last_value) = '0'` (`'0'` and `'1'`
    /// exchanged for the falling edge).
    StdLogicEdge { signal: SignalId, rising: bool },
    /// `rising_edge(s)` or `falling_edge(s)` of `ieee.numeric_bit`, on a `bit`:
    /// `s'event and s = '1'` (`'0'` for the falling edge).
    BitEdge { signal: SignalId, rising: bool },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SubprogramKind {
    /// Called in expressions; never waits, never assigns signals.
    Function,
    /// Called by [`Instr::Call`]; may wait (the calling process's whole call stack suspends) and
    /// drive signals through the calling process's drivers.
    Procedure,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ParamMode {
    In,
    /// Starts at its type's default; copied back to the actual variable on return.
    Out,
    /// Starts at the actual's value; copied back on return.
    InOut,
}

/// `output == input'delayed(delay)`: the input's value `delay` seconds ago, interpolated from
/// the integrator's accepted points (before time 0, its quiescent value). In the quiescent
/// domain the output equals the input (LRM 1076.1, 14.1). The analog engine owns the history
/// and generates the defining equation.
#[derive(Clone, Debug)]
pub struct Delay {
    pub output: QuantityId,
    pub input: QuantityId,
    /// Seconds, positive.
    pub delay: f64,
    pub span: Span,
}

/// `Q'zoh(T)` or `Q'ztf(num, den, T)`: a generated process samples `input` every `period`
/// seconds and drives the implicit real `signal`, which equations read.
#[derive(Clone, Debug, PartialEq)]
pub struct Sampled {
    pub signal: SignalId,
    pub input: QuantityId,
    /// Seconds, positive.
    pub period: f64,
    /// `'ztf`'s numerator and denominator in ascending powers of `z^-1`; `None` for `'zoh`.
    pub filter: Option<(Vec<f64>, Vec<f64>)>,
    pub span: Span,
}

/// A scalar nature, e.g. `electrical is voltage across current through electrical_ref reference`.
#[derive(Clone, Debug)]
pub struct Nature {
    pub name: String,
    /// Tolerance group of the across type (`"DEFAULT_VOLTAGE"`), if its subtype declares one.
    pub across_tolerance: Option<String>,
    /// Tolerance group of the through type.
    pub through_tolerance: Option<String>,
    /// The nature's reference terminal (potential 0).
    pub reference: TerminalId,
}

/// A terminal: a node of its nature's graph. Scalar only (array terminals are expanded).
#[derive(Clone, Debug)]
pub struct Terminal {
    pub name: String,
    pub nature: NatureId,
    /// True for the nature's reference terminal (`electrical_ref`).
    pub is_reference: bool,
    pub span: Span,
}

/// An analog unknown.
#[derive(Clone, Debug)]
pub struct Quantity {
    pub name: String,
    pub kind: QuantityKind,
    /// Tolerance group from the quantity's subtype (`"DEFAULT_CURRENT"`), if any; shared
    /// like `subtype`.
    pub tolerance: Option<Arc<str>>,
    /// Name of the quantity's subtype (`voltage`, `angular_velocity`, `real`), shared by the
    /// quantities of that subtype (`Arc`: a design is sent to the test runner's threads).
    pub subtype: Arc<str>,
    /// Unit symbol from the subtype's `symbol` attribute (`"V"`, `"rad/s"`), if declared;
    /// shared like `subtype`.
    pub unit: Option<Arc<str>>,
    /// The `:= expr` default, used as the Newton starting guess (not an initial condition).
    pub initial_guess: Option<f64>,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum QuantityKind {
    /// `q = potential(plus) - potential(minus)`.
    Across { plus: TerminalId, minus: TerminalId },
    /// A current-like flow from `plus` through the branch to `minus`: it leaves `plus` and
    /// enters `minus` in the conservation law of each terminal.
    Through { plus: TerminalId, minus: TerminalId },
    /// A free quantity (including quantity ports, which are aliases of their actual).
    Free,
}

/// One simultaneous equation `residual = 0` (from `lhs == rhs`: `lhs - rhs`). A simultaneous
/// if or case becomes one equation per position whose residual is an [`Expr::If`] chain.
#[derive(Clone, Debug)]
pub struct Equation {
    pub residual: Expr,
    /// The statement it came from (the branch's statement for simultaneous if/case: the span of
    /// the first branch).
    pub span: Span,
    /// Instance path of the architecture it came from (`""` for the top).
    pub instance: String,
    /// The source text of the statement, whitespace collapsed, for `vams dae` listings.
    pub text: String,
}

/// A signal, including implicit ones.
#[derive(Clone, Debug)]
pub struct Signal {
    pub name: String,
    pub ty: Type,
    pub init: Value,
    pub kind: SignalKind,
    pub span: Span,
    /// The bounds of an integer subtype, as for [`Variable::range`] (LRM 8.4).
    pub range: Option<(i64, i64)>,
    /// A user-defined resolution function (`subtype wired_or_bit is wired_or bit;`);
    /// `std_logic`'s is built into the kernel.
    pub resolution: Option<Resolution>,
    /// `bus` or `register` (LRM 4.3.1.2): its drivers can be disconnected.
    pub guarded: Option<GuardedKind>,
}

/// The kind of a guarded signal (LRM 4.3.1.2): with every driver disconnected, a `bus`
/// takes its resolution function's value for no drivers, a `register` keeps its value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GuardedKind {
    Bus,
    Register,
}

/// A signal's resolution function, applied to the values of its connected drivers each time
/// one of them is active (LRM 2.4). The function is elaborated once per number of values it
/// can receive (its parameter is an unconstrained array, whose bounds a body is lowered with).
#[derive(Clone, Debug, PartialEq)]
pub struct Resolution {
    /// The function's name, for run-time errors.
    pub name: String,
    /// The function for `k` driving values at index `k`, from 0 to the signal's number of
    /// drivers.
    pub by_count: Vec<SubprogramId>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum SignalKind {
    /// A declared signal or signal port.
    Explicit,
    /// `Q'above(level)`: true while `quantity > level`; its events are threshold crossings located
    /// by the analog solver. `quantity` and `level` are analog expressions (`level` usually a
    /// constant).
    Above { quantity: Expr, level: Expr },
    /// A signal of a process that elaboration generates (the state of `S'ramp`, `S'slew`,
    /// `Q'zoh`, `Q'ztf`): driven like a declared one, but not a probe of its own.
    Implicit,
    /// A name for elements of another signal, `parent`, starting at position `first` (from
    /// the left): one element (`len: None`, a port associated with `bus(3)`) or a slice of
    /// `len` elements (`bus(7 downto 4)`). It has no drivers of its own: assigning it drives
    /// those elements of `parent`, and the kernel derives its value, events and attributes
    /// from theirs. `parent` is never itself a view (views of views are composed).
    View {
        parent: SignalId,
        first: usize,
        len: Option<usize>,
    },
    /// `S'transaction` (LRM 14.1): a `bit` that toggles in each simulation cycle in which
    /// `source` is active; the kernel updates it, nothing drives it.
    Transaction { source: SignalId },
    /// `S'stable(T)` (`quiet`: `S'quiet(T)`, LRM 14.1): a `boolean`, true at first; the
    /// kernel makes it false in each simulation cycle in which `source` has an event (is
    /// active), and true again `delay` seconds after the last one (the next delta cycle for
    /// 0). Nothing drives it.
    Stable {
        source: SignalId,
        delay: f64,
        quiet: bool,
    },
    /// An array port associated element by element (`port map (i(1) => a, i(2) => b)`): its
    /// element `k` is `elements[k]`, a whole scalar signal (`None`) or the element at a
    /// position of an array signal, like a [`SignalKind::View`] of several parents. None of
    /// the parents is a view or a gather.
    Gather {
        elements: Vec<(SignalId, Option<usize>)>,
    },
    /// A signal whose value is a conversion of another's (LRM 4.3.2.2): a port of mode `in`
    /// associated with `to_bit(s)` (`source` the actual `s`), or the actual `yb` of a port
    /// of mode `out` associated as `to_bool(y) => yb` (`source` the port `y`). `conversion`
    /// is the function call or type conversion of `Expr::Signal(source)`. Nothing drives it:
    /// the kernel updates it in the cycle its source is active, without a delta cycle, so
    /// the port and the actual change together.
    Converted { source: SignalId, conversion: Expr },
}

/// A process (explicit, or the equivalent process of a concurrent statement: signal
/// assignment, assertion, break).
#[derive(Clone, Debug)]
pub struct Process {
    /// Instance path plus label (`dut.u_ic.direction`), or a generated `_p3` for unlabelled ones.
    pub name: String,
    pub vars: Vec<Variable>,
    pub code: Vec<Instr>,
    /// The source statement of each instruction, for run-time errors (empty for processes
    /// elaboration generates).
    pub spans: Vec<Span>,
    pub span: Span,
    /// Initial driving values other than the signal's initial value: the defaults of the
    /// `out` and `inout` ports through which the process drives these signals (LRM 12.6.1:
    /// a driver starts at the default value of the port it drives, whatever the actual).
    pub driver_inits: Vec<(SignalId, Value)>,
}

#[derive(Clone, Debug)]
pub struct Variable {
    pub name: String,
    pub ty: Type,
    pub init: Value,
    /// The bounds of an integer subtype (`natural`, `integer range 0 to 7`, `integer`
    /// itself): assigning a value outside them is a run-time error (LRM 8.5).
    pub range: Option<(i64, i64)>,
}

/// The scalar and composite types the kernel handles.
#[derive(Clone, Debug, PartialEq)]
pub enum Type {
    Real,
    Integer,
    Boolean,
    /// Physical type `time`, carried as seconds in an `f64`.
    Time,
    /// Enumeration, e.g. `std_ulogic` or `bit` or `character` or `severity_level`.
    Enum {
        name: String,
        literals: Vec<String>,
    },
    String,
    /// One-dimensional array with integer index bounds `left to/downto right`.
    Array {
        element: Box<Type>,
        left: i64,
        right: i64,
        ascending: bool,
    },
    /// A physical type of the user's own: values are `Value::Integer`s counting the primary
    /// unit; `units` are the units with their values in it, the primary first (for
    /// `'image`, which writes the primary unit, and `'value`).
    Physical {
        name: String,
        units: Vec<(String, i64)>,
    },
    /// A record: its fields in order. Its value is a [`Value::Array`] of the fields' values,
    /// and `Expr::Index` selects a field by its position (from 0).
    Record {
        name: String,
        fields: Vec<(String, Type)>,
    },
    /// An access type (its values are [`Value::Access`]).
    Access {
        name: String,
    },
    /// A file type (its objects are [`Value::File`]s).
    File {
        name: String,
    },
}

impl Type {
    /// `(left, ascending)` of the index that selects an element: an array's own bounds, a
    /// record's field positions from 0, a `string`'s positions from 1.
    pub fn index_origin(&self) -> (i64, bool) {
        match self {
            Type::Array {
                left, ascending, ..
            } => (*left, *ascending),
            Type::Record { .. } => (0, true),
            _ => (1, true),
        }
    }
}

/// A run-time value.
#[derive(Clone, Debug, PartialEq)]
pub enum Value {
    Real(f64),
    Integer(i64),
    Boolean(bool),
    /// Seconds.
    Time(f64),
    /// Position of the literal in its enumeration type.
    Enum(u32),
    String(String),
    Array(Vec<Value>),
    /// An access value: the number of the object it designates on the simulation's heap,
    /// 0 for `null`.
    Access(u32),
    /// A file object, by its index in [`Design::files`].
    File(u32),
}

/// `a sll n` and the other shifts and rotations of LRM 7.2.3 on the elements of a
/// one-dimensional array of bit or boolean, positions counted from the left: `sll` moves
/// elements left and fills with `T'left` (`'0'`, `false`), `sla` fills with the rightmost
/// element, `rol` rotates; a negative count is the opposite operation by `-n`. (Also what
/// elaboration folds constant shifts with.)
pub fn shifted(op: BinaryOp, items: &[Value], n: i64) -> Value {
    use BinaryOp::*;
    let len = items.len();
    if len == 0 {
        return Value::Array(Vec::new());
    }
    let (op, n) = match (op, n < 0) {
        (op, false) => (op, n.unsigned_abs()),
        (Sll, true) => (Srl, n.unsigned_abs()),
        (Srl, true) => (Sll, n.unsigned_abs()),
        (Sla, true) => (Sra, n.unsigned_abs()),
        (Sra, true) => (Sla, n.unsigned_abs()),
        (Rol, true) => (Ror, n.unsigned_abs()),
        (_, true) => (Rol, n.unsigned_abs()),
    };
    // Counts beyond the length shift everything out (rotations wrap).
    let k = usize::try_from(n).unwrap_or(usize::MAX).min(len);
    let fill = |v: &Value| match v {
        Value::Boolean(_) => Value::Boolean(false),
        _ => Value::Enum(0),
    };
    let mut out = items.to_vec();
    match op {
        Rol => out.rotate_left((n % len as u64) as usize),
        Ror => out.rotate_right((n % len as u64) as usize),
        Sll | Sla => {
            let f = if op == Sla {
                items[len - 1].clone()
            } else {
                fill(&items[0])
            };
            out.drain(..k);
            out.extend(std::iter::repeat_n(f, k));
        }
        _ => {
            let f = if op == Sra {
                items[0].clone()
            } else {
                fill(&items[0])
            };
            out.truncate(len - k);
            out.splice(0..0, std::iter::repeat_n(f, k));
        }
    }
    Value::Array(out)
}

/// The value of an array aggregate from its elements in index order: a [`Value::String`]
/// for a character array (`string`), else a [`Value::Array`].
pub fn aggregate_value(elems: Vec<Value>, string: bool) -> Value {
    if string {
        Value::String(
            elems
                .iter()
                .filter_map(|v| match v {
                    Value::Enum(c) => char::from_u32(*c),
                    _ => None,
                })
                .collect(),
        )
    } else {
        Value::Array(elems)
    }
}

/// `T'pos` and `T'val` ([`Builtin::Pos`], [`Builtin::EnumVal`], [`Builtin::TimeVal`]), the
/// same at elaboration (folding) and at run time; `Err` with the reason when the result is
/// outside its type, as VHDL requires.
pub fn scalar_attribute(f: Builtin, args: &[Value]) -> Result<Value, String> {
    match (f, args) {
        (Builtin::Pos, [Value::Enum(p)]) => Ok(Value::Integer(i64::from(*p))),
        (Builtin::Pos, [Value::Boolean(b)]) => Ok(Value::Integer(i64::from(*b))),
        (Builtin::Pos, [Value::Integer(i)]) => Ok(Value::Integer(*i)),
        (Builtin::TimePos | Builtin::Pos, [Value::Time(t)]) => {
            let fs = (t * 1e15).round();
            if fs.abs() < 9.2e18 {
                Ok(Value::Integer(fs as i64))
            } else {
                Err(format!("time'pos of {t} s does not fit an integer"))
            }
        }
        (
            Builtin::EnumVal,
            [
                Value::Integer(i),
                Value::Integer(n),
                Value::Integer(boolean),
            ],
        ) => {
            if (0..*n).contains(i) {
                Ok(if *boolean == 1 {
                    Value::Boolean(*i == 1)
                } else {
                    Value::Enum(*i as u32)
                })
            } else {
                Err(format!(
                    "'val({i}) is outside the type's positions 0 to {}",
                    n - 1
                ))
            }
        }
        (Builtin::TimeVal, [Value::Integer(i)]) => Ok(Value::Time(*i as f64 * 1e-15)),
        _ => Err(format!("{f:?} does not apply to these arguments")),
    }
}

impl Value {
    /// The elements of an array value (a string's characters as enumeration positions); a
    /// scalar is its own one element.
    pub fn elements(&self) -> Vec<Value> {
        match self {
            Value::Array(items) => items.clone(),
            Value::String(s) => s.chars().map(|c| Value::Enum(c as u32)).collect(),
            other => vec![other.clone()],
        }
    }

    /// What a view of `len` elements (one element: `None`) from position `first` shows of
    /// this array value ([`SignalKind::View`]); `None` when they are not all inside it.
    pub fn view(&self, first: usize, len: Option<usize>) -> Option<Value> {
        let elements = self.elements();
        match len {
            None => elements.get(first).cloned(),
            Some(n) => elements
                .get(first..first + n)
                .map(|e| aggregate_value(e.to_vec(), matches!(self, Value::String(_)))),
        }
    }

    /// VHDL's ordering (LRM 7.2.2), the same when elaboration folds and at run time:
    /// numbers by value (an integer beside a real as a real, from folded universal
    /// expressions), times by femtoseconds (`time` is integral; the seconds carried in an
    /// `f64` may have picked up rounding), enumerations by position, strings and arrays of
    /// discrete elements lexicographically. `None` for values that do not compare.
    pub fn order(&self, other: &Value) -> Option<std::cmp::Ordering> {
        use Value::*;
        let fs = |t: f64| (t * 1e15).round();
        match (self, other) {
            (Real(x), Real(y)) => x.partial_cmp(y),
            (Time(x), Time(y)) => fs(*x).partial_cmp(&fs(*y)),
            (Integer(x), Integer(y)) => Some(x.cmp(y)),
            (Integer(x), Real(y)) => (*x as f64).partial_cmp(y),
            (Real(x), Integer(y)) => x.partial_cmp(&(*y as f64)),
            (Boolean(x), Boolean(y)) => Some(x.cmp(y)),
            (Enum(x), Enum(y)) => Some(x.cmp(y)),
            (String(x), String(y)) => Some(x.cmp(y)),
            (Array(x), Array(y)) => {
                for (p, q) in x.iter().zip(y) {
                    match p.order(q)? {
                        std::cmp::Ordering::Equal => {}
                        o => return Some(o),
                    }
                }
                Some(x.len().cmp(&y.len()))
            }
            _ => None,
        }
    }

    /// The value as a number for the analog side and for waveforms: booleans and enums as
    /// 0/1 (their position), time in seconds; `None` for strings and arrays.
    pub fn as_f64(&self) -> Option<f64> {
        match *self {
            Value::Real(v) | Value::Time(v) => Some(v),
            Value::Integer(i) => Some(i as f64),
            Value::Boolean(b) => Some(if b { 1.0 } else { 0.0 }),
            Value::Enum(p) => Some(p as f64),
            Value::String(_) | Value::Array(_) | Value::Access(_) | Value::File(_) => None,
        }
    }
}

/// Expressions, shared by equations and processes. In equations every value is an `f64`
/// (booleans 0/1); in processes the kernel evaluates them to [`Value`]s.
#[derive(Clone, Debug, PartialEq)]
pub enum Expr {
    Const(Value),
    /// A quantity's value (in processes: at the current analog solution).
    Quantity(QuantityId),
    /// `Q'dot` (first derivative; elaboration introduces auxiliary quantities for higher orders
    /// and for `'integ`).
    Dot(QuantityId),
    /// A signal's current value (in equations: piecewise constant between events).
    Signal(SignalId),
    /// A process variable (processes only).
    Var(VarId),
    /// Simulation time `now` (seconds).
    Now,
    Unary(UnaryOp, Box<Expr>),
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    /// A predefined function (math_real and the like).
    Call(Builtin, Vec<Expr>),
    /// `if cond then a else b`: from simultaneous if/case and conditional expressions.
    If(Box<Expr>, Box<Expr>, Box<Expr>),
    /// Array element `a(i)` (processes only); index in the array type's own bounds.
    Index {
        array: Box<Expr>,
        index: Box<Expr>,
        ty: Type,
    },
    /// `T'image(x)` (processes only).
    Image(Type, Box<Expr>),
    /// An array built from element values computed at run time, in index order (processes
    /// only; an aggregate of static elements is a constant). `string`: a character array,
    /// whose value is a [`Value::String`].
    Aggregate {
        elems: Vec<Expr>,
        string: bool,
    },
    /// A signal attribute (processes only).
    SignalAttr(SignalId, SignalAttr),
    /// `new T'(value)`: a new object on the heap holding `value`; its access value.
    New(Box<Expr>),
    /// `p.all`: the object an access value designates.
    Deref(Box<Expr>),
    /// `endfile(f)`.
    EndFile(Box<Expr>),
    /// A call of a user-defined function (processes only; equations get pure straight-line
    /// functions inlined): one argument per variable parameter. `signals` are the actuals of
    /// its signal parameters, kept for implicit sensitivity only.
    FnCall {
        sub: SubprogramId,
        args: Vec<Expr>,
        signals: Vec<SignalId>,
    },
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SignalAttr {
    Event,
    Active,
    LastValue,
    /// Seconds since the last event.
    LastEvent,
    /// Seconds since the signal was last active.
    LastActive,
    /// Whether the evaluating process's driver of the signal is connected.
    Driving,
    /// The current value of the evaluating process's driver of the signal.
    DrivingValue,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Neg,
    Plus,
    Abs,
    Not,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    Add,
    Sub,
    Mul,
    Div,
    /// `**`
    Pow,
    Mod,
    Rem,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    And,
    Or,
    Nand,
    Nor,
    Xor,
    Xnor,
    /// `&` on strings and arrays.
    Concat,
    /// The shift and rotate operators on one-dimensional arrays of `bit` or `boolean`
    /// (LRM 7.2.3), by an integer count (a negative count shifts the other way).
    Sll,
    Srl,
    Sla,
    Sra,
    Rol,
    Ror,
}

impl BinaryOp {
    /// True for `sll`, `srl`, `sla`, `sra`, `rol`, `ror`.
    pub fn is_shift(self) -> bool {
        use BinaryOp::*;
        matches!(self, Sll | Srl | Sla | Sra | Rol | Ror)
    }
}

/// Predefined functions callable from both equations and processes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Builtin {
    Exp,
    Log,
    Log10,
    Sqrt,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    /// Two-argument arctangent `arctan(y, x)`.
    Atan2,
    Sinh,
    Cosh,
    Tanh,
    Asinh,
    Acosh,
    Atanh,
    Floor,
    Ceil,
    Round,
    Trunc,
    Sign,
    Realmax,
    Realmin,
    /// Type conversion `real(i)`.
    ToReal,
    /// Type conversion `integer(x)` (round to nearest).
    ToInteger,
    /// `T'pos(x)` of an enumeration, boolean or integer value: its position.
    Pos,
    /// `time'pos(t)`: the number of femtoseconds in `t`.
    TimePos,
    /// `T'val(i)` of an enumeration type: arguments `i`, the number of literals, and whether
    /// the type is `boolean` (1) or not (0); an error outside the type.
    EnumVal,
    /// `time'val(i)`: `i` femtoseconds.
    TimeVal,
    /// A slice `a(l to r)` (processes only): arguments the array, the position of its first
    /// element from the left, and the number of elements.
    Slice,
    /// `T'value(s)` (processes only): arguments the string and what `T` is: the literals of
    /// an enumeration type (an array of strings, characters written `'c'`), or the string
    /// `"integer"`, `"real"`, `"time"` or `"boolean"`.
    ValueOf,
    /// The array `a` with the elements from a position replaced by those of `v` (a slice
    /// assignment `a(l to r) := v`): arguments `a`, the position, the slice's length, `v`.
    Splice,
    /// A character array in the other representation (arguments: the array, and whether
    /// the result is a `string`): a conversion between `string` and another array of
    /// characters (`display_string(s)`), which the kernel holds as a `Value::Array`.
    Restring,
    /// The number of elements of an array value known only at run time (`l'length` of a
    /// textio line).
    Length,
    /// An array value assigned to a target of known length whose own length is known only
    /// at run time (LRM 8.4, 8.5: the lengths must match): arguments the value, the target's
    /// length and what the target is ("variable `v`"); the value itself, or an error
    /// naming the target and both lengths.
    CheckLength,
    /// `vams.tables.pwl(table, x)`: arguments the flat table `(x0, y0, x1, y1, ...)` (a
    /// constant in equations) and `x`; linear between points, constant beyond ([`crate::pwl`]).
    Pwl,
}

impl Builtin {
    /// `'pos`, `'val` and the array operations: not real functions, evaluated by
    /// [`value_builtin`] at elaboration and at run time.
    pub fn on_values(self) -> bool {
        matches!(
            self,
            Builtin::Pos
                | Builtin::TimePos
                | Builtin::EnumVal
                | Builtin::TimeVal
                | Builtin::Slice
                | Builtin::Splice
                | Builtin::ValueOf
                | Builtin::Restring
                | Builtin::Length
                | Builtin::CheckLength
                | Builtin::Pwl
        )
    }
}

/// The builtins of [`Builtin::on_values`], the same at elaboration (folding) and at run time;
/// `Err` with the reason for a result outside its type or a slice outside its array.
pub fn value_builtin(f: Builtin, args: &[Value]) -> Result<Value, String> {
    match (f, args) {
        (Builtin::Length, [Value::String(s)]) => Ok(Value::Integer(s.chars().count() as i64)),
        (Builtin::Length, [Value::Array(items)]) => Ok(Value::Integer(items.len() as i64)),
        (Builtin::CheckLength, [v, Value::Integer(n), Value::String(target)]) => {
            check_length(v, *n, target).map(|()| v.clone())
        }
        (Builtin::Slice, [a, Value::Integer(first), Value::Integer(len)]) => {
            let elements = a.elements();
            let (first, len) = (*first, *len);
            if len <= 0 {
                return Ok(aggregate_value(Vec::new(), matches!(a, Value::String(_))));
            }
            if first < 0 || first + len > elements.len() as i64 {
                return Err(format!(
                    "the slice of {len} element(s) from position {first} is outside the array's {} element(s)",
                    elements.len()
                ));
            }
            Ok(a.view(first as usize, Some(len as usize))
                .unwrap_or_else(|| a.clone()))
        }
        (Builtin::Splice, [a, Value::Integer(first), Value::Integer(len), v]) => {
            let mut elements = a.elements();
            let part = v.elements();
            if part.len() as i64 != (*len).max(0) {
                return Err(format!(
                    "a value of {} element(s) assigned to a slice of {}",
                    part.len(),
                    (*len).max(0)
                ));
            }
            let first = *first;
            if first < 0 || first + part.len() as i64 > elements.len() as i64 {
                return Err(format!(
                    "a slice of {} element(s) from position {first} is outside the array's {} element(s)",
                    part.len(),
                    elements.len()
                ));
            }
            let first = first as usize;
            elements.splice(first..first + part.len(), part);
            Ok(aggregate_value(elements, matches!(a, Value::String(_))))
        }
        (Builtin::ValueOf, [text, kind]) => value_of(text, kind),
        (Builtin::Pwl, [Value::Array(table), x]) => pwl_value(table, x),
        (Builtin::Restring, [a, Value::Boolean(string)]) => {
            Ok(aggregate_value(a.elements(), *string))
        }
        _ => scalar_attribute(f, args),
    }
}

/// `pwl(table, x)` on values: the table checked, then looked up.
fn pwl_value(table: &[Value], x: &Value) -> Result<Value, String> {
    let at = |k: usize| table[k].as_f64().unwrap_or(f64::NAN);
    crate::pwl::check(table.len(), at).map_err(|e| e.to_string())?;
    let x = x
        .as_f64()
        .ok_or_else(|| "pwl's x must be a real".to_string())?;
    let (y, _) = crate::pwl::lookup(table.len() / 2, |k| (at(2 * k), at(2 * k + 1)), x);
    if y.is_nan() {
        return Err("pwl of x = NaN".into());
    }
    Ok(Value::Real(y))
}

/// `Ok` when array value `v` has `n` elements, else the error of an assignment of it to
/// `target` ("variable `v`"), which has `n` (LRM 8.4, 8.5: an implicit subtype conversion
/// keeps the target's bounds, and the lengths must match). See [`Builtin::CheckLength`].
pub fn check_length(v: &Value, n: i64, target: &str) -> Result<(), String> {
    let m = match v {
        Value::Array(items) => items.len(),
        Value::String(s) => s.chars().count(),
        _ => return Ok(()),
    };
    if m as i64 == n {
        Ok(())
    } else {
        Err(length_mismatch(target, n, m as i64))
    }
}

/// The message of an array assignment whose value has `found` elements where the target has
/// `expected`: the same words at elaboration and at run time.
pub fn length_mismatch(target: &str, expected: i64, found: i64) -> String {
    format!("a value of {found} element(s) assigned to {target} of {expected} element(s)")
}

/// `T'value(text)` (LRM 14.1): the literal `text` (leading and trailing blanks ignored,
/// identifiers in any case) as a value of the type `kind` describes ([`Builtin::ValueOf`]).
fn value_of(text: &Value, kind: &Value) -> Result<Value, String> {
    let Value::String(text) = text else {
        return Err("'value takes a string".into());
    };
    let t = text.trim();
    let bad = |what: &str| format!("\"{t}\" is not {what}");
    match kind {
        // A physical type's units: `"5 Mohm"`.
        Value::Array(units) if matches!(units.first(), Some(Value::Array(_))) => {
            let (number, unit) = t.split_once(char::is_whitespace).unwrap_or((t, ""));
            let factor = units.iter().find_map(|u| match u.elements().as_slice() {
                [Value::String(name), Value::Integer(f)]
                    if name.eq_ignore_ascii_case(unit.trim()) =>
                {
                    Some(*f)
                }
                _ => None,
            });
            let n: f64 = number
                .replace('_', "")
                .parse()
                .map_err(|_| bad("a physical literal (`5 kohm`)"))?;
            match factor {
                Some(f) => Ok(Value::Integer((n * f as f64).round() as i64)),
                None => Err(bad("a literal with a unit of the type")),
            }
        }
        Value::Array(literals) => {
            let found = literals.iter().position(|l| match l {
                Value::String(l) if l.starts_with('\'') => l == t,
                Value::String(l) => l.eq_ignore_ascii_case(t),
                _ => false,
            });
            found
                .map(|p| Value::Enum(p as u32))
                .ok_or_else(|| bad("a literal of the type"))
        }
        Value::String(k) => match k.as_str() {
            "integer" => t
                .replace('_', "")
                .parse::<i64>()
                .map(Value::Integer)
                .map_err(|_| bad("an integer literal")),
            "real" => t
                .replace('_', "")
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .map(Value::Real)
                .ok_or_else(|| bad("a real literal")),
            "boolean" => match t.to_ascii_lowercase().as_str() {
                "true" => Ok(Value::Boolean(true)),
                "false" => Ok(Value::Boolean(false)),
                _ => Err(bad("true or false")),
            },
            "time" => {
                let (number, unit) = t
                    .split_once(char::is_whitespace)
                    .ok_or_else(|| bad("a time literal (`10 ns`)"))?;
                let n: f64 = number
                    .replace('_', "")
                    .parse()
                    .map_err(|_| bad("a time literal (`10 ns`)"))?;
                let scale = match unit.trim().to_ascii_lowercase().as_str() {
                    "fs" => 1e-15,
                    "ps" => 1e-12,
                    "ns" => 1e-9,
                    "us" => 1e-6,
                    "ms" => 1e-3,
                    "sec" => 1.0,
                    "min" => 60.0,
                    "hr" => 3600.0,
                    _ => return Err(bad("a time literal with a unit of `time`")),
                };
                Ok(Value::Time(n * scale))
            }
            _ => Err(format!("'value of type {k}")),
        },
        _ => Err("'value of this type".into()),
    }
}

/// One instruction of a lowered process. Execution starts at index 0 and runs until `Wait` or
/// `Halt`.
#[derive(Clone, Debug)]
pub enum Instr {
    /// `var := value` (whole variable).
    SetVar {
        var: VarId,
        value: Expr,
    },
    /// `var(index) := value` for array variables.
    SetVarElement {
        var: VarId,
        index: Expr,
        value: Expr,
    },
    /// A signal assignment: a waveform of `(value, delay)` pairs, delays in seconds from now
    /// (0 = next delta cycle), in increasing order.
    Assign {
        target: SignalId,
        /// `target(index) <= ...`: one element of an array signal (index in the signal's
        /// type's bounds); each element then has its own driver (LRM 12.6.1).
        index: Option<Expr>,
        /// `None` for a null transaction (`null after 5 ns`), which disconnects the driver of
        /// a guarded signal.
        waveform: Vec<(Option<Expr>, Expr)>,
        mechanism: DelayMechanism,
    },
    /// Suspend until an event on one of `on` with `until` true (or, with empty `on`, any event
    /// on a signal read by `until`), or until `timeout` seconds have passed.
    Wait {
        on: Vec<SignalId>,
        until: Option<Expr>,
        timeout: Option<Expr>,
    },
    Jump(usize),
    /// Go to `target` when `cond` is false.
    JumpIfNot {
        cond: Expr,
        target: usize,
    },
    /// `assert cond report msg severity sev` (`report` alone: `cond` is `None`). `severity` is
    /// an expression of type `severity_level` (0 note, 1 warning, 2 error, 3 failure).
    Assert {
        cond: Option<Expr>,
        report: Option<Expr>,
        severity: Expr,
        span: Span,
    },
    /// Sequential `break [reinit list] [when cond]`: announce a discontinuity now and give
    /// quantities new values for the restart.
    Break {
        reinit: Vec<BreakReinit>,
        when: Option<Expr>,
        span: Span,
    },
    /// `std.env.stop` / `finish`: end the simulation cleanly.
    Stop,
    /// Suspend forever (`wait;`).
    Halt,
    /// A procedure call: one argument per variable parameter (an `out` parameter's argument is
    /// its initial value); on return, callee variable `param` is copied to caller variable
    /// `actual` for each of `copy_back`. `signals` are the actuals of its signal parameters
    /// (for implicit sensitivity).
    Call {
        sub: SubprogramId,
        args: Vec<Expr>,
        copy_back: Vec<(VarId, VarId)>,
        signals: Vec<SignalId>,
        span: Span,
    },
    /// Leave the subprogram (with the function's result).
    Return(Option<Expr>),
    /// `p.all := value` (and `p.f := x`, as the whole object updated): the object access
    /// value `pointer` designates gets `value`.
    SetHeap {
        pointer: Expr,
        value: Expr,
    },
    /// A native procedure call: arguments in parameter order; on return argument `param` is
    /// copied to variable `actual` for each of `copy_back` (the `out` and `inout` ones).
    Native {
        op: NativeProc,
        args: Vec<Expr>,
        copy_back: Vec<(usize, VarId)>,
        span: Span,
    },
}

impl Instr {
    /// Calls `f` on each expression the instruction holds (not their sub-expressions).
    pub fn visit_exprs(&self, f: &mut impl FnMut(&Expr)) {
        match self {
            Instr::SetVar { value, .. } => f(value),
            Instr::SetVarElement { index, value, .. } => {
                f(index);
                f(value);
            }
            Instr::Assign {
                index,
                waveform,
                mechanism,
                ..
            } => {
                if let Some(i) = index {
                    f(i);
                }
                for (v, d) in waveform {
                    if let Some(v) = v {
                        f(v);
                    }
                    f(d);
                }
                if let DelayMechanism::Inertial {
                    reject: Some(reject),
                } = mechanism
                {
                    f(reject);
                }
            }
            Instr::Wait { until, timeout, .. } => {
                until.iter().chain(timeout).for_each(f);
            }
            Instr::JumpIfNot { cond, .. } => f(cond),
            Instr::Assert {
                cond,
                report,
                severity,
                ..
            } => {
                cond.iter().chain(report).for_each(&mut *f);
                f(severity);
            }
            Instr::Break { reinit, when, .. } => {
                reinit.iter().for_each(|r| f(&r.value));
                when.iter().for_each(f);
            }
            Instr::Call { args, .. } | Instr::Native { args, .. } => args.iter().for_each(f),
            Instr::SetHeap { pointer, value } => {
                f(pointer);
                f(value);
            }
            Instr::Return(value) => value.iter().for_each(f),
            Instr::Jump(_) | Instr::Stop | Instr::Halt => {}
        }
    }
}

/// `q => value` in a break list, or `for selector use q => value` (`selector` is the quantity
/// whose `'dot` equation is replaced; equal to `quantity` for the plain form).
#[derive(Clone, Debug)]
pub struct BreakReinit {
    pub selector: QuantityId,
    pub quantity: QuantityId,
    pub value: Expr,
}

#[derive(Clone, Debug, PartialEq)]
pub enum DelayMechanism {
    Transport,
    /// Inertial with the given pulse-rejection limit in seconds (`None`: the first delay).
    Inertial {
        reject: Option<Expr>,
    },
}

/// `limit q : nature with max_step;` resolved to quantities.
#[derive(Clone, Debug)]
pub struct Limit {
    pub quantities: Vec<QuantityId>,
    pub max_step: Expr,
}

impl Expr {
    pub fn real(v: f64) -> Expr {
        Expr::Const(Value::Real(v))
    }

    /// True when the expression can appear in an equation: no process variables, array
    /// indexing, images or signal attributes.
    pub fn is_analog(&self) -> bool {
        match self {
            Expr::Const(v) => v.as_f64().is_some(),
            Expr::Quantity(_) | Expr::Dot(_) | Expr::Signal(_) | Expr::Now => true,
            Expr::Var(_)
            | Expr::Index { .. }
            | Expr::Image(..)
            | Expr::Aggregate { .. }
            | Expr::SignalAttr(..)
            | Expr::FnCall { .. }
            | Expr::New(_)
            | Expr::Deref(_)
            | Expr::EndFile(_) => false,
            Expr::Unary(_, a) => a.is_analog(),
            Expr::Binary(op, a, b) => {
                *op != BinaryOp::Concat && !op.is_shift() && a.is_analog() && b.is_analog()
            }
            // A table is a constant array (elaboration checked it).
            Expr::Call(Builtin::Pwl, args) => match args.as_slice() {
                [Expr::Const(Value::Array(_)), x] => x.is_analog(),
                _ => false,
            },
            Expr::Call(_, args) => args.iter().all(Expr::is_analog),
            Expr::If(c, a, b) => c.is_analog() && a.is_analog() && b.is_analog(),
        }
    }

    /// Calls `f` on every sub-expression, this one first.
    pub fn visit(&self, f: &mut impl FnMut(&Expr)) {
        f(self);
        match self {
            Expr::Const(_)
            | Expr::Quantity(_)
            | Expr::Dot(_)
            | Expr::Signal(_)
            | Expr::Var(_)
            | Expr::Now
            | Expr::SignalAttr(..) => {}
            Expr::Unary(_, a)
            | Expr::Image(_, a)
            | Expr::New(a)
            | Expr::Deref(a)
            | Expr::EndFile(a) => a.visit(f),
            Expr::Binary(_, a, b) => {
                a.visit(f);
                b.visit(f);
            }
            Expr::Call(_, args)
            | Expr::FnCall { args, .. }
            | Expr::Aggregate { elems: args, .. } => args.iter().for_each(|a| a.visit(f)),
            Expr::If(c, a, b) => {
                c.visit(f);
                a.visit(f);
                b.visit(f);
            }
            Expr::Index { array, index, .. } => {
                array.visit(f);
                index.visit(f);
            }
        }
    }

    /// This expression with each direct sub-expression replaced by `f` of it (a leaf is
    /// cloned): the one place that knows the shape of every node, for rewrites that change
    /// a few kinds of node and rebuild the rest.
    pub fn try_map_children<E>(
        &self,
        mut f: impl FnMut(&Expr) -> Result<Expr, E>,
    ) -> Result<Expr, E> {
        Ok(match self {
            Expr::Const(_)
            | Expr::Quantity(_)
            | Expr::Dot(_)
            | Expr::Signal(_)
            | Expr::Var(_)
            | Expr::Now
            | Expr::SignalAttr(..) => self.clone(),
            Expr::Unary(op, a) => Expr::Unary(*op, Box::new(f(a)?)),
            Expr::New(a) => Expr::New(Box::new(f(a)?)),
            Expr::Deref(a) => Expr::Deref(Box::new(f(a)?)),
            Expr::EndFile(a) => Expr::EndFile(Box::new(f(a)?)),
            Expr::Binary(op, l, r) => Expr::Binary(*op, Box::new(f(l)?), Box::new(f(r)?)),
            Expr::Call(g, args) => Expr::Call(*g, args.iter().map(f).collect::<Result<_, _>>()?),
            Expr::FnCall { sub, args, signals } => Expr::FnCall {
                sub: *sub,
                args: args.iter().map(f).collect::<Result<_, _>>()?,
                signals: signals.clone(),
            },
            Expr::If(c, x, y) => Expr::If(Box::new(f(c)?), Box::new(f(x)?), Box::new(f(y)?)),
            Expr::Index { array, index, ty } => Expr::Index {
                array: Box::new(f(array)?),
                index: Box::new(f(index)?),
                ty: ty.clone(),
            },
            Expr::Image(ty, x) => Expr::Image(ty.clone(), Box::new(f(x)?)),
            Expr::Aggregate { elems, string } => Expr::Aggregate {
                elems: elems.iter().map(f).collect::<Result<_, _>>()?,
                string: *string,
            },
        })
    }

    /// The signals the expression reads (with repetitions), for implicit sensitivity.
    pub fn signals(&self) -> Vec<SignalId> {
        let mut out = Vec::new();
        self.visit(&mut |e| match e {
            Expr::Signal(s) | Expr::SignalAttr(s, _) => out.push(*s),
            Expr::FnCall { signals, .. } => out.extend(signals),
            _ => {}
        });
        out
    }
}
