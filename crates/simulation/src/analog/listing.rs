//! The text of `vams dae`: unknowns, then equations with their origin and formula.
//!
//! Formulas are the assembled residuals (constants folded, before source scaling) printed with
//! unknown and signal names and the fewest parentheses that keep VHDL's precedence.

use super::AnalogSystem;
use super::build::{self, Origin};
use super::sym::{Bin, Sym, Un};
use vams_design::Design;
use vams_syntax::source::{SourceMap, Span};

/// Where a span is, as `file:line` (or `?` when the span is not in `sources`).
fn location(span: Span, sources: &SourceMap) -> String {
    if (span.file.0 as usize) < sources.len() {
        let (line, _) = sources.line_col(span);
        format!("{}:{}", sources.file(span.file).name, line)
    } else {
        "?".to_string()
    }
}

/// The equation system of `vams dae` as data: what [`Dae`]'s text shows.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Dae {
    /// The model's unknowns, in assembly order.
    pub unknowns: Vec<DaeUnknown>,
    /// The model's equations (residuals, each `= 0`), in assembly order.
    pub equations: Vec<DaeEquation>,
    /// What index reduction added, when the model has index 2 or more.
    pub index_reduction: Option<DaeIndexReduction>,
    /// The solver's unknowns when some were eliminated (else every unknown is one).
    pub solver_unknowns: Vec<String>,
    /// The unknowns eliminated, each as a formula of the solver's unknowns.
    pub eliminated: Vec<DaeEliminated>,
    /// How many unknowns the system has: the model's, and the derivatives index reduction
    /// made unknowns.
    pub all_unknowns: usize,
}

#[derive(Clone, Debug, PartialEq)]
pub struct DaeUnknown {
    pub name: String,
    /// True when some equation reads its derivative.
    pub differential: bool,
}

#[derive(Clone, Debug, PartialEq)]
pub struct DaeEquation {
    /// Where it comes from: `file:line` of a simultaneous statement, or what generated it.
    pub origin: String,
    /// The residual, with unknown and signal names (the equation is `residual = 0`).
    pub residual: String,
}

#[derive(Clone, Debug, PartialEq)]
pub struct DaeIndexReduction {
    /// The structural index of the model as written.
    pub index: usize,
    /// The equations added, numbered after the model's.
    pub added: Vec<DaeEquation>,
    /// The derivatives made algebraic unknowns.
    pub dummies: Vec<String>,
    /// The unknowns whose derivatives remain.
    pub states: Vec<String>,
}

#[derive(Clone, Debug, PartialEq)]
pub struct DaeEliminated {
    /// Its index among the unknowns.
    pub unknown: usize,
    pub name: String,
    /// Its value in terms of the solver's unknowns.
    pub formula: String,
    /// The equation it was solved from.
    pub equation: usize,
}

/// The equation system of `sys`; `None` when `design` (which `sys` was built from, so never
/// expected) does not assemble.
pub fn dae(sys: &AnalogSystem, design: &Design, sources: &SourceMap) -> Option<Dae> {
    // The system keeps only the reduced equations, and the listing shows the model's own.
    let asm = build::assemble(design, &sys.implicit_flows).ok()?;
    let names: Vec<String> = asm.unknowns.iter().map(|u| u.name(design)).collect();
    let mut differential = vec![false; names.len()];
    for r in &asm.residuals {
        r.visit(&mut |e| {
            if let Sym::Dot(j) = e {
                differential[*j] = true;
            }
        });
    }
    let unknowns = (names.iter().zip(differential))
        .map(|(name, differential)| DaeUnknown {
            name: name.clone(),
            differential,
        })
        .collect();
    let printer = Printer {
        names: &names,
        design,
    };
    let equations = (asm.origins.iter().zip(&asm.residuals))
        .map(|(origin, r)| DaeEquation {
            origin: match *origin {
                Origin::User(k) => location(design.equations[k].span, sources),
                Origin::Delayed(k) => location(design.delays[k].span, sources),
                other => other.describe(design),
            },
            residual: printer.text(r),
        })
        .collect();
    let index_reduction = sys.index_reduced.as_ref().map(|reduced| {
        let printer = Printer {
            names: &reduced.names,
            design,
        };
        DaeIndexReduction {
            index: reduced.index,
            added: (reduced.equations.iter())
                .map(|(from, r)| DaeEquation {
                    origin: from.clone(),
                    residual: printer.text(r),
                })
                .collect(),
            dummies: reduced.dummies.clone(),
            states: reduced.states.clone(),
        }
    });
    let names = sys.index_reduced.as_ref().map_or(&names, |r| &r.names);
    let printer = Printer {
        names: &sys.names,
        design,
    };
    let eliminated = (sys.eliminated.iter())
        .map(|e| DaeEliminated {
            unknown: e.unknown,
            name: names[e.unknown].clone(),
            formula: printer.text(&e.replacement),
            equation: e.solved_from,
        })
        .collect::<Vec<_>>();
    Some(Dae {
        unknowns,
        equations,
        index_reduction,
        solver_unknowns: match eliminated.is_empty() {
            true => Vec::new(),
            false => sys.names.clone(),
        },
        eliminated,
        all_unknowns: names.len(),
    })
}

