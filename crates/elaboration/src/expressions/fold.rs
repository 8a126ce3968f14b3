//! Constant folding: evaluates an [`Expr`] that reads no signal, quantity, variable or time to
//! its [`Value`]. Elaboration folds every constant, generic and static sub-expression.

use vams_design::{BinaryOp, Builtin, Expr, UnaryOp, Value, aggregate_value};

/// Why an expression did not fold.
#[derive(Debug, PartialEq)]
pub enum NoFold {
    /// It reads something only known at run time.
    Dynamic,
    /// It is static but cannot be computed (division by zero, index out of range, ...).
    Error(String),
}

fn err<T>(msg: impl Into<String>) -> Result<T, NoFold> {
    Err(NoFold::Error(msg.into()))
}

/// The value of a static expression.
pub fn eval(e: &Expr) -> Result<Value, NoFold> {
    match e {
        Expr::Const(v) => Ok(v.clone()),
        Expr::Quantity(_)
        | Expr::Dot(_)
        | Expr::Signal(_)
        | Expr::Var(_)
        | Expr::Now
        | Expr::SignalAttr(..)
        // User functions run in the kernel (they may read signals or recurse without bound).
        | Expr::FnCall { .. }
        // The heap and the files exist at run time only.
        | Expr::New(_)
        | Expr::Deref(_)
        | Expr::EndFile(_)
        // Images are left to the kernel so that every image has the same format.
        | Expr::Image(..) => Err(NoFold::Dynamic),
        Expr::Aggregate { elems, string } => {
            let vals = elems.iter().map(eval).collect::<Result<Vec<_>, _>>()?;
            Ok(aggregate_value(vals, *string))
        }
        Expr::Unary(op, a) => unary(*op, eval(a)?),
        Expr::Binary(op, a, b) => {
            // Evaluate both sides so a dynamic operand wins over a static error.
            let (a, b) = (eval(a), eval(b));
            binary(*op, a?, b?)
        }
        Expr::Call(f, args) => {
            let vals = args.iter().map(eval).collect::<Result<Vec<_>, _>>()?;
            call(*f, &vals)
        }
        Expr::If(c, a, b) => match eval(c)? {
            Value::Boolean(true) => eval(a),
            Value::Boolean(false) => eval(b),
            _ => err("the condition is not boolean"),
        },
        Expr::Index { array, index, ty } => {
            let (array, index) = (eval(array), eval(index));
            let (array, index) = (array?, index?);
            let Value::Integer(i) = index else {
                return err("an index must be an integer");
            };
            let (left, ascending) = ty.index_origin();
            let offset = if ascending { i - left } else { left - i };
            let n = match &array {
                Value::Array(v) => v.len(),
                Value::String(s) => s.chars().count(),
                _ => return err("indexing a value that is not an array"),
            };
            if offset < 0 || offset as usize >= n {
                return err(format!("index {i} is out of the array's range"));
            }
            Ok(match array {
                Value::Array(v) => v[offset as usize].clone(),
                Value::String(s) => {
                    // In range: checked against the character count above.
                    let c = s.chars().nth(offset as usize).unwrap_or(' ');
                    Value::Enum(c as u32)
                }
                _ => unreachable!("checked above"),
            })
        }
    }
}

fn unary(op: UnaryOp, v: Value) -> Result<Value, NoFold> {
    Ok(match (op, v) {
        (UnaryOp::Plus, v) => v,
        (UnaryOp::Neg, Value::Integer(i)) => Value::Integer(i.checked_neg().ok_or_else(overflow)?),
        (UnaryOp::Neg, Value::Real(x)) => Value::Real(-x),
        (UnaryOp::Neg, Value::Time(x)) => Value::Time(-x),
        (UnaryOp::Abs, Value::Integer(i)) => Value::Integer(i.checked_abs().ok_or_else(overflow)?),
        (UnaryOp::Abs, Value::Real(x)) => Value::Real(x.abs()),
        (UnaryOp::Abs, Value::Time(x)) => Value::Time(x.abs()),
        (UnaryOp::Not, Value::Boolean(b)) => Value::Boolean(!b),
        (UnaryOp::Not, Value::Enum(p)) => Value::Enum(1 - p.min(1)),
        // `not` of a static `bit_vector` or boolean array (`not bv4'("0010")`), element by
        // element as the kernel computes it at run time.
        (UnaryOp::Not, Value::Array(items)) => Value::Array(
            items
                .into_iter()
                .map(|e| unary(UnaryOp::Not, e))
                .collect::<Result<_, _>>()?,
        ),
        _ => return err("operand type not supported by the operator"),
    })
}

