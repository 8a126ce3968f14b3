//! A process's frequent instructions pre-lowered at the start of the run: scalar expressions
//! typed once (integers, enumeration positions and booleans, all as `i64`) and evaluated
//! without a `Value`, an `Env` or a `Result` per node; signal assignments with their driver
//! found and their delay read once; waits with their timeout read once.
//!
//! Only a shortcut, as [`super::fast`] is: a lowered instruction either does exactly what
//! the interpreter would, or declines before changing anything (an operand of another kind
//! at run time, an arithmetic error, a value outside its subtype's range), and the
//! interpreter then runs the instruction and gives the same result or words the error.
//! Instructions of procedures are never lowered (a process's own code only).

use vams_design::{
    BinaryOp, DelayMechanism, Design, Expr, Instr, Intrinsic, Process, SignalAttr, Type, UnaryOp,
    Value,
};

use super::eval::offset;
use super::io::CANCEL_CHECK;
use super::process::{ProcState, Suspend, later};
use super::signals::{Delay, SignalState, Signals};

/// The kind of a lowered value, known when the expression is lowered.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) enum Kind {
    Int,
    /// An enumeration position.
    Enum,
    /// 0 or 1.
    Bool,
}

impl Kind {
    /// The kind of `v`, or `None` for another kind of value.
    fn of(v: &Value) -> Option<Kind> {
        match v {
            Value::Integer(_) => Some(Kind::Int),
            Value::Enum(_) => Some(Kind::Enum),
            Value::Boolean(_) => Some(Kind::Bool),
            _ => None,
        }
    }

    /// `v` as an `i64` when it is of this kind.
    #[inline(always)]
    fn read(self, v: &Value) -> Option<i64> {
        match (self, v) {
            (Kind::Int, Value::Integer(i)) => Some(*i),
            (Kind::Enum, Value::Enum(p)) => Some(i64::from(*p)),
            (Kind::Bool, Value::Boolean(b)) => Some(i64::from(*b)),
            _ => None,
        }
    }

    /// The value of this kind that `x` stands for.
    #[inline(always)]
    pub fn value(self, x: i64) -> Value {
        match self {
            Kind::Int => Value::Integer(x),
            // Positions and booleans come from values of their kind.
            Kind::Enum => Value::Enum(x as u32),
            Kind::Bool => Value::Boolean(x != 0),
        }
    }
}

/// An operand read in place.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Leaf {
    Const(i64),
    Signal(usize, Kind),
    Var(usize, Kind),
    /// `s'event`.
    Event(usize),
    /// `s'active`.
    Active(usize),
    /// `s(i)` for a constant `i`: the element at `at` of array signal `s` while it has `len`
    /// elements (the position `offset` gives for that length), of kind `kind`.
    SignalElement {
        signal: u32,
        at: u32,
        len: u32,
        kind: Kind,
    },
    /// `v(i)` for a constant `i`, of an array variable.
    VarElement {
        var: u32,
        at: u32,
        len: u32,
        kind: Kind,
    },
}

/// `rising_edge(s)` or `falling_edge(s)` of `ieee.std_logic_1164` (`x01`) or of
/// `ieee.numeric_bit`: whether `s` had an event in this cycle and went to the edge's level.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
struct Edge {
    signal: u32,
    rising: bool,
    /// std_logic_1164's: levels through `to_x01` ('H' is '1', 'L' is '0'), and the value
    /// before the event (`s'last_value`) at the other level; numeric_bit's tests `s` alone.
    x01: bool,
}

/// Positions of `std_ulogic`'s literals ('U', 'X', '0', '1', 'Z', 'W', 'L', 'H', '-').
const STD_0: u32 = 2;
const STD_1: u32 = 3;
const STD_L: u32 = 6;
const STD_H: u32 = 7;

impl Edge {
    fn of(intrinsic: Intrinsic) -> Edge {
        match intrinsic {
            Intrinsic::StdLogicEdge { signal, rising } => Edge {
                signal: signal.0,
                rising,
                x01: true,
            },
            Intrinsic::BitEdge { signal, rising } => Edge {
                signal: signal.0,
                rising,
                x01: false,
            },
        }
    }

    /// The function's result, 0 or 1: for std_logic_1164 `s'event and to_x01(s) = '1' and
    /// to_x01(s'last_value) = '0'` (the levels exchanged for the falling edge), for
    /// numeric_bit `s'event and s = '1'` (`'0'`); `None`, for the function to run, when the
    /// signal does not hold an enumeration value (it always does). Out of line, to keep
    /// [`Node::eval`]'s code small where it is inlined.
    #[inline(never)]
    fn read(self, signals: &[SignalState]) -> Option<i64> {
        let st = &signals[self.signal as usize];
        let (Value::Enum(now), Value::Enum(last)) = (&st.value, &st.last_value) else {
            return None;
        };
        let (now, last) = (*now, *last);
        let edge = if self.x01 {
            let high = |p: u32| p == STD_1 || p == STD_H;
            let low = |p: u32| p == STD_0 || p == STD_L;
            if self.rising {
                high(now) && low(last)
            } else {
                low(now) && high(last)
            }
        } else {
            // `bit`: '0' is position 0, '1' position 1.
            now == u32::from(self.rising)
        };
        Some(i64::from(st.event && edge))
    }
}

