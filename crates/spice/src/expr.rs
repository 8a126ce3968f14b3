//! Expressions: the AST and its parser.
//!
//! Takes expression tokens (from a `{...}` brace, a `'...'` quote, a bare `.param` value or a
//! single value field); gives an [`Expr`] tree whose every node keeps its span, or the first
//! syntax error. Never evaluates (that is `eval`'s) and never recurses deeper than
//! [`MAX_DEPTH`].
//!
//! The grammar and precedence are ngspice's `.param` (numparam) ones, checked against
//! ngspice 39, lowest first: `c ? a : b` (right-associative), `||`, `&&`, `==` `!=`,
//! `<` `>` `<=` `>=`, binary `+` `-`, `*` `/` `%`, unary `-` `+` `!`, then `^` (also `**`),
//! which is *left*-associative as in ngspice (`2^3^2` is 64) and binds tighter than unary
//! minus (`-2^2` is -4) while taking a signed exponent (`2^-1` is 0.5). Numbers take SPICE
//! scale factors (`1k*2`). Functions: see [`Func`]. `if(c, a, b)` is the function form of
//! the ternary; `pi` is a constant unless a parameter of that name is in scope.

use vams_syntax::source::{FileId, Span};

use crate::error::SpiceError;
use crate::lexer::{ETok, ExprToken, TokKind, Token, lex_expr};
use crate::number::{BadNumber, parse_number};
use crate::suggest::suggest;

/// Deepest nesting of parentheses, operators and calls accepted.
pub const MAX_DEPTH: usize = 100;

/// An expression with its span.
#[derive(Clone, Debug, PartialEq)]
pub struct Expr {
    pub kind: ExprKind,
    pub span: Span,
}

#[derive(Clone, Debug, PartialEq)]
pub enum ExprKind {
    Num(f64),
    /// A parameter (or the constant `pi`), by its lower-case name.
    Param(String),
    Unary(UnOp, Box<Expr>),
    Binary(BinOp, Box<Expr>, Box<Expr>),
    /// `c ? a : b`
    Ternary(Box<Expr>, Box<Expr>, Box<Expr>),
    Call(Func, Vec<Expr>),
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum UnOp {
    Neg,
    Plus,
    Not,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BinOp {
    Add,
    Sub,
    Mul,
    Div,
    Rem,
    Pow,
    Eq,
    Ne,
    Lt,
    Gt,
    Le,
    Ge,
    And,
    Or,
}

/// The functions an expression may call.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Func {
    Abs,
    Sqrt,
    Exp,
    /// `ln` and `log`: natural logarithm (ngspice's `log` is natural too).
    Ln,
    Log10,
    Sin,
    Cos,
    Tan,
    Asin,
    Acos,
    Atan,
    Sinh,
    Cosh,
    Tanh,
    /// `min(a, b, ...)`, two or more arguments.
    Min,
    Max,
    /// `pow(x, y)`: x^y, NaN (an error) for a negative x and a fractional y.
    Pow,
    /// `pwr(x, y)`: |x|^y, as ngspice's `.param` computes it.
    Pwr,
    /// `int(x)`: towards zero.
    Int,
    Floor,
    Ceil,
    /// `nint(x)`: to the nearest integer, ties to even (C's `rint`, as ngspice).
    Nint,
    Sgn,
    /// `if(c, a, b)`: `a` when `c` is non-zero, else `b`.
    If,
}

impl Func {
    const TABLE: [(&'static str, Func); 26] = [
        ("abs", Func::Abs),
        ("sqrt", Func::Sqrt),
        ("exp", Func::Exp),
        ("ln", Func::Ln),
        ("log", Func::Ln),
        ("log10", Func::Log10),
        ("sin", Func::Sin),
        ("cos", Func::Cos),
        ("tan", Func::Tan),
        ("asin", Func::Asin),
        ("acos", Func::Acos),
        ("atan", Func::Atan),
        ("sinh", Func::Sinh),
        ("cosh", Func::Cosh),
        ("tanh", Func::Tanh),
        ("min", Func::Min),
        ("max", Func::Max),
        ("pow", Func::Pow),
        ("pwr", Func::Pwr),
        ("int", Func::Int),
        ("floor", Func::Floor),
        ("ceil", Func::Ceil),
        ("nint", Func::Nint),
        ("sgn", Func::Sgn),
        ("if", Func::If),
        ("sign", Func::Sgn),
    ];

    const KNOWN: &'static str = "abs sqrt exp ln log log10 sin cos tan asin acos atan sinh \
                                 cosh tanh min max pow pwr int floor ceil nint sgn if";

    pub fn from_name(name: &str) -> Option<Func> {
        Func::TABLE
            .iter()
            .find(|(n, _)| *n == name)
            .map(|(_, f)| *f)
    }

    /// The arity range and the usage line for an error.
    fn arity(self) -> (usize, usize, &'static str) {
        match self {
            Func::Min => (2, usize::MAX, "min(a, b, ...)"),
            Func::Max => (2, usize::MAX, "max(a, b, ...)"),
            Func::Pow => (2, 2, "pow(x, y)"),
            Func::Pwr => (2, 2, "pwr(x, y)"),
            Func::If => (3, 3, "if(condition, then, else)"),
            _ => (1, 1, "f(x)"),
        }
    }
}

impl Expr {
    pub fn num(value: f64, span: Span) -> Expr {
        Expr {
            kind: ExprKind::Num(value),
            span,
        }
    }

