//! Symbolic residuals over solver slots: the form equations take between the design's
//! [`Expr`](vams_design::Expr) and the compiled tape.
//!
//! Quantities become unknown slots, booleans 0/1, calls their numeric function. The smart
//! constructors fold constants and drop neutral terms, so differentiation and compilation see
//! small trees. [`apply_unary`] and [`apply_binary`] are the one definition of every operator's
//! value, shared by constant folding and the tape.

use std::sync::Arc;

use vams_design::pwl::Table;

/// One-argument operations.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Un {
    Neg,
    Abs,
    Not,
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
}

/// Two-argument operations; comparisons and logic give 0/1.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Bin {
    Add,
    Sub,
    Mul,
    Div,
    Pow,
    Mod,
    Rem,
    Atan2,
    Max,
    Min,
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

impl Bin {
    /// Comparisons and logic: piecewise constant, zero derivative.
    pub fn is_logical(self) -> bool {
        !matches!(
            self,
            Bin::Add
                | Bin::Sub
                | Bin::Mul
                | Bin::Div
                | Bin::Pow
                | Bin::Mod
                | Bin::Rem
                | Bin::Atan2
                | Bin::Max
                | Bin::Min
        )
    }
}

/// A piecewise-linear table's value or slope as a function of one argument
/// ([`vams_design::pwl`]). Tables are shared: a residual and its derivatives point at one copy.
#[derive(Clone, Debug)]
pub struct TableFn {
    pub table: Arc<Table>,
    /// The slope instead of the value (the derivative of the value; itself piecewise
    /// constant, zero derivative).
    pub slope: bool,
}

impl TableFn {
    pub fn new(table: Table) -> TableFn {
        TableFn {
            table: Arc::new(table),
            slope: false,
        }
    }

    /// The function's derivative (`None`: zero).
    pub fn derivative(&self) -> Option<TableFn> {
        (!self.slope).then(|| TableFn {
            table: self.table.clone(),
            slope: true,
        })
    }

    pub fn apply(&self, x: f64) -> f64 {
        if self.slope {
            self.table.slope(x)
        } else {
            self.table.value(x)
        }
    }
}

impl PartialEq for TableFn {
    fn eq(&self, other: &TableFn) -> bool {
        self.slope == other.slope
            && (Arc::ptr_eq(&self.table, &other.table) || self.table == other.table)
    }
}

/// A residual expression over solver slots.
#[derive(Clone, Debug, PartialEq)]
pub enum Sym {
    Const(f64),
    /// Unknown `x[slot]`.
    X(usize),
    /// Derivative `x'[slot]`.
    Dot(usize),
    /// Signal value (index into the design's signals).
    Signal(usize),
    Now,
    Un(Un, Box<Sym>),
    Bin(Bin, Box<Sym>, Box<Sym>),
    /// Nonzero condition selects the first branch.
    If(Box<Sym>, Box<Sym>, Box<Sym>),
    /// A table of one argument.
    Table(TableFn, Box<Sym>),
}

fn truth(v: f64) -> bool {
    v != 0.0
}

fn bool01(b: bool) -> f64 {
    if b { 1.0 } else { 0.0 }
}

/// Value of a one-argument operation; domain errors give NaN (Newton rejects the step).
#[inline]
pub fn apply_unary(op: Un, a: f64) -> f64 {
    match op {
        Un::Neg => -a,
        Un::Abs => a.abs(),
        Un::Not => bool01(!truth(a)),
        Un::Exp => a.exp(),
        Un::Log => a.ln(),
        Un::Log10 => a.log10(),
        Un::Sqrt => a.sqrt(),
        Un::Sin => a.sin(),
        Un::Cos => a.cos(),
        Un::Tan => a.tan(),
        Un::Asin => a.asin(),
        Un::Acos => a.acos(),
        Un::Atan => a.atan(),
        Un::Sinh => a.sinh(),
        Un::Cosh => a.cosh(),
        Un::Tanh => a.tanh(),
        Un::Asinh => a.asinh(),
        Un::Acosh => a.acosh(),
        Un::Atanh => a.atanh(),
        Un::Floor => a.floor(),
        Un::Ceil => a.ceil(),
        Un::Round => a.round(),
        Un::Trunc => a.trunc(),
        // math_real SIGN: -1, 0 or 1 (NaN stays NaN).
        Un::Sign => {
            if a > 0.0 {
                1.0
            } else if a < 0.0 {
                -1.0
            } else {
                a * 0.0
            }
        }
    }
}

