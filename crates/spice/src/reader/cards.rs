//! Dot-card lines to [`Card`]s.
//!
//! Takes one logical line starting with `.` (and the text of its file, for `.title` and
//! unquoted paths); gives what the card says as data, or the diagnostics that make it
//! unusable. Structure (subcircuit nesting, includes, library sections) is the reader's: a
//! `.subckt` here is only its header.

use vams_syntax::source::Span;

use crate::deck::{
    AcScale, Analysis, AnalysisCard, DcSweep, Model, ModelKind, Name, NodeValue, OptionItem,
    OptionValue, Output, OutputCard, Param, Part, PrintAnalysis, Vector,
};
use crate::error::SpiceError;
use crate::expr::{Expr, parse_card_tokens};
use crate::lexer::{TokKind, Token};
use crate::lines::Line;
use crate::suggest::suggest;

use super::cursor::{Cursor, expected, is_value_like, missing, name_of, value_of};

/// What a dot-card says.
#[derive(Debug)]
pub enum Card {
    /// `.subckt name ports [params: k=v ...]`: the header; the body follows.
    Subckt {
        name: Name,
        ports: Vec<Name>,
        params: Vec<Param>,
        span: Span,
    },
    Ends(Option<Name>, Span),
    Model(Model),
    Params(Vec<Param>),
    Include {
        path: String,
        span: Span,
    },
    /// `.lib file section`
    Lib {
        path: String,
        section: Name,
        span: Span,
    },
    /// `.lib name`: the start of a section definition.
    LibSection,
    Endl(Span),
    Endc(Span),
    Analysis(AnalysisCard),
    Options(Vec<OptionItem>),
    Temp(Vec<Expr>),
    Ic(Vec<NodeValue>),
    Nodeset(Vec<NodeValue>),
    Output(Output),
    Global(Vec<Name>),
    Title(String),
    /// A card read and ignored: the warning.
    Ignored(SpiceError),
}

/// The cards vams reads, for "did you mean".
const CARDS: [&str; 27] = [
    ".subckt", ".ends", ".model", ".param", ".include", ".inc", ".lib", ".endl", ".options",
    ".option", ".opt", ".temp", ".ic", ".nodeset", ".tran", ".op", ".dc", ".ac", ".print",
    ".probe", ".save", ".global", ".title", ".end", ".control", ".endc", ".width",
];

/// ngspice cards vams does not read yet.
const UNSUPPORTED: [&str; 21] = [
    ".func", ".meas", ".measure", ".four", ".fourier", ".noise", ".tf", ".sens", ".pz", ".disto",
    ".pss", ".sp", ".if", ".elseif", ".else", ".endif", ".csparam", ".plot", ".step", ".data",
    ".spinit",
];

