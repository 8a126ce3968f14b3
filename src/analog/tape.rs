//! Flat instruction tapes: many [`Sym`] trees compiled into one straight-line program over a
//! register file.
//!
//! Registers `0..consts` hold the folded constants (written once at compile time); instruction
//! `k` writes register `consts + k`. Identical sub-expressions are compiled once (hash-consing
//! on the instruction), so a residual and its derivatives share work when compiled together.
//! Evaluation is one pass over the instructions: no allocation, no tree walking. `If` evaluates
//! both branches and selects (a NaN in the branch not taken is harmless).

use rustc_hash::FxHashMap;

use super::sym::{Bin, Sym, Un, apply_binary, apply_unary};

#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
enum Op {
    X(u32),
    Dot(u32),
    Signal(u32),
    Now,
    Un(Un, u32),
    Bin(Bin, u32, u32),
    Select(u32, u32, u32),
}

/// A compiled set of expressions; output `i` is the value of the `i`-th compiled root.
#[derive(Clone, Debug, Default)]
pub struct Tape {
    ops: Vec<Op>,
    regs: Vec<f64>,
    consts: usize,
    outputs: Vec<u32>,
}

/// Compiles roots one after another into a shared tape.
#[derive(Default)]
pub struct TapeBuilder {
    ops: Vec<Op>,
    consts: Vec<f64>,
    const_index: FxHashMap<u64, u32>,
    op_index: FxHashMap<Op, u32>,
    outputs: Vec<u32>,
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

    fn constant(&mut self, v: f64) -> Slot {
        let next = self.consts.len() as u32;
        let id = *self.const_index.entry(v.to_bits()).or_insert(next);
        if id == next {
            self.consts.push(v);
        }
        Slot::Const(id)
    }

    fn emit(&mut self, op: Op) -> Slot {
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
            Sym::If(c, a, b) => {
                let c = self.compile(c);
                let a = self.compile(a);
                let b = self.compile(b);
                self.emit(Op::Select(encode(c), encode(a), encode(b)))
            }
        }
    }

    /// Resolves the operand encoding to final register numbers.
    pub fn finish(self) -> Tape {
        let consts = self.consts.len() as u32;
        let fix = |r: u32| decode(r, consts);
        let ops = self
            .ops
            .iter()
            .map(|op| match *op {
                Op::Un(u, a) => Op::Un(u, fix(a)),
                Op::Bin(b, x, y) => Op::Bin(b, fix(x), fix(y)),
                Op::Select(c, a, b) => Op::Select(fix(c), fix(a), fix(b)),
                other => other,
            })
            .collect::<Vec<_>>();
        let mut regs = self.consts;
        regs.resize(regs.len() + ops.len(), 0.0);
        Tape {
            outputs: self.outputs.iter().map(|&r| fix(r)).collect(),
            ops,
            regs,
            consts: consts as usize,
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

fn decode(r: u32, consts: u32) -> u32 {
    if r & CONST_TAG != 0 {
        r & !CONST_TAG
    } else {
        r + consts
    }
}

impl Tape {
    /// Number of instructions (for tests and reports).
    #[cfg(test)]
    pub fn instructions(&self) -> usize {
        self.ops.len()
    }

    /// Runs the tape. Indices inside were built from the same system's slots, so `x`, `xdot`
    /// and `signals` must have the system's sizes (the caller's invariant).
    pub fn eval(&mut self, t: f64, x: &[f64], xdot: &[f64], signals: &[f64]) {
        let base = self.consts;
        for k in 0..self.ops.len() {
            let r = &self.regs;
            let v = match self.ops[k] {
                Op::X(i) => x[i as usize],
                Op::Dot(i) => xdot[i as usize],
                Op::Signal(s) => signals[s as usize],
                Op::Now => t,
                // The arithmetic that dominates circuit equations, without a second dispatch.
                Op::Bin(Bin::Add, a, b) => r[a as usize] + r[b as usize],
                Op::Bin(Bin::Sub, a, b) => r[a as usize] - r[b as usize],
                Op::Bin(Bin::Mul, a, b) => r[a as usize] * r[b as usize],
                Op::Bin(Bin::Div, a, b) => r[a as usize] / r[b as usize],
                Op::Un(Un::Neg, a) => -r[a as usize],
                Op::Un(op, a) => apply_unary(op, r[a as usize]),
                Op::Bin(op, a, b) => apply_binary(op, r[a as usize], r[b as usize]),
                Op::Select(c, a, b) => {
                    if r[c as usize] != 0.0 {
                        r[a as usize]
                    } else {
                        r[b as usize]
                    }
                }
            };
            self.regs[base + k] = v;
        }
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
