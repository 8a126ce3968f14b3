//! Flat instruction tapes: many [`Sym`] trees compiled into one straight-line program over a
//! register file.
//!
//! Layout of the registers: the folded constants (written once at compile time), then the
//! inputs the tape reads (each `x_i`, `x'_i`, signal and `now` once, gathered at the start of
//! every evaluation), then one register per instruction. Identical sub-expressions are
//! compiled once (hash-consing; operands of `+` and `*` in a canonical order), so a residual
//! and its derivatives share work when compiled together. A few exact rewrites happen on the
//! way (`a + -b` is `a - b`, `--a` is `a`, `x / 2^k` is `x * 2^-k`: the tape's values stay
//! bitwise those of [`Sym::eval`]); instructions no output needs are dropped. Evaluation is one
//! pass over a flat instruction enum: no allocation, no tree walking. The instructions that
//! only one branch of an `If` needs sit behind a jump, so only the taken branch runs (the
//! condition is computed first; a select then picks the branch's value, as it would if both
//! had run); branches with less work than a jump are computed unconditionally.
//!
//! **Sections.** Roots compiled before [`TapeBuilder::end_section`] need only instructions
//! that come before every instruction of later roots, so a tape of residuals followed by their
//! Jacobian entries evaluates the residuals alone as a prefix. The tape remembers how far it
//! has evaluated for the inputs it last gathered: asking for the Jacobian at the point whose
//! residual was just computed runs only the Jacobian's own instructions (the exponentials and
//! conditions they share with the residual are not computed twice).

use rustc_hash::FxHashMap;

use std::sync::Arc;

use super::sym::{Bin, Sym, Un, apply_binary, apply_unary};
use vams_design::pwl::Table;

/// An instruction while compiling: loads are instructions too, so they are hash-consed.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Op {
    X(u32),
    Dot(u32),
    Signal(u32),
    Now,
    Un(Un, u32),
    Bin(Bin, u32, u32),
    Select(u32, u32, u32),
    /// Table `k` of the builder's tables (its slope when true) of an operand.
    Table(u32, bool, u32),
}

/// An instruction of the finished tape, operands as register numbers. The arithmetic that
/// dominates circuit equations has its own variants, so dispatch is a single jump.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Instr {
    Add(u32, u32),
    Sub(u32, u32),
    Mul(u32, u32),
    Div(u32, u32),
    Neg(u32),
    Un(Un, u32),
    Bin(Bin, u32, u32),
    Select(u32, u32, u32),
    /// Jumps to the given position when the register is zero (the else-branch of a select).
    IfZero(u32, u32),
    /// Jumps to the given position.
    Goto(u32),
    /// The value of table `k` of the tape's tables at a register, and its slope.
    Table(u32, u32),
    TableSlope(u32, u32),
}

/// A compiled set of expressions; output `i` is the value of the `i`-th compiled root.
#[derive(Clone, Debug, Default)]
pub struct Tape {
    instrs: Vec<Instr>,
    regs: Vec<f64>,
    /// Register of the first input; inputs are gathered in this order: `x`, `x'`, signals,
    /// `now`.
    inputs: usize,
    /// Register of the first instruction.
    first_instr: usize,
    /// Instructions up to which each section's outputs are computed.
    section_ends: Vec<usize>,
    /// Instructions computed from the inputs now in the input block.
    computed: usize,
    x_loads: Vec<u32>,
    dot_loads: Vec<u32>,
    signal_loads: Vec<u32>,
    reads_now: bool,
    outputs: Vec<u32>,
    /// The tables the instructions look up.
    tables: Vec<Arc<Table>>,
}

/// Compiles roots one after another into a shared tape.
#[derive(Default)]
pub struct TapeBuilder {
    ops: Vec<Op>,
    consts: Vec<f64>,
    const_index: FxHashMap<u64, u32>,
    op_index: FxHashMap<Op, u32>,
    outputs: Vec<u32>,
    /// Number of outputs at the end of each section.
    section_marks: Vec<usize>,
    /// The tables compiled, each once (a residual and its Jacobian entries share theirs).
    tables: Vec<Arc<Table>>,
}