impl Leaf {
    /// `e` as an operand, with its kind.
    fn lower(e: &Expr, cx: &Lowering) -> Option<(Leaf, Kind)> {
        Some(match e {
            Expr::Const(v) => {
                let kind = Kind::of(v)?;
                (Leaf::Const(kind.read(v)?), kind)
            }
            Expr::Signal(s) => {
                let kind = Kind::of(&cx.design.signals.get(s.index())?.init)?;
                (Leaf::Signal(s.index(), kind), kind)
            }
            Expr::Var(v) => {
                let kind = Kind::of(&cx.process.vars.get(v.index())?.init)?;
                (Leaf::Var(v.index(), kind), kind)
            }
            Expr::SignalAttr(s, SignalAttr::Event) => (Leaf::Event(s.index()), Kind::Bool),
            Expr::SignalAttr(s, SignalAttr::Active) => (Leaf::Active(s.index()), Kind::Bool),
            Expr::Index { array, index, ty } => {
                let Expr::Const(Value::Integer(i)) = **index else {
                    return None;
                };
                let init = match **array {
                    Expr::Signal(s) => &cx.design.signals.get(s.index())?.init,
                    Expr::Var(v) => &cx.process.vars.get(v.index())?.init,
                    _ => return None,
                };
                let Value::Array(items) = init else {
                    return None;
                };
                let kind = Kind::of(items.first()?)?;
                let len = u32::try_from(items.len()).ok()?;
                let at = u32::try_from(offset(ty, i, items.len()).ok()?).ok()?;
                let leaf = match **array {
                    Expr::Signal(s) => Leaf::SignalElement {
                        signal: s.0,
                        at,
                        len,
                        kind,
                    },
                    Expr::Var(v) => Leaf::VarElement {
                        var: v.0,
                        at,
                        len,
                        kind,
                    },
                    _ => return None,
                };
                (leaf, kind)
            }
            _ => return None,
        })
    }

    #[inline(always)]
    fn read(self, signals: &[SignalState], vars: &[Value]) -> Option<i64> {
        match self {
            Leaf::Const(c) => Some(c),
            Leaf::Signal(s, kind) => kind.read(&signals[s].value),
            Leaf::Var(v, kind) => kind.read(&vars[v]),
            Leaf::Event(s) => Some(i64::from(signals[s].event)),
            Leaf::Active(s) => Some(i64::from(signals[s].active)),
            Leaf::SignalElement {
                signal,
                at,
                len,
                kind,
            } => element_at(&signals[signal as usize].value, at, len, kind),
            Leaf::VarElement { var, at, len, kind } => {
                element_at(&vars[var as usize], at, len, kind)
            }
        }
    }
}

/// An operator on two lowered values of one kind: integer arithmetic, comparisons (of
/// positions, booleans as 0 and 1, which order as VHDL's `false < true`), logic on booleans
/// and bits.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Operator {
    Add,
    Sub,
    Mul,
    Div,
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
}

impl Operator {
    /// `op` on operands of `kind`, with the kind of its result.
    fn of(op: BinaryOp, kind: Kind) -> Option<(Operator, Kind)> {
        use Kind::*;
        let logic = matches!(kind, Bool | Enum);
        Some(match op {
            BinaryOp::Add if kind == Int => (Operator::Add, Int),
            BinaryOp::Sub if kind == Int => (Operator::Sub, Int),
            BinaryOp::Mul if kind == Int => (Operator::Mul, Int),
            BinaryOp::Div if kind == Int => (Operator::Div, Int),
            BinaryOp::Mod if kind == Int => (Operator::Mod, Int),
            BinaryOp::Rem if kind == Int => (Operator::Rem, Int),
            BinaryOp::Eq => (Operator::Eq, Bool),
            BinaryOp::Ne => (Operator::Ne, Bool),
            BinaryOp::Lt => (Operator::Lt, Bool),
            BinaryOp::Le => (Operator::Le, Bool),
            BinaryOp::Gt => (Operator::Gt, Bool),
            BinaryOp::Ge => (Operator::Ge, Bool),
            BinaryOp::And if logic => (Operator::And, kind),
            BinaryOp::Or if logic => (Operator::Or, kind),
            BinaryOp::Nand if logic => (Operator::Nand, kind),
            BinaryOp::Nor if logic => (Operator::Nor, kind),
            BinaryOp::Xor if logic => (Operator::Xor, kind),
            BinaryOp::Xnor if logic => (Operator::Xnor, kind),
            _ => return None,
        })
    }

