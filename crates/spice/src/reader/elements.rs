//! Element lines to [`Element`]s.
//!
//! Takes one logical line whose first word is not a dot-card; gives the element, or the
//! diagnostics that make it unusable. Decides only what the line's shape decides: which
//! fields are nodes, controls, the model and values, per letter. Whether a model or a
//! subcircuit exists is `flatten`'s question.
//!
//! Where SPICE's shape is ambiguous the rules are ngspice's: for D, Q and M the model is the
//! last word that is not a number or `on`/`off` (so a BJT has 3 to 5 nodes before it); for R,
//! C and L a word after the nodes is a model name or a bare parameter name as the value; an
//! `X` line's subcircuit is its last word before the `k=v` overrides (`params:` optional).

use vams_syntax::source::Span;

use crate::deck::{Ac, Element, ElementKind, InitialState, Name, Param, Source, Waveform};
use crate::error::SpiceError;
use crate::expr::Expr;
use crate::lexer::{TokKind, Token};
use crate::lines::Line;

use super::cursor::{Cursor, expected, is_value_like, missing, name_of, value_of};

/// The element a line defines (its first token is a word not starting with `.`).
pub fn element(line: &Line, errors: &mut Vec<SpiceError>) -> Option<Element> {
    let first = line.tokens.first()?;
    let name = name_of(first);
    let letter = name.key.chars().next().unwrap_or(' ');
    let Some(kind) = ElementKind::from_letter(letter) else {
        errors.push(unknown_element(&name, letter));
        return None;
    };
    let mut el = Element {
        kind,
        name,
        nodes: Vec::new(),
        controls: Vec::new(),
        model: None,
        values: Vec::new(),
        params: Vec::new(),
        state: None,
        source: None,
        span: line.span(),
    };
    let rest = &line.tokens[1..];
    if matches!(
        kind,
        ElementKind::E | ElementKind::F | ElementKind::G | ElementKind::H
    ) {
        let behavioural = rest.iter().enumerate().find(|(i, t)| {
            t.is_keyword("poly")
                || (["value", "vol", "cur", "table", "laplace"]
                    .iter()
                    .any(|k| t.is_keyword(k))
                    && rest.get(i + 1).is_some_and(|n| n.kind == TokKind::Eq))
        });
        if let Some((_, t)) = behavioural {
            errors.push(SpiceError::syntax(
                t.span,
                format!(
                    "the `{}` form of a controlled source is not read yet",
                    t.text
                ),
                "not supported",
                form(kind),
            ));
            return None;
        }
    }
    let ok = match kind {
        ElementKind::V | ElementKind::I => source_element(&mut el, rest, errors),
        _ => {
            let before = errors.len();
            let fields = split_fields(&mut el, rest, errors);
            before == errors.len() && shaped(&mut el, &fields, rest, errors)
        }
    };
    ok.then_some(el)
}

fn unknown_element(name: &Name, letter: char) -> SpiceError {
    let help = match letter {
        'b' => "behavioural sources (B) are not read yet; for a linear dependence use E, F, G or H",
        'j' => "JFETs (J) are not read yet",
        'z' => "MESFETs (Z) are not read yet",
        't' | 'o' | 'u' | 'y' => "transmission lines are not read yet",
        'a' | 'n' => "XSPICE code models and OSDI devices are not read yet",
        'p' => "coupled multiconductor lines (P) are not read yet",
        _ => {
            "an element's first letter says what it is: r c l k v i e f g h s w d q m, x for a \
             subcircuit instance; a dot starts a card"
        }
    };
    let span = Span {
        end: name.span.start + letter.len_utf8() as u32,
        ..name.span
    };
    SpiceError::UnknownElement {
        span,
        name: name.text.clone(),
        letter,
        help: help.to_string(),
    }
}