/// Register reference before constants are counted: constants and instructions are numbered
/// separately while compiling and joined in [`TapeBuilder::finish`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Slot {
    Const(u32),
    Op(u32),
}

impl TapeBuilder {
    /// Adds `e` as the next output; returns its output index.
    pub fn push(&mut self, e: &Sym) -> usize {
        let slot = self.compile(e);
        self.outputs.push(encode(slot));
        self.outputs.len() - 1
    }

    /// Ends the current section: the outputs pushed so far can be evaluated without the
    /// instructions of later ones ([`Tape::eval_section`]). Returns the section's number.
    pub fn end_section(&mut self) -> usize {
        self.section_marks.push(self.outputs.len());
        self.section_marks.len() - 1
    }

    fn constant(&mut self, v: f64) -> Slot {
        let next = self.consts.len() as u32;
        let id = *self.const_index.entry(v.to_bits()).or_insert(next);
        if id == next {
            self.consts.push(v);
        }
        Slot::Const(id)
    }

    /// The instruction behind an encoded operand, if it is one.
    fn op_of(&self, r: u32) -> Option<Op> {
        (r & CONST_TAG == 0).then(|| self.ops[r as usize])
    }

    fn emit(&mut self, op: Op) -> Slot {
        // Exact rewrites first; each returns an instruction emitted the usual way.
        let neg_of = |r: u32| match self.op_of(r) {
            Some(Op::Un(Un::Neg, a)) => Some(a),
            _ => None,
        };
        let op = match op {
            Op::Un(Un::Neg, a) => match neg_of(a) {
                Some(inner) => return decode_slot(inner),
                None => op,
            },
            Op::Bin(Bin::Add, a, b) => match (neg_of(a), neg_of(b)) {
                (_, Some(nb)) => Op::Bin(Bin::Sub, a, nb),
                (Some(na), None) => Op::Bin(Bin::Sub, b, na),
                (None, None) if a > b => Op::Bin(Bin::Add, b, a),
                (None, None) => op,
            },
            Op::Bin(Bin::Sub, a, b) => match neg_of(b) {
                Some(nb) => return self.emit(Op::Bin(Bin::Add, a, nb)),
                None => op,
            },
            Op::Bin(Bin::Div, a, b) if b & CONST_TAG != 0 => {
                let c = self.consts[(b & !CONST_TAG) as usize];
                let inv = 1.0 / c;
                if exact_reciprocal(c, inv) {
                    let c = encode(self.constant(inv));
                    return self.emit(Op::Bin(Bin::Mul, a, c));
                }
                op
            }
            // `+` and `*` commute exactly: one canonical operand order lets both spellings
            // share one instruction.
            Op::Bin(Bin::Mul, a, b) if a > b => Op::Bin(Bin::Mul, b, a),
            other => other,
        };
        let next = self.ops.len() as u32;
        let id = *self.op_index.entry(op).or_insert(next);
        if id == next {
            self.ops.push(op);
        }
        Slot::Op(id)
    }

    fn compile(&mut self, e: &Sym) -> Slot {
        match e {
            Sym::Const(v) => self.constant(*v),
            Sym::X(i) => self.emit(Op::X(*i as u32)),
            Sym::Dot(i) => self.emit(Op::Dot(*i as u32)),
            Sym::Signal(s) => self.emit(Op::Signal(*s as u32)),
            Sym::Now => self.emit(Op::Now),
            Sym::Un(op, a) => {
                let a = self.compile(a);
                self.emit(Op::Un(*op, encode(a)))
            }
            Sym::Bin(op, a, b) => {
                let a = self.compile(a);
                let b = self.compile(b);
                self.emit(Op::Bin(*op, encode(a), encode(b)))
            }
            Sym::Table(f, a) => {
                let a = self.compile(a);
                let k = match self.tables.iter().position(|t| Arc::ptr_eq(t, &f.table)) {
                    Some(k) => k,
                    None => {
                        self.tables.push(f.table.clone());
                        self.tables.len() - 1
                    }
                };
                self.emit(Op::Table(k as u32, f.slope, encode(a)))
            }
            Sym::If(c, a, b) => {
                let c = self.compile(c);
                let a = self.compile(a);
                let b = self.compile(b);
                self.emit(Op::Select(encode(c), encode(a), encode(b)))
            }
        }
    }

