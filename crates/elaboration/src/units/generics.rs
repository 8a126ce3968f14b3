//! Top-level generic overrides (`-g NAME=VALUE`): the text read as a VHDL literal of the
//! generic's type.

use vams_design::Value;

use crate::names::types::Ty;

/// The value `text` denotes for type `ty`, or `None` when it is not a literal of that type.
/// An integer literal is accepted for a real generic (`-g r=5` means 5.0): the command line is
/// not VHDL source, and refusing it would only annoy.
/// `time_unit` gives a unit name's value in femtoseconds (std.standard's units of `time`).
pub(crate) fn parse_literal(
    text: &str,
    ty: &Ty,
    time_unit: impl Fn(&str) -> Option<f64>,
) -> Option<Value> {
    literal(text, ty, &time_unit)
}

fn literal(text: &str, ty: &Ty, time_unit: &dyn Fn(&str) -> Option<f64>) -> Option<Value> {
    let t = text.trim();
    match ty {
        Ty::Real => number(t).map(Value::Real),
        Ty::Physical(p) => {
            let (n, unit) = t.split_once(char::is_whitespace).unwrap_or((t, ""));
            let unit = unit.trim().to_ascii_lowercase();
            let factor = p.units.iter().find(|(u, _)| *u == unit).map(|u| u.1)?;
            number(n).map(|n| Value::Integer((n * factor as f64).round() as i64))
        }
        Ty::Integer => {
            let clean: String = t.chars().filter(|c| *c != '_').collect();
            clean.parse::<i64>().ok().map(Value::Integer)
        }
        Ty::Time => {
            let split = t
                .find(|c: char| c.is_ascii_alphabetic() && c != 'e' && c != 'E')
                .or_else(|| {
                    // `10 ms`: the unit starts after the last space.
                    t.rfind(' ').map(|p| p + 1)
                })?;
            let (num, unit) = t.split_at(split);
            let n = number(num.trim())?;
            time_unit(&unit.trim().to_ascii_lowercase()).map(|f| Value::Time(n * f / 1e15))
        }
        Ty::Boolean => match t.to_ascii_lowercase().as_str() {
            "true" => Some(Value::Boolean(true)),
            "false" => Some(Value::Boolean(false)),
            _ => None,
        },
        Ty::Enum(e) => {
            let lit = if t.starts_with('\'') {
                t.to_string()
            } else {
                t.to_ascii_lowercase()
            };
            e.literals
                .iter()
                .position(|l| *l == lit)
                .map(|p| Value::Enum(p as u32))
        }
        Ty::Array(_) if ty.is_string() => {
            let s = t
                .strip_prefix('"')
                .and_then(|s| s.strip_suffix('"'))
                .unwrap_or(t);
            Some(Value::String(s.to_string()))
        }
        // An array of scalars as a positional aggregate, `(0.0, 1.5, 2.0)`: a table for
        // `vams.tables.pwl`, a list of thresholds.
        Ty::Array(a) => {
            let inner = t.strip_prefix('(')?.strip_suffix(')')?.trim();
            if inner.is_empty() {
                return Some(Value::Array(Vec::new()));
            }
            inner
                .split(',')
                .map(|item| match &a.element {
                    Ty::Array(_) | Ty::Record(_) => None,
                    element => literal(item, element, time_unit),
                })
                .collect::<Option<Vec<Value>>>()
                .map(Value::Array)
        }
        Ty::Record(_) | Ty::Access(_) | Ty::File(_) | Ty::Protected(_) => None,
    }
}

fn number(t: &str) -> Option<f64> {
    let clean: String = t.chars().filter(|c| *c != '_').collect();
    if clean.is_empty()
        || !clean
            .chars()
            .all(|c| c.is_ascii_digit() || matches!(c, '.' | 'e' | 'E' | '+' | '-'))
    {
        return None;
    }
    clean.parse::<f64>().ok().filter(|x| x.is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn literals_of_each_type() {
        let sc = |u: &str| (u == "ms").then_some(1e12);
        assert_eq!(parse_literal("4.5", &Ty::Real, sc), Some(Value::Real(4.5)));
        assert_eq!(
            parse_literal("1e-3", &Ty::Real, sc),
            Some(Value::Real(1e-3))
        );
        assert_eq!(parse_literal("5", &Ty::Real, sc), Some(Value::Real(5.0)));
        assert_eq!(
            parse_literal("1_000", &Ty::Integer, sc),
            Some(Value::Integer(1000))
        );
        assert_eq!(
            parse_literal("10 ms", &Ty::Time, sc),
            Some(Value::Time(0.01))
        );
        assert_eq!(
            parse_literal("2.5ms", &Ty::Time, sc),
            Some(Value::Time(2.5e-3))
        );
        assert_eq!(
            parse_literal("TRUE", &Ty::Boolean, sc),
            Some(Value::Boolean(true))
        );
        assert_eq!(parse_literal("abc", &Ty::Real, sc), None);
        assert_eq!(parse_literal("inf", &Ty::Real, sc), None);
        assert_eq!(parse_literal("10 parsec", &Ty::Time, sc), None);
    }
}
