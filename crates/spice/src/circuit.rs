//! The flat circuit as data: what `flatten` gives.
//!
//! Takes nothing; defines [`Circuit`], the contract between the SPICE frontend and the step
//! that turns it into the simulator's design: one flat list of elements (no subcircuit left),
//! nodes interned as [`NodeId`]s with their hierarchical names, every value a finite `f64`,
//! every model and control reference an index that is valid in its vector. Plain data with
//! public fields; every element, model, analysis and output keeps the span it came from.
//!
//! Names follow ngspice (checked against ngspice 39's `listing expand`): a node `n3` inside
//! instance `x1` is `x1.n3` (nested: `x1.x2.n3`); an element `r2` there is `r.x1.r2`, its
//! letter first (`r.x1.x2.r2` nested); a model `m` defined inside `x1` is `x1:m`. Nodes `0`
//! and `gnd` are ground, [`NodeId::GROUND`], named `0`; `.global` nodes keep their name.

use vams_syntax::source::Span;

use crate::deck::{
    AcScale, ElementKind, InitialState, ModelKind, OutputCard, Part, PrintAnalysis, Source,
};

/// A node: an index into [`Circuit::nodes`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct NodeId(pub u32);

impl NodeId {
    /// The reference node, `0` (and `gnd`).
    pub const GROUND: NodeId = NodeId(0);
}

/// An element: an index into [`Circuit::elements`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ElementId(pub u32);

/// A model: an index into [`Circuit::models`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct ModelId(pub u32);

/// One element of the flat circuit.
#[derive(Clone, Debug, PartialEq)]
pub struct FlatElement {
    pub kind: ElementKind,
    /// The hierarchical name (`r1` at the top, `r.x1.r1` inside `x1`), lower case.
    pub name: String,
    pub nodes: Vec<NodeId>,
    /// F, H, W: the controlling voltage source; K: the two inductors.
    pub controls: Vec<ElementId>,
    pub model: Option<ModelId>,
    /// Positional values: R C L the value (absent for an R/C/L with a model and no value);
    /// K the coupling; E F G H the gain; D Q the area, when given.
    pub values: Vec<f64>,
    /// Instance parameters, lower-case names, in the order written.
    pub params: Vec<(String, f64)>,
    pub state: Option<InitialState>,
    /// V and I.
    pub source: Option<Source<f64>>,
    /// The element line (inside a subcircuit: the line in its body).
    pub span: Span,
}

impl FlatElement {
    /// An instance parameter by (lower-case) name.
    pub fn param(&self, name: &str) -> Option<f64> {
        self.params.iter().find(|(n, _)| n == name).map(|(_, v)| *v)
    }
}

/// A model with numeric parameters.
#[derive(Clone, Debug, PartialEq)]
pub struct FlatModel {
    /// `name` at the top level, `x1:name` for one defined inside instance `x1`.
    pub name: String,
    pub kind: ModelKind,
    /// `level=`, a whole number >= 1, when given.
    pub level: Option<u32>,
    /// Lower-case names, in the order written.
    pub params: Vec<(String, f64)>,
    pub span: Span,
}

impl FlatModel {
    pub fn param(&self, name: &str) -> Option<f64> {
        self.params.iter().find(|(n, _)| n == name).map(|(_, v)| *v)
    }
}

/// What a `.dc` sweeps: an element (a source, or a resistor as ngspice allows) or `temp`.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SweepTarget {
    Element(ElementId),
    Temperature,
}

/// One `.dc` sweep with numbers.
#[derive(Clone, Debug, PartialEq)]
pub struct Sweep {
    pub target: SweepTarget,
    pub start: f64,
    pub stop: f64,
    pub step: f64,
}

/// An analysis with numbers.
#[derive(Clone, Debug, PartialEq)]
pub enum Analysis {
    Op,
    /// `tstep > 0`, `tstop > tstart >= 0`, `tmax > 0` when given.
    Tran {
        tstep: f64,
        tstop: f64,
        tstart: Option<f64>,
        tmax: Option<f64>,
        uic: bool,
    },
    /// The sweeps in the order written (`.dc v1 ... v2 ...`: `v1` inner, `v2` outer).
    Dc {
        sweeps: Vec<Sweep>,
    },
    /// `points >= 1`, `0 < fstart <= fstop` (`fstart` may be 0 for `lin`).
    Ac {
        scale: AcScale,
        points: u32,
        fstart: f64,
        fstop: f64,
    },
}

