//! Expression evaluation against a chain of parameter scopes.
//!
//! Takes [`Expr`] trees and parameter definitions; gives numbers. A [`Scope`] is one level of
//! the chain ngspice uses (the global `.param`s; then, per subcircuit instance, the
//! `params:` defaults with the `X` line's overrides and the body's own `.param`s), built all
//! at once from its definitions: each is evaluated lazily in the scope itself, so definitions
//! may refer to one another in any order, and a definition that depends on itself is a
//! [`SpiceError::ParamCycle`]. A name not defined in a scope is looked up in its parent.
//!
//! Never produces NaN or an infinity: a division by zero or a non-finite result is a located
//! error instead. An error is reported once, where it happens; a value that depends on a
//! parameter that failed fails silently ([`Fail::Reported`]), so one mistake gives one
//! diagnostic.

use std::f64::consts::PI;

use rustc_hash::FxHashMap;
use vams_syntax::source::Span;

use crate::error::SpiceError;
use crate::expr::{BinOp, Expr, ExprKind, Func, UnOp};
use crate::suggest::suggest;

/// Why an evaluation gave no number.
#[derive(Clone, Debug, PartialEq)]
pub enum Fail {
    /// A new diagnostic.
    Error(SpiceError),
    /// It depends on a parameter whose own error is already reported.
    Reported,
}

impl From<SpiceError> for Fail {
    fn from(e: SpiceError) -> Fail {
        Fail::Error(e)
    }
}

/// How a parameter is defined in a scope.
#[derive(Clone, Copy, Debug)]
pub enum Def<'e> {
    /// An expression, evaluated in the scope it is defined in.
    Expr(&'e Expr),
    /// A value computed elsewhere (an `X` line's override, evaluated in the caller's scope);
    /// `None` when that failed and was reported.
    Value(Option<f64>, Span),
}

/// One level of parameters, every value computed.
#[derive(Debug, Default)]
pub struct Scope<'p> {
    parent: Option<&'p Scope<'p>>,
    /// `None`: the definition failed (reported).
    values: FxHashMap<String, Option<f64>>,
}

impl<'p> Scope<'p> {
    /// A scope from its definitions (a later definition of a name replaces an earlier one),
    /// with the diagnostics of the definitions that failed.
    pub fn new(
        parent: Option<&'p Scope<'p>>,
        defs: &[(String, Def<'_>)],
    ) -> (Scope<'p>, Vec<SpiceError>) {
        let mut map: FxHashMap<&str, Def<'_>> = FxHashMap::default();
        let mut order = Vec::new();
        for (name, def) in defs {
            if map.insert(name.as_str(), *def).is_none() {
                order.push(name.as_str());
            }
        }
        let mut b = Builder {
            parent,
            defs: map,
            values: FxHashMap::default(),
            stack: Vec::new(),
            errors: Vec::new(),
        };
        for name in order {
            let _ = b.resolve(name, None);
        }
        let values = b.values.into_iter().map(|(k, v)| (k, v.done())).collect();
        (Scope { parent, values }, b.errors)
    }

    /// The value of a parameter visible here: `Some(None)` when it is defined but failed.
    pub fn get(&self, name: &str) -> Option<Option<f64>> {
        match self.values.get(name) {
            Some(v) => Some(*v),
            None => self.parent.and_then(|p| p.get(name)),
        }
    }

    /// Every parameter name visible here (for suggestions).
    pub fn names(&self) -> Vec<&str> {
        let mut out: Vec<&str> = self.values.keys().map(String::as_str).collect();
        if let Some(p) = self.parent {
            out.extend(p.names());
        }
        out
    }

    /// Evaluates an expression here.
    pub fn eval(&self, expr: &Expr) -> Result<f64, Fail> {
        eval_with(expr, &mut |name, span| match self.get(name) {
            Some(Some(v)) => Ok(v),
            Some(None) => Err(Fail::Reported),
            None => Err(unknown(name, span, self.names())),
        })
    }
}

fn unknown(name: &str, span: Span, names: Vec<&str>) -> Fail {
    Fail::Error(SpiceError::UnknownParam {
        span,
        name: name.to_string(),
        suggestion: suggest(name, names),
    })
}

#[derive(Clone, Copy, Debug)]
enum State {
    Busy,
    Done(Option<f64>),
}

impl State {
    fn done(self) -> Option<f64> {
        match self {
            State::Done(v) => v,
            State::Busy => None,
        }
    }
}

struct Builder<'p, 'e, 'n> {
    parent: Option<&'p Scope<'p>>,
    defs: FxHashMap<&'n str, Def<'e>>,
    values: FxHashMap<String, State>,
    stack: Vec<String>,
    errors: Vec<SpiceError>,
}

impl Builder<'_, '_, '_> {
    /// The value of `name` (defined here), computing it if needed; `used` is the reference
    /// that asks (for the cycle diagnostic).
    fn resolve(&mut self, name: &str, used: Option<Span>) -> Result<f64, Fail> {
        match self.values.get(name) {
            Some(State::Done(Some(v))) => return Ok(*v),
            Some(State::Done(None)) => return Err(Fail::Reported),
            Some(State::Busy) => {
                let from = self.stack.iter().position(|n| n == name).unwrap_or(0);
                let mut chain: Vec<&str> = self.stack[from..].iter().map(String::as_str).collect();
                chain.push(name);
                let span = used.unwrap_or_default();
                return Err(Fail::Error(SpiceError::ParamCycle {
                    span,
                    name: name.to_string(),
                    cycle: chain.join(" -> "),
                }));
            }
            None => {}
        }
        let Some(def) = self.defs.get(name).copied() else {
            return Err(Fail::Reported);
        };
        let result = match def {
            Def::Value(v, _) => v.ok_or(Fail::Reported),
            Def::Expr(expr) => {
                self.values.insert(name.to_string(), State::Busy);
                self.stack.push(name.to_string());
                let r = eval_with(expr, &mut |n, span| self.lookup(n, span));
                self.stack.pop();
                r
            }
        };
        let value = match result {
            Ok(v) => Some(v),
            Err(Fail::Error(e)) => {
                // A cycle is reported once, at the reference that closes it; the other
                // members of the cycle fail silently.
                if matches!(&e, SpiceError::ParamCycle { name: n, .. } if n != name) {
                    self.values.insert(name.to_string(), State::Done(None));
                    return Err(Fail::Error(e));
                }
                self.errors.push(e);
                None
            }
            Err(Fail::Reported) => None,
        };
        self.values.insert(name.to_string(), State::Done(value));
        value.ok_or(Fail::Reported)
    }