/// Parses a dot-card; `None` when it is unusable (the diagnostics are in `errors`).
pub fn card(line: &Line, text: &str, errors: &mut Vec<SpiceError>) -> Option<Card> {
    let head = line.tokens.first()?;
    let key = head.key();
    let mut c = Cursor::new(&line.tokens[1..]);
    let span = line.span();
    let r = match key.as_str() {
        ".subckt" => subckt(&mut c, span),
        ".ends" => Ok(Card::Ends(
            c.next().filter(|t| t.is_word()).map(name_of),
            span,
        )),
        ".model" => model(&mut c, span, errors),
        ".param" => params(&mut c).map(Card::Params),
        ".include" | ".inc" => path(&c, head, text).map(|path| Card::Include { path, span }),
        ".lib" => lib(&mut c, head, text, span),
        ".endl" => Ok(Card::Endl(head.span)),
        ".endc" => Ok(Card::Endc(head.span)),
        ".options" | ".option" | ".opt" => options(&mut c).map(Card::Options),
        ".temp" => values(&mut c, "a temperature").map(Card::Temp),
        ".ic" => node_values(&mut c, ".ic").map(Card::Ic),
        ".nodeset" => node_values(&mut c, ".nodeset").map(Card::Nodeset),
        ".tran" => tran(&mut c, span),
        ".op" => Ok(Card::Analysis(AnalysisCard {
            analysis: Analysis::Op,
            span,
        })),
        ".dc" => dc(&mut c, span),
        ".ac" => ac(&mut c, span),
        ".print" => output(&mut c, OutputCard::Print, span),
        ".probe" => output(&mut c, OutputCard::Probe, span),
        ".save" => output(&mut c, OutputCard::Save, span),
        ".global" => c
            .rest()
            .iter()
            .map(|t| {
                if t.is_word() {
                    Ok(name_of(t))
                } else {
                    Err(expected(
                        t.span,
                        "a node name",
                        &t.text,
                        "write `.global node ...`",
                    ))
                }
            })
            .collect::<Result<Vec<_>, _>>()
            .map(Card::Global),
        ".title" => Ok(Card::Title(match (c.rest().first(), c.rest().last()) {
            (Some(a), Some(b)) => text
                .get(a.span.start as usize..b.span.end as usize)
                .unwrap_or("")
                .to_string(),
            _ => String::new(),
        })),
        ".width" => Ok(Card::Ignored(SpiceError::IgnoredCard {
            span: head.span,
            card: head.text.clone(),
            why: "`.width` sets the printed line width of SPICE2's output; vams's output does not use it",
        })),
        k if UNSUPPORTED.contains(&k) => Err(SpiceError::UnknownCard {
            span: head.span,
            card: head.text.clone(),
            help: format!(
                "`{k}` is an ngspice card that vams does not read yet; remove it to read the rest of the deck"
            ),
        }),
        k => Err(SpiceError::UnknownCard {
            span: head.span,
            card: head.text.clone(),
            help: match suggest(k, CARDS) {
                Some(s) => format!("did you mean `{s}`?"),
                None => format!("the cards vams reads are: {}", CARDS.join(" ")),
            },
        }),
    };
    match r {
        Ok(card) => Some(card),
        Err(e) => {
            errors.push(e);
            None
        }
    }
}

fn subckt(c: &mut Cursor<'_>, span: Span) -> Result<Card, SpiceError> {
    let help = "write `.subckt name port... [params: name=value ...]`";
    let name = c.name("the subcircuit name", help)?;
    let mut ports = Vec::new();
    let mut params = Vec::new();
    while let Some(t) = c.peek() {
        if c.at_key_value() {
            params.push(c.key_value()?);
        } else if t.is_keyword("params:") || t.kind == TokKind::Comma {
            c.next();
        } else if t.is_word() && params.is_empty() {
            c.next();
            ports.push(name_of(t));
        } else {
            return Err(expected(t.span, "a port or `name=value`", &t.text, help));
        }
    }
    Ok(Card::Subckt {
        name,
        ports,
        params,
        span,
    })
}

fn model(c: &mut Cursor<'_>, span: Span, errors: &mut Vec<SpiceError>) -> Result<Card, SpiceError> {
    let help = "write `.model name type (name=value ...)`";
    let name = c.name("the model name", help)?;
    let kind_tok = match c.next() {
        Some(t) if t.is_word() => t,
        Some(t) => return Err(expected(t.span, "the model type", &t.text, help)),
        None => return Err(missing(c.end_span(), "the model type", help)),
    };
    let kind_key = kind_tok.key();
    let Some(kind) = ModelKind::from_name(&kind_key) else {
        return Err(SpiceError::UnknownModelType {
            span: kind_tok.span,
            kind: kind_tok.text.clone(),
            suggestion: suggest(&kind_key, ModelKind::NAMES.iter().map(|(n, _)| *n)),
        });
    };
    let mut level = None;
    let mut params = Vec::new();
    while let Some(t) = c.peek() {
        if c.at_key_value() {
            match c.key_value() {
                Ok(p) if p.name.key == "level" => level = Some(p.value),
                Ok(p) => params.push(p),
                // A bad value spoils one parameter, not the model: go on with the others.
                Err(e) => errors.push(e),
            }
        } else if matches!(t.kind, TokKind::LParen | TokKind::RParen | TokKind::Comma) {
            c.next();
        } else {
            return Err(expected(t.span, "`name=value`", &t.text, help));
        }
    }
    Ok(Card::Model(Model {
        name,
        kind,
        level,
        params,
        span,
    }))
}