/// The usage line of each letter, for help texts.
fn form(kind: ElementKind) -> &'static str {
    use ElementKind::*;
    match kind {
        R => "write `rname n+ n- value [k=v ...]` (or a model instead of, or after, the value)",
        C => "write `cname n+ n- value [ic=v]`",
        L => "write `lname n+ n- value [ic=i]`",
        K => "write `kname lname1 lname2 coupling`",
        V | I => {
            "write `name n+ n- [[dc] v] [ac [mag [phase]]] [pulse(...)|sin(...)|exp(...)|pwl(...)]`"
        }
        E => "write `ename n+ n- nc+ nc- gain` (POLY and VALUE forms are not read yet)",
        G => "write `gname n+ n- nc+ nc- transconductance` (POLY and VALUE forms are not read yet)",
        F => "write `fname n+ n- vcontrol gain` (POLY is not read yet)",
        H => "write `hname n+ n- vcontrol transresistance` (POLY is not read yet)",
        S => "write `sname n+ n- nc+ nc- model [on|off]`",
        W => "write `wname n+ n- vcontrol model [on|off]`",
        D => "write `dname n+ n- model [area] [off] [k=v ...]`",
        Q => "write `qname nc nb ne [ns] model [area] [off] [k=v ...]`",
        M => "write `mname nd ng ns nb model [l=... w=... ...] [off]`",
        X => "write `xname node... subckt [params:] [k=v ...]`",
    }
}

/// Splits the fields after the name into positional ones (returned) and `k=v` parameters
/// (stored in `el`); `params:` is skipped.
fn split_fields<'t>(
    el: &mut Element,
    toks: &'t [Token],
    errors: &mut Vec<SpiceError>,
) -> Vec<&'t Token> {
    let mut c = Cursor::new(toks);
    let mut fields = Vec::new();
    while let Some(t) = c.peek() {
        if c.at_key_value() {
            match c.key_value() {
                Ok(p) => el.params.push(p),
                Err(e) => {
                    errors.push(e);
                    return fields;
                }
            }
            continue;
        }
        c.next();
        match t.kind {
            TokKind::Word if t.is_keyword("params:") && el.kind == ElementKind::X => {}
            TokKind::Word | TokKind::Brace | TokKind::Quote => fields.push(t),
            TokKind::Comma => {}
            _ => {
                errors.push(expected(
                    t.span,
                    "a node, a value or `name=value`",
                    &t.text,
                    form(el.kind),
                ));
                return fields;
            }
        }
    }
    fields
}

