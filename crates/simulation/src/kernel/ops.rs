//! VHDL's predefined operators and math_real functions on run-time [`Value`]s.
//!
//! Elaboration has type-checked the operands, so a mismatch here is reported as a run-time
//! error rather than trusted; integer arithmetic is checked (VHDL requires an overflow to be an
//! error, LRM 5.2.3.1), integer division truncates towards zero, `mod` takes the sign of the
//! right operand and `rem` the sign of the left.

use std::cmp::Ordering;

use vams_design::{BinaryOp, Builtin, UnaryOp, Value};

/// A failure while evaluating an expression; the caller adds the process and the time.
#[derive(Clone, Debug, PartialEq)]
pub(crate) struct EvalError {
    pub message: String,
    pub help: &'static str,
}

/// The help of [`EvalError::interrupted`], which tells it apart.
const INTERRUPTED: &str = "the run was cancelled while a process or function ran";

impl EvalError {
    /// The run was cancelled in the middle of a process's or function's instructions: not
    /// an error of the model (`SimError::Interrupted` where a process reports it).
    pub fn interrupted() -> EvalError {
        EvalError::new("interrupted", INTERRUPTED)
    }

    pub fn is_interrupted(&self) -> bool {
        self.help == INTERRUPTED
    }

    pub fn new(message: impl Into<String>, help: &'static str) -> EvalError {
        EvalError {
            message: message.into(),
            help,
        }
    }
}

const TYPE_HELP: &str = "the operands' types do not fit this operator; this is a bug in \
                         elaboration if the model passed type checking";

fn mismatch(op: &str, a: &Value, b: &Value) -> EvalError {
    EvalError::new(
        format!("operator {op} cannot combine {} and {}", kind(a), kind(b)),
        TYPE_HELP,
    )
}

fn kind(v: &Value) -> &'static str {
    match v {
        Value::Real(_) => "a real",
        Value::Integer(_) => "an integer",
        Value::Boolean(_) => "a boolean",
        Value::Time(_) => "a time",
        Value::Enum(_) => "an enumeration value",
        Value::String(_) => "a string",
        Value::Array(_) => "an array",
        Value::Access(_) => "an access value",
        Value::File(_) => "a file",
    }
}

fn overflow(op: &str) -> EvalError {
    EvalError::new(
        format!("integer overflow in {op}"),
        "VHDL integers are 64-bit here; use real arithmetic for larger values",
    )
}

fn checked(op: &str, r: Option<i64>) -> Result<Value, EvalError> {
    r.map(Value::Integer).ok_or_else(|| overflow(op))
}

pub(crate) fn unary(op: UnaryOp, v: Value) -> Result<Value, EvalError> {
    use Value::*;
    Ok(match (op, v) {
        (UnaryOp::Plus, v @ (Real(_) | Integer(_) | Time(_))) => v,
        (UnaryOp::Neg, Real(x)) => Real(-x),
        (UnaryOp::Neg, Time(x)) => Time(-x),
        (UnaryOp::Neg, Integer(i)) => checked("negation", i.checked_neg())?,
        (UnaryOp::Abs, Real(x)) => Real(x.abs()),
        (UnaryOp::Abs, Time(x)) => Time(x.abs()),
        (UnaryOp::Abs, Integer(i)) => checked("abs", i.checked_abs())?,
        (UnaryOp::Not, Boolean(b)) => Boolean(!b),
        // `bit` (elaboration applies `not` to no other enumeration type): '0' is 0, '1' is 1.
        (UnaryOp::Not, Enum(p)) => Enum(1 - p.min(1)),
        (UnaryOp::Not, Array(items)) => Array(
            items
                .into_iter()
                .map(|e| unary(UnaryOp::Not, e))
                .collect::<Result<_, _>>()?,
        ),
        (op, v) => {
            return Err(EvalError::new(
                format!("operator {op:?} does not apply to {}", kind(&v)),
                TYPE_HELP,
            ));
        }
    })
}