/// `.param a=1 b = 2*a c={a+b}`: each value is the run of tokens up to the next `name=`.
fn params(c: &mut Cursor<'_>) -> Result<Vec<Param>, SpiceError> {
    let help = "write `.param name=value ...`";
    let mut out = Vec::new();
    if c.is_done() {
        return Err(missing(c.end_span(), "a `name=value`", help));
    }
    while !c.is_done() {
        c.skip_commas();
        if c.is_done() {
            break;
        }
        if !c.at_key_value() {
            let t = c.rest()[0].clone();
            let hint = if c.peek_at(1).is_some_and(|n| n.kind == TokKind::LParen) {
                "functions defined with `.param f(x)=...` or `.func` are not read yet"
            } else {
                help
            };
            return Err(expected(t.span, "`name=value`", &t.text, hint));
        }
        let name = c.name("a parameter name", help)?;
        c.next(); // the `=`
        let start = c.rest();
        let mut n = 0;
        let mut depth = 0usize;
        while let Some(t) = start.get(n) {
            match t.kind {
                TokKind::LParen => depth += 1,
                TokKind::RParen => depth = depth.saturating_sub(1),
                TokKind::Comma if depth == 0 => break,
                TokKind::Word
                    if depth == 0 && start.get(n + 1).is_some_and(|e| e.kind == TokKind::Eq) =>
                {
                    break;
                }
                _ => {}
            }
            n += 1;
        }
        if n == 0 {
            return Err(missing(
                name.span,
                &format!("the value of `{}`", name.text),
                help,
            ));
        }
        let value = parse_card_tokens(&start[..n])?;
        for _ in 0..n {
            c.next();
        }
        out.push(Param { name, value });
    }
    Ok(out)
}

/// The file name of an `.include` / `.lib`: a quoted string, or the words as written.
fn path(c: &Cursor<'_>, head: &Token, text: &str) -> Result<String, SpiceError> {
    let rest = c.rest();
    match rest {
        [] => Err(missing(
            head.span,
            "the file name",
            "write `.include \"file\"`",
        )),
        [t, ..] if matches!(t.kind, TokKind::Str | TokKind::Quote) => Ok(t.inner().0.to_string()),
        [first, ..] => {
            let last = rest
                .iter()
                .take_while(|t| t.is_word())
                .last()
                .unwrap_or(first);
            Ok(text
                .get(first.span.start as usize..last.span.end as usize)
                .unwrap_or(&first.text)
                .to_string())
        }
    }
}

fn lib(c: &mut Cursor<'_>, head: &Token, text: &str, span: Span) -> Result<Card, SpiceError> {
    let help =
        "write `.lib file section` to include a section, `.lib section` ... `.endl` to define one";
    match c.rest() {
        [] => Err(missing(head.span, "a file name and a section", help)),
        [one] if one.is_word() => Ok(Card::LibSection),
        [file, section] if section.is_word() => {
            let path = match file.kind {
                TokKind::Str | TokKind::Quote => file.inner().0.to_string(),
                _ => text
                    .get(file.span.start as usize..file.span.end as usize)
                    .unwrap_or(&file.text)
                    .to_string(),
            };
            Ok(Card::Lib {
                path,
                section: name_of(section),
                span,
            })
        }
        [_, _, extra, ..] => Err(expected(
            extra.span,
            "the end of the line",
            &extra.text,
            help,
        )),
        [_, t] | [t] => Err(expected(t.span, "a section name", &t.text, help)),
    }
}

fn options(c: &mut Cursor<'_>) -> Result<Vec<OptionItem>, SpiceError> {
    let mut out = Vec::new();
    while let Some(t) = c.peek() {
        if t.kind == TokKind::Comma {
            c.next();
            continue;
        }
        if c.at_key_value() {
            let name = c.name("an option name", "")?;
            c.next();
            let value = match c.next() {
                Some(v) if v.is_word() && !is_value_like(v) => OptionValue::Word(name_of(v)),
                Some(v) => OptionValue::Expr(value_of(v)?),
                None => {
                    return Err(missing(
                        c.end_span(),
                        &format!("the value of `{}`", name.text),
                        "write `.options name=value ...`",
                    ));
                }
            };
            out.push(OptionItem {
                name,
                value: Some(value),
            });
        } else if t.is_word() {
            c.next();
            out.push(OptionItem {
                name: name_of(t),
                value: None,
            });
        } else {
            return Err(expected(
                t.span,
                "an option",
                &t.text,
                "write `.options name=value ...`",
            ));
        }
    }
    Ok(out)
}

