//! The deck as data: what the reader gives.
//!
//! Takes nothing; defines [`Deck`], a SPICE deck as written (subcircuits still nested, values
//! still [`Expr`]s, names still local), with a span on every item. Names are folded to lower
//! case in [`Name::key`] and kept as written in [`Name::text`] for messages. Plain data with
//! public fields: `flatten` and the tests read it, nothing here computes.
//!
//! The source types ([`Source`], [`Ac`], [`Waveform`]) are generic over the value type `V`:
//! [`Expr`] in the deck, `f64` in the flattened `Circuit`, so both stages share one
//! definition of a `PULSE`.

use vams_syntax::source::{FileId, Span};

use crate::error::SpiceError;
use crate::expr::Expr;

/// A name as written, and folded.
#[derive(Clone, Debug, PartialEq)]
pub struct Name {
    /// Lower case: what SPICE compares.
    pub key: String,
    /// As written, for messages.
    pub text: String,
    pub span: Span,
}

/// `name=value`: an instance, model, subcircuit or `.param` parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct Param {
    pub name: Name,
    pub value: Expr,
}

/// The element letters vams reads.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum ElementKind {
    /// Resistor `r n+ n- [value] [model] [k=v ...]`
    R,
    /// Capacitor `c n+ n- [value] [model] [ic=v] ...`
    C,
    /// Inductor `l n+ n- [value] [model] [ic=v] ...`
    L,
    /// Coupling `k l1 l2 k`: `controls` are the two inductors, `values` the coefficient.
    K,
    /// Independent voltage source: `source`.
    V,
    /// Independent current source: `source`.
    I,
    /// VCVS `e n+ n- nc+ nc- gain`
    E,
    /// CCCS `f n+ n- vcontrol gain`
    F,
    /// VCCS `g n+ n- nc+ nc- transconductance`
    G,
    /// CCVS `h n+ n- vcontrol transresistance`
    H,
    /// Voltage-controlled switch `s n+ n- nc+ nc- model [on|off]`
    S,
    /// Current-controlled switch `w n+ n- vcontrol model [on|off]`
    W,
    /// Diode `d n+ n- model [area] [off] ...`
    D,
    /// BJT `q nc nb ne [ns [nt]] model [area] [off] ...`
    Q,
    /// MOSFET `m nd ng ns nb [more] model [k=v ...] [off]`
    M,
    /// Subcircuit instance `x nodes... subckt [params:] [k=v ...]`: `model` is the subcircuit.
    X,
}

impl ElementKind {
    pub fn from_letter(c: char) -> Option<ElementKind> {
        use ElementKind::*;
        Some(match c.to_ascii_lowercase() {
            'r' => R,
            'c' => C,
            'l' => L,
            'k' => K,
            'v' => V,
            'i' => I,
            'e' => E,
            'f' => F,
            'g' => G,
            'h' => H,
            's' => S,
            'w' => W,
            'd' => D,
            'q' => Q,
            'm' => M,
            'x' => X,
            _ => return None,
        })
    }

    /// A noun for messages (`a resistor`).
    pub fn noun(self) -> &'static str {
        use ElementKind::*;
        match self {
            R => "a resistor",
            C => "a capacitor",
            L => "an inductor",
            K => "a coupling",
            V => "a voltage source",
            I => "a current source",
            E => "a voltage-controlled voltage source",
            F => "a current-controlled current source",
            G => "a voltage-controlled current source",
            H => "a current-controlled voltage source",
            S => "a voltage-controlled switch",
            W => "a current-controlled switch",
            D => "a diode",
            Q => "a bipolar transistor",
            M => "a MOSFET",
            X => "a subcircuit instance",
        }
    }
}

/// A switch's or a semiconductor's initial state keyword.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum InitialState {
    On,
    Off,
}

/// One element line.
#[derive(Clone, Debug, PartialEq)]
pub struct Element {
    pub kind: ElementKind,
    pub name: Name,
    pub nodes: Vec<Name>,
    /// F, H, W: the controlling voltage source; K: the two inductors.
    pub controls: Vec<Name>,
    /// D Q M S W: the model; R C L: an optional model (or, as ngspice allows, a bare parameter
    /// name as the value: `flatten` decides); X: the subcircuit.
    pub model: Option<Name>,
    /// Positional values: R C L the value; K the coupling; E F G H the gain; D Q the area.
    pub values: Vec<Expr>,
    /// `key=value` instance parameters (X: the parameter overrides).
    pub params: Vec<Param>,
    /// `on` / `off`.
    pub state: Option<InitialState>,
    /// V and I: what the source gives.
    pub source: Option<Source<Expr>>,
    /// The whole line.
    pub span: Span,
}

/// An independent source's specification, as ngspice reads it: each part optional.
#[derive(Clone, Debug, PartialEq)]
pub struct Source<V> {
    /// `dc v` or a leading bare value.
    pub dc: Option<V>,
    /// `ac [mag [phase]]`.
    pub ac: Option<Ac<V>>,
    /// The transient function.
    pub tran: Option<Waveform<V>>,
}