fn overflow() -> NoFold {
    NoFold::Error("integer overflow".into())
}

fn int_op(op: BinaryOp, a: i64, b: i64) -> Result<Value, NoFold> {
    let r = match op {
        BinaryOp::Add => a.checked_add(b),
        BinaryOp::Sub => a.checked_sub(b),
        BinaryOp::Mul => a.checked_mul(b),
        BinaryOp::Div | BinaryOp::Mod | BinaryOp::Rem if b == 0 => return err("division by zero"),
        BinaryOp::Div => a.checked_div(b),
        BinaryOp::Rem => a.checked_rem(b),
        // VHDL `mod` takes the sign of the right operand.
        BinaryOp::Mod => a.checked_rem(b).map(|r| {
            if r != 0 && (r < 0) != (b < 0) {
                r + b
            } else {
                r
            }
        }),
        BinaryOp::Pow => {
            if b < 0 {
                return err("an integer raised to a negative power");
            }
            u32::try_from(b).ok().and_then(|e| a.checked_pow(e))
        }
        _ => return cmp(op, a.cmp(&b)),
    };
    r.map(Value::Integer).ok_or_else(overflow)
}

fn real_op(op: BinaryOp, a: f64, b: f64) -> Result<f64, NoFold> {
    Ok(match op {
        BinaryOp::Add => a + b,
        BinaryOp::Sub => a - b,
        BinaryOp::Mul => a * b,
        BinaryOp::Div if b == 0.0 => return err("division by zero"),
        BinaryOp::Div => a / b,
        BinaryOp::Pow => a.powf(b),
        BinaryOp::Mod if b == 0.0 => return err("division by zero"),
        BinaryOp::Mod => a - b * (a / b).floor(),
        BinaryOp::Rem if b == 0.0 => return err("division by zero"),
        BinaryOp::Rem => a % b,
        _ => return err("operator not defined for reals"),
    })
}

fn cmp(op: BinaryOp, o: std::cmp::Ordering) -> Result<Value, NoFold> {
    use std::cmp::Ordering::*;
    Ok(Value::Boolean(match op {
        BinaryOp::Eq => o == Equal,
        BinaryOp::Ne => o != Equal,
        BinaryOp::Lt => o == Less,
        BinaryOp::Le => o != Greater,
        BinaryOp::Gt => o == Greater,
        BinaryOp::Ge => o != Less,
        _ => return err("operator not defined for these operands"),
    }))
}

fn is_cmp(op: BinaryOp) -> bool {
    matches!(
        op,
        BinaryOp::Eq | BinaryOp::Ne | BinaryOp::Lt | BinaryOp::Le | BinaryOp::Gt | BinaryOp::Ge
    )
}

fn logic(op: BinaryOp, a: bool, b: bool) -> Result<bool, NoFold> {
    Ok(match op {
        BinaryOp::And => a && b,
        BinaryOp::Or => a || b,
        BinaryOp::Nand => !(a && b),
        BinaryOp::Nor => !(a || b),
        BinaryOp::Xor => a != b,
        BinaryOp::Xnor => a == b,
        _ => return err("operator not defined for booleans"),
    })
}

fn as_text(v: &Value) -> Option<String> {
    match v {
        Value::String(s) => Some(s.clone()),
        Value::Enum(c) => char::from_u32(*c).map(String::from),
        _ => None,
    }
}