    /// `x op y` as `ops::binary` computes it for two values of the operator's kind; `None`
    /// for an arithmetic error (overflow, division by zero).
    #[inline(always)]
    fn apply(self, x: i64, y: i64) -> Option<i64> {
        // `ops::logic`: booleans, and `bit` with '0' as 0 and '1' as 1.
        let (p, q) = (x != 0, y != 0);
        Some(match self {
            Operator::Add => x.checked_add(y)?,
            Operator::Sub => x.checked_sub(y)?,
            Operator::Mul => x.checked_mul(y)?,
            // Rust's `/` truncates towards zero, as VHDL's does.
            Operator::Div => x.checked_div(y)?,
            // `rem` has the sign of the left operand (Rust's `%`), `mod` that of the right.
            Operator::Rem => x.checked_rem(y)?,
            Operator::Mod => {
                let r = x.checked_rem(y)?;
                if r != 0 && (r < 0) != (y < 0) {
                    r + y
                } else {
                    r
                }
            }
            Operator::Eq => i64::from(x == y),
            Operator::Ne => i64::from(x != y),
            Operator::Lt => i64::from(x < y),
            Operator::Le => i64::from(x <= y),
            Operator::Gt => i64::from(x > y),
            Operator::Ge => i64::from(x >= y),
            Operator::And => i64::from(p && q),
            Operator::Or => i64::from(p || q),
            Operator::Nand => i64::from(!(p && q)),
            Operator::Nor => i64::from(!(p || q)),
            Operator::Xor => i64::from(p != q),
            Operator::Xnor => i64::from(p == q),
        })
    }
}

/// One step of a lowered expression, which works on an accumulator and a small stack.
#[derive(Debug)]
enum Step<'d> {
    /// Pushes the accumulator and loads an operand.
    Load(Leaf),
    /// `acc := acc op operand`.
    With(Operator, Leaf),
    /// `acc := acc op constant`.
    WithConst(Operator, i64),
    /// `acc := popped op acc`.
    Pop(Operator),
    /// Integer negation and `abs`.
    Neg,
    Abs,
    /// `not` of a boolean or a bit (`ops::unary`: '0' is 0, '1' is 1).
    Not,
    /// `acc := s(acc)`, an element of array signal `s` of type `ty`, of kind `kind`.
    SignalElement(usize, &'d Type, Kind),
    /// `acc := v(acc)`, of an array variable.
    VarElement(usize, &'d Type, Kind),
}

/// Operands a lowered expression may hold on its stack at once.
const DEPTH: usize = 4;

/// A scalar expression lowered: its shape and the kind of its value.
#[derive(Debug)]
pub(crate) struct Node<'d> {
    shape: Shape<'d>,
    /// The kind of its value.
    pub kind: Kind,
}

/// The forms of a lowered expression: the two most frequent (an operand, an operand and a
/// constant: `clk = '1'`, `q(3)`) evaluated inline where they are used, without the loop
/// and the stack of the general one.
#[derive(Debug)]
enum Shape<'d> {
    Leaf(Leaf),
    /// `leaf op constant`.
    WithConst(Leaf, Operator, i64),
    /// `leaf op constant op constant ...` (`(count + 1) mod 1000000`): no stack.
    Consts(Leaf, Box<[(Operator, i64)]>),
    /// A call of the bundled `rising_edge(s)` or `falling_edge(s)` (`design::Intrinsic`),
    /// the whole expression (`if rising_edge(clk) then`), read from the signal's state as
    /// the function's body reads it, without a call. A shape rather than an operand: as an
    /// operand its arm in [`Leaf::read`], inlined wherever an operand is read, made the
    /// shift register's `clk = '1'` about 6 % slower.
    Edge(Edge),
    /// Steps in postfix order after the first operand.
    Steps {
        first: Leaf,
        steps: Box<[Step<'d>]>,
    },
}

/// What lowering reads: the design and the process whose code it lowers.
struct Lowering<'d> {
    design: &'d Design,
    process: &'d Process,
}

impl<'d> Node<'d> {
    /// `e` lowered, or `None` when it is not made of the forms above.
    fn lower(e: &'d Expr, cx: &Lowering<'d>) -> Option<Node<'d>> {
        if let Expr::FnCall { sub, args, .. } = e
            && args.is_empty()
        {
            let intrinsic = cx.design.subprograms.get(sub.index())?.intrinsic?;
            return Some(Node {
                shape: Shape::Edge(Edge::of(intrinsic)),
                kind: Kind::Bool,
            });
        }
        let mut steps = Vec::new();
        let mut depth = 0;
        let kind = compile(e, cx, &mut steps, &mut depth, 0)?;
        let Some(Step::Load(first)) = steps.first() else {
            return None;
        };
        let first = *first;
        let shape = match steps[1..] {
            [] => Shape::Leaf(first),
            [Step::WithConst(op, c)] => Shape::WithConst(first, op, c),
            ref rest if rest.iter().all(|s| matches!(s, Step::WithConst(..))) => Shape::Consts(
                first,
                (rest.iter())
                    .filter_map(|s| match s {
                        Step::WithConst(op, c) => Some((*op, *c)),
                        _ => None,
                    })
                    .collect(),
            ),
            _ => {
                steps.remove(0);
                Shape::Steps {
                    first,
                    steps: steps.into_boxed_slice(),
                }
            }
        };
        Some(Node { shape, kind })
    }

    /// The value, as `eval` computes it (as an `i64` of [`Node::kind`]); `None` where `eval`
    /// would give a value of another kind or an error.
    #[inline(always)]
    pub fn eval(&self, signals: &[SignalState], vars: &[Value]) -> Option<i64> {
        match &self.shape {
            Shape::Leaf(leaf) => leaf.read(signals, vars),
            Shape::WithConst(leaf, op, c) => op.apply(leaf.read(signals, vars)?, *c),
            Shape::Consts(leaf, ops) => eval_consts(leaf, ops, signals, vars),
            Shape::Steps { first, steps } => eval_steps(first, steps, signals, vars),
            Shape::Edge(edge) => edge.read(signals),
        }
    }
}