    /// The number, when the expression is a plain one.
    pub fn as_num(&self) -> Option<f64> {
        match self.kind {
            ExprKind::Num(v) => Some(v),
            _ => None,
        }
    }
}

/// Parses the text of an expression that starts at byte `base` of `file`.
pub fn parse_text(text: &str, base: usize, file: FileId, whole: Span) -> Result<Expr, SpiceError> {
    let toks = lex_expr(text, base, file)?;
    parse_tokens(&toks, whole)
}

/// Parses a run of card-level tokens as one expression: a bare `.param` value (`2*a + 1`,
/// `max(a, b)`), or one brace, quote or word.
pub fn parse_card_tokens(tokens: &[Token]) -> Result<Expr, SpiceError> {
    let Some(whole) = tokens
        .first()
        .map(|t| t.span.to(tokens[tokens.len() - 1].span))
    else {
        return Err(SpiceError::syntax(
            Span::default(),
            "an empty expression",
            "here",
            "",
        ));
    };
    let mut toks = Vec::new();
    for t in tokens {
        let single = |kind| ExprToken {
            kind,
            text: t.text.clone(),
            span: t.span,
        };
        match t.kind {
            TokKind::Word | TokKind::Brace | TokKind::Quote => {
                let (text, base) = t.inner();
                if t.kind != TokKind::Word {
                    if text.trim().is_empty() {
                        return Err(SpiceError::syntax(
                            t.span,
                            "an empty expression",
                            "nothing inside",
                            "write a value or an expression between the delimiters",
                        ));
                    }
                    // A nested brace or quote is a parenthesised sub-expression.
                    let inner = lex_expr(text, base, t.span.file)?;
                    if tokens.len() > 1 {
                        toks.push(ExprToken {
                            kind: ETok::LParen,
                            text: "(".into(),
                            span: t.span,
                        });
                        toks.extend(inner);
                        toks.push(ExprToken {
                            kind: ETok::RParen,
                            text: ")".into(),
                            span: t.span,
                        });
                    } else {
                        toks.extend(inner);
                    }
                } else {
                    toks.extend(lex_expr(text, base, t.span.file)?);
                }
            }
            TokKind::LParen => toks.push(single(ETok::LParen)),
            TokKind::RParen => toks.push(single(ETok::RParen)),
            TokKind::Comma => toks.push(single(ETok::Comma)),
            TokKind::Eq | TokKind::Str => {
                return Err(SpiceError::syntax(
                    t.span,
                    format!("unexpected `{}` in an expression", t.text),
                    "not part of an expression",
                    "put a comparison in braces, `{a == b}`",
                ));
            }
        }
    }
    parse_tokens(&toks, whole)
}

/// Parses expression tokens; `whole` is the span to blame when they are empty or end early.
pub fn parse_tokens(toks: &[ExprToken], whole: Span) -> Result<Expr, SpiceError> {
    let mut p = Parser {
        toks,
        pos: 0,
        depth: 0,
        whole,
    };
    let e = p.ternary()?;
    match p.toks.get(p.pos) {
        None => Ok(e),
        Some(t) => Err(SpiceError::syntax(
            t.span,
            format!("unexpected `{}` after the end of the expression", t.text),
            "the expression ends before this",
            "join the parts with an operator, or put the expression in braces",
        )),
    }
}

struct Parser<'t> {
    toks: &'t [ExprToken],
    pos: usize,
    depth: usize,
    whole: Span,
}

impl Parser<'_> {
    fn peek(&self) -> Option<ETok> {
        self.toks.get(self.pos).map(|t| t.kind)
    }