/// Assigns the positional fields by the letter's shape.
fn shaped(
    el: &mut Element,
    fields: &[&Token],
    toks: &[Token],
    errors: &mut Vec<SpiceError>,
) -> bool {
    use ElementKind::*;
    let end = toks.last().map_or(el.name.span, |t| t.span);
    let help = form(el.kind);
    let result = (|| -> Result<(), SpiceError> {
        match el.kind {
            R | C | L => {
                el.nodes = nodes(fields, 2, end, help)?;
                for t in &fields[2..] {
                    if is_value_like(t) {
                        if !el.values.is_empty() {
                            return Err(expected(
                                t.span,
                                "a model name or `name=value`",
                                &t.text,
                                help,
                            ));
                        }
                        el.values.push(value_of(t)?);
                    } else if el.model.is_none() {
                        el.model = Some(name_of(t));
                    } else {
                        return Err(expected(t.span, "`name=value`", &t.text, help));
                    }
                }
                let keys: &[&str] = match el.kind {
                    R => &["r", "resistance"],
                    C => &["c", "capacitance"],
                    _ => &["l", "inductance"],
                };
                if el.values.is_empty() {
                    if let Some(i) = el
                        .params
                        .iter()
                        .position(|p| keys.contains(&p.name.key.as_str()))
                    {
                        let p = el.params.remove(i);
                        el.values.push(p.value);
                    }
                }
                if el.values.is_empty() && el.model.is_none() {
                    return Err(missing(
                        end,
                        &format!("the value of {}", el.kind.noun()),
                        help,
                    ));
                }
            }
            K => {
                if fields.len() != 3 {
                    return Err(count(
                        el,
                        fields,
                        end,
                        "two inductor names and the coupling",
                        help,
                    ));
                }
                el.controls = names(&fields[..2], help)?;
                el.values.push(value_of(fields[2])?);
            }
            E | G => {
                if fields.len() != 5 {
                    return Err(count(el, fields, end, "four nodes and the gain", help));
                }
                el.nodes = nodes(fields, 4, end, help)?;
                el.values.push(value_of(fields[4])?);
            }
            F | H => {
                if fields.len() != 4 {
                    return Err(count(
                        el,
                        fields,
                        end,
                        "two nodes, the controlling source and the gain",
                        help,
                    ));
                }
                el.nodes = nodes(fields, 2, end, help)?;
                el.controls = names(&fields[2..3], help)?;
                el.values.push(value_of(fields[3])?);
            }
            S => semiconductor(el, fields, 4, 4, 0, end)?,
            W => {
                semiconductor(el, fields, 3, 3, 0, end)?;
                el.controls = vec![el.nodes.remove(2)];
            }
            D => semiconductor(el, fields, 2, 2, 1, end)?,
            Q => semiconductor(el, fields, 3, 5, 1, end)?,
            M => semiconductor(el, fields, 4, 7, 0, end)?,
            X => {
                let Some((sub, ports)) = fields.split_last() else {
                    return Err(missing(end, "the subcircuit name", help));
                };
                if !sub.is_word() || is_value_like(sub) {
                    return Err(expected(sub.span, "the subcircuit name", &sub.text, help));
                }
                el.nodes = nodes(ports, ports.len(), end, help)?;
                el.model = Some(name_of(sub));
            }
            V | I => {}
        }
        Ok(())
    })();
    match result {
        Ok(()) => true,
        Err(e) => {
            errors.push(e);
            false
        }
    }
}

/// `nodes... model [values] [on|off]` with `lo..=hi` nodes and at most `max_values` values.
fn semiconductor(
    el: &mut Element,
    fields: &[&Token],
    lo: usize,
    hi: usize,
    max_values: usize,
    end: Span,
) -> Result<(), SpiceError> {
    let help = form(el.kind);
    let mut kept: Vec<&Token> = Vec::new();
    for (i, t) in fields.iter().enumerate() {
        let state = match t.key().as_str() {
            "on" if i >= lo && t.is_word() => Some(InitialState::On),
            "off" if i >= lo && t.is_word() => Some(InitialState::Off),
            _ => None,
        };
        match state {
            Some(s) => el.state = Some(s),
            None => kept.push(t),
        }
    }
    let model_at = kept
        .iter()
        .rposition(|t| t.is_word() && !is_value_like(t))
        .filter(|&i| i >= lo);
    let Some(m) = model_at else {
        return Err(match kept.len() {
            n if n < lo => missing(
                end,
                &format!("{} (of {lo}) and the model", plural_nodes(lo - n)),
                help,
            ),
            _ => missing(end, "the model name", help),
        });
    };
    if m > hi {
        return Err(expected(
            kept[hi].span,
            "the model name",
            &kept[hi].text,
            help,
        ));
    }
    el.nodes = nodes(&kept[..m], m, end, help)?;
    el.model = Some(name_of(kept[m]));
    let values = &kept[m + 1..];
    if values.len() > max_values {
        let t = values[max_values];
        return Err(expected(t.span, "`name=value`", &t.text, help));
    }
    for t in values {
        el.values.push(value_of(t)?);
    }
    Ok(())
}

fn plural_nodes(n: usize) -> String {
    if n == 1 {
        "a node".into()
    } else {
        format!("{n} nodes")
    }
}

/// The first `n` fields as node names.
fn nodes(fields: &[&Token], n: usize, end: Span, help: &str) -> Result<Vec<Name>, SpiceError> {
    if fields.len() < n {
        return Err(missing(end, &plural_nodes(n - fields.len()), help));
    }
    names(&fields[..n], help)
}

