//! Expression evaluation in processes: [`Expr`] to [`Value`] against the current signal values,
//! the process's variables, the analog solution at the current time and `now`.

use std::borrow::Cow;

use vams_design::{BinaryOp, Builtin, Expr, SignalAttr, Subprogram, Type, Value};

use super::image::image;
use super::io::Io;
pub(crate) use super::ops::EvalError;
use super::ops::{binary, builtin, unary};
use super::signals::SignalState;

/// What an expression can read.
pub(crate) struct Env<'a> {
    pub signals: &'a [SignalState],
    pub vars: &'a [Value],
    /// Quantity values and derivatives by `QuantityId` at `now`.
    pub quantities: &'a [f64],
    pub derivatives: &'a [f64],
    pub now: f64,
    /// The design's subprograms, for function calls.
    pub subprograms: &'a [Subprogram],
    /// Subprogram calls active around this evaluation (see `call::MAX_CALL_DEPTH`).
    pub depth: usize,
    /// The heap and the files.
    pub io: &'a Io,
    /// The signals' drivers and the evaluating process, for `'driving` and `'driving_value`
    /// (`None` outside a process).
    pub drivers: Option<(&'a super::signals::Signals, usize)>,
}

/// `Builtin::CheckLength(value, length, target)`. Kept out of [`eval`], whose frame every
/// nested function call adds to the stack.
#[inline(never)]
fn checked_length(args: &[Expr], env: &Env) -> Result<Value, EvalError> {
    match args {
        [
            v,
            Expr::Const(Value::Integer(n)),
            Expr::Const(Value::String(target)),
        ] => {
            let v = eval(v, env)?;
            vams_design::check_length(&v, *n, target)
                .map_err(|m| EvalError::new(m, super::ops::LENGTH_HELP))?;
            Ok(v)
        }
        _ => {
            let values = args
                .iter()
                .map(|a| eval(a, env))
                .collect::<Result<Vec<_>, _>>()?;
            builtin(Builtin::CheckLength, &values)
        }
    }
}

/// The value of `e`. The leaves and operators of ordinary arithmetic are here, in a small
/// frame; everything else is in [`eval_other`], whose frame is large.
pub(crate) fn eval(e: &Expr, env: &Env) -> Result<Value, EvalError> {
    match e {
        Expr::Const(v) => Ok(v.clone()),
        Expr::Signal(s) => Ok(env.signals[s.index()].value.clone()),
        Expr::Var(v) => Ok(env.vars[v.index()].clone()),
        // `and` and `or` on booleans short-circuit (LRM 9.2.2).
        Expr::Binary(op @ (BinaryOp::And | BinaryOp::Or), a, b) => match eval(a, env)? {
            Value::Boolean(x) if x == (*op == BinaryOp::Or) => Ok(Value::Boolean(x)),
            a => binary(*op, a, eval(b, env)?),
        },
        Expr::Binary(op, a, b) => {
            let a = match leaf(a, env) {
                Some(v) => v,
                None => eval(a, env)?,
            };
            let b = match leaf(b, env) {
                Some(v) => v,
                None => eval(b, env)?,
            };
            binary(*op, a, b)
        }
        _ => eval_other(e, env),
    }
}

/// The value of a constant, signal or variable operand, read in place rather than through
/// a call of [`eval`]; `None` for other expressions.
#[inline(always)]
fn leaf(e: &Expr, env: &Env) -> Option<Value> {
    match e {
        Expr::Const(v) => Some(v.clone()),
        Expr::Signal(s) => Some(env.signals[s.index()].value.clone()),
        Expr::Var(v) => Some(env.vars[v.index()].clone()),
        _ => None,
    }
}