impl<V> Source<V> {
    /// The same source with every value mapped (an `Expr` source to numbers, say).
    pub fn map<W>(&self, f: &mut dyn FnMut(&V) -> W) -> Source<W> {
        Source {
            dc: self.dc.as_ref().map(&mut *f),
            ac: self.ac.as_ref().map(|ac| Ac {
                mag: ac.mag.as_ref().map(&mut *f),
                phase: ac.phase.as_ref().map(&mut *f),
            }),
            tran: self.tran.as_ref().map(|w| w.map(f)),
        }
    }
}

impl<V> Waveform<V> {
    /// The same function with every value mapped.
    pub fn map<W>(&self, f: &mut dyn FnMut(&V) -> W) -> Waveform<W> {
        let mut o = |v: &Option<V>| v.as_ref().map(&mut *f);
        match self {
            Waveform::Pulse {
                v1,
                v2,
                td,
                tr,
                tf,
                pw,
                per,
                np,
            } => {
                let (td, tr, tf, pw, per, np) = (o(td), o(tr), o(tf), o(pw), o(per), o(np));
                Waveform::Pulse {
                    v1: f(v1),
                    v2: f(v2),
                    td,
                    tr,
                    tf,
                    pw,
                    per,
                    np,
                }
            }
            Waveform::Sin {
                vo,
                va,
                freq,
                td,
                theta,
                phase,
            } => {
                let (freq, td, theta, phase) = (o(freq), o(td), o(theta), o(phase));
                Waveform::Sin {
                    vo: f(vo),
                    va: f(va),
                    freq,
                    td,
                    theta,
                    phase,
                }
            }
            Waveform::Exp {
                v1,
                v2,
                td1,
                tau1,
                td2,
                tau2,
            } => {
                let (td1, tau1, td2, tau2) = (o(td1), o(tau1), o(td2), o(tau2));
                Waveform::Exp {
                    v1: f(v1),
                    v2: f(v2),
                    td1,
                    tau1,
                    td2,
                    tau2,
                }
            }
            Waveform::Pwl {
                points,
                repeat,
                delay,
            } => {
                let (repeat, delay) = (o(repeat), o(delay));
                Waveform::Pwl {
                    points: points.iter().map(|(t, v)| (f(t), f(v))).collect(),
                    repeat,
                    delay,
                }
            }
        }
    }
}

impl<V> Default for Source<V> {
    fn default() -> Source<V> {
        Source {
            dc: None,
            ac: None,
            tran: None,
        }
    }
}

/// `ac [mag [phase]]`: missing parts are the simulator's defaults (1 and 0).
#[derive(Clone, Debug, PartialEq)]
pub struct Ac<V> {
    pub mag: Option<V>,
    pub phase: Option<V>,
}

/// A transient source function; trailing arguments left out are `None` (the simulator's
/// defaults, which depend on the `.tran` step and stop time).
#[derive(Clone, Debug, PartialEq)]
pub enum Waveform<V> {
    /// `PULSE(v1 v2 td tr tf pw per np)`
    Pulse {
        v1: V,
        v2: V,
        td: Option<V>,
        tr: Option<V>,
        tf: Option<V>,
        pw: Option<V>,
        per: Option<V>,
        np: Option<V>,
    },
    /// `SIN(vo va freq td theta phase)`
    Sin {
        vo: V,
        va: V,
        freq: Option<V>,
        td: Option<V>,
        theta: Option<V>,
        phase: Option<V>,
    },
    /// `EXP(v1 v2 td1 tau1 td2 tau2)`
    Exp {
        v1: V,
        v2: V,
        td1: Option<V>,
        tau1: Option<V>,
        td2: Option<V>,
        tau2: Option<V>,
    },
    /// `PWL(t1 v1 t2 v2 ...) [r=t] [td=t]`
    Pwl {
        points: Vec<(V, V)>,
        /// `r=`: the time the table repeats from.
        repeat: Option<V>,
        /// `td=`: a delay of the whole table.
        delay: Option<V>,
    },
}

/// `.model` types.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ModelKind {
    R,
    C,
    L,
    D,
    Npn,
    Pnp,
    Njf,
    Pjf,
    Nmos,
    Pmos,
    Sw,
    Csw,
}

impl ModelKind {
    pub const NAMES: [(&'static str, ModelKind); 13] = [
        ("r", ModelKind::R),
        ("res", ModelKind::R),
        ("c", ModelKind::C),
        ("l", ModelKind::L),
        ("d", ModelKind::D),
        ("npn", ModelKind::Npn),
        ("pnp", ModelKind::Pnp),
        ("njf", ModelKind::Njf),
        ("pjf", ModelKind::Pjf),
        ("nmos", ModelKind::Nmos),
        ("pmos", ModelKind::Pmos),
        ("sw", ModelKind::Sw),
        ("csw", ModelKind::Csw),
    ];

    pub fn from_name(name: &str) -> Option<ModelKind> {
        ModelKind::NAMES
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, k)| *k)
    }

    pub fn name(self) -> &'static str {
        ModelKind::NAMES
            .iter()
            .find(|(_, k)| *k == self)
            .map_or("?", |(n, _)| n)
    }
}

