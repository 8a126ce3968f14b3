//! `T'image(x)`: the text of a value of type `T`.
//!
//! Reals print as the shortest decimal that reads back to the same number, always with a
//! fractional part or an exponent (`10.5`, `1.0`, `1e-7`), so a report shows the value
//! exactly; times in the largest unit that gives a number of at least 1 (`1.5 sec`, `10 ms`).

use vams_design::{Type, Value};

pub(crate) fn image(ty: &Type, v: &Value) -> String {
    match (ty, v) {
        (Type::Enum { literals, .. }, Value::Enum(p)) => literals
            .get(*p as usize)
            .cloned()
            .unwrap_or_else(|| p.to_string()),
        // In the primary unit (LRM 14.1: `resistance'image(2 kohm)` is "2000 ohm").
        (Type::Physical { units, .. }, Value::Integer(n)) => match units.first() {
            Some((unit, _)) => format!("{n} {unit}"),
            None => n.to_string(),
        },
        (_, v) => value_text(v),
    }
}

/// The text of a value when its type says nothing more (enumerations as positions).
fn value_text(v: &Value) -> String {
    match v {
        Value::Real(x) => real_image(*x),
        Value::Integer(i) => i.to_string(),
        Value::Boolean(b) => b.to_string(),
        Value::Time(t) => time_image(*t),
        Value::Enum(p) => p.to_string(),
        Value::String(s) => s.clone(),
        Value::Array(items) => {
            let parts: Vec<String> = items.iter().map(value_text).collect();
            format!("({})", parts.join(", "))
        }
        Value::Access(0) => "null".to_string(),
        Value::Access(h) => format!("<access {h}>"),
        Value::File(f) => format!("<file {f}>"),
    }
}

pub(crate) fn real_image(x: f64) -> String {
    if x.is_finite() && x != 0.0 && (x.abs() >= 1e15 || x.abs() < 1e-4) {
        // `{}` never uses exponents: 1e-7 would print as 0.0000001 and 1e20 with 20 digits.
        return format!("{x:e}");
    }
    let s = format!("{x}");
    if s.contains(['.', 'e', 'i', 'N']) {
        s
    } else {
        s + ".0"
    }
}

const TIME_UNITS: [(f64, &str); 7] = [
    (3600.0, "hr"),
    (60.0, "min"),
    (1.0, "sec"),
    (1e-3, "ms"),
    (1e-6, "us"),
    (1e-9, "ns"),
    (1e-12, "ps"),
];

pub(crate) fn time_image(t: f64) -> String {
    if t == 0.0 || !t.is_finite() {
        return format!("{t} sec");
    }
    let (scale, unit) = TIME_UNITS
        .iter()
        .copied()
        .find(|(scale, _)| t.abs() >= *scale * (1.0 - 1e-12))
        .unwrap_or((1e-15, "fs"));
    // Round to 12 significant digits so that 0.0015 s prints as 1.5 ms, not 1.5000000000000002.
    let n = t / scale;
    let digits = 11 - n.abs().log10().floor() as i32;
    let p = 10f64.powi(digits.clamp(0, 15));
    format!("{} {unit}", (n * p).round() / p)
}

/// `t` as a multiple of `unit` (seconds), followed by the unit's name: what textio's
/// `write` of a time writes (`1500 ps` for 1.5 ns in ps); a unit that is not one of time's
/// is taken as ns.
pub(crate) fn time_image_in(t: f64, unit: f64) -> String {
    let (scale, name) = std::iter::once((1e-15, "fs"))
        .chain(TIME_UNITS.iter().rev().copied())
        .find(|(s, _)| (unit / s - 1.0).abs() < 1e-9)
        .unwrap_or((1e-9, "ns"));
    let n = t / scale;
    // Twelve significant digits, as `time_image` rounds.
    let digits = if n == 0.0 {
        0
    } else {
        11 - n.abs().log10().floor() as i32
    };
    let p = 10f64.powi(digits.clamp(0, 15));
    format!("{} {name}", (n * p).round() / p)
}

/// The seconds of a unit of time named `name` (any case).
pub(crate) fn time_unit(name: &str) -> Option<f64> {
    let name = name.to_ascii_lowercase();
    if name == "fs" {
        return Some(1e-15);
    }
    if name == "sec" || name == "s" {
        return Some(1.0);
    }
    TIME_UNITS.iter().find(|(_, n)| *n == name).map(|(s, _)| *s)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reals_read_back_and_always_look_real() {
        assert_eq!(real_image(10.5), "10.5");
        assert_eq!(real_image(1.0), "1.0");
        assert_eq!(real_image(-3.0), "-3.0");
        assert_eq!(real_image(0.1), "0.1");
        assert_eq!(real_image(1e-7), "1e-7");
        assert_eq!(real_image(2.5e20), "2.5e20");
        assert_eq!(real_image(12345.678), "12345.678");
    }

    #[test]
    fn times_pick_the_largest_unit() {
        assert_eq!(time_image(1.5), "1.5 sec");
        assert_eq!(time_image(0.01), "10 ms");
        assert_eq!(time_image(0.0015), "1.5 ms");
        assert_eq!(time_image(2e-9), "2 ns");
        assert_eq!(time_image(0.0), "0 sec");
        assert_eq!(time_image(-0.002), "-2 ms");
    }

    #[test]
    fn enumerations_print_their_literal() {
        let ty = Type::Enum {
            name: "state".into(),
            literals: vec!["idle".into(), "run".into()],
        };
        assert_eq!(image(&ty, &Value::Enum(1)), "run");
        assert_eq!(image(&Type::Integer, &Value::Integer(-4)), "-4");
        assert_eq!(image(&Type::Boolean, &Value::Boolean(true)), "true");
    }
}