fn names(fields: &[&Token], help: &str) -> Result<Vec<Name>, SpiceError> {
    fields
        .iter()
        .map(|t| {
            if t.is_word() {
                Ok(name_of(t))
            } else {
                Err(expected(t.span, "a node or element name", &t.text, help))
            }
        })
        .collect()
}

fn count(el: &Element, fields: &[&Token], end: Span, what: &str, help: &str) -> SpiceError {
    let want = match el.kind {
        ElementKind::K => 3,
        ElementKind::E | ElementKind::G => 5,
        _ => 4,
    };
    match fields.get(want) {
        Some(t) => expected(t.span, "the end of the line or `name=value`", &t.text, help),
        None => missing(end, what, help),
    }
}

const SOURCE_KEYWORDS: [&str; 6] = ["dc", "ac", "pulse", "sin", "exp", "pwl"];
const UNSUPPORTED_SOURCES: [&str; 7] = [
    "sffm", "am", "trnoise", "trrandom", "distof1", "distof2", "portnum",
];

fn is_source_keyword(t: &Token) -> bool {
    t.is_word() && {
        let k = t.key();
        SOURCE_KEYWORDS.contains(&k.as_str()) || UNSUPPORTED_SOURCES.contains(&k.as_str())
    }
}

/// `name n+ n- [[dc] v] [ac [mag [phase]]] [function]`
fn source_element(el: &mut Element, toks: &[Token], errors: &mut Vec<SpiceError>) -> bool {
    match source_spec(el, toks) {
        Ok(()) => true,
        Err(e) => {
            errors.push(e);
            false
        }
    }
}

fn source_spec(el: &mut Element, toks: &[Token]) -> Result<(), SpiceError> {
    let help = form(el.kind);
    let mut c = Cursor::new(toks);
    for _ in 0..2 {
        el.nodes.push(c.name("a node", help)?);
    }
    let mut src = Source::default();
    let mut pwl_options: Vec<Param> = Vec::new();
    while let Some(t) = c.peek() {
        if c.at_key_value() {
            pwl_options.push(c.key_value()?);
            continue;
        }
        let key = t.key();
        match key.as_str() {
            "dc" if t.is_word() => {
                c.next();
                let v = c.value("the DC value", help)?;
                src.dc = Some(v);
            }
            "ac" if t.is_word() => {
                c.next();
                let mut ac = Ac {
                    mag: None,
                    phase: None,
                };
                if c.peek().is_some_and(is_value_like) {
                    ac.mag = Some(c.value("the AC magnitude", help)?);
                    if c.peek().is_some_and(is_value_like) {
                        ac.phase = Some(c.value("the AC phase", help)?);
                    }
                }
                src.ac = Some(ac);
            }
            "pulse" | "sin" | "exp" | "pwl" if t.is_word() => {
                c.next();
                if src.tran.is_some() {
                    return Err(SpiceError::syntax(
                        t.span,
                        "a second transient function",
                        "the source already has one",
                        "a source has at most one of PULSE, SIN, EXP, PWL",
                    ));
                }
                let args = function_args(&mut c, t)?;
                src.tran = Some(waveform(&key, t, args)?);
            }
            k if t.is_word() && UNSUPPORTED_SOURCES.contains(&k) => {
                return Err(SpiceError::syntax(
                    t.span,
                    format!("the source function `{}` is not read yet", t.text),
                    "not supported",
                    "vams reads DC, AC, PULSE, SIN, EXP and PWL sources",
                ));
            }
            _ if matches!(t.kind, TokKind::Word | TokKind::Brace | TokKind::Quote)
                && src.dc.is_none()
                && src.ac.is_none()
                && src.tran.is_none() =>
            {
                c.next();
                src.dc = Some(value_of(t)?);
            }
            _ => {
                return Err(expected(
                    t.span,
                    "`dc`, `ac` or a source function",
                    &t.text,
                    help,
                ));
            }
        }
    }
    for p in pwl_options {
        match (&mut src.tran, p.name.key.as_str()) {
            (Some(Waveform::Pwl { repeat, .. }), "r") => *repeat = Some(p.value),
            (Some(Waveform::Pwl { delay, .. }), "td") => *delay = Some(p.value),
            _ => el.params.push(p),
        }
    }
    el.source = Some(src);
    Ok(())
}

