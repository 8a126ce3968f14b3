//! The native procedures: `std.textio`'s `read`, `write`, `readline`, `writeline` (and the
//! hexadecimal and octal forms), the implicit `file_open`, `file_close`, `read` and `write`
//! of file types, and `deallocate` of access types (LRM 3.3.2, 3.4.1, 14.3).
//!
//! A `line` is an access value designating a `Value::String` on the heap; `read`s consume
//! its front, `write`s append. A file of another type than `text` holds one element a line,
//! written as `write` would write it.

use vams_design::{FileMode, NativeProc, Type, Value};

use super::image::{real_image, time_image_in};
use super::io::{Io, OpenStatus};
use super::ops::EvalError;

fn bug(what: &str) -> EvalError {
    EvalError::new(
        format!("a native procedure got {what}"),
        "this is a bug in elaboration",
    )
}

fn file_of(v: &Value) -> Result<u32, EvalError> {
    match v {
        Value::File(f) => Ok(*f),
        _ => Err(bug("a file argument that is not a file")),
    }
}

fn int(v: &Value) -> Result<i64, EvalError> {
    match v {
        Value::Integer(i) => Ok(*i),
        Value::Enum(p) => Ok(i64::from(*p)),
        _ => Err(bug("a non-integer where an integer belongs")),
    }
}

/// Runs [`Instr::Native`](vams_design::Instr::Native) against `env`; `vars` are the
/// variables the `copy_back` pairs write (those `env` reads).
pub(crate) fn call(
    op: &NativeProc,
    args: &[vams_design::Expr],
    copy_back: &[(usize, vams_design::VarId)],
    env: &super::eval::Env,
) -> Result<Vec<(vams_design::VarId, Value)>, EvalError> {
    let mut values = args
        .iter()
        .map(|a| super::eval::eval(a, env))
        .collect::<Result<Vec<_>, _>>()?;
    run(op, &mut values, env.io)?;
    Ok(copy_back
        .iter()
        .map(|&(k, var)| (var, std::mem::replace(&mut values[k], Value::Integer(0))))
        .collect())
}

/// `p.all := v`: the object `pointer` designates gets `value`.
pub(crate) fn set_heap(
    pointer: &vams_design::Expr,
    value: &vams_design::Expr,
    env: &super::eval::Env,
) -> Result<(), EvalError> {
    let p = super::eval::eval(pointer, env)?;
    let v = super::eval::eval(value, env)?;
    *env.io.heap.borrow_mut().get(&p)? = v;
    Ok(())
}

