//! Integer expressions without `Value`s: a statement's expression made of integer constants,
//! signals and variables under arithmetic and comparisons (`(count + 1) mod 10`, `i < n`)
//! evaluated on `i64`s, with no `Result` and no clone or drop of a `Value` per node.
//!
//! Only a shortcut: anything else (another operand type, another operator, a division by
//! zero, an overflow) gives `None`, and the caller evaluates the expression through
//! [`eval`], which gives the same value or words the error. Tried once per statement, not at
//! every node of [`eval`]'s walk, so that an expression of reals pays one failed look at its
//! leftmost operand, not one per level.

use vams_design::{BinaryOp, Expr, Value};

use super::eval::{Env, EvalError, eval, truth};

/// The value of `e`: by the integer shortcut when it applies, else by [`eval`].
#[inline]
pub(crate) fn value(e: &Expr, env: &Env) -> Result<Value, EvalError> {
    match shortcut(e, env) {
        Some(v) => Ok(v),
        None => eval(e, env),
    }
}

/// The truth of condition `e`: by the integer shortcut when it applies, else by [`eval`].
#[inline]
pub(crate) fn condition(e: &Expr, env: &Env) -> Result<bool, EvalError> {
    match shortcut(e, env) {
        Some(Value::Boolean(b)) => Ok(b),
        _ => truth(&eval(e, env)?),
    }
}

/// An integer operation or comparison of integer operands, or `None`.
#[inline]
fn shortcut(e: &Expr, env: &Env) -> Option<Value> {
    let Expr::Binary(op, a, b) = e else {
        return None;
    };
    use BinaryOp::*;
    let compare =
        |f: fn(&i64, &i64) -> bool| Some(Value::Boolean(f(&integer(a, env)?, &integer(b, env)?)));
    match op {
        Add | Sub | Mul | Div | Mod | Rem => Some(Value::Integer(integer(e, env)?)),
        Eq => compare(i64::eq),
        Ne => compare(i64::ne),
        Lt => compare(i64::lt),
        Le => compare(i64::le),
        Gt => compare(i64::gt),
        Ge => compare(i64::ge),
        _ => None,
    }
}

/// Operation `e` as an integer, or `None` when it is not one of the forms above or its
/// arithmetic fails (the general path reports why).
fn integer(e: &Expr, env: &Env) -> Option<i64> {
    match e {
        Expr::Binary(op, a, b) => arithmetic(*op, operand(a, env)?, operand(b, env)?),
        _ => operand(e, env),
    }
}

/// Operand `e` as an integer: a leaf read in place, an operation through [`integer`].
#[inline(always)]
fn operand(e: &Expr, env: &Env) -> Option<i64> {
    match e {
        Expr::Const(Value::Integer(i)) => Some(*i),
        Expr::Signal(s) => match env.signals[s.index()].value {
            Value::Integer(i) => Some(i),
            _ => None,
        },
        Expr::Var(v) => match env.vars[v.index()] {
            Value::Integer(i) => Some(i),
            _ => None,
        },
        Expr::Binary(..) => integer(e, env),
        _ => None,
    }
}

/// `x op y` as `ops::binary` computes it for two integers; `None` for an error or another
/// operator.
fn arithmetic(op: BinaryOp, x: i64, y: i64) -> Option<i64> {
    use BinaryOp::*;
    match op {
        Add => x.checked_add(y),
        Sub => x.checked_sub(y),
        Mul => x.checked_mul(y),
        // Rust's `/` truncates towards zero, as VHDL's does; `None` for 0 and overflow.
        Div => x.checked_div(y),
        Mod | Rem => {
            let r = x.checked_rem(y)?;
            // `rem` has the sign of the left operand (Rust's `%`); `mod` that of the right.
            Some(if op == Mod && r != 0 && (r < 0) != (y < 0) {
                r + y
            } else {
                r
            })
        }
        _ => None,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::kernel::io::Io;

    fn env_eval(e: &Expr) -> (Option<Value>, Result<Value, EvalError>) {
        let io = Io::default();
        let env = Env {
            signals: &[],
            vars: &[Value::Integer(7), Value::Real(1.5)],
            quantities: &[],
            derivatives: &[],
            now: 0.0,
            subprograms: &[],
            depth: 0,
            io: &io,
            drivers: None,
        };
        (shortcut(e, &env), eval(e, &env))
    }

    /// Wherever the shortcut gives a value, the general evaluation gives the same one.
    #[test]
    fn the_shortcut_agrees_with_the_general_evaluation() {
        use BinaryOp::*;
        let ops = [
            Add, Sub, Mul, Div, Mod, Rem, Pow, Eq, Ne, Lt, Le, Gt, Ge, And,
        ];
        let numbers = [0, 1, -1, 2, -3, 7, -7, 1_000_000, i64::MAX, i64::MIN];
        let leaf = |i: i64| Expr::Const(Value::Integer(i));
        let mut checked = 0;
        for op in ops {
            for x in numbers {
                for y in numbers {
                    let e = Expr::Binary(op, Box::new(leaf(x)), Box::new(leaf(y)));
                    let (fast, slow) = env_eval(&e);
                    if let Some(v) = fast {
                        assert_eq!(Ok(v), slow, "{x} {op:?} {y}");
                        checked += 1;
                    }
                    // Nested, with a variable on the left.
                    let var = Expr::Binary(
                        Add,
                        Box::new(Expr::Var(vams_design::VarId(0))),
                        Box::new(leaf(x)),
                    );
                    let e = Expr::Binary(op, Box::new(var), Box::new(leaf(y)));
                    let (fast, slow) = env_eval(&e);
                    if let Some(v) = fast {
                        assert_eq!(Ok(v), slow, "(7 + {x}) {op:?} {y}");
                    }
                }
            }
        }
        assert!(checked > 800, "{checked}");
        // Not integers: the general path.
        let real = Expr::Binary(
            Add,
            Box::new(Expr::Var(vams_design::VarId(1))),
            Box::new(Expr::real(1.0)),
        );
        assert_eq!(env_eval(&real).0, None);
    }
}