/// The arguments of a source function, in parentheses or bare up to the next keyword.
fn function_args(c: &mut Cursor<'_>, func: &Token) -> Result<Vec<Expr>, SpiceError> {
    let mut args = Vec::new();
    if c.peek().is_some_and(|t| t.kind == TokKind::LParen) {
        c.next();
        loop {
            let Some(t) = c.next() else {
                return Err(SpiceError::syntax(
                    func.span,
                    format!("`{}(` is not closed", func.text),
                    "opened here",
                    "close the argument list with `)`",
                ));
            };
            match t.kind {
                TokKind::RParen => break,
                TokKind::Comma => {}
                TokKind::Word | TokKind::Brace | TokKind::Quote => args.push(value_of(t)?),
                _ => return Err(expected(t.span, "a value or `)`", &t.text, "")),
            }
        }
    } else {
        while let Some(t) = c.peek() {
            if t.kind == TokKind::Comma {
                c.next();
                continue;
            }
            if !matches!(t.kind, TokKind::Word | TokKind::Brace | TokKind::Quote)
                || is_source_keyword(t)
                || c.at_key_value()
            {
                break;
            }
            c.next();
            args.push(value_of(t)?);
        }
    }
    Ok(args)
}

fn waveform(key: &str, func: &Token, args: Vec<Expr>) -> Result<Waveform<Expr>, SpiceError> {
    let (lo, hi, usage) = match key {
        "pulse" => (2, 8, "PULSE(v1 v2 [td [tr [tf [pw [per [np]]]]]])"),
        "sin" => (2, 6, "SIN(vo va [freq [td [theta [phase]]]])"),
        "exp" => (2, 6, "EXP(v1 v2 [td1 [tau1 [td2 [tau2]]]])"),
        _ => (2, usize::MAX, "PWL(t1 v1 [t2 v2 ...]) [r=t] [td=t]"),
    };
    let n = args.len();
    if n < lo || n > hi || (key == "pwl" && n % 2 == 1) {
        let what = match key {
            "pwl" if n % 2 == 1 => format!("an odd number of values ({n})"),
            _ if n < lo => format!("{n} argument{}", if n == 1 { "" } else { "s" }),
            _ => format!("{n} arguments"),
        };
        return Err(SpiceError::syntax(
            func.span,
            format!("`{}` with {what}", func.text.to_ascii_uppercase()),
            "wrong number of arguments",
            format!("write `{usage}`"),
        ));
    }
    let mut it = args.into_iter();
    // The arity check above makes the two required arguments present.
    let (Some(a), Some(b)) = (it.next(), it.next()) else {
        return Err(SpiceError::syntax(
            func.span,
            "missing arguments",
            "here",
            usage,
        ));
    };
    let mut next = || it.next();
    Ok(match key {
        "pulse" => Waveform::Pulse {
            v1: a,
            v2: b,
            td: next(),
            tr: next(),
            tf: next(),
            pw: next(),
            per: next(),
            np: next(),
        },
        "sin" => Waveform::Sin {
            vo: a,
            va: b,
            freq: next(),
            td: next(),
            theta: next(),
            phase: next(),
        },
        "exp" => Waveform::Exp {
            v1: a,
            v2: b,
            td1: next(),
            tau1: next(),
            td2: next(),
            tau2: next(),
        },
        _ => {
            let mut points = vec![(a, b)];
            while let (Some(t), Some(v)) = (next(), next()) {
                points.push((t, v));
            }
            Waveform::Pwl {
                points,
                repeat: None,
                delay: None,
            }
        }
    })
}