#[inline(never)]
fn eval_other(e: &Expr, env: &Env) -> Result<Value, EvalError> {
    Ok(match e {
        Expr::Const(_) | Expr::Signal(_) | Expr::Var(_) | Expr::Binary(..) => eval(e, env)?,
        Expr::Quantity(q) => Value::Real(env.quantities[q.index()]),
        Expr::Dot(q) => Value::Real(env.derivatives[q.index()]),
        Expr::Now => Value::Time(env.now),
        Expr::Unary(op, a) => unary(*op, eval(a, env)?)?,
        // An array value checked against its target's length: moved through, not copied.
        Expr::Call(Builtin::CheckLength, args) => checked_length(args, env)?,
        Expr::Call(f, args) => {
            let values = args
                .iter()
                .map(|a| eval(a, env))
                .collect::<Result<Vec<_>, _>>()?;
            builtin(*f, &values)?
        }
        Expr::If(c, a, b) => {
            if truth(&eval(c, env)?)? {
                eval(a, env)?
            } else {
                eval(b, env)?
            }
        }
        Expr::Index { array, index, ty } => match place(e, env)? {
            // An element of a signal or variable read in place: the array is not copied.
            Some(v) => v.into_owned(),
            None => {
                let array = eval(array, env)?;
                let i = integer(&eval(index, env)?)?;
                element(array, i, ty)?
            }
        },
        Expr::Image(ty, x) => Value::String(image(ty, &eval(x, env)?)),
        Expr::Aggregate { elems, string } => {
            let vals = elems
                .iter()
                .map(|e| eval(e, env))
                .collect::<Result<Vec<_>, _>>()?;
            vams_design::aggregate_value(vals, *string)
        }
        Expr::FnCall { sub, args, .. } => super::call::call_function(*sub, args, env)?,
        Expr::New(init) => {
            let v = eval(init, env)?;
            env.io.heap.borrow_mut().alloc(v)?
        }
        Expr::Deref(p) => {
            let p = eval(p, env)?;
            env.io.heap.borrow_mut().get(&p)?.clone()
        }
        Expr::EndFile(f) => match eval(f, env)? {
            Value::File(f) => Value::Boolean(env.io.files.borrow_mut().at_end(f)?),
            _ => {
                return Err(EvalError::new(
                    "endfile of a value that is not a file",
                    "this is a bug in elaboration",
                ));
            }
        },
        Expr::SignalAttr(s, attr) => {
            let st = &env.signals[s.index()];
            match attr {
                SignalAttr::Event => Value::Boolean(st.event),
                SignalAttr::Active => Value::Boolean(st.active),
                SignalAttr::LastValue => st.last_value.clone(),
                // TIME'HIGH when the signal never had an event (LRM 16.2.4).
                SignalAttr::LastEvent => Value::Time(match st.last_event {
                    Some(t) => env.now - t,
                    None => f64::MAX,
                }),
                SignalAttr::LastActive => Value::Time(match st.last_active {
                    Some(t) => env.now - t,
                    None => f64::MAX,
                }),
                SignalAttr::Driving | SignalAttr::DrivingValue => {
                    let driving = env.drivers.and_then(|(d, p)| d.driving(p, *s));
                    let Some((connected, value)) = driving else {
                        return Err(EvalError::new(
                            "`'driving` or `'driving_value` of a signal this process does not drive",
                            "the prefix must be a signal the process assigns (LRM 14.1)",
                        ));
                    };
                    match attr {
                        SignalAttr::Driving => Value::Boolean(connected),
                        _ => value,
                    }
                }
            }
        }
    })
}

/// A condition's value.
pub(crate) fn truth(v: &Value) -> Result<bool, EvalError> {
    match v {
        Value::Boolean(b) => Ok(*b),
        _ => Err(EvalError::new(
            "a condition is not a boolean",
            "conditions must be of type boolean (LRM 10.2)",
        )),
    }
}

pub(crate) fn integer(v: &Value) -> Result<i64, EvalError> {
    match v {
        Value::Integer(i) => Ok(*i),
        _ => Err(EvalError::new(
            "an index is not an integer",
            "array indices must be integers here",
        )),
    }
}

/// Position of index `i` in an array of type `ty` with `len` elements, bounds checked.
pub(crate) fn offset(ty: &Type, i: i64, len: usize) -> Result<usize, EvalError> {
    let (left, ascending) = ty.index_origin();
    let right = match ty {
        Type::Array { right, .. } => *right,
        // `string` from 1 upwards, a record's fields from 0.
        _ => left + len as i64 - 1,
    };
    let (lo, hi) = if ascending {
        (left, right)
    } else {
        (right, left)
    };
    // i128: no overflow whatever index a model computes.
    let pos = if ascending {
        i as i128 - left as i128
    } else {
        left as i128 - i as i128
    };
    if i < lo || i > hi || pos < 0 || pos >= len as i128 {
        let dir = if ascending { "to" } else { "downto" };
        return Err(EvalError::new(
            format!("index {i} is outside the bounds {left} {dir} {right}"),
            "check the index expression against the array's range (LRM 9.3.4.3)",
        ));
    }
    Ok(pos as usize)
}