fn values(c: &mut Cursor<'_>, what: &str) -> Result<Vec<Expr>, SpiceError> {
    let mut out = Vec::new();
    if c.is_done() {
        return Err(missing(c.end_span(), what, ""));
    }
    while !c.is_done() {
        c.skip_commas();
        if c.is_done() {
            break;
        }
        out.push(c.value(what, "")?);
    }
    Ok(out)
}

/// `v(node)=value ...`
fn node_values(c: &mut Cursor<'_>, card: &str) -> Result<Vec<NodeValue>, SpiceError> {
    let help = format!("write `{card} v(node)=value ...`");
    let mut out = Vec::new();
    if c.is_done() {
        return Err(missing(c.end_span(), "a `v(node)=value`", &help));
    }
    while let Some(t) = c.next() {
        if t.kind == TokKind::Comma {
            continue;
        }
        if !t.is_keyword("v") {
            return Err(expected(t.span, "`v(node)=value`", &t.text, &help));
        }
        let open = c.next();
        if !open.is_some_and(|t| t.kind == TokKind::LParen) {
            let at = open.map_or(t.span, |o| o.span);
            return Err(expected(at, "`(`", open.map_or("", |o| &o.text), &help));
        }
        let node = c.name("a node name", &help)?;
        for (kind, what) in [(TokKind::RParen, "`)`"), (TokKind::Eq, "`=`")] {
            match c.next() {
                Some(x) if x.kind == kind => {}
                Some(x) => return Err(expected(x.span, what, &x.text, &help)),
                None => return Err(missing(c.end_span(), what, &help)),
            }
        }
        let value = c.value("a value", &help)?;
        out.push(NodeValue { node, value });
    }
    Ok(out)
}

fn tran(c: &mut Cursor<'_>, span: Span) -> Result<Card, SpiceError> {
    let help = "write `.tran tstep tstop [tstart [tmax]] [uic]`";
    let mut vals = Vec::new();
    let mut uic = false;
    while let Some(t) = c.next() {
        if t.is_keyword("uic") {
            uic = true;
        } else if vals.len() == 4 {
            return Err(expected(
                t.span,
                "`uic` or the end of the line",
                &t.text,
                help,
            ));
        } else {
            vals.push(value_of(t)?);
        }
    }
    if vals.len() < 2 {
        let what = if vals.is_empty() {
            "the time step and stop time"
        } else {
            "the stop time"
        };
        return Err(missing(c.end_span(), what, help));
    }
    let mut it = vals.into_iter();
    let (Some(tstep), Some(tstop)) = (it.next(), it.next()) else {
        return Err(missing(c.end_span(), "the stop time", help));
    };
    Ok(Card::Analysis(AnalysisCard {
        analysis: Analysis::Tran {
            tstep,
            tstop,
            tstart: it.next(),
            tmax: it.next(),
            uic,
        },
        span,
    }))
}

fn dc(c: &mut Cursor<'_>, span: Span) -> Result<Card, SpiceError> {
    let help = "write `.dc source start stop step [source2 start2 stop2 step2]`";
    let mut sweeps = Vec::new();
    while !c.is_done() {
        if sweeps.len() == 2 {
            let t = c.rest()[0].clone();
            return Err(expected(t.span, "the end of the line", &t.text, help));
        }
        let target = c.name("a source name", help)?;
        let start = c.value("the start value", help)?;
        let stop = c.value("the stop value", help)?;
        let step = c.value("the step", help)?;
        sweeps.push(DcSweep {
            target,
            start,
            stop,
            step,
        });
    }
    if sweeps.is_empty() {
        return Err(missing(c.end_span(), "the swept source", help));
    }
    Ok(Card::Analysis(AnalysisCard {
        analysis: Analysis::Dc { sweeps },
        span,
    }))
}