    /// Drops instructions no output needs, moves the loads into the input block, puts the
    /// instructions only one branch of an `If` needs behind a jump, and resolves operands to
    /// final register numbers.
    pub fn finish(self) -> Tape {
        let consts = self.consts.len();
        let live = liveness(&self.ops, &self.outputs);
        let (mut x_loads, mut dot_loads, mut signal_loads) = (vec![], vec![], vec![]);
        let mut reads_now = false;
        for (k, &op) in self.ops.iter().enumerate() {
            match op {
                _ if !live[k] => {}
                Op::X(i) => x_loads.push(i),
                Op::Dot(i) => dot_loads.push(i),
                Op::Signal(s) => signal_loads.push(s),
                Op::Now => reads_now = true,
                _ => {}
            }
        }
        let order = Layout::new(&self.ops, &live, &self.outputs).order();
        // Registers: loads in the input block, each instruction (jumps included) its own
        // after it, by position.
        let mut reg = vec![u32::MAX; self.ops.len()];
        let inputs = consts as u32;
        let (mut next_x, mut next_dot) = (inputs, inputs + x_loads.len() as u32);
        let mut next_signal = next_dot + dot_loads.len() as u32;
        let now_reg = next_signal + signal_loads.len() as u32;
        let first_instr = now_reg + u32::from(reads_now);
        for (k, &op) in self.ops.iter().enumerate() {
            let counter = match op {
                _ if !live[k] => continue,
                Op::X(_) => &mut next_x,
                Op::Dot(_) => &mut next_dot,
                Op::Signal(_) => &mut next_signal,
                Op::Now => {
                    reg[k] = now_reg;
                    continue;
                }
                _ => continue,
            };
            reg[k] = *counter;
            *counter += 1;
        }
        for (pos, e) in order.iter().enumerate() {
            if let Emit::Op(k) = *e {
                reg[k as usize] = first_instr + pos as u32;
            }
        }
        let fix = |r: u32| {
            if r & CONST_TAG != 0 {
                r & !CONST_TAG
            } else {
                reg[r as usize]
            }
        };
        let instrs: Vec<Instr> = order
            .iter()
            .map(|&e| match e {
                Emit::IfZero(c, to) => Instr::IfZero(fix(c), to),
                Emit::Goto(to) => Instr::Goto(to),
                Emit::Op(k) => match self.ops[k as usize] {
                    Op::Un(Un::Neg, a) => Instr::Neg(fix(a)),
                    Op::Un(u, a) => Instr::Un(u, fix(a)),
                    Op::Bin(Bin::Add, a, b) => Instr::Add(fix(a), fix(b)),
                    Op::Bin(Bin::Sub, a, b) => Instr::Sub(fix(a), fix(b)),
                    Op::Bin(Bin::Mul, a, b) => Instr::Mul(fix(a), fix(b)),
                    Op::Bin(Bin::Div, a, b) => Instr::Div(fix(a), fix(b)),
                    Op::Bin(b, x, y) => Instr::Bin(b, fix(x), fix(y)),
                    Op::Select(c, a, b) => Instr::Select(fix(c), fix(a), fix(b)),
                    Op::Table(k, false, a) => Instr::Table(k, fix(a)),
                    Op::Table(k, true, a) => Instr::TableSlope(k, fix(a)),
                    Op::X(_) | Op::Dot(_) | Op::Signal(_) | Op::Now => {
                        unreachable!("loads are in the input block, never in the order")
                    }
                },
            })
            .collect();
        // A section ends after the last instruction its outputs need (the jumps of an `If`
        // it needs lie before that `If`'s select, so the prefix runs on its own).
        let mut position = vec![0usize; self.ops.len()];
        for (pos, e) in order.iter().enumerate() {
            if let Emit::Op(k) = *e {
                position[k as usize] = pos + 1;
            }
        }
        let section_ends = self
            .section_marks
            .iter()
            .map(|&outputs| {
                let needed = liveness(&self.ops, &self.outputs[..outputs]);
                (0..self.ops.len())
                    .filter(|&k| needed[k])
                    .map(|k| position[k])
                    .max()
                    .unwrap_or(0)
            })
            .collect();
        let mut regs = self.consts;
        regs.resize(first_instr as usize + instrs.len(), 0.0);
        Tape {
            first_instr: first_instr as usize,
            section_ends,
            computed: 0,
            outputs: self.outputs.iter().map(|&r| fix(r)).collect(),
            instrs,
            regs,
            inputs: consts,
            x_loads,
            dot_loads,
            signal_loads,
            reads_now,
            tables: self.tables,
        }
    }
}