/// Value of a two-argument operation (division by zero gives inf or NaN, never a panic).
#[inline]
pub fn apply_binary(op: Bin, a: f64, b: f64) -> f64 {
    match op {
        Bin::Add => a + b,
        Bin::Sub => a - b,
        Bin::Mul => a * b,
        Bin::Div => a / b,
        Bin::Pow => a.powf(b),
        // VHDL `mod` takes the sign of the divisor, `rem` that of the dividend.
        Bin::Mod => a - b * (a / b).floor(),
        Bin::Rem => a % b,
        Bin::Atan2 => a.atan2(b),
        Bin::Max => {
            if a >= b || b.is_nan() {
                a
            } else {
                b
            }
        }
        Bin::Min => {
            if a <= b || b.is_nan() {
                a
            } else {
                b
            }
        }
        Bin::Eq => bool01(a == b),
        Bin::Ne => bool01(a != b),
        Bin::Lt => bool01(a < b),
        Bin::Le => bool01(a <= b),
        Bin::Gt => bool01(a > b),
        Bin::Ge => bool01(a >= b),
        Bin::And => bool01(truth(a) && truth(b)),
        Bin::Or => bool01(truth(a) || truth(b)),
        Bin::Nand => bool01(!(truth(a) && truth(b))),
        Bin::Nor => bool01(!(truth(a) || truth(b))),
        Bin::Xor => bool01(truth(a) != truth(b)),
        Bin::Xnor => bool01(truth(a) == truth(b)),
    }
}

impl Sym {
    pub fn as_const(&self) -> Option<f64> {
        match self {
            Sym::Const(v) => Some(*v),
            _ => None,
        }
    }

    pub fn is_const(&self, v: f64) -> bool {
        self.as_const() == Some(v)
    }

    pub fn un(op: Un, a: Sym) -> Sym {
        match (op, a) {
            (_, Sym::Const(v)) => Sym::Const(apply_unary(op, v)),
            (Un::Neg, Sym::Un(Un::Neg, inner)) => *inner,
            // -(a - b) is b - a exactly (rounding is symmetric).
            (Un::Neg, Sym::Bin(Bin::Sub, a, b)) => Sym::Bin(Bin::Sub, b, a),
            (op, a) => Sym::Un(op, Box::new(a)),
        }
    }

    /// `f(a)`, folded when `a` is constant.
    pub fn table(f: TableFn, a: Sym) -> Sym {
        match a {
            Sym::Const(v) => Sym::Const(f.apply(v)),
            a => Sym::Table(f, Box::new(a)),
        }
    }

    pub fn neg(a: Sym) -> Sym {
        Sym::un(Un::Neg, a)
    }

    /// `op(a, b)`, folding constants and neutral elements (`x + 0`, `1 * x`, `0 * x`, ...).
    /// `0 * x` drops `x` even where it could be infinite: derivatives of terms that do not
    /// depend on a variable are zero by definition.
    pub fn bin(op: Bin, a: Sym, b: Sym) -> Sym {
        if let (Some(x), Some(y)) = (a.as_const(), b.as_const()) {
            return Sym::Const(apply_binary(op, x, y));
        }
        match op {
            Bin::Add if a.is_const(0.0) => b,
            Bin::Add | Bin::Sub if b.is_const(0.0) => a,
            Bin::Sub if a.is_const(0.0) => Sym::neg(b),
            Bin::Mul if a.is_const(0.0) || b.is_const(0.0) => Sym::Const(0.0),
            Bin::Mul if a.is_const(1.0) => b,
            Bin::Mul if b.is_const(1.0) => a,
            Bin::Mul if a.is_const(-1.0) => Sym::neg(b),
            Bin::Mul if b.is_const(-1.0) => Sym::neg(a),
            Bin::Div if a.is_const(0.0) => Sym::Const(0.0),
            Bin::Div if b.is_const(1.0) => a,
            Bin::Pow if b.is_const(1.0) => a,
            Bin::Pow if b.is_const(0.0) => Sym::Const(1.0),
            _ => Sym::Bin(op, Box::new(a), Box::new(b)),
        }
    }

    pub fn add(a: Sym, b: Sym) -> Sym {
        Sym::bin(Bin::Add, a, b)
    }

    pub fn sub(a: Sym, b: Sym) -> Sym {
        Sym::bin(Bin::Sub, a, b)
    }

    pub fn mul(a: Sym, b: Sym) -> Sym {
        Sym::bin(Bin::Mul, a, b)
    }

    pub fn div(a: Sym, b: Sym) -> Sym {
        Sym::bin(Bin::Div, a, b)
    }

    /// `if c then a else b`, choosing statically when the condition is constant or both
    /// branches are the same.
    pub fn cond(c: Sym, a: Sym, b: Sym) -> Sym {
        if let Some(v) = c.as_const() {
            return if truth(v) { a } else { b };
        }
        if a == b {
            return a;
        }
        Sym::If(Box::new(c), Box::new(a), Box::new(b))
    }