fn binary(op: BinaryOp, a: Value, b: Value) -> Result<Value, NoFold> {
    use Value::*;
    if is_cmp(op) {
        let o = match (&a, &b) {
            (Array(x), Array(y)) if matches!(op, BinaryOp::Eq | BinaryOp::Ne) => {
                return Ok(Boolean((x == y) == (op == BinaryOp::Eq)));
            }
            _ => a.order(&b),
        };
        return match o {
            Some(o) => cmp(op, o),
            None => err("these values cannot be compared"),
        };
    }
    if op == BinaryOp::Concat {
        if let (Some(x), Some(y)) = (as_text(&a), as_text(&b)) {
            if matches!(a, String(_)) || matches!(b, String(_)) {
                return Ok(String(x + &y));
            }
        }
        let mut items = match a {
            Array(v) => v,
            other => vec![other],
        };
        match b {
            Array(v) => items.extend(v),
            other => items.push(other),
        }
        return Ok(Array(items));
    }
    Ok(match (a, b) {
        (Integer(x), Integer(y)) => return int_op(op, x, y),
        (Real(x), Real(y)) => Real(real_op(op, x, y)?),
        (Real(x), Integer(y)) if op == BinaryOp::Pow => {
            Real(x.powi(i32::try_from(y).map_err(|_| overflow())?))
        }
        (Integer(x), Real(y)) if op == BinaryOp::Pow => Real((x as f64).powf(y)),
        (Time(x), Time(y)) => match op {
            BinaryOp::Add | BinaryOp::Sub => Time(real_op(op, x, y)?),
            BinaryOp::Div => Integer(real_op(op, x, y)?.trunc() as i64),
            _ => return err("operator not defined for two times"),
        },
        (Time(x), Real(y)) if matches!(op, BinaryOp::Mul | BinaryOp::Div) => {
            Time(real_op(op, x, y)?)
        }
        (Time(x), Integer(y)) if matches!(op, BinaryOp::Mul | BinaryOp::Div) => {
            Time(real_op(op, x, y as f64)?)
        }
        (Real(x), Time(y)) if op == BinaryOp::Mul => Time(x * y),
        (Integer(x), Time(y)) if op == BinaryOp::Mul => Time(x as f64 * y),
        (Boolean(x), Boolean(y)) => Boolean(logic(op, x, y)?),
        (Enum(x), Enum(y)) => Enum(u32::from(logic(op, x != 0, y != 0)?)),
        (Array(items), Integer(n)) if op.is_shift() => vams_design::shifted(op, &items, n),
        // The logical operators on two static arrays of one length (`bv4'("1101") and
        // bv4'("0011")`), element by element; analysis checked the lengths' types.
        (Array(x), Array(y)) if x.len() == y.len() && is_logical(op) => Array(
            x.into_iter()
                .zip(y)
                .map(|(p, q)| binary(op, p, q))
                .collect::<Result<_, _>>()?,
        ),
        _ => return err("operand types not supported by the operator"),
    })
}

fn call(f: Builtin, args: &[Value]) -> Result<Value, NoFold> {
    if f.on_values() {
        return vams_design::value_builtin(f, args).map_err(NoFold::Error);
    }
    if f == Builtin::ToReal {
        return match args {
            [Value::Integer(i)] => Ok(Value::Real(*i as f64)),
            [Value::Real(x)] => Ok(Value::Real(*x)),
            _ => err("real() takes an integer"),
        };
    }
    if f == Builtin::ToInteger {
        return match args {
            [Value::Real(x)] if x.abs() < 9.2e18 => Ok(Value::Integer(x.round() as i64)),
            [Value::Integer(i)] => Ok(Value::Integer(*i)),
            _ => err("integer() takes a real in range"),
        };
    }
    let xs: Vec<f64> = args.iter().filter_map(Value::as_f64).collect();
    let x = xs.first().copied().unwrap_or(f64::NAN);
    let y = xs.get(1).copied().unwrap_or(f64::NAN);
    let r = match f {
        Builtin::Exp => x.exp(),
        Builtin::Log if x <= 0.0 => return err("log of a value <= 0"),
        Builtin::Log => x.ln(),
        Builtin::Log10 if x <= 0.0 => return err("log10 of a value <= 0"),
        Builtin::Log10 => x.log10(),
        Builtin::Sqrt if x < 0.0 => return err("sqrt of a negative value"),
        Builtin::Sqrt => x.sqrt(),
        Builtin::Sin => x.sin(),
        Builtin::Cos => x.cos(),
        Builtin::Tan => x.tan(),
        Builtin::Asin => x.asin(),
        Builtin::Acos => x.acos(),
        Builtin::Atan => x.atan(),
        Builtin::Atan2 => x.atan2(y),
        Builtin::Sinh => x.sinh(),
        Builtin::Cosh => x.cosh(),
        Builtin::Tanh => x.tanh(),
        Builtin::Asinh => x.asinh(),
        Builtin::Acosh => x.acosh(),
        Builtin::Atanh => x.atanh(),
        Builtin::Floor => x.floor(),
        Builtin::Ceil => x.ceil(),
        Builtin::Round => x.round(),
        Builtin::Trunc => x.trunc(),
        Builtin::Sign => {
            if x > 0.0 {
                1.0
            } else if x < 0.0 {
                -1.0
            } else {
                0.0
            }
        }
        Builtin::Realmax => x.max(y),
        Builtin::Realmin => x.min(y),
        Builtin::ToReal
        | Builtin::ToInteger
        | Builtin::Pos
        | Builtin::TimePos
        | Builtin::EnumVal
        | Builtin::TimeVal
        | Builtin::Slice
        | Builtin::Splice
        | Builtin::ValueOf
        | Builtin::Restring
        | Builtin::Length
        | Builtin::CheckLength
        | Builtin::Pwl => {
            unreachable!("handled above")
        }
    };
    if r.is_nan() {
        return err("the result is not a number");
    }
    Ok(Value::Real(r))
}