    fn lookup(&mut self, name: &str, span: Span) -> Result<f64, Fail> {
        if self.defs.contains_key(name) {
            return self.resolve(name, Some(span));
        }
        match self.parent.and_then(|p| p.get(name)) {
            Some(Some(v)) => Ok(v),
            Some(None) => Err(Fail::Reported),
            None => {
                let mut names: Vec<&str> = self.defs.keys().copied().collect();
                if let Some(p) = self.parent {
                    names.extend(p.names());
                }
                Err(unknown(name, span, names))
            }
        }
    }
}

/// Evaluates `expr`, asking `lookup` for parameters (the constant `pi` when it has none).
pub fn eval_with(
    expr: &Expr,
    lookup: &mut dyn FnMut(&str, Span) -> Result<f64, Fail>,
) -> Result<f64, Fail> {
    let v = match &expr.kind {
        ExprKind::Num(v) => *v,
        ExprKind::Param(name) => match lookup(name, expr.span) {
            Err(Fail::Error(SpiceError::UnknownParam { .. })) if name == "pi" => PI,
            r => r?,
        },
        ExprKind::Unary(op, a) => {
            let a = eval_with(a, lookup)?;
            match op {
                UnOp::Neg => -a,
                UnOp::Plus => a,
                UnOp::Not => truth(a == 0.0),
            }
        }
        ExprKind::Binary(op, a, b) => {
            let x = eval_with(a, lookup)?;
            // `&&` and `||` need their right side only when the left does not decide.
            match op {
                BinOp::And if x == 0.0 => return Ok(0.0),
                BinOp::Or if x != 0.0 => return Ok(1.0),
                _ => {}
            }
            let y = eval_with(b, lookup)?;
            match op {
                BinOp::Add => x + y,
                BinOp::Sub => x - y,
                BinOp::Mul => x * y,
                BinOp::Div | BinOp::Rem if y == 0.0 => {
                    return Err(SpiceError::DivisionByZero { span: b.span }.into());
                }
                BinOp::Div => x / y,
                BinOp::Rem => x % y,
                BinOp::Pow => x.powf(y),
                BinOp::Eq => truth(x == y),
                BinOp::Ne => truth(x != y),
                BinOp::Lt => truth(x < y),
                BinOp::Gt => truth(x > y),
                BinOp::Le => truth(x <= y),
                BinOp::Ge => truth(x >= y),
                BinOp::And | BinOp::Or => truth(y != 0.0),
            }
        }
        ExprKind::Ternary(c, a, b) => {
            if eval_with(c, lookup)? != 0.0 {
                eval_with(a, lookup)?
            } else {
                eval_with(b, lookup)?
            }
        }
        ExprKind::Call(Func::If, args) => {
            // The parser checked the arity: three arguments.
            let [c, a, b] = args.as_slice() else {
                return Err(Fail::Reported);
            };
            if eval_with(c, lookup)? != 0.0 {
                eval_with(a, lookup)?
            } else {
                eval_with(b, lookup)?
            }
        }
        ExprKind::Call(f, args) => {
            let mut xs = Vec::with_capacity(args.len());
            for a in args {
                xs.push(eval_with(a, lookup)?);
            }
            call(*f, &xs)
        }
    };
    if v.is_finite() {
        Ok(v)
    } else {
        let what = if v.is_nan() {
            "NaN (not a number)"
        } else if v > 0.0 {
            "infinity"
        } else {
            "minus infinity"
        };
        Err(SpiceError::NotFinite {
            span: expr.span,
            what,
        }
        .into())
    }
}