    fn eat(&mut self, kind: ETok) -> Option<&ExprToken> {
        match self.toks.get(self.pos) {
            Some(t) if t.kind == kind => {
                self.pos += 1;
                Some(t)
            }
            _ => None,
        }
    }

    /// The span after which something is missing.
    fn here(&self) -> Span {
        match self.toks.get(self.pos).or_else(|| self.toks.last()) {
            Some(t) => t.span,
            None => self.whole,
        }
    }

    fn missing(&self, what: &str) -> SpiceError {
        let (message, label) = match self.toks.get(self.pos) {
            Some(t) => (
                format!("expected {what}, found `{}`", t.text),
                format!("expected {what}"),
            ),
            None => (
                format!("expected {what}, found the end of the expression"),
                format!("expected {what} after this"),
            ),
        };
        SpiceError::syntax(
            self.here(),
            message,
            label,
            "complete the expression; see the ngspice manual's `.param` section for the syntax",
        )
    }

    fn enter(&mut self) -> Result<(), SpiceError> {
        self.depth += 1;
        if self.depth > MAX_DEPTH {
            return Err(SpiceError::TooDeep {
                span: self.here(),
                limit: MAX_DEPTH,
            });
        }
        Ok(())
    }

    fn ternary(&mut self) -> Result<Expr, SpiceError> {
        let c = self.binary(0)?;
        if self.eat(ETok::Question).is_none() {
            return Ok(c);
        }
        self.enter()?;
        let a = self.ternary()?;
        if self.eat(ETok::Colon).is_none() {
            return Err(self.missing("`:`"));
        }
        let b = self.ternary()?;
        self.depth -= 1;
        let span = c.span.to(b.span);
        Ok(Expr {
            kind: ExprKind::Ternary(Box::new(c), Box::new(a), Box::new(b)),
            span,
        })
    }

    /// The binary operator next, with its precedence (0 is `||`, 5 is `*`).
    fn binary_op(&self) -> Option<(BinOp, u8)> {
        Some(match self.peek()? {
            ETok::OrOr => (BinOp::Or, 0),
            ETok::AndAnd => (BinOp::And, 1),
            ETok::EqEq => (BinOp::Eq, 2),
            ETok::Ne => (BinOp::Ne, 2),
            ETok::Lt => (BinOp::Lt, 3),
            ETok::Gt => (BinOp::Gt, 3),
            ETok::Le => (BinOp::Le, 3),
            ETok::Ge => (BinOp::Ge, 3),
            ETok::Plus => (BinOp::Add, 4),
            ETok::Minus => (BinOp::Sub, 4),
            ETok::Star => (BinOp::Mul, 5),
            ETok::Slash => (BinOp::Div, 5),
            ETok::Percent => (BinOp::Rem, 5),
            _ => return None,
        })
    }

    /// Binary operators of precedence `min` and above, left-associative (precedence
    /// climbing: the recursion is at most as deep as there are precedence levels).
    fn binary(&mut self, min: u8) -> Result<Expr, SpiceError> {
        let mut lhs = self.unary()?;
        while let Some((op, prec)) = self.binary_op().filter(|(_, p)| *p >= min) {
            self.pos += 1;
            let rhs = self.binary(prec + 1)?;
            let span = lhs.span.to(rhs.span);
            lhs = Expr {
                kind: ExprKind::Binary(op, Box::new(lhs), Box::new(rhs)),
                span,
            };
        }
        Ok(lhs)
    }