impl Leaf {
    /// Whether it reads signals and constants only (no variable of the process).
    fn reads_signals_only(self) -> bool {
        !matches!(self, Leaf::Var(..) | Leaf::VarElement { .. })
    }
}

/// A condition that reads signals and constants only, as a value: two processes whose idle
/// branches ([`idle_branch`]) have equal keys have conditions of equal value in any one
/// cycle (signals change only in the update phase), so the kernel evaluates it once per
/// cycle for all of them (the 1001 stages of the shift register all test `clk = '1'`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub(crate) struct CondKey(KeyShape);

/// The shapes of [`CondKey`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum KeyShape {
    Leaf(Leaf),
    WithConst(Leaf, Operator, i64),
    Edge(Edge),
}

impl Node<'_> {
    /// Its [`CondKey`], for the simple shapes that read signals and constants only.
    fn key(&self) -> Option<CondKey> {
        Some(CondKey(match self.shape {
            Shape::Leaf(leaf) if leaf.reads_signals_only() => KeyShape::Leaf(leaf),
            Shape::WithConst(leaf, op, c) if leaf.reads_signals_only() => {
                KeyShape::WithConst(leaf, op, c)
            }
            Shape::Edge(edge) => KeyShape::Edge(edge),
            _ => return None,
        }))
    }
}

/// [`Node::eval`] of `leaf` and its constant operands.
#[inline(never)]
fn eval_consts(
    leaf: &Leaf,
    ops: &[(Operator, i64)],
    signals: &[SignalState],
    vars: &[Value],
) -> Option<i64> {
    let mut acc = leaf.read(signals, vars)?;
    for &(op, c) in ops {
        acc = op.apply(acc, c)?;
    }
    Some(acc)
}

/// [`Node::eval`] of the general shape: `first`, then `steps`.
#[inline(never)]
fn eval_steps(
    first: &Leaf,
    steps: &[Step],
    signals: &[SignalState],
    vars: &[Value],
) -> Option<i64> {
    let mut acc = first.read(signals, vars)?;
    let mut stack = [0i64; DEPTH];
    let mut sp = 0;
    for step in steps {
        acc = match step {
            Step::WithConst(op, c) => op.apply(acc, *c)?,
            Step::With(op, leaf) => op.apply(acc, leaf.read(signals, vars)?)?,
            Step::Load(leaf) => {
                stack[sp] = acc;
                sp += 1;
                leaf.read(signals, vars)?
            }
            Step::Pop(op) => {
                sp -= 1;
                op.apply(stack[sp], acc)?
            }
            Step::Neg => acc.checked_neg()?,
            Step::Abs => acc.checked_abs()?,
            Step::Not => 1 - acc.min(1),
            Step::SignalElement(s, ty, kind) => element(&signals[*s].value, acc, ty, *kind)?,
            Step::VarElement(v, ty, kind) => element(&vars[*v], acc, ty, *kind)?,
        };
    }
    Some(acc)
}

/// Appends the steps of `e`, returning its kind; `depth` is the deepest stack so far, `sp`
/// the stack's height before `e`.
fn compile<'d>(
    e: &'d Expr,
    cx: &Lowering<'d>,
    steps: &mut Vec<Step<'d>>,
    depth: &mut usize,
    sp: usize,
) -> Option<Kind> {
    Some(match e {
        // A constant index is an operand's (`Leaf::SignalElement`).
        Expr::Index { array, index, ty } if !matches!(**index, Expr::Const(_)) => {
            if compile(index, cx, steps, depth, sp)? != Kind::Int {
                return None;
            }
            // The kind of the array's elements, from its initial value.
            let element_kind = |init: &Value| match init {
                Value::Array(items) => Kind::of(items.first()?),
                _ => None,
            };
            let (step, kind) = match **array {
                Expr::Signal(s) => {
                    let kind = element_kind(&cx.design.signals.get(s.index())?.init)?;
                    (Step::SignalElement(s.index(), ty, kind), kind)
                }
                Expr::Var(v) => {
                    let kind = element_kind(&cx.process.vars.get(v.index())?.init)?;
                    (Step::VarElement(v.index(), ty, kind), kind)
                }
                _ => return None,
            };
            steps.push(step);
            kind
        }
        Expr::Unary(op, a) => {
            let kind = compile(a, cx, steps, depth, sp)?;
            match (op, kind) {
                (UnaryOp::Plus, Kind::Int) => {}
                (UnaryOp::Neg, Kind::Int) => steps.push(Step::Neg),
                (UnaryOp::Abs, Kind::Int) => steps.push(Step::Abs),
                (UnaryOp::Not, Kind::Bool | Kind::Enum) => steps.push(Step::Not),
                _ => return None,
            }
            kind
        }
        Expr::Binary(op, a, b) => {
            let kind = compile(a, cx, steps, depth, sp)?;
            let right = match Leaf::lower(b, cx) {
                Some((leaf, right)) => {
                    let operator = Operator::of(*op, kind)?.0;
                    steps.push(match leaf {
                        Leaf::Const(c) => Step::WithConst(operator, c),
                        leaf => Step::With(operator, leaf),
                    });
                    right
                }
                None => {
                    let right = compile(b, cx, steps, depth, sp + 1)?;
                    steps.push(Step::Pop(Operator::of(*op, kind)?.0));
                    right
                }
            };
            // Two operands of one kind only (the general path handles mixed ones).
            if right != kind {
                return None;
            }
            Operator::of(*op, kind)?.1
        }
        _ => {
            // A load pushes the accumulator (the first one pushes nothing that is read).
            *depth = (*depth).max(sp + 1);
            if *depth > DEPTH {
                return None;
            }
            let (leaf, kind) = Leaf::lower(e, cx)?;
            steps.push(Step::Load(leaf));
            kind
        }
    })
}