fn truth(b: bool) -> f64 {
    if b { 1.0 } else { 0.0 }
}

/// A function of already evaluated arguments (arity checked by the parser).
fn call(f: Func, xs: &[f64]) -> f64 {
    let x = xs.first().copied().unwrap_or(f64::NAN);
    let y = xs.get(1).copied().unwrap_or(f64::NAN);
    match f {
        Func::Abs => x.abs(),
        Func::Sqrt => x.sqrt(),
        Func::Exp => x.exp(),
        Func::Ln => x.ln(),
        Func::Log10 => x.log10(),
        Func::Sin => x.sin(),
        Func::Cos => x.cos(),
        Func::Tan => x.tan(),
        Func::Asin => x.asin(),
        Func::Acos => x.acos(),
        Func::Atan => x.atan(),
        Func::Sinh => x.sinh(),
        Func::Cosh => x.cosh(),
        Func::Tanh => x.tanh(),
        Func::Min => xs.iter().copied().fold(f64::INFINITY, f64::min),
        Func::Max => xs.iter().copied().fold(f64::NEG_INFINITY, f64::max),
        Func::Pow => x.powf(y),
        Func::Pwr => x.abs().powf(y),
        Func::Int => x.trunc(),
        Func::Floor => x.floor(),
        Func::Ceil => x.ceil(),
        Func::Nint => x.round_ties_even(),
        Func::Sgn => {
            if x > 0.0 {
                1.0
            } else if x < 0.0 {
                -1.0
            } else {
                0.0
            }
        }
        // Handled before the arguments are evaluated.
        Func::If => f64::NAN,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::expr::parse_text;
    use vams_syntax::source::FileId;

    fn expr(text: &str) -> Expr {
        match parse_text(text, 0, FileId(0), Span::new(FileId(0), 0, text.len())) {
            Ok(e) => e,
            Err(e) => panic!("`{text}`: {e}"),
        }
    }

    fn value(text: &str) -> Result<f64, Fail> {
        let a = expr("2");
        let (scope, errors) = Scope::new(None, &[("a".into(), Def::Expr(&a))]);
        assert!(errors.is_empty());
        scope.eval(&expr(text))
    }

    fn v(text: &str) -> f64 {
        match value(text) {
            Ok(v) => v,
            Err(e) => panic!("`{text}`: {e:?}"),
        }
    }

    /// The values ngspice 39 prints for these `.param` expressions (see the module doc).
    #[test]
    fn values_match_ngspice() {
        let cases = [
            ("a**3", 8.0),
            ("a^2", 4.0),
            ("log10(100)", 2.0),
            ("1 > 2 ? 5 : 7", 7.0),
            ("pwr(-2,3)", 8.0),
            ("pow(-2,3)", -8.0),
            ("int(-2.7)", -2.0),
            ("-2^2", -4.0),
            ("2^3^2", 64.0),
            ("2**3**2", 64.0),
            ("-a**2", -4.0),
            ("2^-1", 0.5),
            ("min(3,1,2)", 1.0),
            ("a&&0", 0.0),
            ("10%3", 1.0),
            ("floor(-2.5)", -3.0),
            ("ceil(2.1)", 3.0),
            ("2*-3", -6.0),
            ("!0", 1.0),
            ("1k*2", 2000.0),
            ("sgn(-3)", -1.0),
            ("nint(2.5)", 2.0),
            ("a == 2", 1.0),
            ("5 != 4", 1.0),
            ("0 ? 1 : 0 ? 2 : 3", 3.0),
            ("1 ? 2 : 3 + 10", 2.0),
            ("3-2-1", 0.0),
            ("8/2/2", 2.0),
            ("2*3^2", 18.0),
            ("if(a == 2, 11, 12)", 11.0),
            ("max(1, a)", 2.0),
            (".5k", 500.0),
        ];
        for (text, want) in cases {
            assert_eq!(v(text), want, "{text}");
        }
        assert!((v("log(10)") - 10f64.ln()).abs() < 1e-15);
        assert!((v("atan(1)*4") - PI).abs() < 1e-15);
        assert_eq!(v("pi"), PI);
    }

    #[test]
    fn no_nan_or_infinity_escapes() {
        assert!(matches!(
            value("1/(a-2)"),
            Err(Fail::Error(SpiceError::DivisionByZero { span })) if span.start == 2
        ));
        assert!(matches!(
            value("5%0"),
            Err(Fail::Error(SpiceError::DivisionByZero { .. }))
        ));
        for text in [
            "sqrt(-1)",
            "pow(-2, 0.5)",
            "exp(1000)",
            "log(0)",
            "1e308*10",
        ] {
            assert!(
                matches!(value(text), Err(Fail::Error(SpiceError::NotFinite { .. }))),
                "{text}"
            );
        }
        // The right side of a deciding `&&` / `||` is not evaluated.
        assert_eq!(v("0 && 1/0"), 0.0);
        assert_eq!(v("1 || 1/0"), 1.0);
    }

    #[test]
    fn unknown_parameters_suggest_a_name() {
        match value("aa + 1") {
            Err(Fail::Error(SpiceError::UnknownParam {
                name, suggestion, ..
            })) => {
                assert_eq!(name, "aa");
                assert_eq!(suggestion.as_deref(), Some("a"));
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn definitions_in_any_order_and_chains() {
        let (x, y, z) = (expr("y*2"), expr("3"), expr("x+w"));
        let (global, errors) = Scope::new(
            None,
            &[("x".into(), Def::Expr(&x)), ("y".into(), Def::Expr(&y))],
        );
        assert!(errors.is_empty());
        assert_eq!(global.get("x"), Some(Some(6.0)));
        let (inst, errors) = Scope::new(
            Some(&global),
            &[
                ("z".into(), Def::Expr(&z)),
                ("w".into(), Def::Value(Some(10.0), Span::default())),
                ("y".into(), Def::Value(Some(100.0), Span::default())),
            ],
        );
        assert!(errors.is_empty());
        // `x` is the parent's (6), `y` is shadowed only here.
        assert_eq!(inst.get("z"), Some(Some(16.0)));
        assert_eq!(inst.get("y"), Some(Some(100.0)));
    }

    #[test]
    fn a_cycle_is_one_error_naming_it() {
        let (a, b, c, d) = (expr("b+1"), expr("c"), expr("a*2"), expr("a"));
        let (scope, errors) = Scope::new(
            None,
            &[
                ("a".into(), Def::Expr(&a)),
                ("b".into(), Def::Expr(&b)),
                ("c".into(), Def::Expr(&c)),
                ("d".into(), Def::Expr(&d)),
            ],
        );
        assert_eq!(errors.len(), 1, "{errors:?}");
        match &errors[0] {
            SpiceError::ParamCycle { name, cycle, .. } => {
                assert_eq!(name, "a");
                assert_eq!(cycle, "a -> b -> c -> a");
            }
            other => panic!("{other:?}"),
        }
        assert_eq!(scope.get("d"), Some(None));
        assert_eq!(scope.eval(&expr("d+1")), Err(Fail::Reported));
        let selfref = expr("s+1");
        let (_, errors) = Scope::new(None, &[("s".into(), Def::Expr(&selfref))]);
        assert!(matches!(&errors[..], [SpiceError::ParamCycle { cycle, .. }] if cycle == "s -> s"));
    }
}