/// Which instructions the given outputs need. Operands always precede their instruction, so
/// one backward pass.
fn liveness(ops: &[Op], outputs: &[u32]) -> Vec<bool> {
    let mut live = vec![false; ops.len()];
    for &r in outputs {
        if r & CONST_TAG == 0 {
            live[r as usize] = true;
        }
    }
    for k in (0..ops.len()).rev() {
        if !live[k] {
            continue;
        }
        for r in operands(ops[k]) {
            if r & CONST_TAG == 0 {
                live[r as usize] = true;
            }
        }
    }
    live
}

/// The operands of an instruction (unused slots are constant 0, which no pass follows).
fn operands(op: Op) -> [u32; 3] {
    const NONE: u32 = CONST_TAG;
    match op {
        Op::Un(_, a) | Op::Table(_, _, a) => [a, NONE, NONE],
        Op::Bin(_, a, b) => [a, b, NONE],
        Op::Select(c, a, b) => [c, a, b],
        Op::X(_) | Op::Dot(_) | Op::Signal(_) | Op::Now => [NONE; 3],
    }
}

fn is_load(op: Op) -> bool {
    matches!(op, Op::X(_) | Op::Dot(_) | Op::Signal(_) | Op::Now)
}

/// An entry of the finished instruction order: an instruction, or a jump (targets are
/// positions in the order).
#[derive(Clone, Copy)]
enum Emit {
    Op(u32),
    /// To the else-block when the condition register is zero (as `Select` picks it).
    IfZero(u32, u32),
    /// From the end of the then-block over the else-block, to the select.
    Goto(u32),
}

/// Instructions grouped by the branch that alone needs them. Block 0 is the top level; every
/// live `Select` opens a then-block and an else-block inside the block that owns it. An
/// instruction belongs to the innermost block that contains all its uses (an output is a use
/// at the top level; a select's condition is a use in the select's own block).
struct Layout<'a> {
    ops: &'a [Op],
    /// Per block: its parent and depth.
    parent: Vec<u32>,
    depth: Vec<u32>,
    /// Per block, its instructions in compile order (so operands come first).
    members: Vec<Vec<u32>>,
    /// Per select instruction, its then- and else-block.
    branches: FxHashMap<u32, (u32, u32)>,
}

/// Branches with fewer instructions between them than this are computed unconditionally: a
/// jump costs about as much, and more when the condition flips.
const MIN_BRANCH_WORK: usize = 2;