/// Arithmetic, comparison, logic and concatenation. `and`/`or` short-circuit in the caller.
pub(crate) fn binary(op: BinaryOp, a: Value, b: Value) -> Result<Value, EvalError> {
    use BinaryOp::*;
    // Two integers (counters, indices, loop bounds) skip the general dispatch; operands
    // matched by value here need no drop.
    let (a, b) = match (a, b) {
        (Value::Integer(x), Value::Integer(y)) => return integers(op, x, y),
        other => other,
    };
    match op {
        Add | Sub | Mul | Div => arithmetic(op, a, b),
        Pow => power(a, b),
        Mod | Rem => modulo(op, a, b),
        Eq => Ok(Value::Boolean(equal(&a, &b))),
        Ne => Ok(Value::Boolean(!equal(&a, &b))),
        Lt | Le | Gt | Ge => {
            let ord = compare(&a, &b).ok_or_else(|| mismatch("comparison", &a, &b))?;
            Ok(Value::Boolean(match op {
                Lt => ord == Ordering::Less,
                Le => ord != Ordering::Greater,
                Gt => ord == Ordering::Greater,
                _ => ord != Ordering::Less,
            }))
        }
        And | Or | Nand | Nor | Xor | Xnor => logic(op, a, b),
        Concat => concat(a, b),
        Sll | Srl | Sla | Sra | Rol | Ror => shift(op, a, b),
    }
}

/// `a sll n` and the other shifts and rotations ([`vams_design::shifted`]).
fn shift(op: BinaryOp, a: Value, b: Value) -> Result<Value, EvalError> {
    match (&a, &b) {
        (Value::Array(items), Value::Integer(n)) => Ok(vams_design::shifted(op, items, *n)),
        _ => Err(mismatch(&format!("{op:?}"), &a, &b)),
    }
}

fn arithmetic(op: BinaryOp, a: Value, b: Value) -> Result<Value, EvalError> {
    use BinaryOp::*;
    use Value::*;
    let real = |x: f64, y: f64| match op {
        Add => x + y,
        Sub => x - y,
        Mul => x * y,
        _ => x / y,
    };
    Ok(match (op, &a, &b) {
        (Div, Real(_), Real(y)) if *y == 0.0 => {
            return Err(EvalError::new(
                "real division by zero",
                "guard the division (LRM 9.2.7 makes it an error, not an infinity)",
            ));
        }
        (_, Real(x), Real(y)) => {
            let r = real(*x, *y);
            if !r.is_finite() && x.is_finite() && y.is_finite() {
                return Err(overflow("real arithmetic"));
            }
            Real(r)
        }
        (_, Integer(x), Integer(y)) => integer_arithmetic(op, *x, *y)?,
        (Add | Sub, Time(x), Time(y)) => Time(real(*x, *y)),
        (Mul | Div, Time(x), Real(y)) => Time(real(*x, *y)),
        (Mul | Div, Time(x), Integer(y)) => Time(real(*x, *y as f64)),
        (Mul, Real(x), Time(y)) => Time(x * y),
        (Mul, Integer(x), Time(y)) => Time(*x as f64 * y),
        // time / time is a universal integer (LRM 9.2.7), truncated.
        (Div, Time(x), Time(y)) => {
            let q = (x / y).trunc();
            if !q.is_finite() || q.abs() >= i64::MAX as f64 {
                return Err(overflow("time division"));
            }
            Integer(q as i64)
        }
        // Universal real times universal integer (folded constants may mix the two).
        (_, Real(x), Integer(y)) => Real(real(*x, *y as f64)),
        (_, Integer(x), Real(y)) => Real(real(*x as f64, *y)),
        _ => return Err(mismatch(&format!("{op:?}"), &a, &b)),
    })
}

/// `x op y` on two integers: what [`binary`] gives for them, by a shorter path.
fn integers(op: BinaryOp, x: i64, y: i64) -> Result<Value, EvalError> {
    use BinaryOp::*;
    match op {
        Add | Sub | Mul | Div => integer_arithmetic(op, x, y),
        Mod | Rem => integer_modulo(op, x, y),
        Pow => integer_power(x, y),
        Eq => Ok(Value::Boolean(x == y)),
        Ne => Ok(Value::Boolean(x != y)),
        Lt => Ok(Value::Boolean(x < y)),
        Le => Ok(Value::Boolean(x <= y)),
        Gt => Ok(Value::Boolean(x > y)),
        Ge => Ok(Value::Boolean(x >= y)),
        // Type errors: the general path words them.
        _ => general(op, Value::Integer(x), Value::Integer(y)),
    }
}

/// [`binary`] without its integer shortcut (which comes back here only for type errors).
#[inline(never)]
fn general(op: BinaryOp, a: Value, b: Value) -> Result<Value, EvalError> {
    use BinaryOp::*;
    match op {
        And | Or | Nand | Nor | Xor | Xnor => logic(op, a, b),
        Concat => concat(a, b),
        Sll | Srl | Sla | Sra | Rol | Ror => shift(op, a, b),
        _ => Err(mismatch(&format!("{op:?}"), &a, &b)),
    }
}