fn ac(c: &mut Cursor<'_>, span: Span) -> Result<Card, SpiceError> {
    let help = "write `.ac dec|oct|lin points fstart fstop`";
    let scale_tok = c.name("`dec`, `oct` or `lin`", help)?;
    let scale = match scale_tok.key.as_str() {
        "dec" => AcScale::Dec,
        "oct" => AcScale::Oct,
        "lin" => AcScale::Lin,
        _ => {
            return Err(expected(
                scale_tok.span,
                "`dec`, `oct` or `lin`",
                &scale_tok.text,
                help,
            ));
        }
    };
    let points = c.value("the number of points", help)?;
    let fstart = c.value("the start frequency", help)?;
    let fstop = c.value("the stop frequency", help)?;
    if let Some(t) = c.next() {
        return Err(expected(t.span, "the end of the line", &t.text, help));
    }
    Ok(Card::Analysis(AnalysisCard {
        analysis: Analysis::Ac {
            scale,
            points,
            fstart,
            fstop,
        },
        span,
    }))
}

fn output(c: &mut Cursor<'_>, card: OutputCard, span: Span) -> Result<Card, SpiceError> {
    let help = "write vectors as `v(node)`, `v(node1, node2)` or `i(vsource)` (ac: vm vp vdb vr vi, im ip idb ir ii)";
    let mut analysis = None;
    if let Some(t) = c
        .peek()
        .filter(|t| t.is_word() && c.peek_at(1).is_none_or(|n| n.kind != TokKind::LParen))
    {
        analysis = match t.key().as_str() {
            "tran" => Some(PrintAnalysis::Tran),
            "dc" => Some(PrintAnalysis::Dc),
            "ac" => Some(PrintAnalysis::Ac),
            "op" => Some(PrintAnalysis::Op),
            "noise" | "disto" | "tf" | "pz" | "sens" if card == OutputCard::Print => {
                return Err(expected(
                    t.span,
                    "`tran`, `dc`, `ac` or `op`",
                    &t.text,
                    "vams has no such analysis yet",
                ));
            }
            _ => None,
        };
        if analysis.is_some() {
            c.next();
        }
    }
    let mut vectors = Vec::new();
    while let Some(t) = c.next() {
        if t.kind == TokKind::Comma {
            continue;
        }
        if !t.is_word() {
            return Err(expected(t.span, "an output vector", &t.text, help));
        }
        if c.peek().is_none_or(|n| n.kind != TokKind::LParen) {
            if t.is_keyword("all") {
                vectors.push(Vector::All { span: t.span });
            } else if t.text.starts_with('@') {
                return Err(SpiceError::syntax(
                    t.span,
                    "device parameters (`@dev[param]`) are not read yet",
                    "not supported",
                    help,
                ));
            } else {
                vectors.push(Vector::Voltage {
                    part: Part::Value,
                    pos: name_of(t),
                    neg: None,
                    span: t.span,
                });
            }
            continue;
        }
        let key = t.key();
        let (voltage, part) = match key.as_str() {
            "v" => (true, Part::Value),
            "vm" => (true, Part::Mag),
            "vp" => (true, Part::Phase),
            "vdb" => (true, Part::Db),
            "vr" => (true, Part::Real),
            "vi" => (true, Part::Imag),
            "i" => (false, Part::Value),
            "im" => (false, Part::Mag),
            "ip" => (false, Part::Phase),
            "idb" => (false, Part::Db),
            "ir" => (false, Part::Real),
            "ii" => (false, Part::Imag),
            _ => {
                return Err(expected(
                    t.span,
                    "`v` or `i` (or an ac form: vm vp vdb vr vi)",
                    &t.text,
                    help,
                ));
            }
        };
        c.next(); // `(`
        let first = c.name("a node or source name", help)?;
        let mut second = None;
        if c.peek().is_some_and(|n| n.kind == TokKind::Comma) && voltage {
            c.next();
            second = Some(c.name("a node name", help)?);
        }
        let close = match c.next() {
            Some(x) if x.kind == TokKind::RParen => x.span,
            Some(x) => return Err(expected(x.span, "`)`", &x.text, help)),
            None => return Err(missing(c.end_span(), "`)`", help)),
        };
        let span = t.span.to(close);
        vectors.push(if voltage {
            Vector::Voltage {
                part,
                pos: first,
                neg: second,
                span,
            }
        } else {
            Vector::Current {
                part,
                element: first,
                span,
            }
        });
    }
    if vectors.is_empty() {
        return Err(missing(c.end_span(), "an output vector", help));
    }
    Ok(Card::Output(Output {
        card,
        analysis,
        vectors,
        span,
    }))
}