/// Runs `op` on `args` (parameter order); `out` and `inout` arguments are updated in place.
pub(crate) fn run(op: &NativeProc, args: &mut [Value], io: &Io) -> Result<(), EvalError> {
    let arg = |k: usize| args.get(k).ok_or_else(|| bug("too few arguments"));
    match op {
        NativeProc::ReadLine => {
            let f = file_of(arg(0)?)?;
            let text = io.files.borrow_mut().read_line(f)?;
            let mut heap = io.heap.borrow_mut();
            // The line read replaces what `l` designated (LRM 14.3: the old line is freed).
            heap.free(arg(1)?)?;
            args[1] = heap.alloc(Value::String(text))?;
        }
        NativeProc::WriteLine => {
            let f = file_of(arg(0)?)?;
            let text = line_text(io, arg(1)?)?;
            io.files.borrow_mut().write_line(f, &text)?;
            set_line(io, &mut args[1], String::new())?;
        }
        NativeProc::Write { ty } => {
            let justified = int(arg(2)?)?;
            let field = int(arg(3)?)?;
            let text = written(ty, arg(1)?, args.get(4))?;
            let text = justify(text, justified == 1, field)?;
            append(io, &mut args[0], &text)?;
        }
        NativeProc::WriteDigits { bits, ty } => {
            let justified = int(arg(2)?)?;
            let field = int(arg(3)?)?;
            let text = digits_of(arg(1)?, *bits, &BitCode::of(ty))?;
            append(io, &mut args[0], &justify(text, justified == 1, field)?)?;
        }
        NativeProc::Read { ty, good } => {
            let line = line_text(io, arg(0)?)?;
            let parsed = parse(ty, &line, arg(1)?);
            finish_read(io, args, parsed, *good, &type_name(ty))?;
        }
        NativeProc::ReadDigits { bits, good, ty } => {
            let line = line_text(io, arg(0)?)?;
            let parsed = parse_digits(&line, arg(1)?, *bits, &BitCode::of(ty));
            let what = if *bits == 4 { "hexadecimal" } else { "octal" };
            finish_read(io, args, parsed, *good, &format!("{what} bit_vector"))?;
        }
        NativeProc::FileOpen { status } => {
            let (f, name, mode) = open_arguments(&args[usize::from(*status)..])?;
            let result = io.files.borrow_mut().open(f, &name, mode);
            if *status {
                args[0] = Value::Enum(result as u32);
            } else if result != OpenStatus::Ok {
                return Err(EvalError::new(
                    format!("file_open cannot open \"{name}\" ({result:?})"),
                    "pass a status variable (`file_open(status, f, name, mode)`) to handle the failure, or check the path",
                ));
            }
        }
        NativeProc::FileDeclare => {
            let (f, name, mode) = open_arguments(args)?;
            let mut files = io.files.borrow_mut();
            files.close(f)?;
            if files.open(f, &name, mode) != OpenStatus::Ok {
                return Err(EvalError::new(
                    format!("cannot open the file \"{name}\" of a file declaration"),
                    "check the path (relative paths start in the directory vams runs in) and its permissions",
                ));
            }
        }
        NativeProc::FileClose => io.files.borrow_mut().close(file_of(arg(0)?)?)?,
        NativeProc::FileWrite { ty } => {
            let f = file_of(arg(0)?)?;
            let text = element_text(ty, arg(1)?)?;
            io.files.borrow_mut().write_line(f, &text)?;
        }
        NativeProc::FileRead { ty } => {
            let f = file_of(arg(0)?)?;
            let text = io.files.borrow_mut().read_line(f)?;
            match element_value(ty, &text, arg(1)?) {
                Some((v, n)) => {
                    args[1] = v;
                    // `read(f, value, length)`: the length of the element in the file.
                    if let Some(length) = args.get_mut(2) {
                        *length = Value::Integer(n as i64);
                    }
                }
                None => {
                    return Err(EvalError::new(
                        format!("the file's line \"{text}\" is not a {}", type_name(ty)),
                        "a file of a type other than text holds one value a line, as `write` wrote it",
                    ));
                }
            }
        }
        NativeProc::Deallocate => {
            io.heap.borrow_mut().free(arg(0)?)?;
            args[0] = Value::Access(0);
        }
    }
    Ok(())
}

/// The file, name and mode at the front of `args` (`file_open`'s after its status).
fn open_arguments(args: &[Value]) -> Result<(u32, String, FileMode), EvalError> {
    let [f, name, kind, ..] = args else {
        return Err(bug("too few arguments"));
    };
    let Value::String(name) = name else {
        return Err(bug("a file name that is not a string"));
    };
    let mode = FileMode::from_position(int(kind)? as u32)
        .ok_or_else(|| bug("an unknown file_open_kind"))?;
    Ok((file_of(f)?, name.clone(), mode))
}

/// The text a `line` designates (`null`: none).
fn line_text(io: &Io, l: &Value) -> Result<String, EvalError> {
    if matches!(l, Value::Access(0)) {
        return Ok(String::new());
    }
    match io.heap.borrow_mut().get(l)? {
        Value::String(s) => Ok(s.clone()),
        _ => Err(bug("a line that does not designate a string")),
    }
}

/// Makes `l` designate `text` (allocating when it is `null`).
fn set_line(io: &Io, l: &mut Value, text: String) -> Result<(), EvalError> {
    let mut heap = io.heap.borrow_mut();
    if matches!(l, Value::Access(0)) {
        *l = heap.alloc(Value::String(text))?;
    } else {
        *heap.get(l)? = Value::String(text);
    }
    Ok(())
}

fn append(io: &Io, l: &mut Value, text: &str) -> Result<(), EvalError> {
    let mut line = line_text(io, l)?;
    line.push_str(text);
    set_line(io, l, line)
}