/// `target(i) := v` on a variable's value of type `ty`: an array's element, or a character of
/// a `string` (strings are `Value::String`, `r(k) := '1'` on `variable r : string(1 to 4)`).
pub(crate) fn set_element(
    target: &mut Value,
    ty: &Type,
    i: i64,
    v: Value,
) -> Result<(), EvalError> {
    match target {
        Value::Array(items) => {
            let pos = offset(ty, i, items.len())?;
            items[pos] = v;
            Ok(())
        }
        Value::String(s) => {
            let mut chars: Vec<char> = s.chars().collect();
            let pos = offset(ty, i, chars.len())?;
            let Value::Enum(c) = v else {
                return Err(EvalError::new(
                    "a character of a string assigned a value that is not a character",
                    "this is a bug in elaboration if the model passed type checking",
                ));
            };
            // `character` positions are Latin-1 codes.
            chars[pos] = char::from_u32(c).unwrap_or(char::REPLACEMENT_CHARACTER);
            *s = chars.into_iter().collect();
            Ok(())
        }
        _ => Err(EvalError::new(
            "element assignment to a variable that is not an array",
            "only array variables can be assigned element by element",
        )),
    }
}

/// The value `e` names in place, when it is a constant, a signal, a variable or an element
/// of one (`a(i)(j)`), read without copying the arrays around it; `None`, having evaluated
/// nothing, for other expressions.
fn place<'v>(e: &'v Expr, env: &'v Env<'_>) -> Result<Option<Cow<'v, Value>>, EvalError> {
    Ok(Some(match e {
        Expr::Const(v) => Cow::Borrowed(v),
        Expr::Signal(s) => Cow::Borrowed(&env.signals[s.index()].value),
        Expr::Var(v) => Cow::Borrowed(&env.vars[v.index()]),
        Expr::Index { array, index, ty } => {
            let Some(array) = place(array, env)? else {
                return Ok(None);
            };
            let i = integer(&eval(index, env)?)?;
            match array {
                Cow::Borrowed(Value::Array(items)) => {
                    Cow::Borrowed(&items[offset(ty, i, items.len())?])
                }
                array => Cow::Owned(element_of(&array, i, ty)?),
            }
        }
        _ => return Ok(None),
    }))
}

/// Element `i` of `array` (of type `ty`), read in place: [`element`] without consuming it.
fn element_of(array: &Value, i: i64, ty: &Type) -> Result<Value, EvalError> {
    match array {
        Value::Array(items) => Ok(items[offset(ty, i, items.len())?].clone()),
        Value::String(s) if s.is_ascii() => {
            let pos = offset(ty, i, s.len())?;
            Ok(Value::Enum(u32::from(s.as_bytes()[pos])))
        }
        other => element(other.clone(), i, ty),
    }
}