fn integer_arithmetic(op: BinaryOp, x: i64, y: i64) -> Result<Value, EvalError> {
    use BinaryOp::*;
    if op == Div && y == 0 {
        return Err(EvalError::new(
            "integer division by zero",
            "guard the division, or use real arithmetic",
        ));
    }
    let r = match op {
        Add => x.checked_add(y),
        Sub => x.checked_sub(y),
        Mul => x.checked_mul(y),
        // Rust's `/` truncates towards zero, as VHDL's does.
        _ => x.checked_div(y),
    };
    checked("integer arithmetic", r)
}

fn integer_power(x: i64, y: i64) -> Result<Value, EvalError> {
    let e = u32::try_from(y).map_err(|_| {
        EvalError::new(
            format!("integer {x} ** {y}: negative exponent"),
            "an integer power needs a non-negative exponent; use real operands",
        )
    })?;
    checked("**", x.checked_pow(e))
}

fn power(a: Value, b: Value) -> Result<Value, EvalError> {
    use Value::*;
    Ok(match (&a, &b) {
        (Integer(x), Integer(y)) => integer_power(*x, *y)?,
        (Real(x), Integer(y)) => match i32::try_from(*y) {
            Ok(e) => Real(x.powi(e)),
            Err(_) => Real(x.powf(*y as f64)),
        },
        (Real(x), Real(y)) => Real(x.powf(*y)),
        (Integer(x), Real(y)) => Real((*x as f64).powf(*y)),
        _ => return Err(mismatch("**", &a, &b)),
    })
}

fn modulo(op: BinaryOp, a: Value, b: Value) -> Result<Value, EvalError> {
    let (Value::Integer(x), Value::Integer(y)) = (&a, &b) else {
        return Err(mismatch(&format!("{op:?}"), &a, &b));
    };
    integer_modulo(op, *x, *y)
}

fn integer_modulo(op: BinaryOp, x: i64, y: i64) -> Result<Value, EvalError> {
    if y == 0 {
        return Err(EvalError::new(
            format!("{x} {} 0", if op == BinaryOp::Mod { "mod" } else { "rem" }),
            "the right operand of mod and rem must not be zero",
        ));
    }
    let r = x.checked_rem(y).ok_or_else(|| overflow("rem"))?;
    // `rem` has the sign of the left operand (Rust's `%`); `mod` that of the right.
    let m = if op == BinaryOp::Mod && r != 0 && (r < 0) != (y < 0) {
        r + y
    } else {
        r
    };
    Ok(Value::Integer(m))
}

fn equal(a: &Value, b: &Value) -> bool {
    match (a, b) {
        // By femtoseconds (`Value::order`): `now - t0 = 21 ns` holds whatever rounding the
        // seconds picked up on the way.
        (Value::Time(_), Value::Time(_)) => a.order(b) == Some(Ordering::Equal),
        (Value::Integer(x), Value::Real(y)) | (Value::Real(y), Value::Integer(x)) => {
            *x as f64 == *y
        }
        _ => a == b,
    }
}

/// VHDL ordering: numbers, enumeration positions, lexicographic strings and arrays.
pub(crate) fn compare(a: &Value, b: &Value) -> Option<Ordering> {
    a.order(b)
}

fn logic(op: BinaryOp, a: Value, b: Value) -> Result<Value, EvalError> {
    use BinaryOp::*;
    let apply = |x: bool, y: bool| match op {
        And => x && y,
        Or => x || y,
        Nand => !(x && y),
        Nor => !(x || y),
        Xor => x != y,
        _ => x == y,
    };
    match (a, b) {
        (Value::Boolean(x), Value::Boolean(y)) => Ok(Value::Boolean(apply(x, y))),
        // `bit` (the only enumeration type elaboration applies these to): '0' is 0, '1' is 1.
        (Value::Enum(x), Value::Enum(y)) => Ok(Value::Enum(u32::from(apply(x != 0, y != 0)))),
        (Value::Array(x), Value::Array(y)) if x.len() == y.len() => Ok(Value::Array(
            x.into_iter()
                .zip(y)
                .map(|(p, q)| logic(op, p, q))
                .collect::<Result<_, _>>()?,
        )),
        (a, b) => Err(mismatch(&format!("{op:?}"), &a, &b)),
    }
}