/// The element at `at` of array value `array` when it has `len` elements (where the
/// position was found), of kind `kind`.
#[inline(always)]
fn element_at(array: &Value, at: u32, len: u32, kind: Kind) -> Option<i64> {
    match array {
        Value::Array(items) if items.len() == len as usize => kind.read(&items[at as usize]),
        _ => None,
    }
}

/// Element `i` of array value `array` of type `ty`, of kind `kind`.
#[inline(always)]
fn element(array: &Value, i: i64, ty: &Type, kind: Kind) -> Option<i64> {
    match array {
        Value::Array(items) => kind.read(&items[offset(ty, i, items.len()).ok()?]),
        _ => None,
    }
}

/// How a lowered assignment edits its driver's waveform.
#[derive(Clone, Copy, Debug)]
pub(crate) enum Mechanism {
    Transport,
    /// Inertial; the rejection interval starts this long after now (the first delay minus
    /// the rejection limit, at least 0).
    Inertial(f64),
}

/// Where a lowered instruction goes on when it falls through: the next instruction, or the
/// target of the `Jump` there, taken in the same dispatch (`jumps` 1: the jump still counts
/// as an instruction, so the runaway limit and the cancel checks come where they did).
#[derive(Clone, Copy, Debug)]
pub(crate) struct Next {
    /// 32 bits, as `jumps`: a smaller [`Op`] (a process's lowered code in fewer cache lines).
    pc: u32,
    jumps: u32,
}

impl Next {
    /// What follows instruction `pc` of `code`.
    fn after(code: &[Instr], pc: usize) -> Option<Next> {
        Next::at(code, pc + 1)
    }

    /// Instruction `pc` of `code`, or the target of the `Jump` there; `None` beyond 32 bits.
    fn at(code: &[Instr], pc: usize) -> Option<Next> {
        Some(match code.get(pc) {
            Some(Instr::Jump(target)) => Next {
                pc: u32::try_from(*target).ok()?,
                jumps: 1,
            },
            _ => Next {
                pc: u32::try_from(pc).ok()?,
                jumps: 0,
            },
        })
    }

    /// The instruction to go on at and the instructions taken to get there (the one that
    /// went on included): through the jump when `THREAD`, else to `plain`.
    #[inline(always)]
    fn go<const THREAD: bool>(self, plain: usize) -> (usize, usize) {
        if THREAD {
            (self.pc as usize, 1 + self.jumps as usize)
        } else {
            (plain, 1)
        }
    }
}

/// A lowered instruction, at the index of the instruction it stands for.
#[derive(Debug)]
pub(crate) enum Op<'d> {
    /// Not lowered: the interpreter runs it.
    General,
    Jump(usize),
    /// `JumpIfNot`.
    Branch {
        cond: Node<'d>,
        target: usize,
        /// Where it goes on when the condition holds, and when it does not.
        holds: Next,
        fails: Next,
    },
    /// A wait of the process's own code: its timeout in seconds, literal and not negative.
    Wait {
        timeout: Option<f64>,
        /// `wait;`: no condition, timeout or sensitivity.
        halts: bool,
    },
    /// A one-element waveform of a scalar value with a literal delay, to a driver found now.
    Assign {
        driver: usize,
        value: Node<'d>,
        delay: f64,
        mechanism: Mechanism,
        /// The target's integer subtype's bounds (all of `i64` without a subtype).
        range: (i64, i64),
        next: Next,
    },
    SetVar {
        var: usize,
        value: Node<'d>,
        range: (i64, i64),
        next: Next,
    },
}

/// What a lowered instruction did.
pub(crate) enum Flow {
    /// Go on at `state.pc`, after this many instructions (a jump taken with it counts).
    Next(usize),
    Suspend(Suspend),
}

