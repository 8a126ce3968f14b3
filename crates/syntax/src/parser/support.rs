//! Helpers the grammar's actions call: AST construction that needs more than one line, and the
//! checks (closing labels, association forms) that become recovered syntax errors.

use lalrpop_util::{ErrorRecovery, ParseError};

use crate::ast::*;
use crate::diagnostics::SyntaxError;
use crate::lexer::Tok;
use crate::source::Span;

pub type Errors<'a> = Vec<ErrorRecovery<usize, Tok<'a>, SyntaxError>>;

/// An element between parentheses before it is known to be an association, an aggregate
/// element or a parenthesised expression.
pub struct PElem {
    pub choices: Vec<Choice>,
    pub actual: Actual,
    pub span: Span,
}

fn report(errors: &mut Errors<'_>, error: SyntaxError) {
    errors.push(ErrorRecovery {
        error: ParseError::User { error },
        dropped_tokens: Vec::new(),
    });
}

/// Collapses the doubled quotes of a string literal and strips its delimiters.
pub fn string_value(raw: &str) -> String {
    raw[1..raw.len() - 1].replace("\"\"", "\"")
}

pub fn check_end(errors: &mut Errors<'_>, name: &Ident, end: Option<Ident>) {
    if let Some(end) = end
        && end.name != name.name
    {
        report(
            errors,
            SyntaxError::EndLabel {
                span: end.span,
                found: end.name,
                expected: name.name.clone(),
            },
        );
    }
}

pub fn check_end_designator(errors: &mut Errors<'_>, name: &Designator, end: Option<Designator>) {
    match (name, end) {
        (Designator::Ident(name), Some(Designator::Ident(end))) => {
            check_end(errors, name, Some(end))
        }
        (Designator::Operator(name, _), Some(Designator::Operator(end, span))) if *name != end => {
            report(
                errors,
                SyntaxError::EndLabel {
                    span,
                    found: format!("\"{end}\""),
                    expected: format!("\"{name}\""),
                },
            )
        }
        _ => {}
    }
}

fn check_label(errors: &mut Errors<'_>, label: &Option<Ident>, end: Option<Ident>) {
    match (label, end) {
        (Some(label), end) => check_end(errors, label, end),
        (None, Some(end)) => report(
            errors,
            SyntaxError::EndLabel {
                span: end.span,
                expected: String::new(),
                found: end.name,
            },
        ),
        (None, None) => {}
    }
}

pub fn conc_stmt(
    errors: &mut Errors<'_>,
    label: Option<Ident>,
    postponed: bool,
    (kind, end): (ConcKind, Option<Ident>),
    span: Span,
) -> ConcStmt {
    check_label(errors, &label, end);
    ConcStmt {
        label,
        postponed,
        kind,
        span,
    }
}

pub fn seq_stmt(
    errors: &mut Errors<'_>,
    label: Option<Ident>,
    (kind, end): (SeqKind, Option<Ident>),
    span: Span,
) -> SeqStmt {
    check_label(errors, &label, end);
    SeqStmt { label, kind, span }
}

pub fn binary(op: BinaryOp, a: Expr, b: Expr, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Binary(op, Box::new(a), Box::new(b)),
        span,
    }
}

pub fn unary(op: UnaryOp, a: Expr, span: Span) -> Expr {
    Expr {
        kind: ExprKind::Unary(op, Box::new(a)),
        span,
    }
}

/// `null` in a waveform disconnects the driver.
pub fn wave_value(e: Expr) -> Option<Expr> {
    match e.kind {
        ExprKind::Literal(Literal::Null) => None,
        _ => Some(e),
    }
}

/// `a'range`, `a'reverse_range`, or either with a dimension (`m'range(2)`): a range, though
/// it parses as a name.
fn is_range_attribute(e: &Expr) -> bool {
    match &e.kind {
        ExprKind::Attribute(_, attr) => attr.name == "range" || attr.name == "reverse_range",
        ExprKind::Apply(prefix, _) => {
            matches!(&prefix.kind, ExprKind::Attribute(..)) && is_range_attribute(prefix)
        }
        _ => false,
    }
}