fn concat(a: Value, b: Value) -> Result<Value, EvalError> {
    use Value::*;
    Ok(match (a, b) {
        (String(mut x), String(y)) => {
            x.push_str(&y);
            String(x)
        }
        // A character is an enumeration position; `character` positions are Latin-1 codes.
        (String(mut x), Enum(c)) => {
            x.push(latin1(c));
            String(x)
        }
        (Enum(c), String(y)) => {
            let mut x = latin1(c).to_string();
            x.push_str(&y);
            String(x)
        }
        (Array(mut x), Array(y)) => {
            x.extend(y);
            Array(x)
        }
        (Array(mut x), e) => {
            x.push(e);
            Array(x)
        }
        (e, Array(mut y)) => {
            y.insert(0, e);
            Array(y)
        }
        // Two elements (`'1' & b`, a bit_vector; characters come as `"" & c & d`).
        (a @ (Enum(_) | Boolean(_)), b @ (Enum(_) | Boolean(_))) => Array(vec![a, b]),
        (a, b) => return Err(mismatch("&", &a, &b)),
    })
}

fn latin1(position: u32) -> char {
    char::from_u32(position).unwrap_or(char::REPLACEMENT_CHARACTER)
}

/// The help of an array assignment whose lengths differ.
pub(crate) const LENGTH_HELP: &str = "an array value must have its target's length (LRM 8.4, 8.5: the target keeps its bounds); resize the value (a slice, `resize`, an aggregate with `others`) or the target";

/// The math_real functions and the numeric type conversions.
pub(crate) fn builtin(f: Builtin, args: &[Value]) -> Result<Value, EvalError> {
    use Builtin::*;
    if f.on_values() {
        let help = if matches!(f, Slice | Splice) {
            "keep a slice within its array's bounds"
        } else if f == ValueOf {
            "'value reads one literal of the type, as 'image writes it"
        } else if f == CheckLength {
            LENGTH_HELP
        } else if f == Pwl {
            vams_design::pwl::TableError::HELP
        } else {
            "keep the argument within the type's range (T'low to T'high)"
        };
        return vams_design::value_builtin(f, args).map_err(|m| EvalError::new(m, help));
    }
    let arity = match f {
        Atan2 | Realmax | Realmin => 2,
        _ => 1,
    };
    if args.len() != arity {
        return Err(EvalError::new(
            format!("{f:?} takes {arity} argument(s), got {}", args.len()),
            TYPE_HELP,
        ));
    }
    if f == ToReal {
        return match args[0] {
            Value::Integer(i) => Ok(Value::Real(i as f64)),
            Value::Real(x) => Ok(Value::Real(x)),
            // Only generated code converts a time (`now` in seconds, for the AMS attributes):
            // the elaborator refuses `real(t)` in models.
            Value::Time(t) => Ok(Value::Real(t)),
            ref v => Err(EvalError::new(format!("real() of {}", kind(v)), TYPE_HELP)),
        };
    }
    let x = real_arg(f, &args[0])?;
    if f == ToInteger {
        // VHDL rounds to the nearest integer, halves away from zero (LRM 9.3.6).
        let r = x.round();
        if !r.is_finite() || r.abs() >= i64::MAX as f64 {
            return Err(EvalError::new(
                format!("integer({x}) is out of range"),
                "the value does not fit an integer",
            ));
        }
        return Ok(Value::Integer(r as i64));
    }
    let y = if arity == 2 {
        real_arg(f, &args[1])?
    } else {
        0.0
    };
    if let Some(message) = outside_domain(f, x, y) {
        return Err(EvalError::new(
            message,
            "math_real reports an argument outside the function's domain as an error \
             (IEEE 1076.2); keep the argument inside it",
        ));
    }
    let r = real_builtin(f, x, y);
    if !r.is_finite() && x.is_finite() && y.is_finite() {
        return Err(overflow(&format!("{f:?}({x})")));
    }
    Ok(Value::Real(r))
}