/// `.model name type (k=v ...)`.
#[derive(Clone, Debug, PartialEq)]
pub struct Model {
    pub name: Name,
    pub kind: ModelKind,
    /// `level=`, taken out of the parameters.
    pub level: Option<Expr>,
    pub params: Vec<Param>,
    pub span: Span,
}

/// What a body (the deck's top level, or a subcircuit's) defines.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Body {
    pub elements: Vec<Element>,
    pub models: Vec<Model>,
    /// Subcircuits defined here, visible here and in the bodies nested in this one.
    pub subckts: Vec<Subckt>,
    /// `.param` definitions, in order (a later one of a name replaces an earlier one).
    pub params: Vec<Param>,
}

/// `.subckt name ports... [params: k=v ...]` ... `.ends`.
#[derive(Clone, Debug, PartialEq)]
pub struct Subckt {
    pub name: Name,
    pub ports: Vec<Name>,
    /// The `params:` defaults.
    pub params: Vec<Param>,
    pub body: Body,
    /// The `.subckt` line.
    pub span: Span,
}

/// An analysis card's contents.
#[derive(Clone, Debug, PartialEq)]
pub enum Analysis {
    /// `.op`
    Op,
    /// `.tran tstep tstop [tstart [tmax]] [uic]`
    Tran {
        tstep: Expr,
        tstop: Expr,
        tstart: Option<Expr>,
        tmax: Option<Expr>,
        uic: bool,
    },
    /// `.dc src start stop step [src2 start2 stop2 step2]`
    Dc { sweeps: Vec<DcSweep> },
    /// `.ac dec|oct|lin n fstart fstop`
    Ac {
        scale: AcScale,
        points: Expr,
        fstart: Expr,
        fstop: Expr,
    },
}

/// One `.dc` sweep: `target` is a source's (or resistor's) name, or `temp`.
#[derive(Clone, Debug, PartialEq)]
pub struct DcSweep {
    pub target: Name,
    pub start: Expr,
    pub stop: Expr,
    pub step: Expr,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum AcScale {
    Dec,
    Oct,
    Lin,
}

/// An analysis card with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct AnalysisCard {
    pub analysis: Analysis,
    pub span: Span,
}

/// `.options` item: `name`, `name=value` or `name=word` (`method=gear`).
#[derive(Clone, Debug, PartialEq)]
pub struct OptionItem {
    pub name: Name,
    pub value: Option<OptionValue>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum OptionValue {
    Expr(Expr),
    Word(Name),
}

/// `.ic` / `.nodeset` item `v(node)=value`.
#[derive(Clone, Debug, PartialEq)]
pub struct NodeValue {
    pub node: Name,
    pub value: Expr,
}

/// Which card an output list comes from.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputCard {
    Print,
    Probe,
    Save,
}

/// The analysis a `.print` names.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PrintAnalysis {
    Tran,
    Dc,
    Ac,
    Op,
}

/// What part of a (complex, in `.ac`) vector: `v` / `i` as is, `vm`, `vp`, `vdb`, `vr`, `vi`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Part {
    Value,
    Mag,
    Phase,
    Db,
    Real,
    Imag,
}

/// An output vector as written.
#[derive(Clone, Debug, PartialEq)]
pub enum Vector {
    /// `v(a)` or `v(a, b)` (a bare node name in `.save` is `v(name)`)
    Voltage {
        part: Part,
        pos: Name,
        neg: Option<Name>,
        span: Span,
    },
    /// `i(vname)`
    Current {
        part: Part,
        element: Name,
        span: Span,
    },
    /// `all` (in `.save` and `.probe`)
    All { span: Span },
}

/// `.print [analysis] vectors`, `.probe vectors`, `.save vectors`.
#[derive(Clone, Debug, PartialEq)]
pub struct Output {
    pub card: OutputCard,
    pub analysis: Option<PrintAnalysis>,
    pub vectors: Vec<Vector>,
    pub span: Span,
}

/// A whole deck, includes spliced in, as written.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Deck {
    pub title: String,
    pub title_span: Span,
    /// The top level: elements, models, subcircuits, `.param`s.
    pub body: Body,
    pub analyses: Vec<AnalysisCard>,
    pub options: Vec<OptionItem>,
    /// `.temp` values.
    pub temps: Vec<Expr>,
    /// `.ic`
    pub initial: Vec<NodeValue>,
    /// `.nodeset`
    pub nodesets: Vec<NodeValue>,
    pub outputs: Vec<Output>,
    /// `.global` nodes: never renamed inside subcircuits.
    pub globals: Vec<Name>,
    /// Every file read, the deck first, then the included ones in the order met.
    pub files: Vec<FileId>,
    /// Warnings (skipped `.control` blocks, ignored cards).
    pub warnings: Vec<SpiceError>,
}