fn element(array: Value, i: i64, ty: &Type) -> Result<Value, EvalError> {
    match array {
        Value::Array(mut items) => {
            let pos = offset(ty, i, items.len())?;
            Ok(items.swap_remove(pos))
        }
        Value::String(s) => {
            let chars: Vec<char> = s.chars().collect();
            let pos = offset(ty, i, chars.len())?;
            Ok(Value::Enum(chars[pos] as u32))
        }
        _ => Err(EvalError::new(
            "indexing a value that is not an array",
            "only arrays and strings can be indexed",
        )),
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vams_design::{BinaryOp::*, Builtin, UnaryOp};

    fn int(i: i64) -> Expr {
        Expr::Const(Value::Integer(i))
    }

    fn bin(op: BinaryOp, a: Expr, b: Expr) -> Expr {
        Expr::Binary(op, Box::new(a), Box::new(b))
    }

    fn run(e: &Expr) -> Result<Value, EvalError> {
        let env = Env {
            signals: &[],
            vars: &[],
            quantities: &[],
            derivatives: &[],
            now: 2e-3,
            subprograms: &[],
            depth: 0,
            io: &Io::default(),
            drivers: None,
        };
        eval(e, &env)
    }

    #[test]
    fn integer_division_truncates_and_mod_rem_follow_vhdl_signs() {
        let cases = [
            (Div, 7, 2, 3),
            (Div, -7, 2, -3),
            (Rem, -7, 2, -1),
            (Mod, -7, 2, 1),
            (Mod, 7, -2, -1),
            (Rem, 7, -2, 1),
            (Pow, 3, 4, 81),
        ];
        for (op, a, b, r) in cases {
            assert_eq!(
                run(&bin(op, int(a), int(b))),
                Ok(Value::Integer(r)),
                "{a} {op:?} {b}"
            );
        }
        assert!(run(&bin(Div, int(1), int(0))).is_err());
        assert!(run(&bin(Mod, int(1), int(0))).is_err());
        assert!(run(&bin(Pow, int(2), int(-1))).is_err());
        assert!(run(&bin(Mul, int(i64::MAX), int(2))).is_err());
    }

    #[test]
    fn time_and_real_arithmetic() {
        let t = |s| Expr::Const(Value::Time(s));
        assert_eq!(
            run(&bin(Mul, Expr::real(1.5), t(1e-3))),
            Ok(Value::Time(1.5e-3))
        );
        assert_eq!(run(&bin(Div, t(1e-3), t(2.5e-4))), Ok(Value::Integer(4)));
        assert_eq!(run(&bin(Sub, Expr::Now, t(1e-3))), Ok(Value::Time(1e-3)));
        assert_eq!(
            run(&bin(Pow, Expr::real(2.0), int(-2))),
            Ok(Value::Real(0.25))
        );
        let sqrt = Expr::Call(Builtin::Sqrt, vec![Expr::real(2.25)]);
        assert_eq!(run(&sqrt), Ok(Value::Real(1.5)));
        let round = Expr::Call(Builtin::ToInteger, vec![Expr::real(-2.5)]);
        assert_eq!(run(&round), Ok(Value::Integer(-3)));
        let abs = Expr::Unary(UnaryOp::Abs, Box::new(Expr::real(-4.0)));
        assert_eq!(run(&abs), Ok(Value::Real(4.0)));
    }

    #[test]
    fn comparisons_logic_and_concatenation() {
        assert_eq!(
            run(&bin(Le, Expr::real(1.0), Expr::real(1.0))),
            Ok(Value::Boolean(true))
        );
        let b = |x| Expr::Const(Value::Boolean(x));
        assert_eq!(run(&bin(Xor, b(true), b(true))), Ok(Value::Boolean(false)));
        assert_eq!(run(&bin(Nor, b(false), b(false))), Ok(Value::Boolean(true)));
        // `false and <error>` never evaluates the right operand.
        assert_eq!(
            run(&bin(And, b(false), bin(Div, int(1), int(0)))),
            Ok(Value::Boolean(false))
        );
        let s = |x: &str| Expr::Const(Value::String(x.into()));
        let img = Expr::Image(Type::Real, Box::new(Expr::real(10.5)));
        assert_eq!(
            run(&bin(Concat, s("v = "), img)),
            Ok(Value::String("v = 10.5".into()))
        );
    }

    #[test]
    fn indexing_is_bounds_checked_in_the_array_type() {
        let ty = Type::Array {
            element: Box::new(Type::Integer),
            left: 7,
            right: 5,
            ascending: false,
        };
        let array = Expr::Const(Value::Array(vec![
            Value::Integer(70),
            Value::Integer(60),
            Value::Integer(50),
        ]));
        let at = |i| Expr::Index {
            array: Box::new(array.clone()),
            index: Box::new(int(i)),
            ty: ty.clone(),
        };
        assert_eq!(run(&at(7)), Ok(Value::Integer(70)));
        assert_eq!(run(&at(5)), Ok(Value::Integer(50)));
        let err = run(&at(8)).unwrap_err();
        assert!(err.message.contains("7 downto 5"), "{}", err.message);
        assert!(run(&at(i64::MIN)).is_err());
        assert!(run(&at(i64::MAX)).is_err());
    }
}