/// math_real's message for an argument outside the domain of `f` (IEEE 1076.2), or `None`.
fn outside_domain(f: Builtin, x: f64, y: f64) -> Option<String> {
    use Builtin::*;
    let (bad, rule) = match f {
        Sqrt => (x < 0.0, "X < 0.0 in SQRT(X)"),
        Log => (x <= 0.0, "X <= 0.0 in LOG(X)"),
        Log10 => (x <= 0.0, "X <= 0.0 in LOG10(X)"),
        Asin => (x.abs() > 1.0, "ABS(X) > 1.0 in ARCSIN(X)"),
        Acos => (x.abs() > 1.0, "ABS(X) > 1.0 in ARCCOS(X)"),
        Acosh => (x < 1.0, "X < 1.0 in ARCCOSH(X)"),
        Atanh => (x.abs() >= 1.0, "ABS(X) >= 1.0 in ARCTANH(X)"),
        Atan2 => (x == 0.0 && y == 0.0, "X = 0.0 and Y = 0.0 in ARCTAN(Y, X)"),
        _ => (false, ""),
    };
    bad.then(|| format!("{rule}, with X = {x}"))
}

/// The real-valued builtins on plain numbers, shared with equation evaluation.
pub(crate) fn real_builtin(f: Builtin, x: f64, y: f64) -> f64 {
    use Builtin::*;
    match f {
        Exp => x.exp(),
        Log => x.ln(),
        Log10 => x.log10(),
        Sqrt => x.sqrt(),
        Sin => x.sin(),
        Cos => x.cos(),
        Tan => x.tan(),
        Asin => x.asin(),
        Acos => x.acos(),
        Atan => x.atan(),
        Atan2 => x.atan2(y),
        Sinh => x.sinh(),
        Cosh => x.cosh(),
        Tanh => x.tanh(),
        Asinh => x.asinh(),
        Acosh => x.acosh(),
        Atanh => x.atanh(),
        Floor => x.floor(),
        Ceil => x.ceil(),
        Round => x.round(),
        Trunc => x.trunc(),
        Sign => {
            if x > 0.0 {
                1.0
            } else if x < 0.0 {
                -1.0
            } else {
                0.0
            }
        }
        Realmax => x.max(y),
        Realmin => x.min(y),
        ToReal => x,
        ToInteger => x.round(),
        // Not real-valued: `builtin` handles them before it reaches here; NaN otherwise.
        Pos | TimePos | EnumVal | TimeVal | Slice | Splice | ValueOf | Restring | Length
        | CheckLength | Pwl => f64::NAN,
    }
}

fn real_arg(f: Builtin, v: &Value) -> Result<f64, EvalError> {
    match v {
        Value::Real(x) => Ok(*x),
        Value::Integer(i) => Ok(*i as f64),
        v => Err(EvalError::new(format!("{f:?} of {}", kind(v)), TYPE_HELP)),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use proptest::prelude::*;

    fn value() -> impl Strategy<Value = Value> {
        prop_oneof![
            any::<f64>().prop_map(Value::Real),
            any::<i64>().prop_map(Value::Integer),
            any::<bool>().prop_map(Value::Boolean),
            any::<f64>().prop_map(Value::Time),
            (0u32..300).prop_map(Value::Enum),
            "[a-z]{0,4}".prop_map(Value::String),
            proptest::collection::vec(any::<bool>().prop_map(Value::Boolean), 0..3)
                .prop_map(Value::Array),
        ]
    }

    const OPS: [BinaryOp; 26] = [
        BinaryOp::Add,
        BinaryOp::Sub,
        BinaryOp::Mul,
        BinaryOp::Div,
        BinaryOp::Pow,
        BinaryOp::Mod,
        BinaryOp::Rem,
        BinaryOp::Eq,
        BinaryOp::Ne,
        BinaryOp::Lt,
        BinaryOp::Le,
        BinaryOp::Gt,
        BinaryOp::Ge,
        BinaryOp::And,
        BinaryOp::Or,
        BinaryOp::Nand,
        BinaryOp::Nor,
        BinaryOp::Xor,
        BinaryOp::Xnor,
        BinaryOp::Concat,
        BinaryOp::Sll,
        BinaryOp::Srl,
        BinaryOp::Sla,
        BinaryOp::Sra,
        BinaryOp::Rol,
        BinaryOp::Ror,
    ];

    proptest! {
        /// Whatever the operands, an operator gives a value or an error, never a panic.
        #[test]
        fn operators_never_panic(op in 0..OPS.len(), a in value(), b in value()) {
            let _ = binary(OPS[op], a.clone(), b);
            for u in [UnaryOp::Neg, UnaryOp::Plus, UnaryOp::Abs, UnaryOp::Not] {
                let _ = unary(u, a.clone());
            }
            let _ = builtin(Builtin::ToInteger, &[a]);
        }
    }
}