/// An analysis and the card it came from.
#[derive(Clone, Debug, PartialEq)]
pub struct AnalysisSpec {
    pub analysis: Analysis,
    pub span: Span,
}

/// `.options` method.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Method {
    Trap,
    Gear,
}

/// A `.options` value kept for a later step to use or warn about.
#[derive(Clone, Debug, PartialEq)]
pub enum OptionValue {
    Number(f64),
    Word(String),
    /// A bare flag (`.options noinit`).
    Flag,
}

/// `.options` (and `.temp`): the known ones typed, the rest kept as written.
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Options {
    pub reltol: Option<f64>,
    pub abstol: Option<f64>,
    pub vntol: Option<f64>,
    pub gmin: Option<f64>,
    /// `.options temp=` or `.temp` (the last one given), in degrees Celsius.
    pub temp: Option<f64>,
    pub tnom: Option<f64>,
    pub method: Option<Method>,
    /// Every other option, lower-case name, with its span.
    pub other: Vec<(String, OptionValue, Span)>,
}

/// A resolved output vector.
#[derive(Clone, Debug, PartialEq)]
pub enum Probe {
    /// `v(pos)` or `v(pos, neg)`.
    Voltage {
        part: Part,
        pos: NodeId,
        neg: Option<NodeId>,
        span: Span,
    },
    /// `i(source)`: the current through an element.
    Current {
        part: Part,
        element: ElementId,
        span: Span,
    },
    /// `all`
    All { span: Span },
}

/// A `.print` / `.probe` / `.save` card, resolved.
#[derive(Clone, Debug, PartialEq)]
pub struct OutputSpec {
    pub card: OutputCard,
    pub analysis: Option<PrintAnalysis>,
    pub probes: Vec<Probe>,
    pub span: Span,
}

/// `.ic` / `.nodeset` value.
#[derive(Clone, Debug, PartialEq)]
pub struct NodeValue {
    pub node: NodeId,
    pub value: f64,
    pub span: Span,
}

/// The flat circuit (see the module doc).
#[derive(Clone, Debug, PartialEq, Default)]
pub struct Circuit {
    pub title: String,
    /// Node names by [`NodeId`]; `nodes[0]` is `"0"`.
    pub nodes: Vec<String>,
    pub elements: Vec<FlatElement>,
    pub models: Vec<FlatModel>,
    pub analyses: Vec<AnalysisSpec>,
    pub options: Options,
    pub initial: Vec<NodeValue>,
    pub nodesets: Vec<NodeValue>,
    pub outputs: Vec<OutputSpec>,
    /// The global `.param` values, sorted by name.
    pub params: Vec<(String, f64)>,
}

impl Circuit {
    /// A node by its (hierarchical, any case) name; `gnd` is ground.
    pub fn node(&self, name: &str) -> Option<NodeId> {
        let key = name.to_ascii_lowercase();
        if key == "gnd" {
            return Some(NodeId::GROUND);
        }
        self.nodes
            .iter()
            .position(|n| *n == key)
            .map(|i| NodeId(i as u32))
    }

    /// An element by its (hierarchical, any case) name.
    pub fn element(&self, name: &str) -> Option<&FlatElement> {
        let key = name.to_ascii_lowercase();
        self.elements.iter().find(|e| e.name == key)
    }

    /// A model by its name (`x1:m` for a subcircuit's).
    pub fn model(&self, name: &str) -> Option<&FlatModel> {
        let key = name.to_ascii_lowercase();
        self.models.iter().find(|m| m.name == key)
    }

    /// The name of a node.
    pub fn node_name(&self, id: NodeId) -> &str {
        self.nodes.get(id.0 as usize).map_or("?", String::as_str)
    }
}