/// Executes lowered instruction `op` at `state.pc` of the process's own code: `None`, having
/// changed nothing, when it is not lowered or declines (the interpreter then runs it). With
/// `THREAD`, an instruction followed by a `Jump` takes it too.
#[inline(always)]
pub(crate) fn step<const THREAD: bool>(
    op: &Op,
    state: &mut ProcState,
    signals: &mut Signals,
    now: f64,
) -> Option<Flow> {
    let pc = state.pc;
    match op {
        Op::General => None,
        Op::Jump(target) => {
            state.pc = *target;
            Some(Flow::Next(1))
        }
        Op::Branch {
            cond,
            target,
            holds,
            fails,
        } => {
            let (to, steps) = if cond.eval(&signals.states, &state.vars)? != 0 {
                holds.go::<THREAD>(pc + 1)
            } else {
                fails.go::<THREAD>(*target)
            };
            state.pc = to;
            Some(Flow::Next(steps))
        }
        Op::Wait { timeout, halts } => {
            state.pc = pc + 1;
            if *halts {
                state.halted = true;
                return Some(Flow::Suspend(Suspend::Halt));
            }
            state.waiting_at = Some(pc);
            state.timeout_at = timeout.map(|d| later(now, d));
            Some(Flow::Suspend(Suspend::Wait))
        }
        Op::Assign {
            driver,
            value,
            delay,
            mechanism,
            range,
            next,
        } => {
            let v = value.eval(&signals.states, &state.vars)?;
            if !in_range(v, *range) {
                return None;
            }
            let mechanism = match *mechanism {
                Mechanism::Transport => Delay::Transport,
                Mechanism::Inertial(start) => Delay::Inertial(later(now, start)),
            };
            signals.assign_scalar(*driver, value.kind, v, later(now, *delay), mechanism);
            let (to, steps) = next.go::<THREAD>(pc + 1);
            state.pc = to;
            Some(Flow::Next(steps))
        }
        Op::SetVar {
            var,
            value,
            range,
            next,
        } => {
            let v = value.eval(&signals.states, &state.vars)?;
            if !in_range(v, *range) {
                return None;
            }
            state.vars[*var] = value.kind.value(v);
            let (to, steps) = next.go::<THREAD>(pc + 1);
            state.pc = to;
            Some(Flow::Next(steps))
        }
    }
}

/// Whether `v` is within `range`, the bounds of the target's integer subtype (lowering
/// keeps them for integer values only).
#[inline(always)]
fn in_range(v: i64, (lo, hi): (i64, i64)) -> bool {
    lo <= v && v <= hi
}

/// The bounds [`in_range`] checks: `range`, or all of `i64` (no check) without one; a pair
/// rather than an `Option`, for a smaller [`Op`].
fn bounds(range: Option<(i64, i64)>) -> (i64, i64) {
    range.unwrap_or((i64::MIN, i64::MAX))
}

/// How far [`run`] got.
pub(crate) enum Ran {
    Suspended(Suspend),
    /// At an instruction it leaves to the interpreter, after `steps` instructions.
    Declined {
        steps: usize,
    },
}

/// Runs the process from `state.pc` through its lowered instructions: to its suspension, or
/// to the first instruction that is not lowered or declines, or (leaving the cancel check to
/// the interpreter) to the step before the interpreter's first look at the cancel flag.
#[inline(always)]
pub(crate) fn run(ops: &[Op], state: &mut ProcState, signals: &mut Signals, now: f64) -> Ran {
    if state.running.is_some() {
        state.waiting_at = None;
        state.timeout_at = None;
        return Ran::Declined { steps: 0 };
    }
    let mut steps = 0;
    // A process resumes after its wait, most often at the jump back to the top of its loop
    // (a process with a sensitivity list): taken on a branch of its own, not through the
    // indirect jump of the shared dispatch below (the shift register about 9 % faster;
    // counted as the dispatch would, so the runaway limit and the cancel checks are where
    // they were).
    if let Some(Op::Jump(target)) = ops.get(state.pc) {
        state.pc = *target;
        steps = 1;
    }
    run_from(ops, state, signals, now, steps)
}

/// [`run`] from `state.pc` of the process's own code, `steps` instructions into the
/// activation (the process resumed: no longer waiting).
#[inline(always)]
pub(crate) fn run_from(
    ops: &[Op],
    state: &mut ProcState,
    signals: &mut Signals,
    now: f64,
    mut steps: usize,
) -> Ran {
    state.waiting_at = None;
    state.timeout_at = None;
    // A step takes at most two instructions (and `steps` starts far below the limit), so
    // this stops at `CANCEL_CHECK - 1` at most.
    while steps < CANCEL_CHECK - 2 {
        match ops
            .get(state.pc)
            .and_then(|op| step::<true>(op, state, signals, now))
        {
            Some(Flow::Next(taken)) => steps += taken,
            Some(Flow::Suspend(s)) => return Ran::Suspended(s),
            None => return Ran::Declined { steps },
        }
    }
    Ran::Declined { steps }
}