impl<'a> Layout<'a> {
    fn new(ops: &'a [Op], live: &[bool], outputs: &[u32]) -> Self {
        let mut this = Self {
            ops,
            parent: vec![0],
            depth: vec![0],
            members: vec![],
            branches: FxHashMap::default(),
        };
        let mut owner = vec![u32::MAX; ops.len()];
        for &r in outputs {
            if r & CONST_TAG == 0 {
                owner[r as usize] = 0;
            }
        }
        // Uses come after definitions: walking backwards, every use of an instruction is
        // placed before the instruction itself is.
        for k in (0..ops.len()).rev() {
            if !live[k] || is_load(ops[k]) {
                continue;
            }
            let own = owner[k];
            let [c, a, b] = operands(ops[k]);
            let (a_block, b_block) = match ops[k] {
                Op::Select(..) => {
                    let then_block = this.open(own);
                    let else_block = this.open(own);
                    this.branches.insert(k as u32, (then_block, else_block));
                    (then_block, else_block)
                }
                _ => (own, own),
            };
            for (r, block) in [(c, own), (a, a_block), (b, b_block)] {
                if r & CONST_TAG == 0 {
                    let r = r as usize;
                    owner[r] = if owner[r] == u32::MAX {
                        block
                    } else {
                        this.common(owner[r], block)
                    };
                }
            }
        }
        this.members = vec![vec![]; this.parent.len()];
        for (k, &o) in owner.iter().enumerate() {
            if live[k] && !is_load(ops[k]) {
                this.members[o as usize].push(k as u32);
            }
        }
        this
    }

    fn open(&mut self, parent: u32) -> u32 {
        self.parent.push(parent);
        self.depth.push(self.depth[parent as usize] + 1);
        (self.parent.len() - 1) as u32
    }

    /// The innermost block containing both.
    fn common(&self, mut a: u32, mut b: u32) -> u32 {
        while a != b {
            if self.depth[a as usize] >= self.depth[b as usize] {
                a = self.parent[a as usize];
            } else {
                b = self.parent[b as usize];
            }
        }
        a
    }

    /// The instruction order: each block's members in compile order, a select's branches
    /// just before it, behind jumps when they hold enough work.
    fn order(&self) -> Vec<Emit> {
        let mut order = Vec::with_capacity(self.ops.len());
        self.emit(0, &mut order);
        order
    }

    fn emit(&self, block: u32, order: &mut Vec<Emit>) {
        for &k in &self.members[block as usize] {
            if let (Op::Select(c, ..), Some(&(t, e))) =
                (self.ops[k as usize], self.branches.get(&k))
            {
                let work = self.members[t as usize].len() + self.members[e as usize].len();
                if work < MIN_BRANCH_WORK {
                    self.emit(t, order);
                    self.emit(e, order);
                } else {
                    let branch = order.len();
                    order.push(Emit::IfZero(c, 0));
                    self.emit(t, order);
                    let goto = order.len();
                    order.push(Emit::Goto(0));
                    self.emit(e, order);
                    order[branch] = Emit::IfZero(c, goto as u32 + 1);
                    order[goto] = Emit::Goto(order.len() as u32);
                }
            }
            order.push(Emit::Op(k));
        }
    }
}

/// While compiling, constants are tagged in the top bit.
const CONST_TAG: u32 = 1 << 31;

fn encode(s: Slot) -> u32 {
    match s {
        Slot::Const(i) => i | CONST_TAG,
        Slot::Op(i) => i,
    }
}

/// True when `x / c == x * inv` for every `x`: `c` and `inv = 1 / c` are both normal powers
/// of two, so both sides are the same exact scaling, rounded once.
fn exact_reciprocal(c: f64, inv: f64) -> bool {
    const MANTISSA: u64 = (1 << 52) - 1;
    c.is_normal() && inv.is_normal() && c.to_bits() & MANTISSA == 0
}

/// The slot an encoded operand stands for.
fn decode_slot(r: u32) -> Slot {
    if r & CONST_TAG != 0 {
        Slot::Const(r & !CONST_TAG)
    } else {
        Slot::Op(r)
    }
}