/// After a read: the value and the rest of the line on success; `good` or an error else.
fn finish_read(
    io: &Io,
    args: &mut [Value],
    parsed: Option<(Value, usize)>,
    good: bool,
    what: &str,
) -> Result<(), EvalError> {
    let ok = parsed.is_some();
    if let Some((v, used)) = parsed {
        let line = line_text(io, &args[0])?;
        let rest = line.get(used..).unwrap_or_default().to_string();
        set_line(io, &mut args[0], rest)?;
        args[1] = v;
    }
    if good {
        args[2] = Value::Boolean(ok);
    } else if !ok {
        let line = line_text(io, &args[0])?;
        return Err(EvalError::new(
            format!("read of a {what} failed on the text \"{line}\""),
            "check the text, or pass a `good` variable to handle a failed read",
        ));
    }
    Ok(())
}

fn type_name(ty: &Type) -> String {
    match ty {
        Type::Real => "real".into(),
        Type::Integer => "integer".into(),
        Type::Boolean => "boolean".into(),
        Type::Time => "time".into(),
        Type::String => "string".into(),
        Type::Enum { name, .. }
        | Type::Physical { name, .. }
        | Type::Record { name, .. }
        | Type::Access { name }
        | Type::File { name } => name.clone(),
        Type::Array { .. } => "bit_vector".into(),
    }
}

/// The widest field `write` pads to: a wider one is an error, not gigabytes of spaces.
const MAX_FIELD: i64 = 1 << 20;

fn justify(text: String, left: bool, field: i64) -> Result<String, EvalError> {
    if field > MAX_FIELD {
        return Err(EvalError::new(
            format!("a field width of {field} characters"),
            "write pads to at most 1048576 characters; check the `field` argument",
        ));
    }
    let pad = usize::try_from(field).unwrap_or(0);
    let len = text.chars().count();
    if len >= pad {
        return Ok(text);
    }
    let fill = " ".repeat(pad - len);
    Ok(if left { text + &fill } else { fill + &text })
}

/// An enumeration literal as text: a character literal without its quotes.
fn literal_text(literal: &str) -> String {
    match literal
        .strip_prefix('\'')
        .and_then(|l| l.strip_suffix('\''))
    {
        Some(c) if !c.is_empty() => c.to_string(),
        _ => literal.to_string(),
    }
}

/// What `write` writes for `v` of type `ty`; `extra` is `digits` (real) or `unit` (time).
fn written(ty: &Type, v: &Value, extra: Option<&Value>) -> Result<String, EvalError> {
    Ok(match (ty, v) {
        (Type::Real, Value::Real(x)) => match extra {
            Some(Value::Integer(d)) if *d > 0 => format!("{x:.*}", (*d).min(300) as usize),
            _ => real_image(*x),
        },
        (Type::Integer, Value::Integer(i)) => i.to_string(),
        (Type::Boolean, Value::Boolean(b)) => if *b { "TRUE" } else { "FALSE" }.into(),
        (Type::Time, Value::Time(t)) => {
            let unit = match extra {
                Some(Value::Time(u)) if *u > 0.0 => *u,
                _ => 1e-9,
            };
            time_image_in(*t, unit)
        }
        (Type::String, Value::String(s)) => s.clone(),
        (Type::Enum { literals, .. }, Value::Enum(p)) => {
            literal_text(literals.get(*p as usize).map_or("?", String::as_str))
        }
        (Type::Array { element, .. }, Value::Array(items)) => {
            let mut out = String::new();
            for item in items {
                out.push_str(&written(element, item, None)?);
            }
            out
        }
        (Type::Physical { units, .. }, Value::Integer(n)) => match units.first() {
            Some((unit, _)) => format!("{n} {unit}"),
            None => n.to_string(),
        },
        _ => {
            return Err(EvalError::new(
                format!("`write` of a value of type {}", type_name(ty)),
                "textio writes bit, bit_vector, boolean, character, integer, real, string and time",
            ));
        }
    })
}