/// For a process with one wait, without a timeout or a condition (a sensitivity list), the
/// branch that it takes first when it resumes, whose false condition leads straight back to
/// that wait (`if rising_edge(clk)`-style bodies: `if clk = '1' then ... end if;`): with the
/// condition false, running the process changes nothing but its instruction count, so
/// [`resume`] lets the kernel leave it waiting (half the activations of a clocked process);
/// with the condition true, the process goes on after the branch without evaluating it
/// again. `None` for any other shape.
pub(crate) fn idle_branch(ops: &[Op], process: &Process) -> Option<IdleBranch> {
    let wait = process
        .code
        .iter()
        .position(|c| matches!(c, Instr::Wait { .. }))?;
    let Op::Wait {
        timeout: None,
        halts: false,
    } = ops.get(wait)?
    else {
        return None;
    };
    // Where it resumes, through the jump there as `run` takes it.
    let (mut pc, mut jumps) = (wait + 1, 0);
    if let Some(Op::Jump(target)) = ops.get(pc) {
        (pc, jumps) = (*target, 1);
    }
    match ops.get(pc)? {
        Op::Branch { holds, fails, .. } if fails.pc as usize == wait => {
            let (to, taken) = holds.go::<true>(pc + 1);
            Some(IdleBranch {
                pc,
                then: u32::try_from(to).ok()?,
                steps: u32::try_from(jumps + taken).ok()?,
                class: NO_CLASS,
            })
        }
        _ => None,
    }
}

/// An [`idle_branch`]: its instruction index, where the process goes on when its condition
/// holds and the instructions it has then taken (the jump back to the top of the process's
/// loop, the branch and the jump it takes with it), and the class of its condition.
#[derive(Clone, Copy, Debug)]
pub(crate) struct IdleBranch {
    pub pc: usize,
    pub then: u32,
    pub steps: u32,
    /// The kernel's number for its condition's `key`, shared by the idle branches with
    /// equal keys ([`NO_CLASS`]: none, evaluated for each process).
    pub class: u32,
}

/// [`IdleBranch::class`] of a condition that is evaluated for each process.
pub(crate) const NO_CLASS: u32 = u32::MAX;

/// What a process resumed at its [`idle_branch`] does.
pub(crate) enum Resume {
    /// Its condition is false: the process would go back to its wait as it is.
    Idle,
    /// Its condition holds: go on at `pc`, `steps` instructions into the activation.
    At { pc: usize, steps: usize },
    /// The lowered condition declines: run the process as usual.
    Run,
}

impl IdleBranch {
    /// What the process of code `ops` does when it resumes at this branch; `known`, the
    /// class of the last condition evaluated in this cycle and its value (`None`: the
    /// lowered condition declined), is used and updated for a condition of signals alone.
    #[inline(always)]
    pub fn resume(
        self,
        ops: &[Op],
        signals: &[SignalState],
        vars: &[Value],
        known: &mut (u32, Option<bool>),
    ) -> Resume {
        let holds = if self.class != NO_CLASS && self.class == known.0 {
            known.1
        } else {
            let holds = match ops.get(self.pc) {
                Some(Op::Branch { cond, .. }) => cond.eval(signals, vars).map(|c| c != 0),
                _ => None,
            };
            if self.class != NO_CLASS {
                *known = (self.class, holds);
            }
            holds
        };
        match holds {
            Some(false) => Resume::Idle,
            Some(true) => Resume::At {
                pc: self.then as usize,
                steps: self.steps as usize,
            },
            None => Resume::Run,
        }
    }
}

/// The [`CondKey`] of the condition of the [`idle_branch`] `at` of `ops`, if it has one.
pub(crate) fn idle_key(ops: &[Op], at: IdleBranch) -> Option<CondKey> {
    match ops.get(at.pc)? {
        Op::Branch { cond, .. } => cond.key(),
        _ => None,
    }
}

/// A literal delay in seconds (as `process::seconds_of` reads one without evaluating it).
fn literal_seconds(e: &Expr) -> Option<f64> {
    match e {
        Expr::Const(Value::Time(t) | Value::Real(t)) => Some(*t),
        _ => None,
    }
}

/// Process `index`'s code lowered, one [`Op`] per instruction; `sensitivity[pc]` the
/// signals the wait at `pc` is sensitive to (`ProcState`'s).
pub(crate) fn lower<'d>(
    design: &'d Design,
    signals: &Signals,
    index: usize,
    process: &'d Process,
) -> Vec<Op<'d>> {
    let waits_on = |pc: usize| match &process.code[pc] {
        Instr::Wait { on, until, .. } if on.is_empty() => {
            until.as_ref().is_some_and(|u| !u.signals().is_empty())
        }
        Instr::Wait { .. } => true,
        _ => false,
    };
    let cx = Lowering { design, process };
    (0..process.code.len())
        .map(|pc| lower_one(&cx, signals, index, pc, waits_on(pc)))
        .map(|op| op.unwrap_or(Op::General))
        .collect()
}