    fn unary(&mut self) -> Result<Expr, SpiceError> {
        let op = match self.peek() {
            Some(ETok::Minus) => UnOp::Neg,
            Some(ETok::Plus) => UnOp::Plus,
            Some(ETok::Not) => UnOp::Not,
            _ => return self.power(),
        };
        let start = self.toks[self.pos].span;
        self.pos += 1;
        self.enter()?;
        let operand = self.unary()?;
        self.depth -= 1;
        let span = start.to(operand.span);
        Ok(Expr {
            kind: ExprKind::Unary(op, Box::new(operand)),
            span,
        })
    }

    /// `a ^ b ^ c`, left-associative; each exponent may be signed.
    fn power(&mut self) -> Result<Expr, SpiceError> {
        let mut lhs = self.primary()?;
        while self.eat(ETok::Pow).is_some() {
            self.enter()?;
            let rhs = self.unary_operand()?;
            self.depth -= 1;
            let span = lhs.span.to(rhs.span);
            lhs = Expr {
                kind: ExprKind::Binary(BinOp::Pow, Box::new(lhs), Box::new(rhs)),
                span,
            };
        }
        Ok(lhs)
    }

    /// An exponent: a primary with optional signs, binding no further powers.
    fn unary_operand(&mut self) -> Result<Expr, SpiceError> {
        let op = match self.peek() {
            Some(ETok::Minus) => UnOp::Neg,
            Some(ETok::Plus) => UnOp::Plus,
            Some(ETok::Not) => UnOp::Not,
            _ => return self.primary(),
        };
        let start = self.toks[self.pos].span;
        self.pos += 1;
        self.enter()?;
        let operand = self.unary_operand()?;
        self.depth -= 1;
        let span = start.to(operand.span);
        Ok(Expr {
            kind: ExprKind::Unary(op, Box::new(operand)),
            span,
        })
    }

    fn primary(&mut self) -> Result<Expr, SpiceError> {
        let Some(t) = self.toks.get(self.pos) else {
            return Err(self.missing("a value"));
        };
        let t = t.clone();
        match t.kind {
            ETok::Number => {
                self.pos += 1;
                match parse_number(&t.text) {
                    Ok(v) => Ok(Expr::num(v, t.span)),
                    Err(e) => Err(bad_number(&t.text, t.span, e)),
                }
            }
            ETok::Ident => {
                self.pos += 1;
                let name = t.text.to_ascii_lowercase();
                if self.peek() != Some(ETok::LParen) {
                    return Ok(Expr {
                        kind: ExprKind::Param(name),
                        span: t.span,
                    });
                }
                let Some(func) = Func::from_name(&name) else {
                    return Err(SpiceError::UnknownFunction {
                        span: t.span,
                        suggestion: suggest(&name, Func::TABLE.iter().map(|(n, _)| *n)),
                        name: t.text.clone(),
                        known: Func::KNOWN,
                    });
                };
                self.pos += 1;
                self.enter()?;
                let mut args = Vec::new();
                if self.eat(ETok::RParen).is_none() {
                    loop {
                        args.push(self.ternary()?);
                        if self.eat(ETok::Comma).is_some() {
                            continue;
                        }
                        if self.eat(ETok::RParen).is_some() {
                            break;
                        }
                        return Err(self.missing("`,` or `)`"));
                    }
                }
                self.depth -= 1;
                let close = self.toks[self.pos - 1].span;
                let span = t.span.to(close);
                let (lo, hi, usage) = func.arity();
                if args.len() < lo || args.len() > hi {
                    let expected = match (lo, hi) {
                        (1, 1) => "one argument".to_string(),
                        (a, b) if a == b => format!("{a} arguments"),
                        (a, _) => format!("{a} or more arguments"),
                    };
                    return Err(SpiceError::Arity {
                        span,
                        name: name.clone(),
                        expected,
                        found: args.len(),
                        usage,
                    });
                }
                Ok(Expr {
                    kind: ExprKind::Call(func, args),
                    span,
                })
            }
            ETok::LParen => {
                self.pos += 1;
                self.enter()?;
                let inner = self.ternary()?;
                self.depth -= 1;
                let Some(close) = self.eat(ETok::RParen).map(|t| t.span) else {
                    return Err(self.missing("`)`"));
                };
                Ok(Expr {
                    kind: inner.kind,
                    span: t.span.to(close),
                })
            }
            _ => Err(self.missing("a value")),
        }
    }
}

