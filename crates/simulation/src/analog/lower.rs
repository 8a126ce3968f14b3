//! Lowering of the design's [`Expr`] to [`Sym`]: quantities to unknown slots, calls to their
//! numeric operations, folding constants on the way.

use super::sym::{Bin, Sym, TableFn, Un};
use vams_design::{BinaryOp, Builtin, Expr, UnaryOp};

/// Why an expression cannot be an analog residual (the elaborator should have refused it).
#[derive(Clone, Debug, PartialEq)]
pub struct NotAnalog(pub &'static str);

/// Lowers a design expression to a [`Sym`], quantity `q` to `X(slot_of(q))`.
pub fn lower(e: &Expr, slot_of: &dyn Fn(usize) -> usize) -> Result<Sym, NotAnalog> {
    let go = |e: &Expr| lower(e, slot_of);
    Ok(match e {
        Expr::Const(v) => Sym::Const(v.as_f64().ok_or(NotAnalog("a string or array constant"))?),
        Expr::Quantity(q) => Sym::X(slot_of(q.index())),
        Expr::Dot(q) => Sym::Dot(slot_of(q.index())),
        Expr::Signal(s) => Sym::Signal(s.index()),
        Expr::Now => Sym::Now,
        Expr::Unary(op, a) => {
            let a = go(a)?;
            match op {
                UnaryOp::Neg => Sym::neg(a),
                UnaryOp::Plus => a,
                UnaryOp::Abs => Sym::un(Un::Abs, a),
                UnaryOp::Not => Sym::un(Un::Not, a),
            }
        }
        Expr::Binary(op, a, b) => {
            let op = match op {
                BinaryOp::Add => Bin::Add,
                BinaryOp::Sub => Bin::Sub,
                BinaryOp::Mul => Bin::Mul,
                BinaryOp::Div => Bin::Div,
                BinaryOp::Pow => Bin::Pow,
                BinaryOp::Mod => Bin::Mod,
                BinaryOp::Rem => Bin::Rem,
                BinaryOp::Eq => Bin::Eq,
                BinaryOp::Ne => Bin::Ne,
                BinaryOp::Lt => Bin::Lt,
                BinaryOp::Le => Bin::Le,
                BinaryOp::Gt => Bin::Gt,
                BinaryOp::Ge => Bin::Ge,
                BinaryOp::And => Bin::And,
                BinaryOp::Or => Bin::Or,
                BinaryOp::Nand => Bin::Nand,
                BinaryOp::Nor => Bin::Nor,
                BinaryOp::Xor => Bin::Xor,
                BinaryOp::Xnor => Bin::Xnor,
                BinaryOp::Concat => return Err(NotAnalog("the concatenation operator `&`")),
                BinaryOp::Sll
                | BinaryOp::Srl
                | BinaryOp::Sla
                | BinaryOp::Sra
                | BinaryOp::Rol
                | BinaryOp::Ror => return Err(NotAnalog("a shift or rotate operator")),
            };
            Sym::bin(op, go(a)?, go(b)?)
        }
        Expr::Call(f, args) => lower_call(*f, args, slot_of)?,
        Expr::If(c, a, b) => Sym::cond(go(c)?, go(a)?, go(b)?),
        Expr::Var(_) => return Err(NotAnalog("a process variable")),
        Expr::Index { .. } => return Err(NotAnalog("array indexing")),
        Expr::Image(..) => return Err(NotAnalog("the 'image attribute")),
        Expr::Aggregate { .. } => return Err(NotAnalog("an aggregate of run-time values")),
        Expr::SignalAttr(..) => return Err(NotAnalog("a signal attribute")),
        Expr::FnCall { .. } => return Err(NotAnalog("a call of a user-defined function")),
        Expr::New(_) | Expr::Deref(_) => return Err(NotAnalog("an access value")),
        Expr::EndFile(_) => return Err(NotAnalog("a file")),
    })
}

fn lower_call(
    f: Builtin,
    args: &[Expr],
    slot_of: &dyn Fn(usize) -> usize,
) -> Result<Sym, NotAnalog> {
    let arg = |i: usize| -> Result<Sym, NotAnalog> {
        let e = args
            .get(i)
            .ok_or(NotAnalog("a call with too few arguments"))?;
        lower(e, slot_of)
    };
    let one = |op: Un| -> Result<Sym, NotAnalog> { Ok(Sym::un(op, arg(0)?)) };
    let two = |op: Bin| -> Result<Sym, NotAnalog> { Ok(Sym::bin(op, arg(0)?, arg(1)?)) };
    match f {
        Builtin::Exp => one(Un::Exp),
        Builtin::Log => one(Un::Log),
        Builtin::Log10 => one(Un::Log10),
        Builtin::Sqrt => one(Un::Sqrt),
        Builtin::Sin => one(Un::Sin),
        Builtin::Cos => one(Un::Cos),
        Builtin::Tan => one(Un::Tan),
        Builtin::Asin => one(Un::Asin),
        Builtin::Acos => one(Un::Acos),
        Builtin::Atan => one(Un::Atan),
        Builtin::Atan2 => two(Bin::Atan2),
        Builtin::Sinh => one(Un::Sinh),
        Builtin::Cosh => one(Un::Cosh),
        Builtin::Tanh => one(Un::Tanh),
        Builtin::Asinh => one(Un::Asinh),
        Builtin::Acosh => one(Un::Acosh),
        Builtin::Atanh => one(Un::Atanh),
        Builtin::Floor => one(Un::Floor),
        Builtin::Ceil => one(Un::Ceil),
        Builtin::Round | Builtin::ToInteger => one(Un::Round),
        Builtin::Trunc => one(Un::Trunc),
        Builtin::Sign => one(Un::Sign),
        Builtin::Realmax => two(Bin::Max),
        Builtin::Realmin => two(Bin::Min),
        Builtin::Pwl => {
            let Some(Expr::Const(vams_design::Value::Array(items))) = args.first() else {
                return Err(NotAnalog("a table that is not a constant"));
            };
            let flat: Vec<f64> = items
                .iter()
                .map(|v| v.as_f64().unwrap_or(f64::NAN))
                .collect();
            let table =
                vams_design::pwl::Table::new(&flat).map_err(|_| NotAnalog("a malformed table"))?;
            Ok(Sym::table(TableFn::new(table), arg(1)?))
        }
        Builtin::ToReal => arg(0),
        // Equations hold enumeration values and booleans as their positions, and time in
        // seconds: `time'pos(now)` (femtoseconds) is a common time-to-number idiom.
        Builtin::Pos => arg(0),
        Builtin::TimePos => Ok(Sym::bin(Bin::Mul, arg(0)?, Sym::Const(1e15))),
        Builtin::TimeVal => Ok(Sym::bin(Bin::Mul, arg(0)?, Sym::Const(1e-15))),
        Builtin::EnumVal => Err(NotAnalog("the 'val attribute of an enumeration type")),
        Builtin::Slice | Builtin::Splice => Err(NotAnalog("a slice")),
        Builtin::ValueOf => Err(NotAnalog("the 'value attribute")),
        Builtin::Restring => Err(NotAnalog("a character array")),
        Builtin::Length | Builtin::CheckLength => Err(NotAnalog("the length of an array")),
    }
}