pub fn listing(sys: &AnalogSystem, design: &Design, sources: &SourceMap) -> String {
    dae(sys, design, sources).map_or_else(String::new, |d| d.to_string())
}

/// The text of `vams dae`.
impl std::fmt::Display for Dae {
    fn fmt(&self, out: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let n = self.unknowns.len();
        let width = self
            .unknowns
            .iter()
            .map(|u| u.name.len())
            .max()
            .unwrap_or(0);
        writeln!(out, "unknowns ({n}):")?;
        for (i, u) in self.unknowns.iter().enumerate() {
            let kind = match u.differential {
                true => "differential",
                false => "algebraic",
            };
            writeln!(out, "  {i:>3}  {:<width$}  {kind}", u.name)?;
        }
        writeln!(out, "equations ({}):", self.equations.len())?;
        write_equations(out, 0, &self.equations)?;
        if let Some(reduced) = &self.index_reduction {
            writeln!(
                out,
                "index reduction (the model has index {}): {} equation(s) added",
                reduced.index,
                reduced.added.len()
            )?;
            write_equations(out, self.equations.len(), &reduced.added)?;
            writeln!(
                out,
                "  dummy derivatives (algebraic unknowns): {}",
                reduced.dummies.join(", ")
            )?;
            writeln!(
                out,
                "  states: {} (chosen at the initial guesses; a run chooses again at its \
                 initial break values)",
                match reduced.states.is_empty() {
                    true => "none".to_string(),
                    false => reduced.states.join(", "),
                }
            )?;
        }
        if self.eliminated.is_empty() {
            return Ok(());
        }
        writeln!(
            out,
            "solver unknowns ({} of {}): {}",
            self.solver_unknowns.len(),
            self.all_unknowns,
            self.solver_unknowns.join(", ")
        )?;
        writeln!(out, "eliminated ({}):", self.eliminated.len())?;
        let width = (self.eliminated.iter())
            .map(|e| e.name.len())
            .max()
            .unwrap_or(0);
        for e in &self.eliminated {
            writeln!(
                out,
                "  {:>3}  {:<width$} = {}   (equation {})",
                e.unknown, e.name, e.formula, e.equation
            )?;
        }
        Ok(())
    }
}

/// One line per equation, numbered from `first`: number, origin (padded to the widest) and
/// residual.
fn write_equations(
    out: &mut std::fmt::Formatter<'_>,
    first: usize,
    equations: &[DaeEquation],
) -> std::fmt::Result {
    let width = (equations.iter())
        .map(|e| e.origin.len())
        .max()
        .unwrap_or(0);
    for (i, e) in equations.iter().enumerate() {
        let i = i + first;
        writeln!(out, "  {i:>3}  {:<width$}  {} = 0", e.origin, e.residual)?;
    }
    Ok(())
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
    /// `e` as text.
    fn text(&self, e: &Sym) -> String {
        let mut out = String::new();
        self.print(e, 0, &mut out);
        out
    }

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
            Sym::Table(f, a) => {
                let n = f.table.len();
                let name = if f.slope { "pwl_slope" } else { "pwl" };
                out.push_str(&format!("{name}(<table of {n} points>, "));
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