impl Tape {
    /// Number of computing instructions, loads not counted (for tests and reports).
    #[cfg(test)]
    pub fn instructions(&self) -> usize {
        self.instrs.len()
    }

    /// Number of conditional jumps (for tests).
    #[cfg(test)]
    pub fn jumps(&self) -> usize {
        self.instrs
            .iter()
            .filter(|i| matches!(i, Instr::IfZero(..)))
            .count()
    }

    /// Runs the tape. Indices inside were built from the same system's slots, so `x`, `xdot`
    /// and `signals` must have the system's sizes (the caller's invariant).
    pub fn eval(&mut self, t: f64, x: &[f64], xdot: &[f64], signals: &[f64]) {
        self.run(self.instrs.len(), t, x, xdot, signals);
    }

    /// Computes the outputs of sections `..=section` only, skipping what was computed at the
    /// same inputs by the last evaluation.
    pub fn eval_section(
        &mut self,
        section: usize,
        t: f64,
        x: &[f64],
        xdot: &[f64],
        signals: &[f64],
    ) {
        let end = self
            .section_ends
            .get(section)
            .copied()
            .unwrap_or(self.instrs.len());
        self.run(end, t, x, xdot, signals);
    }

    /// Gathers the inputs and runs the instructions up to `end`, starting where the last run
    /// stopped if the inputs are bitwise the same.
    fn run(&mut self, end: usize, t: f64, x: &[f64], xdot: &[f64], signals: &[f64]) {
        let regs = &mut self.regs;
        let mut k = self.inputs;
        let mut changed = false;
        let mut load = |v: f64, k: &mut usize| {
            changed |= regs[*k].to_bits() != v.to_bits();
            regs[*k] = v;
            *k += 1;
        };
        for (loads, from) in [(&self.x_loads, x), (&self.dot_loads, xdot)] {
            for &i in loads {
                load(from[i as usize], &mut k);
            }
        }
        for &s in &self.signal_loads {
            load(signals[s as usize], &mut k);
        }
        if self.reads_now {
            load(t, &mut k);
        }
        if changed {
            self.computed = 0;
        }
        if self.computed >= end {
            return;
        }
        let first = self.first_instr;
        let mut pc = self.computed;
        while pc < end {
            let r = &*regs;
            let v = match self.instrs[pc] {
                Instr::Add(a, b) => r[a as usize] + r[b as usize],
                Instr::Sub(a, b) => r[a as usize] - r[b as usize],
                Instr::Mul(a, b) => r[a as usize] * r[b as usize],
                Instr::Div(a, b) => r[a as usize] / r[b as usize],
                Instr::Neg(a) => -r[a as usize],
                Instr::Un(op, a) => apply_unary(op, r[a as usize]),
                Instr::Table(k, a) => self.tables[k as usize].value(r[a as usize]),
                Instr::TableSlope(k, a) => self.tables[k as usize].slope(r[a as usize]),
                Instr::Bin(op, a, b) => apply_binary(op, r[a as usize], r[b as usize]),
                Instr::Select(c, a, b) => {
                    if r[c as usize] != 0.0 {
                        r[a as usize]
                    } else {
                        r[b as usize]
                    }
                }
                // The untaken branch's registers keep stale values the select ignores.
                Instr::IfZero(c, to) => {
                    pc = if r[c as usize] == 0.0 {
                        to as usize
                    } else {
                        pc + 1
                    };
                    continue;
                }
                Instr::Goto(to) => {
                    pc = to as usize;
                    continue;
                }
            };
            regs[first + pc] = v;
            pc += 1;
        }
        self.computed = end;
    }

    /// Number of outputs.
    pub fn len(&self) -> usize {
        self.outputs.len()
    }

    /// True for a tape without outputs.
    pub fn is_empty(&self) -> bool {
        self.outputs.is_empty()
    }

    /// Output `i` of the last [`Tape::eval`].
    pub fn output(&self, i: usize) -> f64 {
        self.regs[self.outputs[i] as usize]
    }
}
