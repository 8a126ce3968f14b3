//! The text of `vams dae`: unknowns, then equations with their origin and formula.
//!
//! Formulas are the assembled residuals (constants folded, before source scaling) printed with
//! unknown and signal names and the fewest parentheses that keep VHDL's precedence.

use std::fmt::Write;

use super::AnalogSystem;
use super::build::{self, Origin};
use super::sym::{Bin, Sym, Un};
use crate::design::Design;
use crate::source::{SourceMap, Span};

/// Where a span is, as `file:line` (or `?` when the span is not in `sources`).
fn location(span: Span, sources: &SourceMap) -> String {
    if (span.file.0 as usize) < sources.len() {
        let (line, _) = sources.line_col(span);
        format!("{}:{}", sources.file(span.file).name, line)
    } else {
        "?".to_string()
    }
}

pub fn listing(sys: &AnalogSystem, design: &Design, sources: &SourceMap) -> String {
    let mut out = String::new();
    // `sys` was built from `design`, so assembling it again succeeds; the system keeps only
    // the reduced equations, and the listing shows the model's own.
    let Ok(asm) = build::assemble(design, &sys.implicit_flows) else {
        return out;
    };
    let names: Vec<String> = asm.unknowns.iter().map(|u| u.name(design)).collect();
    let n = names.len();
    let mut differential = vec![false; n];
    for r in &asm.residuals {
        r.visit(&mut |e| {
            if let Sym::Dot(j) = e {
                differential[*j] = true;
            }
        });
    }
    let width = names.iter().map(String::len).max().unwrap_or(0);
    // Writing into a String cannot fail.
    let _ = writeln!(out, "unknowns ({n}):");
    for (i, name) in names.iter().enumerate() {
        let kind = if differential[i] {
            "differential"
        } else {
            "algebraic"
        };
        let _ = writeln!(out, "  {i:>3}  {name:<width$}  {kind}");
    }
    let _ = writeln!(out, "equations ({}):", asm.residuals.len());
    let printer = Printer {
        names: &names,
        design,
    };
    let origins: Vec<String> = asm
        .origins
        .iter()
        .map(|origin| match *origin {
            Origin::User(k) => location(design.equations[k].span, sources),
            Origin::Delayed(k) => location(design.delays[k].span, sources),
            other => other.describe(design),
        })
        .collect();
    write_equations(&mut out, &printer, 0, origins.iter().zip(&asm.residuals));
    let names: &[String] = match &sys.index_reduced {
        Some(reduced) => {
            let _ = writeln!(
                out,
                "index reduction (the model has index {}): {} equation(s) added",
                reduced.index,
                reduced.equations.len()
            );
            let printer = Printer {
                names: &reduced.names,
                design,
            };
            let added = reduced.equations.iter().map(|(from, r)| (from, r));
            write_equations(&mut out, &printer, asm.residuals.len(), added);
            let _ = writeln!(
                out,
                "  dummy derivatives (algebraic unknowns): {}",
                reduced.dummies.join(", ")
            );
            let _ = writeln!(
                out,
                "  states: {} (chosen at the initial guesses; a run chooses again at its \
                 initial break values)",
                match reduced.states.is_empty() {
                    true => "none".to_string(),
                    false => reduced.states.join(", "),
                }
            );
            &reduced.names
        }
        None => &names,
    };
    let n = names.len();
    if sys.eliminated.is_empty() {
        return out;
    }
    let _ = writeln!(
        out,
        "solver unknowns ({} of {n}): {}",
        sys.names.len(),
        sys.names.join(", ")
    );
    let _ = writeln!(out, "eliminated ({}):", sys.eliminated.len());
    let printer = Printer {
        names: &sys.names,
        design,
    };
    let width = sys
        .eliminated
        .iter()
        .map(|e| names[e.unknown].len())
        .max()
        .unwrap_or(0);
    for e in &sys.eliminated {
        let mut formula = String::new();
        printer.print(&e.replacement, 0, &mut formula);
        let name = &names[e.unknown];
        let _ = writeln!(
            out,
            "  {:>3}  {name:<width$} = {formula}   (equation {})",
            e.unknown, e.solved_from
        );
    }
    out
}

/// One line per equation, numbered from `first`: number, origin (padded to the widest) and
/// formula.
fn write_equations<'e>(
    out: &mut String,
    printer: &Printer,
    first: usize,
    equations: impl Iterator<Item = (&'e String, &'e Sym)> + Clone,
) {
    let width = equations
        .clone()
        .map(|(from, _)| from.len())
        .max()
        .unwrap_or(0);
    for (i, (from, r)) in equations.enumerate() {
        let mut formula = String::new();
        printer.print(r, 0, &mut formula);
        let i = i + first;
        // Writing into a String cannot fail.
        let _ = writeln!(out, "  {i:>3}  {from:<width$}  {formula} = 0");
    }
}

struct Printer<'a> {
    names: &'a [String],
    design: &'a Design,
}