/// One element of a file of `ty` as its line: a scalar as `write` writes it, a string as
/// itself, another array as its elements separated by spaces.
fn element_text(ty: &Type, v: &Value) -> Result<String, EvalError> {
    match (ty, v) {
        (Type::Array { element, .. }, Value::Array(items)) if !is_character(element) => {
            let parts = items
                .iter()
                .map(|x| element_text(element, x))
                .collect::<Result<Vec<_>, _>>()?;
            Ok(parts.join(" "))
        }
        _ => written(ty, v, None),
    }
}

fn is_character(ty: &Type) -> bool {
    matches!(ty, Type::Enum { literals, .. } if literals.iter().all(|l| l.starts_with('\'')))
}

/// The element a file's line holds, into a target like `like`, with the number of elements
/// the line has (an array longer than the target fills it and reports its own length).
fn element_value(ty: &Type, line: &str, like: &Value) -> Option<(Value, usize)> {
    match (ty, like) {
        (Type::String, Value::String(s)) => {
            let n = line.chars().count();
            let mut text: String = line.chars().take(s.chars().count()).collect();
            while text.chars().count() < s.chars().count() {
                text.push(' ');
            }
            Some((Value::String(text), n))
        }
        (Type::Array { element, .. }, Value::Array(items)) => {
            let words: Vec<&str> = if is_character(element) {
                line.char_indices()
                    .map(|(k, c)| &line[k..k + c.len_utf8()])
                    .collect()
            } else {
                line.split_whitespace().collect()
            };
            let mut out = items.clone();
            for (slot, w) in out.iter_mut().zip(&words) {
                *slot = parse_token(element, w, slot)?.0;
            }
            Some((Value::Array(out), words.len()))
        }
        _ => {
            let (v, used) = parse(ty, line, like)?;
            line[used..].trim().is_empty().then_some((v, 1))
        }
    }
}

/// The positions of `'0'` and `'1'` in the element type of a vector written as digits.
struct BitCode {
    zero: u32,
    one: u32,
}

impl BitCode {
    fn of(ty: &Type) -> BitCode {
        let position = |literal: &str| match ty {
            Type::Array { element, .. } => match &**element {
                Type::Enum { literals, .. } => literals.iter().position(|l| l == literal),
                _ => None,
            },
            _ => None,
        };
        BitCode {
            zero: position("'0'").unwrap_or(0) as u32,
            one: position("'1'").unwrap_or(1) as u32,
        }
    }
}

/// Bits as hexadecimal or octal digits (the length must be a multiple of `bits`); a digit
/// with an element that is neither `'0'` nor `'1'` (`'U'`, `'X'` of std_logic) is `X`.
fn digits_of(v: &Value, bits: u32, code: &BitCode) -> Result<String, EvalError> {
    let Value::Array(items) = v else {
        return Err(bug("a bit_vector that is not an array"));
    };
    if items.len() % bits as usize != 0 {
        return Err(EvalError::new(
            format!(
                "a bit_vector of {} bits written as {} digits",
                items.len(),
                if bits == 4 { "hexadecimal" } else { "octal" }
            ),
            "the length must be a multiple of 4 (hwrite) or 3 (owrite)",
        ));
    }
    let mut out = String::new();
    for chunk in items.chunks(bits as usize) {
        let mut d = Some(0);
        for b in chunk {
            d = match b {
                Value::Enum(p) if *p == code.one => d.map(|d| d * 2 + 1),
                Value::Enum(p) if *p == code.zero => d.map(|d| d * 2),
                _ => None,
            };
        }
        out.push(d.map_or('X', |d| {
            char::from_digit(d, 16).unwrap_or('?').to_ascii_uppercase()
        }));
    }
    Ok(out)
}

fn skip_space(s: &str) -> usize {
    s.len() - s.trim_start_matches([' ', '\t', '\u{a0}']).len()
}

/// The longest prefix of `s` made of `ok` characters.
fn prefix_len(s: &str, ok: impl Fn(char) -> bool) -> usize {
    s.find(|c: char| !ok(c)).unwrap_or(s.len())
}