/// Folds `e` when it is static (a dynamic expression is returned unchanged).
pub fn fold(e: Expr) -> Result<Expr, String> {
    if matches!(e, Expr::Const(_)) {
        return Ok(e);
    }
    match eval(&e) {
        Ok(v) => Ok(Expr::Const(v)),
        Err(NoFold::Dynamic) => Ok(element_of_aggregate(e)),
        Err(NoFold::Error(m)) => Err(m),
    }
}

/// `(a, b, c)(i)` at a static `i` is that element, though the others are run-time values (a
/// quantity array read in a loop of a procedural).
fn element_of_aggregate(e: Expr) -> Expr {
    let Expr::Index { array, index, ty } = e else {
        return e;
    };
    match (*array, &*index) {
        (
            Expr::Aggregate {
                mut elems,
                string: false,
            },
            Expr::Const(Value::Integer(i)),
        ) => {
            let (left, ascending) = ty.index_origin();
            let offset = if ascending { i - left } else { left - i };
            match usize::try_from(offset) {
                Ok(at) if at < elems.len() => elems.swap_remove(at),
                _ => Expr::Index {
                    array: Box::new(Expr::Aggregate {
                        elems,
                        string: false,
                    }),
                    index,
                    ty,
                },
            }
        }
        (array, _) => Expr::Index {
            array: Box::new(array),
            index,
            ty,
        },
    }
}

/// `and`, `or`, `nand`, `nor`, `xor`, `xnor`.
pub(crate) fn is_logical(op: BinaryOp) -> bool {
    matches!(
        op,
        BinaryOp::And
            | BinaryOp::Or
            | BinaryOp::Nand
            | BinaryOp::Nor
            | BinaryOp::Xor
            | BinaryOp::Xnor
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use vams_design::Type;

    fn bin(op: BinaryOp, a: Value, b: Value) -> Expr {
        Expr::Binary(op, Box::new(Expr::Const(a)), Box::new(Expr::Const(b)))
    }

    #[test]
    fn arithmetic_folds_exactly() {
        assert_eq!(
            eval(&bin(BinaryOp::Add, Value::Real(0.1), Value::Real(0.05))),
            Ok(Value::Real(0.1 + 0.05))
        );
        assert_eq!(
            eval(&bin(BinaryOp::Mod, Value::Integer(-7), Value::Integer(3))),
            Ok(Value::Integer(2))
        );
        assert_eq!(
            eval(&bin(BinaryOp::Rem, Value::Integer(-7), Value::Integer(3))),
            Ok(Value::Integer(-1))
        );
        assert_eq!(
            eval(&bin(BinaryOp::Mul, Value::Real(2.5), Value::Time(1.0))),
            Ok(Value::Time(2.5))
        );
        assert_eq!(
            eval(&bin(BinaryOp::Pow, Value::Real(2.0), Value::Integer(10))),
            Ok(Value::Real(1024.0))
        );
    }

    #[test]
    fn static_errors_and_dynamic_operands() {
        assert!(matches!(
            eval(&bin(BinaryOp::Div, Value::Integer(1), Value::Integer(0))),
            Err(NoFold::Error(_))
        ));
        let dynamic = Expr::Binary(
            BinaryOp::Add,
            Box::new(Expr::Now),
            Box::new(Expr::real(1.0)),
        );
        assert_eq!(eval(&dynamic), Err(NoFold::Dynamic));
        let index = Expr::Index {
            array: Box::new(Expr::Const(Value::Array(vec![
                Value::Real(1.0),
                Value::Real(2.0),
            ]))),
            index: Box::new(Expr::Const(Value::Integer(2))),
            ty: Type::Array {
                element: Box::new(Type::Real),
                left: 1,
                right: 2,
                ascending: true,
            },
        };
        assert_eq!(eval(&index), Ok(Value::Real(2.0)));
    }

    #[test]
    fn string_concatenation() {
        let e = bin(
            BinaryOp::Concat,
            Value::String("ab".into()),
            Value::Enum('c' as u32),
        );
        assert_eq!(eval(&e), Ok(Value::String("abc".into())));
    }
}