/// Binding strength: higher binds tighter.
fn precedence(e: &Sym) -> u8 {
    match e {
        Sym::Bin(op, ..) => match op {
            Bin::And | Bin::Or | Bin::Nand | Bin::Nor | Bin::Xor | Bin::Xnor => 1,
            Bin::Eq | Bin::Ne | Bin::Lt | Bin::Le | Bin::Gt | Bin::Ge => 2,
            Bin::Add | Bin::Sub => 3,
            Bin::Mul | Bin::Div | Bin::Mod | Bin::Rem => 4,
            Bin::Pow => 6,
            Bin::Atan2 | Bin::Max | Bin::Min => 7,
        },
        Sym::Un(Un::Neg, _) => 3,
        Sym::Un(Un::Not, _) => 6,
        Sym::Const(v) if *v < 0.0 => 3,
        Sym::If(..) => 0,
        _ => 7,
    }
}

fn number(v: f64) -> String {
    let a = v.abs();
    if v == v.trunc() && a < 1e6 {
        format!("{v:.1}")
    } else if (1e-3..1e6).contains(&a) {
        format!("{v}")
    } else {
        format!("{v:e}")
    }
}

fn un_name(op: Un) -> &'static str {
    match op {
        Un::Neg => "-",
        Un::Not => "not ",
        Un::Abs => "abs",
        Un::Exp => "exp",
        Un::Log => "log",
        Un::Log10 => "log10",
        Un::Sqrt => "sqrt",
        Un::Sin => "sin",
        Un::Cos => "cos",
        Un::Tan => "tan",
        Un::Asin => "arcsin",
        Un::Acos => "arccos",
        Un::Atan => "arctan",
        Un::Sinh => "sinh",
        Un::Cosh => "cosh",
        Un::Tanh => "tanh",
        Un::Asinh => "arcsinh",
        Un::Acosh => "arccosh",
        Un::Atanh => "arctanh",
        Un::Floor => "floor",
        Un::Ceil => "ceil",
        Un::Round => "round",
        Un::Trunc => "trunc",
        Un::Sign => "sign",
    }
}

fn bin_name(op: Bin) -> &'static str {
    match op {
        Bin::Add => " + ",
        Bin::Sub => " - ",
        Bin::Mul => " * ",
        Bin::Div => " / ",
        Bin::Pow => " ** ",
        Bin::Mod => " mod ",
        Bin::Rem => " rem ",
        Bin::Atan2 => "arctan",
        Bin::Max => "realmax",
        Bin::Min => "realmin",
        Bin::Eq => " = ",
        Bin::Ne => " /= ",
        Bin::Lt => " < ",
        Bin::Le => " <= ",
        Bin::Gt => " > ",
        Bin::Ge => " >= ",
        Bin::And => " and ",
        Bin::Or => " or ",
        Bin::Nand => " nand ",
        Bin::Nor => " nor ",
        Bin::Xor => " xor ",
        Bin::Xnor => " xnor ",
    }
}

impl Printer<'_> {
    /// Prints `e`, parenthesised when it binds less tightly than `context` requires.
    fn print(&self, e: &Sym, context: u8, out: &mut String) {
        let p = precedence(e);
        let paren = p < context;
        if paren {
            out.push('(');
        }
        match e {
            Sym::Const(v) => out.push_str(&number(*v)),
            Sym::X(i) => out.push_str(&self.names[*i]),
            Sym::Dot(i) => {
                out.push_str(&self.names[*i]);
                out.push_str("'dot");
            }
            Sym::Signal(s) => match self.design.signals.get(*s) {
                Some(sig) => out.push_str(&sig.name),
                // Past the design's signals: the source scale, then the delay histories.
                None => match *s - self.design.signals.len() {
                    0 => out.push_str("<source scale>"),
                    1 => out.push_str("<history ready>"),
                    2 => out.push_str("<time runs>"),
                    k => out.push_str(&format!("<history {}>", k - 3)),
                },
            },
            Sym::Now => out.push_str("now"),
            Sym::Un(op @ (Un::Neg | Un::Not), a) => {
                out.push_str(un_name(*op));
                self.print(a, p + 1, out);
            }
            Sym::Un(op, a) => {
                out.push_str(un_name(*op));
                out.push('(');
                self.print(a, 0, out);
                out.push(')');
            }
            Sym::Bin(op @ (Bin::Atan2 | Bin::Max | Bin::Min), a, b) => {
                out.push_str(bin_name(*op));
                out.push('(');
                self.print(a, 0, out);
                out.push_str(", ");
                self.print(b, 0, out);
                out.push(')');
            }
            Sym::Bin(op, a, b) => {
                // Left-associative: the right operand needs parentheses at equal precedence;
                // `**` and the relations do not chain in VHDL, so both sides get them.
                let chains = matches!(
                    op,
                    Bin::Add | Bin::Sub | Bin::Mul | Bin::Div | Bin::And | Bin::Or
                );
                self.print(a, if chains { p } else { p + 1 }, out);
                out.push_str(bin_name(*op));
                self.print(b, p + 1, out);
            }
            Sym::If(c, a, b) => {
                self.print(a, 1, out);
                out.push_str(" when ");
                self.print(c, 1, out);
                out.push_str(" else ");
                self.print(b, 1, out);
            }
        }
        if paren {
            out.push(')');
        }
    }
}