fn lower_one<'d>(
    cx: &Lowering<'d>,
    signals: &Signals,
    index: usize,
    pc: usize,
    sensitive: bool,
) -> Option<Op<'d>> {
    let (design, process) = (cx.design, cx.process);
    Some(match &process.code[pc] {
        Instr::Jump(target) => Op::Jump(*target),
        Instr::JumpIfNot { cond, target } => Op::Branch {
            cond: Node::lower(cond, cx).filter(|c| c.kind == Kind::Bool)?,
            target: *target,
            holds: Next::after(&process.code, pc)?,
            fails: Next::at(&process.code, *target)?,
        },
        Instr::Wait { until, timeout, .. } => {
            let timeout = match timeout {
                Some(t) => Some(literal_seconds(t).filter(|d| *d >= 0.0)?),
                None => None,
            };
            Op::Wait {
                timeout,
                halts: until.is_none() && timeout.is_none() && !sensitive,
            }
        }
        Instr::SetVar { var, value } => {
            let value = Node::lower(value, cx)?;
            Op::SetVar {
                var: var.index(),
                range: bounds(
                    (process.vars.get(var.index())?.range).filter(|_| value.kind == Kind::Int),
                ),
                value,
                next: Next::after(&process.code, pc)?,
            }
        }
        Instr::Assign {
            target,
            index: element,
            waveform,
            mechanism,
        } => {
            let [(Some(value), delay)] = waveform.as_slice() else {
                return None;
            };
            let delay = literal_seconds(delay).filter(|d| *d >= 0.0)?;
            let mechanism = match mechanism {
                DelayMechanism::Transport => Mechanism::Transport,
                DelayMechanism::Inertial { reject: None } => Mechanism::Inertial(0.0),
                DelayMechanism::Inertial { reject: Some(r) } => {
                    Mechanism::Inertial((delay - literal_seconds(r)?).max(0.0))
                }
            };
            let signal = design.signals.get(target.index())?;
            // The driver the interpreter finds: of the whole signal, or of a static element
            // of a signal driven element by element.
            let driver = match (element, signals.split(*target)) {
                (None, None) => signals.driver(index, *target, None)?,
                (Some(Expr::Const(Value::Integer(i))), Some(n)) => {
                    let k = offset(&signal.ty, *i, n).ok()?;
                    signals.driver(index, *target, Some(k))?
                }
                _ => return None,
            };
            let value = Node::lower(value, cx)?;
            Op::Assign {
                driver,
                range: bounds(signal.range.filter(|_| value.kind == Kind::Int)),
                value,
                delay,
                mechanism,
                next: Next::after(&process.code, pc)?,
            }
        }
        _ => return None,
    })
}

#[cfg(test)]
mod edge_tests;

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::eval::{Env, eval};
    use crate::kernel::io::Io;

    /// Wherever a lowered expression gives a value, the general evaluation gives the same.
    #[test]
    fn lowered_expressions_agree_with_the_general_evaluation() {
        use BinaryOp::*;
        let inits = [
            Value::Integer(7),
            Value::Enum(1),
            Value::Boolean(true),
            Value::Real(1.5),
            Value::Enum(0),
            Value::Boolean(false),
            Value::Integer(-3),
        ];
        let process = Process {
            name: "p".into(),
            vars: inits
                .iter()
                .map(|v| vams_design::Variable {
                    name: "v".into(),
                    ty: Type::Integer,
                    init: v.clone(),
                    range: None,
                })
                .collect(),
            code: Vec::new(),
            spans: Vec::new(),
            span: vams_syntax::source::Span::default(),
            driver_inits: Vec::new(),
        };
        let design = Design::default();
        let cx = Lowering {
            design: &design,
            process: &process,
        };
        let io = Io::default();
        // The values at run time, some of another kind than their initial value's.
        let runs = [
            inits.to_vec(),
            vec![
                Value::Integer(i64::MAX),
                Value::Enum(0),
                Value::Boolean(false),
                Value::Real(1.5),
                Value::Boolean(true),
                Value::Boolean(true),
                Value::Integer(i64::MIN),
            ],
        ];
        let leaves: Vec<Expr> = (0..inits.len())
            .map(|v| Expr::Var(vams_design::VarId(v as u32)))
            .chain([0, 1, -1, 3, i64::MAX, i64::MIN].map(|i| Expr::Const(Value::Integer(i))))
            .chain([
                Expr::Const(Value::Enum(1)),
                Expr::Const(Value::Boolean(true)),
            ])
            .collect();
        let ops = [
            Add, Sub, Mul, Div, Mod, Rem, Eq, Ne, Lt, Le, Gt, Ge, And, Or, Nand, Nor, Xor, Xnor,
            Pow,
        ];
        let mut agreed = 0;
        for vars in &runs {
            let env = Env {
                signals: &[],
                vars,
                quantities: &[],
                derivatives: &[],
                now: 0.0,
                subprograms: &[],
                depth: 0,
                io: &io,
                drivers: None,
            };
            let mut check = |e: &Expr| {
                if let Some(node) = Node::lower(e, &cx)
                    && let Some(v) = node.eval(&[], vars)
                {
                    assert_eq!(Ok(node.kind.value(v)), eval(e, &env), "{e:?}");
                    agreed += 1;
                }
            };
            for a in &leaves {
                for op in [UnaryOp::Neg, UnaryOp::Not, UnaryOp::Abs, UnaryOp::Plus] {
                    check(&Expr::Unary(op, Box::new(a.clone())));
                }
                for b in &leaves {
                    for op in ops {
                        let e = Expr::Binary(op, Box::new(a.clone()), Box::new(b.clone()));
                        check(&e);
                        // Nested on either side, with the stack.
                        let plus = Expr::Binary(Add, Box::new(a.clone()), Box::new(b.clone()));
                        check(&Expr::Binary(
                            op,
                            Box::new(plus.clone()),
                            Box::new(b.clone()),
                        ));
                        check(&Expr::Binary(op, Box::new(a.clone()), Box::new(plus)));
                    }
                }
            }
        }
        assert!(agreed > 2000, "{agreed}");
    }
}