    /// True when some node satisfies `pred` (`e.any(|n| matches!(n, Sym::Now))`).
    pub fn any(&self, pred: impl Fn(&Sym) -> bool) -> bool {
        let mut found = false;
        self.visit(&mut |n| found |= pred(n));
        found
    }

    /// True when the expression is affine in the unknowns (`x` and `x'`) for every value of
    /// the signals and `now`: sums, negations, products and quotients by unknown-free factors,
    /// and `if`s on unknown-free conditions over affine branches. Anything else (a comparison
    /// or rounding of an unknown included: constant derivative, but not affine) counts only
    /// when it reads no unknown.
    pub fn is_affine(&self) -> bool {
        match self {
            Sym::Const(_) | Sym::Signal(_) | Sym::Now | Sym::X(_) | Sym::Dot(_) => true,
            Sym::Un(Un::Neg, a) => a.is_affine(),
            Sym::Bin(Bin::Add | Bin::Sub, a, b) => a.is_affine() && b.is_affine(),
            Sym::Bin(Bin::Mul, a, b) => {
                (!a.reads_unknown() && b.is_affine()) || (a.is_affine() && !b.reads_unknown())
            }
            Sym::Bin(Bin::Div, a, b) => a.is_affine() && !b.reads_unknown(),
            Sym::If(c, a, b) => !c.reads_unknown() && a.is_affine() && b.is_affine(),
            other => !other.reads_unknown(),
        }
    }

    /// True when the expression reads an unknown (`x` or `x'`).
    pub fn reads_unknown(&self) -> bool {
        self.any(|n| matches!(n, Sym::X(_) | Sym::Dot(_)))
    }

    /// Pushes the unknowns (`X` and `Dot` slots) the value can depend on smoothly: those not
    /// only under a condition, a comparison, logic or rounding, which have zero derivative.
    /// This is the structural incidence, without forming derivatives.
    pub fn structural_unknowns(&self, out: &mut Vec<usize>) {
        match self {
            Sym::X(j) | Sym::Dot(j) => out.push(*j),
            Sym::Const(_) | Sym::Signal(_) | Sym::Now => {}
            Sym::Un(Un::Not | Un::Floor | Un::Ceil | Un::Round | Un::Trunc | Un::Sign, _) => {}
            Sym::Un(_, a) => a.structural_unknowns(out),
            Sym::Table(f, _) if f.slope => {}
            Sym::Table(_, a) => a.structural_unknowns(out),
            Sym::Bin(op, _, _) if op.is_logical() => {}
            Sym::Bin(_, a, b) => {
                a.structural_unknowns(out);
                b.structural_unknowns(out);
            }
            Sym::If(_, a, b) => {
                a.structural_unknowns(out);
                b.structural_unknowns(out);
            }
        }
    }

    /// The summands of this expression's top-level sum, signs dropped: `a - (b + -c)` gives
    /// `a`, `b`, `c` (what a balance equation balances).
    pub fn terms<'a>(&'a self, out: &mut Vec<&'a Sym>) {
        match self {
            Sym::Bin(Bin::Add | Bin::Sub, a, b) => {
                a.terms(out);
                b.terms(out);
            }
            Sym::Un(Un::Neg, a) => a.terms(out),
            other => out.push(other),
        }
    }

    /// Calls `f` on every node, this one first.
    pub fn visit(&self, f: &mut impl FnMut(&Sym)) {
        f(self);
        match self {
            Sym::Const(_) | Sym::X(_) | Sym::Dot(_) | Sym::Signal(_) | Sym::Now => {}
            Sym::Un(_, a) | Sym::Table(_, a) => a.visit(f),
            Sym::Bin(_, a, b) => {
                a.visit(f);
                b.visit(f);
            }
            Sym::If(c, a, b) => {
                c.visit(f);
                a.visit(f);
                b.visit(f);
            }
        }
    }

    /// Evaluates the tree directly (tests, reference values and index reduction's choice of
    /// states; the simulator uses the tape).
    pub fn eval(&self, t: f64, x: &[f64], xdot: &[f64], signals: &[f64]) -> f64 {
        match self {
            Sym::Const(v) => *v,
            Sym::X(i) => x[*i],
            Sym::Dot(i) => xdot[*i],
            Sym::Signal(s) => signals[*s],
            Sym::Now => t,
            Sym::Un(op, a) => apply_unary(*op, a.eval(t, x, xdot, signals)),
            Sym::Table(f, a) => f.apply(a.eval(t, x, xdot, signals)),
            Sym::Bin(op, a, b) => apply_binary(
                *op,
                a.eval(t, x, xdot, signals),
                b.eval(t, x, xdot, signals),
            ),
            Sym::If(c, a, b) => {
                if truth(c.eval(t, x, xdot, signals)) {
                    a.eval(t, x, xdot, signals)
                } else {
                    b.eval(t, x, xdot, signals)
                }
            }
        }
    }
}