/// The diagnostic for a token that should be a number.
pub fn bad_number(text: &str, span: Span, e: BadNumber) -> SpiceError {
    let (reason, extra) = match e {
        BadNumber::NotANumber => (
            "not a SPICE number",
            if text.bytes().any(|b| b.is_ascii_alphabetic()) {
                "; a scale factor goes after the digits (`1.5k`, not `1k5`)"
            } else {
                ""
            },
        ),
        BadNumber::OutOfRange => ("too large for a 64-bit float", ""),
    };
    SpiceError::BadNumber {
        span,
        text: text.to_string(),
        reason,
        extra,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn parse(text: &str) -> Result<Expr, SpiceError> {
        parse_text(text, 0, FileId(0), Span::new(FileId(0), 0, text.len()))
    }

    /// A compact rendering of the tree, to check the shape.
    fn show(e: &Expr) -> String {
        match &e.kind {
            ExprKind::Num(v) => format!("{v}"),
            ExprKind::Param(n) => n.clone(),
            ExprKind::Unary(op, a) => format!("({op:?} {})", show(a)),
            ExprKind::Binary(op, a, b) => format!("({op:?} {} {})", show(a), show(b)),
            ExprKind::Ternary(c, a, b) => format!("(? {} {} {})", show(c), show(a), show(b)),
            ExprKind::Call(f, args) => {
                let a: Vec<String> = args.iter().map(show).collect();
                format!("({f:?} {})", a.join(" "))
            }
        }
    }

    fn tree(text: &str) -> String {
        match parse(text) {
            Ok(e) => show(&e),
            Err(e) => format!("error: {e}"),
        }
    }

    #[test]
    fn precedence_follows_ngspice() {
        assert_eq!(tree("1+2*3"), "(Add 1 (Mul 2 3))");
        assert_eq!(tree("-2^2"), "(Neg (Pow 2 2))");
        assert_eq!(tree("2^3^2"), "(Pow (Pow 2 3) 2)");
        assert_eq!(tree("2**-1"), "(Pow 2 (Neg 1))");
        assert_eq!(tree("a > 1 ? b : c ? 2 : 3"), "(? (Gt a 1) b (? c 2 3))");
        assert_eq!(tree("1 < 2 == 1"), "(Eq (Lt 1 2) 1)");
        assert_eq!(tree("a || b && c"), "(Or a (And b c))");
        assert_eq!(tree("8/2/2"), "(Div (Div 8 2) 2)");
        assert_eq!(tree("1k*2"), "(Mul 1000 2)");
        assert_eq!(tree("max(A, 2, -B)"), "(Max a 2 (Neg b))");
        assert_eq!(tree("if(x, 1, 2)"), "(If x 1 2)");
    }

    #[test]
    fn errors_are_located() {
        assert!(tree("sqr(2)").contains("unknown function `sqr`"));
        assert!(tree("pow(2)").contains("`pow` takes 2 arguments, not 1"));
        assert!(tree("1 +").contains("expected a value"));
        assert!(tree("(1").contains("expected `)`"));
        assert!(tree("1 2").contains("unexpected `2`"));
        assert!(tree("").contains("expected a value"));
        match parse("sqr(2)") {
            Err(SpiceError::UnknownFunction {
                suggestion, span, ..
            }) => {
                assert_eq!(suggestion.as_deref(), Some("sqrt"));
                assert_eq!((span.start, span.end), (0, 3));
            }
            other => panic!("{other:?}"),
        }
    }

    #[test]
    fn deep_nesting_is_an_error_not_a_crash() {
        let deep = format!("{}1{}", "(".repeat(5000), ")".repeat(5000));
        assert!(matches!(parse(&deep), Err(SpiceError::TooDeep { .. })));
        let minus = format!("{}1", "-".repeat(5000));
        assert!(matches!(parse(&minus), Err(SpiceError::TooDeep { .. })));
        let pow = format!("2{}", "^-".repeat(5000));
        assert!(parse(&pow).is_err());
    }
}