/// A choice written as an expression: a range attribute (`v'range => '0'`) is a range.
pub fn choice(e: Expr) -> Choice {
    if is_range_attribute(&e) {
        Choice::Range(Range::Attribute(Box::new(e)))
    } else {
        Choice::Expr(e)
    }
}

/// A name in a discrete range is a range attribute (`a'range`) or a type mark (`natural`).
pub fn discrete_name(name: Expr) -> DiscreteRange {
    match is_range_attribute(&name) {
        true => DiscreteRange::Range(Range::Attribute(Box::new(name))),
        false => DiscreteRange::Subtype(SubtypeIndication {
            resolution: None,
            span: name.span,
            type_mark: name,
            range: None,
            tolerance: None,
        }),
    }
}

/// `entity work.e(arch)`: the architecture arrives parsed as an application of the name.
pub fn entity_unit(name: Expr) -> InstantiatedUnit {
    if let ExprKind::Apply(prefix, args) = &name.kind
        && let [
            Assoc {
                formal: None,
                actual:
                    Actual::Expr(Expr {
                        kind: ExprKind::Name(arch),
                        ..
                    }),
                ..
            },
        ] = args.as_slice()
    {
        return InstantiatedUnit::Entity {
            name: (**prefix).clone(),
            architecture: Some(arch.clone()),
        };
    }
    InstantiatedUnit::Entity {
        name,
        architecture: None,
    }
}

/// Elements of a call, index or map: at most one formal, which must be a name.
pub fn to_assocs(errors: &mut Errors<'_>, elems: Vec<PElem>) -> Vec<Assoc> {
    elems
        .into_iter()
        .map(|e| {
            let mut choices = e.choices.into_iter();
            let formal = match (choices.next(), choices.next()) {
                (None, _) => None,
                (Some(Choice::Expr(f)), None) => Some(f),
                (Some(first), _) => {
                    let span = match &first {
                        Choice::Expr(x) => x.span,
                        Choice::Range(Range::Explicit { span, .. }) => *span,
                        Choice::Range(Range::Attribute(x)) => x.span,
                        Choice::Others(s) => *s,
                    };
                    report(
                        errors,
                        SyntaxError::Unexpected {
                            span,
                            found: "a choice list in an association".into(),
                            expected: "a formal name".into(),
                            help: Some(
                                "in a call or map, `formal => actual` names one formal; \
                                 `|`, `others` and ranges belong in aggregates"
                                    .into(),
                            ),
                        },
                    );
                    None
                }
            };
            Assoc {
                formal,
                actual: e.actual,
                span: e.span,
            }
        })
        .collect()
}

/// `(e)` is a parenthesised expression; anything else between parentheses is an aggregate.
pub fn paren_or_aggregate(errors: &mut Errors<'_>, mut elems: Vec<PElem>, span: Span) -> Expr {
    if elems.len() == 1 && elems[0].choices.is_empty() {
        // The length was checked just above.
        let e = elems.pop().expect("one element");
        return match e.actual {
            Actual::Expr(x) => Expr {
                kind: ExprKind::Paren(Box::new(x)),
                span,
            },
            other => {
                not_an_expression(errors, &other);
                Expr {
                    kind: ExprKind::Aggregate(Vec::new()),
                    span,
                }
            }
        };
    }
    let mut out = Vec::with_capacity(elems.len());
    for e in elems {
        match e.actual {
            Actual::Expr(value) => out.push(ElementAssoc {
                choices: e.choices,
                value,
                span: e.span,
            }),
            other => not_an_expression(errors, &other),
        }
    }
    Expr {
        kind: ExprKind::Aggregate(out),
        span,
    }
}

fn not_an_expression(errors: &mut Errors<'_>, actual: &Actual) {
    let (span, what) = match actual {
        Actual::Range(Range::Explicit { span, .. }) => (*span, "a range"),
        Actual::Range(Range::Attribute(x)) => (x.span, "a range"),
        Actual::Open(span) => (*span, "`open`"),
        Actual::Expr(x) => (x.span, "an expression"),
    };
    report(
        errors,
        SyntaxError::Unexpected {
            span,
            found: what.into(),
            expected: "an expression".into(),
            help: Some("ranges and `open` are allowed only in names, calls and maps".into()),
        },
    );
}