/// A number at the front of `s`: its text without underscores, and its length in `s`.
fn number(s: &str, real: bool) -> Option<(String, usize)> {
    let b = s.as_bytes();
    let mut k = usize::from(matches!(b.first(), Some(b'-' | b'+')));
    let digits = |k: usize| k + prefix_len(&s[k..], |c| c.is_ascii_digit() || c == '_');
    let end = digits(k);
    if end == k {
        return None;
    }
    k = end;
    if real && b.get(k) == Some(&b'.') && b.get(k + 1).is_some_and(u8::is_ascii_digit) {
        k = digits(k + 1);
    }
    if matches!(b.get(k), Some(b'e' | b'E')) {
        let sign = usize::from(matches!(b.get(k + 1), Some(b'-' | b'+')));
        let end = digits(k + 1 + sign);
        if end > k + 1 + sign {
            k = end;
        }
    }
    Some((s[..k].replace('_', ""), k))
}

/// Parses a value of type `ty` at the front of `line`: the value and the bytes used.
/// `like` is the target's current value (its length for strings and bit vectors).
fn parse(ty: &Type, line: &str, like: &Value) -> Option<(Value, usize)> {
    match ty {
        Type::Enum { name, .. } if name == "character" => {
            let c = line.chars().next()?;
            Some((Value::Enum(c as u32), c.len_utf8()))
        }
        Type::String => {
            let Value::String(s) = like else { return None };
            let n = s.chars().count();
            let used: usize = line.chars().take(n).map(char::len_utf8).sum();
            (line[..used].chars().count() == n).then(|| (Value::String(line[..used].into()), used))
        }
        _ => {
            let skip = skip_space(line);
            let (v, used) = parse_token(ty, &line[skip..], like)?;
            Some((v, skip + used))
        }
    }
}

fn parse_token(ty: &Type, s: &str, like: &Value) -> Option<(Value, usize)> {
    match ty {
        Type::Integer => {
            let (text, used) = number(s, false)?;
            let v = text.parse::<f64>().ok()?;
            (v.fract() == 0.0 && v.abs() < 9.2e18).then_some((Value::Integer(v as i64), used))
        }
        Type::Real => {
            let (text, used) = number(s, true)?;
            Some((Value::Real(text.parse().ok()?), used))
        }
        Type::Boolean => {
            let n = prefix_len(s, |c| c.is_ascii_alphabetic());
            match s[..n].to_ascii_lowercase().as_str() {
                "true" => Some((Value::Boolean(true), n)),
                "false" => Some((Value::Boolean(false), n)),
                _ => None,
            }
        }
        Type::Time => {
            let (text, used) = number(s, true)?;
            let x: f64 = text.parse().ok()?;
            let rest = &s[used..];
            let gap = skip_space(rest);
            let n = prefix_len(&rest[gap..], |c| c.is_ascii_alphabetic());
            let unit = super::image::time_unit(&rest[gap..gap + n])?;
            Some((Value::Time(x * unit), used + gap + n))
        }
        Type::Enum { literals, .. } => {
            let c = s.chars().next()?;
            let p = literals
                .iter()
                .position(|l| literal_text(l).eq_ignore_ascii_case(&c.to_string()))?;
            Some((Value::Enum(p as u32), c.len_utf8()))
        }
        Type::Array { element, .. } => {
            let Value::Array(items) = like else {
                return None;
            };
            let mut out = Vec::with_capacity(items.len());
            let mut used = 0;
            while out.len() < items.len() {
                let rest = &s[used..];
                if !out.is_empty() && rest.starts_with('_') {
                    used += 1;
                    continue;
                }
                let (v, n) = parse_token(element, rest, &Value::Enum(0))?;
                out.push(v);
                used += n;
            }
            Some((Value::Array(out), used))
        }
        _ => None,
    }
}

