//! The abstract syntax tree of VHDL-AMS design files.
//!
//! Produced by `parser`, consumed by `analysis`. Every node carries the byte [`Span`] it came
//! from. Architecture invariant: the AST holds no semantic information (no resolved names, no
//! types); it is exactly what the source says, with identifiers normalised to lower case
//! (extended identifiers keep their spelling) and the user's spelling recoverable from the span.

// Syntax nodes are built once and walked; boxing the larger variants would only add noise.
#![allow(clippy::large_enum_variant)]

use crate::source::Span;

/// An identifier; `name` is lower case for basic identifiers, verbatim for `\extended\` ones.
#[derive(Clone, Debug, PartialEq)]
pub struct Ident {
    pub name: String,
    pub span: Span,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct DesignFile {
    pub units: Vec<DesignUnit>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct DesignUnit {
    pub context: Vec<ContextItem>,
    pub unit: LibraryUnit,
    pub span: Span,
    /// Every `a.b` of simple identifiers in the unit's text, in order: the library units it
    /// names by selected name (`work.pkg.item` without a `use` clause) are among them, and
    /// analysis must see those units first (LRM 11.4).
    pub dotted: Vec<(Ident, Ident)>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ContextItem {
    Library(Vec<Ident>, Span),
    Use(Vec<Expr>, Span),
}

#[derive(Clone, Debug, PartialEq)]
pub enum LibraryUnit {
    Entity(Entity),
    Architecture(Architecture),
    Package(Package),
    PackageBody(PackageBody),
    Configuration(Configuration),
}

/// `configuration cfg of e is for arch ... end for; end configuration;`
#[derive(Clone, Debug, PartialEq)]
pub struct Configuration {
    pub name: Ident,
    pub entity: Expr,
    /// Names its use clauses make visible (kept for analysis; elaboration needs none).
    pub uses: Vec<Expr>,
    pub block: BlockConfig,
    pub span: Span,
}

/// `for arch_or_label ... end for;`: the configuration of a block (an architecture, a block
/// or generate statement).
#[derive(Clone, Debug, PartialEq)]
pub struct BlockConfig {
    pub spec: Expr,
    pub items: Vec<ConfigItem>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ConfigItem {
    Block(BlockConfig),
    Component(ComponentConfig),
}

/// `for u1, u2 : comp use entity work.e(a); [for a ... end for;] end for;`
#[derive(Clone, Debug, PartialEq)]
pub struct ComponentConfig {
    pub labels: EntityNames,
    pub component: Expr,
    pub binding: Option<Binding>,
    /// The configuration of the bound entity's architecture, for the instances inside it.
    pub block: Option<BlockConfig>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Entity {
    pub name: Ident,
    pub generics: Vec<InterfaceDecl>,
    pub ports: Vec<InterfaceDecl>,
    pub decls: Vec<Decl>,
    pub stmts: Vec<ConcStmt>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Architecture {
    pub name: Ident,
    pub entity: Ident,
    pub decls: Vec<Decl>,
    pub stmts: Vec<ConcStmt>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Package {
    pub name: Ident,
    pub decls: Vec<Decl>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub struct PackageBody {
    pub name: Ident,
    pub decls: Vec<Decl>,
    pub span: Span,
}

// ---------------------------------------------------------------------------------------------
// Interfaces and declarations

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum ObjectClass {
    Constant,
    Signal,
    Variable,
    File,
    Quantity,
    Terminal,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Mode {
    In,
    Out,
    Inout,
    Buffer,
    Linkage,
}

/// A generic, port or subprogram parameter.
#[derive(Clone, Debug, PartialEq)]
pub struct InterfaceDecl {
    /// The explicit class keyword, if written.
    pub class: Option<ObjectClass>,
    pub names: Vec<Ident>,
    pub mode: Option<Mode>,
    /// For terminals, the nature (`electrical`); otherwise the subtype.
    pub subtype: SubtypeIndication,
    /// A `bus` port: a guarded signal whose drivers in the entity can be disconnected.
    pub bus: bool,
    pub default: Option<Expr>,
    pub span: Span,
}

/// `[resolution] type_mark [constraint] [tolerance "group"]`. An index constraint
/// (`real_vector(1 to 3)`) arrives inside `type_mark` as an [`ExprKind::Apply`]; `analysis`
/// separates it.
#[derive(Clone, Debug, PartialEq)]
pub struct SubtypeIndication {
    pub resolution: Option<Expr>,
    pub type_mark: Expr,
    pub range: Option<Range>,
    pub tolerance: Option<Expr>,
    pub span: Span,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Direction {
    To,
    Downto,
}

/// A range: `a to b`, `b downto a`, or a range attribute name (`x'range`).
#[derive(Clone, Debug, PartialEq)]
pub enum Range {
    Explicit {
        left: Box<Expr>,
        dir: Direction,
        right: Box<Expr>,
        span: Span,
    },
    Attribute(Box<Expr>),
}

/// A discrete range: a range or a subtype (`natural`, `natural range 0 to 3`, `t'range`).
#[derive(Clone, Debug, PartialEq)]
pub enum DiscreteRange {
    Range(Range),
    Subtype(SubtypeIndication),
}

#[derive(Clone, Debug, PartialEq)]
pub struct Decl {
    pub kind: DeclKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum DeclKind {
    Constant {
        names: Vec<Ident>,
        subtype: SubtypeIndication,
        value: Option<Expr>,
    },
    Signal {
        names: Vec<Ident>,
        subtype: SubtypeIndication,
        value: Option<Expr>,
        /// `bus` or `register`: a guarded signal, whose drivers a guarded assignment
        /// disconnects while the guard is false (LRM 4.3.1.2).
        guarded: Option<GuardedKind>,
    },
    Variable {
        shared: bool,
        names: Vec<Ident>,
        subtype: SubtypeIndication,
        value: Option<Expr>,
    },
    File {
        names: Vec<Ident>,
        subtype: SubtypeIndication,
        open_kind: Option<Expr>,
        logical_name: Option<Expr>,
    },
    Type {
        name: Ident,
        /// `None` for an incomplete type declaration.
        def: Option<TypeDef>,
    },
    /// `type t is protected body ... end protected body;`: the private variables and the
    /// methods' bodies of protected type `t`.
    ProtectedBody {
        name: Ident,
        decls: Vec<Decl>,
    },
    Subtype {
        name: Ident,
        subtype: SubtypeIndication,
    },
    Nature {
        name: Ident,
        def: NatureDef,
    },
    /// `subnature s is n [tolerance "a" across "t" through];` (the across tolerance group in
    /// `nature.tolerance`).
    Subnature {
        name: Ident,
        nature: SubtypeIndication,
        through_tolerance: Option<Expr>,
    },
    /// `disconnect s1, s2 : t after 3 ns;` (LRM 5.3): the delay of the null transactions of
    /// guarded signals' drivers.
    Disconnect {
        signals: EntityNames,
        type_mark: Expr,
        after: Expr,
    },
    /// A group template (`template: None`) or a group declaration, whose template name
    /// carries the constituents as arguments (`pair (a, b)`, LRM 4.6, 4.7). Groups only
    /// carry user attributes: the simulator has no use for them.
    Group {
        name: Ident,
        template: Option<Expr>,
    },
    Terminal {
        names: Vec<Ident>,
        nature: SubtypeIndication,
    },
    Quantity(QuantityDecl),
    Alias {
        name: Ident,
        subtype: Option<SubtypeIndication>,
        target: Expr,
        /// `[t1, t2 return r]`: which overload a subprogram or enumeration literal alias
        /// denotes (LRM 2.3.2).
        signature: Option<Signature>,
    },
    Attribute {
        name: Ident,
        type_mark: Expr,
    },
    AttributeSpec {
        attribute: Ident,
        entities: EntityNames,
        class: Ident,
        value: Expr,
    },
    Component {
        name: Ident,
        generics: Vec<InterfaceDecl>,
        ports: Vec<InterfaceDecl>,
    },
    Subprogram(SubprogramSpec),
    SubprogramBody {
        spec: SubprogramSpec,
        decls: Vec<Decl>,
        stmts: Vec<SeqStmt>,
    },
    /// `limit q1, q2 : real with 1.0e-3;`
    Limit {
        quantities: EntityNames,
        type_mark: Expr,
        value: Expr,
    },
    Use(Vec<Expr>),
    /// A configuration specification: `for u1, u2 : comp use entity work.e(a);` (labels
    /// `all` or `others` too).
    Configuration {
        labels: EntityNames,
        component: Expr,
        binding: Binding,
    },
}

/// The binding indication of a configuration specification.
#[derive(Clone, Debug, PartialEq)]
pub struct Binding {
    /// `entity ...` or `configuration ...`; `None` for `use open` or an incremental binding.
    pub unit: Option<InstantiatedUnit>,
    /// No entity aspect written: an incremental binding in a component configuration
    /// (`for u1 : comp generic map (...); end for;`, LRM 5.2.1.1), which keeps the entity of
    /// the primary binding (a configuration specification, or the default binding) and adds
    /// its maps.
    pub incremental: bool,
    pub generic_map: Vec<Assoc>,
    pub port_map: Vec<Assoc>,
    pub span: Span,
}

/// `a, b`, `all` or `others` in attribute, limit and configuration specifications.
/// A signature `[t1, t2 return r]`: parameter and result type marks.
#[derive(Clone, Debug, PartialEq)]
pub struct Signature {
    pub params: Vec<Expr>,
    pub result: Option<Expr>,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum EntityNames {
    List(Vec<Expr>),
    All,
    Others,
}

#[derive(Clone, Debug, PartialEq)]
pub enum TypeDef {
    Enumeration(Vec<EnumLiteral>),
    /// Integer or floating type: `range 0 to 10`, `range -1.0e308 to 1.0e308`.
    Range(Range),
    Physical {
        range: Range,
        primary: Ident,
        secondary: Vec<(Ident, Expr)>,
    },
    Array {
        indexes: Vec<IndexDef>,
        element: SubtypeIndication,
    },
    Record(Vec<RecordField>),
    Access(SubtypeIndication),
    File(Expr),
    /// `type t is protected ... end protected;`: the methods (subprogram declarations).
    Protected(Vec<Decl>),
}

#[derive(Clone, Debug, PartialEq)]
pub enum EnumLiteral {
    Ident(Ident),
    Char(char, Span),
}

#[derive(Clone, Debug, PartialEq)]
pub enum IndexDef {
    /// `natural range <>`
    Unconstrained(Expr),
    Constrained(DiscreteRange),
}

#[derive(Clone, Debug, PartialEq)]
pub struct RecordField {
    pub names: Vec<Ident>,
    pub subtype: SubtypeIndication,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum NatureDef {
    /// `voltage across current through electrical_ref reference`; the reference terminal's
    /// name is missing in SEAMS's dialect (`real across real through;`).
    Scalar {
        across: Expr,
        through: Expr,
        reference: Option<Ident>,
    },
    Array {
        indexes: Vec<IndexDef>,
        element: SubtypeIndication,
    },
    Record(Vec<RecordField>),
}

#[derive(Clone, Debug, PartialEq)]
pub enum QuantityDecl {
    /// `quantity q : real [tolerance "g"] [:= init];`
    Free {
        names: Vec<Ident>,
        subtype: SubtypeIndication,
        value: Option<Expr>,
    },
    /// `quantity v across i through p to n;`
    Branch {
        across: Vec<BranchName>,
        through: Vec<BranchName>,
        plus: Option<Expr>,
        minus: Option<Expr>,
    },
    /// `quantity n : real spectrum mag, phase;` / `noise psd;`
    Source {
        names: Vec<Ident>,
        subtype: SubtypeIndication,
        spectrum: Option<(Expr, Expr)>,
        noise: Option<Expr>,
    },
}

/// One name in a branch quantity declaration, with its own tolerance and initial value.
#[derive(Clone, Debug, PartialEq)]
pub struct BranchName {
    pub names: Vec<Ident>,
    pub tolerance: Option<Expr>,
    pub value: Option<Expr>,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Designator {
    Ident(Ident),
    /// An operator symbol: `"+"`, `"and"` (lower case).
    Operator(String, Span),
}

#[derive(Clone, Debug, PartialEq)]
pub struct SubprogramSpec {
    pub designator: Designator,
    pub is_function: bool,
    pub pure: bool,
    pub params: Vec<InterfaceDecl>,
    pub return_type: Option<Expr>,
    pub span: Span,
}

// ---------------------------------------------------------------------------------------------
// Concurrent and simultaneous statements

#[derive(Clone, Debug, PartialEq)]
pub struct ConcStmt {
    pub label: Option<Ident>,
    pub postponed: bool,
    pub kind: ConcKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Sensitivity {
    All,
    List(Vec<Expr>),
}

#[derive(Clone, Debug, PartialEq)]
pub enum ConcKind {
    Process {
        sensitivity: Option<Sensitivity>,
        decls: Vec<Decl>,
        stmts: Vec<SeqStmt>,
    },
    /// `target <= [delay] wave when c else wave;` (a simple assignment has one branch, no condition)
    ConditionalAssign {
        target: Expr,
        /// `target <= guarded ...`: assigns only while the enclosing block's `GUARD` is true
        /// (LRM 9.5).
        guarded: bool,
        delay: DelayMechanism,
        branches: Vec<(Waveform, Option<Expr>)>,
    },
    SelectedAssign {
        selector: Expr,
        target: Expr,
        guarded: bool,
        delay: DelayMechanism,
        alternatives: Vec<(Waveform, Vec<Choice>)>,
    },
    Instance {
        unit: InstantiatedUnit,
        generic_map: Vec<Assoc>,
        port_map: Vec<Assoc>,
    },
    ForGenerate {
        param: Ident,
        range: DiscreteRange,
        decls: Vec<Decl>,
        stmts: Vec<ConcStmt>,
    },
    IfGenerate {
        condition: Expr,
        decls: Vec<Decl>,
        stmts: Vec<ConcStmt>,
    },
    Block {
        guard: Option<Expr>,
        header: BlockHeader,
        decls: Vec<Decl>,
        stmts: Vec<ConcStmt>,
    },
    Assert(Assertion),
    ProcedureCall(Expr),
    Break(BreakStmt),
    Simultaneous(SimKind),
}

#[derive(Clone, Debug, PartialEq)]
pub enum InstantiatedUnit {
    Component(Expr),
    Entity {
        name: Expr,
        architecture: Option<Ident>,
    },
    Configuration(Expr),
}

#[derive(Clone, Debug, PartialEq)]
pub enum SimKind {
    /// `lhs == rhs [tolerance "g"];`
    Simple {
        lhs: Expr,
        rhs: Expr,
        tolerance: Option<Expr>,
    },
    /// `if c use ... elsif c use ... else ... end use;`
    If {
        branches: Vec<(Expr, Vec<ConcStmt>)>,
        otherwise: Option<Vec<ConcStmt>>,
    },
    Case {
        selector: Expr,
        alternatives: Vec<(Vec<Choice>, Vec<ConcStmt>)>,
    },
    Procedural {
        decls: Vec<Decl>,
        stmts: Vec<SeqStmt>,
    },
    Null,
}

#[derive(Clone, Debug, PartialEq)]
pub struct Assertion {
    pub condition: Expr,
    pub report: Option<Expr>,
    pub severity: Option<Expr>,
}

/// `break [for q1 use] q2 => e, ... [on s1, s2] [when cond]`
#[derive(Clone, Debug, PartialEq)]
pub struct BreakStmt {
    pub elements: Vec<BreakElement>,
    pub sensitivity: Vec<Expr>,
    pub condition: Option<Expr>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct BreakElement {
    pub selector: Option<Expr>,
    pub quantity: Expr,
    pub value: Expr,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum DelayMechanism {
    Default,
    Transport,
    Inertial { reject: Option<Expr> },
}

/// The kind of a guarded signal (LRM 4.3.1.2): with every driver disconnected, a `bus`
/// takes its resolution function's value for no drivers, a `register` keeps its value.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum GuardedKind {
    Bus,
    Register,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Waveform {
    Elements(Vec<WaveElement>),
    Unaffected(Span),
}

#[derive(Clone, Debug, PartialEq)]
pub struct WaveElement {
    /// `None` for `null` (driver disconnection).
    pub value: Option<Expr>,
    pub after: Option<Expr>,
    pub span: Span,
}

// ---------------------------------------------------------------------------------------------
// Sequential statements

#[derive(Clone, Debug, PartialEq)]
pub struct SeqStmt {
    pub label: Option<Ident>,
    pub kind: SeqKind,
    pub span: Span,
}

impl SeqStmt {
    /// Calls `f` on this statement and on every statement nested in it (the branches of an
    /// `if` or `case`, the body of a loop), outer first.
    pub fn walk<'s>(&'s self, f: &mut impl FnMut(&'s SeqStmt)) {
        f(self);
        let mut all = |body: &'s [SeqStmt]| body.iter().for_each(|s| s.walk(f));
        match &self.kind {
            SeqKind::If {
                branches,
                otherwise,
            } => {
                for (_, body) in branches {
                    all(body);
                }
                if let Some(body) = otherwise {
                    all(body);
                }
            }
            SeqKind::Case { alternatives, .. } => {
                for (_, body) in alternatives {
                    all(body);
                }
            }
            SeqKind::Loop { body, .. } => all(body),
            _ => {}
        }
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum SeqKind {
    Wait {
        on: Vec<Expr>,
        until: Option<Expr>,
        timeout: Option<Expr>,
    },
    SignalAssign {
        target: Expr,
        delay: DelayMechanism,
        waveform: Waveform,
    },
    VariableAssign {
        target: Expr,
        value: Expr,
    },
    If {
        branches: Vec<(Expr, Vec<SeqStmt>)>,
        otherwise: Option<Vec<SeqStmt>>,
    },
    Case {
        selector: Expr,
        alternatives: Vec<(Vec<Choice>, Vec<SeqStmt>)>,
    },
    Loop {
        scheme: LoopScheme,
        body: Vec<SeqStmt>,
    },
    Next {
        label: Option<Ident>,
        condition: Option<Expr>,
    },
    Exit {
        label: Option<Ident>,
        condition: Option<Expr>,
    },
    Return(Option<Expr>),
    Null,
    Assert(Assertion),
    Report {
        message: Expr,
        severity: Option<Expr>,
    },
    ProcedureCall(Expr),
    Break(BreakStmt),
}

#[derive(Clone, Debug, PartialEq)]
pub enum LoopScheme {
    Forever,
    While(Expr),
    For(Ident, DiscreteRange),
}

// ---------------------------------------------------------------------------------------------
// Expressions and names

#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

impl Expr {
    /// The identifier a simple or selected name ends in (`u`, `work.e`'s `e`); `None` for
    /// any other expression.
    pub fn name_ident(&self) -> Option<&Ident> {
        match &self.kind {
            ExprKind::Name(id) | ExprKind::Selected(_, id) => Some(id),
            _ => None,
        }
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinaryOp {
    And,
    Or,
    Nand,
    Nor,
    Xor,
    Xnor,
    Eq,
    Ne,
    Lt,
    Le,
    Gt,
    Ge,
    Sll,
    Srl,
    Sla,
    Sra,
    Rol,
    Ror,
    Add,
    Sub,
    Concat,
    Mul,
    Div,
    Mod,
    Rem,
    Pow,
}

impl BinaryOp {
    /// The operator an operator symbol names (`"+"` -> `Add`), case-insensitively.
    pub fn from_symbol(symbol: &str) -> Option<BinaryOp> {
        use BinaryOp::*;
        Some(match symbol.to_ascii_lowercase().as_str() {
            "and" => And,
            "or" => Or,
            "nand" => Nand,
            "nor" => Nor,
            "xor" => Xor,
            "xnor" => Xnor,
            "=" => Eq,
            "/=" => Ne,
            "<" => Lt,
            "<=" => Le,
            ">" => Gt,
            ">=" => Ge,
            "sll" => Sll,
            "srl" => Srl,
            "sla" => Sla,
            "sra" => Sra,
            "rol" => Rol,
            "ror" => Ror,
            "+" => Add,
            "-" => Sub,
            "&" => Concat,
            "*" => Mul,
            "/" => Div,
            "mod" => Mod,
            "rem" => Rem,
            "**" => Pow,
            _ => return None,
        })
    }
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnaryOp {
    Plus,
    Minus,
    Abs,
    Not,
}

impl UnaryOp {
    /// The unary operator an operator symbol names (`"-"` -> `Minus`).
    pub fn from_symbol(symbol: &str) -> Option<UnaryOp> {
        Some(match symbol.to_ascii_lowercase().as_str() {
            "+" => UnaryOp::Plus,
            "-" => UnaryOp::Minus,
            "abs" => UnaryOp::Abs,
            "not" => UnaryOp::Not,
            _ => return None,
        })
    }
}

#[derive(Clone, Debug, PartialEq)]
pub enum Literal {
    Integer(i64),
    Real(f64),
    /// `10 ms`: an abstract literal with a unit name.
    Physical(Box<Literal>, Ident),
    Char(char),
    String(String),
    /// A bit-string literal expanded to its bits (`X"F"` is `"1111"`).
    BitString(String),
    Null,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Name(Ident),
    Literal(Literal),
    /// `prefix.suffix`; the suffix may be `all` (name `"all"`), a character or an operator symbol.
    Selected(Box<Expr>, Ident),
    /// `prefix(args)`: a function call, index, slice or type conversion (decided by `analysis`).
    Apply(Box<Expr>, Vec<Assoc>),
    /// `prefix'attribute` (arguments, if any, arrive as an enclosing `Apply`).
    Attribute(Box<Expr>, Ident),
    /// `type_mark'(expr)` or `type_mark'(aggregate)`.
    Qualified(Box<Expr>, Box<Expr>),
    Aggregate(Vec<ElementAssoc>),
    Paren(Box<Expr>),
    Unary(UnaryOp, Box<Expr>),
    Binary(BinaryOp, Box<Expr>, Box<Expr>),
    /// `new subtype` or `new qualified_expression`.
    New(Box<Expr>),
    /// A name with a signature saying which overload it denotes (`inc [integer return
    /// integer]`): the prefix of an attribute name, or a name in an attribute specification.
    Signed(Box<Expr>, Box<Signature>),
}

/// An association in a call, index, generic or port map: `[formal =>] actual`.
#[derive(Clone, Debug, PartialEq)]
pub struct Assoc {
    pub formal: Option<Expr>,
    pub actual: Actual,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Actual {
    Expr(Expr),
    /// A slice or index range: `a(7 downto 0)`.
    Range(Range),
    Open(Span),
}

#[derive(Clone, Debug, PartialEq)]
pub struct ElementAssoc {
    /// Empty for a positional element.
    pub choices: Vec<Choice>,
    pub value: Expr,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum Choice {
    Expr(Expr),
    Range(Range),
    Others(Span),
}

/// The generic and port clauses of a block statement with their maps (empty when absent).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct BlockHeader {
    pub generics: Vec<InterfaceDecl>,
    pub generic_map: Vec<Assoc>,
    pub ports: Vec<InterfaceDecl>,
    pub port_map: Vec<Assoc>,
}