/// `hread` / `oread`: digits of `bits` bits each, as many as the target's length needs.
fn parse_digits(line: &str, like: &Value, bits: u32, code: &BitCode) -> Option<(Value, usize)> {
    let Value::Array(items) = like else {
        return None;
    };
    if items.len() % bits as usize != 0 {
        return None;
    }
    let skip = skip_space(line);
    let mut out = Vec::with_capacity(items.len());
    let mut used = skip;
    for c in line[skip..].chars() {
        if out.len() == items.len() {
            break;
        }
        used += c.len_utf8();
        if c == '_' {
            continue;
        }
        let d = c.to_digit(1 << bits)?;
        for k in (0..bits).rev() {
            let bit = (d >> k) & 1 == 1;
            out.push(Value::Enum(if bit { code.one } else { code.zero }));
        }
    }
    (out.len() == items.len()).then_some((Value::Array(out), used))
}

#[cfg(test)]
mod tests {
    use super::*;

    fn bit() -> Type {
        Type::Enum {
            name: "bit".into(),
            literals: vec!["'0'".into(), "'1'".into()],
        }
    }

    #[test]
    fn numbers_parse_with_signs_underscores_and_exponents() {
        let n = |s: &str, real| number(s, real);
        assert_eq!(n("-1_000 x", false), Some(("-1000".into(), 6)));
        assert_eq!(n("2.5e-3,", true), Some(("2.5e-3".into(), 6)));
        assert_eq!(n("3.", true), Some(("3".into(), 1)));
        assert_eq!(n("x", true), None);
    }

    #[test]
    fn reads_skip_leading_space_except_for_characters_and_strings() {
        let r = |ty: &Type, s: &str, like: &Value| parse(ty, s, like);
        assert_eq!(
            r(&Type::Integer, "  42 7", &Value::Integer(0)),
            Some((Value::Integer(42), 4))
        );
        assert_eq!(
            r(&Type::Time, " 10 ns", &Value::Time(0.0)),
            Some((Value::Time(10e-9), 6))
        );
        assert_eq!(
            r(&Type::String, " ab", &Value::String("xx".into())),
            Some((Value::String(" a".into()), 2))
        );
        let bits = Type::Array {
            element: Box::new(bit()),
            left: 0,
            right: 3,
            ascending: true,
        };
        let like = Value::Array(vec![Value::Enum(0); 4]);
        assert_eq!(
            r(&bits, " 10_01", &like),
            Some((Value::Array([1, 0, 0, 1].map(Value::Enum).to_vec()), 6))
        );
        assert_eq!(r(&Type::Integer, "abc", &Value::Integer(0)), None);
    }

    #[test]
    fn writes_follow_the_type_and_the_field() {
        assert_eq!(written(&bit(), &Value::Enum(1), None).unwrap(), "1");
        assert_eq!(
            written(&Type::Real, &Value::Real(12.25), Some(&Value::Integer(3))).unwrap(),
            "12.250"
        );
        assert_eq!(
            written(&Type::Time, &Value::Time(1.5e-9), Some(&Value::Time(1e-12))).unwrap(),
            "1500 ps"
        );
        assert_eq!(justify("42".into(), false, 5).unwrap(), "   42");
        assert_eq!(justify("42".into(), true, 5).unwrap(), "42   ");
        assert!(justify("42".into(), true, i64::MAX).is_err());
        let v = Value::Array([1, 0, 1, 0, 1, 1, 1, 1].map(Value::Enum).to_vec());
        let bits = Type::Array {
            element: Box::new(bit()),
            left: 0,
            right: 7,
            ascending: true,
        };
        let code = BitCode::of(&bits);
        assert_eq!(digits_of(&v, 4, &code).unwrap(), "AF");
        assert_eq!(
            parse_digits("af", &Value::Array(vec![Value::Enum(0); 8]), 4, &code).map(|p| p.0),
            Some(v)
        );
        // std_ulogic: 'U' 'X' '0' '1' ...; a digit with an unknown bit is X.
        let logic = Type::Array {
            element: Box::new(Type::Enum {
                name: "std_ulogic".into(),
                literals: ["'U'", "'X'", "'0'", "'1'"].map(String::from).to_vec(),
            }),
            left: 7,
            right: 0,
            ascending: false,
        };
        let code = BitCode::of(&logic);
        let v = Value::Array([3, 2, 2, 3, 0, 3, 3, 3].map(Value::Enum).to_vec());
        assert_eq!(digits_of(&v, 4, &code).unwrap(), "9X");
    }
}
